/* top.c — the heavy symmetric top with a fixed tip, integrated as a rigid body
 * (quaternion + body omega, gravity torque about the tip) so that theta = 0 is
 * not singular; conserved p_phi, p_psi, E; turning points of the nutation from
 * the cubic in u = cos theta; sleeping-top stability; steady precession.
 * See mech/rigid/top.h (notes §2.10). */
#include "mech/rigid/top.h"
#include "mech/base/constants.h"

#include <gsl/gsl_math.h>
#include <gsl/gsl_poly.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/rotation/attitude.h"

static enum mech_status validate(const struct mech_top_problem *p, struct mech_error *err)
{
    if (!(isfinite(p->I1) && p->I1 > 0))
        return mech_error_set(err, MECH_EDOMAIN, "I1", "I1 must be finite and > 0");
    if (!(isfinite(p->I3) && p->I3 > 0))
        return mech_error_set(err, MECH_EDOMAIN, "I3", "I3 must be finite and > 0");
    if (!(isfinite(p->mass) && p->mass > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "mass must be finite and > 0");
    if (!(isfinite(p->distance) && p->distance >= 0))
        return mech_error_set(err, MECH_EDOMAIN, "distance", "distance must be finite and >= 0");
    if (!(isfinite(p->g) && p->g >= 0))
        return mech_error_set(err, MECH_EDOMAIN, "g", "g must be finite and >= 0");
    if (p->I3 > 2 * p->I1 * (1 + 1e-12))
        return mech_error_set(err, MECH_EDOMAIN, "I3",
                              "I3 = %.17g exceeds 2 I1 = %.17g: no body has such moments "
                              "(triangle inequality I3 <= I1 + I2)", p->I3, 2 * p->I1);
    double mh2 = p->mass * p->distance * p->distance;
    if (p->I1 < mh2 * (1 - 1e-12))
        return mech_error_set(err, MECH_EDOMAIN, "I1",
                              "I1 = %.17g about the tip is below M h^2 = %.17g (parallel axes: "
                              "I1 = I1_cm + M h^2 with I1_cm >= 0)", p->I1, mh2);
    const double a[6] = {p->phi, p->theta, p->psi, p->phi_dot, p->theta_dot, p->psi_dot};
    static const char *const names[6] = {"phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot"};
    for (int i = 0; i < 6; i++)
        if (!isfinite(a[i])) return mech_error_set(err, MECH_EINVAL, names[i], "must be finite");
    if (!(p->theta >= 0 && p->theta <= MECH_PI))
        return mech_error_set(err, MECH_EINVAL, "theta", "theta must be in [0, pi], got %.17g",
                              p->theta);
    if (!(isfinite(p->t_end) && p->t_end > 0))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0");
    if (p->samples < 2 || p->samples > 100000)
        return mech_error_set(err, MECH_EINVAL, "samples", "samples must be in 2..100000");
    return MECH_OK;
}

/* body omega from Euler rates (notes §2.7):
 * w = (phi' s_th s_psi + th' c_psi, phi' s_th c_psi - th' s_psi, phi' c_th + psi') */
static struct mech_vec3 body_omega(const struct mech_top_problem *p)
{
    const double st = sin(p->theta), ct = cos(p->theta), sp = sin(p->psi), cp = cos(p->psi);
    return mech_vec3_make(p->phi_dot * st * sp + p->theta_dot * cp,
                          p->phi_dot * st * cp - p->theta_dot * sp, p->phi_dot * ct + p->psi_dot);
}

double mech_top_rate_scale(const struct mech_top_problem *p)
{
    double W = fmax(mech_vec3_norm(body_omega(p)), sqrt(p->mass * p->g * p->distance / p->I1));
    if (!(W > 0) || !isfinite(W)) W = 1.0 / p->t_end;
    return W;
}

double mech_top_cost_span(const struct mech_top_problem *p)
{
    if (!p || !(p->I1 > 0.0) || !(p->t_end > 0.0) || !isfinite(p->t_end)) return 0.0;
    const struct mech_vec3 w = body_omega(p);
    const double mgh = p->mass * p->g * p->distance;
    double u_min = -1.0;
    struct mech_top_turning tp;
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_top_turning_points(p, &tp, &e) == MECH_OK && isfinite(tp.u_min))
        u_min = fmax(-1.0, fmin(tp.u_min, cos(p->theta)));
    const double wp2 = w.x * w.x + w.y * w.y + 2.0 * mgh * (cos(p->theta) - u_min) / p->I1;
    const double rate = sqrt(fmax(wp2, 0.0)) + 0.5 * fabs(w.z);
    const double cs = p->t_end * rate;
    return cs > 0.0 && isfinite(cs) ? cs : 0.0;
}

