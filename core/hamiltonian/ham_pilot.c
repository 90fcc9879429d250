/* ham_pilot.c — the chooser's pilot hook for Hamiltonian flows
 * (mech_ham_pilot_run, declared in mech/hamiltonian/hamiltonian.h; the pilot itself is
 * core/ode/chooser_pilot.c): the flow over a fraction of its run, two
 * samples, the end state for the pilot's error estimate. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <string.h>

#include "mech/hamiltonian/hamiltonian.h"

double mech_ham_error_gain(const struct mech_ham_system *s, const double *y0)
{
    if (!s || !y0 || s->kind != MECH_HAM_PENDULUM || !(s->g > 0.0) || !(s->length > 0.0) ||
        !(s->mass > 0.0))
        return 1.0;
    const double ml2 = s->mass * s->length * s->length;
    const double w0 = sqrt(s->g / s->length);
    /* energy above the bottom over the separatrix's: (1 - cos q)/2 + p^2 / (2 ml2 w0)^2,
     * 1 - cos q = 2 sin^2(q/2) without cancellation */
    const double sh = sin(0.5 * y0[0]);
    const double pw = y0[1] / (2.0 * ml2 * w0);
    double m = sh * sh + pw * pw;
    if (!(m > 0.0) || !isfinite(m)) return 1.0;
    if (m > 1.0) m = 1.0 / m; /* over the top: the rotation's modulus */
    if (m > 1.0 - 1e-12) return 1e6;
    gsl_sf_result K, E;
    const double k = sqrt(m);
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K) != GSL_SUCCESS ||
        gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &E) != GSL_SUCCESS || !(K.val > 0.0))
        return 1.0;
    /* m dK/dm / K, dK/dm = (E - (1 - m) K) / (2 m (1 - m)) */
    const double S = (E.val - (1.0 - m) * K.val) / (2.0 * (1.0 - m) * K.val);
    const double gain = 1.0 + 40.0 * pow(fmax(S, 0.0), 0.8);
    return isfinite(gain) ? fmin(gain, 1e6) : 1e6;
}

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
