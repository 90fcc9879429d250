/* ode.c — the initial-value driver of mech/ode/ode.h on the stepper interface of
 * integrators/integrator.h: step loop with budget checks, evenly spaced
 * samples and event location by sub-steps from the start of the accepted
 * step that contains the wanted time.
 *
 * Sub-steps: a value at time tau inside an accepted step [t_a, t_b] is one
 * step of the same method from (t_a, y_a) of length tau - t_a. Its error is
 * the method's local error O(h^(p+1)), as good as the step itself (a cubic
 * Hermite interpolant would cap rk8pd at O(h^4)). For the one-step methods
 * tau = t_b reproduces the accepted step bit for bit (same stepper, same h);
 * radau15 (corrector re-converged, no compensation term) and msbdf (bsimp
 * under the same tolerance) agree with it to round-off / the tolerance. The
 * event's bracket uses g at the accepted ends, so Brent's method only needs
 * G continuous inside, which the sub-step solution is.
 *
 * Event: Brent's method (R. P. Brent, Algorithms for Minimization without
 * Derivatives, 1973, ch. 4, procedure "zero") on G(tau) = g(tau, y(tau)) with
 * y(tau) from a sub-step, tolerance 2 eps |tau|: the stop time is exact to a
 * few ulp of the sub-step solution.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ode/integrators/integrator.h"
#include "mech/ode/ode.h"

/* Brent needs at most about (log2 of width/tolerance) bisections, ~1100 for the
 * full double range (1e15 s down to DBL_MIN); interpolation usually takes ~10. */
enum { ODE_BRENT_MAX_ITER = 4000 };

enum mech_status mech_ode_eval(const struct mech_ode_system *sys, double t, const double *y,
                               double *dydt, struct mech_ode_stats *stats,
                               struct mech_error *err)
{
    if (stats) stats->rhs_evaluations++;
    enum mech_status st = sys->rhs(t, y, dydt, sys->params);
    if (st != MECH_OK)
        return mech_error_set(err, st, NULL, "the right-hand side failed at t = %.9g s", t);
    if (sys->flags & MECH_ODE_FINITE_OUTPUT) return MECH_OK; /* the rhs tested them */
    /* every component finite: x * 0 is 0 for finite x, NaN for inf or NaN;
     * one branch instead of one per component (this runs at every stage) */
    double z = 0.0;
    for (size_t i = 0; i < sys->dim; i++) z += dydt[i] * 0.0;
    if (!(z == 0.0))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite derivative at t = %.9g s", t);
    return MECH_OK;
}

enum mech_status mech_ode_accel(const struct mech_ode_system *sys, double t, const double *q,
                                const double *v, double *a, struct mech_ode_stats *stats,
                                struct mech_error *err)
{
    if (!sys->accel)
        return mech_error_set(err, MECH_EINVAL, NULL, "the system has no second-order form");
    if (stats) stats->rhs_evaluations++;
    enum mech_status st = sys->accel(t, q, v, a, sys->params);
    if (st != MECH_OK)
        return mech_error_set(err, st, NULL, "the acceleration failed at t = %.9g s", t);
    if (sys->flags & MECH_ODE_FINITE_OUTPUT) return MECH_OK; /* the accel tested them */
    for (size_t i = 0; i < sys->dim / 2; i++)
        if (!isfinite(a[i]))
            return mech_error_set(err, MECH_ENUMERIC, NULL,
                                  "non-finite acceleration at t = %.9g s", t);
    return MECH_OK;
}

struct solver {
    const struct mech_ode_problem *p;
    const struct mech_integrator *m;
    void *ws;
    size_t dim;
    double *y, *yprev, *ysub; /* dim each, one block */
    size_t next_sample;
    struct mech_ode_result *res;
    struct mech_error *err;
    /* dense output (see dense_sample): the accepted step's end derivatives
     * (the method's buffers, NULL when it has none for this step), and the
     * starts of the two steps before it, (tc, yc, fc) and (td, yd, fd);
     * n_prev of them are known (0..2) */
    const double *fa, *fb;
    double tc, td, *yc, *fc, *yd, *fd;
    int dense, n_prev;
};

