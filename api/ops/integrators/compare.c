/* compare.c — POST /v1/compare: run one /v1/trajectory scene with several
 * integrator settings and answer, per run, the error against the best
 * reference available, the drift of the conserved quantities, the steps,
 * right-hand-side evaluations and CPU time: the data of a work-precision plot
 * for the user's own scene.
 *
 * Reference: the scene's exact solution when it has one, otherwise a radau15
 * run at its round-off setting (mech/answers/frames/compare_sweep.h, which runs the sweep:
 * this file reads the request, calls mech_compare_sweep once and encodes).
 *
 * CPU time: cost.runs[i].cpu_seconds for row i (and cost.reference_cpu_seconds),
 * only under the top-level cost block, which the framework drops for
 * "cost": false: everything else is deterministic.
 *
 * Budget: ONE step budget and deadline (the request's) shared by the
 * reference run and all runs in order; each run gets what the previous ones
 * left. When a run exhausts it, the runs that finished are kept: the answer
 * is 200 with "partial": true, the run that was stopped and every later one
 * being a row {"status": "not_run", "reason": ...} (the stopped one with its
 * progress). Such an answer depends on the load, so it is marked never to be
 * cached (call->depends_on_load). Only when no run finished, or the reference run
 * itself ran out, is it compute-budget-exceeded (422) naming the run, with
 * the steps the whole request took. A run that fails numerically (an
 * unstable step, a dt that does not resolve a close approach) or whose method
 * does not apply to the scene (boris with drag) is kept as a row with
 * "status": "failed" and the reason.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/answers/frames/compare_sweep.h"
#include "mech/frames/trajectory.h"
#include "request/trajectory_request.h"

#define COMPARE_MAX_RUNS MECH_COMPARE_MAX_RUNS

struct run_spec {
    const json_t *block; /* borrowed from the body or owned by `owned` */
    char pointer[48];
};

/* The runs as requested: a list, or a sweep's blocks built into `owned`. */
struct run_list {
    struct run_spec specs[COMPARE_MAX_RUNS];
    size_t n;
    json_t *owned;
};

/* Fail the whole request for run k (or the reference run, k < 0). */
static json_t *fail_run(struct api_call *c, enum mech_status st, const struct mech_error *e, long k,
                        const char *pointer, long total_steps)
{
    struct mech_error e2 = *e;
    /* Parameters of the integrator block belong to the run, others to the
     * request (a scene error is the same for every run: no run named). */
    const char *prefix = "/request";
    const int scene_error =
        (st == MECH_EINVAL || st == MECH_EDOMAIN) && strncmp(e->param, "integrator/", 11) != 0;
    if (!scene_error && k >= 0) {
        snprintf(e2.text, sizeof e2.text, "run %ld (%s): %.150s", k, pointer, e->text);
        if (!strncmp(e->param, "integrator/", 11)) {
            snprintf(e2.param, sizeof e2.param, "%s", e->param + 11);
            prefix = pointer;
        }
    } else if (!scene_error) {
        snprintf(e2.text, sizeof e2.text, "reference run: %.170s", e->text);
    }
    api_call_fail_core(c, st, &e2, prefix);
    if (st == MECH_EBUDGET || st == MECH_EDEADLINE) {
        if (!c->extra) c->extra = json_object();
        if (c->extra && k >= 0) json_object_set_new_nocheck(c->extra, "run", json_string(pointer));
        /* progress.steps: every step of the request (the reference and the
         * runs before this one too), not only those of the run that stopped,
         * which may be 0 when the deadline had passed as it started. */
        json_t *prog = c->extra ? json_object_get(c->extra, "progress") : NULL;
        if (prog) {
            json_object_set_new_nocheck(prog, "run_steps", json_integer(e->progress.steps));
            json_object_set_new_nocheck(prog, "steps", json_integer(total_steps));
        }
    }
    return NULL;
}

/* The reason a run was not run to its end, into buf: the budget that ran out
 * during run k (its pointer); stop_text: the core's words when run k is the
 * one described, NULL for a later run. */
