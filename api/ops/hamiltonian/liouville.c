/* liouville.c — POST /v1/hamiltonian/liouville: the
 * phase-space area of a closed curve (or the volume of a cloud) of initial
 * conditions over time beside the tangent map's determinant, a symplectic
 * integrator beside a non-symplectic one (core/hamiltonian/liouville.c, the
 * runs and the reference orbit's start in liouville_runs.c). Physics sources:
 * Goldstein §9.9, Arnold §16 (Poincaré's integral invariant).
 * Integrators: up to two blocks through api/ops/hamiltonian/hamiltonian_request.c; without
 * them gauss4 at time scale / 20 beside rk4 at time scale / 2. This file
 * parses the curve, calls the core and encodes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "ops/hamiltonian/hamiltonian_request.h"
#include "mech/answers/hamiltonian/liouville_runs.h"

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

/* A parsed request: the curve's points live here (the problem borrows them). */
struct liou_call {
    struct mech_ham_system s;
    struct mech_liouville_problem p;
    double *verts;
    double ctr[MECH_HAM_MAX_DIM], u[MECH_HAM_MAX_DIM], w[MECH_HAM_MAX_DIM], ref[MECH_HAM_MAX_DIM];
};

static int read_point(struct api_call *c, const json_t *a, size_t dim, const char *ptr, double *y)
{
    if (json_array_size(a) != dim) {
        api_call_invalid(c, ptr,
                         "a phase-space point of this system has %zu values (q..., p...), "
                         "got %zu",
                         dim, json_array_size(a));
        return 0;
    }
    for (size_t i = 0; i < dim; i++)
        y[i] = json_number_value(json_array_get(a, i));
    return 1;
}

