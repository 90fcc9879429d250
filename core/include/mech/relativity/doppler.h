/* mech/relativity/doppler.h — the relativistic Doppler effect and aberration of light
 * between a source and an observer that both move in some frame (the "lab").
 *
 * Notes §3.14 "The Relativistic Doppler Effect": a wave received along the
 * line of flight is shifted by ν_obs/ν_emit = sqrt((1 ∓ β)/(1 ± β)) = e^{∓η}
 * (receding / approaching); a wave received perpendicular to the motion in
 * the observer's frame is red-shifted by 1/γ (time dilation only). In
 * general, with α_S the angle in the source's frame between the light's
 * direction and the observer's velocity, and α_O the angle in the observer's
 * frame between the light's direction and the source's velocity,
 *   D = ν_obs/ν_emit = γ(1 − β cos α_S) = 1/(γ(1 − β cos α_O)),
 *   tan(α_S/2) tan(α_O/2) = e^{−η}          (aberration, half-angle form),
 * so α_S = 90° gives D = γ (blue) and α_O = 90° gives D = 1/γ (red).
 *
 * Velocities are struct mech_boost (mech/relativity/boost.h): each frame moves with
 * velocity βc relative to the lab, and its axes are the lab's axes carried
 * by the pure boost. The relative motion is computed from the boosts'
 * rapidity and light-cone quantities, not by subtracting rounded β's.
 *
 * Precision: D = e^{−η} + 2 sinh η sin²(α_S/2) is a sum of positive terms, so
 * it keeps full relative precision from β = 1e-12 to γ = 1e15 and beyond;
 * D − 1 = (γ − 1) − sinh η cos α_S is formed from γ − 1 so it stays accurate
 * at 1 m/s; angles come from atan2 of cross and dot products and the half-angle
 * aberration formula, never from acos.
 *
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_DOPPLER_H
#define MECH_DOPPLER_H

#include "mech/relativity/boost.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* The frame in which the light's direction is given. */
enum mech_doppler_frame {
    MECH_DOPPLER_SOURCE_FRAME = 0,  /* emission direction, in the source's rest frame */
    MECH_DOPPLER_OBSERVER_FRAME = 1 /* arrival direction, in the observer's rest frame */
};

/* Which geometry was computed (to within MECH_DOPPLER_CASE_TOL rad). */
enum mech_doppler_case {
    MECH_DOPPLER_NO_RELATIVE_MOTION = 0,   /* D = 1 */
    MECH_DOPPLER_LONGITUDINAL_APPROACHING, /* along the line of flight, closing: D = e^{η} */
    MECH_DOPPLER_LONGITUDINAL_RECEDING,    /* along the line of flight, separating: D = e^{−η} */
    MECH_DOPPLER_TRANSVERSE_SOURCE_FRAME,  /* ⟂ relative velocity in the source frame: D = γ */
    MECH_DOPPLER_TRANSVERSE_OBSERVER_FRAME, /* ⟂ relative velocity in the observer frame: D = 1/γ */
    MECH_DOPPLER_GENERAL
};

/* Tolerance (radians) for naming the case; the numbers always use the exact
 * given geometry (at large γ an angle of 1e-15 rad still changes a receding
 * Doppler factor, which depends on γ²α²). */
#define MECH_DOPPLER_CASE_TOL 1e-15

struct mech_doppler {
    enum mech_doppler_case kind;
    double factor;           /* D = ν_obs/ν_emit = λ_emit/λ_obs > 0 */
    double factor_minus_one; /* D − 1, accurate when D is close to 1 */
    /* relative motion of the two frames */
    double gamma;                             /* γ of the relative velocity */
    double gamma_minus_one;                   /* γ − 1 */
    double beta;                              /* relative speed β in [0, 1) */
    double one_minus_beta;                    /* 1 − β */
    double beta_gamma;                        /* βγ = sinh η */
    double rapidity;                          /* η ≥ 0 */
    struct mech_vec3 observer_beta_in_source; /* observer's velocity/c in the source frame */
    struct mech_vec3 source_beta_in_observer; /* source's velocity/c in the observer frame */
    /* the light, in each frame (unit propagation directions, source → observer) */
    struct mech_vec3 direction_source;
    struct mech_vec3 direction_observer;
    double angle_source;   /* α_S (rad) in [0, π]; NaN when there is no relative motion */
    double angle_observer; /* α_O (rad) in [0, π]; NaN when there is no relative motion */
};

/* Stable name of a case: "no_relative_motion", "longitudinal_approaching",
 * "longitudinal_receding", "transverse_source_frame",
 * "transverse_observer_frame", "general". Never NULL. */
const char *mech_doppler_case_name(enum mech_doppler_case c);

/* The observer's velocity as seen in a frame: given the boosts of a frame F
 * and of a moving body M (both relative to the lab), the spatial part w of M's
 * 4-velocity in F's axes (w = γβ of M relative to F), its unit direction
 * (`direction` may be NULL; exactly ±the moving boost's axis when one of the
 * two rests in the lab or the motion is collinear; F's axis when w = 0), with γ and γ − 1 of that
 * relative motion. Uses the light-cone components of M's 4-velocity, u, v = e^{−η_M} + 2 sinh η_M
 * {sin², cos²}(φ/2) (φ the angle between the two velocities: positive terms, no cancellation),
 * scaled by F's e^{±η_F}, or the γ − 1 form when that is more accurate; a body at rest in the lab
 * or a frame equal to the lab is exact. Cannot fail for boosts built by mech/relativity/boost.h (results
 * overflow only beyond a combined rapidity of about 709, which the boost limit of 350 each
 * excludes). */
void mech_doppler_relative_motion(const struct mech_boost *frame, const struct mech_boost *body,
                                  struct mech_vec3 *w, struct mech_vec3 *direction, double *gamma,
                                  double *gamma_minus_one);

/* Doppler factor and aberration for light travelling from a source to an
 * observer. source / observer: their velocities relative to the lab (NULL
 * means at rest). direction: the light's propagation direction (from source
 * towards observer), any nonzero finite length, in the frame named by
 * `frame`. Statuses: MECH_OK; MECH_EINVAL param "direction" (zero or
 * non-finite); MECH_ENUMERIC if a result is not finite. out is written only
 * on success. */
enum mech_status mech_doppler_compute(const struct mech_boost *source,
                                      const struct mech_boost *observer, struct mech_vec3 direction,
                                      enum mech_doppler_frame frame, struct mech_doppler *out,
                                      struct mech_error *err);

#endif
