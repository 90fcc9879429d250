/* coupled_oscillations.c — normal modes of M q'' + K q = 0 (generalised
 * symmetric eigenproblem K v = w^2 M v via GSL's Cholesky reduction), the
 * deterministic basis of degenerate clusters, the motion as a sum of modes,
 * and the M and K of the standard set-ups. */
#include "mech/hamiltonian/coupled_oscillations.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>

#define NMAX MECH_COUPLED_MAX_DOF

/* Largest |entry|, or -1 after recording the first non-finite or asymmetric
 * entry under param "<name>/<i>/<j>". */
static double check_symmetric(size_t n, const double *a, const char *name,
                              struct mech_error *err)
{
    double big = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            if (!isfinite(a[i * n + j])) {
                char p[64];
                snprintf(p, sizeof p, "%s/%zu/%zu", name, i, j);
                mech_error_set(err, MECH_EINVAL, p, "must be finite");
                return -1;
            }
            big = fmax(big, fabs(a[i * n + j]));
        }
    for (size_t i = 1; i < n; i++)
        for (size_t j = 0; j < i; j++)
            if (fabs(a[i * n + j] - a[j * n + i]) > 1e-12 * big) {
                char p[64];
                snprintf(p, sizeof p, "%s/%zu/%zu", name, i, j);
                mech_error_set(err, MECH_EINVAL, p,
                               "the matrix must be symmetric: entry [%zu][%zu] = %.17g but "
                               "[%zu][%zu] = %.17g (they may differ by 1e-12 of the largest "
                               "entry)",
                               i, j, a[i * n + j], j, i, a[j * n + i]);
                return -1;
            }
    return big;
}

/* Even power of two e with big * 2^-e in [0.25, 1) (0 for big = 0). */
static int even_exponent(double big)
{
    int e = 0;
    if (big > 0) frexp(big, &e);
    return (e % 2) ? e + 1 : e;
}

/* The symmetrised, scaled copy (a + a^T)/2 * 2^-e into g. */
static void load_scaled(size_t n, const double *a, int e, gsl_matrix *g)
{
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            gsl_matrix_set(g, i, j, ldexp(0.5 * (a[i * n + j] + a[j * n + i]), -e));
}

/* Smallest and largest eigenvalue of the symmetric matrix in g (destroyed). */
static enum mech_status extreme_eigenvalues(gsl_matrix *g, double *lo, double *hi,
                                            struct mech_error *err)
{
    size_t n = g->size1;
    gsl_vector *ev = gsl_vector_alloc(n);
    gsl_eigen_symm_workspace *w = gsl_eigen_symm_alloc(n);
    if (!ev || !w) {
        gsl_vector_free(ev);
        gsl_eigen_symm_free(w);
        return mech_error_set(err, MECH_ENOMEM, NULL, "eigen-solver workspace");
    }
    int gs = gsl_eigen_symm(g, ev, w);
    gsl_eigen_symm_free(w);
    if (gs == GSL_SUCCESS) gsl_vector_minmax(ev, lo, hi);
    gsl_vector_free(ev);
    if (gs != GSL_SUCCESS)
        return mech_error_set(err, MECH_ENUMERIC, "mass_matrix", "eigen-solver failed: %s",
                              gsl_strerror(gs));
    return MECH_OK;
}

static double m_dot(size_t n, const double *m, const double *x, const double *y)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) {
        double r = 0;
        for (size_t j = 0; j < n; j++) r += m[i * n + j] * y[j];
        s += x[i] * r;
    }
    return s;
}

/* The component of largest magnitude positive (the first within 1e-12). */
static void sign_fix(size_t n, double *v)
{
    double mx = 0;
    for (size_t i = 0; i < n; i++) mx = fmax(mx, fabs(v[i]));
    for (size_t i = 0; i < n; i++)
        if (fabs(v[i]) >= mx * (1 - 1e-12)) {
            if (v[i] < 0)
                for (size_t j = 0; j < n; j++) v[j] = -v[j];
            return;
        }
}

