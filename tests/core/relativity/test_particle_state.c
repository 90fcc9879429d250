/* test_particle_state.c — one particle's γ, β, E, p, T, η from any one of
 * them (core/relativity/particle_state.c) against closed forms evaluated in 60-digit
 * decimal arithmetic (Python decimal, quoted), the round trip through every
 * form, the extremes (1 m/s, 1 − β = 1e-15, rapidity 300, massless), the
 * notes' ½mv² approximation, the muon's lifetime (notes §3.4) and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/particle_state.h"
#include "mech/base/constants.h"
#include "testlib.h"

static struct mech_particle_state state(double m, enum mech_particle_given g, double x)
{
    struct mech_particle_state s;
    memset(&s, 0, sizeof s);
    CHECK_EQ_INT(mech_particle_state_from(m, g, x, &s, NULL), MECH_OK);
    return s;
}

/* β = 0.6: γ = 5/4, βγ = 3/4, η = atanh(0.6) = ln 2, T = m/4, ½mβ² = 0.18 m,
 * relative error (0.18 − 0.25)/0.25 = −0.28. Every form gives the same state. */
static void test_every_form_agrees(void)
{
    const double m = 2.0, LN2 = 0.69314718055994530942;
    const struct { enum mech_particle_given g; double x; } forms[] = {
        {MECH_PARTICLE_GIVEN_BETA, 0.6},
        {MECH_PARTICLE_GIVEN_SPEED, 0.6 * MECH_C},
        {MECH_PARTICLE_GIVEN_GAMMA, 1.25},
        {MECH_PARTICLE_GIVEN_GAMMA_MINUS_ONE, 0.25},
        {MECH_PARTICLE_GIVEN_ONE_MINUS_BETA, 0.4},
        {MECH_PARTICLE_GIVEN_RAPIDITY, LN2},
        {MECH_PARTICLE_GIVEN_BETA_GAMMA, 0.75},
        {MECH_PARTICLE_GIVEN_ENERGY, 2.5},
        {MECH_PARTICLE_GIVEN_MOMENTUM, 1.5},
        {MECH_PARTICLE_GIVEN_KINETIC, 0.5},
    };
    for (size_t i = 0; i < sizeof forms / sizeof forms[0]; i++) {
        struct mech_particle_state s = state(m, forms[i].g, forms[i].x);
        CHECK_EQ_INT(s.has_rest_frame, 1);
        CHECK_CLOSE(s.beta, 0.6, 4e-16, 0);
        CHECK_CLOSE(s.one_minus_beta, 0.4, 1e-15, 0);
        CHECK_CLOSE(s.speed, 0.6 * MECH_C, 4e-16, 0);
        CHECK_CLOSE(s.gamma, 1.25, 4e-16, 0);
        CHECK_CLOSE(s.gamma_minus_one, 0.25, 1e-15, 0);
        CHECK_CLOSE(s.beta_gamma, 0.75, 4e-16, 0);
        CHECK_CLOSE(s.rapidity, LN2, 1e-15, 0);
        CHECK_CLOSE(s.energy, 2.5, 4e-16, 0);
        CHECK_CLOSE(s.momentum, 1.5, 4e-16, 0);
        CHECK_CLOSE(s.kinetic, 0.5, 1e-15, 0);
        CHECK_CLOSE(s.kinetic_newtonian, 0.36, 1e-15, 0);
        CHECK_CLOSE(s.kinetic_newtonian_rel_error, -0.28, 2e-15, 0);
        /* p²/2m = 1.5²/4 = 0.5625, (0.5625 − 0.5)/0.5 = 0.125 = (γ − 1)/2. */
        CHECK_CLOSE(s.kinetic_p2_over_2m, 0.5625, 1e-15, 0);
        CHECK_CLOSE(s.kinetic_p2_over_2m_rel_error, 0.125, 2e-15, 0);
        /* E² = m² + p² and E = m + T as independent identities. */
        CHECK_CLOSE(s.energy * s.energy, m * m + s.momentum * s.momentum, 1e-15, 0);
        CHECK_CLOSE(s.energy, m + s.kinetic, 1e-15, 0);
    }
}

/* 1 m/s, m = 1: decimal γ − 1 = 5.56325028026809220729e-18, βγ =
 * 3.33564095198152051431e-9, (½β² − T)/T = −8.34487542040213825e-18.
 * 1/sqrt(1 − β²) − 1 would give exactly 0 here. */
