/* bench_workprecision.c — work-precision benchmark of every registered ODE
 * method: fixed scenes with exact references, run
 * across methods and tolerances / step sizes, against SciPy's solve_ivp
 * DOP853 measured in the same run (bench/workprecision_scipy.py).
 *
 * Scenes (y = (q, v) in 3-D, dim 6, every method of the registry that
 * applies):
 *   kepler-e0.5, kepler-e0.9  GM = a = 1 (period 2 pi), from pericentre,
 *                             1000 orbits; exact: Kepler's equation.
 *   oscillator                q'' = -q (period 2 pi), 1e5 periods; exact:
 *                             cos / sin.
 *   falling                   notes §1.3 "Deflection of a Falling Object":
 *                             h = 100 m, latitude 32°, g = 9.80665 m/s²,
 *                             Coriolis only (the centrifugal term is in g),
 *                             t = sqrt(2h/g); exact: the closed form of the
 *                             linear system v' = g - 2 W x v (below); the
 *                             notes' first-order east deflection
 *                             (1/3) W cos(lat) sqrt(8 h^3 / g) is printed
 *                             beside it.
 *   stiff                     (extra) overdamped spring x'' = -k x - b x',
 *                             k = 1, b = 1e3, t = 1000: stiffness ratio 1e6,
 *                             the case for msbdf; exact: two exponentials.
 * Columns: position error |q - q_exact| / L at t_end (L = a, the amplitude,
 * h, x0), max |E - E0| / |E0| over every accepted step (energy; for the
 * falling object 1/2 v^2 + g z, which Coriolis conserves), accepted steps,
 * right-hand-side evaluations, thread CPU seconds.
 *
 * Rows: every method of the registry that is not a stub; adaptive ones over
 * rtol = atol = 1e-6 ... 1e-15, fixed-step ones over dt = period / N. A
 * sweep stops after a run costing more than MECHD_BENCH_CAP seconds, and any
 * run after 4 s of wall time (the budget's deadline: it shows as FAILED).
 * Then what the accuracy presets pick on each scene (mech_trajectory_choose)
 * and the error they reach, and the three targets, each printed
 * MET / NOT MET with the numbers: (1) Kepler e = 0.5, |dE/E| <= 1e-13
 * with >= 20x less CPU than DOP853 at rtol = atol = 1e-13; (2) symplectic
 * methods keep a bounded, non-secular energy error over 1e5 orbits;
 * (3) bit-identical results (the same core run four times, the same API
 * request twice).
 *
 * Measures, never asserts: exits 0 when a target is missed (non-zero only
 * when it cannot run at all). Never part of the tests.
 *
 * Usage: bench_workprecision [OUT_DIR] (default build/bench-out). Writes
 * OUT_DIR/workprecision.tsv (every row), OUT_DIR/wp_<scene>.dat (gnuplot
 * blocks, one per method), OUT_DIR/wp_longrun.dat and, with gnuplot,
 * OUT_DIR/workprecision.png (bench/workprecision.gp). The bench/ directory
 * is found from this file's path (__FILE__) or $MECHD_BENCH_DIR.
 * Environment: MECHD_BENCH_CAP (seconds, default 0.5): a sweep stops after
 * a run costing more than this; MECHD_BENCH_PRESETS_ONLY (any value): print
 * only the presets tables (every preset's CPU, error and method on the
 * trajectory scenes, machine/draft and machine/balanced ratios, then
 * the whole scene set through the API beside GSL rk8pd called directly and
 * SciPy DOP853); MECHD_BENCH_SCENES_ONLY: only the scene-set table.
 */
#include <errno.h>
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "api.h"
#include "mech/base/constants.h"
#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory.h"

#define WP_TWO_PI_L MECH_TWO_PI_L
#define WP_MAX_ROWS 4096
#define WP_MAX_CP 24
#define WP_MAX_METHODS 32

/* ---- scenes ----------------------------------------------------------- */

enum scene_kind { SCENE_KEPLER, SCENE_OSC, SCENE_FALL, SCENE_STIFF };

struct scene {
    const char *name;  /* file-name safe */
    const char *title; /* for the table and the plot */
    enum scene_kind kind;
    double e;          /* Kepler eccentricity (GM = a = 1) */
    double lat_deg, g0, h, W; /* falling object */
    double k, b;       /* stiff spring */
    double period;     /* time unit of the dt sweep: dt = period / N */
    double t_end;
    double scale;      /* L for the relative position error */
    double y0[6];
    int has_energy;
    const double *divs; /* fixed-step N values (dt = period / N), ascending */
    size_t n_divs;
    double nvec[3];    /* falling: unit rotation axis (0, cos, sin) */
    double lam_slow, lam_fast; /* stiff: eigenvalues */
};

static void kepler_acc(const double *q, double *a)
{
    double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    double k = -1.0 / (r2 * sqrt(r2));
    a[0] = k * q[0];
    a[1] = k * q[1];
    a[2] = k * q[2];
}

static void cross(const double *u, const double *v, double *w)
{
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
}

static enum mech_status scene_accel(double t, const double *q, const double *v, double *a,
                                    void *params)
{
    (void)t;
    const struct scene *sc = params;
    switch (sc->kind) {
    case SCENE_KEPLER:
        kepler_acc(q, a);
        break;
    case SCENE_OSC:
        for (int i = 0; i < 3; i++) a[i] = -q[i];
        break;
    case SCENE_FALL: {
        /* a = g - 2 W x v (notes §1.3), W = W n */
        double w2[3] = {2 * sc->W * sc->nvec[0], 2 * sc->W * sc->nvec[1], 2 * sc->W * sc->nvec[2]};
        double c[3];
        cross(w2, v, c);
        a[0] = -c[0];
        a[1] = -c[1];
        a[2] = -sc->g0 - c[2];
        break;
    }
    case SCENE_STIFF:
        for (int i = 0; i < 3; i++) a[i] = -sc->k * q[i] - sc->b * v[i];
        break;
    }
    return MECH_OK;
}

static enum mech_status scene_rhs(double t, const double *y, double *dydt, void *params)
{
    memcpy(dydt, y + 3, 3 * sizeof *y);
    return scene_accel(t, y, y + 3, dydt + 3, params);
}

/* Boris split a = e(q) + v x w(q). */
static enum mech_status scene_lorentz(double t, const double *q, double *e, double *w,
                                      void *params)
{
    const struct scene *sc = params;
    double zero[3] = {0, 0, 0};
    w[0] = w[1] = w[2] = 0.0;
    if (sc->kind == SCENE_FALL) {
        /* -2 W x v = v x (2 W) */
        e[0] = 0.0;
        e[1] = 0.0;
        e[2] = -sc->g0;
        for (int i = 0; i < 3; i++) w[i] = 2 * sc->W * sc->nvec[i];
        return MECH_OK;
    }
    return scene_accel(t, q, zero, e, params);
}

static double scene_energy(const struct scene *sc, const double *y)
{
    const double *q = y, *v = y + 3;
    double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    double q2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    switch (sc->kind) {
    case SCENE_KEPLER: return 0.5 * v2 - 1.0 / sqrt(q2);
    case SCENE_OSC: return 0.5 * v2 + 0.5 * q2;
    case SCENE_FALL: return 0.5 * v2 + sc->g0 * q[2];
    case SCENE_STIFF: return 0.5 * v2 + 0.5 * sc->k * q2;
    }
    return 0.0;
}

/* Kepler's equation M = E - e sin E by Newton from E = M + e sin M (or pi
 * for e > 0.8), iterated until the correction stops shrinking. */
static double kepler_E(double M, double e)
{
    double E = e > 0.8 ? MECH_PI : M + e * sin(M);
    double last = INFINITY;
    for (int i = 0; i < 100; i++) {
        double d = (E - e * sin(E) - M) / (1.0 - e * cos(E));
        E -= d;
        if (fabs(d) >= last || fabs(d) < 1e-17) break;
        last = fabs(d);
    }
    return E;
}

/* The exact state at time t. */
static void scene_exact(const struct scene *sc, double t, double *y)
{
    memset(y, 0, 6 * sizeof *y);
    switch (sc->kind) {
    case SCENE_KEPLER: {
        /* Pericentre at t = 0, n = 1: mean anomaly M = t mod 2 pi, reduced in
         * long double so the reduction adds < 1e-16 rad at t = 2 pi 1e5. */
        double e = sc->e;
        double M = (double)fmodl((long double)t, WP_TWO_PI_L);
        double E = kepler_E(M, e);
        double c = cos(E), s = sin(E), f = sqrt(1.0 - e * e), den = 1.0 - e * c;
        y[0] = c - e;
        y[1] = f * s;
        y[3] = -s / den;
        y[4] = f * c / den;
        break;
    }
    case SCENE_OSC:
        y[0] = cos(t);
        y[3] = -sin(t);
        break;
    case SCENE_FALL: {
        /* v' = g - w n x v, w = 2W, from rest at r0. With g = g_par + g_perp
         * (along / across n), v_p = -(n x g_perp) / w, x = w t:
         *   v = g_par t + v_p (1 - cos x) + (n x v_p) sin x
         *   r = r0 + g_par t^2/2 + v_p (x - sin x)/w + (n x v_p)(1 - cos x)/w
         * (n x v_p = g_perp / w). x - sin x by its series (x ~ 7e-4). */
        const double *n = sc->nvec;
        double w = 2.0 * sc->W, g[3] = {0, 0, -sc->g0};
        double gn = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
        double gpar[3], gperp[3], vp[3], nvp[3];
        for (int i = 0; i < 3; i++) {
            gpar[i] = gn * n[i];
            gperp[i] = g[i] - gpar[i];
        }
        cross(n, gperp, vp);
        for (int i = 0; i < 3; i++) vp[i] = -vp[i] / w;
        cross(n, vp, nvp);
        double x = w * t, x2 = x * x;
        double xms = x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0)));
        double sx = sin(0.5 * x), omc = 2.0 * sx * sx, sn = sin(x);
        for (int i = 0; i < 3; i++) {
            y[i] = sc->y0[i] + 0.5 * gpar[i] * t * t + vp[i] * xms / w + nvp[i] * omc / w;
            y[3 + i] = gpar[i] * t + vp[i] * omc + nvp[i] * sn;
        }
        break;
    }
    case SCENE_STIFF: {
        double l1 = sc->lam_slow, l2 = sc->lam_fast;
        double c1 = l2 / (l2 - l1), c2 = -l1 / (l2 - l1);
        double e1 = exp(l1 * t), e2 = exp(l2 * t);
        y[0] = sc->y0[0] * (c1 * e1 + c2 * e2);
        y[3] = sc->y0[0] * (c1 * l1 * e1 + c2 * l2 * e2);
        break;
    }
    }
}

