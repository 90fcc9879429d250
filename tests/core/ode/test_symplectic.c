/* test_symplectic.c — every fixed-step method of the registry (euler,
 * symplectic_euler, rk4, verlet, yoshida4, yoshida6, gauss4, gauss6, boris)
 * against closed forms, through the public driver (mech/ode/ode.h):
 *
 *   - observed order of convergence from two step sizes (h, h/2) on three
 *     problems with exact solutions, checked against the declared order:
 *     the harmonic oscillator x'' = -x; Kepler e = 0.5 over 1.25 orbits
 *     (Kepler's equation solved by Newton in the test; not a whole number of
 *     orbits: symplectic Euler is conjugate to Verlet by a half kick, so
 *     over exactly one period its O(h) error cancels and it looks second
 *     order); a free particle seen
 *     from a rotating frame (Coriolis + centrifugal, velocity-dependent: the
 *     exact solution is the inertial straight line rotated into the frame);
 *   - energy behaviour over long runs: symplectic and symmetric methods keep
 *     |dE/E| bounded (max over the whole run within a small factor of the max
 *     over its first 10 %), euler and rk4 drift secularly (it grows with t);
 *     gauss4/gauss6 conserve the oscillator's quadratic energy to round-off
 *     over 1e4 periods;
 *   - boris: a pure gyration (e = 0, constant w) keeps |v| and the radius to
 *     round-off and turns by exactly 2 atan(w h/2) per step (closed form),
 *     and it runs only with a magnetic-like split (MECH_EINVAL otherwise);
 *   - cost per step (right-hand-side evaluations), history-free step(),
 *     samples that do not perturb the steps;
 *   - a right-hand side that fails (MECH_ENUMERIC, or a NaN) stops every
 *     method of the registry with a typed error and the time it got to;
 *     implicit stages that cannot converge fail with MECH_ENUMERIC naming
 *     integrator/dt; budgets (steps, deadline, cancel) stop runaway runs.
 *
 * Sized to run in a few seconds (well under a minute with ASan+UBSan): the
 * 1e5-orbit figures belong to bench/bench_workprecision.c.
 */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "ode/integrators/integrator.h"
#include "mech/base/constants.h"
#include "mech/ode/ode.h"
#include "testlib.h"

static const char *const FIXED[] = {"euler",    "symplectic_euler", "rk4",
                                    "verlet",   "yoshida4",         "yoshida6",
                                    "gauss4",   "gauss6",           "boris"};
enum { N_FIXED = sizeof FIXED / sizeof FIXED[0] };

/* ---------------------------------------------------------------- problems */

/* Harmonic oscillator x'' = -x, y = (x, v); x = cos t, v = -sin t. */
static enum mech_status ho_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)v, (void)p;
    a[0] = -q[0];
    return MECH_OK;
}
static enum mech_status ho_rhs(double t, const double *y, double *dydt, void *p)
{
    dydt[0] = y[1];
    return ho_accel(t, y, y + 1, dydt + 1, p);
}
static void ho_exact(double t, double *y)
{
    y[0] = cos(t);
    y[1] = -sin(t);
}
static double ho_energy(const double *y) { return 0.5 * (y[0] * y[0] + y[1] * y[1]); }

/* Kepler problem, mu = 1, in 3-D (z = 0) so that boris runs its
 * Lorentz-split path (e = -q/r^3, w = 0). */
static enum mech_status kep_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)v, (void)p;
    double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    double k = -1.0 / (r2 * sqrt(r2));
    for (int i = 0; i < 3; i++) a[i] = k * q[i];
    return MECH_OK;
}
static enum mech_status kep_rhs(double t, const double *y, double *dydt, void *p)
{
    for (int i = 0; i < 3; i++) dydt[i] = y[3 + i];
    return kep_accel(t, y, y + 3, dydt + 3, p);
}
static enum mech_status kep_lorentz(double t, const double *q, double *e, double *w, void *p)
{
    w[0] = w[1] = w[2] = 0.0;
    return kep_accel(t, q, NULL, e, p);
}
static double kep_energy(const double *y)
{
    double r = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
    return 0.5 * (y[3] * y[3] + y[4] * y[4] + y[5] * y[5]) - 1.0 / r;
}

