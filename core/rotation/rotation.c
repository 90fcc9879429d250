/* rotation.c — passive rotation matrices from a matrix, z-x-z Euler angles, an
 * axis-angle pair or a quaternion; quaternions from every form (12 Euler
 * sequences, rotation vector, Shepperd's method for matrices) and back (axis-angle,
 * Euler angles with gimbal-lock branches); composition and residuals
 * (see mech/rotation/rotation.h for the conventions). */
#include "mech/rotation/rotation.h"
#include "mech/base/constants.h"

#include <math.h>
#include <stdio.h>

/* Rows of R^-T for a matrix with rows r0, r1, r2: (r1 x r2, r2 x r0, r0 x r1)/det. */
static struct mech_mat3 inverse_transpose(struct mech_mat3 m, double *det)
{
    struct mech_vec3 r0 = mech_vec3_make(m.a[0][0], m.a[0][1], m.a[0][2]);
    struct mech_vec3 r1 = mech_vec3_make(m.a[1][0], m.a[1][1], m.a[1][2]);
    struct mech_vec3 r2 = mech_vec3_make(m.a[2][0], m.a[2][1], m.a[2][2]);
    struct mech_vec3 c[3] = {mech_vec3_cross(r1, r2), mech_vec3_cross(r2, r0),
                             mech_vec3_cross(r0, r1)};
    double d = mech_vec3_dot(r0, c[0]);
    struct mech_mat3 out;
    for (int i = 0; i < 3; i++) {
        out.a[i][0] = c[i].x / d;
        out.a[i][1] = c[i].y / d;
        out.a[i][2] = c[i].z / d;
    }
    *det = d;
    return out;
}

enum mech_status mech_rotation_from_matrix(struct mech_mat3 m, struct mech_mat3 *out,
                                           struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, "matrix", "no output given");
    if (!mech_mat3_isfinite(m))
        return mech_error_set(err, MECH_EINVAL, "matrix", "entries must be finite");
    struct mech_mat3 mmt = mech_mat3_mul(m, mech_mat3_transpose(m));
    double dev = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double d = fabs(mmt.a[i][j] - (i == j ? 1.0 : 0.0));
            if (!(d <= dev)) dev = d; /* also catches NaN */
        }
    if (!(dev <= MECH_ROTATION_MATRIX_TOL))
        return mech_error_set(err, MECH_EINVAL, "matrix",
                              "must be orthonormal (rows = new axes in old coordinates): "
                              "max |R R^T - 1| = %.3g > %.0e",
                              dev, MECH_ROTATION_MATRIX_TOL);
    double det;
    struct mech_mat3 rit = inverse_transpose(m, &det);
    if (!(fabs(det - 1.0) <= MECH_ROTATION_MATRIX_TOL))
        return mech_error_set(err, MECH_EINVAL, "matrix",
                              "must be a proper rotation with det +1, got det %.17g", det);
    /* Polar decomposition by Newton's iteration R <- (R + R^-T)/2 (Higham,
     * "Functions of Matrices", §8.3): quadratic convergence, so two steps take
     * the accepted 1e-9 error down to round-off. */
    struct mech_mat3 r = m;
    for (int it = 0; it < 2; it++) {
        if (it > 0) rit = inverse_transpose(r, &det);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                r.a[i][j] = 0.5 * (r.a[i][j] + rit.a[i][j]);
    }
    if (!mech_mat3_isfinite(r))
        return mech_error_set(err, MECH_ENUMERIC, "matrix", "orthonormalisation failed");
    *out = r;
    return MECH_OK;
}

enum mech_status mech_rotation_from_euler_zxz(double phi, double theta, double psi,
                                              struct mech_mat3 *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, "euler_zxz", "no output given");
    if (!isfinite(phi) || !isfinite(theta) || !isfinite(psi))
        return mech_error_set(err, MECH_EINVAL, "euler_zxz", "angles must be finite");
    double cf = cos(phi), sf = sin(phi), ct = cos(theta), st = sin(theta);
    double cp = cos(psi), sp = sin(psi);
    /* notes §2.6: R = R_psi R_theta R_phi, rows = body axes in inertial coordinates. */
    struct mech_mat3 r = {{
        {cp * cf - ct * sf * sp, cp * sf + ct * cf * sp, sp * st},
        {-sp * cf - ct * sf * cp, -sp * sf + ct * cf * cp, cp * st},
        {st * sf, -st * cf, ct},
    }};
    *out = r;
    return MECH_OK;
}

