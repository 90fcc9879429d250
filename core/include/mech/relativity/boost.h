/* mech/relativity/boost.h — Lorentz boosts of 4-vectors, kept precise at every speed.
 *
 * A boost is described by its rapidity η ≥ 0 and a unit direction n: the new
 * frame moves with velocity βc n, β = tanh η (passive, as in the notes §3.4:
 * x' = γ(x − βct), ct' = γ(ct − βx); docs/design.md "Conventions").
 * 4-vectors are x = (x0, x1, x2, x3) with x0 = ct (or E/c), metric (−,+,+,+).
 *
 * Precision (notes/numerics.md "Special relativity in floating point"): the
 * boost carries every derived quantity — γ, γ − 1, β, 1 − β, βγ, e^{±η} —
 * computed without cancellation from whichever quantity the caller gave
 * (β, η, γ or 1 − β), never as 1/sqrt(1 − β²) of a rounded β. Vectors are
 * boosted with the light-cone components u = x0 − x∥, v = x0 + x∥
 * (u' = e^{η} u, v' = e^{−η} v) or the γ − 1 form, whichever is more
 * accurate for that component, and invariants use light-cone products.
 *
 * Pure functions of their arguments; thread-safe; no allocation.
 */
#ifndef MECH_BOOST_H
#define MECH_BOOST_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Largest rapidity accepted. Beyond about 354, 1 − β = 2/(e^{2η} + 1) is no
 * longer a normal double; at 350, γ = cosh η ≈ 5e151, so a boosted component of
 * size 1e150 stays finite. */
#define MECH_BOOST_RAPIDITY_MAX 350.0

struct mech_boost {
    struct mech_vec3 direction; /* unit n: the new frame moves with velocity βc n */
    struct mech_vec3 beta_vec;  /* β n (the caller's components when built from β) */
    double rapidity;            /* η = atanh β ≥ 0 */
    double gamma;               /* γ = cosh η ≥ 1 */
    double gamma_minus_one;     /* γ − 1 = 2 sinh²(η/2) ≥ 0, to round-off even at 1 m/s */
    double beta;                /* β = |β| = tanh η in [0, 1) */
    double one_minus_beta;      /* 1 − β in (0, 1], to round-off even as β → 1 */
    double beta_gamma;          /* βγ = sinh η ≥ 0 */
    double exp_rapidity;        /* e^{η} = γ(1 + β): scales u = x0 − x∥ */
    double exp_neg_rapidity;    /* e^{−η} = γ(1 − β): scales v = x0 + x∥ */
};

/* Boost to the frame moving with velocity β c (β dimensionless, |β| < 1).
 * β = 0 is the identity (direction then +x). Statuses: MECH_OK;
 * MECH_EINVAL (param "beta") for non-finite components; MECH_EDOMAIN
 * (param "beta") for |β| ≥ 1. out is written only on success. */
enum mech_status mech_boost_from_beta(struct mech_vec3 beta, struct mech_boost *out,
                                      struct mech_error *err);

/* Boost of rapidity eta along direction (any nonzero finite 3-vector, scaled
 * to unit length). A negative eta is a boost of |eta| along −direction.
 * Statuses: MECH_OK; MECH_EINVAL param "rapidity" (non-finite or
 * |eta| > MECH_BOOST_RAPIDITY_MAX) or "direction" (zero or non-finite). */
enum mech_status mech_boost_from_rapidity(double eta, struct mech_vec3 direction,
                                          struct mech_boost *out, struct mech_error *err);

/* Boost with Lorentz factor gamma ≥ 1 along direction. γ − 1 is taken as
 * gamma − 1 (exact for γ ≤ 2), so its relative precision is what the rounded
 * gamma carries. Statuses: MECH_OK; MECH_EDOMAIN param "gamma" (gamma < 1);
 * MECH_EINVAL param "gamma" (non-finite, or rapidity beyond
 * MECH_BOOST_RAPIDITY_MAX, i.e. γ ≳ 5e151) or "direction". */
enum mech_status mech_boost_from_gamma(double gamma, struct mech_vec3 direction,
                                       struct mech_boost *out, struct mech_error *err);

