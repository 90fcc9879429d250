/* ep_compare.c — POST /v1/compare: run one /v1/trajectory scene with several
 * integrator settings and answer, per run, the error against the best
 * reference available, the drift of the conserved quantities, the steps,
 * right-hand-side evaluations and CPU time: the data of a work-precision plot
 * for the user's own scene.
 *
 * Reference: the scene's exact solution when it has one (kepler, harmonic
 * oscillator, uniform gravity with or without drag: mech/reference.h);
 * otherwise a radau15 run at its round-off setting (rtol 1e-10, the floor of
 * its eps; see core/integrators/radau15.c). A first-order reference (the
 * Coriolis formulas) is not used here: its own O(W^2) error would hide the
 * differences between methods.
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

#include "endpoint.h"
#include "mech/reference.h"
#include "mech/trajectory.h"
#include "trajectory_request.h"

#define COMPARE_MAX_RUNS 64
/* radau15's round-off setting (its eps floor, core/integrators/radau15.c). */
#define COMPARE_REFERENCE_METHOD "radau15"
#define COMPARE_REFERENCE_RTOL 1e-10

struct run_spec {
    const json_t *block; /* borrowed from the body or owned by `owned` */
    char pointer[48];
};

static double max3(double a, double b) { return a > b ? a : b; }

/* Run one trajectory (samples into pos/vel, which hold p.samples each). */
static enum mech_status run_traj(struct api_traj_request *rq, struct mech_budget *b,
                                 struct mech_vec3 *pos, struct mech_vec3 *vel,
                                 struct mech_trajectory_result *r, struct mech_error *e,
                                 double *cpu)
{
    memset(r, 0, sizeof *r);
    r->position = pos;
    r->velocity = vel;
    mech_error_clear(e);
    double c0 = mech_cpu_seconds();
    /* a row that selects by accuracy on a scene with a closed form is answered
     * from it, as /v1/trajectory would (0 steps) */
    enum mech_status st = rq->closed_form ? mech_trajectory_closed_form_ex(&rq->p, r, &rq->evidence, b, e)
                                          : mech_trajectory_integrate(&rq->p, b, r, e);
    *cpu = mech_cpu_seconds() - c0;
    return st;
}

/* Fail the whole request for run k (or the reference run, k < 0). */
static json_t *fail_run(struct api_call *c, enum mech_status st, const struct mech_error *e,
                        long k, const char *pointer, long total_steps)
{
    struct mech_error e2 = *e;
    /* Parameters of the integrator block belong to the run, others to the
     * request (a scene error is the same for every run: no run named). */
    const char *prefix = "/request";
    const int scene_error = (st == MECH_EINVAL || st == MECH_EDOMAIN) &&
                            strncmp(e->param, "integrator/", 11) != 0;
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
        snprintf(what, sizeof what, "the shared step budget of %ld steps ran out", c->budget.max_steps);
    if (stop_text)
        snprintf(buf, n, "stopped: %s during this run (%.150s)", what, stop_text);
    else
        snprintf(buf, n, "not started: %s during run %zu (%s)", what, k, pointer);
}

/* After run k ran out of budget (st, e; cpu its measured time): append its
 * row (already holding its settings; consumed) as not run with its progress,
 * then a not-run row for every later run, with the cost entries that keep
 * cost.runs aligned with the rows. Returns 0, or -1 if memory ran out. */
