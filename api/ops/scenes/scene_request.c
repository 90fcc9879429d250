/* scene_request.c — what the chapter-1 scenes share (see
 * api/ops/scenes/scene_request.h): the accuracy asked for, the Earth's
 * parameters, and the ballistic scenes' run (core/frames/scenes.c) answered
 * beside the notes' first-order formula, their difference and the
 * second-order terms the formula neglects. */
#include "ops/scenes/scene_request.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "request/earth_rotation.h"
#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/frames/scenes.h"
#include "mech/frames/scenes_first_order.h"
#include "mech/frames/trajectory.h"
#include "request/integrator_block.h"
#include "request/trajectory_request.h"

/* The relative accuracy asked for; 0 after recording an error. */
double api_scene_target(struct api_call *c, const json_t *body)
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
void api_scene_rq(struct api_traj_request *rq, const struct mech_trajectory_problem *p,
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

/* The equations the run solved: the model asked for and the terms it kept. */
static json_t *physics_model_json(enum mech_scene_model model,
                                  const struct mech_trajectory_problem *p)
{
    const int cf = (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL) != 0;
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "requested", json_string(mech_scene_model_name(model)));
    json_object_set_new_nocheck(j, "name", json_string(cf ? "coriolis_centrifugal" : "coriolis"));
    json_object_set_new_nocheck(
        j, "equation",
        json_string(cf ? "r'' = g - 2 w x r' - w x (w x r), r from the launch point: Coriolis "
                         "and the change of the centrifugal term along the path"
                       : "r'' = g - 2 w x r': Coriolis only, as most textbooks solve the "
                         "scene (the centrifugal term at the launch point is inside the "
                         "effective g; its change along the path is neglected)"));
    return j;
}

static json_t *ballistic_answer(struct api_call *c, const char *scene,
                                struct mech_scene_ballistic_result *r, json_t *parameters,
                                json_t *formula, int south, const struct mech_vec3 *fwd,
                                const char *accuracy, enum mech_scene_model model)
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
    api_scene_rq(&rq, &r->problem, &r->model, &r->choice, accuracy);
    rq.auto_model = model == MECH_SCENE_MODEL_AUTO;
    json_object_set_new_nocheck(res, "model", api_traj_model(c, &rq, &r->run));
    json_object_set_new_nocheck(res, "physics_model", physics_model_json(model, &r->problem));
    json_object_set_new_nocheck(res, "diagnostics", api_traj_diagnostics(c, &rq, &r->run));
    return res;
}

const char *api_scene_accuracy_name(const json_t *body)
{
    return json_object_get(body, "target_error") ? NULL : api_string_of(body, "accuracy");
}

/* 0 after recording an error (both omega_magnitude and sidereal_day). */
int api_scene_earth_params(struct api_call *c, const json_t *body, struct mech_scene_ballistic *s)
{
    memset(s, 0, sizeof *s);
    s->latitude_deg = api_number(body, "latitude_deg", 0);
    s->g = api_number_of(body, "g");
    const char *m = api_string_of(body, "model");
    s->model = !strcmp(m, "coriolis")               ? MECH_SCENE_MODEL_CORIOLIS
               : !strcmp(m, "coriolis_centrifugal") ? MECH_SCENE_MODEL_CORIOLIS_CENTRIFUGAL
                                                    : MECH_SCENE_MODEL_AUTO;
    return api_earth_rotation(c, body, "", "omega_magnitude", MECH_EARTH_OMEGA_SIDEREAL, &s->omega);
}

json_t *api_scene_run_ballistic(struct api_call *c, const json_t *body, const char *scene,
                                const struct mech_scene_ballistic *s, json_t *parameters,
                                json_t *formula, int south, const struct mech_vec3 *fwd,
                                double target)
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
        api_scene_rq(&rq, &r->problem, &r->model, &r->choice, api_scene_accuracy_name(body));
        rq.auto_model = sd.model == MECH_SCENE_MODEL_AUTO;
        rq.dry_run = 1;
        json_decref(parameters);
        json_decref(formula);
        json_t *res = api_dry_run_answer(c, api_traj_selection(c, &rq, NULL));
        free(r);
        return res;
    }
    json_object_set_new_nocheck(parameters, "model", json_string(mech_scene_model_name(sd.model)));
    json_t *res = ballistic_answer(c, scene, r, parameters, formula, south, fwd,
                                   api_scene_accuracy_name(body), sd.model);
    free(r);
    return res;
}
