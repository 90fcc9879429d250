/* trajectory_request.c — parsing of the /v1/trajectory request and encoding
 * of its diagnostics, shared by api/ops/frames/trajectory.c and api/ops/integrators/compare.c (see
 * api/request/trajectory_request.h). */
#include "request/trajectory_request.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "request/integrator_block.h"
#include "request/trajectory_relativity.h"
#include "mech/frames/reference.h"

static int axis_of(const char *s) { return s[0] - 'x'; }

static enum mech_force_type force_type_of(const char *s)
{
    if (strcmp(s, "central_gravity") == 0) return MECH_FORCE_CENTRAL_GRAVITY;
    if (strcmp(s, "spring") == 0) return MECH_FORCE_SPRING;
    if (strcmp(s, "linear_drag") == 0) return MECH_FORCE_LINEAR_DRAG;
    if (strcmp(s, "lorentz") == 0) return MECH_FORCE_LORENTZ;
    if (strcmp(s, "third_body_tide") == 0) return MECH_FORCE_THIRD_BODY_TIDE;
    return MECH_FORCE_UNIFORM_GRAVITY;
}

void api_traj_request_fix(struct api_traj_request *rq)
{
    rq->p.forces = rq->forces;
}

/* Read the integrator block (NULL: the default, accuracy "balanced") into
 * rq and *q: a given method and its settings go into rq->p; otherwise q is
 * told to choose by accuracy, at the preset's promise or target_error. */
static void traj_block_read(struct api_call *c, struct api_traj_request *rq, const json_t *in,
                            const char *pointer, struct mech_trajectory_plan_request *q)
{
    struct mech_trajectory_problem *p = &rq->p;
    rq->requested = api_call_as_given(c, in, pointer);
    rq->chosen = 0;
    rq->closed_form = 0;
    rq->accuracy = NULL;
    memset(&rq->choice, 0, sizeof rq->choice);
    q->model_target = api_traj_block_target(in);
    rq->model_target = q->model_target;
    const char *method = in ? api_string(in, "method", NULL) : NULL;
    if (method) {
        q->by_accuracy = 0;
        p->method = method;
        p->opt = api_integrator_settings(in);
        return;
    }
    p->closed_form_off = in && json_is_false(json_object_get(in, "closed_form"));
    const json_t *te = in ? json_object_get(in, "target_error") : NULL;
    const struct mech_accuracy_preset *preset = NULL;
    q->by_accuracy = 1;
    q->target = mech_accuracy_target(te != NULL, json_number_value(te),
                                     in ? api_string_of(in, "accuracy") : NULL, &preset);
    rq->accuracy = preset ? preset->name : NULL;
}

/* The run's predicted CPU seconds: the chosen candidate's prediction, twice
 * with "error_estimate" (a second run at a tighter setting); -1 when nothing
 * predicted it (the client gave the method and its step or tolerances). */
static double traj_predicted_cpu(const struct api_traj_request *rq)
{
    const struct mech_selection *sel = &rq->choice.sel;
    if (!rq->chosen || sel->chosen < 0 || (size_t)sel->chosen >= sel->n) return -1.0;
    const struct mech_candidate *k = &sel->c[sel->chosen];
    if (!k->predicted || !(k->predicted_cpu_s >= 0)) return -1.0;
    return k->predicted_cpu_s * (rq->p.error_estimate ? 2.0 : 1.0);
}

/* The block read, then the model → choose pipeline of core
 * (mech_trajectory_plan), with "auto" resolved when with_model says so (the
 * base request; /v1/compare's runs re-choose only). Returns 0 after
 * recording an error: the first pass's at the request, the chooser's at the
 * block. */
