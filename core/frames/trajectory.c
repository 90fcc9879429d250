/* trajectory.c — the trajectory driver: equations of motion of a particle in
 * an inertial, rotating or local Earth frame (notes §1.2 "Rotating frames",
 * §1.3 "Motion near the Earth"), integrated with mech_ode_solve; model-term
 * sizes and the conserved quantities (energy / Jacobi integral, angular
 * momentum) are gathered by the driver's observer at every sample and every
 * step end; the samples are compared with the scene's reference solution
 * (reference.c) or, on request, with a second run at a tighter setting (the
 * error estimate).
 *
 * Why one file of ~1.1k lines: the force loop (its fast path included), the
 * observer and the driver share one context (struct traj_ctx) that the hot
 * path reads field by field; keeping them in one translation unit keeps that
 * context private and the force loop inlined. The rest of the old file lives
 * beside it: frame.c (the frame's angular velocity), trajectory_problem.c
 * (validation, planar scenes, the angular-momentum centre),
 * trajectory_choose.c (accuracy presets, the chooser's profile),
 * term_estimate.c and trajectory_model.c (the auto-model).
 */
#include "mech/trajectory.h"
#include "mech/chooser.h"
#include "mech/reference.h"
#include "trajectory_scene.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for error parameter paths */
#include <stdlib.h>
#include <string.h>

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
    /* relativistic corrections (mech/trajectory_problem.h): special = the
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

static const char *force_name(enum mech_force_type t)
{
    switch (t) {
    case MECH_FORCE_UNIFORM_GRAVITY: return "uniform_gravity";
    case MECH_FORCE_CENTRAL_GRAVITY: return "central_gravity";
    case MECH_FORCE_SPRING: return "spring";
    case MECH_FORCE_LINEAR_DRAG: return "linear_drag";
    case MECH_FORCE_LORENTZ: return "lorentz";
    case MECH_FORCE_THIRD_BODY_TIDE: return "third_body_tide";
    }
    return "unknown";
}

/* Tidal acceleration of a body gm at d (notes §1.4, "The Tides"):
 *   a = gm [(d - r)/s^3 - d/q^3],  s = |d - r|, q = |d|,
 * written as a = gm [d (1/s^3 - 1/q^3) - r/s^3] with
 *   1/s^3 - 1/q^3 = (q - s)(q^2 + q s + s^2) / (s^3 q^3),
 *   q - s = (q^2 - s^2)/(q + s) = (2 d.r - r.r)/(q + s),
 * so nothing cancels when |r| << |d| (the direct difference loses
 * log10(|d|/|r|) digits: 2 at the Earth-Moon ratio 60, all of them at 1 m). */
static __attribute__((noinline)) enum mech_status
tide_accel(const struct traj_ctx *c, size_t i, struct mech_vec3 r, double t, struct mech_vec3 *a)
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
static double tide_potential(const struct mech_force *f, struct mech_vec3 r)
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
static __attribute__((noinline, cold)) enum mech_status
central_gravity_error(const struct traj_ctx *c, size_t i, double dn, double t)
{
    char param[32];
    snprintf(param, sizeof param, "forces/%zu", i);
    return mech_error_set(c->err, MECH_ENUMERIC, param,
                          "the particle reached the centre of central_gravity force %zu "
                          "(distance %.3g m) at t = %.9g s",
                          i, dn, t);
}

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
        if (!(dn > 0.0) || !isfinite(s)) return central_gravity_error(c, i, dn, t);
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
        return tide_accel(c, i, r, t, a);
    }
    return mech_error_set(c->err, MECH_EINTERNAL, NULL, "unknown force type");
}

/* The frame's angular velocity at t: w0 + (dw/dt) t. */
static struct mech_vec3 omega_at(const struct traj_ctx *c, double t)
{
    return mech_vec3_add(c->w, mech_vec3_scale(c->wdot, t));
}

/* notes §1.2: a_Coriolis = -2 w x v, a_centrifugal = -w x (w x r),
 * a_Euler = -(dw/dt) x r, a_translational = -A. */
static struct mech_vec3 coriolis_accel(struct mech_vec3 w, struct mech_vec3 v)
{
    return mech_vec3_scale(mech_vec3_cross(w, v), -2.0);
}
static struct mech_vec3 centrifugal_accel(struct mech_vec3 w, struct mech_vec3 r)
{
    return mech_vec3_scale(mech_vec3_cross(w, mech_vec3_cross(w, r)), -1.0);
}

/* The Schwarzschild 1PN correction of the test particle's acceleration about
 * force pn1_index (harmonic coordinates, mech/trajectory_problem.h):
 *   a = (gm / (c^2 d^2)) [(4 gm/d - v^2) n + 4 (n.v) v]. d > 0 (the central
 * force was evaluated first and refuses d = 0). */
static struct mech_vec3 pn1_accel(const struct traj_ctx *c, struct mech_vec3 r, struct mech_vec3 v)
{
    const struct mech_force *f = &c->p->forces[c->pn1_index];
    return mech_schwarzschild_1pn_accel(f->u.central_gravity.gm,
                                        mech_vec3_sub(r, f->u.central_gravity.center), v);
}

/* gamma and v = u / gamma of a proper velocity u, gamma = sqrt(1 + u^2/c^2). */
static double gamma_of_u(struct mech_vec3 u)
{
    return sqrt(1.0 + mech_vec3_dot(u, u) / (MECH_C * MECH_C));
}

