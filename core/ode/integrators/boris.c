/* integrators/boris.c — the Boris pusher for forces of the form
 * a(t, q, v) = e(t, q) + v x w(t, q) (a magnetic field, w = qB/m, or the
 * Coriolis force, w = 2 W, with centrifugal and other position forces in e),
 * fixed step, second order, on libmech's stepper interface (integrator.h).
 *
 * Reference: J. P. Boris, "Relativistic plasma simulation — optimization of a
 * hybrid code", Proc. Fourth Conf. Numerical Simulation of Plasmas, NRL,
 * Washington DC (1970) 3-67; C. K. Birdsall, A. B. Langdon, Plasma Physics via
 * Computer Simulation (McGraw-Hill 1985), Sect. 4-3 and 4-4; H. Qin et al.,
 * Phys. Plasmas 20 (2013) 084503 (volume preservation); E. Hairer, C. Lubich,
 * BIT Numer. Math. 58 (2018) 969-979 (symmetry, energy behaviour).
 *
 * One step, in the one-step drift-kick-drift form with q and v at the same
 * time (the leapfrog form staggers them):
 *   qh = q + h/2 v,  e = e(t + h/2, qh),  w = w(t + h/2, qh)
 *   v- = v + h/2 e                                   (half kick)
 *   tv = w h/2,  sv = 2 tv / (1 + |tv|^2)
 *   v' = v- + v- x tv,  v+ = v- + v' x sv            (rotation)
 *   v1 = v+ + h/2 e                                  (half kick)
 *   q1 = qh + h/2 v1
 * The rotation solves v+ - v- = h/2 (v+ + v-) x w exactly (a Cayley
 * transform): |v+| = |v-|, and the angle is 2 atan(|w| h / 2) instead of the
 * exact |w| h, so a pure gyration keeps its speed and its radius |v|/|w| to
 * round-off and errs only in phase. The map is symmetric (h -> -h inverts
 * it), hence second order, and volume-preserving; one (e, w) evaluation per
 * step. It is explicit even though the force depends on v, which is why it
 * is preferred over verlet's implicit half kick for Coriolis and magnetic
 * forces.
 *
 * Needs sys->lorentz (mech/ode/ode.h). Linear drag (-b v / m) is not of the form
 * v x w and has no Boris step: such a system leaves lorentz NULL and the
 * step fails with MECH_EINVAL (param "integrator/method"). A system whose
 * forces do not depend on v at all (MECH_ODE_VELOCITY_FREE) and gives no
 * lorentz split is run with e = a(t, q), w = 0, which is exactly the Boris
 * step with no rotating part (the drift-kick-drift leapfrog).
 */
#include <math.h>
#include <stdlib.h>

#include "ode/integrators/integrator.h"

struct boris_ws {
    size_t nq;
    double *qh, *e, *w; /* nq each */
};

static enum mech_status boris_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                    struct mech_error *err)
{
    (void)opt;
    if (dim == 0 || dim % 2 != 0)
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "boris needs a state (q, v) of even dimension, got %zu", dim);
    size_t nq = dim / 2;
    struct boris_ws *b = malloc(sizeof *b);
    double *block = malloc(3 * nq * sizeof *block);
    if (!b || !block) {
        free(b);
        free(block);
        return mech_error_set(err, MECH_ENOMEM, NULL, "boris: out of memory");
    }
    b->nq = nq;
    b->qh = block;
    b->e = block + nq;
    b->w = block + 2 * nq;
    *ws = b;
    return MECH_OK;
}

static void boris_reset(void *ws) { (void)ws; /* stateless between steps */ }

static void boris_free(void *ws)
{
    struct boris_ws *b = ws;
    if (!b) return;
    free(b->qh);
    free(b);
}

/* e, w at (t, q), counted as one right-hand-side evaluation, checked finite. */
static enum mech_status boris_fields(struct boris_ws *b, const struct mech_ode_system *sys,
                                     double t, const double *q, const double *v,
                                     struct mech_ode_stats *stats, struct mech_error *err)
{
    const size_t nq = b->nq;
    if (!sys->lorentz) {
        /* velocity-free forces: e = a(t, q), w = 0 */
        for (size_t i = 0; i < nq; i++) b->w[i] = 0.0;
        return mech_ode_accel(sys, t, q, v, b->e, stats, err);
    }
    if (stats) stats->rhs_evaluations++;
    enum mech_status st = sys->lorentz(t, q, b->e, b->w, sys->params);
    if (st != MECH_OK)
        return mech_error_set(err, st, NULL, "the force field failed at t = %.9g s", t);
    for (size_t i = 0; i < nq; i++)
        if (!isfinite(b->e[i]) || !isfinite(b->w[i]))
            return mech_error_set(err, MECH_ENUMERIC, NULL,
                                  "non-finite force field at t = %.9g s", t);
    return MECH_OK;
}

