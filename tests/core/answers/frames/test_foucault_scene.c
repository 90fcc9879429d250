/* test_foucault_scene.c — mech_foucault_scene (core/answers/frames/foucault_scene.c),
 * one /v1/scenes/foucault computation, against closed forms:
 *   the precession rate: the notes' (§1.4) -W sin(lat) at first order, and
 *     with Airy's correction for a release from rest,
 *     -W sin(lat) (1 - (3/8) sin^2 alpha), to the next order (alpha^2 / 4 of
 *     the Airy term) plus three standard errors of the fit;
 *   the period 2 pi sqrt(l/g) at a small amplitude (0.01 deg), to 1e-10
 *     with the amplitude's alpha^2 / 16 and the rotating frame's
 *     1 / sqrt(1 + (W sin lat / omega0)^2), and at 20 deg the elliptic
 *     4 sqrt(l/g) K(sin(alpha/2)) (the series to alpha^6);
 *   the run's Jacobi integral: its initial value m g l (1 - cos alpha)
 *     (released from rest, no centrifugal term) and its drift;
 *   the Richardson estimate against the period's true error (rattle at 40
 *     steps per swing: the estimate within 20 % of the true error);
 *   the chooser's steps per swing from its documented model
 *     n = ceil(2 pi (0.07 (1 + 3 alpha^2) / (target / 10))^(1/4));
 *   the auto rule: the centrifugal term in when its estimated effect exceeds
 *     target / 10; the dry run integrates nothing;
 *   every error status with the request field it names.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/frames/foucault_scene.h"
#include "testlib.h"

static const double G0 = 9.80665;
static const double WE = 7.2921159e-5; /* the notes' W, rad/s */

static struct mech_foucault_scene_request request(double lat, double amp_deg, double swings)
{
    struct mech_foucault_scene_request q;
    memset(&q, 0, sizeof q);
    q.problem.length = 67.0;
    q.problem.g = G0;
    q.problem.latitude_deg = lat;
    q.problem.omega_magnitude = WE;
    q.problem.mass = 28.0;
    q.problem.amplitude_deg = amp_deg;
    q.problem.method = MECH_PENDULUM_RATTLE_YOSHIDA4;
    q.run_by = MECH_FOUCAULT_RUN_SWINGS;
    q.run_value = swings;
    q.target = 1e-6;
    q.error_estimate = 1;
    q.auto_terms = 0; /* coriolis only: the closed forms below leave out the centrifugal term */
    q.given_coriolis = 1;
    return q;
}

static struct mech_foucault_scene scene; /* large: static */

static enum mech_status run(const struct mech_foucault_scene_request *q, struct mech_error *e)
{
    struct mech_budget b = mech_budget_make(100000000, 600.0);
    mech_error_clear(e);
    return mech_foucault_scene(q, &b, &scene, e);
}

/* The swing plane turns at -W sin(lat) (notes §1.4) corrected by Airy's
 * (3/8) sin^2(alpha) of it for a release from rest. */
static void test_precession(void)
{
    const double lats[] = {32.0, 45.0, -45.0, 90.0};
    for (int i = 0; i < 4; i++) {
        struct mech_foucault_scene_request q = request(lats[i], 3.0, 200);
        struct mech_error e;
        CHECK_EQ_INT(run(&q, &e), MECH_OK);
        const double a = 3.0 * MECH_PI / 180.0, wz = WE * sin(lats[i] * MECH_PI / 180.0);
        const double airy = (3.0 / 8.0) * sin(a) * sin(a) * wz;
        const double want = -wz + airy;
        const double tol = fabs(airy) * (a * a / 4.0) + 3.0 * scene.run.precession.stderr_slope +
                           scene.numerical_rate + 1e-12 * WE;
        CHECK_CLOSE(scene.run.precession.slope, want, 0, tol);
        /* the first order alone is off by the Airy term, which the run resolves */
        CHECK(fabs(scene.run.precession.slope + wz) > 0.5 * fabs(airy));
        CHECK_CLOSE(scene.scales.first_order_rate, -wz, 1e-15, 0);
        CHECK_CLOSE(scene.expected_rate, -wz + scene.run.airy_rate_mean, 1e-15, 0);
        CHECK(fabs(scene.run.precession.slope - scene.expected_rate) <=
              scene.tolerance_next_order + scene.tolerance_fit + scene.numerical_rate);
        CHECK_EQ_INT(scene.ran, 1);
        CHECK_EQ_INT(scene.estimate_done, 1);
    }
}

/* 2 pi sqrt(l/g) at 0.01 deg; the elliptic period at 20 deg; the Jacobi
 * integral. Seen from the rotating Earth the small swing's frequency is
 * sqrt(omega0^2 + (W sin lat)^2) (the Coriolis term splits the two circular
 * modes to omega0 +- W sin lat to first order, their mean shifts at second):
 * at 45 deg the period is 9.1e-9 shorter, four times the 0.01 deg amplitude's
 * alpha^2 / 16 = 1.9e-9, so both are in the closed form. */
