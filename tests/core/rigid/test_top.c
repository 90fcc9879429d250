/* test_top.c — mech/rigid/top.h, the heavy symmetric top (notes §2.10): steady
 * precession (the quadratic's slow root and the gyroscopic approximation
 * M g h / (I3 w3)), turning points of the cubic against the measured extremes
 * of tight runs, conservation of p_phi, p_psi and E, a sleeping top above and
 * below I3^2 w3^2 = 4 I1 M g h, a top started exactly at theta = 0 (and one
 * passing through it), typed errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rigid/top.h"
#include "mech/base/constants.h"
#include "testlib.h"

enum { NS = 20001 };
static double ts[NS], th[NS], ph[NS], ps[NS], pps[NS];
static struct mech_vec3 ax[NS];
static int pole[NS];

static struct mech_top_problem gyro(void)
{
    struct mech_top_problem p;
    memset(&p, 0, sizeof p);
    p.I1 = 0.02;
    p.I3 = 0.01;
    p.mass = 1;
    p.distance = 0.1;
    p.g = 9.80665;
    p.t_end = 5;
    p.samples = NS;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    p.opt.atol = 1e-14;
    return p;
}

static void run(const struct mech_top_problem *p, struct mech_top_result *r, enum mech_status want)
{
    memset(r, 0, sizeof *r);
    r->t = ts;
    r->theta = th;
    r->phi = ph;
    r->psi = ps;
    r->phi_plus_psi = pps;
    r->axis = ax;
    r->at_pole = pole;
    struct mech_budget b = mech_budget_make(10000000, 120);
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_top_integrate(p, &b, r, &e);
    CHECK_EQ_INT(st, want);
    if (st != want) fprintf(stderr, "  %s: %s\n", e.param, e.text);
}

static void test_steady_precession(void)
{
    struct mech_top_problem p = gyro();
    const double w3 = 100, mgh = 0.980665, th0 = MECH_PI / 3, c = 0.5;
    /* slow root of I1 c x^2 - I3 w3 x + M g h = 0 */
    const double B = p.I3 * w3, slow = 2 * mgh / (B + sqrt(B * B - 4 * p.I1 * c * mgh));
    p.theta = th0;
    p.phi_dot = slow;
    p.psi_dot = w3 - slow * c;
    struct mech_top_result r;
    run(&p, &r, MECH_OK);
    CHECK_CLOSE(r.precession_slow, slow, 1e-15, 0);
    CHECK_CLOSE(r.precession_gyroscopic, mgh / B, 1e-15, 0);
    CHECK_CLOSE(r.precession_fast, B / (p.I1 * c) - slow, 1e-13, 0);
    CHECK(r.turning.steady);
    CHECK_CLOSE(r.turning.theta_min, th0, 0, 1e-15);
    CHECK_CLOSE(r.turning.theta_max, th0, 0, 1e-15);
    CHECK_CLOSE(r.theta_max_measured, th0, 0, 1e-10);
    CHECK_CLOSE(r.theta_min_measured, th0, 0, 1e-10);
    CHECK_CLOSE(r.precession_measured, slow, 1e-11, 0);
    CHECK_CLOSE(ph[NS - 1], slow * 5, 1e-11, 0);
    /* the gyroscopic approximation is 1 % off here (I1 c M g h / (I3 w3)^2 ~ 1e-2) */
    CHECK(fabs(slow / (mgh / B) - 1) < 0.02 && fabs(slow / (mgh / B) - 1) > 0.001);
    /* the symmetry axis: (sin th sin phi, -sin th cos phi, cos th) (third row of R) */
    CHECK_CLOSE(ax[NS - 1].x, sin(th0) * sin(ph[NS - 1]), 0, 1e-10);
    CHECK_CLOSE(ax[NS - 1].y, -sin(th0) * cos(ph[NS - 1]), 0, 1e-10);
    CHECK_CLOSE(ax[NS - 1].z, c, 0, 1e-10);
    CHECK(r.max_p_phi_drift < 1e-12 && r.max_p_psi_drift < 1e-13 && r.max_E_drift < 1e-12);
    printf("steady precession: slow %.15g, measured %.15g, drifts %.2g %.2g %.2g\n", slow,
           r.precession_measured, r.max_p_phi_drift, r.max_p_psi_drift, r.max_E_drift);
}

