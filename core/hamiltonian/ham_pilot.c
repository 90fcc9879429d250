/* ham_pilot.c — the chooser's pilot hook for Hamiltonian flows
 * (mech_ham_pilot_run, declared in mech/hamiltonian.h; the pilot itself is
 * core/ode/chooser_pilot.c): the flow over a fraction of its run, two
 * samples, the end state for the pilot's error estimate. */
#include <string.h>

#include "mech/hamiltonian.h"

enum mech_status mech_ham_pilot_run(void *ctx, const char *method,
                                    const struct mech_ode_options *opt, double fraction,
                                    const struct mech_budget *budget,
                                    struct mech_ode_stats *stats, double *y_end, size_t *dim,
                                    struct mech_error *err)
{
    const struct mech_ham_flow_problem *p0 = ctx;
    if (!p0 || !p0->sys || !method || !opt || !stats || !y_end || !dim ||
        !(fraction > 0.0 && fraction <= 1.0))
        return mech_error_set(err, MECH_EINVAL, NULL, "invalid pilot arguments");
    *dim = 0;
    memset(stats, 0, sizeof *stats);
    const struct mech_integrator *m = mech_ode_method_find(method);
    if (!m) return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method");
    struct mech_ham_flow_problem p = *p0;
    p.t_end = p0->t_end * fraction;
    p.n_samples = 2;
    p.method = m;
    p.opt = *opt;
    double t[2], y[2 * MECH_HAM_MAX_DIM];
    struct mech_ham_flow_result r;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.y = y;
    enum mech_status st = mech_ham_flow(&p, budget, &r, err);
    *stats = r.stats;
    if (st != MECH_OK) return st;
    const size_t n = 2 * (size_t)p.sys->dof;
    if (r.n_samples != 2 || n > MECH_HAM_MAX_DIM)
        return mech_error_set(err, MECH_EINTERNAL, NULL, "pilot samples");
    memcpy(y_end, y + n, n * sizeof *y);
    *dim = n;
    return MECH_OK;
}
