/* mech/rotation/rotation.h — rotations: passive matrices from the orientation forms
 * mechd accepts (a 3x3 matrix, z-x-z Euler angles, an axis and angle, a unit
 * quaternion; and, further down, the 12 Euler sequences intrinsic or
 * extrinsic and the rotation vector), conversions back to every form with
 * gimbal-lock handling, composition, residuals, and the active sense.
 *
 * Convention (notes ch. 0 and §2.6; docs/design.md): rotations are
 * PASSIVE. A rotation matrix R takes the components of a vector in the old
 * (scene) axes to its components in the new (body) axes, v_new = R v_old; the
 * rows of R are the new axes written in the old ones. All four constructors
 * below agree on this: the same physical turn of the axes given any of the four
 * ways yields the same R (pinned by tests/core/rotation/test_rotation.c to 1e-15).
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

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

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

/* ==== Representations, conversions and composition ========================
 *
 * Every form below describes one TURN (a right-handed rotation by some angle
 * about some axis). Its matrix depends on the SENSE:
 *  - passive (default, the notes' convention): the axes are turned; R takes a
 *    vector's components in the old axes to its components in the new axes.
 *  - active: the vector is turned in fixed axes; R maps v to the turned v.
 * R_active = R_passive^T for the same turn. A form's parameters therefore do
 * NOT depend on the sense; only the matrix does (and a `matrix` input is read
 * in the sense given).
 *
 * Internally a turn is a unit quaternion q = [w, x, y, z] = [cos(a/2),
 * sin(a/2) n] (Hamilton product). Its ACTIVE matrix is the usual
 * A(q) = [[1-2(y^2+z^2), 2(xy-wz), 2(xz+wy)], ...]; its passive matrix is
 * A(q)^T (mech_rotation_from_quaternion). Turns compose as:
 *  - active, "first A1 then A2" (both about fixed axes): A = A2 A1, q = q2 q1;
 *  - passive, "first turn the axes by R1, then turn the NEW axes by R2" (the
 *    second turn's axis is given in the intermediate axes): R = R2 R1,
 *    q = q1 q2.
 * Both ways a list applied in order gives R_total = R_n ... R_2 R_1 in its own
 * sense (mech_rotation_compose).
 *
 * Euler sequences (12): "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX" (Tait-Bryan,
 * three different axes) and "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ" (proper
 * Euler, first axis = third). The letters are the axes of the three turns in
 * the order they are applied, by angles[0], angles[1], angles[2]:
 *  - intrinsic: each turn is about the axis as moved by the turns before it
 *    (body axes). Active A = A_i(a0) A_j(a1) A_k(a2), q = q_i(a0) q_j(a1) q_k(a2);
 *    passive R = P_k(a2) P_j(a1) P_i(a0) with P = A^T the notes' elementary
 *    passive matrices. ZXZ intrinsic = the notes' z-x-z angles (phi, theta,
 *    psi): R = R_psi R_theta R_phi (mech_rotation_from_euler_zxz).
 *  - extrinsic: each turn is about the fixed (original) axis. Active
 *    A = A_k(a2) A_j(a1) A_i(a0); extrinsic (i, j, k) with (a0, a1, a2) is the
 *    same turn as intrinsic (k, j, i) with (a2, a1, a0).
 * Extracted angles lie in: angles[0], angles[2] in (-pi, pi]; angles[1] in
 * [0, pi] (proper Euler) or [-pi/2, pi/2] (Tait-Bryan).
 *
 * Gimbal lock: angles[1] = 0 or pi (proper), +-pi/2 (Tait-Bryan). There only
 * one combination angles[0] + s angles[2] (s = +1 or -1, which one depends
 * on the sequence and the lock; see struct mech_euler_angles) is determined.
 * Within MECH_EULER_LOCK_TOL of a lock the extraction reports gimbal_lock and
 * returns the branch angles[2] = 0, angles[0] = the combination (wrapped to
 * (-pi, pi]); angles[1] is kept as computed. Elsewhere the three angles are
 * returned; near a lock the combination stays accurate to round-off while the
 * individual angles are ill-conditioned (their error grows like
 * 1e-16 / lock_distance from a rounded quaternion or matrix), which is the
 * conditioning of the rotation itself, not of the method.
 */

