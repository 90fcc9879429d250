/* test_doppler.c — relativistic Doppler factor and aberration (core/relativity/doppler.c)
 * against closed forms (notes §3.14, the twin paradox's 1/3 and 3), the
 * identities approaching × receding = 1 and tan(α_S/2) tan(α_O/2) = e^{−η},
 * an independent long-double computation through explicit 4-vector boosts
 * (which also checks the Wigner rotation of directions), and the extremes
 * β = 1e-12 and γ = 1e15. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/relativity/doppler.h"
#include "testlib.h"

static struct mech_boost beta_boost(double x, double y, double z)
{
    struct mech_boost b;
    CHECK(mech_boost_from_beta(mech_vec3_make(x, y, z), &b, NULL) == MECH_OK);
    return b;
}

static struct mech_doppler run(const struct mech_boost *s, const struct mech_boost *o,
                               struct mech_vec3 dir, enum mech_doppler_frame f)
{
    struct mech_doppler d;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_doppler_compute(s, o, dir, f, &d, &e);
    CHECK(st == MECH_OK);
    if (st != MECH_OK) fprintf(stderr, "  error: %s\n", e.text);
    return d;
}

/* Passive boost of a 4-vector into the frame moving with velocity b
 * (long double, straight from notes §3.3: x0' = γ(x0 − β·x),
 * x' = x + [(γ − 1)(β̂·x) − γ|β| x0] β̂). */
static void ld_boost(const long double b[3], const long double x[4], long double out[4])
{
    long double b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    if (b2 == 0) {
        for (int i = 0; i < 4; i++)
            out[i] = x[i];
        return;
    }
    long double bn = sqrtl(b2), g = 1.0L / sqrtl(1.0L - b2);
    long double n[3] = {b[0] / bn, b[1] / bn, b[2] / bn};
    long double xp = n[0] * x[1] + n[1] * x[2] + n[2] * x[3];
    long double x0 = g * (x[0] - bn * xp);
    long double k = (g - 1) * xp - g * bn * x[0];
    out[0] = x0;
    for (int i = 0; i < 3; i++)
        out[i + 1] = x[i + 1] + k * n[i];
}

/* Reference Doppler factor and the other frame's direction through the lab. */
static long double ld_doppler(const double bs[3], const double bo[3], struct mech_vec3 dir,
                              int in_source, long double other_dir[3])
{
    long double bf[3], bg[3], mbf[3];
    for (int i = 0; i < 3; i++) {
        bf[i] = in_source ? bs[i] : bo[i];
        bg[i] = in_source ? bo[i] : bs[i];
        mbf[i] = -bf[i];
    }
    long double dn =
        sqrtl((long double)dir.x * dir.x + (long double)dir.y * dir.y + (long double)dir.z * dir.z);
    long double k[4] = {1, dir.x / dn, dir.y / dn, dir.z / dn}, lab[4], g[4];
    ld_boost(mbf, k, lab);
    ld_boost(bg, lab, g);
    for (int i = 0; i < 3; i++)
        other_dir[i] = g[i + 1] / g[0];
    return in_source ? g[0] : 1.0L / g[0];
}

