/* trajectory_observe.c — the trajectory driver's observer: at every sample
 * and step end it sizes each force and fictitious term and the relativistic
 * corrections (modelled or not), checks that a fixed step resolves every
 * approach to a central mass, and follows the conserved quantities (energy
 * or Jacobi integral, angular momentum); and the stop event. */
#include "trajectory_context.h"

#include <math.h>

/* max_of(a, b) (the other when one is NaN), inline: libm's fmax is a call,
 * and a call at each of the observer's dozen maxima spilled every
 * register around it (callgrind: a third of the observer's instructions). */
static inline double max_of(double a, double b)
{
    return a > b || b != b ? a : b;
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
            u = m * mech_traj_tide_potential(f, r);
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

enum mech_status mech_traj_observe(double t, const double *y, void *params)
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
        c->term_max[i] = max_of(c->term_max[i], mech_vec3_norm(ai));
        A = mech_vec3_add(A, ai);
    }
    /* the relativistic corrections are sized whether modelled or not (an
     * inertial frame only: elsewhere they are not offered) */
    {
        const double sc = special_correction(A, v, gamma, gm1), an = mech_vec3_norm(A);
        c->rel_max = max_of(c->rel_max, sc);
        if (an > 0.0) c->rel_ratio = max_of(c->rel_ratio, sc / an);
    }
    if (c->pn1_index >= 0) {
        const double pa = mech_vec3_norm(pn1_accel(c, r, v));
        const struct mech_force *f = &c->p->forces[c->pn1_index];
        const double d = mech_vec3_norm(mech_vec3_sub(r, f->u.central_gravity.center));
        c->pn1_max = max_of(c->pn1_max, pa);
        c->pn1_ratio = max_of(c->pn1_ratio, pa / (f->u.central_gravity.gm / (d * d)));
    }
    /* Fictitious terms are sized even when omitted (model only what the
     * scene requires, and say what was left out, with its size); all four
     * are exactly 0 in an inertial frame (w = dw/dt = A = 0 there,
     * mech_traj_ctx_init), where term_max keeps its 0. */
    if (c->noninertial) {
        const struct mech_vec3 wt = omega_at(c, t);
        c->term_max[n] = max_of(c->term_max[n], mech_vec3_norm(coriolis_accel(wt, v)));
        c->term_max[n + 1] = max_of(c->term_max[n + 1], mech_vec3_norm(centrifugal_accel(wt, r)));
        c->term_max[n + 2] =
            max_of(c->term_max[n + 2], mech_vec3_norm(mech_vec3_cross(c->wdot, r)));
        c->term_max[n + 3] = max_of(c->term_max[n + 3], mech_vec3_norm(c->A));
    }
    const double rn = mech_vec3_norm(r), vn = mech_vec3_norm(v); /* reused below */
    c->rmax = max_of(c->rmax, rn);
    c->vmax = max_of(c->vmax, vn);

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
    c->drift_max = max_of(c->drift_max, fabs(inv - c->inv0));
    c->scale_max = max_of(c->scale_max, scale);
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
        c->ldrift_max = max_of(c->ldrift_max, mech_vec3_norm(mech_vec3_sub(l, c->l0)));
        /* |d| = |r| exactly when the centre is the origin (r - 0 = r) */
        const double dn = c->lcenter.x == 0.0 && c->lcenter.y == 0.0 && c->lcenter.z == 0.0
                              ? rn
                              : mech_vec3_norm(d);
        c->lscale_max = max_of(c->lscale_max, c->p->mass * dn * vn);
    }
    c->n_observed++;
    c->t_last = t;
    c->r_last = r;
    return MECH_OK;
}

double mech_traj_event(double t, const double *y, void *params)
{
    (void)t;
    const struct traj_ctx *c = params;
    return y[c->p->stop_axis] - c->p->stop_value;
}

enum mech_status mech_traj_plane_observe(double t, const double *u, void *params)
{
    double y[6];
    plane_expand(params, u, y);
    return mech_traj_observe(t, y, params);
}

double mech_traj_plane_event(double t, const double *u, void *params)
{
    double y[6];
    plane_expand(params, u, y);
    return mech_traj_event(t, y, params);
}