static int traj_plan(struct api_call *c, struct api_traj_request *rq, const json_t *in,
                     const char *pointer, const char *prefix, int with_model)
{
    struct mech_trajectory_plan_request q = {0};
    traj_block_read(c, rq, in, pointer, &q);
    q.auto_model = with_model && rq->auto_model;
    q.dry_run = rq->dry_run;
    /* Under a cost gate: the first pass of "auto" is a run of unknown
     * length before any prediction, so such a request stops here. */
    if (q.auto_model && !q.dry_run && api_call_cost_gate(c, -1.0)) return 0;
    struct mech_trajectory_plan plan;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_trajectory_plan(&rq->p, &q, &c->budget, &plan, &e);
    if (st != MECH_OK && plan.failed == MECH_PLAN_MODEL) {
        if (st == MECH_EBUDGET || st == MECH_EDEADLINE) {
            size_t n = strlen(e.text);
            snprintf(e.text + n, sizeof e.text - n, " (in the first pass of \"fictitious\": \"auto\")");
        }
        api_call_fail_core(c, st, &e, *prefix ? "/request" : "");
        return 0;
    }
    if (st != MECH_OK) {
        api_call_invalid(c, pointer, "%s", e.text);
        return 0;
    }
    if (plan.modelled) rq->model = plan.model;
    if (plan.chosen) {
        rq->chosen = 1;
        rq->choice = plan.choice;
        rq->closed_form = plan.closed_form;
    }
    if (!rq->dry_run && api_call_cost_gate(c, traj_predicted_cpu(rq))) return 0;
    return 1;
}

int api_traj_request_set_integrator(struct api_call *c, struct api_traj_request *rq,
                                    const json_t *in, const char *pointer)
{
    return traj_plan(c, rq, in, pointer, "", 0);
}

int api_traj_request_parse(struct api_call *c, const json_t *body, const char *prefix,
                           struct api_traj_request *rq)
{
    const struct mech_vec3 zero = mech_vec3_make(0, 0, 0);
    memset(rq, 0, sizeof *rq);
    struct mech_trajectory_problem *p = &rq->p;
    const json_t *part = json_object_get(body, "particle");
    p->mass = api_number_of(part, "mass");
    p->charge = api_number_of(part, "charge");
    p->reduce_planar = 1;
    p->position = api_vec3_member(part, "position", zero);
    p->velocity = api_vec3_member(part, "velocity", zero);

    const json_t *frame = json_object_get(body, "frame");
    const char *ft = frame ? api_string_of(frame, "type") : "inertial";
    if (strcmp(ft, "rotating") == 0) {
        p->frame.type = MECH_FRAME_ROTATING;
        p->frame.omega = api_vec3_member(frame, "omega", zero);
        p->frame.omega_dot = api_vec3_member(frame, "omega_dot", zero);
        p->frame.acceleration = api_vec3_member(frame, "acceleration", zero);
    } else if (strcmp(ft, "earth") == 0) {
        p->frame.type = MECH_FRAME_EARTH;
        p->frame.latitude_deg = api_number_of(frame, "latitude_deg");
        char fptr[128];
        snprintf(fptr, sizeof fptr, "%s/frame", prefix);
        if (!api_earth_rotation(c, frame, fptr, "omega_magnitude", MECH_EARTH_OMEGA_SIDEREAL,
                                &p->frame.omega_magnitude))
            return 0;
    } else {
        p->frame.type = MECH_FRAME_INERTIAL;
    }