static int all_finite(const double *y, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(y[i])) return 0;
    return 1;
}

static double sample_time(const struct mech_ode_problem *p, size_t i)
{
    if (i + 1 == p->n_samples) return p->t_end;
    return p->t0 + (p->t_end - p->t0) * ((double)i / (double)(p->n_samples - 1));
}

/* out = state at tau, by a sub-step from (ta, ya). */
static enum mech_status substep(struct solver *s, double ta, const double *ya, double tau,
                                double *out)
{
    memcpy(out, ya, s->dim * sizeof *out);
    if (tau == ta) return MECH_OK;
    enum mech_status st = s->m->step(s->ws, s->p->sys, ta, tau - ta, out, &s->res->stats, s->err);
    if (st != MECH_OK) return st;
    if (!all_finite(out, s->dim))
        return mech_error_set(s->err, MECH_ENUMERIC, NULL, "non-finite state at t = %.9g s", tau);
    return MECH_OK;
}

static enum mech_status observe(struct solver *s, double t, const double *y)
{
    if (!s->p->observe) return MECH_OK;
    enum mech_status st = s->p->observe(t, y, s->p->observe_params);
    if (st != MECH_OK)
        return mech_error_set(s->err, st, NULL, "the observer failed at t = %.9g s", t);
    return MECH_OK;
}

static void write_sample(struct solver *s, double t, const double *y)
{
    const struct mech_ode_problem *p = s->p;
    if (p->sample_t) p->sample_t[s->next_sample] = t;
    if (p->sample_y) memcpy(p->sample_y + s->next_sample * s->dim, y, s->dim * sizeof *y);
    s->next_sample++;
    s->res->n_samples = s->next_sample;
}

/* Dense output of a second-order system y = (q, v), f = (v, a), nq = dim/2
 * (mech_ode_problem.dense_output).
 *
 * Nodes: the accepted step's ends ta, tb and the starts tc, td of the two
 * steps before it (tb > ta > tc > td). Per component, q(ts) is the Hermite
 * interpolant of q, q' = v, q'' = a at ta, tb and tc (degree 8), and v(ts)
 * that of v, v' = a at the same three (degree 5): v is interpolated from its
 * own values, not differentiated from q's, so it keeps every digit when q is
 * large (a free particle far from the origin keeps its exact speed). The
 * further Newton terms through td (degrees 11 and 7) estimate each one's
 * error, as an embedded pair estimates a step's; the sample is taken from the
 * interpolants only when both estimates are within the step's tolerance,
 * atol + rtol max(|y(ta)|, |y(tb)|), for every component: then it is as good
 * as a sub-step's, and costs no evaluation. Otherwise (returns 0) the caller
 * sub-steps. Times are taken relative to ta, so no digit is lost to a large t. */
enum { DENSE_NODES = 4, DENSE_OUT_NODES = 3 };

/* The Hermite interpolant on the first `out` of n nodes (each repeated mult
 * = 2 or 3 times: the value, d1 = its derivative, d2 = half its second
 * derivative) at x, and the further Newton terms through the rest. */
static void hermite_eval(const double *node_t, const double *val, const double *d1,
                         const double *d2, int mult, int n, int out, double x, double *p,
                         double *est)
{
    enum { MAXT = 3 * DENSE_NODES };
    const int nt = mult * n, no = mult * out;
    double z[MAXT], col[MAXT];
    for (int k = 0; k < nt; k++) {
        z[k] = node_t[k / mult];
        col[k] = val[k / mult];
    }
    /* divided differences, confluent where a point repeats, column by column
     * in place from the bottom; the Newton form accumulated as it goes */
    double w = 1.0, sum = col[0], extra = 0.0;
    for (int j = 1; j < nt; j++) {
        for (int k = nt - 1; k >= j; k--) {
            if (k / mult == (k - j) / mult) /* the same point */
                col[k] = j == 1 ? d1[k / mult] : d2[k / mult];
            else
                col[k] = (col[k] - col[k - 1]) / (z[k] - z[k - j]);
        }
        w *= x - z[j - 1];
        if (j < no) sum += col[j] * w;
        else extra += col[j] * w;
    }
    *p = sum;
    *est = extra;
}

