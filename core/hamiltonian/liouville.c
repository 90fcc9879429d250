/* liouville.c — phase-space area of a closed curve of initial conditions
 * under a Hamiltonian flow, by Gauss–Kronrod quadrature on the image curve
 * with tangents from the variational equations, adaptive in the curve
 * parameter; the tangent map's determinant along a reference orbit. See
 * mech/hamiltonian/liouville.h for what is measured and why.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/compensated.h"
#include "mech/base/constants.h"
#include "mech/hamiltonian/liouville.h"

/* Gauss–Kronrod 7/15 nodes and weights on [-1, 1]: R. Piessens, E. de
 * Doncker-Kapenga, C. Überhuber, D. Kahaner, QUADPACK (Springer 1983), routine
 * QK15 (the same table as GSL integration/qk15.c). xgk[1], xgk[3], xgk[5],
 * xgk[7] are the 7-point Gauss nodes, with weights wg. */
static const double xgk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double wgk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082,
                             0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975,
                             0.417959183673469387755102040816327};

enum { LV_NODES = 15, LV_ELLIPSE_START = 4 };

/* Node k (0..14) of the rule: abscissa, Kronrod weight, Gauss weight (0 if none). */
static void node(int k, double *x, double *wk, double *wgauss)
{
    const int i = k < 7 ? k : 14 - k; /* index into xgk */
    *x = k < 7 ? -xgk[i] : xgk[i];
    *wk = wgk[i];
    *wgauss = (i % 2 == 1) ? wg[i / 2] : 0.0;
}

double mech_liouville_shoelace(const double *pts, size_t n, size_t dof)
{
    const size_t dim = 2 * dof;
    struct mech_csum s = {0, 0};
    for (size_t j = 0; j < n; j++) {
        const double *a = pts + j * dim, *b = pts + ((j + 1) % n) * dim;
        for (size_t i = 0; i < dof; i++) {
            mech_csum_add_product(&s, a[i], b[dof + i]);
            mech_csum_add_product(&s, -b[i], a[dof + i]);
        }
    }
    return 0.5 * mech_csum_value(&s);
}

double mech_liouville_det(const double *a, size_t d)
{
    double m[36];
    if (d == 0 || d > 6) return NAN;
    memcpy(m, a, d * d * sizeof *m);
    double det = 1.0;
    for (size_t c = 0; c < d; c++) {
        size_t piv = c;
        for (size_t r = c + 1; r < d; r++)
            if (fabs(m[r * d + c]) > fabs(m[piv * d + c])) piv = r;
        if (m[piv * d + c] == 0.0) return 0.0;
        if (piv != c) {
            for (size_t k = 0; k < d; k++) {
                double t = m[c * d + k];
                m[c * d + k] = m[piv * d + k];
                m[piv * d + k] = t;
            }
            det = -det;
        }
        det *= m[c * d + c];
        for (size_t r = c + 1; r < d; r++) {
            const double f = m[r * d + c] / m[c * d + c];
            for (size_t k = c; k < d; k++) m[r * d + k] -= f * m[c * d + k];
        }
    }
    return det;
}

/* The curve: segment seg at parameter s -> y and dy/ds. */
static void curve_point(const struct mech_liouville_problem *p, size_t dim, size_t seg, double s,
                        double *y, double *dy)
{
    if (p->shape == MECH_LIOUVILLE_POLYGON) {
        const double *a = p->vertices + seg * dim;
        const double *b = p->vertices + ((seg + 1) % p->n_vertices) * dim;
        for (size_t i = 0; i < dim; i++) {
            dy[i] = b[i] - a[i];
            y[i] = s < 0.5 ? a[i] + s * dy[i] : b[i] - (1.0 - s) * dy[i];
        }
    } else {
        const double th = 2.0 * MECH_PI * s, c = cos(th), sn = sin(th);
        for (size_t i = 0; i < dim; i++) {
            y[i] = p->center[i] + p->axis_u[i] * c + p->axis_w[i] * sn;
            dy[i] = 2.0 * MECH_PI * (p->axis_w[i] * c - p->axis_u[i] * sn);
        }
    }
}

struct lv_interval {
    size_t seg;
    double a, b;
    int done;
    double *K, *G; /* per sample: Kronrod and Gauss sums of the interval */
};