static void test_nutation(void)
{
    /* released with spin and no precession: theta_min = theta0 (the top dips) */
    struct mech_top_problem p = gyro();
    p.theta = 0.5;
    p.psi_dot = 60;
    p.t_end = 3;
    struct mech_top_result r;
    run(&p, &r, MECH_OK);
    CHECK(!r.turning.steady);
    CHECK_CLOSE(r.turning.theta_min, 0.5, 0, 1e-15);
    CHECK(r.turning.theta_max > 0.5);
    CHECK_CLOSE(r.theta_min_measured, r.turning.theta_min, 0, 1e-9);
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 0, 1e-7);
    CHECK(r.max_p_phi_drift < 1e-12 && r.max_p_psi_drift < 1e-13 && r.max_E_drift < 1e-12);
    printf("nutation: cubic [%.12g, %.12g], measured [%.12g, %.12g]\n", r.turning.theta_min,
           r.turning.theta_max, r.theta_min_measured, r.theta_max_measured);
    /* a general start: theta' != 0 and phi' != 0, both turning points from the cubic */
    p.theta = 1.0;
    p.theta_dot = 2.0;
    p.phi_dot = 3.0;
    p.psi_dot = 40;
    run(&p, &r, MECH_OK);
    CHECK(r.turning.theta_min < 1.0 && r.turning.theta_max > 1.0);
    CHECK_CLOSE(r.theta_min_measured, r.turning.theta_min, 0, 1e-7);
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 0, 1e-7);
    CHECK(r.max_p_phi_drift < 1e-12 && r.max_p_psi_drift < 1e-13 && r.max_E_drift < 1e-12);
    printf("general: cubic [%.12g, %.12g], measured [%.12g, %.12g]\n", r.turning.theta_min,
           r.turning.theta_max, r.theta_min_measured, r.theta_max_measured);
    /* hanging top (theta > pi/2) */
    p.theta = 2.5;
    run(&p, &r, MECH_OK);
    CHECK_CLOSE(r.theta_min_measured, r.turning.theta_min, 0, 1e-7);
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 0, 1e-7);
}

/* The nutation period and the precession averaged over a nutation (elliptic
 * integrals) against a tight integration run over exactly one period: theta
 * comes back to theta0, reaches theta_max at half the period, and phi advances
 * by precession_mean times the period. */
