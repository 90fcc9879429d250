/* mech/relativity/velocity_addition.h — relativistic velocity addition in any
 * directions, light-like velocities (aberration), and the composition of a
 * chain of boosts into one boost and a Wigner (Thomas) rotation.
 *
 * Velocities are struct mech_boost values (mech/relativity/boost.h): each carries its
 * rapidity, γ − 1, βγ and 1 − β without cancellation, and every result here
 * is built from rapidity differences and light-cone components so that it
 * keeps that precision (never the textbook fraction (u − v)/(1 − uv) on
 * rounded β's: notes/numerics.md "Special relativity in floating point").
 *
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_VELOCITY_ADDITION_H
#define MECH_VELOCITY_ADDITION_H

#include <stddef.h>

#include "mech/relativity/boost.h"
#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Velocity in frame F' of an object moving with `object` in frame F, where F'
 * moves with `frame` relative to F (both in F's axes; notes §3.10:
 * u∥' = (u∥ − v)/(1 − v u∥), u⊥' = u⊥/(γ_v (1 − v u∥))). The answer (in F'
 * axes, which are parallel to F's: a pure boost) is a boost whose γ − 1 is
 *   γ' − 1 = 2 sinh²((η_o − η_f)/2) + sinh η_o sinh η_f (1 − cos θ)
 * (θ the angle between the two velocities): a sum of non-negative terms, so
 * γ' − 1, β', 1 − β' and η' keep full relative precision even for nearly equal
 * or tiny velocities; collinear rapidities subtract exactly. The direction is
 * u∥' = sinh(η_o − η_f) − (1 − cos θ) sinh η_o cosh η_f (or its cos θ < 0 twin),
 * u⊥' = sinh η_o sin θ: normwise accurate to a few ulp.
 * Statuses: MECH_OK; MECH_EINVAL (NULL); MECH_ENUMERIC (param "velocity") if
 * the relative rapidity exceeds MECH_BOOST_RAPIDITY_MAX or a value is not
 * finite. */
enum mech_status mech_velocity_add(const struct mech_boost *object, const struct mech_boost *frame,
                                   struct mech_boost *out, struct mech_error *err);

/* Light: a photon moving along `direction` (any nonzero finite vector) in F
 * is seen in F' (moving with `frame`) moving along *direction_out (unit) —
 * aberration — with frequency ratio *frequency_ratio = ν'/ν = γ(1 − β cos θ)
 * (notes §3.14). Light stays light: computed from the light-cone components
 * 1 ∓ cos θ, which scale by e^{±η}. Statuses: MECH_OK; MECH_EINVAL param
 * "direction" (zero or non-finite) or NULL outputs. */
enum mech_status mech_velocity_add_light(struct mech_vec3 direction, const struct mech_boost *frame,
                                         struct mech_vec3 *direction_out, double *frequency_ratio,
                                         struct mech_error *err);

/* The Wigner rotation of two successive boosts: first to the frame F1 moving
 * with `first` relative to F0, then to F2 moving with `second` relative to F1
 * (in F1's axes). B(second) B(first) = R B(total) with total = first ⊕ second
 * (the velocity of F2 in F0). Closed form (Wigner rotation, e.g. Rhodes &
 * Semon, Am. J. Phys. 72 (2004) 943; checked against the 4x4 polar
 * decomposition in tests/core/relativity/test_velocity_addition.c):
 *   tan(ε/2) = sin θ t1 t2 / (1 + cos θ t1 t2),  t_i = tanh(η_i/2),
 * θ the angle between first and second. F2's axes are F0-boosted axes turned
 * by ε about the unit axis second × first (right-hand rule); *angle in
 * [0, π), *axis = (0, 0, 0) when ε = 0 (collinear or a zero velocity).
 * Statuses: MECH_OK; MECH_EINVAL (NULL). */
enum mech_status mech_wigner_rotation(const struct mech_boost *first,
                                      const struct mech_boost *second, double *angle,
                                      struct mech_vec3 *axis, struct mech_error *err);

/* A chain of boosts composed into one: Λ = B(v_n) ... B(v_2) B(v_1) =
 * R B(total). */
struct mech_boost_composition {
    struct mech_boost total;   /* velocity of the last frame in the first, first frame's axes */
    double quaternion[4];      /* (w, x, y, z), w >= 0: the turn of the axes, below */
    double angle;              /* Wigner rotation angle ε in [0, π] (rad) */
    struct mech_vec3 axis;     /* unit axis; (0, 0, 0) when angle = 0 */
    struct mech_mat3 rotation; /* passive R: rows are the last frame's axes written in the
                                  axes of the pure boost B(total) */
};

/* Compose n ≥ 1 boosts: v[0] is the first frame's velocity relative to the
 * original, v[k] the velocity of frame k+1 relative to frame k, in frame k's
 * axes. The result's axes are the pure boost's axes turned by `angle` about
 * `axis` (R = the passive matrix of that turn). Built pairwise with
 * mech_velocity_add and mech_wigner_rotation, rotations accumulated as
 * quaternions, so collinear chains add rapidities to round-off and small
 * Wigner angles keep relative precision. One budget step per boost.
 * Statuses: MECH_OK; MECH_EINVAL (NULL, n = 0); MECH_ENUMERIC param
 * "boosts/<k>" when the composed rapidity passes MECH_BOOST_RAPIDITY_MAX;
 * MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED from mech_budget_check. */
enum mech_status mech_boost_compose(const struct mech_boost *v, size_t n,
                                    const struct mech_budget *budget,
                                    struct mech_boost_composition *out, struct mech_error *err);

#endif
