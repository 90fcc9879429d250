/* mech/rotation.h — passive rotation matrices from the four orientation forms
 * mechd accepts: a 3x3 matrix, z-x-z Euler angles, an axis and angle, and a
 * unit quaternion.
 *
 * Convention (notes ch. 0 and §2.6; DESIGN.md "Conventions"): rotations are
 * PASSIVE. A rotation matrix R takes the components of a vector in the old
 * (scene) axes to its components in the new (body) axes, v_new = R v_old; the
 * rows of R are the new axes written in the old ones. All four constructors
 * below agree on this: the same physical turn of the axes given any of the four
 * ways yields the same R (pinned by tests/core/test_rotation.c to 1e-15).
 *
 *  - axis-angle (n, a): the axes are turned by a (right-handed, radians) about
 *    the unit axis n: R = cos a 1 + (1 - cos a) n n^T - sin a [n]x, the
 *    transpose of Rodrigues' active matrix. About z by phi this is the notes'
 *    R_phi = [[cos, sin, 0], [-sin, cos, 0], [0, 0, 1]].
 *  - quaternion q = [w, x, y, z] = [cos(a/2), sin(a/2) n]: the same turn as the
 *    axis-angle (n, a); R is the transpose of the usual active matrix of q.
 *  - Euler z-x-z (phi, theta, psi): turn by phi about z, then theta about the
 *    new x (the line of nodes), then psi about the new z: R = R_psi R_theta R_phi
 *    (notes §2.6). At theta = 0 or pi only phi + psi (resp. phi - psi) matters.
 *
 * Pure functions: no allocation, no global state, thread-safe.
 */
#ifndef MECH_ROTATION_H
#define MECH_ROTATION_H

#include "mech/status.h"
#include "mech/vec.h"

/* Largest deviation accepted from orthonormality, max |(R R^T - 1)_ij|, and
 * from det R = +1, for a user-given matrix. */
#define MECH_ROTATION_MATRIX_TOL 1e-9

/* Validate a user-given rotation matrix m (row-major, rows = new axes in old
 * coordinates) and write it to *out, polished to the nearest rotation (two
 * Newton steps of the polar decomposition, R <- (R + R^-T)/2, which take an
 * error of 1e-9 to round-off and leave an exact rotation unchanged to round-off).
 * Returns MECH_OK; MECH_EINVAL with param "matrix" when an entry is not finite,
 * when max |(m m^T - 1)_ij| > MECH_ROTATION_MATRIX_TOL, or when
 * |det m - 1| > MECH_ROTATION_MATRIX_TOL (a reflection, det -1, is refused).
 * out must not be NULL; *out is written only on success. */
enum mech_status mech_rotation_from_matrix(struct mech_mat3 m, struct mech_mat3 *out,
                                           struct mech_error *err);

/* Passive z-x-z Euler rotation R = R_psi R_theta R_phi (notes §2.6), angles in
 * radians, any finite values. MECH_EINVAL with param "euler_zxz" when an angle
 * is not finite. */
enum mech_status mech_rotation_from_euler_zxz(double phi, double theta, double psi,
                                              struct mech_mat3 *out, struct mech_error *err);

/* Passive rotation of the axes by `angle` radians (right-handed) about `axis`
 * (any non-zero finite length; normalised here without overflow or underflow).
 * MECH_EINVAL with param "axis" for a zero or non-finite axis, param "angle"
 * for a non-finite angle. */
enum mech_status mech_rotation_from_axis_angle(struct mech_vec3 axis, double angle,
                                               struct mech_mat3 *out, struct mech_error *err);

/* Passive rotation of the quaternion q = [w, x, y, z] (any non-zero finite
 * length; normalised here), q = [cos(a/2), sin(a/2) n] being the turn by a about
 * n. q and -q give the same matrix. MECH_EINVAL with param "quaternion" for a
 * zero or non-finite q. */
enum mech_status mech_rotation_from_quaternion(const double q[4], struct mech_mat3 *out,
                                               struct mech_error *err);

#endif
