/* ep_relativity_frames.c — changing frames in special relativity:
 *   POST /v1/relativity/velocity-addition  (notes §3.9, §3.10; Wigner rotation)
 *   POST /v1/relativity/interval           (notes §3.5, §3.6)
 *   POST /v1/relativity/worldline          (notes §3.14, §3.15: the twin paradox)
 * The numerics live in core/relativity/velocity_addition.c, interval.c and,
 * for the worldline, one call of mech_worldline_answer
 * (core/relativity/worldline_answer.c); every velocity input is the shared form of
 * api/velocity_request.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/interval.h"
#include "mech/relativity/velocity_addition.h"
#include "mech/relativity/telescope.h"
#include "mech/answers/relativity/worldline_answer.h"
#include "velocity_request.h"

/* ======================= velocity addition ================================= */

static json_t *velocity_in_frame(struct api_call *c, const json_t *vel, const struct mech_boost *f)
{
    struct mech_error e;
    mech_error_clear(&e);
    json_t *res = json_object();
    const json_t *light = json_object_get(vel, "light");
    if (light) {
        struct mech_vec3 k, d = api_vec3_of(light);
        double ratio;
        if (mech_vec3_norm(d) == 0) {
            api_call_invalid(c, "/velocity/light", "the direction of the light must be nonzero");
            json_decref(res);
            return NULL;
        }
        if (mech_velocity_add_light(d, f, &k, &ratio, &e) != MECH_OK) {
            json_decref(res);
            return api_call_fail_core(c, MECH_ENUMERIC, &e, "");
        }
        json_object_set_new_nocheck(res, "light", json_true());
        json_object_set_new_nocheck(res, "direction", api_vec3(c, k));
        json_object_set_new_nocheck(res, "beta", api_vec3(c, k));
        json_object_set_new_nocheck(res, "one_minus_beta", api_real(c, 0.0));
        json_object_set_new_nocheck(res, "frequency_ratio", api_real(c, ratio));
        return res;
    }
    struct mech_boost o, r;
    if (!api_velocity_parse(c, vel, "/velocity", &o)) {
        json_decref(res);
        return NULL;
    }
    if (mech_velocity_add(&o, f, &r, &e) != MECH_OK) {
        api_call_domain(c, "/velocity",
                        "the object's velocity in that frame is too close to the speed of light "
                        "to represent: %s",
                        e.text);
        json_decref(res);
        return NULL;
    }
    api_velocity_describe(c, &r, res);
    json_t *given = json_object();
    api_velocity_describe(c, &o, given);
    json_object_set_new_nocheck(res, "object_velocity", given);
    return res;
}

static json_t *composition(struct api_call *c, const json_t *list)
{
    size_t n = json_array_size(list);
    struct mech_boost *b = malloc(n * sizeof *b);
    if (!b) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    int ok = 1;
    for (size_t i = 0; i < n; i++) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/compose/%zu", i);
        if (!api_velocity_parse(c, json_array_get(list, i), ptr, &b[i])) ok = 0;
    }
    struct mech_boost_composition comp;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = ok ? mech_boost_compose(b, n, &c->budget, &comp, &e) : MECH_EINVAL;
    free(b);
    if (!ok) return NULL;
    if (st == MECH_ENUMERIC && strncmp(e.param, "boosts/", 7) == 0) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/compose/%ld", strtol(e.param + 7, NULL, 10));
        api_call_domain(c, ptr,
                        "the composed velocity up to this boost has a rapidity beyond %g "
                        "(gamma about 5e151), which this server does not represent",
                        MECH_BOOST_RAPIDITY_MAX);
        return NULL;
    }
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *res = json_object();
    json_t *v = json_object();
    api_velocity_describe(c, &comp.total, v);
    json_object_set_new_nocheck(res, "velocity", v);
    json_t *w = json_object();
    json_object_set_new_nocheck(w, "angle", api_real(c, comp.angle));
    json_object_set_new_nocheck(w, "angle_deg",
                                api_real(c, comp.angle * (180.0 / MECH_PI)));
    json_object_set_new_nocheck(w, "axis", comp.angle > 0 ? api_vec3(c, comp.axis) : json_null());
    json_object_set_new_nocheck(w, "quaternion", api_reals(c, comp.quaternion, 4));
    json_object_set_new_nocheck(w, "matrix", api_mat3(c, comp.rotation));
    json_object_set_new_nocheck(res, "wigner_rotation", w);
    /* Λ = R B(total): B's rows (notes §3.9, boost in an arbitrary direction). */
    const struct mech_boost *t = &comp.total;
    double B[4][4], n3[3] = {t->direction.x, t->direction.y, t->direction.z};
    B[0][0] = t->gamma;
    for (int i = 0; i < 3; i++) {
        B[0][i + 1] = B[i + 1][0] = -t->beta_gamma * n3[i];
        for (int j = 0; j < 3; j++)
            B[i + 1][j + 1] = (i == j) + t->gamma_minus_one * n3[i] * n3[j];
    }
    json_t *L = json_array();
    json_array_append_new(L, api_reals(c, B[0], 4));
    for (int i = 0; i < 3; i++) {
        double row[4];
        for (int nu = 0; nu < 4; nu++)
            row[nu] = comp.rotation.a[i][0] * B[1][nu] + comp.rotation.a[i][1] * B[2][nu] +
                      comp.rotation.a[i][2] * B[3][nu];
        json_array_append_new(L, api_reals(c, row, 4));
    }
    json_object_set_new_nocheck(res, "lorentz_matrix", L);
    return res;
}

