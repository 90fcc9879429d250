/* rigid_rotation.c — Euler's equations with a quaternion attitude on the ODE
 * driver of mech/ode/ode.h, and the exact torque-free solution in Jacobi elliptic
 * functions (see mech/rigid/rigid_rotation.h; notes §2.7–2.9, Landau & Lifshitz §37).
 */
#include "mech/rigid/rigid_rotation.h"
#include "mech/base/constants.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/rotation/attitude.h"

/* ---- exact solution ----------------------------------------------------------- */

static double sgn(double x) { return x < 0 ? -1.0 : 1.0; }

/* K(m) = pi / (2 AGM(1, k')) with k' from 1 - m computed without cancellation
 * (Abramowitz & Stegun 17.6.1): full precision as m -> 1, where
 * gsl_sf_ellint_Kcomp(k), which forms 1 - k^2 itself, loses digits. */
static double k_agm(double kprime)
{
    double a = 1.0, b = kprime;
    for (int i = 0; i < 60 && fabs(a - b) > 1e-16 * a; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return MECH_PI / (a + b);
}

/* F(phi | m) for phi in [-pi, pi], continued beyond pi/2 by F(pi - phi) = 2K - F(phi). */
static enum mech_status ellint_f(double phi, double k, double K, double *out, struct mech_error *err)
{
    gsl_sf_result r;
    double a = fabs(phi), sign = phi < 0 ? -1.0 : 1.0;
    int beyond = a > MECH_PI_2;
    if (beyond) a = MECH_PI - a;
    int st = gsl_sf_ellint_F_e(a, k, GSL_PREC_DOUBLE, &r);
    if (st != GSL_SUCCESS || !isfinite(r.val))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "gsl_sf_ellint_F failed: %s",
                              gsl_strerror(st));
    *out = sign * (beyond ? 2 * K - r.val : r.val);
    return MECH_OK;
}

enum mech_status mech_rigid_exact_init(const double I[3], struct mech_vec3 w0,
                                       struct mech_rigid_exact *ex, struct mech_error *err)
{
    if (!I || !ex) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    for (int i = 0; i < 3; i++)
        if (!(isfinite(I[i]) && I[i] > 0))
            return mech_error_set(err, MECH_EINVAL, "moments", "moments must be finite and > 0");
    if (!mech_vec3_isfinite(w0)) return mech_error_set(err, MECH_EINVAL, "omega", "omega must be finite");
    memset(ex, 0, sizeof *ex);
    /* sort ascending (stable), build the signed permutation P (det +1) */
    int o[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 2 - i; j++)
            if (I[o[j]] > I[o[j + 1]]) {
                int t = o[j];
                o[j] = o[j + 1];
                o[j + 1] = t;
            }
    int inversions = (o[0] > o[1]) + (o[0] > o[2]) + (o[1] > o[2]);
    for (int r = 0; r < 3; r++) {
        ex->p[r][o[r]] = (r == 2 && (inversions & 1)) ? -1.0 : 1.0;
        ex->J[r] = I[o[r]];
    }
    const double w[3] = {w0.x, w0.y, w0.z};
    for (int r = 0; r < 3; r++) ex->u0[r] = ex->p[r][o[r]] * w[o[r]];
    const double *J = ex->J, *u = ex->u0;
    ex->s = ex->s_cn = 1.0;
    ex->L2 = J[0] * J[0] * u[0] * u[0] + J[1] * J[1] * u[1] * u[1] + J[2] * J[2] * u[2] * u[2];
    ex->twoE = J[0] * u[0] * u[0] + J[1] * u[1] * u[1] + J[2] * u[2] * u[2];
    ex->kind = MECH_RIGID_EXACT_STEADY;

