/* effective_force.c — the four fictitious forces of an accelerating, rotating
 * frame and the effective force (notes §1.2; derivation and signs in
 * mech/frames/effective_force.h). */
#include "mech/frames/effective_force.h"

#include "mech/base/compensated.h"

/* Compensated sum of up to five vectors, component by component. */
static struct mech_vec3 sum_vectors(const struct mech_vec3 *v, int n)
{
    struct mech_csum sx = {0, 0}, sy = {0, 0}, sz = {0, 0};
    for (int i = 0; i < n; i++) {
        mech_csum_add(&sx, v[i].x);
        mech_csum_add(&sy, v[i].y);
        mech_csum_add(&sz, v[i].z);
    }
    return mech_vec3_make(mech_csum_value(&sx), mech_csum_value(&sy), mech_csum_value(&sz));
}

/* v / m component by component (1/m may overflow where v/m does not). */
static struct mech_vec3 div_vector(struct mech_vec3 v, double m)
{
    return mech_vec3_make(v.x / m, v.y / m, v.z / m);
}

enum mech_status mech_effective_force(const struct mech_frame_motion *frame, double mass,
                                      struct mech_vec3 position, struct mech_vec3 velocity,
                                      struct mech_vec3 force, struct mech_effective_force *out,
                                      struct mech_error *err)
{
    if (!frame || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no frame or no output");
    if (!mech_vec3_isfinite(frame->omega))
        return mech_error_set(err, MECH_EINVAL, "frame/omega", "must be finite");
    if (!mech_vec3_isfinite(frame->omega_dot))
        return mech_error_set(err, MECH_EINVAL, "frame/omega_dot", "must be finite");
    if (!mech_vec3_isfinite(frame->acceleration))
        return mech_error_set(err, MECH_EINVAL, "frame/acceleration", "must be finite");
    if (!mech_vec3_isfinite(position))
        return mech_error_set(err, MECH_EINVAL, "particle/position", "must be finite");
    if (!mech_vec3_isfinite(velocity))
        return mech_error_set(err, MECH_EINVAL, "particle/velocity", "must be finite");
    if (!mech_vec3_isfinite(force))
        return mech_error_set(err, MECH_EINVAL, "force", "must be finite");
    if (!isfinite(mass) || !(mass > 0))
        return mech_error_set(err, MECH_EDOMAIN, "particle/mass", "mass must be > 0, got %.17g",
                              mass);

    struct mech_vec3 w = frame->omega;
    /* notes §1.2: F_A = F_I - m A - 2m w x v_A - m (dw/dt) x x_A - m w x (w x x_A) */
    out->translational = mech_vec3_scale(frame->acceleration, -mass);
    out->euler = mech_vec3_scale(mech_vec3_cross(frame->omega_dot, position), -mass);
    out->coriolis = mech_vec3_scale(mech_vec3_cross(w, velocity), -2 * mass);
    out->centrifugal = mech_vec3_scale(mech_vec3_cross(w, mech_vec3_cross(w, position)), -mass);

    struct mech_vec3 terms[5] = {out->translational, out->euler, out->coriolis, out->centrifugal,
                                 force};
    out->fictitious = sum_vectors(terms, 4);
    out->effective = sum_vectors(terms, 5);
    out->acceleration = div_vector(out->effective, mass);
    out->inertial_acceleration = div_vector(force, mass);
    if (!mech_vec3_isfinite(out->fictitious) || !mech_vec3_isfinite(out->effective) ||
        !mech_vec3_isfinite(out->acceleration) || !mech_vec3_isfinite(out->inertial_acceleration) ||
        !mech_vec3_isfinite(out->euler) || !mech_vec3_isfinite(out->coriolis) ||
        !mech_vec3_isfinite(out->centrifugal) || !mech_vec3_isfinite(out->translational))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "a fictitious force overflowed");
    return MECH_OK;
}
