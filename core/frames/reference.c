/* reference.c — exact and first-order reference solutions for trajectories
 * (mech/frames/reference.h): Kepler (by core/ode/kepler.c's universal variables),
 * the harmonic oscillator, uniform gravity with linear drag, the first-order
 * Coriolis solution, and the recognition of which one a scene has.
 */
#include "mech/frames/reference.h"
#include "mech/base/constants.h"

#include <float.h>
#include <math.h>
#include <string.h>


/* sin(x)/x without cancellation or division by zero. */
static double sinc(double x)
{
    if (fabs(x) < 1e-4) return 1.0 - x * x / 6.0;
    return sin(x) / x;
}

void mech_harmonic_propagate(double omega, struct mech_vec3 anchor, struct mech_vec3 g,
                             struct mech_vec3 r0, struct mech_vec3 v0, double t,
                             struct mech_vec3 *r, struct mech_vec3 *v)
{
    mech_harmonic_propagate_dd(omega, 0.0, anchor, g, r0, v0, t, r, v);
}

void mech_harmonic_omega_dd(double k, double m, double *omega, double *omega_lo)
{
    /* q = k/m to double-double, then sqrt by one Newton correction */
    const double q = k / m;
    const double q_lo = fma(-q, m, k) / m;
    const double w = sqrt(q);
    *omega = w;
    *omega_lo = w > 0.0 ? (fma(-w, w, q) + q_lo) / (2.0 * w) : 0.0;
}

void mech_harmonic_propagate_dd(double omega, double omega_lo, struct mech_vec3 anchor,
                                struct mech_vec3 g, struct mech_vec3 r0, struct mech_vec3 v0,
                                double t, struct mech_vec3 *r, struct mech_vec3 *v)
{
    const double wt = omega * t;
    /* the phase's rounding error (fma) and omega's low part: cos(wt + d) =
     * cos wt - d sin wt to round-off, since |d| ~ 1e-16 |wt| */
    const double d = fma(omega, t, -wt) + omega_lo * t;
    const double c0 = cos(wt), s0 = sin(wt);
    const double c = c0 - d * s0, sn = s0 + d * c0;
    const double s_w = fabs(wt) < 1.0 ? t * sinc(wt) : sn / omega; /* sin(wt)/w */
    const double sh = sinc(0.5 * wt);
    /* (1 - cos)/w^2 = 2 sin^2(wt/2)/w^2: no cancellation near whole periods */
    const double sh2 = sin(0.5 * wt) + 0.5 * d * cos(0.5 * wt);
    const double one_minus_c_w2 =
        fabs(wt) < 1.0 ? 0.5 * t * t * sh * sh : 2.0 * sh2 * sh2 / (omega * omega);
    const double ws = omega * sn;                          /* w sin(wt) */
    struct mech_vec3 d0 = mech_vec3_sub(r0, anchor);
    /* r - a = d0 cos + v0 sin/w + g (1 - cos)/w^2; v = -d0 w sin + v0 cos + g sin/w */
    *r = mech_vec3_add(anchor, mech_vec3_add(mech_vec3_add(mech_vec3_scale(d0, c),
                                                           mech_vec3_scale(v0, s_w)),
                                             mech_vec3_scale(g, one_minus_c_w2)));
    *v = mech_vec3_add(mech_vec3_add(mech_vec3_scale(d0, -ws), mech_vec3_scale(v0, c)),
                       mech_vec3_scale(g, s_w));
}

/* E1(x) = (1 - e^-x)/x and E2(x) = (x - 1 + e^-x)/x^2 (series below 1). */
static void drag_functions(double x, double *e1, double *e2)
{
    if (x < 1.0) {
        /* E1 = sum (-x)^n/(n+1)!, E2 = sum (-x)^n/(n+2)! */
        double t1 = 1.0, t2 = 0.5, s1 = 1.0, s2 = 0.5;
        for (int n = 1; n < 40; n++) {
            t1 *= -x / (n + 1);
            t2 *= -x / (n + 2);
            s1 += t1;
            s2 += t2;
            if (fabs(t1) < 1e-18 * s1 && fabs(t2) < 1e-18 * s2) break;
        }
        *e1 = s1;
        *e2 = s2;
        return;
    }
    const double em = expm1(-x); /* e^-x - 1 */
    *e1 = -em / x;
    *e2 = (x + em) / (x * x);
}

