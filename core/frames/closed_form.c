/* closed_form.c — trajectories evaluated from their exact solution
 * (mech/frames/closed_form.h): the samples, the stop event located on the closed
 * form to round-off, the invariants and the model terms at the samples, and
 * the evidence (invariant drift, Kepler residual). Nothing is integrated.
 */
#include "mech/frames/closed_form.h"
#include "mech/base/constants.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "mech/frames/reference.h"

struct cf_ctx {
    const struct mech_trajectory_problem *p;
    struct mech_trajectory_reference ref;
    int kepler;
    struct mech_vec3 w0, wdot, A;
    int noninertial, coriolis, centrifugal, euler, translational;
    double kepler_residual; /* max over the evaluations */
    /* "relativistic_uniform_fields": the last state's proper velocity and
     * gamma - 1 (the energy needs it without cancellation) */
    int relativistic;
    struct mech_vec3 last_u;
    double last_gm1, last_gamma, rel_max, pn1_max, rel_ratio, pn1_ratio;
    int evaluations;
    struct mech_error *err;
};

/* The state at t. */
static enum mech_status cf_state(struct cf_ctx *c, double t, struct mech_vec3 *r,
                                 struct mech_vec3 *v)
{
    c->evaluations++;
    if (c->kepler) {
        struct mech_vec3 rr, vv;
        double res;
        enum mech_status st = mech_kepler_propagate_residual(
            c->ref.gm, mech_vec3_sub(c->ref.r0, c->ref.center), c->ref.v0, t, &rr, &vv, &res,
            c->err);
        if (st != MECH_OK) return st;
        c->kepler_residual = fmax(c->kepler_residual, res);
        *r = mech_vec3_add(rr, c->ref.center);
        *v = vv;
        return MECH_OK;
    }
    if (c->relativistic) {
        struct mech_charged_motion_state cs;
        enum mech_status st = mech_charged_motion_at_lab_time(&c->ref.charged, t, &cs, c->err);
        if (st != MECH_OK) return st;
        *r = cs.r;
        *v = cs.v;
        c->last_u = cs.u;
        c->last_gm1 = cs.gamma_minus_1;
        c->last_gamma = cs.gamma;
        return MECH_OK;
    }
    return mech_trajectory_reference_eval(&c->ref, t, r, v, NULL, c->err);
}

static double axis_of(struct mech_vec3 a, int axis)
{
    return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}

/* ---- the stop event ------------------------------------------------------- */

/* f(t): the event function (which = 0) or the velocity component along the
 * stop axis (which = 1). */
static enum mech_status cf_fn(struct cf_ctx *c, int which, double t, double *f)
{
    struct mech_vec3 r, v;
    enum mech_status st = cf_state(c, t, &r, &v);
    if (st != MECH_OK) return st;
    *f = which ? axis_of(v, c->p->stop_axis) : axis_of(r, c->p->stop_axis) - c->p->stop_value;
    return MECH_OK;
}

/* A root of f on [a, b] with fa, fb of strictly opposite signs: regula falsi
 * with the Illinois modification, and a bisection whenever a step fails to
 * halve the bracket, until the bracket is a few ulps wide. *root is the end
 * (or interior point) with the smallest |f|. */
static enum mech_status cf_root(struct cf_ctx *c, int which, double a, double fa, double b,
                                double fb, double *root)
{
    double ga = fa, gb = fb; /* the Illinois-weighted values */
    int side = 0;
    for (int it = 0; it < 400; it++) {
        const double width = b - a;
        if (width <= 2.0 * DBL_EPSILON * fmax(fabs(a), fabs(b)) + DBL_MIN) break;
        double x = (a * gb - b * ga) / (gb - ga);
        if (!(x > a && x < b) || (it % 3 == 2)) x = a + 0.5 * width;
        if (!(x > a && x < b)) break;
        double fx;
        enum mech_status st = cf_fn(c, which, x, &fx);
        if (st != MECH_OK) return st;
        if (fx == 0.0) {
            *root = x;
            return MECH_OK;
        }
        if ((fx > 0.0) == (fb > 0.0)) {
            b = x;
            fb = gb = fx;
            if (side == -1) ga *= 0.5;
            side = -1;
        } else {
            a = x;
            fa = ga = fx;
            if (side == 1) gb *= 0.5;
            side = 1;
        }
    }
    *root = fabs(fa) <= fabs(fb) ? a : b;
    return MECH_OK;
}

