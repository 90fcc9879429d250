/* small_oscillations.c — POST /v1/small-oscillations: small oscillations
 * about an equilibrium or a steady motion, for one system per request:
 * a near-circular orbit in a central potential, the conical pendulum, a
 * physical pendulum (a body from /v1/rigid/inertia about any pivot and axis)
 * and the normal modes of the linearised Foucault pendulum.
 * JSON <-> core only; the physics is core/hamiltonian/small_oscillations.c. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/frames/earth.h"
#include "request/earth_rotation.h"
#include "mech/hamiltonian/small_oscillations.h"


#define MAX_TERMS 16

/* clang-format off */
/* clang-format on */

static json_t *nomem(struct api_call *c, json_t *o)
{
    struct mech_error e;
    json_decref(o);
    mech_error_clear(&e);
    mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
    return api_call_fail_core(c, MECH_ENOMEM, &e, "");
}

#define SET(o, k, v) json_object_set_new_nocheck((o), (k), (v))

static json_t *central(struct api_call *c, const json_t *s, json_t *out)
{
    const json_t *tj = json_object_get(s, "terms");
    struct mech_potential_term t[MAX_TERMS];
    size_t n = json_array_size(tj);
    for (size_t i = 0; i < n && i < MAX_TERMS; i++) {
        t[i].k = api_number(json_array_get(tj, i), "k", 0);
        t[i].n = api_number(json_array_get(tj, i), "n", 0);
    }
    struct mech_orbit_oscillation o;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_orbit_oscillation(t, n, api_number_of(s, "mass"),
                                                 api_number(s, "r0", 1), &o, &e);
    if (st != MECH_OK) {
        json_decref(out);
        return api_call_fail_core(c, st, &e, "/system");
    }
    json_t *co = json_object();
    if (!co) return nomem(c, out);
    SET(co, "angular_momentum", api_real(c, o.angular_momentum));
    SET(co, "energy", api_real(c, o.energy));
    SET(co, "omega_phi", api_real(c, o.omega_phi));
    SET(co, "period_phi", api_real(c, 2 * MECH_PI / o.omega_phi));
    SET(out, "circular_orbit", co);
    SET(out, "V", api_real(c, o.v));
    SET(out, "dV", api_real(c, o.dv));
    SET(out, "d2V", api_real(c, o.d2v));
    SET(out, "k_eff", api_real(c, o.k_eff));
    SET(out, "stable", json_boolean(o.stable));
    int ok = o.stable;
    SET(out, "omega_r", ok ? api_real(c, o.omega_r) : json_null());
    SET(out, "period_r", ok ? api_real(c, 2 * MECH_PI / o.omega_r) : json_null());
    SET(out, "frequency_ratio", ok ? api_real(c, o.omega_r / o.omega_phi) : json_null());
    SET(out, "apsidal_angle", ok ? api_real(c, o.apsidal_angle) : json_null());
    SET(out, "apsidal_angle_deg", ok ? api_real(c, o.apsidal_angle * (180 / MECH_PI)) : json_null());
    SET(out, "pericentre_angle", ok ? api_real(c, 2 * o.apsidal_angle) : json_null());
    SET(out, "precession_per_radial_period",
        ok ? api_real(c, 2 * o.apsidal_angle - 2 * MECH_PI) : json_null());
    SET(out, "growth_rate", ok ? json_null() : api_real(c, o.growth_rate));
    return out;
}

static json_t *conical(struct api_call *c, const json_t *s, json_t *out)
{
    struct mech_conical_pendulum p;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_conical_pendulum(api_number_of(s, "length"),
                                                api_number_of(s, "g"),
                                                api_number(s, "angle", 0.5), &p, &e);
    if (st != MECH_OK) {
        json_decref(out);
        return api_call_fail_core(c, st, &e, "/system");
    }
    SET(out, "phi_dot", api_real(c, p.phi_dot));
    SET(out, "period", api_real(c, p.period));
    SET(out, "radius", api_real(c, p.radius));
    SET(out, "speed", api_real(c, p.speed));
    SET(out, "omega_theta", api_real(c, p.omega_theta));
    SET(out, "period_theta", api_real(c, 2 * MECH_PI / p.omega_theta));
    SET(out, "apsidal_angle", api_real(c, p.apsidal_angle));
    SET(out, "apsidal_angle_deg", api_real(c, p.apsidal_angle * (180 / MECH_PI)));
    return out;
}

