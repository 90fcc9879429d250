/* test_earth.c — effective gravity on a rotating spherical Earth (notes §1.3)
 * and WGS 84 normal gravity: the equator's centrifugal reduction W² R, the
 * plumb-line deviation's closed-form peak against a numerical maximisation,
 * the whole effective-g vector against mech_effective_force (gravitation plus
 * the centrifugal term of a particle at rest in the rotating frame, an
 * independent path), Somigliana's published gamma_e and gamma_p, the free-air
 * gradient 0.3086 mGal/m, the 1980 International Gravity Formula against GRS
 * 80's closed formula, sin/cos in degrees, and refused inputs. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/frames/earth.h"
#include "mech/base/constants.h"
#include "mech/frames/effective_force.h"
#include "testlib.h"

static const struct mech_earth_sphere EARTH = {MECH_EARTH_GM, MECH_EARTH_RADIUS_MEAN,
                                               MECH_EARTH_OMEGA};

static void check_sincos(void)
{
    double s, c;
    const double exact[][3] = {{0, 0, 1},       {90, 1, 0},      {180, 0, -1},  {270, -1, 0},
                               {360, 0, 1},     {-90, -1, 0},    {-180, 0, -1}, {30, 0.5, NAN},
                               {150, 0.5, NAN}, {-30, -0.5, NAN}};
    for (size_t i = 0; i < sizeof exact / sizeof exact[0]; i++) {
        mech_sincos_deg(exact[i][0], &s, &c);
        CHECK_CLOSE(s, exact[i][1], 2.3e-16, 0); /* 1 ulp */
        if (!isnan(exact[i][2])) CHECK(c == exact[i][2]);
    }
    for (double d = -400; d <= 400; d += 7.3) {
        mech_sincos_deg(d, &s, &c);
        /* reference in long double (64-bit mantissa) */
        long double x = (long double)d * MECH_PI_L / 180;
        CHECK_CLOSE(s, (double)sinl(x), 0, 2.3e-16);
        CHECK_CLOSE(c, (double)cosl(x), 0, 2.3e-16);
        CHECK_CLOSE(s * s + c * c, 1, 4e-16, 0);
    }
}

static void check_equator_and_pole(void)
{
    struct mech_earth_gravity g;
    const double W = MECH_EARTH_OMEGA, R = MECH_EARTH_RADIUS_MEAN;
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 0, 0, &g, NULL), MECH_OK);
    double g0 = MECH_EARTH_GM / (R * R);
    CHECK_CLOSE(g.gravitation, g0, 1e-16, 0);
    /* notes §1.3: at the equator g = GM/r² - W² r */
    CHECK_CLOSE(g.reduction, W * W * R, 1e-15, 0);
    CHECK_CLOSE(g.magnitude, g0 - W * W * R, 1e-16, 0);
    CHECK_CLOSE(g.reduction, 0.0339, 0, 5e-5); /* "about 0.0339 m/s^2" */
    printf("equator: g0 = %.12f, W^2 R = %.12f, |g| = %.12f m/s^2\n", g0, W * W * R, g.magnitude);
    CHECK(g.horizontal == 0 && g.deviation == 0);
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 90, 0, &g, NULL), MECH_OK);
    CHECK(g.centrifugal == 0 && g.reduction == 0 && g.deviation == 0);
    CHECK(g.magnitude == g0);
    /* height: r = R + h */
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 90, 8848, &g, NULL), MECH_OK);
    CHECK_CLOSE(g.gravitation, MECH_EARTH_GM / ((R + 8848) * (R + 8848)), 1e-15, 0);
    /* at 60 deg: radial g0 - W² R/4, horizontal W² R sqrt(3)/4 */
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 60, 0, &g, NULL), MECH_OK);
    CHECK_CLOSE(g.radial, g0 - W * W * R / 4, 1e-15, 0);
    CHECK_CLOSE(g.horizontal, W * W * R * sqrt(3) / 4, 1e-15, 0);
    CHECK_CLOSE(g.north, -W * W * R * sqrt(3) / 4, 1e-15, 0);
    CHECK_CLOSE(g.reduction, g0 - g.magnitude, 1e-12, 0);
    /* southern hemisphere: mirror, the horizontal part points north (to the equator) */
    struct mech_earth_gravity gs;
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, -60, 0, &gs, NULL), MECH_OK);
    CHECK(gs.north == -g.north && gs.deviation == g.deviation && gs.magnitude == g.magnitude);
}

/* The whole effective-g vector from mech_effective_force: an Earth-centred
 * frame rotating at W about z, particle at rest at r (latitude L in the x-z
 * plane), real force -GM m r_hat / r². */
