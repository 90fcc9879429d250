/* test_rod_answer.c — one /v1/continuum/rod answer
 * (core/answers/continuum/rod_answer.c) against closed forms: the fixed-free
 * (clamped-free) longitudinal frequencies f_n = (2n − 1)/(4L) sqrt(E/ρ), the
 * fixed-fixed flexural roots β_n L = 4.7300407448627, 7.8532046240958,
 * 10.995607838002 of cosh βL cos βL = 1 (Blevins Table 8-1; checked here
 * as cos x = sech x) with ω = (β_n L)² sqrt(EI/(ρA))/L², the cantilever's
 * 1.8751040687120 (cos x cosh x = −1), a circle's torsional speed sqrt(G/ρ)
 * with G = E/(2(1 + ν)), a square's K/J by the direct Saint-Venant series,
 * the notes' flags, and every error at the request's field. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/continuum/rod_answer.h"
#include "testlib.h"

/* Steel, 1 m: E = 200 GPa, rho = 7800 kg/m^3. */
static struct mech_rod_request steel(const char *ends, int modes)
{
    struct mech_rod_request q = {0};
    q.length = 1.0;
    q.density = 7800.0;
    q.youngs_modulus = 2e11;
    q.section = MECH_ROD_SECTION_CIRCLE;
    q.radius = 0.01;
    q.ends = ends;
    q.modes = modes;
    return q;
}

static void test_longitudinal_clamped_free(void)
{
    struct mech_rod_request q = steel("clamped-free", 4);
    struct mech_rod_answer a;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    const double c = sqrt(2e11 / 7800.0), r = 0.01;
    CHECK_CLOSE(a.area, MECH_PI * r * r, 2e-16, 0);
    CHECK_CLOSE(a.second_moment, MECH_PI * pow(r, 4) / 4, 4e-16, 0);
    CHECK_CLOSE(a.radius_of_gyration, r / 2, 2e-16, 0); /* sqrt(I/A) of a disc */
    CHECK_CLOSE(a.longitudinal_speed, c, 2e-16, 0);
    CHECK_EQ_INT(a.n_modes, 4);
    for (int n = 1; n <= 4; n++) {
        const struct mech_wave_mode *m = &a.modes[n - 1].longitudinal;
        CHECK_CLOSE(m->frequency, (2 * n - 1) / (4.0 * q.length) * c, 4e-16, 0);
        CHECK_CLOSE(m->wavelength, 4.0 * q.length / (2 * n - 1), 4e-16, 0);
    }
    /* the cantilever's first bending root, cos x cosh x = -1, and its
     * frequency (1.8751^2 / (2 pi L^2)) sqrt(E I/(rho A)) = 14.036... Hz */
    const double x1 = 1.8751040687119611;
    CHECK_CLOSE(a.modes[0].beta_L, x1, 4e-16, 0);
    CHECK_CLOSE(a.modes[0].bending.frequency, x1 * x1 / (2 * MECH_PI) * c * r / 2, 1e-15, 0);
    CHECK(!a.has_torsion && !a.torsion_needs_polar_moment && !a.thick);
    mech_rod_answer_free(&a);
    CHECK(a.modes == NULL);
}

static void test_bending_clamped_clamped(void)
{
    struct mech_rod_request q = steel("clamped-clamped", 3);
    q.section = MECH_ROD_SECTION_RECTANGLE;
    q.width = 0.03;
    q.height = 0.01;
    struct mech_rod_answer a;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    const double A = 0.03 * 0.01, I = 0.03 * 1e-6 / 12.0;
    CHECK_CLOSE(a.area, A, 2e-16, 0);
    CHECK_CLOSE(a.second_moment, I, 4e-16, 0);
    const double roots[3] = {4.7300407448627040, 7.8532046240958376, 10.995607838001671};
    const double s = sqrt(2e11 * I / (7800.0 * A));
    CHECK_CLOSE(a.stiffness_ratio, s, 4e-16, 0);
    for (int n = 0; n < 3; n++) {
        const struct mech_rod_mode *m = &a.modes[n];
        const double x = m->beta_L;
        CHECK_CLOSE(x, roots[n], 4e-15, 0);
        CHECK_CLOSE(cos(x), 1.0 / cosh(x), 0, 1e-15); /* cosh x cos x = 1 */
        CHECK_CLOSE(m->bending.angular_frequency, roots[n] * roots[n] * s, 1e-14, 0);
        CHECK_CLOSE(m->bending.group_speed, 2 * m->bending.phase_speed, 2e-16, 0);
        /* fixed-fixed axially: f_n = n c / (2L) */
        CHECK_CLOSE(m->longitudinal.frequency, (n + 1) / 2.0 * sqrt(2e11 / 7800.0), 4e-16, 0);
    }
    mech_rod_answer_free(&a);
}

/* Torsion: a circle twists at sqrt(G/rho), G = E/(2(1 + nu)); a square's
 * K/J from Saint-Venant's series summed directly (b = h: J = b^4/6,
 * K = b^4/3 (1 - (192/pi^5) sum_{n odd} tanh(n pi/2)/n^5) = 0.1406 b^4). */