    const json_t *fs = json_object_get(body, "forces");
    p->n_forces = json_array_size(fs);
    for (size_t i = 0; i < p->n_forces && i < MECH_TRAJECTORY_MAX_FORCES; i++) {
        const json_t *f = json_array_get(fs, i);
        struct mech_force *mf = &rq->forces[i];
        memset(mf, 0, sizeof *mf);
        mf->type = force_type_of(api_string_of(f, "type"));
        switch (mf->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            mf->u.uniform_gravity.g = api_vec3_member(f, "g", zero);
            break;
        case MECH_FORCE_CENTRAL_GRAVITY:
            mf->u.central_gravity.gm = api_number_of(f, "gm");
            mf->u.central_gravity.center = api_vec3_member(f, "center", zero);
            break;
        case MECH_FORCE_SPRING:
            mf->u.spring.k = api_number_of(f, "k");
            mf->u.spring.anchor = api_vec3_member(f, "anchor", zero);
            mf->u.spring.rest_length = api_number_of(f, "rest_length");
            break;
        case MECH_FORCE_LINEAR_DRAG:
            mf->u.linear_drag.b = api_number_of(f, "b");
            break;
        case MECH_FORCE_LORENTZ:
            mf->u.lorentz.E = api_vec3_member(f, "E", zero);
            mf->u.lorentz.B = api_vec3_member(f, "B", zero);
            break;
        case MECH_FORCE_THIRD_BODY_TIDE: {
            const int has_m = json_object_get(f, "mass") != NULL;
            const int has_gm = json_object_get(f, "gm") != NULL;
            if (has_m == has_gm) {
                char ptr[64];
                snprintf(ptr, sizeof ptr, "%s/forces/%zu", prefix, i);
                api_call_invalid(c, ptr, "third_body_tide needs exactly one of mass and gm");
                return 0;
            }
            mf->u.third_body_tide.gm = has_gm ? api_number_of(f, "gm")
                                              : MECH_GRAVITATIONAL_CONSTANT * api_number_of(f, "mass");
            mf->u.third_body_tide.position = api_vec3_member(f, "position", zero);
            break;
        }
        }
    }
    api_traj_request_fix(rq);

    const json_t *fic = json_object_get(body, "fictitious");
    if (json_is_string(fic)) {
        /* "auto": resolved below, once the accuracy is known */
        rq->auto_model = 1;
        p->fictitious = MECH_FICTITIOUS_ALL;
    } else if (fic) {
        if (p->frame.type == MECH_FRAME_INERTIAL && json_array_size(fic) > 0) {
            api_call_invalid(c, *prefix ? "/request/fictitious" : "/fictitious",
                             "fictitious terms need a rotating or earth frame; an inertial "
                             "frame has none");
            return 0;
        }
        for (size_t i = 0; i < json_array_size(fic); i++) {
            const char *s = json_string_value(json_array_get(fic, i));
            p->fictitious |= strcmp(s, "coriolis") == 0      ? MECH_FICTITIOUS_CORIOLIS
                             : strcmp(s, "centrifugal") == 0 ? MECH_FICTITIOUS_CENTRIFUGAL
                             : strcmp(s, "euler") == 0       ? MECH_FICTITIOUS_EULER
                                                             : MECH_FICTITIOUS_TRANSLATIONAL;
        }
    } else {
        p->fictitious = MECH_FICTITIOUS_ALL;
    }

    p->t_end = api_number_of(body, "t_end");
    p->samples = (size_t)api_number_of(body, "samples");
    p->error_estimate = json_is_true(json_object_get(body, "error_estimate"));
    rq->dry_run = json_is_true(json_object_get(body, "dry_run"));

    const json_t *stop = json_object_get(body, "stop");
    if (stop) {
        p->has_stop = 1;
        p->stop_axis = axis_of(api_string_of(stop, "coordinate"));
        p->stop_value = api_number_of(stop, "crosses");
        const char *d = api_string_of(stop, "direction");
        p->stop_direction = strcmp(d, "decreasing") == 0   ? MECH_STOP_DECREASING
                            : strcmp(d, "increasing") == 0 ? MECH_STOP_INCREASING
                                                           : MECH_STOP_EITHER;
    }
    if (!api_traj_relativity_parse(c, body, prefix, rq)) return 0;
    /* "auto" and the integrator block: one pass of core's pipeline (a dry run
     * integrates nothing: "auto" then keeps every applicable term) */
    char ptr[64];
    snprintf(ptr, sizeof ptr, "%s/integrator", prefix);
    return traj_plan(c, rq, json_object_get(body, "integrator"), ptr, prefix, 1);
}

double api_traj_block_target(const json_t *in)
{
    const double balanced = mech_accuracy_preset_at(MECH_ACCURACY_BALANCED)->promise;
    if (!in) return balanced;
    const json_t *te = json_object_get(in, "target_error");
    if (te) return json_number_value(te);
    const char *acc = api_string(in, "accuracy", NULL);
    if (acc) return mech_accuracy_target(0, 0.0, acc, NULL);
    /* a given adaptive method: its rtol (the schema fills the default) */
    if (json_object_get(in, "rtol")) {
        double r = api_number_of(in, "rtol");
        return r < 1e-15 ? 1e-15 : r > 0.1 ? 0.1 : r;
    }
    return balanced;
}