static double fpoly(const double c[4], double u) { return ((c[3] * u + c[2]) * u + c[1]) * u + c[0]; }
static double dfpoly(const double c[4], double u) { return (3 * c[3] * u + 2 * c[2]) * u + c[1]; }

static double polish(const double c[4], double u)
{
    for (int i = 0; i < 4; i++) {
        double d = dfpoly(c, u);
        if (d == 0) break;
        double un = u - fpoly(c, u) / d;
        if (!isfinite(un) || fabs(fpoly(c, un)) >= fabs(fpoly(c, u))) break;
        u = un;
    }
    return u;
}

enum mech_status mech_top_turning_points(const struct mech_top_problem *p,
                                         struct mech_top_turning *out, struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    enum mech_status st = validate(p, err);
    if (st != MECH_OK) return st;
    memset(out, 0, sizeof *out);
    const double I1 = p->I1, I3 = p->I3, mgh = p->mass * p->g * p->distance;
    const double s0 = sin(p->theta), u0 = cos(p->theta);
    const double w3 = p->phi_dot * u0 + p->psi_dot;
    const double p_psi = I3 * w3;
    /* Work in x = 1 - sigma u (sigma = +1 for the upper half, -1 for the lower),
     * the distance from the nearer pole, so turning points near theta = 0 or pi
     * keep their relative precision (in u they would be lost to cancellation):
     * u = sigma (1 - x), 1 - u^2 = x (2 - x), and
     *   f = x (2 - x) (A + B x) - (D + C x)^2
     *     = -B x^3 + (2B - A - C^2) x^2 + (2A - 2CD) x - D^2,
     *   A = alpha - sigma beta, B = sigma beta, C = sigma a, D = b - sigma a,
     * with A and D formed from the initial state without cancellation:
     *   I1 A = I1 (theta'^2 + phi'^2 s^2) - 2 sigma M g h x0,
     *   I1 D = p_phi - sigma p_psi = I1 s^2 phi' - sigma p_psi x0,
     *   x0 = 1 - sigma u0 = 2 sin^2(theta0/2) (sigma = 1) or 2 cos^2(theta0/2). */
    const double sigma = u0 >= 0 ? 1.0 : -1.0;
    const double x0 = sigma > 0 ? 2 * pow(sin(0.5 * p->theta), 2) : 2 * pow(cos(0.5 * p->theta), 2);
    const double kin = p->theta_dot * p->theta_dot + p->phi_dot * p->phi_dot * s0 * s0;
    const double A = kin - 2 * sigma * mgh * x0 / I1, B = sigma * 2 * mgh / I1;
    const double C = sigma * p_psi / I1, D = s0 * s0 * p->phi_dot - sigma * p_psi * x0 / I1;
    const double c[4] = {-D * D, 2 * A - 2 * C * D, 2 * B - A - C * C, -B};
    for (int i = 0; i < 4; i++)
        if (!isfinite(c[i]))
            return mech_error_set(err, MECH_ENUMERIC, NULL, "the turning-point cubic overflows");
    double r[3];
    int n;
    double lo, hi; /* the x-interval of the motion, lo <= x0 <= hi */
    const double fx0 = s0 * s0 * p->theta_dot * p->theta_dot; /* = u'^2 at t = 0 */
    if (fx0 == 0) {
        /* x0 is a root: f = (x - x0) g, g = c3 x^2 + (c2 + c3 x0) x + (c1 + x0 (c2 + c3 x0)) */
        const double g2 = c[3], g1 = c[2] + c[3] * x0, g0 = c[1] + x0 * g1;
        double q[2];
        int nq = g2 != 0 ? gsl_poly_solve_quadratic(g2, g1, g0, &q[0], &q[1])
                         : (g1 != 0 ? (q[0] = -g0 / g1, 1) : 0);
        const double gx0 = (g2 * x0 + g1) * x0 + g0; /* = f'(x0) */
        double other = x0;
        int found = 0;
        for (int i = 0; i < nq; i++) {
            double v = polish(c, q[i]);
            if (gx0 > 0 && v > x0 && (!found || v < other)) other = v, found = 1;
            if (gx0 < 0 && v < x0 && (!found || v > other)) other = v, found = 1;
        }
        /* a double root (steady precession) up to round-off */
        if (gx0 == 0 || !found || fabs(other - x0) <= 1e-13 * fmax(x0, 1e-300)) other = x0;
        out->steady = other == x0;
        lo = fmin(x0, other);
        hi = fmax(x0, other);
        n = 0;
        r[n++] = x0;
        for (int i = 0; i < nq; i++) r[n++] = polish(c, q[i]);
    } else {
        if (c[3] != 0)
            n = gsl_poly_solve_cubic(c[2] / c[3], c[1] / c[3], c[0] / c[3], &r[0], &r[1], &r[2]);
        else /* no gravity torque (g = 0 or h = 0): a quadratic */
            n = gsl_poly_solve_quadratic(c[2], c[1], c[0], &r[0], &r[1]);
        int flo = 0, fhi = 0;
        lo = 0;
        hi = 2;
        for (int i = 0; i < n; i++) {
            r[i] = polish(c, r[i]);
            if (r[i] < x0 && (!flo || r[i] > lo)) lo = r[i], flo = 1;
            if (r[i] > x0 && (!fhi || r[i] < hi)) hi = r[i], fhi = 1;
        }
        out->steady = 0;
    }
    lo = fmax(0.0, fmin(2.0, lo));
    hi = fmax(0.0, fmin(2.0, hi));
    for (int i = 0; i < n; i++) r[i] = sigma * (1 - r[i]); /* back to u */
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (r[j] < r[i]) {
                double t = r[i];
                r[i] = r[j];
                r[j] = t;
            }
    out->n_roots = n;
    for (int i = 0; i < n; i++) out->roots[i] = r[i];
    /* theta from x without acos near the poles; theta0 itself kept exact */
    double tlo = lo == x0 ? p->theta : 2 * asin(sqrt(0.5 * lo));
    double thi = hi == x0 ? p->theta : 2 * asin(sqrt(0.5 * hi));
    if (sigma < 0) {
        if (lo != x0) tlo = MECH_PI - tlo;
        if (hi != x0) thi = MECH_PI - thi;
    }
    out->theta_min = fmin(tlo, thi);
    out->theta_max = fmax(tlo, thi);
    if (out->theta_min == out->theta_max) out->steady = 1;
    out->u_min = cos(out->theta_max);
    out->u_max = cos(out->theta_min);
    out->sigma = sigma;
    out->x_lo = out->steady ? x0 : lo;
    out->x_hi = out->steady ? x0 : hi;
    for (int i = 0; i < 4; i++) out->cubic[i] = c[i];
    out->phi_d = D; /* b - sigma a */
    out->phi_c = C; /* sigma a: b - a u = D + C x */
    mech_top_nutation(out);
    return MECH_OK;
}

