/* trajectory_forces.c — the forces of a trajectory's scene where they are
 * not inlined into the equations of motion (trajectory_context.h holds the
 * inlined force loop): the third-body tide's acceleration and potential,
 * written so nothing cancels near the origin, and the typed errors of a
 * particle at a central mass or in a non-finite state. */
#include "trajectory_context.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for error parameter paths */

/* Tidal acceleration of a body gm at d (notes §1.4, "The Tides"):
 *   a = gm [(d - r)/s^3 - d/q^3],  s = |d - r|, q = |d|,
 * written as a = gm [d (1/s^3 - 1/q^3) - r/s^3] with
 *   1/s^3 - 1/q^3 = (q - s)(q^2 + q s + s^2) / (s^3 q^3),
 *   q - s = (q^2 - s^2)/(q + s) = (2 d.r - r.r)/(q + s),
 * so nothing cancels when |r| << |d| (the direct difference loses
 * log10(|d|/|r|) digits: 2 at the Earth-Moon ratio 60, all of them at 1 m). */
__attribute__((noinline)) enum mech_status
mech_traj_tide_accel(const struct traj_ctx *c, size_t i, struct mech_vec3 r, double t,
                     struct mech_vec3 *a)
{
    const struct mech_force *f = &c->p->forces[i];
    const struct mech_vec3 d = f->u.third_body_tide.position;
    const double gm = f->u.third_body_tide.gm;
    const double q = mech_vec3_norm(d);
    const double s = mech_vec3_norm(mech_vec3_sub(d, r));
    if (!(s > 0.0) || !(q > 0.0)) {
        char param[32];
        snprintf(param, sizeof param, "forces/%zu", i);
        return mech_error_set(c->err, MECH_ENUMERIC, param,
                              "the particle reached the tide-raising body of force %zu at "
                              "t = %.9g s",
                              i, t);
    }
    const double qms = (2.0 * mech_vec3_dot(d, r) - mech_vec3_dot(r, r)) / (q + s);
    /* (q - s)(q^2 + q s + s^2)/(s^3 q^3), arranged against overflow */
    const double k1 = (qms / s) * ((q * q + q * s + s * s) / (q * q)) / (s * s * q);
    const double s3 = 1.0 / (s * s * s);
    *a = mech_vec3_scale(mech_vec3_sub(mech_vec3_scale(d, k1), mech_vec3_scale(r, s3)), gm);
    return MECH_OK;
}

/* Tidal potential per unit mass, -gm [1/s - 1/q - d.r/q^3] with
 * 1/s - 1/q = (q - s)/(q s) (q - s as above): zero at r = 0, no cancellation. */
double mech_traj_tide_potential(const struct mech_force *f, struct mech_vec3 r)
{
    const struct mech_vec3 d = f->u.third_body_tide.position;
    const double q = mech_vec3_norm(d), s = mech_vec3_norm(mech_vec3_sub(d, r));
    const double qms = (2.0 * mech_vec3_dot(d, r) - mech_vec3_dot(r, r)) / (q + s);
    return -f->u.third_body_tide.gm * (qms / (q * s) - mech_vec3_dot(d, r) / (q * q * q));
}

/* The typed error of force_accel at the centre of central_gravity force i.
 * Kept out of line (cold): its message buffer would otherwise sit in the
 * frame of the hot force loop (the trajectory costs at most 1.5x its bare
 * integrator, bench/bench_trajectory_overhead.c). */
__attribute__((noinline, cold)) enum mech_status
mech_traj_central_gravity_error(const struct traj_ctx *c, size_t i, double dn, double t)
{
    char param[32];
    snprintf(param, sizeof param, "forces/%zu", i);
    return mech_error_set(c->err, MECH_ENUMERIC, param,
                          "the particle reached the centre of central_gravity force %zu "
                          "(distance %.3g m) at t = %.9g s",
                          i, dn, t);
}

/* A non-finite state or acceleration: say when and where. */
enum mech_status mech_traj_nonfinite_error(const struct traj_ctx *c, double t, struct mech_vec3 r,
                                           struct mech_vec3 v)
{
    if (mech_vec3_isfinite(r) && mech_vec3_isfinite(v))
        return mech_error_set(c->err, MECH_ENUMERIC, NULL,
                              "non-finite acceleration at t = %.9g s, position [%.9g, %.9g, %.9g] m "
                              "(the forces overflow there)",
                              t, r.x, r.y, r.z);
    return mech_error_set(c->err, MECH_ENUMERIC, NULL,
                          "non-finite state inside a step near t = %.9g s; last finite state at "
                          "t = %.9g s, position [%.9g, %.9g, %.9g] m",
                          t, c->t_last, c->r_last.x, c->r_last.y, c->r_last.z);
}