/* Re-basis the cluster of modes [lo, hi) of r (M-orthonormal vectors): see
 * the header. c[j][p] = (M v_p)_j are the coefficients of the projection of
 * e_j on the cluster. */
struct cluster_scratch {
    double c[NMAX][NMAX], q[NMAX][NMAX], nv[NMAX][NMAX];
};

static void cluster_basis(size_t n, const double *m, const double *kmat,
                          struct mech_coupled_modes *r, size_t lo, size_t hi,
                          struct cluster_scratch *sc)
{
    size_t p = hi - lo;
    static const double tie = 1e-9;
    double(*c)[NMAX] = sc->c, (*q)[NMAX] = sc->q, (*nv)[NMAX] = sc->nv;
    for (size_t j = 0; j < n; j++)
        for (size_t a = 0; a < p; a++) {
            double s = 0;
            for (size_t i = 0; i < n; i++) s += m[j * n + i] * r->vectors[lo + a][i];
            c[j][a] = s / sqrt(m[j * n + j]);
        }
    for (size_t b = 0; b < p; b++) {
        double best = -1, nrm[NMAX];
        for (size_t j = 0; j < n; j++) {
            double s = 0;
            for (size_t a = 0; a < p; a++) s += c[j][a] * c[j][a];
            nrm[j] = s;
            best = fmax(best, s);
        }
        size_t pick = 0;
        while (pick + 1 < n && nrm[pick] < best * (1 - tie)) pick++;
        double len = sqrt(nrm[pick]);
        for (size_t a = 0; a < p; a++) q[b][a] = c[pick][a] / len;
        /* deflate: remove q[b] from every coefficient row */
        for (size_t j = 0; j < n; j++) {
            double d = 0;
            for (size_t a = 0; a < p; a++) d += c[j][a] * q[b][a];
            for (size_t a = 0; a < p; a++) c[j][a] -= d * q[b][a];
        }
    }
    for (size_t b = 0; b < p; b++)
        for (size_t i = 0; i < n; i++) {
            double s = 0;
            for (size_t a = 0; a < p; a++) s += q[b][a] * r->vectors[lo + a][i];
            nv[b][i] = s;
        }
    for (size_t b = 0; b < p; b++) {
        memcpy(r->vectors[lo + b], nv[b], n * sizeof(double));
        if (r->omega2[lo] != 0 || r->omega2[hi - 1] != 0)
            r->omega2[lo + b] = m_dot(n, kmat, nv[b], nv[b]);
    }
}

enum mech_status mech_coupled_modes(size_t n, const double *m, const double *k,
                                    struct mech_coupled_modes *out, struct mech_error *err)
{
    if (!out || !m || !k) return mech_error_set(err, MECH_EINVAL, NULL, "no input or output");
    if (n == 0 || n > NMAX)
        return mech_error_set(err, MECH_EINVAL, "mass_matrix",
                              "%zu degrees of freedom: 1 to %d are allowed", n, NMAX);
    double mbig = check_symmetric(n, m, "mass_matrix", err);
    if (mbig < 0) return err ? err->code : MECH_EINVAL;
    double kbig = check_symmetric(n, k, "stiffness_matrix", err);
    if (kbig < 0) return err ? err->code : MECH_EINVAL;
    if (mbig == 0)
        return mech_error_set(err, MECH_EDOMAIN, "mass_matrix",
                              "the mass matrix is zero; it must be positive definite");
    int em = even_exponent(mbig), ek = even_exponent(kbig);

