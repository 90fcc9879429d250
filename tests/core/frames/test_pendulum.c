/* test_pendulum.c — mech_foucault_integrate (the Foucault pendulum, full
 * nonlinear, rotating Earth frame) against closed forms and an independent
 * method:
 *   the planar period 4 sqrt(l/g) K(sin(alpha/2)) against K(1/sqrt2) and the
 *   series 1 + a^2/16 + 11 a^4/3072;
 *   the same trajectory from rk8pd (the driver) on the index-reduced ODE
 *   u'' = F - 2 W x u' + mu u, mu = -(|u'|^2 + u.(F - 2 W x u'))/l^2, to 1e-6 m;
 *   the precession at the pole, 45 deg N and S, 32 deg (the notes' latitude)
 *   against -W sin(lat) + Airy's (3/8) h / l^2, to the next order in the
 *   amplitude (alpha^2/4 of the Airy term);
 *   a FULL precession at 45 deg (l = 67 m, 7418 swings) with the centrifugal
 *   term: the rate, and the Airy term's growth by the anisotropy against the
 *   closed form h0 (1 + cot^2(lat)/8 (1 + 3/(4 pi^2)));
 *   the equator (exactly no precession: the motion stays in the x-z plane);
 *   the spherical pendulum's Airy precession alone (W = 0, elliptic release);
 *   energy and constraint drift; extremes (l = 1 mm, l = 1000 km, W = 1 rad/s,
 *   amplitude 1e-6 deg, 80 deg); every error status.
 */
#include <gsl/gsl_errno.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "mech/ode/ode.h"
#include "mech/base/constants.h"
#include "mech/frames/pendulum.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

static const double G0 = 9.80665;
static const double WE = MECH_EARTH_OMEGA; /* the one Earth rate (constants.h) */

static struct mech_foucault_problem base(double lat, double amp_deg, double swings, long sps)
{
    struct mech_foucault_problem p;
    memset(&p, 0, sizeof p);
    p.length = 67.0;
    p.g = G0;
    p.latitude_deg = lat;
    p.omega_magnitude = WE;
    p.mass = 28.0;
    p.amplitude_deg = amp_deg;
    p.method = MECH_PENDULUM_RATTLE_YOSHIDA4;
    p.t_end = swings * mech_pendulum_period(p.length, p.g, amp_deg * MECH_PI / 180.0);
    p.steps = (long)ceil(swings * (double)sps);
    return p;
}

static enum mech_status run(const struct mech_foucault_problem *p, struct mech_foucault_result *r)
{
    struct mech_budget b = mech_budget_make(100000000, 600.0);
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_foucault_integrate(p, &b, r, &e);
    if (st != MECH_OK) fprintf(stderr, "run: %s (%s)\n", e.text, e.param);
    return st;
}

/* |measured - expected| <= next order in the amplitude and in (W/omega0)^2
 * (the Airy term assumes the oscillator frequency omega0; a rotating frame
 * without centrifugal adds W^2 to omega0^2) + 3 standard errors */
static void check_rate(const struct mech_foucault_problem *p, const struct mech_foucault_result *r)
{
    double alpha = p->amplitude_deg * MECH_PI / 180.0;
    double expected = -r->omega_vertical + r->airy_rate_mean;
    double w2 = p->omega_magnitude * p->omega_magnitude / (r->omega0 * r->omega0);
    /* plus the round-off of the measurement itself: the plane's angle is read
     * from positions of size a = l sin(alpha) that carry round-off ~eps l, so
     * it is uncertain by ~eps l / a, and the slope by that over the run. At an
     * amplitude of 1e-6 deg (a = 1.2 um) the Airy term (~1e-17 W) and the
     * fit's standard error are far below this, and without it the tolerance
     * (2e-28 rad/s) was below even the 7e-21 spacing of doubles near W sin(lat) */
    double roundoff = DBL_EPSILON * p->length / (p->length * sin(alpha)) / p->t_end;
    double tol = fabs(r->airy_rate_mean) * (alpha * alpha / 4.0 + w2) +
                 3.0 * r->precession.stderr_slope + roundoff;
    CHECK_CLOSE(r->precession.slope, expected, 0.0, tol);
    /* and the brief's form: |measured - W sin(lat)| <= Airy correction + tolerance */
    CHECK(fabs(r->precession.slope + r->omega_vertical) <= fabs(r->airy_rate_mean) + tol);
    /* the Airy correction is really there: removing it misses by far more than tol */
    if (fabs(r->airy_rate_mean) > 100.0 * tol)
        CHECK(fabs(r->precession.slope + r->omega_vertical) > 50.0 * tol);
}