void mech_uniform_drag_propagate(struct mech_vec3 g, double gamma, struct mech_vec3 r0,
                                 struct mech_vec3 v0, double t, struct mech_vec3 *r,
                                 struct mech_vec3 *v)
{
    const double x = gamma * t;
    double e1, e2;
    drag_functions(x, &e1, &e2);
    /* e^-x = 1 - x E1 */
    const double ex = exp(-x);
    *v = mech_vec3_add(mech_vec3_scale(v0, ex), mech_vec3_scale(g, t * e1));
    *r = mech_vec3_add(r0, mech_vec3_add(mech_vec3_scale(v0, t * e1),
                                         mech_vec3_scale(g, t * t * e2)));
}

void mech_coriolis_first_order(struct mech_vec3 w, struct mech_vec3 g, int centrifugal,
                               struct mech_vec3 r0, struct mech_vec3 v0, double t,
                               struct mech_vec3 *r, struct mech_vec3 *v,
                               struct mech_vec3 *second_order)
{
    const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
    /* notes §1.3-1.4: r = r0 + v0 t + g t^2/2 - w x (v0 t^2 + g t^3/3) */
    struct mech_vec3 r_0 = mech_vec3_add(r0, mech_vec3_add(mech_vec3_scale(v0, t),
                                                            mech_vec3_scale(g, 0.5 * t2)));
    struct mech_vec3 c1 = mech_vec3_add(mech_vec3_scale(v0, t2), mech_vec3_scale(g, t3 / 3.0));
    *r = mech_vec3_sub(r_0, mech_vec3_cross(w, c1));
    struct mech_vec3 c1d = mech_vec3_add(mech_vec3_scale(v0, 2.0 * t), mech_vec3_scale(g, t2));
    *v = mech_vec3_sub(mech_vec3_add(v0, mech_vec3_scale(g, t)), mech_vec3_cross(w, c1d));
    if (second_order) {
        struct mech_vec3 a = mech_vec3_add(mech_vec3_scale(v0, t3 / 3.0),
                                           mech_vec3_scale(g, t4 / 12.0));
        struct mech_vec3 s = mech_vec3_scale(mech_vec3_cross(w, mech_vec3_cross(w, a)), 2.0);
        if (centrifugal) {
            struct mech_vec3 b = mech_vec3_add(
                mech_vec3_scale(r0, 0.5 * t2),
                mech_vec3_add(mech_vec3_scale(v0, t3 / 6.0), mech_vec3_scale(g, t4 / 24.0)));
            s = mech_vec3_sub(s, mech_vec3_cross(w, mech_vec3_cross(w, b)));
        }
        *second_order = s;
    }
}

/* x turned about the unit axis k by the angle whose cosine and sine are c, s
 * (Rodrigues) */
static struct mech_vec3 rodrigues(struct mech_vec3 k, double c, double s, struct mech_vec3 x)
{
    return mech_vec3_add(
        mech_vec3_add(mech_vec3_scale(x, c), mech_vec3_scale(mech_vec3_cross(k, x), s)),
        mech_vec3_scale(k, mech_vec3_dot(k, x) * (1.0 - c)));
}

/* ---- scene recognition ---------------------------------------------------- */

static int vec_is_zero(struct mech_vec3 a) { return a.x == 0.0 && a.y == 0.0 && a.z == 0.0; }

/* a lies on the axis of w (through the origin): w x a = 0 to round-off of
 * |w| |a| (a point on the axis stays put in the inertial frame) */