json_t *api_traj_model(struct api_call *c, const struct api_traj_request *rq,
                       const struct mech_trajectory_result *r)
{
    json_t *model = json_object();
    json_t *terms = json_array();
    if (!model || !terms) {
        json_decref(model);
        json_decref(terms);
        return NULL;
    }
    json_object_set_new_nocheck(model, "mode", json_string(rq->auto_model ? "auto" : "given"));
    const size_t nf = rq->p.n_forces;
    for (size_t i = 0; i < r->n_terms; i++) {
        json_t *tm = json_object();
        json_object_set_new_nocheck(tm, "term", json_string(r->terms[i].term));
        if (r->terms[i].force_index >= 0)
            json_object_set_new_nocheck(tm, "force_index", json_integer(r->terms[i].force_index));
        json_object_set_new_nocheck(tm, "included", json_boolean(r->terms[i].included));
        json_object_set_new_nocheck(tm, "max_acceleration",
                                    api_real(c, r->terms[i].max_acceleration));
        if (rq->auto_model && i >= nf && i - nf < MECH_TRAJECTORY_N_FICTITIOUS) {
            const struct mech_term_estimate *te = &rq->model.terms[i - nf];
            if (te->applicable) {
                json_t *ee = json_object();
                json_object_set_new_nocheck(ee, "acceleration_bound", api_real(c, te->accel_bound));
                json_object_set_new_nocheck(ee, "position", api_real(c, te->position_effect));
                json_object_set_new_nocheck(ee, "velocity", api_real(c, te->velocity_effect));
                json_object_set_new_nocheck(ee, "relative", api_real(c, te->relative_effect));
                json_object_set_new_nocheck(tm, "estimated_effect", ee);
            } else {
                json_object_set_new_nocheck(tm, "estimated_effect", json_null());
            }
            json_object_set_new_nocheck(tm, "reason", json_string(te->reason));
        }
        json_array_append_new(terms, tm);
    }
    json_object_set_new_nocheck(model, "terms", terms);
    if (rq->auto_model) {
        const struct mech_trajectory_model *m = &rq->model;
        json_t *a = json_object();
        json_object_set_new_nocheck(a, "target_error", api_real(c, m->target));
        json_object_set_new_nocheck(a, "safety_factor", api_real(c, m->safety));
        json_object_set_new(
            a, "rule",
            json_string("a term is included when max(|a| T^2/2 / L, |a| T / V) > target / "
                        "safety, with |a| the term's largest acceleration, L and V the largest "
                        "|r| and |v|, T the duration, all from a first pass with every term at "
                        "draft accuracy (1e-3 relative: the bounds are good to ~1e-3)"));
        json_object_set_new_nocheck(a, "time_scale", api_real(c, m->time_scale));
        json_object_set_new_nocheck(a, "position_scale", api_real(c, m->position_scale));
        json_object_set_new_nocheck(a, "velocity_scale", api_real(c, m->velocity_scale));
        if (m->first_pass_done) {
            json_t *fp = json_object();
            json_object_set_new_nocheck(fp, "method", json_string(m->first_pass_method));
            json_object_set_new_nocheck(fp, "rtol", api_real(c, m->first_pass_opt.rtol));
            json_object_set_new_nocheck(fp, "atol", api_real(c, m->first_pass_opt.atol));
            json_object_set_new_nocheck(fp, "steps", json_integer(m->first_pass_stats.steps));
            json_object_set_new_nocheck(fp, "rhs_evaluations",
                                        json_integer(m->first_pass_stats.rhs_evaluations));
            json_object_set_new_nocheck(a, "first_pass", fp);
        } else {
            json_object_set_new_nocheck(a, "first_pass", json_null());
        }
        json_object_set_new_nocheck(model, "auto", a);
    }
    json_t *state = json_object();
    json_object_set_new_nocheck(state, "dimensions", json_integer(r->dimensions));
    if (r->method && !strcmp(r->method, "closed_form")) {
        json_object_set_new_nocheck(state, "plane_normal", json_null());
        json_object_set_new_nocheck(
            state, "reason",
            json_string("closed form: the exact solution evaluated in three dimensions at each "
                        "sample; nothing integrated"));
    } else if (r->dimensions == 2) {
        json_object_set_new_nocheck(state, "plane_normal", api_vec3(c, r->plane_normal));
        json_object_set_new_nocheck(
            state, "reason",
            json_string("planar scene: r0, v0 and every force and modelled term "
                        "keep the motion in the plane through the origin normal "
                        "to plane_normal; integrated in its two coordinates"));
    } else {
        json_object_set_new_nocheck(state, "plane_normal", json_null());
        json_object_set_new(
            state, "reason",
            json_string("not planar (or a Boris run with velocity-dependent forces): three "
                        "dimensions"));
    }
    json_object_set_new_nocheck(model, "state", state);
    return model;
}

