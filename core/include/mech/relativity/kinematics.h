/* mech/relativity/kinematics.h — relativistic particle kinematics (notes §3, "Kinematics
 * Problems in Electron Volts", π⁰ decay, neutron decay, Compton scattering):
 * invariant masses, two- and three-body decays, Compton scattering and
 * collisions, in natural units (c = 1; energies, masses and momenta all in one
 * energy unit chosen by the caller).
 *
 * Precision: nothing is computed as a difference of large nearly equal
 * numbers when a cancellation-free form exists. Pair invariants
 * E_a E_b − p_a·p_b are a sum of non-negative terms (mass terms plus
 * |p_a||p_b|·2 sin²(θ/2) with θ from atan2 of an fma cross/dot product);
 * Q-values and thresholds come from compensated sums of masses; kinetic
 * energies are p²/(E + m); rest-frame momenta use the factored Källén function.
 * Boosts reuse struct mech_boost (mech/relativity/boost.h) filled from the
 * precise quantities (γ − 1 = T/m, βγ = p/m, 1 − β = m²/(E(E + p))).
 *
 * Pure functions of their arguments; thread-safe; no allocation.
 */
#ifndef MECH_KINEMATICS_H
#define MECH_KINEMATICS_H

#include <stddef.h>

#include "mech/relativity/boost.h"
#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Which member of a motion is the caller's own number (exact), the others
 * being computed from it and the mass. A motion at rest or from a velocity
 * counts as given by its momentum (0, or m βγ of the boost). */
enum mech_kin_given {
    MECH_KIN_GIVEN_MOMENTUM = 0,
    MECH_KIN_GIVEN_ENERGY = 1,
    MECH_KIN_GIVEN_KINETIC = 2,
};

/* A free particle's energy bookkeeping (c = 1): mass m ≥ 0, momentum
 * magnitude p ≥ 0, energy E = hypot(m, p), kinetic energy T = E − m computed
 * as p²/(E + m) or taken from the caller's T (never E − m of a rounded E when
 * T was given). `given` records which of p, E, T was the input. */
struct mech_kin_motion {
    double mass, momentum, energy, kinetic;
    enum mech_kin_given given;
};

/* Build a motion from the mass and one of: momentum p ≥ 0, total energy
 * E ≥ m, kinetic energy T ≥ 0, or at rest. Statuses: MECH_OK; MECH_EDOMAIN
 * with param "mass" (m < 0 or not finite), "momentum" (p < 0), "energy"
 * (E < m: "energy below the rest energy"), "kinetic_energy" (T < 0), or
 * (for a massless particle at rest / with E = 0) the param of the motion given,
 * or "mass" for at_rest. out is written only on success. */
enum mech_status mech_kin_motion_from_momentum(double m, double p, struct mech_kin_motion *out,
                                               struct mech_error *err);
enum mech_status mech_kin_motion_from_energy(double m, double e, struct mech_kin_motion *out,
                                             struct mech_error *err);
enum mech_status mech_kin_motion_from_kinetic(double m, double t, struct mech_kin_motion *out,
                                              struct mech_error *err);
enum mech_status mech_kin_motion_at_rest(double m, struct mech_kin_motion *out,
                                         struct mech_error *err);

/* Motion of a particle of mass m > 0 moving with the velocity of boost b
 * (T = m(γ − 1), p = m βγ). Statuses: MECH_OK; MECH_EDOMAIN param "mass"
 * (m ≤ 0: a massless particle has no velocity below c). */
enum mech_status mech_kin_motion_from_boost(double m, const struct mech_boost *b,
                                            struct mech_kin_motion *out, struct mech_error *err);

/* p_a − p_b of two motions along one line (e.g. the total momentum of two
 * head-on beams), formed from the numbers the motions were built from rather
 * than from the two rounded momenta: (p_a² − p_b²)/(p_a + p_b) with each p²
 * an exact sum of products of its inputs (p·p; E·E − m·m; T·T + 2m·T, split
 * by fma) and the difference summed in about triple precision (Ogita–Rump–
 * Oishi SumK, K = 3). Relative error a few ε even when p_a and p_b agree to
 * 1e-12 and beyond; a − b of the rounded momenta is off by ε p/(p_a − p_b).
 * A motion from a velocity is as exact as its m βγ. Inputs are scaled by one
 * power of two, so any finite motions work; squares more than 2^-1000 below
 * the largest underflow (their contribution is then below ε of the result's
 * scale). Both at rest: 0. Pure; cannot fail. */
