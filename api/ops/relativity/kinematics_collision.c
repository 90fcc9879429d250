/* kinematics_collision.c — POST /v1/relativity/kinematics/collision: two
 * particles colliding, the energy available and the thresholds of the final
 * states. The whole answer is one call, mech_collision_answer
 * (core/answers/relativity/collision_answer.c), which this file reads the request for
 * and encodes.
 * Energies, masses (unit/c²) and momenta (unit/c) are in `energy_unit`
 * (eV … TeV, default MeV; c = 1); particles are a name from the PDG 2024 table
 * (core/relativity/particles.c) or a mass. The numerics live in
 * core/relativity/kinematics.c; the readers and encoders the kinematics
 * operations share are api/ops/relativity/kin_request.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"
#include "ops/relativity/kin_request.h"
#include "mech/answers/relativity/collision_answer.h"

/* The request as the core takes it (mf: room for the final masses); 0 after
 * recording every error found (masses, the crossing angle, the motions, and
 * what cannot go together: a crossing angle with a target at rest, sqrt_s
 * with a beam energy or a moving target). */
static int collision_read(struct api_call *c, const json_t *body, enum mech_energy_unit u,
                          struct mech_collision_request *q, double mf[MECH_COLLISION_MAX_FINAL])
{
    memset(q, 0, sizeof *q);
    const json_t *jb = json_object_get(body, "beam"), *jt = json_object_get(body, "target");
    const json_t *jw = json_object_get(body, "sqrt_s"), *jf = json_object_get(body, "final_state");
    double m1 = 0, m2 = 0;
    int ok = api_kin_mass_of(c, json_object_get(jb, "particle"), "/beam/particle", u, &m1);
    ok &= api_kin_mass_of(c, json_object_get(jt, "particle"), "/target/particle", u, &m2);
    q->n_final = json_array_size(jf); /* the schema's maxItems is the core's limit */
    for (size_t i = 0; i < q->n_final && i < MECH_COLLISION_MAX_FINAL; i++) {
        char p[40];
        snprintf(p, sizeof p, "/final_state/%zu", i);
        ok &= api_kin_mass_of(c, json_array_get(jf, i), p, u, &mf[i]);
    }
    q->final_masses = mf;
    const int hx = api_kin_angle_of(c, body, "crossing_angle", "/crossing_angle", &q->crossing_angle);
    int gt = 0, gb = 0;
    if (!ok || hx < 0 || !api_kin_motion_of(c, jt, "/target", m2, &q->target, &gt)) return 0;
    if (hx && !gt)
        api_call_invalid(
            c, json_object_get(body, "crossing_angle") ? "/crossing_angle" : "/crossing_angle_deg",
            "a crossing angle needs a moving target (a second beam)");
    if (jw) {
        static const char *const keys[] = {"energy", "kinetic_energy", "momentum", "velocity"};
        for (int i = 0; i < 4; i++)
            if (json_object_get(jb, keys[i]))
                api_call_invalid(c, "/sqrt_s", "give either the beam's %s or sqrt_s, not both",
                                 keys[i]);
        if (gt)
            api_call_invalid(c, "/sqrt_s",
                             "sqrt_s is solved for a target at rest; give the "
                             "target no motion");
        q->beam_from_sqrt_s = 1;
        q->sqrt_s = json_number_value(jw);
        q->beam.mass = m1;
    } else if (!api_kin_motion_of(c, jb, "/beam", m1, &q->beam, &gb)) {
        return 0;
    }
    return c->problem == API_PROBLEM_NONE;
}

/* The threshold block of a final state. */
static json_t *threshold_json(struct api_call *c, const struct mech_collision_threshold *t)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "sqrt_s", api_real(c, t->sqrt_s));
    json_object_set_new_nocheck(o, "reached", json_boolean(t->reached));
    if (t->has_fixed_target) {
        json_object_set_new_nocheck(o, "fixed_target_beam_energy",
                                    api_real(c, t->fixed_target_beam_energy));
        json_object_set_new_nocheck(o, "fixed_target_beam_kinetic_energy",
                                    api_real(c, t->fixed_target_beam_kinetic));
        json_object_set_new_nocheck(o, "fixed_target_beam_momentum",
                                    api_real(c, t->fixed_target_beam_momentum));
    }
    if (t->has_symmetric_collider)
        json_object_set_new_nocheck(o, "symmetric_collider_beam_energy",
                                    api_real(c, t->symmetric_collider_beam_energy));
    return o;
}

json_t *api_op_relativity_kinematics_collision(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    struct mech_collision_request q;
    double mf[MECH_COLLISION_MAX_FINAL];
    if (!api_kin_unit_of(c, body, &u) || !collision_read(c, body, u, &q, mf)) return NULL;
    struct mech_collision_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_collision_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "sqrt_s", api_real(c, a.sqrt_s));
    json_object_set_new_nocheck(res, "s", api_real(c, a.s));
    json_object_set_new_nocheck(res, "available_energy", api_real(c, a.available_energy));
    json_object_set_new_nocheck(res, "cm_momentum", api_real(c, a.cm_momentum));
    json_object_set_new_nocheck(res, "beam", api_kin_describe_motion(c, &a.beam));
    json_object_set_new_nocheck(res, "target", api_kin_describe_motion(c, &a.target));
    json_object_set_new_nocheck(res, "center_of_momentum", api_kin_describe_cm(c, &a.cm));
    if (a.has_fixed_target) {
        json_object_set_new_nocheck(res, "fixed_target_beam_energy",
                                    api_real(c, a.fixed_target_beam_energy));
        json_object_set_new_nocheck(res, "fixed_target_beam_kinetic_energy",
                                    api_real(c, a.fixed_target_beam_kinetic));
    }
    if (a.has_symmetric_collider)
        json_object_set_new_nocheck(res, "symmetric_collider_beam_energy",
                                    api_real(c, a.symmetric_collider_beam_energy));
    if (a.has_threshold)
        json_object_set_new_nocheck(res, "threshold", threshold_json(c, &a.threshold));
    return api_kin_finish(c, res);
}
