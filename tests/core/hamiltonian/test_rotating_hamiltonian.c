/* test_rotating_hamiltonian.c — L, p, H in a rotating frame
 * (core/hamiltonian/rotating_hamiltonian.c) against hand-derived closed forms, the two
 * forms of H_rot against each other, E = H_rot + ω·L, and the notes' puck
 * at rest on a rotating table (H_rot = −½mω²r², E = +½mω²r²). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/hamiltonian/rotating_hamiltonian.h"
#include "testlib.h"

/* m = 2, ω = 3 z, r = (1, 0, 0), v = (0, 1, 0) in the rotating frame:
 * ω × r = (0, 3, 0), u = (0, 4, 0), p = (0, 8, 0), L = r × p = (0, 0, 8),
 * ω·L = 24; E = ½·2·16 = 16; H_rot = ½·2·1 − ½·2·9 = −8 = E − ω·L;
 * L_rot = 16 (V = 0). With V = 5: E = 21, H = −3, L_rot = 11. */
static void test_closed_form(void)
{
    struct mech_rotating_hamiltonian h;
    CHECK_EQ_INT(mech_rotating_hamiltonian_compute(2, mech_vec3_make(0, 0, 3), mech_vec3_make(1, 0, 0),
                                                   mech_vec3_make(0, 1, 0), 5, &h, NULL),
                 MECH_OK);
    CHECK_CLOSE(h.canonical_momentum.y, 8, 0, 0);
    CHECK_CLOSE(h.angular_momentum.z, 8, 0, 0);
    CHECK_CLOSE(h.omega_dot_l, 24, 0, 0);
    CHECK_CLOSE(h.inertial_energy, 21, 0, 0);
    CHECK_CLOSE(h.hamiltonian, -3, 0, 0);
    CHECK_CLOSE(h.hamiltonian_from_momentum, -3, 0, 1e-14);
    CHECK_CLOSE(h.lagrangian, 11, 0, 0);
    CHECK_CLOSE(h.inertial_energy - h.hamiltonian, h.omega_dot_l, 0, 1e-14);
}

/* Oblique: the two forms of H agree and E − H = ω·L for arbitrary vectors. */
static void test_identities(void)
{
    struct mech_rotating_hamiltonian h;
    CHECK_EQ_INT(mech_rotating_hamiltonian_compute(
                     0.7, mech_vec3_make(0.3, -1.1, 2.0), mech_vec3_make(1.5, 2.5, -0.5),
                     mech_vec3_make(-0.4, 0.9, 1.3), -2.0, &h, NULL),
                 MECH_OK);
    CHECK_CLOSE(h.hamiltonian_from_momentum, h.hamiltonian, 1e-14, 1e-14);
    CHECK_CLOSE(h.inertial_energy - h.hamiltonian, h.omega_dot_l, 1e-13, 1e-13);
    /* Puck at rest on the table at radius 2 (ω = 0.5 z, m = 1): H_rot = −½ m ω² r² = −0.5,
     * E = +0.5: the rotating-frame Hamiltonian is not the inertial energy. */
    CHECK_EQ_INT(mech_rotating_hamiltonian_compute(1, mech_vec3_make(0, 0, 0.5), mech_vec3_make(2, 0, 0),
                                                   mech_vec3_make(0, 0, 0), 0, &h, NULL),
                 MECH_OK);
    CHECK_CLOSE(h.hamiltonian, -0.5, 0, 0);
    CHECK_CLOSE(h.inertial_energy, 0.5, 0, 0);
    CHECK_CLOSE(h.centrifugal_potential, -0.5, 0, 0);
}

static void test_errors(void)
{
    struct mech_rotating_hamiltonian h;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rotating_hamiltonian_compute(0, mech_vec3_make(0, 0, 1), mech_vec3_make(1, 0, 0),
                                                   mech_vec3_make(0, 0, 0), 0, &h, &e),
                 MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_closed_form();
    test_identities();
    test_errors();
    TEST_MAIN_END();
}