/* The integrator's notion of a crossing (core/ode/ode.c). */
static int cf_crossed(double g0, double g1, enum mech_stop_direction dir)
{
    const int down = g0 > 0.0 && g1 <= 0.0, up = g0 < 0.0 && g1 >= 0.0;
    if (dir == MECH_STOP_DECREASING) return down;
    if (dir == MECH_STOP_INCREASING) return up;
    return down || up;
}

/* A monotonic piece [a, b]: the crossing in it, if any. */
static enum mech_status cf_piece(struct cf_ctx *c, double a, double ca, double b, double cb,
                                 int *found, double *t_stop)
{
    if (!cf_crossed(ca, cb, c->p->stop_direction)) return MECH_OK;
    *found = 1;
    if (cb == 0.0) {
        *t_stop = b;
        return MECH_OK;
    }
    return cf_root(c, 0, a, ca, b, cb, t_stop);
}

/* Scan the grid t[0..n-1] for the first crossing: each grid interval is split
 * at a zero of the velocity component (there is at most one per interval by
 * construction of the grid), so the coordinate is monotonic on each piece. */
static enum mech_status cf_scan(struct cf_ctx *c, const double *grid, size_t n, int *found,
                                double *t_stop)
{
    double ta = grid[0], ca, wa;
    enum mech_status st;
    *found = 0;
    if ((st = cf_fn(c, 0, ta, &ca)) != MECH_OK || (st = cf_fn(c, 1, ta, &wa)) != MECH_OK)
        return st;
    for (size_t k = 1; k < n; k++) {
        const double tb = grid[k];
        if (!(tb > ta)) continue;
        double cb, wb;
        if ((st = cf_fn(c, 0, tb, &cb)) != MECH_OK || (st = cf_fn(c, 1, tb, &wb)) != MECH_OK)
            return st;
        if ((wa > 0.0 && wb < 0.0) || (wa < 0.0 && wb > 0.0)) {
            double tm, cm;
            if ((st = cf_root(c, 1, ta, wa, tb, wb, &tm)) != MECH_OK) return st;
            if ((st = cf_fn(c, 0, tm, &cm)) != MECH_OK) return st;
            if ((st = cf_piece(c, ta, ca, tm, cm, found, t_stop)) != MECH_OK || *found) return st;
            /* the integrator compares with the value at the previous step end; a
             * piece that ends exactly on the value starts the next one at 0 */
            ta = tm;
            ca = cm;
        }
        if ((st = cf_piece(c, ta, ca, tb, cb, found, t_stop)) != MECH_OK || *found) return st;
        ta = tb;
        ca = cb;
        wa = wb;
    }
    return MECH_OK;
}

/* Time from r0, v0 (relative to the centre) to a radial orbit's fall into the
 * centre (INFINITY if it never falls or the orbit is not radial). The
 * universal-variable r(s) touches 0 (a double root) where, with y = sqrt(|beta|) s,
 *   beta > 0: r = a - A cos(y + phi), A = a = gm/beta, tan phi = (sigma0/sqrt(beta))/(a - r0);
 *   beta < 0: r = -a + A cosh(y + phi), A = a = gm/|beta|, tanh phi = (sigma0/sqrt|beta|)/(a + r0);
 *   beta = 0: r = r0 + sigma0 s + gm s^2/2, double root at s = -sigma0/gm;
 * the time is t(s) = r0 G1 + sigma0 G2 + gm G3 there. */
static double kepler_collision_time(double gm, struct mech_vec3 r0v, struct mech_vec3 v0v)
{
    const double r0 = mech_vec3_norm(r0v), v = mech_vec3_norm(v0v);
    const double h = mech_vec3_norm(mech_vec3_cross(r0v, v0v));
    if (h > 1e-14 * r0 * v) return INFINITY;
    const double sigma0 = mech_vec3_dot(r0v, v0v);
    const double beta = 2.0 * gm / r0 - v * v;
    if (beta > 0.0) {
        const double sb = sqrt(beta), a = gm / beta;
        const double phi = atan2(sigma0 / sb, a - r0);
        const double y = phi < 0.0 ? -phi : 2.0 * MECH_PI - phi;
        return r0 * sin(y) / sb + sigma0 * (1.0 - cos(y)) / beta +
               gm * (y - sin(y)) / (beta * sb);
    }
    if (sigma0 >= 0.0) return INFINITY; /* unbound and moving out: never */
    if (beta < 0.0) {
        const double al = -beta, sa = sqrt(al), a = gm / al;
        const double y = -atanh((sigma0 / sa) / (a + r0));
        return r0 * sinh(y) / sa + sigma0 * (cosh(y) - 1.0) / al +
               gm * (sinh(y) - y) / (al * sa);
    }
    const double s = -sigma0 / gm;
    return r0 * s + 0.5 * sigma0 * s * s + gm * s * s * s / 6.0;
}