/* A non-finite state or acceleration: say when and where. */
static enum mech_status nonfinite_error(const struct traj_ctx *c, double t, struct mech_vec3 r,
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

/* ---- the force loop's fast path (trajectory overhead) -----------------------
 * Scenes whose acceleration is a sum of central gravity, uniform gravity,
 * springs and linear drag with no fictitious term (every Kepler, oscillator
 * and falling-object scene of an inertial frame) are evaluated straight from
 * the state's components in the integration's own dimension nd (3, or 2 for a
 * planar scene: the force vectors were projected on e1, e2 once, so nothing
 * is expanded to 3-D per evaluation). Term by term the arithmetic is
 * force_accel's (same operations in the same order), so in 3-D the result is
 * bit-identical to the generic loop; in 2-D it differs from expand-evaluate-
 * project by round-off only (exactly equal when e1, e2 are signed axes). */

/* Whether c qualifies for simple_accel, and its force vectors. Called after
 * ctx_init and again after ctx_plane sets up (or declines) the plane. */
static void ctx_fast_setup(struct traj_ctx *c)
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

static enum mech_status nonfinite_error(const struct traj_ctx *c, double t, struct mech_vec3 r,
                                        struct mech_vec3 v);

/* a(t, q, v) of a `simple` scene in nd = 2 or 3 components (see above);
 * always inlined into simple_accel2/3 so nd is a constant there (measured
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
            if (!(dn > 0.0) || !isfinite(s)) return central_gravity_error(c, i, dn, t);
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
        return nonfinite_error(c, t, r, w);
    }
    a[0] = ax;
    a[1] = ay;
    if (nd == 3) a[2] = az;
    return MECH_OK;
}
/* The fast path as the system's own callbacks (run_scene installs them for
 * `simple` scenes): one call from the integrator to the arithmetic, no
 * traj_rhs -> traj_accel -> plane_accel chain per evaluation. */
static enum mech_status simple_accel2(double t, const double *q, const double *v, double *a,
                                      void *params)
{
    return simple_accel(params, t, q, v, a, 2);
}
static enum mech_status simple_accel3(double t, const double *q, const double *v, double *a,
                                      void *params)
{
    return simple_accel(params, t, q, v, a, 3);
}
static enum mech_status simple_rhs2(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[2];
    dydt[1] = y[3];
    return simple_accel(params, t, y, y + 2, dydt + 2, 2);
}
static enum mech_status simple_rhs3(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[3];
    dydt[1] = y[4];
    dydt[2] = y[5];
    return simple_accel(params, t, y, y + 3, dydt + 3, 3);
}

static enum mech_status traj_accel(double t, const double *q, const double *v, double *a,
                                   void *params)
{
    const struct traj_ctx *c = params;
    if (c->simple && !c->dim2) return simple_accel3(t, q, v, a, params);
    struct mech_vec3 r = mech_vec3_make(q[0], q[1], q[2]);
    struct mech_vec3 vv = mech_vec3_make(v[0], v[1], v[2]);
    struct mech_vec3 acc = mech_vec3_make(0.0, 0.0, 0.0);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, vv, t, &ai);
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    if (c->pn1) acc = mech_vec3_add(acc, pn1_accel(c, r, vv));
    if (c->coriolis || c->centrifugal) { /* W(t) only when a rotation term needs it */
        const struct mech_vec3 w = omega_at(c, t);
        if (c->coriolis) acc = mech_vec3_add(acc, coriolis_accel(w, vv));
        if (c->centrifugal) acc = mech_vec3_add(acc, centrifugal_accel(w, r));
    }
    if (c->euler) acc = mech_vec3_sub(acc, mech_vec3_cross(c->wdot, r));
    if (c->translational) acc = mech_vec3_sub(acc, c->A);
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r) || !mech_vec3_isfinite(vv))
        return nonfinite_error(c, t, r, vv);
    a[0] = acc.x;
    a[1] = acc.y;
    a[2] = acc.z;
    return MECH_OK;
}

static enum mech_status traj_rhs(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[3];
    dydt[1] = y[4];
    dydt[2] = y[5];
    return traj_accel(t, y, y + 3, dydt + 3, params);
}

/* Special-relativistic dynamics in the state y = (r, u), u = gamma v:
 *   dr/dt = u / gamma,  du/dt = F(t, r, v) / m,  gamma = sqrt(1 + u^2/c^2),
 * (dp/dt = F with p = m u). gamma is never formed from 1 - beta, so the
 * state keeps its digits from beta = 1e-9 to gamma = 1e6 and beyond. The
 * frame is inertial (mech_trajectory_check), so only the forces act. */
static enum mech_status rel_rhs(double t, const double *y, double *dydt, void *params)
{
    const struct traj_ctx *c = params;
    const struct mech_vec3 r = mech_vec3_make(y[0], y[1], y[2]);
    const struct mech_vec3 u = mech_vec3_make(y[3], y[4], y[5]);
    const struct mech_vec3 v = mech_vec3_scale(u, 1.0 / gamma_of_u(u));
    struct mech_vec3 acc = mech_vec3_make(0.0, 0.0, 0.0);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, v, t, &ai);
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r) || !mech_vec3_isfinite(v))
        return nonfinite_error(c, t, r, v);
    dydt[0] = v.x;
    dydt[1] = v.y;
    dydt[2] = v.z;
    dydt[3] = acc.x;
    dydt[4] = acc.y;
    dydt[5] = acc.z;
    return MECH_OK;
}

/* Lorentz-type split for Boris (mech/ode.h): a = e(t, q) + v x w(t, q) with
 * e = position-dependent forces / m (with q E / m) + centrifugal + Euler +
 * translational, w = q B / m summed over the lorentz forces + 2 W(t) when
 * Coriolis is modelled (-2 W x v = v x 2W; q v x B / m = v x (q B / m)).
 * Only offered when no drag acts (linear drag -b v/m is not of that form;
 * b = 0 contributes nothing). */
static enum mech_status traj_lorentz(double t, const double *q, double *e, double *w,
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
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r)) return nonfinite_error(c, t, r, zero);
    if (c->coriolis) ww = mech_vec3_add(ww, mech_vec3_scale(wt, 2.0));
    e[0] = acc.x;
    e[1] = acc.y;
    e[2] = acc.z;
    w[0] = ww.x;
    w[1] = ww.y;
    w[2] = ww.z;
    return MECH_OK;
}

