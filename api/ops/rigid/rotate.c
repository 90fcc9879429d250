/* rotate.c — POST /v1/rigid/rotate: a rigid body's free or torqued
 * rotation by Euler's equations with a quaternion attitude (notes §2.7–2.9),
 * with conserved-quantity drifts and, torque-free, the error against the exact
 * solution in Jacobi elliptic functions. The physics is core/rigid/rigid_rotation.c;
 * the run is one call of mech_rigid_answer_run (core/answers/rigid/rigid_answer.c);
 * the body may be given by principal moments or by a full /v1/rigid/inertia
 * request (its schema inlined into this route's by the build, so the
 * validator checks it with the rest of the body), read and computed as that
 * route does (api/ops/rigid/inertia_request.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "catalog/catalog.h"
#include "ops/rigid/inertia_request.h"
#include "request/integrator_block.h"
#include "mech/frames/closed_form.h"
#include "mech/rotation/attitude.h"
#include "mech/answers/rigid/rigid_answer.h"
#include "mech/rigid/rigid_rotation.h"
#include "mech/rotation/rotation.h"
#include "request/rotation_request.h"
#include "request/trajectory_request.h"

/* ---- helpers -------------------------------------------------------------------- */

/* The body of the /v1/rigid/inertia request `in` (validated and its defaults
 * filled with the rest of the body: api/ops/rigid/rotate.json takes that
 * route's request schema for "inertia"; read and computed by
 * api/ops/rigid/inertia_request.c): principal moments (kg m^2, ascending) and axes
 * (rows, scene axes) out. Returns 1; 0 after recording errors in c (pointers
 * under /inertia; a budget, numerical or internal failure as "inertia: ..."). */
static int inertia_principal(struct api_call *c, const json_t *in, double moments[3],
                             struct mech_mat3 *axes)
{
    /* the body read and computed as /v1/rigid/inertia does (api/ops/rigid/inertia_request.c),
     * its errors collected apart and then reported under /inertia */
    struct api_call sub;
    memset(&sub, 0, sizeof sub);
    sub.req = c->req;
    sub.given = json_object_get(c->given, "inertia");
    sub.body = in;
    sub.budget = c->budget;
    struct api_inertia_body b;
    memset(&b, 0, sizeof b);
    int ok = api_inertia_body_compute(&sub, in, &b) && sub.problem == API_PROBLEM_NONE &&
             api_inertia_body_finite(&b);
    if (!ok) {
        size_t ne = json_array_size(sub.errors);
        for (size_t i = 0; i < ne; i++) {
            const json_t *er = json_array_get(sub.errors, i);
            char ptr[300];
            snprintf(ptr, sizeof ptr, "/inertia%s",
                     json_string_value(json_object_get(er, "pointer")));
            const char *d = json_string_value(json_object_get(er, "detail"));
            if (sub.problem == API_PROBLEM_DOMAIN)
                api_call_domain(c, ptr, "%s", d);
            else
                api_call_invalid(c, ptr, "%s", d);
        }
        if (ne == 0) {
            if (c->problem == API_PROBLEM_NONE)
                c->problem = sub.problem != API_PROBLEM_NONE ? sub.problem : API_PROBLEM_NUMERIC;
            snprintf(c->detail, sizeof c->detail, "inertia: %.200s",
                     sub.detail[0] ? sub.detail : "the inertia tensor is not finite");
            if (sub.extra && !c->extra) {
                c->extra = sub.extra;
                sub.extra = NULL;
            }
        }
    } else {
        /* as the inertia answer gives them: -0 reads as 0 (api_real) */
        const struct mech_inertia_principal *pr = &b.result.principal;
        for (size_t k = 0; k < 3; k++)
            moments[k] = pr->moments[k] == 0 ? 0.0 : pr->moments[k];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                axes->a[i][j] = pr->axes.a[i][j] == 0 ? 0.0 : pr->axes.a[i][j];
    }
    api_inertia_body_free(&b);
    json_decref(sub.errors);
    json_decref(sub.extra);
    return ok;
}

