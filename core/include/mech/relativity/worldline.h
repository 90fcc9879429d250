/* mech/relativity/worldline.h — a trip as a chain of legs (constant velocity, or
 * constant proper acceleration along the line of motion), with the proper
 * time of the traveller, the stay-at-home time, and what each twin sees of
 * the other's clock through a telescope (notes §3.14 Doppler, §3.15 the twin
 * paradox).
 *
 * The stay-at-home twin sits at the origin of the inertial frame in which the
 * legs are given; the trip starts there at t = 0. Units: any time unit T and
 * length unit L with the speed of light c in L/T (299792458 for seconds and
 * metres, 1 for years and light-years). Pure functions; thread-safe; no
 * allocation.
 */
#ifndef MECH_WORLDLINE_H
#define MECH_WORLDLINE_H

#include <stddef.h>

#include "mech/relativity/boost.h"
#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

enum mech_leg_kind {
    MECH_LEG_COAST_TIME = 0,        /* constant velocity for a coordinate time */
    MECH_LEG_COAST_DISTANCE = 1,    /* constant velocity for a coordinate distance */
    MECH_LEG_COAST_PROPER_TIME = 2, /* constant velocity for a proper time */
    MECH_LEG_ACCELERATE = 3,        /* constant proper acceleration for a proper time */
};

struct mech_leg {
    enum mech_leg_kind kind;
    struct mech_boost velocity; /* coasting legs: the velocity in the home frame */
    double amount;              /* coordinate time (T), distance (L) or proper time (T), > 0 */
    double acceleration;        /* ACCELERATE: proper acceleration (L/T²), nonzero; negative
                                   means along −direction */
    struct mech_vec3 direction; /* ACCELERATE: the acceleration's direction; zero = along
                                   the current velocity (not allowed from rest) */
};

struct mech_leg_result {
    double proper_time;            /* traveller's clock advance (T) */
    double coordinate_time;        /* home-frame time advance (T) */
    double age_difference;         /* coordinate_time − proper_time, without cancellation (T) */
    double distance;               /* path length in the home frame (L) */
    struct mech_vec3 displacement; /* (L) */
    double start[4], end[4];       /* events [t, x, y, z] (T, L) */
    struct mech_boost final_velocity; /* velocity at the end of the leg */
    /* Telescope bookkeeping (light from the traveller reaches home at t + |x|/c;
     * light from home reaches the traveller when it was emitted at t − |x|/c). */
    double home_clock_seen_start, home_clock_seen_end; /* home clock readings the
                                   traveller sees at the leg's start and end (T) */
    double home_receives_start, home_receives_end;     /* home times when the leg's start
                                   and end are seen at home (T) */
    /* The same intervals from the leg itself, not as end − start of the running
     * totals (which would lose ε·(trip so far)/(leg): 1e-12 for a day after 10
     * years): home time the traveller sees pass during the leg, and home time
     * over which home sees the leg (T, both ≥ 0). */
    double home_clock_seen, home_receives;
};

struct mech_worldline_total {
    double proper_time, coordinate_time, age_difference, distance;
    double end[4]; /* final event [t, x, y, z] */
    struct mech_boost final_velocity;
    double home_clock_seen_end; /* home clock reading the traveller sees at the end */
    double home_receives_end;   /* home time when the end is seen at home */
};

/* Follow n ≥ 1 legs from the origin at rest, t = 0.
 * Coasting legs (velocity |β| < 1, any direction; the velocity jumps to it, as
 * in the notes' instantaneous turnaround): τ = T/γ; a distance D gives
 * T = D/(βc), τ = D/(βγc) (β > 0 required); a proper time τ gives T = γτ.
 * Accelerated legs (hyperbolic motion, notes §3.12 force 4-vector with constant
 * proper acceleration a): rapidity η0 → η0 + aτ/c along the acceleration e,
 * with h = aτ/(2c), m = η0 + h, K = cτ sinh(h)/h:
 *   cΔt = K cosh m,  Δx·e = K sinh m   (= (c/a)(sinh η − sinh η0) etc.),
 * precise for small aτ/c; the current velocity must be along ±e.
 * Home-clock images use cΔt − |Δx| in light-cone form (cT(1 − β), K e^{−|m|})
 * and |x| ± x·e' from cross products, so β = 1 − 1e-15 keeps its digits.
 * legs[] and out[] (n each) are caller-owned. One budget step per leg.
 * Statuses: MECH_OK; MECH_EINVAL (NULL, n = 0, c ≤ 0); MECH_EDOMAIN with
 * param "legs/<k>/..." (distance leg at zero speed; acceleration from rest
 * without a direction; acceleration not along the velocity; rapidity beyond
 * MECH_BOOST_RAPIDITY_MAX); MECH_ENUMERIC param "legs/<k>" (overflow);
 * MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED from mech_budget_check. */
enum mech_status mech_worldline_run(const struct mech_leg *legs, size_t n, double c,
                                    const struct mech_budget *budget, struct mech_leg_result *out,
                                    struct mech_worldline_total *total, struct mech_error *err);

#endif