/* The invariant at (t, r, v) and the sum of the magnitudes of its parts. */
static void invariant_at(const struct traj_ctx *c, double t, struct mech_vec3 r, double ke,
                         double *value, double *scale)
{
    const double m = c->p->mass;
    double sum = ke, mag = fabs(ke);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        const struct mech_force *f = &c->p->forces[i];
        double u = 0.0;
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            u = -m * mech_vec3_dot(f->u.uniform_gravity.g, r);
            break;
        case MECH_FORCE_CENTRAL_GRAVITY:
            u = -m * f->u.central_gravity.gm /
                mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
            break;
        case MECH_FORCE_SPRING: {
            double ext = mech_vec3_norm(mech_vec3_sub(r, f->u.spring.anchor)) -
                         f->u.spring.rest_length;
            u = 0.5 * f->u.spring.k * ext * ext;
            break;
        }
        case MECH_FORCE_LINEAR_DRAG:
            break; /* dissipative: no potential */
        case MECH_FORCE_LORENTZ:
            /* v x B does no work; static uniform E: U = -q E.r */
            u = -c->p->charge * mech_vec3_dot(f->u.lorentz.E, r);
            break;
        case MECH_FORCE_THIRD_BODY_TIDE:
            u = m * tide_potential(f, r);
            break;
        }
        sum += u;
        mag += fabs(u);
    }
    if (c->centrifugal) {
        /* centrifugal potential -1/2 m |w x r|^2 (Jacobi integral) */
        struct mech_vec3 wr = mech_vec3_cross(omega_at(c, t), r);
        double u = -0.5 * m * mech_vec3_dot(wr, wr);
        sum += u;
        mag += fabs(u);
    }
    if (c->translational) {
        /* potential of the uniform fictitious force -m A: +m A.r */
        double u = m * mech_vec3_dot(c->A, r);
        sum += u;
        mag += fabs(u);
    }
    if (c->pn1) {
        /* the 1PN energy of the test particle (harmonic coordinates), from the
         * Lagrangian L/m = v^2/2 + gm/d + (v^4/8 + 3 gm v^2/(2d) - gm^2/(2 d^2))/c^2:
         * E/m = v^2/2 - gm/d + (3 v^4/8 + 3 gm v^2/(2d) + gm^2/(2 d^2))/c^2 */
        const struct mech_force *f = &c->p->forces[c->pn1_index];
        const double gm = f->u.central_gravity.gm;
        const double d = mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
        const double v2 = 2.0 * ke / m;
        double u = m * (0.375 * v2 * v2 + 1.5 * gm * v2 / d + 0.5 * (gm / d) * (gm / d)) /
                   (MECH_C * MECH_C);
        sum += u;
        mag += fabs(u);
    }
    *value = sum;
    *scale = mag;
}

/* A fixed step must resolve every approach to a central mass: it may not
 * exceed the time to cover the distance d to the centre at the current speed
 * (d / |v|), nor the local dynamical time sqrt(d^3 / gm) (~ 1/6 of a circular
 * orbit at that radius). Past that, a fixed-step method jumps through the
 * singularity and returns a finite but meaningless orbit (a radial infall
 * reaches r = 0 in finite time); adaptive methods shrink their steps and
 * fail by themselves (GSL_FAILURE -> MECH_ENUMERIC). */
static enum mech_status check_resolution(const struct traj_ctx *c, struct mech_vec3 r,
                                         struct mech_vec3 v, double t)
{
    const double dt = c->fixed_dt, speed = mech_vec3_norm(v);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        const struct mech_force *f = &c->p->forces[i];
        if (f->type != MECH_FORCE_CENTRAL_GRAVITY) continue;
        if (c->kepler_exact && (int)i == c->kepler_index) continue; /* exact Kepler drift */
        double d = mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
        if (dt * speed > d || dt * dt * f->u.central_gravity.gm > d * d * d)
            return mech_error_set(c->err, MECH_ENUMERIC, "integrator/dt",
                                  "dt = %.6g s does not resolve the approach to the centre of "
                                  "central_gravity force %zu (distance %.6g m, speed %.6g m/s at "
                                  "t = %.9g s): use a smaller dt or an adaptive method",
                                  dt, i, d, speed, t);
    }
    return MECH_OK;
}

/* Size of the special-relativistic correction to the acceleration under
 * the forces' sum A (F/m) at velocity v, Lorentz factor gamma (gm1 = gamma - 1,
 * 0 = beta >= 1: then the whole |A|): dv/dt = (A - (A.v) v/c^2)/gamma, so
 * dv/dt - A = -A (gamma - 1)/gamma - (A.v) v / (gamma c^2). */
static double special_correction(struct mech_vec3 A, struct mech_vec3 v, double gamma, double gm1)
{
    if (!(gamma >= 1.0)) return mech_vec3_norm(A);
    const struct mech_vec3 d = mech_vec3_add(
        mech_vec3_scale(A, -gm1 / gamma),
        mech_vec3_scale(v, -mech_vec3_dot(A, v) / (gamma * MECH_C * MECH_C)));
    return mech_vec3_norm(d);
}

