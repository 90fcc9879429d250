/* stability.c — POST /v1/rigid/stability: linear stability of
 * torque-free spin about a principal axis (notes §2.10). JSON <-> core only;
 * the physics is core/rigid/stability.c (derivation in mech/rigid/stability.h). */
#include <math.h>
#include <stdio.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/rigid/stability.h"


static const char *const roles[] = {"smallest", "intermediate", "largest", "degenerate"};
static const char *const kinds[] = {"stable", "unstable", "marginal"};

json_t *api_op_rigid_stability(struct api_call *c, const json_t *body)
{
    const json_t *mj = json_object_get(body, "moments");
    double m[3];
    for (size_t i = 0; i < 3; i++)
        m[i] = json_number_value(json_array_get(mj, i));
    int axis = (int)api_number(body, "axis", 0);
    double spin = api_number(body, "spin", 0);
    struct mech_stability s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_stability_principal(m, axis, spin, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    char note[400];
    int a = axis, b = s.perturbation_axes[0], cc = s.perturbation_axes[1];
    if (spin == 0)
        snprintf(note, sizeof note, "no spin: k = 0, nothing to be stable or unstable about");
    else if (s.kind == MECH_STABILITY_STABLE)
        snprintf(note, sizeof note,
                 "stable: a small tilt towards axes %d and %d oscillates at %.6g rad/s "
                 "(period %.6g s) and stays small",
                 b, cc, s.frequency, 2 * MECH_PI / s.frequency);
    else if (s.kind == MECH_STABILITY_UNSTABLE)
        snprintf(note, sizeof note,
                 "unstable (axis %d has the intermediate moment): a small tilt grows like "
                 "exp(%.6g t), by e every %.6g s, until the body flips",
                 a, s.growth_rate, 1 / s.growth_rate);
    else
        snprintf(note, sizeof note,
                 "marginal: I%d equals another moment, so k = 0; the linearisation neither "
                 "oscillates nor grows exponentially (a tilt drifts linearly, the spin axis "
                 "wandering in the plane of equal moments)",
                 a);

    json_t *out = json_object();
    json_t *lin = json_object();
    if (!out || !lin) {
        json_decref(out);
        json_decref(lin);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    int stable = s.kind == MECH_STABILITY_STABLE, unstable = s.kind == MECH_STABILITY_UNSTABLE;
    json_object_set_new_nocheck(out, "k", api_real(c, s.k));
    json_object_set_new_nocheck(out, "stable", json_boolean(stable));
    json_object_set_new_nocheck(out, "classification", json_string(kinds[s.kind]));
    json_object_set_new_nocheck(out, "frequency", stable ? api_real(c, s.frequency) : json_null());
    json_object_set_new_nocheck(out, "period",
                                stable ? api_real(c, 2 * MECH_PI / s.frequency) : json_null());
    json_object_set_new_nocheck(out, "growth_rate",
                                unstable ? api_real(c, s.growth_rate) : json_null());
    json_object_set_new_nocheck(out, "e_folding_time",
                                unstable ? api_real(c, 1 / s.growth_rate) : json_null());
    json_object_set_new_nocheck(out, "axis", json_integer(axis));
    json_object_set_new_nocheck(out, "axis_role", json_string(roles[s.role]));
    json_object_set_new_nocheck(out, "intermediate_axis",
                                s.intermediate_axis ? json_integer(s.intermediate_axis)
                                                    : json_null());
    json_t *pa = json_pack("[i,i]", b, cc);
    json_object_set_new_nocheck(lin, "perturbation_axes", pa ? pa : json_null());
    json_object_set_new_nocheck(lin, "coupling", api_reals(c, s.coupling, 2));
    json_object_set_new_nocheck(out, "linearised", lin);
    json_object_set_new_nocheck(out, "note", json_string(note));
    return out;
}

