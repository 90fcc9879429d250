/* effective_force.c — POST /v1/frames/effective-force (notes §1.2: the four
 * fictitious forces of a rotating frame). JSON <-> core only: the physics is
 * core/frames/effective_force.c (derivation in mech/frames/effective_force.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/frames/effective_force.h"

/* Set key to value (a new reference, may be NULL after an allocation failure:
 * then the key is set to null and the answer is incomplete, never a crash). */
static void put(json_t *obj, const char *key, json_t *value)
{
    json_object_set_new(obj, key, value ? value : json_null());
}

json_t *api_op_frames_effective_force(struct api_call *c, const json_t *body)
{
    const struct mech_vec3 zero = {0, 0, 0};
    const json_t *fj = json_object_get(body, "frame");
    const json_t *pj = json_object_get(body, "particle");
    struct mech_frame_motion fr;
    fr.omega = api_vec3_member(fj, "omega", zero);
    fr.omega_dot = api_vec3_member(fj, "omega_dot", zero);
    fr.acceleration = api_vec3_member(fj, "acceleration", zero);
    double mass = api_number(pj, "mass", 0);
    struct mech_vec3 r = api_vec3_member(pj, "position", zero);
    struct mech_vec3 v = api_vec3_member(pj, "velocity", zero);
    struct mech_vec3 F = api_vec3_member(body, "force", zero);

    struct mech_effective_force ef;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_effective_force(&fr, mass, r, v, F, &ef, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object();
    json_t *terms = json_object();
    json_t *mags = json_object();
    if (!out || !terms || !mags) {
        json_decref(terms);
        json_decref(mags);
        return api_call_out_of_memory(c, out);
    }
    put(terms, "translational", api_vec3(c, ef.translational));
    put(terms, "euler", api_vec3(c, ef.euler));
    put(terms, "coriolis", api_vec3(c, ef.coriolis));
    put(terms, "centrifugal", api_vec3(c, ef.centrifugal));
    put(mags, "translational", api_real(c, mech_vec3_norm(ef.translational)));
    put(mags, "euler", api_real(c, mech_vec3_norm(ef.euler)));
    put(mags, "coriolis", api_real(c, mech_vec3_norm(ef.coriolis)));
    put(mags, "centrifugal", api_real(c, mech_vec3_norm(ef.centrifugal)));
    put(mags, "force", api_real(c, mech_vec3_norm(F)));
    put(mags, "effective_force", api_real(c, mech_vec3_norm(ef.effective)));
    put(out, "terms", terms);
    put(out, "magnitudes", mags);
    put(out, "fictitious_total", api_vec3(c, ef.fictitious));
    put(out, "force", api_vec3(c, F));
    put(out, "effective_force", api_vec3(c, ef.effective));
    put(out, "acceleration", api_vec3(c, ef.acceleration));
    put(out, "inertial_acceleration", api_vec3(c, ef.inertial_acceleration));
    put(out, "velocity_rotation_part", api_vec3(c, mech_vec3_cross(fr.omega, r)));
    put(out, "formula",
        json_string("F_eff = F - m A - m (dw/dt) x r - 2 m w x v - m w x (w x r) "
                    "(translational, Euler, Coriolis, centrifugal; notes §1.2)"));
    return out;
}