static enum mech_status traj_observe(double t, const double *y, void *params)
{
    struct traj_ctx *c = params;
    struct mech_vec3 r = mech_vec3_make(y[0], y[1], y[2]);
    struct mech_vec3 v = mech_vec3_make(y[3], y[4], y[5]);
    const size_t n = c->p->n_forces;
    /* gamma, gamma - 1 (as u^2/c^2 / (gamma + 1) or beta^2 gamma^2 / (gamma + 1)),
     * and the kinetic energy: relativistic in a special run */
    double gamma = 0.0, gm1 = 0.0, ke;
    if (c->special) {
        const struct mech_vec3 u = v;
        const double u2c2 = mech_vec3_dot(u, u) / (MECH_C * MECH_C);
        gamma = sqrt(1.0 + u2c2);
        gm1 = u2c2 / (gamma + 1.0);
        v = mech_vec3_scale(u, 1.0 / gamma);
        ke = c->p->mass * MECH_C * MECH_C * gm1;
    } else {
        ke = 0.5 * c->p->mass * mech_vec3_dot(v, v);
        const double beta = mech_vec3_norm(v) / MECH_C;
        if (beta < 1.0) {
            gamma = 1.0 / sqrt((1.0 - beta) * (1.0 + beta));
            gm1 = beta * beta * gamma * gamma / (gamma + 1.0);
        }
    }
    if (c->fixed_dt > 0.0) {
        enum mech_status st = check_resolution(c, r, v, t);
        if (st != MECH_OK) return st;
    }
    struct mech_vec3 A = mech_vec3_make(0.0, 0.0, 0.0);
    for (size_t i = 0; i < n; i++) {
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, v, t, &ai);
        if (st != MECH_OK) return st;
        c->term_max[i] = fmax(c->term_max[i], mech_vec3_norm(ai));
        A = mech_vec3_add(A, ai);
    }
    /* the relativistic corrections are sized whether modelled or not (an
     * inertial frame only: elsewhere they are not offered) */
    {
        const double sc = special_correction(A, v, gamma, gm1), an = mech_vec3_norm(A);
        c->rel_max = fmax(c->rel_max, sc);
        if (an > 0.0) c->rel_ratio = fmax(c->rel_ratio, sc / an);
    }
    if (c->pn1_index >= 0) {
        const double pa = mech_vec3_norm(pn1_accel(c, r, v));
        const struct mech_force *f = &c->p->forces[c->pn1_index];
        const double d = mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
        c->pn1_max = fmax(c->pn1_max, pa);
        c->pn1_ratio = fmax(c->pn1_ratio, pa / (f->u.central_gravity.gm / (d * d)));
    }
    /* Fictitious terms are sized even when omitted (model only what the
     * scene requires, and say what was left out, with its size); all four
     * are exactly 0 in an inertial frame (w = dw/dt = A = 0 there,
     * ctx_init), where term_max keeps its 0. */
    if (c->noninertial) {
        const struct mech_vec3 wt = omega_at(c, t);
        c->term_max[n] = fmax(c->term_max[n], mech_vec3_norm(coriolis_accel(wt, v)));
        c->term_max[n + 1] = fmax(c->term_max[n + 1], mech_vec3_norm(centrifugal_accel(wt, r)));
        c->term_max[n + 2] =
            fmax(c->term_max[n + 2], mech_vec3_norm(mech_vec3_cross(c->wdot, r)));
        c->term_max[n + 3] = fmax(c->term_max[n + 3], mech_vec3_norm(c->A));
    }
    const double rn = mech_vec3_norm(r), vn = mech_vec3_norm(v); /* reused below */
    c->rmax = fmax(c->rmax, rn);
    c->vmax = fmax(c->vmax, vn);

    double inv, scale;
    invariant_at(c, t, r, ke, &inv, &scale);
    if (!isfinite(inv) || !isfinite(scale))
        return mech_error_set(c->err, MECH_ENUMERIC, NULL,
                              "non-finite energy at t = %.9g s", t);
    if (!c->have_inv0) {
        c->have_inv0 = 1;
        c->inv0 = inv;
    }
    c->inv_last = inv;
    c->drift_max = fmax(c->drift_max, fabs(inv - c->inv0));
    c->scale_max = fmax(c->scale_max, scale);
    if (c->track_l) {
        /* L = m (r - c) x v about the common centre of the central forces */
        struct mech_vec3 d = mech_vec3_sub(r, c->lcenter);
        /* r x p, p = m u in a special run (conserved by central forces too) */
        double lf = c->special ? gamma : 1.0;
        if (c->pn1) /* the 1PN momentum: v (1 + v^2/(2c^2) + 3 gm/(c^2 d)) */
            lf = 1.0 + (0.5 * mech_vec3_dot(v, v) +
                        3.0 * c->p->forces[c->pn1_index].u.central_gravity.gm /
                            mech_vec3_norm(d)) /
                           (MECH_C * MECH_C);
        struct mech_vec3 l = mech_vec3_scale(mech_vec3_cross(d, v), c->p->mass * lf);
        if (t == 0.0 && c->n_observed == 0) c->l0 = l;
        c->l_last = l;
        c->ldrift_max = fmax(c->ldrift_max, mech_vec3_norm(mech_vec3_sub(l, c->l0)));
        /* |d| = |r| exactly when the centre is the origin (r - 0 = r) */
        const double dn = c->lcenter.x == 0.0 && c->lcenter.y == 0.0 && c->lcenter.z == 0.0
                              ? rn
                              : mech_vec3_norm(d);
        c->lscale_max = fmax(c->lscale_max, c->p->mass * dn * vn);
    }
    c->n_observed++;
    c->t_last = t;
    c->r_last = r;
    return MECH_OK;
}

static double traj_event(double t, const double *y, void *params)
{
    (void)t;
    const struct traj_ctx *c = params;
    return y[c->p->stop_axis] - c->p->stop_value;
}

/* ---- planar scenes: the state (u1, u2, u1', u2') with r = u1 e1 + u2 e2 ---- */

static void plane_expand(const struct traj_ctx *c, const double *u, double *y)
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

static enum mech_status plane_accel(double t, const double *q, const double *v, double *a,
                                    void *params)
{
    const struct traj_ctx *c = params;
    if (c->simple) return simple_accel2(t, q, v, a, params); /* no 3-D expansion */
    double u[4] = {q[0], q[1], v[0], v[1]}, y[6], a3[3];
    plane_expand(c, u, y);
    enum mech_status st = traj_accel(t, y, y + 3, a3, params);
    if (st != MECH_OK) return st;
    /* the scene is planar: the acceleration lies in the plane; project it */
    struct mech_vec3 av = mech_vec3_make(a3[0], a3[1], a3[2]);
    a[0] = mech_vec3_dot(av, c->e1);
    a[1] = mech_vec3_dot(av, c->e2);
    return MECH_OK;
}

static enum mech_status plane_rhs(double t, const double *y, double *dydt, void *params)
{
    dydt[0] = y[2];
    dydt[1] = y[3];
    return plane_accel(t, y, y + 2, dydt + 2, params);
}

static enum mech_status plane_observe(double t, const double *u, void *params)
{
    double y[6];
    plane_expand(params, u, y);
    return traj_observe(t, y, params);
}

static double plane_event(double t, const double *u, void *params)
{
    double y[6];
    plane_expand(params, u, y);
    return traj_event(t, y, params);
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
    struct mech_vec3 acc = mech_vec3_make(0.0, 0.0, 0.0);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        if ((int)i == c->kepler_index) continue;
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, vv, t, &ai);
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r) || !mech_vec3_isfinite(vv))
        return nonfinite_error(c, t, r, vv);
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

static int scene_velocity_dependent(const struct traj_ctx *c);

/* Fill ks with c's Kepler split in the integration's coordinates (2-D: the
 * centre projected on e1, e2). c->kepler_index >= 0. */
static void kepler_split_fill(const struct traj_ctx *c, struct mech_ode_kepler_split *ks)
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
    ks->velocity_dependent = scene_velocity_dependent(c);
}

/* The integrator's side of mech_trajectory_angular_center: its frame terms. */
static int angular_momentum_center(const struct traj_ctx *c, struct mech_vec3 *center)
{
    const int rot = (c->coriolis || c->centrifugal || c->euler) &&
                    (mech_vec3_norm(c->w) > 0.0 || mech_vec3_norm(c->wdot) > 0.0);
    const int tr = c->translational && mech_vec3_norm(c->A) > 0.0;
    return mech_trajectory_angular_center(c->p, rot, tr, center);
}

