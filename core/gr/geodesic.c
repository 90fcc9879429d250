/* geodesic.c — equatorial Schwarzschild geodesics (mech/gr/geodesic.h): the
 * initial-condition builders, the classification of timelike motion, the
 * exact periapsis advance and light deflection (elliptic integrals and
 * independent quadratures) and the integration of the second-order radial
 * equation with constraint monitoring, capture/escape events and periapses
 * located by the ODE driver's event root-finding.
 *
 * References: Hartle, "Gravity" (2003) §9.2-9.3 (eqs. 9.21-9.35), §11.1
 * (eqs. 11.9-11.14); Carroll, "Spacetime and Geometry" §5.4 (eqs. 5.58-5.62,
 * 5.104); Schutz, "A First Course in General Relativity" §11.1; Byrd &
 * Friedman, "Handbook of Elliptic Integrals", 233.00.
 *
 * Why one file of ~800 lines: its four sections (initial conditions,
 * classification, exact references, integration) are one operation's steps
 * and share its file-local helpers (the orbit constants, the effective
 * potential's roots); the exact references are the integration's own check. */
#include "mech/gr/geodesic.h"
#include "mech/base/constants.h"
#include "mech/gr/schwarzschild.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>

#include <stdlib.h>
#include <string.h>

static double capture_radius(void)
{
    return 2.0 * (1.0 + MECH_GEODESIC_CAPTURE_MARGIN);
}

static enum mech_status check_r0(double r0, struct mech_error *err)
{
    if (!isfinite(r0) || !(r0 > capture_radius()))
        return mech_error_set(err, MECH_EDOMAIN, "r0",
                              "r0 = %.17g GM/c^2 is not outside the horizon r_s = 2GM/c^2 (by the "
                              "capture margin %g): a geodesic that starts %s cannot be followed "
                              "in Schwarzschild coordinates",
                              r0, MECH_GEODESIC_CAPTURE_MARGIN,
                              r0 <= 2.0 ? "at or inside the horizon" : "at the horizon");
    return MECH_OK;
}

/* ---- initial conditions ----------------------------------------------------------- */

enum mech_status mech_geodesic_init_energy(double r0, double phi0, double E, double L, int dir,
                                           struct mech_geodesic_init *out, struct mech_error *err)
{
    enum mech_status st = check_r0(r0, err);
    if (st != MECH_OK) return st;
    if (!(E > 0) || !isfinite(E) || !isfinite(L) || !isfinite(phi0))
        return mech_error_set(err, MECH_EDOMAIN, "energy", "E must be finite and > 0, got %.17g",
                              E);
    const double u = 1.0 / r0;
    const double E2m1 = (E - 1.0) * (E + 1.0);
    /* E^2 - V(r0) = E^2 - 1 + 2u - L^2 u^2 + 2 L^2 u^3 (Carroll eq. 5.61 x 2) */
    const double Lu = L * u;
    const double terms[4] = {E2m1, 2.0 * u, -Lu * Lu, 2.0 * Lu * Lu * u};
    double sum = 0, mag = 0;
    for (int i = 0; i < 4; i++) {
        sum += terms[i];
        mag += fabs(terms[i]);
    }
    if (sum < 0) {
        if (sum < -8 * 2.2e-16 * mag)
            return mech_error_set(err, MECH_EDOMAIN, "energy",
                                  "E = %.17g is below the effective potential at r0: E^2 - V(r0) = "
                                  "%.6g < 0 (V = (1 - r_s/r)(1 + L^2/(c r)^2)); no real motion "
                                  "starts there",
                                  E, sum);
        sum = 0; /* a turning point, up to rounding */
    }
    out->kind = MECH_GEODESIC_TIMELIKE;
    out->r0 = r0;
    out->phi0 = phi0;
    out->E = E;
    out->E2m1 = E2m1;
    out->L = L;
    out->rdot0 = (dir >= 0 ? 1.0 : -1.0) * sqrt(sum);
    return MECH_OK;
}