/* Kepler orbit a = 1, e = KEP_E, started at pericentre at t = 0 (mean
 * motion n = 1, period 2 pi): E - e sin E = t (Kepler's equation, Newton from
 * E = M + e sin M), x = cos E - e, y = sqrt(1-e^2) sin E,
 * v = (-sin E, sqrt(1-e^2) cos E) / (1 - e cos E). */
static const double KEP_E = 0.5;
static void kep_exact(double t, double *y)
{
    const double e = KEP_E, M = fmod(t, 2.0 * MECH_PI);
    double E = M + e * sin(M);
    for (int it = 0; it < 50; it++) {
        double dE = (E - e * sin(E) - M) / (1.0 - e * cos(E));
        E -= dE;
        if (fabs(dE) <= 1e-16) break;
    }
    const double b = sqrt(1.0 - e * e), den = 1.0 - e * cos(E);
    y[0] = cos(E) - e;
    y[1] = b * sin(E);
    y[2] = 0.0;
    y[3] = -sin(E) / den;
    y[4] = b * cos(E) / den;
    y[5] = 0.0;
}

/* Free particle seen from a frame rotating with constant W (tilted axis):
 * a = -2 W x v - W x (W x q) = e(q) + v x w with e = -W x (W x q), w = 2 W.
 * Exact: inertial X(t) = X0 + V0 t; in the frame q(t) = R(-|W| t) X(t),
 * v(t) = R(-|W| t) (V0 - W x X(t)) (R(phi): rotation by phi about W/|W|). */
static const double ROT_W[3] = {0.0, 0.56464247339503535, 0.82533561490967829}; /* sin .6, cos .6 */
static const double ROT_X0[3] = {1.0, -0.5, 0.25};
static const double ROT_V0[3] = {0.3, 0.8, -0.2}; /* inertial velocity */
static void cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static enum mech_status rot_lorentz(double t, const double *q, double *e, double *w, void *p)
{
    (void)t, (void)p;
    double wq[3], wwq[3];
    cross(ROT_W, q, wq);
    cross(ROT_W, wq, wwq);
    for (int i = 0; i < 3; i++) {
        e[i] = -wwq[i];
        w[i] = 2.0 * ROT_W[i];
    }
    return MECH_OK;
}
static enum mech_status rot_accel(double t, const double *q, const double *v, double *a, void *p)
{
    double e[3], w[3], vw[3];
    rot_lorentz(t, q, e, w, p);
    cross(v, w, vw);
    for (int i = 0; i < 3; i++) a[i] = e[i] + vw[i];
    return MECH_OK;
}
static enum mech_status rot_rhs(double t, const double *y, double *dydt, void *p)
{
    for (int i = 0; i < 3; i++) dydt[i] = y[3 + i];
    return rot_accel(t, y, y + 3, dydt + 3, p);
}
/* Rodrigues: rotate x by phi about the unit axis n. */
static void rodrigues(const double *n, double phi, const double *x, double *out)
{
    double nx[3], c = cos(phi), s = sin(phi), nd = n[0] * x[0] + n[1] * x[1] + n[2] * x[2];
    cross(n, x, nx);
    for (int i = 0; i < 3; i++) out[i] = x[i] * c + nx[i] * s + n[i] * nd * (1.0 - c);
}
static void rot_exact(double t, double *y)
{
    /* |W| = 1 */
    double X[3], u[3], wX[3];
    for (int i = 0; i < 3; i++) X[i] = ROT_X0[i] + ROT_V0[i] * t;
    cross(ROT_W, X, wX);
    for (int i = 0; i < 3; i++) u[i] = ROT_V0[i] - wX[i];
    rodrigues(ROT_W, -t, X, y);
    rodrigues(ROT_W, -t, u, y + 3);
}

struct problem {
    const char *name;
    struct mech_ode_system sys;
    void (*exact)(double t, double *y);
    double (*energy)(const double *y); /* NULL: none tested */
    double t_end;                      /* order runs */
};

static struct problem problems[3];

static void problems_init(void)
{
    problems[0] = (struct problem){
        "oscillator", {2, ho_rhs, ho_accel, MECH_ODE_VELOCITY_FREE, NULL, NULL, 1, NULL},
        ho_exact, ho_energy, 10.0};
    problems[1] = (struct problem){
        "kepler e=0.5", {6, kep_rhs, kep_accel, MECH_ODE_VELOCITY_FREE, NULL, kep_lorentz, 3, NULL},
        kep_exact, kep_energy, 2.5 * MECH_PI};
    problems[2] = (struct problem){
        "rotating frame", {6, rot_rhs, rot_accel, 0, NULL, rot_lorentz, 3, NULL}, rot_exact, NULL, 5.0};
}

