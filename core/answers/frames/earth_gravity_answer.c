/* earth_gravity_answer.c — one POST /v1/earth/gravity computation
 * (mech/answers/frames/earth_gravity_answer.h): the sphere from gm or g0 and omega or the
 * sidereal day, earth.c's effective gravity and normal gravity, and their
 * difference. Moved from api/ops/earth/gravity.c (a handler only parses,
 * calls core once and encodes) operation for operation, so the API's
 * answers stay byte-identical. */
#include "mech/answers/frames/earth_gravity_answer.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"

/* The same text the API gives a non-finite answer. */
#define EARTH_NONFINITE "the result is not finite for this input (overflow or a singularity)"

/* The sphere of the request: gm or g0 R², omega or 2 pi / sidereal_day. */
static enum mech_status sphere_of(const struct mech_earth_gravity_request *q,
                                  struct mech_earth_sphere *e, struct mech_error *err)
{
    e->radius = q->radius;
    e->gm = q->gm;
    e->omega = q->omega;
    if (q->has_g0) {
        if (q->gm_given)
            return mech_error_set(err, MECH_EINVAL, "g0",
                                  "give at most one of gm and g0 (g0 sets GM = g0 R^2)");
        if (!(isfinite(q->g0) && q->g0 > 0))
            return mech_error_set(err, MECH_EINVAL, "g0", "must be finite and > 0, got %.17g",
                                  q->g0);
        e->gm = q->g0 * e->radius * e->radius;
    }
    if (q->has_sidereal_day) {
        if (q->omega_given)
            return mech_error_set(err, MECH_EINVAL, "sidereal_day",
                                  "give at most one of omega and sidereal_day (omega = 2 pi / "
                                  "sidereal_day)");
        if (!(isfinite(q->sidereal_day) && q->sidereal_day > 0))
            return mech_error_set(err, MECH_EINVAL, "sidereal_day",
                                  "must be finite and > 0, got %.17g", q->sidereal_day);
        e->omega = 2 * MECH_PI / q->sidereal_day;
    }
    return MECH_OK;
}

enum mech_status mech_earth_gravity_answer(const struct mech_earth_gravity_request *q,
                                           struct mech_earth_gravity_answer *out,
                                           struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(out, 0, sizeof *out);
    enum mech_status st = sphere_of(q, &out->earth, err);
    if (st != MECH_OK) return st;
    struct mech_error e;
    mech_error_clear(&e);
    st = mech_earth_gravity_sphere(&out->earth, q->latitude_deg, q->height, &out->sphere, &e);
    if (st == MECH_OK)
        st = mech_earth_normal_gravity(q->latitude_deg, q->height, &out->ellipsoid, &e);
    if (st != MECH_OK) {
        /* the rate the user set is what is too fast */
        if (st == MECH_EDOMAIN && !strcmp(e.param, "radius")) {
            if (q->omega_given) snprintf(e.param, sizeof e.param, "omega");
            if (q->has_sidereal_day) snprintf(e.param, sizeof e.param, "sidereal_day");
        }
        return mech_error_set(err, st, e.param, "%s", e.text);
    }
    const struct mech_earth_sphere *k = &out->earth;
    out->sidereal_day = 2 * MECH_PI / k->omega;
    out->g0 = k->gm / (k->radius * k->radius);
    out->difference = out->sphere.magnitude - out->ellipsoid.gamma;
    out->relative_difference = out->difference / out->ellipsoid.gamma;
    const double v[] = {out->g0,
                        out->difference,
                        out->relative_difference,
                        out->sphere.deviation_max,
                        out->sphere.horizontal / out->sphere.radial,
                        out->ellipsoid.igf1980,
                        out->ellipsoid.free_air};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i])) return mech_error_set(err, MECH_ENUMERIC, NULL, EARTH_NONFINITE);
    return MECH_OK;
}
