/* mech/answers/hamiltonian/liouville_runs.h — one Liouville comparison: the same closed curve
 * (or cloud) of initial conditions carried by up to two integrators in turn
 * (mech_liouville_run), a symplectic one beside a non-symplectic one, within
 * one step budget; and the start of the reference orbit the tangent map
 * follows. Thread-safe; allocates the runs' sample arrays
 * (mech_liouville_runs_free). */
#ifndef MECH_LIOUVILLE_RUNS_H
#define MECH_LIOUVILLE_RUNS_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/hamiltonian/liouville.h"

#define MECH_LIOUVILLE_MAX_RUNS 2

struct mech_liouville_runs {
    size_t n_runs;
    /* run k: t, area, area_bound, vertex_area, det, symplectic_defect
     * (n_samples each) and reference_y (n_samples * dim), owned */
    struct mech_liouville_result run[MECH_LIOUVILLE_MAX_RUNS];
    double *buf; /* the one block behind every array */
};

/* The reference orbit's start (dim = 2 dof values, SI): p->reference when
 * given, else the mean of the vertices (polygon, cloud) or the centre
 * (ellipse). Never fails; p's arrays as mech_liouville_run documents. */
void mech_liouville_reference_start(const struct mech_liouville_problem *p, double *y);

/* Run p with methods[k] and opts[k] for k < n_runs (1 or 2; p's own method and
 * opt are ignored); run 1 gets the budget's steps less those of run 0.
 * Statuses: MECH_OK; MECH_EINVAL "integrators" for n_runs outside 1..2;
 * MECH_ENOMEM; the statuses of mech_liouville_run, with *failed_run the run
 * that failed (0 otherwise). out is always initialised (safe to free).
 * err may be NULL. */
enum mech_status mech_liouville_runs(const struct mech_liouville_problem *p, size_t n_runs,
                                     const struct mech_integrator *const methods[],
                                     const struct mech_ode_options opts[],
                                     const struct mech_budget *budget,
                                     struct mech_liouville_runs *out, size_t *failed_run,
                                     struct mech_error *err);

void mech_liouville_runs_free(struct mech_liouville_runs *r);

#endif