json_t *api_traj_settings(struct api_call *c, const struct mech_trajectory_problem *p)
{
    json_t *s = json_object();
    const struct mech_integrator *m = mech_ode_method_find(p->method);
    json_object_set_new_nocheck(s, "method", json_string(p->method));
    if (m && mech_ode_method_describe(m).adaptive) {
        json_object_set_new_nocheck(s, "rtol", api_real(c, p->opt.rtol));
        json_object_set_new_nocheck(s, "atol", api_real(c, p->opt.atol));
    } else {
        json_object_set_new_nocheck(s, "dt", api_real(c, p->opt.dt));
    }
    return s;
}

json_t *api_traj_invariant(struct api_call *c, const struct mech_trajectory_invariant *inv)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "name", json_string(inv->name));
    json_object_set_new_nocheck(j, "conserved", json_boolean(inv->conserved));
    if (inv->note) json_object_set_new_nocheck(j, "note", json_string(inv->note));
    json_object_set_new_nocheck(j, "initial", api_real(c, inv->initial));
    json_object_set_new_nocheck(j, "final", api_real(c, inv->final));
    json_object_set_new_nocheck(j, "max_relative_drift", api_real(c, inv->max_relative_drift));
    if (inv->is_vector) {
        json_object_set_new_nocheck(j, "initial_vector", api_vec3(c, inv->initial_vector));
        json_object_set_new_nocheck(j, "final_vector", api_vec3(c, inv->final_vector));
    }
    return j;
}

static json_t *reference_json(struct api_call *c, const struct mech_trajectory_reference_report *rf)
{
    if (rf->kind == MECH_REFERENCE_NONE) return json_null();
    json_t *j = json_object();
    json_object_set_new_nocheck(
        j, "kind", json_string(rf->kind == MECH_REFERENCE_EXACT ? "exact" : "first_order"));
    json_object_set_new_nocheck(j, "name", json_string(rf->name));
    json_object_set_new_nocheck(j, "max_position_error", api_real(c, rf->max_position_error));
    json_object_set_new_nocheck(j, "final_position_error", api_real(c, rf->final_position_error));
    json_object_set_new_nocheck(j, "max_velocity_error", api_real(c, rf->max_velocity_error));
    json_object_set_new_nocheck(j, "max_relative_position_error",
                                api_real(c, rf->max_relative_position_error));
    json_object_set_new_nocheck(j, "max_relative_velocity_error",
                                api_real(c, rf->max_relative_velocity_error));
    if (rf->kind == MECH_REFERENCE_FIRST_ORDER)
        json_object_set_new_nocheck(j, "truncation_estimate", api_real(c, rf->truncation_estimate));
    return j;
}

/* The error evidence of an answer from the closed form, in words (buf). */
static void closed_form_evidence_text(const struct mech_closed_form_evidence *ev, char *buf,
                                      size_t n)
{
    if (!strcmp(ev->solution, "kepler"))
        snprintf(buf, n,
                 "closed form: conserved invariants drift %.2g relative over the samples, "
                 "universal Kepler equation residual %.2g relative",
                 ev->max_invariant_drift, ev->max_kepler_residual);
    else if (ev->max_invariant_drift > 0.0 || strcmp(ev->solution, "uniform_gravity_linear_drag"))
        snprintf(buf, n, "closed form: conserved invariants drift %.2g relative over the samples",
                 ev->max_invariant_drift);
    else
        snprintf(buf, n,
                 "closed form with drag (nothing conserved): round-off of the expm1 forms, a few "
                 "ulps");
}

