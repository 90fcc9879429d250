/* test_earth_gravity_answer.c — one /v1/earth/gravity answer
 * (mech/answers/frames/earth_gravity_answer.h) against a second method: g_eff = g - w x
 * (w x r) built here as vectors in Earth-centred axes (z along w), so its
 * magnitude, its radial and horizontal parts and the plumb line's deflection
 * atan2(|g_eff x r_hat|, -g_eff . r_hat) are compared with the answer's
 * closed forms; at the equator |g_eff| = GM/R² - W² R (the notes'
 * g = g0 - w² r cos² L) and at 45 deg tan(alpha) = (k/2) / (1 - k/2),
 * k = W² r / g0. The ellipsoid: Somigliana at the poles gives WGS 84's
 * gamma_p, the 1980 formula agrees within 1e-6 m/s², the free-air gradient is
 * about -0.3086 mGal/m. Then gm from g0, omega from the sidereal day, a
 * non-rotating sphere, and every refusal with the field it names. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/frames/earth_gravity_answer.h"
#include "testlib.h"

static struct mech_earth_gravity_request request(double lat, double h)
{
    struct mech_earth_gravity_request q;
    memset(&q, 0, sizeof q);
    q.latitude_deg = lat;
    q.height = h;
    q.radius = MECH_EARTH_RADIUS_MEAN;
    q.gm = MECH_EARTH_GM;
    q.omega = MECH_EARTH_OMEGA;
    return q;
}

/* g_eff as vectors: r = (R + h)(cos L, 0, sin L), w = (0, 0, W). */
static void check_vectors(void)
{
    const double lats[] = {0, 10, 30, 45, 60, 89.9, -45};
    for (size_t i = 0; i < sizeof lats / sizeof lats[0]; i++) {
        const double L = lats[i] * MECH_PI / 180, h = 100;
        struct mech_earth_gravity_request q = request(lats[i], h);
        struct mech_earth_gravity_answer a;
        CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
        const double r = q.radius + h, W = q.omega, gm = q.gm;
        const double x = r * cos(L); /* distance from the axis */
        const double g0 = gm / (r * r);
        /* gravitation -GM r_vec / r³ plus centrifugal -w x (w x r) = W² (x, 0, 0) */
        const double gx = -g0 * cos(L) + W * W * x, gz = -g0 * sin(L);
        const double rhat_x = cos(L), rhat_z = sin(L);
        const double radial = -(gx * rhat_x + gz * rhat_z);
        const double cross = fabs(gx * rhat_z - gz * rhat_x); /* |g_eff x r_hat| */
        CHECK_CLOSE(a.sphere.magnitude, hypot(gx, gz), 1e-14, 0);
        CHECK_CLOSE(a.sphere.radial, radial, 1e-14, 0);
        CHECK_CLOSE(a.sphere.horizontal, cross, 1e-9, 1e-15);
        CHECK_CLOSE(a.sphere.deviation, atan2(cross, radial), 1e-9, 1e-15);
        CHECK_CLOSE(a.sphere.gravitation, g0, 1e-15, 0);
        /* (cos of L in radians near 90 deg is itself only good to ~1e-13) */
        CHECK_CLOSE(a.sphere.centrifugal, W * W * x, 1e-12, 0);
        CHECK_CLOSE(a.g0, gm / (q.radius * q.radius), 1e-15, 0);
        CHECK_CLOSE(a.difference, a.sphere.magnitude - a.ellipsoid.gamma, 0, 0);
    }
}

/* Closed forms: the equator and the plumb line at 45 deg. */
static void check_closed_forms(void)
{
    struct mech_earth_gravity_request q = request(0, 0);
    struct mech_earth_gravity_answer a;
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    const double R = q.radius, W = q.omega, g0 = q.gm / (R * R);
    CHECK_CLOSE(a.sphere.magnitude, g0 - W * W * R, 1e-15, 0);
    CHECK_CLOSE(a.sphere.reduction, W * W * R, 1e-13, 0);
    CHECK_CLOSE(a.sphere.reduction, 0.0339, 0.003, 0); /* the notes' 0.034 m/s^2 */
    CHECK_CLOSE(a.sphere.deviation, 0, 0, 0);
    q = request(45, 0);
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    const double k = W * W * R / g0;
    CHECK_CLOSE(a.sphere.k, k, 1e-15, 0);
    CHECK_CLOSE(a.sphere.deviation, atan((k / 2) / (1 - k / 2)), 1e-13, 0);
    CHECK_CLOSE(a.sphere.deviation * 180 / MECH_PI, 0.099, 0.01, 0); /* ~0.1 deg */
    /* the largest deflection: just below 45 deg, tan = k / (2 sqrt(1 - k)) */
    CHECK(a.sphere.deviation_max_latitude < MECH_PI / 4 &&
          a.sphere.deviation_max >= a.sphere.deviation);
    CHECK_CLOSE(tan(a.sphere.deviation_max), k / (2 * sqrt(1 - k)), 1e-13, 0);
    CHECK_CLOSE(tan(a.sphere.deviation_max_latitude), sqrt(1 - k), 1e-13, 0);
}

