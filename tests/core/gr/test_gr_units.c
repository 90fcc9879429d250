/* test_gr_units.c — mech/gr/gr_units.h: GM/c^2 and GM/c^3 of the Sun and the
 * Earth against textbook values (the Sun's Schwarzschild radius 2953.25 m and
 * GM/c^3 = 4.92549 us, IAU 2015 B3's nominal T_sun = 4.925490947641267 us with
 * GM = 1.3271244e20; the Earth's r_s = 8.870 mm), a mass in kg against the
 * Sun's GM (the IAU nominal mass 1.98847e30 kg agrees to the 2e-5 of G's
 * value), the angular-momentum conversion against a second path (a Newtonian
 * circular orbit at 1 AU: L = sqrt(GM r) in m^2/s is sqrt(r/M) in GM/c),
 * round trips, and every way the set-up refuses a mass. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/gr/gr_units.h"
#include "testlib.h"

static void test_values(void)
{
    struct mech_gr_units u;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_SUN, NAN, &u, &e), MECH_OK);
    CHECK_EQ_INT(u.has_mass, 1);
    CHECK_EQ_INT(u.geometric, 0);
    /* 1.32712440041279419e20 / 299792458^2 (40-digit Decimal) */
    CHECK_CLOSE(u.m, 1476.6250385094202, 1e-15, 0);
    CHECK_CLOSE(2.0 * u.m, 2953.25, 1e-5, 0);
    /* nominal T_sun is for GM = 1.3271244e20, 3.1e-10 below DE440's GM */
    CHECK_CLOSE(u.s, 4.925490947641267e-6, 5e-10, 0);
    CHECK_CLOSE(u.s, 4.9254909491733118e-6, 1e-15, 0); /* 40-digit Decimal */
    /* one GM/c^2 in, one out; 1 AU in GM/c^2 */
    CHECK_CLOSE(mech_gr_len_in(&u, u.m), 1.0, 1e-15, 0);
    CHECK_CLOSE(mech_gr_len_out(&u, mech_gr_len_in(&u, MECH_AU)), MECH_AU, 1e-15, 0);
    CHECK_CLOSE(mech_gr_time_out(&u, mech_gr_time_in(&u, 86400.0)), 86400.0, 1e-15, 0);
    CHECK_CLOSE(mech_gr_time_in(&u, u.s), 1.0, 1e-15, 0);
    /* L = sqrt(GM r) at r = 1 AU is sqrt(r/M) = 10065.320120407217 GM/c */
    const double L = sqrt(MECH_SUN_GM * MECH_AU);
    CHECK_CLOSE(mech_gr_ang_in(&u, L), sqrt(mech_gr_len_in(&u, MECH_AU)), 2e-15, 0);
    CHECK_CLOSE(mech_gr_ang_in(&u, L), 10065.320120407217, 2e-15, 0);
    CHECK_CLOSE(mech_gr_ang_out(&u, mech_gr_ang_in(&u, L)), L, 1e-15, 0);
    CHECK_CLOSE(mech_gr_speed_in(&u, MECH_C), 1.0, 0, 0);

    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_EARTH, NAN, &u, &e), MECH_OK);
    CHECK_CLOSE(2.0 * u.m, 8.870e-3, 1e-4, 0);
    CHECK_CLOSE(u.m, 4.4350280391176707e-3, 1e-15, 0);

    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_KG, 1.98847e30, &u, &e), MECH_OK);
    CHECK_CLOSE(u.GM, MECH_SUN_GM, 5e-5, 0);
    CHECK_CLOSE(u.m, 1476.6696910334393, 1e-15, 0);
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_GM, MECH_SUN_GM, &u, &e), MECH_OK);
    CHECK_CLOSE(u.m, 1476.6250385094202, 1e-15, 0);
    CHECK_EQ_INT(e.code, MECH_OK);

    /* geometric: the identity, with or without a mass */
    CHECK_EQ_INT(mech_gr_units_init(1, MECH_GR_MASS_NONE, NAN, &u, &e), MECH_OK);
    CHECK_EQ_INT(u.has_mass, 0);
    CHECK(isnan(u.GM) && isnan(u.m) && isnan(u.s));
    CHECK_CLOSE(mech_gr_len_in(&u, 6.0), 6.0, 0, 0);
    CHECK_CLOSE(mech_gr_ang_out(&u, 4.0), 4.0, 0, 0);
    CHECK_CLOSE(mech_gr_time_out(&u, 2.5), 2.5, 0, 0);
    CHECK_EQ_INT(mech_gr_units_init(1, MECH_GR_MASS_SUN, NAN, &u, &e), MECH_OK);
    CHECK_EQ_INT(u.has_mass, 1);
    CHECK_CLOSE(mech_gr_len_in(&u, 6.0), 6.0, 0, 0);
}

static void test_errors(void)
{
    struct mech_gr_units u;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_NONE, NAN, &u, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "M"));
    CHECK(strstr(e.text, "required with units SI") != NULL);
    const double bad[6] = {0.0, -1.0, NAN, INFINITY, 1e-320, -INFINITY};
    for (int i = 0; i < 6; i++) {
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_KG, bad[i], &u, &e), MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "M"));
        CHECK(strstr(e.text, "is not a usable length") != NULL);
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_gr_units_init(1, MECH_GR_MASS_GM, bad[i], &u, NULL), MECH_EDOMAIN);
    }
    /* GM = G * -1 kg: the text carries GM/c^2 with %.6g */
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_KG, -1.0, &u, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.text, "GM/c^2 = -7.42616e-28 m is not a usable length"));
    /* the largest mass a double holds still gives a finite length */
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_KG, 1.7e308, &u, &e), MECH_OK);
    CHECK(isfinite(u.m) && isfinite(u.s));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_values();
    test_errors();
    TEST_MAIN_END();
}
