/* mech/answers/frames/earth_gravity_answer.h — one POST /v1/earth/gravity answer: the
 * sphere as the request sets it (gm or g0, omega or sidereal_day, radius),
 * the effective gravity g_eff = g - w x (w x r) on it (mech/frames/earth.h), the
 * WGS 84 normal gravity of the ellipsoid at the same latitude and height,
 * and their difference. The API's handler parses, calls
 * mech_earth_gravity_answer() once and encodes.
 *
 * Units SI, angles in degrees where the name says _deg, otherwise radians.
 * Pure, no allocation, thread-safe. */
#ifndef MECH_EARTH_GRAVITY_ANSWER_H
#define MECH_EARTH_GRAVITY_ANSWER_H

#include "mech/frames/earth.h"
#include "mech/base/status.h"

struct mech_earth_gravity_request {
    double latitude_deg; /* [-90, 90] */
    double height;       /* m, [MECH_EARTH_HEIGHT_MIN, MECH_EARTH_HEIGHT_MAX] */
    double radius;       /* m, > 0: the sphere's radius R (the point is at R + height) */
    double gm;           /* m^3/s^2, > 0; replaced by g0 R² when has_g0 */
    double omega;        /* rad/s, >= 0; replaced by 2 pi / sidereal_day when has_sidereal_day */
    int gm_given;        /* 1: the request stated gm (not its default); refused beside g0 */
    int omega_given;     /* 1: the request stated omega; refused beside sidereal_day */
    int has_g0;
    double g0; /* m/s^2, finite > 0: gravitation at R, GM = g0 R² */
    int has_sidereal_day;
    double sidereal_day; /* s, finite > 0: W = 2 pi / sidereal_day */
};

struct mech_earth_gravity_answer {
    struct mech_earth_sphere earth; /* the sphere used */
    double sidereal_day;            /* 2 pi / omega, s; +inf when omega = 0 (no rotation) */
    double g0;                      /* GM / R², m/s^2 (at the sphere's radius, not at R + h) */
    struct mech_earth_gravity sphere;
    struct mech_normal_gravity ellipsoid;
    double difference;          /* sphere.magnitude - ellipsoid.gamma, m/s^2 */
    double relative_difference; /* difference / ellipsoid.gamma */
};

/* Compute *out for request q. Statuses, err->param naming the request's field:
 *   MECH_EINVAL for a NULL pointer; "g0" when both gm_given and has_g0;
 *     "sidereal_day" when both omega_given and has_sidereal_day; "g0" or
 *     "sidereal_day" not finite and > 0; those of mech_earth_gravity_sphere
 *     and mech_earth_normal_gravity ("latitude_deg", "height", "radius", "gm",
 *     "omega");
 *   MECH_EDOMAIN when W² r reaches GM/r² (nothing hangs down): param "omega"
 *     or "sidereal_day" when the request set the rate, else "radius";
 *   MECH_ENUMERIC when a result is not finite.
 * err may be NULL. */
enum mech_status mech_earth_gravity_answer(const struct mech_earth_gravity_request *q,
                                           struct mech_earth_gravity_answer *out,
                                           struct mech_error *err);

#endif