static int on_axis(struct mech_vec3 w, struct mech_vec3 a)
{
    return mech_vec3_norm(mech_vec3_cross(w, a)) <=
           1e-14 * mech_vec3_norm(w) * mech_vec3_norm(a);
}

/* A force that exerts nothing whatever the state. */
static int force_is_null(const struct mech_force *f, double charge)
{
    switch (f->type) {
    case MECH_FORCE_LORENTZ:
        return charge == 0.0 || (vec_is_zero(f->u.lorentz.E) && vec_is_zero(f->u.lorentz.B));
    case MECH_FORCE_THIRD_BODY_TIDE: return 0;
    case MECH_FORCE_UNIFORM_GRAVITY: return vec_is_zero(f->u.uniform_gravity.g);
    case MECH_FORCE_CENTRAL_GRAVITY: return 0;
    case MECH_FORCE_SPRING: return f->u.spring.k == 0.0;
    case MECH_FORCE_LINEAR_DRAG: return f->u.linear_drag.b == 0.0;
    }
    return 0;
}

/* A relativistic scene: exact only for special-relativistic dynamics in an
 * inertial frame under uniform fields (Lorentz forces and uniform gravity,
 * the latter a constant force m g: an electric field m g / q), not null. */
static enum mech_reference_kind relativistic_reference(const struct mech_trajectory_problem *p,
                                                       struct mech_trajectory_reference *ref)
{
    if (p->relativity != MECH_RELATIVITY_SPECIAL || p->frame.type != MECH_FRAME_INERTIAL)
        return ref->kind;
    struct mech_vec3 eps = mech_vec3_make(0, 0, 0), om = mech_vec3_make(0, 0, 0);
    const double qm = p->charge / p->mass;
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        if (force_is_null(f, p->charge)) continue;
        if (f->type == MECH_FORCE_UNIFORM_GRAVITY) {
            eps = mech_vec3_add(eps, f->u.uniform_gravity.g);
        } else if (f->type == MECH_FORCE_LORENTZ) {
            eps = mech_vec3_add(eps, mech_vec3_scale(f->u.lorentz.E, qm));
            om = mech_vec3_add(om, mech_vec3_scale(f->u.lorentz.B, qm));
        } else {
            return ref->kind;
        }
    }
    if (mech_charged_motion_init(eps, om, p->position, mech_trajectory_proper_velocity0(p),
                                 &ref->charged, NULL) != MECH_OK)
        return ref->kind;
    ref->kind = MECH_REFERENCE_EXACT;
    ref->name = "relativistic_uniform_fields";
    return ref->kind;
}

