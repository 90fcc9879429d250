/* test_tides.c — tidal acceleration (notes §1.4) against an independent
 * method: the gradient of the tidal potential's Legendre series
 *   Phi_tide = -GM/d sum_{n>=2} (r/d)^n P_n(cos theta)
 * summed to convergence (radial GM/d² sum n u^(n-1) P_n(c), tangential
 * -GM/d² s sum u^(n-1) P_n'(c)), for r/d from 0.5 down to 1e-10; the direct
 * difference of the two pulls in long double where it still has the digits;
 * the departure from first order against the terms n >= 3 at r/d = 1e-10 (where
 * subtracting doubles would leave no digit); the equilibrium tide heights
 * 0.54 m and 0.25 m of the notes; and refused inputs. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/frames/earth.h"
#include "mech/base/constants.h"
#include "mech/frames/tides.h"
#include "testlib.h"

/* Legendre-series tidal acceleration in units of GM/d²: rad, tan; and the
 * sum of the terms n >= 3 alone (the departure from first order). */
static void legendre(double u, double c, double s, int nmax, double *rad, double *tan_,
                     double *rad3, double *tan3)
{
    /* long double accumulators; P_n by Bonnet's recursion, P_n' from
     * (1 - c²) P_n' = n (P_{n-1} - c P_n), or via recursion P_n' = P_{n-2}' + (2n-1) P_{n-1} */
    long double p0 = 1, p1 = c, dp0 = 0, dp1 = 1, un = u; /* un = u^(n-1) for n = 2 */
    long double sr = 0, st = 0, tr = 0, tt = 0;
    for (int n = 2; n <= nmax; n++) {
        long double p2 = ((2 * n - 1) * c * p1 - (n - 1) * p0) / n;
        long double dp2 = dp0 + (2 * n - 1) * p1;
        sr += n * un * p2;
        st += -s * un * dp2;
        if (n >= 3) {
            tr += n * un * p2;
            tt += -s * un * dp2;
        }
        p0 = p1;
        p1 = p2;
        dp0 = dp1;
        dp1 = dp2;
        un *= u;
    }
    *rad = (double)sr;
    *tan_ = (double)st;
    *rad3 = (double)tr;
    *tan3 = (double)tt;
}

static void check_series(void)
{
    const double us[] = {0.5, 0.2, 0.05, 1.6e-2, 1e-3, 1e-6, 1e-10};
    const double thetas[] = {0, 10, 30, 45, 70, 110, 135, 160, 180};
    double worst = 0, worst_tail = 0;
    for (size_t i = 0; i < sizeof us / sizeof us[0]; i++)
        for (size_t j = 0; j < sizeof thetas / sizeof thetas[0]; j++) {
            double u = us[i], th = thetas[j];
            double d = MECH_MOON_DISTANCE, r = u * d, gm = 4.9e12;
            struct mech_tide_acceleration a;
            CHECK_EQ_INT(mech_tide_acceleration(gm, d, r, th, &a, NULL), MECH_OK);
            double s, c;
            mech_sincos_deg(th, &s, &c);
            double rad, tan_, r3 = 0, t3 = 0;
            legendre(a.u, c, s, 200, &rad, &tan_, &r3, &t3);
            double pull = gm / d / d;
            double mag = hypot(rad, tan_) * pull;
            double er = fabs(a.exact.radial - rad * pull) / mag;
            double et = fabs(a.exact.tangential - tan_ * pull) / mag;
            if (er > worst) worst = er;
            if (et > worst) worst = et;
            /* a few ulp: 4e-16 when the first order dominates (u < 0.05), 1e-15 beyond */
            double tol = u < 0.05 ? 4e-16 : 1e-15;
            CHECK(er < tol && et < tol);
            /* components away from their zeros: relative to themselves */
            if (fabs(rad) > 0.1 * hypot(rad, tan_))
                CHECK_CLOSE(a.exact.radial, rad * pull, 2e-15, 0);
            if (fabs(tan_) > 0.1 * hypot(rad, tan_))
                CHECK_CLOSE(a.exact.tangential, tan_ * pull, 2e-15, 0);
            /* the departure from first order against the terms n >= 3 */
            double tail = hypot(r3, t3) * pull;
            double ed = hypot(a.difference.radial - r3 * pull, a.difference.tangential - t3 * pull);
            if (ed / tail > worst_tail) worst_tail = ed / tail;
            CHECK(ed < 1e-14 * tail);
            /* along/perpendicular are the same vector in other axes */
            CHECK_CLOSE(a.exact.along, a.exact.radial * c - a.exact.tangential * s, 0,
                        1e-15 * a.magnitude);
            CHECK_CLOSE(a.exact.perpendicular, a.exact.radial * s + a.exact.tangential * c, 0,
                        1e-15 * a.magnitude);
            CHECK_CLOSE(a.magnitude, mag, 2e-15, 0);
        }
    printf("exact tidal acceleration vs Legendre series, u = 0.5 .. 1e-10: worst |err|/|a| = %.3g; "
           "exact - first order vs the terms n >= 3: worst rel %.3g\n",
           worst, worst_tail);
}

