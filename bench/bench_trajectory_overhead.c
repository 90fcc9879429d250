/* bench_trajectory_overhead.c — what the trajectory operation costs over its
 * integrator (the goal: at most 1.5x).
 *
 * The same scene, method and tolerance run two (three) ways, in interleaved
 * rounds on the same thread:
 *   api   mech_trajectory_integrate (core/frames/trajectory.c): force loop, observer
 *         (term sizes, energy and angular-momentum drift), planar reduction,
 *         reference report; samples = 2 (t0 and t_end, both step ends, so no
 *         sub-steps on either side);
 *   ode   mech_ode_solve on a minimal hand-written Kepler right-hand side, no
 *         observer (the project's driver and integrator on their own);
 *   gsl   rk8pd only: gsl_odeiv2 called directly (step, control_y, evolve
 *         from h = span * 1e-3 as the driver does), the bare integrator.
 * Scene: Kepler GM = a = 1, e = 0.5, from pericentre, 1000 orbits (period
 * 2 pi), mass 1; "3d" integrates 6 components (reduce_planar = 0), "planar"
 * 4 (reduce_planar = 1: the plane basis mechd picks for normal +z is
 * e1 = -y, e2 = x, which the bare right-hand side uses too). Methods: rk8pd
 * at rtol = atol = 1e-13 and radau15 at rtol 1e-9 (its round-off floor).
 *
 * The bare right-hand side computes a = d (-(GM / |d|^2) / |d|) with
 * |d| = sqrt(d.d), the trajectory's own arithmetic, so "same" means the
 * same accepted steps and a final state equal bit for bit (or the largest
 * difference is printed). The overhead ratio is api / baseline (gsl for
 * rk8pd, ode for radau15) from the minimum CPU over the rounds, and the
 * median of the per-round ratios beside it.
 *
 * Measures, never asserts: exits 0 whatever the figures (non-zero only when
 * a run fails). Not part of the tests.
 * Usage: bench_trajectory_overhead [OUT_DIR] (ignored: prints only).
 * Environment: MECHD_BENCH_ORBITS (default 1000), MECHD_BENCH_ROUNDS
 * (default 5), MECHD_BENCH_ONLY = "<method>-<3d|planar>-<api|ode|gsl>" runs
 * that one configuration once (for perf / callgrind).
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/budget.h"
#include "mech/base/constants.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory.h"

#define OV_ECC 0.5
#define OV_MAX_ROUNDS 50

struct config {
    const char *method;
    double rtol, atol;
    int planar;
};

struct outcome {
    long steps;
    double y[6]; /* final state in 3-D axes */
    double cpu;
};

static double t_end_of(long orbits) { return 2.0 * MECH_PI * (double)orbits; }

/* ---- the bare right-hand sides (GM = 1) ----------------------------------- */

/* a = d (-(GM/|d|^2)/|d|), as core/frames/trajectory_fast.c writes central gravity. */
static void kepler_accel_n(const double *q, double *a, int n)
{
    double s2 = 0.0;
    for (int i = 0; i < n; i++) s2 += q[i] * q[i];
    const double dn = sqrt(s2);
    const double k = -(1.0 / (dn * dn)) / dn;
    for (int i = 0; i < n; i++) a[i] = q[i] * k;
}

static int gsl_kepler3(double t, const double y[], double f[], void *params)
{
    (void)t, (void)params;
    f[0] = y[3], f[1] = y[4], f[2] = y[5];
    kepler_accel_n(y, f + 3, 3);
    return GSL_SUCCESS;
}
static int gsl_kepler2(double t, const double y[], double f[], void *params)
{
    (void)t, (void)params;
    f[0] = y[2], f[1] = y[3];
    kepler_accel_n(y, f + 2, 2);
    return GSL_SUCCESS;
}
static enum mech_status ode_accel3(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)v, (void)p;
    kepler_accel_n(q, a, 3);
    return MECH_OK;
}
static enum mech_status ode_accel2(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)v, (void)p;
    kepler_accel_n(q, a, 2);
    return MECH_OK;
}
static enum mech_status ode_rhs3(double t, const double *y, double *f, void *p)
{
    f[0] = y[3], f[1] = y[4], f[2] = y[5];
    return ode_accel3(t, y, y + 3, f + 3, p);
}
static enum mech_status ode_rhs2(double t, const double *y, double *f, void *p)
{
    f[0] = y[2], f[1] = y[3];
    return ode_accel2(t, y, y + 2, f + 2, p);
}