static void test_period_energy(void)
{
    struct mech_foucault_scene_request q = request(45.0, 0.01, 50);
    q.target = 1e-10;
    struct mech_error e;
    CHECK_EQ_INT(run(&q, &e), MECH_OK);
    const double t0 = 2.0 * MECH_PI * sqrt(67.0 / G0);
    const double wz = WE * sin(MECH_PI / 4.0), w0sq = G0 / 67.0;
    const double a = 0.01 * MECH_PI / 180.0;
    CHECK_CLOSE(scene.run.period, t0 * (1.0 + a * a / 16.0) / sqrt(1.0 + wz * wz / w0sq), 1e-10,
                0);
    /* the notes' 2 pi sqrt(l/g), within the two terms it neglects (1.1e-8) */
    CHECK_CLOSE(scene.run.period, t0, 2e-8, 0);
    CHECK_CLOSE(scene.scales.small_amplitude_period, t0, 1e-15, 0);
    /* m g l (1 - cos a) = 2 m g l sin^2(a/2): no cancellation */
    CHECK_CLOSE(scene.run.energy_initial, 2.0 * 28.0 * G0 * 67.0 * pow(sin(a / 2.0), 2), 1e-9, 0);
    CHECK(scene.run.max_relative_energy_drift < 1e-9);

    q = request(45.0, 20.0, 50);
    CHECK_EQ_INT(run(&q, &e), MECH_OK);
    const double b = 20.0 * MECH_PI / 180.0;
    const double series = 1.0 + b * b / 16.0 + 11.0 * pow(b, 4) / 3072.0 +
                          173.0 * pow(b, 6) / 737280.0; /* next term ~ 22931 b^8 / 1321205760 */
    /* to the target asked (1e-6; the series' next term is 4e-9) */
    CHECK_CLOSE(scene.run.period, t0 * series / sqrt(1.0 + wz * wz / w0sq), 1e-6, 0);
    CHECK_CLOSE(scene.run.energy_initial, 2.0 * 28.0 * G0 * 67.0 * pow(sin(b / 2.0), 2), 1e-9, 0);
    CHECK(scene.run.max_relative_energy_drift < 1e-6);
    CHECK(scene.run.max_constraint_error < 1e-12);
}

/* Richardson: rattle (order 2) at 40 steps per swing, W = 0 (a planar
 * swing): the estimate against the true error from the elliptic period. */
static void test_richardson(void)
{
    struct mech_foucault_scene_request q = request(45.0, 10.0, 40);
    q.problem.omega_magnitude = 0.0;
    q.given_coriolis = 0;
    q.explicit_integrator = 1;
    q.problem.method = MECH_PENDULUM_RATTLE;
    q.steps_per_swing = 40;
    struct mech_error e;
    CHECK_EQ_INT(run(&q, &e), MECH_OK);
    CHECK_EQ_INT(scene.order, 2);
    CHECK_EQ_INT(scene.chosen, 0);
    CHECK_EQ_INT(scene.problem.steps, 1600);
    const double truth = fabs(scene.run.period - scene.scales.period);
    CHECK(truth > 1e-6 * scene.scales.period); /* resolvable: far above round-off */
    /* asymptotic at 40 steps per swing: the estimate within 20 % of the truth */
    CHECK(scene.numerical_period > 0.8 * truth && scene.numerical_period < 1.25 * truth);
    CHECK_CLOSE(scene.achieved, scene.numerical_period / scene.run.period, 1e-15, 0);
}

