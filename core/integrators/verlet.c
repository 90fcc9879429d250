/* integrators/verlet.c — velocity (Störmer–)Verlet, fixed step, second
 * order, on libmech's stepper interface (integrator.h). Needs the system's
 * second-order form y = (q, v), v' = a(t, q, v).
 *
 * Velocity-independent forces (sys->flags & MECH_ODE_VELOCITY_FREE): the
 * classical kick-drift-kick scheme
 *   v+ = v + h/2 a(q),  q1 = q + h v+,  v1 = v+ + h/2 a(q1)
 * (L. Verlet, Phys. Rev. 159 (1967) 98; W. C. Swope et al., J. Chem. Phys. 76
 * (1982) 637), symplectic and time-symmetric: energy errors stay bounded over
 * long runs. One acceleration evaluation per step (the end-of-step value is
 * memoised for the next step).
 *
 * Velocity-dependent forces (Coriolis -2 w x v, linear drag -b v/m): the
 * symmetric generalisation with an implicit first half kick,
 *   v+ = v + h/2 a(t, q, v+)          (fixed-point iteration to round-off)
 *   q1 = q + h v+
 *   v1 = v+ + h/2 a(t + h, q1, v+)
 * which is its own adjoint (swap n <-> n+1, h -> -h), hence second order; it
 * is the Störmer–Verlet scheme for q'' = f(q, q') discussed by E. Hairer,
 * C. Lubich and G. Wanner, "Geometric numerical integration illustrated by the
 * Störmer–Verlet method", Acta Numerica 12 (2003) 399–450. In these (q, v)
 * variables it is NOT exactly symplectic for the rotating-frame Hamiltonian
 * (that would need canonical momenta p = m(v + w x q)), so the Jacobi
 * integral is conserved only to O(h^2) without the symplectic guarantee;
 * with drag the system is dissipative anyway. The fixed point converges when
 * h/2 |da/dv| < 1 (h w << 1, h b / (2m) < 1); otherwise the step fails with
 * MECH_ENUMERIC naming dt.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "integrators/integrator.h"

enum { VERLET_MAX_ITER = 60 };

struct verlet_ws {
    size_t nq;
    double *a0, *a1, *vh, *vtry, *q1; /* nq each */
    int memo_valid;                   /* memo of a(t_m, q_m) for velocity-free forces */
    double t_m;
    double *q_m, *a_m;
};

static enum mech_status verlet_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                     struct mech_error *err)
{
    (void)opt;
    if (dim == 0 || dim % 2 != 0)
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "verlet needs a state (q, v) of even dimension, got %zu", dim);
    size_t nq = dim / 2;
    struct verlet_ws *w = malloc(sizeof *w);
    double *block = malloc(7 * nq * sizeof *block);
    if (!w || !block) {
        free(w);
        free(block);
        return mech_error_set(err, MECH_ENOMEM, NULL, "verlet: out of memory");
    }
    w->nq = nq;
    w->a0 = block;
    w->a1 = block + nq;
    w->vh = block + 2 * nq;
    w->vtry = block + 3 * nq;
    w->q1 = block + 4 * nq;
    w->q_m = block + 5 * nq;
    w->a_m = block + 6 * nq;
    w->memo_valid = 0;
    w->t_m = 0.0;
    *ws = w;
    return MECH_OK;
}

static void verlet_reset(void *ws)
{
    struct verlet_ws *w = ws;
    if (w) w->memo_valid = 0;
}

static void verlet_free(void *ws)
{
    struct verlet_ws *w = ws;
    if (!w) return;
    free(w->a0);
    free(w);
}

/* a0 = a(t, q) for velocity-free forces, from the memo when (t, q) matches it exactly. */
static enum mech_status accel_memo(struct verlet_ws *w, const struct mech_ode_system *sys,
                                   double t, const double *q, const double *v,
                                   struct mech_ode_stats *stats, struct mech_error *err)
{
    const size_t nq = w->nq;
    if (w->memo_valid && w->t_m == t && memcmp(w->q_m, q, nq * sizeof *q) == 0) {
        memcpy(w->a0, w->a_m, nq * sizeof *q);
        return MECH_OK;
    }
    return mech_ode_accel(sys, t, q, v, w->a0, stats, err);
}