static void not_run_reason(char *buf, size_t n, enum mech_status st, const struct api_call *c,
                           size_t k, const char *pointer, const char *stop_text)
{
    char what[96];
    if (st == MECH_EDEADLINE)
        snprintf(what, sizeof what, "the request's deadline passed");
    else
        snprintf(what, sizeof what, "the shared step budget of %ld steps ran out",
                 c->budget.max_steps);
    if (stop_text)
        snprintf(buf, n, "stopped: %s during this run (%.150s)", what, stop_text);
    else
        snprintf(buf, n, "not started: %s during run %zu (%s)", what, k, pointer);
}

/* "runs": each block as given, at /runs/i. */
static void list_from_runs(const json_t *runs, struct run_list *L)
{
    for (size_t i = 0; i < json_array_size(runs) && L->n < COMPARE_MAX_RUNS; i++, L->n++) {
        L->specs[L->n].block = json_array_get(runs, i);
        snprintf(L->specs[L->n].pointer, sizeof L->specs[L->n].pointer, "/runs/%zu", i);
    }
}

/* The list a sweep method takes its values from (NULL: not given). */
static const json_t *sweep_values(const json_t *sweep, const char *m, int *adaptive)
{
    *adaptive = mech_ode_method_describe(mech_ode_method_find(m)).adaptive;
    return json_object_get(sweep, *adaptive ? "tolerances" : "dts");
}

/* The number of runs a sweep makes, after checking every method has its
 * values; 0 after recording an error. */
static size_t sweep_count(struct api_call *c, const json_t *sweep)
{
    const json_t *ms = json_object_get(sweep, "methods");
    size_t need = 0;
    for (size_t i = 0; i < json_array_size(ms); i++) {
        const char *m = json_string_value(json_array_get(ms, i));
        int adaptive;
        const json_t *list = sweep_values(sweep, m, &adaptive);
        if (!list) {
            api_call_invalid(c, adaptive ? "/sweep/tolerances" : "/sweep/dts", "method %s needs %s",
                             m, adaptive ? "tolerances (its rtol values)" : "dts (its steps)");
            return 0;
        }
        need += json_array_size(list);
    }
    if (need > COMPARE_MAX_RUNS) {
        api_call_invalid(c, "/sweep", "the sweep makes %zu runs; at most %d are allowed", need,
                         COMPARE_MAX_RUNS);
        return 0;
    }
    return need;
}

/* "sweep": one block per method and value, atol = rtol x the scene's scale
 * as mech_trajectory_choose() sets it. Returns 0 after recording an error. */
static int list_from_sweep(struct api_call *c, const json_t *sweep,
                           const struct api_traj_request *base, struct run_list *L)
{
    if (!sweep_count(c, sweep)) return 0;
    struct mech_trajectory_choice ch;
    double scale = 1.0;
    if (mech_trajectory_choose(&base->p, 1e-8, &ch, NULL) == MECH_OK) scale = ch.profile.scale;
    const json_t *ms = json_object_get(sweep, "methods");
    for (size_t i = 0; i < json_array_size(ms); i++) {
        const char *m = json_string_value(json_array_get(ms, i));
        int adaptive;
        const json_t *list = sweep_values(sweep, m, &adaptive);
        for (size_t j = 0; j < json_array_size(list); j++, L->n++) {
            double x = json_number_value(json_array_get(list, j));
            json_t *blk =
                adaptive ? json_pack("{s:s,s:f,s:f}", "method", m, "rtol", x, "atol", x * scale)
                         : json_pack("{s:s,s:f}", "method", m, "dt", x);
            if (!blk || json_array_append_new(L->owned, blk)) {
                api_call_fail_core(c, MECH_ENOMEM, NULL, "");
                return 0;
            }
            L->specs[L->n].block = blk;
            snprintf(L->specs[L->n].pointer, sizeof L->specs[L->n].pointer, "/sweep");
        }
    }
    return 1;
}

