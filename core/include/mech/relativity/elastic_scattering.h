/* mech/relativity/elastic_scattering.h — two-body relativistic elastic scattering
 * m1 + m2 → m1 + m2 off a target at rest in the lab, at a given angle (notes
 * §3 "Kinematics Problems in Electron Volts", problem 16; Compton scattering
 * is the m1 = 0 case), answered in the lab and the centre-of-momentum (CM)
 * frame. Natural units (c = 1): masses, energies and momenta in one energy
 * unit chosen by the caller.
 *
 * Target at rest, projectile (m1 ≥ 0, lab momentum p1 > 0, energy E1):
 *   s = m1² + m2² + 2 m2 E1, √s = W;  p* = p1 m2 / W;
 *   E1* = (m1² + m2 E1)/W,  E2* = m2 (E1 + m2)/W  (sums of positive terms);
 *   CM velocity β = p1/(E1 + m2), βγ = p1/W, γ − 1 = p1²/(W (E1 + m2 + W));
 *   t = −2 p*² (1 − cos θ*) = −4 p*² sin²(θ* / 2), the recoil's lab kinetic
 *   energy T4 = −t/(2 m2) exactly; s + t + u = 2 m1² + 2 m2².
 * Lab angles: tan θ3 = sin θ* / (γ (cos θ* + g)), g = β/β1* =
 *   (m1² + m2 E1)/(m2 (E1 + m2)) (g − 1 = (m1 − m2)(m1 + m2)/(m2 (E1 + m2)),
 *   exactly 1 for equal masses); the recoil's tan θ4 = cot(θ* / 2)/γ.
 * The outgoing lab momenta come from mech_kin_decay_lab (the CM frame is a
 * "parent" decaying at θ*), whose energies have no cancellation backward.
 *
 * Pure functions of their arguments; thread-safe; no allocation.
 */
#ifndef MECH_ELASTIC_SCATTERING_H
#define MECH_ELASTIC_SCATTERING_H

#include <stddef.h>

#include "mech/relativity/boost.h"
#include "mech/relativity/kinematics.h"
#include "mech/base/status.h"

/* Which angle the caller gives. */
enum mech_elastic_angle {
    MECH_ELASTIC_CM_ANGLE = 0,     /* θ* ∈ [0, π]: the projectile's CM scattering angle */
    MECH_ELASTIC_LAB_ANGLE = 1,    /* θ3 ∈ [0, π]: the projectile's lab scattering angle */
    MECH_ELASTIC_RECOIL_ANGLE = 2, /* θ4 ∈ [0, π/2): the recoil's lab angle */
};

struct mech_elastic {
    double s, sqrt_s;          /* Mandelstam s and √s (the CM energy) */
    double t, u;               /* t = −4 p*² sin²(θ* / 2) ≤ 0; u = 2m1² + 2m2² − s − t */
    double momentum_transfer;  /* √(−t) = 2 p* sin(θ* / 2) */
    double cm_momentum;        /* p*, both particles, before and after */
    double cm_energy[2];       /* E1*, E2* (unchanged by an elastic collision) */
    double cm_kinetic[2];      /* T1* = p*²/(E1* + m1), T2* = p*²/(E2* + m2) */
    double cm_angle;           /* θ* of the projectile (the recoil leaves at π − θ* from +z) */
    struct mech_boost cm;      /* the CM frame's velocity, along +z (the beam) */
    double velocity_ratio;     /* g = β_cm / β1* (projectile's CM speed); 1 for equal masses */
    struct mech_kin_lab projectile; /* scattered projectile in the lab (momentum_transverse ≥ 0) */
    struct mech_kin_lab recoil;     /* recoiling target in the lab (momentum_transverse ≤ 0) */
    double opening_angle;      /* lab angle between the outgoing momenta, θ3 + θ4 */
    int has_max_angle;         /* 1 when g > 1: the projectile's lab angle is bounded */
    double max_angle;          /* tan θmax = 1/(γ sqrt(g² − 1)) when has_max_angle */
    size_t n_solutions;        /* 1, or 2 for a lab angle below θmax when g > 1 */
    double cm_angle_solutions[2]; /* every θ* giving the requested angle, ascending */
};

/* Elastic scattering of `projectile` (a motion built by mech_kin_motion_*:
 * mass m1 ≥ 0, momentum p1 > 0) off a target of mass m2 > 0 at rest, at the
 * angle `angle` (radians) of kind `kind`. A lab angle has two CM solutions
 * when the projectile is heavier than the target (g > 1) and the angle is
 * below θmax; `branch` (0 or 1) picks the smaller or larger θ* (0 when there
 * is one; 1 then means the only one). Inputs are scaled by a power of two, so
 * any finite energies work. Statuses: MECH_OK; MECH_EINVAL param "angle" (NaN
 * or outside its range: [0, π] or, for the recoil, [0, π/2)) or "branch";
 * MECH_EDOMAIN param "target" (m2 ≤ 0 or not finite), "projectile" (p1 ≤ 0:
 * nothing arrives to scatter; or inconsistent m1, p1, E1), "angle" (a lab angle
 * above θmax, the text giving θmax in degrees; the recoil at 90° or more);
 * MECH_ENUMERIC if a result is not finite. out is written only on success. */
enum mech_status mech_elastic_scatter(const struct mech_kin_motion *projectile, double m2,
                                      enum mech_elastic_angle kind, double angle, int branch,
                                      struct mech_elastic *out, struct mech_error *err);

#endif