static void test_period(void)
{
    double l = 2.0, g = 9.0, T0 = 2.0 * MECH_PI * sqrt(l / g);
    CHECK_CLOSE(mech_pendulum_period(l, g, 0.0), T0, 1e-15, 0);
    /* K(1/sqrt 2) = Gamma(1/4)^2 / (4 sqrt(pi)) = 1.8540746773013719 (A & S 17.3) */
    CHECK_CLOSE(mech_pendulum_period(l, g, MECH_PI / 2.0), 4.0 * sqrt(l / g) * 1.8540746773013719, 1e-14,
                0);
    double a = 0.01;
    CHECK_CLOSE(mech_pendulum_period(l, g, a),
                T0 * (1.0 + a * a / 16.0 + 11.0 * pow(a, 4) / 3072.0), 1e-14, 0);

    /* The correction T/T0 - 1 = 2K(k)/pi - 1 against an independent
     * method: the series sum_{n>=1} ((2n-1)!!/(2n)!!)^2 k^(2n) (A & S 17.3.11) of positive
     * terms, in long double, k = sin(alpha/2). T/T0 - 1 in doubles was off by 1.8e-5
     * relative at alpha = 1e-5 rad, 5.8e-10 at 1e-3, 4.8e-13 at 0.05. */
    static const double alphas[] = {1e-8, 1e-5, 1e-3, 0.05, 0.3, 1.0, MECH_PI / 2.0, 3.0};
    for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
        const long double k = sinl(0.5L * alphas[i]), k2 = k * k;
        long double c = 1.0L, pw = 1.0L, sum = 0.0L;
        for (int n = 1; n < 100000; n++) {
            c *= ((2.0L * n - 1) / (2.0L * n)) * ((2.0L * n - 1) / (2.0L * n));
            pw *= k2;
            sum += c * pw;
            if (c * pw < 1e-22L * sum) break;
        }
        CHECK_CLOSE(mech_pendulum_period_correction(alphas[i]), (double)sum, 1e-14, 0);
    }
    /* closed forms: alpha^2/16 + 11 alpha^4/3072 at 1e-8; 2K(1/sqrt 2)/pi - 1 at pi/2 */
    CHECK_CLOSE(mech_pendulum_period_correction(1e-8), 1e-16 / 16.0, 1e-15, 0);
    CHECK_CLOSE(mech_pendulum_period_correction(MECH_PI / 2.0), 2.0 * 1.8540746773013719 / MECH_PI - 1.0,
                1e-14, 0);
    CHECK(mech_pendulum_period_correction(0.0) == 0.0);
}

/* ---- the independent method: rk8pd on the index-reduced ODE ---- */
struct ir {
    struct mech_vec3 W;
    double l, g;
    int centrifugal;
};

static enum mech_status ir_rhs(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const struct ir *P = params;
    struct mech_vec3 u = {y[0], y[1], y[2]}, v = {y[3], y[4], y[5]};
    struct mech_vec3 F = {0.0, 0.0, -P->g};
    if (P->centrifugal) {
        struct mech_vec3 r = {u.x, u.y, u.z + P->l};
        F = mech_vec3_sub(F, mech_vec3_cross(P->W, mech_vec3_cross(P->W, r)));
    }
    F = mech_vec3_sub(F, mech_vec3_scale(mech_vec3_cross(P->W, v), 2.0));
    double mu = -(mech_vec3_dot(v, v) + mech_vec3_dot(u, F)) / mech_vec3_dot(u, u);
    struct mech_vec3 a = mech_vec3_add(F, mech_vec3_scale(u, mu));
    dy[0] = v.x;
    dy[1] = v.y;
    dy[2] = v.z;
    dy[3] = a.x;
    dy[4] = a.y;
    dy[5] = a.z;
    return MECH_OK;
}