/* A polygon's vertices or a cloud's points. Returns 0 after recording an error. */
static int read_points(struct api_call *c, const json_t *cv, int polygon, struct liou_call *q)
{
    struct mech_liouville_problem *p = &q->p;
    const size_t dim = 2 * (size_t)q->s.dof;
    const json_t *vs = json_object_get(cv, polygon ? "vertices" : "points");
    p->shape = polygon ? MECH_LIOUVILLE_POLYGON : MECH_LIOUVILLE_CLOUD;
    p->n_vertices = json_array_size(vs);
    q->verts = malloc(p->n_vertices * dim * sizeof *q->verts);
    if (!q->verts) {
        struct mech_error e;
        mech_error_clear(&e);
        api_call_fail_core(c, mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory"), &e, "");
        return 0;
    }
    for (size_t j = 0; j < p->n_vertices; j++) {
        char ptr[64];
        snprintf(ptr, sizeof ptr, "/curve/%s/%zu", polygon ? "vertices" : "points", j);
        if (!read_point(c, json_array_get(vs, j), dim, ptr, q->verts + j * dim)) return 0;
    }
    if (!polygon && p->n_vertices < dim + 1) {
        api_call_invalid(c, "/curve/points",
                         "a cloud in the %zu-dimensional phase space needs at least %zu points, "
                         "got %zu",
                         dim, dim + 1, p->n_vertices);
        return 0;
    }
    if (polygon && p->max_intervals < p->n_vertices) {
        api_call_invalid(c, "/max_intervals",
                         "max_intervals (%zu) must be at least the number of edges (%zu)",
                         p->max_intervals, p->n_vertices);
        return 0;
    }
    p->vertices = q->verts;
    return 1;
}

/* An ellipse: centre and semi_axes (1 dof) or axes u and w. */
static int read_ellipse(struct api_call *c, const json_t *cv, struct liou_call *q)
{
    const size_t dim = 2 * (size_t)q->s.dof;
    q->p.shape = MECH_LIOUVILLE_ELLIPSE;
    if (!read_point(c, json_object_get(cv, "center"), dim, "/curve/center", q->ctr)) return 0;
    const json_t *sa = json_object_get(cv, "semi_axes");
    const json_t *ju = json_object_get(cv, "u"), *jw = json_object_get(cv, "w");
    if (sa) {
        if (ju || jw || q->s.dof != 1) {
            api_call_invalid(c, "/curve/semi_axes",
                             "semi_axes [a, b] (an ellipse with axes along q and p) is for "
                             "1 degree of freedom and excludes u and w; give u and w "
                             "otherwise");
            return 0;
        }
        q->u[0] = json_number_value(json_array_get(sa, 0));
        q->u[1] = 0.0;
        q->w[0] = 0.0;
        q->w[1] = json_number_value(json_array_get(sa, 1));
    } else {
        if (!ju || !jw) {
            api_call_invalid(c, "/curve", "an ellipse needs semi_axes, or u and w");
            return 0;
        }
        if (!read_point(c, ju, dim, "/curve/u", q->u) || !read_point(c, jw, dim, "/curve/w", q->w))
            return 0;
    }
    q->p.center = q->ctr;
    q->p.axis_u = q->u;
    q->p.axis_w = q->w;
    return 1;
}

/* The system, the run's settings, the curve and the reference. Returns 0
 * after recording an error. */
static int read_request(struct api_call *c, const json_t *body, struct liou_call *q)
{
    const json_t *js = json_object_get(body, "system"), *cv = json_object_get(body, "curve");
    const char *type = api_string(cv, "type", "polygon");
    const int polygon = !strcmp(type, "polygon"), cloud = !strcmp(type, "cloud");
    /* the dof: from the system, or (oscillator) from the curve's points */
    const json_t *pt0 = polygon ? json_array_get(json_object_get(cv, "vertices"), 0)
                        : cloud ? json_array_get(json_object_get(cv, "points"), 0)
                                : json_object_get(cv, "center");
    if (!api_ham_system_read(c, js, json_array_size(pt0) / 2, &q->s)) return 0;
    struct mech_liouville_problem *p = &q->p;
    p->sys = &q->s;
    p->t_end = api_number(body, "t_end", 1.0);
    p->n_samples = (size_t)api_number_of(body, "samples");
    p->tol = api_number_of(body, "tol");
    p->max_intervals = (size_t)api_number_of(body, "max_intervals");
    if (polygon || cloud ? !read_points(c, cv, polygon, q) : !read_ellipse(c, cv, q)) return 0;
    const json_t *jr = json_object_get(body, "reference");
    if (jr) {
        if (!read_point(c, jr, 2 * (size_t)q->s.dof, "/reference", q->ref)) return 0;
        p->reference = q->ref;
    }
    return 1;
}

/* A core error of run k: "integrator/..." params belong to /integrators/k. */
static void fail_run(struct api_call *c, enum mech_status st, struct mech_error *e, size_t k,
                     int explicit_blocks)
{
    if (!strncmp(e->param, "integrator", 10) && explicit_blocks) {
        char tmp[96];
        snprintf(tmp, sizeof tmp, "integrators/%zu%s", k, e->param + 10);
        snprintf(e->param, sizeof e->param, "%s", tmp);
    } else if (!strncmp(e->param, "integrator", 10)) {
        e->param[0] = 0;
    }
    api_call_fail_core(c, st, e, "");
}

static const char *const MEASURED_CURVE =
    "A = (1/2) sum_i oint (q_i dp_i - p_i dq_i) over the image of the closed curve "
    "(Poincare's integral invariant; 1 degree of freedom: the enclosed (q, p) area, "
    "counter-clockwise positive; more: the sum of the oriented areas of the projections on "
    "the (q_i, p_i) planes). Each edge / arc is split into intervals carrying 15 "
    "Gauss-Kronrod nodes whose orbits are integrated with their tangent vectors "
    "(variational equations, same method), so the image curve is never approximated by a "
    "polygon; intervals are halved until the summed |Kronrod - Gauss| bound is below tol "
    "|A0|. vertex_polygon_area: the shoelace area of the vertex images (compensated), which "
    "changes as the edges bend. The tangent map Phi = dy(t)/dy(0) along the reference orbit "
    "comes from the variational equations with the same method: det Phi = 1 is Liouville's "
    "theorem, Phi^T J Phi = J symplecticity.";

static const char *const MEASURED_CLOUD =
    "a cloud: its covariance volume sqrt(det C) (C the covariance of the points in phase "
    "space; conserved exactly by linear volume-preserving maps, C -> A C A^T) and, for dim + "
    "1 points, the volume |det(x_i - x_0)|/dim! of their simplex. Under a nonlinear flow "
    "neither is the volume of the image region (they differ at O(cloud size / flow scale)); "
    "Liouville's theorem itself is det Phi = 1 along the reference orbit (the cloud's mean), "
    "from the variational equations with the same method.";

/* One run's object. */
static json_t *run_json(struct api_call *c, const struct liou_call *q,
                        const struct mech_liouville_result *x, const struct api_ham_integ *hi,
                        double tau)
{
    const size_t ns = q->p.n_samples, dim = 2 * (size_t)q->s.dof;
    const int cloud = q->p.shape == MECH_LIOUVILLE_CLOUD;
    json_t *o = json_object();
    set(o, "method", json_string(hi->ch.method));
    set(o, "symplectic", json_boolean(mech_ode_method_describe(hi->m).symplectic));
    if (cloud) {
        set(o, "covariance_volume", api_reals(c, x->area, ns));
        if (q->p.n_vertices == dim + 1) set(o, "simplex_volume", api_reals(c, x->vertex_area, ns));
        set(o, "max_relative_covariance_volume_drift", api_real(c, x->max_rel_area_drift));
    } else {
        set(o, "area", api_reals(c, x->area, ns));
        set(o, "area_quadrature_bound", api_reals(c, x->area_bound, ns));
        if (q->p.shape == MECH_LIOUVILLE_POLYGON)
            set(o, "vertex_polygon_area", api_reals(c, x->vertex_area, ns));
        set(o, "max_relative_area_drift", api_real(c, x->max_rel_area_drift));
    }
    set(o, "det_tangent_map", api_reals(c, x->det, ns));
    set(o, "symplectic_defect", api_reals(c, x->symplectic_defect, ns));
    set(o, "max_det_drift", api_real(c, x->max_det_drift));
    set(o, "max_symplectic_defect", api_real(c, x->max_symplectic_defect));
    if (!cloud) {
        set(o, "quadrature_converged", json_boolean(x->converged));
        set(o, "max_relative_quadrature_bound", api_real(c, x->max_area_bound_rel));
        set(o, "intervals", json_integer((json_int_t)x->n_intervals));
    }
    set(o, "node_trajectories", json_integer(x->trajectories));
    json_t *ro = json_array();
    for (size_t i = 0; i < ns; i++)
        json_array_append_new(ro, api_reals(c, x->reference_y + i * dim, dim));
    set(o, "reference_orbit", ro);
    set(o, "diagnostics", api_ham_diagnostics(c, hi, &x->stats, x->second_order, tau));
    return o;
}

json_t *api_op_hamiltonian_liouville(struct api_call *c, const json_t *body)
{
    struct liou_call q;
    memset(&q, 0, sizeof q);
    json_t *out = NULL;
    struct mech_liouville_runs runs;
    memset(&runs, 0, sizeof runs);
    if (!read_request(c, body, &q)) goto done;
    const size_t dim = 2 * (size_t)q.s.dof;
    double y_ref[MECH_HAM_MAX_DIM];
    mech_liouville_reference_start(&q.p, y_ref);
    const double tau = mech_ham_time_scale(&q.s, y_ref);

    const json_t *blocks = json_object_get(body, "integrators");
    const size_t nrun = blocks ? json_array_size(blocks) : 2;
    struct api_ham_integ hi[MECH_LIOUVILLE_MAX_RUNS];
    const struct mech_integrator *methods[MECH_LIOUVILLE_MAX_RUNS];
    struct mech_ode_options opts[MECH_LIOUVILLE_MAX_RUNS];
    for (size_t k = 0; k < nrun; k++) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/integrators/%zu", k);
        if (!api_ham_integrator_read(c, blocks ? json_array_get(blocks, k) : NULL, ptr, &q.s, y_ref,
                                     tau, q.p.t_end / tau, k == 0 ? "gauss4" : "rk4",
                                     k == 0 ? 20.0 : 2.0, NULL, &hi[k]))
            goto done;
        methods[k] = hi[k].m;
        opts[k] = hi[k].ch.opt;
    }
    if (api_dry_run_requested(body)) {
        /* the first block's selection; every block's in selections */
        json_t *sels = json_array();
        for (size_t k = 0; sels && k < nrun; k++)
            json_array_append_new(sels, api_ham_selection(c, &hi[k]));
        out = api_dry_run_answer(c, api_ham_selection(c, &hi[0]));
        if (out)
            json_object_set_new_nocheck(json_object_get(out, "diagnostics"), "selections", sels);
        else
            json_decref(sels);
        goto done;
    }
    struct mech_error e;
    mech_error_clear(&e);
    size_t failed = 0;
    enum mech_status st =
        mech_liouville_runs(&q.p, nrun, methods, opts, &c->budget, &runs, &failed, &e);
    if (st != MECH_OK) {
        fail_run(c, st, &e, failed, blocks != NULL);
        goto done;
    }
    const int cloud = q.p.shape == MECH_LIOUVILLE_CLOUD;
    out = json_object();
    set(out, "system", api_ham_system_json(&q.s, json_object_get(body, "system")));
    set(out, "measured", json_string(cloud ? MEASURED_CLOUD : MEASURED_CURVE));
    json_object_set_new(out, cloud ? "covariance_volume_initial" : "area_initial",
                        api_real(c, runs.run[0].area0));
    set(out, "t", api_reals(c, runs.run[0].t, q.p.n_samples));
    set(out, "reference_start", api_reals(c, y_ref, dim));
    json_t *ja = json_array();
    for (size_t k = 0; k < nrun; k++)
        json_array_append_new(ja, run_json(c, &q, &runs.run[k], &hi[k], tau));
    set(out, "runs", ja);
    set(out, "cost", json_object());
done:
    mech_liouville_runs_free(&runs);
    free(q.verts);
    return out;
}