double mech_kin_momentum_difference(const struct mech_kin_motion *a,
                                    const struct mech_kin_motion *b);

/* The boost to the particle's rest frame (its velocity p/E along direction):
 * γ = E/m, γ − 1 = T/m, βγ = p/m, 1 − β = m²/(E(E + p)), η = log1p(βγ + γ − 1).
 * Statuses: MECH_OK; MECH_EDOMAIN param "mass" (m ≤ 0: no rest frame);
 * MECH_EINVAL param "direction" (zero or non-finite direction when p > 0). */
enum mech_status mech_kin_motion_boost(const struct mech_kin_motion *k, struct mech_vec3 direction,
                                       struct mech_boost *out, struct mech_error *err);

/* ---- invariant mass ------------------------------------------------------ */

/* One particle: mass ≥ 0, energy, momentum 3-vector, with energy² = mass² + |p|². */
struct mech_kin_particle {
    double mass;
    double energy;
    struct mech_vec3 momentum;
};

/* From a 4-momentum [E, px, py, pz]: m² = E² − |p|² with error-free products
 * and compensated summation (mech_minkowski_square). A result spacelike by no
 * more than 8 ε E² (rounding of a light-like input such as [1, 0.6, 0.8, 0])
 * is taken as massless and *clamped (may be NULL) is set to 1.
 * Statuses: MECH_OK; MECH_EDOMAIN (param NULL) when E < 0 or E < |p| beyond
 * that tolerance (an unphysical, spacelike 4-momentum), with a sentence
 * stating E and |p|; MECH_EINVAL for non-finite input. */
enum mech_status mech_kin_particle_from_four(const double p4[4], struct mech_kin_particle *out,
                                             int *clamped, struct mech_error *err);

/* From a mass m ≥ 0 and a momentum 3-vector: E = hypot(m, |p|).
 * Statuses: MECH_OK; MECH_EDOMAIN param "mass" (m < 0); MECH_EINVAL
 * (non-finite). */
enum mech_status mech_kin_particle_from_mass(double m, struct mech_vec3 p,
                                             struct mech_kin_particle *out, struct mech_error *err);

/* E_a E_b − p_a·p_b ≥ 0 of two physical particles, without cancellation:
 *   (m_a² E_b² + |p_a|² m_b²)/(E_a E_b + |p_a||p_b|) + |p_a||p_b| · 2 sin²(θ/2),
 * θ = atan2(|p_a × p_b|, p_a·p_b) with fma-accurate cross and dot products.
 * Every term is ≥ 0, so the result is accurate to a few ulp, for massless and
 * nearly collinear particles too. Inputs should be scaled so squares of the
 * energies neither overflow nor underflow (|E| within 1e-70 … 1e70). */
double mech_kin_pair_product(const struct mech_kin_particle *a, const struct mech_kin_particle *b);

/* The same with the angle between the momenta given through 1 − cos θ
 * (0 … 2, e.g. 2 for head-on, 2 sin²(θ/2) in general) and magnitudes only. */
double mech_kin_pair_product_angle(const struct mech_kin_motion *a, const struct mech_kin_motion *b,
                                   double one_minus_cos);

/* A system's total 4-momentum and its centre-of-momentum (CM) velocity. */
struct mech_kin_system {
    double mass;               /* invariant mass M = sqrt(M²) ≥ 0 */
    double mass_squared;       /* M² = Σ m_i² + 2 Σ_{i<j} (E_iE_j − p_i·p_j) */
    double energy;             /* Σ E_i */
    struct mech_vec3 momentum; /* Σ p_i (compensated sums) */
    double momentum_norm;      /* |Σ p_i| */
    int has_rest_frame;        /* 0 when M = 0 (light-like total): no CM frame */
    /* CM velocity (valid when has_rest_frame): β = P/E along `direction`. */
    struct mech_vec3 beta;  /* β vector */
    double gamma;           /* E/M */
    double gamma_minus_one; /* |P|²/(M(E + M)) */
    double beta_gamma;      /* |P|/M */
    double one_minus_beta;  /* M²/(E(E + |P|)) */
    double rapidity;        /* log1p(βγ + γ − 1) = asinh(|P|/M) */
};

