/* rotating_table.c — POST /v1/scenes/rotating-table: a puck sliding on a
 * turntable, seen from the table and from the room. The checks, buffers and
 * run are one call, mech_rotating_table_scene()
 * (core/answers/frames/rotating_table_scene.c); the model and diagnostics encoders are
 * the trajectory's (api/request/trajectory_request.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/answers/frames/rotating_table_scene.h"
#include "ops/scenes/scene_request.h"
#include "request/integrator_block.h"
#include "request/trajectory_request.h"

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
    api_scene_rq(&rq, &r->problem, &r->model, &r->choice, accuracy);
    json_object_set_new_nocheck(res, "model", api_traj_model(c, &rq, &r->run));
    json_object_set_new_nocheck(res, "diagnostics", api_traj_diagnostics(c, &rq, &r->run));
    return res;
}

json_t *api_op_scenes_rotating_table(struct api_call *c, const json_t *body)
{
    struct mech_rotating_table_request q;
    memset(&q, 0, sizeof q);
    q.target = api_scene_target(c, body);
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
        api_scene_rq(&rq, &s->result.problem, &s->result.model, &s->result.choice, api_scene_accuracy_name(body));
        rq.dry_run = 1;
        res = api_dry_run_answer(c, api_traj_selection(c, &rq, NULL));
    } else {
        res = table_answer(c, s, api_scene_accuracy_name(body));
    }
    mech_rotating_table_scene_free(s);
    return res;
}
