/* schwarzschild.c — clocks, circular orbits and effective potentials of the
 * Schwarzschild metric ds^2 = -(1 - 2M/r) dt^2 + dr^2/(1 - 2M/r) + r^2 dOmega^2
 * (Hartle eq. 9.1; Carroll eq. 5.38), in geometric units with M = 1. See
 * mech/gr/schwarzschild.h for the contracts. */
#include "mech/gr/schwarzschild.h"
#include "mech/base/constants.h"

#include <math.h>

/* 1 - sqrt(1 - x) for x <= 1, without cancellation for small x. */
static double one_minus_sqrt1m(double x)
{
    return x / (1.0 + sqrt(1.0 - x));
}

enum mech_status mech_schw_static_clock(double r, struct mech_schw_static *out,
                                        struct mech_error *err)
{
    if (!isfinite(r) || !(r > MECH_SCHW_HORIZON))
        return mech_error_set(err, MECH_EDOMAIN, "r",
                              "a static clock needs r > r_s = 2GM/c^2; got r = %.17g GM/c^2", r);
    const double x = MECH_SCHW_HORIZON / r;
    const double s = sqrt(1.0 - x);
    out->x = x;
    out->rate = s;                           /* Hartle eq. (9.17) */
    out->rate_deficit = one_minus_sqrt1m(x); /* 1 - sqrt(1 - x) */
    out->redshift = out->rate_deficit / s;   /* 1/s - 1 = (1 - s)/s, Hartle eq. (9.18) */
    return MECH_OK;
}

enum mech_status mech_schw_circular_orbit(double r, struct mech_schw_circular *out,
                                          struct mech_error *err)
{
    if (!isfinite(r) || !(r > MECH_SCHW_HORIZON))
        return mech_error_set(err, MECH_EDOMAIN, "r",
                              "circular orbits need r > r_s = 2GM/c^2; got r = %.17g GM/c^2", r);
    out->rate = out->rate_deficit = out->energy = out->angular_momentum = NAN;
    out->local_speed = out->omega = out->period_t = out->period_tau = NAN;
    out->binding_efficiency = NAN;
    if (!(r > MECH_SCHW_PHOTON_SPHERE)) {
        out->stability = MECH_SCHW_ORBIT_NONE;
        return MECH_OK;
    }
    out->stability = r > MECH_SCHW_ISCO    ? MECH_SCHW_ORBIT_STABLE
                     : r == MECH_SCHW_ISCO ? MECH_SCHW_ORBIT_MARGINAL
                                           : MECH_SCHW_ORBIT_UNSTABLE;
    const double y = 3.0 / r, s = sqrt(1.0 - y);
    out->rate = s; /* u^t = dt/dtau = 1/sqrt(1 - 3M/r): Hartle eq. (9.37)-(9.38), Carroll 5.72 */
    out->rate_deficit = one_minus_sqrt1m(y);
    out->energy = (1.0 - 2.0 / r) / s;   /* Carroll eq. (5.71) solved for E */
    out->angular_momentum = sqrt(r) / s; /* L^2 = M r / (1 - 3M/r) */
    out->local_speed = 1.0 / sqrt(r - 2.0);
    out->omega = pow(r, -1.5); /* Omega^2 = M/r^3 (Hartle eq. 9.45) */
    out->period_t = 2.0 * MECH_PI * r * sqrt(r);
    out->period_tau = out->period_t * s;
    /* 1 - E = (s - (1 - 2/r))/s with s - 1 + 2/r = (1/r)(2s - 1)/(1 + s) and
     * 2s - 1 = 3(1 - 4/r)/(2s + 1): every factor free of cancellation. */
    out->binding_efficiency = 3.0 * ((r - 4.0) / r) / (r * s * (1.0 + s) * (1.0 + 2.0 * s));
    return MECH_OK;
}

double mech_schw_veff_massive(double r, double L)
{
    return (1.0 - 2.0 / r) * (1.0 + L * L / (r * r));
}

double mech_schw_veff_photon(double r)
{
    return (1.0 - 2.0 / r) / (r * r);
}

