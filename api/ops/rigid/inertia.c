/* inertia.c — POST /v1/rigid/inertia: inertia tensor, principal axes, angular
 * momentum and kinetic energy of a rigid body made of simple parts, holes and
 * closed triangle meshes, with each part's own contribution for auditing.
 * JSON <-> core only: api/ops/rigid/inertia_request.c reads the parts and calls
 * core/rigid/inertia.c; this file encodes the answer. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "ops/rigid/inertia_request.h"
#include "mech/base/constants.h"
#include "mech/rigid/rigid_problems.h"

/* ---- handler ----------------------------------------------------------------- */

static json_t *parts_json(struct api_call *c, const struct mech_inertia_part *parts,
                          const struct mech_inertia_part_props *pp, size_t n)
{
    json_t *arr = json_array();
    for (size_t i = 0; arr && i < n; i++) {
        json_t *o = json_object();
        if (!o || json_array_append_new(arr, o)) {
            json_decref(arr);
            return NULL;
        }
        json_object_set_new_nocheck(o, "shape",
                                    json_string(api_inertia_shape_name(parts[i].shape)));
        json_object_set_new_nocheck(o, "hole", json_boolean(parts[i].hole));
        json_object_set_new_nocheck(o, "mass", api_real(c, pp[i].mass));
        json_object_set_new_nocheck(o, "center_of_mass", api_vec3(c, pp[i].center_of_mass));
        json_object_set_new_nocheck(o, "tensor", api_mat3(c, pp[i].tensor));
        if (parts[i].shape == MECH_SHAPE_MESH) {
            json_object_set_new_nocheck(o, "volume", api_real(c, pp[i].volume));
            json_object_set_new_nocheck(o, "inverted", json_boolean(pp[i].inverted));
        }
    }
    return arr;
}

/* The incline block (rolling without slipping from rest), or NULL after
 * recording the problem. */
static json_t *incline_json(struct api_call *c, const json_t *inc, const struct mech_inertia *res)
{
    const json_t *aj = json_object_get(inc, "angle"), *dj = json_object_get(inc, "angle_deg");
    if ((aj != NULL) == (dj != NULL)) {
        api_call_invalid(c, aj ? "/incline/angle_deg" : "/incline/angle",
                         "give the slope's angle once: angle (rad, 0 to pi/2) or angle_deg (0 "
                         "to 90)");
        return NULL;
    }
    const double angle = aj ? json_number_value(aj) : json_number_value(dj) * (MECH_PI / 180);
    struct mech_vec3 n = api_vec3_member(inc, "axis", mech_vec3_make(0, 0, 1));
    double len = mech_vec3_norm(n);
    if (!(len > 0) || !isfinite(len)) {
        api_call_invalid(c, "/incline/axis", "the rolling axis must be a non-zero vector");
        return NULL;
    }
    n = mech_vec3_scale(n, 1 / len);
    const double moment = mech_vec3_dot(n, mech_mat3_mul_vec(res->tensor_cm, n));
    const json_t *lj = json_object_get(inc, "length");
    struct mech_rolling_incline r;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rolling_incline(res->mass, fmax(moment, 0), api_number_of(inc, "radius"),
                                               angle, api_number_of(inc, "g"),
                                               lj ? json_number_value(lj) : 0, &r, &e);
    if (st != MECH_OK) {
        if (!strcmp(e.param, "angle") && dj) strcpy(e.param, "angle_deg");
        api_call_fail_core(c, st, &e, "/incline");
        return NULL;
    }
    json_t *o = json_object();
    if (!o) return NULL;
    json_object_set_new_nocheck(o, "moment_axis", api_real(c, r.moment_axis));
    json_object_set_new_nocheck(o, "k", api_real(c, r.k));
    json_object_set_new_nocheck(o, "acceleration", api_real(c, r.acceleration));
    json_object_set_new_nocheck(o, "friction_force", api_real(c, r.friction_force));
    json_object_set_new_nocheck(o, "min_friction_coefficient", api_real(c, r.min_friction_coefficient));
    json_object_set_new_nocheck(o, "time", lj ? api_real(c, r.time) : json_null());
    json_object_set_new_nocheck(o, "speed", lj ? api_real(c, r.speed) : json_null());
    json_object_set_new_nocheck(o, "angular_speed", lj ? api_real(c, r.angular_speed) : json_null());
    json_object_set_new_nocheck(o, "translational_energy_fraction", api_real(c, r.sliding_fraction));
    return o;
}

json_t *api_op_rigid_inertia(struct api_call *c, const json_t *body)
{
    struct api_inertia_body b;
    if (!api_inertia_body_compute(c, body, &b)) {
        api_inertia_body_free(&b);
        return NULL;
    }
    const json_t *inc = json_object_get(body, "incline");
    json_t *incj = inc ? incline_json(c, inc, &b.result) : NULL;
    if (inc && !incj) {
        api_inertia_body_free(&b);
        if (c->problem == API_PROBLEM_NONE) {
            struct mech_error e;
            mech_error_clear(&e);
            mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
            return api_call_fail_core(c, MECH_ENOMEM, &e, "");
        }
        return NULL;
    }
    const struct mech_inertia *res = &b.result;
    json_t *out = json_object();
    json_t *pr = json_object();
    json_t *pj = parts_json(c, b.parts, b.props, b.n);
    api_inertia_body_free(&b);
    if (!out || !pr || !pj) {
        json_decref(out);
        json_decref(pr);
        json_decref(pj);
        json_decref(incj);
        struct mech_error e;
        mech_error_clear(&e);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    json_object_set_new_nocheck(out, "mass", api_real(c, res->mass));
    json_object_set_new_nocheck(out, "center_of_mass", api_vec3(c, res->center_of_mass));
    json_object_set_new_nocheck(out, "origin", api_vec3(c, res->origin));
    json_object_set_new_nocheck(out, "tensor", api_mat3(c, res->tensor));
    json_object_set_new_nocheck(out, "tensor_center_of_mass", api_mat3(c, res->tensor_cm));
    json_object_set_new_nocheck(pr, "moments", api_reals(c, res->principal.moments, 3));
    json_object_set_new_nocheck(pr, "axes", api_mat3(c, res->principal.axes));
    json_object_set_new_nocheck(pr, "degenerate", json_boolean(res->principal.degenerate));
    json_object_set_new_nocheck(out, "principal", pr);
    if (b.has_omega) {
        json_object_set_new_nocheck(out, "angular_momentum", api_vec3(c, b.angular_momentum));
        json_object_set_new_nocheck(out, "kinetic_energy", api_real(c, b.kinetic_energy));
        json_object_set_new_nocheck(out, "angle_L_omega", b.has_pair && b.pair.has_angle
                                                              ? api_real(c, b.pair.angle)
                                                              : json_null());
        json_object_set_new_nocheck(out, "torque_to_hold_axis",
                                    b.has_pair ? api_vec3(c, b.pair.cross) : json_null());
    }
    if (incj) json_object_set_new_nocheck(out, "incline", incj);
    json_object_set_new_nocheck(out, "parts", pj);
    return out;
}