#define CF_GRID_PER_PERIOD 16
#define CF_GRID_MAX (CF_GRID_PER_PERIOD + 3)

/* The scan grid: pieces on which the velocity component along any axis has
 * at most one zero. Periodic motions: 16 per period (uniform in the
 * eccentric anomaly y = sqrt(beta) s for Kepler ellipses, where every
 * coordinate is a + b cos y + c sin y; uniform in t for the oscillator), over
 * one period and a piece; the rest: the velocity component has at most one
 * zero in all (Kepler hyperbola and parabola: x'(s) = A sinh + B cosh or
 * linear; gravity with drag: v monotonic), so {0, t_hi}. */
static size_t cf_grid(const struct cf_ctx *c, double t_hi, double *grid)
{
    size_t n = 0;
    int periodic = 0; /* the grid covers more than a period before t_hi: stop there */
    grid[n++] = 0.0;
    if (c->kepler) {
        const struct mech_vec3 r0v = mech_vec3_sub(c->ref.r0, c->ref.center);
        const double r0 = mech_vec3_norm(r0v), gm = c->ref.gm;
        const double sigma0 = mech_vec3_dot(r0v, c->ref.v0);
        const double beta = 2.0 * gm / r0 - mech_vec3_dot(c->ref.v0, c->ref.v0);
        if (beta > 0.0) {
            const double sb = sqrt(beta);
            for (int k = 1; k <= CF_GRID_PER_PERIOD + 1; k++) {
                const double y = 2.0 * MECH_PI * k / CF_GRID_PER_PERIOD;
                const double t = r0 * sin(y) / sb + sigma0 * (1.0 - cos(y)) / beta +
                                 gm * (y - sin(y)) / (beta * sb);
                if (t >= t_hi) break;
                if (t > grid[n - 1]) grid[n++] = t;
                periodic = k == CF_GRID_PER_PERIOD + 1;
            }
        }
    } else if (!strcmp(c->ref.name, "harmonic_oscillator")) {
        const double T = 2.0 * MECH_PI / c->ref.omega;
        for (int k = 1; k <= CF_GRID_PER_PERIOD + 1; k++) {
            const double t = T * k / CF_GRID_PER_PERIOD;
            if (t >= t_hi) break;
            grid[n++] = t;
            periodic = k == CF_GRID_PER_PERIOD + 1;
        }
    }
    if (!periodic) grid[n++] = t_hi;
    return n;
}

/* ---- invariants and terms -------------------------------------------------- */

static struct mech_vec3 cf_omega(const struct cf_ctx *c, double t)
{
    return mech_vec3_add(c->w0, mech_vec3_scale(c->wdot, t));
}

/* Energy (or Jacobi integral) at (t, r, v), and the sum of its parts' sizes;
 * the same expression as the integrator's (core/frames/trajectory_observe.c). */
static void cf_energy(const struct cf_ctx *c, double t, struct mech_vec3 r, struct mech_vec3 v,
                      double *value, double *scale)
{
    const struct mech_trajectory_problem *p = c->p;
    const double m = p->mass;
    double ke = c->relativistic ? m * MECH_C * MECH_C * c->last_gm1 /* (gamma - 1) m c^2 */
                                : 0.5 * m * mech_vec3_dot(v, v);
    double sum = ke, mag = fabs(ke);
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        double u = 0.0;
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY: u = -m * mech_vec3_dot(f->u.uniform_gravity.g, r); break;
        case MECH_FORCE_CENTRAL_GRAVITY:
            u = -m * f->u.central_gravity.gm /
                mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
            break;
        case MECH_FORCE_SPRING: {
            const double ext =
                mech_vec3_norm(mech_vec3_sub(r, f->u.spring.anchor)) - f->u.spring.rest_length;
            u = 0.5 * f->u.spring.k * ext * ext;
            break;
        }
        case MECH_FORCE_LORENTZ: u = -p->charge * mech_vec3_dot(f->u.lorentz.E, r); break;
        case MECH_FORCE_LINEAR_DRAG:
        case MECH_FORCE_THIRD_BODY_TIDE: break; /* no potential / never a closed form */
        }
        sum += u;
        mag += fabs(u);
    }
    if (c->centrifugal) {
        const struct mech_vec3 wr = mech_vec3_cross(cf_omega(c, t), r);
        const double u = -0.5 * m * mech_vec3_dot(wr, wr);
        sum += u;
        mag += fabs(u);
    }
    if (c->translational) {
        const double u = m * mech_vec3_dot(c->A, r);
        sum += u;
        mag += fabs(u);
    }
    *value = sum;
    *scale = mag;
}

