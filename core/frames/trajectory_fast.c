/* trajectory_fast.c — the force loop's fast path of the trajectory driver
 * (its overhead over the bare integrator, bench/bench_trajectory_overhead.c).
 * Scenes whose acceleration is a sum of central gravity, uniform gravity,
 * springs and linear drag with no fictitious term (every Kepler, oscillator
 * and falling-object scene of an inertial frame) are evaluated straight from
 * the state's components in the integration's own dimension nd (3, or 2 for a
 * planar scene: the force vectors were projected on e1, e2 once, so nothing
 * is expanded to 3-D per evaluation). Term by term the arithmetic is
 * force_accel's (same operations in the same order), so in 3-D the result is
 * bit-identical to the generic loop; in 2-D it differs from expand-evaluate-
 * project by round-off only (exactly equal when e1, e2 are signed axes). */

#include "trajectory_context.h"

#include <math.h>

/* Whether c qualifies for simple_accel, and its force vectors. Called after
 * mech_traj_ctx_init and again after mech_traj_ctx_plane sets up (or declines) the plane. */
void mech_traj_fast_setup(struct traj_ctx *c)
{
    const struct mech_trajectory_problem *p = c->p;
    c->simple = !c->coriolis && !c->centrifugal && !c->euler && !c->translational &&
                !c->special && !c->pn1 && p->n_forces <= MECH_TRAJECTORY_MAX_FORCES;
    for (size_t i = 0; i < p->n_forces && c->simple; i++) {
        const struct mech_force *f = &p->forces[i];
        struct mech_vec3 u;
        switch (f->type) {
        case MECH_FORCE_CENTRAL_GRAVITY: u = f->u.central_gravity.center; break;
        case MECH_FORCE_UNIFORM_GRAVITY: u = f->u.uniform_gravity.g; break;
        case MECH_FORCE_SPRING: u = f->u.spring.anchor; break;
        case MECH_FORCE_LINEAR_DRAG: u = mech_vec3_make(0, 0, 0); break;
        default: c->simple = 0; continue;
        }
        if (c->dim2) {
            c->fvec[i][0] = mech_vec3_dot(u, c->e1);
            c->fvec[i][1] = mech_vec3_dot(u, c->e2);
            c->fvec[i][2] = 0.0;
        } else {
            c->fvec[i][0] = u.x;
            c->fvec[i][1] = u.y;
            c->fvec[i][2] = u.z;
        }
    }
}

/* The rare end of the finiteness screen (see simple_accel): the exact test,
 * and the error naming the 3-D state. Out of line, so that the callers keep
 * a small frame. */
static __attribute__((noinline, cold)) enum mech_status
screen_failed(const struct traj_ctx *c, double t, const double *q, const double *v, double ax,
              double ay, double az, int nd)
{
    const double qz = nd == 3 ? q[2] : 0.0, vz = nd == 3 ? v[2] : 0.0;
    if (isfinite(q[0]) && isfinite(q[1]) && isfinite(qz) && isfinite(v[0]) && isfinite(v[1]) &&
        isfinite(vz) && isfinite(ax) && isfinite(ay) && isfinite(az))
        return MECH_OK; /* the screen's sum overflowed: every term is finite */
    struct mech_vec3 r = mech_vec3_make(q[0], q[1], qz), w = mech_vec3_make(v[0], v[1], vz);
    if (nd == 2) {
        r = mech_vec3_add(mech_vec3_scale(c->e1, q[0]), mech_vec3_scale(c->e2, q[1]));
        w = mech_vec3_add(mech_vec3_scale(c->e1, v[0]), mech_vec3_scale(c->e2, v[1]));
    }
    return mech_traj_nonfinite_error(c, t, r, w);
}

/* mech_vec3_norm's scaled branch, out of line (a call in the hot path makes
 * every register caller-saved there). */
static __attribute__((noinline, cold)) double norm_scaled(double x, double y, double z)
{
    return hypot(hypot(x, y), z);
}

/* a(t, q, v) of a `simple` scene in nd = 2 or 3 components (see above);
 * always inlined into mech_traj_simple_accel2/3 so nd is a constant there (measured
 * with callgrind: the generic-nd version ran ~2x the instructions). */
