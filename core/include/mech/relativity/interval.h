/* mech/relativity/interval.h — the spacetime interval between two events (notes §3.5,
 * §3.6): s² = −Δ(ct)² + |Δx|², its kind, proper time or proper length, and
 * whether a boost can reverse the events' time order.
 *
 * Events are [ct, x, y, z] in any one length unit, metric (−,+,+,+).
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_INTERVAL_H
#define MECH_INTERVAL_H

#include "mech/relativity/boost.h"
#include "mech/base/status.h"

/* Relative tolerance of the light-like test, in units of DBL_EPSILON: an
 * interval is light-like when |s²| ≤ 4 ε (Δct² + |Δx|²) + input_error. */
#define MECH_INTERVAL_LIGHTLIKE_ULPS 4.0

enum mech_interval_kind {
    MECH_INTERVAL_TIMELIKE = 0,
    MECH_INTERVAL_SPACELIKE = 1,
    MECH_INTERVAL_LIGHTLIKE = 2,
};

struct mech_interval {
    double delta[4];    /* event2 − event1, each correctly rounded */
    double s2;          /* −Δct² + |Δx|² of the exact differences of the binary inputs */
    double scale;       /* Δct² + |Δx|² (the Euclidean size, for relative figures) */
    double input_error; /* largest change of s2 if each input coordinate moved by half
                           an ulp (what a decimal input's rounding can do) */
    double tolerance;   /* |s2| at or below this counts as light-like */
    enum mech_interval_kind kind;
    int coincident;            /* the two events are the same event (Δ = 0) */
    double proper;             /* sqrt(|s2|): c·(proper time) if timelike, proper length if
                                  spacelike, 0 if light-like */
    int time_order_reversible; /* 1 exactly when spacelike */
    int has_frame;             /* frame below is set (timelike or spacelike, not coincident) */
    struct mech_boost frame;   /* a frame in which the events are co-located (timelike) or
                                  simultaneous (spacelike) */
};

/* The interval from e1 to e2 (4 doubles each, |components| ≤ 1e150).
 * Δ is formed exactly (TwoSum: hi + lo), then s² = Σ ±(hi + lo)² with
 * error-free products and compensated summation: relative error about
 * 2e-16 + 1e-31 (Δct² + |Δx|²)/|s²| for the binary inputs, however far the
 * events are from the origin. How precise the inputs are is reported in
 * input_error. The example frame's 1 − β is s²-based
 * (|s²| / (|Δ_big| (|Δct| + |Δx|))) so it keeps its precision near the light cone.
 * Statuses: MECH_OK; MECH_EINVAL param "events" (NULL or non-finite). */
enum mech_status mech_interval_compute(const double e1[4], const double e2[4],
                                       struct mech_interval *out, struct mech_error *err);

#endif