static const char *cf_force_name(enum mech_force_type t)
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

/* |acceleration| of each force and fictitious term at (t, r, v). */
/* Records each term's |a| at (t, r, v); returns the sum of the forces' |a|. */
static double cf_terms(const struct cf_ctx *c, double t, struct mech_vec3 r, struct mech_vec3 v,
                       struct mech_trajectory_result *res)
{
    double asum = 0.0;
    const struct mech_trajectory_problem *p = c->p;
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        double a = 0.0;
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY: a = mech_vec3_norm(f->u.uniform_gravity.g); break;
        case MECH_FORCE_CENTRAL_GRAVITY: {
            const double d = mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
            a = f->u.central_gravity.gm / (d * d);
            break;
        }
        case MECH_FORCE_SPRING:
            a = f->u.spring.k / p->mass *
                fabs(mech_vec3_norm(mech_vec3_sub(r, f->u.spring.anchor)) - f->u.spring.rest_length);
            break;
        case MECH_FORCE_LINEAR_DRAG: a = f->u.linear_drag.b / p->mass * mech_vec3_norm(v); break;
        case MECH_FORCE_LORENTZ:
            a = fabs(p->charge) / p->mass *
                mech_vec3_norm(mech_vec3_add(f->u.lorentz.E, mech_vec3_cross(v, f->u.lorentz.B)));
            break;
        case MECH_FORCE_THIRD_BODY_TIDE: break;
        }
        res->terms[i].max_acceleration = fmax(res->terms[i].max_acceleration, a);
        asum += a;
    }
    if (c->noninertial) {
        const size_t n = p->n_forces;
        const struct mech_vec3 w = cf_omega(c, t);
        const double ac[4] = {
            2.0 * mech_vec3_norm(mech_vec3_cross(w, v)),
            mech_vec3_norm(mech_vec3_cross(w, mech_vec3_cross(w, r))),
            mech_vec3_norm(mech_vec3_cross(c->wdot, r)),
            mech_vec3_norm(c->A),
        };
        for (int k = 0; k < 4; k++)
            res->terms[n + k].max_acceleration = fmax(res->terms[n + k].max_acceleration, ac[k]);
    }
    return asum;
}

/* Whether angular momentum about one point is conserved: the integrator's
 * rule (mech_trajectory_angular_center) on the closed form's frame terms. */
static int cf_angular_center(const struct cf_ctx *c, struct mech_vec3 *center)
{
    const int rot = (c->coriolis || c->centrifugal || c->euler) &&
                    (mech_vec3_norm(c->w0) > 0.0 || mech_vec3_norm(c->wdot) > 0.0);
    const int tr = c->translational && mech_vec3_norm(c->A) > 0.0;
    return mech_trajectory_angular_center(c->p, rot, tr, center);
}

/* Running invariants over the evaluated states. */
struct cf_inv {
    int have0;
    double e0, e_last, e_drift, e_scale;
    int track_l;
    struct mech_vec3 lc, l0, l_last;
    double l_drift, l_scale;
};

