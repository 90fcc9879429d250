/* test_continuum_waves.c — string and rod waves (core/continuum/continuum_waves.c):
 * wave speeds against sqrt(T/mu), axial mode numbers, the beam's
 * characteristic roots against Blevins (1979) Table 8-1 and an independent
 * solve of cos x cosh x = +-1 in its original form (scipy brentq, quoted),
 * the mode-shape ratios sigma, the asymptotes (n + 1/2) pi and (n - 1/2) pi
 * for large n, and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/continuum/continuum_waves.h"
#include "mech/base/constants.h"
#include "testlib.h"

static void test_string(void)
{
    double c = 0;
    CHECK_EQ_INT(mech_string_wave_speed(100.0, 0.01, &c, NULL), MECH_OK);
    CHECK_CLOSE(c, 100.0, 2e-16, 0); /* sqrt(100 N / 0.01 kg/m) */
    /* A guitar E string: T = 70 N, mu = 3.9e-3 kg/m: c = sqrt(17948.7...) = 133.973... */
    CHECK_EQ_INT(mech_string_wave_speed(70.0, 3.9e-3, &c, NULL), MECH_OK);
    CHECK_CLOSE(c * c, 70.0 / 3.9e-3, 4e-16, 0);
    /* Extremes: no overflow of T/mu. */
    CHECK_EQ_INT(mech_string_wave_speed(1e300, 1e-300, &c, NULL), MECH_OK);
    CHECK_CLOSE(c, 1e300, 4e-16, 0);
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_string_wave_speed(0.0, 1.0, &c, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "tension"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_string_wave_speed(1.0, -1.0, &c, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "linear_density"));
}

static void test_axial(void)
{
    double kl = 0;
    CHECK_EQ_INT(mech_rod_axial_mode(MECH_ROD_FREE_FREE, 3, &kl, NULL), MECH_OK);
    CHECK_CLOSE(kl, 3 * MECH_PI, 0, 0);
    CHECK_EQ_INT(mech_rod_axial_mode(MECH_ROD_CLAMPED_FREE, 1, &kl, NULL), MECH_OK);
    CHECK_CLOSE(kl, MECH_PI / 2, 0, 0); /* quarter wave: f1 = c/(4L) */
    CHECK_EQ_INT(mech_rod_axial_mode(MECH_ROD_PINNED_PINNED, 2, &kl, NULL), MECH_OK);
    CHECK_CLOSE(kl, 2 * MECH_PI, 0, 0); /* pins hold the ends axially */
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_axial_mode((enum mech_rod_ends)9, 1, &kl, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "ends"));
}

/* Roots of cos x cosh x = 1 and = -1 (scipy.optimize.brentq on the product
 * form, xtol 1e-15; Blevins Table 8-1 to 9 digits: 4.73004074, 7.85320462,
 * 10.9956078, 14.1371655, 17.2787597 and 1.87510407, 4.69409113, 7.85475744,
 * 10.9955407, 14.1371684), and sigma (Blevins: 0.982502215, 1.000777312,
 * 0.999966450; cantilever 0.734095514, 1.018467319, 0.999224497). */
static void test_bending_roots(void)
{
    const double cc[5] = {4.730040744862704, 7.853204624095838, 10.995607838001671,
                          14.137165491257464, 17.27875965739948};
    const double cf[5] = {1.8751040687119611, 4.694091132974175, 7.854757438237613,
                          10.995540734875467, 14.13716839104647};
    const double scc[3] = {0.9825022145762381, 1.000777311907269, 0.9999664501254086};
    const double scf[3] = {0.7340955137589128, 1.0184673187592197, 0.9992244965174284};
    for (int n = 1; n <= 5; n++) {
        double x, s, y;
        CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_CLAMPED_CLAMPED, n, &x, &s, NULL), MECH_OK);
        CHECK_CLOSE(x, cc[n - 1], 3e-16, 0);
        if (n <= 3) CHECK_CLOSE(s, scc[n - 1], 1e-14, 0);
        CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_FREE_FREE, n, &y, NULL, NULL), MECH_OK);
        CHECK_CLOSE(y, x, 0, 0); /* same equation */
        CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_CLAMPED_FREE, n, &x, &s, NULL), MECH_OK);
        CHECK_CLOSE(x, cf[n - 1], 3e-16, 0);
        if (n <= 3) CHECK_CLOSE(s, scf[n - 1], 1e-14, 0);
        CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_PINNED_PINNED, n, &x, &s, NULL), MECH_OK);
        CHECK_CLOSE(x, n * MECH_PI, 0, 0);
        CHECK_CLOSE(s, 0, 0, 0);
    }
    /* Large n: the roots are (n + 1/2) pi and (n - 1/2) pi to within
     * 2 e^{-x} (e^{-3000}: nothing in double), where cosh x overflows. */
    const int big[3] = {30, 1000, 100000};
    for (int i = 0; i < 3; i++) {
        int n = big[i];
        double x, s;
        CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_CLAMPED_CLAMPED, n, &x, &s, NULL), MECH_OK);
        CHECK_CLOSE(x, (n + 0.5) * MECH_PI, 4e-16, 0);
        CHECK_CLOSE(s, 1.0, 1e-12, 0);
        CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_CLAMPED_FREE, n, &x, &s, NULL), MECH_OK);
        CHECK_CLOSE(x, (n - 0.5) * MECH_PI, 4e-16, 0);
        CHECK_CLOSE(s, 1.0, 1e-12, 0);
    }
    struct mech_error e;
    double x;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_beam_bending_root(MECH_ROD_CLAMPED_FREE, 0, &x, NULL, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "modes"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_string();
    test_axial();
    test_bending_roots();
    TEST_MAIN_END();
}