/* ---------------------------------------------------------------- runner */

struct watch {
    double (*energy)(const double *y);
    double e0, t_early;
    double max_early, max_all;
};

static enum mech_status watch_energy(double t, const double *y, void *p)
{
    struct watch *w = p;
    double d = fabs(w->energy(y) - w->e0) / fabs(w->e0);
    if (d > w->max_all) w->max_all = d;
    if (t <= w->t_early && d > w->max_early) w->max_early = d;
    return MECH_OK;
}

struct outcome {
    enum mech_status st;
    double err; /* max abs error of the final state against the closed form */
    double drift_early, drift_all, drift_final;
    struct mech_ode_stats stats;
    double y_end[6];
};

static struct outcome run(const char *method, const struct problem *pb, double dt, double t_end,
                          int watch)
{
    struct outcome o;
    memset(&o, 0, sizeof o);
    const size_t dim = pb->sys.dim;
    double y0[6], ys[12], yex[6];
    pb->exact(0.0, y0);
    struct mech_ode_problem p = {0};
    p.sys = &pb->sys;
    p.method = mech_ode_method_find(method);
    p.opt.dt = dt;
    p.t0 = 0.0;
    p.t_end = t_end;
    p.y0 = y0;
    p.n_samples = 2;
    p.sample_y = ys;
    struct watch w = {pb->energy, 0.0, 0.1 * t_end, 0.0, 0.0};
    if (watch && pb->energy) {
        w.e0 = pb->energy(y0);
        p.observe = watch_energy;
        p.observe_params = &w;
    }
    struct mech_budget b = mech_budget_make(100000000, 600.0);
    struct mech_ode_result r;
    struct mech_error e;
    mech_error_clear(&e);
    o.st = mech_ode_solve(&p, &b, &r, &e);
    if (o.st != MECH_OK) {
        fprintf(stderr, "%s on %s: %s: %s\n", method, pb->name, mech_status_name(o.st), e.text);
        o.err = INFINITY;
        return o;
    }
    o.stats = r.stats;
    pb->exact(t_end, yex);
    for (size_t i = 0; i < dim; i++) {
        o.y_end[i] = ys[dim + i];
        o.err = fmax(o.err, fabs(ys[dim + i] - yex[i]));
    }
    o.drift_early = w.max_early;
    o.drift_all = w.max_all;
    if (pb->energy) o.drift_final = fabs(pb->energy(ys + dim) / pb->energy(y0) - 1.0);
    return o;
}

/* --------------------------------------------------------- orders of accuracy */

/* Steps over t_end for the coarse run (the fine one takes twice as many),
 * per problem and method (FIXED order), chosen so both errors lie in the
 * asymptotic range, well above round-off. */
static const long ORDER_STEPS[3][N_FIXED] = {
    /* euler symp_eu rk4  verlet y4   y6   g4   g6   boris */
    {20000, 20000, 100, 500, 100, 50, 50, 25, 500},          /* oscillator, t = 10 */
    {200000, 40000, 1000, 2000, 1000, 400, 400, 200, 2000}, /* Kepler, 1.25 orbits */
    {10000, 10000, 100, 200, 100, 50, 50, 25, 200},          /* rotating frame, t = 5 */
};

static void test_orders(void)
{
    printf("\n%-16s %-15s %12s %12s %8s %8s\n", "method", "problem", "err(h)", "err(h/2)",
           "order", "rhs/step");
    for (int pi = 0; pi < 3; pi++) {
        const struct problem *pb = &problems[pi];
        for (int mi = 0; mi < N_FIXED; mi++) {
            const struct mech_integrator *m = mech_ode_method_find(FIXED[mi]);
            CHECK(m != NULL);
            if (!m) continue;
            const double n1 = (double)ORDER_STEPS[pi][mi];
            struct outcome a = run(m->name, pb, pb->t_end / n1, pb->t_end, 0);
            struct outcome b = run(m->name, pb, pb->t_end / (2.0 * n1), pb->t_end, 0);
            CHECK_EQ_INT(a.st, MECH_OK);
            CHECK_EQ_INT(b.st, MECH_OK);
            CHECK_EQ_INT(a.stats.steps, (long)n1);
            const double order = log2(a.err / b.err);
            const double per_step = (double)b.stats.rhs_evaluations / (double)b.stats.steps;
            printf("%-16s %-15s %12.3e %12.3e %8.3f %8.2f\n", m->name, pb->name, a.err, b.err,
                   order, per_step);
            if (!(fabs(order - m->order) <= 0.3))
                fprintf(stderr, "  %s on %s: observed order %.3f, declared %d\n", m->name,
                        pb->name, order, m->order);
            CHECK(fabs(order - m->order) <= 0.3);
            CHECK(b.err > 1e-13); /* measured above round-off */
        }
    }
}

