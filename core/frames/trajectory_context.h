/* trajectory_context.h — private to core/frames: the context one trajectory
 * run shares between its driver (trajectory.c), its equations of motion
 * (trajectory_equations.c), their fast path (trajectory_fast.c), its observer
 * (trajectory_observe.c) and its set-up (trajectory_context.c); the force
 * loop and the small frame terms the hot right-hand sides inline; and the
 * functions the pieces call across files. Nothing here is public: every
 * name is mech_traj_* (the library's prefix) only because it crosses files.
 */
#ifndef MECH_FRAMES_TRAJECTORY_CONTEXT_H
#define MECH_FRAMES_TRAJECTORY_CONTEXT_H

#include "mech/frames/trajectory.h"

#include <math.h>
#include <stddef.h>


struct traj_ctx {
    const struct mech_trajectory_problem *p;
    struct mech_vec3 w;   /* frame angular velocity at t = 0, frame axes */
    struct mech_vec3 wdot;/* its constant rate of change (rotating frames), else 0 */
    struct mech_vec3 A;   /* acceleration of the origin (rotating frames), else 0 */
    int noninertial;
    int coriolis, centrifugal, euler, translational; /* modelled */
    /* planar integration: r = u1 e1 + u2 e2 (dim2 = 1) */
    int dim2;
    struct mech_vec3 e1, e2;
    /* fast path (simple_accel): every force is central gravity, uniform
     * gravity, a spring or drag and no fictitious term is modelled; fvec[i]
     * is force i's centre / g / anchor in the integration's coordinates
     * (projected on e1, e2 when dim2) */
    int simple;
    double fvec[MECH_TRAJECTORY_MAX_FORCES][3];
    double fixed_dt;      /* step of a fixed-step method, 0 for adaptive ones */
    /* Kepler split (wisdom_holman): index of the one central_gravity force
     * in an inertial frame, -1 if the scene has no split; kepler_exact when
     * the method moves that force's part exactly (no resolution check) */
    int kepler_index, kepler_exact;
    /* relativistic corrections (mech/frames/trajectory_problem.h): special = the
     * state is (r, u = gamma v); pn1 = the 1PN term of force pn1_index;
     * pn1_index is the one central_gravity of an inertial scene (-1: none),
     * whose 1PN size is measured whether modelled or not */
    int special, pn1, pn1_index;
    double rel_max, pn1_max; /* largest |a| of the two corrections observed */
    double rel_ratio, pn1_ratio; /* and relative to what they correct */
    struct mech_error *err;
    /* observer accumulators */
    double term_max[MECH_TRAJECTORY_MAX_FORCES + MECH_TRAJECTORY_N_FICTITIOUS];
    double rmax, vmax; /* largest |r| and |v| observed */
    int have_inv0;
    double inv0, inv_last, drift_max, scale_max;
    /* angular momentum about `lcenter` when the scene conserves it */
    int track_l;
    struct mech_vec3 lcenter, l0, l_last;
    double ldrift_max, lscale_max;
    /* last finite state observed, for error messages */
    double t_last;
    struct mech_vec3 r_last;
    long n_observed;
};

/* ---- the forces (trajectory_forces.c) ----------------------------------- */

/* Tidal acceleration *a (m/s^2) of the third_body_tide force i at r (m) at
 * time t (s). MECH_ENUMERIC (recorded in c->err) when r reaches the body. */
__attribute__((noinline)) enum mech_status
mech_traj_tide_accel(const struct traj_ctx *c, size_t i, struct mech_vec3 r, double t,
                     struct mech_vec3 *a);
/* Tidal potential per unit mass (J/kg) of third_body_tide force f at r:
 * 0 at r = 0, no cancellation for |r| << |d|. */
double mech_traj_tide_potential(const struct mech_force *f, struct mech_vec3 r);
/* Records and returns MECH_ENUMERIC: the particle at distance dn (m) of the
 * centre of central_gravity force i at time t (s). */
__attribute__((noinline, cold)) enum mech_status
mech_traj_central_gravity_error(const struct traj_ctx *c, size_t i, double dn, double t);
/* Records and returns MECH_ENUMERIC for a non-finite acceleration at (t, r, v)
 * or, when r or v is not finite, the last finite state observed. */
enum mech_status mech_traj_nonfinite_error(const struct traj_ctx *c, double t,
                                           struct mech_vec3 r, struct mech_vec3 v);

/* Acceleration of force i at (r, v). MECH_ENUMERIC at the centre of a central mass.
 * Inlined into the right-hand sides (called 13 times per rk8pd step). */