static const double divs_k05[] = {50, 100, 200, 400, 800, 1600, 3200, 6400};
static const double divs_k09[] = {200, 400, 800, 1600, 3200, 6400, 12800};
static const double divs_osc[] = {8, 16, 32, 64, 128};
static const double divs_fall[] = {10, 30, 100, 300, 1000, 3000, 10000};
static const double divs_stiff[] = {1e2, 1e3, 1e4, 1e5, 1e6};
#define NDIV(a) (sizeof(a) / sizeof(a)[0])

static void scene_kepler(struct scene *sc, const char *name, const char *title, double e,
                         double orbits, const double *divs, size_t n_divs)
{
    memset(sc, 0, sizeof *sc);
    sc->name = name;
    sc->title = title;
    sc->kind = SCENE_KEPLER;
    sc->e = e;
    sc->period = 2.0 * MECH_PI;
    sc->t_end = orbits * (2.0 * MECH_PI);
    sc->scale = 1.0;
    sc->y0[0] = 1.0 - e;
    sc->y0[4] = sqrt((1.0 + e) / (1.0 - e));
    sc->has_energy = 1;
    sc->divs = divs;
    sc->n_divs = n_divs;
}

static void scenes_make(struct scene *s)
{
    scene_kepler(&s[0], "kepler-e0.5", "Kepler e = 0.5, 1000 orbits", 0.5, 1000, divs_k05,
                 NDIV(divs_k05));
    scene_kepler(&s[1], "kepler-e0.9", "Kepler e = 0.9, 1000 orbits", 0.9, 1000, divs_k09,
                 NDIV(divs_k09));

    struct scene *o = &s[2];
    memset(o, 0, sizeof *o);
    o->name = "oscillator";
    o->title = "Harmonic oscillator, 1e5 periods";
    o->kind = SCENE_OSC;
    o->period = 2.0 * MECH_PI;
    o->t_end = 1e5 * (2.0 * MECH_PI);
    o->scale = 1.0;
    o->y0[0] = 1.0;
    o->has_energy = 1;
    o->divs = divs_osc;
    o->n_divs = NDIV(divs_osc);

    struct scene *f = &s[3];
    memset(f, 0, sizeof *f);
    f->name = "falling";
    f->title = "Falling object, h = 100 m, lat 32 deg (Coriolis)";
    f->kind = SCENE_FALL;
    f->lat_deg = 32.0;
    f->g0 = 9.80665;
    f->h = 100.0;
    f->W = MECH_EARTH_OMEGA_SIDEREAL;
    double lat = f->lat_deg * (MECH_PI / 180.0);
    f->nvec[1] = cos(lat);
    f->nvec[2] = sin(lat);
    f->t_end = sqrt(2.0 * f->h / f->g0);
    f->period = f->t_end;
    f->scale = f->h;
    f->y0[2] = f->h;
    f->has_energy = 1;
    f->divs = divs_fall;
    f->n_divs = NDIV(divs_fall);

    struct scene *k = &s[4];
    memset(k, 0, sizeof *k);
    k->name = "stiff";
    k->title = "Stiff overdamped spring, k = 1, b = 1e3, t = 1000";
    k->kind = SCENE_STIFF;
    k->k = 1.0;
    k->b = 1e3;
    double disc = sqrt(k->b * k->b - 4.0 * k->k);
    k->lam_slow = -2.0 * k->k / (k->b + disc); /* no cancellation */
    k->lam_fast = -0.5 * (k->b + disc);
    k->period = 1000.0;
    k->t_end = 1000.0;
    k->scale = 1.0;
    k->y0[0] = 1.0;
    k->has_energy = 0;
    k->divs = divs_stiff;
    k->n_divs = NDIV(divs_stiff);
}

/* ---- one run ------------------------------------------------------------ */

struct row {
    const struct scene *sc;
    char method[32];
    int adaptive;
    double setting; /* rtol or dt */
    double atol;    /* adaptive: atol (0: = rtol) */
    const char *preset; /* accuracy preset name for preset rows, else NULL */
    double div;     /* fixed step: N with dt = period / N; 0 for adaptive */
    double t_end;
    enum mech_status st;
    char msg[200];
    double y[6];
    double pos_err, drift;
    struct mech_ode_stats stats;
    double cpu; /* thread CPU seconds per run */
    int repeats;
    size_t n_cp;
    double cp_t[WP_MAX_CP], cp_drift[WP_MAX_CP];
};

/* Wall-clock limit of one run (the budget's deadline): sweeps use a few
 * seconds, so one method that is slow on a scene (radau15 on the stiff one)
 * cannot stall the benchmark; the long runs of target 2 get more. */
static double run_seconds = 4.0;

/* Observer: max |E - E0| / |E0| over every accepted step, and its value so
 * far at each checkpoint time. */
struct watch {
    const struct scene *sc;
    double e0, max_drift;
    const double *cp_t;
    size_t n_cp, next;
    double *cp_drift;
};

static enum mech_status watch_observe(double t, const double *y, void *params)
{
    struct watch *w = params;
    if (w->sc->has_energy) {
        double d = fabs(scene_energy(w->sc, y) - w->e0) / fabs(w->e0);
        if (d > w->max_drift) w->max_drift = d;
    }
    while (w->next < w->n_cp && t >= w->cp_t[w->next] * (1.0 - 1e-12))
        w->cp_drift[w->next++] = w->max_drift;
    return MECH_OK;
}

static double pos_error(const struct scene *sc, double t, const double *y)
{
    double ex[6], s = 0.0;
    scene_exact(sc, t, ex);
    for (int i = 0; i < 3; i++) s += (y[i] - ex[i]) * (y[i] - ex[i]);
    return sqrt(s) / sc->scale;
}

static enum mech_status solve_once(struct row *r, const struct mech_integrator *m,
                                   struct watch *w, double *cpu)
{
    const struct scene *sc = r->sc;
    struct mech_ode_system sys = {
        .dim = 6,
        .rhs = scene_rhs,
        .accel = scene_accel,
        .flags = (sc->kind == SCENE_KEPLER || sc->kind == SCENE_OSC) ? MECH_ODE_VELOCITY_FREE : 0u,
        .params = (void *)sc,
        .lorentz = sc->kind == SCENE_STIFF ? NULL : scene_lorentz, /* drag has no Lorentz split */
        .particle_dim = 3, /* one body in 3-D */
    };
    struct mech_ode_options opt = {0, 0, 0};
    if (r->adaptive) {
        opt.rtol = r->setting;
        opt.atol = r->atol > 0 ? r->atol : r->setting;
    }
    else opt.dt = r->setting;
    double sample_y[12];
    struct mech_ode_problem p = {
        .sys = &sys, .method = m, .opt = opt, .t0 = 0.0, .t_end = r->t_end, .y0 = sc->y0,
        .n_samples = 2, .sample_t = NULL, .sample_y = sample_y, .event = NULL,
        .event_direction = MECH_ODE_EITHER, .event_params = NULL, .observe = watch_observe,
        .observe_params = w, .y_stop = NULL,
    };
    struct mech_budget b = mech_budget_make(60000000, run_seconds);
    struct mech_error err;
    struct mech_ode_result res;
    mech_error_clear(&err);
    memset(&res, 0, sizeof res);
    w->e0 = scene_energy(sc, sc->y0);
    w->max_drift = 0.0;
    w->next = 0;
    double c0 = mech_cpu_seconds();
    enum mech_status st = mech_ode_solve(&p, &b, &res, &err);
    *cpu = mech_cpu_seconds() - c0;
    r->st = st;
    r->stats = res.stats;
    if (st != MECH_OK) {
        snprintf(r->msg, sizeof r->msg, "%s: %.150s", mech_status_name(st), err.text);
        return st;
    }
    memcpy(r->y, sample_y + 6, sizeof r->y);
    return MECH_OK;
}

/* Run r (sc, method, adaptive, setting, t_end filled in). Runs under 2 ms
 * are repeated for >= 5 ms of CPU and the mean is reported (same numbers
 * every time: the runs are deterministic). */
static void run_row(struct row *r, const struct mech_integrator *m, const double *cp_t, size_t n_cp)
{
    struct watch w = {r->sc, 0.0, 0.0, cp_t, n_cp, 0, r->cp_drift};
    r->n_cp = n_cp;
    for (size_t i = 0; i < n_cp; i++) {
        r->cp_t[i] = cp_t[i];
        r->cp_drift[i] = NAN;
    }
    r->msg[0] = '\0';
    double cpu;
    if (solve_once(r, m, &w, &cpu) != MECH_OK) {
        r->cpu = cpu;
        r->pos_err = r->drift = NAN;
        r->repeats = 1;
        return;
    }
    r->drift = r->sc->has_energy ? w.max_drift : NAN;
    r->pos_err = pos_error(r->sc, r->t_end, r->y);
    double total = cpu;
    int n = 1;
    if (cpu < 2e-3) {
        int more = cpu > 0 ? (int)fmin(500.0, ceil(5e-3 / cpu)) : 500;
        struct row tmp = *r;
        struct watch w2 = w;
        w2.n_cp = 0;
        for (int i = 0; i < more; i++) {
            double c;
            if (solve_once(&tmp, m, &w2, &c) != MECH_OK) break;
            total += c;
            n++;
        }
    }
    r->cpu = total / n;
    r->repeats = n;
}

/* ---- table ---------------------------------------------------------------- */

static struct row rows[WP_MAX_ROWS];
static size_t n_rows;

static void setting_text(const struct row *r, char *buf, size_t n)
{
    if (strcmp(r->method, "scipy-DOP853") == 0 || r->adaptive)
        snprintf(buf, n, "rtol=%.0e", r->setting);
    else if (r->sc->kind == SCENE_KEPLER || r->sc->kind == SCENE_OSC)
        snprintf(buf, n, "dt=P/%.0f", r->div);
    else
        snprintf(buf, n, "dt=T/%.0f", r->div);
}

static void print_header(void)
{
    printf("%-12s %-16s %-12s %10s %10s %10s %12s %10s\n", "scene", "method", "setting",
           "pos_err", "max|dE/E|", "steps", "rhs_evals", "cpu_s");
}

static void print_row(const struct row *r)
{
    char set[32];
    setting_text(r, set, sizeof set);
    if (r->st != MECH_OK) {
        printf("%-12s %-16s %-12s %10s  %.*s (after %ld steps, %.3g s)\n", r->sc->name, r->method,
               set, "FAILED", 90, r->msg, r->stats.steps, r->cpu);
        return;
    }
    char drift[16];
    if (isnan(r->drift)) snprintf(drift, sizeof drift, "-");
    else snprintf(drift, sizeof drift, "%.2e", r->drift);
    printf("%-12s %-16s %-12s %10.2e %10s %10ld %12ld %10.5f\n", r->sc->name, r->method, set,
           r->pos_err, drift, r->stats.steps, r->stats.rhs_evaluations, r->cpu);
    fflush(stdout);
}

static struct row *row_new(void)
{
    if (n_rows >= WP_MAX_ROWS) return NULL;
    struct row *r = &rows[n_rows++];
    memset(r, 0, sizeof *r);
    return r;
}