    const double tol = MECH_RIGID_SYMMETRIC_RTOL * J[2];
    const int eq12 = J[1] - J[0] <= tol, eq23 = J[2] - J[1] <= tol;
    if (ex->L2 == 0 || (eq12 && eq23)) return MECH_OK;
    if (eq12 || eq23) {
        /* notes §2.9: the pair normal to the symmetry axis turns at
         * Omega = (I_sym - I_perp) / I_perp w_sym (sym axis 3), and for
         * symmetry axis 1: d/dt (u3 + i u2) = i Omega' (u3 + i u2),
         * Omega' = (J_perp - J1) / J_perp u1. */
        ex->kind = MECH_RIGID_EXACT_SYMMETRIC;
        if (eq12) {
            double ja = 0.5 * (J[0] + J[1]);
            ex->sym_axis = 2;
            ex->lambda = (J[2] - ja) / ja * u[2];
        } else {
            double jb = 0.5 * (J[1] + J[2]);
            ex->sym_axis = 0;
            ex->lambda = (jb - J[0]) / jb * u[0];
        }
        ex->period = ex->lambda != 0 ? 2 * MECH_PI / fabs(ex->lambda) : 0;
        return MECH_OK;
    }
    /* D_j = L^2 - 2 E J_j = sum_i J_i (J_i - J_j) u_i^2 */
    const double D1 = J[1] * (J[1] - J[0]) * u[1] * u[1] + J[2] * (J[2] - J[0]) * u[2] * u[2];
    const double D2 = J[0] * (J[0] - J[1]) * u[0] * u[0] + J[2] * (J[2] - J[1]) * u[2] * u[2];
    const double mD3 = J[0] * (J[2] - J[0]) * u[0] * u[0] + J[1] * (J[2] - J[1]) * u[1] * u[1];
    if (D1 == 0 || mD3 == 0 || (u[0] == 0 && u[2] == 0)) return MECH_OK; /* about a principal axis */
    const double J123 = J[0] * J[1] * J[2];
    if (fabs(D2) <= MECH_RIGID_SEPARATRIX_RTOL * ex->L2) {
        /* k = 1: u1 = s1 A1 sech, u2 = s1 s3 A2 tanh, u3 = s3 A3 sech (L&L §37) */
        ex->kind = MECH_RIGID_EXACT_SEPARATRIX;
        ex->cn_axis = 0;
        ex->dn_axis = 2;
        ex->A[0] = sqrt(mD3 / (J[0] * (J[2] - J[0])));
        ex->A[1] = sqrt(mD3 / (J[1] * (J[2] - J[1])));
        ex->A[2] = sqrt(D1 / (J[2] * (J[2] - J[0])));
        ex->lambda = sqrt((J[2] - J[1]) * D1 / J123);
        ex->s_cn = sgn(u[0]);
        ex->s = sgn(u[2]);
        ex->m = 1.0;
        /* sinh(tau0) = tanh / sech, each from its own component: well conditioned */
        double th = ex->s_cn * ex->s * u[1] / ex->A[1], sh = fabs(u[0]) / ex->A[0];
        ex->tau0 = asinh(th / sh);
        return MECH_OK;
    }
    ex->kind = MECH_RIGID_EXACT_ELLIPTIC;
    if (D2 > 0) {
        ex->cn_axis = 0;
        ex->dn_axis = 2;
        ex->A[0] = sqrt(mD3 / (J[0] * (J[2] - J[0])));
        ex->A[1] = sqrt(mD3 / (J[1] * (J[2] - J[1])));
        ex->A[2] = sqrt(D1 / (J[2] * (J[2] - J[0])));
        ex->lambda = sqrt((J[2] - J[1]) * D1 / J123);
        ex->m = (J[1] - J[0]) * mD3 / ((J[2] - J[1]) * D1);
        ex->kprime2 = (J[2] - J[0]) * D2 / ((J[2] - J[1]) * D1);
        ex->s = sgn(u[2]);
    } else {
        ex->cn_axis = 2;
        ex->dn_axis = 0;
        ex->A[2] = sqrt(D1 / (J[2] * (J[2] - J[0])));
        ex->A[1] = sqrt(D1 / (J[1] * (J[1] - J[0])));
        ex->A[0] = sqrt(mD3 / (J[0] * (J[2] - J[0])));
        ex->lambda = sqrt((J[1] - J[0]) * mD3 / J123);
        ex->m = (J[2] - J[1]) * D1 / ((J[1] - J[0]) * mD3);
        ex->kprime2 = (J[2] - J[0]) * (-D2) / ((J[1] - J[0]) * mD3);
        ex->s = sgn(u[0]);
    }
    if (ex->m > 1) ex->m = 1; /* round-off; kprime2 carries the distance to 1 */
    const double k = sqrt(ex->m);
    if (ex->m < 0.9) {
        gsl_sf_result r;
        int st = gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r);
        if (st != GSL_SUCCESS || !isfinite(r.val))
            return mech_error_set(err, MECH_ENUMERIC, NULL, "gsl_sf_ellint_Kcomp failed: %s",
                                  gsl_strerror(st));
        ex->K = r.val;
    } else {
        ex->K = k_agm(sqrt(ex->kprime2));
    }
    const int c = ex->cn_axis;
    double cn0 = u[c] / ex->A[c], sn0 = ex->s * u[1] / ex->A[1];
    enum mech_status st = ellint_f(atan2(sn0, cn0), k, ex->K, &ex->tau0, err);
    if (st != MECH_OK) return st;
    ex->period = 4 * ex->K / ex->lambda;
    ex->flip_interval = 2 * ex->K / ex->lambda;
    if (!isfinite(ex->period) || !isfinite(ex->tau0))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "the exact solution's period is not finite");
    return MECH_OK;
}

