/* test_particle_answer.c — one /v1/relativity/particle answer
 * (core/answers/relativity/particle_answer.c) against closed forms: E² = (pc)² +
 * (mc²)², checked as T (E + m) = p² (no cancellation however slow the
 * particle), T = mβ²/2 (1 + 3β²/4 + …) at β = 1e-9 where a direct γ − 1
 * would be 0, γ = 1e6 (p = m sqrt((γ − 1)(γ + 1)), 1 − β = 1/(γ²(1 + β))),
 * the muon's lifetime at βγ = 1 (decay length cτ exactly, lab lifetime
 * √2 τ), a photon, the table's masses in every unit, and every error at the
 * request's field. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/relativity/particle_answer.h"
#include "testlib.h"

static const double M_E_MEV = 0.51099895000; /* CODATA 2018 electron mass, MeV */

static enum mech_status run(const char *unit, const char *name, double m,
                            enum mech_particle_given given, double value, int has_tau, double tau,
                            struct mech_particle_answer *a, struct mech_error *e)
{
    struct mech_particle_request q = {unit, name, m, given, value, has_tau, tau};
    mech_error_clear(e);
    return mech_particle_answer(&q, a, e);
}

/* E² = p² + m² as T (E + m) = p², and E = m + T. */
static void check_shell(const struct mech_particle_state *s, double rtol)
{
    CHECK_CLOSE(s->kinetic * (s->energy + s->mass), s->momentum * s->momentum, rtol, 0);
    CHECK_CLOSE(s->energy, s->mass + s->kinetic, rtol, 0);
}

/* β = 1e-9: γ − 1 = β²/2 + 3β⁴/8 + …, so T = m β²/2 (1 + 3β²/4) and p =
 * m β (1 + β²/2); 1 − 1/sqrt(1 − β²) would give T = 0 (β² is below the
 * spacing of doubles near 1). */
static void test_slow(void)
{
    struct mech_particle_answer a;
    struct mech_error e;
    const double b = 1e-9;
    CHECK_EQ_INT(run("MeV", "electron", 0, MECH_PARTICLE_GIVEN_BETA, b, 0, 0, &a, &e), MECH_OK);
    const struct mech_particle_state *s = &a.state;
    CHECK_EQ_INT(a.unit, MECH_MEV);
    CHECK_CLOSE(s->mass, M_E_MEV, 0, 0);
    CHECK_CLOSE(s->kinetic, M_E_MEV * b * b / 2 * (1 + 0.75 * b * b), 2e-16, 0);
    CHECK_CLOSE(s->gamma_minus_one, b * b / 2 * (1 + 0.75 * b * b), 2e-16, 0);
    CHECK_CLOSE(s->momentum, M_E_MEV * b * (1 + b * b / 2), 2e-16, 0);
    CHECK_CLOSE(s->speed, b * MECH_C, 2e-16, 0);
    CHECK_CLOSE(s->rapidity, b + b * b * b / 3, 2e-16, 0); /* atanh */
    check_shell(s, 4e-16);
    /* the notes' 1/2 m v^2 is low by (gamma - 1)(2 gamma + 1)/(2 gamma^2) = 3 beta^2/4 */
    CHECK_CLOSE(s->kinetic_newtonian, M_E_MEV * b * b / 2, 2e-16, 0);
    CHECK_CLOSE(s->kinetic_newtonian_rel_error, -0.75 * b * b, 1e-9, 0);
    CHECK_CLOSE(s->kinetic_p2_over_2m_rel_error, b * b / 4, 1e-9, 0); /* (gamma - 1)/2 */
    CHECK(!a.has_lifetime);
    /* the same electron in keV: the table's mass times 1000, the state alike */
    CHECK_EQ_INT(run("keV", "electron", 0, MECH_PARTICLE_GIVEN_BETA, b, 0, 0, &a, &e), MECH_OK);
    CHECK_EQ_INT(a.unit, MECH_KEV);
    CHECK_CLOSE(a.state.mass, 510.99895, 2e-16, 0);
    CHECK_CLOSE(a.state.kinetic, 510.99895 * b * b / 2 * (1 + 0.75 * b * b), 4e-16, 0);
}

/* γ = 1e6: E = γm, p = m sqrt((γ − 1)(γ + 1)), T = (γ − 1)m, 1 − β =
 * 1/(γ²(1 + β)) = 5e-13, η = ln(γ + sqrt(γ² − 1)). */