static void check_against_reference(double sx, double sy, double sz, double ox, double oy,
                                    double oz, struct mech_vec3 dir, int in_source, double tol)
{
    struct mech_boost s = beta_boost(sx, sy, sz), o = beta_boost(ox, oy, oz);
    const double bs[3] = {sx, sy, sz}, bo[3] = {ox, oy, oz};
    long double od[3];
    long double ref = ld_doppler(bs, bo, dir, in_source, od);
    struct mech_doppler d =
        run(&s, &o, dir, in_source ? MECH_DOPPLER_SOURCE_FRAME : MECH_DOPPLER_OBSERVER_FRAME);
    CHECK_CLOSE(d.factor, (double)ref, tol, 0);
    CHECK_CLOSE(d.factor_minus_one, (double)(ref - 1.0L), tol, tol * 1e-16);
    struct mech_vec3 other = in_source ? d.direction_observer : d.direction_source;
    CHECK_CLOSE(other.x, (double)od[0], 0, tol);
    CHECK_CLOSE(other.y, (double)od[1], 0, tol);
    CHECK_CLOSE(other.z, (double)od[2], 0, tol);
    /* Aberration identity between the two reported angles. */
    CHECK_CLOSE(tan(0.5 * d.angle_source) * tan(0.5 * d.angle_observer), exp(-d.rapidity), tol, 0);
    /* Round trip: the other frame's direction, given back, returns D and the
     * original direction. */
    struct mech_doppler back =
        run(&s, &o, other, in_source ? MECH_DOPPLER_OBSERVER_FRAME : MECH_DOPPLER_SOURCE_FRAME);
    CHECK_CLOSE(back.factor, d.factor, tol, 0);
    struct mech_vec3 again = in_source ? back.direction_source : back.direction_observer;
    double dl = mech_vec3_norm(dir);
    CHECK_CLOSE(again.x, dir.x / dl, 0, tol);
    CHECK_CLOSE(again.y, dir.y / dl, 0, tol);
    CHECK_CLOSE(again.z, dir.z / dl, 0, tol);
}