enum mech_status mech_rigid_exact_omega(const struct mech_rigid_exact *ex, double t,
                                        struct mech_vec3 *wout, struct mech_error *err)
{
    double u[3] = {ex->u0[0], ex->u0[1], ex->u0[2]};
    switch (ex->kind) {
    case MECH_RIGID_EXACT_STEADY:
        break;
    case MECH_RIGID_EXACT_SYMMETRIC: {
        /* (u_a + i u_b)(t) = (u_a + i u_b)(0) e^{i Omega t} */
        int a = ex->sym_axis == 2 ? 0 : 2, b = 1;
        double ph = fmod(ex->lambda * t, 2 * MECH_PI), c = cos(ph), s = sin(ph);
        u[a] = ex->u0[a] * c - ex->u0[b] * s;
        u[b] = ex->u0[a] * s + ex->u0[b] * c;
        break;
    }
    case MECH_RIGID_EXACT_SEPARATRIX: {
        double tau = ex->lambda * t + ex->tau0, e = exp(-2 * fabs(tau));
        double sech = 2 * exp(-fabs(tau)) / (1 + e), th = tanh(tau);
        u[0] = ex->s_cn * ex->A[0] * sech;
        u[1] = ex->s_cn * ex->s * ex->A[1] * th;
        u[2] = ex->s * ex->A[2] * sech;
        break;
    }
    case MECH_RIGID_EXACT_ELLIPTIC: {
        /* reduce the phase modulo one period 4K */
        double P = 4 * ex->K, tau = fmod(ex->lambda * t, P) + ex->tau0;
        tau -= P * floor(tau / P);
        double sn, cn, dn;
        int st = gsl_sf_elljac_e(tau, ex->m, &sn, &cn, &dn);
        if (st != GSL_SUCCESS)
            return mech_error_set(err, MECH_ENUMERIC, NULL, "gsl_sf_elljac_e failed: %s",
                                  gsl_strerror(st));
        u[ex->cn_axis] = ex->A[ex->cn_axis] * cn;
        u[1] = ex->s * ex->A[1] * sn;
        u[ex->dn_axis] = ex->s * ex->A[ex->dn_axis] * dn;
        break;
    }
    }
    /* w = P^T u */
    double w[3] = {0, 0, 0};
    for (int r = 0; r < 3; r++)
        for (int i = 0; i < 3; i++) w[i] += ex->p[r][i] * u[r];
    *wout = mech_vec3_make(w[0], w[1], w[2]);
    if (!mech_vec3_isfinite(*wout))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "the exact solution is not finite at t = %g", t);
    return MECH_OK;
}

/* ---- integration -------------------------------------------------------------- */