    enum mech_status st = MECH_OK;
    gsl_matrix *gm = gsl_matrix_alloc(n, n), *gk = gsl_matrix_alloc(n, n),
               *gv = gsl_matrix_alloc(n, n);
    gsl_vector *ev = gsl_vector_alloc(n);
    gsl_eigen_gensymmv_workspace *w = gsl_eigen_gensymmv_alloc(n);
    struct mech_coupled_modes *r = out; /* filled below, valid only on MECH_OK */
    struct cluster_scratch *sc = NULL;
    if (!gm || !gk || !gv || !ev || !w) {
        st = mech_error_set(err, MECH_ENOMEM, NULL, "eigen-solver workspace");
        goto done;
    }
    /* positive definiteness, with the margin a massless coordinate would need */
    double mu_lo, mu_hi;
    load_scaled(n, m, em, gm);
    if ((st = extreme_eigenvalues(gm, &mu_lo, &mu_hi, err)) != MECH_OK) goto done;
    if (!(mu_lo > 1e-14 * mu_hi)) {
        st = mech_error_set(err, MECH_EDOMAIN, "mass_matrix",
                            "the mass matrix must be positive definite: its eigenvalues run "
                            "from %.6g to %.6g (the smallest must be > 1e-14 of the largest; "
                            "every coordinate needs inertia)",
                            ldexp(mu_lo, em), ldexp(mu_hi, em));
        goto done;
    }
    load_scaled(n, m, em, gm);
    load_scaled(n, k, ek, gk);
    int gs = gsl_eigen_gensymmv(gk, gm, ev, gv, w);
    if (gs == GSL_SUCCESS) gs = gsl_eigen_gensymmv_sort(ev, gv, GSL_EIGEN_SORT_VAL_ASC);
    if (gs != GSL_SUCCESS) {
        st = mech_error_set(err, MECH_ENUMERIC, "mass_matrix", "eigen-solver failed: %s",
                            gsl_strerror(gs));
        goto done;
    }
    memset(r, 0, sizeof *r);
    r->n = n;
    r->mass_min_eigenvalue = ldexp(mu_lo, em);
    /* ||K||_inf of the scaled K, in units of 2^ek; w^2 = lambda' 2^(ek - em) */
    double kinf = 0;
    for (size_t i = 0; i < n; i++) {
        double s = 0;
        for (size_t j = 0; j < n; j++) s += fabs(k[i * n + j]);
        kinf = fmax(kinf, s);
    }
    r->zero_tol = 256.0 * (double)n * DBL_EPSILON * kinf / r->mass_min_eigenvalue;
    double top = 0;
    for (size_t a = 0; a < n; a++) {
        r->omega2[a] = ldexp(gsl_vector_get(ev, a), ek - em);
        top = fmax(top, fabs(r->omega2[a]));
        double s = ldexp(1.0, -em / 2);
        for (size_t i = 0; i < n; i++) r->vectors[a][i] = gsl_matrix_get(gv, i, a) * s;
        /* mass-normalise in full precision against the caller's M */
        double nn = m_dot(n, m, r->vectors[a], r->vectors[a]);
        if (!(nn > 0) || !isfinite(nn)) {
            st = mech_error_set(err, MECH_ENUMERIC, "mass_matrix",
                                "mode %zu has no finite positive mass", a);
            goto done;
        }
        double f = 1 / sqrt(nn);
        for (size_t i = 0; i < n; i++) r->vectors[a][i] *= f;
    }
    for (size_t a = 0; a < n; a++)
        if (fabs(r->omega2[a]) <= r->zero_tol) r->omega2[a] = 0;
    /* clusters: consecutive w^2 within the tolerance (zero modes form one) */
    double tol = fmax(MECH_COUPLED_DEGENERATE_RTOL * top, r->zero_tol);
    for (size_t lo = 0; lo < n;) {
        size_t hi = lo + 1;
        while (hi < n && r->omega2[hi] - r->omega2[hi - 1] <= tol) hi++;
        if (hi - lo > 1) {
            r->degenerate = 1;
            for (size_t a = lo; a < hi; a++) r->degenerate_mode[a] = 1;
            if (!sc && !(sc = malloc(sizeof *sc))) {
                st = mech_error_set(err, MECH_ENOMEM, NULL, "scratch for a degenerate cluster");
                goto done;
            }
            cluster_basis(n, m, k, r, lo, hi, sc);
        }
        lo = hi;
    }
    r->stable = 1;
    for (size_t a = 0; a < n; a++) {
        sign_fix(n, r->vectors[a]);
        double w2 = r->omega2[a];
        if (w2 == 0 || fabs(w2) <= r->zero_tol) {
            r->omega2[a] = 0;
            r->kind[a] = MECH_MODE_ZERO;
            r->zero_modes++;
        } else if (w2 > 0) {
            r->kind[a] = MECH_MODE_OSCILLATING;
            r->omega[a] = sqrt(w2);
        } else {
            r->kind[a] = MECH_MODE_UNSTABLE;
            r->growth[a] = sqrt(-w2);
            r->stable = 0;
        }
        for (size_t i = 0; i < n; i++)
            if (!isfinite(r->vectors[a][i])) {
                st = mech_error_set(err, MECH_ENUMERIC, "mass_matrix",
                                    "mode %zu is not finite", a);
                goto done;
            }
        if (!isfinite(r->omega2[a]) || !isfinite(r->omega[a]) || !isfinite(r->growth[a])) {
            st = mech_error_set(err, MECH_ENUMERIC, "stiffness_matrix",
                                "a frequency is beyond the double range; scale the units");
            goto done;
        }
    }
done:
    free(sc);
    gsl_eigen_gensymmv_free(w);
    gsl_vector_free(ev);
    gsl_matrix_free(gv);
    gsl_matrix_free(gk);
    gsl_matrix_free(gm);
    return st;
}