/* ---- integration ------------------------------------------------------------------ */

struct top_ctx {
    const struct mech_top_problem *p;
    struct mech_top_result *res;
    double W, Imax, j1, j3, kappa; /* kappa = M g h / (Imax W^2) */
    struct mech_error *err;
    /* Euler angles followed continuously through every observer call (step
     * ends and samples), so phi and psi unwrap correctly even when the top
     * turns by more than pi between samples */
    double prev_phi, prev_psi;
    double *unw;        /* [2 n]: unwrapped phi, psi at sample k */
    unsigned char *have;/* [n]: sample k recorded */
    size_t n;
    double ds;          /* sample spacing, dimensionless time */
};

static double unwrap(double x, double ref)
{
    return x - 2 * MECH_PI * round((x - ref) / (2 * MECH_PI));
}

static struct mech_vec3 z_body(const double *q)
{
    /* space z in body axes = third column of R (normalised q) */
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    return mech_vec3_make(2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y));
}

static enum mech_status top_rhs(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const struct top_ctx *c = params;
    struct mech_vec3 w = mech_vec3_make(y[4], y[5], y[6]);
    mech_attitude_quat_rate(y, w, dy);
    /* gravity torque about the tip: G = -M g h e3 x z_b = M g h (z_b.y, -z_b.x, 0) */
    struct mech_vec3 zb = z_body(y);
    const double g1 = c->kappa * zb.y, g2 = -c->kappa * zb.x;
    /* Euler's equations (notes §2.8) with I1 = I2 */
    dy[4] = ((c->j1 - c->j3) * w.y * w.z + g1) / c->j1;
    dy[5] = ((c->j3 - c->j1) * w.z * w.x + g2) / c->j1;
    dy[6] = 0;
    return MECH_OK;
}