static enum mech_status boris_step(void *ws, const struct mech_ode_system *sys, double t, double h,
                                   double *y, struct mech_ode_stats *stats, struct mech_error *err)
{
    struct boris_ws *b = ws;
    const size_t nq = b->nq;
    double *q = y, *v = y + nq;
    if (!sys->lorentz && !(sys->flags & MECH_ODE_VELOCITY_FREE))
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "boris needs forces whose velocity dependence is magnetic-like "
                              "(v x w: Coriolis, a magnetic field), not drag; use verlet, "
                              "gauss6 or an adaptive method");
    if (sys->lorentz && nq % 3 != 0)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "boris needs 3-vectors (q, v per particle), got %zu position "
                              "components",
                              nq);
    /* Drift h/2 (Birdsall & Langdon Sect. 4-3, in drift-kick-drift form). */
    for (size_t i = 0; i < nq; i++) b->qh[i] = q[i] + 0.5 * h * v[i];
    enum mech_status st = boris_fields(b, sys, t + 0.5 * h, b->qh, v, stats, err);
    if (st != MECH_OK) return st;
    if (sys->lorentz) {
        for (size_t p = 0; p < nq; p += 3) {
            const double *e = b->e + p, *w = b->w + p;
            double *vp = v + p;
            /* half kick */
            double vm[3] = {vp[0] + 0.5 * h * e[0], vp[1] + 0.5 * h * e[1],
                            vp[2] + 0.5 * h * e[2]};
            /* rotation (Boris 1970; Birdsall & Langdon Sect. 4-4) */
            double tv[3] = {0.5 * h * w[0], 0.5 * h * w[1], 0.5 * h * w[2]};
            double t2 = tv[0] * tv[0] + tv[1] * tv[1] + tv[2] * tv[2];
            double sv[3] = {2.0 * tv[0] / (1.0 + t2), 2.0 * tv[1] / (1.0 + t2),
                            2.0 * tv[2] / (1.0 + t2)};
            double v1[3] = {vm[0] + vm[1] * tv[2] - vm[2] * tv[1],
                            vm[1] + vm[2] * tv[0] - vm[0] * tv[2],
                            vm[2] + vm[0] * tv[1] - vm[1] * tv[0]};
            double vpl[3] = {vm[0] + v1[1] * sv[2] - v1[2] * sv[1],
                             vm[1] + v1[2] * sv[0] - v1[0] * sv[2],
                             vm[2] + v1[0] * sv[1] - v1[1] * sv[0]};
            /* half kick */
            for (int c = 0; c < 3; c++) vp[c] = vpl[c] + 0.5 * h * e[c];
        }
    } else {
        for (size_t i = 0; i < nq; i++) v[i] += h * b->e[i];
    }
    /* Drift h/2 with the new velocity. */
    for (size_t i = 0; i < nq; i++) q[i] = b->qh[i] + 0.5 * h * v[i];
    return MECH_OK;
}

const struct mech_integrator mech_integrator_boris = {
    .name = "boris",
    .order = 2,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_EXPLICIT | MECH_INTEGRATOR_SYMMETRIC |
             MECH_INTEGRATOR_SECOND_ORDER,
    .doc = "Boris pusher for velocity-dependent forces of the form e(q) + v x w(q) (Coriolis "
           "with centrifugal and other position forces, or a magnetic field): half kick with "
           "e, exact-length rotation of v about w, half kick, in a drift-kick-drift step. "
           "Fixed step dt, explicit, one force evaluation per step, global error O(dt^2), "
           "time-symmetric and volume-preserving; a pure gyration keeps speed and radius to "
           "round-off (its phase advances by 2 atan(|w| dt/2) per step instead of |w| dt). "
           "Not for drag (not of the form v x w).",
    .reference = "J. P. Boris, Proc. Fourth Conf. Numerical Simulation of Plasmas, NRL (1970) "
                 "3-67; C. K. Birdsall, A. B. Langdon, Plasma Physics via Computer Simulation "
                 "(McGraw-Hill, 1985), Sects. 4-3, 4-4; H. Qin et al., Phys. Plasmas 20 (2013) "
                 "084503.",
    .alloc = boris_alloc,
    .reset = boris_reset,
    .free = boris_free,
    .step = boris_step,
    .evolve = NULL,
};
