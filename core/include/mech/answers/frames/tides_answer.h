/* mech/answers/frames/tides_answer.h — one POST /v1/earth/tides answer, from the request as
 * read to everything the answer states: the tide-raising body resolved (the
 * Moon, the Sun or a custom body, each from gm or mass and a distance), its
 * tidal acceleration exact and to first order (mech/frames/tides.h), its
 * equilibrium tide, and the Moon and the Sun together (spring and neap
 * tides). The API's handler parses, calls mech_tides_answer() once and
 * encodes.
 *
 * Units SI, angles in degrees. Pure, no allocation, thread-safe. */
#ifndef MECH_TIDES_ANSWER_H
#define MECH_TIDES_ANSWER_H

#include "mech/base/named_bodies.h"
#include "mech/base/status.h"
#include "mech/frames/tides.h"

/* The body the request names. */
enum mech_tides_body_kind {
    MECH_TIDES_BODY_MOON = 0, /* the Moon (DE440 GM, 3.844e8 m), or `moon` as given */
    MECH_TIDES_BODY_SUN,      /* the Sun (DE440 GM, 1 au), or `sun` as given */
    MECH_TIDES_BODY_CUSTOM    /* `custom`: gm or mass, and distance, all from the request */
};

/* A body as the request states it: each member used only when its has_ flag
 * is set (gm m^3/s^2, mass kg, distance m). */
struct mech_tides_body_given {
    int has_gm, has_mass, has_distance;
    double gm, mass, distance;
};

/* The body the tides are raised on, when it is not the Earth of
 * radius/gm_earth: a named body of the set, or gm or mass and a radius. */
struct mech_tides_on_given {
    const char *name; /* "earth", "moon", "sun" (the set's values), or NULL: custom */
    int has_gm, has_mass, has_radius;
    double gm, mass, radius; /* m^3/s^2, kg, m (the point's distance from its centre) */
};

struct mech_tides_request {
    enum mech_body_set set; /* the named bodies' constants: DE440 (0, default) or legacy */
    int has_on;             /* 1: `on` replaces radius and gm_earth */
    struct mech_tides_on_given on;
    enum mech_tides_body_kind body;
    struct mech_tides_body_given custom;    /* the body object (MECH_TIDES_BODY_CUSTOM only; without
                                               a distance it is 0, refused as inside the sphere) */
    struct mech_tides_body_given moon, sun; /* overrides of the built-in Moon and Sun */
    double angle_deg; /* [0, 180], between the body and the point, at the Earth's centre */
    double radius;    /* m, > 0: the point's distance from the Earth's centre (has_on: unused) */
    double gm_earth;  /* m^3/s^2, > 0: g = GM_E / r² in the tide height (has_on: unused) */
};

/* A body as used: name "moon", "sun" or "custom" and the source of its
 * constants (static strings). */
struct mech_tides_body {
    const char *name;
    double gm, mass, distance;
    const char *source;
};

struct mech_tides_answer {
    struct mech_tides_body body;      /* the tide-raising body */
    struct mech_tides_body on;        /* the body raised on (distance: 0; the Earth by default) */
    double on_radius, on_gm;          /* m, m^3/s^2: the point's radius and the GM of `on` used */
    struct mech_tides_body moon, sun; /* as used by spring_neap */
    struct mech_tide_acceleration acceleration;
    struct mech_tide_height height; /* the body's equilibrium tide */
    /* Moon and Sun together at this radius and angle; has_spring_neap == 0
     * (nothing below set) when the radius reaches the Moon or the Sun */
    int has_spring_neap;
    struct mech_tide_height moon_height, sun_height;
    struct mech_tide_height sun_quadrature_height; /* the Sun at |90 - angle| */
    double sun_to_moon;                            /* sun_height.range / moon_height.range */
    double spring_range;                           /* moon + sun ranges (aligned) */
    double neap_range;                             /* |moon - sun| ranges (at 90 deg) */
    double spring_height;                          /* moon + sun heights at angle */
    double neap_height; /* moon height at angle + sun height at |90 - angle| */
};

/* Compute *out for request q. Statuses, err->param naming the request's field:
 *   MECH_EINVAL for a NULL pointer or an unknown body kind; "moon", "sun" or
 *     "body" when one body gives both gm and mass; "body" when the custom
 *     body gives neither; "<body>/gm", "/mass", "/distance" for a given value
 *     not finite and > 0; those of mech_tide_acceleration and mech_tide_height
 *     ("angle_deg", "radius", "gm_earth", ...);
 *   MECH_EINVAL "on" for both gm and mass, neither, or an unknown name;
 *     "on/radius" (or "on/gm", "on/mass") not finite and > 0; "on" naming
 *     the tide-raising body itself;
 *   MECH_EDOMAIN when the body does not lie outside the sphere through the
 *     point: "moon/distance" or "sun/distance" when that distance was given,
 *     "radius" when the built-in one was, "body/distance" for a custom body;
 *   MECH_ENUMERIC when a result is not finite (overflow near the body, or a
 *     Moon so light that its tide underflows to 0 in sun_to_moon).
 * err may be NULL. */
enum mech_status mech_tides_answer(const struct mech_tides_request *q,
                                   struct mech_tides_answer *out, struct mech_error *err);

#endif
