/* elastic_answer.c — the POST /v1/relativity/kinematics/elastic answer (see
 * mech/answers/relativity/elastic_answer.h): the angle as given turned into radians, the
 * scattering (elastic_scattering.c), the projectile's boost (kinematics.c). */
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/relativity/elastic_answer.h"

const char *mech_elastic_angle_key(enum mech_elastic_angle kind, int in_degrees)
{
    static const char *const keys[3][2] = {
        {"cm_angle", "cm_angle_deg"},
        {"angle", "angle_deg"},
        {"recoil_angle", "recoil_angle_deg"},
    };
    if ((int)kind < 0 || (int)kind > 2) return "angle";
    return keys[kind][in_degrees ? 1 : 0];
}

enum mech_status mech_elastic_answer(const struct mech_elastic_request *q,
                                     struct mech_elastic_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    struct mech_elastic_answer a;
    const double rad = q->angle_in_degrees ? q->angle / 180.0 * MECH_PI : q->angle;
    enum mech_status st =
        mech_elastic_scatter(&q->projectile, q->target_mass, q->kind, rad, q->branch, &a.scatter, err);
    if (st != MECH_OK) {
        if (err && !strcmp(err->param, "angle"))
            snprintf(err->param, sizeof err->param, "%s",
                     mech_elastic_angle_key(q->kind, q->angle_in_degrees));
        return st;
    }
    /* the projectile's own velocity, when it has a rest frame (m1 > 0) */
    a.has_projectile_boost =
        q->projectile.mass > 0 &&
        mech_kin_motion_boost(&q->projectile, mech_vec3_make(0, 0, 1), &a.projectile_boost, NULL) ==
            MECH_OK;
    a.branch = q->branch < (int)a.scatter.n_solutions ? q->branch : 0;
    *out = a;
    return MECH_OK;
}
