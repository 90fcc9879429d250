/* kepler.c — two-body Kepler motion by universal variables (mech/ode/kepler.h):
 * the bracketed propagator every Kepler reference and closed form uses, and
 * the Kepler drift of the Wisdom–Holman splitting (integrators/wisdom_holman.c).
 * In core/ode because the splitting needs it; the trajectory's references
 * (core/frames/reference.c) build on it in turn.
 */
#include "mech/ode/kepler.h"
#include "mech/base/constants.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* ---- Stumpff functions ----------------------------------------------------
 * c_k(z) = sum_j (-z)^j / (k + 2j)!  (Danby §6.9; Vallado §2.2, eqs. 2-52).
 * Series for |z| < 2 (terms fall by z/((k+2j+1)(k+2j+2)) each, 25 terms are
 * far below round-off), closed forms otherwise. */
static void stumpff(double z, double c[4])
{
    if (fabs(z) < 2.0) {
        /* c_k(z) = 1/k! - z/(k+2)! + z^2/(k+4)! - ... */
        for (int k = 0; k < 4; k++) {
            double term = 1.0, sum;
            for (int i = 2; i <= k; i++) term /= i; /* 1/k! */
            sum = term;
            for (int j = 1; j < 25; j++) {
                term *= -z / ((double)(k + 2 * j - 1) * (double)(k + 2 * j));
                sum += term;
                if (fabs(term) < 1e-18 * fabs(sum)) break;
            }
            c[k] = sum;
        }
        return;
    }
    if (z > 0.0) {
        double y = sqrt(z), sh = sin(0.5 * y);
        c[0] = cos(y);
        c[1] = sin(y) / y;
        c[2] = 2.0 * sh * sh / z;
        c[3] = (y - sin(y)) / (z * y);
    } else {
        double y = sqrt(-z), sh = sinh(0.5 * y);
        c[0] = cosh(y);
        c[1] = sinh(y) / y;
        c[2] = 2.0 * sh * sh / (-z);
        c[3] = (sinh(y) - y) / (-z * y);
    }
}

/* ---- double-double helpers (Dekker, Knuth; fma for the products) ---------- */

/* a + b = s + e exactly */
static void two_sum(double a, double b, double *s, double *e)
{
    *s = a + b;
    const double bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
}

/* |u|^2 as hi + lo (the rounding errors of the squares and sums kept) */
static void sum_squares_dd(struct mech_vec3 u, double *hi, double *lo)
{
    const double px = u.x * u.x, py = u.y * u.y, pz = u.z * u.z;
    const double ex = fma(u.x, u.x, -px), ey = fma(u.y, u.y, -py), ez = fma(u.z, u.z, -pz);
    double s1, e1, s2, e2;
    two_sum(px, py, &s1, &e1);
    two_sum(s1, pz, &s2, &e2);
    *hi = s2;
    *lo = ex + ey + ez + e1 + e2;
}

/* beta = 2 gm / |r0| - |v0|^2 (Danby's alpha; gm / a). Near parabolic the two
 * terms nearly cancel (beta / (2 gm / r0) ~ 1 - e), so each is formed in
 * double-double and the difference is taken on the high parts (exact by
 * Sterbenz when they are within a factor 2) plus the low parts: beta to a few
 * eps relative instead of eps / (1 - e) (at e = 0.99999 the period was off by
 * ~5e-11 relative, its position near periapsis by as much). */
static double kepler_beta(double gm, struct mech_vec3 r0v, struct mech_vec3 v0v, double *lo)
{
    double r2, r2_lo, v2, v2_lo;
    sum_squares_dd(r0v, &r2, &r2_lo);
    sum_squares_dd(v0v, &v2, &v2_lo);
    const double r0 = sqrt(r2);
    const double r0_lo = (fma(-r0, r0, r2) + r2_lo) / (2.0 * r0);
    const double g2 = 2.0 * gm; /* exact */
    const double q = g2 / r0;
    const double q_lo = (fma(-q, r0, g2) - q * r0_lo) / r0;
    const double d = q - v2, d_lo = q_lo - v2_lo;
    const double b = d + d_lo;
    if (lo) *lo = (d - b) + d_lo; /* what rounding b dropped */
    return b;
}

