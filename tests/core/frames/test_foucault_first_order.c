/* test_foucault_first_order.c — the Foucault pendulum's closed forms
 * (core/frames/foucault_first_order.c) against hand values:
 *   first-order rate -W sin(lat) (notes §1.4): -W / sqrt 2 at 45 deg,
 *     exactly -W / +W at the poles (-90 / 90), and cos(lat) exactly 0 there;
 *   the full turn 2 pi / (W sin lat) = sidereal day / sin(lat) (Paris,
 *     48.85 deg: 31.786 h with the notes' W = 7.2921159e-5);
 *   the release point's height l (1 - cos a) = 2 l sin^2(a/2), checked
 *     against the series l a^2/2 (1 - a^2/12) at a = 1e-6 deg, where
 *     l (1 - cos a) would keep no digit;
 *   the small-amplitude period 2 pi sqrt(l/g), the finite-amplitude period
 *     against 2 pi sqrt(l/g) (1 + a^2/16 + 11 a^4/3072);
 *   released from rest, the Airy term (3/8) (a/l)^2 W sin(lat) makes the
 *     expected rate -W sin(lat) (1 - (3/8) sin^2 a);
 *   the centrifugal estimate: 0 rate at the poles and with W = 0, at the
 *     equator W^2 / (4 omega0) + (3/32) (a/l)^2 W^2 t_end;
 *   out-of-range input gives NaN.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/frames/foucault_first_order.h"
#include "testlib.h"

static const double W_NOTES = 7.2921159e-5;

static struct mech_foucault_problem problem(double lat, double amplitude_deg)
{
    struct mech_foucault_problem p;
    memset(&p, 0, sizeof p);
    p.length = 67.0;
    p.g = 9.80665;
    p.latitude_deg = lat;
    p.omega_magnitude = W_NOTES;
    p.mass = 28.0;
    p.amplitude_deg = amplitude_deg;
    p.azimuth_deg = 30.0;
    return p;
}

static void test_scales(void)
{
    struct mech_foucault_problem p = problem(45.0, 3.0);
    struct mech_foucault_scales s;
    mech_foucault_scales(&p, &s);
    CHECK_CLOSE(s.first_order_rate, -W_NOTES / sqrt(2.0), 1e-15, 0);
    CHECK_CLOSE(s.omega.y, W_NOTES / sqrt(2.0), 1e-15, 0);
    CHECK_CLOSE(s.omega0, sqrt(9.80665 / 67.0), 1e-15, 0);
    CHECK_CLOSE(s.small_amplitude_period, 2.0 * MECH_PI * sqrt(67.0 / 9.80665), 1e-15, 0);
    const double a = 3.0 * MECH_PI / 180.0;
    CHECK_CLOSE(s.period,
                2.0 * MECH_PI * sqrt(67.0 / 9.80665) *
                    (1.0 + a * a / 16.0 + 11.0 * pow(a, 4) / 3072.0),
                1e-9, 0); /* the next term, 173 a^6 / 737280, is 1e-9 */
    CHECK_CLOSE(s.amplitude, 67.0 * sin(a), 1e-15, 0);
    CHECK_CLOSE(s.release_position.x, 67.0 * sin(a) * cos(MECH_PI / 6.0), 1e-15, 0);
    CHECK_CLOSE(s.release_position.y, 67.0 * sin(a) * 0.5, 1e-15, 0);
    CHECK_CLOSE(s.release_position.z, 67.0 * (1.0 - cos(a)), 1e-12, 0);

    /* the height near a = 0, where 1 - cos a cancels */
    p = problem(45.0, 1e-6);
    mech_foucault_scales(&p, &s);
    const double b = 1e-6 * MECH_PI / 180.0;
    CHECK_CLOSE(s.release_position.z, 67.0 * b * b / 2.0 * (1.0 - b * b / 12.0), 1e-14, 0);
    CHECK(s.release_position.z > 0.0);

    /* the poles: exactly +-W, cos exactly 0 */
    p = problem(90.0, 3.0);
    mech_foucault_scales(&p, &s);
    CHECK(s.omega_vertical == W_NOTES && s.first_order_rate == -W_NOTES);
    CHECK(s.cos_latitude == 0.0 && s.omega.y == 0.0);
    p = problem(-90.0, 3.0);
    mech_foucault_scales(&p, &s);
    CHECK(s.omega_vertical == -W_NOTES && s.first_order_rate == W_NOTES);
    /* the equator: no precession */
    p = problem(0.0, 3.0);
    mech_foucault_scales(&p, &s);
    CHECK(s.first_order_rate == 0.0);
    CHECK(isinf(mech_foucault_full_precession_time(s.first_order_rate)));

    /* out of range */
    const double bad[][2] = {{91.0, 3.0}, {45.0, 0.0}, {45.0, 90.0}, {NAN, 3.0}};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        p = problem(bad[i][0], bad[i][1]);
        mech_foucault_scales(&p, &s);
        CHECK(isnan(s.first_order_rate) && isnan(s.period) && isnan(s.release_position.z));
    }
    p = problem(45.0, 3.0);
    p.length = 0.0;
    mech_foucault_scales(&p, &s);
    CHECK(isnan(s.omega0));
    p = problem(45.0, 3.0);
    p.omega_magnitude = 2.0;
    mech_foucault_scales(&p, &s);
    CHECK(isnan(s.omega_vertical));
}

