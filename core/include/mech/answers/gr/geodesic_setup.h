/* mech/answers/gr/geodesic_setup.h — the set-up of one POST /v1/gr/geodesic run, from
 * the request's initial-condition form in the caller's units (mech/gr/gr_units.h)
 * to a ready mech_geodesic_problem (mech/gr/geodesic.h) in geometric units: the
 * start radius (its default for a ray from far away), the initial state, the
 * classification of timelike motion with the exact periapsis advance and the
 * radial periods of a bound orbit, the escape radius and the run's length.
 * Pure; thread-safe; no allocation except the GSL quadrature workspace inside
 * mech_geodesic_precession_quadrature (freed before returning). */
#ifndef MECH_GEODESIC_SETUP_H
#define MECH_GEODESIC_SETUP_H

#include <stddef.h>

#include "mech/gr/geodesic.h"
#include "mech/gr/gr_units.h"
#include "mech/base/status.h"

/* How the initial state is given (one form per request). */
enum mech_geodesic_form {
    MECH_GEODESIC_FORM_ENERGY = 0, /* energy, angular_momentum, radial direction at r0 */
    MECH_GEODESIC_FORM_LOCAL,      /* local_velocity (radial, tangential) of a static observer */
    MECH_GEODESIC_FORM_IMPACT,     /* light: impact_parameter and radial direction */
    MECH_GEODESIC_FORM_TURNING,    /* bound orbit: periapsis and apoapsis */
    MECH_GEODESIC_FORM_AXES        /* bound orbit: semi_major_axis and eccentricity */
};

/* One request, every length, time, angular momentum and speed in the units
 * of `units` (SI or geometric). The has_* flags say what was given. */
struct mech_geodesic_request {
    struct mech_gr_units units;
    enum mech_geodesic_kind kind;
    enum mech_geodesic_form form;
    int has_r0;
    double r0;             /* start radius (not given: only for FORM_IMPACT, then 100 b,
                              at least 1000 GM/c^2; turning-point forms start at periapsis) */
    double phi0;           /* rad */
    double energy;         /* FORM_ENERGY: E/(m c^2) */
    double angular_momentum; /* FORM_ENERGY */
    int outward;           /* FORM_ENERGY, FORM_IMPACT: 1 outward, 0 inward */
    double v_radial, v_tangential; /* FORM_LOCAL */
    double impact_parameter;       /* FORM_IMPACT */
    double periapsis, apoapsis;    /* FORM_TURNING */
    double semi_major_axis, eccentricity; /* FORM_AXES */
    int has_tau_end, has_orbits, has_lambda_end, has_r_escape;
    double tau_end;    /* timelike: proper time to run */
    double orbits;     /* timelike bound: radial periods to run (from periapsis) */
    double lambda_end; /* null: affine parameter to run (default: the straight path to
                          r_escape, 2 % longer, plus 100 loops of the photon sphere) */
    double r_escape;   /* default: twice the apoapsis (bound) or twice r0 */
    double constraint_bound; /* passed on, checked by mech_geodesic_integrate */
    size_t samples;          /* passed on, checked by mech_geodesic_integrate */
};

/* The set-up, geometric units (M = 1). */
struct mech_geodesic_setup {
    struct mech_geodesic_problem problem; /* all but method and opt, which the caller sets */
    enum mech_geodesic_class cls;         /* timelike; PLUNGE for light */
    struct mech_geodesic_bound bd;        /* timelike: the turning points' 1/r (NaN otherwise) */
    int bound;                            /* cls == MECH_GEODESIC_BOUND */
    double adv_exact, adv_quad;           /* bound: periapsis advance per orbit, rad (NaN) */
    double period_tau, period_t;          /* bound: radial period, proper and coordinate */
    double time_unit;                     /* mech_geodesic_time_unit of the initial state */
};

/* Name of a motion class: "bound", "unbound", "circular" or "plunge". Never NULL. */
const char *mech_geodesic_class_name(enum mech_geodesic_class k);

/* Build the run of `req`. The caller has checked the request's shape (a form
 * fitting the kind, exactly one of tau_end and orbits for timelike motion,
 * lambda_end only for light, r0 given unless the form needs none).
 * Statuses (param names the request's field, as a JSON-pointer path without
 * the leading '/'):
 *   MECH_EINVAL / MECH_EDOMAIN from the initial state: "r0" or
 *     "initial/<field>" ("initial/semi_major_axis" for turning points out of
 *     range in FORM_AXES);
 *   MECH_EINVAL "orbits" (orbits for a motion that is not bound), "r_escape"
 *     (not beyond the start radius), "tau_end"/"lambda_end" (the run's length
 *     not representable);
 *   the statuses of mech_geodesic_classify / _precession_exact /
 *     _precession_quadrature unchanged (MECH_EDOMAIN, MECH_ENUMERIC, MECH_ENOMEM).
 * out is written in full only on MECH_OK. err may be NULL. */
enum mech_status mech_geodesic_setup(const struct mech_geodesic_request *req,
                                     struct mech_geodesic_setup *out, struct mech_error *err);

#endif
