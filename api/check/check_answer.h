/* check_answer.h — what a student typed, read for POST /v1/check: a number
 * or an expression ("0.4636", "-1.5e3", "5.0 x 10^-3", "pi/2", "2 pi",
 * "sqrt(3)/2") with an optional unit after it ("27.9 deg", "27.9°",
 * "5 kg*m^2", "5 kg·m²"), a JSON array written as text ("[0, 0, 1]"), or
 * such strings inside an array; and the unit names a student writes
 * ("metres", "kg m2", "µm", "rev/min"). Reading never fails the request:
 * whatever cannot be read is a problem code that the verdict names in plain
 * words (the answer is then wrong, not refused).
 *
 * Reentrant; no global state. Allocation only for the returned JSON values.
 */
#ifndef API_CHECK_ANSWER_H
#define API_CHECK_ANSWER_H

#include <jansson.h>
#include <stddef.h>

#include "check/check_kind.h"

/* Why a student's answer could not be graded as a value (API_ANSWER_OK:
 * it could). Append-only: the codes are the verdict's "mistake" strings. */
enum api_answer_problem {
    API_ANSWER_OK,
    API_ANSWER_EMPTY,          /* null, "" or only spaces */
    API_ANSWER_NOT_NUMBER,     /* text with no number in it, a boolean, an array of such */
    API_ANSWER_NOT_FINITE,     /* a value that overflows ("1e999") or is not a number */
    API_ANSWER_UNIT_UNKNOWN,   /* a unit mechd does not know */
    API_ANSWER_UNIT_DIMENSION, /* a unit of another dimension than the field's */
    API_ANSWER_SHAPE           /* not the shape of the expected value */
};

/* The read answer. value: a new reference (a numeric tree, or an
 * {"axis", "angle"} object as given), NULL unless problem is API_ANSWER_OK;
 * unit: the unit written with the value or given as answer.unit (the typed
 * text, copied, at most 63 bytes; "" when none); su: that unit when mechd
 * knows it, else NULL. */
struct api_answer {
    json_t *value;
    char unit[64];
    const struct api_unit *su;
    enum api_answer_problem problem;
};

/* Read the student's value (borrowed; may be NULL when absent) with the
 * unit given beside it (answer.unit; NULL when none). A unit written inside
 * a string value wins over unit_given when both are present and differ only
 * when unit_given is NULL; when both are given the one in the text is used.
 * Fills *out (caller releases out->value with json_decref). Returns 0, or -1
 * when out of memory (then out->value is NULL). */
int api_answer_read(const json_t *value, const char *unit_given, struct api_answer *out);

/* The unit a student wrote: api_unit_find's exact names first, then the same
 * names compared without spaces, '*', '.', '·' and '^' ("kg*m^2", "kg m2",
 * "kg·m²"), with µ/μ as u, ° as deg, "**" as '^', and common words
 * ("metres", "seconds", "degrees", "radians", "rev/min", "sec"). Case
 * matters (mm is not Mm). NULL when none matches. */
const struct api_unit *api_unit_read(const char *typed);

/* What a dimension measures, in words with its article ("a length", "a moment
 * of inertia", "a pure number"); dim is api_unit.dim. Static string. */
const char *api_unit_dim_words(const char *dim);

/* The problem's code as a string ("not_a_number", "unit_unknown", ...); NULL
 * for API_ANSWER_OK. Static string. */
const char *api_answer_problem_name(enum api_answer_problem p);

#endif