static json_t *invariant(struct api_call *c, const char *name, int conserved, double initial,
                         double final, double drift)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "name", json_string(name));
    json_object_set_new_nocheck(j, "conserved", json_boolean(conserved));
    json_object_set_new_nocheck(j, "initial", api_real(c, initial));
    json_object_set_new_nocheck(j, "final", api_real(c, final));
    json_object_set_new_nocheck(j, "max_relative_drift", api_real(c, drift));
    return j;
}

static const char *kind_name(enum mech_rigid_exact_kind k)
{
    switch (k) {
    case MECH_RIGID_EXACT_SYMMETRIC:
        return "symmetric";
    case MECH_RIGID_EXACT_ELLIPTIC:
        return "elliptic";
    case MECH_RIGID_EXACT_SEPARATRIX:
        return "separatrix";
    default:
        return "steady";
    }
}

/* diagnostics.selection of an answer from the closed form: the chooser's
 * selection (candidates with predictions, closed_form chosen) and the
 * closed form's evidence as `achieved`. */
static json_t *closed_form_selection(struct api_call *c, const struct api_integrator_choice *ch,
                                     const struct mech_rigid_closed_form_evidence *ev)
{
    char evid[200];
    snprintf(evid, sizeof evid,
             "closed form (%s): kinetic energy, |L| and the L vector in space drift %.2g "
             "relative over the samples",
             ev->solution, ev->max_invariant_drift);
    json_t *sel = api_integrator_block_selection_achieved(c, ch, ev->error_bound, evid, 0.0);
    json_t *ach = sel ? json_object_get(sel, "achieved") : NULL;
    if (ach) json_object_set_new_nocheck(ach, "evaluations", json_integer(ev->evaluations));
    return sel;
}

/* ---- reading the request ------------------------------------------------------------ */

/* The principal moments, from "moments" or the "inertia" request (its axes
 * into *P, else identity). Returns 1; 0 after recording an error. */
static int read_moments(struct api_call *c, const json_t *body, struct mech_rigid_problem *p,
                        struct mech_mat3 *P)
{
    const json_t *mj = json_object_get(body, "moments"), *ij = json_object_get(body, "inertia");
    if ((mj != NULL) == (ij != NULL)) {
        api_call_invalid(c, mj ? "/inertia" : "/moments",
                         "give exactly one of moments and inertia");
        return 0;
    }
    *P = mech_mat3_identity();
    if (mj) {
        for (size_t k = 0; k < 3; k++)
            p->moments[k] = json_number_value(json_array_get(mj, k));
    } else if (!inertia_principal(c, ij, p->moments, P)) {
        return 0;
    }
    if (ij && !(p->moments[0] > 0 && p->moments[1] > 0 && p->moments[2] > 0)) {
        api_call_domain(c, "/inertia",
                        "the body's principal moments (%.17g, %.17g, %.17g) include 0 (a thin rod "
                        "or point masses on a line): Euler's equations need all three > 0",
                        p->moments[0], p->moments[1], p->moments[2]);
        return 0;
    }
    return 1;
}

/* omega, the orientation and the torque: body axes (moments) or the built
 * body's axes P (inertia); t_end and samples. Returns 0 after recording an
 * error (the orientation's, naming the field). */