enum mech_status mech_geodesic_init_local(enum mech_geodesic_kind kind, double r0, double phi0,
                                          double vr, double vt, struct mech_geodesic_init *out,
                                          struct mech_error *err)
{
    enum mech_status st = check_r0(r0, err);
    if (st != MECH_OK) return st;
    if (!isfinite(vr) || !isfinite(vt) || !isfinite(phi0))
        return mech_error_set(err, MECH_EINVAL, "local_velocity", "non-finite velocity");
    const double x = 2.0 / r0, lapse = sqrt(1.0 - x);
    out->kind = kind;
    out->r0 = r0;
    out->phi0 = phi0;
    if (kind == MECH_GEODESIC_NULL) {
        const double n = hypot(vr, vt);
        if (!(n > 0))
            return mech_error_set(err, MECH_EDOMAIN, "local_velocity",
                                  "a photon's direction (radial, tangential) must not be zero");
        const double ca = vr / n, sa = vt / n;
        out->E = 1.0;
        out->E2m1 = 0.0;
        out->L = r0 * sa / lapse; /* b = r0 sin(alpha) / sqrt(1 - 2/r0) */
        out->rdot0 = ca;
        return MECH_OK;
    }
    const double v2 = vr * vr + vt * vt;
    if (!(v2 < 1.0))
        return mech_error_set(err, MECH_EDOMAIN, "local_velocity",
                              "a massive particle needs a local speed < c; got |v|/c = %.17g",
                              sqrt(v2));
    const double g2 = 1.0 / ((1.0 - sqrt(v2)) * (1.0 + sqrt(v2))), g = sqrt(g2);
    out->E = g * lapse;          /* E = -u_t = gamma sqrt(1 - 2M/r) */
    out->E2m1 = g2 * (v2 - x);   /* gamma^2 (1 - x) - 1 = gamma^2 (v^2 - x) */
    out->L = g * vt * r0;        /* L = u_phi = gamma v_t r */
    out->rdot0 = g * vr * lapse; /* u^r = sqrt(1 - 2M/r) u^rhat */
    return MECH_OK;
}

enum mech_status mech_geodesic_init_impact(double r0, double phi0, double b, int dir,
                                           struct mech_geodesic_init *out, struct mech_error *err)
{
    enum mech_status st = check_r0(r0, err);
    if (st != MECH_OK) return st;
    if (!(b >= 0) || !isfinite(b) || !isfinite(phi0))
        return mech_error_set(err, MECH_EDOMAIN, "impact_parameter",
                              "b must be finite and >= 0, got %.17g", b);
    const double q = b / r0;
    /* (dr/dlambda)^2 = 1 - b^2 W(r0), W = (1 - 2/r)/r^2 (Hartle eq. 11.10 with E = 1) */
    const double s = (1.0 - q) * (1.0 + q) + 2.0 * q * q / r0;
    if (s < 0)
        return mech_error_set(err, MECH_EDOMAIN, "impact_parameter",
                              "a photon with b = %.17g GM/c^2 cannot be at r0 = %.17g GM/c^2: "
                              "1/b^2 < W(r0) = (1 - r_s/r0)/r0^2 (it turns before reaching r0)",
                              b, r0);
    out->kind = MECH_GEODESIC_NULL;
    out->r0 = r0;
    out->phi0 = phi0;
    out->E = 1.0;
    out->E2m1 = 0.0;
    out->L = b;
    out->rdot0 = (dir >= 0 ? 1.0 : -1.0) * sqrt(s);
    return MECH_OK;
}

enum mech_status mech_geodesic_init_orbit(double r_p, double r_a, double phi0,
                                          struct mech_geodesic_init *out, struct mech_error *err)
{
    if (!isfinite(r_p) || !(r_p > capture_radius()))
        return mech_error_set(err, MECH_EDOMAIN, "periapsis",
                              "the periapsis must be outside the horizon, got %.17g GM/c^2", r_p);
    if (!isfinite(r_a) || !(r_a >= r_p))
        return mech_error_set(err, MECH_EDOMAIN, "apoapsis",
                              "the apoapsis %.17g must be >= the periapsis %.17g", r_a, r_p);
    const double u1 = 1.0 / r_a, u2 = 1.0 / r_p, u3 = 0.5 - u1 - u2;
    if (!(u3 > u2))
        return mech_error_set(err, MECH_EDOMAIN, "periapsis",
                              "no bound orbit turns at r_p = %.17g and r_a = %.17g GM/c^2: it "
                              "needs 1/r_a + 2/r_p < 1/2 (the third root u3 = 1/2 - u1 - u2 "
                              "above u2; a circular orbit needs r > 6GM/c^2)",
                              r_p, r_a);
    /* (du/dphi)^2 = 2 (u - u1)(u - u2)(u - u3) against
     * 2u^3 - u^2 + 2u/L^2 + (E^2 - 1)/L^2 (Hartle eq. 9.27 with u = 1/r) */
    const double L2 = 1.0 / (u1 * u2 + u3 * (u1 + u2));
    out->kind = MECH_GEODESIC_TIMELIKE;
    out->r0 = r_p;
    out->phi0 = phi0;
    out->E2m1 = -2.0 * u1 * u2 * u3 * L2;
    out->E = sqrt(1.0 + out->E2m1);
    out->L = sqrt(L2);
    out->rdot0 = 0.0;
    return MECH_OK;
}

/* ---- classification --------------------------------------------------------------- */

/* P(u) = E^2 - 1 + 2u - L^2 u^2 + 2 L^2 u^3 and its derivative */
static double radial_poly(double u, double E2m1, double L2, double *dP)
{
    if (dP) *dP = 2.0 - 2.0 * L2 * u + 6.0 * L2 * u * u;
    return E2m1 + 2.0 * u - L2 * u * u + 2.0 * L2 * u * u * u;
}