/* Invariant mass and CM velocity of n ≥ 1 particles. O(n²) pair products
 * (all non-negative, so M² has no cancellation; relative error ≲ 4ε + n ε)
 * after scaling every component by one power of two; one budget step per
 * particle. Statuses: MECH_OK; MECH_EINVAL (NULL, n = 0, no budget);
 * MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED; MECH_ENUMERIC if a result
 * is not finite. */
enum mech_status mech_kin_invariant_mass(const struct mech_kin_particle *ps, size_t n,
                                         const struct mech_budget *budget,
                                         struct mech_kin_system *out, struct mech_error *err);

/* Fill the CM-velocity members of *out from M ≥ 0, M² , E > 0 and the total
 * momentum (mass, mass_squared, energy, momentum must already be set). */
void mech_kin_system_finish(struct mech_kin_system *out);

/* ---- decays -------------------------------------------------------------- */

/* Q = M − Σ m_i with a compensated sum (exact for the usual masses). */
double mech_kin_q_value(double parent, const double *m, size_t n);

/* Two-body decay M → m1 + m2 in the parent's rest frame:
 * p* = sqrt(λ(M², m1², m2²))/(2M) with λ factored as
 * (M − m1 − m2)(M + m1 + m2)(M − m1 + m2)(M + m1 − m2) (M − m1 − m2 = Q, from a
 * compensated sum), E_i* = hypot(m_i, p*), T_i* = p*²/(E_i* + m_i). */
struct mech_kin_two_body {
    double q_value;
    double momentum;
    double energy[2];
    double kinetic[2];
};

/* Statuses: MECH_OK; MECH_EDOMAIN param "parent/particle" (M ≤ 0) or
 * "daughters" (M < m1 + m2: below threshold, text says by how much). */
enum mech_status mech_kin_two_body_rest(double parent, double m1, double m2,
                                        struct mech_kin_two_body *out, struct mech_error *err);

/* A daughter (mass m, rest-frame momentum p*, energy E*) emitted at rest-frame
 * angle θ* to the parent's direction of motion (boost b: the parent's
 * velocity), seen in the lab. If `partner` is nonzero the daughter is the one
 * emitted opposite (at θ* + π, on the other side of the axis).
 * E = γE* + βγ p* cos θ* (forward) or γ(E* − βp*) + βγ p*·2cos²(θ* / 2) with
 * γ(E* − βp*) = (γm² + p*²/γ)/(E* + βp*) (backward): all terms ≥ 0.
 * p_par = γ p* cos θ* + βγ E*, p_perp = p* sin θ* (signed: the partner has the
 * opposite sign), angle = atan2(|p_perp|, p_par) ∈ [0, π]. */
struct mech_kin_lab {
    double energy, kinetic, momentum, momentum_parallel, momentum_transverse, angle;
};
void mech_kin_decay_lab(const struct mech_boost *b, double m, double pstar, double estar,
                        double theta_star, int partner, struct mech_kin_lab *out);

/* Largest lab angle of a daughter, sin θ_max = (p* / m)/(βγ), when it exists
 * (daughter's rest-frame speed below the parent's: p* < m βγ); returns 0 and
 * leaves *theta_max unset otherwise (any angle up to π, or up to π/2 not
 * attained when equal). */
int mech_kin_decay_max_angle(const struct mech_boost *b, double m, double pstar, double *theta_max);

/* Minimum lab opening angle between the two daughters over all θ* in [0, π]
 * (sampled at 513 points then refined by golden section: a fixed amount of
 * work). *at_theta_star receives the rest-frame angle of daughter 1 where it
 * occurs. For massless daughters it equals 2 asin(1/γ) at θ* = 90°. */
void mech_kin_decay_min_opening(const struct mech_boost *b, const double m[2], double pstar,
                                const double estar[2], double *angle, double *at_theta_star);

/* Energy ranges of daughter `which` (0 or 1) when it is seen within lab angle
 * half_angle (0, π] of the parent's direction: up to two disjoint intervals
 * [lo, hi] (two when the daughter has a maximum lab angle above half_angle:
 * forward and backward rest-frame emission both reach the cone). Returns the
 * number of intervals (1 or 2) written to ranges[0..1][0..1]. The lab angle is
 * inverted by bisection in θ* on monotone pieces (fixed ≤ 200 halvings). */
int mech_kin_decay_cone(const struct mech_boost *b, double m, double pstar, double estar,
                        double half_angle, double ranges[2][2], double theta_star_edges[2]);