static void test_nutation_period(void)
{
    const double starts[][4] = {{0.5, 0, 0, 60}, {1.0, 2.0, 3.0, 40}, {2.5, 2.0, 3.0, 40},
                                {0.8, 0, -4, 25}, {0.3, 0, 0, 8}};
    for (int i = 0; i < 5; i++) {
        struct mech_top_problem p = gyro();
        p.theta = starts[i][0];
        p.theta_dot = starts[i][1];
        p.phi_dot = starts[i][2];
        p.psi_dot = starts[i][3];
        struct mech_top_turning tp;
        struct mech_error e;
        mech_error_clear(&e);
        CHECK(mech_top_turning_points(&p, &tp, &e) == MECH_OK);
        CHECK(isfinite(tp.nutation_period) && tp.nutation_period > 0);
        p.t_end = tp.nutation_period;
        struct mech_top_result r;
        run(&p, &r, MECH_OK);
        CHECK_CLOSE(th[NS - 1], p.theta, 0, 1e-9);
        CHECK_CLOSE(ph[NS - 1] - ph[0], tp.precession_mean * tp.nutation_period, 1e-9, 1e-12);
        if (p.theta_dot == 0) /* released at a turning point: half-way is the other one */
            CHECK_CLOSE(th[(NS - 1) / 2],
                        fabs(th[0] - tp.theta_min) < 1e-12 ? tp.theta_max : tp.theta_min, 0,
                        1e-9);
        printf("nutation period %.15g s, mean precession %.15g rad/s, measured %.15g\n",
               tp.nutation_period, tp.precession_mean, (ph[NS - 1] - ph[0]) / p.t_end);
    }
    /* steady precession: the mean is the steady rate; the period is that of a small
     * nutation about it, against a slightly disturbed run's theta returning */
    struct mech_top_problem p = gyro();
    const double w3 = 100, mgh = 0.980665, th0 = MECH_PI / 3, c = 0.5;
    const double B = p.I3 * w3, slow = 2 * mgh / (B + sqrt(B * B - 4 * p.I1 * c * mgh));
    p.theta = th0;
    p.phi_dot = slow;
    p.psi_dot = w3 - slow * c;
    struct mech_top_turning tp, tq;
    struct mech_error e;
    CHECK(mech_top_turning_points(&p, &tp, &e) == MECH_OK);
    CHECK(tp.steady);
    CHECK_CLOSE(tp.precession_mean, slow, 1e-12, 0);
    p.phi_dot = slow * (1 + 1e-6);
    CHECK(mech_top_turning_points(&p, &tq, &e) == MECH_OK);
    CHECK(!tq.steady);
    CHECK_CLOSE(tq.nutation_period, tp.nutation_period, 1e-5, 0);
    /* no gravity torque (g = 0): the free symmetric top's axis circles L at
     * |L|/I1, so theta's period is 2 pi I1/|L| */
    p = gyro();
    p.g = 0;
    p.theta = 0.7;
    p.theta_dot = 1.5;
    p.phi_dot = 2;
    p.psi_dot = 9;
    CHECK(mech_top_turning_points(&p, &tp, &e) == MECH_OK);
    double s0 = sin(p.theta), w3f = p.phi_dot * cos(p.theta) + p.psi_dot;
    double wp2 = p.theta_dot * p.theta_dot + p.phi_dot * p.phi_dot * s0 * s0;
    double L = sqrt(p.I1 * p.I1 * wp2 + p.I3 * p.I3 * w3f * w3f);
    CHECK_CLOSE(tp.nutation_period, 2 * MECH_PI * p.I1 / L, 1e-14, 0);
    p.t_end = tp.nutation_period;
    struct mech_top_result r;
    run(&p, &r, MECH_OK);
    CHECK_CLOSE(th[NS - 1], p.theta, 0, 1e-9);
    CHECK_CLOSE(ph[NS - 1] - ph[0], tp.precession_mean * tp.nutation_period, 1e-9, 1e-12);
}