static void check_against_effective_force(void)
{
    for (double lat = -90; lat <= 90; lat += 7.5) {
        double s, c;
        mech_sincos_deg(lat, &s, &c);
        double h = 1234.5, r = MECH_EARTH_RADIUS_MEAN + h;
        struct mech_vec3 up = {c, 0, s}, north = {-s, 0, c};
        struct mech_frame_motion fr = {{0, 0, MECH_EARTH_OMEGA}, {0, 0, 0}, {0, 0, 0}};
        struct mech_effective_force ef;
        double F = MECH_EARTH_GM / (r * r);
        CHECK_EQ_INT(mech_effective_force(&fr, 1, mech_vec3_scale(up, r), mech_vec3_make(0, 0, 0),
                                          mech_vec3_scale(up, -F), &ef, NULL),
                     MECH_OK);
        struct mech_earth_gravity g;
        CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, lat, h, &g, NULL), MECH_OK);
        CHECK_CLOSE(mech_vec3_dot(ef.acceleration, up), -g.radial, 1e-15, 0);
        CHECK_CLOSE(mech_vec3_dot(ef.acceleration, north), g.north, 1e-13, 1e-18);
        CHECK_CLOSE(mech_vec3_norm(ef.acceleration), g.magnitude, 1e-15, 0);
        CHECK_CLOSE(mech_vec3_norm(ef.centrifugal), g.centrifugal, 1e-15, 1e-20);
    }
}

static void check_deviation_peak(void)
{
    struct mech_earth_gravity g;
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 45, 0, &g, NULL), MECH_OK);
    double k = g.k;
    /* at 45 deg tan(alpha) = (k/2) / (1 - k/2) */
    CHECK_CLOSE(g.deviation, atan(0.5 * k / (1 - 0.5 * k)), 1e-15, 0);
    /* golden-section maximisation of the deviation over latitude */
    double a = 30, b = 60, phi = 0.5 * (sqrt(5) - 1);
    for (int i = 0; i < 200 && b - a > 1e-10; i++) {
        double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
        struct mech_earth_gravity g1, g2;
        mech_earth_gravity_sphere(&EARTH, x1, 0, &g1, NULL);
        mech_earth_gravity_sphere(&EARTH, x2, 0, &g2, NULL);
        if (g1.deviation < g2.deviation)
            a = x1;
        else
            b = x2;
    }
    double lat_max = 0.5 * (a + b);
    struct mech_earth_gravity gm;
    mech_earth_gravity_sphere(&EARTH, lat_max, 0, &gm, NULL);
    printf("deviation peak: closed form %.17g rad (%.12f deg) at %.9f deg; "
           "numerical max %.17g rad at %.9f deg; k/2 = %.17g\n",
           g.deviation_max, g.deviation_max * 180 / MECH_PI, g.deviation_max_latitude * 180 / MECH_PI,
           gm.deviation, lat_max, k / 2);
    CHECK_CLOSE(gm.deviation, g.deviation_max, 1e-14, 0);
    CHECK_CLOSE(lat_max, g.deviation_max_latitude * 180 / MECH_PI, 0, 1e-4);
    CHECK(g.deviation_max_latitude * 180 / MECH_PI < 45 &&
          g.deviation_max_latitude * 180 / MECH_PI > 44.9);
    /* about W² R / (2 g0) ~ 0.1 deg */
    CHECK_CLOSE(g.deviation_max, k / 2, 2e-3, 0);
    CHECK_CLOSE(g.deviation_max * 180 / MECH_PI, 0.0991, 0, 1e-3);
}

