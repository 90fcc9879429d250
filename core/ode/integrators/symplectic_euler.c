/* integrators/symplectic_euler.c — the symplectic Euler method (kick, then
 * drift), fixed step, first order, on libmech's stepper interface
 * (integrator.h). Needs the second-order form y = (q, v), v' = a(t, q, v).
 *
 * Velocity-independent forces: the standard kick-then-drift scheme
 *   v1 = v + h a(t, q),   q1 = q + h v1
 * which is the symplectic Euler method p_{n+1} = p_n - h H_q(p_{n+1}, q_n),
 * q_{n+1} = q_n + h H_p(p_{n+1}, q_n) for H = p^2/2 + V(q) (E. Hairer,
 * C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed., Springer
 * 2006, eq. (I.1.9) and Theorem VI.3.3, after R. de Vogelaere 1956; also
 * known as Euler–Cromer, A. Cromer, Am. J. Phys. 49 (1981) 455). First order,
 * not symmetric, but symplectic: it conserves a modified energy, so the
 * energy error stays bounded (O(h)) instead of growing as in explicit Euler.
 *
 * Velocity-dependent forces (Coriolis, drag): the kick uses the velocity at
 * the start of the step, v1 = v + h a(t, q, v), then q1 = q + h v1 — still
 * explicit and first order (the Euler–Cromer form), but no longer symplectic
 * (no method in (q, v) variables is, for Coriolis; use boris or verlet for
 * those). This keeps the teaching baseline one force evaluation per step.
 */
#include <stdlib.h>

#include "ode/integrators/integrator.h"

struct symp_euler_ws {
    size_t nq;
    double *a; /* nq */
};

static enum mech_status symplectic_euler_alloc(void **ws, size_t dim,
                                               const struct mech_ode_options *opt,
                                               struct mech_error *err)
{
    (void)opt;
    if (dim == 0 || dim % 2 != 0)
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "symplectic_euler needs a state (q, v) of even dimension, got %zu",
                              dim);
    struct symp_euler_ws *w = malloc(sizeof *w);
    double *a = malloc(dim / 2 * sizeof *a);
    if (!w || !a) {
        free(w);
        free(a);
        return mech_error_set(err, MECH_ENOMEM, NULL, "symplectic_euler: out of memory");
    }
    w->nq = dim / 2;
    w->a = a;
    *ws = w;
    return MECH_OK;
}

static void symplectic_euler_reset(void *ws) { (void)ws; /* stateless between steps */ }

static void symplectic_euler_free(void *ws)
{
    struct symp_euler_ws *w = ws;
    if (!w) return;
    free(w->a);
    free(w);
}

static enum mech_status symplectic_euler_step(void *ws, const struct mech_ode_system *sys,
                                              double t, double h, double *y,
                                              struct mech_ode_stats *stats,
                                              struct mech_error *err)
{
    struct symp_euler_ws *w = ws;
    const size_t nq = w->nq;
    double *q = y, *v = y + nq;
    enum mech_status st = mech_ode_accel(sys, t, q, v, w->a, stats, err);
    if (st != MECH_OK) return st;
    /* GNI eq. (I.1.9): kick with the force at q_n, then drift with v_{n+1}. */
    for (size_t i = 0; i < nq; i++) {
        v[i] += h * w->a[i];
        q[i] += h * v[i];
    }
    return MECH_OK;
}

const struct mech_integrator mech_integrator_symplectic_euler = {
    .name = "symplectic_euler",
    .order = 1,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_EXPLICIT | MECH_INTEGRATOR_SYMPLECTIC |
             MECH_INTEGRATOR_SECOND_ORDER,
    .doc = "Symplectic Euler (kick v += dt a(t, q, v), then drift q += dt v), fixed step dt, one "
           "force evaluation per step, global error O(dt). A teaching baseline: as cheap as "
           "explicit Euler, but for velocity-independent forces it is symplectic, so its energy "
           "error stays bounded (of order dt) over long runs instead of growing. With Coriolis "
           "or drag the kick uses the start-of-step velocity (explicit, first order, not "
           "symplectic): prefer boris or verlet there.",
    .reference = "E. Hairer, C. Lubich, G. Wanner, Geometric Numerical Integration, 2nd ed. "
                 "(Springer, 2006), eq. (I.1.9) and Theorem VI.3.3 (R. de Vogelaere, 1956); "
                 "A. Cromer, Am. J. Phys. 49 (1981) 455-459.",
    .alloc = symplectic_euler_alloc,
    .reset = symplectic_euler_reset,
    .free = symplectic_euler_free,
    .step = symplectic_euler_step,
    .evolve = NULL,
};