static int read_motion(struct api_call *c, const json_t *body, const struct mech_mat3 *P,
                       struct mech_rigid_problem *p)
{
    p->omega = mech_mat3_mul_vec(*P, api_vec3_member(body, "omega", mech_vec3_make(0, 0, 0)));
    struct mech_mat3 R0 = mech_mat3_identity();
    const json_t *oj = json_object_get(body, "orientation");
    if (oj) {
        struct api_rotation rot;
        if (api_rotation_read(c, oj, "/orientation", MECH_ROTATION_PASSIVE, &rot) != 0) return 0;
        api_rotation_set_sense(&rot, MECH_ROTATION_PASSIVE);
        R0 = rot.matrix;
    }
    mech_attitude_from_matrix(mech_mat3_mul(*P, R0), p->q0);
    const json_t *tj = json_object_get(body, "torque");
    if (tj) {
        p->torque_frame = !strcmp(api_string(tj, "frame", "body"), "space")
                              ? MECH_RIGID_TORQUE_SPACE
                              : MECH_RIGID_TORQUE_BODY;
        p->torque = api_vec3_member(tj, "value", mech_vec3_make(0, 0, 0));
        /* a body torque with inertia: given in the built body's axes */
        if (p->torque_frame == MECH_RIGID_TORQUE_BODY) p->torque = mech_mat3_mul_vec(*P, p->torque);
    }
    p->t_end = api_number(body, "t_end", 1);
    p->samples = (size_t)api_number_of(body, "samples");
    return 1;
}

/* The integrator block: a method, or by accuracy with the closed form a
 * candidate when torque-free off the separatrix (core/ode/chooser.c).
 * Returns 0 after recording an error. */
static int choose_method(struct api_call *c, const json_t *body, const struct mech_rigid_problem *p,
                         struct api_integrator_choice *ch)
{
    const double W = mech_rigid_rate_scale(p);
    static const struct api_integrator_system euler_eqs = {
        "Euler's equations with a quaternion attitude",
        "the dimensionless state (quaternion and omega / rate scale)", 1.0, 0, 0.0, "rigid_body", 0};
    struct api_integrator_system sys = euler_eqs;
    sys.samples = p->samples;
    /* the closed form's own cost: its quadrature (core/rigid/rigid_closed_form.c) */
    const struct api_integrator_hooks hooks = {0.0, mech_rigid_closed_form_predict_evaluations(p),
                                               MECH_RIGID_CLOSED_FORM_CPU_PER_EVAL, NULL, 0.0};
    return api_integrator_block_parse_hooks(
        c, json_object_get(body, "integrator"), "/integrator", p->t_end * W, &sys,
        mech_rigid_has_closed_form(p) ? "torque-free rigid body" : NULL, &hooks, ch);
}

/* ---- encoding the answer ------------------------------------------------------------ */

/* moments, principal_axes (inertia), and the samples. */
static json_t *encode_samples(struct api_call *c, const struct mech_rigid_problem *p,
                              const struct mech_mat3 *P, int inertia,
                              const struct mech_rigid_result *r)
{
    json_t *out = json_object();
    json_object_set_new_nocheck(out, "moments", api_reals(c, p->moments, 3));
    if (inertia) json_object_set_new_nocheck(out, "principal_axes", api_mat3(c, *P));
    json_object_set_new_nocheck(out, "t", api_reals(c, r->t, r->n_samples));
    json_t *ja = json_array(), *jq = json_array(), *jl = json_array();
    for (size_t i = 0; i < r->n_samples; i++) {
        json_array_append_new(ja, api_vec3(c, r->omega[i]));
        json_array_append_new(jq, api_reals(c, r->quaternion + 4 * i, 4));
        json_array_append_new(jl, api_vec3(c, r->angular_momentum[i]));
    }
    json_object_set_new_nocheck(out, "omega", ja);
    json_object_set_new_nocheck(out, "orientation", jq);
    json_object_set_new_nocheck(out, "angular_momentum", jl);
    json_object_set_new_nocheck(out, "kinetic_energy",
                                api_reals(c, r->kinetic_energy, r->n_samples));
    json_object_set_new_nocheck(out, "rate_scale", api_real(c, r->rate_scale));
    return out;
}

/* diagnostics' method and counts: the closed form's, or the integrator's. */
static void encode_method(struct api_call *c, json_t *d, const struct api_integrator_choice *ch,
                          const struct mech_rigid_answer *a)
{
    if (!a->closed) {
        api_integrator_block_stats(c, d, ch, &a->r.stats);
        return;
    }
    json_object_set_new_nocheck(d, "method", json_string("closed_form"));
    json_object_set_new_nocheck(d, "order", json_null());
    json_object_set_new_nocheck(d, "steps", json_integer(0));
    json_object_set_new_nocheck(d, "rejected_steps", json_integer(0));
    json_object_set_new_nocheck(d, "rhs_evaluations", json_integer(0));
    json_object_set_new_nocheck(d, "evaluations", json_integer(a->ev.evaluations));
}

