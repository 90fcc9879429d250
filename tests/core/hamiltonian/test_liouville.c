/* test_liouville.c — Liouville's theorem measured by mech/hamiltonian/liouville.h:
 * the oscillator's energy ellipse (area 2 pi E / omega) over 1000 periods with
 * symplectic methods (conserved to 1e-10) and rk4 at a coarse step (not); a
 * pendulum blob whose edges bend (the quadrature keeps the area, the vertex
 * polygon does not); a 2-dof Hénon–Heiles loop (sum of projected areas) and
 * its 4x4 tangent map; typed errors and the helpers. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/hamiltonian/liouville.h"
#include "mech/base/constants.h"
#include "testlib.h"

enum { NS = 5 };

struct run_out {
    double t[NS], area[NS], bound[NS], vertex[NS], det[NS], defect[NS];
    struct mech_liouville_result r;
    struct mech_error e;
    enum mech_status st;
};

static void run(struct mech_liouville_problem *p, const char *method, double dt,
                struct run_out *o)
{
    memset(o, 0, sizeof *o);
    p->method = mech_ode_method_find(method);
    p->opt.dt = dt;
    p->n_samples = NS;
    o->r.t = o->t;
    o->r.area = o->area;
    o->r.area_bound = o->bound;
    o->r.vertex_area = o->vertex;
    o->r.det = o->det;
    o->r.symplectic_defect = o->defect;
    mech_error_clear(&o->e);
    struct mech_budget b = mech_budget_make(200000000, 300.0);
    o->st = mech_liouville_run(p, &b, &o->r, &o->e);
}

static void test_oscillator_1000_periods(void)
{
    /* m = 2, k = 8: omega = 2, E = 1: the energy ellipse has semi-axes
     * sqrt(2E/k) = 0.5 and sqrt(2mE) = 2, area pi a b = 2 pi E / omega = pi */
    struct mech_ham_system s = {.kind = MECH_HAM_OSCILLATOR, .dof = 1, .mass = 2.0, .k = {8.0}};
    const double c[2] = {0.0, 0.0}, u[2] = {0.5, 0.0}, w[2] = {0.0, 2.0};
    const double T = MECH_PI; /* period 2 pi / omega */
    struct mech_liouville_problem p = {.sys = &s, .t_end = 1000 * T, .shape = MECH_LIOUVILLE_ELLIPSE,
                                       .center = c, .axis_u = u, .axis_w = w, .tol = 1e-12,
                                       .max_intervals = 64};
    struct run_out o;
    const char *sym[] = {"gauss4", "gauss6", "yoshida4", "yoshida6"};
    for (int m = 0; m < 4; m++) {
        /* 1000 periods for gauss4 and yoshida6, 100 for the others (time) */
        p.t_end = (m == 0 || m == 3 ? 1000 : 100) * T;
        run(&p, sym[m], T / (m == 0 ? 10 : 20), &o);
        CHECK_EQ_INT(o.st, MECH_OK);
        CHECK_CLOSE(o.r.area0, MECH_PI, 1e-15, 0);
        CHECK(o.r.converged);
        CHECK(o.r.max_rel_area_drift < 1e-10);
        CHECK(o.r.max_det_drift < 1e-10);
        CHECK(o.r.max_symplectic_defect < 1e-10);
        CHECK_CLOSE(o.area[NS - 1], MECH_PI, 1e-10, 0);
        CHECK(isnan(o.vertex[0]));
        CHECK_EQ_INT(o.r.second_order, m >= 2);
        fprintf(stderr, "[%.2f s] oscillator %s: area drift %.3g, det drift %.3g, bound %.3g, %zu intervals\n",
                mech_cpu_seconds(), sym[m], o.r.max_rel_area_drift, o.r.max_det_drift, o.r.max_area_bound_rel,
                o.r.n_intervals);
    }
    p.t_end = 1000 * T;
    /* rk4 at 10 steps per period: det = |1 - h^6 w^6/144 ...|^n drifts visibly */
    run(&p, "rk4", T / 10, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    fprintf(stderr, "oscillator rk4: area drift %.3g, det drift %.3g\n", o.r.max_rel_area_drift,
            o.r.max_det_drift);
    CHECK(o.r.max_rel_area_drift > 1e-3);
    CHECK(o.r.max_det_drift > 1e-3);
    /* rk4's one-step amplification for y' = i w y: |R(i x)|^2 = 1 - x^6/72 + x^8/576, x = w h;
     * the area scales by |R|^2 per step, exactly (the flow is linear) */
    const double x = 2.0 * T / 10, R2 = 1.0 - pow(x, 6) / 72.0 + pow(x, 8) / 576.0;
    CHECK_CLOSE(o.area[NS - 1], MECH_PI * pow(R2, 10000), 1e-9, 0);
    CHECK_CLOSE(o.det[NS - 1], pow(R2, 10000), 1e-9, 0);
}