void mech_coupled_project(const struct mech_coupled_modes *modes, const double *m,
                          const double *q0, const double *v0, double *a, double *b,
                          double *energy)
{
    size_t n = modes->n;
    for (size_t p = 0; p < n; p++) {
        a[p] = m_dot(n, m, modes->vectors[p], q0);
        b[p] = m_dot(n, m, modes->vectors[p], v0);
        if (energy) energy[p] = 0.5 * (b[p] * b[p] + modes->omega2[p] * a[p] * a[p]);
    }
}

enum mech_status mech_coupled_at(const struct mech_coupled_modes *modes, const double *a,
                                 const double *b, double t, double *q, double *qdot,
                                 struct mech_error *err)
{
    size_t n = modes->n;
    for (size_t i = 0; i < n; i++) {
        q[i] = 0;
        if (qdot) qdot[i] = 0;
    }
    for (size_t p = 0; p < n; p++) {
        double c, cd;
        if (modes->kind[p] == MECH_MODE_OSCILLATING) {
            double w = modes->omega[p], s = sin(w * t), co = cos(w * t);
            c = a[p] * co + b[p] * s / w;
            cd = -a[p] * w * s + b[p] * co;
        } else if (modes->kind[p] == MECH_MODE_ZERO) {
            c = a[p] + b[p] * t;
            cd = b[p];
        } else {
            double g = modes->growth[p], s = sinh(g * t), co = cosh(g * t);
            c = a[p] * co + b[p] * s / g;
            cd = a[p] * g * s + b[p] * co;
        }
        for (size_t i = 0; i < n; i++) {
            q[i] += modes->vectors[p][i] * c;
            if (qdot) qdot[i] += modes->vectors[p][i] * cd;
        }
    }
    for (size_t i = 0; i < n; i++)
        if (!isfinite(q[i]) || (qdot && !isfinite(qdot[i])))
            return mech_error_set(err, MECH_ENUMERIC, "initial/times",
                                  "the motion at t = %.6g s is beyond the double range", t);
    return MECH_OK;
}

static int positive(double x)
{
    return isfinite(x) && x > 0;
}