static double polish(double u, double E2m1, double L2)
{
    for (int i = 0; i < 8; i++) {
        double d, P = radial_poly(u, E2m1, L2, &d);
        if (!(d != 0) || !isfinite(P)) break;
        double un = u - P / d;
        if (!isfinite(un) || fabs(un - u) <= 1e-16 * fabs(u)) {
            if (isfinite(un)) u = un;
            break;
        }
        u = un;
    }
    return u;
}

enum mech_status mech_geodesic_classify(const struct mech_geodesic_init *in,
                                        enum mech_geodesic_class *cls,
                                        struct mech_geodesic_bound *b, struct mech_error *err)
{
    if (in->kind != MECH_GEODESIC_TIMELIKE)
        return mech_error_set(err, MECH_EINVAL, "kind", "classification is for timelike motion");
    b->u1 = b->u2 = b->u3 = NAN;
    const double u0 = 1.0 / in->r0, L2 = in->L * in->L;
    if (L2 == 0) {
        /* radial: P = E^2 - 1 + 2u >= 0; it ends in the horizon unless it flies out */
        *cls = (in->E2m1 >= 0 && in->rdot0 > 0) ? MECH_GEODESIC_UNBOUND : MECH_GEODESIC_PLUNGE;
        return MECH_OK;
    }
    double x[3];
    int n;
    const double disc = 1.0 + in->E2m1 * L2;
    if (disc > 0 && (1.0 + sqrt(disc)) / L2 < 1e-3) {
        /* weak field (r_p > ~1000 GM/c^2): the cubic's coefficients span too many
         * orders for a general solver (it can lose the two small roots). Start from
         * the Newtonian quadratic L^2 u^2 - 2u - (E^2 - 1) = 0, roots formed without
         * cancellation, polish on the full cubic; the third root from the sum 1/2. */
        const double q = sqrt(disc);
        x[0] = polish(-in->E2m1 / (1.0 + q), in->E2m1, L2);
        x[1] = polish((1.0 + q) / L2, in->E2m1, L2);
        if (x[0] > x[1]) {
            double t = x[0];
            x[0] = x[1];
            x[1] = t;
        }
        x[2] = 0.5 - x[0] - x[1];
        n = 3;
    } else {
        n = gsl_poly_solve_cubic(-0.5, 1.0 / L2, in->E2m1 / (2.0 * L2), &x[0], &x[1], &x[2]);
        for (int i = 0; i < n; i++)
            x[i] = polish(x[i], in->E2m1, L2);
    }
    const double tol = 1e-9 * u0;
    if (n == 3 && u0 <= x[1] + tol && x[0] > 0 && u0 >= x[0] - tol) {
        b->u1 = x[0];
        b->u2 = x[1];
        b->u3 = 0.5 - x[0] - x[1];
        /* near a double root the roots carry ~sqrt(eps) noise: closer than 1e-6
         * relative is circular within what E and L in double precision can say */
        *cls = (x[1] - x[0]) <= 1e-6 * x[1] ? MECH_GEODESIC_CIRCULAR : MECH_GEODESIC_BOUND;
        if (!(b->u3 > b->u2)) *cls = MECH_GEODESIC_CIRCULAR; /* marginal: the ISCO */
        return MECH_OK;
    }
    if (n == 3 && u0 <= x[1] + tol) {
        *cls = MECH_GEODESIC_UNBOUND; /* x0 <= 0: reaches u = 0 */
        return MECH_OK;
    }
    /* beyond the barrier (u0 >= x2) or a single real root */
    if (n == 1 && x[0] <= 0 && in->rdot0 > 0)
        *cls = MECH_GEODESIC_UNBOUND;
    else
        *cls = MECH_GEODESIC_PLUNGE;
    return MECH_OK;
}

/* ---- exact references --------------------------------------------------------------- */

/* K(m) - pi/2 for the parameter m = k^2 in [0, 1) */
static double ellK_minus_half_pi(double m)
{
    if (m < 0.1) {
        /* K = pi/2 sum_n [(2n-1)!! / (2n)!!]^2 m^n (A&S 17.3.11) */
        double c = 1.0, sum = 0.0, mn = 1.0;
        for (int n = 1; n < 80; n++) {
            c *= (2.0 * n - 1.0) / (2.0 * n);
            mn *= m;
            double term = c * c * mn;
            sum += term;
            if (term < 1e-18 * sum) break;
        }
        return MECH_PI_2 * sum;
    }
    return gsl_sf_ellint_Kcomp(sqrt(m), GSL_PREC_DOUBLE) - MECH_PI_2;
}

enum mech_status mech_geodesic_precession_exact(const struct mech_geodesic_bound *b,
                                                double *advance, struct mech_error *err)
{
    const double u1 = b->u1, u2 = b->u2, u3 = b->u3;
    if (!(u1 > 0 && u2 >= u1 && u3 > u2))
        return mech_error_set(err, MECH_EDOMAIN, "periapsis",
                              "not a bound orbit: u1 = %.6g, u2 = %.6g, u3 = %.6g", u1, u2, u3);
    const double m = (u2 - u1) / (u3 - u1);
    const double s2 = 2.0 * (u3 - u1), s = sqrt(s2);
    const double one_minus_s = (4.0 * u1 + 2.0 * u2) / (1.0 + s); /* 1 - s^2 = 4u1 + 2u2 */
    /* Delta phi - 2 pi = 4 K / s - 2 pi = 4 (K - pi/2)/s + 2 pi (1 - s)/s */
    *advance = 4.0 * ellK_minus_half_pi(m) / s + 2.0 * MECH_PI * one_minus_s / s;
    if (!isfinite(*advance))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite periapsis advance");
    return MECH_OK;
}

