/* integrators/gauss_legendre.c — the 2- and 3-stage Gauss–Legendre
 * collocation methods (orders 4 and 6), implicit, symplectic and symmetric,
 * fixed step, on libmech's stepper interface (integrator.h). They work on the
 * first-order right-hand side, so they handle any system.
 *
 * Reference: J. C. Butcher, "Implicit Runge-Kutta processes", Math. Comp. 18
 * (1964) 50-64 (the Butcher tableaux below); E. Hairer, C. Lubich,
 * G. Wanner, Geometric Numerical Integration, 2nd ed. (Springer, 2006),
 * Sect. II.1.3 (Gauss collocation methods), Sect. IV.2.1 (they conserve
 * every quadratic first integral exactly) and Sect. VI.4 (symplectic).
 *
 *   K_i = f(t + c_i h, y + h sum_j a_ij K_j),  i = 1..s,
 *   y1  = y + h sum_i b_i K_i.
 *
 * Stage equations: fixed-point (Picard) iteration ITERATED TO ROUND-OFF,
 * started from K_i = f(t, y) at every call (no guess is carried between
 * calls, so step() is a pure function of (t, h, y), as the driver's
 * sub-steps need). The iteration runs until the increments vanish: it stops
 * when the largest change of h K_i, relative to |y| + |h K_i| per component,
 * is exactly 0, or when it stops decreasing at the round-off floor
 * (<= GL_STALL_TOL) — the criterion of E. Hairer, R. I. McLachlan,
 * A. Razakarivony, BIT 48 (2008) 231-243. Stopping earlier, at 2 eps, costs
 * one iteration less but leaves a systematic error: measured 6e-13 instead of
 * 3e-14 energy drift over 1e4 oscillator periods. It fails with
 * MECH_ENUMERIC "implicit stage equations did not converge at t = ..."
 * (param "integrator/dt") after GL_MAX_ITER iterations or when it diverges.
 * It converges when h L rho(A) < 1 (L the Lipschitz constant of f): steps
 * must resolve the fastest time scale, which fixed-step users do anyway; stiff
 * problems belong to msbdf. GSL's rk4imp takes its iteration tolerance from
 * the driver's error control and is not converged at fixed step
 * (notes/numerics.md), hence this file.
 *
 * Cost per step: 1 + s * (iterations) evaluations; measured about 8
 * iterations on Kepler e = 0.5 at 400 steps per orbit (gauss4 17.6, gauss6
 * 24.7 evaluations per step), 10-13 at 20 steps per oscillator period.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ode/integrators/integrator.h"

enum { GL_MAX_ITER = 100, GL_MAX_STAGES = 3 };
/* A relative change this small that no longer decreases is round-off. */
static const double GL_STALL_TOL = 1e-14;

/* Butcher (1964); HLW GNI Sect. II.1.3.
 *
 * Exact symplecticity in floating point. A Runge-Kutta method conserves
 * quadratic invariants (and is symplectic) if b_i a_ij + b_j a_ji = b_i b_j
 * for all i, j (G. J. Cooper, IMA J. Numer. Anal. 7 (1987) 1-13; HLW GNI
 * Sects. IV.2.1, VI.4). Rounded coefficients
 * break this by ~1e-17, which shows as a LINEAR energy drift (measured:
 * 4.6e-13 over 1e4 oscillator periods). So the stored values below satisfy
 * the condition exactly as real numbers (checked with exact rational
 * arithmetic), at the price of moving one coefficient of each pair by
 * < 3e-15 relative (irrelevant to the order conditions at double
 * precision).
 *
 * s = 2, order 4: c = 1/2 -+ sqrt(3)/6, b = [1/2, 1/2],
 * A = [[1/4, 1/4 - sqrt(3)/6], [1/4 + sqrt(3)/6, 1/4]].
 * G4_A21 is 1/4 + sqrt(3)/6 correctly rounded; a12 = 1/2 - G4_A21 (exact in
 * floating point, Sterbenz), so b1 a12 + b2 a21 = b1 b2 exactly. */
static const double G4_C1 = 0.2113248654051871177454256;  /* 1/2 - sqrt(3)/6 */
static const double G4_C2 = 0.7886751345948128822545744;  /* 1/2 + sqrt(3)/6 */
static const double G4_A21 = 0.5386751345948128822545744;  /* 1/4 + sqrt(3)/6 */

