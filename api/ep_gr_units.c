/* ep_gr_units.c — the units block of the general-relativity operations
 * (api/ep_gr_units.h): the request's M and units, the answer's units object.
 * The set-up and its checks are core/gr/gr_units.c. */
#include <math.h>
#include <string.h>

#include "ep_gr_units.h"
#include "mech/constants.h"

/* Parse M and units; the set-up and its checks are mech_gr_units_init.
 * Returns 0 after recording an error. */
int api_gr_units_read(struct api_call *c, const json_t *body, struct mech_gr_units *u)
{
    const int geometric = !strcmp(api_string_of(body, "units"), "geometric");
    const json_t *M = json_object_get(body, "M");
    enum mech_gr_mass kind = MECH_GR_MASS_NONE;
    double value = NAN;
    if (json_is_string(M)) {
        kind = !strcmp(json_string_value(M), "sun") ? MECH_GR_MASS_SUN : MECH_GR_MASS_EARTH;
    } else if (json_is_object(M)) {
        kind = MECH_GR_MASS_GM;
        value = api_number(M, "gm", 0);
    } else if (M) {
        kind = MECH_GR_MASS_KG;
        value = json_number_value(M);
    }
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_gr_units_init(geometric, kind, value, u, &e);
    if (st == MECH_EDOMAIN) api_call_domain(c, "/M", "%s", e.text);
    if (st != MECH_OK && st != MECH_EDOMAIN) api_call_invalid(c, "/M", "%s", e.text);
    return st == MECH_OK;
}

json_t *api_gr_units_json(struct api_call *c, const struct mech_gr_units *u)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "system", json_string(u->geometric ? "geometric" : "SI"));
    json_object_set_new_nocheck(j, "length", json_string(u->geometric ? "GM/c^2" : "m"));
    json_object_set_new_nocheck(j, "time", json_string(u->geometric ? "GM/c^3" : "s"));
    json_object_set_new_nocheck(j, "specific_angular_momentum",
                                json_string(u->geometric ? "GM/c" : "m^2/s"));
    json_object_set_new_nocheck(j, "speed", json_string(u->geometric ? "c" : "m/s"));
    json_object_set_new_nocheck(j, "specific_energy", json_string("E/(m c^2), dimensionless"));
    json_object_set_new_nocheck(j, "angle", json_string("rad"));
    json_object_set_new_nocheck(j, "c", api_real(c, MECH_C));
    if (u->has_mass) {
        json_object_set_new_nocheck(j, "GM", api_real(c, u->GM));
        json_object_set_new_nocheck(j, "GM_over_c2", api_real(c, u->m));
        json_object_set_new_nocheck(j, "GM_over_c3", api_real(c, u->s));
        json_object_set_new_nocheck(
            j, "mass_kg", api_real(c, u->GM / MECH_GRAVITATIONAL_CONSTANT)); /* M = GM/G */
    }
    return j;
}