/* Distance (rad) of the middle Euler angle from a lock within which the
 * rotation is treated as locked. Below it the individual angles are not
 * determined by a double-precision matrix (1e-16 / 1e-14 = 1e-2 rad), and the
 * branch above reproduces the rotation to about 3e-14. */
#define MECH_EULER_LOCK_TOL 1e-14

enum mech_rotation_sense { MECH_ROTATION_PASSIVE = 0, MECH_ROTATION_ACTIVE = 1 };

/* Order and names fixed: "XYZ","XZY","YXZ","YZX","ZXY","ZYX","XYX","XZX","YXY",
 * "YZY","ZXZ","ZYZ". */
enum mech_euler_sequence {
    MECH_EULER_XYZ = 0, MECH_EULER_XZY, MECH_EULER_YXZ, MECH_EULER_YZX, MECH_EULER_ZXY,
    MECH_EULER_ZYX, MECH_EULER_XYX, MECH_EULER_XZX, MECH_EULER_YXY, MECH_EULER_YZY,
    MECH_EULER_ZXZ, MECH_EULER_ZYZ, MECH_EULER_SEQUENCE_COUNT
};

/* Name of a sequence ("XYZ"), or "" for an out-of-range value. Never NULL. */
const char *mech_euler_sequence_name(enum mech_euler_sequence seq);

/* The sequence called `name` (exactly one of the 12, upper case) in *out.
 * MECH_EINVAL with param "sequence" otherwise. */
enum mech_status mech_euler_sequence_find(const char *name, enum mech_euler_sequence *out,
                                          struct mech_error *err);

/* Euler angles extracted from a turn. */
struct mech_euler_angles {
    double angles[3];     /* rad, ranges as above */
    int gimbal_lock;      /* 1 when lock_distance <= MECH_EULER_LOCK_TOL */
    double lock_distance; /* rad: distance of angles[1] from the NEAREST lock value */
    int combination_sign; /* +1: angles[0] + angles[2] is the combination determined at the
                             nearest lock; -1: angles[0] - angles[2] */
    double combination;   /* its value, wrapped to (-pi, pi]; continuous through the lock */
};

/* Hamilton product r = p q (r may alias p or q: computed into a temporary).
 * Cannot fail. */
void mech_quaternion_mul(const double p[4], const double q[4], double r[4]);

/* Put a non-zero finite quaternion in canonical form: unit length (scaled
 * first, no overflow/underflow) and sign chosen so that w > 0, or, when
 * w == 0, the first non-zero of x, y, z is > 0. q and -q are the same turn.
 * MECH_EINVAL with param "quaternion" for zero or non-finite input. */
enum mech_status mech_quaternion_canonical(double q[4], struct mech_error *err);

/* Unit quaternion of the turn by `angle` about `axis` (as
 * mech_rotation_from_axis_angle; same errors and params "axis"/"angle"). */
enum mech_status mech_quaternion_from_axis_angle(struct mech_vec3 axis, double angle, double q[4],
                                                 struct mech_error *err);

/* Unit quaternion of the rotation vector r = angle * unit axis (rad, any
 * finite length; r = 0 is the identity). Accurate for tiny |r| (no 1 - cos).
 * MECH_EINVAL with param "rotation_vector" for non-finite components. */
enum mech_status mech_quaternion_from_rotation_vector(struct mech_vec3 r, double q[4],
                                                      struct mech_error *err);

/* Unit quaternion of an Euler sequence (see above), computed as the product
 * of the three elementary half-angle quaternions, so a small angles[1] keeps
 * full relative precision. intrinsic: nonzero for body-axis turns.
 * MECH_EINVAL with param "sequence" for a bad sequence, "angles" for a
 * non-finite angle. */
