/* tides_answer.c — one POST /v1/earth/tides computation
 * (mech/answers/frames/tides_answer.h): the body resolved from gm or mass, the tidal
 * acceleration and equilibrium tide of tides.c, and the Moon and the Sun
 * combined. Moved from api/ops/earth/gravity.c (a handler only parses, calls
 * core once and encodes) operation for operation, so the API's answers stay
 * byte-identical. */
#include "mech/answers/frames/tides_answer.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"

/* The same text the API gives a non-finite answer. */
#define TIDES_NONFINITE "the result is not finite for this input (overflow or a singularity)"

/* A named body of the request's set, as the tides use it. */
static struct mech_tides_body builtin(enum mech_body_set set, const char *name)
{
    const struct mech_named_body *nb = mech_named_body(set, name);
    if (!nb) nb = mech_named_body(MECH_BODY_SET_DE440, name);
    struct mech_tides_body b = {nb->name, nb->gm, nb->mass, nb->distance, nb->source};
    return b;
}

/* The body the tides are raised on: the Earth of q->radius and q->gm_earth,
 * or q->on (a named body of the set, or gm or mass with a radius). */
static enum mech_status resolve_on(const struct mech_tides_request *q,
                                   struct mech_tides_answer *o, struct mech_error *err)
{
    if (!q->has_on) {
        o->on = builtin(q->set, "earth");
        o->on.gm = q->gm_earth;
        o->on.mass = q->gm_earth / MECH_GRAVITATIONAL_CONSTANT;
        if (q->gm_earth != MECH_EARTH_GM) o->on.source = "earth: GM as given (gm_earth)";
        o->on_radius = q->radius;
        o->on_gm = q->gm_earth;
        return MECH_OK;
    }
    const struct mech_tides_on_given *g = &q->on;
    if (g->name) {
        if (!mech_named_body(q->set, g->name))
            return mech_error_set(err, MECH_EINVAL, "on", "on must be earth, moon or sun, got %s",
                                  g->name);
        o->on = builtin(q->set, g->name);
        o->on_radius = mech_named_body(q->set, g->name)->radius;
    } else {
        if (g->has_gm == g->has_mass)
            return mech_error_set(err, MECH_EINVAL, "on",
                                  "give the body's gm (m^3/s^2) or its mass (kg), one of them");
        const double v = g->has_gm ? g->gm : g->mass;
        if (!(isfinite(v) && v > 0))
            return mech_error_set(err, MECH_EINVAL, g->has_gm ? "on/gm" : "on/mass",
                                  "must be finite and > 0, got %.17g", v);
        o->on.name = "custom";
        o->on.gm = g->has_gm ? g->gm : MECH_GRAVITATIONAL_CONSTANT * g->mass;
        o->on.mass = g->has_gm ? g->gm / MECH_GRAVITATIONAL_CONSTANT : g->mass;
        o->on.source = g->has_gm ? "GM as given" : "GM = G mass, G = 6.67430e-11 (CODATA 2018)";
        o->on_radius = NAN;
    }
    if (g->has_radius) o->on_radius = g->radius;
    if (!(isfinite(o->on_radius) && o->on_radius > 0))
        return mech_error_set(err, MECH_EINVAL, "on/radius",
                              "give the point's distance from the centre of the body the tides "
                              "are raised on, finite and > 0 (m)");
    o->on.distance = 0.0;
    o->on_gm = o->on.gm;
    if (q->body != MECH_TIDES_BODY_CUSTOM && !strcmp(o->on.name, o->body.name))
        return mech_error_set(err, MECH_EINVAL, "on", "a body raises no tides on itself (%s)",
                              o->on.name);
    return MECH_OK;
}

/* Apply what the request gives (g) to body b; `field` names the request's
 * object ("moon", "sun", "body"). EINVAL for both gm and mass, or a given
 * value not finite and > 0. */
static enum mech_status apply_given(const struct mech_tides_body_given *g, const char *field,
                                    struct mech_tides_body *b, struct mech_error *err)
{
    if (g->has_gm && g->has_mass)
        return mech_error_set(err, MECH_EINVAL, field,
                              "give at most one of gm and mass (GM = G mass)");
    const struct {
        int has;
        double v;
        const char *name;
    } v[] = {{g->has_gm, g->gm, "gm"},
             {g->has_mass, g->mass, "mass"},
             {g->has_distance, g->distance, "distance"}};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (v[i].has && !(isfinite(v[i].v) && v[i].v > 0)) {
            char param[32];
            snprintf(param, sizeof param, "%s/%s", field, v[i].name);
            return mech_error_set(err, MECH_EINVAL, param, "must be finite and > 0, got %.17g",
                                  v[i].v);
        }
    if (g->has_gm || g->has_mass)
        b->source = g->has_gm ? "GM as given" : "GM = G mass, G = 6.67430e-11 (CODATA 2018)";
    if (g->has_gm) {
        b->gm = g->gm;
        b->mass = b->gm / MECH_GRAVITATIONAL_CONSTANT;
    } else if (g->has_mass) {
        b->mass = g->mass;
        b->gm = MECH_GRAVITATIONAL_CONSTANT * b->mass;
    }
    if (g->has_distance) b->distance = g->distance;
    return MECH_OK;
}

