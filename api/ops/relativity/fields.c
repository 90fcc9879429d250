/* fields.c — POST /v1/relativity/fields: E and B under a boost (notes "Lorentz
 * Transformation of the Fields"). The numerics are core/relativity/em_fields.c;
 * the velocity is the shared input of api/ops/relativity/velocity_request.h. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/em_fields.h"
#include "ops/relativity/velocity_request.h"

/* In SI the first invariant is E^2 - c^2 B^2: it is answered under that
 * name too (E2_minus_B2 keeps the same number for existing clients), and
 * c E.B, the second in the same unit V^2/m^2. */
static json_t *invariants_json(struct api_call *c, const struct mech_em_invariants *v, int si)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "E2_minus_B2", api_real(c, v->e2_minus_b2));
    json_object_set_new_nocheck(o, "E_dot_B", api_real(c, v->e_dot_b));
    if (si) {
        json_object_set_new_nocheck(o, "E2_minus_c2_B2", api_real(c, v->e2_minus_b2));
        json_object_set_new_nocheck(o, "c_E_dot_B", api_real(c, MECH_EM_C * v->e_dot_b));
    }
    return o;
}

json_t *api_op_relativity_fields(struct api_call *c, const json_t *body)
{
    struct mech_boost b;
    if (!api_velocity_parse(c, json_object_get(body, "velocity"), "/velocity", &b)) return NULL;
    const char *units = api_string_of(body, "units");
    const int si = !strcmp(units, "si");
    const struct mech_vec3 e = api_vec3_member(body, "E", mech_vec3_make(0, 0, 0));
    const struct mech_vec3 bf = api_vec3_member(body, "B", mech_vec3_make(0, 0, 0));
    struct mech_em_boosted r;
    struct mech_error err;
    mech_error_clear(&err);
    enum mech_status st =
        mech_em_fields_boost(&b, e, bf, si ? MECH_EM_SI : MECH_EM_HEAVISIDE_LORENTZ, &r, &err);
    if (st != MECH_OK) return api_call_fail_core(c, st, &err, "");

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "units", json_string(si ? "si" : "heaviside_lorentz"));
    json_object_set_new(
        res, "convention",
        json_string(si ? "passive boost into the frame moving with velocity v = beta c: "
                         "E'par = Epar, B'par = Bpar, E'perp = gamma (E + v x B)perp, "
                         "B'perp = gamma (B - v x E / c^2)perp; E in V/m, B in T"
                       : "passive boost into the frame moving with velocity beta (c = 1): "
                         "E'par = Epar, B'par = Bpar, E'perp = gamma (E + beta x B)perp, "
                         "B'perp = gamma (B - beta x E)perp"));
    json_object_set_new_nocheck(res, "E", api_vec3(c, r.e));
    json_object_set_new_nocheck(res, "B", api_vec3(c, r.b));
    api_velocity_describe(c, &b, res);
    json_object_set_new_nocheck(res, "invariants_before", invariants_json(c, &r.before, si));
    json_object_set_new_nocheck(res, "invariants_after", invariants_json(c, &r.after, si));
    json_object_set_new_nocheck(res, "field_scale_squared", api_real(c, r.scale2));
    json_t *diff = json_object();
    const double s2 = r.scale2 > 0 ? r.scale2 : 1.0;
    const double k = si ? MECH_EM_C : 1.0;
    json_object_set_new_nocheck(diff, "E2_minus_B2",
                                api_real(c, fabs(r.after.e2_minus_b2 - r.before.e2_minus_b2) / s2));
    json_object_set_new_nocheck(diff, "E_dot_B",
                                api_real(c, fabs(r.after.e_dot_b - r.before.e_dot_b) * k / s2));
    json_object_set_new_nocheck(res, "invariants_difference", diff);
    if (!res || !diff) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}