static int mark_not_run(struct api_call *c, json_t *rows, json_t *row, json_t *cost_runs,
                        const struct run_spec *specs, size_t k, size_t n, enum mech_status st,
                        const struct mech_error *e, double cpu)
{
    char reason[320];
    not_run_reason(reason, sizeof reason, st, c, k, specs[k].pointer, e->text);
    json_object_set_new_nocheck(row, "status", json_string("not_run"));
    json_object_set_new_nocheck(row, "reason", json_string(reason));
    /* t_reached only when it ran: a fixed-step run refused up front reports
     * how far the budget would have reached, which it did not. */
    json_t *prog = json_pack("{s:I}", "steps", (json_int_t)e->progress.steps);
    if (prog && e->progress.steps > 0 && isfinite(e->progress.t_reached))
        json_object_set_new_nocheck(prog, "t_reached", json_real(e->progress.t_reached));
    if (prog && isfinite(e->progress.t_target))
        json_object_set_new_nocheck(prog, "t_target", json_real(e->progress.t_target));
    json_object_set_new_nocheck(row, "progress", prog);
    json_array_append_new(cost_runs, json_pack("{s:f}", "cpu_seconds", cpu));
    if (!row || json_array_append_new(rows, row)) return -1;
    not_run_reason(reason, sizeof reason, st, c, k, specs[k].pointer, NULL);
    for (size_t j = k + 1; j < n; j++) {
        json_t *r = json_pack("{s:O,s:s,s:s}", "requested", api_call_as_given(c, specs[j].block, specs[j].pointer), "status", "not_run",
                              "reason", reason);
        json_array_append_new(cost_runs, json_pack("{s:f}", "cpu_seconds", 0.0));
        if (!r || json_array_append_new(rows, r)) return -1;
    }
    return 0;
}

