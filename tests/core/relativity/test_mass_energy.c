/* test_mass_energy.c — E = m c^2 and the rest-mass loss L / c^2
 * (core/relativity/mass_energy.c), against values worked in 40-digit
 * decimal arithmetic (c^2 = 89875517873681764 m^2/s^2 exactly):
 *   1 kg: E = 8.9875517873681764e16 J;
 *   the Sun, L = 3.828e26 W (IAU 2015 nominal): 4.2592244145733e9 kg/s, and
 *     over 1 Gyr (3.15576e16 s) 1.3441090038534e26 kg;
 *   the notes' §3 homework 8, the solar constant 1366 W/m^2 at 1 AU
 *     (1.495978707e11 m): L = 4 pi d^2 F = 3.8415933193229e26 W,
 *     dm/dt = 4.2743490220799e9 kg/s, 1.3488819669919e17 kg per Julian year;
 *   the range's ends answer finite normal numbers; E -> m -> E round trips.
 */
#include <gsl/gsl_errno.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "mech/relativity/mass_energy.h"
#include "testlib.h"

static struct mech_mass_energy_answer A;

static enum mech_status run(enum mech_mass_energy_form f, double v, double d, double dur,
                            struct mech_error *e)
{
    struct mech_mass_energy_request q = {f, v, d, dur > 0.0, dur};
    mech_error_clear(e);
    return mech_mass_energy(&q, &A, e);
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_error e;
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_MASS, 1.0, 0, 0, &e), MECH_OK);
    CHECK_CLOSE(A.energy, 8.9875517873681764e16, 1e-16, 0);
    CHECK_EQ_INT(A.rate, 0);
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_ENERGY, 8.9875517873681764e16, 0, 0, &e), MECH_OK);
    CHECK_CLOSE(A.mass, 1.0, 2e-16, 0);
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_LUMINOSITY, 3.828e26, 0, 3.15576e16, &e), MECH_OK);
    /* inputs and c^2 each rounded once, then one division: 4e-16 */
    CHECK_CLOSE(A.mass_loss_rate, 4.259224414573251e9, 4e-16, 0);
    CHECK_CLOSE(A.mass_lost, 1.3441090038533684e26, 6e-16, 0);
    CHECK_CLOSE(A.mass_loss_per_year, 4.259224414573251e9 * 365.25 * 86400.0, 4e-16, 0);
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_FLUX, 1366.0, 1.495978707e11, 0, &e), MECH_OK);
    CHECK_CLOSE(A.luminosity, 3.8415933193229377e26, 4e-16, 0);
    CHECK_CLOSE(A.mass_loss_rate, 4.2743490220798727e9, 4e-16, 0);
    CHECK_CLOSE(A.mass_loss_per_year, 1.3488819669918779e17, 6e-16, 0);
    CHECK_CLOSE(A.mass_lost, 0.0, 0, 0); /* no duration, none reported */
    /* the range's ends: finite, normal */
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_MASS, 1e-250, 0, 0, &e), MECH_OK);
    CHECK_CLOSE(A.energy, 8.9875517873681764e-234, 1e-15, 0);
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_ENERGY, 1e200, 0, 0, &e), MECH_OK);
    CHECK_CLOSE(A.mass, 1.112650056053618432e183, 1e-15, 0);
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_LUMINOSITY, 1e-250, 0, 1e-30, &e), MECH_OK);
    CHECK(A.mass_lost >= DBL_MIN && isfinite(A.mass_lost));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_FLUX, 1e-100, 1e-20, 1e-30, &e), MECH_OK);
    CHECK(A.mass_lost >= DBL_MIN);
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_FLUX, 1e100, 1e50, 1e30, &e), MECH_OK);
    CHECK(isfinite(A.mass_lost));
    /* errors name the field */
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_MASS, -1.0, 0, 0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass"));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_ENERGY, INFINITY, 0, 0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "energy"));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_LUMINOSITY, NAN, 0, 0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "luminosity"));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_FLUX, 1366.0, 0.0, 0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "distance"));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_FLUX, 1e101, 1.0, 0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "flux"));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_LUMINOSITY, 1.0, 0, 1e31, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "duration"));
    CHECK_EQ_INT(run(MECH_MASS_ENERGY_MASS, 1.0, 0, 5.0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "duration"));
    CHECK_EQ_INT(mech_mass_energy(NULL, &A, &e), MECH_EINVAL);
    TEST_MAIN_END();
}
