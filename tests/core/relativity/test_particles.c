/* test_particles.c — the particle mass table (core/relativity/particles.c, PDG 2024 /
 * CODATA 2018) and energy-unit conversion: lookups, aliases agree, every mass
 * finite and ≥ 0, the values the kinematics tests rely on, conversions that
 * round-trip to within one rounding, and hc from the exact SI constants. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/particles.h"
#include "testlib.h"

static void test_table(void)
{
    size_t n = mech_particle_count();
    CHECK(n >= 30);
    for (size_t i = 0; i < n; i++) {
        const struct mech_particle *p = mech_particle_at(i);
        CHECK(p && p->name && p->source && isfinite(p->mass) && p->mass >= 0);
        CHECK(mech_particle_find(p->name) == p); /* names are unique */
    }
    CHECK(mech_particle_at(n) == NULL);
    CHECK(mech_particle_find("proton")->mass == 938.27208816);
    CHECK(mech_particle_find("electron")->mass == 0.51099895000);
    CHECK(mech_particle_find("pi0")->mass == 134.9768);
    CHECK(mech_particle_find("pi+")->mass == 139.57039);
    CHECK(mech_particle_find("muon")->mass == 105.6583755);
    CHECK(mech_particle_find("neutron")->mass == 939.5654205);
    CHECK(mech_particle_find("photon")->mass == 0);
    CHECK(mech_particle_find("alpha")->mass == 3727.3794066);
    /* particle and antiparticle, aliases */
    CHECK(mech_particle_find("pi-")->mass == mech_particle_find("pi+")->mass);
    CHECK(mech_particle_find("e+")->mass == mech_particle_find("e-")->mass);
    CHECK(mech_particle_find("pbar")->mass == mech_particle_find("proton")->mass);
    CHECK(mech_particle_find("Proton") == NULL); /* exact spelling */
    CHECK(mech_particle_find("") == NULL);
    CHECK(mech_particle_find(NULL) == NULL);
    /* nuclear binding: the deuteron is lighter than p + n by 2.224566 MeV */
    double b = mech_particle_find("proton")->mass + mech_particle_find("neutron")->mass -
               mech_particle_find("deuteron")->mass;
    CHECK_CLOSE(b, 2.22456610, 1e-7, 0);
}

static void test_units(void)
{
    enum mech_energy_unit u;
    const char *names[] = {"eV", "keV", "MeV", "GeV", "TeV"};
    for (int i = 0; i < 5; i++) {
        CHECK_EQ_INT(mech_energy_unit_parse(names[i], &u, NULL), MECH_OK);
        CHECK_EQ_INT(u, i);
        CHECK(strcmp(mech_energy_unit_name(u), names[i]) == 0);
    }
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_energy_unit_parse("mev", &u, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "energy_unit") == 0);
    CHECK(strcmp(mech_energy_unit_name(MECH_ENERGY_UNIT_COUNT), "?") == 0);

    CHECK(mech_energy_convert(938.27208816, MECH_MEV, MECH_GEV) == 0.93827208816);
    CHECK(mech_energy_convert(1.0, MECH_TEV, MECH_EV) == 1e12);
    CHECK(mech_energy_convert(1.0, MECH_EV, MECH_TEV) == 1e-12);
    /* Round trips through every pair of units: within one rounding. */
    const double xs[] = {938.27208816, 0.51099895, 134.9768, 1e-7, 3.3e59, 7.0 / 3.0};
    double worst = 0;
    for (size_t k = 0; k < sizeof xs / sizeof xs[0]; k++)
        for (int a = 0; a < 5; a++)
            for (int c = 0; c < 5; c++) {
                double y =
                    mech_energy_convert(xs[k], (enum mech_energy_unit)a, (enum mech_energy_unit)c);
                double z =
                    mech_energy_convert(y, (enum mech_energy_unit)c, (enum mech_energy_unit)a);
                double r = fabs(z - xs[k]) / xs[k];
                if (r > worst) worst = r;
                CHECK(r <= 1.2e-16);
                /* and the forward value is the correctly rounded decimal shift */
                long double exact = (long double)xs[k] * powl(1000.0L, a - c);
                CHECK_CLOSE(y, (double)exact, 1.2e-16, 0);
            }
    /* hc = 1.239841984332002622e-6 eV m (exact SI constants, decimal) */
    CHECK_CLOSE(mech_energy_hc(MECH_EV), 1.239841984332002622e-6, 1.2e-16, 0);
    CHECK_CLOSE(mech_energy_hc(MECH_MEV), 1.239841984332002622e-12, 2.3e-16, 0);
    /* Compton wavelength of the electron, CODATA 2018: 2.42631023867(73) pm */
    CHECK_CLOSE(mech_energy_hc(MECH_MEV) / 0.51099895000, 2.42631023867e-12, 1e-11, 0);
    printf("worst unit round-trip error %.3g\n", worst);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_table();
    test_units();
    TEST_MAIN_END();
}
