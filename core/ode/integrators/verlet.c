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
#include <stdlib.h>

#include "ode/integrators/integrator.h"
#include "ode/integrators/verlet_kernel.h"

/* The stage itself (and its implicit half kick) lives in verlet_kernel.c,
 * shared with the Yoshida compositions. */
static enum mech_status verlet_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                     struct mech_error *err)
{
    (void)opt;
    struct mech_verlet_kernel *k = malloc(sizeof *k);
    if (!k) return mech_error_set(err, MECH_ENOMEM, NULL, "verlet: out of memory");
    enum mech_status st = mech_verlet_kernel_init(k, dim, "verlet", err);
    if (st != MECH_OK) {
        free(k);
        return st;
    }
    *ws = k;
    return MECH_OK;
}

static void verlet_reset(void *ws) { mech_verlet_kernel_reset(ws); }

static void verlet_free(void *ws)
{
    if (!ws) return;
    mech_verlet_kernel_release(ws);
    free(ws);
}

static enum mech_status verlet_step(void *ws, const struct mech_ode_system *sys, double t,
                                    double h, double *y, struct mech_ode_stats *stats,
                                    struct mech_error *err)
{
    struct mech_verlet_kernel *k = ws;
    return mech_verlet_kernel_stage(k, sys, t, h, t + h, y, y + k->nq, "verlet", stats, err);
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
           "and symmetric, but not exactly symplectic in (position, velocity) variables.",
    .reference = "L. Verlet, Phys. Rev. 159 (1967) 98-103; W. C. Swope, H. C. Andersen, "
                 "P. H. Berens, K. R. Wilson, J. Chem. Phys. 76 (1982) 637-649; E. Hairer, "
                 "C. Lubich, G. Wanner, Acta Numerica 12 (2003) 399-450.",
    .alloc = verlet_alloc,
    .reset = verlet_reset,
    .free = verlet_free,
    .step = verlet_step,
    .evolve = NULL,
};