static void test_pendulum_blob(void)
{
    /* a square of initial conditions around (theta, p) = (1, 0): the period
     * depends on the energy, so the square shears into a curved band */
    struct mech_ham_system s = {.kind = MECH_HAM_PENDULUM, .mass = 1.0, .length = 1.0, .g = 1.0};
    const double v[8] = {0.9, 1.1, 1.1, 0.9, -0.1, -0.1, 0.1, 0.1};
    double verts[8];
    for (int j = 0; j < 4; j++) {
        verts[2 * j] = v[j];
        verts[2 * j + 1] = v[4 + j];
    }
    struct mech_liouville_problem p = {.sys = &s, .t_end = 60.0, .shape = MECH_LIOUVILLE_POLYGON,
                                       .n_vertices = 4, .vertices = verts, .tol = 1e-12,
                                       .max_intervals = 512};
    struct run_out o;
    run(&p, "gauss6", 0.05, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    CHECK_CLOSE(o.r.area0, 0.04, 1e-14, 0);
    CHECK(o.r.converged);
    CHECK(o.r.max_rel_area_drift < 1e-10);
    CHECK(o.r.max_det_drift < 1e-12);
    /* the vertex polygon's area changes by far more */
    CHECK(fabs(o.vertex[NS - 1] - 0.04) > 1e-3 * 0.04);
    fprintf(stderr, "[%.2f s] pendulum gauss6: area drift %.3g, vertex polygon %.6g (of 0.04), %zu intervals, "
            "%ld trajectories\n",
            mech_cpu_seconds(), o.r.max_rel_area_drift, o.vertex[NS - 1], o.r.n_intervals, o.r.trajectories);
    run(&p, "yoshida6", 0.05, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    CHECK(o.r.max_rel_area_drift < 1e-10);
    /* a clockwise polygon has negative oriented area */
    double cw[8];
    for (int j = 0; j < 4; j++) memcpy(cw + 2 * j, verts + 2 * (3 - j), 2 * sizeof *cw);
    p.vertices = cw;
    p.t_end = 10.0;
    run(&p, "gauss6", 0.05, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    CHECK_CLOSE(o.r.area0, -0.04, 1e-14, 0);
    CHECK_CLOSE(o.area[NS - 1], -0.04, 1e-10, 0);
    /* non-symplectic at a coarse step */
    run(&p, "rk4", 0.5, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    CHECK(o.r.max_rel_area_drift > 1e-4);
}

static void test_henon_heiles_loop(void)
{
    /* a loop in 4D phase space: u in the (x, p_x) plane, w mixing both planes */
    struct mech_ham_system s = {.kind = MECH_HAM_HENON_HEILES};
    const double c[4] = {0.0, 0.1, 0.35, 0.1}, u[4] = {0.02, 0.0, 0.0, 0.01},
                 w[4] = {0.0, 0.015, 0.02, 0.0};
    /* omega(u, w) = u_x w_px - u_px w_x + u_y w_py - u_py w_y = 0.02*0.02 - 0.01*0.015 */
    struct mech_liouville_problem p = {.sys = &s, .t_end = 20.0, .shape = MECH_LIOUVILLE_ELLIPSE,
                                       .center = c, .axis_u = u, .axis_w = w, .tol = 1e-12,
                                       .max_intervals = 256};
    struct run_out o;
    run(&p, "gauss6", 0.02, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    CHECK_CLOSE(o.r.area0, MECH_PI * (0.02 * 0.02 - 0.01 * 0.015), 1e-14, 0);
    CHECK(o.r.max_rel_area_drift < 1e-10);
    CHECK(o.r.max_det_drift < 1e-12);
    CHECK(o.r.max_symplectic_defect < 1e-11);
    fprintf(stderr, "[%.2f s] henon-heiles gauss6: area drift %.3g, det drift %.3g, defect %.3g, %zu intervals\n",
            mech_cpu_seconds(), o.r.max_rel_area_drift, o.r.max_det_drift, o.r.max_symplectic_defect, o.r.n_intervals);
}

static void test_errors_and_helpers(void)
{
    struct mech_ham_system s = {.kind = MECH_HAM_PENDULUM, .mass = 1.0, .length = 1.0, .g = 1.0};
    const double line[6] = {0, 0, 1, 1, 2, 2}; /* collinear: zero area */
    struct mech_liouville_problem p = {.sys = &s, .t_end = 1.0, .shape = MECH_LIOUVILLE_POLYGON,
                                       .n_vertices = 3, .vertices = line, .tol = 1e-12,
                                       .max_intervals = 64};
    struct run_out o;
    run(&p, "gauss6", 0.01, &o);
    CHECK_EQ_INT(o.st, MECH_EDOMAIN);
    CHECK(!strcmp(o.e.param, "curve"));
    p.n_vertices = 2;
    run(&p, "gauss6", 0.01, &o);
    CHECK_EQ_INT(o.st, MECH_EINVAL);
    /* central: a vertex at r <= 0 */
    struct mech_ham_system k = {.kind = MECH_HAM_CENTRAL, .mass = 1, .strength = -1, .power = -1};
    const double kv[12] = {1, 0, 0, 1, 1.1, 0, 0, 1, -0.1, 0, 0, 1};
    p.sys = &k;
    p.n_vertices = 3;
    p.vertices = kv;
    run(&p, "gauss6", 0.01, &o);
    CHECK_EQ_INT(o.st, MECH_EDOMAIN);
    CHECK(!strcmp(o.e.param, "curve/vertices/2"));
    /* yoshida on the central problem: not separable */
    const double kv2[12] = {1, 0, 0, 1, 1.1, 0, 0, 1, 1.0, 0.1, 0.1, 1};
    p.vertices = kv2;
    run(&p, "yoshida4", 0.01, &o);
    CHECK_EQ_INT(o.st, MECH_EINVAL);
    CHECK(!strcmp(o.e.param, "integrator/method"));
    /* budget */
    p.sys = &s;
    const double sq[8] = {0, 0, 0.1, 0, 0.1, 0.1, 0, 0.1};
    p.vertices = sq;
    p.n_vertices = 4;
    p.method = mech_ode_method_find("gauss6");
    p.opt.dt = 0.01;
    p.t_end = 100.0;
    double t[NS], a[NS];
    struct mech_liouville_result r = {.t = t, .area = a};
    struct mech_error e;
    mech_error_clear(&e);
    /* the step budget must stop it: a deadline far away keeps slow (ASan) builds honest */
    struct mech_budget b = mech_budget_make(30000, 600.0);
    CHECK_EQ_INT(mech_liouville_run(&p, &b, &r, &e), MECH_EBUDGET);
    /* helpers */
    const double tri[6] = {0, 0, 1, 0, 0, 1}; /* (q, p) = (0,0), (1,0), (0,1): ccw */
    CHECK_CLOSE(mech_liouville_shoelace(tri, 3, 1), 0.5, 1e-16, 0);
    const double far[6] = {1e8, 1e8, 1e8 + 1, 1e8, 1e8, 1e8 + 1};
    CHECK_CLOSE(mech_liouville_shoelace(far, 3, 1), 0.5, 1e-15, 0);
    const double m3[9] = {0, 2, 1, 1, 0, 0, 3, 1, 4};
    CHECK_CLOSE(mech_liouville_det(m3, 3), 0 * (0 - 0) - 2 * (4 - 0) + 1 * (1 - 0), 1e-15, 0);
}

static void test_cloud(void)
{
    /* Hénon–Heiles, 5 points in 4D (a simplex): nonlinear, so the simplex and
     * covariance volumes are only approximately conserved; det Phi = 1 exactly */
    struct mech_ham_system s = {.kind = MECH_HAM_HENON_HEILES};
    const double pts[20] = {0, 0.1, 0.35, 0.1, 0.01, 0.1, 0.35, 0.1, 0, 0.11, 0.35, 0.1,
                            0, 0.1, 0.36, 0.1, 0, 0.1, 0.35, 0.11};
    struct mech_liouville_problem p = {.sys = &s, .t_end = 10.0, .shape = MECH_LIOUVILLE_CLOUD,
                                       .n_vertices = 5, .vertices = pts, .tol = 1e-12,
                                       .max_intervals = 4};
    struct run_out o;
    run(&p, "gauss6", 0.02, &o);
    CHECK_EQ_INT(o.st, MECH_OK);
    CHECK_CLOSE(o.vertex[0], 1e-8 / 24.0, 1e-12, 0); /* a corner simplex of edge 0.01: 0.01^4/4! */
    CHECK(o.r.max_det_drift < 1e-12);
    /* small cloud: close, not exact (the flow bends it) */
    CHECK(o.r.max_rel_area_drift > 1e-6 && o.r.max_rel_area_drift < 0.2);
    fprintf(stderr, "cloud gauss6: covariance volume drift %.3g, simplex %.6g of %.6g\n",
            o.r.max_rel_area_drift, o.vertex[NS - 1], o.vertex[0]);
    /* too few points, degenerate cloud */
    p.n_vertices = 4;
    run(&p, "gauss6", 0.02, &o);
    CHECK_EQ_INT(o.st, MECH_EINVAL);
    const double flat[20] = {0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0};
    p.vertices = flat;
    p.n_vertices = 5;
    run(&p, "gauss6", 0.02, &o);
    CHECK_EQ_INT(o.st, MECH_EDOMAIN);
    CHECK(!strcmp(o.e.param, "curve"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_oscillator_1000_periods();
    test_pendulum_blob();
    test_henon_heiles_loop();
    test_errors_and_helpers();
    test_cloud();
    TEST_MAIN_END();
}