static void test_sleeping(void)
{
    struct mech_top_problem p = gyro();
    /* critical spin 2 sqrt(I1 M g h) / I3 = 2 sqrt(0.0196133) / 0.01 = 28.0094... */
    const double crit = 2 * sqrt(0.02 * 0.980665) / 0.01;
    p.theta = 1e-3;
    p.psi_dot = 1.2 * crit;
    p.t_end = 10;
    struct mech_top_result r;
    run(&p, &r, MECH_OK);
    CHECK_CLOSE(r.critical_omega3, crit, 1e-15, 0);
    CHECK(r.sleep_stable);
    CHECK_CLOSE(r.sleep_lhs, 0.01 * 0.01 * (1.2 * crit) * (1.2 * crit), 1e-14, 0);
    CHECK_CLOSE(r.sleep_rhs, 4 * 0.02 * 0.980665, 1e-15, 0);
    CHECK(r.theta_max_measured < 0.01); /* stays up */
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 1e-6, 0);
    printf("sleeping above: theta_max cubic %.12g measured %.12g\n", r.turning.theta_max,
           r.theta_max_measured);
    p.psi_dot = 0.8 * crit;
    run(&p, &r, MECH_OK);
    CHECK(!r.sleep_stable);
    CHECK(r.turning.theta_max > 1.0); /* falls: cos theta_max ~ a^2 / beta - 1 = 2 (0.64) - 1 */
    CHECK_CLOSE(cos(r.turning.theta_max), 2 * 0.64 - 1, 1e-3, 0);
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 0, 1e-6);
    printf("sleeping below: theta_max cubic %.12g measured %.12g\n", r.turning.theta_max,
           r.theta_max_measured);

    /* exactly at theta = 0: the equilibrium is kept exactly, phi + psi advances at w3 */
    p.theta = 0;
    p.phi = 0.3;
    p.psi = 0.2;
    p.phi_dot = 5;
    p.psi_dot = 0.8 * crit;
    p.samples = 101;
    run(&p, &r, MECH_OK);
    CHECK(r.turning.steady);
    CHECK(r.theta_max_measured == 0);
    CHECK(pole[0] && pole[100]);
    CHECK(th[100] == 0);
    CHECK_CLOSE(pps[100], 0.5 + (5 + 0.8 * crit) * 10, 1e-12, 0);
    CHECK_CLOSE(ps[100], 0.2, 0, 1e-15); /* documented branch: psi kept */
    CHECK(ax[100].x == 0 && ax[100].y == 0 && ax[100].z == 1);
    /* passing through theta = 0: theta' = 1 from the pole, then back through it */
    p.theta_dot = 1;
    p.phi_dot = 0;
    p.samples = NS;
    p.t_end = 2; /* sampling error of the extremes <= theta'' dt^2 / 8 ~ 1e-7 */
    run(&p, &r, MECH_OK);
    CHECK_CLOSE(r.turning.theta_min, 0, 0, 1e-15);
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 0, 1e-7);
    CHECK(r.max_E_drift < 1e-12 && r.max_p_phi_drift < 1e-12);
    printf("through the pole: theta_max cubic %.12g measured %.12g, min measured %.3g\n",
           r.turning.theta_max, r.theta_max_measured, r.theta_min_measured);
}

static void test_errors(void)
{
    struct mech_top_problem p = gyro();
    struct mech_top_result r;
    memset(&r, 0, sizeof r);
    p.I3 = 0.05;
    struct mech_error e;
    struct mech_budget b = mech_budget_make(1000, 60);
    mech_error_clear(&e);
    CHECK(mech_top_integrate(&p, &b, &r, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "I3"));
    p = gyro();
    p.I1 = 0.005; /* < M h^2 = 0.01 */
    p.I3 = 0.005;
    mech_error_clear(&e);
    CHECK(mech_top_integrate(&p, &b, &r, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "I1"));
    p = gyro();
    p.method = "yoshida4";
    mech_error_clear(&e);
    CHECK(mech_top_integrate(&p, &b, &r, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "integrator/method"));
    p = gyro();
    p.psi_dot = 100;
    p.t_end = 1000;
    mech_error_clear(&e);
    CHECK(mech_top_integrate(&p, &b, &r, &e) == MECH_EBUDGET);
    /* no gravity: a torque-free symmetric top; the cubic degenerates to a quadratic */
    p = gyro();
    p.g = 0;
    p.theta = 0.7;
    p.theta_dot = 0.5;
    p.psi_dot = 30;
    p.samples = NS;
    p.t_end = 2;
    run(&p, &r, MECH_OK);
    CHECK_CLOSE(r.theta_min_measured, r.turning.theta_min, 0, 1e-7);
    CHECK_CLOSE(r.theta_max_measured, r.turning.theta_max, 0, 1e-7);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_steady_precession();
    test_nutation();
    test_nutation_period();
    test_sleeping();
    test_errors();
    TEST_MAIN_END();
}
