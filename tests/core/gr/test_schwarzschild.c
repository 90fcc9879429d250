/* test_schwarzschild.c — mech/gr/schwarzschild.h: static clocks and red shift
 * (closed forms, and the series 1 - sqrt(1 - x) = x/2 + x^2/8 + x^3/16 for
 * x = 1e-12 where the naive formula keeps no digit), circular orbits at the
 * ISCO and inside the photon sphere, the extrema of V_eff (L = 4: r = 4, 12,
 * the textbook case), and the GPS clock budget against values computed
 * independently with 40-digit arithmetic (mpmath). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/gr/schwarzschild.h"
#include "mech/base/constants.h"
#include "testlib.h"

/* Binding efficiency 1 - E of circular orbits (50-digit Decimal of
 * 1 - (1 - 2/r)/sqrt(1 - 3/r)): r = 1e6: 4.99999624998312495e-7 (the direct
 * formula in doubles keeps only ~10 digits here), r = 10: 0.0438171125324850880,
 * r = 4.5: 0.0377495513506237258, r = 3.5: -0.133893419027681682 (unbound),
 * the ISCO: 1 - sqrt(8/9) = 0.0571909584179366341, and 0 at r = 4; the uniform
 * field red shift g h / c^2 = m (r - R)/R^2 beside the exact gravitational part. */
static void test_binding_and_uniform_field(void)
{
    struct mech_schw_circular co;
    const double r[5] = {1e6, 10, 4.5, 3.5, 6};
    const double want[5] = {4.9999962499831249e-7, 0.043817112532485088, 0.037749551350623726,
                            -0.13389341902768168, 0.057190958417936634};
    for (int i = 0; i < 5; i++) {
        CHECK_EQ_INT(mech_schw_circular_orbit(r[i], &co, NULL), MECH_OK);
        CHECK_CLOSE(co.binding_efficiency, want[i], 2e-15, 0);
    }
    CHECK_CLOSE(MECH_SCHW_ISCO_BINDING_EFFICIENCY, 1.0 / (9.0 + 6.0 * sqrt(2.0)), 2e-16, 0);
    CHECK_EQ_INT(mech_schw_circular_orbit(4.0, &co, NULL), MECH_OK);
    CHECK_CLOSE(co.binding_efficiency, 0.0, 0, 0);
    /* Far out 1 - E -> 1/(2r) (Newton: binding energy GMm/(2r)). */
    CHECK_EQ_INT(mech_schw_circular_orbit(1e200, &co, NULL), MECH_OK);
    CHECK_CLOSE(co.binding_efficiency, 0.5e-200, 1e-15, 0);

    /* Pound-Rebka: a 22.5 m tower on the Earth, R = 6371000 m, GM/c^2 =
     * 3.986004418e14/299792458^2 m: g h/c^2 = m h/R^2 = 2.4570e-15; the exact
     * gravitational part differs from it by ~h/R = 3.5e-6 relative. The orbit
     * radius must allow a circular orbit, so compare at r = R + 22.5 m with the
     * static part only (gravitational). */
    struct mech_schw_clock_compare cc;
    const double m = MECH_EARTH_GM / (MECH_C * MECH_C);
    CHECK_EQ_INT(mech_schw_clock_compare(6371000.0, 6371022.5, m, &cc, NULL), MECH_OK);
    CHECK_CLOSE(cc.uniform_field_gravitational, m * 22.5 / (6371000.0 * 6371000.0), 4e-16, 0);
    CHECK_CLOSE(cc.uniform_field_gravitational, cc.gravitational, 1e-5, 0);
    CHECK(fabs(cc.uniform_field_gravitational / cc.gravitational - 1) > 1e-7); /* an approximation */
}