/* ---- methods ---------------------------------------------------------------- */

struct method_entry {
    const struct mech_integrator *m;
    struct mech_ode_method_info info;
    int available;
    char why[256];
};
static struct method_entry methods[WP_MAX_METHODS];
static size_t n_methods;

static const struct mech_integrator *method_by_name(const char *name, int *available)
{
    for (size_t i = 0; i < n_methods; i++)
        if (strcmp(methods[i].info.name, name) == 0) {
            if (available) *available = methods[i].available;
            return methods[i].m;
        }
    if (available) *available = 0;
    return NULL;
}

/* A method is available when it integrates one orbit of Kepler e = 0.5
 * (a stub, or a method that cannot do even that, is listed as missing). */
static void methods_probe(const struct scene *sc)
{
    n_methods = 0;
    for (size_t i = 0; i < mech_ode_method_count() && n_methods < WP_MAX_METHODS; i++) {
        struct method_entry *e = &methods[n_methods++];
        e->m = mech_ode_method_at(i);
        e->info = mech_ode_method_describe(e->m);
        struct row r;
        memset(&r, 0, sizeof r);
        r.sc = sc;
        r.adaptive = e->info.adaptive;
        r.setting = e->info.adaptive ? 1e-8 : 0.01;
        r.t_end = sc->period;
        struct watch w = {sc, 0.0, 0.0, NULL, 0, 0, NULL};
        double cpu;
        e->available = solve_once(&r, e->m, &w, &cpu) == MECH_OK;
        snprintf(e->why, sizeof e->why, "%s", e->available ? "" : r.msg);
    }
}

static double cap_seconds(void)
{
    const char *s = getenv("MECHD_BENCH_CAP");
    double c = s ? atof(s) : 0.5;
    return c > 0 ? c : 0.5;
}

static const double rtols[] = {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15};

/* Every available method over its setting sweep, loose to tight; a sweep
 * stops after a run costing more than the cap. */
static void sweep_scene(const struct scene *sc, double cap)
{
    printf("\n## %s\n", sc->title);
    print_header();
    double cp[WP_MAX_CP];
    size_t n_cp = 0;
    if (sc->kind == SCENE_KEPLER || sc->kind == SCENE_OSC) {
        static const double m125[] = {1, 2, 5};
        for (double dec = 1; n_cp < WP_MAX_CP; dec *= 10) {
            int done = 0;
            for (int j = 0; j < 3 && n_cp < WP_MAX_CP; j++) {
                double t = m125[j] * dec * sc->period;
                if (t > sc->t_end * (1 + 1e-12)) {
                    done = 1;
                    break;
                }
                cp[n_cp++] = t;
            }
            if (done) break;
        }
    }
    for (size_t i = 0; i < n_methods; i++) {
        const struct method_entry *e = &methods[i];
        if (!e->available) continue;
        size_t n_set = e->info.adaptive ? sizeof rtols / sizeof rtols[0] : sc->n_divs;
        for (size_t j = 0; j < n_set; j++) {
            struct row *r = row_new();
            if (!r) return;
            r->sc = sc;
            snprintf(r->method, sizeof r->method, "%s", e->info.name);
            r->adaptive = e->info.adaptive;
            r->div = e->info.adaptive ? 0.0 : sc->divs[j];
            r->setting = e->info.adaptive ? rtols[j] : sc->period / sc->divs[j];
            r->t_end = sc->t_end;
            run_row(r, e->m, cp, n_cp);
            print_row(r);
            if (r->st == MECH_EINVAL) {
                printf("%-12s %-16s (does not apply to this scene: sweep stopped)\n", sc->name,
                       e->info.name);
                break;
            }
            if (r->cpu > cap) {
                if (j + 1 < n_set)
                    printf("%-12s %-16s (sweep stopped: the last run took more than %.2g s)\n",
                           sc->name, e->info.name, cap);
                break;
            }
        }
    }
}

/* ---- SciPy DOP853 baseline ------------------------------------------------- */

/* Run bench/workprecision_scipy.py on a Kepler scene up to t_end; one row
 * per rtol parsed from its output. Returns the number of rows added. */
static size_t scipy_run(const char *bench_dir, const struct scene *sc, double t_end, int repeats,
                        const char *rtol_list, struct row **first)
{
    char cmd[1024];
    const double *y = sc->y0;
    snprintf(cmd, sizeof cmd,
             "/usr/bin/python3 '%s/workprecision_scipy.py' 1 %.17g %.17g %.17g %.17g %.17g %.17g "
             "%.17g %d %s 2>&1",
             bench_dir, t_end, y[0], y[1], y[2], y[3], y[4], y[5], repeats, rtol_list);
    FILE *f = popen(cmd, "r");
    if (!f) {
        printf("scipy baseline: cannot run /usr/bin/python3: %s\n", strerror(errno));
        return 0;
    }
    char line[2048];
    size_t added = 0;
    *first = NULL;
    while (fgets(line, sizeof line, f)) {
        double rtol, cpu, drift, yf[6];
        long steps, nfev;
        if (sscanf(line,
                   "dop853 rtol=%lf steps=%ld nfev=%ld cpu=%lf max_rel_dE=%lf final=%lf %lf %lf "
                   "%lf %lf %lf",
                   &rtol, &steps, &nfev, &cpu, &drift, &yf[0], &yf[1], &yf[2], &yf[3], &yf[4],
                   &yf[5]) != 11) {
            printf("scipy baseline: %s", line);
            continue;
        }
        struct row *r = row_new();
        if (!r) break;
        if (!*first) *first = r;
        r->sc = sc;
        snprintf(r->method, sizeof r->method, "scipy-DOP853");
        r->adaptive = 1;
        r->setting = rtol;
        r->t_end = t_end;
        r->st = MECH_OK;
        memcpy(r->y, yf, sizeof yf);
        r->pos_err = pos_error(sc, t_end, yf);
        r->drift = drift;
        r->stats.steps = steps;
        r->stats.rhs_evaluations = nfev;
        r->cpu = cpu;
        r->repeats = repeats;
        added++;
    }
    int rc = pclose(f);
    if (rc != 0) printf("scipy baseline: the script exited with status %d\n", rc);
    return added;
}

/* ---- accuracy presets ------------------------------------------------------------ */

/* The same scene as a mech_trajectory_problem (unit mass), for
 * mech_trajectory_choose(): central gravity gm = 1 (Kepler), a spring k = 1
 * at the origin (oscillator), uniform gravity in the Earth frame with
 * Coriolis only (falling), spring + linear drag (stiff). */
static void trajectory_problem_of(const struct scene *sc, struct mech_trajectory_problem *tp,
                                  struct mech_force *forces)
{
    memset(tp, 0, sizeof *tp);
    memset(forces, 0, 2 * sizeof *forces);
    tp->mass = 1.0;
    tp->position = mech_vec3_make(sc->y0[0], sc->y0[1], sc->y0[2]);
    tp->velocity = mech_vec3_make(sc->y0[3], sc->y0[4], sc->y0[5]);
    tp->frame.type = MECH_FRAME_INERTIAL;
    tp->forces = forces;
    tp->n_forces = 1;
    tp->t_end = sc->t_end;
    tp->samples = 2;
    switch (sc->kind) {
    case SCENE_KEPLER:
        forces[0].type = MECH_FORCE_CENTRAL_GRAVITY;
        forces[0].u.central_gravity.gm = 1.0;
        break;
    case SCENE_OSC:
        forces[0].type = MECH_FORCE_SPRING;
        forces[0].u.spring.k = 1.0;
        break;
    case SCENE_FALL:
        tp->frame.type = MECH_FRAME_EARTH;
        tp->frame.latitude_deg = sc->lat_deg;
        tp->frame.omega_magnitude = sc->W;
        tp->fictitious = MECH_FICTITIOUS_CORIOLIS;
        forces[0].type = MECH_FORCE_UNIFORM_GRAVITY;
        forces[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -sc->g0);
        break;
    case SCENE_STIFF:
        forces[0].type = MECH_FORCE_SPRING;
        forces[0].u.spring.k = sc->k;
        forces[1].type = MECH_FORCE_LINEAR_DRAG;
        forces[1].u.linear_drag.b = sc->b;
        tp->n_forces = 2;
        break;
    }
}

/* What {"accuracy": preset} picks on each scene (mech_trajectory_choose),
 * run on the benchmark's own system, against the exact solution. */
static void presets_section(const struct scene *scenes, size_t n_scenes)
{
    printf("\n## Accuracy presets: what mech_trajectory_choose() picks, measured on each scene\n");
    printf("%-12s %-9s %8s %-8s %9s %9s %10s %10s %10s %10s  %s\n", "scene", "preset", "promise",
           "method", "rtol", "atol", "pos_err", "max|dE/E|", "rhs_evals", "cpu_s", "kept?");
    for (size_t s = 0; s < n_scenes; s++) {
        const struct scene *sc = &scenes[s];
        struct mech_trajectory_problem tp;
        struct mech_force forces[2];
        trajectory_problem_of(sc, &tp, forces);
        for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
            const struct mech_accuracy_preset *pr = mech_accuracy_preset_at((enum mech_accuracy)a);
            struct mech_trajectory_choice ch;
            struct mech_error err;
            mech_error_clear(&err);
            if (!pr || mech_trajectory_choose(&tp, pr->promise, &ch, &err) != MECH_OK) {
                printf("%-12s %-9s choose failed: %s\n", sc->name, pr ? pr->name : "?", err.text);
                continue;
            }
            int avail;
            const struct mech_integrator *m = method_by_name(ch.method, &avail);
            if (!m || !avail) {
                printf("%-12s %-9s %8.0e %-8s (method not available)\n", sc->name, pr->name,
                       pr->promise, ch.method);
                continue;
            }
            struct row *r = row_new();
            if (!r) return;
            r->sc = sc;
            r->preset = pr->name;
            snprintf(r->method, sizeof r->method, "%s", ch.method);
            r->adaptive = mech_ode_method_describe(m).adaptive;
            r->setting = r->adaptive ? ch.opt.rtol : ch.opt.dt;
            r->atol = ch.opt.atol;
            r->t_end = sc->t_end;
            run_row(r, m, NULL, 0);
            if (r->st != MECH_OK) {
                printf("%-12s %-9s %8.0e %-8s FAILED %s\n", sc->name, pr->name, pr->promise,
                       r->method, r->msg);
                continue;
            }
            char drift[16];
            if (isnan(r->drift)) snprintf(drift, sizeof drift, "-");
            else snprintf(drift, sizeof drift, "%.2e", r->drift);
            printf("%-12s %-9s %8.0e %-8s %9.2e %9.2e %10.2e %10s %10ld %10.5f  %s\n", sc->name,
                   pr->name, pr->promise, r->method, ch.opt.rtol, ch.opt.atol, r->pos_err, drift,
                   r->stats.rhs_evaluations, r->cpu, r->pos_err <= pr->promise ? "yes" : "NO");
            fflush(stdout);
        }
    }
}

