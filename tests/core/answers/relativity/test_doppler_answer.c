/* test_doppler_answer.c — one /v1/relativity/doppler answer
 * (core/answers/relativity/doppler_answer.c) against closed forms (notes §3.14),
 * evaluated in long double from the exact inputs:
 *   - longitudinal: D = sqrt((1 + β)/(1 − β)) approaching, its inverse
 *     receding, at β = 0.6 (2 and 1/2), β = 1e-9 (D − 1 = e^{atanh β} − 1)
 *     and 1 − β = 1e-12 (given as one_minus_beta, D ≈ 1.4e6);
 *   - transverse: D = 1/γ when the light arrives perpendicular to the
 *     source's velocity in the observer's frame, D = γ when it leaves
 *     perpendicular to the observer's velocity in the source's frame; D − 1
 *     and z from γ − 1 = β²/(sqrt(1 − β²)(1 + sqrt(1 − β²))), so β = 1e-9
 *     (D − 1 = −5e-19) is checked to round-off, not to 1e-7;
 *   - aberration: source at rest, observer moving along x, light leaving at
 *     θ to x: cos θ' = (cos θ − β)/(1 − β cos θ), sin θ' = sin θ/(γ(1 − β cos θ)),
 *     D = γ(1 − β cos θ). At β = 1e-9 the angle changes by
 *     δ = asin(sin θ (β − cos θ β²/(1 + sqrt(1 − β²)))/(1 − β cos θ)) (no
 *     cancellation) and D − 1 = (γ − 1) − βγ cos θ cancels in the direct
 *     form; at 1 − β = 1e-12, θ = atan(1e-6), 1 − β cos θ = (1 − β) cos θ +
 *     2 sin²(θ/2) and cos θ − β = (1 − β) − 2 sin²(θ/2) are both 1e-12-sized
 *     and formed here without cancellation;
 *   - the light (λ = c/ν, ν_obs = D ν, λ z), the shift's name, and every
 *     error: field names, out-of-range light, NULL. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/relativity/doppler_answer.h"
#include "testlib.h"

static const long double PI_L = 3.141592653589793238462643383279502884L;

static struct mech_boost along_x(double beta)
{
    struct mech_boost b;
    CHECK(mech_boost_from_beta(mech_vec3_make(beta, 0, 0), &b, NULL) == MECH_OK);
    return b;
}

static struct mech_boost near_c_x(double one_minus_beta, double sign)
{
    struct mech_boost b;
    CHECK(mech_boost_from_one_minus_beta(one_minus_beta, mech_vec3_make(sign, 0, 0), &b, NULL) ==
          MECH_OK);
    return b;
}

static struct mech_doppler_answer answer(const struct mech_boost *s, const struct mech_boost *o,
                                         struct mech_vec3 dir, enum mech_doppler_frame f)
{
    struct mech_doppler_request q = {.source = s, .observer = o, .direction = dir, .frame = f};
    struct mech_doppler_answer a;
    memset(&a, 0, sizeof a);
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_doppler_answer(&q, &a, &e), MECH_OK);
    if (e.code != MECH_OK) fprintf(stderr, "  error: %s\n", e.text);
    return a;
}

/* γ − 1 from β without cancellation. */
static long double gamma_m1(long double b)
{
    long double s = sqrtl((1 - b) * (1 + b));
    return b * b / (s * (1 + s));
}

