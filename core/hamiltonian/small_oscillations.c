/* small_oscillations.c — linearised motion about circular orbits, the conical
 * pendulum's steady precession and a physical pendulum's hanging equilibrium
 * (mech/hamiltonian/small_oscillations.h). Closed forms only. */
#include "mech/hamiltonian/small_oscillations.h"
#include "mech/base/constants.h"

#include <math.h>
#include <stdio.h>

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
        r.apsidal_angle = MECH_PI / sqrt(q);
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
    if (!(angle > 0 && angle < MECH_PI / 2))
        return mech_error_set(err, MECH_EINVAL, "angle",
                              "the cone half-angle must lie in (0, pi/2): at 0 the bob hangs "
                              "still, at pi/2 no finite rate holds it");
    double c = cos(angle), s = sin(angle);
    struct mech_conical_pendulum r;
    r.phi_dot = sqrt(g / (length * c));
    r.period = 2 * MECH_PI / r.phi_dot;
    double f = sqrt(1 + 3 * c * c);
    r.omega_theta = r.phi_dot * f;
    r.apsidal_angle = MECH_PI / f;
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
    r.period = 2 * MECH_PI / r.omega;
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
    if (!(fabs(latitude) <= MECH_PI / 2))
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

/* Largest-magnitude component positive (the first of near-ties). */
static struct mech_vec3 sign_rule(struct mech_vec3 v)
{
    double c[3] = {v.x, v.y, v.z};
    double mx = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
    for (int i = 0; i < 3; i++)
        if (fabs(c[i]) >= mx * (1 - 1e-12)) return c[i] < 0 ? mech_vec3_scale(v, -1) : v;
    return v;
}

enum mech_status mech_ball_pendulum(double mass, struct mech_mat3 i_cm, struct mech_vec3 d,
                                    double g, struct mech_ball_pendulum *out,
                                    struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    /* the tensor about the pivot and the checks: through the hinge version, about an
     * axis normal to d (any; only tensor_pivot is used from it) */
    struct mech_vec3 a = fabs(d.x) <= fabs(d.y) && fabs(d.x) <= fabs(d.z)
                             ? mech_vec3_make(1, 0, 0)
                             : (fabs(d.y) <= fabs(d.z) ? mech_vec3_make(0, 1, 0)
                                                       : mech_vec3_make(0, 0, 1));
    double dn = mech_vec3_norm(d);
    if (!(dn > 0) && mech_vec3_isfinite(d))
        return mech_error_set(err, MECH_EDOMAIN, "offset",
                              "the centre of mass is at the pivot: no restoring torque");
    struct mech_physical_pendulum h;
    enum mech_status st = mech_physical_pendulum(mass, i_cm, d, mech_vec3_cross(d, a), g, &h, err);
    if (st != MECH_OK) return st;
    struct mech_vec3 e = mech_vec3_scale(d, -1 / dn);
    struct mech_vec3 u = mech_vec3_cross(d, a);
    u = mech_vec3_scale(u, 1 / mech_vec3_norm(u));
    struct mech_vec3 v = mech_vec3_cross(e, u);
    const struct mech_mat3 ip = h.tensor_pivot;
#define Q(x, y) mech_vec3_dot((x), mech_mat3_mul_vec(ip, (y)))
    double iuu = Q(u, u), ivv = Q(v, v), iuv = Q(u, v), iee = Q(e, e), iue = Q(u, e),
           ive = Q(v, e);
#undef Q
    double tr = ip.a[0][0] + ip.a[1][1] + ip.a[2][2];
    if (iee > 1e-12 * tr) {
        iuu -= iue * iue / iee;
        ivv -= ive * ive / iee;
        iuv -= iue * ive / iee;
    }
    double mean = 0.5 * (iuu + ivv), half = 0.5 * (iuu - ivv), r = hypot(half, iuv);
    double m0 = mean - r, m1 = mean + r;
    if (!(m0 > 0))
        return mech_error_set(err, MECH_EDOMAIN, "tensor",
                              "a reduced moment about a horizontal axis is %.6g kg m^2, not > 0",
                              m0);
    /* eigenvector of [[iuu, iuv], [iuv, ivv]] for m1: angle t with tan 2t = 2 iuv/(iuu - ivv) */
    double t = 0.5 * atan2(iuv, half);
    struct mech_vec3 w1 = mech_vec3_add(mech_vec3_scale(u, cos(t)), mech_vec3_scale(v, sin(t)));
    struct mech_vec3 w0 = mech_vec3_cross(e, w1);
    struct mech_ball_pendulum b;
    b.tensor_pivot = ip;
    b.arm = dn;
    b.moment[0] = m0;
    b.moment[1] = m1;
    b.axis[0] = sign_rule(w0);
    b.axis[1] = sign_rule(w1);
    b.omega[0] = sqrt(mass * g * dn / m0);
    b.omega[1] = sqrt(mass * g * dn / m1);
    if (!isfinite(b.omega[0]) || !isfinite(b.omega[1]))
        return mech_error_set(err, MECH_ENUMERIC, "tensor", "a result is not finite");
    *out = b;
    return MECH_OK;
}
