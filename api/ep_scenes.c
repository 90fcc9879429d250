/* ep_scenes.c — POST /v1/scenes/falling-object, /vertical-shot, /cannonball
 * and /rotating-table: the notes' chapter-1 scenes (core/frames/scenes.c), each
 * answering the numerical result (fictitious terms chosen by "auto" at the
 * requested accuracy) beside the notes' first-order formula, their
 * difference and the second-order terms the formula neglects. The closed
 * forms quoted beside them are core/frames/scenes_first_order.c; the
 * rotating table's checks, buffers and run are one call,
 * mech_rotating_table_scene() (core/frames/rotating_table_scene.c); this
 * file reads requests and encodes answers. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "earth_rotation.h"
#include "endpoint.h"
#include "mech/base/constants.h"
#include "mech/answers/frames/rotating_table_scene.h"
#include "mech/frames/scenes.h"
#include "mech/frames/scenes_first_order.h"
#include "mech/frames/trajectory.h"
#include "integrator_block.h"
#include "trajectory_request.h"

/* ---- shared request readers -------------------------------------------------- */

/* The relative accuracy asked for; 0 after recording an error. */
static double scene_target(struct api_call *c, const json_t *body)
{
    const json_t *te = json_object_get(body, "target_error");
    /* accuracy always has a value (its default); an error only when both were given */
    const char *acc = api_string_of(body, "accuracy");
    if (te && api_call_given(c, "/accuracy")) {
        api_call_invalid(c, "/target_error", "give accuracy or target_error, not both");
        return 0.0;
    }
    return mech_accuracy_target(te != NULL, json_number_value(te), acc, NULL);
}

/* A request-like view of a core scene run, for the shared model/diagnostics encoders. */
static void scene_rq(struct api_traj_request *rq, const struct mech_trajectory_problem *p,
                     const struct mech_trajectory_model *m, const struct mech_trajectory_choice *ch,
                     const char *accuracy)
{
    memset(rq, 0, sizeof *rq);
    rq->p = *p;
    for (size_t i = 0; i < p->n_forces && i < MECH_TRAJECTORY_MAX_FORCES; i++)
        rq->forces[i] = p->forces[i];
    api_traj_request_fix(rq);
    rq->requested = NULL;
    rq->chosen = 1;
    rq->accuracy = accuracy;
    rq->choice = *ch;
    rq->auto_model = 1;
    rq->model = *m;
}

/* {"t", "east", "north"} (+ "south" or firing-direction components). */
static json_t *landing_json(struct api_call *c, const struct mech_scene_landing *l, int south,
                            const struct mech_vec3 *fwd)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "t", api_real(c, l->t));
    json_object_set_new_nocheck(j, "east", api_real(c, l->r.x));
    json_object_set_new_nocheck(j, "north", api_real(c, l->r.y));
    if (south) json_object_set_new_nocheck(j, "south", api_real(c, -l->r.y));
    if (fwd) {
        /* along the firing direction, and to its right (f x z) */
        json_object_set_new_nocheck(j, "range", api_real(c, l->r.x * fwd->x + l->r.y * fwd->y));
        json_object_set_new_nocheck(j, "right", api_real(c, l->r.x * fwd->y - l->r.y * fwd->x));
    }
    return j;
}