static int dense_sample(const struct solver *s, double ta, const double *ya, double tb,
                        const double *yb, double ts, double *out)
{
    const size_t nq = s->dim / 2;
    const double rtol = s->p->opt.rtol, atol = s->p->opt.atol;
    const double node_t[DENSE_NODES] = {0.0, tb - ta, s->tc - ta, s->td - ta};
    const double *ny[DENSE_NODES] = {ya, yb, s->yc, s->yd};
    const double *nf[DENSE_NODES] = {s->fa, s->fb, s->fc, s->fd};
    const double x = ts - ta;
    for (size_t i = 0; i < nq; i++) {
        double q[DENSE_NODES], v[DENSE_NODES], a[DENSE_NODES], ha[DENSE_NODES];
        for (int k = 0; k < DENSE_NODES; k++) {
            q[k] = ny[k][i];
            v[k] = nf[k][i]; /* q' = v, as the system computed it */
            a[k] = nf[k][nq + i];
            ha[k] = 0.5 * a[k];
        }
        double qs, eq, vs, ev;
        hermite_eval(node_t, q, v, ha, 3, DENSE_NODES, DENSE_OUT_NODES, x, &qs, &eq);
        for (int k = 0; k < DENSE_NODES; k++) v[k] = ny[k][nq + i];
        hermite_eval(node_t, v, a, NULL, 2, DENSE_NODES, DENSE_OUT_NODES, x, &vs, &ev);
        const double tq = atol + rtol * fmax(fabs(ya[i]), fabs(yb[i]));
        const double tv = atol + rtol * fmax(fabs(ya[nq + i]), fabs(yb[nq + i]));
        if (!(fabs(eq) <= tq) || !(fabs(ev) <= tv) || !isfinite(qs) || !isfinite(vs)) return 0;
        out[i] = qs;
        out[nq + i] = vs;
    }
    return 1;
}

/* After an accepted step [tprev, t]: its start becomes the next step's node
 * c, and c its node d (or, when the method had no derivatives for it, the
 * nodes are forgotten). */
static void dense_shift(struct solver *s, double tprev)
{
    if (!s->fa) {
        s->n_prev = 0;
        return;
    }
    double *ty = s->yd, *tf = s->fd;
    s->yd = s->yc, s->fd = s->fc, s->td = s->tc;
    s->yc = ty, s->fc = tf, s->tc = tprev;
    memcpy(s->yc, s->yprev, s->dim * sizeof *s->yc);
    memcpy(s->fc, s->fa, s->dim * sizeof *s->fc);
    if (s->n_prev < 2) s->n_prev++;
}

/* Write every sample with time <= t_hi, the step being [ta, tb] with states ya, yb. */
static enum mech_status emit_samples(struct solver *s, double ta, const double *ya, double tb,
                                     const double *yb, double t_hi)
{
    while (s->next_sample < s->p->n_samples) {
        double ts = sample_time(s->p, s->next_sample);
        if (ts > t_hi) break;
        const double *ys = yb;
        if (ts != tb) {
            ys = s->ysub;
            if (!(s->fa && s->n_prev == 2 && dense_sample(s, ta, ya, tb, yb, ts, s->ysub))) {
                enum mech_status st = substep(s, ta, ya, ts, s->ysub);
                if (st != MECH_OK) return st;
            }
        }
        enum mech_status st = observe(s, ts, ys);
        if (st != MECH_OK) return st;
        write_sample(s, ts, ys);
    }
    return MECH_OK;
}

static int crossed(double g0, double g1, int dir)
{
    int down = g0 > 0.0 && g1 <= 0.0;
    int up = g0 < 0.0 && g1 >= 0.0;
    if (dir == MECH_ODE_DECREASING) return down;
    if (dir == MECH_ODE_INCREASING) return up;
    return down || up;
}