/* ---- the presets on the trajectory scenes -------------------------------------
 * Through mech_trajectory_integrate (what a request gets: 201 samples, the
 * observer, the reference), each preset's method, rtol, error against the
 * exact reference (the falling object: a radau15 run at its round-off floor),
 * rhs evaluations and thread CPU (best of 3), the machine/draft and
 * machine/balanced ratios per scene and their geometric means. */
enum { IS_NS = 201 };
static double is_t[IS_NS];
static struct mech_vec3 is_pos[IS_NS], is_vel[IS_NS], is_rp[IS_NS], is_rv[IS_NS];

static enum mech_status issue_run(const struct mech_trajectory_problem *p,
                                  struct mech_trajectory_result *r, double *cpu)
{
    enum mech_status st = MECH_OK;
    *cpu = INFINITY;
    for (int k = 0; k < 3; k++) {
        struct mech_budget b = mech_budget_make(200000000, 60.0);
        memset(r, 0, sizeof *r);
        r->t = is_t;
        r->position = is_pos;
        r->velocity = is_vel;
        double t0 = mech_cpu_seconds();
        st = mech_trajectory_integrate(p, &b, r, NULL);
        *cpu = fmin(*cpu, mech_cpu_seconds() - t0);
        if (st != MECH_OK) break;
    }
    return st;
}

static void issue_presets_section(void)
{
    printf("\n## The presets on the trajectory scenes (through mech_trajectory_integrate, "
           "201 samples, CPU best of 3)\n");
    printf("%-22s %-9s %8s %-8s %9s %10s %-6s %10s %9s\n", "scene", "preset", "promise", "method",
           "rtol", "rel_err", "kept?", "rhs_evals", "cpu_s");
    const double PI = MECH_PI, gm = MECH_EARTH_GM;
    double log_md = 0, log_mb = 0;
    int n_sc = 0;
    for (int sc = 0; sc < 6; sc++) {
        struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
        struct mech_trajectory_problem p;
        memset(&p, 0, sizeof p);
        p.mass = 1000;
        p.forces = &f;
        p.n_forces = 1;
        p.samples = IS_NS;
        char name[40];
        if (sc < 4) {
            const double e = sc < 2 ? 0.5 : 0.9, n = sc % 2 ? 1000 : 10, q = 7e6, a = q / (1 - e);
            f.u.central_gravity.gm = gm;
            p.position = mech_vec3_make(q, 0, 0);
            p.velocity = mech_vec3_make(0, sqrt(gm * (1 + e) / q), 0);
            p.t_end = n * 2 * PI * sqrt(a * a * a / gm);
            snprintf(name, sizeof name, "kepler e=%.1f %.0f orb", e, n);
        } else if (sc == 4) {
            f.type = MECH_FORCE_SPRING;
            f.u.spring.k = 50;
            p.mass = 2;
            p.position = mech_vec3_make(0.1, 0, 0);
            p.velocity = mech_vec3_make(0, 0.2, 0);
            p.t_end = 1e4 * 2 * PI / 5;
            snprintf(name, sizeof name, "oscillator 1e4 per");
        } else {
            f.type = MECH_FORCE_UNIFORM_GRAVITY;
            f.u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
            p.mass = 1;
            p.frame.type = MECH_FRAME_EARTH;
            p.frame.latitude_deg = 32;
            p.frame.omega_magnitude = MECH_EARTH_OMEGA;
            p.fictitious = MECH_FICTITIOUS_CORIOLIS;
            p.position = mech_vec3_make(0, 0, 100);
            p.t_end = sqrt(2 * 100 / 9.80665);
            p.method = "radau15";
            p.opt.rtol = 1e-9;
            p.opt.atol = 1e-14;
            struct mech_trajectory_result r;
            double c;
            if (issue_run(&p, &r, &c) != MECH_OK) continue;
            memcpy(is_rp, is_pos, sizeof is_rp);
            memcpy(is_rv, is_vel, sizeof is_rv);
            snprintf(name, sizeof name, "falling 100m Coriolis");
        }
        double cpu[MECH_ACCURACY_COUNT] = {0};
        int ok = 1;
        for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
            const struct mech_accuracy_preset *pr = mech_accuracy_preset_at((enum mech_accuracy)a);
            struct mech_trajectory_choice ch;
            if (mech_trajectory_choose(&p, pr->promise, &ch, NULL) != MECH_OK) { ok = 0; break; }
            p.method = ch.method;
            p.opt = ch.opt;
            struct mech_trajectory_result r;
            if (issue_run(&p, &r, &cpu[a]) != MECH_OK) { ok = 0; break; }
            double er = 0;
            if (sc < 5) {
                er = fmax(r.reference.max_relative_position_error,
                          r.reference.max_relative_velocity_error);
            } else {
                for (int k = 0; k < IS_NS; k++) {
                    er = fmax(er, mech_vec3_norm(mech_vec3_sub(is_pos[k], is_rp[k])) / 100);
                    er = fmax(er, mech_vec3_norm(mech_vec3_sub(is_vel[k], is_rv[k])) /
                                      (9.80665 * p.t_end));
                }
            }
            printf("%-22s %-9s %8.0e %-8s %9.2e %10.2e %-6s %10ld %9.5f%s\n", name, pr->name,
                   pr->promise, ch.method, ch.opt.rtol, er,
                   er <= pr->promise ? "yes" : "NO", r.stats.rhs_evaluations, cpu[a],
                   strstr(ch.reason, "beyond what the preset") ? "  (selection: may be beyond)"
                                                                : "");
        }
        if (!ok) {
            printf("%-22s FAILED\n", name);
            continue;
        }
        const double md = cpu[MECH_ACCURACY_MACHINE] / cpu[MECH_ACCURACY_DRAFT];
        const double mb = cpu[MECH_ACCURACY_MACHINE] / cpu[MECH_ACCURACY_BALANCED];
        printf("%-22s machine/draft %.2fx, machine/balanced %.2fx\n", name, md, mb);
        log_md += log(md);
        log_mb += log(mb);
        n_sc++;
    }
    if (n_sc)
        printf("geometric mean over %d scenes: machine/draft %.2fx (issue: >= 10), "
               "machine/balanced %.2fx (issue: >= 3 where the physics allows)\n",
               n_sc, exp(log_md / n_sc), exp(log_mb / n_sc));
    fflush(stdout);
}


/* ---- the scene set through the API, beside GSL rk8pd and DOP853 -------------
 * Every scene of tests/api/scene_set.h (the same requests and references
 * test_preset_scenes checks), each preset through api_handle (JSON, what a
 * request gets; the method and settings read from the answer's
 * diagnostics, so a new chooser is measured unchanged): thread CPU, the
 * median of SS_ROUNDS interleaved rounds (round r runs every preset once),
 * the error against the scene's reference, the ratios machine/draft and
 * machine/balanced and their geometric means. Beside them, where the scene
 * has a bare right-hand side here (Kepler, oscillator, rigid body, the
 * falling object, the heavy top in Euler angles, Henon-Heiles; not Mercury's
 * geodesic): GSL rk8pd called directly (gsl_odeiv2_evolve_apply, rtol =
 * atol 1e-6 .. 1e-15) and SciPy DOP853 (rtol 1e-6 .. 1e-14), each its best
 * error over the sweep (final state against the same reference, the same
 * floor) and the CPU of that run. */
#include "../tests/api/scene_set.h"

enum { SS_ROUNDS = 3 };

struct ss_bare {
    const char *scipy; /* scene name for workprecision_scipy.py, NULL: none */
    size_t dim;
    double y0[6];
    size_t cmp; /* components compared with the reference (the first cmp; 0: all) */
};

static int ss_rhs_kepler(double t, const double y[], double f[], void *p)
{
    (void)t, (void)p;
    double a[3];
    kepler_acc(y, a);
    f[0] = y[3], f[1] = y[4], f[2] = y[5], f[3] = a[0], f[4] = a[1], f[5] = a[2];
    return GSL_SUCCESS;
}
static int ss_rhs_osc(double t, const double y[], double f[], void *p)
{
    (void)t, (void)p;
    f[0] = y[3], f[1] = y[4], f[2] = y[5], f[3] = -y[0], f[4] = -y[1], f[5] = -y[2];
    return GSL_SUCCESS;
}
static int ss_rhs_rigid(double t, const double w[], double f[], void *p)
{
    (void)t, (void)p;
    f[0] = (2.0 - 3.0) / 1.0 * w[1] * w[2];
    f[1] = (3.0 - 1.0) / 2.0 * w[2] * w[0];
    f[2] = (1.0 - 2.0) / 3.0 * w[0] * w[1];
    return GSL_SUCCESS;
}
static int ss_rhs_hh(double t, const double y[], double f[], void *p)
{
    (void)t, (void)p;
    f[0] = y[2], f[1] = y[3];
    f[2] = -y[0] - 2 * y[0] * y[1];
    f[3] = -y[1] - y[0] * y[0] + y[1] * y[1];
    return GSL_SUCCESS;
}

/* The falling object in the Earth frame (east, north, up) at 32 deg N with
 * Coriolis only: a = g - 2 W x v, W = Omega (0, cos lat, sin lat). */
static int ss_rhs_fall(double t, const double y[], double f[], void *p)
{
    (void)t, (void)p;
    const double W = MECH_EARTH_OMEGA, lat = 32.0 * SS_PI / 180.0;
    const double wy = W * cos(lat), wz = W * sin(lat);
    f[0] = y[3], f[1] = y[4], f[2] = y[5];
    /* W x v = (wy vz - wz vy, wz vx, -wy vx) */
    f[3] = -2.0 * (wy * y[5] - wz * y[4]);
    f[4] = -2.0 * (wz * y[3]);
    f[5] = -9.80665 - 2.0 * (-wy * y[3]);
    return GSL_SUCCESS;
}

/* The heavy symmetric top of the scene set (I1 = 0.02, I3 = 0.01, M g l =
 * 0.980665, theta0 = pi/3, phi' = 0.99, psi' = 99.5) in Euler angles, an
 * independent formulation of mechd's quaternion integration:
 * y = (theta, phi, psi, theta'), with the conserved p_psi = I3 (psi' + phi' cos theta),
 * p_phi = I1 phi' sin^2 theta + p_psi cos theta. */
#define SS_TOP_I1 0.02
#define SS_TOP_I3 0.01
#define SS_TOP_MGL (1.0 * 9.80665 * 0.1)
static double ss_top_ppsi(void) { return SS_TOP_I3 * (99.5 + 0.99 * cos(SS_PI / 3)); }
static double ss_top_pphi(void)
{
    const double s = sin(SS_PI / 3);
    return SS_TOP_I1 * 0.99 * s * s + ss_top_ppsi() * cos(SS_PI / 3);
}
static int ss_rhs_top(double t, const double y[], double f[], void *p)
{
    (void)t, (void)p;
    const double th = y[0], s = sin(th), c = cos(th), pp = ss_top_ppsi(), pf = ss_top_pphi();
    const double phid = (pf - pp * c) / (SS_TOP_I1 * s * s);
    f[0] = y[3];
    f[1] = phid;
    f[2] = pp / SS_TOP_I3 - phid * c;
    f[3] = (SS_TOP_I1 * phid * phid * s * c - pp * phid * s + SS_TOP_MGL * s) / SS_TOP_I1;
    return GSL_SUCCESS;
}