static json_t *ballistic_answer(struct api_call *c, const char *scene,
                                struct mech_scene_ballistic_result *r, json_t *parameters,
                                json_t *formula, int south, const struct mech_vec3 *fwd,
                                const char *accuracy)
{
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "scene", json_string(scene));
    json_object_set_new_nocheck(res, "parameters", parameters);
    json_object_set_new_nocheck(res, "numerical", landing_json(c, &r->numerical, south, fwd));
    json_t *fo = landing_json(c, &r->first_order, south, fwd);
    json_object_set_new_nocheck(fo, "formula", formula);
    json_object_set_new_nocheck(res, "first_order", fo);
    json_object_set_new_nocheck(res, "difference", landing_json(c, &r->difference, south, fwd));
    json_t *so = landing_json(c, &r->second_order, south, fwd);
    json_object_set_new_nocheck(so, "coriolis", landing_json(c, &r->second_coriolis, south, fwd));
    json_object_set_new_nocheck(so, "centrifugal",
                                landing_json(c, &r->second_centrifugal, south, fwd));
    json_object_set_new_nocheck(
        so, "centrifugal_modelled",
        json_boolean((r->problem.fictitious & MECH_FICTITIOUS_CENTRIFUGAL) != 0));
    json_object_set_new(
        so, "derivation",
        json_string(
            "landing of the series r_0 + r_1 + r_2 (r_2 = 2 w x (w x (v0 t^3/3 + g t^4/12)) "
            "from Coriolis acting on the first-order velocity, and - w x (w x (r0 t^2/2 + "
            "v0 t^3/6 + g t^4/24)) from the centrifugal term of the displacement when it "
            "is modelled), its landing time solved exactly, minus the first-order landing"));
    json_object_set_new_nocheck(res, "second_order", so);
    json_object_set_new_nocheck(res, "unexplained", landing_json(c, &r->unexplained, south, fwd));
    const double dh = hypot(r->difference.r.x, r->difference.r.y);
    const double sh = hypot(r->second_order.r.x, r->second_order.r.y);
    const double uh = hypot(r->unexplained.r.x, r->unexplained.r.y);
    json_t *q = json_object();
    json_object_set_new_nocheck(q, "difference_horizontal", api_real(c, dh));
    json_object_set_new_nocheck(q, "second_order_horizontal", api_real(c, sh));
    json_object_set_new_nocheck(q, "unexplained_horizontal", api_real(c, uh));
    json_object_set_new_nocheck(q, "integration_tolerance", api_real(c, r->integration_tolerance));
    json_object_set_new_nocheck(q, "within_second_order",
                                json_boolean(dh <= 2.0 * sh + r->integration_tolerance));
    json_object_set_new_nocheck(
        q, "rule",
        json_string("within_second_order: |numerical - first_order| <= 2 "
                    "|second_order| + integration_tolerance (horizontal); "
                    "unexplained = difference - second_order is third order in w "
                    "plus the integration error"));
    json_object_set_new_nocheck(res, "agreement", q);
    struct api_traj_request rq;
    scene_rq(&rq, &r->problem, &r->model, &r->choice, accuracy);
    json_object_set_new_nocheck(res, "model", api_traj_model(c, &rq, &r->run));
    json_object_set_new_nocheck(res, "diagnostics", api_traj_diagnostics(c, &rq, &r->run));
    return res;
}

static const char *accuracy_name(const json_t *body)
{
    return json_object_get(body, "target_error") ? NULL : api_string_of(body, "accuracy");
}

/* 0 after recording an error (both omega_magnitude and sidereal_day). */
static int earth_params(struct api_call *c, const json_t *body, struct mech_scene_ballistic *s)
{
    memset(s, 0, sizeof *s);
    s->latitude_deg = api_number(body, "latitude_deg", 0);
    s->g = api_number_of(body, "g");
    return api_earth_rotation(c, body, "", "omega_magnitude", MECH_EARTH_OMEGA_SIDEREAL, &s->omega);
}