enum mech_reference_kind mech_trajectory_reference_find(const struct mech_trajectory_problem *p,
                                                        struct mech_trajectory_reference *ref)
{
    memset(ref, 0, sizeof *ref);
    ref->kind = MECH_REFERENCE_NONE;
    ref->name = "";
    if (!p) return ref->kind;
    ref->r0 = p->position;
    ref->v0 = p->velocity;
    if (p->relativity) return relativistic_reference(p, ref);
    struct mech_vec3 w = mech_frame_omega(&p->frame);
    const int rotating = p->frame.type == MECH_FRAME_ROTATING;
    const int noninertial = p->frame.type != MECH_FRAME_INERTIAL && !vec_is_zero(w);
    const int coriolis = noninertial && (p->fictitious & MECH_FICTITIOUS_CORIOLIS);
    const int centrifugal = noninertial && (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    /* A rotation that changes with time has no reference here (the first-order
     * solution assumes a constant w); a constant origin acceleration A is a
     * uniform field -A and joins g. */
    if (rotating && !vec_is_zero(p->frame.omega_dot) &&
        (p->fictitious & (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL |
                          MECH_FICTITIOUS_EULER)))
        return ref->kind;
    size_t n_central = 0, n_spring = 0, n_uniform = 0, n_drag = 0, n_lorentz = 0;
    const struct mech_force *central = NULL, *spring = NULL;
    struct mech_vec3 g = mech_vec3_make(0, 0, 0);
    double b = 0.0;
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        if (force_is_null(f, p->charge)) continue;
        switch (f->type) {
        case MECH_FORCE_CENTRAL_GRAVITY: n_central++; central = f; break;
        case MECH_FORCE_SPRING: n_spring++; spring = f; break;
        case MECH_FORCE_UNIFORM_GRAVITY:
            n_uniform++;
            g = mech_vec3_add(g, f->u.uniform_gravity.g);
            break;
        case MECH_FORCE_LINEAR_DRAG: n_drag++; b += f->u.linear_drag.b; break;
        case MECH_FORCE_LORENTZ: n_lorentz++; break;
        case MECH_FORCE_THIRD_BODY_TIDE:
            return ref->kind; /* no reference with these */
        }
    }
    if (rotating && (p->fictitious & MECH_FICTITIOUS_TRANSLATIONAL) &&
        !vec_is_zero(p->frame.acceleration)) {
        g = mech_vec3_sub(g, p->frame.acceleration);
        n_uniform++;
    }
    ref->g = g;
    if (n_lorentz) {
        /* Newton's motion in uniform E and B (and uniform gravity) in an
         * inertial frame: drift, gyration and the parallel fall
         * (lorentz_propagate); evidence for the integrated run only, never a
         * closed-form answer (ref->evidence_only) */
        if (coriolis || centrifugal || n_central + n_spring + n_drag != 0 || p->charge == 0.0)
            return ref->kind;
        const double qm = p->charge / p->mass;
        struct mech_vec3 a0 = g, om = mech_vec3_make(0, 0, 0);
        for (size_t i = 0; i < p->n_forces; i++) {
            const struct mech_force *f = &p->forces[i];
            if (f->type != MECH_FORCE_LORENTZ) continue;
            a0 = mech_vec3_add(a0, mech_vec3_scale(f->u.lorentz.E, qm));
            om = mech_vec3_add(om, mech_vec3_scale(f->u.lorentz.B, qm));
        }
        if (!mech_vec3_isfinite(a0) || !mech_vec3_isfinite(om)) return ref->kind;
        ref->kind = MECH_REFERENCE_EXACT;
        ref->name = "uniform_fields_newtonian";
        ref->evidence_only = 1;
        ref->g = a0;
        ref->w = om;
        return ref->kind;
    }
    if (!coriolis && !centrifugal) {
        if (n_central == 1 && n_spring + n_uniform + n_drag == 0) {
            ref->kind = MECH_REFERENCE_EXACT;
            ref->name = "kepler";
            ref->gm = central->u.central_gravity.gm;
            ref->center = central->u.central_gravity.center;
        } else if (n_spring == 1 && spring->u.spring.rest_length == 0.0 && n_central + n_drag == 0) {
            ref->kind = MECH_REFERENCE_EXACT;
            ref->name = "harmonic_oscillator";
            mech_harmonic_omega_dd(spring->u.spring.k, p->mass, &ref->omega, &ref->omega_lo);
            ref->center = spring->u.spring.anchor;
        } else if (n_central + n_spring == 0) {
            ref->kind = MECH_REFERENCE_EXACT;
            ref->name = n_drag ? "uniform_gravity_linear_drag" : "uniform_gravity";
            ref->gamma = b / p->mass;
        }
    } else if (rotating && coriolis && centrifugal && vec_is_zero(p->frame.omega_dot) &&
               !((p->fictitious & MECH_FICTITIOUS_TRANSLATIONAL) &&
                 !vec_is_zero(p->frame.acceleration)) &&
               n_drag == 0 && on_axis(w, g) &&
               (!central || on_axis(w, central->u.central_gravity.center)) &&
               (!spring || on_axis(w, spring->u.spring.anchor)) &&
               ((n_central == 1 && n_spring + n_uniform == 0) ||
                (n_spring == 1 && spring->u.spring.rest_length == 0.0 && n_central == 0) ||
                n_central + n_spring == 0)) {
        /* every force is the same seen from the inertial frame that
         * coincides with this one at t = 0: the inertial solution through
         * (r0, v0 + w x r0), turned back by w t (mech_trajectory_reference_eval) */
        ref->kind = MECH_REFERENCE_EXACT;
        ref->rotated = 1;
        ref->spin = w;
        ref->v0 = mech_vec3_add(p->velocity, mech_vec3_cross(w, p->position));
        if (n_central == 1) {
            ref->name = "kepler_rotating";
            ref->gm = central->u.central_gravity.gm;
            ref->center = central->u.central_gravity.center;
        } else if (n_spring == 1) {
            ref->name = "harmonic_oscillator_rotating";
            mech_harmonic_omega_dd(spring->u.spring.k, p->mass, &ref->omega, &ref->omega_lo);
            ref->center = spring->u.spring.anchor;
        } else {
            ref->name = "uniform_gravity_rotating";
            ref->gamma = 0.0;
        }
    } else if (coriolis && n_central + n_spring + n_drag == 0) {
        ref->kind = MECH_REFERENCE_FIRST_ORDER;
        ref->name = "coriolis_first_order";
        ref->w = w;
        ref->centrifugal = centrifugal;
    }
    return ref->kind;
}