/* Unit vector along v (non-zero, finite), scaled first so that no square
 * overflows or underflows. Returns 0 for a zero vector. Products with the
 * reciprocals, where mech_vec3_unit_checked (mech/base/vec.h) divides: the two
 * differ in the last bit, and the rotation operations' answers are kept as they
 * are. */
static int unit(struct mech_vec3 v, struct mech_vec3 *u)
{
    double s = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    if (!(s > 0)) return 0;
    v = mech_vec3_scale(v, 1.0 / s);
    double n = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    *u = mech_vec3_scale(v, 1.0 / n);
    return 1;
}

/* Passive matrix of the quaternion (w, x, y, z), of any non-zero length, in the
 * homogeneous form (entries divided by |q|^2) so that the rounding of the norm
 * does not spoil orthonormality. Active matrix: e.g. Kuipers, "Quaternions and
 * Rotation Sequences", eq. 5.11; the passive R is its transpose. */
static struct mech_mat3 quat_matrix(double w, double x, double y, double z)
{
    double s = 1.0 / (w * w + x * x + y * y + z * z);
    double ww = w * w, xx = x * x, yy = y * y, zz = z * z;
    struct mech_mat3 r = {{
        {(ww + xx - yy - zz) * s, 2 * (x * y + w * z) * s, 2 * (x * z - w * y) * s},
        {2 * (x * y - w * z) * s, (ww - xx + yy - zz) * s, 2 * (y * z + w * x) * s},
        {2 * (x * z + w * y) * s, 2 * (y * z - w * x) * s, (ww - xx - yy + zz) * s},
    }};
    return r;
}

enum mech_status mech_rotation_from_axis_angle(struct mech_vec3 axis, double angle,
                                               struct mech_mat3 *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, "axis", "no output given");
    if (!mech_vec3_isfinite(axis))
        return mech_error_set(err, MECH_EINVAL, "axis", "components must be finite");
    if (!isfinite(angle)) return mech_error_set(err, MECH_EINVAL, "angle", "must be finite");
    struct mech_vec3 n;
    if (!unit(axis, &n))
        return mech_error_set(err, MECH_EINVAL, "axis", "must not be the zero vector");
    /* Passive R = cos a 1 + (1 - cos a) n n^T - sin a [n]x (the transpose of
     * Rodrigues' formula), evaluated through q = (cos(a/2), sin(a/2) n): the same
     * matrix, orthonormal to round-off and accurate for small angles. */
    double c = cos(0.5 * angle), s = sin(0.5 * angle);
    *out = quat_matrix(c, s * n.x, s * n.y, s * n.z);
    return MECH_OK;
}

enum mech_status mech_rotation_from_quaternion(const double q[4], struct mech_mat3 *out,
                                               struct mech_error *err)
{
    if (!out || !q) return mech_error_set(err, MECH_EINVAL, "quaternion", "no quaternion given");
    double s = 0;
    for (int i = 0; i < 4; i++) {
        if (!isfinite(q[i]))
            return mech_error_set(err, MECH_EINVAL, "quaternion", "components must be finite");
        s = fmax(s, fabs(q[i]));
    }
    if (!(s > 0)) return mech_error_set(err, MECH_EINVAL, "quaternion", "must not be zero");
    /* scale by the largest component so no square overflows or underflows */
    *out = quat_matrix(q[0] / s, q[1] / s, q[2] / s, q[3] / s);
    return MECH_OK;
}

/* ==== Representations, conversions, composition ==============================
 * Conventions: mech/rotation/rotation.h. Quaternions are [w, x, y, z], Hamilton product,
 * and describe the ACTIVE turn; passive matrices are the transposes. */

/* Axis letters of the 12 sequences, in enum order. */
static const char *const euler_names[MECH_EULER_SEQUENCE_COUNT] = {
    "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ",
};

const char *mech_euler_sequence_name(enum mech_euler_sequence seq)
{
    if ((int)seq < 0 || seq >= MECH_EULER_SEQUENCE_COUNT) return "";
    return euler_names[seq];
}

enum mech_status mech_euler_sequence_find(const char *name, enum mech_euler_sequence *out,
                                          struct mech_error *err)
{
    if (name && out)
        for (int k = 0; k < MECH_EULER_SEQUENCE_COUNT; k++) {
            const char *a = euler_names[k];
            if (name[0] == a[0] && name[1] == a[1] && name[2] == a[2] && name[3] == '\0') {
                *out = (enum mech_euler_sequence)k;
                return MECH_OK;
            }
        }
    return mech_error_set(err, MECH_EINVAL, "sequence",
                          "must be one of XYZ, XZY, YXZ, YZX, ZXY, ZYX, XYX, XZX, YXY, YZY, "
                          "ZXZ, ZYZ");
}