static void test_one_metre_per_second(void)
{
    struct mech_particle_state s = state(1.0, MECH_PARTICLE_GIVEN_SPEED, 1.0);
    CHECK_CLOSE(s.gamma_minus_one, 5.5632502802680922e-18, 1e-15, 0);
    CHECK_CLOSE(s.kinetic, 5.5632502802680922e-18, 1e-15, 0);
    CHECK_CLOSE(s.beta_gamma, 3.3356409519815205e-09, 1e-15, 0);
    CHECK_CLOSE(s.momentum, 3.3356409519815205e-09, 1e-15, 0);
    CHECK_CLOSE(s.rapidity, 3.3356409519815205e-09, 1e-15, 0);
    CHECK_CLOSE(s.kinetic_newtonian_rel_error, -8.3448754204021382e-18, 1e-14, 0);
    CHECK_CLOSE(s.speed, 1.0, 1e-15, 0);
    /* βγ = 1e-8: γ − 1 = 4.999999999999999875e-17, β = 9.99999999999999950e-9. */
    s = state(3.0, MECH_PARTICLE_GIVEN_BETA_GAMMA, 1e-8);
    CHECK_CLOSE(s.gamma_minus_one, 4.9999999999999999e-17, 1e-15, 0);
    CHECK_CLOSE(s.kinetic, 3 * 4.9999999999999999e-17, 1e-15, 0);
    CHECK_CLOSE(s.beta, 9.9999999999999995e-09, 1e-15, 0);
}

/* 1 − β = 1e-15: γ = 1/sqrt(ε(2 − ε)) = 22360679.7749979025542617, βγ =
 * 22360679.7749978801935819, η = 17.6159617877353150348. Rapidity 300:
 * γ = βγ = 9.71213197620627968292e129, 1 − β = 2/(e^600 + 1) =
 * 5.30079310600862163268e-261. */
static void test_near_c(void)
{
    struct mech_particle_state s = state(1.0, MECH_PARTICLE_GIVEN_ONE_MINUS_BETA, 1e-15);
    CHECK_CLOSE(s.gamma, 22360679.774997903, 1e-15, 0);
    CHECK_CLOSE(s.gamma_minus_one, 22360678.774997903, 1e-15, 0);
    CHECK_CLOSE(s.beta_gamma, 22360679.77499788, 1e-15, 0);
    CHECK_CLOSE(s.rapidity, 17.615961787735315, 1e-15, 0);
    CHECK_CLOSE(s.one_minus_beta, 1e-15, 0, 0);
    CHECK_CLOSE(s.kinetic_newtonian_rel_error, -(22360678.774997903 / 22360679.774997903) *
                                                   (1 + 0.5 / 22360679.774997903), 1e-15, 0);
    s = state(1e-30, MECH_PARTICLE_GIVEN_RAPIDITY, 300);
    CHECK_CLOSE(s.gamma, 9.7121319762062797e129, 1e-14, 0);
    CHECK_CLOSE(s.beta_gamma, 9.7121319762062797e129, 1e-14, 0);
    CHECK_CLOSE(s.energy, 9.7121319762062797e99, 1e-14, 0);
    CHECK_CLOSE(s.one_minus_beta, 5.3007931060086216e-261, 1e-13, 0);
    CHECK_CLOSE(s.kinetic_newtonian_rel_error, -1.0, 1e-15, 0);
    /* The same state from its energy: the round trip keeps 1 − β. */
    struct mech_particle_state t = state(1e-30, MECH_PARTICLE_GIVEN_ENERGY, s.energy);
    CHECK_CLOSE(t.one_minus_beta, 5.3007931060086216e-261, 1e-13, 0);
    CHECK_CLOSE(t.rapidity, 300, 1e-15, 0);
}

/* Notes §3 "Kinematics problems in eV": a 1 MeV proton, m = 938.27208816 MeV:
 * p = 43.3306378480631184904, β = 0.0461321467914012739, η =
 * 0.0461649144027158261, (½mβ² − T)/T = −0.00159641459784390129. */
static void test_proton_and_massless(void)
{
    struct mech_particle_state s = state(938.27208816, MECH_PARTICLE_GIVEN_KINETIC, 1.0);
    CHECK_CLOSE(s.momentum, 43.330637848063118, 1e-15, 0);
    CHECK_CLOSE(s.beta, 0.046132146791401274, 1e-15, 0);
    CHECK_CLOSE(s.rapidity, 0.046164914402715826, 1e-15, 0);
    CHECK_CLOSE(s.kinetic_newtonian_rel_error, -0.0015964145978439013, 1e-13, 0);
    CHECK_CLOSE(s.kinetic, 1.0, 0, 0);
    /* p²/2m = 43.3306.../(2 · 938.27...) = T(T + 2m)/2m = 1 + 1/(2 · 938.27208816) */
    CHECK_CLOSE(s.kinetic_p2_over_2m, 1.0 + 0.5 / 938.27208816, 1e-15, 0);
    CHECK_CLOSE(s.kinetic_p2_over_2m_rel_error, 0.5 / 938.27208816, 1e-14, 0);

    s = state(0.0, MECH_PARTICLE_GIVEN_ENERGY, 5.0);
    CHECK_EQ_INT(s.has_rest_frame, 0);
    CHECK_CLOSE(s.momentum, 5.0, 0, 0);
    CHECK_CLOSE(s.kinetic, 5.0, 0, 0);
    CHECK_CLOSE(s.beta, 1.0, 0, 0);
    CHECK_CLOSE(s.one_minus_beta, 0.0, 0, 0);
    CHECK_CLOSE(s.speed, MECH_C, 0, 0);
}