/* At u = 1e-10 the departure from first order is 1e-10 of the acceleration:
 * computed directly it keeps its digits; the n = 3 term is its leading part
 * (n = 4 adds a relative u). Subtracting the pulls in double loses ~10 digits. */
static void check_far(void)
{
    const double d = 1e16, r = 1e6, gm = 1e20; /* u = 1e-10 */
    const double thetas[] = {0, 20, 40, 60, 80, 100, 140, 180};
    double worst_diff = 0, worst_naive = 0;
    for (size_t j = 0; j < sizeof thetas / sizeof thetas[0]; j++) {
        double th = thetas[j], s, c;
        mech_sincos_deg(th, &s, &c);
        struct mech_tide_acceleration a;
        CHECK_EQ_INT(mech_tide_acceleration(gm, d, r, th, &a, NULL), MECH_OK);
        double rad, tan_, r3 = 0, t3 = 0;
        legendre(a.u, c, s, 10, &rad, &tan_, &r3, &t3);
        double pull = gm / d / d, u = a.u;
        double scale = pull * u;
        /* first order closed forms */
        CHECK_CLOSE(a.first_order.radial, scale * (3 * c * c - 1), 1e-15, 1e-16 * scale);
        CHECK_CLOSE(a.first_order.tangential, -1.5 * scale * sin(2 * th * MECH_PI / 180), 1e-15,
                    4e-16 * scale);
        CHECK_CLOSE(a.first_order.along, 2 * scale * c, 1e-15, 0);
        CHECK_CLOSE(a.first_order.perpendicular, -scale * s, 1e-15, 0);
        /* differences vs the series without its n = 2 term */
        double e1 = fabs(a.difference.radial - r3 * pull),
               e2 = fabs(a.difference.tangential - t3 * pull);
        double ref = hypot(r3, t3) * pull;
        if (e1 / ref > worst_diff) worst_diff = e1 / ref;
        if (e2 / ref > worst_diff) worst_diff = e2 / ref;
        CHECK(e1 < 2e-15 * ref && e2 < 2e-15 * ref);
        CHECK_CLOSE(a.relative_difference, ref / (scale * sqrt(1 + 3 * c * c)), 1e-14, 0);
        /* exact = first + diff to full precision */
        CHECK_CLOSE(a.exact.radial, rad * pull, 1e-15, 1e-16 * scale);
        /* the naive double subtraction: for the record */
        double px = d - r * c, py = -r * s, dd = hypot(px, py);
        double ax = gm * px / (dd * dd * dd) - gm / (d * d), ay = gm * py / (dd * dd * dd);
        double nr = ax * c + ay * s;
        double en = fabs(nr - a.exact.radial) / (a.magnitude);
        if (en > worst_naive) worst_naive = en;
    }
    printf("u = 1e-10: departure from first order vs the Legendre terms n >= 3: worst rel %.3g; "
           "naive double subtraction of the pulls: rel error %.3g\n",
           worst_diff, worst_naive);
    CHECK(worst_naive > 1e-9); /* what the rearrangement avoids */
}

/* Moderate u: direct subtraction in long double has ~19 - log10(1/u) digits. */
static void check_long_double(void)
{
    const double gm = 4.9e12, d = MECH_MOON_DISTANCE, r = MECH_EARTH_RADIUS_MEAN;
    for (double th = 0; th <= 180; th += 15) {
        double s, c;
        mech_sincos_deg(th, &s, &c);
        struct mech_tide_acceleration a;
        CHECK_EQ_INT(mech_tide_acceleration(gm, d, r, th, &a, NULL), MECH_OK);
        long double px = (long double)d - (long double)r * c, py = -(long double)r * s;
        long double dd2 = px * px + py * py, dd = sqrtl(dd2);
        long double ax = gm * px / (dd2 * dd) - gm / ((long double)d * d),
                    ay = gm * py / (dd2 * dd);
        double rad = (double)(ax * c + ay * s), tan_ = (double)(-ax * s + ay * c);
        CHECK_CLOSE(a.exact.radial, rad, 0, 3e-15 * a.magnitude);
        CHECK_CLOSE(a.exact.tangential, tan_, 0, 3e-15 * a.magnitude);
        CHECK_CLOSE(a.exact.along, (double)ax, 0, 3e-15 * a.magnitude);
        CHECK_CLOSE(a.exact.perpendicular, (double)ay, 0, 3e-15 * a.magnitude);
    }
}

