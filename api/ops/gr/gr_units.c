/* gr_units.c — the units block of the general-relativity operations
 * (api/ops/gr/gr_units.h): the request's M and units, the answer's units object.
 * The set-up and its checks are core/gr/gr_units.c. */
#include <math.h>
#include <string.h>

#include "ops/gr/gr_units.h"
#include "mech/base/constants.h"
#include "mech/base/named_bodies.h"

/* The named body M names in the request's set (named_bodies, default
 * "DE440"), or NULL when M is not a name. */
static const struct mech_named_body *named_m(const json_t *body)
{
    const json_t *M = body ? json_object_get(body, "M") : NULL;
    enum mech_body_set set = MECH_BODY_SET_DE440;
    const char *sn = api_string_of(body, "named_bodies");
    if (*sn && !mech_body_set_parse(sn, &set)) return NULL;
    return json_is_string(M) ? mech_named_body(set, json_string_value(M)) : NULL;
}

/* Parse M and units; the set-up and its checks are mech_gr_units_init.
 * Returns 0 after recording an error. */
int api_gr_units_read(struct api_call *c, const json_t *body, struct mech_gr_units *u)
{
    const int geometric = !strcmp(api_string_of(body, "units"), "geometric");
    const json_t *M = json_object_get(body, "M");
    enum mech_gr_mass kind = MECH_GR_MASS_NONE;
    double value = NAN;
    if (json_is_string(M)) {
        /* a named body: its GM in the request's set (the schema allows only
         * known names and sets) */
        const struct mech_named_body *nb = named_m(body);
        kind = MECH_GR_MASS_GM;
        value = nb ? nb->gm : NAN;
    } else if (json_is_object(M) && json_object_get(M, "surface_gravity")) {
        /* g = GM/R^2 at R: GM = g R^2 */
        const double g = api_number_of(M, "surface_gravity"), r = api_number_of(M, "radius");
        kind = MECH_GR_MASS_GM;
        value = g * r * r;
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

/* Where GM came from, read from the request's M (c->body): the named
 * bodies' values with their sources, so an answer says which constants it
 * used. */
static const char *mass_source(const struct api_call *c)
{
    const json_t *M = c->body ? json_object_get(c->body, "M") : NULL;
    const struct mech_named_body *nb = named_m(c->body);
    if (nb) return nb->source;
    if (json_is_object(M) && json_object_get(M, "surface_gravity"))
        return "GM = g R^2 from the given surface gravity and radius";
    if (json_is_object(M)) return "GM as given";
    if (M) return "GM = G M, G = 6.67430e-11 m^3/(kg s^2) (CODATA 2018)";
    return NULL;
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
        const char *src = mass_source(c);
        if (src) json_object_set_new_nocheck(j, "GM_source", json_string(src));
        if (c->body && json_is_string(json_object_get(c->body, "M"))) {
            const char *sn = api_string_of(c->body, "named_bodies");
            json_object_set_new_nocheck(j, "named_bodies", json_string(*sn ? sn : "DE440"));
        }
    }
    return j;
}