static inline __attribute__((always_inline)) enum mech_status
simple_accel(const struct traj_ctx *c, double t, const double *q, const double *v, double *a,
             int nd)
{
    const struct mech_trajectory_problem *p = c->p;
    const double m = p->mass;
    /* the sum in scalars (kept in registers; an array went through memory) */
    double ax = 0.0, ay = 0.0, az = 0.0;
    const double qz = nd == 3 ? q[2] : 0.0, vz = nd == 3 ? v[2] : 0.0;
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        const double *u = c->fvec[i];
        switch (f->type) {
        case MECH_FORCE_CENTRAL_GRAVITY: {
            const double dx = q[0] - u[0], dy = q[1] - u[1], dz = nd == 3 ? qz - u[2] : 0.0;
            const double dn = mech_vec3_norm(mech_vec3_make(dx, dy, dz));
            double s = f->u.central_gravity.gm / (dn * dn);
            if (!(dn > 0.0) || !isfinite(s)) return mech_traj_central_gravity_error(c, i, dn, t);
            s = -s / dn;
            ax += dx * s;
            ay += dy * s;
            if (nd == 3) az += dz * s; /* 2-D: no third component */
            break;
        }
        case MECH_FORCE_UNIFORM_GRAVITY:
            ax += u[0];
            ay += u[1];
            if (nd == 3) az += u[2];
            break;
        case MECH_FORCE_SPRING: {
            const double dx = q[0] - u[0], dy = q[1] - u[1], dz = nd == 3 ? qz - u[2] : 0.0;
            const double dn = mech_vec3_norm(mech_vec3_make(dx, dy, dz));
            double s = dn > 0.0 ? f->u.spring.k * (1.0 - f->u.spring.rest_length / dn) : 0.0;
            s = -s / m;
            ax += dx * s;
            ay += dy * s;
            if (nd == 3) az += dz * s; /* 2-D: no third component */
            break;
        }
        case MECH_FORCE_LINEAR_DRAG: {
            const double s = -f->u.linear_drag.b / m;
            ax += v[0] * s;
            ay += v[1] * s;
            if (nd == 3) az += vz * s;
            break;
        }
        default:
            return mech_error_set(c->err, MECH_EINTERNAL, NULL, "force outside the fast path");
        }
    }
    /* q, v and a all finite, screened without a branch per component: the
     * sum times 0 is 0 when every term is finite and the sum does not
     * overflow, NaN otherwise; only then the exact test (callgrind: an
     * isfinite chain was a third of this function's instructions) */
    const double z = nd == 3 ? ((q[0] + q[1] + qz) + (v[0] + v[1] + vz) + (ax + ay + az)) * 0.0
                             : ((q[0] + q[1]) + (v[0] + v[1]) + (ax + ay)) * 0.0;
    if (!(z == 0.0) &&
        !(isfinite(q[0]) && isfinite(q[1]) && isfinite(qz) && isfinite(v[0]) && isfinite(v[1]) &&
          isfinite(vz) && isfinite(ax) && isfinite(ay) && isfinite(az))) {
        /* rare: the 3-D state for the message */
        struct mech_vec3 r = mech_vec3_make(q[0], q[1], qz), w = mech_vec3_make(v[0], v[1], vz);
        if (nd == 2) {
            r = mech_vec3_add(mech_vec3_scale(c->e1, q[0]), mech_vec3_scale(c->e2, q[1]));
            w = mech_vec3_add(mech_vec3_scale(c->e1, v[0]), mech_vec3_scale(c->e2, v[1]));
        }
        return mech_traj_nonfinite_error(c, t, r, w);
    }
    a[0] = ax;
    a[1] = ay;
    if (nd == 3) a[2] = az;
    return MECH_OK;
}
/* The two commonest scenes, one central mass and one spring without drag,
 * have their own callbacks: the same arithmetic as simple_accel's in the
 * same order (so the same bits), without the loop over forces and its
 * switch, and with the rare branches out of line (callgrind: ~2.5x fewer
 * instructions per evaluation than the loop, near a bare right-hand side).
 * The sums start from 0.0 as the loop's do (0.0 + x turns -0 into +0). */
static inline __attribute__((always_inline)) enum mech_status
gravity1_accel(const struct traj_ctx *c, double t, const double *q, const double *v, double *a,
               int nd)
{
    const double *u = c->fvec[0];
    const double dx = q[0] - u[0], dy = q[1] - u[1], dz = nd == 3 ? q[2] - u[2] : 0.0;
    const double s2 = dx * dx + dy * dy + dz * dz;
    const double dn = s2 >= 0x1p-968 && s2 <= 0x1.fffffffffffffp+1023 ? sqrt(s2)
                                                                      : norm_scaled(dx, dy, dz);
    double s = c->p->forces[0].u.central_gravity.gm / (dn * dn);
    if (!(dn > 0.0) || !isfinite(s)) return mech_traj_central_gravity_error(c, 0, dn, t);
    s = -s / dn;
    const double ax = 0.0 + dx * s, ay = 0.0 + dy * s, az = nd == 3 ? 0.0 + dz * s : 0.0;
    const double z = nd == 3 ? ((q[0] + q[1] + q[2]) + (v[0] + v[1] + v[2]) + (ax + ay + az)) * 0.0
                             : ((q[0] + q[1]) + (v[0] + v[1]) + (ax + ay)) * 0.0;
    if (!(z == 0.0)) {
        const enum mech_status st = screen_failed(c, t, q, v, ax, ay, az, nd);
        if (st != MECH_OK) return st;
    }
    a[0] = ax;
    a[1] = ay;
    if (nd == 3) a[2] = az;
    return MECH_OK;
}