static enum mech_status verlet_step(void *ws, const struct mech_ode_system *sys, double t,
                                    double h, double *y, struct mech_ode_stats *stats,
                                    struct mech_error *err)
{
    struct verlet_ws *w = ws;
    const size_t nq = w->nq;
    double *q = y, *v = y + nq;
    enum mech_status st;
    const int vfree = (sys->flags & MECH_ODE_VELOCITY_FREE) != 0;

    if (vfree) {
        if ((st = accel_memo(w, sys, t, q, v, stats, err)) != MECH_OK) return st;
        for (size_t i = 0; i < nq; i++) w->vh[i] = v[i] + 0.5 * h * w->a0[i];
    } else {
        /* Implicit half kick v+ = v + h/2 a(t, q, v+), explicit predictor. */
        if ((st = mech_ode_accel(sys, t, q, v, w->a0, stats, err)) != MECH_OK) return st;
        for (size_t i = 0; i < nq; i++) w->vh[i] = v[i] + 0.5 * h * w->a0[i];
        int converged = 0;
        double prev_diff = INFINITY;
        for (int it = 0; it < VERLET_MAX_ITER && !converged; it++) {
            if ((st = mech_ode_accel(sys, t, q, w->vh, w->a0, stats, err)) != MECH_OK) return st;
            double diff = 0.0, scale = 0.0;
            for (size_t i = 0; i < nq; i++) {
                w->vtry[i] = v[i] + 0.5 * h * w->a0[i];
                diff = fmax(diff, fabs(w->vtry[i] - w->vh[i]));
                scale = fmax(scale, fabs(w->vtry[i]));
            }
            memcpy(w->vh, w->vtry, nq * sizeof *v);
            /* Converged to round-off, or stalled at the round-off floor. */
            if (diff <= 4.0 * DBL_EPSILON * scale || diff == 0.0 ||
                (diff >= prev_diff && diff <= 1e-13 * scale))
                converged = 1;
            prev_diff = diff;
        }
        if (!converged)
            return mech_error_set(err, MECH_ENUMERIC, "integrator/dt",
                                  "verlet: the implicit velocity half step does not converge at "
                                  "t = %.6g s with dt = %.6g s (velocity-dependent forces too "
                                  "strong for this step: reduce dt)",
                                  t, h);
    }
    /* Drift. */
    for (size_t i = 0; i < nq; i++) w->q1[i] = q[i] + h * w->vh[i];
    /* Second half kick, explicit in v+. */
    if ((st = mech_ode_accel(sys, t + h, w->q1, w->vh, w->a1, stats, err)) != MECH_OK) return st;
    for (size_t i = 0; i < nq; i++) {
        q[i] = w->q1[i];
        v[i] = w->vh[i] + 0.5 * h * w->a1[i];
    }
    if (vfree) {
        w->memo_valid = 1;
        w->t_m = t + h;
        memcpy(w->q_m, w->q1, nq * sizeof *q);
        memcpy(w->a_m, w->a1, nq * sizeof *q);
    }
    return MECH_OK;
}

const struct mech_integrator mech_integrator_verlet = {
    .name = "verlet",
    .order = 2,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_SYMMETRIC |
             MECH_INTEGRATOR_SECOND_ORDER,
    .doc = "Velocity (Stormer-)Verlet, fixed step dt, global error O(dt^2). With "
           "velocity-independent forces it is explicit, symplectic and time-symmetric (one "
           "force evaluation per step; energy error bounded over long runs). With Coriolis or "
           "drag the first half kick is implicit (iterated to round-off): still second order "
           "and symmetric, but not exactly symplectic in (position, velocity) variables. "
           "References: L. Verlet, Phys. Rev. 159 (1967) 98; E. Hairer, C. Lubich, G. Wanner, "
           "Acta Numerica 12 (2003) 399-450.",
    .alloc = verlet_alloc,
    .reset = verlet_reset,
    .free = verlet_free,
    .step = verlet_step,
    .evolve = NULL,
};