static void test_against_rk8pd(void)
{
    struct mech_foucault_problem p = base(45.0, 10.0, 20.0, 1000);
    p.centrifugal = 1;
    p.omega_magnitude = 1e-2; /* a fast Earth makes every term visible in 20 swings */
    p.azimuth_deg = 30.0;
    p.transverse_velocity = 0.05;
    struct mech_foucault_result r;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);

    double lat = 45.0 * MECH_PI / 180.0, al = 10.0 * MECH_PI / 180.0, az = 30.0 * MECH_PI / 180.0;
    struct ir P = {{0.0, p.omega_magnitude * cos(lat), p.omega_magnitude * sin(lat)}, 67.0, G0, 1};
    double y0[6] = {67.0 * sin(al) * cos(az), 67.0 * sin(al) * sin(az), -67.0 * cos(al),
                    -0.05 * sin(az),          0.05 * cos(az),           0.0};
    struct mech_ode_system sys = {6, ir_rhs, NULL, 0, &P, NULL, 0, NULL};
    double sy[2 * 6];
    struct mech_ode_problem op;
    memset(&op, 0, sizeof op);
    op.sys = &sys;
    op.method = mech_ode_method_find("rk8pd");
    op.opt.rtol = 1e-13;
    op.opt.atol = 1e-13;
    op.t0 = 0.0;
    op.t_end = p.t_end;
    op.y0 = y0;
    op.n_samples = 2;
    op.sample_y = sy;
    struct mech_ode_result orr;
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&op, &b, &orr, &e), MECH_OK);
    const double *yf = sy + 6;
    CHECK_CLOSE(r.final_position.x, yf[0], 0, 1e-6);
    CHECK_CLOSE(r.final_position.y, yf[1], 0, 1e-6);
    CHECK_CLOSE(r.final_position.z, 67.0 + yf[2], 0, 1e-6);
    CHECK_CLOSE(r.final_velocity.x, yf[3], 0, 1e-6);
    CHECK_CLOSE(r.final_velocity.y, yf[4], 0, 1e-6);
    CHECK_CLOSE(r.final_velocity.z, yf[5], 0, 1e-6);
    CHECK(r.max_constraint_error < 1e-14);
    CHECK(r.max_relative_energy_drift < 1e-9);

    /* order 2 RATTLE agrees too, with its larger error (h^2) */
    p.method = MECH_PENDULUM_RATTLE;
    p.steps *= 4;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK_CLOSE(r.final_position.x, yf[0], 0, 1e-3);
    CHECK_CLOSE(r.final_position.y, yf[1], 0, 1e-3);
}

static void test_latitudes(void)
{
    struct mech_foucault_result r;
    /* pole: W vertical, h exactly conserved, the rate is the leading order */
    struct mech_foucault_problem p = base(90.0, 3.0, 200.0, 200);
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK_CLOSE(r.omega_vertical, WE, 1e-15, 0);
    double a = 67.0 * sin(3.0 * MECH_PI / 180.0);
    CHECK_CLOSE(r.airy_rate, 0.375 * WE * a * a / (67.0 * 67.0), 1e-13, 0);
    CHECK_CLOSE(r.airy_rate_mean, r.airy_rate, 1e-6, 0);
    check_rate(&p, &r);
    CHECK_CLOSE(r.period, r.finite_amplitude_period, 2e-7, 0);
    CHECK_CLOSE(r.swings, 200.0, 1e-6, 0);
    CHECK_EQ_INT(r.turning_points, 400);
    /* minor axis of the rosette: b = a W / omega0 (released from rest) */
    CHECK_CLOSE(r.mean_pericentre, a * WE / sqrt(G0 / 67.0), 2e-3, 0);
    CHECK(r.max_relative_energy_drift < 1e-6);
    CHECK(r.max_constraint_error < 1e-14);

    /* 45 N and 45 S: opposite senses, both to the Airy correction */
    p = base(45.0, 3.0, 200.0, 200);
    p.centrifugal = 1;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK(r.precession.slope < 0);
    check_rate(&p, &r);
    double north = r.precession.slope;
    p.latitude_deg = -45.0;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK(r.precession.slope > 0);
    check_rate(&p, &r);
    CHECK_CLOSE(r.precession.slope, -north, 1e-5, 0);

    /* the notes' latitude (32 deg, chapter 1's examples): W sin(lat) */
    p = base(32.0, 3.0, 200.0, 200);
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK_CLOSE(r.omega_vertical, WE * sin(32.0 * MECH_PI / 180.0), 1e-15, 0);
    check_rate(&p, &r);

    /* equator, release east: W = (0, W, 0) keeps the motion in the x-z plane
     * exactly (every force and the Cayley rotation have no y part) */
    p = base(0.0, 3.0, 50.0, 200);
    p.centrifugal = 1;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK(r.precession.slope == 0.0);
    CHECK(r.final_position.y == 0.0);
    CHECK_CLOSE(r.period, r.finite_amplitude_period, 2e-7, 0);
}

