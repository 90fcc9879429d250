/* check_tree.c — JSON pointers and numeric trees for POST /v1/check
 * (contracts in api/check/check_tree.h). Moved unchanged from api/ops/tools/check.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "check/check_tree.h"

/* Resolve pointer in doc; NULL if it does not exist or is malformed. When
 * parent is not NULL it receives the container holding the target (NULL for
 * the root). *bad is set when the pointer is syntactically invalid. */
json_t *api_check_pointer_get(json_t *doc, const char *ptr, json_t **parent, int *bad)
{
    *bad = 0;
    if (parent) *parent = NULL;
    if (!ptr[0]) return doc;
    if (ptr[0] != '/') {
        *bad = 1;
        return NULL;
    }
    json_t *cur = doc;
    const char *p = ptr;
    char tok[256];
    while (*p == '/') {
        p++;
        size_t n = 0;
        while (*p && *p != '/') {
            char ch = *p++;
            if (ch == '~') {
                if (*p == '0')
                    ch = '~';
                else if (*p == '1')
                    ch = '/';
                else {
                    *bad = 1;
                    return NULL;
                }
                p++;
            }
            if (n + 1 >= sizeof tok) {
                *bad = 1;
                return NULL;
            }
            tok[n++] = ch;
        }
        tok[n] = '\0';
        if (parent) *parent = cur;
        if (json_is_object(cur)) {
            cur = json_object_get(cur, tok);
        } else if (json_is_array(cur)) {
            /* array index: "0" or digits without a leading zero */
            if (!n || (n > 1 && tok[0] == '0') || n > 9) return NULL;
            size_t idx = 0;
            for (size_t i = 0; i < n; i++) {
                if (tok[i] < '0' || tok[i] > '9') return NULL;
                idx = idx * 10 + (size_t)(tok[i] - '0');
            }
            cur = json_array_get(cur, idx);
        } else {
            return NULL;
        }
        if (!cur) return NULL;
    }
    return cur;
}

/* Largest |number| in a JSON value (numbers and nested arrays). */
double api_check_max_abs(const json_t *j, int depth)
{
    if (json_is_number(j)) return fabs(json_number_value(j));
    double m = 0;
    if (json_is_array(j) && depth < 8) {
        size_t i;
        json_t *v;
        json_array_foreach(j, i, v) {
            double x = api_check_max_abs(v, depth + 1);
            if (x > m) m = x;
        }
    }
    return m;
}

/* Numbers in a numeric tree. */
static size_t count_numbers(const json_t *j, int depth)
{
    if (json_is_number(j)) return 1;
    size_t n = 0;
    if (json_is_array(j) && depth < 8)
        for (size_t i = 0; i < json_array_size(j); i++)
            n += count_numbers(json_array_get(j, i), depth + 1);
    return n;
}

/* Shape of a numeric tree in words: "a number", "an array of 3 numbers",
 * "a 3 x 3 array", or "nested arrays of 12 numbers". */
void api_check_shape_words(const json_t *j, char *buf, size_t n)
{
    if (json_is_number(j)) {
        snprintf(buf, n, "a number");
        return;
    }
    size_t rows = json_array_size(j);
    const json_t *first = json_array_get(j, 0);
    if (json_is_number(first)) {
        snprintf(buf, n, "an array of %zu number%s", rows, rows == 1 ? "" : "s");
        return;
    }
    size_t cols = json_array_size(first);
    int rect = json_is_array(first);
    for (size_t i = 0; i < rows && rect; i++) {
        const json_t *r = json_array_get(j, i);
        rect =
            json_is_array(r) && json_array_size(r) == cols && json_is_number(json_array_get(r, 0));
    }
    if (rect)
        snprintf(buf, n, "a %zu x %zu array (%zu arrays of %zu numbers)", rows, cols, rows, cols);
    else
        snprintf(buf, n, "nested arrays of %zu numbers in all", count_numbers(j, 0));
}

