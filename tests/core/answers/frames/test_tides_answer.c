/* test_tides_answer.c — one /v1/earth/tides answer (mech/answers/frames/tides_answer.h)
 * against closed forms: along the axis (theta = 0) the exact tidal
 * acceleration is GM/(d - r)² - GM/d² = GM r (2d - r) / (d² (d - r)²),
 * 2 GM r/d³ to first order, and its departure from first order is
 * GM r² (3d - 2r) / (d³ (d - r)²) (both rewritten so no two nearly equal
 * numbers are subtracted); across it (theta = 90 deg) the along component is
 * GM/d² ((1 + u²)^(-3/2) - 1), summed here as its binomial series, and the
 * perpendicular one -GM r/d³ (1 + u²)^(-3/2) (first order -GM r/d³); all at
 * r/d = 1e-8, where a direct subtraction keeps no more than 8 digits. Then
 * the equilibrium tides of the notes (0.54 m Moon, 0.25 m Sun) and their
 * spring and neap sums, bodies given by gm or mass, and every refusal with
 * the field it names. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/frames/tides_answer.h"
#include "testlib.h"

static struct mech_tides_request request(void)
{
    struct mech_tides_request q;
    memset(&q, 0, sizeof q);
    q.body = MECH_TIDES_BODY_MOON;
    q.angle_deg = 0;
    q.radius = 6371008.8;
    q.gm_earth = MECH_EARTH_GM;
    return q;
}

static struct mech_tides_request custom(double gm, double d, double r, double theta)
{
    struct mech_tides_request q = request();
    q.body = MECH_TIDES_BODY_CUSTOM;
    q.custom.has_gm = q.custom.has_distance = 1;
    q.custom.gm = gm;
    q.custom.distance = d;
    q.radius = r;
    q.angle_deg = theta;
    return q;
}

/* Along the axis: exact, first order and their difference in closed form. */
static void check_along_axis(void)
{
    const double gm = 1e20, us[] = {1e-8, 1e-3, 0.1, 0.3, 0.9};
    for (size_t i = 0; i < sizeof us / sizeof us[0]; i++) {
        const double d = 1e15, r = us[i] * d, dr = d - r;
        struct mech_tides_request q = custom(gm, d, r, 0);
        struct mech_tides_answer a;
        CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
        const double exact = gm * r * (2 * d - r) / (d * d * dr * dr);
        const double first = 2 * gm * r / (d * d * d);
        const double rest = gm * r * r * (3 * d - 2 * r) / (d * d * d * dr * dr);
        CHECK_CLOSE(a.acceleration.exact.along, exact, 4e-15, 0);
        CHECK_CLOSE(a.acceleration.exact.radial, exact, 4e-15, 0); /* r_hat = e at theta = 0 */
        CHECK_CLOSE(a.acceleration.first_order.along, first, 1e-15, 0);
        CHECK_CLOSE(a.acceleration.difference.along, rest, 1e-14, 0);
        CHECK_CLOSE(a.acceleration.exact.perpendicular, 0, 0, 1e-300);
        CHECK_CLOSE(a.acceleration.u, us[i], 1e-15, 0);
    }
    /* the notes' Moon at the sub-lunar point: 2 GM r/d³ = 1.10e-6 m/s^2 */
    struct mech_tides_request q = request();
    struct mech_tides_answer a;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.acceleration.first_order.along, 1.10e-6, 0.01, 0);
    CHECK(strcmp(a.body.name, "moon") == 0);
    CHECK_CLOSE(a.body.gm, MECH_MOON_GM, 0, 0);
    CHECK_CLOSE(a.body.distance, 3.844e8, 0, 0);
}

/* Across the axis at r/d = 1e-8: the binomial series of (1 + u²)^(-3/2). */
static void check_across_axis(void)
{
    const double gm = 1e20, d = 1e15, u = 1e-8, r = u * d, u2 = u * u;
    struct mech_tides_request q = custom(gm, d, r, 90);
    struct mech_tides_answer a;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    const double pull = gm / (d * d);
    /* (1 + x)^(-3/2) - 1 = -3/2 x + 15/8 x² - 35/16 x³ + ...; x = u² = 1e-16 */
    const double e = -1.5 * u2 + 1.875 * u2 * u2 - 2.1875 * u2 * u2 * u2;
    CHECK_CLOSE(a.acceleration.exact.along, pull * e, 1e-15, 0);
    CHECK_CLOSE(a.acceleration.exact.perpendicular, -pull * u * (1 + e), 1e-15, 0);
    CHECK_CLOSE(a.acceleration.first_order.perpendicular, -gm * r / (d * d * d), 1e-15, 0);
    CHECK_CLOSE(a.acceleration.first_order.radial, -gm * r / (d * d * d), 1e-15, 0);
    CHECK_CLOSE(a.acceleration.first_order.along, 0, 0, 0);
    /* the departure from first order across the axis: -u s E = 3/2 u³ GM/d² */
    CHECK_CLOSE(a.acceleration.difference.perpendicular, -pull * u * e, 1e-14, 0);
    /* relative difference ~ u: |(E e - u E p)| / (u pull) = |E| / u = 1.5 u */
    CHECK_CLOSE(a.acceleration.relative_difference, 1.5 * u, 1e-7, 0);
}