/* s = 3, order 6: c = 1/2 - sqrt(15)/10, 1/2, 1/2 + sqrt(15)/10,
 * b = [5/18, 4/9, 5/18],
 * A = [[5/36, 2/9 - sqrt(15)/15, 5/36 - sqrt(15)/30],
 *      [5/36 + sqrt(15)/24, 2/9, 5/36 - sqrt(15)/24],
 *      [5/36 + sqrt(15)/30, 2/9 + sqrt(15)/15, 5/36]].
 * 5/18 and 4/9 are not binary fractions, so the step works with the scaled
 * integer weights B = 18 b = [5, 8, 5] and G = 36 A (diagonal 5, 8, 5), with
 * Y_i = y + (h/36) sum_j G_ij K_j and y1 = y + 2 (h/36) sum_i B_i K_i (the
 * factor 2 is exact, so both use the same rounded h/36). The symplecticity
 * condition becomes B_i G_ij + B_j G_ji = 2 B_i B_j:
 *   G13 = 10 - G31 (exact), with G31 = 5 + 1.2 sqrt(15) correctly rounded;
 *   G12 = 8 - 2.4 sqrt(15) rounded to a multiple of 2^-46, G21 = (80 - 5 G12)/8;
 *   G32 = 8 + 2.4 sqrt(15) rounded to a multiple of 2^-46, G23 = (80 - 5 G32)/8;
 * every operation exact in floating point. */
static const double G6_C1 = 0.1127016653792583114820735;   /* 1/2 - sqrt(15)/10 */
static const double G6_C3 = 0.8872983346207416885179265;   /* 1/2 + sqrt(15)/10 */
static const double G6_G12 = -1.2951600308978044;  /* 36 (2/9 - sqrt(15)/15), 46-bit fraction */
static const double G6_G31 = 9.6475800154489004;   /* 36 (5/36 + sqrt(15)/30) */
static const double G6_G32 = 17.295160030897804;   /* 36 (2/9 + sqrt(15)/15), 46-bit fraction */

struct gl_ws {
    const char *name;
    size_t dim;
    int s;
    /* a_ij = a[i][j] / scale, b_i = 2 b[i] / scale (scale 36, gauss6) or
     * a_ij = a[i][j], b_i = b[i] (scale 1, gauss4) */
    double a[GL_MAX_STAGES][GL_MAX_STAGES], b[GL_MAX_STAGES], c[GL_MAX_STAGES];
    double scale;
    double *k;    /* s * dim: current stage derivatives */
    double *knew; /* s * dim */
    double *ys;   /* dim: a stage state */
};

static enum mech_status gl_alloc(void **ws, size_t dim, int s, const char *name,
                                 struct mech_error *err)
{
    struct gl_ws *w = calloc(1, sizeof *w);
    double *block = malloc((2 * (size_t)s + 1) * (dim ? dim : 1) * sizeof *block);
    if (!w || !block) {
        free(w);
        free(block);
        return mech_error_set(err, MECH_ENOMEM, NULL, "%s: out of memory", name);
    }
    w->name = name;
    w->dim = dim;
    w->s = s;
    w->k = block;
    w->knew = block + (size_t)s * dim;
    w->ys = block + 2 * (size_t)s * dim;
    if (s == 2) {
        w->c[0] = G4_C1;
        w->c[1] = G4_C2;
        w->a[0][0] = 0.25;
        w->a[0][1] = 0.5 - G4_A21; /* exact */
        w->a[1][0] = G4_A21;
        w->a[1][1] = 0.25;
        w->b[0] = 0.5;
        w->b[1] = 0.5;
        w->scale = 1.0;
    } else {
        /* scaled: G = 36 A, B = 18 b (see above) */
        w->c[0] = G6_C1;
        w->c[1] = 0.5;
        w->c[2] = G6_C3;
        w->a[0][0] = 5.0;
        w->a[0][1] = G6_G12;
        w->a[0][2] = 10.0 - G6_G31; /* exact */
        w->a[1][0] = (80.0 - 5.0 * G6_G12) / 8.0; /* exact */
        w->a[1][1] = 8.0;
        w->a[1][2] = (80.0 - 5.0 * G6_G32) / 8.0; /* exact */
        w->a[2][0] = G6_G31;
        w->a[2][1] = G6_G32;
        w->a[2][2] = 5.0;
        w->b[0] = 5.0;
        w->b[1] = 8.0;
        w->b[2] = 5.0;
        w->scale = 36.0;
    }
    *ws = w;
    return MECH_OK;
}

static enum mech_status gauss4_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                     struct mech_error *err)
{
    (void)opt;
    return gl_alloc(ws, dim, 2, "gauss4", err);
}

static enum mech_status gauss6_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                     struct mech_error *err)
{
    (void)opt;
    return gl_alloc(ws, dim, 3, "gauss6", err);
}

static void gl_reset(void *ws) { (void)ws; /* stateless between steps */ }

static void gl_free(void *ws)
{
    struct gl_ws *w = ws;
    if (!w) return;
    free(w->k);
    free(w);
}

static enum mech_status gl_not_converged(const struct gl_ws *w, double t, double h, int it,
                                         double d, struct mech_error *err)
{
    return mech_error_set(err, MECH_ENUMERIC, "integrator/dt",
                          "%s: implicit stage equations did not converge at t = %.9g s "
                          "(step %.6g s, %d iterations, last relative change %.3g): reduce dt",
                          w->name, t, h, it, d);
}