enum mech_status mech_coupled_chain(size_t n, const double *masses, const double *springs,
                                    size_t n_springs, int left_wall, int right_wall, double *m,
                                    double *k, struct mech_error *err)
{
    if (n == 0 || n > NMAX)
        return mech_error_set(err, MECH_EINVAL, "masses",
                              "%zu masses: 1 to %d are allowed", n, NMAX);
    size_t want = n - 1 + (left_wall != 0) + (right_wall != 0);
    if (n_springs != want)
        return mech_error_set(err, MECH_EINVAL, "springs",
                              "%zu masses with %s need %zu springs, got %zu", n,
                              left_wall && right_wall ? "a wall at each end"
                              : left_wall             ? "a wall at the left end"
                              : right_wall            ? "a wall at the right end"
                                                      : "no wall",
                              want, n_springs);
    for (size_t i = 0; i < n; i++)
        if (!positive(masses[i])) {
            char p[32];
            snprintf(p, sizeof p, "masses/%zu", i);
            return mech_error_set(err, MECH_EINVAL, p, "must be finite and > 0, got %.17g",
                                  masses[i]);
        }
    for (size_t j = 0; j < n_springs; j++)
        if (!positive(springs[j])) {
            char p[32];
            snprintf(p, sizeof p, "springs/%zu", j);
            return mech_error_set(err, MECH_EINVAL, p, "must be finite and > 0, got %.17g",
                                  springs[j]);
        }
    memset(m, 0, n * n * sizeof *m);
    memset(k, 0, n * n * sizeof *k);
    size_t s = 0;
    for (size_t i = 0; i < n; i++) m[i * n + i] = masses[i];
    if (left_wall) k[0] += springs[s++];
    for (size_t i = 0; i + 1 < n; i++, s++) {
        /* spring between mass i and i+1: V = s (x_{i+1} - x_i)^2 / 2 */
        k[i * n + i] += springs[s];
        k[(i + 1) * n + i + 1] += springs[s];
        k[i * n + i + 1] -= springs[s];
        k[(i + 1) * n + i] -= springs[s];
    }
    if (right_wall) k[(n - 1) * n + n - 1] += springs[s];
    return MECH_OK;
}

enum mech_status mech_coupled_double_pendulum(double m1, double m2, double l1, double l2,
                                              double g, double *m, double *k,
                                              struct mech_error *err)
{
    const char *names[5] = {"m1", "m2", "l1", "l2", "g"};
    double v[5] = {m1, m2, l1, l2, g};
    for (int i = 0; i < 5; i++)
        if (!positive(v[i]))
            return mech_error_set(err, MECH_EINVAL, names[i], "must be finite and > 0, got %.17g",
                                  v[i]);
    m[0] = (m1 + m2) * l1 * l1;
    m[1] = m[2] = m2 * l1 * l2;
    m[3] = m2 * l2 * l2;
    k[0] = (m1 + m2) * g * l1;
    k[1] = k[2] = 0;
    k[3] = m2 * g * l2;
    return MECH_OK;
}

enum mech_status mech_coupled_pendulums(double mass, double length, double spring,
                                        double attach, double g, double *m, double *k,
                                        struct mech_error *err)
{
    if (!positive(mass)) return mech_error_set(err, MECH_EINVAL, "mass", "must be finite and > 0");
    if (!positive(length))
        return mech_error_set(err, MECH_EINVAL, "length", "must be finite and > 0");
    if (!positive(g)) return mech_error_set(err, MECH_EINVAL, "g", "must be finite and > 0");
    if (!(isfinite(spring) && spring >= 0))
        return mech_error_set(err, MECH_EINVAL, "k", "must be finite and >= 0");
    if (!(attach > 0 && attach <= length))
        return mech_error_set(err, MECH_EINVAL, "attach",
                              "must be in (0, length = %.17g] m, got %.17g", length, attach);
    double c = spring * attach * attach, d = mass * g * length;
    m[0] = m[3] = mass * length * length;
    m[1] = m[2] = 0;
    k[0] = k[3] = d + c;
    k[1] = k[2] = -c;
    return MECH_OK;
}