/* ------------------------------------------------------------ cost per step */

static void test_cost(void)
{
    /* Right-hand-side (or force) evaluations per step on Kepler, h = P/400. */
    const struct problem *pb = &problems[1];
    printf("\ncost per step on Kepler e = 0.5, h = P/400:\n");
    for (int mi = 0; mi < N_FIXED; mi++) {
        struct outcome o = run(FIXED[mi], pb, 2.0 * MECH_PI / 400.0, 2.0 * MECH_PI, 0);
        CHECK_EQ_INT(o.st, MECH_OK);
        const double per = (double)o.stats.rhs_evaluations / (double)o.stats.steps;
        printf("  %-16s %6.2f evaluations/step\n", FIXED[mi], per);
        const char *n = FIXED[mi];
        /* explicit methods: exact counts (the Verlet-based ones reuse the
         * force at a stage's end for the next stage: one start-up
         * evaluation in all) */
        if (!strcmp(n, "euler") || !strcmp(n, "symplectic_euler") || !strcmp(n, "boris"))
            CHECK_EQ_INT(o.stats.rhs_evaluations, o.stats.steps);
        if (!strcmp(n, "rk4")) CHECK_EQ_INT(o.stats.rhs_evaluations, 4 * o.stats.steps);
        if (!strcmp(n, "verlet")) CHECK_EQ_INT(o.stats.rhs_evaluations, o.stats.steps + 1);
        if (!strcmp(n, "yoshida4")) CHECK_EQ_INT(o.stats.rhs_evaluations, 3 * o.stats.steps + 1);
        if (!strcmp(n, "yoshida6")) CHECK_EQ_INT(o.stats.rhs_evaluations, 7 * o.stats.steps + 1);
        /* Gauss: 1 + s * iterations, iterations in [2, 30] at this step */
        if (!strcmp(n, "gauss4")) CHECK(per >= 1 + 2 * 2 && per <= 1 + 2 * 30);
        if (!strcmp(n, "gauss6")) CHECK(per >= 1 + 3 * 2 && per <= 1 + 3 * 30);
    }
}

/* ---------------------------------------------------------- energy behaviour */

