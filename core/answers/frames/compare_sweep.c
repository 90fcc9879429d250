/* compare_sweep.c — one scene run with several integrator settings against
 * one reference, in one shared budget (mech/answers/frames/compare_sweep.h): what
 * POST /v1/compare computes; the handler parses and encodes. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mech/frames/closed_form.h"
#include "mech/answers/frames/compare_sweep.h"
#include "mech/frames/reference.h"

static double max2(double a, double b)
{
    return a > b ? a : b;
}

/* The run's sample buffers and its stop point. */
struct run_out {
    struct mech_vec3 *pos, *vel;
    struct mech_trajectory_result r;
};

/* Run one configuration into o (samples into o->pos, o->vel); cpu: its time. */
static enum mech_status run_one(const struct mech_trajectory_problem *p, int closed_form,
                                const struct mech_budget *b, struct run_out *o,
                                struct mech_error *e, double *cpu)
{
    memset(&o->r, 0, sizeof o->r);
    o->r.position = o->pos;
    o->r.velocity = o->vel;
    mech_error_clear(e);
    struct mech_closed_form_evidence evidence;
    double c0 = mech_cpu_seconds();
    /* a row that selects by accuracy on a scene with a closed form is answered
     * from it, as /v1/trajectory would (0 steps) */
    enum mech_status st = closed_form ? mech_trajectory_closed_form_ex(p, &o->r, &evidence, b, e)
                                      : mech_trajectory_integrate(p, b, &o->r, e);
    *cpu = mech_cpu_seconds() - c0;
    return st;
}

/* The errors of run o against the reference run ref, over their common
 * samples and, when both stopped, the stop points. */
static void errors_against_run(const struct run_out *o, const struct run_out *ref,
                               struct mech_compare_row *row)
{
    const struct mech_trajectory_result *r = &o->r, *rr = &ref->r;
    size_t m = r->n_samples < rr->n_samples ? r->n_samples : rr->n_samples;
    double emax = 0, efin = 0, evmax = 0, rmax = 0, vmax = 0;
    for (size_t i = 0; i <= m; i++) {
        struct mech_vec3 a, av, b0, bv;
        if (i < m) {
            a = o->pos[i], av = o->vel[i], b0 = ref->pos[i], bv = ref->vel[i];
        } else if (r->stopped && rr->stopped) {
            a = r->stop_position, av = r->stop_velocity;
            b0 = rr->stop_position, bv = rr->stop_velocity;
        } else {
            break;
        }
        efin = mech_vec3_norm(mech_vec3_sub(a, b0));
        emax = max2(emax, efin);
        evmax = max2(evmax, mech_vec3_norm(mech_vec3_sub(av, bv)));
        rmax = max2(rmax, mech_vec3_norm(b0));
        vmax = max2(vmax, mech_vec3_norm(bv));
    }
    row->max_position_error = emax;
    row->final_position_error = efin;
    row->max_velocity_error = evmax;
    row->max_relative_position_error = rmax > 0 ? emax / rmax : 0;
    row->max_relative_velocity_error = vmax > 0 ? evmax / vmax : 0;
}

/* Fill a finished run's row (state RUN_OK). */
static void row_ok(const struct run_out *o, const struct run_out *ref, int exact,
                   struct mech_compare_row *row)
{
    const struct mech_trajectory_result *r = &o->r;
    row->state = MECH_COMPARE_RUN_OK;
    if (exact) {
        row->max_position_error = r->reference.max_position_error;
        row->final_position_error = r->reference.final_position_error;
        row->max_velocity_error = r->reference.max_velocity_error;
        row->max_relative_position_error = r->reference.max_relative_position_error;
        row->max_relative_velocity_error = r->reference.max_relative_velocity_error;
    } else {
        errors_against_run(o, ref, row);
    }
    row->n_invariants = r->n_invariants;
    memcpy(row->invariants, r->invariants, sizeof row->invariants);
    row->stats = r->stats;
}

/* The reference: the exact solution's name, or the radau15 run into ref. */
static enum mech_status reference_run(const struct mech_trajectory_problem *base,
                                      const struct mech_budget *budget, struct run_out *ref,
                                      struct mech_compare_result *out, struct mech_error *e)
{
    struct mech_trajectory_reference exact;
    if (mech_trajectory_reference_find(base, &exact) == MECH_REFERENCE_EXACT) {
        out->reference_exact = 1;
        out->reference_name = exact.name;
        return MECH_OK;
    }
    struct mech_trajectory_problem p = *base;
    p.method = MECH_COMPARE_REFERENCE_METHOD;
    p.opt.rtol = MECH_COMPARE_REFERENCE_RTOL;
    p.opt.atol = 0;
    struct mech_budget b = *budget;
    double cpu = 0.0;
    enum mech_status st = run_one(&p, 0, &b, ref, e, &cpu);
    if (st != MECH_OK) {
        out->failed_run = -1;
        out->total_steps = e->progress.steps;
        return st;
    }
    out->total_steps = ref->r.total_steps;
    out->reference_name = MECH_COMPARE_REFERENCE_METHOD;
    out->reference_stats = ref->r.stats;
    out->reference_cpu_seconds = cpu;
    return MECH_OK;
}