int mech_schw_veff_extrema(double L, double *r_unstable, double *r_stable)
{
    const double L2 = L * L;
    *r_unstable = *r_stable = NAN;
    if (!(L2 >= 12.0)) return 0;
    const double q = sqrt(1.0 - 12.0 / L2);
    *r_unstable = 6.0 / (1.0 + q);    /* (L^2/2)(1 - q) without cancellation */
    *r_stable = 0.5 * L2 * (1.0 + q); /* Hartle eq. (9.33) */
    return L2 == 12.0 ? 1 : 2;
}

enum mech_status mech_schw_clock_compare(double r_ref, double r_orbit, double mass_length,
                                         struct mech_schw_clock_compare *out,
                                         struct mech_error *err)
{
    if (!isfinite(mass_length) || !(mass_length > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "M",
                              "the clock comparison needs GM/c^2 > 0; got %.17g", mass_length);
    /* the checks (and the rates) on the radii in GM/c^2; the differences below on the
     * radii as given, so r - R is exact (Sterbenz) and not the difference of two
     * rounded quotients */
    const double xr = r_ref / mass_length, xo = r_orbit / mass_length;
    struct mech_schw_static g = {0}, so = {0}; /* zeroed: GCC -O3 cannot see every path sets them */
    struct mech_schw_circular co = {0};
    enum mech_status st = mech_schw_static_clock(xr, &g, NULL);
    if (st != MECH_OK)
        return mech_error_set(err, st, "reference_r",
                              "the reference clock needs r > r_s; got %.17g GM/c^2", xr);
    if ((st = mech_schw_static_clock(xo, &so, err)) != MECH_OK) return st;
    if ((st = mech_schw_circular_orbit(xo, &co, err)) != MECH_OK) return st;
    if (co.stability == MECH_SCHW_ORBIT_NONE)
        return mech_error_set(err, MECH_EDOMAIN, "r",
                              "no circular orbit at r = %.17g GM/c^2 <= 3 (the photon sphere)", xo);
    /* Rates a = sqrt(1 - u) with u = 2m/R (reference), 2m/r (static at r), 3m/r (orbit).
     * A ratio minus one, a1/a0 - 1 = (a1^2 - a0^2) / (a0 (a1 + a0)) = (u0 - u1) / (a0 (a1 + a0)),
     * and the u differences in closed form:
     *   2m/R - 2m/r = 2m (r - R)/(r R)       (r - R exact for r near R: the tower, the ground)
     *   2m/r - 3m/r = -m/r
     *   2m/R - 3m/r = m (2r - 3R)/(r R)      (2r - 3R by one fma: net ~ 0 at r = 1.5 R)
     * so no result is a difference of two nearly equal computed numbers. */
    const double m = mass_length, m_R = m / r_ref; /* m/R < 1/2: r R itself could underflow */
    const double a_ref = g.rate, a_static = so.rate, a_orbit = co.rate;
    const double du_grav = 2.0 * ((r_orbit - r_ref) / r_orbit) * m_R;
    const double du_vel = -(m / r_orbit);
    const double du_net = (fma(-3.0, r_ref, 2.0 * r_orbit) / r_orbit) * m_R;
    out->gravitational = du_grav / (a_ref * (a_static + a_ref));
    out->velocity = du_vel / (a_ref * (a_orbit + a_static));
    out->net = du_net / (a_ref * (a_orbit + a_ref));
    out->first_order_gravitational = 0.5 * du_grav; /* GM/c^2 (1/R - 1/r) */
    out->first_order_velocity = 0.5 * du_vel;       /* -GM/(2 c^2 r) */
    out->first_order_net = 0.5 * du_net;            /* GM/c^2 (1/R - 3/(2r)) */
    out->uniform_field_gravitational = ((r_orbit - r_ref) / r_ref) * m_R; /* g h/c^2 */
    if (!isfinite(out->net) || !isfinite(out->gravitational) || !isfinite(out->velocity))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite clock comparison");
    return MECH_OK;
}