static void test_energy(void)
{
    printf("\nenergy error |dE/E|: max over the first 10%% / over the whole run\n");
    /* Kepler e = 0.5 over 1e4 orbits at h = P/200 (symplectic_euler: P/500,
     * it is first order; euler: 3 orbits at P/20000, it escapes otherwise).
     * Bounded: whole <= 2 x first 10 %
     * (+ a round-off allowance); secular: whole >= 4 x first 10 %. */
    const struct problem *kp = &problems[1];
    for (int mi = 0; mi < N_FIXED; mi++) {
        const struct mech_integrator *m = mech_ode_method_find(FIXED[mi]);
        const int is_euler = !strcmp(m->name, "euler");
        const double orbits = is_euler ? 3.0 : 1e4;
        const double steps_per_orbit = is_euler                                 ? 20000.0
                                       : !strcmp(m->name, "symplectic_euler") ? 500.0
                                                                              : 200.0;
        const double t_end = orbits * 2.0 * MECH_PI;
        struct outcome o = run(m->name, kp, 2.0 * MECH_PI / steps_per_orbit, t_end, 1);
        CHECK_EQ_INT(o.st, MECH_OK);
        printf("  kepler %6.0f orbits, %6.0f steps/orbit  %-16s %10.3e / %10.3e (ratio %.2f), "
               "final %.3e\n",
               orbits, steps_per_orbit, m->name, o.drift_early, o.drift_all,
               o.drift_all / o.drift_early, o.drift_final);
        if (m->flags & (MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_SYMMETRIC))
            CHECK(o.drift_all <= 2.0 * o.drift_early + 1e-13);
        else
            CHECK(o.drift_all >= 4.0 * o.drift_early);
    }
    /* Harmonic oscillator over 1e4 periods, 20.37 steps per period (not an
     * integer, so round-off does not repeat with the period) (euler:
     * 10 periods at 1000 steps/period, its energy grows by (1 + h^2) per
     * step). Gauss methods conserve this quadratic energy exactly: only
     * round-off remains. */
    const struct problem *hp = &problems[0];
    for (int mi = 0; mi < N_FIXED; mi++) {
        const struct mech_integrator *m = mech_ode_method_find(FIXED[mi]);
        const int is_euler = !strcmp(m->name, "euler");
        const double periods = is_euler ? 10.0 : 1e4;
        const double spp = is_euler ? 1000.0 : 20.37;
        struct outcome o = run(m->name, hp, 2.0 * MECH_PI / spp, periods * 2.0 * MECH_PI, 1);
        CHECK_EQ_INT(o.st, MECH_OK);
        printf("  oscillator %6.0f periods, %5.2f steps/period %-16s %10.3e / %10.3e\n", periods,
               spp, m->name, o.drift_early, o.drift_all);
        if (is_euler) {
            /* exact: E_n = E_0 (1 + h^2)^n */
            const double h = 2.0 * MECH_PI / spp, n = periods * spp;
            CHECK_CLOSE(o.drift_all, pow(1.0 + h * h, n) - 1.0, 1e-9, 0);
        } else if (!strcmp(m->name, "gauss4") || !strcmp(m->name, "gauss6")) {
            CHECK(o.drift_all < 1e-13);
        } else if (m->flags & (MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_SYMMETRIC)) {
            CHECK(o.drift_all <= 2.0 * o.drift_early + 1e-13);
        } else {
            CHECK(o.drift_all >= 4.0 * o.drift_early);
        }
    }
}

/* ------------------------------------------------------------------- boris */

static const double GYRO_W = 2.0;
static enum mech_status gyro_lorentz(double t, const double *q, double *e, double *w, void *p)
{
    (void)t, (void)q, (void)p;
    e[0] = e[1] = e[2] = 0.0;
    w[0] = w[1] = 0.0;
    w[2] = GYRO_W;
    return MECH_OK;
}
static enum mech_status gyro_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)q, (void)p;
    /* a = v x (0, 0, w) */
    a[0] = v[1] * GYRO_W;
    a[1] = -v[0] * GYRO_W;
    a[2] = 0.0;
    return MECH_OK;
}
static enum mech_status gyro_rhs(double t, const double *y, double *dydt, void *p)
{
    for (int i = 0; i < 3; i++) dydt[i] = y[3 + i];
    return gyro_accel(t, y, y + 3, dydt + 3, p);
}
struct speed_watch {
    double v0, max_dev;
};
static enum mech_status watch_speed(double t, const double *y, void *p)
{
    (void)t;
    struct speed_watch *s = p;
    double sp = sqrt(y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
    s->max_dev = fmax(s->max_dev, fabs(sp - s->v0) / s->v0);
    return MECH_OK;
}

static void test_boris(void)
{
    /* Pure gyration: dv/dt = v x w, w = (0, 0, 2), v0 = (1, 0.5, 0.3),
     * h = 0.1, 1000 steps. Boris turns v by theta = 2 atan(w h / 2) per step
     * (exact: w h) about -z, keeps |v|, and keeps the guiding centre
     * c = q - (-vy, vx, .)/w fixed (the discrete orbit q_n = c + i v_n / w in
     * complex notation has the exact radius |v_perp| / w). */
    struct mech_ode_system sys = {6, gyro_rhs, gyro_accel, 0, NULL, gyro_lorentz, 3, NULL};
    const double h = 0.1, n = 1000.0, t_end = h * n;
    double y0[6] = {0.2, -0.1, 0.05, 1.0, 0.5, 0.3}, ys[12];
    struct speed_watch sw = {sqrt(1.0 + 0.25 + 0.09), 0.0};
    struct mech_ode_problem p = {0};
    p.sys = &sys;
    p.method = mech_ode_method_find("boris");
    p.opt.dt = h;
    p.t_end = t_end;
    p.y0 = y0;
    p.n_samples = 2;
    p.sample_y = ys;
    p.observe = watch_speed;
    p.observe_params = &sw;
    struct mech_budget b = mech_budget_make(1000000, 600.0);
    struct mech_ode_result r;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_OK);
    CHECK_EQ_INT(r.stats.steps, 1000);
    CHECK_EQ_INT(r.stats.rhs_evaluations, 1000);
    const double theta = n * 2.0 * atan(GYRO_W * h / 2.0); /* total turn */
    const double c = cos(theta), s = sin(theta);
    /* rotation by -theta about z */
    const double vx = y0[3] * c + y0[4] * s, vy = -y0[3] * s + y0[4] * c;
    const double cx = y0[0] + y0[4] / GYRO_W, cy = y0[1] - y0[3] / GYRO_W;
    const double *yN = ys + 6;
    printf("\nboris gyration: |v| max rel dev %.2e; v error %.2e, %.2e; phase lag vs exact "
           "%.4f rad\n",
           sw.max_dev, yN[3] - vx, yN[4] - vy, GYRO_W * t_end - theta);
    CHECK(sw.max_dev < 1e-14);
    CHECK_CLOSE(yN[3], vx, 0, 1e-13);
    CHECK_CLOSE(yN[4], vy, 0, 1e-13);
    CHECK(yN[5] == y0[5]);
    CHECK_CLOSE(yN[0], cx - yN[4] / GYRO_W, 0, 1e-13);
    CHECK_CLOSE(yN[1], cy + yN[3] / GYRO_W, 0, 1e-13);
    CHECK_CLOSE(yN[2], y0[2] + y0[5] * t_end, 1e-13, 0); /* 2000 rounded additions */
    /* ... and the phase really is Boris's, not the exact w t (0.66 rad apart) */
    CHECK(fabs(yN[3] - (y0[3] * cos(GYRO_W * t_end) + y0[4] * sin(GYRO_W * t_end))) > 0.1);

