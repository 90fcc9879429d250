/* ep_rigid_stability.c — POST /v1/rigid/stability: linear stability of
 * torque-free spin about a principal axis (notes §2.10). JSON <-> core only;
 * the physics is core/stability.c (derivation in mech/stability.h). */
#include <math.h>
#include <stdio.h>

#include "endpoint.h"
#include "mech/stability.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* clang-format off */
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"moments\",\"axis\",\"spin\"],\"properties\":{"
    "\"moments\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"
    "{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30},"
    "\"description\":\"principal moments [I1, I2, I3], kg m^2, > 0, any order; each at "
    "most the sum of the other two (to 1e-12 relative), as for every rigid body\"},"
    "\"axis\":{\"type\":\"integer\",\"minimum\":1,\"maximum\":3,\"description\":\"the principal axis "
    "of the spin (1-based index into moments)\"},"
    "\"spin\":{\"type\":\"number\",\"minimum\":-1e12,\"maximum\":1e12,"
    "\"description\":\"spin rate about that axis, rad/s (sign irrelevant)\"}}}";
/* clang-format on */

static const char description[] =
    "Stability of torque-free rotation about a principal axis (notes §2.10). A body with "
    "principal moments I1, I2, I3 spins at rate w about axis a; (a, b, c) is the cyclic "
    "order starting at a ((1,2,3), (2,3,1) or (3,1,2)). Euler's equations without torque "
    "(notes §2.8), I_a w_a' = (I_b - I_c) w_b w_c and cyclically, linearised about "
    "w e_a + eps e_b + eta e_c, give eps' = A eta, eta' = B eps with "
    "A = (I_c - I_a) w / I_b and B = (I_a - I_b) w / I_c, so eps'' = k eps and eta'' = k eta "
    "with k = A B = (I_c - I_a)(I_a - I_b) w^2 / (I_b I_c) (for axis 1 the notes' "
    "(I3 - I1)(I1 - I2) w1^2 / (I2 I3)). Answer: k (s^-2); stable (k < 0); classification "
    "stable / unstable / marginal (k = 0); frequency sqrt(-k) (rad/s) and period when "
    "stable, growth_rate sqrt(k) (1/s) and e_folding_time when unstable (null otherwise); "
    "axis_role: where I_a sits (smallest, intermediate, largest, or degenerate = equal to "
    "another moment); intermediate_axis: the axis with the strictly intermediate moment "
    "(null when two moments are equal); linearised: {perturbation_axes [b, c], coupling "
    "[A, B] (1/s)}; note: a sentence saying what happens. Intermediate-axis theorem: "
    "spin about the smallest or largest moment is stable, about the intermediate one "
    "unstable (the tennis-racket or book flip). Degenerate cases: when I_a equals another "
    "moment, or w = 0, k = 0 exactly: marginal (the linearisation neither oscillates nor "
    "grows exponentially; a perturbation drifts linearly, the spin axis wandering in the "
    "plane of equal moments); a symmetric body spinning about its symmetry axis is stable "
    "(k = -(I_b - I_a)^2 w^2 / I_b^2). Precision: k is the product of the two couplings, "
    "each a difference of given moments (exact for nearby moments) over a moment, so k is "
    "right to a few ulp even for nearly equal moments; |k| <= w^2. Refused (422, naming "
    "the field): a moment <= 0 (schema), a moment larger than the sum of the other two "
    "(at /moments/<i>; no rigid body has it), axis not 1, 2 or 3.";

static const char example[] = "{\"moments\":[1,2,3],\"axis\":2,\"spin\":10}";

static const char *const roles[] = {"smallest", "intermediate", "largest", "degenerate"};
static const char *const kinds[] = {"stable", "unstable", "marginal"};

static json_t *stability(struct api_call *c, const json_t *body)
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
                 b, cc, s.frequency, 2 * M_PI / s.frequency);
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
                                stable ? api_real(c, 2 * M_PI / s.frequency) : json_null());
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

const struct api_route api_route_rigid_stability = {
    "POST",
    "/v1/rigid/stability",
    "Stability of spin about a principal axis: k in eps'' = k eps, the frequency or growth "
    "rate, and which axis is intermediate",
    description,
    schema,
    example,
    stability,
    0,
    0,
};
