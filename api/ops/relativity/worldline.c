/* worldline.c — POST /v1/relativity/worldline (notes §3.14, §3.15: the twin
 * paradox): a journey of legs, each clock's reading and what a telescope
 * shows. The answer is one call of mech_worldline_answer
 * (core/answers/relativity/worldline_answer.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/telescope.h"
#include "mech/answers/relativity/worldline_answer.h"
#include "ops/relativity/velocity_request.h"

/* The legs as asked (schema-validated: each leg is one of the five shapes);
 * a zero acceleration or a zero direction is named here, every leg at once.
 * Returns 0 when the request is invalid (problems recorded on c). */
static int read_legs(struct api_call *c, const json_t *jl, struct mech_worldline_leg_request *q)
{
    for (size_t k = 0; k < json_array_size(jl); k++) {
        const json_t *L = json_array_get(jl, k), *v = json_object_get(L, "velocity");
        struct mech_leg *l = &q[k].leg;
        char ptr[64];
        if (v) {
            static const char *const by[] = {"coordinate_time", "distance", "proper_time"};
            snprintf(ptr, sizeof ptr, "/legs/%zu/velocity", k);
            api_velocity_parse(c, v, ptr, &l->velocity);
            l->kind = json_object_get(L, by[0])   ? MECH_LEG_COAST_TIME
                      : json_object_get(L, by[1]) ? MECH_LEG_COAST_DISTANCE
                                                  : MECH_LEG_COAST_PROPER_TIME;
            l->amount = api_number(L, by[l->kind], 0);
            continue;
        }
        l->kind = MECH_LEG_ACCELERATE;
        l->amount = api_number(L, "proper_time", 0);
        q[k].acceleration_in_g = json_object_get(L, "proper_acceleration_g") != NULL;
        const char *key = q[k].acceleration_in_g ? "proper_acceleration_g" : "proper_acceleration";
        l->acceleration = api_number(L, key, 0);
        snprintf(ptr, sizeof ptr, "/legs/%zu/%s", k, key);
        if (l->acceleration == 0)
            api_call_invalid(c, ptr, "the proper acceleration must be nonzero; to coast, give a "
                                     "leg with a velocity instead");
        l->direction = api_vec3_member(L, "direction", mech_vec3_make(0, 0, 0));
        snprintf(ptr, sizeof ptr, "/legs/%zu/direction", k);
        if (json_object_get(L, "direction") && mech_vec3_norm(l->direction) == 0)
            api_call_invalid(c, ptr, "the direction must be a nonzero vector");
    }
    return c->problem == API_PROBLEM_NONE;
}

static json_t *clock_view_json(struct api_call *c, const char *from_key, const char *to_key,
                               const struct mech_worldline_clock_view *v)
{
    json_t *o = json_object();
    json_object_set_new(o, from_key, api_real(c, v->from));
    json_object_set_new(o, to_key, api_real(c, v->to));
    json_object_set_new_nocheck(o, "ticks", api_real(c, v->ticks));
    json_object_set_new_nocheck(o, "rate", api_real(c, v->rate));
    return o;
}

static json_t *telescope_json(struct api_call *c, const struct mech_telescope_view *v)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "home_time", api_real(c, v->home_time));
    json_object_set_new_nocheck(o, "traveller_clock", api_real(c, v->traveller_clock));
    json_object_set_new_nocheck(o, "leg", v->leg < 0 ? json_null() : json_integer(v->leg));
    json_object_set_new_nocheck(o, "emission_event", api_reals(c, v->emission, 4));
    json_object_set_new_nocheck(o, "light_travel_time", api_real(c, v->light_time));
    return o;
}

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

static json_t *velocity_json(struct api_call *c, const struct mech_boost *b)
{
    json_t *o = json_object();
    api_velocity_describe(c, b, o);
    return o;
}