static json_t *run_ballistic(struct api_call *c, const json_t *body, const char *scene,
                             const struct mech_scene_ballistic *s, json_t *parameters,
                             json_t *formula, int south, const struct mech_vec3 *fwd, double target)
{
    struct mech_scene_ballistic_result *r = malloc(sizeof *r);
    if (!r) {
        json_decref(parameters);
        json_decref(formula);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_scene_ballistic sd = *s;
    sd.dry_run = api_dry_run_requested(body);
    enum mech_status st = mech_scene_ballistic_run(&sd, target, &c->budget, r, &e);
    if (st != MECH_OK) {
        free(r);
        json_decref(parameters);
        json_decref(formula);
        /* parameter names of the core map onto the request's */
        if (!strcmp(e.param, "omega")) snprintf(e.param, sizeof e.param, "omega_magnitude");
        if (!strcmp(e.param, "r0") || !strcmp(e.param, "v0")) e.param[0] = '\0';
        return api_call_fail_core(c, st, &e, "");
    }
    mech_scene_ballistic_fix(r);
    if (sd.dry_run) {
        struct api_traj_request rq;
        scene_rq(&rq, &r->problem, &r->model, &r->choice, accuracy_name(body));
        rq.dry_run = 1;
        json_decref(parameters);
        json_decref(formula);
        json_t *res = api_dry_run_answer(c, api_traj_selection(c, &rq, NULL));
        free(r);
        return res;
    }
    json_t *res =
        ballistic_answer(c, scene, r, parameters, formula, south, fwd, accuracy_name(body));
    free(r);
    return res;
}

/* ---- falling object ---------------------------------------------------------- */

json_t *api_op_scenes_falling_object(struct api_call *c, const json_t *body)
{
    double target = scene_target(c, body);
    if (!(target > 0.0)) return NULL;
    struct mech_scene_ballistic s;
    if (!earth_params(c, body, &s)) return NULL;
    const double h = api_number(body, "height", 0);
    s.r0 = mech_vec3_make(0, 0, h);
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "height", api_real(c, h));
    json_object_set_new_nocheck(par, "latitude_deg", api_real(c, s.latitude_deg));
    json_object_set_new_nocheck(par, "g", api_real(c, s.g));
    json_object_set_new_nocheck(par, "omega_magnitude", api_real(c, s.omega));
    json_object_set_new_nocheck(par, "target_error", api_real(c, target));
    json_t *f = json_string("x_east = (W cos(lat) / 3) sqrt(8 h^3 / g), t = sqrt(2 h / g), no "
                            "north-south deflection (notes §1.4)");
    return run_ballistic(c, body, "falling-object", &s, par, f, 1, NULL, target);
}

/* ---- vertical shot ------------------------------------------------------------ */

json_t *api_op_scenes_vertical_shot(struct api_call *c, const json_t *body)
{
    double target = scene_target(c, body);
    if (!(target > 0.0)) return NULL;
    struct mech_scene_ballistic s;
    if (!earth_params(c, body, &s)) return NULL;
    const int has_v = json_object_get(body, "speed") != NULL;
    const int has_h = json_object_get(body, "height") != NULL;
    if (has_v == has_h) {
        api_call_invalid(c, "", "give exactly one of speed and height");
        return NULL;
    }
    const double v0 = has_v ? api_number(body, "speed", 0)
                            : mech_scene_vertical_shot_speed(api_number(body, "height", 0), s.g);
    struct mech_scene_vertical_shot_first_order fo;
    mech_scene_vertical_shot_first_order(v0, s.g, s.omega, s.latitude_deg, &fo);
    s.v0 = mech_vec3_make(0, 0, v0);
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "speed", api_real(c, v0));
    json_object_set_new_nocheck(par, "height", api_real(c, fo.height));
    json_object_set_new_nocheck(par, "latitude_deg", api_real(c, s.latitude_deg));
    json_object_set_new_nocheck(par, "g", api_real(c, s.g));
    json_object_set_new_nocheck(par, "omega_magnitude", api_real(c, s.omega));
    json_object_set_new_nocheck(par, "target_error", api_real(c, target));
    json_object_set_new_nocheck(par, "drop_deflection_east", api_real(c, fo.drop_east));
    json_t *f = json_string("x_west = (4/3) W cos(lat) sqrt(8 h^3 / g), t = 2 v0 / g (notes §1.5 "
                            "problem 3): 4 x the drop's eastward deflection for the same height");
    return run_ballistic(c, body, "vertical-shot", &s, par, f, 0, NULL, target);
}

/* ---- cannonball ---------------------------------------------------------------- */