static void check_heights(void)
{
    const double gmoon = MECH_GRAVITATIONAL_CONSTANT * MECH_MOON_MASS;
    struct mech_tide_height hm, hs;
    CHECK_EQ_INT(mech_tide_height(gmoon, MECH_EARTH_GM, MECH_MOON_DISTANCE, MECH_EARTH_RADIUS_MEAN,
                                  0, &hm, NULL),
                 MECH_OK);
    CHECK_EQ_INT(mech_tide_height(MECH_SUN_GM, MECH_EARTH_GM, MECH_AU, MECH_EARTH_RADIUS_MEAN, 90,
                                  &hs, NULL),
                 MECH_OK);
    printf("equilibrium tide range: Moon %.6f m, Sun %.6f m (notes: 0.54, 0.25)\n", hm.range,
           hs.range);
    CHECK_CLOSE(hm.range, 0.54, 0, 0.006);
    CHECK_CLOSE(hs.range, 0.25, 0, 0.006);
    /* closed form: 3 M r^4 / (2 M_E d^3) */
    double R = MECH_EARTH_RADIUS_MEAN;
    CHECK_CLOSE(hm.range,
                1.5 * gmoon / MECH_EARTH_GM * R * R * R * R /
                    (MECH_MOON_DISTANCE * MECH_MOON_DISTANCE * MECH_MOON_DISTANCE),
                1e-14, 0);
    CHECK_CLOSE(hm.height, hm.high, 1e-15, 0);
    CHECK_CLOSE(hs.height, hs.low, 1e-15, 0);
    CHECK_CLOSE(hm.high - hm.low, hm.range, 1e-15, 0);
    /* the notes' own constants: 6367 km, 7.35e22/5.97e24, 3.84e8 m */
    struct mech_tide_height hn;
    CHECK_EQ_INT(mech_tide_height(7.35e22 / 5.97e24, 1, 3.84e8, 6.367e6, 0, &hn, NULL), MECH_OK);
    CHECK_CLOSE(hn.range, 0.54, 0, 0.005);
    /* mean over the sphere is zero: integral of (3c² - 1) d(cos) = 0; Gauss-Legendre 3 points */
    const double x[3] = {-sqrt(0.6), 0, sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double mean = 0;
    for (int i = 0; i < 3; i++) {
        CHECK_EQ_INT(mech_tide_height(gmoon, MECH_EARTH_GM, MECH_MOON_DISTANCE, R,
                                      acos(x[i]) * 180 / MECH_PI, &hn, NULL),
                     MECH_OK);
        mean += w[i] * hn.height;
    }
    CHECK(fabs(mean) < 1e-15);
    /* the tidal acceleration is the gradient of the tide potential g h: the
     * tangential first order -3/2 GM r/d³ sin 2theta = -(g/r) dh/dtheta */
    struct mech_tide_acceleration a;
    CHECK_EQ_INT(mech_tide_acceleration(gmoon, MECH_MOON_DISTANCE, R, 30, &a, NULL), MECH_OK);
    double g = MECH_EARTH_GM / (R * R);
    double dhdth = -1.5 * hm.high * sin(2 * 30 * MECH_PI / 180); /* h = base (3c²-1)/2 */
    CHECK_CLOSE(a.first_order.tangential, g / R * dhdth, 1e-14, 0);
}

static void check_refusals(void)
{
    struct mech_tide_acceleration a;
    struct mech_tide_height h;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tide_acceleration(1e12, 6e6, 6.4e6, 0, &a, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "distance") == 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tide_acceleration(1e12, 1e8, 6.4e6, 181, &a, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "angle_deg") == 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tide_acceleration(0, 1e8, 6.4e6, 10, &a, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "gm") == 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tide_height(1, 0, 1e8, 6.4e6, 10, &h, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "gm_earth") == 0);
    /* a point almost touching the body: u = 1 - 1e-12 at theta = 0; still
     * exact: a_along = GM [1/(d - r)² - 1/d²] */
    double d = 1e8, r = d * (1 - 1e-12);
    CHECK_EQ_INT(mech_tide_acceleration(1e10, d, r, 0, &a, NULL), MECH_OK);
    double gap = d - r;
    CHECK_CLOSE(a.exact.along, 1e10 / (gap * gap) - 1e10 / (d * d), 1e-9, 0);
    /* and at 180 deg: GM [1/(d + r)² - 1/d²] = -(3/4) GM/d² (u = 1) */
    CHECK_EQ_INT(mech_tide_acceleration(1e10, d, r, 180, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.exact.along, 1e10 / ((d + r) * (d + r)) - 1e10 / (d * d), 1e-14, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_series();
    check_far();
    check_long_double();
    check_heights();
    check_refusals();
    TEST_MAIN_END();
}