/* physical p_phi, p_psi, E and theta of a dimensionless state */
static void top_invariants(const struct top_ctx *c, const double *y, double *pphi, double *ppsi,
                           double *E, double *theta)
{
    const struct mech_top_problem *p = c->p;
    struct mech_vec3 zb = z_body(y);
    const double W = c->W, w1 = y[4] * W, w2 = y[5] * W, w3 = y[6] * W;
    *pphi = p->I1 * (w1 * zb.x + w2 * zb.y) + p->I3 * w3 * zb.z;
    *ppsi = p->I3 * w3;
    *E = 0.5 * (p->I1 * (w1 * w1 + w2 * w2) + p->I3 * w3 * w3) +
         p->mass * p->g * p->distance * zb.z;
    double n = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
    *theta = 2 * atan2(hypot(y[1], y[2]) / n, hypot(y[0], y[3]) / n);
}

static enum mech_status top_observe(double s, const double *y, void *params)
{
    struct top_ctx *c = params;
    struct mech_top_result *r = c->res;
    double pphi, ppsi, E, th;
    top_invariants(c, y, &pphi, &ppsi, &E, &th);
    r->max_p_phi_drift = fmax(r->max_p_phi_drift, fabs(pphi - r->p_phi0) / r->L_scale);
    r->max_p_psi_drift = fmax(r->max_p_psi_drift, fabs(ppsi - r->p_psi0) / r->L_scale);
    r->max_E_drift = fmax(r->max_E_drift, fabs(E - r->E0) / r->E_scale);
    r->theta_min_measured = fmin(r->theta_min_measured, th);
    r->theta_max_measured = fmax(r->theta_max_measured, th);
    double qn = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
    r->max_quaternion_norm_drift = fmax(r->max_quaternion_norm_drift, fabs(qn - 1));
    if (!(isfinite(qn) && qn > 0))
        return mech_error_set(c->err, MECH_ENUMERIC, NULL, "the attitude quaternion degenerated");
    double ph, t2, ps;
    mech_attitude_euler_zxz(y, c->prev_psi, &ph, &t2, &ps, NULL);
    c->prev_psi = unwrap(ps, c->prev_psi);
    c->prev_phi = unwrap(ph, c->prev_phi);
    double kf = round(s / c->ds);
    if (kf >= 0 && kf < (double)c->n && fabs(s - kf * c->ds) <= 1e-9 * c->ds) {
        size_t k = (size_t)kf;
        if (!c->have[k]) {
            c->have[k] = 1;
            c->unw[2 * k] = c->prev_phi;
            c->unw[2 * k + 1] = c->prev_psi;
        }
    }
    return MECH_OK;
}