/* Equilibrium tides: h(theta) = GM r⁴ (3 cos² theta - 1) / (2 GM_E d³),
 * range 3 GM r⁴ / (2 GM_E d³); the notes: 0.54 m (Moon), 0.25 m (Sun). */
static double h_eq(double gm, double gme, double d, double r, double c)
{
    return gm * pow(r, 4) * (3 * c * c - 1) / (2 * gme * d * d * d);
}

static void check_heights(void)
{
    struct mech_tides_request q = request();
    q.angle_deg = 60; /* cos 60 = 1/2, cos 30 = sqrt(3)/2 */
    struct mech_tides_answer a;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    const double r = q.radius, gme = q.gm_earth;
    const double dm = MECH_MOON_DISTANCE, ds = MECH_AU;
    const double hm = 1.5 * MECH_MOON_GM * pow(r, 4) / (gme * dm * dm * dm);
    const double hs = 1.5 * MECH_SUN_GM * pow(r, 4) / (gme * ds * ds * ds);
    CHECK(fabs(hm - 0.54) < 0.006 && fabs(hs - 0.25) < 0.005);
    CHECK_CLOSE(a.height.range, hm, 1e-14, 0);
    CHECK_CLOSE(a.height.high, hm * 2 / 3, 1e-14, 0);
    CHECK_CLOSE(a.height.low, -hm / 3, 1e-14, 0);
    CHECK_CLOSE(a.height.height, h_eq(MECH_MOON_GM, gme, dm, r, 0.5), 1e-13, 0);
    CHECK_EQ_INT(a.has_spring_neap, 1);
    CHECK_CLOSE(a.moon_height.range, hm, 1e-14, 0);
    CHECK_CLOSE(a.sun_height.range, hs, 1e-14, 0);
    CHECK_CLOSE(a.spring_range, hm + hs, 1e-14, 0);
    CHECK_CLOSE(a.neap_range, hm - hs, 1e-14, 0);
    CHECK_CLOSE(a.sun_to_moon, hs / hm, 1e-14, 0);
    CHECK(a.sun_to_moon > 0.45 && a.sun_to_moon < 0.47);
    CHECK_CLOSE(a.spring_height,
                h_eq(MECH_MOON_GM, gme, dm, r, 0.5) + h_eq(MECH_SUN_GM, gme, ds, r, 0.5), 1e-13, 0);
    CHECK_CLOSE(a.neap_height,
                h_eq(MECH_MOON_GM, gme, dm, r, 0.5) + h_eq(MECH_SUN_GM, gme, ds, r, sqrt(3) / 2),
                1e-13, 1e-17);
    /* the Sun as the body, 1 au */
    q.body = MECH_TIDES_BODY_SUN;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    CHECK(strcmp(a.body.name, "sun") == 0);
    CHECK_CLOSE(a.height.range, hs, 1e-14, 0);
    CHECK_CLOSE(a.body.mass, MECH_SUN_GM / MECH_GRAVITATIONAL_CONSTANT, 1e-15, 0);
    /* a point beyond the Moon's orbit: no spring and neap */
    q = custom(1e12, 1e10, 4e8, 30);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    CHECK_EQ_INT(a.has_spring_neap, 0);
}