/* The tide-raising body and where its distance came from (the request's
 * field to name when the body is not outside the point's sphere). */
static enum mech_status resolve_body(const struct mech_tides_request *q,
                                     struct mech_tides_answer *o, const char **dist_field,
                                     struct mech_error *err)
{
    switch (q->body) {
    case MECH_TIDES_BODY_MOON:
    case MECH_TIDES_BODY_SUN: {
        const int is_sun = q->body == MECH_TIDES_BODY_SUN;
        o->body = is_sun ? o->sun : o->moon;
        *dist_field = (is_sun ? q->sun : q->moon).has_distance
                          ? (is_sun ? "sun/distance" : "moon/distance")
                          : "radius";
        return MECH_OK;
    }
    case MECH_TIDES_BODY_CUSTOM: {
        struct mech_tides_body b = {"custom", 0, 0, 0, NULL};
        enum mech_status st = apply_given(&q->custom, "body", &b, err);
        if (st != MECH_OK) return st;
        if (!(b.gm > 0))
            return mech_error_set(err, MECH_EINVAL, "body",
                                  "give the body's gm (m^3/s^2) or its mass (kg)");
        o->body = b;
        *dist_field = "body/distance";
        return MECH_OK;
    }
    }
    return mech_error_set(err, MECH_EINVAL, "body", "unknown body kind %d", (int)q->body);
}

/* The Moon and the Sun together at this radius and angle (notes §1.4):
 * aligned (spring) and at 90 deg (neap). */
static enum mech_status spring_neap(const struct mech_tides_request *q, struct mech_tides_answer *o,
                                    struct mech_error *err)
{
    const double r = o->on_radius, th = q->angle_deg, gme = o->on_gm;
    enum mech_status st =
        mech_tide_height(o->moon.gm, gme, o->moon.distance, r, th, &o->moon_height, err);
    if (st == MECH_OK)
        st = mech_tide_height(o->sun.gm, gme, o->sun.distance, r, th, &o->sun_height, err);
    /* the Sun at 90 deg from the Moon in the point's plane: angle |90 - theta| */
    if (st == MECH_OK)
        st = mech_tide_height(o->sun.gm, gme, o->sun.distance, r, fabs(90 - th),
                              &o->sun_quadrature_height, err);
    if (st != MECH_OK) return st;
    const double hm = o->moon_height.range, hs = o->sun_height.range;
    o->sun_to_moon = hs / hm;
    o->spring_range = hm + hs;
    o->neap_range = fabs(hm - hs);
    o->spring_height = o->moon_height.height + o->sun_height.height;
    o->neap_height = o->moon_height.height + o->sun_quadrature_height.height;
    if (!isfinite(o->sun_to_moon) || !isfinite(o->spring_range) || !isfinite(o->spring_height) ||
        !isfinite(o->neap_height))
        return mech_error_set(err, MECH_ENUMERIC, NULL, TIDES_NONFINITE);
    return MECH_OK;
}

enum mech_status mech_tides_answer(const struct mech_tides_request *q,
                                   struct mech_tides_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    struct mech_tides_answer *o = out;
    *o = (struct mech_tides_answer){0};
    o->moon = builtin(q->set, "moon");
    o->sun = builtin(q->set, "sun");
    enum mech_status st = apply_given(&q->moon, "moon", &o->moon, err);
    if (st == MECH_OK) st = apply_given(&q->sun, "sun", &o->sun, err);
    const char *dist_field = "radius";
    if (st == MECH_OK) st = resolve_body(q, o, &dist_field, err);
    if (st == MECH_OK) st = resolve_on(q, o, err);
    if (st != MECH_OK) return st;
    const double radius = o->on_radius;
    if (q->has_on && !q->on.has_radius && !strcmp(dist_field, "radius")) dist_field = "on";
    if (!(o->body.distance > radius))
        return mech_error_set(err, MECH_EDOMAIN, dist_field,
                              "the body (distance %.17g m) must lie outside the sphere through "
                              "the point (radius %.17g m)",
                              o->body.distance, radius);
    const struct mech_tides_body *b = &o->body;
    st = mech_tide_acceleration(b->gm, b->distance, radius, q->angle_deg, &o->acceleration, err);
    if (st == MECH_OK)
        st = mech_tide_height(b->gm, o->on_gm, b->distance, radius, q->angle_deg, &o->height, err);
    if (st != MECH_OK) return st;
    /* Moon and Sun with the standard constants (or as given), at this radius,
     * on the Earth only (their distances are from the Earth's centre); none
     * when the radius reaches either */
    const int on_earth = !q->has_on || !strcmp(o->on.name, "earth");
    o->has_spring_neap = on_earth && radius < o->moon.distance && radius < o->sun.distance;
    if (o->has_spring_neap) return spring_neap(q, o, err);
    return MECH_OK;
}
