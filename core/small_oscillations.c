/* small_oscillations.c — linearised motion about circular orbits, the conical
 * pendulum's steady precession and a physical pendulum's hanging equilibrium
 * (mech/small_oscillations.h). Closed forms only. */
#include "mech/small_oscillations.h"

#include <math.h>
#include <stdio.h>

#define PI 3.14159265358979323846

static int pos(double x) { return isfinite(x) && x > 0; }

enum mech_status mech_orbit_oscillation(const struct mech_potential_term *terms, size_t n,
                                        double mass, double r0,
                                        struct mech_orbit_oscillation *out,
                                        struct mech_error *err)
{
    if (!out || !terms || n == 0)
        return mech_error_set(err, MECH_EINVAL, "terms", "at least one term is required");
    if (!pos(mass)) return mech_error_set(err, MECH_EINVAL, "mass", "must be finite and > 0");
    if (!pos(r0)) return mech_error_set(err, MECH_EINVAL, "r0", "must be finite and > 0");
    struct mech_orbit_oscillation r = {0};
    for (size_t i = 0; i < n; i++) {
        char p[48];
        double k = terms[i].k, e = terms[i].n;
        if (!isfinite(k) || !isfinite(e)) {
            snprintf(p, sizeof p, "terms/%zu/%s", i, isfinite(k) ? "n" : "k");
            return mech_error_set(err, MECH_EINVAL, p, "must be finite");
        }
        /* V' = c r^(n-1) with c = k n (k for the logarithm), V'' = c (n-1) r^(n-2) */
        double c = e == 0 ? k : k * e;
        double rn1 = pow(r0, e - 1);
        r.v += e == 0 ? k * log(r0) : k * pow(r0, e);
        r.dv += c * rn1;
        r.d2v += c * (e - 1) * rn1 / r0;
    }
    if (!(r.dv > 0))
        return mech_error_set(err, MECH_EDOMAIN, "r0",
                              "no circular orbit at r0 = %.17g: V'(r0) = %.6g N is not an "
                              "attraction (it must be > 0)",
                              r0, r.dv);
    r.angular_momentum = sqrt(mass * r0 * r0 * r0 * r.dv);
    r.energy = 0.5 * r0 * r.dv + r.v;
    r.omega_phi = sqrt(r.dv / (mass * r0));
    r.k_eff = r.d2v + 3 * r.dv / r0;
    r.stable = r.k_eff > 0;
    double q = 3 + r0 * r.d2v / r.dv; /* = r0 k_eff / V' */
    if (r.stable) {
        r.omega_r = sqrt(r.k_eff / mass);
        r.apsidal_angle = PI / sqrt(q);
    } else {
        r.growth_rate = sqrt(-r.k_eff / mass);
    }
    if (!isfinite(r.angular_momentum) || !isfinite(r.energy) || !isfinite(r.omega_phi) ||
        !isfinite(r.k_eff) || !isfinite(r.omega_r) || !isfinite(r.growth_rate) ||
        !isfinite(r.apsidal_angle))
        return mech_error_set(err, MECH_ENUMERIC, "r0", "a result is not finite (overflow)");
    *out = r;
    return MECH_OK;
}

enum mech_status mech_conical_pendulum(double length, double g, double angle,
                                       struct mech_conical_pendulum *out,
                                       struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!pos(length)) return mech_error_set(err, MECH_EINVAL, "length", "must be finite and > 0");
    if (!pos(g)) return mech_error_set(err, MECH_EINVAL, "g", "must be finite and > 0");
    if (!(angle > 0 && angle < PI / 2))
        return mech_error_set(err, MECH_EINVAL, "angle",
                              "the cone half-angle must lie in (0, pi/2): at 0 the bob hangs "
                              "still, at pi/2 no finite rate holds it");
    double c = cos(angle), s = sin(angle);
    struct mech_conical_pendulum r;
    r.phi_dot = sqrt(g / (length * c));
    r.period = 2 * PI / r.phi_dot;
    double f = sqrt(1 + 3 * c * c);
    r.omega_theta = r.phi_dot * f;
    r.apsidal_angle = PI / f;
    r.radius = length * s;
    r.speed = r.radius * r.phi_dot;
    if (!isfinite(r.phi_dot) || !isfinite(r.speed))
        return mech_error_set(err, MECH_ENUMERIC, "angle", "a result is not finite");
    *out = r;
    return MECH_OK;
}