struct quad_orbit {
    double u1, u2, u3, E, L;
    int which; /* 0 advance, 1 T_tau, 2 T_t */
};

static double quad_orbit_f(double chi, void *params)
{
    const struct quad_orbit *q = params;
    const double u = q->u1 + (q->u2 - q->u1) * 0.5 * (1.0 - cos(chi));
    const double w = sqrt(2.0 * (q->u3 - u));
    if (q->which == 0) return 2.0 * (q->u1 + q->u2 + u) / (w * (1.0 + w)); /* 1/w - 1 */
    const double dtau = 1.0 / (q->L * u * u * w);
    return q->which == 1 ? dtau : q->E * dtau / (1.0 - 2.0 * u);
}

static enum mech_status qag(gsl_function *f, double a, double b, double *out,
                            struct mech_error *err)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(256);
    if (!ws) return mech_error_set(err, MECH_ENOMEM, NULL, "quadrature workspace");
    double abserr;
    int gs = gsl_integration_qag(f, a, b, 0.0, 1e-13, 256, GSL_INTEG_GAUSS61, ws, out, &abserr);
    gsl_integration_workspace_free(ws);
    if (gs == GSL_EROUND && isfinite(*out) && abserr <= 1e-10 * fabs(*out)) gs = GSL_SUCCESS;
    if (gs != GSL_SUCCESS || !isfinite(*out))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "quadrature failed: %s (error %.3g)",
                              gsl_strerror(gs), abserr);
    return MECH_OK;
}

enum mech_status mech_geodesic_precession_quadrature(const struct mech_geodesic_bound *b, double E,
                                                     double L, double *advance, double *period_tau,
                                                     double *period_t, struct mech_error *err)
{
    if (!(b->u1 > 0 && b->u2 >= b->u1 && b->u3 > b->u2) || !(fabs(L) > 0))
        return mech_error_set(err, MECH_EDOMAIN, "periapsis", "not a bound orbit");
    struct quad_orbit q = {b->u1, b->u2, b->u3, E, fabs(L), 0};
    gsl_function f = {quad_orbit_f, &q};
    double *outs[3] = {advance, period_tau, period_t};
    for (int k = 0; k < 3; k++) {
        if (!outs[k]) continue;
        q.which = k;
        double v;
        enum mech_status st = qag(&f, 0.0, MECH_PI, &v, err);
        if (st != MECH_OK) return st;
        *outs[k] = 2.0 * v;
    }
    return MECH_OK;
}

/* F(w) = 1 - w^2 + 2 eps w^3 for light (w = b u, eps = 1/b) */
static double light_F(double w, void *params)
{
    const double eps = *(const double *)params;
    return 1.0 - w * w + 2.0 * eps * w * w * w;
}

/* The smallest positive root w1 of F. Weak fields (eps < 1e-4): w1 = 1 + d with
 * d = eps (1 + d)^3 - d^2/2 by fixed-point iteration (a contraction, |d'| ~ 3 eps),
 * accurate for any eps (Brent on [1, b/3] stalls there: F(1) = 2 eps is ~0 at the
 * bracket's scale). Stronger fields: Brent on [1, b/3] (F(1) = 2 eps > 0,
 * F(b/3) = 1 - b^2/27 < 0 iff b > 3 sqrt 3), then Newton. */
static enum mech_status light_w1(double b, double *w1, struct mech_error *err)
{
    if (!(b > MECH_SCHW_CRITICAL_IMPACT) || !isfinite(b)) {
        return mech_error_set(err, MECH_EDOMAIN, "impact_parameter",
                              "b = %.17g GM/c^2 <= 3 sqrt(3) GM/c^2: the light is captured (no "
                              "closest approach, no deflection)",
                              b);
    }
    double eps = 1.0 / b;
    if (eps < 1e-4) {
        double d = eps;
        for (int i = 0; i < 100; i++) {
            double dn = eps * (1.0 + d) * (1.0 + d) * (1.0 + d) - 0.5 * d * d;
            int done = fabs(dn - d) <= 1e-17 * fabs(dn);
            d = dn;
            if (done) break;
        }
        *w1 = 1.0 + d;
        return MECH_OK;
    }
    gsl_function F = {light_F, &eps};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return mech_error_set(err, MECH_ENOMEM, NULL, "root solver");
    double lo = 1.0, hi = b / 3.0, r = 1.0;
    int gs = gsl_root_fsolver_set(s, &F, lo, hi);
    for (int it = 0; gs == GSL_SUCCESS && it < 400; it++) {
        gs = gsl_root_fsolver_iterate(s);
        r = gsl_root_fsolver_root(s);
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
    }
    gsl_root_fsolver_free(s);
    if (gs != GSL_SUCCESS || !isfinite(r))
        return mech_error_set(err, MECH_ENUMERIC, "impact_parameter",
                              "closest approach not found: %s", gsl_strerror(gs));
    for (int i = 0; i < 20; i++) {
        double d = -2.0 * r + 6.0 * eps * r * r;
        if (!(d < 0)) break;
        double rn = r - light_F(r, &eps) / d;
        if (!isfinite(rn) || rn < lo - 1e-12 || rn > hi + 1e-12) break;
        int done = fabs(rn - r) <= 1e-16 * r;
        r = rn;
        if (done) break;
    }
    *w1 = r;
    return MECH_OK;
}

