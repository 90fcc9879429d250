/* integrators/verlet_kernel.h — the one Störmer–Verlet step shared by
 * verlet.c (one stage per step) and yoshida.c (compositions of 3 or 7
 * stages), internal to libmech.
 *
 * A stage advances (q, v) from t to t1 = t + h (the caller passes t1 so that
 * composed stages end exactly where the next one starts, which keeps the
 * force memo below effective):
 *
 *   velocity-free forces (sys->flags & MECH_ODE_VELOCITY_FREE), kick-drift-kick
 *     v+ = v + h/2 a(t, q),  q1 = q + h v+,  v1 = v+ + h/2 a(t1, q1);
 *   velocity-dependent forces (Coriolis, drag), the symmetric variant with an
 *   implicit first half kick (E. Hairer, C. Lubich, G. Wanner, Acta Numerica
 *   12 (2003) 399-450, Sect. 1.4 / 2.6 on q'' = f(q, q')):
 *     v+ = v + h/2 a(t, q, v+)   (fixed-point iteration to round-off)
 *     q1 = q + h v+,  v1 = v+ + h/2 a(t1, q1, v+).
 *
 * Memo: for velocity-free forces the end-of-stage force a(t1, q1) is kept and
 * reused when the next stage starts at exactly (t1, q1) (bitwise compare), so
 * a composition of s stages costs s force evaluations per step. The memo is a
 * pure cache: a(t, q) is a function of its arguments, so results never
 * depend on it (step() stays history-free, as integrator.h requires).
 */
#ifndef MECH_INTEGRATORS_VERLET_KERNEL_H
#define MECH_INTEGRATORS_VERLET_KERNEL_H

#include <stddef.h>

#include "ode/integrators/integrator.h"

struct mech_verlet_kernel {
    size_t nq;                        /* dim / 2 */
    double *a0, *a1, *vh, *vtry, *q1; /* nq each: scratch */
    int memo_valid;                   /* memo of a(t_m, q_m), velocity-free forces only */
    double t_m;
    double *q_m, *a_m;
};

/* Allocate the scratch of a kernel for a state (q, v) of dimension dim
 * (even, > 0). `name` is the method's name for messages. MECH_EINVAL (odd or
 * zero dim), MECH_ENOMEM. On failure nothing is held. */
enum mech_status mech_verlet_kernel_init(struct mech_verlet_kernel *k, size_t dim,
                                         const char *name, struct mech_error *err);
/* Free the scratch (safe on a zeroed or failed kernel). */
void mech_verlet_kernel_release(struct mech_verlet_kernel *k);
/* Forget the memo. Cannot fail. */
void mech_verlet_kernel_reset(struct mech_verlet_kernel *k);

/* One Störmer–Verlet stage of size h from (t, q, v) to t1 (= t + h as the
 * caller computes it), in place. Statuses: MECH_OK; the acceleration's
 * status; MECH_ENUMERIC (non-finite force, or the implicit half kick not
 * converging: param "integrator/dt", message naming t and h). */
enum mech_status mech_verlet_kernel_stage(struct mech_verlet_kernel *k,
                                          const struct mech_ode_system *sys, double t,
                                          double h, double t1, double *q, double *v,
                                          const char *name, struct mech_ode_stats *stats,
                                          struct mech_error *err);

#endif
