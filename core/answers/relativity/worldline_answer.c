/* worldline_answer.c — one POST /v1/relativity/worldline answer (notes
 * §3.14 Doppler ticks, §3.15 the twin paradox): the units, the legs through
 * mech_worldline_run, per leg the ticks and rates each twin sees, the
 * totals, and the stay-at-home twin's telescope views (mech_telescope_home_view,
 * which needs scratch copies of the legs). The physics is in worldline.c and
 * telescope.c; this is the orchestration, so the handler only parses and
 * encodes. */
#include "mech/answers/relativity/worldline_answer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/constants.h"

static const char NOT_FINITE[] = "the result is not finite for this input (overflow or a singularity)";

static enum mech_status check_request(const struct mech_worldline_request *q,
                                      const struct mech_budget *budget, struct mech_error *err)
{
    if (!q || !budget || !q->legs)
        return mech_error_set(err, MECH_EINVAL, NULL, "NULL request, legs or budget");
    if (q->n < 1 || q->n > MECH_WORLDLINE_MAX_LEGS)
        return mech_error_set(err, MECH_EINVAL, "legs", "give 1 to %d legs",
                              MECH_WORLDLINE_MAX_LEGS);
    if (q->n_views > MECH_WORLDLINE_MAX_VIEWS || (q->n_views && !q->telescope_home_times))
        return mech_error_set(err, MECH_EINVAL, "telescope_home_times",
                              "give at most %d telescope home times", MECH_WORLDLINE_MAX_VIEWS);
    if (q->units != MECH_WORLDLINE_SECONDS && q->units != MECH_WORLDLINE_YEARS)
        return mech_error_set(err, MECH_EINVAL, "units", "units must be seconds or years");
    if (!(q->tick_interval > 0) || !isfinite(q->tick_interval))
        return mech_error_set(err, MECH_EINVAL, "tick_interval",
                              "the tick interval must be finite and > 0");
    return MECH_OK;
}

/* The telescope views (notes §3.15) at the request's home times. */
static enum mech_status views_run(const struct mech_worldline_request *q, const struct mech_leg *legs,
                                  const struct mech_leg_result *res, const struct mech_budget *budget,
                                  struct mech_worldline_answer *out, struct mech_error *err)
{
    struct mech_leg *sl = calloc(q->n, sizeof *sl);
    struct mech_leg_result *sr = calloc(q->n, sizeof *sr);
    out->views = calloc(q->n_views, sizeof *out->views);
    enum mech_status st = MECH_OK;
    if (!sl || !sr || !out->views) st = mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    for (size_t i = 0; st == MECH_OK && i < q->n_views; i++) {
        st = mech_telescope_home_view(legs, res, q->n, out->c, q->telescope_home_times[i], sl, sr,
                                      budget, &out->views[i], err);
        if (st != MECH_OK && err && !strcmp(err->param, "telescope_home_times"))
            snprintf(err->param, sizeof err->param, "telescope_home_times/%zu", i);
    }
    out->n_views = q->n_views;
    free(sl);
    free(sr);
    return st;
}

/* Per leg: c τ, and the ticks and rates of mech/answers/relativity/worldline_answer.h, each from
 * the leg's own intervals (never a difference of the running totals). */
static int leg_answer(const struct mech_leg_result *r, int accelerated, double c, double tick,
                      struct mech_worldline_leg_answer *o)
{
    double seen = r->home_clock_seen, recv = r->home_receives;
    o->r = *r;
    o->accelerated = accelerated;
    o->proper_time_ct = r->proper_time * c;
    o->traveller_sees_home = (struct mech_worldline_clock_view){
        r->home_clock_seen_start, r->home_clock_seen_end, seen / tick, seen / r->proper_time};
    o->home_sees_traveller = (struct mech_worldline_clock_view){
        r->home_receives_start, r->home_receives_end, r->proper_time / tick, r->proper_time / recv};
    return isfinite(o->proper_time_ct) && isfinite(o->traveller_sees_home.ticks) &&
           isfinite(o->traveller_sees_home.rate) && isfinite(o->home_sees_traveller.ticks) &&
           isfinite(o->home_sees_traveller.rate);
}

enum mech_status mech_worldline_answer(const struct mech_worldline_request *req,
                                       const struct mech_budget *budget,
                                       struct mech_worldline_answer *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL answer");
    memset(out, 0, sizeof *out);
    enum mech_status st = check_request(req, budget, err);
    if (st != MECH_OK) return st;
    const int years = req->units == MECH_WORLDLINE_YEARS;
    out->c = years ? 1.0 : MECH_C;
    out->g = years ? MECH_WORLDLINE_STANDARD_G * MECH_WORLDLINE_JULIAN_YEAR / MECH_C
                   : MECH_WORLDLINE_STANDARD_G;
    out->tick_interval = req->tick_interval;

    const size_t n = req->n;
    struct mech_leg *legs = calloc(n, sizeof *legs);
    struct mech_leg_result *res = calloc(n, sizeof *res);
    out->legs = calloc(n, sizeof *out->legs);
    if (!legs || !res || !out->legs) st = mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    for (size_t k = 0; st == MECH_OK && k < n; k++) {
        legs[k] = req->legs[k].leg;
        if (legs[k].kind == MECH_LEG_ACCELERATE && req->legs[k].acceleration_in_g)
            legs[k].acceleration *= out->g;
    }
    if (st == MECH_OK) st = mech_worldline_run(legs, n, out->c, budget, res, &out->total, err);
    if (st == MECH_OK && req->n_views) st = views_run(req, legs, res, budget, out, err);
    int finite = 1;
    for (size_t k = 0; st == MECH_OK && k < n; k++)
        finite &= leg_answer(&res[k], legs[k].kind == MECH_LEG_ACCELERATE, out->c,
                             req->tick_interval, &out->legs[k]);
    out->n = n;
    free(legs);
    free(res);
    if (st != MECH_OK) {
        mech_worldline_answer_free(out);
        return st;
    }

    const struct mech_worldline_total *t = &out->total;
    out->total_proper_time_ct = t->proper_time * out->c;
    out->returned = mech_vec3_norm(mech_vec3_make(t->end[1], t->end[2], t->end[3])) <=
                    1e-12 * t->distance;
    out->total_home_ticks_seen = t->home_clock_seen_end / req->tick_interval;
    out->total_traveller_ticks = t->proper_time / req->tick_interval;
    if (!finite || !isfinite(out->total_proper_time_ct) || !isfinite(out->total_home_ticks_seen) ||
        !isfinite(out->total_traveller_ticks)) {
        mech_worldline_answer_free(out);
        return mech_error_set(err, MECH_ENUMERIC, NULL, NOT_FINITE);
    }
    return MECH_OK;
}

void mech_worldline_answer_free(struct mech_worldline_answer *a)
{
    if (!a) return;
    free(a->legs);
    free(a->views);
    a->legs = NULL;
    a->views = NULL;
    a->n = a->n_views = 0;
}
