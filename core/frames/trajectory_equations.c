/* trajectory_equations.c — the equations of motion of a particle in an
 * inertial, rotating or local Earth frame (notes §1.2 "Rotating frames",
 * §1.3 "Motion near the Earth") as the ODE driver's callbacks: the generic
 * right-hand side and acceleration, the special-relativistic (r, u) form,
 * the Lorentz-type split Boris takes, the planar (2-D) form and the Kepler
 * split's perturbation (wisdom_holman); and what the chooser's profile asks
 * of them (trajectory_scene.h). */
#include "trajectory_context.h"
#include "trajectory_scene.h"

#include <string.h>

enum mech_status mech_traj_accel(double t, const double *q, const double *v, double *a,
                                 void *params)
{
    const struct traj_ctx *c = params;
    if (c->simple && !c->dim2) return mech_traj_simple_accel3(t, q, v, a, params);
    struct mech_vec3 r = mech_vec3_make(q[0], q[1], q[2]);
    struct mech_vec3 vv = mech_vec3_make(v[0], v[1], v[2]);
    struct mech_vec3 acc;
    enum mech_status st = force_sum(c, t, r, vv, -1, &acc);
    if (st != MECH_OK) return st;
    if (c->pn1) acc = mech_vec3_add(acc, pn1_accel(c, r, vv));
    if (c->coriolis || c->centrifugal) { /* W(t) only when a rotation term needs it */
        const struct mech_vec3 w = omega_at(c, t);
        if (c->coriolis) acc = mech_vec3_add(acc, coriolis_accel(w, vv));
        if (c->centrifugal) acc = mech_vec3_add(acc, centrifugal_accel(w, r));
    }
    if (c->euler) acc = mech_vec3_sub(acc, mech_vec3_cross(c->wdot, r));
    if (c->translational) acc = mech_vec3_sub(acc, c->A);
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r) || !mech_vec3_isfinite(vv))
        return mech_traj_nonfinite_error(c, t, r, vv);
    a[0] = acc.x;
    a[1] = acc.y;
    a[2] = acc.z;
    return MECH_OK;
}

enum mech_status mech_traj_rhs(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[3];
    dydt[1] = y[4];
    dydt[2] = y[5];
    return mech_traj_accel(t, y, y + 3, dydt + 3, params);
}

/* Special-relativistic dynamics in the state y = (r, u), u = gamma v:
 *   dr/dt = u / gamma,  du/dt = F(t, r, v) / m,  gamma = sqrt(1 + u^2/c^2),
 * (dp/dt = F with p = m u). gamma is never formed from 1 - beta, so the
 * state keeps its digits from beta = 1e-9 to gamma = 1e6 and beyond. The
 * frame is inertial (mech_trajectory_check), so only the forces act. */
enum mech_status mech_traj_rel_rhs(double t, const double *y, double *dydt, void *params)
{
    const struct traj_ctx *c = params;
    const struct mech_vec3 r = mech_vec3_make(y[0], y[1], y[2]);
    const struct mech_vec3 u = mech_vec3_make(y[3], y[4], y[5]);
    const struct mech_vec3 v = mech_vec3_scale(u, 1.0 / gamma_of_u(u));
    struct mech_vec3 acc;
    enum mech_status st = force_sum(c, t, r, v, -1, &acc);
    if (st != MECH_OK) return st;
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r) || !mech_vec3_isfinite(v))
        return mech_traj_nonfinite_error(c, t, r, v);
    dydt[0] = v.x;
    dydt[1] = v.y;
    dydt[2] = v.z;
    dydt[3] = acc.x;
    dydt[4] = acc.y;
    dydt[5] = acc.z;
    return MECH_OK;
}

/* Lorentz-type split for Boris (mech/ode/ode.h): a = e(t, q) + v x w(t, q) with
 * e = position-dependent forces / m (with q E / m) + centrifugal + Euler +
 * translational, w = q B / m summed over the lorentz forces + 2 W(t) when
 * Coriolis is modelled (-2 W x v = v x 2W; q v x B / m = v x (q B / m)).
 * Only offered when no drag acts (linear drag -b v/m is not of that form;
 * b = 0 contributes nothing). */
enum mech_status mech_traj_lorentz(double t, const double *q, double *e, double *w,
                                   void *params)
{
    const struct traj_ctx *c = params;
    struct mech_vec3 r = mech_vec3_make(q[0], q[1], q[2]);
    const struct mech_vec3 zero = mech_vec3_make(0.0, 0.0, 0.0);
    struct mech_vec3 acc = zero;
    struct mech_vec3 ww = zero;
    const struct mech_vec3 wt = omega_at(c, t);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        const struct mech_force *f = &c->p->forces[i];
        if (f->type == MECH_FORCE_LINEAR_DRAG) continue;
        if (f->type == MECH_FORCE_LORENTZ)
            ww = mech_vec3_add(ww, mech_vec3_scale(f->u.lorentz.B, c->p->charge / c->p->mass));
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, zero, t, &ai); /* lorentz: q E / m */
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    if (c->centrifugal) acc = mech_vec3_add(acc, centrifugal_accel(wt, r));
    if (c->euler) acc = mech_vec3_sub(acc, mech_vec3_cross(c->wdot, r));
    if (c->translational) acc = mech_vec3_sub(acc, c->A);
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r))
        return mech_traj_nonfinite_error(c, t, r, zero);
    if (c->coriolis) ww = mech_vec3_add(ww, mech_vec3_scale(wt, 2.0));
    e[0] = acc.x;
    e[1] = acc.y;
    e[2] = acc.z;
    w[0] = ww.x;
    w[1] = ww.y;
    w[2] = ww.z;
    return MECH_OK;
}