void mech_top_closed_forms(const struct mech_top_problem *p, struct mech_top_result *res)
{
    const double mgh = p->mass * p->g * p->distance;
    const struct mech_vec3 w0 = body_omega(p);
    /* sleeping top, notes §2.11 problem 11 */
    res->sleep_lhs = p->I3 * p->I3 * w0.z * w0.z;
    res->sleep_rhs = 4 * p->I1 * mgh;
    res->sleep_stable = res->sleep_lhs > res->sleep_rhs;
    res->critical_omega3 = 2 * sqrt(p->I1 * mgh) / p->I3;
    /* steady precession at theta0: I1 cos(th) x^2 - I3 w3 x + M g h = 0. The
     * root of the larger |x| is q / (I1 cos th) with q = (B + sgn(B) sqrt(disc)) / 2
     * (no cancellation: both terms have B's sign), the other is M g h / q by
     * Vieta's product (x1 x2 = M g h / (I1 cos th)), never (B - sqrt(disc)) / 2,
     * which loses the slow rate's digits when I3^2 w3^2 >> 4 I1 M g h cos th. */
    const double ct = cos(p->theta), B = p->I3 * w0.z;
    res->precession_gyroscopic = B != 0 ? mgh / B : NAN;
    res->precession_slow = res->precession_fast = NAN;
    if (ct * p->I1 == 0 || fabs(ct) < 1e-300) {
        if (B != 0) res->precession_slow = mgh / B;
    } else {
        double disc = B * B - 4 * p->I1 * ct * mgh;
        if (disc >= 0) {
            double q = 0.5 * (B + (B >= 0 ? 1 : -1) * sqrt(disc));
            if (q != 0) {
                double r1 = mgh / q, r2 = q / (p->I1 * ct);
                res->precession_slow = fabs(r1) <= fabs(r2) ? r1 : r2;
                res->precession_fast = fabs(r1) <= fabs(r2) ? r2 : r1;
            }
        }
    }
}