struct kepler_eq {
    double r0, sigma0, gm, beta, t; /* sigma0 = r0.v0, beta = gm (2/r0 - v0^2/gm) */
};

/* G-functions G_k = s^k c_k(beta s^2); F(s) = r0 G1 + sigma0 G2 + gm G3 - t and
 * F'(s) = r(s) = r0 G0 + sigma0 G1 + gm G2. */
static void kepler_eval(const struct kepler_eq *k, double s, double G[4], double *F, double *r)
{
    double c[4];
    stumpff(k->beta * s * s, c);
    G[0] = c[0];
    G[1] = s * c[1];
    G[2] = s * s * c[2];
    G[3] = s * s * s * c[3];
    *F = k->r0 * G[1] + k->sigma0 * G[2] + k->gm * G[3] - k->t;
    *r = k->r0 * G[0] + k->sigma0 * G[1] + k->gm * G[2];
}

enum mech_status mech_kepler_propagate(double gm, struct mech_vec3 r0v, struct mech_vec3 v0v,
                                       double t, struct mech_vec3 *r, struct mech_vec3 *v,
                                       struct mech_error *err)
{
    return mech_kepler_propagate_residual(gm, r0v, v0v, t, r, v, NULL, err);
}

enum mech_status mech_kepler_propagate_residual(double gm, struct mech_vec3 r0v,
                                                struct mech_vec3 v0v, double t,
                                                struct mech_vec3 *r, struct mech_vec3 *v,
                                                double *residual, struct mech_error *err)
{
    if (residual) *residual = 0.0;
    if (!r || !v) return mech_error_set(err, MECH_EINVAL, NULL, "NULL output");
    const double r0 = mech_vec3_norm(r0v);
    if (!(isfinite(gm) && gm > 0.0) || !(r0 > 0.0 && isfinite(r0)) ||
        !mech_vec3_isfinite(v0v) || !isfinite(t))
        return mech_error_set(err, MECH_EINVAL, NULL, "invalid Kepler propagation arguments");
    struct kepler_eq k;
    k.r0 = r0;
    k.sigma0 = mech_vec3_dot(r0v, v0v);
    k.gm = gm;
    /* beta = gm / a = 2 gm / r0 - v^2 (Danby's alpha), > 0 bound, 0 parabolic. */
    double beta_lo;
    k.beta = kepler_beta(gm, r0v, v0v, &beta_lo);
    k.t = t;

    double lo, hi;
    if (k.beta > 0.0) {
        /* Bound orbit: reduce by whole periods P = 2 pi gm / beta^(3/2)
         * (= 2 pi sqrt(a^3 / gm)). The reduction t - k P multiplies P's
         * error by the k periods removed: P in double (2-3 ulp) moved the
         * answer after 1000 orbits of e = 0.9 by 1.5e-10 (its pericentre
         * speed times 1000 x 1.5 ulp of P), 1e5 times round-off. So P comes
         * from beta's high and low parts in long double (64-bit mantissa on
         * x86-64: 2^-11 of a double's error; quad elsewhere), and the
         * remainder is formed there too; the solve within one period then
         * needs beta only in double. */
        const long double B = (long double)k.beta + (long double)beta_lo;
        const long double PL =
            MECH_TWO_PI_L * (long double)gm / (B * sqrtl(B));
        long double kp = floorl((long double)t / PL);
        long double trl = (long double)t - kp * PL;
        if (trl < 0.0L) trl += PL;
        if (trl >= PL) trl -= PL;
        double tr = (double)trl;
        k.t = tr;
        lo = 0.0;
        hi = 2.0 * MECH_PI / sqrt(k.beta); /* F(hi) = P - tr >= 0 */
    } else {
        /* F is increasing (F' = r > 0); bracket by doubling from t / r0. */
        double s = t / r0, G[4], F, rr;
        if (s == 0.0) {
            *r = r0v;
            *v = v0v;
            return MECH_OK;
        }
        int it = 0;
        for (;; it++) {
            kepler_eval(&k, s, G, &F, &rr);
            if (isnan(F)) F = s > 0.0 ? INFINITY : -INFINITY; /* overflow: beyond the root */
            if ((s > 0.0 && F >= 0.0) || (s < 0.0 && F <= 0.0)) break;
            if (it > 2100) return mech_error_set(err, MECH_ENUMERIC, NULL,
                                                 "Kepler equation: no bracket found");
            s *= 2.0;
        }
        lo = s > 0.0 ? 0.0 : s;
        hi = s > 0.0 ? s : 0.0;
    }

    /* Newton safeguarded by bisection (Numerical Recipes' rtsafe). */
    double s = 0.5 * (lo + hi), G[4], F, rr;
    if (k.beta > 0.0) s = k.t / (2.0 * MECH_PI * gm / (k.beta * sqrt(k.beta))) * hi; /* mean-anomaly guess */
    for (int it = 0; it < 2200; it++) {
        kepler_eval(&k, s, G, &F, &rr);
        if (!isfinite(F)) F = s > 0.0 ? INFINITY : -INFINITY;
        if (F == 0.0) break;
        if (F < 0.0) lo = s;
        else hi = s;
        double sn = s - F / rr;
        if (!(sn > lo && sn < hi) || !isfinite(sn)) sn = 0.5 * (lo + hi);
        const double tol = 2.0 * DBL_EPSILON * fabs(sn) + DBL_MIN;
        if (fabs(sn - s) <= tol || hi - lo <= tol) {
            s = sn;
            break;
        }
        s = sn;
    }
    kepler_eval(&k, s, G, &F, &rr);
    if (residual) {
        /* |F(s)| relative to the size of the terms it balances */
        const double scale = fabs(k.r0 * G[1]) + fabs(k.sigma0 * G[2]) + fabs(k.gm * G[3]) +
                             fabs(k.t);
        *residual = scale > 0.0 ? fabs(F) / scale : 0.0;
    }
    if (!(rr > 0.0) || !isfinite(rr))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the Kepler orbit passes through the centre (radial orbit)");
    /* f and g functions (Danby eqs. 6.9.x): no t - ... cancellation in g. */
    const double f = 1.0 - gm * G[2] / r0;
    const double g = r0 * G[1] + k.sigma0 * G[2];
    const double fd = -gm * G[1] / (rr * r0);
    const double gd = 1.0 - gm * G[2] / rr;
    *r = mech_vec3_add(mech_vec3_scale(r0v, f), mech_vec3_scale(v0v, g));
    *v = mech_vec3_add(mech_vec3_scale(r0v, fd), mech_vec3_scale(v0v, gd));
    if (!mech_vec3_isfinite(*r) || !mech_vec3_isfinite(*v))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite Kepler state at t = %.9g s",
                              t);
    return MECH_OK;
}