/* G(tau) = g(tau, y(tau)), y(tau) by a sub-step from (ta, ya). */
static enum mech_status event_value(struct solver *s, double ta, const double *ya, double tau,
                                    double *g)
{
    enum mech_status st = substep(s, ta, ya, tau, s->ysub);
    if (st != MECH_OK) return st;
    *g = s->p->event(tau, s->ysub, s->p->event_params);
    if (!isfinite(*g))
        return mech_error_set(s->err, MECH_ENUMERIC, NULL,
                              "non-finite event function at t = %.9g s", tau);
    return MECH_OK;
}

/* Brent's zero (Brent 1973, ch. 4) of G on [a, b], G(a) = fa, G(b) = fb of
 * opposite signs (or fb == 0). */
static enum mech_status locate_event(struct solver *s, double a, const double *ya, double fa,
                                     double b, double fb, double *root)
{
    const double ta = a;
    double c = a, fc = fa, d = b - a, e = d;
    for (int it = 0; it < ODE_BRENT_MAX_ITER; it++) {
        if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0)) {
            c = a;
            fc = fa;
            d = e = b - a;
        }
        if (fabs(fc) < fabs(fb)) {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        const double tol1 = 2.0 * DBL_EPSILON * fabs(b) + DBL_MIN;
        const double xm = 0.5 * (c - b);
        if (fabs(xm) <= tol1 || fb == 0.0) {
            *root = b;
            return MECH_OK;
        }
        if (fabs(e) >= tol1 && fabs(fa) > fabs(fb)) {
            double p, q, r, sr = fb / fa;
            if (a == c) {
                p = 2.0 * xm * sr;
                q = 1.0 - sr;
            } else {
                q = fa / fc;
                r = fb / fc;
                p = sr * (2.0 * xm * q * (q - r) - (b - a) * (r - 1.0));
                q = (q - 1.0) * (r - 1.0) * (sr - 1.0);
            }
            if (p > 0.0) q = -q;
            else p = -p;
            if (2.0 * p < fmin(3.0 * xm * q - fabs(tol1 * q), fabs(e * q))) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        b += fabs(d) > tol1 ? d : copysign(tol1, xm);
        enum mech_status st = event_value(s, ta, ya, b, &fb);
        if (st != MECH_OK) return st;
    }
    /* Brent converges in far fewer iterations; reaching here is a bug. */
    return mech_error_set(s->err, MECH_EINTERNAL, NULL, "event location did not converge");
}

static enum mech_status check_problem(const struct mech_ode_problem *p,
                                      const struct mech_budget *budget, struct mech_ode_result *res,
                                      struct mech_error *err)
{
    if (!p || !res || !p->sys || !p->sys->rhs || !p->method || !p->y0 || p->sys->dim == 0)
        return mech_error_set(err, MECH_EINVAL, NULL, "incomplete ODE problem");
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "no compute budget given");
    if (!isfinite(p->t0) || !isfinite(p->t_end) || !(p->t_end > p->t0))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > t0");
    if (p->n_samples < 2)
        return mech_error_set(err, MECH_EINVAL, "samples", "at least 2 samples are needed");
    if (p->event && !p->y_stop)
        return mech_error_set(err, MECH_EINVAL, NULL, "an event needs a y_stop buffer");
    if (!all_finite(p->y0, p->sys->dim))
        return mech_error_set(err, MECH_EINVAL, NULL, "the initial state is not finite");
    const unsigned f = p->method->flags;
    if ((f & MECH_INTEGRATOR_SECOND_ORDER) && (!p->sys->accel || p->sys->dim % 2 != 0))
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "method %s needs a second-order system", p->method->name);
    if ((f & MECH_INTEGRATOR_KEPLER_SPLIT) &&
        (!p->sys->kepler || !p->sys->kepler->perturbation || !(p->sys->kepler->gm > 0.0) ||
         !isfinite(p->sys->kepler->gm) || p->sys->particle_dim < 2 ||
         p->sys->dim != 2 * p->sys->particle_dim))
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "method %s needs one body about one central mass with small "
                              "perturbations (a Kepler split: exactly one central_gravity in "
                              "an inertial frame); this system has none",
                              p->method->name);
    if ((f & MECH_INTEGRATOR_SECOND_ORDER) &&
        (p->sys->particle_dim > 3 ||
         (p->sys->particle_dim > 0 && (p->sys->dim / 2) % p->sys->particle_dim != 0)))
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "particle_dim %zu does not divide the %zu coordinates into "
                              "points of 1 to 3 components",
                              p->sys->particle_dim, p->sys->dim / 2);
    if (f & MECH_INTEGRATOR_ADAPTIVE) {
        if (!p->method->evolve)
            return mech_error_set(err, MECH_EINTERNAL, NULL, "adaptive method without evolve");
        if (!(p->opt.rtol >= 0.0 && p->opt.rtol < 1.0))
            return mech_error_set(err, MECH_EINVAL, "integrator/rtol",
                                  "rtol must be in [0, 1), got %.17g", p->opt.rtol);
        if (!(p->opt.atol >= 0.0 && isfinite(p->opt.atol)))
            return mech_error_set(err, MECH_EINVAL, "integrator/atol",
                                  "atol must be finite and >= 0, got %.17g", p->opt.atol);
        if (!(p->opt.rtol + p->opt.atol > 0.0))
            return mech_error_set(err, MECH_EINVAL, "integrator/rtol",
                                  "rtol and atol cannot both be 0");
    } else if (!(p->opt.dt > 0.0 && isfinite(p->opt.dt))) {
        return mech_error_set(err, MECH_EINVAL, "integrator/dt",
                              "dt must be finite and > 0, got %.17g", p->opt.dt);
    }
    return MECH_OK;
}