/* Boost with speed β = 1 − one_minus_beta along direction: the precise way to
 * ask for β near 1 (one_minus_beta = 1e-15 gives γ = 1/sqrt(ε(2 − ε)) to
 * round-off). one_minus_beta in (1, 2) means β < 0, i.e. a boost along
 * −direction. Statuses: MECH_OK; MECH_EDOMAIN param "one_minus_beta" (≤ 0 or
 * ≥ 2); MECH_EINVAL param "one_minus_beta" (non-finite, or rapidity beyond
 * MECH_BOOST_RAPIDITY_MAX, i.e. ε ≲ 2e-304) or "direction". */
enum mech_status mech_boost_from_one_minus_beta(double one_minus_beta, struct mech_vec3 direction,
                                                struct mech_boost *out, struct mech_error *err);

/* Boost with γ − 1 = gamma_minus_one ≥ 0 along direction: the precise way to
 * build a boost whose γ − 1 was computed without cancellation (e.g. a
 * relative velocity, core/relativity/velocity_addition.c). γ = 1 + (γ − 1),
 * βγ = sqrt((γ − 1)(γ + 1)), e^{η} = γ + βγ, η = log1p((γ − 1) + βγ),
 * 1 − β = 1/(γ e^{η}): each to a few ulp. gamma_minus_one = 0 is the identity
 * and then direction may be zero (it is +x then). Statuses: MECH_OK;
 * MECH_EDOMAIN param "gamma_minus_one" (< 0); MECH_EINVAL param
 * "gamma_minus_one" (non-finite, or rapidity beyond MECH_BOOST_RAPIDITY_MAX)
 * or "direction" (zero or non-finite while gamma_minus_one > 0). */
enum mech_status mech_boost_from_gamma_minus_one(double gamma_minus_one,
                                                 struct mech_vec3 direction,
                                                 struct mech_boost *out, struct mech_error *err);

/* The boost's 4×4 matrix Λ (x' = Λ x, notes §3 "A Boost in an Arbitrary
 * Direction"): Λ00 = γ, Λ0i = Λi0 = −βγ n_i, Λij = δij + (γ − 1) n_i n_j,
 * from the boost's exact γ − 1 and βγ (so Λ − I is right to round-off at
 * 1 m/s). Row-major, caller-owned m[4][4]. Symmetric; Λ(β)Λ(−β) = I and
 * Λᵀ diag(−1,1,1,1) Λ = diag(−1,1,1,1) to round-off of γ². Cannot fail. */
void mech_boost_matrix(const struct mech_boost *b, double m[4][4]);

/* The inverse boost (same speed, opposite direction). Cannot fail. */
struct mech_boost mech_boost_inverse(const struct mech_boost *b);

/* −x0² + x1² + x2² + x3² of one 4-vector, with error-free products and
 * compensated summation: accurate to about one rounding of the result plus
 * 1e-30 of the largest component squared. Finite for components ≤ 1e154. */
double mech_minkowski_square(const double x[4]);

/* Boost one 4-vector: out = Λ x (out may be the same array as x).
 * inv_before / inv_after (each may be NULL) receive −x0² + |x|² of the input
 * (mech_minkowski_square) and of the output, the latter from the boosted
 * light-cone product −u'v' + |x⊥|² (u' = e^{η}(x0 − x∥), v' = e^{−η}(x0 + x∥)),
 * not from the rounded large output components, which would cancel.
 * Accuracy: each output component within a few ulp of
 * max(|x0'|, |x∥'|, |x|) and, where no cancellation is inherent, of itself
 * (a light-like vector along n keeps full relative precision at η = 35).
 * Statuses: MECH_OK; MECH_ENUMERIC (param "vectors") if the input or a result
 * is not finite; outputs are then unspecified. */
enum mech_status mech_boost_apply(const struct mech_boost *b, const double x[4], double out[4],
                                  double *inv_before, double *inv_after, struct mech_error *err);

/* Boost n 4-vectors: x and out hold 4n doubles each (vector i at x[4i..4i+3];
 * out may equal x). inv_before / inv_after hold n doubles each or are NULL.
 * All arrays are caller-owned. One budget step per vector (budget required).
 * Statuses: MECH_OK; MECH_EINVAL (NULL arrays or budget);
 * MECH_ENUMERIC with param "vectors/<i>" for the first vector with a
 * non-finite input or result; MECH_EBUDGET / MECH_EDEADLINE /
 * MECH_ECANCELLED from mech_budget_check (progress.steps = vectors done). */
enum mech_status mech_boost_apply_batch(const struct mech_boost *b, const double *x, double *out,
                                        double *inv_before, double *inv_after, size_t n,
                                        const struct mech_budget *budget, struct mech_error *err);

#endif