/* T, |L| and, unless a body torque acts, the L vector against its reference. */
static json_t *encode_invariants(struct api_call *c, const struct mech_rigid_problem *p,
                                 const struct mech_rigid_result *r)
{
    const size_t last = r->n_samples - 1;
    const struct mech_vec3 Lf = r->angular_momentum[last];
    json_t *inv = json_array();
    json_array_append_new(inv, invariant(c, "kinetic_energy", r->torque_free, r->T0,
                                         r->kinetic_energy[last], r->max_T_drift));
    json_array_append_new(inv, invariant(c, "angular_momentum_norm", r->torque_free,
                                         mech_vec3_norm(r->L0), mech_vec3_norm(Lf),
                                         r->max_L_norm_drift));
    if (p->torque_frame != MECH_RIGID_TORQUE_BODY || r->torque_free) {
        json_t *lv = invariant(c, "angular_momentum_vector", r->torque_free, mech_vec3_norm(r->L0),
                               mech_vec3_norm(Lf), r->max_L_vector_drift);
        json_object_set_new_nocheck(lv, "reference",
                                    json_string(r->torque_free
                                                    ? "L0 (no torque)"
                                                    : "L0 + torque t (constant space torque)"));
        json_object_set_new_nocheck(lv, "initial_vector", api_vec3(c, r->L0));
        json_object_set_new_nocheck(lv, "final_vector", api_vec3(c, Lf));
        json_array_append_new(inv, lv);
    }
    return inv;
}

/* diagnostics.reference: the exact torque-free solution and the errors
 * against it, or null. */
static json_t *encode_reference(struct api_call *c, const struct mech_rigid_answer *a)
{
    const struct mech_rigid_result *r = &a->r;
    if (!r->has_exact) return json_null();
    const struct mech_rigid_exact *x = &r->exact;
    json_t *rf = json_object();
    json_object_set_new_nocheck(rf, "kind", json_string("exact"));
    json_object_set_new_nocheck(rf, "name", json_string("torque_free_rigid_body"));
    json_object_set_new_nocheck(rf, "solution", json_string(kind_name(x->kind)));
    if (x->kind == MECH_RIGID_EXACT_SYMMETRIC) {
        json_object_set_new_nocheck(rf, "precession_rate", api_real(c, x->lambda));
        json_object_set_new_nocheck(rf, "period", api_real(c, x->period));
    } else if (x->kind == MECH_RIGID_EXACT_ELLIPTIC || x->kind == MECH_RIGID_EXACT_SEPARATRIX) {
        json_object_set_new_nocheck(rf, "lambda", api_real(c, x->lambda));
        json_object_set_new_nocheck(rf, "modulus_squared", api_real(c, x->m));
        json_object_set_new_nocheck(
            rf, "L2_greater_than_2EI2",
            json_boolean(x->kind == MECH_RIGID_EXACT_ELLIPTIC && x->cn_axis == 0));
        if (x->kind == MECH_RIGID_EXACT_ELLIPTIC) {
            json_object_set_new_nocheck(rf, "K", api_real(c, x->K));
            json_object_set_new_nocheck(rf, "period", api_real(c, x->period));
        }
    }
    json_object_set_new_nocheck(rf, "max_omega_error", api_real(c, r->max_omega_error));
    json_object_set_new_nocheck(rf, "max_relative_omega_error",
                                api_real(c, r->max_relative_omega_error));
    json_object_set_new_nocheck(rf, "final_omega_error", api_real(c, r->final_omega_error));
    if (a->closed)
        json_object_set_new_nocheck(
            rf, "note",
            json_string("the answer is this exact solution (omega and the attitude) evaluated "
                        "at each sample: its error is round-off, see selection.achieved"));
    return rf;
}

