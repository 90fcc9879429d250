/* test_scenes_first_order.c — the chapter-1 closed forms
 * (core/frames/scenes_first_order.c) against the notes' worked example and
 * against a second method:
 *   falling object, h = 100 m, lat 32 deg, W = 7.2921159e-5: x_east =
 *     (W cos lat / 3) sqrt(8 h^3 / g) = 0.0186182 m (notes §1.4; 1.9 cm),
 *     and W cos(lat) g t^3 / 3 at t = sqrt(2 h / g) (the same x_1, by time);
 *   vertical shot: west (4/3) W cos lat sqrt(8 h^3 / g), and the series
 *     landing of mech_scene_ballistic_formulas (an independent code path:
 *     r_1 = -w x (v0 t^2 + g t^3 / 3) at the linearised landing time);
 *   cannonball fired due east: the notes' problems 4-5 against the same
 *     series landing; near elevation 60 deg (where the range increase
 *     vanishes) against the cancellation-free 4 W cos(lat) v0^3 sin(a)
 *     (2 cos a - 1)(2 cos a + 1) / (3 g^2);
 *   out-of-range input gives NaN, never a crash.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/frames/scenes.h"
#include "mech/frames/scenes_first_order.h"
#include "testlib.h"

static const double G0 = 9.80665;
static const double W_NOTES = 7.2921159e-5; /* the notes' Earth rate, rad/s */

static struct mech_scene_ballistic_result R;

/* The first-order landing by the series code of core/frames/scenes.c. */
static int series_landing(double lat_deg, struct mech_vec3 r0, struct mech_vec3 v0,
                          struct mech_scene_landing *fo)
{
    struct mech_scene_ballistic s;
    memset(&s, 0, sizeof s);
    s.latitude_deg = lat_deg;
    s.g = G0;
    s.omega = W_NOTES;
    s.r0 = r0;
    s.v0 = v0;
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_scene_ballistic_formulas(&s, 0, &R, &e) != MECH_OK) return 0;
    *fo = R.first_order;
    return 1;
}

static void test_drop(void)
{
    const double h = 100.0, lat = 32.0 * MECH_PI / 180.0;
    const double x = mech_scene_drop_east(h, G0, W_NOTES, 32.0);
    CHECK_CLOSE(x, 0.0186182, 0, 5e-8); /* the notes' value, 6 digits */
    const double t = sqrt(2.0 * h / G0);
    CHECK_CLOSE(x, W_NOTES * cos(lat) * G0 * t * t * t / 3.0, 1e-14, 0);
    struct mech_scene_landing fo = {0, {0, 0, 0}};
    CHECK(series_landing(32.0, mech_vec3_make(0, 0, h), mech_vec3_make(0, 0, 0), &fo));
    CHECK_CLOSE(x, fo.r.x, 1e-13, 0);
    /* extremes: no height, the poles (cos 90 deg = 6e-17: round-off, not exactly 0), W = 0 */
    CHECK_CLOSE(mech_scene_drop_east(0.0, G0, W_NOTES, 32.0), 0.0, 0, 0);
    CHECK_CLOSE(mech_scene_drop_east(h, G0, W_NOTES, 90.0), 0.0, 0,
                1e-16 * mech_scene_drop_east(h, G0, W_NOTES, 0.0));
    CHECK_CLOSE(mech_scene_drop_east(h, G0, 0.0, 32.0), 0.0, 0, 0);
    CHECK_CLOSE(mech_scene_drop_east(1e5, 1e-3, 1e-2, 0.0), 1e-2 / 3.0 * sqrt(8e15 / 1e-3), 1e-14,
                0);
    CHECK(isnan(mech_scene_drop_east(-1.0, G0, W_NOTES, 32.0)));
    CHECK(isnan(mech_scene_drop_east(h, 0.0, W_NOTES, 32.0)));
    CHECK(isnan(mech_scene_drop_east(h, G0, -1e-5, 32.0)));
    CHECK(isnan(mech_scene_drop_east(h, G0, W_NOTES, 90.5)));
    CHECK(isnan(mech_scene_drop_east(NAN, G0, W_NOTES, 32.0)));
    CHECK(isnan(mech_scene_drop_east(h, INFINITY, W_NOTES, 32.0)));
}