enum mech_status mech_physical_pendulum(double mass, struct mech_mat3 i_cm, struct mech_vec3 d,
                                        struct mech_vec3 axis, double g,
                                        struct mech_physical_pendulum *out,
                                        struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!pos(mass)) return mech_error_set(err, MECH_EINVAL, "mass", "must be finite and > 0");
    if (!pos(g)) return mech_error_set(err, MECH_EINVAL, "g", "must be finite and > 0");
    if (!mech_mat3_isfinite(i_cm))
        return mech_error_set(err, MECH_EINVAL, "tensor", "entries must be finite");
    if (!mech_vec3_isfinite(d)) return mech_error_set(err, MECH_EINVAL, "offset", "must be finite");
    double na = mech_vec3_norm(axis);
    if (!(na > 0) || !isfinite(na))
        return mech_error_set(err, MECH_EINVAL, "axis", "must be finite and non-zero");
    struct mech_vec3 n = mech_vec3_scale(axis, 1 / na);
    struct mech_physical_pendulum r;
    double dd = mech_vec3_dot(d, d);
    double dv[3] = {d.x, d.y, d.z};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.tensor_pivot.a[i][j] = 0.5 * (i_cm.a[i][j] + i_cm.a[j][i]) +
                                     mass * ((i == j ? dd : 0) - dv[i] * dv[j]);
    r.moment_axis = mech_vec3_dot(n, mech_mat3_mul_vec(r.tensor_pivot, n));
    struct mech_vec3 across = mech_vec3_sub(d, mech_vec3_scale(n, mech_vec3_dot(d, n)));
    r.arm = mech_vec3_norm(across);
    if (!(r.arm > 1e-12 * sqrt(dd)) || r.arm == 0)
        return mech_error_set(err, MECH_EDOMAIN, "offset",
                              "the centre of mass lies on the axis (distance %.3g m): gravity "
                              "has no torque about it, so there is no oscillation",
                              r.arm);
    if (!(r.moment_axis > 0))
        return mech_error_set(err, MECH_EDOMAIN, "tensor",
                              "the moment of inertia about the axis is %.6g kg m^2, not > 0",
                              r.moment_axis);
    r.omega = sqrt(mass * g * r.arm / r.moment_axis);
    r.period = 2 * PI / r.omega;
    r.equivalent_length = r.moment_axis / (mass * r.arm);
    if (!isfinite(r.omega) || !isfinite(r.period) || !isfinite(r.equivalent_length) ||
        !mech_mat3_isfinite(r.tensor_pivot))
        return mech_error_set(err, MECH_ENUMERIC, "tensor", "a result is not finite");
    *out = r;
    return MECH_OK;
}

enum mech_status mech_foucault_modes(double length, double g, double omega, double latitude,
                                     struct mech_foucault_modes *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!pos(length)) return mech_error_set(err, MECH_EINVAL, "length", "must be finite and > 0");
    if (!pos(g)) return mech_error_set(err, MECH_EINVAL, "g", "must be finite and > 0");
    if (!(isfinite(omega) && omega >= 0))
        return mech_error_set(err, MECH_EINVAL, "omega_earth", "must be finite and >= 0");
    if (!(fabs(latitude) <= PI / 2))
        return mech_error_set(err, MECH_EINVAL, "latitude_deg", "must lie in [-90, 90] deg");
    struct mech_foucault_modes r;
    r.omega0 = sqrt(g / length);
    r.omega_z = omega * sin(latitude);
    r.swing = hypot(r.omega0, r.omega_z);
    r.ccw = r.swing - r.omega_z;
    r.cw = r.swing + r.omega_z;
    r.precession = -r.omega_z;
    if (!isfinite(r.swing) || !isfinite(r.cw))
        return mech_error_set(err, MECH_ENUMERIC, "length", "a result is not finite");
    *out = r;
    return MECH_OK;
}