static void test_longitudinal(void)
{
    const double betas[] = {0.6, 1e-9, 0.3};
    for (size_t i = 0; i < 3; i++) {
        const double b = betas[i];
        const long double lb = b, up = sqrtl((1 + lb) / (1 - lb));
        /* Observer moving towards the source, against the light (+x): approaching. */
        struct mech_boost toward = along_x(-b), away = along_x(b);
        struct mech_doppler_answer a =
            answer(NULL, &toward, mech_vec3_make(1, 0, 0), MECH_DOPPLER_SOURCE_FRAME);
        CHECK_EQ_INT(a.d.kind, MECH_DOPPLER_LONGITUDINAL_APPROACHING);
        CHECK_CLOSE(a.d.factor, (double)up, 4e-16, 0);
        CHECK_CLOSE(a.d.factor_minus_one, (double)expm1l(atanhl(lb)), 1e-15, 0);
        CHECK_EQ_INT(a.shift, MECH_DOPPLER_SHIFT_BLUE);
        CHECK_CLOSE(a.redshift_z, (double)expm1l(-atanhl(lb)), 1e-15, 0); /* 1/D − 1 */
        /* The source receding from an observer at rest: the inverse. */
        a = answer(&away, NULL, mech_vec3_make(-1, 0, 0), MECH_DOPPLER_OBSERVER_FRAME);
        CHECK_EQ_INT(a.d.kind, MECH_DOPPLER_LONGITUDINAL_RECEDING);
        CHECK_CLOSE(a.d.factor, (double)(1 / up), 4e-16, 0);
        CHECK_CLOSE(a.d.factor_minus_one, (double)expm1l(-atanhl(lb)), 1e-15, 0);
        CHECK_CLOSE(a.redshift_z, (double)expm1l(atanhl(lb)), 1e-15, 0);
        CHECK_EQ_INT(a.shift, MECH_DOPPLER_SHIFT_RED);
    }
    struct mech_boost rest = along_x(0);
    struct mech_doppler_answer r =
        answer(NULL, &rest, mech_vec3_make(1, 0, 0), MECH_DOPPLER_SOURCE_FRAME);
    CHECK_CLOSE(r.d.factor, 1, 0, 0);
    CHECK_EQ_INT(r.shift, MECH_DOPPLER_SHIFT_NONE);
    /* 1 − β = 1e-12 exactly as given: D = sqrt((2 − δ)/δ). */
    const double d = 1e-12;
    const long double up = sqrtl((2 - (long double)d) / d);
    struct mech_boost fast = near_c_x(d, 1);
    struct mech_doppler_answer a =
        answer(&fast, NULL, mech_vec3_make(1, 0, 0), MECH_DOPPLER_OBSERVER_FRAME);
    CHECK_EQ_INT(a.d.kind, MECH_DOPPLER_LONGITUDINAL_APPROACHING);
    CHECK_CLOSE(a.d.factor, (double)up, 1e-15, 0);
    CHECK_CLOSE(a.d.one_minus_beta, d, 1e-15, 0);
    a = answer(&fast, NULL, mech_vec3_make(-1, 0, 0), MECH_DOPPLER_OBSERVER_FRAME);
    CHECK_CLOSE(a.d.factor, (double)(1 / up), 1e-15, 0);
    CHECK_CLOSE(a.redshift_z, (double)(up - 1), 1e-15, 0);
}

static void test_transverse(void)
{
    const double betas[] = {0.6, 1e-9, 0.999};
    for (size_t i = 0; i < 3; i++) {
        const long double b = betas[i], gm1 = gamma_m1(b), g = 1 + gm1;
        struct mech_boost v = along_x(betas[i]);
        /* Observer frame: the moving source's light arrives along y: 1/γ. */
        struct mech_doppler_answer a =
            answer(&v, NULL, mech_vec3_make(0, 1, 0), MECH_DOPPLER_OBSERVER_FRAME);
        CHECK_EQ_INT(a.d.kind, MECH_DOPPLER_TRANSVERSE_OBSERVER_FRAME);
        CHECK_CLOSE(a.d.factor, (double)(1 / g), 4e-16, 0);
        CHECK_CLOSE(a.d.factor_minus_one, (double)(-gm1 / g), 1e-15, 0);
        CHECK_CLOSE(a.redshift_z, (double)gm1, 1e-15, 0);
        CHECK_CLOSE(a.d.angle_observer, MECH_PI / 2, 2e-16, 0);
        /* Source frame: light leaves along y, the observer moving along x: γ. */
        a = answer(NULL, &v, mech_vec3_make(0, 1, 0), MECH_DOPPLER_SOURCE_FRAME);
        CHECK_EQ_INT(a.d.kind, MECH_DOPPLER_TRANSVERSE_SOURCE_FRAME);
        CHECK_CLOSE(a.d.factor, (double)g, 4e-16, 0);
        CHECK_CLOSE(a.d.factor_minus_one, (double)gm1, 1e-15, 0);
        CHECK_CLOSE(a.redshift_z, (double)(-gm1 / g), 1e-15, 0);
        CHECK_CLOSE(a.d.gamma_minus_one, (double)gm1, 1e-15, 0);
    }
    /* 1 − β = 1e-12: γ = 1/sqrt(δ(2 − δ)) ≈ 7.07e5. */
    const double d = 1e-12;
    const long double g = 1 / sqrtl((long double)d * (2 - (long double)d));
    struct mech_boost fast = near_c_x(d, 1);
    CHECK_CLOSE(answer(&fast, NULL, mech_vec3_make(0, 0, 1), MECH_DOPPLER_OBSERVER_FRAME).d.factor,
                (double)(1 / g), 1e-15, 0);
    CHECK_CLOSE(answer(NULL, &fast, mech_vec3_make(0, 0, 1), MECH_DOPPLER_SOURCE_FRAME).d.factor,
                (double)g, 1e-15, 0);
}

