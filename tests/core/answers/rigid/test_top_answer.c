/* test_top_answer.c — mech/answers/rigid/top_answer.h and mech_top_closed_forms (notes
 * §2.10-2.11), against closed forms derived here:
 *  - steady precession: the roots of I1 cos(th) x^2 - I3 w3 x + M g h = 0,
 *    Omega+- = (I3 w3 +- sqrt(I3^2 w3^2 - 4 I1 M g h cos th)) / (2 I1 cos th),
 *    checked by Vieta (sum B / (I1 c), product M g h / (I1 c)) and, at fast
 *    spins where the textbook "-" root cancels, against the Catalan series
 *    Omega- = (M g h / B) sum_n C_n e^n, e = I1 c M g h / B^2 (from
 *    (1 - sqrt(1 - 4e)) / (2e) = sum C_n e^n); the textbook form is shown to
 *    lose >= 1e-8 there, so the check can fail;
 *  - the sleeping top's critical spin 2 sqrt(I1 M g h) / I3;
 *  - a run: E, p_phi, p_psi at t = 0 from the Lagrangian's expressions, E
 *    conserved to 1e-11, the lower turning point of a top released with
 *    theta' = phi' = 0 from the quadratic beta u^2 - a^2 u + a^2 u0 - beta = 0
 *    (f(u) = (u0 - u)[beta (1 - u^2) - a^2 (u0 - u)]), every sample inside
 *    the turning points, the axis (sin th sin phi, -sin th cos phi, cos th);
 *  - omega at t = 0 from Goldstein (4.87) and its space form;
 *  - typed errors (samples, I3 > 2 I1, budget, overflow) and a freeable
 *    answer on every path. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/rigid/top_answer.h"
#include "testlib.h"

#define MGH (1.0 * 9.80665 * 0.1)

static struct mech_top_problem base(void)
{
    struct mech_top_problem p;
    memset(&p, 0, sizeof p);
    p.I1 = 0.02;
    p.I3 = 0.01;
    p.mass = 1;
    p.distance = 0.1;
    p.g = 9.80665;
    p.theta = 0.5;
    p.psi_dot = 60;
    p.t_end = 2;
    p.samples = 201;
    p.method = "rk8pd";
    p.opt.rtol = 1e-13;
    p.opt.atol = 1e-13;
    return p;
}

static struct mech_top_result closed(const struct mech_top_problem *p)
{
    struct mech_top_result r;
    memset(&r, 0, sizeof r);
    mech_top_closed_forms(p, &r);
    return r;
}

/* theta0 = pi/3 (cos = 1/2), w3 = 100: both roots against Vieta's relations
 * and the textbook formula evaluated in long double (no cancellation to
 * speak of at this spin: e ~ 1e-2). */
static void test_precession_ordinary(void)
{
    struct mech_top_problem p = base();
    p.theta = MECH_PI / 3;
    p.psi_dot = 100; /* phi' = 0: w3 = psi' */
    const double c = cos(p.theta), B = p.I3 * 100;
    struct mech_top_result r = closed(&p);
    const long double d = sqrtl((long double)B * B - 4.0L * p.I1 * c * MGH);
    CHECK_CLOSE(r.precession_fast, (double)((B + d) / (2.0L * p.I1 * c)), 1e-14, 0);
    CHECK_CLOSE(r.precession_slow, (double)((B - d) / (2.0L * p.I1 * c)), 1e-12, 0);
    CHECK_CLOSE(r.precession_slow + r.precession_fast, B / (p.I1 * c), 1e-15, 0);
    CHECK_CLOSE(r.precession_slow * r.precession_fast, MGH / (p.I1 * c), 1e-15, 0);
    CHECK_CLOSE(r.precession_gyroscopic, MGH / B, 1e-15, 0);
    /* a negative spin turns both rates over */
    p.psi_dot = -100;
    struct mech_top_result n = closed(&p);
    CHECK_CLOSE(n.precession_slow, -r.precession_slow, 1e-15, 0);
    CHECK_CLOSE(n.precession_fast, -r.precession_fast, 1e-15, 0);
}

/* Fast spins: w3 = 1e6 (the API's largest psi') and 1e9, where
 * B - sqrt(B^2 - 4x) keeps ~6 digits and ~1; the slow root must still match
 * the series to 1e-15. */
static void test_precession_fast_spin(void)
{
    const double spins[2] = {1e6, 1e9};
    for (int k = 0; k < 2; k++) {
        struct mech_top_problem p = base();
        p.theta = MECH_PI / 3;
        p.psi_dot = spins[k];
        const double c = cos(p.theta), B = p.I3 * spins[k];
        const double e = p.I1 * c * MGH / (B * B); /* ~1e-10, ~1e-16 */
        const double series = MGH / B * (1 + e * (1 + e * (2 + e * (5 + 14 * e))));
        struct mech_top_result r = closed(&p);
        CHECK_CLOSE(r.precession_slow, series, 1e-15, 0);
        CHECK_CLOSE(r.precession_fast, B / (p.I1 * c) - series, 1e-15, 0);
        CHECK_CLOSE(r.precession_slow * r.precession_fast, MGH / (p.I1 * c), 1e-15, 0);
        /* the textbook "-" root loses the digits the check above demands */
        const double naive = (B - sqrt(B * B - 4 * p.I1 * c * MGH)) / (2 * p.I1 * c);
        CHECK(!(fabs(naive - series) <= 1e-8 * series));
    }
}