static inline enum mech_status force_accel(const struct traj_ctx *c, size_t i,
                                           struct mech_vec3 r, struct mech_vec3 v, double t,
                                           struct mech_vec3 *a)
{
    const struct mech_force *f = &c->p->forces[i];
    const double m = c->p->mass;
    switch (f->type) {
    case MECH_FORCE_UNIFORM_GRAVITY:
        *a = f->u.uniform_gravity.g;
        return MECH_OK;
    case MECH_FORCE_CENTRAL_GRAVITY: {
        struct mech_vec3 d = mech_vec3_sub(r, f->u.central_gravity.center);
        double dn = mech_vec3_norm(d);
        /* a = -gm d / |d|^3, written as (gm / |d|^2)(d / |d|) so |d|^3 cannot
         * underflow first; |d| -> 0 gives a typed error, never a NaN. */
        double s = f->u.central_gravity.gm / (dn * dn);
        if (!(dn > 0.0) || !isfinite(s)) return mech_traj_central_gravity_error(c, i, dn, t);
        *a = mech_vec3_scale(d, -s / dn);
        return MECH_OK;
    }
    case MECH_FORCE_SPRING: {
        struct mech_vec3 d = mech_vec3_sub(r, f->u.spring.anchor);
        double dn = mech_vec3_norm(d);
        /* F = -k (|d| - L) d/|d| = -k (1 - L/|d|) d; at |d| = 0 the direction is
         * undefined and the force is taken as 0 (symmetric equilibrium). */
        double s = dn > 0.0 ? f->u.spring.k * (1.0 - f->u.spring.rest_length / dn) : 0.0;
        *a = mech_vec3_scale(d, -s / m);
        return MECH_OK;
    }
    case MECH_FORCE_LINEAR_DRAG:
        *a = mech_vec3_scale(v, -f->u.linear_drag.b / m);
        return MECH_OK;
    case MECH_FORCE_LORENTZ: {
        /* F = q (E + v x B) (SI), fields in the frame's axes */
        const double qm = c->p->charge / m;
        *a = mech_vec3_scale(mech_vec3_add(f->u.lorentz.E, mech_vec3_cross(v, f->u.lorentz.B)), qm);
        return MECH_OK;
    }
    case MECH_FORCE_THIRD_BODY_TIDE:
        return mech_traj_tide_accel(c, i, r, t, a);
    }
    return mech_error_set(c->err, MECH_EINTERNAL, NULL, "unknown force type");
}

/* The sum of the forces' accelerations at (r, v, t) in force order (the
 * order fixes the round-off), force `skip` left out (-1: none). The first
 * force's error status is returned as is. */
static inline enum mech_status force_sum(const struct traj_ctx *c, double t, struct mech_vec3 r,
                                         struct mech_vec3 v, int skip, struct mech_vec3 *sum)
{
    struct mech_vec3 acc = mech_vec3_make(0.0, 0.0, 0.0);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        if ((int)i == skip) continue;
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, v, t, &ai);
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    *sum = acc;
    return MECH_OK;
}

/* The frame's angular velocity at t: w0 + (dw/dt) t. */
static inline struct mech_vec3 omega_at(const struct traj_ctx *c, double t)
{
    return mech_vec3_add(c->w, mech_vec3_scale(c->wdot, t));
}

/* notes §1.2: a_Coriolis = -2 w x v, a_centrifugal = -w x (w x r),
 * a_Euler = -(dw/dt) x r, a_translational = -A. */
static inline struct mech_vec3 coriolis_accel(struct mech_vec3 w, struct mech_vec3 v)
{
    return mech_vec3_scale(mech_vec3_cross(w, v), -2.0);
}
static inline struct mech_vec3 centrifugal_accel(struct mech_vec3 w, struct mech_vec3 r)
{
    return mech_vec3_scale(mech_vec3_cross(w, mech_vec3_cross(w, r)), -1.0);
}

/* The Schwarzschild 1PN correction of the test particle's acceleration about
 * force pn1_index (harmonic coordinates, mech/frames/trajectory_problem.h):
 *   a = (gm / (c^2 d^2)) [(4 gm/d - v^2) n + 4 (n.v) v]. d > 0 (the central
 * force was evaluated first and refuses d = 0). */
static inline struct mech_vec3 pn1_accel(const struct traj_ctx *c, struct mech_vec3 r,
                                         struct mech_vec3 v)
{
    const struct mech_force *f = &c->p->forces[c->pn1_index];
    return mech_schwarzschild_1pn_accel(f->u.central_gravity.gm,
                                        mech_vec3_sub(r, f->u.central_gravity.center), v);
}

/* gamma and v = u / gamma of a proper velocity u, gamma = sqrt(1 + u^2/c^2). */
static inline double gamma_of_u(struct mech_vec3 u)
{
    return sqrt(1.0 + mech_vec3_dot(u, u) / (MECH_C * MECH_C));
}