static enum mech_status gl_step(void *ws, const struct mech_ode_system *sys, double t, double h,
                                double *y, struct mech_ode_stats *stats, struct mech_error *err)
{
    struct gl_ws *w = ws;
    const size_t n = w->dim;
    const int s = w->s;
    enum mech_status st;
    /* stage and update factors: h a_ij = ha a[i][j], h b_i = hb b[i] */
    const double ha = w->scale == 1.0 ? h : h / w->scale;
    const double hb = w->scale == 1.0 ? h : 2.0 * ha;

    /* Starting guess K_i = f(t, y): the same at every call. */
    if ((st = mech_ode_eval(sys, t, y, w->k, stats, err)) != MECH_OK) return st;
    for (int i = 1; i < s; i++) memcpy(w->k + (size_t)i * n, w->k, n * sizeof *y);

    double d_prev = INFINITY;
    int converged = 0, it = 0;
    double d = INFINITY;
    while (!converged) {
        if (it == GL_MAX_ITER) return gl_not_converged(w, t, h, it, d, err);
        it++;
        /* K_new_i = f(t + c_i h, y + h sum_j a_ij K_j) (Butcher 1964). */
        for (int i = 0; i < s; i++) {
            for (size_t m = 0; m < n; m++) {
                double z = 0.0;
                for (int j = 0; j < s; j++) z += w->a[i][j] * w->k[(size_t)j * n + m];
                w->ys[m] = y[m] + ha * z;
            }
            st = mech_ode_eval(sys, t + w->c[i] * h, w->ys, w->knew + (size_t)i * n, stats, err);
            if (st != MECH_OK) return st;
        }
        /* Largest change of h K relative to |y| + |h K|, per component. */
        d = 0.0;
        for (int i = 0; i < s; i++)
            for (size_t m = 0; m < n; m++) {
                const size_t idx = (size_t)i * n + m;
                const double dk = fabs(h * (w->knew[idx] - w->k[idx]));
                if (dk == 0.0) continue;
                const double scale =
                    fabs(y[m]) + fabs(h * w->knew[idx]) + fabs(h * w->k[idx]);
                d = fmax(d, dk / scale);
            }
        memcpy(w->k, w->knew, (size_t)s * n * sizeof *y);
        if (d == 0.0) converged = 1;
        else if (d >= d_prev && d <= GL_STALL_TOL) converged = 1; /* round-off floor */
        else if (d >= d_prev && d > 1.0 && it >= 3) return gl_not_converged(w, t, h, it, d, err);
        d_prev = d;
    }
    /* y1 = y + h sum_i b_i K_i */
    for (size_t m = 0; m < n; m++) {
        double z = 0.0;
        for (int i = 0; i < s; i++) z += w->b[i] * w->k[(size_t)i * n + m];
        y[m] += hb * z;
    }
    return MECH_OK;
}

const struct mech_integrator mech_integrator_gauss4 = {
    .name = "gauss4",
    .order = 4,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_SYMMETRIC,
    .doc = "Two-stage Gauss-Legendre collocation, implicit, fixed step dt, global error "
           "O(dt^4). Symplectic and time-symmetric for any Hamiltonian system, conserves "
           "quadratic invariants (angular momentum, a harmonic oscillator's energy) to "
           "round-off; the stage equations are iterated to round-off (1 + 2 x 6-12 "
           "right-hand-side evaluations per step). Works on any system; dt must resolve the "
           "fastest time scale (it is not meant for stiff problems).",
    .reference = "J. C. Butcher, Math. Comp. 18 (1964) 50-64; E. Hairer, C. Lubich, G. Wanner, "
                 "Geometric Numerical Integration, 2nd ed. (Springer, 2006), Sect. II.1.3, "
                 "Sects. IV.2.1 and VI.4.",
    .alloc = gauss4_alloc,
    .reset = gl_reset,
    .free = gl_free,
    .step = gl_step,
    .evolve = NULL,
};

const struct mech_integrator mech_integrator_gauss6 = {
    .name = "gauss6",
    .order = 6,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_SYMMETRIC,
    .doc = "Three-stage Gauss-Legendre collocation, implicit, fixed step dt, global error "
           "O(dt^6). Symplectic and time-symmetric for any Hamiltonian system, conserves "
           "quadratic invariants to round-off; the stage equations are iterated to round-off "
           "(1 + 3 x 6-12 right-hand-side evaluations per step). Works on any system, "
           "velocity-dependent forces included; dt must resolve the fastest time scale.",
    .reference = "J. C. Butcher, Math. Comp. 18 (1964) 50-64; E. Hairer, C. Lubich, G. Wanner, "
                 "Geometric Numerical Integration, 2nd ed. (Springer, 2006), Sect. II.1.3, "
                 "Sects. IV.2.1 and VI.4.",
    .alloc = gauss6_alloc,
    .reset = gl_reset,
    .free = gl_free,
    .step = gl_step,
    .evolve = NULL,
};
