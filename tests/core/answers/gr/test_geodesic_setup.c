/* test_geodesic_setup.c — mech/answers/gr/geodesic_setup.h against closed forms:
 *  - a near-circular orbit at r = 20 GM/c^2 (strong field): the radial
 *    (epicyclic) frequency in coordinate time, w_r^2 = (M/r^3)(1 - 6M/r),
 *    gives T_t = 2 pi / w_r; the proper period is T_t sqrt(1 - 3M/r) (dtau/dt
 *    on a circular orbit); the advance per orbit 2 pi/sqrt(1 - 6M/r) - 2 pi
 *    (a turning-point pair closer than ~1e-7 is classified circular: no period);
 *  - Mercury in SI (a = 5.7909e10 m, e = 0.2056, the Sun's GM): the advance
 *    against the weak-field 6 pi GM/(c^2 a (1 - e^2)) and ~43"/century, the
 *    coordinate radial period against Kepler's 2 pi sqrt(a^3/GM);
 *  - a ray from far away: the default start 100 b and run length (the
 *    straight path to r_escape, 2 % longer, plus 600 pi);
 *  - every error names the request's field. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/gr/geodesic_setup.h"
#include "testlib.h"

static struct mech_geodesic_request request(int geometric, enum mech_gr_mass mass)
{
    struct mech_geodesic_request q;
    memset(&q, 0, sizeof q);
    mech_gr_units_init(geometric, mass, NAN, &q.units, NULL);
    q.constraint_bound = 1e-6;
    q.samples = 10;
    return q;
}

static void test_near_circular(void)
{
    struct mech_geodesic_request q = request(1, MECH_GR_MASS_NONE);
    q.form = MECH_GEODESIC_FORM_TURNING;
    q.periapsis = 20.0;
    q.apoapsis = 20.0 * (1.0 + 2e-4); /* e = 1e-4: the closed forms hold to O(e^2) */
    q.has_orbits = 1;
    q.orbits = 3;
    struct mech_geodesic_setup s;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, &e), MECH_OK);
    CHECK_EQ_INT(s.bound, 1);
    CHECK(!strcmp(mech_geodesic_class_name(s.cls), "bound"));
    const double r = 20.0 * (1.0 + 1e-4), wr /* r = a */ = sqrt((1.0 - 6.0 / r) / (r * r * r));
    CHECK_CLOSE(s.period_t, 2.0 * MECH_PI / wr, 1e-7, 0);
    CHECK_CLOSE(s.period_tau, 2.0 * MECH_PI / wr * sqrt(1.0 - 3.0 / r), 1e-7, 0);
    const double adv = 2.0 * MECH_PI / sqrt(1.0 - 6.0 / r) - 2.0 * MECH_PI;
    CHECK_CLOSE(s.adv_exact, adv, 1e-7, 0);
    CHECK_CLOSE(s.adv_quad, adv, 1e-7, 0);
    /* three radial periods from periapsis, a quarter period's look-ahead,
     * default escape at twice the apoapsis */
    CHECK_CLOSE(s.problem.param_end, 3.0 * s.period_tau, 1e-15, 0);
    CHECK_CLOSE(s.problem.periapsis_lookahead, 0.25 * s.period_tau, 1e-15, 0);
    /* 1/u1, u1 found again by classify from E and L */
    CHECK_CLOSE(s.problem.r_escape, 40.0 * (1.0 + 2e-4), 1e-10, 0);
    CHECK_CLOSE(s.problem.init.r0, 20.0, 1e-15, 0);
    CHECK_EQ_INT((int)s.problem.samples, 10);
}

static void test_mercury_si(void)
{
    struct mech_geodesic_request q = request(0, MECH_GR_MASS_SUN);
    q.form = MECH_GEODESIC_FORM_AXES;
    q.semi_major_axis = 5.7909e10;
    q.eccentricity = 0.2056;
    q.has_tau_end = 1;
    q.tau_end = 86400.0;
    struct mech_geodesic_setup s;
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, NULL), MECH_OK);
    CHECK_EQ_INT(s.bound, 1);
    const double a = 5.7909e10, ec = 0.2056;
    const double first = 6.0 * MECH_PI * MECH_SUN_GM / (MECH_C * MECH_C * a * (1.0 - ec * ec));
    /* the next order is ~ (GM/c^2)/(a(1 - e^2)) ~ 3e-8 relative */
    CHECK_CLOSE(s.adv_exact, first, 1e-6, 0);
    CHECK_CLOSE(s.adv_quad, s.adv_exact, 1e-10, 0);
    const double kepler = 2.0 * MECH_PI * sqrt(a * a * a / MECH_SUN_GM); /* 87.97 days */
    CHECK_CLOSE(mech_gr_time_out(&q.units, s.period_t), kepler, 1e-6, 0);
    CHECK_CLOSE(kepler / 86400.0, 87.97, 1e-4, 0);
    /* 42.98 arcsec per Julian century */
    const double arcsec = s.adv_exact * (36525.0 * 86400.0) / kepler * (180.0 * 3600.0 / MECH_PI);
    CHECK_CLOSE(arcsec, 42.98, 2e-4, 0);
    CHECK_CLOSE(s.problem.param_end, 86400.0 / q.units.s, 1e-15, 0);
    CHECK_CLOSE(s.problem.periapsis_lookahead, 0.0, 0, 0);
}