/* Axis indices (0 = x, 1 = y, 2 = z) of a sequence's three turns. */
static void seq_axes(enum mech_euler_sequence seq, int ax[3])
{
    for (int m = 0; m < 3; m++)
        ax[m] = euler_names[seq][m] - 'X';
}

void mech_quaternion_mul(const double p[4], const double q[4], double r[4])
{
    double t[4];
    t[0] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
    t[1] = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2];
    t[2] = p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1];
    t[3] = p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0];
    for (int i = 0; i < 4; i++)
        r[i] = t[i];
}

enum mech_status mech_quaternion_canonical(double q[4], struct mech_error *err)
{
    if (!q) return mech_error_set(err, MECH_EINVAL, "quaternion", "no quaternion given");
    double s = 0;
    for (int i = 0; i < 4; i++) {
        if (!isfinite(q[i]))
            return mech_error_set(err, MECH_EINVAL, "quaternion", "components must be finite");
        s = fmax(s, fabs(q[i]));
    }
    if (!(s > 0)) return mech_error_set(err, MECH_EINVAL, "quaternion", "must not be zero");
    double u[4], n2 = 0;
    for (int i = 0; i < 4; i++) {
        u[i] = q[i] / s;
        n2 += u[i] * u[i];
    }
    double n = sqrt(n2);
    /* sign: w > 0; at w == 0 the first non-zero of x, y, z positive */
    double sign = 1;
    for (int i = 0; i < 4; i++)
        if (u[i] != 0) {
            sign = u[i] > 0 ? 1.0 : -1.0;
            break;
        }
    for (int i = 0; i < 4; i++)
        q[i] = sign * u[i] / n + 0.0; /* + 0.0: no negative zero */
    return MECH_OK;
}

enum mech_status mech_quaternion_from_axis_angle(struct mech_vec3 axis, double angle, double q[4],
                                                 struct mech_error *err)
{
    if (!q) return mech_error_set(err, MECH_EINVAL, "axis", "no output given");
    if (!mech_vec3_isfinite(axis))
        return mech_error_set(err, MECH_EINVAL, "axis", "components must be finite");
    if (!isfinite(angle)) return mech_error_set(err, MECH_EINVAL, "angle", "must be finite");
    struct mech_vec3 n;
    if (!unit(axis, &n))
        return mech_error_set(err, MECH_EINVAL, "axis", "must not be the zero vector");
    double c = cos(0.5 * angle), s = sin(0.5 * angle);
    q[0] = c;
    q[1] = s * n.x;
    q[2] = s * n.y;
    q[3] = s * n.z;
    return mech_quaternion_canonical(q, err);
}

enum mech_status mech_quaternion_from_rotation_vector(struct mech_vec3 r, double q[4],
                                                      struct mech_error *err)
{
    if (!q) return mech_error_set(err, MECH_EINVAL, "rotation_vector", "no output given");
    if (!mech_vec3_isfinite(r))
        return mech_error_set(err, MECH_EINVAL, "rotation_vector", "components must be finite");
    double a = mech_vec3_norm(r);
    if (a == 0) {
        q[0] = 1;
        q[1] = q[2] = q[3] = 0;
        return MECH_OK;
    }
    /* q = (cos(a/2), sin(a/2) r/a): sin(a/2)/a has no cancellation at any a > 0 */
    double f = sin(0.5 * a) / a;
    q[0] = cos(0.5 * a);
    q[1] = f * r.x;
    q[2] = f * r.y;
    q[3] = f * r.z;
    return mech_quaternion_canonical(q, err);
}