json_t *api_op_scenes_cannonball(struct api_call *c, const json_t *body)
{
    double target = scene_target(c, body);
    if (!(target > 0.0)) return NULL;
    struct mech_scene_ballistic s;
    if (!earth_params(c, body, &s)) return NULL;
    const double v0 = api_number(body, "speed", 0);
    const double g = s.g, W = s.omega;
    struct mech_scene_cannonball_first_order fo;
    mech_scene_cannonball_first_order(v0, api_number(body, "elevation_deg", 0),
                                      api_number_of(body, "azimuth_deg"), g, W, s.latitude_deg,
                                      &fo);
    const struct mech_vec3 fwd = fo.forward;
    s.v0 = fo.velocity;
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "speed", api_real(c, v0));
    json_object_set_new_nocheck(par, "elevation_deg", api_real(c, fo.elevation * 180.0 / MECH_PI));
    json_object_set_new_nocheck(par, "azimuth_deg", api_real(c, fo.azimuth * 180.0 / MECH_PI));
    json_object_set_new_nocheck(par, "latitude_deg", api_real(c, s.latitude_deg));
    json_object_set_new_nocheck(par, "g", api_real(c, g));
    json_object_set_new_nocheck(par, "omega_magnitude", api_real(c, W));
    json_object_set_new_nocheck(par, "target_error", api_real(c, target));
    json_object_set_new_nocheck(par, "velocity", api_vec3(c, s.v0));
    json_t *f = json_string("r_1(T0) - v_h z_1(T0) / z_0'(T0) with r_1 = -w x (v0 t^2 + g t^3/3), "
                            "T0 = 2 v0 sin(alpha) / g (notes §1.4, homework §1.5 problems 4-5)");
    json_t *res = run_ballistic(c, body, "cannonball", &s, par, f, 0, &fwd, target);
    if (!res) return NULL;
    /* the no-rotation landing and the notes' due-east formulas (core) */
    json_t *z = json_object();
    json_object_set_new_nocheck(z, "t", api_real(c, fo.t0));
    json_object_set_new_nocheck(z, "range", api_real(c, fo.range));
    json_object_set_new_nocheck(res, "zeroth_order", z);
    json_t *ne = json_object();
    json_object_set_new_nocheck(ne, "south_deflection", api_real(c, fo.south_due_east));
    json_object_set_new_nocheck(ne, "range_increase", api_real(c, fo.range_increase_due_east));
    json_object_set_new_nocheck(
        ne, "formula",
        json_string("notes §1.5 problems 4-5 (firing due east): d = 4 v0^3 W "
                    "sin(lat) sin^2(alpha) cos(alpha) / g^2 south; dR = W cos(lat) "
                    "sqrt(2 R^3 / g) (cot^1/2 alpha - tan^3/2 alpha / 3)"));
    json_object_set_new_nocheck(res, "notes_due_east", ne);
    return res;
}

/* ---- rotating table -------------------------------------------------------------- */

static json_t *vecs_json(struct api_call *c, const struct mech_vec3 *v, size_t n)
{
    json_t *a = json_array();
    for (size_t i = 0; a && i < n; i++)
        json_array_append_new(a, api_vec3(c, v[i]));
    return a;
}