/* The base scene and the list of runs. Returns 0 after recording an error;
 * L->owned is the caller's to release either way. */
static int read_request(struct api_call *c, const json_t *body, struct api_traj_request *base,
                        struct run_list *L)
{
    if (!api_traj_request_parse(c, json_object_get(body, "request"), "/request", base)) return 0;
    base->p.error_estimate = 0;
    const json_t *runs = json_object_get(body, "runs"), *sweep = json_object_get(body, "sweep");
    if (!!runs == !!sweep) {
        api_call_invalid(c, runs ? "/sweep" : "", "give exactly one of runs and sweep");
        return 0;
    }
    if (!(L->owned = json_array())) {
        api_call_fail_core(c, MECH_ENOMEM, NULL, "");
        return 0;
    }
    if (runs) list_from_runs(runs, L);
    return runs || list_from_sweep(c, sweep, base, L);
}

/* Every run's request: the base with its integrator block, checked before
 * anything runs (a run the budget leaves not run must still be a valid one).
 * A new array of L->n (free()), or NULL after recording an error. */
static struct api_traj_request *
configure_runs(struct api_call *c, const struct api_traj_request *base, const struct run_list *L)
{
    struct api_traj_request *rqs = malloc((L->n ? L->n : 1) * sizeof *rqs);
    if (!rqs) {
        api_call_fail_core(c, MECH_ENOMEM, NULL, "");
        return NULL;
    }
    for (size_t k = 0; k < L->n; k++) {
        rqs[k] = *base;
        api_traj_request_fix(&rqs[k]);
        if (!api_traj_request_set_integrator(c, &rqs[k], L->specs[k].block, L->specs[k].pointer)) {
            free(rqs);
            return NULL;
        }
    }
    return rqs;
}

/* "dry_run": every run's selection and predictions; nothing integrated. */
static json_t *encode_dry_run(struct api_call *c, struct api_traj_request *rqs,
                              const struct run_list *L)
{
    json_t *rows = json_array();
    for (size_t k = 0; rows && k < L->n; k++) {
        rqs[k].dry_run = 1;
        json_t *row = json_object();
        json_object_set_new_nocheck(
            row, "requested",
            json_deep_copy(api_call_as_given(c, L->specs[k].block, L->specs[k].pointer)));
        json_object_set_new_nocheck(row, "status", json_string("dry_run"));
        json_object_set_new_nocheck(row, "selection", api_traj_selection(c, &rqs[k], NULL));
        json_array_append_new(rows, row);
    }
    json_t *res = json_object();
    if (!res || !rows) {
        json_decref(res);
        json_decref(rows);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    json_object_set_new_nocheck(res, "dry_run", json_true());
    json_object_set_new_nocheck(res, "operation", json_string("/v1/trajectory"));
    json_object_set_new_nocheck(res, "runs", rows);
    json_object_set_new_nocheck(res, "total_steps", json_integer(0));
    json_object_set_new_nocheck(res, "total_rhs_evaluations", json_integer(0));
    return res;
}

/* The reference block: exact (kind, name) or the radau15 run. */
static json_t *encode_reference(struct api_call *c, const struct mech_compare_result *out)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "kind",
                                json_string(out->reference_exact ? "exact" : "numerical"));
    json_object_set_new_nocheck(j, "name", json_string(out->reference_name));
    if (!out->reference_exact) {
        json_object_set_new_nocheck(j, "rtol", api_real(c, MECH_COMPARE_REFERENCE_RTOL));
        json_object_set_new_nocheck(j, "steps", json_integer(out->reference_stats.steps));
        json_object_set_new_nocheck(j, "rhs_evaluations",
                                    json_integer(out->reference_stats.rhs_evaluations));
    }
    return j;
}