    /* Rotating-frame free particle against the rotated straight line: the
     * order runs cover convergence; here one accurate run, t = 5, h = 1e-3. */
    struct outcome o = run("boris", &problems[2], 1e-3, 5.0, 0);
    CHECK_EQ_INT(o.st, MECH_OK);
    printf("boris rotating frame, h = 1e-3, t = 5: max state error %.3e\n", o.err);
    CHECK(o.err < 1e-5); /* second order: 2.9e-3 at h = 0.025 (order runs) x (1/25)^2 */

    /* No magnetic-like split and a velocity-dependent force (drag): refused. */
    struct mech_ode_system drag = {6, rot_rhs, rot_accel, 0, NULL, NULL, 3, NULL};
    struct mech_ode_problem q = p;
    double z0[6] = {1, 0, 0, 0, 1, 0};
    q.sys = &drag;
    q.y0 = z0;
    q.observe = NULL;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&q, &b, &r, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "integrator/method") == 0);
    CHECK(strstr(e.text, "magnetic-like") != NULL);
    /* a Lorentz split needs 3-vectors */
    struct mech_ode_system odd = {4, ho_rhs, ho_accel, 0, NULL, gyro_lorentz, 1, NULL};
    q.sys = &odd;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&q, &b, &r, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "integrator/method") == 0);
}

/* ------------------------------------------------- step() is history-free */

