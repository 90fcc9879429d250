/* trajectory_relativity.c — "relativity" of POST /v1/trajectory (see
 * api/request/trajectory_relativity.h): parse, judge a finished run with core's
 * mech_trajectory_relativity_select, set up the run again when a correction
 * must be added or dropped, and encode model.relativity. */
#include "request/trajectory_relativity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const unsigned ALL = MECH_RELATIVITY_SPECIAL | MECH_RELATIVITY_SCHWARZSCHILD_1PN;

int api_traj_relativity_parse(struct api_call *c, const json_t *body, const char *prefix,
                              struct api_traj_request *rq)
{
    struct mech_trajectory_problem *p = &rq->p;
    const json_t *rel = json_object_get(body, "relativity");
    rq->rel_auto = !rel || json_is_string(rel);
    rq->rel_on = rq->rel_off = 0;
    for (size_t i = 0; !rq->rel_auto && i < json_array_size(rel); i++) {
        const char *s = json_string_value(json_array_get(rel, i));
        rq->rel_on |= s && !strcmp(s, "relativistic") ? MECH_RELATIVITY_SPECIAL
                                                      : MECH_RELATIVITY_SCHWARZSCHILD_1PN;
    }
    if (!rq->rel_auto) rq->rel_off = ALL & ~rq->rel_on;
    const json_t *part = json_object_get(body, "particle");
    const json_t *pv = json_object_get(part, "proper_velocity");
    const int has_v = json_object_get(part, "velocity") != NULL;
    char ptr[64];
    snprintf(ptr, sizeof ptr, "%s/particle", prefix);
    if (!!pv == has_v) {
        api_call_invalid(c, ptr, "give exactly one of velocity and proper_velocity (u = gamma v)");
        return 0;
    }
    if (pv) {
        if (rq->rel_off & MECH_RELATIVITY_SPECIAL) {
            snprintf(ptr, sizeof ptr, "%s/particle/proper_velocity", prefix);
            api_call_invalid(c, ptr,
                             "a proper velocity is the state of special-relativistic dynamics: "
                             "\"relativity\" must list \"relativistic\" (or be \"auto\")");
            return 0;
        }
        const struct mech_vec3 u = api_vec3_member(part, "proper_velocity", p->velocity);
        const double g = sqrt(1.0 + mech_vec3_dot(u, u) / (MECH_C * MECH_C));
        p->has_proper_velocity = 1;
        p->proper_velocity = u;
        p->velocity = mech_vec3_scale(u, 1.0 / g);
        rq->rel_on |= MECH_RELATIVITY_SPECIAL; /* given in u: relativistic from the start */
    }
    p->relativity = rq->rel_on;
    return 1;
}

int api_traj_relativity_judge(struct api_call *c, struct api_traj_request *rq,
                              const struct mech_trajectory_result *r, enum mech_status *st,
                              struct mech_error *e)
{
    *st = mech_trajectory_relativity_select(&rq->p, r, rq->model_target, rq->rel_on, rq->rel_off,
                                            &rq->rel_model, e);
    if (*st != MECH_OK || rq->rel_model.relativity == rq->p.relativity) return 0;
    /* run again with the corrections chosen: a new scene for the chooser */
    rq->rel_rerun = 1;
    rq->rel_first_method = r->method;
    rq->rel_first_stats = r->stats;
    rq->p.relativity = rq->rel_model.relativity;
    if (rq->chosen) {
        *st = mech_trajectory_choose(&rq->p, rq->choice.target, &rq->choice, e);
        if (*st != MECH_OK) return 0;
        rq->p.method = rq->choice.method;
        rq->p.opt = rq->choice.opt;
        rq->closed_form = rq->choice.closed_form && mech_trajectory_has_closed_form(&rq->p);
    }
    const long used = r->stats.steps;
    if (used > 0)
        c->budget.max_steps = c->budget.max_steps - used > 1 ? c->budget.max_steps - used : 1;
    return 1;
}

