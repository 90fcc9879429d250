/* schwarzschild.c — clocks, circular orbits and effective potentials of the
 * Schwarzschild metric ds^2 = -(1 - 2M/r) dt^2 + dr^2/(1 - 2M/r) + r^2 dOmega^2
 * (Hartle eq. 9.1; Carroll eq. 5.38), in geometric units with M = 1. See
 * mech/schwarzschild.h for the contracts. */
#include "mech/schwarzschild.h"

#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#ifndef M_PI_2
#define M_PI_2 1.57079632679489661923
#endif

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
    out->period_t = 2.0 * M_PI * r * sqrt(r);
    out->period_tau = out->period_t * s;
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

enum mech_status mech_schw_clock_compare(double r_ref, double r_orbit,
                                         struct mech_schw_clock_compare *out,
                                         struct mech_error *err)
{
    struct mech_schw_static g = {0}, so = {0}; /* zeroed: GCC -O3 cannot see every path sets them */
    struct mech_schw_circular co = {0};
    enum mech_status st = mech_schw_static_clock(r_ref, &g, NULL);
    if (st != MECH_OK)
        return mech_error_set(err, st, "reference_r",
                              "the reference clock needs r > r_s; got %.17g GM/c^2", r_ref);
    if ((st = mech_schw_static_clock(r_orbit, &so, err)) != MECH_OK) return st;
    if ((st = mech_schw_circular_orbit(r_orbit, &co, err)) != MECH_OK) return st;
    if (co.stability == MECH_SCHW_ORBIT_NONE)
        return mech_error_set(err, MECH_EDOMAIN, "r",
                              "no circular orbit at r = %.17g GM/c^2 <= 3 (the photon sphere)",
                              r_orbit);
    /* rates are 1 - deficit; differences of rates are differences of deficits */
    out->gravitational = (g.rate_deficit - so.rate_deficit) / g.rate;
    out->velocity = (so.rate_deficit - co.rate_deficit) / g.rate;
    out->net = (g.rate_deficit - co.rate_deficit) / g.rate;
    out->first_order_gravitational = 1.0 / r_ref - 1.0 / r_orbit;
    out->first_order_velocity = -0.5 / r_orbit;
    if (!isfinite(out->net))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite clock comparison");
    return MECH_OK;
}