static void check_somigliana(void)
{
    struct mech_normal_gravity n;
    CHECK_EQ_INT(mech_earth_normal_gravity(0, 0, &n, NULL), MECH_OK);
    CHECK_CLOSE(n.surface, 9.7803253359, 1e-16, 0);
    CHECK(n.free_air == 0 && n.gamma == n.surface);
    CHECK_EQ_INT(mech_earth_normal_gravity(90, 0, &n, NULL), MECH_OK);
    /* the published constants are rounded to 1e-10 m/s^2 */
    CHECK_CLOSE(n.surface, 9.8321849378, 0, 1e-10);
    CHECK_EQ_INT(mech_earth_normal_gravity(-90, 0, &n, NULL), MECH_OK);
    CHECK_CLOSE(n.surface, 9.8321849378, 0, 1e-10);
    /* k = b gamma_p / (a gamma_e) - 1 to the published digits */
    CHECK_CLOSE(MECH_WGS84_B * MECH_WGS84_GAMMA_P / (MECH_WGS84_A * MECH_WGS84_GAMMA_E) - 1,
                MECH_WGS84_K, 0, 2e-11);
    /* e² = 2f - f² */
    CHECK_CLOSE(2 * MECH_WGS84_F - MECH_WGS84_F * MECH_WGS84_F, MECH_WGS84_E2, 1e-12, 0);
    /* m = W² a² b / GM */
    CHECK_CLOSE(MECH_EARTH_OMEGA * MECH_EARTH_OMEGA * MECH_WGS84_A * MECH_WGS84_A * MECH_WGS84_B /
                    MECH_EARTH_GM,
                MECH_WGS84_M, 1e-11, 0);
    /* free-air gradient at 45 deg: 0.3086 mGal/m (1 mGal = 1e-5 m/s^2) */
    CHECK_EQ_INT(mech_earth_normal_gravity(45, 1, &n, NULL), MECH_OK);
    CHECK_CLOSE(-n.free_air, 0.3086e-5, 1e-3, 0);
    /* second-order term: for a sphere (f = m = 0) the series is R²/(R+h)² to O(h³) */
    CHECK_EQ_INT(mech_earth_normal_gravity(45, 10000, &n, NULL), MECH_OK);
    double a = MECH_WGS84_A, f = MECH_WGS84_F, m = MECH_WGS84_M, h = 10000, s2 = 0.5;
    double want = -2 / a * (1 + f + m - 2 * f * s2) * h + 3 * h * h / (a * a);
    CHECK_CLOSE(n.free_air / n.surface, want, 1e-14, 0);
    double sph = a * a / ((a + h) * (a + h)) - 1;
    CHECK_CLOSE(want, sph, 1e-2, 0); /* same size: only f and m differ */
    /* monotonic from equator to pole, symmetric */
    double prev = 0;
    for (double lat = 0; lat <= 90; lat += 5) {
        struct mech_normal_gravity p, q;
        mech_earth_normal_gravity(lat, 0, &p, NULL);
        mech_earth_normal_gravity(-lat, 0, &q, NULL);
        CHECK(p.surface == q.surface);
        CHECK(p.surface > prev);
        prev = p.surface;
    }
    /* sphere vs ellipsoid: within 0.2 % everywhere, sphere too heavy at the equator and
     * too light at the poles (the sphere leaves out the flattening and its mass) */
    struct mech_earth_gravity g;
    mech_earth_gravity_sphere(&EARTH, 0, 0, &g, NULL);
    mech_earth_normal_gravity(0, 0, &n, NULL);
    CHECK(g.magnitude > n.gamma && fabs(g.magnitude - n.gamma) / n.gamma < 2e-3);
    mech_earth_gravity_sphere(&EARTH, 90, 0, &g, NULL);
    mech_earth_normal_gravity(90, 0, &n, NULL);
    CHECK(g.magnitude < n.gamma && fabs(g.magnitude - n.gamma) / n.gamma < 2e-3);
}

/* The 1980 International Gravity Formula (a series) against a second method,
 * GRS 80's closed Somigliana formula with GRS 80's own constants (Moritz 1980:
 * gamma_e = 9.7803267715, k = 0.001931851353, e^2 = 0.00669438002290): the
 * series is stated good to 0.1 mGal = 1e-6 m/s^2 (measured: 6.8e-7 at most);
 * at the equator it is gamma_e's rounded 9.780327 exactly, at the pole
 * 9.780327 x 1.0053024 (sin^2 2L = 0 at both). */
static void check_igf1980(void)
{
    struct mech_normal_gravity n;
    double worst = 0;
    for (int i = -90; i <= 90; i++) {
        CHECK_EQ_INT(mech_earth_normal_gravity(i, 0, &n, NULL), MECH_OK);
        double s2 = sin(i * MECH_PI / 180) * sin(i * MECH_PI / 180);
        double closed = 9.7803267715 * (1 + 0.001931851353 * s2) / sqrt(1 - 0.00669438002290 * s2);
        worst = fmax(worst, fabs(n.igf1980 - closed));
    }
    printf("IGF 1980 series vs GRS 80 closed Somigliana: worst %.3g m/s^2\n", worst);
    CHECK(worst < 1e-6);
    CHECK(worst > 1e-8); /* it is a series, not the closed formula */
    CHECK_EQ_INT(mech_earth_normal_gravity(0, 0, &n, NULL), MECH_OK);
    CHECK_CLOSE(n.igf1980, 9.780327, 1e-16, 0);
    CHECK_EQ_INT(mech_earth_normal_gravity(-90, 500, &n, NULL), MECH_OK);
    CHECK_CLOSE(n.igf1980, 9.780327 * 1.0053024, 2e-16, 0); /* sea level: h plays no part */
}

static void check_refusals(void)
{
    struct mech_earth_gravity g;
    struct mech_normal_gravity n;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 90.5, 0, &g, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "latitude_deg") == 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_earth_gravity_sphere(&EARTH, 10, 2e5, &g, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "height") == 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_earth_normal_gravity(NAN, 0, &n, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "latitude_deg") == 0);
    struct mech_earth_sphere big = {MECH_EARTH_GM, 1e9, MECH_EARTH_OMEGA};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_earth_gravity_sphere(&big, 10, 0, &g, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "radius") == 0);
    /* no rotation: no deviation anywhere */
    struct mech_earth_sphere still = {MECH_EARTH_GM, MECH_EARTH_RADIUS_MEAN, 0};
    CHECK_EQ_INT(mech_earth_gravity_sphere(&still, 45, 0, &g, NULL), MECH_OK);
    CHECK(g.deviation == 0 && g.deviation_max == 0 && g.reduction == 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_sincos();
    check_equator_and_pole();
    check_against_effective_force();
    check_deviation_peak();
    check_somigliana();
    check_igf1980();
    check_refusals();
    TEST_MAIN_END();
}
