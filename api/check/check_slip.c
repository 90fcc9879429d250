/* check_slip.c — naming the slip that explains a wrong answer of POST
 * /v1/check (contracts in api/check/check_slip.h): each candidate slip is undone on
 * the student's value and the result graded again with the same kind,
 * factor and tolerance; the first that grades correct is named.
 */
#include "check/check_slip.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check/check_tree.h"
#include "mech/base/constants.h"

#define SLIP_SWAP_MAX 16 /* longest array whose pairs of components are tried */
#define SLIP_TEN_MAX 12  /* largest power of ten tried */

/* One candidate: the slip and the factor that undoes it. */
struct slip_try {
    enum api_check_slip_kind kind;
    double fix;
};

/* Grade value as g did but with the factor multiplied by m; 1 when correct,
 * 0 when wrong, -1 on a failure recorded on c. */
static int correct_with(struct api_call *c, const struct api_check_grade *g, double m,
                        const json_t *want, const json_t *value, const json_t *parent,
                        const char *pointer)
{
    struct api_check_grade t;
    memset(&t, 0, sizeof t);
    t.tol = g->tol;
    t.kind = g->kind;
    t.factor = g->factor * m;
    t.wrong_ptrs = NULL;
    if (api_check_grade_field(c, &t, want, value, parent, pointer, "/answer/kind")) return -1;
    return t.wrong == 0 && t.count > 0;
}

/* 1/x of every number (times f) of a numeric tree (new reference; NULL when
 * a number is 0, or out of memory: then *nomem is set). */
static json_t *reciprocal_copy(const json_t *j, double f, int depth, int *nomem)
{
    json_t *out;
    if (json_is_number(j)) {
        double x = json_number_value(j) * f;
        if (!(x != 0 && isfinite(1 / x))) return NULL;
        if (!(out = json_real(1 / x))) *nomem = 1;
        return out;
    }
    if (!(out = json_array())) *nomem = 1;
    if (!out || depth > 8) return out;
    for (size_t i = 0; i < json_array_size(j); i++) {
        json_t *e = reciprocal_copy(json_array_get(j, i), f, depth + 1, nomem);
        if (!e || json_array_append_new(out, e)) {
            if (e) *nomem = 1;
            json_decref(out);
            return NULL;
        }
    }
    return out;
}

/* Record an allocation failure on c; returns -1. */
static int slip_nomem(struct api_call *c)
{
    struct mech_error me;
    mech_error_clear(&me);
    mech_error_set(&me, MECH_ENOMEM, NULL, "out of memory");
    api_call_fail_core(c, MECH_ENOMEM, &me, "");
    return -1;
}

/* The largest magnitude the expected value has (the angle of an axis_angle). */
static double expected_size(const json_t *want)
{
    if (json_is_object(want)) return fabs(json_number_value(json_object_get(want, "angle")));
    return api_check_max_abs(want, 0);
}

static int is_flat_array(const json_t *j)
{
    if (!json_is_array(j) || json_array_size(j) < 2 || json_array_size(j) > SLIP_SWAP_MAX)
        return 0;
    for (size_t i = 0; i < json_array_size(j); i++)
        if (!json_is_number(json_array_get(j, i))) return 0;
    return 1;
}

/* Swapped components: the first pair (i, j) whose exchange makes value
 * right. 1 found, 0 none, -1 failure. */
static int find_swap(struct api_call *c, const struct api_check_grade *g, const json_t *want,
                     const json_t *value, const json_t *parent, const char *pointer,
                     struct api_check_slip *s)
{
    if (!is_flat_array(value)) return 0;
    size_t n = json_array_size(value);
    json_t *sw = json_deep_copy(value);
    if (!sw) return slip_nomem(c);
    int found = 0;
    for (size_t i = 0; i < n && found == 0; i++)
        for (size_t j = i + 1; j < n && found == 0; j++) {
            json_t *a = json_array_get(value, i), *b = json_array_get(value, j);
            if (json_number_value(a) == json_number_value(b)) continue;
            if (json_array_set(sw, i, b) || json_array_set(sw, j, a)) {
                json_decref(sw);
                return slip_nomem(c);
            }
            found = correct_with(c, g, 1, want, sw, parent, pointer);
            if (json_array_set(sw, i, a) || json_array_set(sw, j, b)) {
                json_decref(sw);
                return slip_nomem(c);
            }
            if (found == 1) {
                s->i = i;
                s->j = j;
            }
        }
    json_decref(sw);
    return found;
}