enum mech_status mech_quaternion_from_euler(enum mech_euler_sequence seq, int intrinsic,
                                            const double angles[3], double q[4],
                                            struct mech_error *err)
{
    if ((int)seq < 0 || seq >= MECH_EULER_SEQUENCE_COUNT)
        return mech_error_set(err, MECH_EINVAL, "sequence", "unknown Euler sequence");
    if (!angles || !q) return mech_error_set(err, MECH_EINVAL, "angles", "no angles given");
    for (int m = 0; m < 3; m++)
        if (!isfinite(angles[m]))
            return mech_error_set(err, MECH_EINVAL, "angles", "angles must be finite");
    int ax[3];
    seq_axes(seq, ax);
    double acc[4] = {1, 0, 0, 0};
    for (int m = 0; m < 3; m++) {
        double e[4] = {cos(0.5 * angles[m]), 0, 0, 0};
        e[1 + ax[m]] = sin(0.5 * angles[m]);
        /* intrinsic: A = A_i A_j A_k (later turns multiply on the right);
         * extrinsic: A = A_k A_j A_i (later turns multiply on the left) */
        if (intrinsic)
            mech_quaternion_mul(acc, e, acc);
        else
            mech_quaternion_mul(e, acc, acc);
    }
    for (int i = 0; i < 4; i++)
        q[i] = acc[i];
    return mech_quaternion_canonical(q, err);
}

enum mech_status mech_rotation_matrix_of_quaternion(const double q[4],
                                                    enum mech_rotation_sense sense,
                                                    struct mech_mat3 *out, struct mech_error *err)
{
    struct mech_mat3 r;
    enum mech_status st = mech_rotation_from_quaternion(q, &r, err);
    if (st != MECH_OK) return st;
    *out = sense == MECH_ROTATION_ACTIVE ? mech_mat3_transpose(r) : r;
    return MECH_OK;
}

enum mech_status mech_rotation_from_euler(enum mech_euler_sequence seq, int intrinsic,
                                          const double angles[3], struct mech_mat3 *out,
                                          struct mech_error *err)
{
    double q[4];
    if (!out) return mech_error_set(err, MECH_EINVAL, "angles", "no output given");
    enum mech_status st = mech_quaternion_from_euler(seq, intrinsic, angles, q, err);
    if (st != MECH_OK) return st;
    *out = quat_matrix(q[0], q[1], q[2], q[3]);
    return MECH_OK;
}

enum mech_status mech_quaternion_from_matrix(struct mech_mat3 r, enum mech_rotation_sense sense,
                                             double q[4], struct mech_error *err)
{
    if (!q) return mech_error_set(err, MECH_EINVAL, "matrix", "no output given");
    struct mech_mat3 p;
    enum mech_status st = mech_rotation_from_matrix(r, &p, err);
    if (st != MECH_OK) return st;
    /* the active matrix A: passive input is A^T */
    struct mech_mat3 a = sense == MECH_ROTATION_ACTIVE ? p : mech_mat3_transpose(p);
    const double(*m)[3] = a.a;
    /* Shepperd (1978): pick the largest of 4w^2 - 1 = tr A, 4x^2 - 1 = 2A00 - tr A, ... */
    double tr = m[0][0] + m[1][1] + m[2][2];
    double cand[4] = {tr, m[0][0], m[1][1], m[2][2]};
    int best = 0;
    for (int i = 1; i < 4; i++)
        if (cand[i] > cand[best]) best = i;
    double w, x, y, z;
    if (best == 0) {
        double t = 2 * sqrt(1 + tr); /* 4 w */
        w = 0.25 * t;
        x = (m[2][1] - m[1][2]) / t;
        y = (m[0][2] - m[2][0]) / t;
        z = (m[1][0] - m[0][1]) / t;
    } else if (best == 1) {
        double t = 2 * sqrt(1 + m[0][0] - m[1][1] - m[2][2]); /* 4 x */
        x = 0.25 * t;
        w = (m[2][1] - m[1][2]) / t;
        y = (m[0][1] + m[1][0]) / t;
        z = (m[0][2] + m[2][0]) / t;
    } else if (best == 2) {
        double t = 2 * sqrt(1 - m[0][0] + m[1][1] - m[2][2]); /* 4 y */
        y = 0.25 * t;
        w = (m[0][2] - m[2][0]) / t;
        x = (m[0][1] + m[1][0]) / t;
        z = (m[1][2] + m[2][1]) / t;
    } else {
        double t = 2 * sqrt(1 - m[0][0] - m[1][1] + m[2][2]); /* 4 z */
        z = 0.25 * t;
        w = (m[1][0] - m[0][1]) / t;
        x = (m[0][2] + m[2][0]) / t;
        y = (m[1][2] + m[2][1]) / t;
    }
    q[0] = w;
    q[1] = x;
    q[2] = y;
    q[3] = z;
    struct mech_error e2;
    mech_error_clear(&e2);
    if (mech_quaternion_canonical(q, &e2) != MECH_OK)
        return mech_error_set(err, MECH_ENUMERIC, "matrix", "quaternion extraction failed");
    return MECH_OK;
}