/* Newton's motion under v' = a0 + v x w (a0 = q E / m + g, w = q B / m,
 * both uniform and constant): the parallel part falls uniformly, the
 * perpendicular part drifts at v_d = a0 x w / |w|^2 and turns about w at
 * the rate -|w|:
 *   u(t) = u0 cos(W t) - (b x u0) sin(W t),  u0 = v0_perp - v_d,
 *   r(t) = r0 + (v0_par + v_d) t + a0_par t^2 / 2 + u0 sin(W t) / W
 *          - (b x u0) 2 sin^2(W t / 2) / W
 * (1 - cos written as 2 sin^2 so that small W t keeps its digits; the angle
 * reduced mod 2 pi in long double). w = 0: the uniform fall. */
static void lorentz_propagate(const struct mech_trajectory_reference *ref, double t,
                              struct mech_vec3 *r, struct mech_vec3 *v)
{
    const struct mech_vec3 a0 = ref->g, w = ref->w;
    const double W = mech_vec3_norm(w);
    if (!(W > 0.0)) {
        *v = mech_vec3_add(ref->v0, mech_vec3_scale(a0, t));
        *r = mech_vec3_add(ref->r0, mech_vec3_add(mech_vec3_scale(ref->v0, t),
                                                  mech_vec3_scale(a0, 0.5 * t * t)));
        return;
    }
    const struct mech_vec3 b = mech_vec3_scale(w, 1.0 / W);
    const struct mech_vec3 vpar = mech_vec3_scale(b, mech_vec3_dot(ref->v0, b));
    const struct mech_vec3 apar = mech_vec3_scale(b, mech_vec3_dot(a0, b));
    const struct mech_vec3 vd = mech_vec3_scale(mech_vec3_cross(a0, w), 1.0 / (W * W));
    const struct mech_vec3 u0 = mech_vec3_sub(mech_vec3_sub(ref->v0, vpar), vd);
    const struct mech_vec3 bu = mech_vec3_cross(b, u0);
    const long double ang = fmodl((long double)W * (long double)t,
                                  6.283185307179586476925286766559L);
    const double c = (double)cosl(ang), sn = (double)sinl(ang), sh = (double)sinl(0.5L * ang);
    *v = mech_vec3_add(mech_vec3_add(vpar, mech_vec3_scale(apar, t)),
                       mech_vec3_add(vd, mech_vec3_sub(mech_vec3_scale(u0, c),
                                                       mech_vec3_scale(bu, sn))));
    struct mech_vec3 d = mech_vec3_add(mech_vec3_scale(mech_vec3_add(vpar, vd), t),
                                       mech_vec3_scale(apar, 0.5 * t * t));
    d = mech_vec3_add(d, mech_vec3_sub(mech_vec3_scale(u0, sn / W),
                                       mech_vec3_scale(bu, 2.0 * sh * sh / W)));
    *r = mech_vec3_add(ref->r0, d);
}