/* the bare form of scene s (index into SCENES), or NULL */
static int (*ss_bare_of(size_t s, struct ss_bare *b))(double, const double *, double *, void *)
{
    memset(b, 0, sizeof *b);
    if (SCENES[s].ref == REF_KEPLER) {
        const double e = SCENES[s].e;
        *b = (struct ss_bare){"kepler", 6, {1 - e, 0, 0, 0, sqrt((1 + e) / (1 - e)), 0}, 0};
        return ss_rhs_kepler;
    }
    if (SCENES[s].ref == REF_OSC) {
        *b = (struct ss_bare){"oscillator", 6, {1, 0, 0, 0, 0.5, 0}, 0};
        return ss_rhs_osc;
    }
    if (SCENES[s].ref == REF_RIGID) {
        *b = (struct ss_bare){"rigid", 3, {0.05, 1, 0.05}, 0};
        return ss_rhs_rigid;
    }
    if (strstr(SCENES[s].name, "falling")) {
        *b = (struct ss_bare){"falling", 6, {0, 0, 100, 0, 0, 0}, 0};
        return ss_rhs_fall;
    }
    if (strcmp(SCENES[s].path, "/v1/rigid/top") == 0) {
        *b = (struct ss_bare){"top", 4, {SS_PI / 3, 0, 0, 0}, 3};
        return ss_rhs_top;
    }
    if (strcmp(SCENES[s].path, "/v1/hamiltonian/flow") == 0) {
        *b = (struct ss_bare){"henon_heiles", 4, {0, 0, 0.1, 0}, 0};
        return ss_rhs_hh;
    }
    return NULL;
}

/* the reference final state of scene s in its bare form (from the reference
 * answer: last sample), 0 when there is none */
static int ss_bare_ref(size_t s, const json_t *ref, double *yr)
{
    const struct scene_def *sc = &SCENES[s];
    (void)sc;
    if (strcmp(SCENES[s].path, "/v1/rigid/top") == 0) {
        static const char *const k3[3] = {"theta", "phi", "psi"};
        for (int k = 0; k < 3; k++) {
            const json_t *A = json_object_get(ref, k3[k]);
            if (!json_array_size(A)) return 0;
            yr[k] = json_number_value(json_array_get(A, json_array_size(A) - 1));
        }
        return 1;
    }
    if (SCENES[s].ref == REF_KEPLER || SCENES[s].ref == REF_OSC || json_object_get(ref, "position")) {
        const json_t *P = json_object_get(ref, "position"), *V = json_object_get(ref, "velocity");
        size_t n = json_array_size(P);
        if (!n) return 0;
        for (int k = 0; k < 3; k++) {
            yr[k] = json_number_value(json_array_get(json_array_get(P, n - 1), k));
            yr[3 + k] = json_number_value(json_array_get(json_array_get(V, n - 1), k));
        }
        return 1;
    }
    if (SCENES[s].ref == REF_RIGID) {
        const json_t *W = json_object_get(ref, "omega");
        size_t n = json_array_size(W);
        if (!n) return 0;
        for (int k = 0; k < 3; k++)
            yr[k] = json_number_value(json_array_get(json_array_get(W, n - 1), k));
        return 1;
    }
    const json_t *Q = json_object_get(ref, "q"), *Pp = json_object_get(ref, "p");
    size_t n = json_array_size(Q);
    if (!n) return 0;
    for (int k = 0; k < 2; k++) {
        yr[k] = json_number_value(json_array_get(json_array_get(Q, n - 1), k));
        yr[2 + k] = json_number_value(json_array_get(json_array_get(Pp, n - 1), k));
    }
    return 1;
}

static double ss_state_err(const double *y, const double *yr, size_t dim, double floor_)
{
    double e = 0;
    for (size_t i = 0; i < dim; i++) {
        if (!isfinite(y[i])) return INFINITY;
        e = fmax(e, fabs(y[i] - yr[i]) / fmax(fabs(yr[i]), floor_));
    }
    return e;
}

/* GSL rk8pd called directly: best error over the rtol sweep and its CPU */
static void ss_gsl_direct(int (*f)(double, const double *, double *, void *),
                          const struct ss_bare *b, double t_end, const double *yr, double floor_,
                          double cap, double *best_err, double *best_cpu, double *best_rtol)
{
    *best_err = INFINITY, *best_cpu = NAN, *best_rtol = NAN;
    for (size_t j = 0; j < sizeof rtols / sizeof rtols[0]; j++) {
        gsl_odeiv2_system sys = {f, NULL, b->dim, NULL};
        gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, b->dim);
        gsl_odeiv2_control *con = gsl_odeiv2_control_y_new(rtols[j], rtols[j]);
        gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(b->dim);
        double y[6], t = 0, h = 1e-3;
        memcpy(y, b->y0, sizeof y);
        const double c0 = mech_cpu_seconds();
        int gs = GSL_SUCCESS;
        while (t < t_end && gs == GSL_SUCCESS) gs = gsl_odeiv2_evolve_apply(ev, con, st, &sys, &t, t_end, &h, y);
        const double cpu = mech_cpu_seconds() - c0;
        gsl_odeiv2_evolve_free(ev);
        gsl_odeiv2_control_free(con);
        gsl_odeiv2_step_free(st);
        if (gs != GSL_SUCCESS) break;
        const double e = ss_state_err(y, yr, b->cmp ? b->cmp : b->dim, floor_);
        if (e < *best_err) *best_err = e, *best_cpu = cpu, *best_rtol = rtols[j];
        if (cpu > cap) break;
    }
}

/* SciPy DOP853: best error over its rtol sweep and its CPU; 0 if it did not run */
static int ss_scipy(const char *bench_dir, const struct ss_bare *b, double t_end, const double *yr,
                    double floor_, double cap, double *best_err, double *best_cpu)
{
    *best_err = INFINITY, *best_cpu = NAN;
    char cmd[2048];
    int n = snprintf(cmd, sizeof cmd, "/usr/bin/python3 '%s/workprecision_scipy.py' --scene %s %.17g %g",
                     bench_dir, b->scipy, t_end, cap);
    for (size_t i = 0; i < b->dim; i++)
        n += snprintf(cmd + n, sizeof cmd - (size_t)n, " %.17g", b->y0[i]);
    snprintf(cmd + n, sizeof cmd - (size_t)n,
             " -- 1e-6 1e-7 1e-8 1e-9 1e-10 1e-11 1e-12 1e-13 1e-14 2>&1");
    FILE *fp = popen(cmd, "r");
    if (!fp) return 0;
    char line[2048];
    int got = 0;
    while (fgets(line, sizeof line, fp)) {
        double rtol, cpu, y[6] = {0};
        long nfev;
        int off = 0;
        if (sscanf(line, "dop853 rtol=%lf nfev=%ld cpu=%lf final=%n", &rtol, &nfev, &cpu, &off) < 3 ||
            !off) {
            printf("  scipy: %s", line);
            continue;
        }
        char *q = line + off;
        for (size_t i = 0; i < b->dim; i++) y[i] = strtod(q, &q);
        const double e = ss_state_err(y, yr, b->cmp ? b->cmp : b->dim, floor_);
        if (e < *best_err) *best_err = e, *best_cpu = cpu;
        got = 1;
    }
    pclose(fp);
    return got;
}

static int ss_cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The chosen candidate's predicted evaluations and CPU in an answer's
 * diagnostics.selection (0 when absent). */
static void ss_predicted(const json_t *ans, double *evals, double *cpu)
{
    *evals = *cpu = 0;
    const json_t *c = at(ans, "diagnostics/selection/candidates");
    for (size_t i = 0; i < json_array_size(c); i++) {
        const json_t *k = json_array_get(c, i);
        const char *v = json_string_value(json_object_get(k, "verdict"));
        if (v && !strcmp(v, "chosen")) {
            *evals = json_number_value(json_object_get(k, "predicted_evaluations"));
            *cpu = json_number_value(json_object_get(k, "predicted_cpu_s"));
        }
    }
}

/* The closed form as a client gets it (balanced, no "closed_form": false),
 * in the same columns as the integrating presets: its error against the
 * scene's reference, predicted and counted evaluations, CPU. */
static void ss_closed_form_row(const struct scene_def *sc)
{
    double cpu[SS_ROUNDS], err = INFINITY, pev = 0, pcpu = 0, nev = 0;
    const char *m = "?";
    char method[32] = "?";
    for (int r = 0; r < SS_ROUNDS; r++) {
        json_t *b = with_integrator(sc->body, json_pack("{ss}", "accuracy", "balanced"));
        int st;
        const double c0 = mech_cpu_seconds();
        json_t *ans = post(sc->path, b, &st);
        cpu[r] = mech_cpu_seconds() - c0;
        json_decref(b);
        if (st != 200 || !ans) {
            json_decref(ans);
            printf("%-34s closed form: FAILED\n", sc->name);
            return;
        }
        if (r == 0) {
            m = json_string_value(at(ans, "diagnostics/selection/method"));
            snprintf(method, sizeof method, "%s", m ? m : "?");
            ss_predicted(ans, &pev, &pcpu);
            const json_t *d = json_object_get(ans, "diagnostics");
            const json_t *ne = json_object_get(d, "evaluations");
            if (!ne) ne = json_object_get(d, "rhs_evaluations");
            nev = json_number_value(ne);
            json_t *rf = sc->ref == REF_KEPLER ? exact_trajectory(ans, 1, sc->body)
                       : sc->ref == REF_OSC    ? exact_trajectory(ans, 0, sc->body)
                                               : exact_rigid(ans);
            err = rf ? 0 : INFINITY;
            for (int k = 0; rf && k < 3 && sc->arrays[k]; k++)
                err = fmax(err, tree_err(at(ans, sc->arrays[k]), at(rf, sc->arrays[k]),
                                         sc->floor_));
            json_decref(rf);
        }
        json_decref(ans);
    }
    qsort(cpu, SS_ROUNDS, sizeof cpu[0], ss_cmp_double);
    const double med = cpu[SS_ROUNDS / 2];
    printf("%-34s %-9s %7.0e %-26s %10.2e %-9s %9.5f %10.0f/%-10.0f %8.2f\n", sc->name,
           "(client)", 1e-8, method, err, err <= 1e-8 ? "yes" : "NO", med, pev, nev,
           pcpu > 0 ? med / pcpu : 0.0);
}

