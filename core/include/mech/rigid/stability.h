/* mech/rigid/stability.h — linear stability of torque-free rotation about a
 * principal axis (notes §2.10, "Stability of Rigid Body Rotations").
 *
 * A body with principal moments I1, I2, I3 spins at rate w about principal
 * axis a; the other two axes are b, c with (a, b, c) a cyclic order of
 * (1, 2, 3). Euler's equations without torque (notes §2.8),
 *   I_a w_a' = (I_b - I_c) w_b w_c   (and cyclically),
 * linearised about w = (w along a) + eps (along b) + eta (along c), give
 *   eps' = A eta,  eta' = B eps,  A = (I_c - I_a) w / I_b,  B = (I_a - I_b) w / I_c,
 * so eps'' = k eps (and eta'' = k eta) with
 *   k = A B = (I_c - I_a)(I_a - I_b) w^2 / (I_b I_c).
 * For a = 1 this is the notes' (I3 - I1)(I1 - I2) w1^2 / (I2 I3). k < 0: the
 * perturbation oscillates at sqrt(-k) (stable); k > 0: it grows like
 * exp(sqrt(k) t) (unstable: the intermediate axis); k = 0 (the spin axis
 * shares its moment with another axis, or w = 0): marginal, the linearisation
 * neither oscillates nor grows exponentially (eps drifts linearly at rate A eta
 * when A != 0: the spin axis wanders in the degenerate plane).
 *
 * Pure functions, no allocation, thread-safe.
 */
#ifndef MECH_STABILITY_H
#define MECH_STABILITY_H

#include "mech/base/status.h"

/* Relative slack allowed in the triangle inequality I_i <= I_j + I_k (a flat
 * lamina sits exactly on it, and decimal input may round just past it). */
#define MECH_STABILITY_TRIANGLE_TOL 1e-12

enum mech_stability_kind {
    MECH_STABILITY_STABLE = 0,   /* k < 0 */
    MECH_STABILITY_UNSTABLE = 1, /* k > 0 */
    MECH_STABILITY_MARGINAL = 2  /* k == 0 */
};

/* Where the spin axis's moment sits among the three. */
enum mech_stability_role {
    MECH_AXIS_SMALLEST = 0,     /* strictly smallest moment */
    MECH_AXIS_INTERMEDIATE = 1, /* strictly between the others */
    MECH_AXIS_LARGEST = 2,      /* strictly largest */
    MECH_AXIS_DEGENERATE = 3    /* equals another moment */
};

struct mech_stability {
    double k;                 /* s^-2: eps'' = k eps */
    double coupling[2];       /* 1/s: A, B in eps' = A eta, eta' = B eps */
    int perturbation_axes[2]; /* 1-based axes of eps and eta: b, c */
    enum mech_stability_kind kind;
    double frequency;   /* rad/s, sqrt(-k) when stable, else 0 */
    double growth_rate; /* 1/s, sqrt(k) when unstable, else 0 */
    enum mech_stability_role role;
    int intermediate_axis; /* 1-based axis with the strictly intermediate moment, or 0
                              when two moments are equal (none is intermediate) */
};

/* Stability of spin `spin` (rad/s, finite, any sign) about principal axis
 * `axis` (1, 2 or 3) of a body with principal moments `moments` (kg m^2,
 * finite, > 0, satisfying I_i <= (I_j + I_k)(1 + MECH_STABILITY_TRIANGLE_TOL)
 * for every i, as every rigid body does; need not be sorted).
 * k is computed as the product of A and B, each a ratio with |ratio| <= 1 by
 * the triangle inequality, so |k| <= w^2 (1 + tol)^2 and nothing overflows
 * for finite input.
 * Statuses: MECH_OK; MECH_EINVAL (param "moments/<i>" 0-based for a
 * non-finite moment, "axis", "spin"; NULL pointers); MECH_EDOMAIN (param
 * "moments/<i>" for a moment <= 0 or one exceeding the sum of the others). */
enum mech_status mech_stability_principal(const double moments[3], int axis, double spin,
                                          struct mech_stability *out, struct mech_error *err);

#endif