enum mech_status mech_quaternion_from_euler(enum mech_euler_sequence seq, int intrinsic,
                                            const double angles[3], double q[4],
                                            struct mech_error *err);

/* Unit quaternion of a matrix R in the given sense, by Shepperd's method
 * (J. Guidance and Control 1(3), 1978: the largest of w, x, y, z is taken from
 * a square root of a diagonal combination, the others from sums/differences of
 * off-diagonal pairs divided by it; error ~ 1 ulp everywhere, including at
 * 180 degrees). R is validated first as in mech_rotation_from_matrix (same
 * errors, param "matrix"). The result is canonical. */
enum mech_status mech_quaternion_from_matrix(struct mech_mat3 r, enum mech_rotation_sense sense,
                                             double q[4], struct mech_error *err);

/* Matrix of the unit quaternion q in the given sense (passive = A(q)^T,
 * active = A(q)). q need not be normalised (the homogeneous form is used).
 * MECH_EINVAL with param "quaternion" for zero or non-finite q. */
enum mech_status mech_rotation_matrix_of_quaternion(const double q[4],
                                                    enum mech_rotation_sense sense,
                                                    struct mech_mat3 *out, struct mech_error *err);

/* Passive matrix of an Euler sequence (see above; errors as
 * mech_quaternion_from_euler). ZXZ intrinsic equals mech_rotation_from_euler_zxz. */
enum mech_status mech_rotation_from_euler(enum mech_euler_sequence seq, int intrinsic,
                                          const double angles[3], struct mech_mat3 *out,
                                          struct mech_error *err);

/* Axis and angle of a turn q (any non-zero finite length): angle in [0, pi]
 * (2 atan2(|v|, |w|), accurate at 0 and pi), axis unit, sign from the
 * canonical q. At angle 0 the axis is arbitrary: [0, 0, 1] is returned. The
 * rotation vector is angle * axis. MECH_EINVAL with param "quaternion" for a
 * zero or non-finite q. */
enum mech_status mech_quaternion_to_axis_angle(const double q[4], struct mech_vec3 *axis,
                                               double *angle, struct mech_error *err);

/* Euler angles of a turn q (any non-zero finite length) in a sequence.
 * Method: Bernardes & Viollet, "Quaternion to Euler angles conversion: a
 * direct, general and computationally efficient method", PLoS ONE 17(11)
 * e0276302 (2022), re-derived in rotation.c: the middle angle from
 * 2 atan2(hypot(., .), hypot(., .)) and the outer ones from the half-sum and
 * half-difference atan2's, so no arcsin/arccos of a rounded value anywhere.
 * Ranges, lock handling and branch as described above.
 * MECH_EINVAL (param "quaternion" or "sequence") for bad input. */
enum mech_status mech_quaternion_to_euler(const double q[4], enum mech_euler_sequence seq,
                                          int intrinsic, struct mech_euler_angles *out,
                                          struct mech_error *err);

/* Product of n turns applied in order, in the given sense (see above):
 * R_total = R_{n-1} ... R_1 R_0, as a canonical unit quaternion. n >= 1;
 * q is n rows of 4 (each any non-zero finite length). The loop honours the
 * budget (one step per factor). MECH_EINVAL (param "rotations/<i>" for a bad
 * factor, "rotations" for n = 0), budget statuses. */
enum mech_status mech_rotation_compose(const double (*q)[4], size_t n,
                                       enum mech_rotation_sense sense, double out[4],
                                       const struct mech_budget *budget, struct mech_error *err);

/* Residuals of a 3x3 matrix as a rotation: *orth = max_ij |(M^T M - 1)_ij|
 * (the measure MECH_ROTATION_MATRIX_TOL bounds), *det = det M - 1. Cannot fail
 * (non-finite in, non-finite out). */
void mech_rotation_residuals(struct mech_mat3 m, double *orth, double *det);

/* T' = R T R^T for a 3x3 tensor T and a matrix R. Cannot fail. */
struct mech_mat3 mech_rotation_apply_tensor(struct mech_mat3 r, struct mech_mat3 t);

#endif
