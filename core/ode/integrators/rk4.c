/* integrators/rk4.c — the classical fourth-order Runge–Kutta method, fixed
 * step, on libmech's stepper interface (integrator.h).
 *
 * Reference: Abramowitz & Stegun, Handbook of Mathematical Functions,
 * eq. 25.5.10 (as GSL ode-initval2/rk4.c):
 *   k1 = f(t, y), k2 = f(t + h/2, y + h k1/2), k3 = f(t + h/2, y + h k2/2),
 *   k4 = f(t + h, y + h k3),  y1 = y + h (k1 + 2 k2 + 2 k3 + k4) / 6.
 * Four right-hand-side evaluations per step, global error O(h^4).
 */
#include <stdlib.h>

#include "ode/integrators/integrator.h"

struct rk4_ws {
    size_t dim;
    double *k1, *k2, *k3, *k4, *ytmp; /* one block of 5 * dim doubles */
};

static enum mech_status rk4_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                  struct mech_error *err)
{
    (void)opt;
    struct rk4_ws *w = malloc(sizeof *w);
    double *block = malloc(5 * dim * sizeof *block);
    if (!w || !block) {
        free(w);
        free(block);
        return mech_error_set(err, MECH_ENOMEM, NULL, "rk4: out of memory");
    }
    w->dim = dim;
    w->k1 = block;
    w->k2 = block + dim;
    w->k3 = block + 2 * dim;
    w->k4 = block + 3 * dim;
    w->ytmp = block + 4 * dim;
    *ws = w;
    return MECH_OK;
}

static void rk4_reset(void *ws) { (void)ws; /* stateless between steps */ }

static void rk4_free(void *ws)
{
    struct rk4_ws *w = ws;
    if (!w) return;
    free(w->k1);
    free(w);
}

static enum mech_status rk4_step(void *ws, const struct mech_ode_system *sys, double t, double h,
                                 double *y, struct mech_ode_stats *stats, struct mech_error *err)
{
    struct rk4_ws *w = ws;
    const size_t n = w->dim;
    enum mech_status st;
    /* A&S 25.5.10 */
    if ((st = mech_ode_eval(sys, t, y, w->k1, stats, err)) != MECH_OK) return st;
    for (size_t i = 0; i < n; i++) w->ytmp[i] = y[i] + 0.5 * h * w->k1[i];
    if ((st = mech_ode_eval(sys, t + 0.5 * h, w->ytmp, w->k2, stats, err)) != MECH_OK) return st;
    for (size_t i = 0; i < n; i++) w->ytmp[i] = y[i] + 0.5 * h * w->k2[i];
    if ((st = mech_ode_eval(sys, t + 0.5 * h, w->ytmp, w->k3, stats, err)) != MECH_OK) return st;
    for (size_t i = 0; i < n; i++) w->ytmp[i] = y[i] + h * w->k3[i];
    if ((st = mech_ode_eval(sys, t + h, w->ytmp, w->k4, stats, err)) != MECH_OK) return st;
    for (size_t i = 0; i < n; i++)
        y[i] += h / 6.0 * (w->k1[i] + 2.0 * w->k2[i] + 2.0 * w->k3[i] + w->k4[i]);
    return MECH_OK;
}

const struct mech_integrator mech_integrator_rk4 = {
    .name = "rk4",
    .order = 4,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_EXPLICIT,
    .doc = "Classical fourth-order Runge-Kutta, fixed step dt, 4 right-hand-side evaluations "
           "per step, global error O(dt^4); not symplectic (energy drifts secularly).",
    .reference = "M. Abramowitz, I. A. Stegun, Handbook of Mathematical Functions (1964), "
                 "eq. 25.5.10; W. Kutta, Z. Math. Phys. 46 (1901) 435-453.",
    .alloc = rk4_alloc,
    .reset = rk4_reset,
    .free = rk4_free,
    .step = rk4_step,
    .evolve = NULL,
};
