/* check_grade.h — grading one field for POST /v1/check: the student's value
 * (a numeric tree, or an {"axis", "angle"} object) against the operation's
 * expected value, as the field's kind (api/check/check_kind.h) and in the student's
 * unit, with the errors, the bound applied and the wrong elements; and the
 * student-facing feedback sentence. api/ops/tools/check.c reads the request, runs the
 * operation and encodes the verdict; the tolerance rules are in
 * docs/grading.md.
 */
#ifndef API_CHECK_GRADE_H
#define API_CHECK_GRADE_H

#include <jansson.h>
#include <stddef.h>

#include "check/check_kind.h"
#include "run/endpoint.h"

/* A field's grade. The caller sets tol, kind, factor and wrong_ptrs (a new
 * array it owns, or NULL to not list the wrong elements) and zeroes the rest;
 * api_check_grade_field fills the rest. */
struct api_check_grade {
    struct api_check_tol tol;
    enum api_check_kind kind;
    double factor; /* student's unit -> the field's unit (> 0) */
    double max_abs_err, max_rel_err, max_bound;
    int have_rel;        /* max_rel_err is valid (some expected value was nonzero) */
    size_t count, wrong; /* numbers compared; wrong elements or rows */
    const char *note;    /* from the comparison (a zero axis ...), static; NULL if none */
    json_t *wrong_ptrs;  /* JSON pointers into the operation's answer, at most 20 */
};

/* Grade value (the student's, borrowed) against want (the expected value at
 * JSON pointer `pointer` of the operation's answer; parent its container or
 * NULL; both borrowed) into g. NUMBER and ANGLE compare every number of the
 * tree on its own; the other kinds compare the whole value (EIGENVECTORS with
 * the eigenvalues of a sibling "moments" or "eigenvalues" array when there is
 * one). The student's numbers (the angle, for AXIS_ANGLE) are multiplied by
 * g->factor first.
 *
 * Preconditions (api/ops/tools/check.c checks them): for NUMBER and ANGLE, want and
 * value are numeric trees of the same shape (api_check_same_shape).
 * Returns 0, or -1 after recording the failure on c: a 422 naming kind_ptr
 * ("/answer/kind" or "/answer/pointer") when the kind does not fit want, or
 * "/answer/value" when an axis_angle answer is not that object; a 500 when
 * out of memory. */
int api_check_grade_field(struct api_call *c, struct api_check_grade *g, const json_t *want,
                          const json_t *value, const json_t *parent, const char *pointer,
                          const char *kind_ptr);

/* The student-facing message for a graded field: the verdict (correct), the
 * sentence `why` (a slip or a problem with the answer, plain words; NULL or
 * "" for none), what was expected (kind, shape and unit: the student's unit,
 * else field_unit; both may be NULL, then no unit is named) and, only when
 * reveal is set, the expected value converted to the student's unit
 * (divided by g->factor; numbers in their shortest form to 6 significant
 * figures). Never a JSON pointer or a field path. New reference (NULL only
 * when out of memory). */
json_t *api_check_feedback(const struct api_check_grade *g, int correct, const json_t *want,
                           const char *unit, const char *field_unit, int reveal, const char *why);

/* x in its shortest form to 6 significant figures, for words: 5, 0.25,
 * 26.5651, 1.5e-7, 5e7 (no "5.0", no "e+07", no "-0"). Into buf (n bytes). */
void api_check_number_words(double x, char *buf, size_t n);

#endif
