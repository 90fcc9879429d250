/* poincare_orbits.c — a Poincaré section of several orbits within one step
 * budget, each orbit handed to the caller as it completes, an angle plane
 * reduced to [0, 2 pi) (mech/answers/hamiltonian/poincare_orbits.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/hamiltonian/poincare_orbits.h"

enum mech_status mech_poincare_orbits(const struct mech_poincare_problem *base,
                                      const double *starts, size_t n_orbits,
                                      const struct mech_budget *budget,
                                      mech_poincare_orbit_fn visit, void *ctx,
                                      struct mech_poincare_totals *totals, struct mech_error *err)
{
    memset(totals, 0, sizeof *totals);
    const size_t maxc = base->max_crossings;
    if (maxc < 1 || maxc > MECH_POINCARE_ORBITS_MAX_CROSSINGS)
        return mech_error_set(err, MECH_EINVAL, "max_crossings",
                              "max_crossings must be 1 to %d, got %zu",
                              MECH_POINCARE_ORBITS_MAX_CROSSINGS, maxc);
    double *buf = malloc(7 * maxc * sizeof *buf);
    if (!buf) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    /* the plane is the other coordinate's; phi there is reduced mod 2 pi */
    const size_t o = 1 - base->section.index;
    const int wrap = !strcmp(mech_ham_coordinate_name(base->sys, o), "phi");
    enum mech_status st = MECH_OK;
    for (size_t k = 0; k < n_orbits && st == MECH_OK; k++) {
        struct mech_poincare_problem pp = *base;
        pp.y0 = starts + 4 * k;
        struct mech_poincare_result r;
        memset(&r, 0, sizeof r);
        r.t = buf;
        r.u = buf + maxc;
        r.v = buf + 2 * maxc;
        r.y = buf + 3 * maxc;
        struct mech_budget b = *budget;
        b.max_steps -= totals->stats.steps;
        st = b.max_steps > 0 ? mech_poincare_run(&pp, &b, &r, err)
                             : mech_error_set(err, MECH_EBUDGET, NULL,
                                              "the step budget is exhausted before orbit %zu", k);
        if (st != MECH_OK) break;
        totals->stats.steps += r.stats.steps;
        totals->stats.rejected_steps += r.stats.rejected_steps;
        totals->stats.rhs_evaluations += r.stats.rhs_evaluations;
        totals->second_order = r.second_order;
        if (wrap)
            for (size_t i = 0; i < r.n_crossings; i++) {
                r.u[i] = fmod(r.u[i], 2.0 * MECH_PI);
                if (r.u[i] < 0.0) r.u[i] += 2.0 * MECH_PI;
            }
        if (visit(ctx, k, &r))
            st = mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for orbit %zu", k);
    }
    free(buf);
    return st;
}