/* A hanging top (theta0 = 2 pi / 3, cos = -1/2): the roots have opposite
 * signs; with no spin they are +-sqrt(M g h / (I1 |cos|)) (a conical
 * pendulum); too slow an upright spin has no steady precession at all. */
static void test_precession_other_branches(void)
{
    struct mech_top_problem p = base();
    p.theta = 2 * MECH_PI / 3;
    p.psi_dot = 50;
    const double c = cos(p.theta), B = p.I3 * 50;
    struct mech_top_result r = closed(&p);
    CHECK(r.precession_slow * r.precession_fast < 0);
    CHECK_CLOSE(r.precession_slow * r.precession_fast, MGH / (p.I1 * c), 1e-15, 0);
    CHECK_CLOSE(r.precession_slow + r.precession_fast, B / (p.I1 * c), 1e-14, 0);
    CHECK(fabs(r.precession_slow) < fabs(r.precession_fast));
    p.psi_dot = 0;
    r = closed(&p);
    const double cone = sqrt(MGH / (p.I1 * 0.5));
    CHECK_CLOSE(fabs(r.precession_slow), cone, 1e-15, 0);
    CHECK_CLOSE(fabs(r.precession_fast), cone, 1e-15, 0);
    CHECK(isnan(r.precession_gyroscopic));
    /* upright, w3 = 1: B^2 = 1e-4 < 4 I1 M g h cos(0.5) ~ 0.069 */
    p = base();
    p.psi_dot = 1;
    r = closed(&p);
    CHECK(isnan(r.precession_slow) && isnan(r.precession_fast));
    CHECK_CLOSE(r.precession_gyroscopic, MGH / 0.01, 1e-15, 0);
}

/* Sleeping top (notes §2.11 problem 11): stable iff I3^2 w3^2 > 4 I1 M g h. */
static void test_sleeping(void)
{
    struct mech_top_problem p = base();
    p.theta = 0;
    const double crit = 2 * sqrt(0.02 * MGH) / 0.01; /* 28.01 rad/s */
    p.psi_dot = crit * (1 + 1e-9);
    struct mech_top_result r = closed(&p);
    CHECK_CLOSE(r.critical_omega3, crit, 1e-15, 0);
    CHECK_CLOSE(r.sleep_rhs, 4 * 0.02 * MGH, 1e-15, 0);
    CHECK(r.sleep_stable);
    p.psi_dot = crit * (1 - 1e-9);
    CHECK(!closed(&p).sleep_stable);
}

static void run(const struct mech_top_problem *p, struct mech_top_answer *a, long max_steps,
                enum mech_status want, struct mech_error *e)
{
    struct mech_budget b = mech_budget_make(max_steps, 120);
    mech_error_clear(e);
    enum mech_status st = mech_top_answer_run(p, &b, a, e);
    CHECK_EQ_INT(st, want);
    if (st != want) fprintf(stderr, "  %s: %s\n", e->param, e->text);
}

/* The catalog's top (theta0 = 0.5, w3 = 60, released with theta' = phi' = 0):
 * it falls from theta0 (the upper turning point) to the lower one and back. */
static void test_run_conserves(void)
{
    struct mech_top_problem p = base();
    struct mech_top_answer a;
    struct mech_error e;
    run(&p, &a, 10000000, MECH_OK, &e);
    const struct mech_top_result *r = &a.r;
    CHECK_EQ_INT(r->n_samples, 201);
    const double u0 = cos(0.5), w3 = 60;
    /* E = I3 w3^2 / 2 + M g h cos theta0; p_psi = I3 w3; p_phi = I3 w3 cos theta0 */
    CHECK_CLOSE(r->E0, 0.5 * 0.01 * w3 * w3 + MGH * u0, 1e-15, 0);
    CHECK_CLOSE(r->p_psi0, 0.01 * w3, 1e-15, 0);
    CHECK_CLOSE(r->p_phi0, 0.01 * w3 * u0, 1e-15, 0);
    CHECK_CLOSE(r->E_final, r->E0, 1e-11, 0);
    CHECK(r->max_E_drift < 1e-11 && r->max_p_phi_drift < 1e-11 && r->max_p_psi_drift < 1e-11);
    /* the lower turning point: beta u^2 - a^2 u + (a^2 u0 - beta) = 0,
     * a = I3 w3 / I1, beta = 2 M g h / I1; the root below u0 in the
     * cancellation-free form 2 (a^2 u0 - beta) / (a^2 + sqrt(disc)) */
    const double a2 = pow(0.01 * w3 / 0.02, 2), beta = 2 * MGH / 0.02;
    const double u1 = 2 * (a2 * u0 - beta) / (a2 + sqrt(a2 * a2 - 4 * beta * (a2 * u0 - beta)));
    CHECK_CLOSE(r->turning.theta_min, 0.5, 0, 1e-15);
    CHECK_CLOSE(r->turning.theta_max, acos(u1), 0, 1e-12);
    CHECK(!r->turning.steady);
    CHECK_CLOSE(r->theta_max_measured, acos(u1), 0, 1e-6); /* reached, seen at step ends */
    int inside = 1, on_axis = 1;
    for (size_t i = 0; i < r->n_samples; i++) {
        const double th = r->theta[i], ph = r->phi[i];
        inside &= th >= 0.5 - 1e-9 && th <= acos(u1) + 1e-9;
        on_axis &= fabs(r->axis[i].x - sin(th) * sin(ph)) < 1e-12 &&
                   fabs(r->axis[i].y + sin(th) * cos(ph)) < 1e-12 &&
                   fabs(r->axis[i].z - cos(th)) < 1e-12;
        CHECK_CLOSE(r->t[i], 0.01 * (double)i, 1e-14, 1e-15);
        CHECK_CLOSE(r->phi_plus_psi[i], r->phi[i] + r->psi[i], 1e-15, 1e-15);
    }
    CHECK(inside);
    CHECK(on_axis);
    /* phi' starts at 0, so the top starts with no body rate about axes 1, 2 */
    CHECK(a.has_initial_omega);
    CHECK_CLOSE(a.initial_omega_magnitude, w3, 1e-15, 0);
    mech_top_answer_free(&a);
    mech_top_answer_free(&a);
}