/* The Foucault pendulum, 100 swings at 48.846 deg (Paris), through
 * /v1/scenes/foucault by accuracy: error = max(|period - ref| / ref, |rate -
 * ref| / W) against rattle_yoshida4 at 12800 steps per swing (its own
 * error ~1e-14 on the period, ~1e-12 on the rate: the round-off of the
 * azimuth over 0.12 rad of Earth's turn). The count includes the error
 * estimate's run. Returns 1 with the machine/draft and machine/balanced
 * CPU ratios. */
static int foucault_rows(double *md, double *mb)
{
    static const char *const presets[] = {"draft", "balanced", "precise", "machine"};
    static const double promise[] = {1e-3, 1e-8, 1e-10, 1e-11};
    const char *base = "{\"latitude_deg\":48.846,\"swings\":100,\"cost\":false";
    const double W = 7.292115e-05;
    char body[256];
    snprintf(body, sizeof body, "%s,\"integrator\":{\"steps_per_swing\":12800}}", base);
    json_t *b = json_loads(body, 0, NULL);
    int st;
    json_t *ref = post("/v1/scenes/foucault", b, &st);
    json_decref(b);
    if (st != 200 || !ref) {
        json_decref(ref);
        printf("%-34s FAILED (reference)\n", "Foucault 100 swings");
        return 0;
    }
    const double P0 = json_number_value(at(ref, "swing/period"));
    const double R0 = json_number_value(at(ref, "precession/measured_rate"));
    json_decref(ref);
    double cpu[4][SS_ROUNDS], err[4] = {0}, pev[4] = {0}, pcpu[4] = {0}, nev[4] = {0};
    char how[4][64] = {{0}};
    for (int r = 0; r < SS_ROUNDS; r++)
        for (int p = 0; p < 4; p++) {
            snprintf(body, sizeof body, "%s,\"accuracy\":\"%s\"}", base, presets[p]);
            b = json_loads(body, 0, NULL);
            const double c0 = mech_cpu_seconds();
            json_t *ans = post("/v1/scenes/foucault", b, &st);
            cpu[p][r] = mech_cpu_seconds() - c0;
            json_decref(b);
            if (st != 200 || !ans) {
                json_decref(ans);
                return 0;
            }
            if (r == 0) {
                const json_t *d = json_object_get(ans, "diagnostics");
                const char *m = json_string_value(json_object_get(d, "method"));
                snprintf(how[p], sizeof how[p], "%s (%.0f/swing)", m ? m : "?",
                         json_number_value(json_object_get(d, "steps_per_swing")));
                ss_predicted(ans, &pev[p], &pcpu[p]);
                const double per = m && !strcmp(m, "rattle") ? 1 : 3;
                nev[p] = json_number_value(json_object_get(d, "force_evaluations")) +
                         json_number_value(at(ans, "diagnostics/error_estimate/steps")) * per + 1;
                err[p] = fmax(fabs(json_number_value(at(ans, "swing/period")) - P0) / P0,
                              fabs(json_number_value(at(ans, "precession/measured_rate")) - R0) /
                                  W);
            }
            json_decref(ans);
        }
    double med[4];
    for (int p = 0; p < 4; p++) {
        qsort(cpu[p], SS_ROUNDS, sizeof cpu[p][0], ss_cmp_double);
        med[p] = cpu[p][SS_ROUNDS / 2];
        printf("%-34s %-9s %7.0e %-26s %10.2e %-9s %9.5f %10.0f/%-10.0f %8.2f\n",
               "Foucault 100 swings", presets[p], promise[p], how[p], err[p],
               err[p] <= promise[p] ? "yes" : "NO", med[p], pev[p], nev[p],
               pcpu[p] > 0 ? med[p] / pcpu[p] : 0.0);
    }
    *md = med[3] / med[0];
    *mb = med[3] / med[1];
    printf("%-34s machine/draft %.2fx  machine/balanced %.2fx  (reference: rattle_yoshida4 at "
           "12800 steps per swing)\n", "Foucault 100 swings", *md, *mb);
    return 1;
}

static void scene_set_section(const char *bench_dir)
{
    static const char *const presets[] = {"draft", "balanced", "precise", "machine"};
    static const double promise[] = {1e-3, 1e-8, 1e-10, 1e-11};
    const int have_scipy = system("/usr/bin/python3 -c 'import scipy' >/dev/null 2>&1") == 0;
    printf("\n## The scene set through the API (api_handle, JSON; CPU = median of %d "
           "interleaved rounds, thread CPU of the whole request)\n", SS_ROUNDS);
    printf("# error: max over samples of |got - ref| / max(|ref|, scale) against the scene's "
           "reference (tests/api/scene_set.h)\n");
    if (!have_scipy)
        printf("# SciPy DOP853 column: not measured (python3-scipy is not installed: "
               "scripts/install-deps.sh --bench)\n");
    printf("# kept?: yes, re-stated (beyond the promise but within the figure the answer's "
           "selection re-states for round-off), NO\n");
    printf("# evals: the chosen candidate's predicted_evaluations / the answer's count; "
           "cpu/pred: the measured CPU of the whole request over the chosen candidate's "
           "predicted_cpu_s (the model predicts the integration only)\n");
    printf("%-34s %-9s %7s %-26s %10s %-9s %9s %21s %8s\n", "scene", "preset", "promise",
           "method (settings)", "error", "kept?", "cpu_s", "evals pred/count", "cpu/pred");
    double log_md = 0, log_mb = 0;
    int n_md = 0;
    for (size_t s = 0; s < N_SCENES; s++) {
        const struct scene_def *sc = &SCENES[s];
        double cpu[4][SS_ROUNDS], err[4] = {0}, restated[4] = {0};
        double pev[4] = {0}, pcpu[4] = {0}, nev[4] = {0};
        char how[4][64] = {{0}};
        const char *evidence = "exact";
        json_t *ref = NULL;
        int ok = 1;
        for (int r = 0; r < SS_ROUNDS && ok; r++) {
            for (int p = 0; p < 4 && ok; p++) {
                /* the integrating presets: a client asking by accuracy on a
                 * scene with a closed form gets that instead (bench_closed_form) */
                json_t *b = with_integrator(
                    sc->body, json_pack("{sssb}", "accuracy", presets[p], "closed_form", 0));
                int st;
                const double c0 = mech_cpu_seconds();
                json_t *ans = post(sc->path, b, &st);
                cpu[p][r] = mech_cpu_seconds() - c0;
                json_decref(b);
                if (st != 200 || !ans) {
                    ok = 0;
                    json_decref(ans);
                    break;
                }
                if (r == 0) {
                    const json_t *d = json_object_get(ans, "diagnostics");
                    const char *m = json_string_value(json_object_get(d, "method"));
                    ss_predicted(ans, &pev[p], &pcpu[p]);
                    nev[p] = json_number_value(json_object_get(d, "rhs_evaluations"));
                    const json_t *rt = json_object_get(d, "rtol"), *dt = json_object_get(d, "dt");
                    if (rt)
                        snprintf(how[p], sizeof how[p], "%s (rtol %.1e)", m ? m : "?",
                                 json_number_value(rt));
                    else if (dt)
                        snprintf(how[p], sizeof how[p], "%s (dt %.2g)", m ? m : "?",
                                 json_number_value(dt));
                    else
                        snprintf(how[p], sizeof how[p], "%s", m ? m : "?");
                    json_t *rf = NULL;
                    switch (sc->ref) {
                    case REF_KEPLER: rf = exact_trajectory(ans, 1, sc->body); break;
                    case REF_OSC: rf = exact_trajectory(ans, 0, sc->body); break;
                    case REF_RIGID: rf = exact_rigid(ans); break;
                    case REF_RUN: rf = reference_run(sc, m ? m : "", &evidence); break;
                    }
                    double e = rf ? 0 : INFINITY;
                    for (int k = 0; rf && k < 3 && sc->arrays[k]; k++)
                        e = fmax(e, tree_err(at(ans, sc->arrays[k]), at(rf, sc->arrays[k]),
                                             sc->floor_));
                    err[p] = e;
                    restated[p] = ss_restated(ans, promise[p]);
                    if (!ref && rf && sc->ref != REF_RUN) ref = json_incref(rf);
                    if (!ref && rf && p == 3) ref = json_incref(rf); /* the round-off ref */
                    json_decref(rf);
                }
                json_decref(ans);
            }
        }
        if (!ok) {
            printf("%-34s FAILED (a preset's request did not answer 200)\n", sc->name);
            json_decref(ref);
            continue;
        }
        double med[4];
        for (int p = 0; p < 4; p++) {
            qsort(cpu[p], SS_ROUNDS, sizeof cpu[p][0], ss_cmp_double);
            med[p] = cpu[p][SS_ROUNDS / 2];
            printf("%-34s %-9s %7.0e %-26s %10.2e %-9s %9.5f %10.0f/%-10.0f %8.2f\n", sc->name,
                   presets[p], promise[p], how[p], err[p],
                   err[p] <= promise[p] ? "yes" : err[p] <= restated[p] ? "re-stated" : "NO",
                   med[p], pev[p], nev[p], pcpu[p] > 0 ? med[p] / pcpu[p] : 0.0);
        }
        if (sc->ref != REF_RUN) ss_closed_form_row(sc);
        const double md = med[3] / med[0], mb = med[3] / med[1];
        log_md += log(md), log_mb += log(mb), n_md++;
        printf("%-34s machine/draft %.2fx  machine/balanced %.2fx  (reference: %s)\n", sc->name, md,
               mb, evidence);
        struct ss_bare bare;
        int (*f)(double, const double *, double *, void *) = ss_bare_of(s, &bare);
        double yr[6];
        if (f && ref && ss_bare_ref(s, ref, yr)) {
            json_t *ts = json_object_get(ref, "t");
            double t_end = json_number_value(json_array_get(ts, json_array_size(ts) - 1));
            if (!ts) { /* the reference is answer-shaped; take t_end from the request */
                json_t *b = json_loads(sc->body, 0, NULL);
                t_end = json_number_value(json_object_get(b, "t_end"));
                json_decref(b);
            }
            double ge, gc, gr;
            ss_gsl_direct(f, &bare, t_end, yr, sc->floor_, 2.0, &ge, &gc, &gr);
            printf("%-34s GSL rk8pd direct: best error %.2e at rtol %.0e, cpu %.5f s\n", sc->name,
                   ge, gr, gc);
            double se, scpu;
            if (have_scipy && ss_scipy(bench_dir, &bare, t_end, yr, sc->floor_, 3.0, &se, &scpu))
                printf("%-34s SciPy DOP853: best error %.2e, cpu %.5f s\n", sc->name, se, scpu);
            else if (have_scipy)
                printf("%-34s SciPy DOP853: did not run\n", sc->name);
        } else {
            printf("%-34s GSL rk8pd direct / SciPy DOP853: not measured (no bare right-hand side "
                   "of this scene in the bench)\n", sc->name);
        }
        json_decref(ref);
        fflush(stdout);
    }
    double fmd, fmb;
    if (foucault_rows(&fmd, &fmb)) {
        log_md += log(fmd), log_mb += log(fmb), n_md++;
    }
    if (n_md)
        printf("geometric mean over %d scenes: machine/draft %.2fx (issue: >= 10), "
               "machine/balanced %.2fx (issue: >= 3 where the physics allows)\n",
               n_md, exp(log_md / n_md), exp(log_mb / n_md));
    fflush(stdout);
}