static void test_fast(void)
{
    struct mech_particle_answer a;
    struct mech_error e;
    const double g = 1e6, bg = sqrt((g - 1) * (g + 1)), beta = bg / g;
    CHECK_EQ_INT(run("GeV", NULL, 2.5, MECH_PARTICLE_GIVEN_GAMMA, g, 0, 0, &a, &e), MECH_OK);
    const struct mech_particle_state *s = &a.state;
    CHECK_CLOSE(s->energy, 2.5e6, 2e-16, 0);
    CHECK_CLOSE(s->kinetic, 2.5 * 999999.0, 2e-16, 0);
    CHECK_CLOSE(s->momentum, 2.5 * bg, 2e-16, 0);
    CHECK_CLOSE(s->one_minus_beta, 1.0 / (g * g * (1 + beta)), 4e-16, 0);
    CHECK_CLOSE(s->rapidity, log(g + bg), 2e-16, 0);
    CHECK_CLOSE(s->beta_gamma, bg, 2e-16, 0);
    CHECK_CLOSE(s->energy * s->energy, s->momentum * s->momentum + 2.5 * 2.5, 4e-16, 0);
    check_shell(s, 4e-16);
    CHECK_CLOSE(s->kinetic_p2_over_2m_rel_error, (g - 1) / 2, 2e-16, 0);
    /* the proton at 7 TeV kinetic (the LHC's beam): gamma - 1 = 7e6 / 938.27...,
     * from the table's mass, the shell exact */
    CHECK_EQ_INT(run("TeV", "proton", 0, MECH_PARTICLE_GIVEN_KINETIC, 7.0, 0, 0, &a, &e), MECH_OK);
    CHECK_CLOSE(a.state.gamma_minus_one, 7.0 / a.state.mass, 2e-16, 0);
    CHECK_CLOSE(a.state.mass * 1e6, 938.27208816, 1e-15, 0);
    check_shell(&a.state, 4e-16);
    /* the schema's largest kinetic energy still answers, E^2 = p^2 + m^2 to
     * the rounding of T, E and p (p squared: 2 ulps of it, a few in all) */
    CHECK_EQ_INT(run("eV", "proton", 0, MECH_PARTICLE_GIVEN_KINETIC, 1e60, 0, 0, &a, &e), MECH_OK);
    check_shell(&a.state, 1e-15);
}

/* The muon at βγ = 1 (γ = √2): lab lifetime √2 τ, decay length βγcτ = cτ. */
static void test_lifetime(void)
{
    struct mech_particle_answer a;
    struct mech_error e;
    const double tau = 2.1969811e-6;
    CHECK_EQ_INT(run("MeV", "muon", 0, MECH_PARTICLE_GIVEN_BETA_GAMMA, 1.0, 1, tau, &a, &e),
                 MECH_OK);
    CHECK(a.has_lifetime);
    CHECK_CLOSE(a.state.gamma, sqrt(2.0), 2e-16, 0);
    CHECK_CLOSE(a.lifetime.proper, tau, 0, 0);
    CHECK_CLOSE(a.lifetime.c_tau, MECH_C * tau, 2e-16, 0);
    CHECK_CLOSE(a.lifetime.lab, sqrt(2.0) * tau, 2e-16, 0);
    CHECK_CLOSE(a.lab_c_tau, sqrt(2.0) * MECH_C * tau, 4e-16, 0);
    CHECK_CLOSE(a.lifetime.decay_length, MECH_C * tau, 2e-16, 0);
}

/* A photon of 1 MeV: E = p = T, β = 1, no rest frame. */
static void test_photon(void)
{
    struct mech_particle_answer a;
    struct mech_error e;
    CHECK_EQ_INT(run("MeV", "photon", 0, MECH_PARTICLE_GIVEN_ENERGY, 1.0, 0, 0, &a, &e), MECH_OK);
    CHECK(!a.state.has_rest_frame);
    CHECK_CLOSE(a.state.momentum, 1.0, 0, 0);
    CHECK_CLOSE(a.state.kinetic, 1.0, 0, 0);
    CHECK_CLOSE(a.state.beta, 1.0, 0, 0);
    CHECK_CLOSE(a.state.one_minus_beta, 0.0, 0, 0);
    CHECK_CLOSE(a.state.speed, MECH_C, 0, 0);
}

/* Each error at the request's field. */
static void test_errors(void)
{
    struct mech_particle_answer a;
    struct mech_error e;
    CHECK_EQ_INT(run("MeV", "photon", 0, MECH_PARTICLE_GIVEN_BETA, 0.5, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "particle"));
    CHECK_EQ_INT(run("MeV", "photon", 0, MECH_PARTICLE_GIVEN_ENERGY, 1, 1, 1e-6, &a, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "particle"));
    CHECK_EQ_INT(run("MeV", NULL, -1, MECH_PARTICLE_GIVEN_ENERGY, 1, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "particle"));
    CHECK_EQ_INT(run("MeV", "graviton", 0, MECH_PARTICLE_GIVEN_ENERGY, 1, 0, 0, &a, &e),
                 MECH_EINVAL);
    CHECK(!strcmp(e.param, "particle"));
    CHECK(!strcmp(e.text, "unknown particle name \"graviton\""));
    CHECK_EQ_INT(run("MeV/c", "electron", 0, MECH_PARTICLE_GIVEN_ENERGY, 1, 0, 0, &a, &e),
                 MECH_EINVAL);
    CHECK(!strcmp(e.param, "energy_unit"));
    CHECK_EQ_INT(run(NULL, "electron", 0, MECH_PARTICLE_GIVEN_ENERGY, 1, 0, 0, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "energy_unit"));
    CHECK_EQ_INT(run("MeV", "muon", 0, MECH_PARTICLE_GIVEN_BETA, 0.5, 1, 0.0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "proper_lifetime"));
    CHECK_EQ_INT(run("MeV", NULL, 1, MECH_PARTICLE_GIVEN_ENERGY, 0.5, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "energy"));
    CHECK_EQ_INT(run("MeV", NULL, 1, MECH_PARTICLE_GIVEN_BETA, 1.0, 0, 0, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "beta"));
    CHECK_EQ_INT(run("MeV", NULL, 1, MECH_PARTICLE_GIVEN_GAMMA, NAN, 0, 0, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "gamma"));
    CHECK_EQ_INT(mech_particle_answer(NULL, &a, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_slow();
    test_fast();
    test_lifetime();
    test_photon();
    test_errors();
    TEST_MAIN_END();
}