int api_check_slip_find(struct api_call *c, const struct api_check_grade *g, const json_t *want,
                        const json_t *value, const json_t *parent, const char *pointer,
                        const char *field_dim, int check_unit, struct api_check_slip *s)
{
    memset(s, 0, sizeof *s);
    enum api_check_kind k = g->kind;
    int scalable = k == API_KIND_NUMBER || k == API_KIND_ANGLE || k == API_KIND_VECTOR ||
                   k == API_KIND_MATRIX || k == API_KIND_AXIS_ANGLE;
    /* An expected value that counts as zero at the problem's scale has no
     * sign, size or order to get wrong: any multiple of a small answer would
     * look "right". */
    if (!(expected_size(want) > api_check_bound(&g->tol, g->tol.scale))) return 0;
    struct slip_try tries[8 + 2 * SLIP_TEN_MAX];
    size_t nt = 0;
    if (check_unit && g->factor > 0) tries[nt++] = (struct slip_try){API_SLIP_UNIT, 1 / g->factor};
    if (scalable) tries[nt++] = (struct slip_try){API_SLIP_SIGN, -1};
    for (size_t i = 0; i < nt; i++) {
        int r = correct_with(c, g, tries[i].fix, want, value, parent, pointer);
        if (r < 0) return -1;
        if (r) {
            s->kind = tries[i].kind;
            s->fix = tries[i].fix;
            return 0;
        }
    }
    if (k == API_KIND_NUMBER || k == API_KIND_VECTOR || k == API_KIND_AXIS) {
        int r = find_swap(c, g, want, value, parent, pointer, s);
        if (r < 0) return -1;
        if (r) {
            s->kind = API_SLIP_SWAPPED;
            return 0;
        }
    }
    if (!scalable) return 0;
    nt = 0;
    for (int e = 1; e <= SLIP_TEN_MAX; e++) {
        tries[nt++] = (struct slip_try){API_SLIP_POWER_OF_TEN, pow(10.0, e)};
        tries[nt++] = (struct slip_try){API_SLIP_POWER_OF_TEN, pow(10.0, -e)};
    }
    int angular = field_dim ? !strncmp(field_dim, "angle", 5)
                            : (k == API_KIND_ANGLE || k == API_KIND_AXIS_ANGLE);
    if (angular) {
        tries[nt++] = (struct slip_try){API_SLIP_DEGREES_FOR_RADIANS, MECH_PI / 180};
        tries[nt++] = (struct slip_try){API_SLIP_RADIANS_FOR_DEGREES, 180 / MECH_PI};
    }
    tries[nt++] = (struct slip_try){API_SLIP_FACTOR_2, 2};
    tries[nt++] = (struct slip_try){API_SLIP_FACTOR_2, 0.5};
    tries[nt++] = (struct slip_try){API_SLIP_FACTOR_2PI, 2 * MECH_PI};
    tries[nt++] = (struct slip_try){API_SLIP_FACTOR_2PI, 1 / (2 * MECH_PI)};
    for (size_t i = 0; i < nt; i++) {
        int r = correct_with(c, g, tries[i].fix, want, value, parent, pointer);
        if (r < 0) return -1;
        if (r) {
            s->kind = tries[i].kind;
            s->fix = tries[i].fix;
            return 0;
        }
    }
    if (k == API_KIND_NUMBER && !json_is_object(value)) {
        int nomem = 0;
        json_t *rv = reciprocal_copy(value, g->factor, 0, &nomem);
        if (nomem) return slip_nomem(c);
        if (rv) {
            struct api_check_grade t = *g;
            t.factor = 1; /* rv is already in the field's unit */
            int r = correct_with(c, &t, 1, want, rv, parent, pointer);
            json_decref(rv);
            if (r < 0) return -1;
            if (r) s->kind = API_SLIP_RECIPROCAL;
        }
    }
    return 0;
}