/* The Kepler split of a scene (wisdom_holman, mech/ode.h): the index of its
 * one central_gravity force when the frame is inertial and exactly one
 * central_gravity acts (the other forces are the perturbation), else -1 with
 * *why (may be NULL) saying what is missing. */
static int kepler_split_index(const struct mech_trajectory_problem *p, const char **why)
{
    int idx = -1, n = 0;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) {
            idx = (int)i;
            n++;
        }
    const char *w = NULL;
    if (p->frame.type != MECH_FRAME_INERTIAL) w = "the frame is not inertial";
    else if (p->relativity) w = "a relativistic term is modelled (integrated whole, no split)";
    else if (n == 0) w = "the scene has no central_gravity force";
    else if (n > 1) w = "the scene has more than one";
    if (why) *why = w;
    return w ? -1 : idx;
}

static void ctx_init(struct traj_ctx *c, const struct mech_trajectory_problem *p, double fixed_dt,
                     struct mech_error *err)
{
    memset(c, 0, sizeof *c);
    c->p = p;
    c->err = err;
    c->noninertial = p->frame.type != MECH_FRAME_INERTIAL;
    c->w = mech_frame_omega(&p->frame);
    if (p->frame.type == MECH_FRAME_ROTATING) {
        c->wdot = p->frame.omega_dot;
        c->A = p->frame.acceleration;
    }
    c->coriolis = c->noninertial && (p->fictitious & MECH_FICTITIOUS_CORIOLIS);
    c->centrifugal = c->noninertial && (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    c->euler = c->noninertial && (p->fictitious & MECH_FICTITIOUS_EULER);
    c->translational = c->noninertial && (p->fictitious & MECH_FICTITIOUS_TRANSLATIONAL);
    c->fixed_dt = fixed_dt;
    c->kepler_index = kepler_split_index(p, NULL);
    c->special = !c->noninertial && (p->relativity & MECH_RELATIVITY_SPECIAL);
    c->pn1_index = -1;
    if (!c->noninertial) {
        size_t n = 0;
        for (size_t i = 0; i < p->n_forces; i++)
            if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) {
                n++;
                c->pn1_index = (int)i;
            }
        if (n != 1) c->pn1_index = -1;
    }
    c->pn1 = c->pn1_index >= 0 && (p->relativity & MECH_RELATIVITY_SCHWARZSCHILD_1PN);
    c->track_l = angular_momentum_center(c, &c->lcenter);
    c->r_last = p->position;
    ctx_fast_setup(c);
}

static int scene_has_drag(const struct mech_trajectory_problem *p)
{
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LINEAR_DRAG && p->forces[i].u.linear_drag.b > 0.0)
            return 1;
    return 0;
}

/* Whether the acceleration depends on the velocity: drag, Coriolis in a
 * rotating frame, or a magnetic field acting on a charge. */
static int scene_velocity_dependent(const struct traj_ctx *c)
{
    const struct mech_trajectory_problem *p = c->p;
    if (scene_has_drag(p)) return 1;
    if (c->special || c->pn1) return 1; /* v/c terms */
    if (c->coriolis && (mech_vec3_norm(c->w) > 0.0 || mech_vec3_norm(c->wdot) > 0.0)) return 1;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LORENTZ && p->charge != 0.0 &&
            mech_vec3_norm(p->forces[i].u.lorentz.B) > 0.0)
            return 1;
    return 0;
}

/* Whether the time-dependent rotation makes the equations depend on t. */
static int scene_time_dependent(const struct traj_ctx *c)
{
    return (c->coriolis || c->centrifugal || c->euler) && mech_vec3_norm(c->wdot) > 0.0;
}

/* Set up planar integration in c when asked and possible for this method. */
static void ctx_plane(struct traj_ctx *c, const struct mech_ode_method_info *mi)
{
    struct mech_vec3 n;
    c->dim2 = 0;
    /* a special run's state is (r, u): no planar form */
    if (!c->p->reduce_planar || c->special || !mech_trajectory_plane(c->p, &n)) return;
    /* Boris rotates 3-vectors: 2-D only when it needs no Lorentz split */
    if (!strcmp(mi->name, "boris") && scene_velocity_dependent(c)) return;
    c->dim2 = 1;
    mech_trajectory_plane_axes(n, &c->e1, &c->e2);
    ctx_fast_setup(c); /* the force vectors in plane coordinates */
}

/* Buffers of one run: samples (t, y) and the stop state. */
struct traj_run {
    double *sample_t, *sample_y; /* samples, samples * 6: (r, v) */
    double y_stop[6];
    struct mech_vec3 *sample_u;  /* special runs: the proper velocities, else NULL */
    struct mech_vec3 u_stop;
    struct mech_ode_result out;
};