/* Largest energy a daughter i of an n-body decay can have (rest frame):
 * E_max = (M² + m_i² − (Σ_{j≠i} m_j)²)/(2M), computed as
 * T_max = Q (M − m_i + S_i)/(2M), S_i = Σ_{j≠i} m_j, E_max = m_i + T_max,
 * p_max = sqrt(T_max (T_max + 2 m_i)) — the other daughters recoil together as
 * one body of mass S_i. Statuses: MECH_OK; MECH_EINVAL (n < 2, i ≥ n);
 * MECH_EDOMAIN param "daughters" (Q < 0). */
enum mech_status mech_kin_endpoint(double parent, const double *m, size_t n, size_t i,
                                   double *e_max, double *t_max, double *p_max,
                                   struct mech_error *err);

/* Three-body decay at rest in one plane: theta12, theta23 are the angles
 * between the momenta of daughters 1–2 and 2–3 (radians), the third is
 * 2π − θ12 − θ23. Momentum balance fixes the ratios
 * p1 : p2 : p3 = sin θ23 : sin θ31 : sin θ12 (sine rule of the closed
 * triangle); energy conservation Σ T_i = Q fixes the scale (bisection on a
 * monotone sum of non-negative kinetic energies, ≤ 200 halvings).
 * Statuses: MECH_OK; MECH_EDOMAIN param "daughters" (Q < 0) or "angles"
 * (an angle outside (0, π] or all momenta forced to zero). */
enum mech_status mech_kin_three_body_planar(double parent, const double m[3], double theta12,
                                            double theta23, double momentum[3], double energy[3],
                                            double kinetic[3], struct mech_error *err);

/* ---- Compton scattering -------------------------------------------------- */

struct mech_kin_compton {
    double one_minus_cos;   /* 1 − cos θ = 2 sin²(θ/2) */
    double energy_out;      /* E' = E/(1 + (E/m)(1 − cos θ)) */
    double recoil_kinetic;  /* T = E − E' = E k/(1 + k), k = (E/m)(1 − cos θ) */
    double recoil_momentum; /* sqrt(T(T + 2m)) */
    double recoil_angle;    /* φ with cot φ = (1 + E/m) tan(θ/2), in [0, π/2] */
};

/* Photon of energy e > 0 scattered by angle theta ∈ [0, π] off a target of
 * mass m > 0 at rest (notes §3 "Compton Scattering": 1/E' − 1/E = (1 − cos θ)/m).
 * Statuses: MECH_OK; MECH_EDOMAIN param "target" (m ≤ 0) or "energy" (e ≤ 0);
 * MECH_EINVAL param "angle" (outside [0, π]). */
enum mech_status mech_kin_compton(double e, double m, double theta, struct mech_kin_compton *out,
                                  struct mech_error *err);

/* ---- collisions ---------------------------------------------------------- */

/* s = m1² + m2² + 2(E1E2 − p1·p2) for momenta at angle α (1 − cos α given;
 * 2 for head-on, 0 for the same direction) via mech_kin_pair_product_angle,
 * and s − (m1 + m2)² = 2(E1E2 − p1·p2 − m1m2) without cancellation
 * (T1E2 + m1T2 + p1p2 for head-on; 2m1m2 sinh²(Δη/2) + p1p2(1 − cos α)
 * otherwise). */
void mech_kin_collision_s(const struct mech_kin_motion *a, const struct mech_kin_motion *b,
                          double one_minus_cos, double *s, double *s_minus_threshold);

/* CM momentum p* = sqrt(d (d + 4 m1 m2))/(2√s), d = s − (m1 + m2)². */
double mech_kin_cm_momentum(double sqrt_s, double d, double m1, double m2);

/* Beam kinetic energy on a target of mass m2 > 0 at rest that gives
 * √s = w: T = (w − m1 − m2)(w + m1 + m2)/(2 m2) (w − m1 − m2 compensated).
 * Statuses: MECH_OK; MECH_EDOMAIN param "target/particle" (m2 ≤ 0: a massless
 * target cannot be at rest) or "sqrt_s" (w < m1 + m2: the two particles at
 * rest already have more energy). */
enum mech_status mech_kin_fixed_target_kinetic(double w, double m1, double m2, double *kinetic,
                                               struct mech_error *err);

#endif