/* ---- the Kepler drift of a splitting method (mech_kepler_drift) -------------
 * Per-step use: the step is usually a small fraction of an orbit, so z =
 * beta s^2 is small and only c2, c3 need their series, evaluated by Horner
 * with constant coefficients (c0 = 1 - z c2, c1 = 1 - z c3, Danby eq. 6.9.x
 * recursion); the first guess is the second-order series of
 * s(t) = integral dt / r,
 *   s ~ dt / r0 - sigma0 dt^2 / (2 r0^3)        (dr/dt = sigma0 / r0 at t = 0),
 * improved by Halley's method (cubic: F' = r, F'' = dr/ds = sigma0 G0 +
 * (gm - beta r0) G1; as in H. Rein, D. Tamayo, MNRAS 452 (2015) 376, whose
 * incremental update r = r0 + (f - 1) r0 + g v0 is also used). Once a
 * correction is below 1e-7 |s| the next one would be below round-off (cubic
 * convergence), so the G-functions are evaluated once more there and used:
 * 3 evaluations for a step of 1/100 orbit.
 * The guess is a function of (r0, v0, dt) only (no warm start from the
 * previous step): a stepper's step must not depend on its history
 * (integrators/integrator.h), and the series guess already costs no more
 * iterations than a warm start would. */
enum { KEPLER_DRIFT_MAX_ITER = 12 };

