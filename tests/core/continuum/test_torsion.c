/* test_torsion.c — torsional waves (core/continuum/torsion.c): the rectangle's torsion
 * constant against the direct Timoshenko–Goodier series Σ tanh(nπb/2h)/n⁵
 * summed term by term to n = 39999 in 40-digit Decimal (python3, quoted; a
 * float sum of the same terms is 1.3e-14 off) and against the thin-strip limit
 * K = (b h³/3)(1 − 0.630249 h/b) (exact up to e^{−π b/h}); the circle's
 * speed sqrt(G/ρ) (K = J); G = E/(2(1 + ν)); quarter- and half-wave modes
 * through mech_rod_axial_mode; extremes and errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/continuum/continuum_waves.h"
#include "mech/continuum/torsion.h"
#include "testlib.h"


static void test_rectangle(void)
{
    const struct { double b, h, k; } t[] = {{1, 1, 0.14057701495515372},
                                             {2, 1, 0.45736335423914153},
                                             {1, 3, 0.78995079300450032},
                                             {10, 1, 3.1232503745720539},
                                             {1e-3, 2e-3, 4.5736335423914153e-13}};
    for (size_t i = 0; i < 5; i++) {
        double j, k;
        CHECK_EQ_INT(mech_torsion_rectangle(t[i].b, t[i].h, &j, &k, NULL), MECH_OK);
        CHECK_CLOSE(k, t[i].k, 1e-14, 0);
        CHECK_CLOSE(j, t[i].b * t[i].h * (t[i].b * t[i].b + t[i].h * t[i].h) / 12, 1e-15, 0);
        CHECK(k < j);
    }
    /* Thin strip b/h = 100: K = (b h³/3)(1 − (192/π⁵)(31/32)ζ(5) h/b). */
    double j, k;
    CHECK_EQ_INT(mech_torsion_rectangle(1.0, 0.01, &j, &k, NULL), MECH_OK);
    CHECK_CLOSE(k, 1e-6 / 3 * (1 - 0.6302488762838669 * 0.01), 1e-15, 0);
    /* Extremes: a 1e-100 m square and a 1e100 : 1 strip stay finite. */
    CHECK_EQ_INT(mech_torsion_rectangle(1e-50, 1e-50, &j, &k, NULL), MECH_OK);
    CHECK_CLOSE(k, 0.14057701495515372e-200, 1e-14, 0);
    CHECK_EQ_INT(mech_torsion_rectangle(1e6, 1e-6, &j, &k, NULL), MECH_OK);
    CHECK_CLOSE(k, 1e6 * 1e-18 / 3 * (1 - 0.6302488762838669e-12), 1e-15, 0);
}

static void test_speed_and_modes(void)
{
    /* A steel circle: K = J = π r⁴/2, c = sqrt(G/ρ), G = E/(2(1 + ν)). */
    double g, c;
    CHECK_EQ_INT(mech_shear_modulus(200e9, 0.3, &g, NULL), MECH_OK);
    CHECK_CLOSE(g, 200e9 / 2.6, 1e-15, 0);
    const double jc = MECH_PI / 2 * 1e-8;
    CHECK_EQ_INT(mech_torsional_wave_speed(g, 7850, jc, jc, &c, NULL), MECH_OK);
    CHECK_CLOSE(c, sqrt(g / 7850), 2e-16, 0);
    /* Clamped-free: f1 = c/(4L); free-free: f_n = n c/(2L); clamped-clamped the same. */
    double kl;
    CHECK_EQ_INT(mech_rod_axial_mode(MECH_ROD_CLAMPED_FREE, 1, &kl, NULL), MECH_OK);
    struct mech_wave_mode m = mech_wave_mode_nondispersive(c, 2.0, kl);
    CHECK_CLOSE(m.frequency, c / 8, 1e-15, 0);
    CHECK_EQ_INT(mech_rod_axial_mode(MECH_ROD_FREE_FREE, 3, &kl, NULL), MECH_OK);
    m = mech_wave_mode_nondispersive(c, 2.0, kl);
    CHECK_CLOSE(m.frequency, 3 * c / 4, 1e-15, 0);
    /* A square bar is slower by sqrt(K/J) = sqrt(0.140577/(1/6)). */
    double j, k;
    CHECK_EQ_INT(mech_torsion_rectangle(0.02, 0.02, &j, &k, NULL), MECH_OK);
    CHECK_EQ_INT(mech_torsional_wave_speed(g, 7850, k, j, &c, NULL), MECH_OK);
    CHECK_CLOSE(c, sqrt(g / 7850) * sqrt(0.14057701495515372 * 6), 1e-14, 0);
    /* Extreme moduli: no overflow of G/ρ. */
    CHECK_EQ_INT(mech_torsional_wave_speed(1e300, 1e-300, 1, 1, &c, NULL), MECH_OK);
    CHECK_CLOSE(c, 1e300, 1e-15, 0);
}

static void test_errors(void)
{
    double g, c, j, k;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_shear_modulus(1e9, 0.6, &g, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "poisson_ratio"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_shear_modulus(1e9, -1, &g, &e), MECH_EDOMAIN);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_torsional_wave_speed(1e9, 1000, 2, 1, &c, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "section/torsion_constant"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_torsional_wave_speed(1e9, 0, 1, 1, &c, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "density"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_torsion_rectangle(NAN, 1, &j, &k, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "width"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_rectangle();
    test_speed_and_modes();
    test_errors();
    TEST_MAIN_END();
}