/* A full precession at 45 deg: 7418 swings of the 67 m pendulum. */
static void test_full_precession(void)
{
    double lat = 45.0 * MECH_PI / 180.0, wz = WE * sin(lat);
    struct mech_foucault_problem p = base(45.0, 3.0, 1.0, 100);
    p.centrifugal = 1;
    p.t_end = 2.0 * MECH_PI / wz;
    p.steps = (long)ceil(100.0 * p.t_end / mech_pendulum_period(67.0, G0, 3.0 * MECH_PI / 180.0));
    struct mech_foucault_result r;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK(r.swings > 7410.0 && r.swings < 7425.0); /* 2 pi / (W sin 45) / T = 7418 */
    check_rate(&p, &r);
    /* the centrifugal anisotropy raises h by (cot^2(lat)/8) h0 on average
     * over the precession (release east, psi0 = 0), and the least-squares
     * slope over exactly one turn adds 3/(4 pi^2) of that (core/frames/pendulum.c) */
    double cot2 = 1.0 / (tan(lat) * tan(lat));
    CHECK_CLOSE(r.airy_rate_mean, r.airy_rate * (1.0 + cot2 / 8.0 * (1.0 + 3.0 / (4.0 * MECH_PI * MECH_PI))),
                2e-3, 0);
    CHECK(r.max_relative_energy_drift < 1e-5);
    CHECK(r.max_constraint_error < 1e-14);

    /* without the centrifugal term h stays h0 */
    p.centrifugal = 0;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    check_rate(&p, &r);
    CHECK_CLOSE(r.airy_rate_mean, r.airy_rate, 1e-3, 0);
}

/* W = 0: the spherical pendulum alone; an elliptic release precesses at
 * Airy's (3/8) omega0 a b / l^2 = (3/8) a v / l^2 (h = a v). */
static void test_airy(void)
{
    struct mech_foucault_problem p = base(45.0, 5.0, 200.0, 200);
    p.omega_magnitude = 0.0;
    double a = 67.0 * sin(5.0 * MECH_PI / 180.0), w0 = sqrt(G0 / 67.0);
    p.transverse_velocity = 0.1 * a * w0; /* b = a / 10 */
    struct mech_foucault_result r;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK_CLOSE(r.airy_rate, 0.375 * a * p.transverse_velocity / (67.0 * 67.0), 1e-13, 0);
    double al = 5.0 * MECH_PI / 180.0;
    CHECK_CLOSE(r.precession.slope, r.airy_rate, al * al / 4.0, 0);
    CHECK_CLOSE(r.mean_pericentre, a / 10.0, 1e-2, 0);
}

static void test_extremes(void)
{
    struct mech_foucault_result r;
    /* l = 1 mm: omega0 = 99 rad/s, the precession still W sin(lat) */
    struct mech_foucault_problem p = base(90.0, 2.0, 100.0, 200);
    p.length = 1e-3;
    p.t_end = 100.0 * mech_pendulum_period(p.length, G0, 2.0 * MECH_PI / 180.0);
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK(r.turning_points == 200);
    CHECK_CLOSE(r.period, r.finite_amplitude_period, 2e-7, 0);
    CHECK(r.max_constraint_error < 1e-14);
    /* l = 1000 km: omega0 = 3.1e-3 rad/s, W / omega0 = 0.023; over one
     * precession (about 43 swings) */
    p = base(90.0, 0.5, 1.0, 400);
    p.length = 1e6;
    p.t_end = 2.0 * MECH_PI / WE;
    p.steps = 400 * 50;
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    check_rate(&p, &r);
    /* W = 1 rad/s, l = 1 m: W / omega0 = 0.32, the linear theory's rate is
     * still exactly -W at the pole */
    p = base(90.0, 1.0, 100.0, 400);
    p.length = 1.0;
    p.omega_magnitude = 1.0;
    p.t_end = 100.0 * mech_pendulum_period(1.0, G0, MECH_PI / 180.0);
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    check_rate(&p, &r);
    /* amplitude 1e-6 deg (6 um) and 80 deg */
    p = base(45.0, 1e-6, 100.0, 200);
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    check_rate(&p, &r);
    /* the height 2 l sin^2(alpha/2) ~ 1e-14 m is computed without cancellation */
    double ha = 0.5e-6 * MECH_PI / 180.0;
    CHECK_CLOSE(r.energy_initial, 28.0 * G0 * 2.0 * 67.0 * sin(ha) * sin(ha), 1e-13, 0);
    CHECK(r.max_relative_energy_drift < 1e-6);
    p = base(45.0, 80.0, 50.0, 400);
    CHECK_EQ_INT(run(&p, &r), MECH_OK);
    CHECK_CLOSE(r.period, r.finite_amplitude_period, 1e-6, 0);
    CHECK(r.max_constraint_error < 1e-14);
    CHECK(r.max_relative_energy_drift < 1e-6);
}