/* The negative root w3 of F (in (-1, 0)): Newton from -1, monotone (F is increasing
 * and concave there, F(-1) = -2 eps < 0). */
static double light_w3(double b)
{
    double eps = 1.0 / b, w = -1.0;
    for (int i = 0; i < 100; i++) {
        double d = -2.0 * w + 6.0 * eps * w * w;
        double wn = w - light_F(w, &eps) / d;
        if (!isfinite(wn)) break;
        int done = fabs(wn - w) <= 1e-16 * fabs(w);
        w = wn;
        if (done) break;
    }
    return w;
}

enum mech_status mech_geodesic_deflection_exact(double b, double *delta, double *r_min,
                                                struct mech_error *err)
{
    if (!isfinite(b) || !(b > MECH_SCHW_CRITICAL_IMPACT))
        return mech_error_set(err, MECH_EDOMAIN, "impact_parameter",
                              "b = %.17g GM/c^2 <= 3 sqrt(3) GM/c^2: the light is captured", b);
    const double eps = 1.0 / b;
    double w1;
    enum mech_status st = light_w1(b, &w1, err);
    if (st != MECH_OK) return st;
    const double w3 = light_w3(b), w2 = 0.5 * b - w1 - w3; /* roots sum to b/2 */
    if (!(w3 < 0 && w1 > 0 && w2 > w1))
        return mech_error_set(err, MECH_ENUMERIC, "impact_parameter",
                              "unexpected roots %.6g %.6g %.6g", w3, w1, w2);
    const double k2 = (w1 - w3) / (w2 - w3);
    const double sin2 = (w2 - w3) * w1 / ((w1 - w3) * w2);
    const double phi = asin(sqrt(fmin(1.0, sin2)));
    gsl_sf_result F;
    int gs = gsl_sf_ellint_F_e(phi, sqrt(k2), GSL_PREC_DOUBLE, &F);
    if (gs != GSL_SUCCESS)
        return mech_error_set(err, MECH_ENUMERIC, NULL, "elliptic integral F failed: %s",
                              gsl_strerror(gs));
    /* int_0^{w1} = g F / sqrt(2 eps), g = 2/sqrt(w2 - w3) (Byrd & Friedman 233.00) */
    *delta = 2.0 * (2.0 / sqrt(w2 - w3)) * F.val / sqrt(2.0 * eps) - MECH_PI;
    if (r_min) *r_min = b / w1;
    if (!isfinite(*delta)) return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite deflection");
    return MECH_OK;
}

struct quad_light {
    double eps, w1;
};

/* f - 1 at theta, w = w1 sin(theta): see mech_geodesic_deflection_quadrature */
static double quad_light_f(double th, void *params)
{
    const struct quad_light *q = params;
    const double s = sin(th), w = q->w1 * s;
    const double cub = 2.0 * q->eps * (w * w + w * q->w1 + q->w1 * q->w1);
    const double G = w + q->w1 - cub;
    return cub / (sqrt(G) * (sqrt(q->w1 * (1.0 + s)) + sqrt(G)));
}

/* int_0^{theta0} (f - 1) dtheta */
static enum mech_status light_excess(double b, double w1, double theta0, double *out,
                                     struct mech_error *err)
{
    struct quad_light q = {1.0 / b, w1};
    gsl_function f = {quad_light_f, &q};
    if (theta0 <= 0) {
        *out = 0;
        return MECH_OK;
    }
    return qag(&f, 0.0, theta0, out, err);
}

enum mech_status mech_geodesic_deflection_quadrature(double b, double *delta,
                                                     struct mech_error *err)
{
    double w1, ex;
    enum mech_status st = light_w1(b, &w1, err);
    if (st != MECH_OK) return st;
    if ((st = light_excess(b, w1, MECH_PI_2, &ex, err)) != MECH_OK) return st;
    *delta = 2.0 * ex;
    return MECH_OK;
}

/* ---- integration -------------------------------------------------------------------- */

