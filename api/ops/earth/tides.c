/* tides.c — POST /v1/earth/tides (notes §1.4: tidal acceleration and tide
 * heights). JSON <-> core only: the answer is one call, mech_tides_answer()
 * (core/answers/frames/tides_answer.c; the physics is core/frames/tides.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/answers/frames/tides_answer.h"

/* Set key to value (a new reference, may be NULL after an allocation failure:
 * then the key is set to null and the answer is incomplete, never a crash). */
static void put(json_t *obj, const char *key, json_t *value)
{
    json_object_set_new(obj, key, value ? value : json_null());
}

/* A request's {gm | mass, distance} object (may be NULL: nothing given). */
static struct mech_tides_body_given td_given(const json_t *o)
{
    struct mech_tides_body_given g = {0};
    g.has_gm = json_object_get(o, "gm") != NULL;
    g.has_mass = json_object_get(o, "mass") != NULL;
    g.has_distance = json_object_get(o, "distance") != NULL;
    g.gm = api_number(o, "gm", 0);
    g.mass = api_number(o, "mass", 0);
    g.distance = api_number(o, "distance", 0);
    return g;
}

static json_t *components(struct api_call *c, const struct mech_tide_components *x)
{
    json_t *o = json_object();
    if (!o) return NULL;
    put(o, "radial", api_real(c, x->radial));
    put(o, "tangential", api_real(c, x->tangential));
    put(o, "along", api_real(c, x->along));
    put(o, "perpendicular", api_real(c, x->perpendicular));
    put(o, "magnitude", api_real(c, hypot(x->radial, x->tangential)));
    return o;
}

/* "spring_neap": the Moon and the Sun together, or null. */
static json_t *td_spring_neap(struct api_call *c, const struct mech_tides_answer *a)
{
    json_t *s = a->has_spring_neap ? json_object() : NULL;
    if (!s) return json_null();
    put(s, "moon_range", api_real(c, a->moon_height.range));
    put(s, "sun_range", api_real(c, a->sun_height.range));
    put(s, "sun_to_moon", api_real(c, a->sun_to_moon));
    put(s, "spring_range", api_real(c, a->spring_range));
    put(s, "neap_range", api_real(c, a->neap_range));
    put(s, "moon_gm", api_real(c, a->moon.gm));
    put(s, "moon_distance", api_real(c, a->moon.distance));
    put(s, "sun_gm", api_real(c, a->sun.gm));
    put(s, "sun_distance", api_real(c, a->sun.distance));
    put(s, "spring_height", api_real(c, a->spring_height));
    put(s, "neap_height", api_real(c, a->neap_height));
    put(s, "moon_source", json_string(a->moon.source));
    put(s, "sun_source", json_string(a->sun.source));
    return s;
}

json_t *api_op_earth_tides(struct api_call *c, const json_t *body)
{
    const json_t *bj = json_object_get(body, "body");
    struct mech_tides_request q = {0};
    q.body = !json_is_string(bj)                     ? MECH_TIDES_BODY_CUSTOM
             : !strcmp(json_string_value(bj), "sun") ? MECH_TIDES_BODY_SUN
                                                     : MECH_TIDES_BODY_MOON;
    q.custom = td_given(json_is_object(bj) ? bj : NULL);
    q.moon = td_given(json_object_get(body, "moon"));
    q.sun = td_given(json_object_get(body, "sun"));
    q.angle_deg = api_number_of(body, "angle_deg");
    q.radius = api_number_of(body, "radius");
    q.gm_earth = api_number_of(body, "gm_earth");
    mech_body_set_parse(api_string_of(body, "named_bodies"), &q.set); /* the schema's enum */
    const json_t *on = json_object_get(body, "on");
    if (on && (api_call_given(c, "/radius") || api_call_given(c, "/gm_earth"))) {
        api_call_invalid(c, api_call_given(c, "/radius") ? "/radius" : "/gm_earth",
                         "give on (the body the tides are raised on, with its radius and GM) "
                         "or the older radius and gm_earth, not both");
        return NULL;
    }
    q.has_on = on != NULL;
    if (json_is_string(on)) q.on.name = json_string_value(on);
    if (json_is_object(on)) {
        q.on.has_gm = json_object_get(on, "gm") != NULL;
        q.on.has_mass = json_object_get(on, "mass") != NULL;
        q.on.has_radius = json_object_get(on, "radius") != NULL;
        q.on.gm = api_number(on, "gm", 0);
        q.on.mass = api_number(on, "mass", 0);
        q.on.radius = api_number(on, "radius", 0);
    }
    struct mech_tides_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_tides_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object(), *bo = json_object(), *acc = json_object(), *eq = json_object();
    if (!out || !bo || !acc || !eq) {
        json_decref(bo);
        json_decref(acc);
        json_decref(eq);
        return api_call_out_of_memory(c, out);
    }
    put(bo, "name", json_string(a.body.name));
    put(bo, "gm", api_real(c, a.body.gm));
    put(bo, "mass", api_real(c, a.body.mass));
    put(bo, "distance", api_real(c, a.body.distance));
    put(bo, "source", json_string(a.body.source));
    put(out, "body", bo);
    json_t *oo = json_object();
    put(oo, "name", json_string(a.on.name));
    put(oo, "gm", api_real(c, a.on_gm));
    put(oo, "mass", api_real(c, a.on.mass));
    put(oo, "radius", api_real(c, a.on_radius));
    put(oo, "source", json_string(a.on.source));
    put(out, "on", oo);
    put(out, "named_bodies", json_string(mech_body_set_name(q.set)));
    put(out, "radius", api_real(c, a.on_radius));
    put(out, "angle_deg", api_real(c, q.angle_deg));
    put(out, "r_over_d", api_real(c, a.acceleration.u));
    put(out, "pull_at_centre", api_real(c, a.acceleration.pull));
    put(out, "tidal_scale", api_real(c, a.acceleration.scale));
    put(acc, "exact", components(c, &a.acceleration.exact));
    put(acc, "first_order", components(c, &a.acceleration.first_order));
    put(acc, "difference", components(c, &a.acceleration.difference));
    put(acc, "relative_difference", api_real(c, a.acceleration.relative_difference));
    put(out, "acceleration", acc);
    put(eq, "height", api_real(c, a.height.height));
    put(eq, "high", api_real(c, a.height.high));
    put(eq, "low", api_real(c, a.height.low));
    put(eq, "range", api_real(c, a.height.range));
    put(eq, "gm_on", api_real(c, a.on_gm));
    put(eq, "gm_earth", api_real(c, a.on_gm)); /* the older name of gm_on */
    put(eq, "formula",
        json_string("h = GM r^4 (3 cos^2 theta - 1) / (2 GM_E d^3); range = "
                    "3 GM r^4 / (2 GM_E d^3) (notes: g h = 3 GM r^2 / (2 d^3))"));
    put(out, "equilibrium_tide", eq);
    put(out, "spring_neap", td_spring_neap(c, &a));
    return out;
}