static void test_torsion(void)
{
    struct mech_rod_request q = steel("clamped-free", 3);
    q.has_poisson_ratio = 1;
    q.poisson_ratio = 0.25;
    struct mech_rod_answer a;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    CHECK(a.has_torsion);
    const double G = 2e11 / 2.5, ct = sqrt(G / 7800.0);
    CHECK_CLOSE(a.torsion.shear_modulus, G, 2e-16, 0);
    CHECK_CLOSE(a.torsion.polar_moment, MECH_PI * 1e-8 / 2, 4e-16, 0);
    CHECK_CLOSE(a.torsion.torsion_constant, a.torsion.polar_moment, 0, 0);
    CHECK_CLOSE(a.torsion.wave_speed, ct, 4e-16, 0);
    for (int n = 1; n <= 3; n++)
        CHECK_CLOSE(a.modes[n - 1].torsional.frequency, (2 * n - 1) / 4.0 * ct, 4e-16, 0);
    mech_rod_answer_free(&a);

    q.section = MECH_ROD_SECTION_RECTANGLE;
    q.width = q.height = 0.02;
    q.has_poisson_ratio = 0;
    q.has_shear_modulus = 1;
    q.shear_modulus = 8e10;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    double sum = 0;
    /* summed smallest first to n = 20001 (the tail beyond, ~1/(8 n^4), is 4e-19) */
    for (int n = 20001; n >= 1; n -= 2) sum += tanh(n * MECH_PI / 2) / pow(n, 5);
    const double b4 = pow(0.02, 4), K = b4 / 3 * (1 - 192 / pow(MECH_PI, 5) * sum), J = b4 / 6;
    CHECK_CLOSE(K / b4, 0.1406, 1e-3, 0);
    CHECK_CLOSE(a.torsion.torsion_constant, K, 1e-14, 0);
    CHECK_CLOSE(a.torsion.polar_moment, J, 4e-16, 0);
    CHECK_CLOSE(a.torsion.wave_speed, sqrt(8e10 / 7800.0) * sqrt(K / J), 1e-14, 0);
    mech_rod_answer_free(&a);

    /* a section by area alone: torsion asked for but J missing, said so */
    q.section = MECH_ROD_SECTION_GIVEN;
    q.area = 1e-4;
    q.second_moment = 1e-9;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    CHECK(!a.has_torsion && a.torsion_needs_polar_moment);
    mech_rod_answer_free(&a);
    /* with J, K defaults to J */
    q.has_polar_moment = 1;
    q.polar_moment = 2e-9;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    CHECK(a.has_torsion);
    CHECK_CLOSE(a.torsion.wave_speed, sqrt(8e10 / 7800.0), 4e-16, 0);
    mech_rod_answer_free(&a);
}

/* The notes' flags: a stubby rod (k r_g > 0.1), free-free ends. */
static void test_flags(void)
{
    struct mech_rod_request q = steel("free-free", 1000);
    struct mech_rod_answer a;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    CHECK_EQ_INT(a.ends, MECH_ROD_FREE_FREE);
    CHECK_EQ_INT(a.n_modes, 1000);
    /* mode 1000: beta L -> (n + 1/2) pi, k r_g = 1000.5 pi * 0.005 = 15.7 > 0.1 */
    CHECK_CLOSE(a.modes[999].beta_L, 1000.5 * MECH_PI, 1e-15, 0);
    CHECK(a.thick);
    mech_rod_answer_free(&a);
    q = steel("clamped-free", 1);
    q.radius = 0.5;
    q.length = 0.1;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_OK);
    CHECK(a.thick);
    mech_rod_answer_free(&a);
}

static void test_errors(void)
{
    struct mech_rod_answer a;
    struct mech_error e;
    struct mech_rod_request q = steel("sideways", 3);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "ends") && a.modes == NULL);
    q = steel("free-free", 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "modes"));
    q.modes = MECH_ROD_ANSWER_MAX_MODES + 1;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "modes"));
    q = steel("free-free", 2);
    q.length = 0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "length"));
    q = steel("free-free", 2);
    q.density = NAN;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "density"));
    q = steel("free-free", 2);
    q.radius = -1;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "section/radius"));
    q = steel("free-free", 2);
    q.has_poisson_ratio = q.has_shear_modulus = 1;
    q.poisson_ratio = 0.3;
    q.shear_modulus = 8e10;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "poisson_ratio") && a.modes == NULL);
    q.has_shear_modulus = 0;
    q.poisson_ratio = 0.7;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "poisson_ratio"));
    /* K > J */
    q = steel("free-free", 2);
    q.section = MECH_ROD_SECTION_GIVEN;
    q.area = 1e-4;
    q.second_moment = 1e-9;
    q.has_polar_moment = q.has_torsion_constant = q.has_shear_modulus = 1;
    q.polar_moment = 2e-9;
    q.torsion_constant = 3e-9;
    q.shear_modulus = 8e10;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "section/torsion_constant"));
    /* a rectangle whose K underflows: the error at the section */
    q = steel("free-free", 2);
    q.section = MECH_ROD_SECTION_RECTANGLE;
    q.width = 1e-300;
    q.height = 1e6;
    q.has_shear_modulus = 1;
    q.shear_modulus = 8e10;
    mech_error_clear(&e);
    CHECK(mech_rod_answer(&q, &a, &e) != MECH_OK);
    CHECK(!strcmp(e.param, "section"));
    /* a radius whose r^2 underflows: A = 0, r_g = 0/0, not finite */
    q = steel("free-free", 2);
    q.radius = 1e-300;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rod_answer(&q, &a, &e), MECH_ENUMERIC);
    CHECK(e.param[0] == '\0' && a.modes == NULL);
    q.section = (enum mech_rod_section)9;
    CHECK_EQ_INT(mech_rod_answer(&q, &a, NULL), MECH_EINVAL);
    CHECK_EQ_INT(mech_rod_answer(NULL, &a, NULL), MECH_EINVAL);
    mech_rod_answer_free(&a);
    mech_rod_answer_free(NULL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_longitudinal_clamped_free();
    test_bending_clamped_clamped();
    test_torsion();
    test_flags();
    test_errors();
    TEST_MAIN_END();
}