static void test_vertical_shot(void)
{
    const double h = 100.0, lat = 32.0 * MECH_PI / 180.0;
    const double v0 = mech_scene_vertical_shot_speed(h, G0);
    CHECK_CLOSE(v0 * v0, 2.0 * G0 * h, 1e-15, 0);
    struct mech_scene_vertical_shot_first_order vs;
    mech_scene_vertical_shot_first_order(v0, G0, W_NOTES, 32.0, &vs);
    CHECK_CLOSE(vs.height, h, 2e-15, 0);
    CHECK_CLOSE(vs.flight_time, 2.0 * sqrt(2.0 * h / G0), 1e-15, 0);
    CHECK_CLOSE(vs.west, 4.0 / 3.0 * W_NOTES * cos(lat) * sqrt(8.0 * h * h * h / G0), 1e-14, 0);
    CHECK_CLOSE(vs.west, 0.0744728, 0, 5e-8); /* 4 x the drop's 1.86 cm */
    CHECK_CLOSE(vs.drop_east, mech_scene_drop_east(h, G0, W_NOTES, 32.0), 1e-15, 0);
    struct mech_scene_landing fo = {0, {0, 0, 0}};
    CHECK(series_landing(32.0, mech_vec3_make(0, 0, 0), mech_vec3_make(0, 0, v0), &fo));
    CHECK_CLOSE(-fo.r.x, vs.west, 1e-12, 0);
    CHECK_CLOSE(fo.t, vs.flight_time, 1e-14, 0);
    /* the largest shot the API allows: 1e4 m/s at g = 1e-3 (h = 5e10 m) stays finite */
    mech_scene_vertical_shot_first_order(1e4, 1e-3, 1e-2, 0.0, &vs);
    CHECK(isfinite(vs.west) && vs.west > 0);
    mech_scene_vertical_shot_first_order(-1.0, G0, W_NOTES, 32.0, &vs);
    CHECK(isnan(vs.height) && isnan(vs.west) && isnan(vs.flight_time) && isnan(vs.drop_east));
    CHECK(isnan(mech_scene_vertical_shot_speed(-1.0, G0)));
    CHECK(isnan(mech_scene_vertical_shot_speed(h, 0.0)));
}