struct lv_ctx {
    const struct mech_liouville_problem *p;
    struct mech_ham_system sys;
    size_t dof, dim;
    const struct mech_budget *budget;
    struct mech_liouville_result *res;
    struct mech_error *err;
};

/* A sub-budget with the steps the whole run has left. */
static enum mech_status sub_budget(struct lv_ctx *c, struct mech_budget *b)
{
    *b = *c->budget;
    b->max_steps = c->budget->max_steps - c->res->stats.steps;
    if (b->max_steps <= 0) {
        enum mech_status st =
            mech_error_set(c->err, MECH_EBUDGET, NULL,
                           "the step budget (%ld steps for all integrations together) is "
                           "exhausted after %ld node trajectories",
                           c->budget->max_steps, c->res->trajectories);
        if (c->err && c->err->code == MECH_EBUDGET) c->err->progress.steps = c->res->stats.steps;
        return st;
    }
    return MECH_OK;
}

static void add_stats(struct mech_ode_stats *a, const struct mech_ode_stats *b)
{
    a->steps += b->steps;
    a->rejected_steps += b->rejected_steps;
    a->rhs_evaluations += b->rhs_evaluations;
}

/* Integrate an ensemble from Y0 and write its n_samples states into Ys. */
static enum mech_status run_ensemble(struct lv_ctx *c, const struct mech_ode_system *ode,
                                     const double *Y0, double *Ys)
{
    struct mech_budget b;
    enum mech_status st = sub_budget(c, &b);
    if (st != MECH_OK) return st;
    struct mech_ode_problem op = {
        .sys = ode, .method = c->p->method, .opt = c->p->opt, .t0 = 0.0,
        .t_end = c->p->t_end, .y0 = Y0, .n_samples = c->p->n_samples,
        .sample_t = c->res->t, .sample_y = Ys,
    };
    struct mech_ode_result r;
    memset(&r, 0, sizeof r);
    st = mech_ode_solve(&op, &b, &r, c->err);
    add_stats(&c->res->stats, &r.stats);
    if (st == MECH_OK && r.n_samples != c->p->n_samples)
        st = mech_error_set(c->err, MECH_EINTERNAL, NULL, "missing samples");
    return st;
}

static enum mech_status compute_interval(struct lv_ctx *c, struct lv_interval *iv, double *Y0,
                                         double *Ys)
{
    struct mech_ham_ensemble e;
    struct mech_ode_system ode;
    enum mech_status st = mech_ham_ensemble_init(&e, &c->sys, LV_NODES, 1, c->p->method, &ode, c->err);
    if (st != MECH_OK) return st;
    const double mid = 0.5 * (iv->a + iv->b), half = 0.5 * (iv->b - iv->a);
    for (int k = 0; k < LV_NODES; k++) {
        double x, wk, wgs, y[MECH_HAM_MAX_DIM], dy[MECH_HAM_MAX_DIM];
        node(k, &x, &wk, &wgs);
        curve_point(c->p, c->dim, iv->seg, mid + half * x, y, dy);
        if (mech_ham_state_check(&c->sys, y, NULL) != MECH_OK)
            return mech_error_set(c->err, MECH_EDOMAIN, "curve",
                                  "the curve passes through a state outside the system's "
                                  "domain (r <= 0 or a pole with p_phi != 0) near segment %zu, "
                                  "s = %.6g",
                                  iv->seg, mid + half * x);
        const double *tans[1] = {dy};
        mech_ham_ensemble_put(&e, Y0, (size_t)k, y, tans);
    }
    if ((st = run_ensemble(c, &ode, Y0, Ys)) != MECH_OK) return st;
    c->res->trajectories += LV_NODES;
    const size_t D = ode.dim;
    for (size_t i = 0; i < c->p->n_samples; i++) {
        struct mech_csum K = {0, 0}, G = {0, 0};
        for (int k = 0; k < LV_NODES; k++) {
            double x, wk, wgs, y[MECH_HAM_MAX_DIM], tan[MECH_HAM_MAX_DIM];
            node(k, &x, &wk, &wgs);
            mech_ham_ensemble_get(&e, Ys + i * D, (size_t)k, y, 0, tan);
            struct mech_csum f = {0, 0};
            for (size_t d = 0; d < c->dof; d++) {
                mech_csum_add_product(&f, y[d], tan[c->dof + d]);
                mech_csum_add_product(&f, -y[c->dof + d], tan[d]);
            }
            const double fv = 0.5 * mech_csum_value(&f);
            mech_csum_add_product(&K, wk * half, fv);
            if (wgs != 0.0) mech_csum_add_product(&G, wgs * half, fv);
        }
        iv->K[i] = mech_csum_value(&K);
        iv->G[i] = mech_csum_value(&G);
    }
    iv->done = 1;
    return MECH_OK;
}