static void test_ray_default(void)
{
    struct mech_geodesic_request q = request(1, MECH_GR_MASS_NONE);
    q.kind = MECH_GEODESIC_NULL;
    q.form = MECH_GEODESIC_FORM_IMPACT;
    q.impact_parameter = 1e4;
    struct mech_geodesic_setup s;
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, NULL), MECH_OK);
    CHECK_EQ_INT(s.bound, 0);
    CHECK(isnan(s.adv_exact));
    const double b = 1e4, r0 = 1e6, re = 2e6;
    CHECK_CLOSE(s.problem.init.r0, r0, 0, 0);
    CHECK_CLOSE(fabs(s.problem.init.L), b, 1e-15, 0);
    CHECK_CLOSE(s.problem.r_escape, re, 0, 0);
    const double path = sqrt(r0 * r0 - b * b) + sqrt(re * re - b * b);
    CHECK_CLOSE(s.problem.param_end, 1.02 * path + 600.0 * MECH_PI, 1e-14, 0);
    /* a small b starts at 1000 GM/c^2 */
    q.impact_parameter = 6.0;
    CHECK_EQ_INT(mech_geodesic_setup(&q, &s, NULL), MECH_OK);
    CHECK_CLOSE(s.problem.init.r0, 1000.0, 0, 0);
}

static void expect(const struct mech_geodesic_request *q, enum mech_status want,
                   const char *param)
{
    struct mech_geodesic_setup s;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_geodesic_setup(q, &s, &e), want);
    CHECK(!strcmp(e.param, param));
    CHECK(e.text[0] != 0);
}

static void test_errors(void)
{
    struct mech_geodesic_request q = request(1, MECH_GR_MASS_NONE);
    q.form = MECH_GEODESIC_FORM_ENERGY;
    q.has_r0 = 1;
    q.r0 = 1.5; /* inside the horizon */
    q.energy = 0.97;
    q.angular_momentum = 4.0;
    q.has_tau_end = 1;
    q.tau_end = 100.0;
    expect(&q, MECH_EDOMAIN, "r0");
    q.r0 = 10.0;
    q.energy = -1.0;
    expect(&q, MECH_EDOMAIN, "initial/energy");
    q.energy = 1.5; /* unbound: orbits does not apply */
    q.has_tau_end = 0;
    q.has_orbits = 1;
    q.orbits = 2;
    expect(&q, MECH_EINVAL, "orbits");
    q.has_orbits = 0;
    q.has_tau_end = 1;
    q.has_r_escape = 1;
    q.r_escape = 5.0;
    expect(&q, MECH_EINVAL, "r_escape");
    q.has_r_escape = 0;
    q.tau_end = -1.0;
    expect(&q, MECH_EINVAL, "tau_end");
    q.tau_end = NAN;
    expect(&q, MECH_EINVAL, "tau_end");

    q.form = MECH_GEODESIC_FORM_AXES; /* e > 1: turning points are a's */
    q.semi_major_axis = 100.0;
    q.eccentricity = 1.5;
    expect(&q, MECH_EDOMAIN, "initial/semi_major_axis");
    q.form = MECH_GEODESIC_FORM_TURNING;
    q.periapsis = 100.0;
    q.apoapsis = 50.0;
    expect(&q, MECH_EDOMAIN, "initial/apoapsis");

    q.kind = MECH_GEODESIC_NULL; /* light: a huge lambda_end in SI overflows */
    q.units = request(0, MECH_GR_MASS_EARTH).units;
    q.form = MECH_GEODESIC_FORM_IMPACT;
    q.impact_parameter = 1.0;
    q.has_r0 = 0;
    q.has_lambda_end = 1;
    q.lambda_end = 1e308;
    expect(&q, MECH_EINVAL, "lambda_end");
    q.form = MECH_GEODESIC_FORM_LOCAL;
    q.has_r0 = 1;
    q.r0 = 1.0;
    q.v_radial = 0.0;
    q.v_tangential = 2.0 * MECH_C; /* faster than light: a massive particle cannot */
    q.kind = MECH_GEODESIC_TIMELIKE;
    q.has_lambda_end = 0;
    q.has_tau_end = 1;
    q.tau_end = 100.0;
    expect(&q, MECH_EDOMAIN, "initial/local_velocity");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_near_circular();
    test_mercury_si();
    test_ray_default();
    test_errors();
    TEST_MAIN_END();
}