/* Initial state: pericentre (1 - e, 0, 0), speed sqrt((1 + e)/(1 - e)) along +y. */
static void initial_3d(double y[6])
{
    memset(y, 0, 6 * sizeof *y);
    y[0] = 1.0 - OV_ECC;
    y[4] = sqrt((1.0 + OV_ECC) / (1.0 - OV_ECC));
}
/* The plane coordinates u = (r.e1, r.e2, v.e1, v.e2), e1 = -y, e2 = x. */
static void to_plane(const double y[6], double u[4])
{
    u[0] = -y[1], u[1] = y[0], u[2] = -y[4], u[3] = y[3];
}
static void from_plane(const double u[4], double y[6])
{
    y[0] = u[1], y[1] = -u[0], y[2] = 0.0, y[3] = u[3], y[4] = -u[2], y[5] = 0.0;
}

/* ---- the three ways ---------------------------------------------------------- */

static int run_api(const struct config *c, long orbits, struct outcome *o)
{
    double y0[6];
    initial_3d(y0);
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = 1.0;
    f.u.central_gravity.center = mech_vec3_make(0, 0, 0);
    struct mech_trajectory_problem p = {
        .mass = 1.0,
        .position = mech_vec3_make(y0[0], y0[1], y0[2]),
        .velocity = mech_vec3_make(y0[3], y0[4], y0[5]),
        .frame = {.type = MECH_FRAME_INERTIAL},
        .forces = &f,
        .n_forces = 1,
        .t_end = t_end_of(orbits),
        .samples = 2,
        .method = c->method,
        .opt = {.rtol = c->rtol, .atol = c->atol},
        .reduce_planar = c->planar,
    };
    struct mech_vec3 pos[2], vel[2];
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r);
    r.position = pos;
    r.velocity = vel;
    struct mech_budget b = mech_budget_make(100000000L, 600.0);
    struct mech_error err;
    mech_error_clear(&err);
    double c0 = mech_cpu_seconds();
    enum mech_status st = mech_trajectory_integrate(&p, &b, &r, &err);
    o->cpu = mech_cpu_seconds() - c0;
    if (st != MECH_OK) {
        fprintf(stderr, "api %s: %s\n", c->method, err.text);
        return -1;
    }
    if (r.dimensions != (c->planar ? 2 : 3)) {
        fprintf(stderr, "api %s: integrated in %d dimensions\n", c->method, r.dimensions);
        return -1;
    }
    o->steps = r.stats.steps;
    double yf[6] = {pos[1].x, pos[1].y, pos[1].z, vel[1].x, vel[1].y, vel[1].z};
    memcpy(o->y, yf, sizeof yf);
    return 0;
}

static int run_ode(const struct config *c, long orbits, struct outcome *o)
{
    double y0[6], u0[4], ys[2 * 6];
    initial_3d(y0);
    to_plane(y0, u0);
    struct mech_ode_system sys = {6, ode_rhs3, ode_accel3, MECH_ODE_VELOCITY_FREE, NULL, NULL, 3, NULL};
    if (c->planar)
        sys = (struct mech_ode_system){4, ode_rhs2, ode_accel2, MECH_ODE_VELOCITY_FREE,
                                       NULL, NULL, 2, NULL};
    struct mech_ode_problem p = {
        .sys = &sys,
        .method = mech_ode_method_find(c->method),
        .opt = {.rtol = c->rtol, .atol = c->atol},
        .t0 = 0.0,
        .t_end = t_end_of(orbits),
        .y0 = c->planar ? u0 : y0,
        .n_samples = 2,
        .sample_y = ys,
    };
    struct mech_ode_result r;
    struct mech_budget b = mech_budget_make(100000000L, 600.0);
    struct mech_error err;
    mech_error_clear(&err);
    double c0 = mech_cpu_seconds();
    enum mech_status st = mech_ode_solve(&p, &b, &r, &err);
    o->cpu = mech_cpu_seconds() - c0;
    if (st != MECH_OK) {
        fprintf(stderr, "ode %s: %s\n", c->method, err.text);
        return -1;
    }
    o->steps = r.stats.steps;
    if (c->planar) from_plane(ys + 4, o->y);
    else memcpy(o->y, ys + 6, 6 * sizeof *o->y);
    return 0;
}