/* One integration of the scene with (method, opt), observed through c. */
static enum mech_status run_scene(const struct mech_trajectory_problem *p,
                                  const struct mech_integrator *method,
                                  struct mech_ode_options opt, const struct mech_budget *budget,
                                  struct traj_ctx *c, struct traj_run *run,
                                  struct mech_error *err)
{
    const int dissipative = scene_has_drag(p);
    const int velocity_free = !scene_velocity_dependent(c);
    /* one body: its 3 (planar: 2) coordinates are one particle */
    struct mech_ode_system sys = {6, traj_rhs, traj_accel,
                                  velocity_free ? MECH_ODE_VELOCITY_FREE : 0u, c,
                                  dissipative || c->pn1 ? NULL : traj_lorentz, 3, NULL};
    double y0[6] = {p->position.x, p->position.y, p->position.z,
                    p->velocity.x, p->velocity.y, p->velocity.z};
    if (c->special) {
        /* first order in (r, u): no second-order form, no Lorentz split */
        const struct mech_vec3 u0v = mech_trajectory_proper_velocity0(p);
        sys = (struct mech_ode_system){6, rel_rhs, NULL, 0u, c, NULL, 3, NULL};
        y0[3] = u0v.x;
        y0[4] = u0v.y;
        y0[5] = u0v.z;
        if (!run->sample_u) {
            run->sample_u = malloc(p->samples * sizeof *run->sample_u);
            if (!run->sample_u) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
        }
    }
    double u0[4], u_stop[4] = {0, 0, 0, 0};
    double *u_samples = NULL;
    if (c->dim2) {
        /* planar: 4 components, r = u1 e1 + u2 e2 */
        sys = (struct mech_ode_system){4, plane_rhs, plane_accel,
                                       velocity_free ? MECH_ODE_VELOCITY_FREE : 0u, c, NULL, 2,
                                       NULL};
        u0[0] = mech_vec3_dot(p->position, c->e1);
        u0[1] = mech_vec3_dot(p->position, c->e2);
        u0[2] = mech_vec3_dot(p->velocity, c->e1);
        u0[3] = mech_vec3_dot(p->velocity, c->e2);
        u_samples = malloc(p->samples * 4 * sizeof *u_samples);
        if (!u_samples) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    }
    if (c->simple) { /* the force loop's fast path, called directly */
        sys.rhs = c->dim2 ? simple_rhs2 : simple_rhs3;
        sys.accel = c->dim2 ? simple_accel2 : simple_accel3;
        sys.flags |= MECH_ODE_FINITE_OUTPUT; /* simple_accel screens q, v and a */
    }
    struct mech_ode_kepler_split ks;
    if (c->kepler_index >= 0) { /* one central body: offer the Kepler split */
        kepler_split_fill(c, &ks);
        sys.kepler = &ks;
        c->kepler_exact = mech_ode_method_describe(method).kepler_split;
    }
    struct mech_ode_problem op = {
        .sys = &sys,
        .method = method,
        .opt = opt,
        .t0 = 0.0,
        .t_end = p->t_end,
        .y0 = c->dim2 ? u0 : y0,
        .n_samples = p->samples,
        .sample_t = run->sample_t,
        .sample_y = c->dim2 ? u_samples : run->sample_y,
        .event = p->has_stop ? (c->dim2 ? plane_event : traj_event) : NULL,
        .event_direction = (int)p->stop_direction,
        .event_params = c,
        .observe = c->dim2 ? plane_observe : traj_observe,
        .observe_params = c,
        .y_stop = c->dim2 ? u_stop : run->y_stop,
    };
    memset(&run->out, 0, sizeof run->out);
    enum mech_status st = mech_ode_solve(&op, budget, &run->out, err);
    if (c->dim2) {
        for (size_t i = 0; i < run->out.n_samples; i++)
            plane_expand(c, u_samples + 4 * i, run->sample_y + 6 * i);
        if (run->out.stopped) plane_expand(c, u_stop, run->y_stop);
        free(u_samples);
    }
    if (c->special) {
        /* (r, u) -> (r, v), the proper velocities kept beside */
        for (size_t i = 0; i <= run->out.n_samples; i++) {
            double *y = i < run->out.n_samples ? run->sample_y + 6 * i : run->y_stop;
            if (i == run->out.n_samples && !run->out.stopped) break;
            const struct mech_vec3 u = mech_vec3_make(y[3], y[4], y[5]);
            const double g = gamma_of_u(u);
            if (i < run->out.n_samples) run->sample_u[i] = u;
            else run->u_stop = u;
            y[3] = u.x / g;
            y[4] = u.y / g;
            y[5] = u.z / g;
        }
    }
    if (st == MECH_ENUMERIC && err && err->code == MECH_ENUMERIC && !strstr(err->text, "position") &&
        !strstr(err->text, "distance")) {
        /* The driver's own message (a non-finite state after a step) does not
         * say where: add the last finite state observed. */
        size_t n = strlen(err->text);
        snprintf(err->text + n, sizeof err->text - n,
                 "; last state t = %.9g s, r = [%.6g, %.6g, %.6g] m", c->t_last,
                 c->r_last.x, c->r_last.y, c->r_last.z);
    }
    return st;
}

static void run_free(struct traj_run *run)
{
    free(run->sample_t);
    free(run->sample_y);
    free(run->sample_u);
    run->sample_t = run->sample_y = NULL;
    run->sample_u = NULL;
}

static enum mech_status run_alloc(struct traj_run *run, size_t n, struct mech_error *err)
{
    memset(run, 0, sizeof *run);
    run->sample_t = malloc(n * sizeof *run->sample_t);
    run->sample_y = malloc(n * 6 * sizeof *run->sample_y);
    if (!run->sample_t || !run->sample_y) {
        run_free(run);
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    }
    return MECH_OK;
}

static struct mech_vec3 yvec(const double *y, int off)
{
    return mech_vec3_make(y[off], y[off + 1], y[off + 2]);
}

/* Errors of run against the reference at every sample and the stop point,
 * relative to the scene's scales: positions to the largest distance from the
 * reference's centre (Kepler's body, the spring's anchor; the origin for the
 * uniform fields) over the samples, the orbit's or oscillation's size;
 * velocities to the largest speed over the samples and over every step of
 * the run (speed_max), never to a value that passes through zero (a 1-D
 * oscillator sampled once a period is at rest at every sample). */
static enum mech_status reference_report(const struct mech_trajectory_problem *p,
                                         const struct traj_run *run, double speed_max,
                                         struct mech_trajectory_reference_report *rep,
                                         struct mech_error *err)
{
    struct mech_trajectory_reference ref;
    memset(rep, 0, sizeof *rep);
    rep->name = "";
    if (mech_trajectory_reference_find(p, &ref) == MECH_REFERENCE_NONE) return MECH_OK;
    double rmax = 0.0, vmax = isfinite(speed_max) ? speed_max : 0.0;
    const int centred = !strncmp(ref.name, "kepler", 6) || !strncmp(ref.name, "harmonic", 8);
    const size_t n = run->out.n_samples;
    for (size_t i = 0; i <= n; i++) {
        const double *y;
        double t;
        if (i < n) {
            y = run->sample_y + 6 * i;
            t = run->sample_t[i];
        } else if (run->out.stopped) {
            y = run->y_stop;
            t = run->out.t_stop;
        } else {
            break;
        }
        struct mech_vec3 rr, vr;
        double so;
        enum mech_status st = mech_trajectory_reference_eval(&ref, t, &rr, &vr, &so, err);
        if (st != MECH_OK) return st;
        double de = mech_vec3_norm(mech_vec3_sub(yvec(y, 0), rr));
        double dv = mech_vec3_norm(mech_vec3_sub(yvec(y, 3), vr));
        rep->max_position_error = fmax(rep->max_position_error, de);
        rep->max_velocity_error = fmax(rep->max_velocity_error, dv);
        rep->final_position_error = de;
        rep->truncation_estimate = fmax(rep->truncation_estimate, so);
        rmax = fmax(rmax, mech_vec3_norm(centred ? mech_vec3_sub(rr, ref.center) : rr));
        vmax = fmax(vmax, mech_vec3_norm(vr));
    }
    rep->kind = (int)ref.kind;
    rep->name = ref.name;
    rep->max_relative_position_error = rmax > 0.0 ? rep->max_position_error / rmax : 0.0;
    rep->max_relative_velocity_error = vmax > 0.0 ? rep->max_velocity_error / vmax : 0.0;
    return MECH_OK;
}