/* ---- output files ------------------------------------------------------------ */

static int mkdir_p(const char *path)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
    return 0;
}

/* wp_<scene>.dat: one gnuplot block per method (first line: the method's
 * name, then cpu_s pos_err drift steps rhs_evals setting rows). Blocks are
 * separated by two blank lines (gnuplot `index`). */
static void write_scene_data(const char *dir, const struct scene *sc)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/wp_%s.dat", dir, sc->name);
    FILE *f = fopen(path, "w");
    if (!f) {
        printf("cannot write %s: %s\n", path, strerror(errno));
        return;
    }
    fprintf(f, "# %s: thread CPU seconds, position error / L, max |dE/E| (-1: none)\n", sc->title);
    char done[64][32];
    size_t n_done = 0, blocks = 0;
    for (size_t i = 0; i < n_rows; i++) {
        if (rows[i].sc != sc || rows[i].st != MECH_OK || rows[i].preset) continue;
        int seen = 0;
        for (size_t k = 0; k < n_done; k++)
            if (strcmp(done[k], rows[i].method) == 0) seen = 1;
        if (seen || n_done >= 64) continue;
        snprintf(done[n_done++], sizeof done[0], "%s", rows[i].method);
        if (blocks++) fprintf(f, "\n\n");
        fprintf(f, "%s cpu_s pos_err drift steps rhs_evals setting lt\n", rows[i].method);
        int lt = (int)n_methods + 1; /* the baseline */
        for (size_t k = 0; k < n_methods; k++)
            if (strcmp(methods[k].info.name, rows[i].method) == 0) lt = (int)k + 1;
        for (size_t j = i; j < n_rows; j++) {
            const struct row *r = &rows[j];
            if (r->sc != sc || r->st != MECH_OK || r->preset ||
                strcmp(r->method, rows[i].method) != 0)
                continue;
            fprintf(f, "%.6e %.6e %.6e %ld %ld %.6e %d\n", fmax(r->cpu, 1e-7),
                    fmax(r->pos_err, 1e-17), isnan(r->drift) ? -1.0 : fmax(r->drift, 1e-17),
                    r->stats.steps, r->stats.rhs_evaluations, r->setting, lt);
        }
    }
    fclose(f);
}

static void write_tsv(const char *dir)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/workprecision.tsv", dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        printf("cannot write %s: %s\n", path, strerror(errno));
        return;
    }
    fprintf(f, "scene\tmethod\tsetting\tt_end\tstatus\tpos_err\tmax_rel_dE\tsteps\trhs_evals\tcpu_s\n");
    for (size_t i = 0; i < n_rows; i++) {
        const struct row *r = &rows[i];
        char set[32];
        setting_text(r, set, sizeof set);
        char name[64];
        snprintf(name, sizeof name, "%s%s%s", r->preset ? r->preset : "", r->preset ? "->" : "",
                 r->method);
        fprintf(f, "%s\t%s\t%s\t%.17g\t%s\t%.6e\t%.6e\t%ld\t%ld\t%.6e\n", r->sc->name, name,
                set, r->t_end, mech_status_name(r->st), r->pos_err, r->drift, r->stats.steps,
                r->stats.rhs_evaluations, r->cpu);
    }
    fclose(f);
}

/* ---- targets ---------------------------------------------------------------- */

static int same_bits(const struct row *a, const struct row *b)
{
    return a->st == b->st && memcmp(a->y, b->y, sizeof a->y) == 0 &&
           memcmp(&a->drift, &b->drift, sizeof a->drift) == 0 &&
           a->stats.steps == b->stats.steps && a->stats.rhs_evaluations == b->stats.rhs_evaluations;
}

/* Target 2: energy error of the symplectic methods over 1e5 orbits of
 * Kepler e = 0.5, max |dE/E| so far at 1e3, 1e4 and 1e5 orbits. Bounded
 * (non-secular): growth from 1e3 to 1e5 orbits <= 3 (a secular linear
 * drift grows 100x, a round-off random walk 10x). */
struct longrun_spec {
    const char *method;
    double div;
    int target; /* one of the three targets */
};
static const struct longrun_spec longrun[] = {
    {"verlet", 200, 1},         {"yoshida4", 100, 1}, {"yoshida6", 50, 1}, {"gauss4", 100, 1},
    {"gauss6", 50, 1},          {"symplectic_euler", 200, 0}, {"boris", 200, 0},
    {"rk4", 100, 0},
};

static int longrun_target(const struct scene *k05, const char *dir, char *summary, size_t n_sum)
{
    struct scene sc = *k05;
    sc.name = "kepler-e0.5-1e5";
    sc.t_end = 1e5 * (2.0 * MECH_PI);
    static const double orbits[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1e3, 2e3, 5e3,
                                    1e4, 2e4, 5e4, 1e5};
    size_t n_cp = sizeof orbits / sizeof orbits[0];
    double cp[WP_MAX_CP];
    for (size_t i = 0; i < n_cp; i++) cp[i] = orbits[i] * sc.period;

    printf("\n## Target 2: energy error over 1e5 orbits (Kepler e = 0.5), max |dE/E| so far\n");
    printf("%-17s %-9s %11s %11s %11s %9s %10s %8s  %s\n", "method", "dt", "1e3 orbits",
           "1e4 orbits", "1e5 orbits", "1e5/1e3", "rhs_evals", "cpu_s", "verdict");
    char path[1200];
    snprintf(path, sizeof path, "%s/wp_longrun.dat", dir);
    FILE *f = fopen(path, "w");
    if (f) fprintf(f, "# Kepler e = 0.5, 1e5 orbits: orbits, max |dE/E| up to then\n");
    int all_met = 1, blocks = 0;
    size_t pos = 0;
    summary[0] = '\0';
    for (size_t i = 0; i < sizeof longrun / sizeof longrun[0]; i++) {
        int avail;
        const struct mech_integrator *m = method_by_name(longrun[i].method, &avail);
        if (!m || !avail) {
            printf("%-17s (not available: not measured)\n", longrun[i].method);
            if (longrun[i].target) {
                all_met = 0;
                pos += (size_t)snprintf(summary + pos, pos < n_sum ? n_sum - pos : 0,
                                        "%s not measured (missing); ", longrun[i].method);
            }
            continue;
        }
        struct row r;
        memset(&r, 0, sizeof r);
        r.sc = &sc;
        snprintf(r.method, sizeof r.method, "%s", longrun[i].method);
        r.div = longrun[i].div;
        r.setting = sc.period / longrun[i].div;
        r.t_end = sc.t_end;
        run_row(&r, m, cp, n_cp);
        char dt[16];
        snprintf(dt, sizeof dt, "P/%.0f", r.div);
        if (r.st != MECH_OK) {
            printf("%-17s %-9s FAILED %s\n", r.method, dt, r.msg);
            if (longrun[i].target) all_met = 0;
            continue;
        }
        double d3 = r.cp_drift[9], d4 = r.cp_drift[12], d5 = r.cp_drift[15];
        double growth = d5 / d3;
        int bounded = growth <= 3.0;
        const char *verdict = bounded ? "bounded" : "GROWS";
        printf("%-17s %-9s %11.3e %11.3e %11.3e %9.2f %10ld %8.3f  %s%s\n", r.method, dt, d3, d4,
               d5, growth, r.stats.rhs_evaluations, r.cpu, verdict,
               longrun[i].target ? "" : " (not a target; for contrast)");
        if (longrun[i].target) {
            if (!bounded) all_met = 0;
            pos += (size_t)snprintf(summary + pos, pos < n_sum ? n_sum - pos : 0,
                                    "%s %.2e/%.2e/%.2e (x%.2f); ", r.method, d3, d4, d5, growth);
        }
        if (f) {
            if (blocks++) fprintf(f, "\n\n");
            int lt = 1;
            for (size_t k = 0; k < n_methods; k++)
                if (strcmp(methods[k].info.name, r.method) == 0) lt = (int)k + 1;
            fprintf(f, "%s orbits drift lt\n", r.method);
            for (size_t k = 0; k < n_cp; k++)
                fprintf(f, "%.6e %.6e %d\n", orbits[k], fmax(r.cp_drift[k], 1e-17), lt);
        }
        fflush(stdout);
    }
    if (f) fclose(f);
    return all_met;
}

/* Target 3, API side: the same /v1/trajectory request twice (cost: false). */
static int api_identical(char *note, size_t n_note)
{
    static const char body[] =
        "{\"particle\": {\"mass\": 1, \"position\": [0.5, 0, 0], \"velocity\": [0, "
        "1.7320508075688772, 0]}, \"forces\": [{\"type\": \"central_gravity\", \"gm\": 1}], "
        "\"t_end\": 62.831853071795862, \"samples\": 101, \"cost\": false}";
    struct api_response a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    struct api_request req = {"POST", "/v1/trajectory", "application/json", body, strlen(body),
                              10000000, mech_clock_seconds() + 60, NULL};
    api_handle(&req, &a);
    req.deadline = mech_clock_seconds() + 60;
    api_handle(&req, &b);
    int same = a.status == b.status && a.body_len == b.body_len &&
               memcmp(a.body, b.body, a.body_len) == 0;
    snprintf(note, n_note, "POST /v1/trajectory (Kepler e = 0.5, 10 orbits, default integrator) "
             "twice: status %d/%d, %zu/%zu bytes, %s", a.status, b.status, a.body_len, b.body_len,
             same ? "byte-identical" : "DIFFERENT");
    if (a.status != 200) printf("API answered %d: %.300s\n", a.status, a.body ? a.body : "");
    int ok = same && a.status == 200;
    api_response_free(&a);
    api_response_free(&b);
    return ok;
}

/* ---- main ---------------------------------------------------------------------- */

static void machine_line(void)
{
    struct utsname u;
    char model[256] = "unknown CPU";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f)) {
            char *c = strchr(line, ':');
            if (strncmp(line, "model name", 10) == 0 && c) {
                snprintf(model, sizeof model, "%s", c + 2);
                model[strcspn(model, "\n")] = '\0';
                break;
            }
        }
        fclose(f);
    }
    time_t now = time(NULL);
    struct tm tmv;
    char date[64];
    gmtime_r(&now, &tmv);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &tmv);
    if (uname(&u) != 0) memset(&u, 0, sizeof u);
    printf("# machine: %s, %ld cores online, %s %s %s; date %s\n", model,
           sysconf(_SC_NPROCESSORS_ONLN), u.sysname, u.release, u.machine, date);
}