/* The chooser's model, the auto rule, the dry run. */
static void test_choice(void)
{
    struct mech_foucault_scene_request q = request(32.0, 3.0, 200);
    q.auto_terms = 1;
    q.target_defaulted = 1;
    q.dry_run = 1;
    struct mech_error e;
    CHECK_EQ_INT(run(&q, &e), MECH_OK);
    const double a = 3.0 * MECH_PI / 180.0;
    const double n = ceil(2.0 * MECH_PI * pow(0.07 * (1.0 + 3.0 * a * a) / 1e-7, 0.25));
    CHECK_EQ_INT(scene.chosen, 1);
    CHECK_EQ_INT((int)scene.steps_per_swing, (int)n);
    CHECK_EQ_INT(scene.problem.method, MECH_PENDULUM_RATTLE_YOSHIDA4);
    CHECK_EQ_INT(scene.problem.steps, (long)ceil(200.0 * n));
    CHECK(strncmp(scene.reason, "target_error 1e-6 by default: ", 30) == 0);
    CHECK_EQ_INT(scene.ran, 0);
    CHECK_EQ_INT((int)scene.run.steps, 0);
    /* auto: the centrifugal effect at 32 deg, W^2 cos^2(lat) / (4 omega0) / W ~ 4e-5 of
       the rate, is above target / 10 = 1e-7: in; at target 1e-3: out */
    const double c2 = pow(cos(32.0 * MECH_PI / 180.0), 2), w0 = sqrt(G0 / 67.0);
    CHECK(scene.centrifugal.relative_rate >= WE * c2 / (4.0 * w0));
    CHECK_EQ_INT(scene.problem.centrifugal, 1);
    q.target = 1e-3;
    CHECK_EQ_INT(run(&q, &e), MECH_OK);
    CHECK_EQ_INT(scene.problem.centrifugal, 0);
    /* the run's length by precessions: one turn at W sin(lat) */
    q.run_by = MECH_FOUCAULT_RUN_PRECESSIONS;
    q.run_value = 1.0;
    CHECK_EQ_INT(run(&q, &e), MECH_OK);
    CHECK_CLOSE(scene.problem.t_end, 2.0 * MECH_PI / (WE * sin(32.0 * MECH_PI / 180.0)), 1e-15,
                0);
}

#define EXPECT(q, st, field)                                                          \
    do {                                                                              \
        struct mech_error e_;                                                         \
        CHECK_EQ_INT(run(&(q), &e_), (st));                                           \
        CHECK(strcmp(e_.param, (field)) == 0);                                          \
        CHECK(e_.text[0] != '\0');                                                    \
    } while (0)

static void test_errors(void)
{
    struct mech_foucault_scene_request q = request(0.0, 3.0, 100);
    q.run_by = MECH_FOUCAULT_RUN_PRECESSIONS;
    q.run_value = 1.0;
    EXPECT(q, MECH_EDOMAIN, "precessions"); /* no precession at the equator */
    q = request(45.0, 3.0, 1.5);
    EXPECT(q, MECH_EDOMAIN, "swings"); /* fewer than 2 swings */
    q = request(45.0, 3.0, 100);
    q.run_by = MECH_FOUCAULT_RUN_DURATION;
    q.run_value = 20.0; /* ~1.2 swings of 16.4 s */
    EXPECT(q, MECH_EDOMAIN, "duration");
    q.run_value = NAN;
    EXPECT(q, MECH_EINVAL, "duration");
    q = request(45.0, 3.0, 100);
    q.given_coriolis = 0;
    EXPECT(q, MECH_EDOMAIN, "fictitious");
    q = request(45.0, 3.0, 100);
    q.explicit_integrator = 1;
    q.steps_per_swing = 2; /* a step of half a period: the core's "steps" */
    EXPECT(q, MECH_EDOMAIN, "integrator/steps_per_swing");
    q.steps_per_swing = 0.5;
    EXPECT(q, MECH_EINVAL, "integrator/steps_per_swing");
    q = request(45.0, 3.0, 1e6);
    q.explicit_integrator = 1;
    q.steps_per_swing = 1e7;
    EXPECT(q, MECH_EDOMAIN, "swings"); /* 1e13 steps */
    q = request(45.0, 3.0, 100);
    q.target = 0.5;
    EXPECT(q, MECH_EINVAL, "target_error"); /* the chooser's range */
    q = request(45.0, 3.0, 100);
    q.problem.length = -1.0;
    EXPECT(q, MECH_EDOMAIN, "");
    q = request(45.0, 3.0, 100);
    q.problem.mass = 0.0; /* not in the scales: the run names it */
    EXPECT(q, MECH_EDOMAIN, "mass");

    /* the step budget: the answer's run refused; the estimate skipped */
    q = request(45.0, 3.0, 100);
    struct mech_budget b = mech_budget_make(1000, 600.0);
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_foucault_scene(&q, &b, &scene, &e), MECH_EBUDGET);
    CHECK(strcmp(e.param, "integrator/steps_per_swing") == 0);
    q.explicit_integrator = 1;
    q.steps_per_swing = 100;
    b = mech_budget_make(10000, 600.0); /* 10000 for the run, none left for the estimate */
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_foucault_scene(&q, &b, &scene, &e), MECH_OK);
    CHECK_EQ_INT(scene.estimate_done, 0);
    CHECK(strstr(scene.estimate_skip, "budget") != NULL);
    CHECK_EQ_INT((int)scene.achieved, -2);
    CHECK_EQ_INT(mech_foucault_scene(NULL, &b, &scene, &e), MECH_EINVAL);
    CHECK_EQ_INT(mech_foucault_scene(&q, &b, &scene, NULL), MECH_OK);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_precession();
    test_period_energy();
    test_richardson();
    test_choice();
    test_errors();
    TEST_MAIN_END();
}