/* Shape check: want (the expected value) and got (the answer's value) are both
 * numbers or arrays of the same length down to numbers. Returns 0, or -1 with
 * the pointer (relative to /answer/value) of the first mismatch in where. */
int api_check_same_shape(const json_t *want, const json_t *got, char *where, size_t n,
                         size_t *count, int depth)
{
    if (json_is_number(want)) {
        if (!json_is_number(got)) return -1;
        (*count)++;
        return 0;
    }
    if (!json_is_array(want) || !json_is_array(got) || depth > 8 ||
        json_array_size(want) != json_array_size(got))
        return -1;
    size_t len = strlen(where);
    for (size_t i = 0; i < json_array_size(want); i++) {
        snprintf(where + len, n - len, "/%zu", i);
        if (api_check_same_shape(json_array_get(want, i), json_array_get(got, i), where, n, count,
                                 depth + 1))
            return -1;
        where[len] = '\0';
    }
    return *count > API_CHECK_MAX_ELEMENTS ? -1 : 0;
}

/* Flatten a number, an array of numbers or a rectangular array of arrays of
 * numbers into x (malloc'ed, *rows x *cols); -1 for any other shape, -2 when
 * out of memory (*x stays NULL then). */
int api_check_flatten(const json_t *j, double **x, size_t *rows, size_t *cols)
{
    *x = NULL;
    if (json_is_number(j)) {
        *rows = *cols = 1;
    } else if (json_is_number(json_array_get(j, 0))) {
        *rows = 1;
        *cols = json_array_size(j);
    } else {
        *rows = json_array_size(j);
        *cols = json_array_size(json_array_get(j, 0));
    }
    if (!*rows || !*cols || *rows * *cols > API_CHECK_MAX_ELEMENTS) return -1;
    *x = malloc(*rows * *cols * sizeof **x);
    if (!*x) return -2;
    if (json_is_number(j)) {
        (*x)[0] = json_number_value(j);
        return 0;
    }
    for (size_t r = 0; r < *rows; r++) {
        const json_t *row =
            *rows == 1 && json_is_number(json_array_get(j, 0)) ? j : json_array_get(j, r);
        if (json_array_size(row) != *cols) goto bad;
        for (size_t c = 0; c < *cols; c++) {
            const json_t *v = json_array_get(row, c);
            if (!json_is_number(v)) goto bad;
            (*x)[r * *cols + c] = json_number_value(v);
        }
    }
    return 0;
bad:
    free(*x);
    *x = NULL;
    return -1;
}

/* {"axis": [x, y, z], "angle": t} as [x, y, z, t]; -1 if not that shape. */
int api_check_axis_angle_of(const json_t *j, double x[4])
{
    const json_t *axis = json_object_get(j, "axis");
    const json_t *angle = json_object_get(j, "angle");
    if (!json_is_object(j) || json_object_size(j) != 2 || !json_is_array(axis) ||
        json_array_size(axis) != 3 || !json_is_number(angle))
        return -1;
    for (size_t i = 0; i < 3; i++) {
        if (!json_is_number(json_array_get(axis, i))) return -1;
        x[i] = json_number_value(json_array_get(axis, i));
    }
    x[3] = json_number_value(angle);
    return 0;
}

/* Whether a value is a number or a (nested) array with only numbers. */
int api_check_numeric_tree(const json_t *j, int depth)
{
    if (json_is_number(j)) return 1;
    if (!json_is_array(j) || depth > 8 || json_array_size(j) == 0) return 0;
    size_t i;
    json_t *v;
    json_array_foreach(j, i, v)
        if (!api_check_numeric_tree(v, depth + 1)) return 0;
    return 1;
}

/* A copy of a numeric tree with every number multiplied by f. */
json_t *api_check_scaled_copy(const json_t *j, double f, int depth)
{
    if (json_is_number(j)) return json_real(json_number_value(j) * f);
    json_t *out = json_array();
    if (!out || depth > 8) return out;
    for (size_t i = 0; i < json_array_size(j); i++)
        json_array_append_new(out, api_check_scaled_copy(json_array_get(j, i), f, depth + 1));
    return out;
}