static json_t *leg_json(struct api_call *c, const struct mech_worldline_leg_answer *l)
{
    const struct mech_leg_result *r = &l->r;
    json_t *o = json_object();
    set(o, "kind", json_string(l->accelerated ? "accelerate" : "coast"));
    set(o, "proper_time", api_real(c, r->proper_time));
    set(o, "proper_time_ct", api_real(c, l->proper_time_ct));
    set(o, "coordinate_time", api_real(c, r->coordinate_time));
    set(o, "age_difference", api_real(c, r->age_difference));
    set(o, "distance", api_real(c, r->distance));
    set(o, "displacement", api_vec3(c, r->displacement));
    set(o, "start", api_reals(c, r->start, 4));
    set(o, "end", api_reals(c, r->end, 4));
    set(o, "final_velocity", velocity_json(c, &r->final_velocity));
    set(o, "traveller_sees_home",
        clock_view_json(c, "home_clock_from", "home_clock_to", &l->traveller_sees_home));
    set(o, "home_sees_traveller",
        clock_view_json(c, "home_time_from", "home_time_to", &l->home_sees_traveller));
    return o;
}

static json_t *total_json(struct api_call *c, const struct mech_worldline_answer *a)
{
    const struct mech_worldline_total *t = &a->total;
    json_t *o = json_object(), *ts = json_object(), *hs = json_object();
    set(o, "proper_time", api_real(c, t->proper_time));
    set(o, "proper_time_ct", api_real(c, a->total_proper_time_ct));
    set(o, "coordinate_time", api_real(c, t->coordinate_time));
    set(o, "stay_at_home_time", api_real(c, t->coordinate_time));
    set(o, "age_difference", api_real(c, t->age_difference));
    set(o, "distance", api_real(c, t->distance));
    set(o, "end", api_reals(c, t->end, 4));
    set(o, "returned", json_boolean(a->returned));
    set(o, "final_velocity", velocity_json(c, &t->final_velocity));
    set(ts, "ticks", api_real(c, a->total_home_ticks_seen));
    set(ts, "home_clock_to", api_real(c, t->home_clock_seen_end));
    set(o, "traveller_sees_home", ts);
    set(hs, "ticks", api_real(c, a->total_traveller_ticks));
    set(hs, "home_time_to", api_real(c, t->home_receives_end));
    set(o, "home_sees_traveller", hs);
    return o;
}

json_t *api_op_relativity_worldline(struct api_call *c, const json_t *body)
{
    const json_t *jl = json_object_get(body, "legs");
    const json_t *tj = json_object_get(body, "telescope_home_times");
    struct mech_worldline_request q = {
        .units = strcmp(api_string_of(body, "units"), "years") == 0 ? MECH_WORLDLINE_YEARS
                                                                    : MECH_WORLDLINE_SECONDS,
        .tick_interval = api_number_of(body, "tick_interval"),
        .n = json_array_size(jl),
        .n_views = json_array_size(tj)};
    struct mech_worldline_leg_request *legs = calloc(q.n ? q.n : 1, sizeof *legs);
    double views[MECH_WORLDLINE_MAX_VIEWS];
    if (!legs) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    for (size_t i = 0; i < q.n_views && i < MECH_WORLDLINE_MAX_VIEWS; i++)
        views[i] = json_number_value(json_array_get(tj, i));
    q.legs = legs;
    q.telescope_home_times = views;
    struct mech_worldline_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    const int valid = read_legs(c, jl, legs);
    enum mech_status st = valid ? mech_worldline_answer(&q, &c->budget, &a, &e) : MECH_EINVAL;
    free(legs);
    if (!valid) return NULL;
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *res = json_object(), *u = json_object(), *arr = json_array();
    set(u, "time", json_string(q.units == MECH_WORLDLINE_YEARS ? "yr" : "s"));
    set(u, "length", json_string(q.units == MECH_WORLDLINE_YEARS ? "ly" : "m"));
    set(u, "c", api_real(c, a.c));
    set(u, "g", api_real(c, a.g));
    set(u, "tick_interval", api_real(c, a.tick_interval));
    set(res, "units", u);
    for (size_t k = 0; k < a.n; k++) json_array_append_new(arr, leg_json(c, &a.legs[k]));
    set(res, "legs", arr);
    if (tj) {
        json_t *views_json = json_array();
        for (size_t i = 0; i < a.n_views; i++)
            json_array_append_new(views_json, telescope_json(c, &a.views[i]));
        set(res, "home_telescope", views_json);
    }
    set(res, "total", total_json(c, &a));
    mech_worldline_answer_free(&a);
    return res;
}
