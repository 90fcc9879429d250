/* integrators/integrator.h — the one stepper interface every ODE method in
 * libmech is written on (one method a file, after REBOUND's integrator_*.c and GSL's
 * ode-initval2/rk4.c).
 *
 * DESIGN
 * - One method per file (gsl_rk.c, rk4.c, verlet.c, ...). Each exports one
 *   `const struct mech_integrator` descriptor: name, order, flags, a doc
 *   string with its citation, and the operations alloc/reset/free/step and,
 *   for adaptive methods, evolve.
 * - registry.c holds the const table of every descriptor, in catalog order.
 *   Nothing registers at run time.
 * - Two operations advance the state:
 *     step   — ONE step of exactly size h from (t, y), no error control. Fixed
 *              step methods advance with it; every method also uses it for
 *              "sub-steps": re-integrating from the start of an accepted step
 *              to an off-grid time (samples, event location). A sub-step of a
 *              method of order p has local error O(h^(p+1)), so sampled values
 *              are as good as the steps themselves (no low-order interpolant).
 *     evolve — adaptive methods only: one ACCEPTED step from *t towards t1
 *              (never beyond it), retrying rejected trials internally,
 *              updating *t and the proposed next step *h.
 *   A sample inside an accepted step is interpolated instead of sub-stepped
 *   when the method hands over the step's end derivatives (step_derivs)
 *   and the interpolant's estimated error is within the tolerance (ode.c).
 *   step() must leave evolve()'s state (step-size history) untouched, so
 *   sampling never perturbs the main step sequence: results at t_end do not
 *   depend on how many samples were asked for.
 * - The state vector is y = (q, v) with q' = v, v' = accel(t, q, v) when the
 *   system provides `accel` (second-order form, needed by methods flagged
 *   MECH_INTEGRATOR_SECOND_ORDER such as Störmer–Verlet, Yoshida, Boris); the
 *   first-order right-hand side `rhs` is always provided. sys->particle_dim
 *   says how q groups into points (1..3 components, checked by the driver);
 *   step-size control that measures per body (radau15) reads it in evolve().
 * - Right-hand sides return enum mech_status: anything but MECH_OK stops the
 *   integration cleanly (a GSL stepper sees GSL_EBADFUNC) and the driver
 *   reports that status. One exception in the GSL adapters (gsl_rhs.h): a
 *   numerical failure (a non-finite derivative) on a TRIAL state of an
 *   adaptive step is a rejected trial and the step shrinks; only one at the
 *   accepted state, or one no smaller step avoids, stops the run.
 * - Statistics (steps, rejected steps, right-hand-side evaluations) are
 *   counted by the caller-owned struct mech_ode_stats passed to each call;
 *   methods count every evaluation through mech_ode_eval()/mech_ode_accel().
 * - Workspaces are per call (alloc/free), never shared between threads;
 *   descriptors are immutable and thread-safe.
 *
 * - Shared kernels: the Störmer–Verlet stage (with its implicit half kick
 *   for velocity-dependent forces) lives in verlet_kernel.h/.c and is used
 *   by verlet.c and yoshida.c; methods never copy each other's code.
 * - step() is a pure function of (t, h, y) as far as results go: a
 *   workspace may cache values (verlet_kernel's force memo, keyed bitwise on
 *   (t, q)), never carry guesses that change the answer (gauss_legendre.c
 *   restarts its stage iteration from f(t, y) at every call).
 *
 * Internal to libmech (not under core/include/): the public driver is
 * mech/ode/ode.h. Every method fills `reference`; see MECH_INTEGRATOR_* flags.
 */
#ifndef MECH_INTEGRATORS_INTEGRATOR_H
#define MECH_INTEGRATORS_INTEGRATOR_H

#include <stddef.h>

#include "mech/ode/ode.h"
#include "mech/base/status.h"

/* Descriptor flags. The catalog's "implicit" is !MECH_INTEGRATOR_EXPLICIT
 * (registry.c): a method that solves implicit equations for SOME systems
 * (verlet and yoshida* with velocity-dependent forces; gauss* always) is not
 * flagged EXPLICIT. */
#define MECH_INTEGRATOR_ADAPTIVE 0x1u     /* has evolve(); takes rtol/atol */
#define MECH_INTEGRATOR_FIXED_STEP 0x2u   /* advanced with step() and a user dt */
#define MECH_INTEGRATOR_SYMPLECTIC 0x4u   /* symplectic for velocity-free forces */
#define MECH_INTEGRATOR_SYMMETRIC 0x8u    /* time-reversible (symmetric) method */
#define MECH_INTEGRATOR_SECOND_ORDER 0x10u/* needs sys->accel (y = (q, v) layout) */
#define MECH_INTEGRATOR_EXPLICIT 0x20u    /* no implicit stage equations */
#define MECH_INTEGRATOR_KEPLER_SPLIT 0x40u/* needs sys->kepler (one central body) */

