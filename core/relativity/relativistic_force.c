/* relativistic_force.c — F = dp/dt split along and across v (see
 * mech/relativity/relativistic_force.h). */
#include "mech/relativity/relativistic_force.h"

#include <math.h>

/* x = x∥ + x⊥ along the unit n. */
static void split(struct mech_vec3 x, struct mech_vec3 n, struct mech_vec3 *par,
                  struct mech_vec3 *perp)
{
    *par = mech_vec3_scale(n, mech_vec3_dot(n, x));
    *perp = mech_vec3_sub(x, *par);
}

static int finite3(struct mech_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static enum mech_status finish(double m, const struct mech_boost *b, struct mech_rel_force *o,
                               struct mech_error *err)
{
    const double g = b->gamma;
    o->transverse_mass = g * m;
    o->longitudinal_mass = g * g * g * m;
    const struct mech_vec3 v = mech_vec3_scale(b->beta_vec, MECH_C);
    o->power = mech_vec3_dot(o->force, v);
    o->four_force[0] = g * o->power / MECH_C;
    o->four_force[1] = g * o->force.x;
    o->four_force[2] = g * o->force.y;
    o->four_force[3] = g * o->force.z;
    if (!finite3(o->force) || !finite3(o->acceleration) || !isfinite(o->power) ||
        !isfinite(o->longitudinal_mass) || !isfinite(o->four_force[0]))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "a result overflows the double range (gamma = %.6g)", g);
    return MECH_OK;
}

static enum mech_status check_mass(double m, struct mech_error *err)
{
    if (!isfinite(m) || !(m > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "a mass is a finite number > 0 kg, got %.17g",
                              m);
    return MECH_OK;
}

enum mech_status mech_rel_force_from_acceleration(double m, const struct mech_boost *b,
                                                  struct mech_vec3 a, struct mech_rel_force *out,
                                                  struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (!finite3(a)) return mech_error_set(err, MECH_EINVAL, "acceleration", "must be finite");
    struct mech_rel_force o;
    o.acceleration = a;
    split(a, b->direction, &o.acceleration_parallel, &o.acceleration_perpendicular);
    const double g = b->gamma;
    o.force_parallel = mech_vec3_scale(o.acceleration_parallel, g * g * g * m);
    o.force_perpendicular = mech_vec3_scale(o.acceleration_perpendicular, g * m);
    o.force = mech_vec3_add(o.force_parallel, o.force_perpendicular);
    st = finish(m, b, &o, err);
    if (st == MECH_OK) *out = o;
    return st;
}

enum mech_status mech_rel_force_from_force(double m, const struct mech_boost *b,
                                           struct mech_vec3 f, struct mech_rel_force *out,
                                           struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (!finite3(f)) return mech_error_set(err, MECH_EINVAL, "force", "must be finite");
    struct mech_rel_force o;
    o.force = f;
    split(f, b->direction, &o.force_parallel, &o.force_perpendicular);
    const double g = b->gamma;
    o.acceleration_parallel = mech_vec3_scale(o.force_parallel, 1.0 / (g * g * g * m));
    o.acceleration_perpendicular = mech_vec3_scale(o.force_perpendicular, 1.0 / (g * m));
    o.acceleration = mech_vec3_add(o.acceleration_parallel, o.acceleration_perpendicular);
    st = finish(m, b, &o, err);
    if (st == MECH_OK) *out = o;
    return st;
}