static void test_errors(void)
{
    struct mech_foucault_result r;
    struct mech_budget b = mech_budget_make(100000, 60.0);
    struct mech_error e;
    struct mech_foucault_problem p;

#define EXPECT(st_, param_)                                                                        \
    do {                                                                                           \
        mech_error_clear(&e);                                                                      \
        CHECK_EQ_INT(mech_foucault_integrate(&p, &b, &r, &e), st_);                                \
        CHECK(!strcmp(e.param, param_));                                                           \
    } while (0)

    p = base(45, 90.0, 10, 100);
    EXPECT(MECH_EDOMAIN, "release/amplitude_deg");
    p = base(45, 0.0, 10, 100);
    p.amplitude_deg = 0;
    EXPECT(MECH_EDOMAIN, "release/amplitude_deg");
    p = base(45, 3, 10, 100);
    p.length = -1;
    EXPECT(MECH_EDOMAIN, "length");
    p = base(45, 3, 10, 100);
    p.g = 0;
    EXPECT(MECH_EDOMAIN, "g");
    p = base(45, 3, 10, 100);
    p.latitude_deg = 91;
    EXPECT(MECH_EDOMAIN, "latitude_deg");
    p = base(45, 3, 10, 100);
    p.omega_magnitude = NAN;
    EXPECT(MECH_EDOMAIN, "omega_magnitude");
    p = base(45, 3, 10, 100);
    p.mass = 0;
    EXPECT(MECH_EDOMAIN, "mass");
    p = base(45, 3, 10, 100);
    p.steps = 50;
    EXPECT(MECH_EDOMAIN, "steps");
    p = base(45, 3, 10, 100);
    p.steps = 0;
    EXPECT(MECH_EINVAL, "steps");
    p = base(45, 3, 10, 100);
    p.t_end = INFINITY;
    EXPECT(MECH_EINVAL, "t_end");
    p = base(45, 3, 10, 100);
    p.transverse_velocity = 1.0;
    EXPECT(MECH_EDOMAIN, "release/transverse_velocity");
    p = base(45, 3, 10, 100);
    p.method = (enum mech_pendulum_method)7;
    EXPECT(MECH_EINVAL, "method");
    p = base(45, 3, 0.9, 100);
    EXPECT(MECH_EDOMAIN, "t_end"); /* 3 turning points needed */
    /* step budget: refused up front, with how far it would go */
    p = base(45, 3, 2000, 100);
    EXPECT(MECH_EBUDGET, "steps");
    CHECK_CLOSE(e.progress.t_reached, 100000.0 * p.t_end / (double)p.steps, 1e-12, 0);
    /* a deadline already passed */
    b = mech_budget_make(100000000, -1.0);
    p = base(45, 3, 10, 100);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_foucault_integrate(&p, &b, &r, &e), MECH_EDEADLINE);
    CHECK_EQ_INT(mech_foucault_integrate(NULL, &b, &r, NULL), MECH_EINVAL);
    CHECK(mech_pendulum_method_name(MECH_PENDULUM_RATTLE) != NULL);
    CHECK(mech_pendulum_method_name((enum mech_pendulum_method)9) == NULL);
#undef EXPECT
}

int main(void)
{
    gsl_set_error_handler_off();
    test_period();
    test_against_rk8pd();
    test_latitudes();
    test_full_precession();
    test_airy();
    test_extremes();
    test_errors();
    TEST_MAIN_END();
}
