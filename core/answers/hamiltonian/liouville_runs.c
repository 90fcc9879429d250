/* liouville_runs.c — a Liouville comparison of up to two integrators on one
 * curve of initial conditions, the budget shared, and the reference orbit's
 * start (mech/answers/hamiltonian/liouville_runs.h). */
#include <stdlib.h>
#include <string.h>

#include "mech/answers/hamiltonian/liouville_runs.h"

void mech_liouville_reference_start(const struct mech_liouville_problem *p, double *y)
{
    const size_t dim = mech_ham_dim(p->sys);
    for (size_t i = 0; i < dim; i++)
        y[i] = 0.0;
    if (p->reference) {
        memcpy(y, p->reference, dim * sizeof *y);
    } else if (p->shape == MECH_LIOUVILLE_POLYGON || p->shape == MECH_LIOUVILLE_CLOUD) {
        for (size_t j = 0; j < p->n_vertices; j++)
            for (size_t i = 0; i < dim; i++)
                y[i] += p->vertices[j * dim + i] / (double)p->n_vertices;
    } else {
        memcpy(y, p->center, dim * sizeof *y);
    }
}

enum mech_status mech_liouville_runs(const struct mech_liouville_problem *p, size_t n_runs,
                                     const struct mech_integrator *const methods[],
                                     const struct mech_ode_options opts[],
                                     const struct mech_budget *budget,
                                     struct mech_liouville_runs *out, size_t *failed_run,
                                     struct mech_error *err)
{
    memset(out, 0, sizeof *out);
    *failed_run = 0;
    if (n_runs < 1 || n_runs > MECH_LIOUVILLE_MAX_RUNS)
        return mech_error_set(err, MECH_EINVAL, "integrators",
                              "one or two integrators are compared, got %zu", n_runs);
    const size_t ns = p->n_samples, dim = mech_ham_dim(p->sys);
    const size_t per = 6 * ns + ns * dim;
    out->buf = malloc(n_runs * per * sizeof *out->buf);
    if (!out->buf) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    out->n_runs = n_runs;
    struct mech_liouville_problem q = *p;
    for (size_t k = 0; k < n_runs; k++) {
        double *b = out->buf + k * per;
        struct mech_liouville_result *r = &out->run[k];
        r->t = b;
        r->area = b + ns;
        r->area_bound = b + 2 * ns;
        r->vertex_area = b + 3 * ns;
        r->det = b + 4 * ns;
        r->symplectic_defect = b + 5 * ns;
        r->reference_y = b + 6 * ns;
        q.method = methods[k];
        q.opt = opts[k];
        struct mech_budget bud = *budget;
        if (k > 0) bud.max_steps -= out->run[0].stats.steps;
        const enum mech_status st = mech_liouville_run(&q, &bud, r, err);
        if (st != MECH_OK) {
            *failed_run = k;
            return st;
        }
    }
    return MECH_OK;
}

void mech_liouville_runs_free(struct mech_liouville_runs *r)
{
    free(r->buf);
    memset(r, 0, sizeof *r);
}
