/* telescope.c — the traveller's clock as the stay-at-home twin sees it at a
 * given home time (see mech/relativity/telescope.h). */
#include "mech/relativity/telescope.h"

#include <math.h>
#include <string.h>

/* Run legs[0..k] with leg k cut to the fraction f of its amount: the event
 * reached, its proper time and the home time its light arrives. */
static enum mech_status trial(const struct mech_leg *legs, size_t k, double c, double f,
                              struct mech_leg *sl, struct mech_leg_result *sr,
                              const struct mech_budget *budget, struct mech_worldline_total *tot,
                              double *arrival, struct mech_error *err)
{
    memcpy(sl, legs, (k + 1) * sizeof *sl);
    sl[k].amount = legs[k].amount * f;
    enum mech_status st = mech_worldline_run(sl, k + 1, c, budget, sr, tot, err);
    if (st != MECH_OK) return st;
    *arrival = tot->end[0] + hypot(hypot(tot->end[1], tot->end[2]), tot->end[3]) / c;
    return MECH_OK;
}

enum mech_status mech_telescope_home_view(const struct mech_leg *legs,
                                          const struct mech_leg_result *run, size_t n, double c,
                                          double t_home, struct mech_leg *scratch_legs,
                                          struct mech_leg_result *scratch_run,
                                          const struct mech_budget *budget,
                                          struct mech_telescope_view *out,
                                          struct mech_error *err)
{
    if (!legs || !run || !n || !scratch_legs || !scratch_run || !out)
        return mech_error_set(err, MECH_EINVAL, NULL, "NULL array or no legs");
    if (!isfinite(t_home) || t_home < 0)
        return mech_error_set(err, MECH_EDOMAIN, "telescope_home_times",
                              "a home time is >= 0 (the trip starts at t = 0), got %.17g", t_home);
    const double last = run[n - 1].home_receives_end;
    if (t_home > last)
        return mech_error_set(err, MECH_EDOMAIN, "telescope_home_times",
                              "the light of the trip's end reaches home at %.17g; what the "
                              "telescope shows at %.17g depends on what the traveller does next",
                              last, t_home);
    struct mech_telescope_view v;
    memset(&v, 0, sizeof v);
    v.home_time = t_home;
    if (t_home == 0) {
        v.leg = -1; /* departure: the traveller is at home, both clocks read 0 */
        *out = v;
        return MECH_OK;
    }
    size_t k = 0;
    while (k + 1 < n && run[k].home_receives_end < t_home) k++;
    double lo = 0, hi = 1, arrival;
    struct mech_worldline_total tot;
    enum mech_status st;
    for (int i = 0; i < 200; i++) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        st = trial(legs, k, c, mid, scratch_legs, scratch_run, budget, &tot, &arrival, err);
        if (st != MECH_OK) return st;
        if (arrival < t_home)
            lo = mid;
        else
            hi = mid;
    }
    st = trial(legs, k, c, hi, scratch_legs, scratch_run, budget, &tot, &arrival, err);
    if (st != MECH_OK) return st;
    v.leg = (long)k;
    v.traveller_clock = tot.proper_time;
    memcpy(v.emission, tot.end, sizeof v.emission);
    v.light_time = hypot(hypot(tot.end[1], tot.end[2]), tot.end[3]) / c;
    *out = v;
    return MECH_OK;
}