enum mech_status mech_quaternion_to_axis_angle(const double q[4], struct mech_vec3 *axis,
                                               double *angle, struct mech_error *err)
{
    if (!q || !axis || !angle)
        return mech_error_set(err, MECH_EINVAL, "quaternion", "no quaternion given");
    double u[4] = {q[0], q[1], q[2], q[3]};
    enum mech_status st = mech_quaternion_canonical(u, err);
    if (st != MECH_OK) return st;
    struct mech_vec3 v = mech_vec3_make(u[1], u[2], u[3]);
    double n = mech_vec3_norm(v);
    *angle = 2 * atan2(n, u[0]); /* u[0] >= 0: angle in [0, pi] */
    *axis = n > 0 ? mech_vec3_scale(v, 1.0 / n) : mech_vec3_make(0, 0, 1);
    if (n > 0 && !unit(*axis, axis)) /* renormalise the rounded quotient */
        return mech_error_set(err, MECH_ENUMERIC, "quaternion", "axis extraction failed");
    return MECH_OK;
}

/* x wrapped to (-pi, pi], for x in (-3 pi, 3 pi). */
static double wrap_pi(double x)
{
    if (x > MECH_PI)
        x -= 2 * MECH_PI;
    else if (x <= -MECH_PI)
        x += 2 * MECH_PI;
    if (x > MECH_PI) x -= 2 * MECH_PI; /* rounding of the first subtraction */
    return x + 0.0;
}

/* Euler angles, re-derived here from q = q_i(a) q_j(b) q_k(c) (intrinsic,
 * active; e = +1 if (i, j, m) is an even permutation, m the axis not in {i, j}):
 *
 * proper (k = i): w = cos(b/2) cos S, q_i = cos(b/2) sin S,
 *                 q_j = sin(b/2) cos D, e q_m = sin(b/2) sin D,
 *   with S = (a + c)/2, D = (a - c)/2; so the pair P = (w, q_i) has length
 *   cos(b/2) and angle S, the pair Q = (q_j, e q_m) length sin(b/2), angle D.
 * Tait-Bryan (k = m), e = +1: P = (w + q_j, q_i + q_k) = sqrt2 cos(B/2)(cos S, sin S),
 *                             Q = (w - q_j, q_i - q_k) = sqrt2 sin(B/2)(cos D, sin D),
 *                             b = pi/2 - B;
 *                    e = -1: P = (w - q_j, q_i + q_k), Q = (w + q_j, q_i - q_k), b = B - pi/2,
 *   (expand the product and use cos(b/2) -+ sin(b/2) = sqrt2 cos(b/2 +- pi/4)).
 * In every case B = 2 atan2(|Q|, |P|) in [0, pi], S = atan2(P), D = atan2(Q),
 * a = S + D, c = S - D. Locks: B = 0 (only a + c = 2S determined) and B = pi
 * (only a - c = 2D). Checked against products of elementary matrices in
 * tests/core/rotation/test_rotation.c for all 24 sequences. */
