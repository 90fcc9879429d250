/* mech/answers/relativity/worldline_answer.h — one POST /v1/relativity/worldline answer: the
 * units (seconds and metres, or years and light-years with c = 1), the legs
 * run by mech_worldline_run (mech/relativity/worldline.h) with each leg's telescope
 * ticks and rates, the totals (whether the traveller is back home), and on
 * request what the stay-at-home twin sees of the traveller's clock through a
 * telescope (mech/relativity/telescope.h). The API's handler reads the legs, calls
 * mech_worldline_answer once and encodes.
 * Thread-safe; allocates only the answer's arrays (freed by
 * mech_worldline_answer_free). */
#ifndef MECH_WORLDLINE_ANSWER_H
#define MECH_WORLDLINE_ANSWER_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/relativity/telescope.h"
#include "mech/relativity/worldline.h"

#define MECH_WORLDLINE_STANDARD_G 9.80665     /* m/s², exact by definition (CGPM 1901) */
#define MECH_WORLDLINE_JULIAN_YEAR 31557600.0 /* s, 365.25 d */
#define MECH_WORLDLINE_MAX_LEGS 1000          /* the request schema's maxItems */
#define MECH_WORLDLINE_MAX_VIEWS 20           /* telescope_home_times' maxItems */

enum mech_worldline_units {
    MECH_WORLDLINE_SECONDS = 0, /* T = s, L = m, c = 299792458 m/s, g = 9.80665 m/s² */
    MECH_WORLDLINE_YEARS = 1    /* T = Julian yr, L = ly, c = 1, g = 9.80665 yr/c ≈ 1.0323 ly/yr² */
};

/* One leg as asked: a struct mech_leg whose acceleration (ACCELERATE legs) is
 * in L/T², or in standard g when acceleration_in_g is set. */
struct mech_worldline_leg_request {
    struct mech_leg leg;
    int acceleration_in_g;
};

struct mech_worldline_request {
    enum mech_worldline_units units;
    double tick_interval;                          /* T, finite, > 0 */
    const struct mech_worldline_leg_request *legs; /* n, caller-owned */
    size_t n;                                      /* 1 .. MECH_WORLDLINE_MAX_LEGS */
    const double *telescope_home_times;            /* n_views home times (T), caller-owned */
    size_t n_views;                                /* 0 (none asked) .. MECH_WORLDLINE_MAX_VIEWS */
};

/* What one twin sees of the other's clock during one leg (notes §3.14). */
struct mech_worldline_clock_view {
    double from, to; /* traveller_sees_home: home clock readings seen at the leg's start and
                        end; home_sees_traveller: home times when they are seen (T) */
    double ticks;    /* the other clock's ticks seen during the leg: its advance / tick_interval */
    double rate;     /* the other clock's advance per own-clock time (dimensionless) */
};

struct mech_worldline_leg_answer {
    struct mech_leg_result r;
    int accelerated;       /* 1: constant proper acceleration; 0: coasting */
    double proper_time_ct; /* c times the proper time (L) */
    struct mech_worldline_clock_view traveller_sees_home, home_sees_traveller;
};

struct mech_worldline_answer {
    double c, g, tick_interval; /* L/T, L/T², T */
    size_t n;
    struct mech_worldline_leg_answer *legs; /* n, owned by the answer */
    struct mech_worldline_total total;
    double total_proper_time_ct;      /* L */
    int returned;                     /* |end| <= 1e-12 of the path length */
    double total_home_ticks_seen;     /* home ticks the traveller sees over the trip */
    double total_traveller_ticks;     /* the traveller's ticks, all seen at home eventually */
    size_t n_views;
    struct mech_telescope_view *views; /* n_views (the request's), owned; NULL when none */
};

/* Answer `req` under `budget` (one step per leg and per telescope trial).
 * Accelerations given in g become g·MECH_WORLDLINE_STANDARD_G (SI) or
 * that times MECH_WORLDLINE_JULIAN_YEAR / c (years).
 * Statuses (param is the request's field as a JSON-pointer path without the
 * leading '/'):
 *   MECH_EINVAL for NULL pointers, n outside 1 .. MECH_WORLDLINE_MAX_LEGS,
 *     n_views above MECH_WORLDLINE_MAX_VIEWS, an unknown units, a
 *     tick_interval not finite and > 0;
 *   mech_worldline_run's ("legs/<k>/..."; budget, deadline, cancel);
 *   mech_telescope_home_view's, with param "telescope_home_times/<i>";
 *   MECH_ENOMEM;
 *   MECH_ENUMERIC (no param) when a number of the answer is not finite (a
 *     tick_interval so small that the ticks overflow), the text "the result
 *     is not finite for this input (overflow or a singularity)".
 * out is always initialised (safe to free); on failure it holds no arrays.
 * err may be NULL. */
enum mech_status mech_worldline_answer(const struct mech_worldline_request *req,
                                       const struct mech_budget *budget,
                                       struct mech_worldline_answer *out, struct mech_error *err);

/* Free the arrays of an answer (safe on a zeroed or failed one). */
void mech_worldline_answer_free(struct mech_worldline_answer *a);

#endif