json_t *api_op_relativity_velocity_addition(struct api_call *c, const json_t *body)
{
    const json_t *vel = json_object_get(body, "velocity");
    const json_t *fv = json_object_get(body, "frame_velocity");
    const json_t *list = json_object_get(body, "compose");
    if (vel && !fv)
        api_call_invalid(c, "/frame_velocity",
                         "give frame_velocity (the velocity of the new frame) with velocity");
    if (fv && !vel)
        api_call_invalid(c, "/velocity",
                         "give velocity (the object's velocity in the original frame) with "
                         "frame_velocity");
    if (!vel && !fv && !list)
        api_call_invalid(c, "", "give velocity and frame_velocity, or compose, or both");
    if (c->problem != API_PROBLEM_NONE) return NULL;

    json_t *res = json_object();
    if (vel) {
        struct mech_boost f;
        if (!api_velocity_parse(c, fv, "/frame_velocity", &f)) {
            json_decref(res);
            return NULL;
        }
        json_t *vin = velocity_in_frame(c, vel, &f);
        if (!vin) {
            json_decref(res);
            return NULL;
        }
        json_t *given = json_object_get(vin, "object_velocity");
        if (given) {
            json_object_set(res, "object_velocity", given);
            json_object_del(vin, "object_velocity");
        }
        json_object_set_new_nocheck(res, "velocity_in_frame", vin);
        json_t *fd = json_object();
        api_velocity_describe(c, &f, fd);
        json_object_set_new_nocheck(res, "frame_velocity", fd);
    }
    if (list) {
        json_t *comp = composition(c, list);
        if (!comp) {
            json_decref(res);
            return NULL;
        }
        json_object_set_new_nocheck(res, "composition", comp);
    }
    return res;
}

/* ======================= interval ========================================= */

json_t *api_op_relativity_interval(struct api_call *c, const json_t *body)
{
    const json_t *ev = json_object_get(body, "events");
    double e1[4], e2[4];
    for (size_t k = 0; k < 4; k++) {
        e1[k] = json_number_value(json_array_get(json_array_get(ev, 0), k));
        e2[k] = json_number_value(json_array_get(json_array_get(ev, 1), k));
    }
    const int ly = strcmp(api_string_of(body, "units"), "years") == 0;
    const double c_light = ly ? 1.0 : MECH_C;
    struct mech_interval iv;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_interval_compute(e1, e2, &iv, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    static const char *const kinds[] = {"timelike", "spacelike", "lightlike"};
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "delta", api_reals(c, iv.delta, 4));
    json_object_set_new_nocheck(res, "s2", api_real(c, iv.s2));
    json_object_set_new_nocheck(res, "kind", json_string(kinds[iv.kind]));
    json_object_set_new_nocheck(res, "lightlike_tolerance", api_real(c, iv.tolerance));
    json_object_set_new_nocheck(res, "s2_input_uncertainty", api_real(c, iv.input_error));
    json_object_set_new_nocheck(res, "coincident", json_boolean(iv.coincident));
    /* Every key always present: null where the quantity does not exist (a
     * spacelike pair has no proper time, a timelike one no proper length);
     * light-like pairs have both, and both are 0. */
    const int has_time = iv.kind != MECH_INTERVAL_SPACELIKE;
    const int has_length = iv.kind != MECH_INTERVAL_TIMELIKE;
    json_object_set_new_nocheck(res, "proper_time",
                                has_time ? api_real(c, iv.proper / c_light) : json_null());
    json_object_set_new_nocheck(res, "proper_time_ct",
                                has_time ? api_real(c, iv.proper) : json_null());
    json_object_set_new_nocheck(res, "proper_length",
                                has_length ? api_real(c, iv.proper) : json_null());
    json_object_set_new_nocheck(res, "time_order",
                                json_string(iv.delta[0] > 0   ? "first_before_second"
                                            : iv.delta[0] < 0 ? "second_before_first"
                                                              : "simultaneous"));
    json_object_set_new_nocheck(res, "time_order_reversible",
                                json_boolean(iv.time_order_reversible));
    if (iv.has_frame) {
        json_t *f = json_object();
        json_object_set_new(
            f, "makes_events",
            json_string(iv.kind == MECH_INTERVAL_TIMELIKE ? "co-located" : "simultaneous"));
        json_t *v = json_object();
        api_velocity_describe(c, &iv.frame, v);
        json_object_set_new_nocheck(f, "velocity", v);
        json_object_set_new_nocheck(res, "example_frame", f);
    } else {
        json_object_set_new_nocheck(res, "example_frame", json_null());
    }
    return res;
}

/* ======================= worldline ========================================= */

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
