/* test_relativistic_force.c — F = dp/dt split along and across v
 * (core/relativity/relativistic_force.c): beta = 0.6 closed forms (gamma = 5/4, gamma^3 =
 * 125/64), the round trip force -> acceleration -> force, the power against
 * d(gamma m c^2)/dt by a finite difference of gamma along the motion (a second
 * method), the 4-force's orthogonality to the 4-velocity, and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/relativistic_force.h"
#include "mech/base/constants.h"
#include "testlib.h"

static void test_closed_form(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &b, NULL), MECH_OK);
    struct mech_rel_force f;
    const double m = 2.0;
    CHECK_EQ_INT(mech_rel_force_from_acceleration(m, &b, mech_vec3_make(1, 2, 0), &f, NULL), MECH_OK);
    CHECK_CLOSE(f.force_parallel.x, 125.0 / 64.0 * m, 1e-15, 0); /* gamma^3 m a_par */
    CHECK_CLOSE(f.force_perpendicular.y, 1.25 * m * 2, 1e-15, 0); /* gamma m a_perp */
    CHECK_CLOSE(f.force.x, 3.90625, 1e-15, 0);
    CHECK_CLOSE(f.force.y, 5.0, 1e-15, 0);
    CHECK_CLOSE(f.longitudinal_mass, 3.90625, 1e-15, 0);
    CHECK_CLOSE(f.transverse_mass, 2.5, 1e-15, 0);
    CHECK_CLOSE(f.power, 3.90625 * 0.6 * MECH_C, 1e-15, 0);
    /* Second method for the power: d(gamma m c^2)/dt with v(t) = v + a t, central
     * difference at t = 0 with h = 1000 s (a h / c ~ 1e-5: truncation ~1e-10
     * relative, rounding of the gamma difference ~1e-11). */
    const double h = 1000.0;
    double vp[3] = {0.6 * MECH_C + h, 2 * h, 0}, vm[3] = {0.6 * MECH_C - h, -2 * h, 0};
    double gp = 1 / sqrt(1 - (vp[0] * vp[0] + vp[1] * vp[1]) / (MECH_C * MECH_C));
    double gm = 1 / sqrt(1 - (vm[0] * vm[0] + vm[1] * vm[1]) / (MECH_C * MECH_C));
    CHECK_CLOSE(m * MECH_C * MECH_C * (gp - gm) / (2 * h), f.power, 1e-8, 0);
    /* K.u = 0: the 4-force is orthogonal to the 4-velocity u = gamma (c, v). */
    const double u[4] = {1.25 * MECH_C, 1.25 * 0.6 * MECH_C, 0, 0};
    const double ku = -f.four_force[0] * u[0] + f.four_force[1] * u[1] + f.four_force[2] * u[2];
    CHECK_CLOSE(ku, 0.0, 0, 1e-15 * fabs(f.four_force[1] * u[1]));

    /* The inverse returns the acceleration. */
    struct mech_rel_force g;
    CHECK_EQ_INT(mech_rel_force_from_force(m, &b, f.force, &g, NULL), MECH_OK);
    CHECK_CLOSE(g.acceleration.x, 1.0, 1e-15, 0);
    CHECK_CLOSE(g.acceleration.y, 2.0, 1e-15, 0);
    CHECK_CLOSE(g.acceleration.z, 0.0, 0, 1e-15);
}

/* Near c: 1 - beta = 1e-15 (gamma = 22360679.77499790), a force along v gives
 * a = F/(gamma^3 m), across v a = F/(gamma m). */
static void test_near_c(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_one_minus_beta(1e-15, mech_vec3_make(0, 0, 1), &b, NULL), MECH_OK);
    struct mech_rel_force f;
    CHECK_EQ_INT(mech_rel_force_from_force(1.0, &b, mech_vec3_make(1, 0, 1), &f, NULL), MECH_OK);
    const double g = 22360679.774997903;
    CHECK_CLOSE(f.acceleration.z, 1.0 / (g * g * g), 4e-15, 0);
    CHECK_CLOSE(f.acceleration.x, 1.0 / g, 2e-15, 0);
}

static void test_errors(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.1, 0, 0), &b, NULL), MECH_OK);
    struct mech_rel_force f;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rel_force_from_acceleration(0.0, &b, mech_vec3_make(1, 0, 0), &f, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rel_force_from_force(1.0, &b, mech_vec3_make(NAN, 0, 0), &f, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "force"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_closed_form();
    test_near_c();
    test_errors();
    TEST_MAIN_END();
}