enum mech_status mech_top_integrate(const struct mech_top_problem *p,
                                    const struct mech_budget *budget,
                                    struct mech_top_result *res, struct mech_error *err)
{
    if (!p || !res || !budget) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    enum mech_status s = mech_top_turning_points(p, &res->turning, err);
    if (s != MECH_OK) return s;
    const struct mech_integrator *m = p->method ? mech_ode_method_find(p->method) : NULL;
    if (!m)
        return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method \"%s\"",
                              p->method ? p->method : "(null)");
    if (mech_ode_method_describe(m).second_order)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "%s needs a second-order system q'' = a(t, q, v); the top is "
                              "integrated as a first-order rigid body (quaternion + omega)",
                              p->method);
    struct top_ctx c;
    memset(&c, 0, sizeof c);
    c.p = p;
    c.res = res;
    c.err = err;
    c.W = mech_top_rate_scale(p);
    c.Imax = fmax(p->I1, p->I3);
    c.j1 = p->I1 / c.Imax;
    c.j3 = p->I3 / c.Imax;
    const double mgh = p->mass * p->g * p->distance;
    c.kappa = mgh / (c.Imax * c.W * c.W);

    struct mech_vec3 w0 = body_omega(p);
    double y0[7];
    mech_attitude_from_euler_zxz(p->phi, p->theta, p->psi, y0);
    y0[4] = w0.x / c.W;
    y0[5] = w0.y / c.W;
    y0[6] = w0.z / c.W;

    res->rate_scale = c.W;
    res->omega3 = w0.z;
    double th0;
    res->max_p_phi_drift = res->max_p_psi_drift = res->max_E_drift = 0;
    res->max_quaternion_norm_drift = 0;
    res->L_scale = 1, res->E_scale = 1;
    top_invariants(&c, y0, &res->p_phi0, &res->p_psi0, &res->E0, &th0);
    struct mech_vec3 Lb = mech_vec3_make(p->I1 * w0.x, p->I1 * w0.y, p->I3 * w0.z);
    res->L_scale = mech_vec3_norm(Lb);
    if (!(res->L_scale > 0)) res->L_scale = p->I1 * c.W;
    res->E_scale = 0.5 * (p->I1 * (w0.x * w0.x + w0.y * w0.y) + p->I3 * w0.z * w0.z) + mgh;
    if (!(res->E_scale > 0)) res->E_scale = 0.5 * p->I1 * c.W * c.W;
    res->theta_min_measured = res->theta_max_measured = p->theta;
    mech_top_closed_forms(p, res);

    const size_t n = p->samples, dim = 7;
    double *sy = malloc(n * dim * sizeof *sy), *stt = malloc(n * sizeof *stt);
    c.unw = malloc(2 * n * sizeof *c.unw);
    c.have = calloc(n, 1);
    c.n = n;
    c.ds = p->t_end * c.W / (double)(n - 1);
    c.prev_phi = p->phi;
    c.prev_psi = p->psi;
    if (!sy || !stt || !c.unw || !c.have) {
        free(sy);
        free(stt);
        free(c.unw);
        free(c.have);
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
    }
    struct mech_ode_system sys = {dim, top_rhs, NULL, 0, &c, NULL, 0, NULL};
    struct mech_ode_problem op;
    memset(&op, 0, sizeof op);
    op.sys = &sys;
    op.method = m;
    op.opt = p->opt;
    op.opt.dt = p->opt.dt * c.W;
    op.t_end = p->t_end * c.W;
    op.y0 = y0;
    op.n_samples = n;
    op.sample_t = stt;
    op.sample_y = sy;
    op.observe = top_observe;
    op.observe_params = &c;
    struct mech_ode_result orr;
    memset(&orr, 0, sizeof orr);
    s = mech_ode_solve(&op, budget, &orr, err);
    res->stats = orr.stats;
    if (s != MECH_OK && err) {
        err->progress.t_reached /= c.W;
        err->progress.t_target = p->t_end;
    }
    double prev_phi = p->phi, prev_psi = p->psi;
    for (size_t i = 0; i < orr.n_samples; i++) {
        const double *y = sy + i * dim;
        double ph, th, ps;
        int pole;
        if (c.have[i]) { /* the branch followed through the steps */
            prev_phi = c.unw[2 * i];
            prev_psi = c.unw[2 * i + 1];
        }
        mech_attitude_euler_zxz(y, prev_psi, &ph, &th, &ps, &pole);
        ps = unwrap(ps, prev_psi);
        ph = unwrap(ph, prev_phi);
        prev_phi = ph;
        prev_psi = ps;
        if (res->t) res->t[i] = stt[i] / c.W;
        if (res->theta) res->theta[i] = th;
        if (res->phi) res->phi[i] = ph;
        if (res->psi) res->psi[i] = ps;
        if (res->phi_plus_psi) res->phi_plus_psi[i] = ph + ps;
        if (res->at_pole) res->at_pole[i] = pole;
        if (res->axis) res->axis[i] = mech_attitude_to_space(y, mech_vec3_make(0, 0, 1));
        if (i == orr.n_samples - 1) {
            double th2;
            top_invariants(&c, y, &res->p_phi_final, &res->p_psi_final, &res->E_final, &th2);
            res->precession_measured = stt[i] > 0 ? (ph - p->phi) / (stt[i] / c.W) : NAN;
        }
    }
    res->n_samples = orr.n_samples;
    free(sy);
    free(stt);
    free(c.unw);
    free(c.have);
    return s;
}

enum mech_status mech_top_pilot_run(void *ctx, const char *method,
                                    const struct mech_ode_options *opt, double fraction,
                                    const struct mech_budget *budget,
                                    struct mech_ode_stats *stats, double *y_end, size_t *dim,
                                    struct mech_error *err)
{
    const struct mech_top_problem *p0 = ctx;
    if (!p0 || !method || !opt || !stats || !y_end || !dim || !(fraction > 0.0 && fraction <= 1.0))
        return mech_error_set(err, MECH_EINVAL, NULL, "invalid pilot arguments");
    *dim = 0;
    struct mech_top_problem p = *p0;
    p.t_end = p0->t_end * fraction;
    p.samples = 2;
    p.method = method;
    p.opt = *opt;
    double t[2], th[2], ph[2], ps[2];
    struct mech_top_result r;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.theta = th;
    r.phi = ph;
    r.psi = ps;
    enum mech_status st = mech_top_integrate(&p, budget, &r, err);
    *stats = r.stats;
    if (st != MECH_OK) return st;
    if (r.n_samples != 2) return mech_error_set(err, MECH_EINTERNAL, NULL, "pilot samples");
    y_end[0] = th[1];
    y_end[1] = ph[1];
    y_end[2] = ps[1];
    *dim = 3;
    return MECH_OK;
}