static void cf_observe(struct cf_ctx *c, struct cf_inv *iv, double t, struct mech_vec3 r,
                       struct mech_vec3 v, struct mech_trajectory_result *res)
{
    double e, scale;
    cf_energy(c, t, r, v, &e, &scale);
    struct mech_vec3 l = mech_vec3_make(0, 0, 0);
    if (iv->track_l) l = mech_vec3_scale(mech_vec3_cross(mech_vec3_sub(r, iv->lc), v), c->p->mass);
    if (!iv->have0) {
        iv->have0 = 1;
        iv->e0 = e;
        iv->l0 = l;
    }
    iv->e_last = e;
    iv->e_drift = fmax(iv->e_drift, fabs(e - iv->e0));
    iv->e_scale = fmax(iv->e_scale, scale);
    if (iv->track_l) {
        iv->l_last = l;
        iv->l_drift = fmax(iv->l_drift, mech_vec3_norm(mech_vec3_sub(l, iv->l0)));
        iv->l_scale = fmax(iv->l_scale, mech_vec3_norm(l));
    }
    res->max_radius = fmax(res->max_radius, mech_vec3_norm(r));
    res->max_speed = fmax(res->max_speed, mech_vec3_norm(v));
    const double asum = cf_terms(c, t, r, v, res);
    if (!c->relativistic && !c->noninertial) {
        /* the relativistic corrections this Newtonian answer leaves out, sized
         * at the samples: special relativity bounded by sum |a| ((gamma - 1) +
         * beta^2)/gamma (all of it at or beyond c), the 1PN term of the one
         * central mass */
        const double beta = mech_vec3_norm(v) / MECH_C;
        double srel = asum;
        if (beta < 1.0) {
            const double g = 1.0 / sqrt((1.0 - beta) * (1.0 + beta));
            srel = asum * (beta * beta * g * g / (g + 1.0) + beta * beta) / g;
        }
        c->rel_max = fmax(c->rel_max, srel);
        if (asum > 0.0) c->rel_ratio = fmax(c->rel_ratio, srel / asum);
        if (c->kepler) {
            const struct mech_vec3 d = mech_vec3_sub(r, c->ref.center);
            const double pa = mech_vec3_norm(mech_schwarzschild_1pn_accel(c->ref.gm, d, v));
            const double dn = mech_vec3_norm(d);
            c->pn1_max = fmax(c->pn1_max, pa);
            c->pn1_ratio = fmax(c->pn1_ratio, pa / (c->ref.gm / (dn * dn)));
        }
    }
    if (c->relativistic) {
        /* the special-relativistic term's size: dv/dt - A with A = eps + v x Omega,
         * dv/dt = (A - (A.v) v/c^2)/gamma */
        const struct mech_vec3 A =
            mech_vec3_add(c->ref.charged.eps, mech_vec3_cross(v, c->ref.charged.omega));
        const double g = c->last_gamma;
        const struct mech_vec3 d = mech_vec3_add(
            mech_vec3_scale(A, -c->last_gm1 / g),
            mech_vec3_scale(v, -mech_vec3_dot(A, v) / (g * MECH_C * MECH_C)));
        c->rel_max = fmax(c->rel_max, mech_vec3_norm(d));
        const double an = mech_vec3_norm(A);
        if (an > 0.0) c->rel_ratio = fmax(c->rel_ratio, mech_vec3_norm(d) / an);
    }
}

/* ---- the operation ----------------------------------------------------------- */

int mech_trajectory_has_closed_form(const struct mech_trajectory_problem *p)
{
    struct mech_trajectory_reference ref;
    /* the relativistic closed form has no stop-event scan (no monotonic grid) */
    return p && !(p->relativity && p->has_stop) &&
           mech_trajectory_reference_find(p, &ref) == MECH_REFERENCE_EXACT && !ref.rotated &&
           !ref.evidence_only;
}

enum mech_status mech_trajectory_closed_form(const struct mech_trajectory_problem *p,
                                             struct mech_trajectory_result *res,
                                             struct mech_error *err)
{
    return mech_trajectory_closed_form_ex(p, res, NULL, NULL, err);
}