/* Notes §3.4 muon: τ = 2 µs, β = 0.9999: γ = 70.7124459519056355 (for the
 * double 0.9999), γτ = 1.41424891903811271e-4 s, cτ = 599.584916 m,
 * βγcτ = 42393.8761546312582 m (the notes' "about 42 km"). */
static void test_muon_lifetime(void)
{
    struct mech_particle_state s = state(105.6583755, MECH_PARTICLE_GIVEN_BETA, 0.9999);
    struct mech_particle_lifetime l;
    CHECK_EQ_INT(mech_particle_lifetime_of(&s, 2e-6, &l, NULL), MECH_OK);
    CHECK_CLOSE(l.proper, 2e-6, 0, 0);
    CHECK_CLOSE(l.c_tau, 599.584916, 1e-16, 0);
    CHECK_CLOSE(l.lab, 1.4142489190381127e-4, 1e-15, 0);
    CHECK_CLOSE(l.decay_length, 42393.876154631258, 1e-15, 0);
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_particle_lifetime_of(&s, 0.0, &l, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "proper_lifetime"));
    struct mech_particle_state g = state(0.0, MECH_PARTICLE_GIVEN_MOMENTUM, 1.0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_particle_lifetime_of(&g, 1.0, &l, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass"));
}

static void expect_error(double m, enum mech_particle_given g, double x, enum mech_status want,
                         const char *param)
{
    struct mech_particle_state s;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_particle_state_from(m, g, x, &s, &e), want);
    if (strcmp(e.param, param)) {
        fprintf(stderr, "param '%s', want '%s' (%s)\n", e.param, param, e.text);
        CHECK(0);
    }
}

static void test_errors(void)
{
    expect_error(1, MECH_PARTICLE_GIVEN_BETA, 1.0, MECH_EDOMAIN, "beta");
    expect_error(1, MECH_PARTICLE_GIVEN_BETA, -0.1, MECH_EDOMAIN, "beta");
    expect_error(1, MECH_PARTICLE_GIVEN_SPEED, MECH_C, MECH_EDOMAIN, "speed");
    expect_error(1, MECH_PARTICLE_GIVEN_GAMMA, 0.5, MECH_EDOMAIN, "gamma");
    expect_error(1, MECH_PARTICLE_GIVEN_GAMMA_MINUS_ONE, -1e-3, MECH_EDOMAIN, "gamma_minus_one");
    expect_error(1, MECH_PARTICLE_GIVEN_ONE_MINUS_BETA, 0.0, MECH_EDOMAIN, "one_minus_beta");
    expect_error(1, MECH_PARTICLE_GIVEN_ONE_MINUS_BETA, 1.5, MECH_EDOMAIN, "one_minus_beta");
    expect_error(1, MECH_PARTICLE_GIVEN_RAPIDITY, 400, MECH_EINVAL, "rapidity");
    expect_error(1, MECH_PARTICLE_GIVEN_BETA_GAMMA, 1e200, MECH_EINVAL, "beta_gamma");
    expect_error(1, MECH_PARTICLE_GIVEN_ENERGY, 0.5, MECH_EDOMAIN, "energy");
    expect_error(1, MECH_PARTICLE_GIVEN_MOMENTUM, -1, MECH_EDOMAIN, "momentum");
    expect_error(1, MECH_PARTICLE_GIVEN_KINETIC, -1, MECH_EDOMAIN, "kinetic_energy");
    expect_error(0, MECH_PARTICLE_GIVEN_BETA, 0.5, MECH_EDOMAIN, "mass");
    expect_error(0, MECH_PARTICLE_GIVEN_ENERGY, 0.0, MECH_EDOMAIN, "energy");
    expect_error(-1, MECH_PARTICLE_GIVEN_ENERGY, 2.0, MECH_EDOMAIN, "mass");
    expect_error(1, MECH_PARTICLE_GIVEN_GAMMA, NAN, MECH_EINVAL, "gamma");
    expect_error(1e300, MECH_PARTICLE_GIVEN_GAMMA, 1e100, MECH_EDOMAIN, "gamma");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_every_form_agrees();
    test_one_metre_per_second();
    test_near_c();
    test_proton_and_massless();
    test_muon_lifetime();
    test_errors();
    TEST_MAIN_END();
}
