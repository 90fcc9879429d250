/* test_interval.c — the interval of two events (core/relativity/interval.c) against an
 * exact binary128 evaluation of the binary inputs (products of doubles are
 * exact in __float128), the notes' muon (§3.4) and length contraction, the
 * example frames (boosting Δ with them makes Δct' or Δx' vanish), far events
 * with tiny intervals, and the kinds at the light cone. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

#include "mech/relativity/interval.h"
#include "mech/base/constants.h"
#include "testlib.h"

static double worst_s2;

static double exact_s2(const double a[4], const double b[4])
{
    __float128 s = 0;
    for (int i = 0; i < 4; i++) {
        __float128 d = (__float128)b[i] - (__float128)a[i]; /* exact: ≤ 2 × 53 bits */
        s += (i == 0 ? -1 : 1) * d * d;
    }
    return (double)s;
}

static void check_s2(const double a[4], const double b[4], double rtol)
{
    struct mech_interval iv;
    CHECK_EQ_INT(mech_interval_compute(a, b, &iv, NULL), MECH_OK);
    double want = exact_s2(a, b);
    CHECK_CLOSE(iv.s2, want, rtol, 0);
    if (want != 0) worst_s2 = fmax(worst_s2, fabs(iv.s2 - want) / fabs(want));
}

static void test_muon(void)
{
    /* Notes §3.4: τ = 2 µs, β = 0.9999: production (0) and decay (γcτ, βγcτ)
     * in the earth frame; the proper time is τ, the co-moving frame has β. */
    const double c = MECH_C, ctau = c * 2e-6, b = 0.9999;
    const double g = 1 / sqrt((1 - b) * (1 + b));
    double e1[4] = {0, 0, 0, 0}, e2[4] = {g * ctau, b * g * ctau, 0, 0};
    struct mech_interval iv;
    CHECK_EQ_INT(mech_interval_compute(e1, e2, &iv, NULL), MECH_OK);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_TIMELIKE);
    /* The inputs carry γ's rounding: each coordinate ≈ 4.2e4 m off by up to
     * half an ulp moves s² by ~4e-7 m² (1e-12 relative). The computed s² is
     * within the input_error the answer reports of the true −(cτ)². */
    CHECK(fabs(iv.s2 + ctau * ctau) <= iv.input_error);
    CHECK(iv.input_error < 5e-12 * ctau * ctau);
    CHECK_CLOSE(iv.proper / c, 2e-6, 1e-12, 0);
    CHECK(!iv.time_order_reversible);
    CHECK(iv.has_frame);
    CHECK_CLOSE(iv.frame.beta_vec.x, b, 1e-14, 0);
    CHECK_CLOSE(iv.frame.gamma, g, 1e-12, 0);
    check_s2(e1, e2, 2e-16);
    /* Boosting Δ into that frame leaves Δx' = 0 (to round-off of Δct'). */
    double out[4];
    CHECK_EQ_INT(mech_boost_apply(&iv.frame, iv.delta, out, NULL, NULL, NULL), MECH_OK);
    CHECK_CLOSE(out[1], 0, 0, 1e-15 * e2[0] * g);
    CHECK_CLOSE(out[0], ctau, 1e-12, 0);
}

static void test_length_contraction(void)
{
    /* A stick of rest length 1 m along x, measured at t' = 0 in a frame moving
     * at 0.6c: its far end at t' = 0 is the event (ct, x) = (βl, l); the
     * interval is spacelike with proper length l/γ = 0.8 m, and the frame that
     * makes the two events simultaneous moves with β = Δct/Δx = 0.6. */
    double e1[4] = {0, 0, 0, 0}, e2[4] = {0.6, 1, 0, 0};
    struct mech_interval iv;
    CHECK_EQ_INT(mech_interval_compute(e1, e2, &iv, NULL), MECH_OK);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_SPACELIKE);
    CHECK_CLOSE(iv.proper, 0.8, 2e-16, 0);
    CHECK(iv.time_order_reversible);
    CHECK_CLOSE(iv.frame.beta_vec.x, 0.6, 2e-16, 0);
    CHECK_CLOSE(iv.frame.gamma, 1.25, 4e-16, 0);
    double out[4];
    CHECK_EQ_INT(mech_boost_apply(&iv.frame, iv.delta, out, NULL, NULL, NULL), MECH_OK);
    CHECK_CLOSE(out[0], 0, 0, 1e-16);
    CHECK_CLOSE(out[1], 0.8, 4e-16, 0);
}

