/* trajectory.c — equations of motion of a particle in an inertial, rotating
 * or local Earth frame (notes §1.2 "Rotating frames", §1.3 "Motion near the
 * Earth"), integrated with mech_ode_solve; model-term sizes and the energy /
 * Jacobi integral are gathered by the driver's observer at every sample and
 * every step end.
 */
#include "mech/trajectory.h"

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

    struct traj_ctx c;
    memset(&c, 0, sizeof c);
    c.p = p;
    c.err = err;
    c.noninertial = p->frame.type != MECH_FRAME_INERTIAL;
    c.w = mech_frame_omega(&p->frame);
    c.coriolis = c.noninertial && (p->fictitious & MECH_FICTITIOUS_CORIOLIS);
    c.centrifugal = c.noninertial && (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    c.fixed_dt = mech_ode_method_describe(method).adaptive ? 0.0 : p->opt.dt;

    int velocity_free = !(c.coriolis && mech_vec3_norm(c.w) > 0.0);
    int dissipative = 0;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LINEAR_DRAG && p->forces[i].u.linear_drag.b > 0.0) {
            velocity_free = 0;
            dissipative = 1;
        }

    struct mech_ode_system sys = {6, traj_rhs, traj_accel,
                                  velocity_free ? MECH_ODE_VELOCITY_FREE : 0u, &c};
    double y0[6] = {p->position.x, p->position.y, p->position.z,
                    p->velocity.x, p->velocity.y, p->velocity.z};
    double y_stop[6];
    double *sample_y = malloc(p->samples * 6 * sizeof *sample_y);
    if (!sample_y) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");

    struct mech_ode_problem op = {
        .sys = &sys,
        .method = method,
        .opt = p->opt,
        .t0 = 0.0,
        .t_end = p->t_end,
        .y0 = y0,
        .n_samples = p->samples,
        .sample_t = res->t,
        .sample_y = sample_y,
        .event = p->has_stop ? traj_event : NULL,
        .event_direction = (int)p->stop_direction,
        .event_params = (void *)p,
        .observe = traj_observe,
        .observe_params = &c,
        .y_stop = y_stop,
    };
    struct mech_ode_result or;
    memset(&or, 0, sizeof or);
    st = mech_ode_solve(&op, budget, &or, err);
    /* Samples written so far are returned on every path. */
    const size_t ns = or.n_samples;
    res->n_samples = ns;
    for (size_t i = 0; i < ns; i++) {
        const double *y = sample_y + 6 * i;
        if (res->position) res->position[i] = mech_vec3_make(y[0], y[1], y[2]);
        if (res->velocity) res->velocity[i] = mech_vec3_make(y[3], y[4], y[5]);
    }
    free(sample_y);
    if (st != MECH_OK) return st;

    res->stopped = or.stopped;
    if (or.stopped) {
        res->t_stop = or.t_stop;
        res->stop_position = mech_vec3_make(y_stop[0], y_stop[1], y_stop[2]);
        res->stop_velocity = mech_vec3_make(y_stop[3], y_stop[4], y_stop[5]);
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
    res->method = mech_ode_method_describe(method).name;
    res->stats = or.stats;
    res->invariant.name = c.noninertial ? "jacobi_integral" : "energy";
    res->invariant.conserved = !dissipative;
    res->invariant.initial = c.inv0;
    res->invariant.final = c.inv_last;
    double denom = c.inv0 != 0.0 ? fabs(c.inv0) : c.scale_max;
    res->invariant.max_relative_drift = denom > 0.0 ? c.drift_max / denom : 0.0;
    return MECH_OK;
}
