/* integrators/euler.c — the explicit (forward) Euler method, fixed step, on
 * libmech's stepper interface (integrator.h). A teaching baseline: the
 * simplest method there is, first order, and the one whose failure to
 * conserve energy (it grows secularly on every oscillation) the others fix.
 *
 * Reference: L. Euler, Institutionum calculi integralis, vol. I (1768),
 * sect. II ch. VII; E. Hairer, S. P. Nørsett, G. Wanner, Solving Ordinary
 * Differential Equations I, 2nd ed. (1993), sect. I.7 (Euler polygons):
 *   y1 = y + h f(t, y).
 * One right-hand-side evaluation per step, global error O(h). Works on the
 * first-order right-hand side, so it handles any system.
 */
#include <stdlib.h>

#include "ode/integrators/integrator.h"

struct euler_ws {
    size_t dim;
    double *k; /* dim: f(t, y) */
};

static enum mech_status euler_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                    struct mech_error *err)
{
    (void)opt;
    struct euler_ws *w = malloc(sizeof *w);
    double *k = malloc((dim ? dim : 1) * sizeof *k);
    if (!w || !k) {
        free(w);
        free(k);
        return mech_error_set(err, MECH_ENOMEM, NULL, "euler: out of memory");
    }
    w->dim = dim;
    w->k = k;
    *ws = w;
    return MECH_OK;
}

static void euler_reset(void *ws) { (void)ws; /* stateless between steps */ }

static void euler_free(void *ws)
{
    struct euler_ws *w = ws;
    if (!w) return;
    free(w->k);
    free(w);
}

static enum mech_status euler_step(void *ws, const struct mech_ode_system *sys, double t, double h,
                                   double *y, struct mech_ode_stats *stats, struct mech_error *err)
{
    struct euler_ws *w = ws;
    enum mech_status st = mech_ode_eval(sys, t, y, w->k, stats, err);
    if (st != MECH_OK) return st;
    for (size_t i = 0; i < w->dim; i++) y[i] += h * w->k[i]; /* HNW I sect. I.7 */
    return MECH_OK;
}

const struct mech_integrator mech_integrator_euler = {
    .name = "euler",
    .order = 1,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_EXPLICIT,
    .doc = "Explicit (forward) Euler, fixed step dt, one right-hand-side evaluation per step, "
           "global error O(dt). A teaching baseline only: on any oscillation its energy grows "
           "secularly (by a factor 1 + (w dt)^2 per step on a harmonic oscillator of angular "
           "frequency w); compare with symplectic_euler, which costs the same.",
    .reference = "L. Euler, Institutionum calculi integralis, vol. I (1768); E. Hairer, "
                 "S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, 2nd ed. "
                 "(Springer, 1993), sect. I.7.",
    .alloc = euler_alloc,
    .reset = euler_reset,
    .free = euler_free,
    .step = euler_step,
    .evolve = NULL,
};
