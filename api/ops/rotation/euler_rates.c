/* euler_rates.c — POST /v1/rotation/euler-rates: Euler-angle kinematics.
 * z-x-z angles with their rates -> the angular velocity in body and space
 * axes, the rotation matrix and its time derivative (dR/dt = -[omega_body]x R
 * for the passive R); or angles with omega -> the rates, with gimbal lock
 * answered by a typed note, never NaN. JSON <-> core only; the mathematics is
 * core/rotation/euler_rates.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/rotation/euler_rates.h"

json_t *api_op_rotation_euler_rates(struct api_call *c, const json_t *body)
{
    static const char *const forms[3] = {"rates", "omega_body", "omega_space"};
    int given = -1;
    for (int k = 0; k < 3; k++)
        if (json_object_get(body, forms[k])) {
            if (given >= 0) {
                char p[32];
                snprintf(p, sizeof p, "/%s", forms[k]);
                api_call_invalid(c, p, "give exactly one of rates, omega_body, omega_space; "
                                       "%s is already given", forms[given]);
                return NULL;
            }
            given = k;
        }
    if (given < 0) {
        api_call_invalid(c, "", "give one of rates, omega_body, omega_space");
        return NULL;
    }
    struct mech_vec3 av = api_vec3_member(body, "euler_zxz", mech_vec3_make(0, 0, 0));
    struct mech_vec3 gv = api_vec3_member(body, forms[given], mech_vec3_make(0, 0, 0));
    double angles[3] = {av.x, av.y, av.z}, in[3] = {gv.x, gv.y, gv.z};
    struct mech_euler_kinematics k;
    struct mech_error e;
    mech_error_clear(&e);
    double comb = 0;
    enum mech_status st = given == 0 ? mech_euler_kinematics(angles, in, &k, &e)
                                     : mech_euler_rates_from_omega(angles, gv, given == 1, &k,
                                                                   &comb, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *rates = json_object(), *notes = json_array();
    if (!out || !rates || !notes) {
        json_decref(out);
        json_decref(rates);
        json_decref(notes);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    int undetermined = given != 0 && k.gimbal_lock;
    int at_pi = cos(angles[1]) < 0;
    json_object_set_new_nocheck(rates, "phi_dot", undetermined ? json_null() : api_real(c, k.rates[0]));
    json_object_set_new_nocheck(rates, "theta_dot", api_real(c, k.rates[1]));
    json_object_set_new_nocheck(rates, "psi_dot", undetermined ? json_null() : api_real(c, k.rates[2]));
    if (k.gimbal_lock) {
        /* theta = 0: phi' + psi'; theta = pi: psi' - phi' (from the rates or omega) */
        double v = undetermined ? comb : (at_pi ? k.rates[2] - k.rates[0] : k.rates[0] + k.rates[2]);
        json_object_set_new_nocheck(rates, at_pi ? "psi_dot_minus_phi_dot" : "phi_dot_plus_psi_dot",
                                    api_real(c, v));
        json_array_append_new(notes, json_string(
            at_pi ? "gimbal lock (theta = pi): the z axes are antiparallel, so phi and psi turn "
                    "about the same line and only psi' - phi' affects omega"
                  : "gimbal lock (theta = 0): the z axes coincide, so phi and psi turn about the "
                    "same line and only phi' + psi' affects omega"));
        if (undetermined)
            json_array_append_new(notes, json_string(
                "phi_dot and psi_dot are not determined by omega at the lock: they are null, "
                "and only their combination is given"));
    }
    json_object_set_new_nocheck(out, "rates", rates);
    json_object_set_new_nocheck(out, "omega_body", api_vec3(c, k.omega_body));
    json_object_set_new_nocheck(out, "omega_space", api_vec3(c, k.omega_space));
    json_object_set_new_nocheck(out, "omega_magnitude", api_real(c, mech_vec3_norm(k.omega_body)));
    json_object_set_new_nocheck(out, "rotation", api_mat3(c, k.rotation));
    json_object_set_new_nocheck(out, "rotation_rate", api_mat3(c, k.rotation_rate));
    json_object_set_new_nocheck(out, "omega_cross_body", api_mat3(c, k.omega_cross_body));
    json_object_set_new_nocheck(out, "omega_cross_space", api_mat3(c, k.omega_cross_space));
    json_object_set_new_nocheck(out, "residual", api_real(c, k.residual));
    json_object_set_new_nocheck(out, "gimbal_lock", json_boolean(k.gimbal_lock));
    json_object_set_new_nocheck(out, "notes", notes);
    return out;
}

