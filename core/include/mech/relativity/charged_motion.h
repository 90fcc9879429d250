/* mech/relativity/charged_motion.h — the exact special-relativistic motion of a point
 * charge in uniform, static E and B (and any constant force, which acts as
 * an electric field F/q): the helix in B, hyperbolic motion in E, the E x B
 * drift (|E| < c|B|, E perpendicular to B), crossed fields with |E| > c|B|,
 * parallel E and B, and every other non-null uniform field.
 *
 * Equation of motion (SI): dp/dt = q (E + v x B) + F, p = gamma m v. Written
 * per unit mass with the proper velocity u = gamma v (m/s):
 *   du/dt = eps + v x Omega,   eps = (q E + F)/m (m/s^2),  Omega = q B/m (rad/s),
 * and in proper time tau with U^0 = gamma c:
 *   dU^0/dtau = eps.u / c,   du/dtau = (U^0/c) eps + u x Omega.
 *
 * Method (Landau & Lifshitz, The Classical Theory of Fields, sections 20-22;
 * Jackson, Classical Electrodynamics, section 12.4): unless E and B are
 * already parallel (or one is zero), boost to the frame S' moving with
 * velocity w along eps x Omega where they are parallel,
 *   (w/c) / (1 + w^2/c^2) = c |eps x Omega| / (eps^2 + c^2 Omega^2),
 * taken as w/c = 2s / (1 + sqrt(1 - 4 s^2)) (s the right-hand side; the
 * drift w = E/B for |E| < c|B| crossed, c^2 B/E for |E| > c|B|). There the
 * fields are eps' = a n and Omega' = omega n, their sizes from the two
 * invariants I1 = eps^2 - c^2 Omega^2 = a^2 - c^2 omega^2 and
 * I2 = eps.Omega = a omega (never from the cancelling vector sum), and the
 * motion in proper time is exact:
 *   (U^0, u_n) turn hyperbolically at rate k = a/c:
 *     U^0 = U^0_0 cosh k tau + u_n0 sinh k tau,  u_n = u_n0 cosh + U^0_0 sinh;
 *   u_perp turns about n by the angle -omega tau;
 *   c t = c t_0 + U^0_0 S_k + u_n0 C_k,  r_n = r_n0 + u_n0 S_k + U^0_0 C_k,
 *   r_perp = r_perp0 + u_perp0 S_w - (n x u_perp0) C_w,
 * with S_k = sinh(k tau)/k, C_k = (cosh(k tau) - 1)/k = 2 sinh^2(k tau/2)/k,
 * S_w = sin(omega tau)/omega, C_w = (1 - cos(omega tau))/omega, all written
 * as tau times sinh(x)/x, sin(x)/x forms so nothing cancels for small k tau,
 * omega tau. The event is then boosted back to the lab. gamma - 1 is always
 * u^2/c^2 / (gamma + 1), never 1/sqrt(1 - beta^2) - 1.
 *
 * Lab time to proper time: t(tau) increases with dt/dtau = gamma >= 1. With
 * no boost it is inverted exactly (magnetic: tau = t/gamma0; with an
 * electric part: the root of a quadratic in e^{k tau}, taken with log1p and
 * no cancellation); otherwise by Newton's method on t(tau), safeguarded by
 * bisection on [0, t], to a few ulps.
 *
 * Not covered: null fields (E perpendicular to B with |E| = c|B| exactly,
 * both invariants zero, E != 0): no frame makes them parallel (MECH_EDOMAIN).
 *
 * Units: SI. Thread-safety: reentrant, no globals, no allocation.
 */
#ifndef MECH_CHARGED_MOTION_H
#define MECH_CHARGED_MOTION_H

#include "mech/base/status.h"
#include "mech/base/vec.h"