/* Number of fixed steps covering [t0, t_end]: ceil((t_end - t0) / dt), taking
 * a ratio within 1e-9 of an integer k as exactly k steps (so t_end = 1,
 * dt = 0.1 is 10 steps, not 10 and a sliver). Returns a double (may be huge). */
static double fixed_step_count(double span, double dt)
{
    double r = span / dt;
    double k = nearbyint(r);
    if (k >= 1.0 && fabs(r - k) <= 1e-9 * k) return k;
    return ceil(r);
}

static void fill_progress(struct mech_error *err, enum mech_status st, long steps, double t_reached,
                          double t_target)
{
    if (!err || err->code != st) return;
    if (err->progress.steps == 0) err->progress.steps = steps;
    if (!isfinite(err->progress.t_reached)) err->progress.t_reached = t_reached;
    if (!isfinite(err->progress.t_target)) err->progress.t_target = t_target;
}

enum mech_status mech_ode_solve(const struct mech_ode_problem *p, const struct mech_budget *budget,
                                struct mech_ode_result *res, struct mech_error *err)
{
    enum mech_status st = check_problem(p, budget, res, err);
    if (st != MECH_OK) return st;
    memset(res, 0, sizeof *res);
    res->t_stop = NAN;
    res->t_reached = p->t0;

    const struct mech_integrator *m = p->method;
    const int adaptive = (m->flags & MECH_INTEGRATOR_ADAPTIVE) != 0;
    const double span = p->t_end - p->t0;
    double n_fixed = 0.0;
    if (!adaptive) {
        n_fixed = fixed_step_count(span, p->opt.dt);
        if (n_fixed > (double)budget->max_steps) {
            double could = p->t0 + (double)budget->max_steps * p->opt.dt;
            st = mech_error_set(err, MECH_EBUDGET, "integrator/dt",
                                "%s with dt = %.6g s needs %.6g steps to reach t_end = %.6g s; "
                                "the budget of %ld steps reaches only t = %.6g s",
                                m->name, p->opt.dt, n_fixed, p->t_end, budget->max_steps, could);
            fill_progress(err, st, 0, could, p->t_end);
            return st;
        }
    }
    st = mech_budget_check(budget, 0, 1, err);
    if (st != MECH_OK) {
        fill_progress(err, st, 0, p->t0, p->t_end);
        return st;
    }

