/* mech/gr/schwarzschild.h — static quantities of the Schwarzschild geometry:
 * clocks, red shift, circular orbits, the special radii and the effective
 * potentials (the notes' "A Little General Relativity", built as Hartle,
 * "Gravity" ch. 6, 9, 11; Carroll, "Spacetime and Geometry" ch. 5; Schutz,
 * "A First Course in General Relativity" ch. 11).
 *
 * Units: geometric, G = c = 1 with the mass as unit (M = 1): radii in GM/c^2,
 * times in GM/c^3, specific angular momenta L/m in GM/c, specific energies
 * E/(m c^2) dimensionless. The Schwarzschild radius is r_s = 2. The API layer
 * converts SI through GM/c^2.
 *
 * Precision: every "1 - something" that is small for r >> r_s is formed
 * without cancellation (1 - sqrt(1 - x) = x / (1 + sqrt(1 - x))), so the
 * GPS-size effects (1e-10) keep full relative precision.
 *
 * Thread-safety: pure functions, reentrant; nothing global.
 */
#ifndef MECH_SCHWARZSCHILD_H
#define MECH_SCHWARZSCHILD_H

#include "mech/base/status.h"

/* Named radii (GM/c^2). */
#define MECH_SCHW_HORIZON 2.0                       /* r_s = 2GM/c^2 */
#define MECH_SCHW_PHOTON_SPHERE 3.0                 /* Hartle eq. (11.12): the maximum of W_eff */
#define MECH_SCHW_ISCO 6.0                          /* Hartle eq. (9.35) with L^2 = 12 */
#define MECH_SCHW_CRITICAL_IMPACT 5.196152422706632 /* 3 sqrt(3), Hartle eq. (11.13) */

/* A static observer's clock at r (hovering at fixed r, phi). */
struct mech_schw_static {
    double x;            /* r_s / r = 2 / r */
    double rate;         /* dtau/dt = sqrt(1 - 2/r)  (Hartle eq. 9.17) */
    double rate_deficit; /* 1 - dtau/dt = x / (1 + sqrt(1 - x)), no cancellation */
    double redshift;     /* z = 1/sqrt(1 - x) - 1 = deficit / rate, light sent from r
                            and received at infinity (Hartle eq. 9.18) */
};

/* Static clock at r (GM/c^2). Statuses: MECH_OK; MECH_EDOMAIN (param "r") for
 * r <= 2 (no static observer at or inside the horizon) or r not finite. */
enum mech_status mech_schw_static_clock(double r, struct mech_schw_static *out,
                                        struct mech_error *err);

enum mech_schw_stability {
    MECH_SCHW_ORBIT_NONE = 0,     /* r <= 3: no circular geodesic (inside the photon sphere) */
    MECH_SCHW_ORBIT_UNSTABLE = 1, /* 3 < r < 6: a maximum of V_eff */
    MECH_SCHW_ORBIT_MARGINAL = 2, /* r == 6: the ISCO, inflection of V_eff */
    MECH_SCHW_ORBIT_STABLE = 3    /* r > 6: a minimum of V_eff */
};

/* A circular geodesic at r (Hartle §9.3, Carroll eqs. 5.70-5.72). Fields other
 * than `stability` are NaN when stability == NONE. */
struct mech_schw_circular {
    enum mech_schw_stability stability;
    double rate;             /* dtau/dt = sqrt(1 - 3/r) (u^t = 1/sqrt(1 - 3M/r)) */
    double rate_deficit;     /* 1 - dtau/dt = (3/r) / (1 + sqrt(1 - 3/r)) */
    double energy;           /* E/(m c^2) = (1 - 2/r) / sqrt(1 - 3/r) */
    double angular_momentum; /* L/(m) in GM/c: sqrt(r) / sqrt(1 - 3/r) */
    double local_speed;      /* v/c seen by a static observer: 1/sqrt(r - 2) */
    double omega;            /* dphi/dt = r^(-3/2) (Kepler's law holds in t), c^3/GM */
    double period_t;         /* 2 pi r^(3/2), GM/c^3 */
    double period_tau;       /* period_t * rate */
    double binding_efficiency; /* 1 - E/(m c^2): the fraction of the rest energy released
                                  spiralling in from infinity, 3(r - 4)/(r^2 s (1 + s)(1 + 2s)),
                                  s = sqrt(1 - 3/r), without cancellation: 1/(2r) far out,
                                  1 - sqrt(8/9) = 5.72 % at the ISCO, 0 at r = 4 (marginally
                                  bound), negative inside (E > 1: unbound) */
};