/* Run k's status as the sweep treats it: 1 a row failure (kept as a row). */
static int is_row_failure(enum mech_status st, const struct mech_error *e)
{
    return st == MECH_ENUMERIC ||
           ((st == MECH_EINVAL || st == MECH_EDOMAIN) && !strncmp(e->param, "integrator", 10));
}

/* Runs k (stopped: status st, e, cpu) and every later one are not run. */
static void mark_not_run(struct mech_compare_row *rows, size_t k, size_t n, enum mech_status st,
                         const struct mech_error *e, double cpu)
{
    rows[k].state = MECH_COMPARE_RUN_NOT_RUN;
    rows[k].status = st;
    rows[k].err = *e;
    rows[k].cpu_seconds = cpu;
    for (size_t j = k + 1; j < n; j++) {
        rows[j].state = MECH_COMPARE_RUN_NOT_RUN;
        rows[j].status = st;
        mech_error_clear(&rows[j].err);
    }
}

/* Run every configuration after the reference (buffers ready). */
static enum mech_status run_all(const struct mech_compare_config *runs, size_t n,
                                const struct mech_budget *budget, struct run_out *o,
                                const struct run_out *ref, struct mech_compare_row *rows,
                                struct mech_compare_result *out, struct mech_error *err)
{
    size_t finished = 0;
    for (size_t k = 0; k < n; k++) {
        struct mech_compare_row *row = &rows[k];
        struct mech_error e;
        struct mech_budget b = *budget;
        b.max_steps = budget->max_steps - out->total_steps;
        double cpu = 0.0;
        enum mech_status st;
        if (b.max_steps <= 0) {
            mech_error_clear(&e);
            st = mech_error_set(&e, MECH_EBUDGET, NULL,
                                "no steps left of the shared budget of %ld steps",
                                budget->max_steps);
            e.progress.steps = 0;
        } else {
            st = run_one(runs[k].p, runs[k].closed_form, &b, o, &e, &cpu);
        }
        if (st == MECH_OK)
            out->total_steps += o->r.total_steps;
        else if (e.progress.steps > 0)
            out->total_steps += e.progress.steps;
        const int out_of_budget = st == MECH_EBUDGET || st == MECH_EDEADLINE;
        if (st != MECH_OK && !is_row_failure(st, &e) && !(out_of_budget && finished > 0)) {
            out->failed_run = (long)k;
            if (err) *err = e;
            return st;
        }
        if (out_of_budget) { /* keep the finished runs */
            mark_not_run(rows, k, n, st, &e, cpu);
            out->partial = 1;
            out->stopped_run = k;
            return MECH_OK;
        }
        finished++;
        row->status = st;
        if (st != MECH_OK) {
            row->state = MECH_COMPARE_RUN_FAILED;
            row->err = e;
        } else {
            row_ok(o, ref, out->reference_exact, row);
            row->cpu_seconds = cpu;
        }
    }
    return MECH_OK;
}

enum mech_status mech_compare_sweep(const struct mech_trajectory_problem *base,
                                    const struct mech_compare_config *runs, size_t n,
                                    const struct mech_budget *budget, struct mech_compare_row *rows,
                                    struct mech_compare_result *out, struct mech_error *err)
{
    memset(out, 0, sizeof *out);
    out->reference_cpu_seconds = -1.0;
    out->failed_run = -2;
    if (n > MECH_COMPARE_MAX_RUNS)
        return mech_error_set(err, MECH_EINVAL, "runs", "%zu runs; at most %d are allowed", n,
                              MECH_COMPARE_MAX_RUNS);
    memset(rows, 0, n * sizeof *rows);
    const size_t ns = base->samples;
    if (ns > SIZE_MAX / (4 * sizeof(struct mech_vec3)))
        return mech_error_set(err, MECH_EINVAL, "samples", "%zu samples cannot be stored", ns);
    struct mech_vec3 *buf = malloc(4 * ns * sizeof *buf);
    if (!buf) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", ns);
    struct run_out ref = {.pos = buf, .vel = buf + ns},
                   o = {.pos = buf + 2 * ns, .vel = buf + 3 * ns};
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = reference_run(base, budget, &ref, out, &e);
    if (st != MECH_OK) {
        if (err) *err = e;
    } else {
        st = run_all(runs, n, budget, &o, &ref, rows, out, err);
    }
    free(buf);
    return st;
}