/* A run's settings as it ran: the closed form, or method, tolerances, order. */
static void encode_settings(struct api_call *c, json_t *row, const struct api_traj_request *rq)
{
    if (rq->closed_form) {
        json_object_set_new_nocheck(row, "method", json_string("closed_form"));
        json_object_set_new_nocheck(row, "order", json_null());
        return;
    }
    json_t *set = api_traj_settings(c, &rq->p);
    json_object_update(row, set);
    json_decref(set);
    const struct mech_integrator *mm = mech_ode_method_find(rq->p.method);
    json_object_set_new_nocheck(row, "order",
                                json_integer(mm ? mech_ode_method_describe(mm).order : 0));
}

/* A finished run's measurements against the reference. */
static void encode_ok(struct api_call *c, json_t *row, const struct mech_compare_row *w)
{
    json_object_set_new_nocheck(row, "status", json_string("ok"));
    json_object_set_new_nocheck(row, "max_position_error", api_real(c, w->max_position_error));
    json_object_set_new_nocheck(row, "final_position_error", api_real(c, w->final_position_error));
    json_object_set_new_nocheck(row, "max_velocity_error", api_real(c, w->max_velocity_error));
    json_object_set_new_nocheck(row, "max_relative_position_error",
                                api_real(c, w->max_relative_position_error));
    json_object_set_new_nocheck(row, "max_relative_velocity_error",
                                api_real(c, w->max_relative_velocity_error));
    json_t *invs = json_array();
    for (size_t i = 0; invs && i < w->n_invariants; i++)
        json_array_append_new(invs, json_pack("{s:s,s:o}", "name", w->invariants[i].name,
                                              "max_relative_drift",
                                              api_real(c, w->invariants[i].max_relative_drift)));
    json_object_set_new_nocheck(row, "invariants", invs);
    json_object_set_new_nocheck(row, "steps", json_integer(w->stats.steps));
    json_object_set_new_nocheck(row, "rejected_steps", json_integer(w->stats.rejected_steps));
    json_object_set_new_nocheck(row, "rhs_evaluations", json_integer(w->stats.rhs_evaluations));
}

/* The stopped run's status, reason and progress (t_reached only when it
 * ran: a fixed-step run refused up front reports how far the budget would
 * have reached, which it did not). */
static void encode_stopped(struct api_call *c, json_t *row, const struct mech_compare_row *w,
                           const struct run_list *L, size_t k)
{
    char reason[320];
    not_run_reason(reason, sizeof reason, w->status, c, k, L->specs[k].pointer, w->err.text);
    json_object_set_new_nocheck(row, "status", json_string("not_run"));
    json_object_set_new_nocheck(row, "reason", json_string(reason));
    const struct mech_progress *pg = &w->err.progress;
    json_t *prog = json_pack("{s:I}", "steps", (json_int_t)pg->steps);
    if (prog && pg->steps > 0 && isfinite(pg->t_reached))
        json_object_set_new_nocheck(prog, "t_reached", json_real(pg->t_reached));
    if (prog && isfinite(pg->t_target))
        json_object_set_new_nocheck(prog, "t_target", json_real(pg->t_target));
    json_object_set_new_nocheck(row, "progress", prog);
}

/* Row k: what was asked, its settings and its outcome. New reference. */
static json_t *encode_row(struct api_call *c, const struct api_traj_request *rq,
                          const struct mech_compare_row *w, const struct run_list *L, size_t k,
                          const struct mech_compare_result *out)
{
    const json_t *asked = api_call_as_given(c, L->specs[k].block, L->specs[k].pointer);
    if (out->partial && k > out->stopped_run) {
        char reason[320];
        size_t s = out->stopped_run;
        not_run_reason(reason, sizeof reason, w->status, c, s, L->specs[s].pointer, NULL);
        return json_pack("{s:O,s:s,s:s}", "requested", asked, "status", "not_run", "reason",
                         reason);
    }
    json_t *row = json_object();
    if (!row) return NULL;
    json_object_set_new_nocheck(row, "requested", json_deep_copy(asked));
    encode_settings(c, row, rq);
    if (w->state == MECH_COMPARE_RUN_NOT_RUN) {
        encode_stopped(c, row, w, L, k);
    } else if (w->state == MECH_COMPARE_RUN_FAILED) {
        json_object_set_new_nocheck(row, "status", json_string("failed"));
        json_object_set_new_nocheck(row, "problem", json_string(mech_status_name(w->status)));
        json_object_set_new_nocheck(row, "detail", json_string(w->err.text));
    } else {
        encode_ok(c, row, w);
    }
    return row;
}

