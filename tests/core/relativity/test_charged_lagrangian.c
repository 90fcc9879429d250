/* test_charged_lagrangian.c — L, P, H of a charged particle
 * (core/relativity/charged_lagrangian.c): exact rational closed forms at beta = 0.6,
 * H = P.v − L (the Legendre transform) and H from P as two further methods,
 * the slow limit L + mc² → ½mv² (the notes' L = T − V), the uniform-field
 * gauge, and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/charged_lagrangian.h"
#include "mech/base/constants.h"
#include "testlib.h"

/* m = 1 kg, q = 2 C, beta = 0.6 x (gamma = 5/4), phi = 3 V, A = (4, 0, 0) T m:
 * L = −c²/γ + q A·v − qφ = −0.8c² + 4.8c − 6; P = (0.75c + 8, 0, 0);
 * H = 1.25c² + 6, and P·v − L = 0.45c² + 4.8c + 0.8c² − 4.8c + 6 = H. */
static void test_closed_form(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &b, NULL), MECH_OK);
    struct mech_charged_state s;
    CHECK_EQ_INT(mech_charged_state_compute(1.0, 2.0, &b, 3.0, mech_vec3_make(4, 0, 0), &s, NULL),
                 MECH_OK);
    CHECK_CLOSE(s.lagrangian, -0.8 * MECH_C * MECH_C + 4.8 * MECH_C - 6, 1e-15, 0);
    CHECK_CLOSE(s.lagrangian_plus_rest, 0.2 * MECH_C * MECH_C + 4.8 * MECH_C - 6, 1e-15, 0);
    CHECK_CLOSE(s.canonical_momentum.x, 0.75 * MECH_C + 8, 1e-15, 0);
    CHECK_CLOSE(s.kinetic_momentum.x, 0.75 * MECH_C, 1e-15, 0);
    CHECK_CLOSE(s.hamiltonian, 1.25 * MECH_C * MECH_C + 6, 1e-15, 0);
    CHECK_CLOSE(s.hamiltonian_minus_rest, 0.25 * MECH_C * MECH_C + 6, 1e-15, 0);
    CHECK_CLOSE(s.hamiltonian_from_momentum, s.hamiltonian, 1e-15, 0);
    CHECK_CLOSE(s.legendre_residual, 0.0, 0, 1e-15 * s.hamiltonian);
    CHECK_CLOSE(s.potential_energy, 6.0, 0, 0);
    /* The notes' non-relativistic L + mc² = ½ m v² + qA·v − qφ = 0.18c² + 4.8c − 6. */
    CHECK_CLOSE(s.lagrangian_newtonian_plus_rest, 0.18 * MECH_C * MECH_C + 4.8 * MECH_C - 6, 1e-15, 0);
}

/* 1 m/s, no fields: L + mc² = mc²(γ − 1)/γ = ½mv²(1 + β²/4 + ...) = 0.5 J
 * for m = 1 kg, while −mc²/γ + mc² in doubles would be 0. */
static void test_slow(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(1.0 / MECH_C, 0, 0), &b, NULL), MECH_OK);
    struct mech_charged_state s;
    CHECK_EQ_INT(mech_charged_state_compute(1.0, 0.0, &b, 0, mech_vec3_make(0, 0, 0), &s, NULL),
                 MECH_OK);
    CHECK_CLOSE(s.lagrangian_plus_rest, 0.5, 2e-15, 0);
    CHECK_CLOSE(s.hamiltonian_minus_rest, 0.5, 2e-15, 0);
    CHECK_CLOSE(s.lagrangian_newtonian_plus_rest, 0.5, 2e-15, 0);
    CHECK_CLOSE(s.lagrangian, -MECH_C * MECH_C, 1e-16, 0);
}

static void test_uniform_gauge(void)
{
    double phi;
    struct mech_vec3 a;
    /* E = 10 z, B = 2 z at r = (1, 2, 3): phi = −E·r = −30, A = ½ B × r = (−2, 1, 0). */
    mech_charged_uniform_potentials(mech_vec3_make(0, 0, 10), mech_vec3_make(0, 0, 2),
                                    mech_vec3_make(1, 2, 3), &phi, &a);
    CHECK_CLOSE(phi, -30, 0, 0);
    CHECK_CLOSE(a.x, -2, 0, 0);
    CHECK_CLOSE(a.y, 1, 0, 0);
    CHECK_CLOSE(a.z, 0, 0, 0);
}

static void test_errors(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.1, 0, 0), &b, NULL), MECH_OK);
    struct mech_charged_state s;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_charged_state_compute(0.0, 1, &b, 0, mech_vec3_make(0, 0, 0), &s, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_charged_state_compute(1.0, 1, &b, NAN, mech_vec3_make(0, 0, 0), &s, &e),
                 MECH_EINVAL);
    CHECK(!strcmp(e.param, "scalar_potential"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_closed_form();
    test_slow();
    test_uniform_gauge();
    test_errors();
    TEST_MAIN_END();
}