enum mech_status mech_trajectory_integrate(const struct mech_trajectory_problem *p,
                                           const struct mech_budget *budget,
                                           struct mech_trajectory_result *res,
                                           struct mech_error *err)
{
    if (!p || !res) return mech_error_set(err, MECH_EINVAL, NULL, "NULL problem or result");
    res->n_samples = 0;
    res->stopped = 0;
    res->t_stop = NAN;
    enum mech_status st = mech_trajectory_check(p, err);
    if (st != MECH_OK) return st;
    const struct mech_integrator *method = mech_ode_method_find(p->method);
    if (!method)
        return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method \"%s\"",
                              p->method ? p->method : "(null)");
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "no compute budget given");
    const struct mech_ode_method_info mi = mech_ode_method_describe(method);
    if ((p->relativity & MECH_RELATIVITY_SPECIAL) && mi.second_order)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "%s integrates q'' = a(q, v); special-relativistic dynamics are "
                              "first order in (r, u = gamma v): use rk8pd, rkf45, rkck, gauss6 "
                              "or choose by accuracy",
                              mi.name);
    const char *no_split = NULL;
    if (mi.kepler_split && kepler_split_index(p, &no_split) < 0)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "%s needs exactly one central_gravity force in an inertial "
                              "frame, the other forces being small perturbations; %s",
                              mi.name, no_split);

    struct traj_ctx c;
    ctx_init(&c, p, mi.adaptive ? 0.0 : p->opt.dt, err);
    ctx_plane(&c, &mi);
    const int dissipative = scene_has_drag(p);

    struct traj_run run;
    if ((st = run_alloc(&run, p->samples, err)) != MECH_OK) return st;
    st = run_scene(p, method, p->opt, budget, &c, &run, err);
    /* Samples written so far are returned on every path. */
    const size_t ns = run.out.n_samples;
    res->n_samples = ns;
    for (size_t i = 0; i < ns; i++) {
        const double *y = run.sample_y + 6 * i;
        if (res->t) res->t[i] = run.sample_t[i];
        if (res->position) res->position[i] = yvec(y, 0);
        if (res->velocity) res->velocity[i] = yvec(y, 3);
        if (res->proper_velocity && run.sample_u) res->proper_velocity[i] = run.sample_u[i];
    }
    if (st != MECH_OK) {
        run_free(&run);
        return st;
    }

    res->stopped = run.out.stopped;
    if (run.out.stopped) {
        res->t_stop = run.out.t_stop;
        res->stop_position = yvec(run.y_stop, 0);
        res->stop_velocity = yvec(run.y_stop, 3);
        res->stop_proper_velocity = c.special ? run.u_stop : mech_vec3_make(0, 0, 0);
    }
    res->n_terms = p->n_forces + MECH_TRAJECTORY_N_FICTITIOUS;
    res->dimensions = c.dim2 ? 2 : 3;
    res->max_radius = c.rmax;
    res->max_speed = c.vmax;
    res->plane_normal = c.dim2 ? mech_vec3_cross(c.e1, c.e2) : mech_vec3_make(0, 0, 0);
    for (size_t i = 0; i < p->n_forces; i++) {
        res->terms[i].term = force_name(p->forces[i].type);
        res->terms[i].force_index = (int)i;
        res->terms[i].included = 1;
        res->terms[i].max_acceleration = c.term_max[i];
    }
    res->terms[p->n_forces] = (struct mech_trajectory_term){"coriolis", -1, c.coriolis,
                                                            c.term_max[p->n_forces]};
    res->terms[p->n_forces + 1] = (struct mech_trajectory_term){"centrifugal", -1, c.centrifugal,
                                                                c.term_max[p->n_forces + 1]};
    res->terms[p->n_forces + 2] = (struct mech_trajectory_term){"euler", -1, c.euler,
                                                                c.term_max[p->n_forces + 2]};
    res->terms[p->n_forces + 3] = (struct mech_trajectory_term){
        "translational", -1, c.translational, c.term_max[p->n_forces + 3]};
    res->relativity_terms[0] =
        (struct mech_trajectory_term){"relativistic", -1, c.special, c.rel_max};
    res->relativity_terms[1] =
        (struct mech_trajectory_term){"schwarzschild_1pn", -1, c.pn1, c.pn1_max};
    res->relativity_ratio[0] = c.rel_ratio;
    res->relativity_ratio[1] = c.pn1_ratio;
    res->relativistic = c.special;
    res->method = mi.name;
    res->stats = run.out.stats;
    res->total_steps = run.out.stats.steps;

    struct mech_trajectory_invariant *inv = &res->invariants[0];
    memset(res->invariants, 0, sizeof res->invariants);
    inv->name = c.noninertial ? "jacobi_integral" : "energy";
    const int time_dependent = scene_time_dependent(&c);
    inv->conserved = !dissipative && !time_dependent;
    inv->note = time_dependent
                    ? "not conserved: the frame's angular velocity changes with time (omega_dot), "
                      "so the equations depend on t and no energy-like integral exists"
                : dissipative ? "not conserved: linear drag dissipates it"
                : c.noninertial
                    ? "conserved: 1/2 m v^2 + U - 1/2 m |w x r|^2 (if centrifugal modelled) + m A.r "
                      "(if translational modelled); Coriolis and q v x B do no work"
                : c.special
                    ? "conserved: (gamma - 1) m c^2 + U, gamma - 1 = (u/c)^2/(gamma + 1) (q v x B "
                      "does no work; U includes -q E.r)"
                : c.pn1
                    ? "conserved: the 1PN energy 1/2 m v^2 + U + m (3 v^4/8 + 3 gm v^2/(2 d) + "
                      "gm^2/(2 d^2))/c^2 (harmonic coordinates)"
                    : "conserved: 1/2 m v^2 + U (q v x B does no work; U includes -q E.r)";
    inv->initial = c.inv0;
    inv->final = c.inv_last;
    double denom = c.inv0 != 0.0 ? fabs(c.inv0) : c.scale_max;
    inv->max_relative_drift = denom > 0.0 ? c.drift_max / denom : 0.0;
    res->n_invariants = 1;
    if (c.track_l) {
        struct mech_trajectory_invariant *l = &res->invariants[1];
        l->name = "angular_momentum";
        l->conserved = 1;
        l->note = c.special ? "conserved: r x p with p = gamma m v; every force is central about "
                              "one point"
                  : c.pn1 ? "conserved: the 1PN angular momentum m (r x v) (1 + v^2/(2 c^2) + "
                            "3 gm/(c^2 d)); every force is central about one point"
                          : "conserved: every force is central about one point";
        l->is_vector = 1;
        l->initial_vector = c.l0;
        l->final_vector = c.l_last;
        l->initial = mech_vec3_norm(c.l0);
        l->final = mech_vec3_norm(c.l_last);
        double ld = l->initial > 0.0 ? l->initial : c.lscale_max;
        l->max_relative_drift = ld > 0.0 ? c.ldrift_max / ld : 0.0;
        res->n_invariants = 2;
    }
    res->invariant = res->invariants[0];

    st = reference_report(p, &run, res->max_speed, &res->reference, err);
    memset(&res->error_estimate, 0, sizeof res->error_estimate);
    if (st == MECH_OK && p->error_estimate && res->reference.kind == MECH_REFERENCE_NONE) {
        /* Second run at a tighter setting with what is left of the budget. */
        struct mech_trajectory_error_estimate *ee = &res->error_estimate;
        struct mech_ode_options o2 = p->opt;
        const struct mech_integrator *method2 = method;
        if (mi.adaptive && !strcmp(mi.name, "radau15") && p->opt.rtol / 100.0 < 1e-10) {
            /* radau15 floors its eps at 1e-10 (round-off): a tighter radau15
             * run would repeat this one bit for bit. */
            method2 = mech_ode_method_find("rk8pd");
            o2.rtol = 1e-14;
            o2.atol = 0.0;
            ee->rule = "radau15 is at its round-off floor: compared with rk8pd at rtol 1e-14";
        } else if (mi.adaptive && p->opt.rtol / 100.0 < 1e-13) {
            /* GSL's methods gain nothing below rtol ~1e-13: compare with radau15 */
            method2 = mech_ode_method_find("radau15");
            o2.rtol = 1e-10;
            o2.atol = 0.0;
            ee->rule = "rtol/100 is below what the method resolves: compared with radau15 at "
                       "its round-off setting (rtol 1e-10)";
        } else if (mi.adaptive) {
            o2.rtol = p->opt.rtol / 100.0;
            o2.atol = p->opt.atol / 100.0;
            ee->rule = "same method, rtol/100 and atol/100";
        } else {
            o2.dt = p->opt.dt / 2.0;
            ee->rule = "same method, dt/2; the estimate is the difference times 2^p/(2^p - 1)";
        }
        struct mech_budget b2 = *budget;
        b2.max_steps = budget->max_steps - run.out.stats.steps;
        struct traj_run run2;
        struct traj_ctx c2;
        ctx_init(&c2, p, mi.adaptive ? 0.0 : o2.dt, err);
        {
            const struct mech_ode_method_info mi2 =
                method2 ? mech_ode_method_describe(method2) : mi;
            ctx_plane(&c2, &mi2);
        }
        if (b2.max_steps <= 0) {
            st = mech_error_set(err, MECH_EBUDGET, NULL,
                                "no steps left in the budget for the error estimate's second run");
        } else if ((st = run_alloc(&run2, p->samples, err)) == MECH_OK) {
            st = method2 ? run_scene(p, method2, o2, &b2, &c2, &run2, err)
                         : mech_error_set(err, MECH_EINTERNAL, NULL, "estimate method missing");
            if (st == MECH_OK) {
                size_t n = run.out.n_samples < run2.out.n_samples ? run.out.n_samples
                                                                  : run2.out.n_samples;
                for (size_t i = 0; i < n; i++) {
                    const double *a = run.sample_y + 6 * i, *b = run2.sample_y + 6 * i;
                    double dr = mech_vec3_norm(mech_vec3_sub(yvec(a, 0), yvec(b, 0)));
                    double dv = mech_vec3_norm(mech_vec3_sub(yvec(a, 3), yvec(b, 3)));
                    ee->max_position_difference = fmax(ee->max_position_difference, dr);
                    ee->max_velocity_difference = fmax(ee->max_velocity_difference, dv);
                    ee->final_position_difference = dr;
                }
                if (run.out.stopped && run2.out.stopped) {
                    double dr = mech_vec3_norm(
                        mech_vec3_sub(yvec(run.y_stop, 0), yvec(run2.y_stop, 0)));
                    ee->max_position_difference = fmax(ee->max_position_difference, dr);
                    ee->final_position_difference = dr;
                }
                double f = 1.0;
                if (!mi.adaptive) {
                    double q = ldexp(1.0, mi.order);
                    f = q / (q - 1.0);
                }
                ee->max_position_error_estimate = f * ee->max_position_difference;
                ee->done = 1;
                ee->method = mech_ode_method_describe(method2).name;
                ee->opt = o2;
                ee->stats = run2.out.stats;
                res->total_steps += run2.out.stats.steps;
            }
            run_free(&run2);
        }
    }
    run_free(&run);
    return st;
}

/* ---- what the chooser's profile asks of the equations (trajectory_scene.h) -- */

enum mech_status mech_trajectory_start_acceleration(const struct mech_trajectory_problem *p,
                                                    double a[3])
{
    struct traj_ctx c;
    ctx_init(&c, p, 0.0, NULL);
    double q0[3] = {p->position.x, p->position.y, p->position.z},
           v0[3] = {p->velocity.x, p->velocity.y, p->velocity.z};
    return traj_accel(0.0, q0, v0, a, &c);
}

int mech_trajectory_velocity_dependent(const struct mech_trajectory_problem *p)
{
    struct traj_ctx c;
    ctx_init(&c, p, 0.0, NULL);
    return scene_velocity_dependent(&c);
}