static void test_cannonball(void)
{
    const double v0 = 300.0;
    const double lats[] = {32.0, -45.0, 0.0, 89.0};
    const double els[] = {10.0, 30.0, 45.0, 75.0};
    for (size_t i = 0; i < sizeof lats / sizeof *lats; i++)
        for (size_t j = 0; j < sizeof els / sizeof *els; j++) {
            struct mech_scene_cannonball_first_order cb;
            mech_scene_cannonball_first_order(v0, els[j], 0.0, G0, W_NOTES, lats[i], &cb);
            const double a = els[j] * MECH_PI / 180.0;
            CHECK_CLOSE(cb.t0, 2.0 * v0 * sin(a) / G0, 1e-15, 0);
            CHECK_CLOSE(cb.range, 2.0 * v0 * v0 * sin(a) * cos(a) / G0, 1e-15, 0);
            CHECK_CLOSE(cb.velocity.x, v0 * cos(a), 1e-15, 0);
            CHECK_CLOSE(cb.velocity.y, 0.0, 0, 0);
            CHECK_CLOSE(cb.velocity.z, v0 * sin(a), 1e-15, 0);
            struct mech_scene_landing fo = {0, {0, 0, 0}};
            CHECK(series_landing(lats[i], mech_vec3_make(0, 0, 0), cb.velocity, &fo));
            /* south = -y; the range increase: x beyond the zeroth-order range
             * (its subtraction loses ~R / dR of the digits: 1e-11 relative) */
            CHECK_CLOSE(cb.south_due_east, -fo.r.y, 1e-12, 1e-18);
            CHECK_CLOSE(cb.range_increase_due_east, fo.r.x - cb.range, 1e-8, 1e-12);
        }
    /* the notes' magnitudes at lat 32 deg, 45 deg elevation, 300 m/s: the
     * south deflection 4 v0^3 W sin(lat) / (2^1.5 g^2) */
    struct mech_scene_cannonball_first_order cb;
    mech_scene_cannonball_first_order(v0, 45.0, 0.0, G0, W_NOTES, 32.0, &cb);
    CHECK_CLOSE(cb.south_due_east,
                4.0 * v0 * v0 * v0 * W_NOTES * sin(32.0 * MECH_PI / 180.0) / (pow(2.0, 1.5) * G0 * G0),
                1e-14, 0);
    /* firing north: the forward direction and the launch velocity follow the azimuth */
    mech_scene_cannonball_first_order(v0, 30.0, 90.0, G0, W_NOTES, 32.0, &cb);
    CHECK_CLOSE(cb.forward.x, 0.0, 0, 1e-16);
    CHECK_CLOSE(cb.forward.y, 1.0, 1e-16, 0);
    CHECK_CLOSE(cb.velocity.y, v0 * cos(MECH_PI / 6.0), 1e-15, 0);
    CHECK_CLOSE(cb.azimuth, MECH_PI / 2.0, 1e-16, 0);
    /* near 60 deg the notes' two terms of the range increase cancel (the
     * increase is 0 at 60 deg): against an independent long-double form,
     * 2 cos(60 + d) - 1 = -sqrt(3) sin d - 2 sin^2(d/2), every digit is kept
     * (the notes' form, and even (2 cos a - 1) in doubles, lose ~1e-16/d of it) */
    const double dels[] = {1e-12, 1e-9, -1e-6, 1e-3, -5.0, 20.0};
    for (size_t k = 0; k < sizeof dels / sizeof *dels; k++) {
        const double el = 60.0 + dels[k];
        const long double d = (long double)(el - 60.0) * MECH_PI_L / 180.0L;
        const long double a = (long double)el * MECH_PI_L / 180.0L;
        const long double lat = 32.0L * MECH_PI_L / 180.0L;
        const long double tcm1 = -sqrtl(3.0L) * sinl(d) - 2.0L * sinl(0.5L * d) * sinl(0.5L * d);
        const long double want = 4.0L * W_NOTES * cosl(lat) * (long double)v0 * v0 * v0 * sinl(a) *
                                 tcm1 * (2.0L * cosl(a) + 1.0L) / (3.0L * G0 * G0);
        mech_scene_cannonball_first_order(v0, el, 0.0, G0, W_NOTES, 32.0, &cb);
        CHECK_CLOSE(cb.range_increase_due_east, (double)want, 1e-13, 0);
    }
    mech_scene_cannonball_first_order(v0, 60.0, 0.0, G0, W_NOTES, 32.0, &cb);
    CHECK(cb.range_increase_due_east == 0.0);
    /* extremes: straight up (cos a = 6e-17: finite), and bad input */
    mech_scene_cannonball_first_order(1e4, 90.0, 0.0, 1e-3, 1e-2, 0.0, &cb);
    CHECK(isfinite(cb.range) && isfinite(cb.range_increase_due_east) &&
          isfinite(cb.south_due_east));
    mech_scene_cannonball_first_order(v0, 0.0, 0.0, G0, W_NOTES, 32.0, &cb);
    CHECK(isnan(cb.t0) && isnan(cb.range_increase_due_east) && isnan(cb.velocity.x));
    mech_scene_cannonball_first_order(v0, 45.0, NAN, G0, W_NOTES, 32.0, &cb);
    CHECK(isnan(cb.range) && isnan(cb.forward.x));
    mech_scene_cannonball_first_order(v0, 45.0, 0.0, G0, W_NOTES, -91.0, &cb);
    CHECK(isnan(cb.south_due_east));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_drop();
    test_vertical_shot();
    test_cannonball();
    TEST_MAIN_END();
}