static void test_precession(void)
{
    /* Paris: sidereal day / sin(lat) */
    struct mech_foucault_problem p = problem(48.85, 3.0);
    struct mech_foucault_scales s;
    mech_foucault_scales(&p, &s);
    const double day = 2.0 * MECH_PI / W_NOTES;
    CHECK_CLOSE(mech_foucault_full_precession_time(s.first_order_rate),
                day / sin(48.85 * MECH_PI / 180.0), 1e-15, 0);
    CHECK_CLOSE(mech_foucault_full_precession_time(s.first_order_rate) / 3600.0, 31.786, 0, 5e-4);
    CHECK(isnan(mech_foucault_full_precession_time(NAN)));

    /* released from rest: Airy's (3/8) h / l^2 with h = W sin(lat) a^2 */
    const double a = 3.0 * MECH_PI / 180.0, sl = sin(48.85 * MECH_PI / 180.0);
    const double airy = 0.375 * sin(a) * sin(a) * W_NOTES * sl;
    double next = 0;
    const double rate = mech_foucault_expected_rate(&s, W_NOTES, airy, &next);
    CHECK_CLOSE(rate, -W_NOTES * sl * (1.0 - 0.375 * sin(a) * sin(a)), 1e-15, 0);
    CHECK_CLOSE(next, airy * (a * a / 4.0 + W_NOTES * W_NOTES / (s.omega0 * s.omega0)), 1e-15, 0);
    CHECK(next < 1e-3 * fabs(airy)); /* the neglected terms are small at 3 deg */
    CHECK(isnan(mech_foucault_expected_rate(&s, W_NOTES, INFINITY, &next)) && isnan(next));
    CHECK_CLOSE(mech_foucault_expected_rate(&s, W_NOTES, 0.0, NULL), s.first_order_rate, 0, 0);
}

static void test_centrifugal(void)
{
    struct mech_foucault_problem p = problem(90.0, 3.0);
    struct mech_foucault_scales s;
    struct mech_foucault_centrifugal_effect cf;
    mech_foucault_scales(&p, &s);
    mech_foucault_centrifugal_effect(&s, W_NOTES, p.length, 1e5, &cf);
    /* the pole: isotropic, no precession effect; period W^2 (1 + 1) / (4 omega0^2) */
    CHECK_CLOSE(cf.rate, 0.0, 0, 0);
    CHECK_CLOSE(cf.relative_period, W_NOTES * W_NOTES / (2.0 * s.omega0 * s.omega0), 1e-15, 0);
    CHECK_CLOSE(cf.relative, cf.relative_period, 0, 0);

    /* the equator: dh grows with the whole run (no precession caps it) */
    p = problem(0.0, 10.0);
    mech_foucault_scales(&p, &s);
    const double T = 3600.0, a = 67.0 * sin(10.0 * MECH_PI / 180.0);
    mech_foucault_centrifugal_effect(&s, W_NOTES, p.length, T, &cf);
    const double want = W_NOTES * W_NOTES / (4.0 * s.omega0) +
                        3.0 / 32.0 * (a / 67.0) * (a / 67.0) * W_NOTES * W_NOTES * T;
    CHECK_CLOSE(cf.rate, want, 1e-15, 0);
    CHECK_CLOSE(cf.relative_rate, want / W_NOTES, 1e-15, 0);
    CHECK_CLOSE(cf.relative_period, W_NOTES * W_NOTES / (4.0 * s.omega0 * s.omega0), 1e-15, 0);

    /* mid latitude: dh capped at one precession, 1 / |W sin lat| < t_end */
    p = problem(45.0, 10.0);
    mech_foucault_scales(&p, &s);
    mech_foucault_centrifugal_effect(&s, W_NOTES, p.length, 1e9, &cf);
    const double c2 = 0.5; /* cos^2 45 */
    CHECK_CLOSE(cf.rate,
                W_NOTES * W_NOTES * c2 / (4.0 * s.omega0) +
                    3.0 / 32.0 * (a / 67.0) * (a / 67.0) * W_NOTES * c2 * sqrt(2.0),
                1e-14, 0);

    /* no rotation: nothing */
    p = problem(45.0, 10.0);
    p.omega_magnitude = 0.0;
    mech_foucault_scales(&p, &s);
    mech_foucault_centrifugal_effect(&s, 0.0, p.length, 100.0, &cf);
    CHECK(cf.rate == 0.0 && cf.relative_rate == 0.0 && cf.relative == 0.0);

    /* out of range */
    mech_foucault_centrifugal_effect(&s, W_NOTES, p.length, 0.0, &cf);
    CHECK(isnan(cf.rate) && isnan(cf.relative));
    mech_foucault_centrifugal_effect(&s, W_NOTES, -1.0, 10.0, &cf);
    CHECK(isnan(cf.relative_period));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_scales();
    test_precession();
    test_centrifugal();
    TEST_MAIN_END();
}
