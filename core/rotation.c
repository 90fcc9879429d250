/* rotation.c — passive rotation matrices from a matrix, z-x-z Euler angles, an
 * axis-angle pair or a quaternion (see mech/rotation.h for the convention). */
#include "mech/rotation.h"

#include <math.h>

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
 * overflows or underflows. Returns 0 for a zero vector. */
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