static json_t *ball(struct api_call *c, const json_t *s, json_t *out, struct mech_mat3 t)
{
    struct mech_ball_pendulum b;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st =
        mech_ball_pendulum(api_number_of(s, "mass"), t,
                           api_vec3_member(s, "offset", mech_vec3_make(0, 0, 0)),
                           api_number_of(s, "g"), &b, &e);
    if (st != MECH_OK) {
        if (!strcmp(e.param, "tensor")) strcpy(e.param, "tensor_center_of_mass");
        json_decref(out);
        return api_call_fail_core(c, st, &e, "/system");
    }
    json_t *modes = json_array();
    if (!modes) return nomem(c, out);
    for (int k = 0; k < 2; k++) {
        json_t *m = json_object();
        if (!m) {
            json_decref(modes);
            return nomem(c, out);
        }
        SET(m, "axis", api_vec3(c, b.axis[k]));
        SET(m, "moment", api_real(c, b.moment[k]));
        SET(m, "omega", api_real(c, b.omega[k]));
        SET(m, "period", api_real(c, 2 * MECH_PI / b.omega[k]));
        SET(m, "equivalent_length", api_real(c, b.moment[k] / (api_number_of(s, "mass") * b.arm)));
        json_array_append_new(modes, m);
    }
    SET(out, "pivot", json_string("ball_joint"));
    SET(out, "tensor_pivot", api_mat3(c, b.tensor_pivot));
    SET(out, "arm", api_real(c, b.arm));
    SET(out, "modes", modes);
    return out;
}

static json_t *physical(struct api_call *c, const json_t *s, json_t *out)
{
    const json_t *tj = json_object_get(s, "tensor_center_of_mass");
    struct mech_mat3 t;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t.a[i][j] = json_number_value(json_array_get(json_array_get(tj, i), j));
    if (!json_object_get(s, "axis")) return ball(c, s, out, t);
    struct mech_physical_pendulum p;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_physical_pendulum(
        api_number_of(s, "mass"), t, api_vec3_member(s, "offset", mech_vec3_make(0, 0, 0)),
        api_vec3_member(s, "axis", mech_vec3_make(0, 0, 0)), api_number_of(s, "g"), &p, &e);
    if (st != MECH_OK) {
        if (!strcmp(e.param, "tensor")) strcpy(e.param, "tensor_center_of_mass");
        json_decref(out);
        return api_call_fail_core(c, st, &e, "/system");
    }
    SET(out, "pivot", json_string("hinge"));
    SET(out, "tensor_pivot", api_mat3(c, p.tensor_pivot));
    SET(out, "moment_axis", api_real(c, p.moment_axis));
    SET(out, "arm", api_real(c, p.arm));
    SET(out, "omega", api_real(c, p.omega));
    SET(out, "period", api_real(c, p.period));
    SET(out, "equivalent_length", api_real(c, p.equivalent_length));
    return out;
}

static json_t *foucault(struct api_call *c, const json_t *s, json_t *out)
{
    struct mech_foucault_modes f;
    struct mech_error e;
    mech_error_clear(&e);
    double w_earth;
    if (!api_earth_rotation(c, s, "/system", "omega_earth", MECH_EARTH_OMEGA, &w_earth)) {
        json_decref(out);
        return NULL;
    }
    enum mech_status st = mech_foucault_modes(
        api_number_of(s, "length"), api_number_of(s, "g"), w_earth,
        api_number(s, "latitude_deg", 0) * (MECH_PI / 180), &f, &e);
    if (st != MECH_OK) {
        json_decref(out);
        return api_call_fail_core(c, st, &e, "/system");
    }
    json_t *modes = json_array(), *m1 = json_object(), *m2 = json_object();
    if (!modes || !m1 || !m2) {
        json_decref(modes);
        json_decref(m1);
        json_decref(m2);
        return nomem(c, out);
    }
    SET(m1, "sense", json_string("counterclockwise"));
    SET(m1, "omega", api_real(c, f.ccw));
    SET(m1, "period", api_real(c, 2 * MECH_PI / f.ccw));
    SET(m2, "sense", json_string("clockwise"));
    SET(m2, "omega", api_real(c, f.cw));
    SET(m2, "period", api_real(c, 2 * MECH_PI / f.cw));
    json_array_append_new(modes, m1);
    json_array_append_new(modes, m2);
    SET(out, "omega0", api_real(c, f.omega0));
    SET(out, "omega_z", api_real(c, f.omega_z));
    SET(out, "swing_omega", api_real(c, f.swing));
    SET(out, "swing_period", api_real(c, 2 * MECH_PI / f.swing));
    SET(out, "modes", modes);
    SET(out, "precession_rate", api_real(c, fabs(f.omega_z)));
    SET(out, "precession_sense", json_string(f.omega_z > 0   ? "clockwise"
                                             : f.omega_z < 0 ? "counterclockwise"
                                                             : "none"));
    SET(out, "precession_period",
        f.omega_z != 0 ? api_real(c, 2 * MECH_PI / fabs(f.omega_z)) : json_null());
    return out;
}

json_t *api_op_small_oscillations(struct api_call *c, const json_t *body)
{
    const json_t *s = json_object_get(body, "system");
    const char *name = api_string(s, "name", "");
    json_t *out = json_object();
    if (!out) return nomem(c, NULL);
    SET(out, "system", json_string(name));
    if (!strcmp(name, "central_orbit")) return central(c, s, out);
    if (!strcmp(name, "conical_pendulum")) return conical(c, s, out);
    if (!strcmp(name, "foucault_pendulum")) return foucault(c, s, out);
    return physical(c, s, out);
}