static void test_far_tiny(void)
{
    /* Far from the origin, nearly light-like: Δ = (5 + δ, 3, 4, 0) at 1e8 m.
     * The naive s² of rounded differences would be off; this one matches the
     * exact binary128 value of the same binary inputs. */
    double e1[4] = {1e8, 3e7, 4e7, -2e7};
    double e2[4] = {1e8 + 5.000001, 3e7 + 3, 4e7 + 4, -2e7};
    check_s2(e1, e2, 1e-15);
    struct mech_interval iv;
    mech_interval_compute(e1, e2, &iv, NULL);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_TIMELIKE);
    CHECK(iv.input_error > 0 && iv.input_error < 1e-6);
    /* Random far pairs at 1e12 with |s²| down to 1e-10 of the scale. */
    unsigned s = 99;
    for (int k = 0; k < 2000; k++) {
        double a[4], b[4];
        for (int i = 0; i < 4; i++) {
            s = s * 1103515245u + 12345u;
            a[i] = 1e12 * (((s >> 8) & 0xffff) / 65536.0 - 0.5);
        }
        double dx[3], r = 0;
        for (int i = 0; i < 3; i++) {
            s = s * 1103515245u + 12345u;
            dx[i] = ((s >> 8) & 0xffff) / 65536.0 - 0.5;
            r += dx[i] * dx[i];
        }
        r = sqrt(r);
        s = s * 1103515245u + 12345u;
        double rel = (((s >> 8) & 0xffff) / 65536.0 - 0.5) * 2e-6;
        b[0] = a[0] + r * (1 + rel);
        for (int i = 0; i < 3; i++)
            b[i + 1] = a[i + 1] + dx[i];
        check_s2(a, b, 1e-14);
    }
}

static void test_kinds(void)
{
    struct mech_interval iv;
    double o[4] = {0, 0, 0, 0};
    double l[4] = {1, 1, 0, 0};
    CHECK_EQ_INT(mech_interval_compute(o, l, &iv, NULL), MECH_OK);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_LIGHTLIKE);
    CHECK(iv.s2 == 0 && iv.proper == 0 && !iv.has_frame && !iv.time_order_reversible);
    /* Light-like within the inputs' rounding: 0.3 and (0.1, 0.2, 0.2) in
     * decimal are exactly light-like; their doubles are not quite. */
    double d[4] = {0.3, 0.1, 0.2, 0.2};
    CHECK_EQ_INT(mech_interval_compute(o, d, &iv, NULL), MECH_OK);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_LIGHTLIKE);
    CHECK(fabs(iv.s2) <= iv.tolerance);
    CHECK(iv.s2 != 0);
    /* Just off the cone by 1e-10 relative: not light-like. */
    double t[4] = {1 + 1e-10, 1, 0, 0};
    CHECK_EQ_INT(mech_interval_compute(o, t, &iv, NULL), MECH_OK);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_TIMELIKE);
    CHECK_CLOSE(iv.s2, exact_s2(o, t), 1e-15, 0);
    /* Its co-moving frame is at β = 1/(1 + 1e-10): 1 − β from s², not from a
     * difference. */
    CHECK_CLOSE(iv.frame.one_minus_beta, (t[0] - 1) / t[0], 1e-15, 0); /* t0 − 1 exact */
    /* Time order reversed (Δct < 0): the frame still moves with Δx/Δct. */
    double p[4] = {-2, 1, 0, 0};
    CHECK_EQ_INT(mech_interval_compute(o, p, &iv, NULL), MECH_OK);
    CHECK_EQ_INT(iv.kind, MECH_INTERVAL_TIMELIKE);
    CHECK_CLOSE(iv.frame.beta_vec.x, -0.5, 2e-16, 0);
    CHECK_CLOSE(iv.proper, sqrt(3.0), 2e-16, 0);
    /* Same event. */
    CHECK_EQ_INT(mech_interval_compute(p, p, &iv, NULL), MECH_OK);
    CHECK(iv.coincident && iv.kind == MECH_INTERVAL_LIGHTLIKE);
    /* Purely spatial / purely temporal: the example frame is at rest. */
    double q[4] = {0, 0, 3, 4};
    CHECK_EQ_INT(mech_interval_compute(o, q, &iv, NULL), MECH_OK);
    CHECK(iv.kind == MECH_INTERVAL_SPACELIKE && iv.proper == 5 && iv.frame.beta == 0);
    double bad[4] = {0, NAN, 0, 0};
    CHECK_EQ_INT(mech_interval_compute(o, bad, &iv, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_muon();
    test_length_contraction();
    test_far_tiny();
    test_kinds();
    printf("worst relative s2 error vs exact binary128: %.3g\n", worst_s2);
    TEST_MAIN_END();
}
