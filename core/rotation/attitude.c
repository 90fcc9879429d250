/* attitude.c — unit-quaternion attitude kinematics (see mech/rotation/attitude.h).
 * Passive convention of core/rotation/rotation.c: R = A(q)^T with A the active matrix. */
#include "mech/rotation/attitude.h"

#include <math.h>

void mech_attitude_quat_mul(const double a[4], const double b[4], double out[4])
{
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

void mech_attitude_quat_rate(const double q[4], struct mech_vec3 w, double dq[4])
{
    /* dq/dt = 1/2 q (x) (0, w): the body axes A e_i turn with dA/dt = A [w]x */
    dq[0] = 0.5 * (-q[1] * w.x - q[2] * w.y - q[3] * w.z);
    dq[1] = 0.5 * (q[0] * w.x + q[2] * w.z - q[3] * w.y);
    dq[2] = 0.5 * (q[0] * w.y - q[1] * w.z + q[3] * w.x);
    dq[3] = 0.5 * (q[0] * w.z + q[1] * w.y - q[2] * w.x);
}

struct mech_mat3 mech_attitude_matrix(const double qi[4])
{
    double n = sqrt(qi[0] * qi[0] + qi[1] * qi[1] + qi[2] * qi[2] + qi[3] * qi[3]);
    double w = qi[0] / n, x = qi[1] / n, y = qi[2] / n, z = qi[3] / n;
    struct mech_mat3 r;
    /* active A = (w^2 - v.v) 1 + 2 v v^T + 2 w [v]x; R = A^T */
    r.a[0][0] = 1 - 2 * (y * y + z * z);
    r.a[1][1] = 1 - 2 * (x * x + z * z);
    r.a[2][2] = 1 - 2 * (x * x + y * y);
    r.a[0][1] = 2 * (x * y + w * z);
    r.a[1][0] = 2 * (x * y - w * z);
    r.a[0][2] = 2 * (x * z - w * y);
    r.a[2][0] = 2 * (x * z + w * y);
    r.a[1][2] = 2 * (y * z + w * x);
    r.a[2][1] = 2 * (y * z - w * x);
    return r;
}

struct mech_vec3 mech_attitude_to_space(const double q[4], struct mech_vec3 v)
{
    return mech_mat3_mul_vec(mech_mat3_transpose(mech_attitude_matrix(q)), v);
}

struct mech_vec3 mech_attitude_to_body(const double q[4], struct mech_vec3 v)
{
    return mech_mat3_mul_vec(mech_attitude_matrix(q), v);
}

void mech_attitude_from_matrix(struct mech_mat3 r, double q[4])
{
    /* A = R^T: A_ij = r.a[j][i]. Shepperd (1978): pick the largest of
     * 4w^2 = 1 + tr, 4x^2 = 1 + 2A00 - tr, ... */
    const double a00 = r.a[0][0], a11 = r.a[1][1], a22 = r.a[2][2];
    const double a21 = r.a[1][2], a12 = r.a[2][1]; /* A21, A12 */
    const double a02 = r.a[2][0], a20 = r.a[0][2];
    const double a10 = r.a[0][1], a01 = r.a[1][0];
    const double tr = a00 + a11 + a22;
    const double c[4] = {1 + tr, 1 + 2 * a00 - tr, 1 + 2 * a11 - tr, 1 + 2 * a22 - tr};
    int k = 0;
    for (int i = 1; i < 4; i++)
        if (c[i] > c[k]) k = i;
    const double s = 0.5 * sqrt(c[k]), f = 0.25 / s;
    switch (k) {
    case 0:
        q[0] = s, q[1] = (a21 - a12) * f, q[2] = (a02 - a20) * f, q[3] = (a10 - a01) * f;
        break;
    case 1:
        q[1] = s, q[0] = (a21 - a12) * f, q[2] = (a01 + a10) * f, q[3] = (a02 + a20) * f;
        break;
    case 2:
        q[2] = s, q[0] = (a02 - a20) * f, q[1] = (a01 + a10) * f, q[3] = (a12 + a21) * f;
        break;
    default:
        q[3] = s, q[0] = (a10 - a01) * f, q[1] = (a02 + a20) * f, q[2] = (a12 + a21) * f;
        break;
    }
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    int flip = 0;
    for (int i = 0; i < 4; i++)
        if (fabs(q[i]) > 1e-15) {
            flip = q[i] < 0;
            break;
        }
    for (int i = 0; i < 4; i++) q[i] = (flip ? -q[i] : q[i]) / n;
}

void mech_attitude_from_euler_zxz(double phi, double theta, double psi, double q[4])
{
    const double ct = cos(0.5 * theta), st = sin(0.5 * theta);
    const double s = 0.5 * (phi + psi), d = 0.5 * (phi - psi);
    q[0] = ct * cos(s);
    q[1] = st * cos(d);
    q[2] = st * sin(d);
    q[3] = ct * sin(s);
}

void mech_attitude_euler_zxz(const double q[4], double psi_hint, double *phi, double *theta,
                             double *psi, int *gimbal)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double pe = hypot(x, y), pw = hypot(w, z);
    *theta = 2 * atan2(pe, pw);
    int g = 0;
    if (pe == 0) { /* theta = 0: only phi + psi */
        *psi = psi_hint;
        *phi = 2 * atan2(z, w) - psi_hint;
        g = 1;
    } else if (pw == 0) { /* theta = pi: only phi - psi */
        *psi = psi_hint;
        *phi = 2 * atan2(y, x) + psi_hint;
        g = 1;
    } else {
        const double s = 2 * atan2(z, w), d = 2 * atan2(y, x);
        *phi = 0.5 * (s + d);
        *psi = 0.5 * (s - d);
    }
    if (gimbal) *gimbal = g;
}