/* Light leaving a source at rest at angle θ = atan2(ty, 1) to x, seen by an
 * observer moving along x (given as β, or as 1 − β when near_c). */
static void check_aberration(double beta, int near_c, double ty, double rtol_dir)
{
    const long double b = near_c ? 1 - (long double)beta : beta, th = atan2l(ty, 1);
    const long double om = near_c ? beta : 1 - b; /* 1 − β, exact when given */
    /* γ from 1 − β itself near c (1 − (1 − δ) in long double would keep 7 digits of δ). */
    const long double g = near_c ? 1 / sqrtl(om * (2 - om)) : 1 + gamma_m1(b);
    const long double s2 = 2 * sinl(th / 2) * sinl(th / 2);
    const long double den = om * cosl(th) + s2;   /* 1 − β cos θ */
    const long double cos_p = (om - s2) / den;    /* (cos θ − β)/(1 − β cos θ) */
    const long double sin_p = sinl(th) / (g * den);
    struct mech_boost v = near_c ? near_c_x(beta, 1) : along_x(beta);
    struct mech_doppler_answer a =
        answer(NULL, &v, mech_vec3_make(1, ty, 0), MECH_DOPPLER_SOURCE_FRAME);
    CHECK_CLOSE(a.d.direction_observer.x, (double)cos_p, rtol_dir, 1e-16);
    CHECK_CLOSE(a.d.direction_observer.y, (double)sin_p, rtol_dir, 1e-16);
    CHECK_CLOSE(a.d.factor, (double)(g * den), rtol_dir, 0);
    /* Angles are unsigned, in [0, π]; α_O is measured from the source's
     * velocity in the observer's frame (−x). */
    CHECK_CLOSE(a.d.angle_source, (double)fabsl(th), 4e-16, 0);
    CHECK_CLOSE(a.d.angle_observer, (double)atan2l(fabsl(sin_p), -cos_p), 4e-16, 0);
}

static void test_aberration(void)
{
    check_aberration(0.6, 0, 1, 1e-15);
    check_aberration(0.6, 0, -3, 1e-15);
    check_aberration(0.9, 0, 0.2, 1e-15);
    /* β = 1e-9, θ = 45°: the angle moves by δ ≈ β sin θ = 7.1e-10 and D − 1 is
     * −7.1e-10 + 5e-19; both must keep their digits. */
    const long double b = 1e-9L, th = atan2l(1, 1), c = cosl(th), s = sinl(th);
    const long double one_m_inv_g = b * b / (1 + sqrtl(1 - b * b)); /* 1 − 1/γ */
    const long double delta = asinl(s * (b - c * one_m_inv_g) / (1 - b * c));
    const long double gm1 = gamma_m1(b);
    struct mech_boost v = along_x(1e-9);
    struct mech_doppler_answer a =
        answer(NULL, &v, mech_vec3_make(1, 1, 0), MECH_DOPPLER_SOURCE_FRAME);
    CHECK_CLOSE(a.d.factor_minus_one, (double)(gm1 - b * (1 + gm1) * c), 1e-15, 0);
    CHECK_CLOSE(a.d.angle_observer, (double)(PI_L - th - delta), 4e-16, 0);
    /* The aberration itself, to the precision two stored angles allow (4e-16 / 7e-10). */
    CHECK_CLOSE((MECH_PI - a.d.angle_observer) - a.d.angle_source, (double)delta, 1e-6, 0);
    check_aberration(1e-9, 0, 1, 1e-15);
    /* 1 − β = 1e-12 and θ = atan(1e-6): cos θ' = (1e-12 − 5e-13)/(1e-12 + 5e-13) ≈ 1/3. */
    check_aberration(1e-12, 1, 1e-6, 1e-13);
    check_aberration(1e-12, 1, 1, 1e-15);
    check_aberration(1e-12, 1, -1e-3, 1e-15);
}