/* One spring of rest length 0 (the oscillator): s = k (1 - 0/|d|) is k
 * exactly for any |d| > 0, and the loop's s = 0 at |d| = 0 gives the same
 * +0 components, so |d| is never needed: a = d (-k/m). */
static inline __attribute__((always_inline)) enum mech_status
spring1_accel(const struct traj_ctx *c, double t, const double *q, const double *v, double *a,
              int nd)
{
    const double *u = c->fvec[0];
    const double s = -c->p->forces[0].u.spring.k / c->p->mass;
    const double dx = q[0] - u[0], dy = q[1] - u[1], dz = nd == 3 ? q[2] - u[2] : 0.0;
    const double ax = 0.0 + dx * s, ay = 0.0 + dy * s, az = nd == 3 ? 0.0 + dz * s : 0.0;
    const double z = nd == 3 ? ((q[0] + q[1] + q[2]) + (v[0] + v[1] + v[2]) + (ax + ay + az)) * 0.0
                             : ((q[0] + q[1]) + (v[0] + v[1]) + (ax + ay)) * 0.0;
    if (!(z == 0.0)) {
        const enum mech_status st = screen_failed(c, t, q, v, ax, ay, az, nd);
        if (st != MECH_OK) return st;
    }
    a[0] = ax;
    a[1] = ay;
    if (nd == 3) a[2] = az;
    return MECH_OK;
}

#define MECH_TRAJ_FAST_CALLBACKS(NAME, ACCEL, ND)                                               \
    static enum mech_status NAME##_accel##ND(double t, const double *q, const double *v,       \
                                             double *a, void *params)                          \
    {                                                                                          \
        return ACCEL(params, t, q, v, a, ND);                                                  \
    }                                                                                          \
    static enum mech_status NAME##_rhs##ND(double t, const double *y, double *dydt,            \
                                           void *params)                                       \
    {                                                                                          \
        for (int k = 0; k < ND; k++) dydt[k] = y[ND + k];                                      \
        return ACCEL(params, t, y, y + ND, dydt + ND, ND);                                     \
    }
MECH_TRAJ_FAST_CALLBACKS(gravity1, gravity1_accel, 2)
MECH_TRAJ_FAST_CALLBACKS(gravity1, gravity1_accel, 3)
MECH_TRAJ_FAST_CALLBACKS(spring1, spring1_accel, 2)
MECH_TRAJ_FAST_CALLBACKS(spring1, spring1_accel, 3)
#undef MECH_TRAJ_FAST_CALLBACKS

/* The fast path as the system's own callbacks (run_scene installs them for
 * `simple` scenes): one call from the integrator to the arithmetic, no
 * mech_traj_rhs -> mech_traj_accel -> mech_traj_plane_accel chain per evaluation. */
enum mech_status mech_traj_simple_accel2(double t, const double *q, const double *v, double *a,
                                         void *params)
{
    return simple_accel(params, t, q, v, a, 2);
}
enum mech_status mech_traj_simple_accel3(double t, const double *q, const double *v, double *a,
                                         void *params)
{
    return simple_accel(params, t, q, v, a, 3);
}
enum mech_status mech_traj_simple_rhs2(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[2];
    dydt[1] = y[3];
    return simple_accel(params, t, y, y + 2, dydt + 2, 2);
}
enum mech_status mech_traj_simple_rhs3(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[3];
    dydt[1] = y[4];
    dydt[2] = y[5];
    return simple_accel(params, t, y, y + 3, dydt + 3, 3);
}

void mech_traj_fast_install(const struct traj_ctx *c, struct mech_ode_system *sys)
{
    if (!c->simple) return;
    const struct mech_trajectory_problem *p = c->p;
    const int one = p->n_forces == 1;
    if (one && p->forces[0].type == MECH_FORCE_CENTRAL_GRAVITY) {
        sys->rhs = c->dim2 ? gravity1_rhs2 : gravity1_rhs3;
        sys->accel = c->dim2 ? gravity1_accel2 : gravity1_accel3;
    } else if (one && p->forces[0].type == MECH_FORCE_SPRING &&
               p->forces[0].u.spring.rest_length == 0.0) {
        sys->rhs = c->dim2 ? spring1_rhs2 : spring1_rhs3;
        sys->accel = c->dim2 ? spring1_accel2 : spring1_accel3;
    } else {
        sys->rhs = c->dim2 ? mech_traj_simple_rhs2 : mech_traj_simple_rhs3;
        sys->accel = c->dim2 ? mech_traj_simple_accel2 : mech_traj_simple_accel3;
    }
    sys->flags |= MECH_ODE_FINITE_OUTPUT; /* every fast callback screens q, v and a */
}