/* c2(z), c3(z) for |z| <= 1: sum_j (-z)^j / (2j+2)! and / (2j+3)!, 10 terms
 * (the first neglected is below 1/22! = 9e-22), by Horner; closed forms
 * (stumpff) beyond. */
static void stumpff23(double z, double *c2, double *c3)
{
    static const double k2[10] = {1.0 / 2.0,
                                  1.0 / 24.0,
                                  1.0 / 720.0,
                                  1.0 / 40320.0,
                                  1.0 / 3628800.0,
                                  1.0 / 479001600.0,
                                  1.0 / 87178291200.0,
                                  1.0 / 20922789888000.0,
                                  1.0 / 6402373705728000.0,
                                  1.0 / 2432902008176640000.0};
    static const double k3[10] = {1.0 / 6.0,
                                  1.0 / 120.0,
                                  1.0 / 5040.0,
                                  1.0 / 362880.0,
                                  1.0 / 39916800.0,
                                  1.0 / 6227020800.0,
                                  1.0 / 1307674368000.0,
                                  1.0 / 355687428096000.0,
                                  1.0 / 121645100408832000.0,
                                  1.0 / 51090942171709440000.0};
    if (fabs(z) > 1.0) {
        double c[4];
        stumpff(z, c);
        *c2 = c[2];
        *c3 = c[3];
        return;
    }
    double a2 = k2[9], a3 = k3[9];
    for (int j = 8; j >= 0; j--) {
        a2 = k2[j] - z * a2;
        a3 = k3[j] - z * a3;
    }
    *c2 = a2;
    *c3 = a3;
}

/* Whether a radial orbit (zero angular momentum) from (rn0, sigma0 = r0.v0,
 * beta) reaches the centre within dt, given the radial velocity's sign at
 * the end (sigma1). Bound: r = a (1 - cos E), t = (E - sin E)/n from the
 * last collision (Danby §6.4); unbound: one collision at most, after which
 * the (reflected) solution moves outwards, so the sign of r.v flips. */
static int radial_collision(double gm, double rn0, double sigma0, double beta, double dt,
                            double sigma1)
{
    const double dir = dt > 0.0 ? 1.0 : -1.0;
    if (!(beta > 0.0)) return sigma0 * dir < 0.0 && sigma1 * dir > 0.0;
    const double a = gm / beta, n = sqrt(beta * beta * beta) / gm, P = 2.0 * MECH_PI / n;
    double c = 1.0 - rn0 / a;
    c = c > 1.0 ? 1.0 : c < -1.0 ? -1.0 : c;
    double E = acos(c); /* rising (sigma0 > 0): E in [0, pi] */
    if (sigma0 < 0.0) E = 2.0 * MECH_PI - E;
    const double since = (E - sin(E)) / n; /* time since the last collision */
    return dt > 0.0 ? dt >= P - since : -dt >= since;
}

/* Store (nr, nv) in (r, v) unless the orbit is radial (|r0 x v0| below
 * 1e-12 |r0| |v0|: no angular momentum to round-off) and reached the centre
 * during the step: the universal-variable solution would continue it as a
 * reflection, which is not the physics (a collision). */
static enum mech_status radial_check(double gm, const double r0[3], const double v0[3],
                                     double rn0, double sigma0, double beta, double dt,
                                     const double nr[3], const double nv[3], double r[3],
                                     double v[3], struct mech_error *err)
{
    const double lx = r0[1] * v0[2] - r0[2] * v0[1], ly = r0[2] * v0[0] - r0[0] * v0[2],
                 lz = r0[0] * v0[1] - r0[1] * v0[0];
    const double v2 = v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2];
    if (lx * lx + ly * ly + lz * lz <= 1e-24 * rn0 * rn0 * v2) {
        const double sigma1 = nr[0] * nv[0] + nr[1] * nv[1] + nr[2] * nv[2];
        if (radial_collision(gm, rn0, sigma0, beta, dt, sigma1))
            return mech_error_set(err, MECH_ENUMERIC, NULL,
                                  "the radial Kepler orbit reaches the centre within %.9g s",
                                  dt);
    }
    for (int i = 0; i < 3; i++) {
        r[i] = nr[i];
        v[i] = nv[i];
    }
    return MECH_OK;
}

