/* test_geodesic_run.c — mech/answers/gr/geodesic_run.h against closed forms:
 *  - light from far away with b = 1e5 GM/c^2: the deflection by quadrature
 *    against the weak-field series 4/b + 15 pi/(4 b^2) + (128/3)/b^3 (Keeton &
 *    Petters 2005, eq. 28 with M = 1), the measured deflection against it, the
 *    references 4/b and 4/b + 15 pi/(4 b^2) themselves, the closest approach
 *    against r_min = b - 1 - 3/(2b) + O(1/b^2) (from
 *    u^2 (1 - 2u) = 1/b^2: u = 1/b + 1/b^2 + 5/(2 b^3) + ...);
 *  - a near-circular orbit at a = 20 GM/c^2 run for 3 radial periods: the
 *    measured advance against 2 pi/sqrt(1 - 6/a) - 2 pi, the first-order
 *    reference 3 pi (u1 + u2) = 6 pi/(a(1 - e^2));
 *  - light with b < 3 sqrt 3 is captured; errors leave the answer freeable. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/gr/geodesic_run.h"
#include "testlib.h"

static struct mech_geodesic_request request(void)
{
    struct mech_geodesic_request q;
    memset(&q, 0, sizeof q);
    mech_gr_units_init(1, MECH_GR_MASS_NONE, NAN, &q.units, NULL);
    q.constraint_bound = 1e-6;
    q.samples = 50;
    return q;
}

static struct mech_geodesic_problem problem(const struct mech_geodesic_setup *s)
{
    struct mech_geodesic_problem p = s->problem;
    p.method = "rk8pd";
    p.opt.rtol = 1e-13;
    p.opt.atol = 1e-13;
    return p;
}

static void test_deflection(void)
{
    struct mech_geodesic_request q = request();
    q.kind = MECH_GEODESIC_NULL;
    q.form = MECH_GEODESIC_FORM_IMPACT;
    const double b = 1e5;
    q.impact_parameter = b;
    struct mech_geodesic_setup s;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, &e), MECH_OK);
    struct mech_geodesic_problem p = problem(&s);
    struct mech_budget B = mech_budget_make(10000000, 600);
    struct mech_geodesic_answer a;
    CHECK_EQ_INT(mech_geodesic_run(&s, &p, &B, &a, &e), MECH_OK);
    CHECK_EQ_INT(a.integrated, 1);
    CHECK_EQ_INT(a.scatter, 1);
    CHECK(!strcmp(a.motion, "scatter"));
    CHECK_EQ_INT(a.result.escaped, 1);
    const double series = 4.0 / b + 15.0 * MECH_PI / (4.0 * b * b) + 128.0 / 3.0 / (b * b * b);
    CHECK_CLOSE(a.deflection_exact, series, 1e-12, 0); /* next term ~1e-20 */
    CHECK_CLOSE(a.deflection_exact, 4.0 / b, 3e-5, 0); /* 15 pi/(16 b) ~ 3e-5 above */
    CHECK_CLOSE(a.result.measured_deflection, series, 1e-8, 0);
    CHECK_CLOSE(a.deflection_first_order, 4e-5, 1e-15, 0);
    CHECK_CLOSE(a.deflection_second_order, 4e-5 + 15.0 * MECH_PI / 4e10, 1e-15, 0);
    /* the elliptic form keeps ~12 digits at delta = 4e-5 */
    CHECK_CLOSE(a.deflection_elliptic, series, 1e-10, 0);
    CHECK_CLOSE(a.elliptic_precision, 4e-16 * MECH_PI / a.deflection_exact, 1e-15, 0);
    /* u = 1/b + 1/b^2 + 5/(2 b^3) + ...: r_min = b - 1 - 3/(2b) + O(1/b^2) */
    CHECK_CLOSE(a.closest_approach, b - 1.0 - 1.5 / b, 1e-13, 0);
    CHECK(isnan(a.advance_first_order));
    mech_geodesic_answer_free(&a);
    mech_geodesic_answer_free(&a); /* idempotent */

    /* b = 5 < 3 sqrt 3 = 5.196: captured, no deflection */
    q.impact_parameter = 5.0;
    q.has_r0 = 1;
    q.r0 = 100.0;
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, &e), MECH_OK);
    p = problem(&s);
    CHECK_EQ_INT(mech_geodesic_run(&s, &p, &B, &a, &e), MECH_OK);
    CHECK(!strcmp(a.motion, "capture"));
    CHECK_EQ_INT(a.scatter, 0);
    CHECK_EQ_INT(a.result.captured, 1);
    CHECK(isnan(a.deflection_exact));
    mech_geodesic_answer_free(&a);
}

static void test_advance(void)
{
    struct mech_geodesic_request q = request();
    q.form = MECH_GEODESIC_FORM_TURNING;
    q.periapsis = 20.0 * (1.0 - 1e-4);
    q.apoapsis = 20.0 * (1.0 + 1e-4);
    q.has_orbits = 1;
    q.orbits = 3;
    struct mech_geodesic_setup s;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, &e), MECH_OK);
    struct mech_geodesic_problem p = problem(&s);
    struct mech_budget B = mech_budget_make(10000000, 600);
    struct mech_geodesic_answer a;
    CHECK_EQ_INT(mech_geodesic_run(&s, &p, &B, &a, &e), MECH_OK);
    CHECK(!strcmp(a.motion, "bound"));
    CHECK_EQ_INT((int)a.result.n_periapses, 4);
    const double adv = 2.0 * MECH_PI / sqrt(1.0 - 6.0 / 20.0) - 2.0 * MECH_PI;
    CHECK_CLOSE(a.result.measured_advance, adv, 1e-7, 0);
    /* 6 pi/(a(1 - e^2)), a = 20, e = 1e-4; u1, u2 are found again by classify
     * from E and L (~1e-13 relative) */
    CHECK_CLOSE(a.advance_first_order, 6.0 * MECH_PI / (20.0 * (1.0 - 1e-8)), 1e-11, 0);
    CHECK(isnan(a.deflection_exact));
    mech_geodesic_answer_free(&a);

    /* a budget of 10 steps: EBUDGET from the integration, answer still freeable */
    struct mech_budget small = mech_budget_make(10, 600);
    CHECK_EQ_INT(mech_geodesic_run(&s, &p, &small, &a, &e), MECH_EBUDGET);
    CHECK_EQ_INT(a.integrated, 0);
    mech_geodesic_answer_free(&a);

    /* absurd sample counts: refused or out of memory, never an overflowed array */
    p.samples = SIZE_MAX;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_geodesic_run(&s, &p, &B, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "samples"));
    mech_geodesic_answer_free(&a);
    p.samples = 1;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_geodesic_run(&s, &p, &B, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "samples"));
    mech_geodesic_answer_free(&a);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_deflection();
    test_advance();
    TEST_MAIN_END();
}