static void test_step_pure(void)
{
    /* The same step from the same state gives the same bits whatever came
     * before (the driver's sub-steps rely on it), and sampling does not
     * change the main step sequence. */
    const struct problem *pb = &problems[2]; /* velocity-dependent: implicit kicks too */
    struct mech_ode_options opt = {0, 0, 0.01};
    for (int pi = 1; pi <= 2; pi++) {
        pb = &problems[pi];
        for (int mi = 0; mi < N_FIXED; mi++) {
            const struct mech_integrator *m = mech_ode_method_find(FIXED[mi]);
            void *ws = NULL;
            CHECK_EQ_INT(m->alloc(&ws, 6, &opt, NULL), MECH_OK);
            m->reset(ws);
            double y0[6], a[6], b[6], other[6];
            pb->exact(0.3, y0);
            pb->exact(1.7, other);
            struct mech_ode_stats st = {0, 0, 0};
            memcpy(a, y0, sizeof a);
            CHECK_EQ_INT(m->step(ws, &pb->sys, 0.3, 0.05, a, &st, NULL), MECH_OK);
            for (int k = 0; k < 3; k++)
                CHECK_EQ_INT(m->step(ws, &pb->sys, 1.7, 0.031 * (k + 1), other, &st, NULL),
                             MECH_OK);
            memcpy(b, y0, sizeof b);
            CHECK_EQ_INT(m->step(ws, &pb->sys, 0.3, 0.05, b, &st, NULL), MECH_OK);
            CHECK(memcmp(a, b, sizeof a) == 0);
            /* a step forward then back returns close to the start; exactly
             * symmetric methods to round-off plus the solver tolerance */
            if (m->flags & MECH_INTEGRATOR_SYMMETRIC) {
                CHECK_EQ_INT(m->step(ws, &pb->sys, 0.35, -0.05, b, &st, NULL), MECH_OK);
                double dev = 0.0;
                for (int i = 0; i < 6; i++) dev = fmax(dev, fabs(b[i] - y0[i]));
                if (!(dev < 1e-14)) fprintf(stderr, "  %s not reversible: %.3e\n", m->name, dev);
                CHECK(dev < 1e-14);
            }
            m->free(ws);
        }
    }
    /* Driver level: 2 samples or 1001, same final bits, same step count. */
    static double many[1001 * 6];
    for (int mi = 0; mi < N_FIXED; mi++) {
        double y0[6], two[12];
        pb = &problems[1];
        pb->exact(0.0, y0);
        struct mech_ode_problem p = {0};
        p.sys = &pb->sys;
        p.method = mech_ode_method_find(FIXED[mi]);
        p.opt.dt = 2.0 * MECH_PI / 300.0;
        p.t_end = 2.0 * MECH_PI * 1.37;
        p.y0 = y0;
        struct mech_budget bud = mech_budget_make(1000000, 600.0);
        struct mech_ode_result r1, r2;
        p.n_samples = 2;
        p.sample_y = two;
        CHECK_EQ_INT(mech_ode_solve(&p, &bud, &r1, NULL), MECH_OK);
        p.n_samples = 1001;
        p.sample_y = many;
        CHECK_EQ_INT(mech_ode_solve(&p, &bud, &r2, NULL), MECH_OK);
        CHECK_EQ_INT(r1.stats.steps, r2.stats.steps);
        CHECK(memcmp(two + 6, many + 1000 * 6, 6 * sizeof *two) == 0);
    }
}

/* ------------------------------------------------------------ failures */

struct fail_params {
    int nan; /* 0: return MECH_ENUMERIC, 1: produce a NaN */
};
static enum mech_status fail_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)v;
    const struct fail_params *f = p;
    for (int i = 0; i < 3; i++) a[i] = -q[i];
    if (t >= 0.5) {
        if (!f->nan) return MECH_ENUMERIC;
        a[1] = NAN;
    }
    return MECH_OK;
}
static enum mech_status fail_rhs(double t, const double *y, double *dydt, void *p)
{
    for (int i = 0; i < 3; i++) dydt[i] = y[3 + i];
    return fail_accel(t, y, y + 3, dydt + 3, p);
}
static enum mech_status fail_lorentz(double t, const double *q, double *e, double *w, void *p)
{
    w[0] = w[1] = w[2] = 0.0;
    return fail_accel(t, q, NULL, e, p);
}

/* y' = -lambda y, lambda = 1e4: explicit fixed-point stages diverge at h = 0.01 */
static enum mech_status stiff_rhs(double t, const double *y, double *dydt, void *p)
{
    (void)t, (void)p;
    dydt[0] = -1e4 * y[0];
    dydt[1] = 0.0;
    return MECH_OK;
}
/* strong drag a = -b v, b = 1e3: the implicit half kick diverges at h = 0.01 */
static enum mech_status drag_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)q, (void)p;
    a[0] = -1e3 * v[0];
    return MECH_OK;
}
static enum mech_status drag_rhs(double t, const double *y, double *dydt, void *p)
{
    dydt[0] = y[1];
    return drag_accel(t, y, y + 1, dydt + 1, p);
}