    struct solver s = {p, m, NULL, p->sys->dim, NULL, NULL, NULL, 0, res, err,
                       NULL, NULL, 0.0, 0.0, NULL, NULL, NULL, NULL, 0, 0};
    /* dense output: asked for, a second-order system, a method that hands
     * over its step's derivatives, and samples that can fall inside a step */
    s.dense = p->dense_output && adaptive && m->step_derivs && p->sys->accel &&
              s.dim % 2 == 0 && p->n_samples > 2;
    double *block = malloc((s.dense ? 7 : 3) * s.dim * sizeof *block);
    if (!block) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    s.y = block;
    s.yprev = block + s.dim;
    s.ysub = block + 2 * s.dim;
    if (s.dense) {
        s.yc = block + 3 * s.dim;
        s.fc = block + 4 * s.dim;
        s.yd = block + 5 * s.dim;
        s.fd = block + 6 * s.dim;
    }
    st = m->alloc(&s.ws, s.dim, &p->opt, err);
    if (st != MECH_OK) {
        free(block);
        return st;
    }
    m->reset(s.ws);

    double t = p->t0, tprev = t;
    memcpy(s.y, p->y0, s.dim * sizeof *s.y);
    double g_prev = 0.0;
    if ((st = observe(&s, t, s.y)) != MECH_OK) goto fail;
    write_sample(&s, t, s.y);
    if (p->event) {
        g_prev = p->event(t, s.y, p->event_params);
        if (!isfinite(g_prev)) {
            st = mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite event function at t0");
            goto fail;
        }
    }

    /* Adaptive: first trial step; the controller shrinks it when too long. */
    double h = adaptive ? span * 1e-3 : p->opt.dt;
    long k = 0; /* fixed-step index */
    while (t < p->t_end) {
        st = mech_budget_check(budget, res->stats.steps + 1, 0, err);
        if (st != MECH_OK) goto fail;
        memcpy(s.yprev, s.y, s.dim * sizeof *s.y);
        tprev = t;
        if (adaptive) {
            st = m->evolve(s.ws, p->sys, &t, p->t_end, &h, s.y, &res->stats, err);
        } else {
            double tn = (double)(k + 1) >= n_fixed ? p->t_end : p->t0 + (double)(k + 1) * p->opt.dt;
            st = m->step(s.ws, p->sys, t, tn - t, s.y, &res->stats, err);
            t = tn;
            k++;
        }
        if (st != MECH_OK) {
            t = tprev;
            goto fail;
        }
        if (!all_finite(s.y, s.dim)) {
            st = mech_error_set(err, MECH_ENUMERIC, NULL,
                                "non-finite state after the step from t = %.9g s", tprev);
            t = tprev;
            goto fail;
        }
        res->stats.steps++;
        res->t_reached = t;
        if (s.dense && !m->step_derivs(s.ws, &s.fa, &s.fb)) s.fa = s.fb = NULL;

        if (p->event) {
            double g_new = p->event(t, s.y, p->event_params);
            if (!isfinite(g_new)) {
                st = mech_error_set(err, MECH_ENUMERIC, NULL,
                                    "non-finite event function at t = %.9g s", t);
                goto fail;
            }
            if (crossed(g_prev, g_new, p->event_direction)) {
                double t_stop = t;
                if (g_new != 0.0) {
                    st = locate_event(&s, tprev, s.yprev, g_prev, t, g_new, &t_stop);
                    if (st != MECH_OK) goto fail;
                }
                if ((st = emit_samples(&s, tprev, s.yprev, t, s.y, t_stop)) != MECH_OK) goto fail;
                if ((st = substep(&s, tprev, s.yprev, t_stop, p->y_stop)) != MECH_OK) goto fail;
                if ((st = observe(&s, t_stop, p->y_stop)) != MECH_OK) goto fail;
                res->stopped = 1;
                res->t_stop = t_stop;
                res->t_reached = t_stop;
                break;
            }
            g_prev = g_new;
        }
        /* Observed only when the step end is part of the answer (not past a stop). */
        if ((st = observe(&s, t, s.y)) != MECH_OK) goto fail;
        if ((st = emit_samples(&s, tprev, s.yprev, t, s.y, t)) != MECH_OK) goto fail;
        if (s.dense) dense_shift(&s, tprev);
    }
    m->free(s.ws);
    free(block);
    return MECH_OK;

fail:
    fill_progress(err, st, res->stats.steps, t, p->t_end);
    m->reset(s.ws);
    m->free(s.ws);
    free(block);
    return st;
}
