/* trajectory.c — equations of motion of a particle in an inertial, rotating
 * or local Earth frame (notes §1.2 "Rotating frames", §1.3 "Motion near the
 * Earth"), integrated with mech_ode_solve; model-term sizes and the
 * conserved quantities (energy / Jacobi integral, angular momentum) are
 * gathered by the driver's observer at every sample and every step end; the
 * samples are compared with the scene's reference solution (reference.c) or,
 * on request, with a second run at a tighter setting. Also: the accuracy
 * presets and the method choice behind {"accuracy": ...} / {"target_error": ...}.
 */
#include "mech/trajectory.h"
#include "mech/reference.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for error parameter paths */
#include <stdlib.h>
#include <string.h>

static const double traj_pi = 3.14159265358979323846;

struct traj_ctx {
    const struct mech_trajectory_problem *p;
    struct mech_vec3 w;   /* frame angular velocity, frame axes */
    int noninertial;
    int coriolis, centrifugal; /* modelled */
    double fixed_dt;      /* step of a fixed-step method, 0 for adaptive ones */
    struct mech_error *err;
    /* observer accumulators */
    double term_max[MECH_TRAJECTORY_MAX_FORCES + 2];
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
    }
    return "unknown";
}

struct mech_vec3 mech_frame_omega(const struct mech_frame *frame)
{
    switch (frame->type) {
    case MECH_FRAME_ROTATING:
        return frame->omega;
    case MECH_FRAME_EARTH: {
        /* notes §1.3: w points from the south to the north pole; in local
         * axes (east, north, up) at latitude lat: w = W (0, cos lat, sin lat). */
        double lat = frame->latitude_deg * (traj_pi / 180.0);
        return mech_vec3_make(0.0, frame->omega_magnitude * cos(lat),
                              frame->omega_magnitude * sin(lat));
    }
    case MECH_FRAME_INERTIAL:
    default:
        return mech_vec3_make(0.0, 0.0, 0.0);
    }
}

/* Acceleration of force i at (r, v). MECH_ENUMERIC at the centre of a central mass. */
static enum mech_status force_accel(const struct traj_ctx *c, size_t i, struct mech_vec3 r,
                                    struct mech_vec3 v, double t, struct mech_vec3 *a)
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
        if (!(dn > 0.0) || !isfinite(s)) {
            char param[32];
            snprintf(param, sizeof param, "forces/%zu", i);
            return mech_error_set(c->err, MECH_ENUMERIC, param,
                                  "the particle reached the centre of central_gravity force %zu "
                                  "(distance %.3g m) at t = %.9g s",
                                  i, dn, t);
        }
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
    }
    return mech_error_set(c->err, MECH_EINTERNAL, NULL, "unknown force type");
}

