/* integrators/verlet_kernel.c — the Störmer–Verlet stage shared by verlet.c
 * and yoshida.c (see verlet_kernel.h for the scheme and its references).
 * Moved here from verlet.c unchanged in arithmetic, so `verlet` gives the
 * same bits as before.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ode/integrators/verlet_kernel.h"

enum { VERLET_MAX_ITER = 60 };

enum mech_status mech_verlet_kernel_init(struct mech_verlet_kernel *k, size_t dim,
                                         const char *name, struct mech_error *err)
{
    memset(k, 0, sizeof *k);
    if (dim == 0 || dim % 2 != 0)
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "%s needs a state (q, v) of even dimension, got %zu", name, dim);
    size_t nq = dim / 2;
    double *block = malloc(7 * nq * sizeof *block);
    if (!block) return mech_error_set(err, MECH_ENOMEM, NULL, "%s: out of memory", name);
    k->nq = nq;
    k->a0 = block;
    k->a1 = block + nq;
    k->vh = block + 2 * nq;
    k->vtry = block + 3 * nq;
    k->q1 = block + 4 * nq;
    k->q_m = block + 5 * nq;
    k->a_m = block + 6 * nq;
    k->memo_valid = 0;
    k->t_m = 0.0;
    return MECH_OK;
}

void mech_verlet_kernel_release(struct mech_verlet_kernel *k)
{
    if (!k) return;
    free(k->a0);
    memset(k, 0, sizeof *k);
}

void mech_verlet_kernel_reset(struct mech_verlet_kernel *k)
{
    if (k) k->memo_valid = 0;
}

/* a0 = a(t, q) for velocity-free forces, from the memo when (t, q) matches it exactly. */
static enum mech_status accel_memo(struct mech_verlet_kernel *k, const struct mech_ode_system *sys,
                                   double t, const double *q, const double *v,
                                   struct mech_ode_stats *stats, struct mech_error *err)
{
    const size_t nq = k->nq;
    if (k->memo_valid && k->t_m == t && memcmp(k->q_m, q, nq * sizeof *q) == 0) {
        memcpy(k->a0, k->a_m, nq * sizeof *q);
        return MECH_OK;
    }
    return mech_ode_accel(sys, t, q, v, k->a0, stats, err);
}

enum mech_status mech_verlet_kernel_stage(struct mech_verlet_kernel *k,
                                          const struct mech_ode_system *sys, double t,
                                          double h, double t1, double *q, double *v,
                                          const char *name, struct mech_ode_stats *stats,
                                          struct mech_error *err)
{
    const size_t nq = k->nq;
    enum mech_status st;
    const int vfree = (sys->flags & MECH_ODE_VELOCITY_FREE) != 0;

    if (vfree) {
        if ((st = accel_memo(k, sys, t, q, v, stats, err)) != MECH_OK) return st;
        for (size_t i = 0; i < nq; i++) k->vh[i] = v[i] + 0.5 * h * k->a0[i];
    } else {
        /* Implicit half kick v+ = v + h/2 a(t, q, v+), explicit predictor. */
        if ((st = mech_ode_accel(sys, t, q, v, k->a0, stats, err)) != MECH_OK) return st;
        for (size_t i = 0; i < nq; i++) k->vh[i] = v[i] + 0.5 * h * k->a0[i];
        int converged = 0;
        double prev_diff = INFINITY;
        for (int it = 0; it < VERLET_MAX_ITER && !converged; it++) {
            if ((st = mech_ode_accel(sys, t, q, k->vh, k->a0, stats, err)) != MECH_OK) return st;
            double diff = 0.0, scale = 0.0;
            for (size_t i = 0; i < nq; i++) {
                k->vtry[i] = v[i] + 0.5 * h * k->a0[i];
                diff = fmax(diff, fabs(k->vtry[i] - k->vh[i]));
                scale = fmax(scale, fabs(k->vtry[i]));
            }
            memcpy(k->vh, k->vtry, nq * sizeof *v);
            /* Converged to round-off, or stalled at the round-off floor. */
            if (diff <= 4.0 * DBL_EPSILON * scale || diff == 0.0 ||
                (diff >= prev_diff && diff <= 1e-13 * scale))
                converged = 1;
            prev_diff = diff;
        }
        if (!converged)
            return mech_error_set(err, MECH_ENUMERIC, "integrator/dt",
                                  "%s: the implicit velocity half step does not converge at "
                                  "t = %.6g s with step %.6g s (velocity-dependent forces too "
                                  "strong for this step: reduce dt)",
                                  name, t, h);
    }
    /* Drift. */
    for (size_t i = 0; i < nq; i++) k->q1[i] = q[i] + h * k->vh[i];
    /* Second half kick, explicit in v+. */
    if ((st = mech_ode_accel(sys, t1, k->q1, k->vh, k->a1, stats, err)) != MECH_OK) return st;
    for (size_t i = 0; i < nq; i++) {
        q[i] = k->q1[i];
        v[i] = k->vh[i] + 0.5 * h * k->a1[i];
    }
    if (vfree) {
        k->memo_valid = 1;
        k->t_m = t1;
        memcpy(k->q_m, k->q1, nq * sizeof *q);
        memcpy(k->a_m, k->a1, nq * sizeof *q);
    }
    return MECH_OK;
}