/* Bodies given by gm or mass; overrides of the Moon and the Sun. */
static void check_bodies(void)
{
    struct mech_tides_request q = request();
    q.moon.has_mass = 1;
    q.moon.mass = 7.342e22;
    q.sun.has_gm = q.sun.has_distance = 1;
    q.sun.gm = 1.32712440018e20;
    q.sun.distance = 1.5e11;
    struct mech_tides_answer a;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.body.gm, MECH_GRAVITATIONAL_CONSTANT * 7.342e22, 1e-15, 0);
    CHECK_CLOSE(a.body.mass, 7.342e22, 0, 0);
    CHECK(strstr(a.body.source, "GM = G mass") != NULL);
    CHECK_CLOSE(a.sun.gm, 1.32712440018e20, 0, 0);
    CHECK_CLOSE(a.sun.mass, 1.32712440018e20 / MECH_GRAVITATIONAL_CONSTANT, 1e-15, 0);
    CHECK_CLOSE(a.sun.distance, 1.5e11, 0, 0);
    CHECK(strcmp(a.sun.source, "GM as given") == 0);
    q = custom(0, 1e9, 6.4e6, 0);
    q.custom.has_gm = 0;
    q.custom.has_mass = 1;
    q.custom.mass = 1e20;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    CHECK(strcmp(a.body.name, "custom") == 0);
    CHECK_CLOSE(a.body.gm, MECH_GRAVITATIONAL_CONSTANT * 1e20, 1e-15, 0);
}

static void expect(const struct mech_tides_request *q, enum mech_status st, const char *param)
{
    struct mech_tides_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tides_answer(q, &a, &e), st);
    CHECK(strcmp(e.param, param) == 0);
    if (strcmp(e.param, param)) fprintf(stderr, "  param '%s', want '%s'\n", e.param, param);
}

static void check_refusals(void)
{
    struct mech_tides_request q = request();
    q.moon.has_gm = q.moon.has_mass = 1;
    q.moon.gm = 1e12;
    q.moon.mass = 1e22;
    expect(&q, MECH_EINVAL, "moon");
    q = request();
    q.sun.has_gm = q.sun.has_mass = 1;
    q.sun.gm = q.sun.mass = 1;
    expect(&q, MECH_EINVAL, "sun");
    q = custom(1e12, 1e9, 6.4e6, 0);
    q.custom.has_mass = 1;
    q.custom.mass = 1;
    expect(&q, MECH_EINVAL, "body");
    q = custom(1e12, 1e9, 6.4e6, 0);
    q.custom.has_gm = 0;
    expect(&q, MECH_EINVAL, "body");
    q = custom(1e12, 6e6, 6.4e6, 0);
    expect(&q, MECH_EDOMAIN, "body/distance");
    q = custom(1e12, 6.4e6, 6.4e6, 0); /* on the sphere: not outside */
    expect(&q, MECH_EDOMAIN, "body/distance");
    q = request();
    q.moon.has_distance = 1;
    q.moon.distance = 5e6;
    expect(&q, MECH_EDOMAIN, "moon/distance");
    q = request();
    q.body = MECH_TIDES_BODY_SUN;
    q.radius = 2e11;
    expect(&q, MECH_EDOMAIN, "radius");
    q = request();
    q.moon.has_gm = 1;
    q.moon.gm = -1;
    expect(&q, MECH_EINVAL, "moon/gm");
    q = request();
    q.sun.has_distance = 1;
    q.sun.distance = NAN;
    expect(&q, MECH_EINVAL, "sun/distance");
    q = request();
    q.angle_deg = 181;
    expect(&q, MECH_EINVAL, "angle_deg");
    q = request();
    q.gm_earth = 0;
    expect(&q, MECH_EINVAL, "gm_earth");
    q = request();
    q.body = (enum mech_tides_body_kind)7;
    expect(&q, MECH_EINVAL, "body");
    /* a Moon so light its tide underflows: the Sun-to-Moon ratio is not finite */
    q = request();
    q.body = MECH_TIDES_BODY_SUN;
    q.moon.has_gm = 1;
    q.moon.gm = 1e-300;
    expect(&q, MECH_ENUMERIC, "");
    /* the largest inputs the API allows, and a point nearly touching the body */
    q = custom(1e22, 1e16, 1e12, 180);
    struct mech_tides_answer a;
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    CHECK(isfinite(a.acceleration.exact.along) && isfinite(a.height.range));
    q = custom(1e22, 1.0000001e6, 1e6, 0);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, NULL), MECH_OK);
    const double d = 1.0000001e6, r = 1e6, dr = d - r;
    CHECK_CLOSE(a.acceleration.exact.along, 1e22 * r * (2 * d - r) / (d * d * dr * dr), 1e-8, 0);
    CHECK_EQ_INT(mech_tides_answer(NULL, &a, NULL), MECH_EINVAL);
    CHECK_EQ_INT(mech_tides_answer(&q, NULL, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_along_axis();
    check_across_axis();
    check_heights();
    check_bodies();
    check_refusals();
    TEST_MAIN_END();
}