/* The ellipsoid: Somigliana's poles, the 1980 formula, the free-air gradient. */
static void check_ellipsoid(void)
{
    struct mech_earth_gravity_answer a;
    struct mech_earth_gravity_request q = request(0, 0);
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.ellipsoid.surface, MECH_WGS84_GAMMA_E, 1e-15, 0);
    q = request(-90, 0);
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.ellipsoid.surface, MECH_WGS84_GAMMA_P, 1e-10, 0);
    CHECK_CLOSE(a.sphere.deviation, 0, 0, 1e-18);
    q = request(45, 0);
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.ellipsoid.igf1980, 9.780327 * (1 + 0.0053024 * 0.5 - 0.0000058), 1e-15, 0);
    /* the 1980 formula is the series of GRS 80's closed Somigliana formula
     * (Moritz 1980: gamma_e 9.7803267715, k 0.001931851353, e² 0.00669438002290),
     * within 1e-6 m/s²; WGS 84's gamma_e is 1.4e-6 m/s² lower (its GM), so
     * WGS 84's surface gravity is within 2e-6 of GRS 80's */
    const double grs80 =
        9.7803267715 * (1 + 0.001931851353 * 0.5) / sqrt(1 - 0.00669438002290 * 0.5);
    CHECK_CLOSE(a.ellipsoid.igf1980, grs80, 0, 1e-6);
    CHECK_CLOSE(a.ellipsoid.surface, grs80, 0, 2e-6);
    q = request(45, 100);
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.ellipsoid.free_air / 100, -3.086e-6, 1e-3, 0);
    CHECK_CLOSE(a.relative_difference, a.difference / a.ellipsoid.gamma, 1e-15, 0);
    CHECK(fabs(a.relative_difference) < 1.2e-3); /* the sphere is within 0.12 % */
}

/* The sphere from g0 and the sidereal day; a sphere that does not turn. */
static void check_given(void)
{
    struct mech_earth_gravity_request q = request(30, 0);
    q.has_g0 = 1;
    q.g0 = 9.81;
    q.radius = 6.4e6;
    q.has_sidereal_day = 1;
    q.sidereal_day = 86164.0989;
    struct mech_earth_gravity_answer a;
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.earth.gm, 9.81 * 6.4e6 * 6.4e6, 1e-15, 0);
    CHECK_CLOSE(a.g0, 9.81, 1e-15, 0);
    CHECK_CLOSE(a.earth.omega, 2 * MECH_PI / 86164.0989, 1e-15, 0);
    CHECK_CLOSE(a.earth.omega, 7.292115e-5, 3e-8, 0); /* the IERS nominal W, rounded */
    CHECK_CLOSE(a.sidereal_day, 86164.0989, 1e-15, 0);
    q = request(50, 0);
    q.omega = 0;
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, &a, NULL), MECH_OK);
    CHECK(isinf(a.sidereal_day));
    CHECK_CLOSE(a.sphere.magnitude, q.gm / (q.radius * q.radius), 1e-15, 0);
    CHECK_CLOSE(a.sphere.deviation, 0, 0, 0);
}

static void expect(const struct mech_earth_gravity_request *q, enum mech_status st,
                   const char *param)
{
    struct mech_earth_gravity_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_earth_gravity_answer(q, &a, &e), st);
    CHECK(strcmp(e.param, param) == 0);
    if (strcmp(e.param, param)) fprintf(stderr, "  param '%s', want '%s'\n", e.param, param);
}

static void check_refusals(void)
{
    struct mech_earth_gravity_request q = request(10, 0);
    q.gm_given = q.has_g0 = 1;
    q.g0 = 9;
    expect(&q, MECH_EINVAL, "g0");
    q = request(10, 0);
    q.omega_given = q.has_sidereal_day = 1;
    q.sidereal_day = 5000;
    expect(&q, MECH_EINVAL, "sidereal_day");
    q = request(10, 0);
    q.has_g0 = 1;
    q.g0 = 0;
    expect(&q, MECH_EINVAL, "g0");
    q = request(10, 0);
    q.has_sidereal_day = 1;
    q.sidereal_day = -1;
    expect(&q, MECH_EINVAL, "sidereal_day");
    /* too fast to hang anything: W² r >= GM / r², named by what set the rate */
    q = request(10, 0);
    q.omega = 0.01;
    q.omega_given = 1;
    expect(&q, MECH_EDOMAIN, "omega");
    q = request(10, 0);
    q.has_sidereal_day = 1;
    q.sidereal_day = 1000;
    expect(&q, MECH_EDOMAIN, "sidereal_day");
    q = request(10, 0);
    q.radius = 5e7; /* r³ > GM / W² = 7.5e22 m³ at the default rate */
    expect(&q, MECH_EDOMAIN, "radius");
    q = request(91, 0);
    expect(&q, MECH_EINVAL, "latitude_deg");
    q = request(10, 2e5);
    expect(&q, MECH_EINVAL, "height");
    q = request(10, 0);
    q.gm = NAN;
    expect(&q, MECH_EINVAL, "gm");
    struct mech_earth_gravity_answer a;
    CHECK_EQ_INT(mech_earth_gravity_answer(NULL, &a, NULL), MECH_EINVAL);
    CHECK_EQ_INT(mech_earth_gravity_answer(&q, NULL, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_vectors();
    check_closed_forms();
    check_ellipsoid();
    check_given();
    check_refusals();
    TEST_MAIN_END();
}