enum mech_status mech_quaternion_to_euler(const double q[4], enum mech_euler_sequence seq,
                                          int intrinsic, struct mech_euler_angles *out,
                                          struct mech_error *err)
{
    if ((int)seq < 0 || seq >= MECH_EULER_SEQUENCE_COUNT)
        return mech_error_set(err, MECH_EINVAL, "sequence", "unknown Euler sequence");
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, "quaternion", "no quaternion given");
    double u[4] = {q[0], q[1], q[2], q[3]};
    enum mech_status st = mech_quaternion_canonical(u, err);
    if (st != MECH_OK) return st;
    int ax[3];
    seq_axes(seq, ax);
    if (!intrinsic) { /* extrinsic (i, j, k) with (a, b, c) = intrinsic (k, j, i) with (c, b, a) */
        int t = ax[0];
        ax[0] = ax[2];
        ax[2] = t;
    }
    int i = ax[0], j = ax[1], proper = ax[0] == ax[2];
    int m = 3 - i - j;
    double e = (j - i + 3) % 3 == 1 ? 1.0 : -1.0;
    double w = u[0], qi = u[1 + i], qj = u[1 + j], qm = u[1 + m];
    double p0, p1, d0, d1;
    if (proper) {
        p0 = w, p1 = qi, d0 = qj, d1 = e * qm;
    } else if (e > 0) {
        p0 = w + qj, p1 = qi + qm, d0 = w - qj, d1 = qi - qm;
    } else {
        p0 = w - qj, p1 = qi + qm, d0 = w + qj, d1 = qi - qm;
    }
    double hp = hypot(p0, p1), hd = hypot(d0, d1);
    double big = 2 * atan2(hd, hp); /* B in [0, pi] */
    double sh = atan2(p1, p0), dh = atan2(d1, d0);
    double mid = proper ? big : (e > 0 ? 0.5 * MECH_PI - big : big - 0.5 * MECH_PI);
    double a = wrap_pi(sh + dh), c = wrap_pi(sh - dh);
    out->lock_distance = 2 * atan2(fmin(hp, hd), fmax(hp, hd));
    if (hd <= hp) { /* nearest lock B = 0: a + c = 2S */
        out->combination_sign = 1;
        out->combination = wrap_pi(2 * sh);
    } else { /* nearest lock B = pi: a - c = 2D (extrinsic: swapped below, so -2D) */
        out->combination_sign = -1;
        out->combination = wrap_pi(intrinsic ? 2 * dh : -2 * dh);
    }
    if (!intrinsic) {
        double t = a;
        a = c;
        c = t;
    }
    out->gimbal_lock = out->lock_distance <= MECH_EULER_LOCK_TOL;
    if (out->gimbal_lock) { /* branch: angles[2] = 0, angles[0] = the combination */
        a = out->combination;
        c = 0;
    }
    out->angles[0] = a;
    out->angles[1] = mid + 0.0;
    out->angles[2] = c;
    if (!isfinite(a) || !isfinite(mid) || !isfinite(c) || !isfinite(out->combination))
        return mech_error_set(err, MECH_ENUMERIC, "quaternion", "Euler extraction failed");
    return MECH_OK;
}

enum mech_status mech_rotation_compose(const double (*q)[4], size_t n,
                                       enum mech_rotation_sense sense, double out[4],
                                       const struct mech_budget *budget, struct mech_error *err)
{
    if (!q || !out || n == 0)
        return mech_error_set(err, MECH_EINVAL, "rotations", "at least one rotation is needed");
    double acc[4] = {1, 0, 0, 0};
    for (size_t k = 0; k < n; k++) {
        enum mech_status st = mech_budget_check(budget, (long)k, 0, err);
        if (st != MECH_OK) return st;
        double f[4] = {q[k][0], q[k][1], q[k][2], q[k][3]};
        struct mech_error e2;
        mech_error_clear(&e2);
        if (mech_quaternion_canonical(f, &e2) != MECH_OK) {
            char param[48];
            snprintf(param, sizeof param, "rotations/%zu", k);
            return mech_error_set(err, MECH_EINVAL, param, "%s", e2.text);
        }
        /* active: q = q_{n-1} ... q_0; passive: q = q_0 q_1 ... q_{n-1} (header) */
        if (sense == MECH_ROTATION_ACTIVE)
            mech_quaternion_mul(f, acc, acc);
        else
            mech_quaternion_mul(acc, f, acc);
        if (k % 16 == 15) { /* keep |acc| = 1 against slow drift over long lists */
            enum mech_status s2 = mech_quaternion_canonical(acc, err);
            if (s2 != MECH_OK) return s2;
        }
    }
    for (int i = 0; i < 4; i++)
        out[i] = acc[i];
    return mech_quaternion_canonical(out, err);
}

void mech_rotation_residuals(struct mech_mat3 m, double *orth, double *det)
{
    struct mech_mat3 p = mech_mat3_mul(mech_mat3_transpose(m), m);
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double x = fabs(p.a[i][j] - (i == j ? 1.0 : 0.0));
            if (!(x <= d)) d = x;
        }
    if (orth) *orth = d;
    if (det) {
        struct mech_vec3 r0 = mech_vec3_make(m.a[0][0], m.a[0][1], m.a[0][2]);
        struct mech_vec3 r1 = mech_vec3_make(m.a[1][0], m.a[1][1], m.a[1][2]);
        struct mech_vec3 r2 = mech_vec3_make(m.a[2][0], m.a[2][1], m.a[2][2]);
        *det = mech_vec3_dot(r0, mech_vec3_cross(r1, r2)) - 1.0;
    }
}

struct mech_mat3 mech_rotation_apply_tensor(struct mech_mat3 r, struct mech_mat3 t)
{
    return mech_mat3_mul(r, mech_mat3_mul(t, mech_mat3_transpose(r)));
}
