/* tides_answer.c — one POST /v1/earth/tides computation
 * (mech/answers/frames/tides_answer.h): the body resolved from gm or mass, the tidal
 * acceleration and equilibrium tide of tides.c, and the Moon and the Sun
 * combined. Moved from api/ep_frames_earth.c (a handler only parses, calls
 * core once and encodes) operation for operation, so the API's answers stay
 * byte-identical. */
#include "mech/answers/frames/tides_answer.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "mech/base/constants.h"

/* The same text the API gives a non-finite answer. */
#define TIDES_NONFINITE "the result is not finite for this input (overflow or a singularity)"

static struct mech_tides_body builtin_moon(void)
{
    struct mech_tides_body b = {"moon", MECH_MOON_GM, MECH_MOON_MASS, MECH_MOON_DISTANCE,
                                "GM = 4.902800118e12 m^3/s^2 (JPL DE440), mass = GM/G; mean "
                                "distance 3.844e8 m (semi-major axis)"};
    return b;
}

static struct mech_tides_body builtin_sun(void)
{
    struct mech_tides_body b = {"sun", MECH_SUN_GM, MECH_SUN_GM / MECH_GRAVITATIONAL_CONSTANT,
                                MECH_AU,
                                "GM = 1.32712440041279419e20 m^3/s^2 (JPL DE440), mass = GM/G; "
                                "distance 1 au = 1.495978707e11 m (IAU 2012 B2)"};
    return b;
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
    const double r = q->radius, th = q->angle_deg, gme = q->gm_earth;
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
    o->moon = builtin_moon();
    o->sun = builtin_sun();
    enum mech_status st = apply_given(&q->moon, "moon", &o->moon, err);
    if (st == MECH_OK) st = apply_given(&q->sun, "sun", &o->sun, err);
    const char *dist_field = "radius";
    if (st == MECH_OK) st = resolve_body(q, o, &dist_field, err);
    if (st != MECH_OK) return st;
    if (!(o->body.distance > q->radius))
        return mech_error_set(err, MECH_EDOMAIN, dist_field,
                              "the body (distance %.17g m) must lie outside the sphere through "
                              "the point (radius %.17g m)",
                              o->body.distance, q->radius);
    const struct mech_tides_body *b = &o->body;
    st = mech_tide_acceleration(b->gm, b->distance, q->radius, q->angle_deg, &o->acceleration, err);
    if (st == MECH_OK)
        st = mech_tide_height(b->gm, q->gm_earth, b->distance, q->radius, q->angle_deg, &o->height,
                              err);
    if (st != MECH_OK) return st;
    /* Moon and Sun with the standard constants (or as given), at this radius;
     * none when the radius reaches either */
    o->has_spring_neap = q->radius < o->moon.distance && q->radius < o->sun.distance;
    if (o->has_spring_neap) return spring_neap(q, o, err);
    return MECH_OK;
}
