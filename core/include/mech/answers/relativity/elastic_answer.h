/* mech/answers/relativity/elastic_answer.h — one POST /v1/relativity/kinematics/elastic answer,
 * from the request as read to everything the answer states: the angle given
 * (the projectile's CM or lab angle, or the recoil's lab angle, in radians
 * or degrees) turned into the scattering (mech/relativity/elastic_scattering.h), the
 * projectile's own γ, β and rapidity, and the branch used. The API's handler
 * reads the unit, the masses and the projectile's motion (api/ops/relativity/kin_request.c,
 * shared with the other kinematics operations), calls mech_elastic_answer()
 * once and encodes.
 *
 * Units: natural (c = 1), one energy unit for every mass, energy and
 * momentum; angles in radians. Pure; thread-safe; no allocation. */
#ifndef MECH_ELASTIC_ANSWER_H
#define MECH_ELASTIC_ANSWER_H

#include "mech/relativity/boost.h"
#include "mech/relativity/elastic_scattering.h"
#include "mech/relativity/kinematics.h"
#include "mech/base/status.h"

struct mech_elastic_request {
    struct mech_kin_motion projectile; /* m1 >= 0 moving along +z, p1 > 0 (mech_kin_motion_*) */
    double target_mass;                /* m2 > 0, at rest */
    enum mech_elastic_angle kind;      /* which angle is given */
    double angle;                      /* its value: radians, or degrees when angle_in_degrees */
    int angle_in_degrees;              /* 1: the request gave the *_deg key */
    int branch;                        /* 0 or 1: which CM solution of a lab angle */
};

struct mech_elastic_answer {
    struct mech_elastic scatter;    /* the scattering in the lab and the CM frame */
    int has_projectile_boost;       /* 1 when m1 > 0: the projectile has a rest frame */
    struct mech_boost projectile_boost; /* its γ, β, rapidity in the lab (along +z) */
    int branch;                     /* the branch used: the request's when two solutions
                                       exist, else 0 */
};

/* The request's key for an angle of kind `kind` ("cm_angle", "angle",
 * "recoil_angle", with "_deg" when in degrees); "angle" for an unknown kind.
 * Static storage. */
const char *mech_elastic_angle_key(enum mech_elastic_angle kind, int in_degrees);

/* Compute *out for request q: the angle in radians (degrees × π/180), then
 * mech_elastic_scatter. Statuses, err->param naming the request's field:
 *   MECH_EINVAL (no param) for a NULL pointer;
 *   mech_elastic_scatter's statuses, its param "angle" reported at the key
 *     the angle was given as (mech_elastic_angle_key: a lab angle above
 *     θmax at "angle_deg", the recoil at 90° at "recoil_angle_deg", ...),
 *     "target", "projectile" and "branch" unchanged.
 * out is written only on success. err may be NULL. */
enum mech_status mech_elastic_answer(const struct mech_elastic_request *q,
                                     struct mech_elastic_answer *out, struct mech_error *err);

#endif
