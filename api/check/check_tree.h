/* check_tree.h — the JSON values POST /v1/check compares: RFC 6901 pointers
 * into an operation's answer and "numeric trees" (a number, or arrays nested
 * down to numbers), their shapes in words and their flattening into the plain
 * double arrays api/check/check_kind.h compares. Used by api/ops/tools/check.c, api/check/check_evidence.c
 * and api/check/check_grade.c.
 *
 * All functions are reentrant; recursion stops at a fixed depth (8 or 9
 * levels of arrays), so no input can exhaust the stack.
 */
#ifndef API_CHECK_TREE_H
#define API_CHECK_TREE_H

#include <jansson.h>
#include <stddef.h>

#define API_CHECK_MAX_ELEMENTS 100000 /* numbers compared in one answer */

/* The value at JSON pointer ptr (RFC 6901; "" = doc itself) in doc, borrowed
 * from doc; NULL if it does not exist. When parent is not NULL it receives the
 * container holding the target (NULL for the root). *bad is set to 1 when ptr
 * is syntactically invalid (no leading '/', a '~' not followed by 0 or 1, a
 * token of 256 bytes or more), else 0. Array tokens are "0" or digits without
 * a leading zero, at most 9 of them. */
json_t *api_check_pointer_get(json_t *doc, const char *ptr, json_t **parent, int *bad);

/* 1 if j is a number or a non-empty (nested, at most 9 levels) array whose
 * leaves are all numbers; else 0. */
int api_check_numeric_tree(const json_t *j, int depth);

/* Largest |number| in a number or nested arrays of numbers (8 levels; other
 * members count as 0). 0 for anything else. */
double api_check_max_abs(const json_t *j, int depth);

/* Shape check: want (the expected value) and got (the student's value) are
 * both numbers or arrays of the same length down to numbers, with at most
 * API_CHECK_MAX_ELEMENTS numbers. Returns 0, or -1 with the pointer (relative
 * to /answer/value) of the first mismatch appended to where (n bytes, holding
 * a NUL-terminated prefix on entry). *count accumulates the numbers seen. */
int api_check_same_shape(const json_t *want, const json_t *got, char *where, size_t n,
                         size_t *count, int depth);

/* Shape of a numeric tree in words, into buf (n bytes, truncated): "a number",
 * "an array of 3 numbers", "a 3 x 3 array (3 arrays of 3 numbers)" or "nested
 * arrays of 12 numbers in all". */
void api_check_shape_words(const json_t *j, char *buf, size_t n);

/* Flatten a number, an array of numbers or a rectangular array of arrays of
 * numbers into *x (malloc'ed, owned by the caller, *rows x *cols, row-major).
 * Returns 0; -1 for any other shape, an empty one or more than
 * API_CHECK_MAX_ELEMENTS numbers; -2 when out of memory. *x is NULL on any
 * failure. */
int api_check_flatten(const json_t *j, double **x, size_t *rows, size_t *cols);

/* {"axis": [x, y, z], "angle": t} (exactly those two members, all numbers) as
 * x = [x, y, z, t]; returns 0, or -1 if j is not that shape. */
int api_check_axis_angle_of(const json_t *j, double x[4]);

/* A copy of a numeric tree with every number multiplied by f (a new
 * reference: reals; NULL only when out of memory; deeper than 8 levels of
 * arrays gives an empty array). */
json_t *api_check_scaled_copy(const json_t *j, double f, int depth);

#endif