struct rr_ctx {
    double j[3];          /* moments / I_max */
    double Imax, W;       /* scales */
    enum mech_rigid_torque_frame tf;
    struct mech_vec3 g;   /* dimensionless torque G / (I_max W^2) */
    const struct mech_rigid_problem *p;
    struct mech_rigid_result *res;
    double L0n;           /* |L0| or the L scale */
    double Lscale;        /* denominator of the L-vector drift */
    struct mech_error *err;
};

static enum mech_status rr_rhs(double t, const double *y, double *dy, void *params)
{
    (void)t;
    const struct rr_ctx *c = params;
    struct mech_vec3 w = mech_vec3_make(y[4], y[5], y[6]);
    mech_attitude_quat_rate(y, w, dy);
    struct mech_vec3 g = c->g;
    if (c->tf == MECH_RIGID_TORQUE_SPACE) g = mech_attitude_to_body(y, c->g);
    /* Euler's equations, notes §2.8: I1 w1' = (I2 - I3) w2 w3 + G1 (cyclic) */
    dy[4] = ((c->j[1] - c->j[2]) * w.y * w.z + g.x) / c->j[0];
    dy[5] = ((c->j[2] - c->j[0]) * w.z * w.x + g.y) / c->j[1];
    dy[6] = ((c->j[0] - c->j[1]) * w.x * w.y + g.z) / c->j[2];
    return MECH_OK;
}

/* physical L (space axes) and T of a dimensionless state */
static void rr_invariants(const struct rr_ctx *c, const double *y, struct mech_vec3 *L, double *T)
{
    const double *I = c->p->moments, W = c->W;
    struct mech_vec3 Lb = mech_vec3_make(I[0] * W * y[4], I[1] * W * y[5], I[2] * W * y[6]);
    *L = mech_attitude_to_space(y, Lb);
    *T = 0.5 * W * W * (I[0] * y[4] * y[4] + I[1] * y[5] * y[5] + I[2] * y[6] * y[6]);
}

static enum mech_status rr_observe(double s, const double *y, void *params)
{
    struct rr_ctx *c = params;
    struct mech_rigid_result *r = c->res;
    struct mech_vec3 L;
    double T;
    rr_invariants(c, y, &L, &T);
    double qn = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
    double dl = fabs(mech_vec3_norm(L) - mech_vec3_norm(r->L0));
    double dT = fabs(T - r->T0);
    r->max_L_norm_drift = fmax(r->max_L_norm_drift, r->L0.x == 0 && r->L0.y == 0 && r->L0.z == 0
                                                        ? dl : dl / mech_vec3_norm(r->L0));
    r->max_T_drift = fmax(r->max_T_drift, r->T0 > 0 ? dT / r->T0 : dT);
    r->max_quaternion_norm_drift = fmax(r->max_quaternion_norm_drift, fabs(qn - 1));
    if (c->tf != MECH_RIGID_TORQUE_BODY) {
        double t = s / c->W;
        struct mech_vec3 Lref = r->L0;
        if (c->tf == MECH_RIGID_TORQUE_SPACE)
            Lref = mech_vec3_add(Lref, mech_vec3_scale(c->p->torque, t));
        double d = mech_vec3_norm(mech_vec3_sub(L, Lref));
        r->max_L_vector_drift = fmax(r->max_L_vector_drift, c->Lscale > 0 ? d / c->Lscale : d);
    }
    if (!(isfinite(qn) && qn > 0))
        return mech_error_set(c->err, MECH_ENUMERIC, NULL, "the attitude quaternion degenerated");
    return MECH_OK;
}

double mech_rigid_rate_scale(const struct mech_rigid_problem *p)
{
    double imin = fmin(p->moments[0], fmin(p->moments[1], p->moments[2]));
    double W = mech_vec3_norm(p->omega);
    if (p->torque_frame != MECH_RIGID_TORQUE_NONE)
        W = fmax(W, sqrt(mech_vec3_norm(p->torque) / imin));
    if (!(W > 0) || !isfinite(W)) W = 1.0 / p->t_end;
    return W;
}