const char *api_check_slip_name(enum api_check_slip_kind k)
{
    switch (k) {
    case API_SLIP_UNIT: return "unit";
    case API_SLIP_SIGN: return "sign";
    case API_SLIP_SWAPPED: return "swapped_components";
    case API_SLIP_POWER_OF_TEN: return "power_of_ten";
    case API_SLIP_DEGREES_FOR_RADIANS: return "degrees_for_radians";
    case API_SLIP_RADIANS_FOR_DEGREES: return "radians_for_degrees";
    case API_SLIP_FACTOR_2: return "factor_2";
    case API_SLIP_FACTOR_2PI: return "factor_2pi";
    case API_SLIP_RECIPROCAL: return "reciprocal";
    default: return NULL;
    }
}

/* "1st", "2nd", ... of component i (0-based) and its axis name for 3. */
static void component_words(size_t i, size_t n, char *buf, size_t len)
{
    static const char *const ord[] = {"1st", "2nd", "3rd"};
    static const char *const xyz[] = {"x", "y", "z"};
    if (n == 3)
        snprintf(buf, len, "%s (%s)", ord[i], xyz[i]);
    else if (i < 3)
        snprintf(buf, len, "%s", ord[i]);
    else
        snprintf(buf, len, "%zuth", i + 1);
}

void api_check_slip_words(const struct api_check_slip *s, size_t ncomponents,
                          const char *field_unit, const char *given_unit, char *buf, size_t n)
{
    buf[0] = '\0';
    char a[32], b[32];
    /* fix > 1: the student's value is too small by that factor */
    const char *size = s->fix > 1 ? "small" : "large";
    double by = s->fix > 1 ? s->fix : 1 / s->fix;
    switch (s->kind) {
    case API_SLIP_UNIT:
        snprintf(buf, n,
                 "The magnitude of your answer is right, but the unit is wrong: the number is "
                 "right in %s, not in %s.",
                 field_unit ? field_unit : "the answer's unit", given_unit ? given_unit : "it");
        break;
    case API_SLIP_SIGN:
        snprintf(buf, n, "The sign is wrong: the same size with the opposite sign would be right.");
        break;
    case API_SLIP_SWAPPED:
        component_words(s->i, ncomponents, a, sizeof a);
        component_words(s->j, ncomponents, b, sizeof b);
        snprintf(buf, n, "Two components are swapped: the %s and the %s.", a, b);
        break;
    case API_SLIP_POWER_OF_TEN: {
        int e = (int)lround(log10(by));
        if (e <= 3)
            snprintf(buf, n, "Your answer is %.0f times too %s: check the exponent and the "
                     "prefix of the unit.", by, size);
        else
            snprintf(buf, n, "Your answer is 10^%d times too %s: check the exponent and the "
                     "prefix of the unit.", e, size);
        break;
    }
    case API_SLIP_DEGREES_FOR_RADIANS:
        snprintf(buf, n, "The number looks like degrees where radians are asked: convert it "
                 "(multiply by pi/180) or say that it is in degrees.");
        break;
    case API_SLIP_RADIANS_FOR_DEGREES:
        snprintf(buf, n, "The number looks like radians where degrees are asked: convert it "
                 "(multiply by 180/pi) or say that it is in radians.");
        break;
    case API_SLIP_FACTOR_2:
        snprintf(buf, n, "Your answer is %s the right value: look for a factor of 2.",
                 s->fix > 1 ? "half" : "twice");
        break;
    case API_SLIP_FACTOR_2PI:
        snprintf(buf, n, "Your answer is too %s by a factor of 2 pi: check turns against "
                 "radians, or a frequency against an angular frequency.", size);
        break;
    case API_SLIP_RECIPROCAL:
        snprintf(buf, n, "Your answer is the reciprocal (1/x) of the right value.");
        break;
    default: break;
    }
}
