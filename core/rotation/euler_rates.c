/* euler_rates.c — z-x-z Euler angles and their rates <-> angular velocity in
 * body and space axes, and dR/dt by the product rule as an independent check
 * of dR/dt = -[omega_body]x R (mech/rotation/euler_rates.h). */
#include "mech/rotation/euler_rates.h"

#include <math.h>

/* Passive turn about z by a (R_phi, R_psi), its derivative d/da; about x (R_theta). */
static struct mech_mat3 rot_z(double a)
{
    double c = cos(a), s = sin(a);
    struct mech_mat3 m = {{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}};
    return m;
}
static struct mech_mat3 drot_z(double a)
{
    double c = cos(a), s = sin(a);
    struct mech_mat3 m = {{{-s, c, 0}, {-c, -s, 0}, {0, 0, 0}}};
    return m;
}
static struct mech_mat3 rot_x(double a)
{
    double c = cos(a), s = sin(a);
    struct mech_mat3 m = {{{1, 0, 0}, {0, c, s}, {0, -s, c}}};
    return m;
}
static struct mech_mat3 drot_x(double a)
{
    double c = cos(a), s = sin(a);
    struct mech_mat3 m = {{{0, 0, 0}, {0, -s, c}, {0, -c, -s}}};
    return m;
}

static struct mech_mat3 mat_scale(struct mech_mat3 m, double k)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) m.a[i][j] *= k;
    return m;
}
static struct mech_mat3 mat_add3(struct mech_mat3 a, struct mech_mat3 b, struct mech_mat3 c)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) a.a[i][j] += b.a[i][j] + c.a[i][j];
    return a;
}
static struct mech_mat3 cross_matrix(struct mech_vec3 w)
{
    struct mech_mat3 m = {{{0, -w.z, w.y}, {w.z, 0, -w.x}, {-w.y, w.x, 0}}};
    return m;
}

enum mech_status mech_euler_kinematics(const double angles[3], const double rates[3],
                                       struct mech_euler_kinematics *out,
                                       struct mech_error *err)
{
    if (!out || !angles || !rates) return mech_error_set(err, MECH_EINVAL, NULL, "no input or output");
    for (int k = 0; k < 3; k++) {
        if (!isfinite(angles[k]))
            return mech_error_set(err, MECH_EINVAL, "euler_zxz", "angles must be finite");
        if (!isfinite(rates[k]))
            return mech_error_set(err, MECH_EINVAL, "rates", "rates must be finite");
    }
    double ph = angles[0], th = angles[1], ps = angles[2];
    double dph = rates[0], dth = rates[1], dps = rates[2];
    double sth = sin(th), cth = cos(th), sps = sin(ps), cps = cos(ps), sph = sin(ph), cph = cos(ph);
    struct mech_euler_kinematics r;
    for (int k = 0; k < 3; k++) r.rates[k] = rates[k];
    r.omega_body = mech_vec3_make(dph * sth * sps + dth * cps, dph * sth * cps - dth * sps,
                                  dph * cth + dps);
    r.omega_space = mech_vec3_make(dth * cph + dps * sth * sph, dth * sph - dps * sth * cph,
                                   dph + dps * cth);
    struct mech_mat3 rf = rot_z(ph), rt = rot_x(th), rp = rot_z(ps);
    r.rotation = mech_mat3_mul(rp, mech_mat3_mul(rt, rf));
    r.rotation_rate = mat_add3(mat_scale(mech_mat3_mul(drot_z(ps), mech_mat3_mul(rt, rf)), dps),
                               mat_scale(mech_mat3_mul(rp, mech_mat3_mul(drot_x(th), rf)), dth),
                               mat_scale(mech_mat3_mul(rp, mech_mat3_mul(rt, drot_z(ph))), dph));
    r.omega_cross_body =
        mat_scale(mech_mat3_mul(r.rotation_rate, mech_mat3_transpose(r.rotation)), -1);
    r.omega_cross_space =
        mat_scale(mech_mat3_mul(mech_mat3_transpose(r.rotation), r.rotation_rate), -1);
    struct mech_mat3 wr = mech_mat3_mul(cross_matrix(r.omega_body), r.rotation);
    r.residual = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.residual = fmax(r.residual, fabs(r.rotation_rate.a[i][j] + wr.a[i][j]));
    r.gimbal_lock = fabs(sth) <= MECH_EULER_LOCK_SIN;
    if (!mech_vec3_isfinite(r.omega_body) || !mech_vec3_isfinite(r.omega_space) ||
        !mech_mat3_isfinite(r.rotation_rate) || !isfinite(r.residual))
        return mech_error_set(err, MECH_ENUMERIC, "rates", "a result overflows");
    *out = r;
    return MECH_OK;
}

enum mech_status mech_euler_rates_from_omega(const double angles[3], struct mech_vec3 omega,
                                             int body, struct mech_euler_kinematics *out,
                                             double *combined, struct mech_error *err)
{
    const char *param = body ? "omega_body" : "omega_space";
    if (!out || !angles) return mech_error_set(err, MECH_EINVAL, NULL, "no input or output");
    for (int k = 0; k < 3; k++)
        if (!isfinite(angles[k]))
            return mech_error_set(err, MECH_EINVAL, "euler_zxz", "angles must be finite");
    if (!mech_vec3_isfinite(omega)) return mech_error_set(err, MECH_EINVAL, param, "must be finite");
    double th = angles[1], ps = angles[2];
    struct mech_vec3 w = omega;
    if (!body) { /* to body components: w_body = R w_space */
        struct mech_mat3 r = mech_mat3_mul(rot_z(ps), mech_mat3_mul(rot_x(th), rot_z(angles[0])));
        w = mech_mat3_mul_vec(r, omega);
    }
    double sth = sin(th), cth = cos(th), sps = sin(ps), cps = cos(ps);
    double rates[3];
    rates[1] = w.x * cps - w.y * sps;
    double across = w.x * sps + w.y * cps; /* = phi' sin(theta) */
    double comb = 0;
    if (fabs(sth) <= MECH_EULER_LOCK_SIN) {
        if (fabs(across) > 1e-12 * mech_vec3_norm(w))
            return mech_error_set(err, MECH_EDOMAIN, param,
                                  "at gimbal lock (sin theta = %.3g) omega has a component "
                                  "%.6g along (sin psi, cos psi, 0) in body axes, which would "
                                  "need an infinite phi'; no finite Euler rates give this omega",
                                  sth, across);
        /* theta = 0: w3 = phi' + psi'; theta = pi: w3 = psi' - phi' */
        comb = w.z;
        rates[0] = 0;
        rates[2] = w.z;
    } else {
        rates[0] = across / sth;
        rates[2] = w.z - rates[0] * cth;
    }
    if (!isfinite(rates[0]) || !isfinite(rates[2]))
        return mech_error_set(err, MECH_ENUMERIC, "euler_zxz",
                              "theta is so close to the lock (sin theta = %.3g) that phi' "
                              "overflows",
                              sth);
    enum mech_status st = mech_euler_kinematics(angles, rates, out, err);
    if (st == MECH_OK && combined) *combined = comb;
    return st;
}