int main(void)
{
    gsl_set_error_handler_off();
    test_binding_and_uniform_field();
    struct mech_error e;
    struct mech_schw_static s;
    struct mech_schw_circular co;

    /* r = 10 GM/c^2: dtau/dt = sqrt(0.8), z = 1/sqrt(0.8) - 1 */
    CHECK(mech_schw_static_clock(10.0, &s, NULL) == MECH_OK);
    CHECK_CLOSE(s.rate, sqrt(0.8), 1e-15, 0);
    CHECK_CLOSE(s.redshift, 1.0 / sqrt(0.8) - 1.0, 1e-15, 0);
    CHECK_CLOSE(s.rate_deficit, 1.0 - sqrt(0.8), 1e-15, 0);

    /* r = 2e12: x = 1e-12; deficit = x/2 + x^2/8 + ..., z = x/2 + 3x^2/8 + ... */
    CHECK(mech_schw_static_clock(2e12, &s, NULL) == MECH_OK);
    CHECK_CLOSE(s.rate_deficit, 0.5e-12 + 1e-24 / 8, 1e-15, 0);
    CHECK_CLOSE(s.redshift, 0.5e-12 + 3e-24 / 8, 1e-15, 0);
    /* r = 2e30: x = 1e-30, still full precision */
    CHECK(mech_schw_static_clock(2e30, &s, NULL) == MECH_OK);
    CHECK_CLOSE(s.redshift, 0.5e-30, 1e-15, 0);
    CHECK(s.rate == 1.0);

    /* horizon and inside: typed error naming r */
    mech_error_clear(&e);
    CHECK(mech_schw_static_clock(2.0, &s, &e) == MECH_EDOMAIN);
    CHECK(e.param[0] == 'r' && e.param[1] == 0);
    CHECK(mech_schw_static_clock(-1.0, &s, NULL) == MECH_EDOMAIN);
    CHECK(mech_schw_static_clock(NAN, &s, NULL) == MECH_EDOMAIN);
    CHECK(mech_schw_static_clock(1.0 / 0.0, &s, NULL) == MECH_EDOMAIN);

    /* ISCO: rate sqrt(1/2), E = sqrt(8/9), L = sqrt(12), local speed c/2 */
    CHECK(mech_schw_circular_orbit(6.0, &co, NULL) == MECH_OK);
    CHECK(co.stability == MECH_SCHW_ORBIT_MARGINAL);
    CHECK_CLOSE(co.rate, sqrt(0.5), 1e-15, 0);
    CHECK_CLOSE(co.energy, sqrt(8.0 / 9.0), 1e-15, 0);
    CHECK_CLOSE(co.angular_momentum, sqrt(12.0), 1e-15, 0);
    CHECK_CLOSE(co.local_speed, 0.5, 1e-15, 0);
    CHECK_CLOSE(co.period_t, 2 * MECH_PI * pow(6.0, 1.5), 1e-15, 0);
    /* the circular E and L sit at the extremum of V: V(r) = E^2, V'(r) = 0 */
    CHECK(mech_schw_circular_orbit(10.0, &co, NULL) == MECH_OK);
    CHECK(co.stability == MECH_SCHW_ORBIT_STABLE);
    CHECK_CLOSE(mech_schw_veff_massive(10.0, co.angular_momentum), co.energy * co.energy, 1e-15, 0);
    double h = 1e-5;
    double dV = (mech_schw_veff_massive(10.0 + h, co.angular_momentum) -
                 mech_schw_veff_massive(10.0 - h, co.angular_momentum)) /
                (2 * h);
    CHECK(fabs(dV) < 1e-10);
    CHECK(mech_schw_circular_orbit(4.0, &co, NULL) == MECH_OK);
    CHECK(co.stability == MECH_SCHW_ORBIT_UNSTABLE);
    CHECK_CLOSE(co.local_speed, 1.0 / sqrt(2.0), 1e-15, 0);
    CHECK(mech_schw_circular_orbit(3.0, &co, NULL) == MECH_OK);
    CHECK(co.stability == MECH_SCHW_ORBIT_NONE);
    CHECK(isnan(co.rate));
    CHECK(mech_schw_circular_orbit(2.5, &co, NULL) == MECH_OK);
    CHECK(co.stability == MECH_SCHW_ORBIT_NONE);
    CHECK(mech_schw_circular_orbit(1.5, &co, NULL) == MECH_EDOMAIN);
    /* a far orbit: deficit 3/(2r) + 9/(8 r^2) */
    CHECK(mech_schw_circular_orbit(3e15, &co, NULL) == MECH_OK);
    CHECK_CLOSE(co.rate_deficit, 0.5e-15 + 1e-30 / 8.0, 1e-15, 0);

    /* V_eff extrema: L = 4 -> r = 4 (max) and 12 (min) (Hartle §9.3) */
    double ru, rs;
    CHECK_EQ_INT(mech_schw_veff_extrema(4.0, &ru, &rs), 2);
    CHECK_CLOSE(ru, 4.0, 1e-15, 0);
    CHECK_CLOSE(rs, 12.0, 1e-15, 0);
    CHECK(mech_schw_veff_extrema(sqrt(12.0) * (1 + 4e-16), &ru, &rs) >=
          1); /* L^2 = 12 up to rounding */
    CHECK_CLOSE(ru, 6.0, 1e-7, 0);
    CHECK_CLOSE(rs, 6.0, 1e-7, 0);
    CHECK_EQ_INT(mech_schw_veff_extrema(3.0, &ru, &rs), 0);
    CHECK(isnan(ru) && isnan(rs));
    /* huge L: unstable orbit tends to the photon sphere, 3 + 9/L^2 */
    CHECK_EQ_INT(mech_schw_veff_extrema(1e8, &ru, &rs), 2);
    CHECK_CLOSE(ru, 3.0 + 9e-16, 1e-15, 0);
    CHECK_CLOSE(rs, 1e16 - 6.0, 1e-15, 0);
    CHECK_CLOSE(mech_schw_veff_photon(3.0), 1.0 / 27.0, 1e-15, 0);
    CHECK_CLOSE(MECH_SCHW_CRITICAL_IMPACT, 3.0 * sqrt(3.0), 1e-16, 0);

    /* GPS: ground R = 6371 km, orbit r = 26561.75 km, GM_earth = 3.986004418e14,
     * c = 299792458; references from mpmath at 40 digits: +45.719163359084836,
     * -7.2131245668393341, +38.506038792245501 us/day */
    const double c = MECH_C, GMe = MECH_EARTH_GM, m = GMe / (c * c);
    struct mech_schw_clock_compare cc;
    CHECK(mech_schw_clock_compare(6371000.0, 26561750.0, m, &cc, NULL) == MECH_OK);
    const double day = 86400e6;
    CHECK_CLOSE(cc.gravitational * day, 45.719163359084836, 1e-13, 0);
    CHECK_CLOSE(cc.velocity * day, -7.2131245668393341, 1e-13, 0);
    CHECK_CLOSE(cc.net * day, 38.506038792245501, 1e-13, 0);
    CHECK_CLOSE(cc.net, 4.456717452806192e-10, 1e-13, 0);
    /* first order agrees to O(x^2) ~ 1e-9 relative */
    CHECK_CLOSE(cc.first_order_gravitational, cc.gravitational, 2e-9, 0);
    CHECK_CLOSE(cc.first_order_velocity, cc.velocity, 2e-9, 0);
    /* net in closed form to first order: GM/c^2 (1/R - 3/(2r)) = 4.4567174476e-10 */
    CHECK_CLOSE(cc.net, GMe / (c * c) * (1.0 / 6371000.0 - 1.5 / 26561750.0), 2e-9, 0);
    CHECK_CLOSE(cc.first_order_net, GMe / (c * c) * (1.0 / 6371000.0 - 1.5 / 26561750.0), 1e-15, 0);
    /* equatorial radius: 38.438737351513172 us/day */
    CHECK(mech_schw_clock_compare(6378137.0, 26561750.0, m, &cc, NULL) == MECH_OK);
    CHECK_CLOSE(cc.net * day, 38.438737351513172, 1e-13, 0);
    mech_error_clear(&e);
    CHECK(mech_schw_clock_compare(1.0, 100.0, 1.0, &cc, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "reference_r"));
    mech_error_clear(&e);
    CHECK(mech_schw_clock_compare(100.0, 2.9, 1.0, &cc, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "r"));
    mech_error_clear(&e);
    CHECK(mech_schw_clock_compare(100.0, 200.0, 0.0, &cc, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "M"));
    /* the same radii in metres and in GM/c^2 (m = 2, lengths doubled) agree */
    CHECK(mech_schw_clock_compare(20.0, 21.0, 2.0, &cc, NULL) == MECH_OK);
    CHECK_CLOSE(cc.net, sqrt(1.0 - 3.0 / 10.5) / sqrt(1.0 - 2.0 / 10.0) - 1.0, 1e-14, 0);
    /* ... and at the ends of the double range, where r R would underflow or overflow */
    struct mech_schw_clock_compare c1, c2, c3;
    CHECK(mech_schw_clock_compare(10.0, 21.0, 1.0, &c1, NULL) == MECH_OK);
    CHECK(mech_schw_clock_compare(10e-300, 21e-300, 1e-300, &c2, NULL) == MECH_OK);
    CHECK(mech_schw_clock_compare(10e300, 21e300, 1e300, &c3, NULL) == MECH_OK);
    CHECK_CLOSE(c2.gravitational, c1.gravitational, 1e-15, 0);
    CHECK_CLOSE(c3.gravitational, c1.gravitational, 1e-15, 0);
    CHECK_CLOSE(c2.net, c1.net, 1e-15, 0);
    CHECK_CLOSE(c3.net, c1.net, 1e-15, 0);

    /* Clocks near the reference: the tower and the ground.
     * R = 6371000 m, m = GM_earth/c^2 as the API forms it (the double 0x1.22a76c6285c0bp-8),
     * r = R + 1 cm, 1 m, 22.5 m (Pound-Rebka), 1 km, the GPS orbit, and r = 1.5 R + 1 m and
     * 1.5 R where net changes sign. Expected values: Python's decimal at 80 digits from the
     * same input doubles, by the definitions themselves (cancellation costs ~18 of the 80
     * digits): a = sqrt(1 - u), gravitational = a(2m/r)/a(2m/R) - 1, velocity =
     * (a(3m/r) - a(2m/r))/a(2m/R), net = a(3m/r)/a(2m/R) - 1, first-order gravitational
     * m (1/R - 1/r) and net m (1/R - 3/(2r)). The old code (rates of radii already
     * divided by m, subtracted) was off by 6.5e-8 relative at 1 cm, 1.5e-9 at 1 m,
     * 7.2e-11 at 22.5 m, and got a net of ~1e-22 instead of 0 at r = 1.5 R. */
    {
        const double mE = 0x1.22a76c6285c0bp-8;
        CHECK(mE == m);
        static const struct {
            double r, grav, vel, net, fo_grav, fo_net;
        } near[] = {
            {6371000.01, 1.0926502008728e-18, -3.4806372932843523e-10, -3.4806372823578506e-10,
             1.0926501993515525e-18, -3.4806372769061746e-10},
            {6371001, 1.0926500555067757e-16, -3.4806367524225754e-10, -3.4806356597725195e-10,
             1.0926500539855283e-16, -3.4806356543208461e-10},
            {6371022.5, 2.4584543284281855e-15, -3.4806250064759485e-10, -3.480600421932664e-10,
             2.4584543250053934e-15, -3.4806004164810521e-10},
            {6372000, 1.0924787502014035e-13, -3.4800910593719327e-10, -3.4789985806217313e-10,
             1.0924787486804543e-13, -3.4789985751729065e-10},
            {26561750, 5.2915698332274115e-10, -8.3485238042121916e-11, 4.456717452806192e-10,
             5.2915698272602329e-10, 4.4567174475944222e-10},
            {9556501, 2.3204253507809614e-10, -2.320424622347553e-10, 7.2843340844977913e-17,
             2.3204253478195566e-10, 7.2843340743561425e-17},
        };
        for (size_t i = 0; i < sizeof near / sizeof near[0]; i++) {
            CHECK(mech_schw_clock_compare(6371000.0, near[i].r, mE, &cc, NULL) == MECH_OK);
            CHECK_CLOSE(cc.gravitational, near[i].grav, 1e-14, 0);
            CHECK_CLOSE(cc.velocity, near[i].vel, 1e-14, 0);
            CHECK_CLOSE(cc.net, near[i].net, 1e-14, 0);
            CHECK_CLOSE(cc.first_order_gravitational, near[i].fo_grav, 1e-14, 0);
            CHECK_CLOSE(cc.first_order_net, near[i].fo_net, 1e-14, 0);
        }
        /* r = 1.5 R: the orbit's time dilation cancels the height gain exactly */
        CHECK(mech_schw_clock_compare(6371000.0, 9556500.0, mE, &cc, NULL) == MECH_OK);
        CHECK(cc.net == 0.0 && cc.first_order_net == 0.0);
        CHECK_CLOSE(cc.gravitational, 2.3204248651586892e-10, 1e-14, 0);
        /* Pound-Rebka closed form: g h / c^2 with g = GM/R^2, to O(h/R) ~ 3.5e-6 */
        CHECK(mech_schw_clock_compare(6371000.0, 6371022.5, mE, &cc, NULL) == MECH_OK);
        CHECK_CLOSE(cc.gravitational,
                    MECH_EARTH_GM / (6371000.0 * 6371000.0) * 22.5 / (MECH_C * MECH_C),
                    1e-5, 0);
    }
    TEST_MAIN_END();
}