/* What the uniform fields are, the frame classification a course names. */
enum mech_charged_field_kind {
    MECH_CHARGED_FREE = 0,         /* eps = 0 and Omega = 0: straight line */
    MECH_CHARGED_MAGNETIC,         /* eps = 0: the helix */
    MECH_CHARGED_ELECTRIC,         /* Omega = 0: hyperbolic motion */
    MECH_CHARGED_PARALLEL,         /* eps parallel to Omega, both non-zero */
    MECH_CHARGED_CROSSED_MAGNETIC, /* eps perpendicular to Omega, |eps| < c|Omega|: E x B
                                      drift; E vanishes in the drift frame */
    MECH_CHARGED_CROSSED_ELECTRIC, /* eps perpendicular, |eps| > c|Omega|: B vanishes in
                                      the frame moving at c^2 B/E */
    MECH_CHARGED_GENERAL,          /* neither: parallel in the boosted frame */
};

/* "free", "magnetic", "electric", "parallel", "crossed_magnetic",
 * "crossed_electric", "general" (static). */
const char *mech_charged_field_kind_name(enum mech_charged_field_kind k);

/* A prepared motion: the fields and the initial state, seen from the frame
 * where the fields are parallel. Filled by mech_charged_motion_init; read
 * its public members, treat the rest as internal. */
struct mech_charged_motion {
    enum mech_charged_field_kind kind;
    struct mech_vec3 eps, omega;     /* the lab fields (m/s^2, rad/s) as given */
    /* the frame S' where the fields are parallel (or one vanishes) */
    int boosted;                     /* 0: S' is the lab */
    struct mech_vec3 beta_w;         /* its velocity / c in the lab (0 when not boosted) */
    double beta_w_norm, gamma_w;     /* |beta_w| and its gamma (1 when not boosted) */
    double a_prime;                  /* |eps'| >= 0 (m/s^2), along n */
    double omega_prime;              /* Omega'.n (rad/s, signed) */
    struct mech_vec3 n;              /* unit direction of the fields in S' (any unit
                                        vector for the free particle) */
    /* internal: the initial event and 4-velocity in S' (m, m/s) */
    double ct0p, U00p, un0p;
    struct mech_vec3 rn0p, rperp0p, uperp0p, nxuperp0p;
    struct mech_vec3 r0, u0;         /* the lab initial state as given */
    double gamma0;                   /* the initial Lorentz factor */
};

/* One state on the worldline. */
struct mech_charged_motion_state {
    double t;                /* lab time since the start, s */
    double tau;              /* proper time since the start, s */
    struct mech_vec3 r;      /* lab position, m */
    struct mech_vec3 u;      /* proper velocity gamma v, m/s */
    struct mech_vec3 v;      /* velocity u / gamma, m/s */
    double gamma;            /* sqrt(1 + u^2/c^2) */
    double gamma_minus_1;    /* u^2/c^2 / (gamma + 1), exact for slow particles */
};

/* Prepare the motion from r0 (m) and proper velocity u0 = gamma0 v0 (m/s) at
 * t = 0 in the fields eps = (q E + F)/m (m/s^2) and Omega = q B/m (rad/s),
 * all finite. Statuses: MECH_OK; MECH_EINVAL (NULL m, a non-finite input,
 * param "eps", "omega", "r0", "u0"); MECH_EDOMAIN (null fields: E
 * perpendicular to B and |E| = c|B| to within 1e-12 of their scale, where
 * no frame makes them parallel: param "fields"). */
enum mech_status mech_charged_motion_init(struct mech_vec3 eps, struct mech_vec3 omega,
                                          struct mech_vec3 r0, struct mech_vec3 u0,
                                          struct mech_charged_motion *m, struct mech_error *err);

/* The state at proper time tau >= 0 (s) since the start. Statuses: MECH_OK;
 * MECH_EINVAL (NULL, tau not finite or < 0, param "tau"); MECH_ENUMERIC (the
 * state overflows: gamma beyond ~1e300, param "tau"). */
enum mech_status mech_charged_motion_at_proper_time(const struct mech_charged_motion *m,
                                                    double tau, struct mech_charged_motion_state *s,
                                                    struct mech_error *err);

/* The state at lab time t >= 0 (s) since the start (proper time found as
 * the header says). Statuses: those of mech_charged_motion_at_proper_time,
 * param "t". */
enum mech_status mech_charged_motion_at_lab_time(const struct mech_charged_motion *m, double t,
                                                 struct mech_charged_motion_state *s,
                                                 struct mech_error *err);

#endif