/* The answer of a sweep that ran (partial or whole). */
static json_t *encode_answer(struct api_call *c, const struct api_traj_request *rqs,
                             const struct mech_compare_row *w, const struct run_list *L,
                             const struct mech_compare_result *out)
{
    json_t *rows = json_array(), *cost_runs = json_array();
    for (size_t k = 0; rows && k < L->n; k++) {
        json_t *row = encode_row(c, &rqs[k], &w[k], L, k, out);
        json_array_append_new(cost_runs, json_pack("{s:f}", "cpu_seconds", w[k].cpu_seconds));
        if (!row || json_array_append_new(rows, row)) {
            json_decref(rows);
            rows = NULL;
        }
    }
    json_t *res = json_object();
    if (!res || !rows || !cost_runs) {
        json_decref(res);
        json_decref(rows);
        json_decref(cost_runs);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    json_object_set_new_nocheck(res, "operation", json_string("/v1/trajectory"));
    json_object_set_new_nocheck(res, "reference", encode_reference(c, out));
    json_object_set_new_nocheck(res, "partial", json_boolean(out->partial));
    json_object_set_new_nocheck(res, "runs", rows);
    json_object_set_new_nocheck(res, "total_steps", json_integer(out->total_steps));
    /* depends on the load and the deadline: never cached */
    if (out->partial) c->depends_on_load = 1;
    /* measured time lives under the top-level cost block only, so the rest
     * of the answer is byte-identical from run to run; the framework adds
     * cost.cpu_seconds (the whole request) and drops the block for "cost": false */
    json_t *jc = json_object();
    if (out->reference_cpu_seconds >= 0.0)
        json_object_set_new_nocheck(jc, "reference_cpu_seconds",
                                    json_real(out->reference_cpu_seconds));
    json_object_set_new_nocheck(jc, "runs", cost_runs);
    json_object_set_new_nocheck(res, "cost", jc);
    return res;
}

/* Run the sweep (one core call) and encode it, or fail naming the run. */
static json_t *run_sweep(struct api_call *c, const struct api_traj_request *base,
                         const struct api_traj_request *rqs, const struct run_list *L)
{
    struct mech_compare_config cfg[COMPARE_MAX_RUNS];
    for (size_t k = 0; k < L->n; k++)
        cfg[k] = (struct mech_compare_config){.p = &rqs[k].p, .closed_form = rqs[k].closed_form};
    struct mech_compare_row *w = malloc((L->n ? L->n : 1) * sizeof *w);
    if (!w) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    struct mech_compare_result out;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_compare_sweep(&base->p, cfg, L->n, &c->budget, w, &out, &e);
    json_t *res = NULL;
    if (st == MECH_OK)
        res = encode_answer(c, rqs, w, L, &out);
    else if (out.failed_run == -2)
        api_call_fail_core(c, st, st == MECH_ENOMEM ? NULL : &e, "");
    else
        fail_run(c, st, &e, out.failed_run,
                 out.failed_run >= 0 ? L->specs[out.failed_run].pointer : "", out.total_steps);
    free(w);
    return res;
}

json_t *api_op_compare(struct api_call *c, const json_t *body)
{
    struct api_traj_request base;
    struct run_list L = {.n = 0, .owned = NULL};
    json_t *res = NULL;
    if (read_request(c, body, &base, &L)) {
        struct api_traj_request *rqs = configure_runs(c, &base, &L);
        if (rqs && (json_is_true(json_object_get(body, "dry_run")) || base.dry_run))
            res = encode_dry_run(c, rqs, &L);
        else if (rqs)
            res = run_sweep(c, &base, rqs, &L);
        free(rqs);
    }
    json_decref(L.owned);
    return res;
}
