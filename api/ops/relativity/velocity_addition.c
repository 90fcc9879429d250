/* velocity_addition.c — POST /v1/relativity/velocity-addition (notes §3.9,
 * §3.10; the Wigner rotation of a composition). The numerics are
 * core/relativity/velocity_addition.c; every velocity input is the shared
 * form of api/ops/relativity/velocity_request.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/velocity_addition.h"
#include "ops/relativity/velocity_request.h"

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
