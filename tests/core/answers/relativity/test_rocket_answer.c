/* test_rocket_answer.c — one /v1/relativity/rocket answer
 * (core/answers/relativity/rocket_answer.c) against the relativistic rocket
 * equation β = tanh((u/c) ln(m_i/m_f)) and its inverse: m_i/m_f = 243 for
 * β = 1/2 at u = c/10 (atanh ½ = ½ ln 3, so (3)^(1/(2·0.1)) = 3^5), the
 * photon rocket's m_i/m_f = γ(1 + β), the near-zero burn η = 1e-9 keeping
 * its digits (γ − 1 = 2 sinh²(η/2), Tsiolkovsky's error −(η − tanh η)/β_e
 * ≈ −η³/(3 β_e)), and every error at the request's field. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/relativity/rocket_answer.h"
#include "testlib.h"

static enum mech_status run(enum mech_rocket_exhaust ex, double exv, int has_mr, double mr,
                            enum mech_particle_given given, double value,
                            struct mech_rocket_answer *a, struct mech_error *e)
{
    struct mech_rocket_request q = {ex, exv, has_mr, mr, given, value};
    mech_error_clear(e);
    return mech_rocket_answer(&q, a, e);
}

/* β = 1/2 at u = c/10, the speed given and reached from the mass ratio,
 * the exhaust in m/s (u = 29979245.8 m/s). */
static void test_ln3(void)
{
    struct mech_rocket_answer a;
    struct mech_error e;
    const double u = 0.1 * MECH_C, ln3 = 1.0986122886681098;
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_SPEED, u, 0, 0, MECH_PARTICLE_GIVEN_BETA, 0.5, &a, &e),
                 MECH_OK);
    CHECK_CLOSE(a.exhaust_beta, 0.1, 2e-16, 0);
    CHECK_CLOSE(a.rocket.mass_ratio, 243.0, 3e-15, 0);
    CHECK_CLOSE(a.rocket.log_mass_ratio, 5.0 * ln3, 2e-15, 0);
    CHECK_CLOSE(a.rocket.fuel_fraction, 242.0 / 243.0, 2e-16, 0);
    /* Tsiolkovsky: exp(0.5 / 0.1) = e^5, too small by e^5/243 - 1 */
    CHECK_CLOSE(a.rocket.newtonian_mass_ratio, exp(5.0), 2e-15, 0);
    CHECK_CLOSE(a.rocket.newtonian_rel_error, exp(5.0) / 243.0 - 1.0, 2e-15, 0);
    /* and back: burning to m_f = m_i/243 at u = c/10 reaches tanh(ln 3 / 2) = 1/2 */
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_SPEED, u, 1, 243.0, 0, 0, &a, &e), MECH_OK);
    CHECK_CLOSE(a.final.beta, 0.5, 4e-16, 0);
    CHECK_CLOSE(a.final.gamma, 2.0 / sqrt(3.0), 4e-16, 0);
    CHECK_CLOSE(a.final.rapidity, 0.5 * ln3, 4e-16, 0);
    CHECK_CLOSE(a.final.speed, 0.5 * MECH_C, 4e-16, 0);
    CHECK_CLOSE(a.rocket.mass_ratio, 243.0, 3e-15, 0);
}

/* The photon rocket (no exhaust given): m_i/m_f = γ(1 + β) = e^η. */
static void test_photon(void)
{
    struct mech_rocket_answer a;
    struct mech_error e;
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_PHOTON, 0, 1, 2.0, 0, 0, &a, &e), MECH_OK);
    CHECK_CLOSE(a.exhaust_beta, 1.0, 0, 0);
    CHECK_CLOSE(a.final.beta, 0.6, 4e-16, 0); /* tanh ln 2 = 3/5 */
    CHECK_CLOSE(a.final.gamma, 1.25, 4e-16, 0);
    CHECK_CLOSE(a.final.one_minus_beta, 0.4, 4e-16, 0);
    CHECK_CLOSE(a.rocket.fuel_fraction, 0.5, 4e-16, 0);
    /* gamma = 1e6: m_i/m_f = gamma + sqrt((gamma - 1)(gamma + 1)), ln of it = acosh gamma */
    const double g = 1e6, bg = sqrt((g - 1.0) * (g + 1.0));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_PHOTON, 0, 0, 0, MECH_PARTICLE_GIVEN_GAMMA, g, &a, &e),
                 MECH_OK);
    /* exp(eta) carries eta's rounding times eta = 14.5: a few ulps */
    CHECK_CLOSE(a.rocket.mass_ratio, g + bg, 2e-15, 0);
    CHECK_CLOSE(a.rocket.log_mass_ratio, log(g + bg), 4e-16, 0);
    CHECK_CLOSE(a.final.one_minus_beta, 1.0 / (g * (g + bg)), 4e-16, 0); /* 1/(gamma^2 (1 + beta)) */
    CHECK_CLOSE(a.rocket.newtonian_mass_ratio, exp(bg / g), 4e-16, 0); /* exp(beta): e, nearly */
}