static void test_failures(void)
{
    /* every registered method, both failure kinds */
    for (int kind = 0; kind < 2; kind++) {
        struct fail_params fp = {kind};
        /* wisdom_holman needs a Kepler split: the failing force as the
         * perturbation of a central mass gm = 1 */
        const struct mech_ode_kepler_split ks = {1.0, {0, 0, 0}, fail_accel, 0};
        struct mech_ode_system sys = {6, fail_rhs, fail_accel, MECH_ODE_VELOCITY_FREE, &fp,
                                      fail_lorentz, 3, &ks};
        for (size_t i = 0; i < mech_ode_method_count(); i++) {
            const struct mech_integrator *m = mech_ode_method_at(i);
            double y0[6] = {1, 0, 0, 0, 1, 0}, ys[6 * 5];
            struct mech_ode_problem p = {0};
            p.sys = &sys;
            p.method = m;
            p.opt.dt = 0.01;
            p.opt.rtol = 1e-8;
            p.opt.atol = 1e-10;
            p.t_end = 1.0;
            p.y0 = y0;
            p.n_samples = 5;
            p.sample_y = ys;
            struct mech_budget b = mech_budget_make(1000000, 600.0);
            struct mech_ode_result r;
            struct mech_error e;
            mech_error_clear(&e);
            enum mech_status st = mech_ode_solve(&p, &b, &r, &e);
            if (st != MECH_ENUMERIC)
                fprintf(stderr, "  %s (%s): %s: %s\n", m->name, kind ? "NaN" : "status",
                        mech_status_name(st), e.text);
            CHECK_EQ_INT(st, MECH_ENUMERIC);
            CHECK_EQ_INT(e.code, MECH_ENUMERIC);
            CHECK(strlen(e.text) > 10);
            CHECK(e.progress.t_reached <= 0.5 + 1e-12);
            CHECK(r.n_samples >= 1 && r.n_samples <= 3);
            for (size_t k = 0; k < r.n_samples * 6; k++) CHECK(isfinite(ys[k]));
        }
    }

    /* Implicit stages that cannot converge: typed, naming integrator/dt. */
    struct mech_ode_system stiff = {2, stiff_rhs, NULL, 0, NULL, NULL, 0, NULL};
    struct mech_ode_system drag = {2, drag_rhs, drag_accel, 0, NULL, NULL, 1, NULL};
    const char *implicit[] = {"gauss4", "gauss6", "verlet", "yoshida4", "yoshida6"};
    for (int k = 0; k < 5; k++) {
        double y0[2] = {1.0, 1.0};
        struct mech_ode_problem p = {0};
        p.sys = k < 2 ? &stiff : &drag;
        p.method = mech_ode_method_find(implicit[k]);
        p.opt.dt = 0.01;
        p.t_end = 1.0;
        p.y0 = y0;
        p.n_samples = 2;
        struct mech_budget b = mech_budget_make(1000000, 600.0);
        struct mech_ode_result r;
        struct mech_error e;
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_ENUMERIC);
        CHECK(strcmp(e.param, "integrator/dt") == 0);
        CHECK(strstr(e.text, "converge") != NULL);
        printf("%s, stiff: %s\n", implicit[k], e.text);
        /* the same at a resolving step succeeds */
        p.opt.dt = k < 2 ? 1e-5 : 1e-4;
        p.t_end = 0.01;
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_OK);
    }
}

static void test_budgets(void)
{
    /* Runaway requests stop: too many steps (refused up front, saying how
     * far the budget reaches), a deadline, a cancel flag, for every
     * fixed-step method. */
    const struct problem *pb = &problems[1];
    for (int mi = 0; mi < N_FIXED; mi++) {
        double y0[6];
        pb->exact(0.0, y0);
        struct mech_ode_problem p = {0};
        p.sys = &pb->sys;
        p.method = mech_ode_method_find(FIXED[mi]);
        p.opt.dt = 1e-3;
        p.t_end = 1e6;
        p.y0 = y0;
        p.n_samples = 2;
        struct mech_ode_result r;
        struct mech_error e;
        struct mech_budget small = mech_budget_make(1000, 600.0);
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &small, &r, &e), MECH_EBUDGET);
        CHECK(strcmp(e.param, "integrator/dt") == 0);
        CHECK_CLOSE(e.progress.t_reached, 1.0, 1e-12, 0);
        /* a deadline already passed */
        struct mech_budget late = mech_budget_make(2000000000L, -1.0);
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &late, &r, &e), MECH_EDEADLINE);
        /* cancelled */
        volatile int cancel = 1;
        struct mech_budget cb = mech_budget_make(2000000000L, 600.0);
        cb.cancel = &cancel;
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &cb, &r, &e), MECH_ECANCELLED);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    problems_init();
    test_orders();
    test_cost();
    test_energy();
    test_boris();
    test_step_pure();
    test_failures();
    test_budgets();
    TEST_MAIN_END();
}