/* flip: the intermediate-axis flips of an elliptic motion (NULL otherwise). */
static json_t *encode_flip(struct api_call *c, const struct mech_rigid_result *r)
{
    if (!r->has_exact || r->exact.kind != MECH_RIGID_EXACT_ELLIPTIC) return NULL;
    json_t *f = json_object();
    json_object_set_new_nocheck(f, "exact_period", api_real(c, r->exact.period));
    json_object_set_new_nocheck(f, "exact_flip_interval", api_real(c, r->exact.flip_interval));
    json_object_set_new_nocheck(f, "sign_changes_seen", json_integer(r->flips));
    json_object_set_new_nocheck(f, "measured_period",
                                r->flips >= 2 ? api_real(c, r->measured_period) : json_null());
    return f;
}

/* The whole answer of a run that succeeded. */
static json_t *encode_answer(struct api_call *c, const struct mech_rigid_problem *p,
                             const struct mech_mat3 *P, int inertia,
                             const struct api_integrator_choice *ch,
                             const struct mech_rigid_answer *a)
{
    json_t *out = encode_samples(c, p, P, inertia, &a->r);
    json_t *d = json_object();
    encode_method(c, d, ch, a);
    json_object_set_new_nocheck(d, "invariants", encode_invariants(c, p, &a->r));
    json_object_set_new_nocheck(d, "quaternion_norm_drift",
                                api_real(c, a->r.max_quaternion_norm_drift));
    json_object_set_new_nocheck(d, "reference", encode_reference(c, a));
    json_object_set_new_nocheck(d, "selection",
                                a->closed ? closed_form_selection(c, ch, &a->ev)
                                          : api_integrator_block_selection_run(
                                                c, ch,
                                                a->r.has_exact ? a->r.max_relative_omega_error
                                                               : -1.0,
                                                "the exact torque-free solution "
                                                "(diagnostics.reference): max |omega - exact| "
                                                "/ |omega0| over the samples",
                                                0));
    json_t *ach = json_object_get(json_object_get(d, "selection"), "achieved");
    if (ach) /* the schema's count: the run's own right-hand sides */
        json_object_set_new_nocheck(ach, "evaluations",
                                    json_integer((json_int_t)a->r.stats.rhs_evaluations));
    json_object_set_new_nocheck(out, "diagnostics", d);
    json_t *f = encode_flip(c, &a->r);
    if (f) json_object_set_new_nocheck(out, "flip", f);
    json_object_set_new_nocheck(out, "cost", json_object());
    return out;
}

/* ---- handler ---------------------------------------------------------------------- */

json_t *api_op_rigid_rotate(struct api_call *c, const json_t *body)
{
    const int inertia = json_object_get(body, "inertia") != NULL;
    struct mech_rigid_problem p;
    memset(&p, 0, sizeof p);
    struct mech_mat3 P;
    struct api_integrator_choice ch;
    if (!read_moments(c, body, &p, &P) || !read_motion(c, body, &P, &p) ||
        !choose_method(c, body, &p, &ch))
        return NULL;
    if (api_dry_run_requested(body))
        return api_dry_run_answer(c, api_integrator_block_selection(c, &ch));
    p.method = ch.method;
    p.opt = ch.opt;
    /* by accuracy, torque-free and off the separatrix: the chooser picks the
     * closed form when allowed and predicted cheaper */
    struct mech_rigid_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st =
        mech_rigid_answer_run(&p, ch.chosen && ch.mc.closed_form, &c->budget, &a, &e);
    json_t *out = NULL;
    if (st == MECH_OK) {
        out = encode_answer(c, &p, &P, inertia, &ch, &a);
    } else if (inertia && !strcmp(e.param, "moments")) {
        e.param[0] = 0; /* the built body's moments: the inertia request's */
        api_call_fail_core(c, st, &e, "/inertia");
    } else {
        api_call_fail_core(c, st, &e, "");
    }
    mech_rigid_answer_free(&a);
    return out;
}
