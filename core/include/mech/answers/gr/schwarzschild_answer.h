/* mech/answers/gr/schwarzschild_answer.h — one POST /v1/gr/schwarzschild answer in the
 * caller's units (mech/gr/gr_units.h): the named radii, and on request the
 * static clock and circular orbit at r, the clock comparison with a static
 * reference clock, the proper times of a radial infall and samples of the
 * effective potentials with their extrema. The physics is
 * mech/gr/schwarzschild.h and mech/gr/radial_infall.h in geometric units; this is
 * the orchestration and the unit conversion, so the API layer only parses
 * and encodes.
 * Thread-safe; allocates only the potential's sample arrays (freed by
 * mech_schw_answer_free). */
#ifndef MECH_SCHWARZSCHILD_ANSWER_H
#define MECH_SCHWARZSCHILD_ANSWER_H

#include <stddef.h>

#include "mech/gr/gr_units.h"
#include "mech/gr/radial_infall.h"
#include "mech/gr/schwarzschild.h"
#include "mech/base/status.h"

/* The most samples of the effective potentials one answer holds. */
#define MECH_SCHW_POTENTIAL_MAX_SAMPLES 10000

/* One request; every radius in the units of `units` (m, or GM/c^2 when
 * geometric), the potential's angular momentum in m^2/s (or GM/c). */
struct mech_schw_request {
    struct mech_gr_units units;
    int has_r;
    double r; /* static clock and circular orbit at r */
    int has_reference_r;
    double reference_r; /* static reference clock (needs r) */
    int has_infall_from;
    double infall_from; /* radius of rest of a radial fall */
    int has_potential;
    double potential_L; /* specific angular momentum of the sampled potential */
    int has_r_min, has_r_max;
    double r_min, r_max; /* sampled range; defaults r_s and max(30, 3 r_stable) GM/c^2 */
    size_t samples;      /* 2 .. MECH_SCHW_POTENTIAL_MAX_SAMPLES */
};

/* At r: the static clock (dimensionless, as in mech/gr/schwarzschild.h) and the
 * circular geodesic with angular_momentum, omega, period_t and period_tau in
 * the caller's units (m^2/s, 1/s, s; or geometric). */
struct mech_schw_at_r {
    double r;                    /* as given */
    double r_over_rs;            /* r / r_s */
    double weak_field_potential; /* GM/(r c^2) */
    struct mech_schw_static stat;
    struct mech_schw_circular circ;
};

/* The effective potentials sampled evenly in the caller's length unit from
 * r_min to r_max (the given ends exactly): massive V (dimensionless, E^2
 * normalisation), V - 1 formed without cancellation, the photon W in 1/m^2
 * (or (GM/c^2)^-2); the extrema of V (count 0, 1 or 2; radii in the caller's
 * unit, NaN when absent) and the photon maximum W(3GM/c^2). */
struct mech_schw_potential {
    double L; /* the angular momentum, caller's units (through geometric and back) */
    size_t n;
    double *r, *massive, *massive_minus_one, *photon; /* n each, owned by the answer */
    int n_extrema;
    double unstable_r, unstable_V, stable_r, stable_V;
    double photon_max_r, photon_max_W;
};

struct mech_schw_answer {
    /* lengths in the caller's unit */
    double schwarzschild_radius, photon_sphere, isco, critical_impact_parameter;
    double isco_binding_efficiency; /* 1 - sqrt(8/9) */
    int has_at_r;
    struct mech_schw_at_r at_r;
    int has_clock;                        /* reference_r given */
    struct mech_schw_clock_compare clock; /* fractions, relative to the reference clock */
    int has_infall;
    struct mech_radial_infall infall; /* proper times in the caller's time unit */
    int has_potential;
    struct mech_schw_potential potential;
};

/* Answer `req`. Valid range: any doubles (checked, not assumed); the units
 * set up by mech_gr_units_init.
 * Statuses (param is the request's field as a JSON-pointer path without the
 * leading '/'):
 *   MECH_EINVAL "r": reference_r without r;
 *   MECH_EDOMAIN "r": r at or inside the horizon (or not finite), the text
 *     naming r and r_s in the caller's unit;
 *   mech_schw_clock_compare's statuses ("reference_r", "r", "M", MECH_ENUMERIC);
 *   mech_radial_infall_from_rest's (MECH_EDOMAIN "infall_from");
 *   MECH_EDOMAIN "effective_potential/r_min": r_min inside the horizon;
 *   MECH_EINVAL "effective_potential/r_max": r_max not above r_min or not finite;
 *   MECH_EINVAL "effective_potential/samples": outside 2 .. MECH_SCHW_POTENTIAL_MAX_SAMPLES;
 *   MECH_ENOMEM for the samples;
 *   MECH_ENUMERIC (no param) when a number of the answer is not finite (a
 *     mass so small that GM/c^2 or GM/c^3 over- or underflows the radii or
 *     periods in geometric units), the text "the result is not finite for
 *     this input (overflow or a singularity)".
 * out is always initialised (safe to free); on failure it holds no arrays.
 * err may be NULL. */
enum mech_status mech_schw_answer(const struct mech_schw_request *req, struct mech_schw_answer *out,
                                  struct mech_error *err);

/* Free the arrays of an answer (safe on a zeroed or failed one). */
void mech_schw_answer_free(struct mech_schw_answer *a);

#endif