/* diagnostics of an answer from the closed form: no integrator settings, 0
 * steps, the invariants and the selection. */
static json_t *closed_form_diagnostics(struct api_call *c, const struct api_traj_request *rq,
                                       const struct mech_trajectory_result *r)
{
    json_t *d = json_object();
    if (!d) return NULL;
    json_object_set_new_nocheck(d, "method", json_string("closed_form"));
    json_object_set_new_nocheck(d, "order", json_null());
    json_object_set_new_nocheck(d, "steps", json_integer(0));
    json_object_set_new_nocheck(d, "rejected_steps", json_integer(0));
    json_object_set_new_nocheck(d, "rhs_evaluations", json_integer(0));
    json_object_set_new_nocheck(d, "evaluations", json_integer(rq->evidence.evaluations));
    json_object_set_new_nocheck(d, "invariant", api_traj_invariant(c, &r->invariant));
    json_t *invs = json_array();
    for (size_t i = 0; invs && i < r->n_invariants; i++)
        json_array_append_new(invs, api_traj_invariant(c, &r->invariants[i]));
    json_object_set_new_nocheck(d, "invariants", invs);
    json_t *ref = json_object();
    json_object_set_new_nocheck(ref, "kind", json_string("exact"));
    json_object_set_new_nocheck(ref, "name", json_string(r->reference.name));
    json_object_set_new_nocheck(
        ref, "note",
        json_string("the answer is this exact solution evaluated at each sample: its error is "
                    "round-off, see selection.achieved"));
    json_object_set_new_nocheck(d, "reference", ref);
    if (rq->p.error_estimate)
        json_object_set_new_nocheck(
            d, "error_estimate",
            json_pack("{s:s}", "skipped", "answered from the closed form: see reference"));
    json_object_set_new_nocheck(d, "selection", api_traj_selection(c, rq, r));
    return d;
}

json_t *api_traj_diagnostics(struct api_call *c, const struct api_traj_request *rq,
                             const struct mech_trajectory_result *r)
{
    const struct mech_trajectory_problem *p = &rq->p;
    if (r->method && !strcmp(r->method, "closed_form")) return closed_form_diagnostics(c, rq, r);
    json_t *d = json_object();
    if (!d) return NULL;
    struct mech_ode_method_info mi = mech_ode_method_describe(mech_ode_method_find(r->method));
    json_object_set_new_nocheck(d, "method", json_string(r->method));
    if (mi.adaptive) {
        json_object_set_new_nocheck(d, "rtol", api_real(c, p->opt.rtol));
        json_object_set_new_nocheck(d, "atol", api_real(c, p->opt.atol));
    } else {
        json_object_set_new_nocheck(d, "dt", api_real(c, p->opt.dt));
    }
    json_object_set_new_nocheck(d, "order", json_integer(mi.order));
    json_object_set_new_nocheck(d, "steps", json_integer(r->stats.steps));
    json_object_set_new_nocheck(d, "rejected_steps", json_integer(r->stats.rejected_steps));
    json_object_set_new_nocheck(d, "rhs_evaluations", json_integer(r->stats.rhs_evaluations));
    json_object_set_new_nocheck(d, "invariant", api_traj_invariant(c, &r->invariant));
    json_t *invs = json_array();
    for (size_t i = 0; invs && i < r->n_invariants; i++)
        json_array_append_new(invs, api_traj_invariant(c, &r->invariants[i]));
    json_object_set_new_nocheck(d, "invariants", invs);
    json_object_set_new_nocheck(d, "reference", reference_json(c, &r->reference));
    if (p->error_estimate) {
        const struct mech_trajectory_error_estimate *ee = &r->error_estimate;
        json_t *j = json_object();
        if (ee->done) {
            struct mech_trajectory_problem p2 = *p;
            p2.method = ee->method;
            p2.opt = ee->opt;
            json_object_set_new_nocheck(j, "settings", api_traj_settings(c, &p2));
            json_object_set_new_nocheck(j, "rule", json_string(ee->rule));
            json_object_set_new_nocheck(j, "max_position_difference",
                                        api_real(c, ee->max_position_difference));
            json_object_set_new_nocheck(j, "final_position_difference",
                                        api_real(c, ee->final_position_difference));
            json_object_set_new_nocheck(j, "max_velocity_difference",
                                        api_real(c, ee->max_velocity_difference));
            json_object_set_new_nocheck(j, "max_position_error_estimate",
                                        api_real(c, ee->max_position_error_estimate));
            json_object_set_new_nocheck(j, "steps", json_integer(ee->stats.steps));
            json_object_set_new_nocheck(j, "rhs_evaluations",
                                        json_integer(ee->stats.rhs_evaluations));
        } else {
            json_object_set_new_nocheck(
                j, "skipped", json_string("the scene has a reference solution: see reference"));
        }
        json_object_set_new_nocheck(d, "error_estimate", j);
    }
    json_object_set_new_nocheck(d, "selection", api_traj_selection(c, rq, r));
    return d;
}