struct geo_ctx {
    double kappa, eps, ell, E, h; /* scaled constants */
    double bound;
    struct mech_error *err;
    double max_abs, max_rel, last_rel;
    /* periapsis search */
    const struct mech_ode_system *sys;
    const struct mech_integrator *method;
    struct mech_ode_options opt;
    const struct mech_budget *budget;
    int have_prev;
    double prev_s, prev_y[4];
    long n_peri;
    double first[3], last[3]; /* phi, s, that */
    double rho_cap, rho_esc;
};

static enum mech_status geo_rhs(double s, const double *y, double *dy, void *params)
{
    (void)s;
    const struct geo_ctx *c = params;
    /* A trial stage of an adaptive step may land inside the capture radius (or at
     * rho <= 0); answer finite values there (rho clamped to the capture radius,
     * where 1 - 2M/r = 1e-6) so the step's error estimate rejects it instead of
     * the run failing. Accepted steps stop at the capture event. */
    const double rho = y[0] > c->rho_cap ? y[0] : c->rho_cap;
    const double ir = 1.0 / rho, ir2 = ir * ir, l2 = c->ell * c->ell;
    dy[0] = y[1];
    /* d^2r/dtau^2 = -kappa M/r^2 + L^2/r^3 - 3 M L^2/r^4, scaled (Hartle eq. 9.29 differentiated)
     */
    dy[1] = ir2 * (-c->kappa + l2 * ir - 3.0 * c->eps * l2 * ir2);
    dy[2] = c->ell * ir2;                     /* dphi/dtau = L/r^2 */
    dy[3] = c->E / (1.0 - 2.0 * c->eps * ir); /* dt/dtau = E/(1 - 2M/r) */
    return MECH_OK;
}

/* constraint residual (scaled) and the size of its terms */
static double constraint(const struct geo_ctx *c, const double *y, double *scale)
{
    const double ir = 1.0 / y[0], l2 = c->ell * c->ell, v2 = y[1] * y[1];
    if (c->kappa > 0) {
        /* [(dr/dtau)^2 + V - E^2] / eps = rho'^2 - 2/rho + l^2/rho^2 - 2 eps l^2/rho^3 - h */
        const double a = 2.0 * ir, bq = l2 * ir * ir, d = 2.0 * c->eps * l2 * ir * ir * ir;
        *scale = v2 + a + bq + d + fabs(c->h);
        return v2 - a + bq - d - c->h;
    }
    const double bq = l2 * ir * ir;
    *scale = 1.0 + v2 + bq;
    return v2 + (1.0 - 2.0 * c->eps * ir) * bq - 1.0;
}

static double rhodot_event(double s, const double *y, void *params)
{
    (void)s;
    (void)params;
    return y[1];
}

static double bounds_event(double s, const double *y, void *params)
{
    (void)s;
    const struct geo_ctx *c = params;
    return (y[0] - c->rho_cap) * (c->rho_esc - y[0]);
}

static void record_periapsis(struct geo_ctx *c, double s, const double *y)
{
    double v[3] = {y[2], s, y[3]};
    if (c->n_peri == 0) memcpy(c->first, v, sizeof v);
    memcpy(c->last, v, sizeof v);
    c->n_peri++;
}

static enum mech_status geo_observe(double s, const double *y, void *params)
{
    struct geo_ctx *c = params;
    double scale, res = constraint(c, y, &scale);
    double rel = fabs(res) / scale;
    double gabs = fabs(res) / (1.0 - 2.0 * c->eps / y[0]);
    if (c->kappa > 0) gabs *= c->eps; /* C = eps x residual */
    if (rel > c->max_rel) c->max_rel = rel;
    if (gabs > c->max_abs) c->max_abs = gabs;
    c->last_rel = rel;
    if (!(rel <= c->bound))
        return mech_error_set(c->err, MECH_ENUMERIC, "constraint_bound",
                              "the constraint g(u,u) = %s drifted by %.3g relative at the scaled "
                              "time %.9g, beyond the bound %.3g: the integration is no longer a "
                              "geodesic; tighten the integrator",
                              c->kappa > 0 ? "-1" : "0", rel, s, c->bound);
    if (c->have_prev && s > c->prev_s && c->prev_y[1] < 0 && y[1] >= 0) {
        /* a periapsis between prev and now: locate it by the driver's event on a sub-run */
        struct mech_ode_problem q;
        memset(&q, 0, sizeof q);
        double ys[4], st_[2], sy[8];
        q.sys = c->sys;
        q.method = c->method;
        q.opt = c->opt;
        q.t0 = c->prev_s;
        q.t_end = s;
        q.y0 = c->prev_y;
        q.n_samples = 2;
        q.sample_t = st_;
        q.sample_y = sy;
        q.event = rhodot_event;
        q.event_direction = MECH_ODE_INCREASING;
        q.y_stop = ys;
        struct mech_ode_result r;
        memset(&r, 0, sizeof r);
        struct mech_error e2;
        mech_error_clear(&e2);
        enum mech_status st = mech_ode_solve(&q, c->budget, &r, &e2);
        if (st != MECH_OK) return mech_error_set(c->err, st, NULL, "periapsis search: %s", e2.text);
        if (r.stopped) {
            record_periapsis(c, r.t_stop, ys);
        } else {
            /* the sub-run saw no sign change (both ends within round-off of 0):
             * interpolate linearly in drho/ds */
            double f = c->prev_y[1] / (c->prev_y[1] - y[1]), yi[4];
            for (int k = 0; k < 4; k++)
                yi[k] = c->prev_y[k] + f * (y[k] - c->prev_y[k]);
            record_periapsis(c, c->prev_s + f * (s - c->prev_s), yi);
        }
    }
    if (!c->have_prev || s > c->prev_s) {
        c->have_prev = 1;
        c->prev_s = s;
        memcpy(c->prev_y, y, sizeof c->prev_y);
    }
    return MECH_OK;
}