/* r, v (frame axes) of a planar state u = (u1, u2, u1', u2'): y = (r, v). */
static inline void plane_expand(const struct traj_ctx *c, const double *u, double *y)
{
    struct mech_vec3 r = mech_vec3_add(mech_vec3_scale(c->e1, u[0]), mech_vec3_scale(c->e2, u[1]));
    struct mech_vec3 v = mech_vec3_add(mech_vec3_scale(c->e1, u[2]), mech_vec3_scale(c->e2, u[3]));
    y[0] = r.x;
    y[1] = r.y;
    y[2] = r.z;
    y[3] = v.x;
    y[4] = v.y;
    y[5] = v.z;
}

/* ---- the fast path (trajectory_fast.c) ---------------------------------- */

/* Whether c qualifies for the fast path (c->simple), and its force vectors
 * (c->fvec) in the integration's coordinates. Called after
 * mech_traj_ctx_init and again after mech_traj_ctx_plane. */
void mech_traj_fast_setup(struct traj_ctx *c);
/* The fast path as the ODE system's callbacks, planar (2) or 3-D (3);
 * params is the struct traj_ctx. */
enum mech_status mech_traj_simple_accel2(double t, const double *q, const double *v, double *a,
                                         void *params);
enum mech_status mech_traj_simple_accel3(double t, const double *q, const double *v, double *a,
                                         void *params);
enum mech_status mech_traj_simple_rhs2(double t, const double *y, double *dydt, void *params);
enum mech_status mech_traj_simple_rhs3(double t, const double *y, double *dydt, void *params);
/* Install the fast path's callbacks in sys when c->simple (nothing
 * otherwise): the loop above, or for one central mass or one spring of rest
 * length 0 their own callbacks (same results bit for bit). */
struct mech_ode_system;
void mech_traj_fast_install(const struct traj_ctx *c, struct mech_ode_system *sys);

/* ---- the equations of motion (trajectory_equations.c) ------------------- */

/* The ODE system's callbacks (mech/ode/ode.h); params is the struct traj_ctx.
 * accel/rhs: the generic 3-D form, q'' = a(t, q, v); rel_rhs: the
 * special-relativistic first-order form in (r, u = gamma v); lorentz: the
 * split a = e + v x w for Boris; plane_*: the planar form in (u1, u2). */
enum mech_status mech_traj_accel(double t, const double *q, const double *v, double *a,
                                 void *params);
enum mech_status mech_traj_rhs(double t, const double *y, double *dydt, void *params);
enum mech_status mech_traj_rel_rhs(double t, const double *y, double *dydt, void *params);
enum mech_status mech_traj_lorentz(double t, const double *q, double *e, double *w,
                                   void *params);
enum mech_status mech_traj_plane_accel(double t, const double *q, const double *v, double *a,
                                       void *params);
enum mech_status mech_traj_plane_rhs(double t, const double *y, double *dydt, void *params);
/* Fill ks with c's Kepler split in the integration's coordinates (2-D: the
 * centre projected on e1, e2). c->kepler_index >= 0. */
void mech_traj_kepler_split_fill(const struct traj_ctx *c, struct mech_ode_kepler_split *ks);

/* ---- the observer (trajectory_observe.c) -------------------------------- */

/* The ODE driver's observer at (t, y = (r, v) or, special runs, (r, u)) and
 * the stop event's function; plane_*: the same for a planar state.
 * params is the struct traj_ctx (the observer writes its accumulators). */
enum mech_status mech_traj_observe(double t, const double *y, void *params);
double mech_traj_event(double t, const double *y, void *params);
enum mech_status mech_traj_plane_observe(double t, const double *u, void *params);
double mech_traj_plane_event(double t, const double *u, void *params);

/* ---- the context (trajectory_context.c) --------------------------------- */

/* The Kepler split of a scene (wisdom_holman, mech/ode/ode.h): the index of its
 * one central_gravity force when the frame is inertial and exactly one
 * central_gravity acts, else -1 with *why (may be NULL) saying what is
 * missing. */
int mech_traj_kepler_split_index(const struct mech_trajectory_problem *p, const char **why);
/* c set up for one run of the valid scene p with a fixed step fixed_dt (s;
 * 0 for adaptive methods); errors go to err (may be NULL). */
void mech_traj_ctx_init(struct traj_ctx *c, const struct mech_trajectory_problem *p,
                        double fixed_dt, struct mech_error *err);
/* Planar integration set up in c when the scene asks for it and method mi
 * allows it (c->dim2), the fast path's vectors projected again. */
void mech_traj_ctx_plane(struct traj_ctx *c, const struct mech_ode_method_info *mi);
/* 1 if p has a linear drag force with b > 0. */
int mech_traj_scene_has_drag(const struct mech_trajectory_problem *p);
/* 1 if the modelled acceleration depends on the velocity. */
int mech_traj_scene_velocity_dependent(const struct traj_ctx *c);
/* 1 if the frame's changing rotation makes the equations depend on t. */
int mech_traj_scene_time_dependent(const struct traj_ctx *c);

#endif