/* The reference orbit with the full tangent map. */
static enum mech_status reference_orbit(struct lv_ctx *c, const double *y0)
{
    const size_t dim = c->dim, ns = c->p->n_samples;
    struct mech_ham_ensemble e;
    struct mech_ode_system ode;
    enum mech_status st = mech_ham_ensemble_init(&e, &c->sys, 1, dim, c->p->method, &ode, c->err);
    if (st != MECH_OK) return st;
    const size_t D = ode.dim;
    double *Y0 = malloc(D * sizeof *Y0), *Ys = malloc(ns * D * sizeof *Ys);
    if (!Y0 || !Ys) {
        free(Y0);
        free(Ys);
        return mech_error_set(c->err, MECH_ENOMEM, NULL, "out of memory for the tangent map");
    }
    double eye[MECH_HAM_MAX_DIM][MECH_HAM_MAX_DIM] = {{0}};
    const double *tans[MECH_HAM_MAX_DIM];
    for (size_t k = 0; k < dim; k++) {
        eye[k][k] = 1.0;
        tans[k] = eye[k];
    }
    mech_ham_ensemble_put(&e, Y0, 0, y0, tans);
    st = run_ensemble(c, &ode, Y0, Ys);
    if (st == MECH_OK) {
        struct mech_liouville_result *r = c->res;
        for (size_t i = 0; i < ns; i++) {
            double Phi[36], col[MECH_HAM_MAX_DIM][MECH_HAM_MAX_DIM], y[MECH_HAM_MAX_DIM];
            mech_ham_ensemble_get(&e, Ys + i * D, 0, y, 0, NULL);
            for (size_t k = 0; k < dim; k++) {
                mech_ham_ensemble_get(&e, Ys + i * D, 0, NULL, k, col[k]);
                for (size_t row = 0; row < dim; row++) Phi[row * dim + k] = col[k][row];
            }
            const double det = mech_liouville_det(Phi, dim);
            /* (Phi^T J Phi)_ab = omega(col_a, col_b) = sum_i a_qi b_pi - a_pi b_qi */
            double defect = 0.0;
            for (size_t a = 0; a < dim; a++)
                for (size_t b = 0; b < dim; b++) {
                    struct mech_csum w = {0, 0};
                    for (size_t d = 0; d < c->dof; d++) {
                        mech_csum_add_product(&w, col[a][d], col[b][c->dof + d]);
                        mech_csum_add_product(&w, -col[a][c->dof + d], col[b][d]);
                    }
                    const double J = (a < c->dof && b == a + c->dof)   ? 1.0
                                     : (b < c->dof && a == b + c->dof) ? -1.0
                                                                       : 0.0;
                    defect = fmax(defect, fabs(mech_csum_value(&w) - J));
                }
            if (r->det) r->det[i] = det;
            if (r->symplectic_defect) r->symplectic_defect[i] = defect;
            if (r->reference_y) memcpy(r->reference_y + i * dim, y, dim * sizeof *y);
            r->max_det_drift = fmax(r->max_det_drift, fabs(det - 1.0));
            r->max_symplectic_defect = fmax(r->max_symplectic_defect, defect);
            if (!isfinite(det) || !isfinite(defect))
                st = mech_error_set(c->err, MECH_ENUMERIC, NULL,
                                    "the tangent map became non-finite at t = %.9g s", r->t[i]);
        }
    }
    free(Y0);
    free(Ys);
    return st;
}