enum mech_status mech_trajectory_closed_form_ex(const struct mech_trajectory_problem *p,
                                                struct mech_trajectory_result *res,
                                                struct mech_closed_form_evidence *evidence,
                                                const struct mech_budget *budget,
                                                struct mech_error *err)
{
    if (!p || !res) return mech_error_set(err, MECH_EINVAL, NULL, "NULL problem or result");
    res->n_samples = 0;
    res->stopped = 0;
    res->t_stop = NAN;
    enum mech_status st = mech_trajectory_check(p, err);
    if (st != MECH_OK) return st;
    struct cf_ctx c;
    memset(&c, 0, sizeof c);
    c.p = p;
    c.err = err;
    if (mech_trajectory_reference_find(p, &c.ref) != MECH_REFERENCE_EXACT || c.ref.rotated ||
        c.ref.evidence_only)
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "the scene has no closed form (only Kepler, the harmonic "
                              "oscillator, uniform gravity with or without linear drag and the "
                              "free particle have one): integrate it");
    c.kepler = !strcmp(c.ref.name, "kepler");
    c.relativistic = !strcmp(c.ref.name, "relativistic_uniform_fields");
    if (c.relativistic && p->has_stop)
        return mech_error_set(err, MECH_EINVAL, "stop",
                              "the relativistic closed form has no stop event: integrate it");
    c.noninertial = p->frame.type != MECH_FRAME_INERTIAL;
    c.w0 = mech_frame_omega(&p->frame);
    if (p->frame.type == MECH_FRAME_ROTATING) {
        c.wdot = p->frame.omega_dot;
        c.A = p->frame.acceleration;
    }
    c.coriolis = c.noninertial && (p->fictitious & MECH_FICTITIOUS_CORIOLIS);
    c.centrifugal = c.noninertial && (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    c.euler = c.noninertial && (p->fictitious & MECH_FICTITIOUS_EULER);
    c.translational = c.noninertial && (p->fictitious & MECH_FICTITIOUS_TRANSLATIONAL);

    /* A radial orbit falls into the centre in finite time. */
    double t_hi = p->t_end;
    double t_collide = INFINITY;
    if (c.kepler) {
        t_collide = kepler_collision_time(c.ref.gm, mech_vec3_sub(c.ref.r0, c.ref.center),
                                          c.ref.v0);
        /* the scan stops just short of the centre, where the solution is singular */
        if (t_collide <= t_hi) t_hi = t_collide * (1.0 - 1e-9);
    }

    /* The stop event, before any sample is written. */
    double t_stop = INFINITY;
    if (p->has_stop) {
        double grid[CF_GRID_MAX];
        const size_t ng = cf_grid(&c, t_hi, grid);
        int found = 0;
        st = cf_scan(&c, grid, ng, &found, &t_stop);
        if (st != MECH_OK && !(isfinite(t_collide) && t_collide <= p->t_end)) return st;
        if (st != MECH_OK || !found) t_stop = INFINITY;
        if (err && st != MECH_OK) mech_error_clear(err); /* replaced by the message below */
    }
    if (t_collide <= p->t_end && !(t_stop < t_collide))
        return mech_error_set(err, MECH_ENUMERIC, "particle/velocity",
                              "the radial orbit reaches the centre of the central_gravity force at "
                              "t = %.9g s, before t_end = %.9g s (r0 x v0 = 0): stop it earlier "
                              "or give it a sideways velocity",
                              t_collide, p->t_end);

    /* Terms and invariants. */
    memset(res->terms, 0, sizeof res->terms);
    res->n_terms = p->n_forces + MECH_TRAJECTORY_N_FICTITIOUS;
    for (size_t i = 0; i < p->n_forces; i++) {
        res->terms[i].term = cf_force_name(p->forces[i].type);
        res->terms[i].force_index = (int)i;
        res->terms[i].included = 1;
    }
    const size_t nf = p->n_forces;
    const char *fict[4] = {"coriolis", "centrifugal", "euler", "translational"};
    const int incl[4] = {c.coriolis, c.centrifugal, c.euler, c.translational};
    for (int k = 0; k < 4; k++) {
        res->terms[nf + k].term = fict[k];
        res->terms[nf + k].force_index = -1;
        res->terms[nf + k].included = incl[k];
    }
    res->max_radius = 0.0;
    res->max_speed = 0.0;
    struct cf_inv iv;
    memset(&iv, 0, sizeof iv);
    iv.track_l = cf_angular_center(&c, &iv.lc);

    /* The samples: t_i = t_end (i / (n - 1)), as the integrator places them. */
    const size_t n = p->samples;
    struct mech_budget clock_only;
    if (budget) {
        clock_only = *budget;
        clock_only.max_steps = LONG_MAX; /* deadline and cancel only */
    }
    for (size_t i = 0; i < n; i++) {
        const double ti = p->t_end * ((double)i / (double)(n - 1));
        if (ti > t_stop) break;
        if (budget && (st = mech_budget_check(&clock_only, (long)i, 0, err)) != MECH_OK) {
            if (err) {
                err->progress.t_reached = i > 0 ? p->t_end * ((double)(i - 1) / (double)(n - 1)) : 0.0;
                err->progress.t_target = p->t_end;
            }
            return st;
        }
        struct mech_vec3 r, v;
        if ((st = cf_state(&c, ti, &r, &v)) != MECH_OK) return st;
        if (res->t) res->t[i] = ti;
        if (res->position) res->position[i] = r;
        if (res->velocity) res->velocity[i] = v;
        if (res->proper_velocity && c.relativistic) res->proper_velocity[i] = c.last_u;
        res->n_samples = i + 1;
        cf_observe(&c, &iv, ti, r, v, res);
    }
    if (isfinite(t_stop)) {
        struct mech_vec3 r, v;
        if ((st = cf_state(&c, t_stop, &r, &v)) != MECH_OK) return st;
        res->stopped = 1;
        res->t_stop = t_stop;
        res->stop_position = r;
        res->stop_velocity = v;
        cf_observe(&c, &iv, t_stop, r, v, res);
    }

    const int dissipative = !strcmp(c.ref.name, "uniform_gravity_linear_drag");
    memset(res->invariants, 0, sizeof res->invariants);
    struct mech_trajectory_invariant *inv = &res->invariants[0];
    inv->name = c.noninertial ? "jacobi_integral" : "energy";
    inv->conserved = !dissipative;
    inv->note = dissipative ? "not conserved: linear drag dissipates it"
                : c.noninertial
                    ? "conserved: 1/2 m v^2 + U - 1/2 m |w x r|^2 (if centrifugal modelled) + "
                      "m A.r (if translational modelled); evaluated on the closed form"
                    : "conserved: 1/2 m v^2 + U; evaluated on the closed form at the samples";
    inv->initial = iv.e0;
    inv->final = iv.e_last;
    const double denom = iv.e0 != 0.0 ? fabs(iv.e0) : iv.e_scale;
    inv->max_relative_drift = denom > 0.0 ? iv.e_drift / denom : 0.0;
    res->n_invariants = 1;
    double drift = inv->conserved ? inv->max_relative_drift : 0.0;
    if (iv.track_l) {
        struct mech_trajectory_invariant *l = &res->invariants[1];
        l->name = "angular_momentum";
        l->conserved = 1;
        l->note = "conserved: every force is central about one point";
        l->is_vector = 1;
        l->initial_vector = iv.l0;
        l->final_vector = iv.l_last;
        l->initial = mech_vec3_norm(iv.l0);
        l->final = mech_vec3_norm(iv.l_last);
        const double ld = l->initial > 0.0 ? l->initial : iv.l_scale;
        l->max_relative_drift = ld > 0.0 ? iv.l_drift / ld : 0.0;
        res->n_invariants = 2;
        drift = fmax(drift, l->max_relative_drift);
    }
    res->invariant = res->invariants[0];

    res->relativistic = c.relativistic;
    res->relativity_terms[0] =
        (struct mech_trajectory_term){"relativistic", -1, c.relativistic, c.rel_max};
    res->relativity_terms[1] =
        (struct mech_trajectory_term){"schwarzschild_1pn", -1, 0, c.pn1_max};
    res->relativity_ratio[0] = c.rel_ratio;
    res->relativity_ratio[1] = c.pn1_ratio;
    if (c.relativistic) {
        inv->note = "conserved: (gamma - 1) m c^2 + U (U includes -q E.r); evaluated on the "
                    "closed form at the samples";
        res->invariant = res->invariants[0];
    }
    res->dimensions = 3;
    res->plane_normal = mech_vec3_make(0, 0, 0);
    res->method = "closed_form";
    memset(&res->stats, 0, sizeof res->stats);
    res->total_steps = 0;
    memset(&res->reference, 0, sizeof res->reference);
    res->reference.kind = MECH_REFERENCE_EXACT;
    res->reference.name = c.ref.name;
    memset(&res->error_estimate, 0, sizeof res->error_estimate);

    if (evidence) {
        evidence->solution = c.ref.name;
        evidence->max_invariant_drift = drift;
        evidence->max_kepler_residual = c.kepler_residual;
        evidence->error_bound = fmax(fmax(drift, c.kepler_residual), 4.0 * DBL_EPSILON);
        evidence->evaluations = c.evaluations;
    }
    return MECH_OK;
}