/* tail of the light's phi beyond radius r (w = b/r) to infinity */
static enum mech_status light_tail(double b, double w1, double r, double *out,
                                   struct mech_error *err)
{
    double w = b / r;
    if (!(w < w1)) return mech_error_set(err, MECH_ENUMERIC, NULL, "tail beyond the turning point");
    double th = asin(w / w1), ex;
    enum mech_status st = light_excess(b, w1, th, &ex, err);
    if (st != MECH_OK) return st;
    *out = th + ex;
    return MECH_OK;
}

double mech_geodesic_time_unit(const struct mech_geodesic_init *in)
{
    return in->kind == MECH_GEODESIC_TIMELIKE ? in->r0 * sqrt(in->r0) : in->r0;
}

enum mech_status mech_geodesic_integrate(const struct mech_geodesic_problem *p,
                                         const struct mech_budget *budget,
                                         struct mech_geodesic_result *res, struct mech_error *err)
{
    const struct mech_geodesic_init *in = &p->init;
    enum mech_status st = check_r0(in->r0, err);
    if (st != MECH_OK) return st;
    if (p->samples < 2)
        return mech_error_set(err, MECH_EINVAL, "samples", "need at least 2 samples");
    if (!(p->r_escape > in->r0) || !isfinite(p->r_escape))
        return mech_error_set(err, MECH_EINVAL, "r_escape",
                              "r_escape (%.17g GM/c^2) must be beyond r0 (%.17g)", p->r_escape,
                              in->r0);
    if (!(p->param_end > 0) || !isfinite(p->param_end))
        return mech_error_set(err, MECH_EINVAL,
                              in->kind == MECH_GEODESIC_NULL ? "lambda_end" : "tau_end",
                              "the end of the run must be > 0");
    if (!(p->constraint_bound > 0 && p->constraint_bound < 1))
        return mech_error_set(err, MECH_EINVAL, "constraint_bound", "must be in (0, 1)");
    const struct mech_integrator *m = mech_ode_method_find(p->method ? p->method : "");
    if (!m)
        return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method \"%s\"",
                              p->method ? p->method : "(null)");
    const double r0 = in->r0;
    const int timelike = in->kind == MECH_GEODESIC_TIMELIKE;
    struct geo_ctx c;
    memset(&c, 0, sizeof c);
    c.kappa = timelike ? 1.0 : 0.0;
    c.eps = 1.0 / r0;
    c.ell = timelike ? in->L / sqrt(r0) : in->L / r0;
    c.E = in->E;
    c.h = timelike ? in->E2m1 * r0 : 0.0;
    c.bound = p->constraint_bound;
    c.err = err;
    c.max_abs = c.max_rel = c.last_rel = 0;
    c.rho_cap = capture_radius() / r0;
    c.rho_esc = p->r_escape / r0;
    const double T = mech_geodesic_time_unit(in);
    res->time_unit = T;

    struct mech_ode_system sys;
    memset(&sys, 0, sizeof sys);
    sys.dim = 4;
    sys.rhs = geo_rhs;
    sys.params = &c;
    c.sys = &sys;
    c.method = m;
    c.opt = p->opt;
    c.budget = budget;

    const double y0[4] = {1.0, timelike ? in->rdot0 * sqrt(r0) : in->rdot0, in->phi0, 0.0};
    /* a start exactly at periapsis counts */
    {
        double dy[4];
        geo_rhs(0, y0, dy, &c);
        if (y0[1] == 0 && dy[1] > 0) record_periapsis(&c, 0.0, y0);
    }
    const size_t n = p->samples;
    double *ts = malloc(n * sizeof *ts), *ys = malloc(4 * n * sizeof *ys);
    if (!ts || !ys) {
        free(ts);
        free(ys);
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
    }
    double ystop[4];
    struct mech_ode_problem q;
    memset(&q, 0, sizeof q);
    q.sys = &sys;
    q.method = m;
    q.opt = p->opt;
    q.t0 = 0.0;
    q.t_end = p->param_end / T;
    q.y0 = y0;
    q.n_samples = n;
    q.sample_t = ts;
    q.sample_y = ys;
    q.event = bounds_event;
    q.event_direction = MECH_ODE_DECREASING;
    q.event_params = &c;
    q.observe = geo_observe;
    q.observe_params = &c;
    q.y_stop = ystop;
    struct mech_ode_result r;
    memset(&r, 0, sizeof r);
    st = mech_ode_solve(&q, budget, &r, err);
    res->stats = r.stats;
    if (st != MECH_OK && err) {
        err->progress.t_reached *= T;
        err->progress.t_target = p->param_end;
    }
    res->n_samples = r.n_samples;
    for (size_t i = 0; i < r.n_samples; i++) {
        const double *y = ys + 4 * i;
        if (res->param) res->param[i] = ts[i] * T;
        if (res->t) res->t[i] = y[3] * T;
        if (res->r) res->r[i] = y[0] * r0;
        if (res->phi) res->phi[i] = y[2];
    }
    if (st == MECH_OK && !r.stopped && p->periapsis_lookahead > 0 && c.have_prev &&
        c.prev_y[1] < 0) {
        /* the run ended just before a periapsis: find it on a short continuation */
        struct mech_ode_problem q2;
        memset(&q2, 0, sizeof q2);
        double ys2[4], st2[2], sy2[8], yend[4];
        memcpy(yend, c.prev_y, sizeof yend);
        q2.sys = &sys;
        q2.method = m;
        q2.opt = p->opt;
        q2.t0 = c.prev_s;
        q2.t_end = c.prev_s + p->periapsis_lookahead / T;
        q2.y0 = yend;
        q2.n_samples = 2;
        q2.sample_t = st2;
        q2.sample_y = sy2;
        q2.event = rhodot_event;
        q2.event_direction = MECH_ODE_INCREASING;
        q2.y_stop = ys2;
        struct mech_ode_result r2;
        memset(&r2, 0, sizeof r2);
        struct mech_error e2;
        mech_error_clear(&e2);
        /* A failed look-ahead (out of memory, budget) is the run's failure: dropping
         * the periapsis silently would change periapses_found and the advance. */
        enum mech_status sta = mech_ode_solve(&q2, budget, &r2, &e2);
        if (sta != MECH_OK) {
            st = mech_error_set(err, sta, NULL, "periapsis look-ahead: %s", e2.text);
            if (err && err->code == sta) {
                err->progress = e2.progress;
                err->progress.t_reached = e2.progress.t_reached * T;
                err->progress.t_target = p->param_end;
            }
        } else if (r2.stopped) {
            record_periapsis(&c, r2.t_stop, ys2);
        }
        res->stats.steps += r2.stats.steps;
        res->stats.rejected_steps += r2.stats.rejected_steps;
        res->stats.rhs_evaluations += r2.stats.rhs_evaluations;
    }
    const double *ye = r.stopped ? ystop : (r.n_samples ? ys + 4 * (r.n_samples - 1) : y0);
    const double se = r.stopped ? r.t_stop : (r.n_samples ? ts[r.n_samples - 1] : 0.0);
    res->captured = r.stopped && fabs(ye[0] - c.rho_cap) < fabs(ye[0] - c.rho_esc);
    res->escaped = r.stopped && !res->captured;
    res->end_param = se * T;
    res->end_t = ye[3] * T;
    res->end_r = ye[0] * r0;
    res->end_phi = ye[2];
    res->end_rdot = ye[1] * r0 / T;
    res->n_periapses = c.n_peri;
    res->first_periapsis_phi = c.n_peri ? c.first[0] : NAN;
    res->last_periapsis_phi = c.n_peri ? c.last[0] : NAN;
    res->first_periapsis_param = c.n_peri ? c.first[1] * T : NAN;
    res->last_periapsis_param = c.n_peri ? c.last[1] * T : NAN;
    res->first_periapsis_t = c.n_peri ? c.first[2] * T : NAN;
    res->last_periapsis_t = c.n_peri ? c.last[2] * T : NAN;
    res->measured_advance = NAN;
    if (c.n_peri >= 2)
        res->measured_advance = fabs(c.last[0] - c.first[0]) / (double)(c.n_peri - 1) - 2.0 * MECH_PI;
    res->constraint_max_abs = c.max_abs;
    res->constraint_max_relative = c.max_rel;
    res->constraint_final_relative = c.last_rel;
    res->measured_deflection = NAN;
    if (st == MECH_OK && !timelike && res->escaped && in->rdot0 <= 0) {
        const double b = fabs(in->L);
        double w1 = 0.0, t0 = 0.0, t1 = 0.0; /* initialised: GCC -O3 warns (maybe-uninitialized) */
        struct mech_error e2;
        mech_error_clear(&e2);
        if (light_w1(b, &w1, &e2) == MECH_OK && light_tail(b, w1, r0, &t0, &e2) == MECH_OK &&
            light_tail(b, w1, res->end_r, &t1, &e2) == MECH_OK)
            res->measured_deflection = fabs(ye[2] - in->phi0) + t0 + t1 - MECH_PI;
    }
    free(ts);
    free(ys);
    return st;
}