static int run_gsl(const struct config *c, long orbits, struct outcome *o)
{
    const size_t dim = c->planar ? 4 : 6;
    double y0[6], y[6];
    initial_3d(y0);
    if (c->planar) to_plane(y0, y);
    else memcpy(y, y0, sizeof y0);
    gsl_odeiv2_system sys = {c->planar ? gsl_kepler2 : gsl_kepler3, NULL, dim, NULL};
    gsl_odeiv2_step *s = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, dim);
    gsl_odeiv2_control *con = gsl_odeiv2_control_y_new(c->atol, c->rtol);
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(dim);
    const double t1 = t_end_of(orbits);
    double t = 0.0, h = t1 * 1e-3;
    long steps = 0;
    int gs = GSL_SUCCESS;
    double c0 = mech_cpu_seconds();
    while (t < t1 && gs == GSL_SUCCESS) {
        gs = gsl_odeiv2_evolve_apply(ev, con, s, &sys, &t, t1, &h, y);
        steps++;
    }
    o->cpu = mech_cpu_seconds() - c0;
    gsl_odeiv2_evolve_free(ev);
    gsl_odeiv2_control_free(con);
    gsl_odeiv2_step_free(s);
    if (gs != GSL_SUCCESS) {
        fprintf(stderr, "gsl rk8pd: %s\n", gsl_strerror(gs));
        return -1;
    }
    o->steps = steps;
    if (c->planar) from_plane(y, o->y);
    else memcpy(o->y, y, 6 * sizeof *o->y);
    return 0;
}

/* ---- driver ------------------------------------------------------------------------ */

enum way { WAY_API, WAY_ODE, WAY_GSL, WAY_COUNT };
static const char *const way_name[WAY_COUNT] = {"api", "ode", "gsl"};