/* Vertex images and their shoelace area. */
static enum mech_status vertex_polygon(struct lv_ctx *c)
{
    const size_t nv = c->p->n_vertices, ns = c->p->n_samples, dim = c->dim;
    struct mech_ham_ensemble e;
    struct mech_ode_system ode;
    enum mech_status st = mech_ham_ensemble_init(&e, &c->sys, nv, 0, c->p->method, &ode, c->err);
    if (st != MECH_OK) return st;
    const size_t D = ode.dim;
    double *Y0 = malloc(D * sizeof *Y0), *Ys = malloc(ns * D * sizeof *Ys),
           *pts = malloc(nv * dim * sizeof *pts);
    if (!Y0 || !Ys || !pts) {
        st = mech_error_set(c->err, MECH_ENOMEM, NULL, "out of memory for the vertices");
        goto done;
    }
    for (size_t j = 0; j < nv; j++) mech_ham_ensemble_put(&e, Y0, j, c->p->vertices + j * dim, NULL);
    if ((st = run_ensemble(c, &ode, Y0, Ys)) != MECH_OK) goto done;
    for (size_t i = 0; i < ns; i++) {
        for (size_t j = 0; j < nv; j++) mech_ham_ensemble_get(&e, Ys + i * D, j, pts + j * dim, 0, NULL);
        c->res->vertex_area[i] = mech_liouville_shoelace(pts, nv, c->dof);
    }
done:
    free(Y0);
    free(Ys);
    free(pts);
    return st;
}

/* Covariance volume sqrt(det C) of n points in dim dimensions (two-pass mean). */
static double covariance_volume(const double *pts, size_t n, size_t dim)
{
    double mean[MECH_HAM_MAX_DIM] = {0}, C[36] = {0};
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < dim; i++) mean[i] += pts[j * dim + i] / (double)n;
    for (size_t j = 0; j < n; j++)
        for (size_t a = 0; a < dim; a++)
            for (size_t b = 0; b < dim; b++)
                C[a * dim + b] += (pts[j * dim + a] - mean[a]) * (pts[j * dim + b] - mean[b]) / (double)n;
    const double d = mech_liouville_det(C, dim);
    return d > 0.0 ? sqrt(d) : 0.0;
}

/* Simplex volume |det(x_i - x_0)| / dim! of dim + 1 points. */
static double simplex_volume(const double *pts, size_t dim)
{
    double D[36];
    double fact = 1.0;
    for (size_t i = 1; i <= dim; i++) {
        fact *= (double)i;
        for (size_t k = 0; k < dim; k++) D[(i - 1) * dim + k] = pts[i * dim + k] - pts[k];
    }
    return fabs(mech_liouville_det(D, dim)) / fact;
}

/* The cloud: every point's orbit, and its volumes at every sample. */
static enum mech_status cloud_run(struct lv_ctx *c)
{
    const size_t nv = c->p->n_vertices, ns = c->p->n_samples, dim = c->dim;
    struct mech_ham_ensemble e;
    struct mech_ode_system ode;
    enum mech_status st = mech_ham_ensemble_init(&e, &c->sys, nv, 0, c->p->method, &ode, c->err);
    if (st != MECH_OK) return st;
    const size_t D = ode.dim;
    double *Y0 = malloc(D * sizeof *Y0), *Ys = malloc(ns * D * sizeof *Ys),
           *pts = malloc(nv * dim * sizeof *pts);
    if (!Y0 || !Ys || !pts) {
        st = mech_error_set(c->err, MECH_ENOMEM, NULL, "out of memory for the cloud");
        goto done;
    }
    for (size_t j = 0; j < nv; j++) mech_ham_ensemble_put(&e, Y0, j, c->p->vertices + j * dim, NULL);
    if ((st = run_ensemble(c, &ode, Y0, Ys)) != MECH_OK) goto done;
    c->res->trajectories += (long)nv;
    for (size_t i = 0; i < ns; i++) {
        for (size_t j = 0; j < nv; j++) mech_ham_ensemble_get(&e, Ys + i * D, j, pts + j * dim, 0, NULL);
        c->res->area[i] = covariance_volume(pts, nv, dim);
        if (c->res->area_bound) c->res->area_bound[i] = 0.0;
        if (c->res->vertex_area) c->res->vertex_area[i] = nv == dim + 1 ? simplex_volume(pts, dim) : NAN;
        if (!isfinite(c->res->area[i])) {
            st = mech_error_set(c->err, MECH_ENUMERIC, NULL,
                                "the cloud's volume is not finite at t = %.9g s", c->res->t[i]);
            goto done;
        }
        c->res->max_rel_area_drift =
            fmax(c->res->max_rel_area_drift, fabs(c->res->area[i] - c->res->area0) / c->res->area0);
    }
done:
    free(Y0);
    free(Ys);
    free(pts);
    return st;
}