json_t *api_traj_relativity_json(struct api_call *c, const struct api_traj_request *rq,
                                 const struct mech_trajectory_result *r)
{
    const struct mech_relativity_model *m = &rq->rel_model;
    json_t *j = json_object(), *terms = json_array();
    if (!j || !terms) {
        json_decref(j);
        json_decref(terms);
        return NULL;
    }
    json_object_set_new_nocheck(j, "mode", json_string(rq->rel_auto ? "auto" : "given"));
    static const char *const names[MECH_TRAJECTORY_N_RELATIVITY] = {"relativistic",
                                                                    "schwarzschild_1pn"};
    static const unsigned bits[MECH_TRAJECTORY_N_RELATIVITY] = {
        MECH_RELATIVITY_SPECIAL, MECH_RELATIVITY_SCHWARZSCHILD_1PN};
    for (int k = 0; k < MECH_TRAJECTORY_N_RELATIVITY; k++) {
        json_t *t = json_object();
        json_object_set_new_nocheck(t, "term", json_string(names[k]));
        json_object_set_new_nocheck(t, "included",
                                    json_boolean((rq->p.relativity & bits[k]) != 0));
        json_object_set_new_nocheck(
            t, "max_acceleration",
            r ? api_real(c, r->relativity_terms[k].max_acceleration) : json_null());
        const struct mech_term_estimate *te = &m->terms[k];
        if (m->judged) {
            json_t *ee = json_object();
            json_object_set_new_nocheck(ee, "acceleration_bound", api_real(c, te->accel_bound));
            json_object_set_new_nocheck(ee, "position", api_real(c, te->position_effect));
            json_object_set_new_nocheck(ee, "velocity", api_real(c, te->velocity_effect));
            json_object_set_new_nocheck(ee, "relative", api_real(c, te->relative_effect));
            json_object_set_new_nocheck(t, "estimated_effect", ee);
            json_object_set_new_nocheck(t, "reason", json_string(te->reason));
        } else {
            json_object_set_new_nocheck(t, "estimated_effect", json_null());
            json_object_set_new_nocheck(
                t, "reason",
                json_string((rq->p.relativity & bits[k])
                                ? "included as requested; not judged (dry run)"
                                : rq->rel_auto ? "dry run: \"auto\" is judged from a run, none made"
                                               : "left out as requested; not judged (dry run)"));
        }
        json_array_append_new(terms, t);
    }
    json_object_set_new_nocheck(j, "terms", terms);
    json_object_set_new_nocheck(j, "target_error", api_real(c, rq->model_target));
    json_object_set_new_nocheck(j, "safety_factor", api_real(c, MECH_TRAJECTORY_AUTO_SAFETY));
    json_object_set_new_nocheck(
        j, "rule",
        json_string("a correction is included when eps (1 + V T / L) > target / safety, with eps "
                    "its largest size relative to the acceleration it corrects, measured along a "
                    "run of the scene (relativistic: dv/dt - F/m of p = gamma m v at the speed "
                    "reached against |F/m|, 1 at or beyond c; schwarzschild_1pn: |(4 gm/d - v^2) n "
                    "+ 4 (n.v) v| / c^2 about the one central mass), L and V the largest |r| and "
                    "|v|, T the duration (V T / L: the radians of an orbit or gyration the "
                    "correction shifts by ~eps each); a correction needed that cannot be modelled "
                    "is a 422 naming it"));
    if (m->judged) {
        json_object_set_new_nocheck(j, "time_scale", api_real(c, m->time_scale));
        json_object_set_new_nocheck(j, "position_scale", api_real(c, m->position_scale));
        json_object_set_new_nocheck(j, "velocity_scale", api_real(c, m->velocity_scale));
    }
    if (rq->rel_rerun) {
        json_t *fr = json_object();
        json_object_set_new_nocheck(fr, "method", json_string(rq->rel_first_method));
        json_object_set_new_nocheck(fr, "steps", json_integer(rq->rel_first_stats.steps));
        json_object_set_new_nocheck(fr, "rhs_evaluations",
                                    json_integer(rq->rel_first_stats.rhs_evaluations));
        json_object_set_new_nocheck(j, "first_run", fr);
    } else {
        json_object_set_new_nocheck(j, "first_run", json_null());
    }
    return j;
}