static void test_light(void)
{
    struct mech_boost toward = along_x(-0.6);
    struct mech_doppler_request q = {.observer = &toward,
                                     .direction = mech_vec3_make(1, 0, 0),
                                     .frame = MECH_DOPPLER_SOURCE_FRAME,
                                     .light = MECH_DOPPLER_LIGHT_FREQUENCY,
                                     .light_value = 1e9};
    struct mech_doppler_answer a;
    CHECK_EQ_INT(mech_doppler_answer(&q, &a, NULL), MECH_OK); /* D = 2 */
    CHECK_EQ_INT(a.has_light, 1);
    CHECK_CLOSE(a.frequency_observed, 2e9, 4e-16, 0);
    CHECK_CLOSE(a.wavelength_emitted, 299792458.0 / 1e9, 2e-16, 0);
    CHECK_CLOSE(a.wavelength_observed, 299792458.0 / 2e9, 4e-16, 0);
    CHECK_CLOSE(a.frequency_shift, 1e9, 1e-15, 0);
    CHECK_CLOSE(a.wavelength_shift, -299792458.0 / 2e9, 1e-15, 0);
    CHECK(strcmp(mech_doppler_shift_name(a.shift), "blue") == 0);
    q.light = MECH_DOPPLER_LIGHT_WAVELENGTH;
    q.light_value = 656.28e-9; /* H-alpha */
    CHECK_EQ_INT(mech_doppler_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.wavelength_observed, 328.14e-9, 4e-16, 0);
    CHECK_CLOSE(a.frequency_emitted, 299792458.0 / 656.28e-9, 2e-16, 0);
    q.light = MECH_DOPPLER_LIGHT_NONE;
    CHECK_EQ_INT(mech_doppler_answer(&q, &a, NULL), MECH_OK);
    CHECK_EQ_INT(a.has_light, 0);
    CHECK(strcmp(mech_doppler_shift_name(MECH_DOPPLER_SHIFT_RED), "red") == 0);
    CHECK(strcmp(mech_doppler_shift_name(MECH_DOPPLER_SHIFT_NONE), "none") == 0);
}

static void test_errors(void)
{
    struct mech_boost s, o;
    CHECK(mech_boost_from_rapidity(350, mech_vec3_make(1, 0, 0), &s, NULL) == MECH_OK);
    CHECK(mech_boost_from_rapidity(350, mech_vec3_make(-1, 0, 0), &o, NULL) == MECH_OK);
    struct mech_doppler_request q = {.source = &s,
                                     .observer = &o,
                                     .direction = mech_vec3_make(1, 0, 0),
                                     .frame = MECH_DOPPLER_OBSERVER_FRAME,
                                     .light = MECH_DOPPLER_LIGHT_FREQUENCY,
                                     .light_value = 1e100};
    struct mech_doppler_answer a;
    struct mech_error e;
#define EXPECT(status, field)                                                                      \
    do {                                                                                           \
        mech_error_clear(&e);                                                                      \
        CHECK_EQ_INT(mech_doppler_answer(&q, &a, &e), status);                                     \
        CHECK(strcmp(e.param, field) == 0);                                                        \
        if (strcmp(e.param, field)) fprintf(stderr, "  param %s: %s\n", e.param, e.text);        \
    } while (0)
    /* D = e^{700} ≈ 1e304: 1e100 Hz overflows, the factor alone does not. */
    EXPECT(MECH_ENUMERIC, "frequency");
    q.light = MECH_DOPPLER_LIGHT_WAVELENGTH;
    q.light_value = 1e-100; /* ν = 3e108 Hz, observed ×1e304 */
    EXPECT(MECH_ENUMERIC, "wavelength");
    q.light_value = 0;
    EXPECT(MECH_ENUMERIC, "wavelength");
    q.light_value = NAN;
    EXPECT(MECH_ENUMERIC, "wavelength");
    q.light = MECH_DOPPLER_LIGHT_NONE;
    EXPECT(MECH_OK, "");
    CHECK(a.d.factor > 1e304 && isfinite(a.d.factor));
    q.direction = mech_vec3_make(0, 0, 0);
    EXPECT(MECH_EINVAL, "arrival_direction");
    q.frame = MECH_DOPPLER_SOURCE_FRAME;
    EXPECT(MECH_EINVAL, "emission_direction");
    q.direction = mech_vec3_make(INFINITY, 0, 0);
    EXPECT(MECH_EINVAL, "emission_direction");
    q.direction = mech_vec3_make(1, 0, 0);
    q.light = (enum mech_doppler_light)9;
    EXPECT(MECH_EINVAL, "");
    CHECK_EQ_INT(mech_doppler_answer(NULL, &a, NULL), MECH_EINVAL);
    q.light = MECH_DOPPLER_LIGHT_NONE;
    CHECK_EQ_INT(mech_doppler_answer(&q, NULL, NULL), MECH_EINVAL);
#undef EXPECT
}

int main(void)
{
    gsl_set_error_handler_off();
    test_longitudinal();
    test_transverse();
    test_aberration();
    test_light();
    test_errors();
    TEST_MAIN_END();
}