enum mech_status mech_trajectory_reference_eval(const struct mech_trajectory_reference *ref,
                                                double t, struct mech_vec3 *r,
                                                struct mech_vec3 *v, double *second_order,
                                                struct mech_error *err)
{
    if (second_order) *second_order = 0.0;
    if (!ref || ref->kind == MECH_REFERENCE_NONE)
        return mech_error_set(err, MECH_EINVAL, NULL, "no reference solution");
    if (ref->rotated) {
        /* the inertial motion, then seen from the frame turned by w t about
         * w: r_R = R(-w t) r_I, v_R = R(-w t) v_I - w x r_R */
        struct mech_trajectory_reference in = *ref;
        in.rotated = 0;
        in.name = !strcmp(ref->name, "kepler_rotating")                ? "kepler"
                : !strcmp(ref->name, "harmonic_oscillator_rotating") ? "harmonic_oscillator"
                                                                       : "uniform_gravity";
        struct mech_vec3 ri, vi;
        enum mech_status st = mech_trajectory_reference_eval(&in, t, &ri, &vi, NULL, err);
        if (st != MECH_OK) return st;
        const double wn = mech_vec3_norm(ref->spin);
        const struct mech_vec3 k = mech_vec3_scale(ref->spin, 1.0 / wn);
        /* the angle reduced mod 2 pi in long double: over many turns the
         * rounding of w t alone would move the reference */
        const long double ang = fmodl((long double)wn * (long double)t, 6.283185307179586476925286766559L);
        const double c = (double)cosl(ang), sn = -(double)sinl(ang);
        *r = rodrigues(k, c, sn, ri);
        *v = mech_vec3_sub(rodrigues(k, c, sn, vi), mech_vec3_cross(ref->spin, *r));
    } else if (!strcmp(ref->name, "uniform_fields_newtonian")) {
        lorentz_propagate(ref, t, r, v);
    } else if (!strcmp(ref->name, "relativistic_uniform_fields")) {
        struct mech_charged_motion_state cs;
        enum mech_status st = mech_charged_motion_at_lab_time(&ref->charged, t, &cs, err);
        if (st != MECH_OK) return st;
        *r = cs.r;
        *v = cs.v;
    } else if (!strcmp(ref->name, "kepler")) {
        struct mech_vec3 rr, vv;
        enum mech_status st = mech_kepler_propagate(ref->gm, mech_vec3_sub(ref->r0, ref->center),
                                                    ref->v0, t, &rr, &vv, err);
        if (st != MECH_OK) return st;
        *r = mech_vec3_add(rr, ref->center);
        *v = vv;
    } else if (!strcmp(ref->name, "harmonic_oscillator")) {
        mech_harmonic_propagate_dd(ref->omega, ref->omega_lo, ref->center, ref->g, ref->r0,
                                   ref->v0, t, r, v);
    } else if (!strcmp(ref->name, "coriolis_first_order")) {
        struct mech_vec3 s;
        mech_coriolis_first_order(ref->w, ref->g, ref->centrifugal, ref->r0, ref->v0, t, r, v,
                                  &s);
        if (second_order) *second_order = mech_vec3_norm(s);
    } else {
        mech_uniform_drag_propagate(ref->g, ref->gamma, ref->r0, ref->v0, t, r, v);
    }
    if (!mech_vec3_isfinite(*r) || !mech_vec3_isfinite(*v))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite reference state at t = %.9g s",
                              t);
    return MECH_OK;
}