/* notes §1.2: a_Coriolis = -2 w x v, a_centrifugal = -w x (w x r). */
static struct mech_vec3 coriolis_accel(struct mech_vec3 w, struct mech_vec3 v)
{
    return mech_vec3_scale(mech_vec3_cross(w, v), -2.0);
}
static struct mech_vec3 centrifugal_accel(struct mech_vec3 w, struct mech_vec3 r)
{
    return mech_vec3_scale(mech_vec3_cross(w, mech_vec3_cross(w, r)), -1.0);
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

static enum mech_status traj_accel(double t, const double *q, const double *v, double *a,
                                   void *params)
{
    const struct traj_ctx *c = params;
    struct mech_vec3 r = mech_vec3_make(q[0], q[1], q[2]);
    struct mech_vec3 vv = mech_vec3_make(v[0], v[1], v[2]);
    struct mech_vec3 acc = mech_vec3_make(0.0, 0.0, 0.0);
    for (size_t i = 0; i < c->p->n_forces; i++) {
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, vv, t, &ai);
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    if (c->coriolis) acc = mech_vec3_add(acc, coriolis_accel(c->w, vv));
    if (c->centrifugal) acc = mech_vec3_add(acc, centrifugal_accel(c->w, r));
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

/* Lorentz-type split for Boris (mech/ode.h): a = e(t, q) + v x w(t, q) with
 * e = position-dependent forces / m + centrifugal, w = 2 W when Coriolis is
 * modelled (-2 W x v = v x 2W), else 0. Only offered when no drag acts
 * (linear drag -b v/m is not of that form; b = 0 contributes nothing). */
static enum mech_status traj_lorentz(double t, const double *q, double *e, double *w,
                                     void *params)
{
    const struct traj_ctx *c = params;
    struct mech_vec3 r = mech_vec3_make(q[0], q[1], q[2]);
    const struct mech_vec3 zero = mech_vec3_make(0.0, 0.0, 0.0);
    struct mech_vec3 acc = zero;
    for (size_t i = 0; i < c->p->n_forces; i++) {
        if (c->p->forces[i].type == MECH_FORCE_LINEAR_DRAG) continue;
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, zero, t, &ai);
        if (st != MECH_OK) return st;
        acc = mech_vec3_add(acc, ai);
    }
    if (c->centrifugal) acc = mech_vec3_add(acc, centrifugal_accel(c->w, r));
    if (!mech_vec3_isfinite(acc) || !mech_vec3_isfinite(r)) return nonfinite_error(c, t, r, zero);
    struct mech_vec3 ww = c->coriolis ? mech_vec3_scale(c->w, 2.0) : zero;
    e[0] = acc.x;
    e[1] = acc.y;
    e[2] = acc.z;
    w[0] = ww.x;
    w[1] = ww.y;
    w[2] = ww.z;
    return MECH_OK;
}

/* The invariant at (r, v) and the sum of the magnitudes of its parts. */
static void invariant_at(const struct traj_ctx *c, struct mech_vec3 r, struct mech_vec3 v,
                         double *value, double *scale)
{
    const double m = c->p->mass;
    double ke = 0.5 * m * mech_vec3_dot(v, v);
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
        }
        sum += u;
        mag += fabs(u);
    }
    if (c->centrifugal) {
        /* centrifugal potential -1/2 m |w x r|^2 (Jacobi integral) */
        struct mech_vec3 wr = mech_vec3_cross(c->w, r);
        double u = -0.5 * m * mech_vec3_dot(wr, wr);
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

static enum mech_status traj_observe(double t, const double *y, void *params)
{
    struct traj_ctx *c = params;
    struct mech_vec3 r = mech_vec3_make(y[0], y[1], y[2]);
    struct mech_vec3 v = mech_vec3_make(y[3], y[4], y[5]);
    const size_t n = c->p->n_forces;
    if (c->fixed_dt > 0.0) {
        enum mech_status st = check_resolution(c, r, v, t);
        if (st != MECH_OK) return st;
    }
    for (size_t i = 0; i < n; i++) {
        struct mech_vec3 ai;
        enum mech_status st = force_accel(c, i, r, v, t, &ai);
        if (st != MECH_OK) return st;
        c->term_max[i] = fmax(c->term_max[i], mech_vec3_norm(ai));
    }
    /* Fictitious terms are sized even when omitted (DESIGN: say what was
     * left out, with its size); both are 0 in an inertial frame. */
    c->term_max[n] = fmax(c->term_max[n], mech_vec3_norm(coriolis_accel(c->w, v)));
    c->term_max[n + 1] = fmax(c->term_max[n + 1], mech_vec3_norm(centrifugal_accel(c->w, r)));

    double inv, scale;
    invariant_at(c, r, v, &inv, &scale);
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
        struct mech_vec3 l = mech_vec3_scale(mech_vec3_cross(d, v), c->p->mass);
        if (t == 0.0 && c->n_observed == 0) c->l0 = l;
        c->l_last = l;
        c->ldrift_max = fmax(c->ldrift_max, mech_vec3_norm(mech_vec3_sub(l, c->l0)));
        c->lscale_max = fmax(c->lscale_max, c->p->mass * mech_vec3_norm(d) * mech_vec3_norm(v));
    }
    c->n_observed++;
    c->t_last = t;
    c->r_last = r;
    return MECH_OK;
}