enum mech_status mech_kepler_drift(double gm, const double r0[3], const double v0[3], double dt,
                                   double r[3], double v[3], int *newton_iterations,
                                   struct mech_error *err)
{
    if (newton_iterations) *newton_iterations = 0;
    const double rr0 = r0[0] * r0[0] + r0[1] * r0[1] + r0[2] * r0[2];
    const double rn0 = sqrt(rr0);
    const double sigma0 = r0[0] * v0[0] + r0[1] * v0[1] + r0[2] * v0[2];
    const double v2 = v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2];
    const double beta = 2.0 * gm / rn0 - v2;
    if (dt == 0.0 && rn0 > 0.0 && isfinite(rn0)) {
        for (int i = 0; i < 3; i++) {
            r[i] = r0[i];
            v[i] = v0[i];
        }
        return MECH_OK;
    }
    int ok = isfinite(beta) && isfinite(sigma0) && rn0 > 0.0 && isfinite(dt) && gm > 0.0 &&
             isfinite(gm);
    double s = 0.0, c2 = 0.0, c3 = 0.0, rs = 0.0, G1 = 0.0, G2 = 0.0;
    int it = 0;
    if (ok) {
        const double zeta0 = gm - beta * rn0;
        s = dt / rn0 - sigma0 * dt * dt / (2.0 * rn0 * rn0 * rn0);
        ok = 0;
        int last = 0;
        for (it = 1; it <= KEPLER_DRIFT_MAX_ITER && isfinite(s); it++) {
            const double z = beta * s * s;
            stumpff23(z, &c2, &c3);
            const double G0 = 1.0 - z * c2;
            G1 = s * (1.0 - z * c3);
            G2 = s * s * c2;
            const double G3 = s * s * s * c3;
            rs = rn0 * G0 + sigma0 * G1 + gm * G2;
            if (!(rs > 0.0)) break;
            if (last) {
                ok = 1;
                break;
            }
            const double F = rn0 * G1 + sigma0 * G2 + gm * G3 - dt;
            const double Fpp = sigma0 * G0 + zeta0 * G1;
            const double den = rs - 0.5 * F * Fpp / rs;
            const double ds = den > 0.5 * rs ? F / den : F / rs; /* Halley, else Newton */
            s -= ds;
            last = fabs(ds) <= 1e-7 * fabs(s);
        }
    }
    if (newton_iterations) *newton_iterations = it;
    if (!ok) {
        /* Long step (a large fraction of an orbit), a near-radial passage or
         * a bad argument: the bracketed solver (period reduction, Newton
         * safeguarded by bisection), which returns a status, never a guess. */
        struct mech_vec3 a, b;
        enum mech_status st =
            mech_kepler_propagate(gm, mech_vec3_make(r0[0], r0[1], r0[2]),
                                  mech_vec3_make(v0[0], v0[1], v0[2]), dt, &a, &b, err);
        if (st != MECH_OK) return st;
        const double nr[3] = {a.x, a.y, a.z}, nv[3] = {b.x, b.y, b.z};
        return radial_check(gm, r0, v0, rn0, sigma0, beta, dt, nr, nv, r, v, err);
    }
    /* f and g functions at the converged s (Danby §6.9), as increments
     * (f - 1, g, fd, gd - 1) so no 1 + tiny rounds away the motion of a
     * short step; g without the dt - gm G3 cancellation. */
    const double fm1 = -gm * G2 / rn0, g = rn0 * G1 + sigma0 * G2;
    const double fd = -gm * G1 / (rs * rn0), gdm1 = -gm * G2 / rs;
    double nr[3], nv[3];
    for (int i = 0; i < 3; i++) {
        nr[i] = r0[i] + (fm1 * r0[i] + g * v0[i]);
        nv[i] = v0[i] + (fd * r0[i] + gdm1 * v0[i]);
    }
    for (int i = 0; i < 3; i++)
        if (!isfinite(nr[i]) || !isfinite(nv[i]))
            return mech_error_set(err, MECH_ENUMERIC, NULL,
                                  "non-finite Kepler drift state after %.9g s", dt);
    return radial_check(gm, r0, v0, rn0, sigma0, beta, dt, nr, nv, r, v, err);
}