/* omega at t = 0 (notes §2.7, Goldstein (4.87)) for arbitrary angles and rates. */
static void test_initial_omega(void)
{
    struct mech_top_problem p = base();
    p.phi = 0.3, p.theta = 0.5, p.psi = 0.2;
    p.phi_dot = 1.5, p.theta_dot = -0.7, p.psi_dot = 40;
    p.t_end = 0.05;
    p.samples = 3;
    struct mech_top_answer a;
    struct mech_error e;
    run(&p, &a, 10000000, MECH_OK, &e);
    const double sf = sin(p.phi), cf = cos(p.phi), st = sin(p.theta), ct = cos(p.theta);
    const double sp = sin(p.psi), cp = cos(p.psi);
    const struct mech_vec3 wb = a.initial_omega_body, ws = a.initial_omega_space;
    CHECK_CLOSE(wb.x, p.phi_dot * st * sp + p.theta_dot * cp, 1e-14, 1e-15);
    CHECK_CLOSE(wb.y, p.phi_dot * st * cp - p.theta_dot * sp, 1e-14, 1e-15);
    CHECK_CLOSE(wb.z, p.phi_dot * ct + p.psi_dot, 1e-15, 0);
    CHECK_CLOSE(ws.x, p.theta_dot * cf + p.psi_dot * st * sf, 1e-14, 1e-15);
    CHECK_CLOSE(ws.y, p.theta_dot * sf - p.psi_dot * st * cf, 1e-14, 1e-15);
    CHECK_CLOSE(ws.z, p.phi_dot + p.psi_dot * ct, 1e-15, 0);
    CHECK_CLOSE(a.initial_omega_magnitude, mech_vec3_norm(ws), 1e-15, 0);
    CHECK_CLOSE(a.r.omega3, wb.z, 1e-15, 0);
    mech_top_answer_free(&a);
}

static void test_errors(void)
{
    struct mech_top_answer a;
    struct mech_error e;
    struct mech_top_problem p = base();
    p.samples = 1; /* no arrays allocated; the core names the field */
    run(&p, &a, 1000, MECH_EINVAL, &e);
    CHECK(!strcmp(e.param, "samples"));
    CHECK(a.r.t == NULL && a.r.axis == NULL);
    mech_top_answer_free(&a);
    p = base();
    p.I3 = 0.05; /* > 2 I1: no body has these moments */
    run(&p, &a, 1000, MECH_EDOMAIN, &e);
    CHECK(!strcmp(e.param, "I3"));
    mech_top_answer_free(&a);
    p = base();
    p.t_end = 1000;
    run(&p, &a, 100, MECH_EBUDGET, &e);
    CHECK_CLOSE(e.progress.t_target, 1000, 0, 0);
    CHECK(e.progress.t_reached > 0 && e.progress.t_reached < 1000);
    mech_top_answer_free(&a);
    /* I3^2 w3^2 = 1e400 overflows: a typed error, not an inf in the answer */
    p = base();
    p.I1 = p.I3 = 1e200;
    p.psi_dot = 1e6;
    p.t_end = 1e-5;
    p.samples = 3;
    run(&p, &a, 10000000, MECH_ENUMERIC, &e);
    mech_top_answer_free(&a);
    CHECK_EQ_INT(mech_top_answer_run(&p, NULL, NULL, NULL), MECH_EINVAL);
    mech_top_answer_free(NULL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_precession_ordinary();
    test_precession_fast_spin();
    test_precession_other_branches();
    test_sleeping();
    test_run_conserves();
    test_initial_omega();
    test_errors();
    TEST_MAIN_END();
}