json_t *api_traj_selection(struct api_call *c, const struct api_traj_request *rq,
                           const struct mech_trajectory_result *r)
{
    const struct mech_trajectory_problem *p = &rq->p;
    json_t *sel = json_object();
    json_object_set_new_nocheck(sel, "requested",
                                rq->requested ? json_deep_copy(rq->requested) : json_null());
    if (rq->closed_form) {
        json_object_set_new_nocheck(sel, "method", json_string("closed_form"));
    } else {
        json_t *set = api_traj_settings(c, p);
        json_object_update(sel, set);
        json_decref(set);
    }
    if (!rq->chosen) {
        json_object_set_new_nocheck(sel, "reason",
                                    json_string("method and settings given in the request"));
        return sel;
    }
    json_object_set_new_nocheck(sel, "target_error", api_real(c, rq->choice.target));
    char why[sizeof rq->choice.reason + 160];
    snprintf(why, sizeof why, "%s%s%s",
             rq->requested ? "" : "no integrator block: accuracy \"balanced\" by default; ",
             rq->choice.reason,
             rq->dry_run && rq->auto_model
                 ? "; dry run: \"fictitious\": \"auto\" not resolved (it needs a first pass), "
                   "every applicable term assumed"
                 : "");
    json_object_set_new_nocheck(sel, "reason", json_string(why));
    api_selection_predictions(c, &rq->choice.sel, sel);
    if (r && rq->choice.sel.chosen >= 0) {
        const struct mech_candidate *k = &rq->choice.sel.c[rq->choice.sel.chosen];
        double err = -1.0;
        const char *ev = "none";
        char evbuf[240];
        if (rq->closed_form) {
            err = rq->evidence.error_bound;
            closed_form_evidence_text(&rq->evidence, evbuf, sizeof evbuf);
            ev = evbuf;
        } else if (r->reference.kind == MECH_REFERENCE_EXACT) {
            err = fmax(r->reference.max_relative_position_error,
                       r->reference.max_relative_velocity_error);
            ev = "exact reference (diagnostics.reference), max over the samples";
        } else if (r->error_estimate.done && r->max_radius > 0.0) {
            err = r->error_estimate.max_position_error_estimate / r->max_radius;
            ev = "error_estimate's second run: max position difference / max |r|";
        } else if (r->reference.kind == MECH_REFERENCE_FIRST_ORDER) {
            ev = "none: the reference is first order in the rotation rate (see "
                 "diagnostics.reference), not exact";
        }
        json_object_set_new_nocheck(sel, "achieved",
                                    api_selection_achieved(c, k, rq->choice.target, err, ev,
                                                           rq->cpu_s));
    }
    return sel;
}

json_t *api_traj_dry_run(struct api_call *c, const struct api_traj_request *rq)
{
    return api_dry_run_answer(c, api_traj_selection(c, rq, NULL));
}