static enum mech_status check_problem(const struct mech_liouville_problem *p,
                                      struct mech_liouville_result *res, struct mech_error *err)
{
    if (!p || !p->sys || !p->method || !res || !res->t || !res->area)
        return mech_error_set(err, MECH_EINVAL, NULL, "incomplete Liouville problem");
    if (p->n_samples < 2)
        return mech_error_set(err, MECH_EINVAL, "samples", "at least 2 samples are needed");
    if (!(p->t_end > 0.0 && isfinite(p->t_end)))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0");
    if (!(p->tol >= 1e-15 && p->tol <= 1e-2))
        return mech_error_set(err, MECH_EINVAL, "tol", "tol must be in [1e-15, 1e-2], got %.17g",
                              p->tol);
    if (p->shape == MECH_LIOUVILLE_CLOUD) {
        if (!p->vertices || p->n_vertices < 3)
            return mech_error_set(err, MECH_EINVAL, "curve",
                                  "a cloud needs at least dim + 1 points (dim = 2 x degrees of "
                                  "freedom)");
    } else if (p->shape == MECH_LIOUVILLE_POLYGON) {
        if (!p->vertices || p->n_vertices < 3)
            return mech_error_set(err, MECH_EINVAL, "curve", "a polygon needs at least 3 vertices");
        if (p->max_intervals < p->n_vertices)
            return mech_error_set(err, MECH_EINVAL, "max_intervals",
                                  "max_intervals must be >= the number of edges (%zu)",
                                  p->n_vertices);
    } else {
        if (!p->center || !p->axis_u || !p->axis_w)
            return mech_error_set(err, MECH_EINVAL, "curve", "an ellipse needs a centre and two axes");
        if (p->max_intervals < LV_ELLIPSE_START)
            return mech_error_set(err, MECH_EINVAL, "max_intervals", "max_intervals must be >= %d",
                                  LV_ELLIPSE_START);
    }
    return MECH_OK;
}