static int run_way(enum way w, const struct config *c, long orbits, struct outcome *o)
{
    switch (w) {
    case WAY_API: return run_api(c, orbits, o);
    case WAY_ODE: return run_ode(c, orbits, o);
    case WAY_GSL: return run_gsl(c, orbits, o);
    default: return -1;
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double max_diff(const double *a, const double *b)
{
    double m = 0.0;
    for (int i = 0; i < 6; i++) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

int main(int argc, char **argv)
{
    (void)argc, (void)argv;
    gsl_set_error_handler_off();
    const char *eo = getenv("MECHD_BENCH_ORBITS"), *er = getenv("MECHD_BENCH_ROUNDS");
    const char *only = getenv("MECHD_BENCH_ONLY");
    long orbits = eo ? atol(eo) : 1000;
    int rounds = er ? atoi(er) : 5;
    if (orbits < 1) orbits = 1;
    if (rounds < 1) rounds = 1;
    if (rounds > OV_MAX_ROUNDS) rounds = OV_MAX_ROUNDS;

    const struct config configs[] = {
        {"rk8pd", 1e-13, 1e-13, 0},
        {"rk8pd", 1e-13, 1e-13, 1},
        {"radau15", 1e-9, 0.0, 0},
        {"radau15", 1e-9, 0.0, 1},
    };
    const size_t nc = sizeof configs / sizeof configs[0];

    if (only) {
        for (size_t i = 0; i < nc; i++)
            for (int w = 0; w < WAY_COUNT; w++) {
                char name[64];
                snprintf(name, sizeof name, "%s-%s-%s", configs[i].method,
                         configs[i].planar ? "planar" : "3d", way_name[w]);
                if (strcmp(name, only)) continue;
                struct outcome o;
                if (run_way((enum way)w, &configs[i], orbits, &o)) return 1;
                printf("%s: %ld steps, %.4f s CPU\n", name, o.steps, o.cpu);
                return 0;
            }
        fprintf(stderr, "MECHD_BENCH_ONLY=%s matches no configuration\n", only);
        return 2;
    }

    printf("# trajectory overhead: Kepler e = %.1f, %ld orbits, %d interleaved rounds; thread CPU s\n",
           OV_ECC, orbits, rounds);
    printf("# api = mech_trajectory_integrate, ode = mech_ode_solve on a bare Kepler rhs, "
           "gsl = gsl_odeiv2 rk8pd directly\n");
    static double cpu[8][WAY_COUNT][OV_MAX_ROUNDS];
    struct outcome first[8][WAY_COUNT];
    int failed = 0;
    for (int r = 0; r < rounds; r++)
        for (size_t i = 0; i < nc; i++)
            for (int w = 0; w < WAY_COUNT; w++) {
                if (w == WAY_GSL && strcmp(configs[i].method, "rk8pd")) continue;
                struct outcome o;
                if (run_way((enum way)w, &configs[i], orbits, &o)) {
                    failed = 1;
                    continue;
                }
                cpu[i][w][r] = o.cpu;
                if (r == 0) first[i][w] = o;
            }
    if (failed) return 1;

    printf("%-8s %-7s %-4s %9s %10s %10s  %s\n", "method", "scene", "way", "steps", "min_cpu_s",
           "med_cpu_s", "final state vs api");
    for (size_t i = 0; i < nc; i++) {
        const int has_gsl = !strcmp(configs[i].method, "rk8pd");
        double mins[WAY_COUNT] = {0}, med_ratio = 0.0;
        for (int w = 0; w < WAY_COUNT; w++) {
            if (w == WAY_GSL && !has_gsl) continue;
            double v[OV_MAX_ROUNDS];
            memcpy(v, cpu[i][w], (size_t)rounds * sizeof *v);
            qsort(v, (size_t)rounds, sizeof *v, cmp_double);
            mins[w] = v[0];
            const struct outcome *o = &first[i][w], *a = &first[i][WAY_API];
            char same[96];
            if (w == WAY_API) snprintf(same, sizeof same, "-");
            else {
                double d = max_diff(o->y, a->y);
                snprintf(same, sizeof same, "%s steps, %s (max |diff| %.3g)",
                         o->steps == a->steps ? "same" : "DIFFERENT",
                         d == 0.0 ? "bit-identical" : "differs", d);
            }
            printf("%-8s %-7s %-4s %9ld %10.4f %10.4f  %s\n", configs[i].method,
                   configs[i].planar ? "planar" : "3d", way_name[w], o->steps, v[0],
                   v[rounds / 2], same);
        }
        const int base = has_gsl ? WAY_GSL : WAY_ODE;
        double ratios[OV_MAX_ROUNDS];
        for (int r = 0; r < rounds; r++) ratios[r] = cpu[i][WAY_API][r] / cpu[i][base][r];
        qsort(ratios, (size_t)rounds, sizeof *ratios, cmp_double);
        med_ratio = ratios[rounds / 2];
        printf("  -> overhead api/%s = %.2fx (min CPU), %.2fx (median of per-round ratios)",
               way_name[base], mins[WAY_API] / mins[base], med_ratio);
        if (has_gsl)
            printf("; api/ode = %.2fx, ode/gsl = %.2fx", mins[WAY_API] / mins[WAY_ODE],
                   mins[WAY_ODE] / mins[WAY_GSL]);
        printf("; target <= 1.5x: %s\n", mins[WAY_API] / mins[base] <= 1.5 ? "MET" : "NOT MET");
    }
    return 0;
}
