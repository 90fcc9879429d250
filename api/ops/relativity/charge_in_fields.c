/* charge_in_fields.c — POST /v1/relativity/charge-in-fields: a
 * charge in uniform static E and B (and a constant force), what a course
 * asks: the kind of field and its invariants, the frame where E and B are
 * parallel or one vanishes (the E x B drift frame), the helix or hyperbolic
 * motion there, and the state at lab times and at proper times. JSON <-> core
 * only; the physics is core/relativity/charged_motion{,_answer}.c. */
#include <stdlib.h>

#include "run/endpoint.h"
#include "mech/answers/relativity/charged_motion_answer.h"
#include "mech/base/constants.h"
#include "ops/relativity/velocity_request.h"

static double *times_of(const json_t *a, size_t *n)
{
    *n = json_array_size(a);
    double *x = malloc((*n ? *n : 1) * sizeof *x);
    for (size_t i = 0; x && i < *n; i++) x[i] = json_number_value(json_array_get(a, i));
    return x;
}

static json_t *states_json(struct api_call *c, const struct mech_charged_motion_state *s, size_t n,
                           double m)
{
    json_t *arr = json_array();
    for (size_t i = 0; arr && i < n; i++) {
        json_t *o = json_object();
        json_object_set_new_nocheck(o, "t", api_real(c, s[i].t));
        json_object_set_new_nocheck(o, "tau", api_real(c, s[i].tau));
        json_object_set_new_nocheck(o, "position", api_vec3(c, s[i].r));
        json_object_set_new_nocheck(o, "velocity", api_vec3(c, s[i].v));
        json_object_set_new_nocheck(o, "proper_velocity", api_vec3(c, s[i].u));
        json_object_set_new_nocheck(o, "gamma", api_real(c, s[i].gamma));
        json_object_set_new_nocheck(o, "gamma_minus_one", api_real(c, s[i].gamma_minus_1));
        json_object_set_new_nocheck(o, "kinetic_energy",
                                    api_real(c, s[i].gamma_minus_1 * m * MECH_C * MECH_C));
        json_array_append_new(arr, o);
    }
    return arr;
}

json_t *api_op_relativity_charge_in_fields(struct api_call *c, const json_t *body)
{
    const struct mech_vec3 zero = mech_vec3_make(0, 0, 0);
    struct mech_charged_question q = {0};
    q.mass = api_number_of(body, "mass");
    q.charge = api_number_of(body, "charge");
    q.E = api_vec3_member(body, "E", zero);
    q.B = api_vec3_member(body, "B", zero);
    q.force = api_vec3_member(body, "force", zero);
    q.position = api_vec3_member(body, "position", zero);
    const json_t *vj = json_object_get(body, "velocity"), *uj = json_object_get(body, "proper_velocity");
    if (vj && uj) {
        api_call_invalid(c, "/proper_velocity", "give velocity or proper_velocity, not both");
        return NULL;
    }
    if (vj) {
        struct mech_boost b;
        if (!api_velocity_parse(c, vj, "/velocity", &b)) return NULL;
        q.proper_velocity = mech_vec3_scale(b.direction, b.beta_gamma * MECH_C);
    } else {
        q.proper_velocity = api_vec3_member(body, "proper_velocity", zero);
    }
    q.t = times_of(json_object_get(body, "times"), &q.n_t);
    q.tau = times_of(json_object_get(body, "proper_times"), &q.n_tau);
    struct mech_charged_motion_state *st_t = malloc((q.n_t ? q.n_t : 1) * sizeof *st_t);
    struct mech_charged_motion_state *st_tau = malloc((q.n_tau ? q.n_tau : 1) * sizeof *st_tau);
    struct mech_charged_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = !(q.t && q.tau && st_t && st_tau)
                              ? MECH_ENOMEM
                              : mech_charged_answer(&q, &a, st_t, st_tau, &e);
    json_t *out = st == MECH_OK ? json_object() : NULL;
    if (out) {
        const struct mech_charged_motion *m = &a.motion;
        json_t *f = json_object();
        json_object_set_new_nocheck(f, "kind", json_string(mech_charged_field_kind_name(m->kind)));
        json_object_set_new_nocheck(f, "e2_minus_c2b2", api_real(c, a.e2_minus_c2b2));
        json_object_set_new_nocheck(f, "e_dot_b", api_real(c, a.e_dot_b));
        json_object_set_new_nocheck(out, "fields", f);
        json_t *fr = json_object();
        json_object_set_new_nocheck(fr, "velocity", api_vec3(c, a.frame_velocity));
        json_object_set_new_nocheck(fr, "beta", api_real(c, a.frame_beta));
        json_object_set_new_nocheck(fr, "gamma", api_real(c, a.frame_gamma));
        json_object_set_new_nocheck(fr, "E", a.has_frame_fields ? api_vec3(c, a.frame_E) : json_null());
        json_object_set_new_nocheck(fr, "B", a.has_frame_fields ? api_vec3(c, a.frame_B) : json_null());
        json_object_set_new_nocheck(fr, "vanishes", json_string(a.vanishes));
        json_object_set_new_nocheck(fr, "axis", api_vec3(c, m->n));
        json_object_set_new_nocheck(out, "frame", fr);
        if (a.has_helix) {
            json_t *h = json_object();
            json_object_set_new_nocheck(h, "omega_proper", api_real(c, a.omega_proper));
            json_object_set_new_nocheck(h, "radius", api_real(c, a.radius));
            json_object_set_new_nocheck(h, "proper_period", api_real(c, a.proper_period));
            json_object_set_new_nocheck(h, "period", a.has_pitch ? api_real(c, a.period) : json_null());
            json_object_set_new_nocheck(h, "pitch", a.has_pitch ? api_real(c, a.pitch) : json_null());
            json_object_set_new_nocheck(h, "speed_along_axis",
                                        a.has_pitch ? api_real(c, a.speed_along) : json_null());
            json_object_set_new_nocheck(out, "helix", h);
        } else {
            json_object_set_new_nocheck(out, "helix", json_null());
        }
        if (a.has_hyperbolic) {
            json_t *h = json_object();
            json_object_set_new_nocheck(h, "acceleration", api_real(c, a.accel_proper));
            json_object_set_new_nocheck(h, "rapidity_rate", api_real(c, a.accel_proper / MECH_C));
            json_object_set_new_nocheck(out, "hyperbolic", h);
        } else {
            json_object_set_new_nocheck(out, "hyperbolic", json_null());
        }
        json_object_set_new_nocheck(out, "initial_gamma", api_real(c, m->gamma0));
        json_object_set_new_nocheck(out, "at_times", states_json(c, st_t, q.n_t, q.mass));
        json_object_set_new_nocheck(out, "at_proper_times", states_json(c, st_tau, q.n_tau, q.mass));
    }
    free((void *)q.t);
    free((void *)q.tau);
    free(st_t);
    free(st_tau);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    if (!out) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    return out;
}