/* 1 - E of the ISCO, 1 - sqrt(8/9) = 1/(9 + 6 sqrt 2) (Hartle §9.3, the accretion efficiency). */
#define MECH_SCHW_ISCO_BINDING_EFFICIENCY 0.057190958417936634

/* Circular geodesic at r (GM/c^2). Statuses: MECH_OK (also for r <= 3, then
 * stability NONE); MECH_EDOMAIN (param "r") for r <= 2 or non-finite. */
enum mech_status mech_schw_circular_orbit(double r, struct mech_schw_circular *out,
                                          struct mech_error *err);

/* Massive effective potential in the E^2 normalisation:
 * (dr/dtau)^2 + V(r) = E^2 with V = (1 - 2/r)(1 + L^2/r^2) (Carroll eq. 5.61
 * rearranged; Hartle eq. 9.29 is (V - 1)/2). L in GM/c, r > 0. Cannot fail. */
double mech_schw_veff_massive(double r, double L);

/* Photon effective potential W(r) = (1 - 2/r)/r^2, with (1/L^2)(dr/dlambda)^2
 * = 1/b^2 - W (Hartle eq. 11.9-11.10); units (GM/c^2)^-2. Cannot fail. */
double mech_schw_veff_photon(double r);

/* Extrema of the massive V for angular momentum L: circular orbits at
 * r = (L^2/2)(1 +- sqrt(1 - 12/L^2)) (Hartle eq. 9.33), the minus root formed
 * as 6 / (1 + sqrt(1 - 12/L^2)). Returns the number found: 0 (L^2 < 12),
 * 1 (L^2 == 12: r_stable = r_unstable = 6) or 2; unused outputs are NaN. */
int mech_schw_veff_extrema(double L, double *r_unstable, double *r_stable);

/* Clock comparison between a static clock at r_ref (e.g. the ground) and a
 * clock on a circular geodesic at r_orbit (GPS), both against coordinate time
 * t and expressed relative to the reference clock:
 *   net = rate_orbit / rate_ref - 1 = gravitational + velocity, with
 *   gravitational = (rate_static(r_orbit) - rate_ref) / rate_ref,
 *   velocity      = (rate_orbit - rate_static(r_orbit)) / rate_ref.
 * Each is formed as (u0 - u1) / (a0 (a1 + a0)) with rates a = sqrt(1 - u) and
 * the differences u0 - u1 in closed form on the radii as given (2m (r - R)/(r R),
 * -m/r, m (2r - 3R)/(r R)), so a tower (r - R = 22.5 m on the Earth: 2.5e-15)
 * or a 1 cm step keeps full relative precision, as does net near r = 1.5 R
 * where it changes sign. first_order_*: the weak-field forms m (1/R - 1/r),
 * -m/(2r) and their sum m (1/R - 3/(2r)), formed the same way. */
struct mech_schw_clock_compare {
    double gravitational, velocity, net;
    double first_order_gravitational, first_order_velocity, first_order_net;
    double uniform_field_gravitational; /* the notes' uniform-field red shift g h / c^2 with
                                           g = GM/R^2 at the reference and h = r - R:
                                           m (r - R)/R^2 (an approximation: the field's fall-off
                                           over h is left out, relative error ~h/R) */
};

/* r_ref and r_orbit in any length unit, mass_length = GM/c^2 in that unit (1 for
 * geometric radii; 4.435e-3 for the Earth in metres). The radii are passed
 * unscaled so their difference is formed before any rounding.
 * Statuses: MECH_OK; MECH_EDOMAIN with param "reference_r" (r_ref <= 2 GM/c^2),
 * "r" (r_orbit <= 3 GM/c^2: no circular orbit) or "M" (mass_length not > 0 or
 * not finite); MECH_ENUMERIC for a non-finite result. */
enum mech_status mech_schw_clock_compare(double r_ref, double r_orbit, double mass_length,
                                         struct mech_schw_clock_compare *out,
                                         struct mech_error *err);

#endif