/* A burn of η = (u/c) ln(m_i/m_f) = 1e-9: u/c = 1e-9 / ln 2, m_i/m_f = 2.
 * tanh η = η − η³/3 + …, so β = η to 1e-18; γ − 1 = 2 sinh²(η/2) = 5e-19
 * (1 + η²/12); 1 − β = 2/(e^{2η} + 1); Tsiolkovsky's relative error
 * expm1(−(η − β)/β_e) = −(η³/3 − 2η⁵/15)/β_e ≈ −2.3105e-19 — every digit
 * of which a direct 1/sqrt(1 − β²) − 1 or η − β would lose. */
static void test_near_zero(void)
{
    struct mech_rocket_answer a;
    struct mech_error e;
    const double LN2 = 0.69314718055994530942, be = 1e-9 / LN2, eta = be * LN2;
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_BETA, be, 1, 2.0, 0, 0, &a, &e), MECH_OK);
    CHECK_CLOSE(a.final.rapidity, 1e-9, 4e-16, 0);
    CHECK_CLOSE(a.final.beta, eta - eta * eta * eta / 3.0, 4e-16, 0);
    CHECK_CLOSE(a.final.gamma_minus_one, 0.5 * eta * eta * (1.0 + eta * eta / 12.0), 1e-15, 0);
    CHECK_CLOSE(a.final.one_minus_beta, 2.0 / (exp(2.0 * eta) + 1.0), 3e-16, 0);
    CHECK_CLOSE(a.final.beta_gamma, eta + eta * eta * eta / 6.0, 4e-16, 0); /* sinh */
    CHECK_CLOSE(a.final.speed, 1e-9 * MECH_C, 1e-15, 0);
    CHECK_CLOSE(a.rocket.log_mass_ratio, LN2, 4e-16, 0);
    CHECK_CLOSE(a.rocket.mass_ratio, 2.0, 4e-16, 0);
    CHECK_CLOSE(a.rocket.fuel_fraction, 0.5, 4e-16, 0);
    CHECK_CLOSE(a.rocket.newtonian_rel_error, -(eta * eta * eta / 3.0) / be, 1e-14, 0);
    CHECK(a.rocket.newtonian_rel_error < 0);
    /* the same burn given as its final speed: 1 - beta = 1 - 1e-9 reaches the same ratio */
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_BETA, be, 0, 0, MECH_PARTICLE_GIVEN_RAPIDITY, 1e-9, &a, &e),
                 MECH_OK);
    CHECK_CLOSE(a.rocket.mass_ratio, 2.0, 4e-16, 0);
    CHECK_CLOSE(a.rocket.newtonian_rel_error, -(eta * eta * eta / 3.0) / be, 1e-14, 0);
    /* no burn at all */
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_BETA, 0.3, 1, 1.0, 0, 0, &a, &e), MECH_OK);
    CHECK_CLOSE(a.final.beta, 0.0, 0, 0);
    CHECK_CLOSE(a.rocket.fuel_fraction, 0.0, 0, 0);
}

/* Each error at the request's field, never at a core name it does not have. */
static void test_errors(void)
{
    struct mech_rocket_answer a;
    struct mech_error e;
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_SPEED, 0.0, 0, 0, MECH_PARTICLE_GIVEN_BETA, 0.5, &a, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "exhaust_speed"));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_SPEED, NAN, 1, 2.0, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "exhaust_speed"));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_SPEED, 2.0 * MECH_C, 1, 2.0, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "exhaust_speed"));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_BETA, 1.5, 0, 0, MECH_PARTICLE_GIVEN_BETA, 0.5, &a, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "exhaust_beta"));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_PHOTON, 0, 1, 0.5, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass_ratio"));
    /* ln(1e300) = 690.8 > 350: a speed too close to c, the mass ratio's doing */
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_PHOTON, 0, 1, 1e300, 0, 0, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "mass_ratio"));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_PHOTON, 0, 0, 0, MECH_PARTICLE_GIVEN_BETA, 1.0, &a, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "beta"));
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_PHOTON, 0, 0, 0, MECH_PARTICLE_GIVEN_GAMMA, NAN, &a, &e),
                 MECH_EINVAL);
    CHECK(!strcmp(e.param, "gamma"));
    CHECK_EQ_INT(run((enum mech_rocket_exhaust)7, 0, 1, 2.0, 0, 0, &a, &e), MECH_EINVAL);
    CHECK_EQ_INT(mech_rocket_answer(NULL, &a, NULL), MECH_EINVAL);
    /* the mass ratio at the schema's extremes still answers */
    CHECK_EQ_INT(run(MECH_ROCKET_EXHAUST_BETA, 1e-3, 1, 1e300, 0, 0, &a, &e), MECH_OK);
    CHECK_CLOSE(a.final.rapidity, 1e-3 * 300.0 * log(10.0), 1e-15, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_ln3();
    test_photon();
    test_near_zero();
    test_errors();
    TEST_MAIN_END();
}