static double traj_event(double t, const double *y, void *params)
{
    (void)t;
    const struct mech_trajectory_problem *p = params;
    return y[p->stop_axis] - p->stop_value;
}

static enum mech_status check_vec(struct mech_vec3 v, const char *param, struct mech_error *err)
{
    if (!mech_vec3_isfinite(v))
        return mech_error_set(err, MECH_EINVAL, param, "components must be finite");
    return MECH_OK;
}

static enum mech_status check_problem(const struct mech_trajectory_problem *p,
                                      struct mech_error *err)
{
    enum mech_status st;
    char param[64];
    if (!(isfinite(p->mass) && p->mass > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "particle/mass",
                              "mass must be finite and > 0, got %.17g", p->mass);
    if ((st = check_vec(p->position, "particle/position", err)) != MECH_OK) return st;
    if ((st = check_vec(p->velocity, "particle/velocity", err)) != MECH_OK) return st;
    switch (p->frame.type) {
    case MECH_FRAME_INERTIAL:
        break;
    case MECH_FRAME_ROTATING:
        if ((st = check_vec(p->frame.omega, "frame/omega", err)) != MECH_OK) return st;
        break;
    case MECH_FRAME_EARTH:
        if (!(p->frame.latitude_deg >= -90.0 && p->frame.latitude_deg <= 90.0))
            return mech_error_set(err, MECH_EDOMAIN, "frame/latitude_deg",
                                  "latitude must be in [-90, 90] degrees, got %.17g",
                                  p->frame.latitude_deg);
        if (!(isfinite(p->frame.omega_magnitude) && p->frame.omega_magnitude >= 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "frame/omega_magnitude",
                                  "omega_magnitude must be finite and >= 0, got %.17g",
                                  p->frame.omega_magnitude);
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, "frame/type", "unknown frame type");
    }
    if (p->n_forces > MECH_TRAJECTORY_MAX_FORCES || (p->n_forces && !p->forces))
        return mech_error_set(err, MECH_EINVAL, "forces", "at most %d forces",
                              MECH_TRAJECTORY_MAX_FORCES);
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            snprintf(param, sizeof param, "forces/%zu/g", i);
            if ((st = check_vec(f->u.uniform_gravity.g, param, err)) != MECH_OK) return st;
            break;
        case MECH_FORCE_CENTRAL_GRAVITY: {
            snprintf(param, sizeof param, "forces/%zu/gm", i);
            if (!(isfinite(f->u.central_gravity.gm) && f->u.central_gravity.gm > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "gm must be finite and > 0");
            snprintf(param, sizeof param, "forces/%zu/center", i);
            if ((st = check_vec(f->u.central_gravity.center, param, err)) != MECH_OK) return st;
            struct mech_vec3 d = mech_vec3_sub(p->position, f->u.central_gravity.center);
            if (!(mech_vec3_norm(d) > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, "particle/position",
                                      "the particle starts at the centre of force %zu", i);
            break;
        }
        case MECH_FORCE_SPRING:
            snprintf(param, sizeof param, "forces/%zu/k", i);
            if (!(isfinite(f->u.spring.k) && f->u.spring.k >= 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "k must be finite and >= 0");
            snprintf(param, sizeof param, "forces/%zu/rest_length", i);
            if (!(isfinite(f->u.spring.rest_length) && f->u.spring.rest_length >= 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param,
                                      "rest_length must be finite and >= 0");
            snprintf(param, sizeof param, "forces/%zu/anchor", i);
            if ((st = check_vec(f->u.spring.anchor, param, err)) != MECH_OK) return st;
            break;
        case MECH_FORCE_LINEAR_DRAG:
            snprintf(param, sizeof param, "forces/%zu/b", i);
            if (!(isfinite(f->u.linear_drag.b) && f->u.linear_drag.b >= 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "b must be finite and >= 0");
            break;
        default:
            snprintf(param, sizeof param, "forces/%zu/type", i);
            return mech_error_set(err, MECH_EINVAL, param, "unknown force type");
        }
    }
    if (!(isfinite(p->t_end) && p->t_end > 0.0))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0");
    if (p->samples < MECH_TRAJECTORY_MIN_SAMPLES || p->samples > MECH_TRAJECTORY_MAX_SAMPLES)
        return mech_error_set(err, MECH_EINVAL, "samples", "samples must be in [%d, %d]",
                              MECH_TRAJECTORY_MIN_SAMPLES, MECH_TRAJECTORY_MAX_SAMPLES);
    if (p->has_stop) {
        if (p->stop_axis < 0 || p->stop_axis > 2)
            return mech_error_set(err, MECH_EINVAL, "stop/coordinate", "axis must be x, y or z");
        if (!isfinite(p->stop_value))
            return mech_error_set(err, MECH_EINVAL, "stop/crosses", "value must be finite");
        if (p->stop_direction != MECH_STOP_EITHER && p->stop_direction != MECH_STOP_INCREASING &&
            p->stop_direction != MECH_STOP_DECREASING)
            return mech_error_set(err, MECH_EINVAL, "stop/direction", "unknown direction");
    }
    return MECH_OK;
}

/* Whether the scene conserves angular momentum about one point: inertial
 * frame (or no fictitious term active), at least one central force, and
 * every active force central about the same point (central gravity centred
 * there, springs anchored there). */
static int angular_momentum_center(const struct traj_ctx *c, struct mech_vec3 *center)
{
    const struct mech_trajectory_problem *p = c->p;
    if ((c->coriolis || c->centrifugal) && mech_vec3_norm(c->w) > 0.0) return 0;
    int have = 0;
    struct mech_vec3 ctr = mech_vec3_make(0, 0, 0);
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        struct mech_vec3 fc;
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            if (mech_vec3_norm(f->u.uniform_gravity.g) > 0.0) return 0;
            continue;
        case MECH_FORCE_LINEAR_DRAG:
            if (f->u.linear_drag.b > 0.0) return 0;
            continue;
        case MECH_FORCE_SPRING:
            if (f->u.spring.k == 0.0) continue;
            fc = f->u.spring.anchor;
            break;
        case MECH_FORCE_CENTRAL_GRAVITY:
            fc = f->u.central_gravity.center;
            break;
        default:
            return 0;
        }
        if (have && (fc.x != ctr.x || fc.y != ctr.y || fc.z != ctr.z)) return 0;
        ctr = fc;
        have = 1;
    }
    *center = ctr;
    return have;
}

static void ctx_init(struct traj_ctx *c, const struct mech_trajectory_problem *p, double fixed_dt,
                     struct mech_error *err)
{
    memset(c, 0, sizeof *c);
    c->p = p;
    c->err = err;
    c->noninertial = p->frame.type != MECH_FRAME_INERTIAL;
    c->w = mech_frame_omega(&p->frame);
    c->coriolis = c->noninertial && (p->fictitious & MECH_FICTITIOUS_CORIOLIS);
    c->centrifugal = c->noninertial && (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    c->fixed_dt = fixed_dt;
    c->track_l = angular_momentum_center(c, &c->lcenter);
    c->r_last = p->position;
}

static int scene_has_drag(const struct mech_trajectory_problem *p)
{
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LINEAR_DRAG && p->forces[i].u.linear_drag.b > 0.0)
            return 1;
    return 0;
}

/* Buffers of one run: samples (t, y) and the stop state. */
struct traj_run {
    double *sample_t, *sample_y; /* samples, samples * 6 */
    double y_stop[6];
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
    const int velocity_free = !dissipative && !(c->coriolis && mech_vec3_norm(c->w) > 0.0);
    struct mech_ode_system sys = {6, traj_rhs, traj_accel,
                                  velocity_free ? MECH_ODE_VELOCITY_FREE : 0u, c,
                                  dissipative ? NULL : traj_lorentz};
    double y0[6] = {p->position.x, p->position.y, p->position.z,
                    p->velocity.x, p->velocity.y, p->velocity.z};
    struct mech_ode_problem op = {
        .sys = &sys,
        .method = method,
        .opt = opt,
        .t0 = 0.0,
        .t_end = p->t_end,
        .y0 = y0,
        .n_samples = p->samples,
        .sample_t = run->sample_t,
        .sample_y = run->sample_y,
        .event = p->has_stop ? traj_event : NULL,
        .event_direction = (int)p->stop_direction,
        .event_params = (void *)p,
        .observe = traj_observe,
        .observe_params = c,
        .y_stop = run->y_stop,
    };
    memset(&run->out, 0, sizeof run->out);
    enum mech_status st = mech_ode_solve(&op, budget, &run->out, err);
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
    run->sample_t = run->sample_y = NULL;
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

/* Errors of run against the reference at every sample and the stop point. */
static enum mech_status reference_report(const struct mech_trajectory_problem *p,
                                         const struct traj_run *run,
                                         struct mech_trajectory_reference_report *rep,
                                         struct mech_error *err)
{
    struct mech_trajectory_reference ref;
    memset(rep, 0, sizeof *rep);
    rep->name = "";
    if (mech_trajectory_reference_find(p, &ref) == MECH_REFERENCE_NONE) return MECH_OK;
    double rmax = 0.0, vmax = 0.0;
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
        rmax = fmax(rmax, mech_vec3_norm(rr));
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
    enum mech_status st = check_problem(p, err);
    if (st != MECH_OK) return st;
    const struct mech_integrator *method = mech_ode_method_find(p->method);
    if (!method)
        return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method \"%s\"",
                              p->method ? p->method : "(null)");
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "no compute budget given");
    const struct mech_ode_method_info mi = mech_ode_method_describe(method);

    struct traj_ctx c;
    ctx_init(&c, p, mi.adaptive ? 0.0 : p->opt.dt, err);
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
    }
    res->n_terms = p->n_forces + 2;
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
    res->method = mi.name;
    res->stats = run.out.stats;
    res->total_steps = run.out.stats.steps;