struct mech_integrator {
    const char *name;  /* stable API name: "rk8pd", "verlet", ... */
    int order;         /* global order of accuracy */
    unsigned flags;    /* MECH_INTEGRATOR_* */
    const char *doc;   /* one paragraph: what it is, when to use it, shown in catalogs */
    const char *reference; /* the citation: paper or book, equation/section */

    /* Allocate a workspace for a system of dimension dim with the given
     * options (rtol/atol for adaptive methods, dt for fixed-step ones; the
     * driver has validated them). On success *ws owns its memory (free with
     * free()). MECH_ENOMEM, MECH_EINVAL. */
    enum mech_status (*alloc)(void **ws, size_t dim, const struct mech_ode_options *opt,
                              struct mech_error *err);
    /* Forget step-size history and cached values (after a failure or before
     * a new integration). Cannot fail. */
    void (*reset)(void *ws);
    /* Free a workspace (NULL is fine). */
    void (*free)(void *ws);

    /* One step of exactly h (h may be negative or smaller than the method's
     * dt) from (t, y), overwriting y with the state at t + h. No error
     * control, no effect on evolve()'s state. On failure y is unspecified and
     * the status (the rhs's, or MECH_ENUMERIC) is returned and recorded. */
    enum mech_status (*step)(void *ws, const struct mech_ode_system *sys, double t,
                             double h, double *y, struct mech_ode_stats *stats,
                             struct mech_error *err);

    /* Adaptive methods only (NULL otherwise): one accepted step from *t
     * towards t1 (t1 > *t), proposing *h (> 0) and returning the next
     * proposal in *h. Updates *t and y; adds the rejected trials to
     * stats->rejected_steps (the driver counts accepted steps). On failure
     * the workspace must be reset. */
    enum mech_status (*evolve)(void *ws, const struct mech_ode_system *sys, double *t,
                               double t1, double *h, double *y, struct mech_ode_stats *stats,
                               struct mech_error *err);

    /* Optional (NULL otherwise), adaptive methods: the derivatives f(t, y) at
     * the start and at the end of the step the last successful evolve()
     * accepted, as that step computed them (no new evaluation). The driver
     * interpolates samples from them (dense output, ode.c). Returns 1 and
     * sets both pointers (valid until the next call on ws), or 0 when they
     * are not available. */
    int (*step_derivs)(void *ws, const double **f_start, const double **f_end);
};

/* The registry (registry.c): every method, in catalog order. */
extern const struct mech_integrator *const mech_integrator_table[];
extern const size_t mech_integrator_count;

/* Every method, in catalog order (adaptive first, then fixed step), with the
 * file that defines its descriptor mech_integrator_<name>: the one list. It
 * declares the descriptors here and fills registry.c's table, so a method is
 * added by its file and one line here. */
#define MECH_INTEGRATOR_LIST(X)                                                                 \
    X(rk8pd)                    /* gsl_rk.c */                                                  \
    X(rkck)                     /* gsl_rk.c */                                                  \
    X(rkf45)                    /* gsl_rk.c */                                                  \
    X(radau15)                  /* radau15.c */                                                 \
    X(msbdf)                    /* gsl_msbdf.c */                                               \
    X(euler)                    /* euler.c */                                                   \
    X(symplectic_euler)         /* symplectic_euler.c */                                        \
    X(rk4)                      /* rk4.c */                                                     \
    X(verlet)                   /* verlet.c */                                                  \
    X(yoshida4)                 /* yoshida.c */                                                 \
    X(yoshida6)                 /* yoshida.c */                                                 \
    X(gauss4)                   /* gauss_legendre.c */                                          \
    X(gauss6)                   /* gauss_legendre.c */                                          \
    X(boris)                    /* boris.c */                                                   \
    X(wisdom_holman)            /* wisdom_holman.c */                                           \
    X(wisdom_holman_corrected)  /* wisdom_holman.c */

#define MECH_INTEGRATOR_DECLARE(name) extern const struct mech_integrator mech_integrator_##name;
MECH_INTEGRATOR_LIST(MECH_INTEGRATOR_DECLARE)
#undef MECH_INTEGRATOR_DECLARE

/* Evaluate the first-order right-hand side, counting one evaluation and
 * checking the result is finite (MECH_ENUMERIC otherwise). */
enum mech_status mech_ode_eval(const struct mech_ode_system *sys, double t, const double *y,
                               double *dydt, struct mech_ode_stats *stats,
                               struct mech_error *err);

/* Evaluate the second-order acceleration a(t, q, v) (nq = dim/2 components),
 * counting one evaluation and checking finiteness. MECH_EINVAL when the
 * system has no accel. */
enum mech_status mech_ode_accel(const struct mech_ode_system *sys, double t, const double *q,
                                const double *v, double *a, struct mech_ode_stats *stats,
                                struct mech_error *err);

#endif