int main(void)
{
    gsl_set_error_handler_off();
    const struct mech_vec3 ex = mech_vec3_make(1, 0, 0), ey = mech_vec3_make(0, 1, 0);
    const struct mech_vec3 mex = mech_vec3_make(-1, 0, 0);

    /* Notes §3.14 / twin paradox: β = 0.8 along the line of flight gives
     * sqrt((1 − β)/(1 + β)) = 1/3 receding and 3 approaching. The reference
     * values are for the double nearest 0.8 (Python Decimal, 40 digits). */
    {
        struct mech_boost o = beta_boost(0.8, 0, 0);
        struct mech_doppler rec = run(NULL, &o, ex, MECH_DOPPLER_SOURCE_FRAME);
        struct mech_doppler app = run(NULL, &o, mex, MECH_DOPPLER_SOURCE_FRAME);
        CHECK_EQ_INT(rec.kind, MECH_DOPPLER_LONGITUDINAL_RECEDING);
        CHECK_EQ_INT(app.kind, MECH_DOPPLER_LONGITUDINAL_APPROACHING);
        CHECK_CLOSE(rec.factor, 0.3333333333333332922139620509201266107357, 3e-16, 0);
        CHECK_CLOSE(app.factor, 3.000000000000000370074341541718826, 3e-16, 0);
        CHECK_CLOSE(rec.factor * app.factor, 1.0, 3e-16, 0);
        CHECK_CLOSE(rec.factor_minus_one, 0.3333333333333332922139620509201266107357 - 1, 3e-16, 0);
        /* Moving source instead of observer (source recedes at −0.8 along the
         * light, which runs +x): the same factors. */
        struct mech_boost s = beta_boost(-0.8, 0, 0);
        struct mech_doppler rec2 = run(&s, NULL, ex, MECH_DOPPLER_OBSERVER_FRAME);
        CHECK_EQ_INT(rec2.kind, MECH_DOPPLER_LONGITUDINAL_RECEDING);
        CHECK_CLOSE(rec2.factor, rec.factor, 3e-16, 0);
        CHECK(strcmp(mech_doppler_case_name(rec2.kind), "longitudinal_receding") == 0);
    }

    /* Longitudinal: D = e^{∓η} exactly via rapidity, and approaching × receding
     * = 1, for η from 1e-12 to 35 (γ = 8e14). */
    {
        const double etas[] = {1e-12, 1e-6, 0.5, 3, 17.6, 35};
        for (size_t i = 0; i < sizeof etas / sizeof etas[0]; i++) {
            struct mech_boost o;
            CHECK(mech_boost_from_rapidity(etas[i], mech_vec3_make(0, 0, 2), &o, NULL) == MECH_OK);
            struct mech_doppler rec =
                run(NULL, &o, mech_vec3_make(0, 0, 1), MECH_DOPPLER_SOURCE_FRAME);
            struct mech_doppler app =
                run(NULL, &o, mech_vec3_make(0, 0, -3), MECH_DOPPLER_OBSERVER_FRAME);
            CHECK_EQ_INT(rec.kind, MECH_DOPPLER_LONGITUDINAL_RECEDING);
            CHECK_EQ_INT(app.kind, MECH_DOPPLER_LONGITUDINAL_APPROACHING);
            CHECK_CLOSE(rec.factor, exp(-etas[i]), 4e-16, 0);
            CHECK_CLOSE(app.factor, exp(etas[i]), 4e-16, 0);
            CHECK_CLOSE(rec.factor * app.factor, 1.0, 6e-16, 0);
            CHECK_CLOSE(rec.factor_minus_one, expm1(-etas[i]), 4e-16, 0);
            CHECK_CLOSE(app.factor_minus_one, expm1(etas[i]), 4e-16, 0);
            CHECK_CLOSE(rec.rapidity, etas[i], 2e-16, 0);
        }
    }

    /* Transverse: light perpendicular to the motion in the source frame is
     * blue-shifted by γ; perpendicular in the observer frame, red-shifted by
     * 1/γ (notes §3.14: ν' = ν/γ); and each angle maps to cos(other) = β. */
    {
        const double gammas[] = {1.0000001, 1.25, 7, 1e6, 1e15};
        for (size_t i = 0; i < sizeof gammas / sizeof gammas[0]; i++) {
            struct mech_boost o;
            CHECK(mech_boost_from_gamma(gammas[i], ex, &o, NULL) == MECH_OK);
            struct mech_doppler ts = run(NULL, &o, ey, MECH_DOPPLER_SOURCE_FRAME);
            struct mech_doppler to = run(NULL, &o, ey, MECH_DOPPLER_OBSERVER_FRAME);
            CHECK_EQ_INT(ts.kind, MECH_DOPPLER_TRANSVERSE_SOURCE_FRAME);
            CHECK_EQ_INT(to.kind, MECH_DOPPLER_TRANSVERSE_OBSERVER_FRAME);
            CHECK_CLOSE(ts.factor, gammas[i], 2e-16, 0);
            CHECK_CLOSE(to.factor, 1.0 / gammas[i], 2.3e-16, 0);
            CHECK_CLOSE(ts.factor_minus_one, gammas[i] - 1.0, 2e-16, 0);
            CHECK_CLOSE(to.factor_minus_one, -(gammas[i] - 1.0) / gammas[i], 4e-16, 0);
            /* Aberration of 90°: cos of the angle in the other frame is β. */
            /* (cos of a reported angle near 90° carries the angle's rounding,
             * ~2e-16 absolute; the direction vectors carry cos exactly.) */
            CHECK_CLOSE(cos(ts.angle_observer), o.beta, 4e-16, 4e-16);
            CHECK_CLOSE(cos(to.angle_source), o.beta, 4e-16, 4e-16);
            CHECK_CLOSE(to.direction_source.x, o.beta, 4e-16, 0);
            CHECK_CLOSE(to.direction_source.y, 1.0 / gammas[i], 4e-16, 0);
            /* π − α_O = angle from the observer's own velocity; near 0 at large γ it
             * is 1/γ (sin α_O = 1/γ), which acos(β) could not resolve. */
            CHECK_CLOSE(sin(ts.angle_observer), 1.0 / gammas[i], 4e-16, 0);
            CHECK_CLOSE(ts.direction_observer.x, -o.beta, 4e-16, 0);
            CHECK_CLOSE(ts.direction_observer.y, 1.0 / gammas[i], 4e-16, 0);
        }
    }

    /* 1 m/s-like speeds: β = 1e-12 from a decimal β. D − 1 ≈ ∓β + β²/2 keeps
     * full relative precision; the transverse shift γ − 1 = β²/2 too. */
    {
        const double b = 1e-12;
        struct mech_boost o = beta_boost(b, 0, 0);
        const double eta = atanh(b);
        struct mech_doppler rec = run(NULL, &o, ex, MECH_DOPPLER_SOURCE_FRAME);
        struct mech_doppler app = run(NULL, &o, mex, MECH_DOPPLER_SOURCE_FRAME);
        struct mech_doppler ts = run(NULL, &o, ey, MECH_DOPPLER_SOURCE_FRAME);
        struct mech_doppler to = run(NULL, &o, ey, MECH_DOPPLER_OBSERVER_FRAME);
        CHECK_CLOSE(rec.factor_minus_one, expm1(-eta), 1e-15, 0);
        CHECK_CLOSE(app.factor_minus_one, expm1(eta), 1e-15, 0);
        CHECK_CLOSE(ts.factor_minus_one, 0.5 * b * b, 1e-15, 0); /* + O(β⁴) */
        CHECK_CLOSE(to.factor_minus_one, -0.5 * b * b, 1e-15, 0);
        /* 45° in the source frame: D − 1 = γ − 1 − βγ/√2. */
        struct mech_doppler g45 = run(NULL, &o, mech_vec3_make(1, 1, 0), MECH_DOPPLER_SOURCE_FRAME);
        CHECK_CLOSE(g45.factor_minus_one, 0.5 * b * b - b / sqrt(2.0), 1e-15, 0);
        CHECK_EQ_INT(g45.kind, MECH_DOPPLER_GENERAL);
    }

    /* γ = 1e15 given precisely: receding D = 1/(γ + βγ) (a value near 5e-16
     * that a 1 − β·cos form would return as 0 or garbage), approaching γ + βγ. */
    {
        struct mech_boost o;
        CHECK(mech_boost_from_gamma(1e15, mech_vec3_make(0, 3, 4), &o, NULL) == MECH_OK);
        const double bg = sqrt(1e30 - 1); /* correctly rounded: 1e15 to 16 digits */
        struct mech_doppler rec = run(NULL, &o, mech_vec3_make(0, 3, 4), MECH_DOPPLER_SOURCE_FRAME);
        struct mech_doppler app =
            run(NULL, &o, mech_vec3_make(0, -3, -4), MECH_DOPPLER_SOURCE_FRAME);
        CHECK_CLOSE(rec.factor, 1.0 / (1e15 + bg), 1e-15, 0);
        CHECK_CLOSE(app.factor, 1e15 + bg, 1e-15, 0);
        CHECK_CLOSE(rec.factor * app.factor, 1.0, 1e-15, 0);
        CHECK_CLOSE(rec.one_minus_beta, 1.0 / (1e15 * (1e15 + bg)), 1e-15, 0);
        /* A light ray 1e-15 rad off the line of flight (exactly representable
         * as a direction [1, 1e-15, 0] with the boost along x): D = e^{−η} +
         * 2βγ sin²(α/2), here about (1 + γ²α²) e^{−η} = 2 e^{−η}. */
        struct mech_boost ox;
        CHECK(mech_boost_from_gamma(1e15, ex, &ox, NULL) == MECH_OK);
        struct mech_doppler off =
            run(NULL, &ox, mech_vec3_make(1, 1e-15, 0), MECH_DOPPLER_SOURCE_FRAME);
        const double a = atan(1e-15);
        CHECK_CLOSE(off.factor, 1.0 / (1e15 + bg) + 2 * bg * sin(a / 2) * sin(a / 2), 1e-15, 0);
    }

    /* Two moving frames, collinear at high γ: η_s = 17, η_o = 17.5 along x;
     * the relative rapidity 0.5 is recovered from the light-cone components
     * (not from 1 − β_s β_o, which would lose ~γ² ε). */
    {
        struct mech_boost s, o;
        CHECK(mech_boost_from_rapidity(17, ex, &s, NULL) == MECH_OK);
        CHECK(mech_boost_from_rapidity(17.5, ex, &o, NULL) == MECH_OK);
        struct mech_doppler rec = run(&s, &o, ex, MECH_DOPPLER_SOURCE_FRAME);
        CHECK_EQ_INT(rec.kind, MECH_DOPPLER_LONGITUDINAL_RECEDING);
        CHECK_CLOSE(rec.factor, exp(-0.5), 2e-14, 0);
        CHECK_CLOSE(rec.rapidity, 0.5, 4e-14, 0);
        CHECK_CLOSE(rec.gamma_minus_one, cosh(0.5) - 1, 4e-14, 0);
        CHECK_CLOSE(rec.observer_beta_in_source.x, tanh(0.5), 4e-14, 0);
        CHECK_CLOSE(rec.source_beta_in_observer.x, -tanh(0.5), 4e-14, 0);
        /* Equal velocities: one frame, D = 1 exactly. */
        struct mech_doppler same = run(&s, &s, ey, MECH_DOPPLER_SOURCE_FRAME);
        CHECK_EQ_INT(same.kind, MECH_DOPPLER_NO_RELATIVE_MOTION);
        CHECK(same.factor == 1.0 && same.factor_minus_one == 0.0);
        CHECK(isnan(same.angle_source));
        struct mech_doppler rest = run(NULL, NULL, ey, MECH_DOPPLER_OBSERVER_FRAME);
        CHECK_EQ_INT(rest.kind, MECH_DOPPLER_NO_RELATIVE_MOTION);
        CHECK(rest.direction_source.y == 1.0);
    }

    /* General geometry against the long-double 4-vector computation through
     * the lab, including non-collinear source and observer velocities (the
     * directions then differ by the Wigner rotation between the frames). */
    check_against_reference(0, 0, 0, 0.6, 0, 0, mech_vec3_make(1, 2, 0), 1, 3e-15);
    check_against_reference(0.3, -0.2, 0.1, 0, 0, 0, mech_vec3_make(-1, 0.5, 2), 0, 3e-15);
    check_against_reference(0.5, 0, 0, 0, 0.7, 0, mech_vec3_make(1, 1, 1), 1, 5e-15);
    check_against_reference(0.5, 0, 0, 0, 0.7, 0, mech_vec3_make(-0.3, 1, 0.2), 0, 5e-15);
    check_against_reference(0.9, 0.1, 0, -0.2, 0.8, 0.3, mech_vec3_make(0.1, -1, 0.4), 1, 2e-14);
    check_against_reference(0.9, 0.1, 0, -0.2, 0.8, 0.3, mech_vec3_make(0.1, -1, 0.4), 0, 2e-14);
    check_against_reference(0.99, 0, 0, 0.95, 0.05, 0, mech_vec3_make(0, 0, 1), 1, 5e-14);
    check_against_reference(0.6, 0, 0, 0.6, 0, 0.000001, mech_vec3_make(1, 0, 1), 1, 1e-9);

    /* Invalid direction: typed error naming it. */
    {
        struct mech_doppler d;
        struct mech_error e;
        mech_error_clear(&e);
        CHECK(mech_doppler_compute(NULL, NULL, mech_vec3_make(0, 0, 0), MECH_DOPPLER_SOURCE_FRAME,
                                   &d, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "direction") == 0);
        CHECK(mech_doppler_compute(NULL, NULL, mech_vec3_make(NAN, 0, 1), MECH_DOPPLER_SOURCE_FRAME,
                                   &d, NULL) == MECH_EINVAL);
    }

    /* Rapidity 350 each way, opposite directions: relative rapidity 700 is
     * e^{700} ≈ 1e304, still finite. */
    {
        struct mech_boost s, o;
        CHECK(mech_boost_from_rapidity(350, ex, &s, NULL) == MECH_OK);
        CHECK(mech_boost_from_rapidity(-350, ex, &o, NULL) == MECH_OK);
        struct mech_doppler d = run(&s, &o, ex, MECH_DOPPLER_SOURCE_FRAME);
        CHECK_EQ_INT(d.kind, MECH_DOPPLER_LONGITUDINAL_APPROACHING);
        CHECK_CLOSE(log(d.factor), 700, 1e-14, 0);
    }
    TEST_MAIN_END();
}
