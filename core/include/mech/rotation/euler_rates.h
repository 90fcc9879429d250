/* mech/rotation/euler_rates.h — Euler-angle kinematics (notes §2.6 "Euler Angles",
 * "Body Frame Coordinates"; ch. 0 HW 7): the angular velocity in body and in
 * space axes from z-x-z angles and their rates, the time derivative of the
 * rotation matrix and its relation to omega, and back from omega to the rates.
 *
 * Convention: passive R = R_psi R_theta R_phi (mech/rotation/rotation.h), scene (space)
 * components -> body components. With the body axes turning at omega,
 *   dR/dt = -[omega_body]x R = -R [omega_space]x,   omega_space = R^T omega_body,
 * where [w]x v = w x v ([w]x = [[0,-w3,w2],[w3,0,-w1],[-w2,w1,0]]). (The active
 * matrix A = R^T obeys dA/dt = [omega_space]x A.) For a turn about z at rate w
 * (ch. 0 HW 7), dR/dt at t = 0 is w [[0,1,0],[-1,0,0],[0,0,0]] = -[w z]x.
 * Body components (Goldstein (4.87)):
 *   w1 = phi' sin(theta) sin(psi) + theta' cos(psi)
 *   w2 = phi' sin(theta) cos(psi) - theta' sin(psi)
 *   w3 = phi' cos(theta) + psi'
 * space components:
 *   wx = theta' cos(phi) + psi' sin(theta) sin(phi)
 *   wy = theta' sin(phi) - psi' sin(theta) cos(phi)
 *   wz = phi' + psi' cos(theta)
 * Units: rad, rad/s (or any time unit, used throughout). Pure, thread-safe.
 */
#ifndef MECH_EULER_RATES_H
#define MECH_EULER_RATES_H

#include "mech/base/status.h"
#include "mech/base/constants.h"
#include "mech/base/vec.h"

/* |sin theta| at or below this is gimbal lock: theta = 0 or pi within round-off
 * of pi's double (sin(MECH_PI) = 1.2e-16). */
#define MECH_EULER_LOCK_SIN 1e-15

struct mech_euler_kinematics {
    double rates[3];                 /* phi', theta', psi' (rad/s) */
    struct mech_vec3 omega_body;     /* rad/s, body components */
    struct mech_vec3 omega_space;    /* rad/s, space components */
    struct mech_mat3 rotation;       /* passive R */
    struct mech_mat3 rotation_rate;  /* dR/dt (1/s), by the product rule on R_psi R_theta
                                        R_phi: independent of the omega formulas */
    struct mech_mat3 omega_cross_body;  /* -dR/dt R^T = [omega_body]x */
    struct mech_mat3 omega_cross_space; /* -R^T dR/dt = [omega_space]x */
    double residual;                 /* max |dR/dt + [omega_body]x R|_ij: the two routes
                                        agree to round-off (~1e-16 |omega|) */
    int gimbal_lock;                 /* |sin theta| <= MECH_EULER_LOCK_SIN: the forward map is
                                        still exact, but phi' and psi' enter omega only through
                                        phi' + psi' (theta = 0) or psi' - phi' (theta = pi) */
};

/* Forward map: angles (phi, theta, psi) and rates (phi', theta', psi'), all
 * finite, to everything in struct mech_euler_kinematics. No singularity
 * (gimbal lock is only flagged). Returns MECH_OK; MECH_EINVAL with param
 * "euler_zxz" or "rates" for a non-finite value; MECH_ENUMERIC (param
 * "rates") if a result overflows. out must not be NULL. */
enum mech_status mech_euler_kinematics(const double angles[3], const double rates[3],
                                       struct mech_euler_kinematics *out,
                                       struct mech_error *err);

/* Inverse map: omega (rad/s; body components if body != 0, else space
 * components) at the angles -> the rates, then the forward map (*out).
 *   theta' = w1 cos(psi) - w2 sin(psi),  phi' = (w1 sin(psi) + w2 cos(psi)) / sin(theta),
 *   psi' = w3 - phi' cos(theta).
 * At gimbal lock (out->gimbal_lock set) phi' and psi' are not separately
 * determined: *combined receives phi' + psi' (theta = 0) or psi' - phi'
 * (theta = pi), and the rates are reported with phi' = 0 (so psi' = the
 * combination); the caller says so. At the lock an omega with a component
 * along (sin psi, cos psi, 0) (body axes) beyond 1e-12 |omega| would need an
 * infinite phi': MECH_EDOMAIN with param "omega_body" / "omega_space".
 * Other errors: MECH_EINVAL "euler_zxz" or "omega_body"/"omega_space" for
 * non-finite input; MECH_ENUMERIC if a rate overflows (theta extremely close
 * to, but not at, the lock). combined may be NULL. */
enum mech_status mech_euler_rates_from_omega(const double angles[3], struct mech_vec3 omega,
                                             int body, struct mech_euler_kinematics *out,
                                             double *combined, struct mech_error *err);

#endif