enum mech_status mech_liouville_run(const struct mech_liouville_problem *p,
                                    const struct mech_budget *budget,
                                    struct mech_liouville_result *res, struct mech_error *err)
{
    enum mech_status st = check_problem(p, res, err);
    if (st != MECH_OK) return st;
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "no compute budget given");
    struct lv_ctx c = {p, *p->sys, 0, 0, budget, res, err};
    if ((st = mech_ham_system_check(&c.sys, err)) != MECH_OK) return st;
    c.dof = (size_t)c.sys.dof;
    c.dim = 2 * c.dof;
    const size_t dim = c.dim, ns = p->n_samples;
    res->n_samples = 0;
    res->max_rel_area_drift = res->max_det_drift = res->max_symplectic_defect = 0.0;
    res->max_area_bound_rel = 0.0;
    res->converged = 0;
    res->n_intervals = 0;
    res->trajectories = 0;
    res->stats = (struct mech_ode_stats){0, 0, 0};
    res->second_order = 0;

    /* initial area and the reference start */
    double ref[MECH_HAM_MAX_DIM] = {0};
    size_t n_seg;
    if (p->shape == MECH_LIOUVILLE_CLOUD) {
        if (p->n_vertices < dim + 1)
            return mech_error_set(err, MECH_EINVAL, "curve",
                                  "a cloud in %zu dimensions needs at least %zu points, got %zu", dim,
                                  dim + 1, p->n_vertices);
        for (size_t j = 0; j < p->n_vertices; j++) {
            char prm[48];
            snprintf(prm, sizeof prm, "curve/points/%zu", j);
            if (mech_ham_state_check(&c.sys, p->vertices + j * dim, NULL) != MECH_OK)
                return mech_error_set(err, MECH_EDOMAIN, prm,
                                      "point %zu is outside the system's domain (r <= 0, or a "
                                      "pole with p_phi != 0)",
                                      j);
            for (size_t i = 0; i < dim; i++) ref[i] += p->vertices[j * dim + i] / (double)p->n_vertices;
        }
        res->area0 = covariance_volume(p->vertices, p->n_vertices, dim);
        if (!(isfinite(res->area0) && res->area0 > 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "curve",
                                  "the cloud spans fewer than %zu dimensions (its covariance is "
                                  "singular): it has no volume",
                                  dim);
        if (p->reference) memcpy(ref, p->reference, dim * sizeof *ref);
        if (mech_ham_state_check(&c.sys, ref, NULL) != MECH_OK)
            return mech_error_set(err, MECH_EDOMAIN, "reference",
                                  "the reference orbit starts outside the system's domain");
        struct mech_ham_ensemble e;
        struct mech_ode_system ode;
        if ((st = mech_ham_ensemble_init(&e, &c.sys, 1, 0, p->method, &ode, err)) != MECH_OK)
            return st;
        res->second_order = e.second_order;
        res->converged = 1;
        if ((st = cloud_run(&c)) != MECH_OK) return st;
        if ((st = reference_orbit(&c, ref)) != MECH_OK) return st;
        res->n_samples = ns;
        return MECH_OK;
    }
    if (p->shape == MECH_LIOUVILLE_POLYGON) {
        n_seg = p->n_vertices;
        for (size_t j = 0; j < n_seg; j++) {
            char prm[48];
            snprintf(prm, sizeof prm, "curve/vertices/%zu", j);
            if (mech_ham_state_check(&c.sys, p->vertices + j * dim, NULL) != MECH_OK)
                return mech_error_set(err, MECH_EDOMAIN, prm,
                                      "vertex %zu is outside the system's domain (r <= 0, or a "
                                      "pole with p_phi != 0)",
                                      j);
            for (size_t i = 0; i < dim; i++) ref[i] += p->vertices[j * dim + i] / (double)n_seg;
        }
        res->area0 = mech_liouville_shoelace(p->vertices, n_seg, c.dof);
    } else {
        n_seg = 1;
        struct mech_csum w = {0, 0};
        for (size_t d = 0; d < c.dof; d++) {
            mech_csum_add_product(&w, p->axis_u[d], p->axis_w[c.dof + d]);
            mech_csum_add_product(&w, -p->axis_u[c.dof + d], p->axis_w[d]);
        }
        res->area0 = MECH_PI * mech_csum_value(&w);
        memcpy(ref, p->center, dim * sizeof *ref);
    }
    if (!(isfinite(res->area0) && res->area0 != 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "curve",
                              "the curve encloses zero (symplectic) area: nothing to conserve");
    if (p->reference) memcpy(ref, p->reference, dim * sizeof *ref);
    if (mech_ham_state_check(&c.sys, ref, NULL) != MECH_OK)
        return mech_error_set(err, MECH_EDOMAIN, "reference",
                              "the reference orbit starts outside the system's domain (r <= 0, "
                              "or a pole with p_phi != 0)");
    {
        struct mech_ham_ensemble e;
        struct mech_ode_system ode;
        if ((st = mech_ham_ensemble_init(&e, &c.sys, 1, 0, p->method, &ode, err)) != MECH_OK)
            return st;
        res->second_order = e.second_order;
    }

    /* intervals */
    const size_t cap = p->max_intervals;
    struct lv_interval *iv = calloc(cap, sizeof *iv);
    double *sums = calloc(2 * cap * ns, sizeof *sums);
    const size_t Dn = 2 * dim * LV_NODES;
    double *Y0 = malloc(Dn * sizeof *Y0), *Ys = malloc(ns * Dn * sizeof *Ys);
    if (!iv || !sums || !Y0 || !Ys) {
        st = mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu intervals", cap);
        goto done;
    }
    for (size_t k = 0; k < cap; k++) {
        iv[k].K = sums + 2 * k * ns;
        iv[k].G = iv[k].K + ns;
    }
    size_t n_iv = 0;
    if (p->shape == MECH_LIOUVILLE_POLYGON) {
        for (size_t j = 0; j < n_seg; j++, n_iv++) {
            iv[n_iv].seg = j;
            iv[n_iv].a = 0.0;
            iv[n_iv].b = 1.0;
        }
    } else {
        for (size_t j = 0; j < LV_ELLIPSE_START; j++, n_iv++) {
            iv[n_iv].seg = 0;
            iv[n_iv].a = (double)j / LV_ELLIPSE_START;
            iv[n_iv].b = (double)(j + 1) / LV_ELLIPSE_START;
        }
    }
    const double goal = p->tol * fabs(res->area0), S = (double)n_seg;
    for (;;) {
        for (size_t k = 0; k < n_iv; k++)
            if (!iv[k].done && (st = compute_interval(&c, &iv[k], Y0, Ys)) != MECH_OK) goto done;
        double worst = 0.0;
        for (size_t i = 0; i < ns; i++) {
            double b = 0.0;
            for (size_t k = 0; k < n_iv; k++) b += fabs(iv[k].K[i] - iv[k].G[i]);
            worst = fmax(worst, b);
        }
        if (worst <= goal) {
            res->converged = 1;
            break;
        }
        /* split intervals over their share of the goal; at least the worst one */
        size_t worst_k = 0;
        double worst_e = -1.0;
        int any = 0;
        const size_t n_before = n_iv;
        for (size_t k = 0; k < n_before; k++) {
            double e = 0.0;
            for (size_t i = 0; i < ns; i++) e = fmax(e, fabs(iv[k].K[i] - iv[k].G[i]));
            if (e > worst_e) {
                worst_e = e;
                worst_k = k;
            }
            if (e > goal * (iv[k].b - iv[k].a) / S) {
                if (n_iv == cap) goto capped;
                const double m = 0.5 * (iv[k].a + iv[k].b);
                iv[n_iv].seg = iv[k].seg;
                iv[n_iv].a = m;
                iv[n_iv].b = iv[k].b;
                iv[n_iv].done = 0;
                iv[k].b = m;
                iv[k].done = 0;
                n_iv++;
                any = 1;
            }
        }
        if (!any) {
            if (n_iv == cap) goto capped;
            const double m = 0.5 * (iv[worst_k].a + iv[worst_k].b);
            iv[n_iv].seg = iv[worst_k].seg;
            iv[n_iv].a = m;
            iv[n_iv].b = iv[worst_k].b;
            iv[n_iv].done = 0;
            iv[worst_k].b = m;
            iv[worst_k].done = 0;
            n_iv++;
        }
        continue;
    capped:
        /* the cap is reached: recompute what was split, report unconverged */
        for (size_t k = 0; k < n_iv; k++)
            if (!iv[k].done && (st = compute_interval(&c, &iv[k], Y0, Ys)) != MECH_OK) goto done;
        break;
    }
    res->n_intervals = n_iv;
    for (size_t i = 0; i < ns; i++) {
        struct mech_csum A = {0, 0};
        double b = 0.0;
        for (size_t k = 0; k < n_iv; k++) {
            mech_csum_add(&A, iv[k].K[i]);
            b += fabs(iv[k].K[i] - iv[k].G[i]);
        }
        res->area[i] = mech_csum_value(&A);
        if (!isfinite(res->area[i]) || !isfinite(b)) {
            st = mech_error_set(err, MECH_ENUMERIC, NULL,
                                "the area is not finite at t = %.9g s (values too large)", res->t[i]);
            goto done;
        }
        if (res->area_bound) res->area_bound[i] = b;
        res->max_rel_area_drift =
            fmax(res->max_rel_area_drift, fabs(res->area[i] - res->area0) / fabs(res->area0));
        res->max_area_bound_rel = fmax(res->max_area_bound_rel, b / fabs(res->area0));
    }
    if (res->vertex_area) {
        if (p->shape == MECH_LIOUVILLE_POLYGON) {
            if ((st = vertex_polygon(&c)) != MECH_OK) goto done;
        } else {
            for (size_t i = 0; i < ns; i++) res->vertex_area[i] = NAN;
        }
    }
    if ((st = reference_orbit(&c, ref)) != MECH_OK) goto done;
    res->n_samples = ns;
done:
    free(iv);
    free(sums);
    free(Y0);
    free(Ys);
    return st;
}