    struct mech_trajectory_invariant *inv = &res->invariants[0];
    memset(res->invariants, 0, sizeof res->invariants);
    inv->name = c.noninertial ? "jacobi_integral" : "energy";
    inv->conserved = !dissipative;
    inv->initial = c.inv0;
    inv->final = c.inv_last;
    double denom = c.inv0 != 0.0 ? fabs(c.inv0) : c.scale_max;
    inv->max_relative_drift = denom > 0.0 ? c.drift_max / denom : 0.0;
    res->n_invariants = 1;
    if (c.track_l) {
        struct mech_trajectory_invariant *l = &res->invariants[1];
        l->name = "angular_momentum";
        l->conserved = 1;
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

    st = reference_report(p, &run, &res->reference, err);
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

/* ---- choosing by accuracy ----------------------------------------------------
 * Presets (measured in tests/core/test_trajectory_diagnostics.c against the
 * exact references, e.g. Kepler e = 0.5 over 10 orbits, the harmonic
 * oscillator, drag): each keeps its `promise` there. */
static const struct mech_accuracy_preset traj_presets[MECH_ACCURACY_COUNT] = {
    {"draft", 1e-3, "radau15", "rkf45", 1e-5, 1e-5,
     "cheap: few steps; for plots and previews (1e-3 relative)"},
    {"balanced", 1e-8, "radau15", "rk8pd", 1e-8, 1e-12,
     "the default: better than 1e-8 relative at moderate cost"},
    {"precise", 1e-10, "radau15", "rk8pd", 1e-9, 1e-13,
     "for grading and reference answers: 1e-10 relative"},
    {"machine", 1e-11, "radau15", "rk8pd", 1e-10, 1e-15,
     "the methods at their round-off floor (radau15 eps 1e-9, rk8pd rtol 1e-15); the "
     "remaining error is round-off accumulated over the run (1e-11 relative or better on "
     "10 orbits of e = 0.9, ~1e-14 on easy scenes)"},
};

const struct mech_accuracy_preset *mech_accuracy_preset_at(enum mech_accuracy a)
{
    return (int)a >= 0 && a < MECH_ACCURACY_COUNT ? &traj_presets[a] : NULL;
}

enum mech_status mech_trajectory_choose(const struct mech_trajectory_problem *p, double target,
                                        struct mech_trajectory_choice *out,
                                        struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    if (!(target >= 1e-15 && target <= 0.1))
        return mech_error_set(err, MECH_EINVAL, "integrator/target_error",
                              "target_error must be in [1e-15, 0.1], got %.17g", target);
    memset(out, 0, sizeof *out);
    struct traj_ctx c;
    ctx_init(&c, p, 0.0, NULL);
    const int dissipative = scene_has_drag(p);
    const int velocity_free = !dissipative && !(c.coriolis && mech_vec3_norm(c.w) > 0.0);

    /* The loosest preset whose promise meets the target; below a preset's
     * promise its rtol scales with the target (radau15's eps is floored at
     * 1e-10 by the method itself: round-off). */
    const struct mech_accuracy_preset *pr = &traj_presets[MECH_ACCURACY_DRAFT];
    for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
        pr = &traj_presets[a];
        if (pr->promise <= target) break;
    }
    /* Scale of the motion: positions max(|r0|, |v0| T, |a0| T^2/2), velocities
     * max(|v0|, |a0| T), T = min(t_end, sqrt(|r0| / |a0|)); atol = rtol * the smaller. */
    double a0[3] = {0, 0, 0}, q0[3] = {p->position.x, p->position.y, p->position.z},
           v0[3] = {p->velocity.x, p->velocity.y, p->velocity.z};
    struct mech_vec3 acc = mech_vec3_make(0, 0, 0);
    if (traj_accel(0.0, q0, v0, a0, &c) == MECH_OK) acc = mech_vec3_make(a0[0], a0[1], a0[2]);
    const double an = mech_vec3_norm(acc), vn = mech_vec3_norm(p->velocity);
    const double rn = mech_vec3_norm(p->position);
    /* T: t_end, or the dynamical time sqrt(|r0| / |a0|) when shorter (an
     * orbit or an oscillation does not keep accelerating one way) */
    double T = p->t_end;
    if (an > 0.0 && rn > 0.0) T = fmin(T, sqrt(rn / an));
    double L = fmax(rn, fmax(vn * T, 0.5 * an * T * T));
    double V = fmax(vn, an * T);
    double S = L > 0.0 && V > 0.0 ? fmin(L, V) : fmax(L, V);
    if (!(S > 0.0 && isfinite(S))) S = 1.0;

    /* The global error of an adaptive run grows about linearly with the
     * number of dynamical times it spans (the phase error of orbits and
     * oscillations). The presets were calibrated on 10 orbits, 20 pi ~ 63
     * dynamical times, so a longer run gets a proportionally tighter rtol
     * (measured by bench/bench_workprecision: without this, "draft" missed
     * its 1e-3 over 1000 Kepler orbits). */
    const double calibrated_span = 62.831853071795865; /* 20 pi */
    const double span = T > 0.0 ? p->t_end / T : 1.0;
    const double length_factor = span > calibrated_span ? calibrated_span / span : 1.0;

    const double base = velocity_free ? pr->rtol : pr->rtol_other;
    double rtol = base * fmin(target / pr->promise, 10.0) * length_factor;
    if (rtol < 1e-15) rtol = 1e-15;
    out->method = velocity_free ? pr->method : pr->method_other;
    out->target = target;

    out->opt.rtol = rtol;
    out->opt.atol = rtol * S;
    snprintf(out->reason, sizeof out->reason,
             "%s scene: %s; preset \"%s\" (promise %.0e relative) at rtol %.3g%s%s; atol = rtol x "
             "%.3g (the smaller of the position scale %.3g m and the velocity scale %.3g m/s)",
             velocity_free ? "velocity-free" : "velocity-dependent (drag or Coriolis)",
             velocity_free ? "radau15-class methods reach round-off in few steps"
                           : "rk8pd handles velocity-dependent forces robustly",
             pr->name, pr->promise, rtol,
             target < pr->promise ? " (target below every promise: round-off)" : "",
             length_factor < 1.0 ? " (tightened for a run of many dynamical times)" : "", S, L, V);
    return MECH_OK;
}