static void bench_dir_of(char *buf, size_t n)
{
    const char *env = getenv("MECHD_BENCH_DIR");
    if (env && *env) {
        snprintf(buf, n, "%s", env);
        return;
    }
    snprintf(buf, n, "%s", __FILE__);
    char *slash = strrchr(buf, '/');
    if (slash) *slash = '\0';
    else snprintf(buf, n, "bench");
}

static const char *met(int ok) { return ok ? "MET" : "NOT MET"; }

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    const char *out = argc > 1 ? argv[1] : "build/bench-out";
    char bench_dir[1024];
    bench_dir_of(bench_dir, sizeof bench_dir);
    if (mkdir_p(out) != 0) {
        fprintf(stderr, "bench_workprecision: cannot create %s: %s\n", out, strerror(errno));
        return 1;
    }
    const double cap = cap_seconds();
    double wall0 = mech_clock_seconds();

    printf("# bench_workprecision: error versus cost of every libmech ODE method\n");
    machine_line();
    printf("# pos_err = |q - q_exact| / L at t_end (L = a, amplitude, h, x0); max|dE/E| over every "
           "accepted step;\n# cpu_s = thread CPU seconds per run (runs < 2 ms repeated, mean); "
           "sweeps stop after a run > %.2g s\n", cap);

    if (getenv("MECHD_BENCH_SCENES_ONLY")) { /* only the scene-set table */
        scene_set_section(bench_dir);
        return 0;
    }
    if (getenv("MECHD_BENCH_PRESETS_ONLY")) { /* only the presets tables */
        issue_presets_section();
        scene_set_section(bench_dir);
        return 0;
    }
    static struct scene scenes[5];
    scenes_make(scenes);
    methods_probe(&scenes[0]);
    printf("# methods:");
    for (size_t i = 0; i < n_methods; i++)
        printf(" %s%s", methods[i].info.name, methods[i].available ? "" : "(MISSING)");
    printf("\n");
    int missing = 0;
    for (size_t i = 0; i < n_methods; i++)
        if (!methods[i].available) {
            printf("# not available, not measured: %s (%s)\n", methods[i].info.name, methods[i].why);
            missing = 1;
        }

    for (size_t s = 0; s < 5; s++) sweep_scene(&scenes[s], cap);

    /* Oscillator: energy error growth over 1e5 periods at each method's
     * coarsest step (checkpoints 1e3, 1e4, 1e5 periods are 9, 12, 15). */
    printf("\n# oscillator, max |dE/E| so far at 1e3 / 1e4 / 1e5 periods (first setting of each "
           "method):\n");
    for (size_t i = 0; i < n_rows; i++) {
        const struct row *r = &rows[i];
        if (r->sc != &scenes[2] || r->st != MECH_OK || r->n_cp < 16 || r->preset) continue;
        if (i > 0 && rows[i - 1].sc == r->sc && strcmp(rows[i - 1].method, r->method) == 0)
            continue;
        char set[32];
        setting_text(r, set, sizeof set);
        printf("#   %-16s %-12s %.3e %.3e %.3e  growth x%.2f\n", r->method, set, r->cp_drift[9],
               r->cp_drift[12], r->cp_drift[15], r->cp_drift[15] / r->cp_drift[9]);
    }

    /* Falling object: the notes' first-order east deflection beside the exact one. */
    {
        const struct scene *f = &scenes[3];
        double lat = f->lat_deg * (MECH_PI / 180.0);
        double first = f->W * cos(lat) * sqrt(8.0 * f->h * f->h * f->h / f->g0) / 3.0;
        double ex[6];
        scene_exact(f, f->t_end, ex);
        printf("\n# falling: east deflection at t = sqrt(2h/g) = %.9f s: exact (Coriolis-only model) "
               "%.12e m, notes' first order (1/3) W cos(lat) sqrt(8h^3/g) = %.12e m "
               "(relative difference %.2e: the O(W^2) terms)\n",
               f->t_end, ex[0], first, fabs(ex[0] - first) / first);
    }

    /* SciPy baseline on Kepler e = 0.5. */
    printf("\n## Baseline: SciPy solve_ivp DOP853 (rtol = atol), Kepler e = 0.5\n");
    print_header();
    struct row *base = NULL, *tmp = NULL, *base100 = NULL;
    struct scene k100 = scenes[0];
    k100.name = "kepler-e0.5-100";
    k100.t_end = 100 * (2.0 * MECH_PI);
    size_t nb = scipy_run(bench_dir, &scenes[0], scenes[0].t_end, 1, "1e-6 1e-8 1e-10 1e-12", &tmp);
    for (size_t i = 0; i < nb; i++) print_row(tmp + i);
    if (scipy_run(bench_dir, &scenes[0], scenes[0].t_end, 3, "1e-13", &base) == 1) print_row(base);
    else base = NULL;
    if (scipy_run(bench_dir, &k100, k100.t_end, 1, "1e-13", &base100) == 1) print_row(base100);
    else base100 = NULL;

    /* Target 1. */
    printf("\n## Target 1: Kepler e = 0.5, 1000 orbits, |dE/E| <= 1e-13 with >= 20x less CPU than "
           "DOP853 at rtol = atol = 1e-13\n");
    const struct row *pick = NULL, *best_drift = NULL;
    for (size_t i = 0; i < n_rows; i++) {
        const struct row *r = &rows[i];
        if (r->sc != &scenes[0] || r->st != MECH_OK || r->preset ||
            strcmp(r->method, "scipy-DOP853") == 0)
            continue;
        if (!best_drift || r->drift < best_drift->drift) best_drift = r;
        if (r->drift <= 1e-13 && (!pick || r->cpu < pick->cpu)) pick = r;
    }
    int t1 = 0, t3_core = 0;
    char t1_text[600] = "", t3_text[600] = "";
    /* Re-time the pick (or, failing one, the lowest-drift run): three more
     * runs, min CPU; all four must be bit-identical (target 3). */
    const struct row *rep = pick ? pick : best_drift;
    double best_cpu = rep ? rep->cpu : NAN;
    if (rep) {
        struct row again[3];
        t3_core = 1;
        const struct mech_integrator *m = method_by_name(rep->method, NULL);
        for (int k = 0; k < 3; k++) {
            again[k] = *rep;
            run_row(&again[k], m, NULL, 0);
            if (!same_bits(&again[k], rep)) t3_core = 0;
            if (again[k].cpu < best_cpu) best_cpu = again[k].cpu;
        }
        char set[32];
        setting_text(rep, set, sizeof set);
        snprintf(t3_text, sizeof t3_text, "%s %s on Kepler e = 0.5 run 4 times: final state, drift, "
                 "steps and evaluations %s", rep->method, set,
                 t3_core ? "bit-identical" : "DIFFERENT");
    }
    if (!pick) {
        snprintf(t1_text, sizeof t1_text, "no mechd run reached |dE/E| <= 1e-13 (best: %s %.2e)",
                 best_drift ? best_drift->method : "none", best_drift ? best_drift->drift : NAN);
    } else {
        char set[32];
        setting_text(pick, set, sizeof set);
        if (base) {
            double ratio = base->cpu / best_cpu;
            t1 = ratio >= 20.0;
            snprintf(t1_text, sizeof t1_text,
                     "mechd %s %s: |dE/E| = %.2e, pos_err = %.2e, %ld rhs evals, %.4f s CPU (min of 4) "
                     "vs DOP853 rtol=1e-13: |dE/E| = %.2e, pos_err = %.2e, %ld rhs evals, %.3f s CPU "
                     "(min of 3): %.0fx less CPU",
                     pick->method, set, pick->drift, pick->pos_err, pick->stats.rhs_evaluations,
                     best_cpu, base->drift, base->pos_err, base->stats.rhs_evaluations, base->cpu,
                     ratio);
        } else {
            snprintf(t1_text, sizeof t1_text, "mechd %s %s: |dE/E| = %.2e in %.4f s CPU; the DOP853 "
                     "baseline did not run (scipy missing?), ratio not measured",
                     pick->method, set, pick->drift, best_cpu);
        }
    }
    printf("%s: %s\n", met(t1), t1_text);
    if (base100)
        printf("  (guide: the target expects DOP853 at 1e-13 only reaches about 4e-11 over 100 orbits; "
               "measured %.2e in %.3f s; and mechd 1000 orbits in about 50 ms: measured %.4f s)\n",
               base100->drift, base100->cpu, pick ? best_cpu : NAN);
    for (size_t i = 0; i < n_rows && base; i++) {
        const struct row *r = &rows[i];
        if (r->sc == &scenes[0] && r->st == MECH_OK && r->adaptive && r->setting == 1e-13 &&
            !r->preset &&
            strcmp(r->method, "scipy-DOP853") != 0)
            printf("  same rtol = 1e-13: %-8s |dE/E| = %.2e, pos_err = %.2e, %.4f s: %.1fx less CPU "
                   "than DOP853\n", r->method, r->drift, r->pos_err, r->cpu, base->cpu / r->cpu);
    }
    fflush(stdout);

    presets_section(scenes, 5);
    issue_presets_section();

    /* Target 2. */
    run_seconds = 60.0;
    char t2_text[1200];
    int t2 = longrun_target(&scenes[0], out, t2_text, sizeof t2_text);
    printf("%s: symplectic methods keep a bounded (non-secular) energy error over 1e5 orbits "
           "(max|dE/E| at 1e3/1e4/1e5 orbits, growth): %s\n", met(t2), t2_text);

    /* Target 3. */
    char api_note[400];
    int t3_api = api_identical(api_note, sizeof api_note);
    printf("\n## Target 3: bit-identical results\n  core: %s\n  api: %s\n%s: the same request gives "
           "bit-identical numbers on every run\n",
           rep ? t3_text : "(no run to repeat)", api_note, met(t3_core && t3_api));

    /* Files and the plot. */
    write_tsv(out);
    for (size_t s = 0; s < 5; s++) write_scene_data(out, &scenes[s]);
    char cmd[3000];
    snprintf(cmd, sizeof cmd,
             "gnuplot -e \"datadir='%s'; outfile='%s/workprecision.png'\" '%s/workprecision.gp'",
             out, out, bench_dir);
    int rc = system(cmd);
    printf("\n# data: %s/workprecision.tsv, %s/wp_*.dat; plot: %s/workprecision.png (%s)\n", out,
           out, out, rc == 0 ? "written" : "gnuplot FAILED or missing");

    printf("\n## Summary (%.0f s wall)\n", mech_clock_seconds() - wall0);
    printf("  target 1 (Kepler e=0.5, |dE/E|<=1e-13, >=20x less CPU than DOP853): %s\n", met(t1));
    printf("  target 2 (bounded energy error over 1e5 orbits, verlet/yoshida*/gauss*): %s\n", met(t2));
    printf("  target 3 (bit-identical numbers): %s\n", met(t3_core && t3_api));
    if (missing) {
        printf("  methods not available (not measured):");
        for (size_t i = 0; i < n_methods; i++)
            if (!methods[i].available) printf(" %s", methods[i].info.name);
        printf("\n");
    }
    return 0;
}
