/* trajectory.c — POST /v1/trajectory: integrate a particle in an
 * inertial, rotating or local Earth frame (notes §1.2–1.3) with a chosen ODE
 * method, sampled evenly in time, optionally stopped at a coordinate
 * crossing; answers the samples, the stop event, the model terms with their
 * sizes, and diagnostics (steps, evaluations, energy / Jacobi drift).
 * core/frames/trajectory.c does the physics, core/ode/ode.c the integration. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/frames/trajectory.h"
#include "request/trajectory_relativity.h"
#include "request/trajectory_request.h"

/* The answer's run: the closed form or the integration of rq->p. */
static enum mech_status run_once(struct api_call *c, struct api_traj_request *rq,
                                 struct mech_trajectory_result *r, struct mech_error *e)
{
    return rq->closed_form ? mech_trajectory_closed_form_ex(&rq->p, r, &rq->evidence, &c->budget, e)
                           : mech_trajectory_integrate(&rq->p, &c->budget, r, e);
}

json_t *api_op_trajectory(struct api_call *c, const json_t *body)
{
    struct api_traj_request rq;
    if (!api_traj_request_parse(c, body, "", &rq)) return NULL;
    if (rq.dry_run) return api_traj_dry_run(c, &rq);

    /* Output buffers, owned here: samples x (t, position, velocity). */
    const size_t n = rq.p.samples;
    double *t = malloc(n * sizeof *t);
    struct mech_vec3 *pos = malloc(n * sizeof *pos);
    struct mech_vec3 *vel = malloc(n * sizeof *vel);
    struct mech_vec3 *pvel = malloc(n * sizeof *pvel);
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.position = pos;
    r.velocity = vel;
    r.proper_velocity = pvel;
    struct mech_error e;
    mech_error_clear(&e);
    const double cpu0 = mech_cpu_seconds();
    enum mech_status st = !(t && pos && vel && pvel) ? MECH_ENOMEM : run_once(c, &rq, &r, &e);
    /* "relativity": the run judged; with a correction added (or dropped),
     * the scene runs again (api/request/trajectory_relativity.h) */
    if (st == MECH_OK && api_traj_relativity_judge(c, &rq, &r, &st, &e)) {
        memset(&r, 0, sizeof r);
        r.t = t;
        r.position = pos;
        r.velocity = vel;
        r.proper_velocity = pvel;
        st = run_once(c, &rq, &r, &e);
    }
    rq.cpu_s = mech_cpu_seconds() - cpu0;
    if (st != MECH_OK) {
        free(t);
        free(pos);
        free(vel);
        free(pvel);
        return api_call_fail_core(c, st, &e, "");
    }

    json_t *res = json_object();
    json_t *jp = json_array(), *jv = json_array();
    json_object_set_new_nocheck(res, "t", api_reals(c, t, r.n_samples));
    for (size_t i = 0; jp && jv && i < r.n_samples; i++) {
        json_array_append_new(jp, api_vec3(c, pos[i]));
        json_array_append_new(jv, api_vec3(c, vel[i]));
    }
    json_object_set_new_nocheck(res, "position", jp);
    json_object_set_new_nocheck(res, "velocity", jv);
    if (r.relativistic) { /* u = gamma v: the digits a speed near c cannot hold */
        json_t *ju = json_array();
        for (size_t i = 0; ju && i < r.n_samples; i++) json_array_append_new(ju, api_vec3(c, pvel[i]));
        json_object_set_new_nocheck(res, "proper_velocity", ju);
    }
    free(t);
    free(pos);
    free(vel);
    free(pvel);

    if (r.stopped) {
        json_t *s = json_object();
        json_object_set_new_nocheck(s, "t", api_real(c, r.t_stop));
        json_object_set_new_nocheck(s, "position", api_vec3(c, r.stop_position));
        json_object_set_new_nocheck(s, "velocity", api_vec3(c, r.stop_velocity));
        if (r.relativistic)
            json_object_set_new_nocheck(s, "proper_velocity", api_vec3(c, r.stop_proper_velocity));
        json_object_set_new_nocheck(res, "stopped", s);
    } else {
        json_object_set_new_nocheck(res, "stopped", json_null());
    }

    json_t *model = api_traj_model(c, &rq, &r);
    json_t *relativity = api_traj_relativity_json(c, &rq, &r);
    if (model && relativity) json_object_set_new_nocheck(model, "relativity", relativity);
    else json_decref(relativity);
    json_object_set_new_nocheck(res, "model", model);

    json_t *d = api_traj_diagnostics(c, &rq, &r);
    json_object_set_new_nocheck(res, "diagnostics", d);

    if (!res || !jp || !jv || !model || !relativity || !d ||
        json_array_size(jp) != r.n_samples) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}

