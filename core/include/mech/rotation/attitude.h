/* mech/rotation/attitude.h — unit-quaternion attitude kinematics for rigid bodies.
 *
 * Convention (mech/rotation/rotation.h, the notes' convention): orientations are PASSIVE. The
 * quaternion q = [w, x, y, z] = [cos(a/2), sin(a/2) n] describes the turn of
 * the space axes by a about n into the body axes; its passive matrix
 * R = (w^2 - |v|^2) 1 + 2 v v^T - 2 w [v]x takes space components to body
 * components (rows of R = body axes in space axes), exactly as
 * mech_rotation_from_quaternion() builds it.
 *
 * Kinematics: with the angular velocity w_b in BODY components,
 * dq/dt = 1/2 q (x) (0, w_b) (Hamilton product), which keeps |q| constant in
 * exact arithmetic.
 *
 * Pure functions on small arrays: no allocation, no state, thread-safe.
 * Quaternions need not be normalised on input unless a function says so.
 */
#ifndef MECH_ATTITUDE_H
#define MECH_ATTITUDE_H

#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Hamilton product out = a (x) b (out may alias neither input). */
void mech_attitude_quat_mul(const double a[4], const double b[4], double out[4]);

/* dq/dt = 1/2 q (x) (0, omega_body) (rad/s). */
void mech_attitude_quat_rate(const double q[4], struct mech_vec3 omega_body, double dq[4]);

/* Passive matrix R of q / |q| (space -> body components). q must be finite
 * and non-zero (not checked: callers integrate from a unit quaternion). */
struct mech_mat3 mech_attitude_matrix(const double q[4]);

/* Space components of a body vector (R^T v) and body components of a space
 * vector (R v), for q / |q|. */
struct mech_vec3 mech_attitude_to_space(const double q[4], struct mech_vec3 v_body);
struct mech_vec3 mech_attitude_to_body(const double q[4], struct mech_vec3 v_space);

/* Unit quaternion of a passive rotation matrix R (Shepperd's method: the
 * largest of w^2, x^2, y^2, z^2 is taken from the trace combination that gives
 * it, so no division by a small number), sign fixed so that the first non-zero
 * of w, x, y, z (in that order, |.| > 1e-15) is positive. R must be a rotation
 * (not checked; use mech_rotation_from_matrix() to validate first). */
void mech_attitude_from_matrix(struct mech_mat3 r, double q[4]);

/* Quaternion of z-x-z Euler angles (notes §2.6): R = R_psi R_theta R_phi,
 * q = q_z(phi) (x) q_x(theta) (x) q_z(psi), i.e.
 * w = cos(theta/2) cos((phi+psi)/2), x = sin(theta/2) cos((phi-psi)/2),
 * y = sin(theta/2) sin((phi-psi)/2), z = cos(theta/2) sin((phi+psi)/2). */
void mech_attitude_from_euler_zxz(double phi, double theta, double psi, double q[4]);

/* z-x-z Euler angles of q / |q|: theta in [0, pi] from
 * 2 atan2(sqrt(x^2 + y^2), sqrt(w^2 + z^2)) (accurate at both poles),
 * s = phi + psi = 2 atan2(z, w), d = phi - psi = 2 atan2(y, x).
 * At theta = 0 only s is determined and at theta = pi only d: the free one is
 * taken from *psi_hint (theta = 0: psi = *psi_hint, phi = s - psi) or
 * *psi_hint again (theta = pi: psi = *psi_hint, phi = d + psi); *gimbal is
 * set to 1 there (0 otherwise; may be NULL). Angles are NOT unwrapped; phi and
 * psi are in (-2 pi, 2 pi] away from the poles. */
void mech_attitude_euler_zxz(const double q[4], double psi_hint, double *phi, double *theta,
                             double *psi, int *gimbal);

#endif
