/* check_slip.h — the common slips that explain a wrong answer of POST
 * /v1/check: a flipped sign, a power of ten, degrees read as radians (or
 * the reverse), a missing or extra factor of 2 or 2 pi, the reciprocal,
 * two swapped components, and the right number in the wrong unit. A slip is
 * named when — and only when — undoing it makes the answer correct under the
 * same tolerance; otherwise none is named (a guess is worse than nothing).
 */
#ifndef API_CHECK_SLIP_H
#define API_CHECK_SLIP_H

#include <jansson.h>
#include <stddef.h>

#include "check/check_grade.h"

enum api_check_slip_kind {
    API_SLIP_NONE,
    API_SLIP_UNIT,                /* the number is right in the field's unit, the unit is not */
    API_SLIP_SIGN,                /* the opposite sign would be right */
    API_SLIP_SWAPPED,             /* two components exchanged (a 1-D array) */
    API_SLIP_POWER_OF_TEN,        /* off by 10^k, k != 0, |k| <= 12 */
    API_SLIP_DEGREES_FOR_RADIANS, /* a number of degrees read in radians */
    API_SLIP_RADIANS_FOR_DEGREES, /* a number of radians read in degrees */
    API_SLIP_FACTOR_2,            /* twice or half the right value */
    API_SLIP_FACTOR_2PI,          /* 2 pi times or 1/(2 pi) of the right value */
    API_SLIP_RECIPROCAL           /* 1/x of the right value (element-wise) */
};

/* A slip found. fix: the factor that turns the student's value into a right
 * one (for UNIT, POWER_OF_TEN, FACTOR_*, the angle units; -1 for SIGN);
 * i, j: the swapped components (0-based), for SWAPPED. */
struct api_check_slip {
    enum api_check_slip_kind kind;
    double fix;
    size_t i, j;
};

/* Look for a slip that explains the student's wrong value (borrowed), graded
 * as g was (its kind, factor and tolerance; g is not changed) against want
 * at pointer (parent its container; all borrowed). field_dim: the dimension
 * of the field's unit (api_unit.dim; NULL when unknown), to try degrees and
 * radians only for angles. check_unit: 1 to try the number in the field's
 * own unit (the student gave a unit other than the field's). Fills *s
 * (kind NONE when nothing explains the answer). Tries at most ~170 gradings
 * of the value (swaps only for arrays of at most 16 numbers). Returns 0, or
 * -1 after recording a failure on c (out of memory). */
int api_check_slip_find(struct api_call *c, const struct api_check_grade *g, const json_t *want,
                        const json_t *value, const json_t *parent, const char *pointer,
                        const char *field_dim, int check_unit, struct api_check_slip *s);

/* The slip's code in the verdict ("sign", "power_of_ten", ...); NULL for
 * NONE. Static string. */
const char *api_check_slip_name(enum api_check_slip_kind k);

/* The slip in plain words for the student, into buf (n bytes), e.g. "Your
 * answer is 1000 times too large: check the exponent and the unit's
 * prefix." field_unit and given_unit (may be NULL) name the units of a
 * UNIT slip. Writes "" for NONE. */
void api_check_slip_words(const struct api_check_slip *s, size_t ncomponents,
                          const char *field_unit, const char *given_unit, char *buf, size_t n);

#endif