enum mech_status mech_rigid_moments_check(const double I[3], struct mech_error *err)
{
    if (!I) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    for (int i = 0; i < 3; i++)
        if (!(isfinite(I[i]) && I[i] > 0))
            return mech_error_set(err, MECH_EDOMAIN, "moments",
                                  "moments must be finite and > 0, got I%d = %.17g", i + 1, I[i]);
    for (int i = 0; i < 3; i++) {
        const double other = I[(i + 1) % 3] + I[(i + 2) % 3];
        if (I[i] > other * (1 + 1e-12))
            return mech_error_set(err, MECH_EDOMAIN, "moments",
                                  "not a physical body: I%d = %.17g exceeds the sum of the other "
                                  "two, %.17g (a body's moments obey the triangle inequality)",
                                  i + 1, I[i], other);
    }
    return MECH_OK;
}

enum mech_status mech_rigid_rotate(const struct mech_rigid_problem *p,
                                   const struct mech_budget *budget,
                                   struct mech_rigid_result *res, struct mech_error *err)
{
    if (!p || !res || !budget) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    const double *I = p->moments;
    enum mech_status mst = mech_rigid_moments_check(I, err);
    if (mst != MECH_OK) return mst;
    if (!mech_vec3_isfinite(p->omega))
        return mech_error_set(err, MECH_EINVAL, "omega", "omega must be finite");
    double qn = 0;
    for (int i = 0; i < 4; i++) qn += p->q0[i] * p->q0[i];
    qn = sqrt(qn);
    if (!(isfinite(qn) && qn > 0))
        return mech_error_set(err, MECH_EINVAL, "orientation", "the orientation must be a non-zero finite quaternion");
    if (p->torque_frame != MECH_RIGID_TORQUE_NONE && !mech_vec3_isfinite(p->torque))
        return mech_error_set(err, MECH_EINVAL, "torque/value", "torque must be finite");
    if (!(isfinite(p->t_end) && p->t_end > 0))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0");
    if (p->samples < 2 || p->samples > 100000)
        return mech_error_set(err, MECH_EINVAL, "samples", "samples must be in 2..100000");
    const struct mech_integrator *m = p->method ? mech_ode_method_find(p->method) : NULL;
    if (!m)
        return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method \"%s\"",
                              p->method ? p->method : "(null)");
    struct mech_ode_method_info mi = mech_ode_method_describe(m);
    if (mi.second_order)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "%s needs a second-order system q'' = a(t, q, v); Euler's "
                              "equations are first order (w' = f(w, q)): use an adaptive rk8pd, "
                              "rkck, rkf45 or msbdf, or a fixed-step rk4, gauss4, gauss6 or euler",
                              p->method);

    struct rr_ctx c;
    memset(&c, 0, sizeof c);
    c.p = p;
    c.res = res;
    c.err = err;
    c.Imax = fmax(I[0], fmax(I[1], I[2]));
    for (int i = 0; i < 3; i++) c.j[i] = I[i] / c.Imax;
    c.W = mech_rigid_rate_scale(p);
    c.tf = p->torque_frame;
    if (c.tf != MECH_RIGID_TORQUE_NONE) c.g = mech_vec3_scale(p->torque, 1.0 / (c.Imax * c.W * c.W));

    const size_t n = p->samples, dim = 7;
    double *sy = malloc(n * dim * sizeof *sy), *st = malloc(n * sizeof *st);
    if (!sy || !st) {
        free(sy);
        free(st);
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
    }
    double y0[7];
    for (int i = 0; i < 4; i++) y0[i] = p->q0[i] / qn;
    y0[4] = p->omega.x / c.W;
    y0[5] = p->omega.y / c.W;
    y0[6] = p->omega.z / c.W;

    res->rate_scale = c.W;
    res->n_samples = 0;
    res->max_L_norm_drift = res->max_T_drift = res->max_L_vector_drift = 0;
    res->max_quaternion_norm_drift = 0;
    res->torque_free = c.tf == MECH_RIGID_TORQUE_NONE || (p->torque.x == 0 && p->torque.y == 0 && p->torque.z == 0);
    rr_invariants(&c, y0, &res->L0, &res->T0);
    c.Lscale = mech_vec3_norm(res->L0);
    if (c.tf == MECH_RIGID_TORQUE_SPACE)
        c.Lscale = fmax(c.Lscale, mech_vec3_norm(p->torque) * p->t_end);
    if (c.tf == MECH_RIGID_TORQUE_BODY) res->max_L_vector_drift = NAN;

    struct mech_ode_system sys = {dim, rr_rhs, NULL, 0, &c, NULL, 0, NULL};
    struct mech_ode_problem op;
    memset(&op, 0, sizeof op);
    op.sys = &sys;
    op.method = m;
    op.opt = p->opt;
    op.opt.dt = p->opt.dt * c.W;
    op.t0 = 0;
    op.t_end = p->t_end * c.W;
    op.y0 = y0;
    op.n_samples = n;
    op.sample_t = st;
    op.sample_y = sy;
    op.observe = rr_observe;
    op.observe_params = &c;
    struct mech_ode_result orr;
    memset(&orr, 0, sizeof orr);
    enum mech_status s = mech_ode_solve(&op, budget, &orr, err);
    res->stats = orr.stats;
    if (s != MECH_OK && err) {
        err->progress.t_reached /= c.W;
        err->progress.t_target = p->t_end;
    }
    size_t ns = orr.n_samples;
    /* write the samples (also on failure: those reached) */
    for (size_t i = 0; i < ns; i++) {
        const double *y = sy + i * dim;
        double qq = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
        if (res->t) res->t[i] = st[i] / c.W;
        if (res->omega) res->omega[i] = mech_vec3_make(y[4] * c.W, y[5] * c.W, y[6] * c.W);
        if (res->quaternion)
            for (int k = 0; k < 4; k++) res->quaternion[4 * i + k] = y[k] / qq;
        struct mech_vec3 L;
        double T;
        rr_invariants(&c, y, &L, &T);
        if (res->angular_momentum) res->angular_momentum[i] = L;
        if (res->kinetic_energy) res->kinetic_energy[i] = T;
    }
    res->n_samples = ns;
    res->has_exact = 0;
    res->flips = 0;
    res->measured_period = NAN;
    if (s == MECH_OK && res->torque_free) {
        s = mech_rigid_exact_init(I, p->omega, &res->exact, err);
        double wn = mech_vec3_norm(p->omega);
        res->max_omega_error = res->final_omega_error = 0;
        double first = NAN, last = NAN, prev_u2 = 0, prev_t = 0;
        for (size_t i = 0; s == MECH_OK && i < ns; i++) {
            const double *y = sy + i * dim;
            double t = st[i] / c.W;
            struct mech_vec3 we, wn_ = mech_vec3_make(y[4] * c.W, y[5] * c.W, y[6] * c.W);
            s = mech_rigid_exact_omega(&res->exact, t, &we, err);
            if (s != MECH_OK) break;
            double e = mech_vec3_norm(mech_vec3_sub(wn_, we));
            res->max_omega_error = fmax(res->max_omega_error, e);
            res->final_omega_error = e;
            /* intermediate-axis component in sorted axes: row 1 of P */
            const double(*P)[3] = res->exact.p;
            double u2 = P[1][0] * wn_.x + P[1][1] * wn_.y + P[1][2] * wn_.z;
            if (i > 0 && ((prev_u2 < 0 && u2 >= 0) || (prev_u2 > 0 && u2 <= 0)) && u2 != prev_u2) {
                double tc = prev_t + (t - prev_t) * prev_u2 / (prev_u2 - u2);
                if (res->flips == 0) first = tc;
                last = tc;
                res->flips++;
            }
            prev_u2 = u2;
            prev_t = t;
        }
        if (s == MECH_OK) {
            res->has_exact = 1;
            res->max_relative_omega_error = wn > 0 ? res->max_omega_error / wn : res->max_omega_error;
            if (res->flips >= 2) res->measured_period = 2 * (last - first) / (double)(res->flips - 1);
        }
    }
    free(sy);
    free(st);
    return s;
}