/* The answer of a table run (not a dry run). */
static json_t *table_answer(struct api_call *c, const struct mech_rotating_table_scene *s,
                            const char *accuracy)
{
    const struct mech_scene_table_result *r = &s->result;
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "scene", json_string("rotating-table"));
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "experiment", json_string(s->experiment));
    json_object_set_new_nocheck(par, "omega", api_real(c, s->scene.omega));
    json_object_set_new_nocheck(par, "mass", api_real(c, s->scene.mass));
    if (s->scene.experiment != MECH_TABLE_CUSTOM)
        json_object_set_new_nocheck(par, "radius", api_real(c, s->scene.radius));
    json_object_set_new_nocheck(par, "t_end", api_real(c, r->t_end));
    json_object_set_new_nocheck(par, "target_error", api_real(c, s->target));
    json_object_set_new_nocheck(res, "parameters", par);
    json_t *init = json_object();
    json_object_set_new_nocheck(init, "position", api_vec3(c, r->r0_inertial));
    json_object_set_new_nocheck(init, "velocity_inertial", api_vec3(c, r->v0_inertial));
    json_object_set_new_nocheck(init, "velocity_rotating", api_vec3(c, r->v0_rotating));
    json_object_set_new_nocheck(res, "initial", init);
    json_t *f = json_object();
    json_object_set_new_nocheck(f, "centrifugal", api_vec3(c, r->centrifugal));
    json_object_set_new_nocheck(f, "coriolis", api_vec3(c, r->coriolis));
    json_object_set_new_nocheck(f, "total", api_vec3(c, r->total));
    json_object_set_new_nocheck(res, "effective_force_at_start", f);
    json_object_set_new_nocheck(res, "t", api_reals(c, r->t, r->n_samples));
    json_object_set_new_nocheck(res, "inertial", vecs_json(c, r->inertial, r->n_samples));
    json_object_set_new_nocheck(res, "rotating", vecs_json(c, r->rotating, r->n_samples));
    json_object_set_new_nocheck(res, "rotating_exact",
                                vecs_json(c, r->rotating_exact, r->n_samples));
    json_object_set_new_nocheck(res, "end_rotating", api_vec3(c, r->end_rotating));
    json_t *err = json_object();
    json_object_set_new_nocheck(err, "max_position_error", api_real(c, r->max_position_error));
    json_object_set_new_nocheck(err, "max_relative_position_error",
                                api_real(c, r->max_relative_position_error));
    json_object_set_new_nocheck(res, "rotating_vs_exact", err);
    struct api_traj_request rq;
    scene_rq(&rq, &r->problem, &r->model, &r->choice, accuracy);
    json_object_set_new_nocheck(res, "model", api_traj_model(c, &rq, &r->run));
    json_object_set_new_nocheck(res, "diagnostics", api_traj_diagnostics(c, &rq, &r->run));
    return res;
}

json_t *api_op_scenes_rotating_table(struct api_call *c, const json_t *body)
{
    struct mech_rotating_table_request q;
    memset(&q, 0, sizeof q);
    q.target = scene_target(c, body);
    if (!(q.target > 0.0)) return NULL;
    const char *ex = api_string_of(body, "experiment");
    q.scene.experiment = !strcmp(ex, "at_rest")  ? MECH_TABLE_AT_REST
                         : !strcmp(ex, "custom") ? MECH_TABLE_CUSTOM
                                                 : MECH_TABLE_THROUGH_CENTER;
    q.scene.omega = api_number(body, "omega", 0); /* no schema default: refused as 0 */
    q.scene.radius = api_number_of(body, "radius");
    q.scene.mass = api_number_of(body, "mass");
    q.scene.samples = (size_t)api_number_of(body, "samples");
    q.has_position = json_object_get(body, "position") != NULL;
    q.has_velocity = json_object_get(body, "velocity") != NULL;
    q.has_t_end = json_object_get(body, "t_end") != NULL;
    q.scene.r0 = api_vec3_member(body, "position", mech_vec3_make(0, 0, 0));
    q.scene.v0 = api_vec3_member(body, "velocity", mech_vec3_make(0, 0, 0));
    q.scene.t_end = api_number(body, "t_end", 1);
    q.scene.dry_run = api_dry_run_requested(body);

    struct mech_rotating_table_scene *s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rotating_table_scene(&q, &c->budget, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *res;
    if (s->scene.dry_run) {
        struct api_traj_request rq;
        scene_rq(&rq, &s->result.problem, &s->result.model, &s->result.choice, accuracy_name(body));
        rq.dry_run = 1;
        res = api_dry_run_answer(c, api_traj_selection(c, &rq, NULL));
    } else {
        res = table_answer(c, s, accuracy_name(body));
    }
    mech_rotating_table_scene_free(s);
    return res;
}