json_t *api_op_compare(struct api_call *c, const json_t *body)
{
    struct api_traj_request base;
    if (!api_traj_request_parse(c, json_object_get(body, "request"), "/request", &base))
        return NULL;
    base.p.error_estimate = 0;
    const json_t *runs = json_object_get(body, "runs"), *sweep = json_object_get(body, "sweep");
    if (!!runs == !!sweep) {
        api_call_invalid(c, runs ? "/sweep" : "", "give exactly one of runs and sweep");
        return NULL;
    }

    /* ---- the list of runs ---- */
    struct run_spec specs[COMPARE_MAX_RUNS];
    size_t n = 0;
    json_t *owned = json_array(); /* blocks built for a sweep */
    if (!owned) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    if (runs) {
        for (size_t i = 0; i < json_array_size(runs) && n < COMPARE_MAX_RUNS; i++, n++) {
            specs[n].block = json_array_get(runs, i);
            snprintf(specs[n].pointer, sizeof specs[n].pointer, "/runs/%zu", i);
        }
    } else {
        const json_t *ms = json_object_get(sweep, "methods");
        const json_t *tols = json_object_get(sweep, "tolerances");
        const json_t *dts = json_object_get(sweep, "dts");
        /* atol = rtol x the scene's scale, as mech_trajectory_choose() sets it */
        struct mech_trajectory_choice ch;
        double scale = 1.0;
        if (mech_trajectory_choose(&base.p, 1e-8, &ch, NULL) == MECH_OK)
            scale = ch.profile.scale;
        size_t need = 0;
        for (size_t i = 0; i < json_array_size(ms); i++) {
            const char *m = json_string_value(json_array_get(ms, i));
            int adaptive = mech_ode_method_describe(mech_ode_method_find(m)).adaptive;
            const json_t *list = adaptive ? tols : dts;
            if (!list) {
                api_call_invalid(c, adaptive ? "/sweep/tolerances" : "/sweep/dts",
                                 "method %s needs %s", m,
                                 adaptive ? "tolerances (its rtol values)" : "dts (its steps)");
                json_decref(owned);
                return NULL;
            }
            need += json_array_size(list);
        }
        if (need > COMPARE_MAX_RUNS) {
            api_call_invalid(c, "/sweep", "the sweep makes %zu runs; at most %d are allowed", need,
                             COMPARE_MAX_RUNS);
            json_decref(owned);
            return NULL;
        }
        for (size_t i = 0; i < json_array_size(ms); i++) {
            const char *m = json_string_value(json_array_get(ms, i));
            int adaptive = mech_ode_method_describe(mech_ode_method_find(m)).adaptive;
            const json_t *list = adaptive ? tols : dts;
            for (size_t j = 0; j < json_array_size(list); j++, n++) {
                double x = json_number_value(json_array_get(list, j));
                json_t *blk = adaptive ? json_pack("{s:s,s:f,s:f}", "method", m, "rtol", x,
                                                   "atol", x * scale)
                                       : json_pack("{s:s,s:f}", "method", m, "dt", x);
                if (!blk || json_array_append_new(owned, blk)) {
                    json_decref(owned);
                    return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
                }
                specs[n].block = blk;
                snprintf(specs[n].pointer, sizeof specs[n].pointer, "/sweep");
            }
        }
    }

    /* Every run's block is checked before anything runs: a run that the
     * budget leaves not run must still be a valid one. */
    for (size_t k = 0; k < n; k++) {
        struct api_traj_request rq = base;
        api_traj_request_fix(&rq);
        if (!api_traj_request_set_integrator(c, &rq, specs[k].block, specs[k].pointer)) {
            json_decref(owned);
            return NULL;
        }
    }

    if (json_is_true(json_object_get(body, "dry_run")) || base.dry_run) {
        /* every run's selection and predictions; nothing integrated */
        json_t *res = json_object(), *rows = json_array();
        for (size_t k = 0; res && rows && k < n; k++) {
            struct api_traj_request rq = base;
            api_traj_request_fix(&rq);
            api_traj_request_set_integrator(c, &rq, specs[k].block, specs[k].pointer);
            rq.dry_run = 1;
            json_t *row = json_object();
            json_object_set_new_nocheck(row, "requested", json_deep_copy(api_call_as_given(c, specs[k].block, specs[k].pointer)));
            json_object_set_new_nocheck(row, "status", json_string("dry_run"));
            json_object_set_new_nocheck(row, "selection", api_traj_selection(c, &rq, NULL));
            json_array_append_new(rows, row);
        }
        json_decref(owned);
        json_object_set_new_nocheck(res, "dry_run", json_true());
        json_object_set_new_nocheck(res, "operation", json_string("/v1/trajectory"));
        json_object_set_new_nocheck(res, "runs", rows);
        json_object_set_new_nocheck(res, "total_steps", json_integer(0));
        json_object_set_new_nocheck(res, "total_rhs_evaluations", json_integer(0));
        if (!res || !rows) {
            json_decref(res);
            return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
        }
        return res;
    }

    const size_t ns = base.p.samples;
    struct mech_vec3 *buf = malloc(4 * ns * sizeof *buf);
    if (!buf) {
        json_decref(owned);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    struct mech_vec3 *ref_pos = buf, *ref_vel = buf + ns, *pos = buf + 2 * ns,
                     *vel = buf + 3 * ns;
    long used = 0;
    struct mech_error e;
    struct mech_trajectory_result r;
    double cpu = 0.0;
    json_t *res = NULL;
    json_t *cost_runs = json_array();
    double ref_cpu = -1.0;

    /* ---- the reference ---- */
    struct mech_trajectory_reference exact;
    const int have_exact =
        mech_trajectory_reference_find(&base.p, &exact) == MECH_REFERENCE_EXACT;
    json_t *jref = json_object();
    size_t ref_n = 0;
    int ref_stopped = 0;
    struct mech_vec3 ref_stop = mech_vec3_make(0, 0, 0), ref_stop_v = ref_stop;
    if (have_exact) {
        json_object_set_new_nocheck(jref, "kind", json_string("exact"));
        json_object_set_new_nocheck(jref, "name", json_string(exact.name));
    } else {
        struct api_traj_request rq = base;
        api_traj_request_fix(&rq);
        rq.p.method = COMPARE_REFERENCE_METHOD;
        rq.p.opt.rtol = COMPARE_REFERENCE_RTOL;
        rq.p.opt.atol = 0;
        struct mech_budget b = c->budget;
        enum mech_status st = run_traj(&rq, &b, ref_pos, ref_vel, &r, &e, &cpu);
        if (st != MECH_OK) {
            fail_run(c, st, &e, -1, "", (long)e.progress.steps);
            goto done;
        }
        used += r.total_steps;
        ref_n = r.n_samples;
        ref_stopped = r.stopped;
        ref_stop = r.stop_position;
        ref_stop_v = r.stop_velocity;
        json_object_set_new_nocheck(jref, "kind", json_string("numerical"));
        json_object_set_new_nocheck(jref, "name", json_string(COMPARE_REFERENCE_METHOD));
        json_object_set_new_nocheck(jref, "rtol", api_real(c, COMPARE_REFERENCE_RTOL));
        json_object_set_new_nocheck(jref, "steps", json_integer(r.stats.steps));
        json_object_set_new_nocheck(jref, "rhs_evaluations", json_integer(r.stats.rhs_evaluations));
        ref_cpu = cpu;
    }

    /* ---- the runs ---- */
    json_t *rows = json_array();
    size_t finished = 0; /* rows with status ok or failed */
    int partial = 0;
    for (size_t k = 0; rows && k < n; k++) {
        struct api_traj_request rq = base;
        api_traj_request_fix(&rq);
        if (!api_traj_request_set_integrator(c, &rq, specs[k].block, specs[k].pointer)) {
            json_decref(rows);
            rows = NULL;
            goto done;
        }
        json_t *row = json_object();
        json_object_set_new_nocheck(row, "requested", json_deep_copy(api_call_as_given(c, specs[k].block, specs[k].pointer)));
        if (rq.closed_form) {
            json_object_set_new_nocheck(row, "method", json_string("closed_form"));
            json_object_set_new_nocheck(row, "order", json_null());
        } else {
            json_t *set = api_traj_settings(c, &rq.p);
            json_object_update(row, set);
            json_decref(set);
            const struct mech_integrator *mm = mech_ode_method_find(rq.p.method);
            json_object_set_new_nocheck(row, "order",
                                        json_integer(mm ? mech_ode_method_describe(mm).order : 0));
        }
        struct mech_budget b = c->budget;
        b.max_steps = c->budget.max_steps - used;
        enum mech_status st;
        if (b.max_steps <= 0) {
            mech_error_clear(&e);
            st = mech_error_set(&e, MECH_EBUDGET, NULL,
                                "no steps left of the shared budget of %ld steps",
                                c->budget.max_steps);
            e.progress.steps = 0;
        } else {
            st = run_traj(&rq, &b, pos, vel, &r, &e, &cpu);
        }
        if (st == MECH_OK) used += r.total_steps;
        else if (e.progress.steps > 0) used += e.progress.steps;
        const int row_failure =
            st == MECH_ENUMERIC ||
            ((st == MECH_EINVAL || st == MECH_EDOMAIN) && !strncmp(e.param, "integrator", 10));
        const int out_of_budget = st == MECH_EBUDGET || st == MECH_EDEADLINE;
        if (st != MECH_OK && !row_failure && !(out_of_budget && finished > 0)) {
            json_decref(row);
            json_decref(rows);
            rows = NULL;
            fail_run(c, st, &e, (long)k, specs[k].pointer, used);
            goto done;
        }
        if (out_of_budget) {
            /* Keep the finished runs: this one and the rest are not run. */
            if (mark_not_run(c, rows, row, cost_runs, specs, k, n, st, &e, cpu)) {
                json_decref(rows);
                rows = NULL;
                api_call_fail_core(c, MECH_ENOMEM, NULL, "");
                goto done;
            }
            partial = 1;
            break;
        }
        finished++;
        if (st != MECH_OK) {
            json_object_set_new_nocheck(row, "status", json_string("failed"));
            json_object_set_new_nocheck(row, "problem", json_string(mech_status_name(st)));
            json_object_set_new_nocheck(row, "detail", json_string(e.text));
        } else {
            json_object_set_new_nocheck(row, "status", json_string("ok"));
            double emax, efin, evmax, erel, evrel;
            if (have_exact) {
                emax = r.reference.max_position_error;
                efin = r.reference.final_position_error;
                evmax = r.reference.max_velocity_error;
                erel = r.reference.max_relative_position_error;
                evrel = r.reference.max_relative_velocity_error;
            } else {
                /* against the reference run, over the common samples and the stop */
                size_t m = r.n_samples < ref_n ? r.n_samples : ref_n;
                double rmax = 0, vmax = 0;
                emax = efin = evmax = 0;
                for (size_t i = 0; i <= m; i++) {
                    struct mech_vec3 a, av, b0, bv;
                    if (i < m) {
                        a = pos[i], av = vel[i], b0 = ref_pos[i], bv = ref_vel[i];
                    } else if (r.stopped && ref_stopped) {
                        a = r.stop_position, av = r.stop_velocity, b0 = ref_stop, bv = ref_stop_v;
                    } else {
                        break;
                    }
                    efin = mech_vec3_norm(mech_vec3_sub(a, b0));
                    emax = max3(emax, efin);
                    evmax = max3(evmax, mech_vec3_norm(mech_vec3_sub(av, bv)));
                    rmax = max3(rmax, mech_vec3_norm(b0));
                    vmax = max3(vmax, mech_vec3_norm(bv));
                }
                erel = rmax > 0 ? emax / rmax : 0;
                evrel = vmax > 0 ? evmax / vmax : 0;
            }
            json_object_set_new_nocheck(row, "max_position_error", api_real(c, emax));
            json_object_set_new_nocheck(row, "final_position_error", api_real(c, efin));
            json_object_set_new_nocheck(row, "max_velocity_error", api_real(c, evmax));
            json_object_set_new_nocheck(row, "max_relative_position_error", api_real(c, erel));
            json_object_set_new_nocheck(row, "max_relative_velocity_error", api_real(c, evrel));
            json_t *invs = json_array();
            for (size_t i = 0; invs && i < r.n_invariants; i++)
                json_array_append_new(invs, json_pack("{s:s,s:o}", "name", r.invariants[i].name,
                                                      "max_relative_drift",
                                                      api_real(c, r.invariants[i].max_relative_drift)));
            json_object_set_new_nocheck(row, "invariants", invs);
            json_object_set_new_nocheck(row, "steps", json_integer(r.stats.steps));
            json_object_set_new_nocheck(row, "rejected_steps",
                                        json_integer(r.stats.rejected_steps));
            json_object_set_new_nocheck(row, "rhs_evaluations",
                                        json_integer(r.stats.rhs_evaluations));
        }
        /* measured time lives under the top-level cost block only, so the
         * rest of the answer is byte-identical from run to run */
        json_array_append_new(cost_runs, json_pack("{s:f}", "cpu_seconds", st == MECH_OK ? cpu : 0.0));
        if (!row || json_array_append_new(rows, row)) {
            json_decref(rows);
            rows = NULL;
            api_call_fail_core(c, MECH_ENOMEM, NULL, "");
            goto done;
        }
    }
    if (!rows) {
        api_call_fail_core(c, MECH_ENOMEM, NULL, "");
        goto done;
    }
    res = json_object();
    if (res) {
        json_object_set_new_nocheck(res, "operation", json_string("/v1/trajectory"));
        json_object_set_new_nocheck(res, "reference", jref);
        jref = NULL;
        json_object_set_new_nocheck(res, "partial", json_boolean(partial));
        json_object_set_new_nocheck(res, "runs", rows);
        json_object_set_new_nocheck(res, "total_steps", json_integer(used));
        /* depends on the load and the deadline: never cached */
        if (partial) c->depends_on_load = 1;
        /* the framework adds cost.cpu_seconds (the whole request) and drops
         * the block for "cost": false */
        json_t *jc = json_object();
        if (ref_cpu >= 0.0)
            json_object_set_new_nocheck(jc, "reference_cpu_seconds", json_real(ref_cpu));
        json_object_set_new_nocheck(jc, "runs", cost_runs);
        cost_runs = NULL;
        json_object_set_new_nocheck(res, "cost", jc);
    } else {
        json_decref(rows);
        api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
done:
    json_decref(cost_runs);
    json_decref(jref);
    json_decref(owned);
    free(buf);
    return res;
}

