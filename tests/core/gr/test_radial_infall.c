/* test_radial_infall.c — proper times of a radial fall from rest
 * (core/gr/radial_infall.c) against the cycloid evaluated in 50-digit Decimal
 * (asin by its series; quoted), the Newtonian free-fall time (π/2)
 * sqrt(r0³/2GM) as a second method for τ(r0 → 0), additivity, the limits
 * (4/3) M far out and π M at the horizon, and the domain error. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/gr/radial_infall.h"
#include "mech/base/constants.h"
#include "testlib.h"

static void test_values(void)
{
    const struct { double r0, sing, hor, h2s; } t[] = {
        {10, 35.124073655203632, 33.700869851892333, 1.4232038033112994},
        {1000, 35124.073655203632, 35122.739521012043, 1.3341341915888949},
        {1e8, 1110720734539.5916, 1110720734538.2582, 1.3333333413333334},
        {2.5, 4.3905092069004540, 2.4139684529137021, 1.9765407539867519},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        struct mech_radial_infall f;
        CHECK_EQ_INT(mech_radial_infall_from_rest(t[i].r0, &f, NULL), MECH_OK);
        CHECK_CLOSE(f.to_singularity, t[i].sing, 4e-16, 0);
        CHECK_CLOSE(f.to_horizon, t[i].hor, 1e-15, 0);
        CHECK_CLOSE(f.horizon_to_singularity, t[i].h2s, 1e-15, 0);
        /* Newton: a radial Kepler orbit of semi-major axis r0/2 falls in half a period,
         * (1/2) 2π sqrt((r0/2)³/GM) = (π/2) sqrt(r0³/2): the same number. */
        CHECK_CLOSE(f.to_singularity, 0.5 * MECH_PI * t[i].r0 * sqrt(t[i].r0 / 2.0), 4e-16, 0);
        CHECK_CLOSE(f.to_horizon + f.horizon_to_singularity, f.to_singularity, 1e-15, 0);
    }
    /* Far out: horizon to r = 0 tends to (4/3) GM/c³ (s → 0: A · 2 · (2/3) s³ = 4/3). */
    struct mech_radial_infall f;
    CHECK_EQ_INT(mech_radial_infall_from_rest(1e200, &f, NULL), MECH_OK);
    CHECK_CLOSE(f.horizon_to_singularity, 4.0 / 3.0, 1e-15, 0);
    /* Just outside the horizon: τ(2M → 0) → π M, τ(r0 → 2M) → 0. */
    CHECK_EQ_INT(mech_radial_infall_from_rest(2.0 * (1 + 1e-12), &f, NULL), MECH_OK);
    CHECK_CLOSE(f.horizon_to_singularity, MECH_PI, 1e-5, 0);
    CHECK(f.to_horizon < 1e-5);
    CHECK(!f.on_horizon);
    /* On the horizon (and within 1e-12 below it, as a radius in metres rounds): the
     * limit, tau(r0 -> 2M) = 0, tau(-> 0) = (pi/2) sqrt(2^3/2) = pi */
    const double on[] = {2.0, 2.0 * (1 - 1e-13)};
    for (int i = 0; i < 2; i++) {
        CHECK_EQ_INT(mech_radial_infall_from_rest(on[i], &f, NULL), MECH_OK);
        CHECK(f.on_horizon);
        CHECK(f.to_horizon == 0);
        CHECK_CLOSE(f.to_singularity, MECH_PI, 1e-15, 0);
        CHECK_CLOSE(f.horizon_to_singularity, MECH_PI, 1e-15, 0);
    }
}

static void test_errors(void)
{
    struct mech_radial_infall f;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_radial_infall_from_rest(2.0 * (1 - 1e-9), &f, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "infall_from"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_radial_infall_from_rest(NAN, &f, &e), MECH_EDOMAIN);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_values();
    test_errors();
    TEST_MAIN_END();
}