/* ---- planar scenes: the state (u1, u2, u1', u2') with r = u1 e1 + u2 e2 ---- */

enum mech_status mech_traj_plane_accel(double t, const double *q, const double *v, double *a,
                                       void *params)
{
    const struct traj_ctx *c = params;
    if (c->simple) return mech_traj_simple_accel2(t, q, v, a, params); /* no 3-D expansion */
    double u[4] = {q[0], q[1], v[0], v[1]}, y[6], a3[3];
    plane_expand(c, u, y);
    enum mech_status st = mech_traj_accel(t, y, y + 3, a3, params);
    if (st != MECH_OK) return st;
    /* the scene is planar: the acceleration lies in the plane; project it */
    struct mech_vec3 av = mech_vec3_make(a3[0], a3[1], a3[2]);
    a[0] = mech_vec3_dot(av, c->e1);
    a[1] = mech_vec3_dot(av, c->e2);
    return MECH_OK;
}

enum mech_status mech_traj_plane_rhs(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[2];
    dydt[1] = y[3];
    return mech_traj_plane_accel(t, y, y + 2, dydt + 2, params);
}

/* ---- the Kepler split's perturbation (wisdom_holman) -------------------------
 * Every force but the one central_gravity (inertial frame: no fictitious
 * term), so accel = Kepler term + perturbation term by term. */
static enum mech_status kepler_perturbation3(double t, const double *q, const double *v,
                                             double *a, void *params)
{
    const struct traj_ctx *c = params;
    const struct mech_vec3 r = mech_vec3_make(q[0], q[1], q[2]);
    const struct mech_vec3 vv = mech_vec3_make(v[0], v[1], v[2]);
    struct mech_vec3 acc;
    enum mech_status st = force_sum(c, t, r, vv, c->kepler_index, &acc);
    if (st != MECH_OK) return st;
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r) || !mech_vec3_isfinite(vv))
        return mech_traj_nonfinite_error(c, t, r, vv);
    a[0] = acc.x;
    a[1] = acc.y;
    a[2] = acc.z;
    return MECH_OK;
}

static enum mech_status kepler_perturbation2(double t, const double *q, const double *v,
                                             double *a, void *params)
{
    const struct traj_ctx *c = params;
    double u[4] = {q[0], q[1], v[0], v[1]}, y[6], a3[3];
    plane_expand(c, u, y);
    enum mech_status st = kepler_perturbation3(t, y, y + 3, a3, params);
    if (st != MECH_OK) return st;
    const struct mech_vec3 av = mech_vec3_make(a3[0], a3[1], a3[2]);
    a[0] = mech_vec3_dot(av, c->e1);
    a[1] = mech_vec3_dot(av, c->e2);
    return MECH_OK;
}

/* Fill ks with c's Kepler split in the integration's coordinates (2-D: the
 * centre projected on e1, e2). c->kepler_index >= 0. */
void mech_traj_kepler_split_fill(const struct traj_ctx *c, struct mech_ode_kepler_split *ks)
{
    const struct mech_force *f = &c->p->forces[c->kepler_index];
    const struct mech_vec3 ctr = f->u.central_gravity.center;
    memset(ks, 0, sizeof *ks);
    ks->gm = f->u.central_gravity.gm;
    if (c->dim2) {
        ks->center[0] = mech_vec3_dot(ctr, c->e1);
        ks->center[1] = mech_vec3_dot(ctr, c->e2);
        ks->perturbation = kepler_perturbation2;
    } else {
        ks->center[0] = ctr.x;
        ks->center[1] = ctr.y;
        ks->center[2] = ctr.z;
        ks->perturbation = kepler_perturbation3;
    }
    ks->velocity_dependent = mech_traj_scene_velocity_dependent(c);
}

/* ---- what the chooser's profile asks of the equations (trajectory_scene.h) -- */

enum mech_status mech_trajectory_start_acceleration(const struct mech_trajectory_problem *p,
                                                    double a[3])
{
    struct traj_ctx c;
    mech_traj_ctx_init(&c, p, 0.0, NULL);
    double q0[3] = {p->position.x, p->position.y, p->position.z},
           v0[3] = {p->velocity.x, p->velocity.y, p->velocity.z};
    return mech_traj_accel(0.0, q0, v0, a, &c);
}

int mech_trajectory_velocity_dependent(const struct mech_trajectory_problem *p)
{
    struct traj_ctx c;
    mech_traj_ctx_init(&c, p, 0.0, NULL);
    return mech_traj_scene_velocity_dependent(&c);
}
