/* test_integrators.c — the stepper interface, the registry and the ODE
 * driver (mech/ode/ode.h), on problems with closed forms:
 *   harmonic oscillator x'' = -x (x = cos t), with the observed convergence
 *   order of rk4 (4) and verlet (2) from two step sizes (every fixed-step
 *   method's order on two problems is in test_symplectic.c);
 *   the registry (14 methods, each with doc and reference);
 *   free fall stop time sqrt(2h/g) located to 1e-10 relative by every method
 *   of order >= 2 that is exact on a parabola (msbdf: 1e-9 at rtol 1e-10),
 *   the Euler methods' dt/2 offset;
 *   samples that do not perturb the main step sequence; budget and failure
 *   statuses with progress; right-hand-side failures through GSL.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "ode/integrators/integrator.h"
#include "mech/base/constants.h"
#include "mech/ode/ode.h"
#include "testlib.h"

/* ---- harmonic oscillator, y = (x, v), x'' = -w^2 x ---- */
static enum mech_status ho_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t;
    (void)v;
    double w = *(const double *)p;
    a[0] = -w * w * q[0];
    return MECH_OK;
}
static enum mech_status ho_rhs(double t, const double *y, double *dydt, void *p)
{
    dydt[0] = y[1];
    return ho_accel(t, y, y + 1, dydt + 1, p);
}

/* ---- free fall, y = (z, vz), z'' = -g ---- */
static const double G0 = 9.80665;
static enum mech_status ff_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)q, (void)v, (void)p;
    a[0] = -G0;
    return MECH_OK;
}
static enum mech_status ff_rhs(double t, const double *y, double *dydt, void *p)
{
    dydt[0] = y[1];
    return ff_accel(t, y, y + 1, dydt + 1, p);
}
static double ff_event(double t, const double *y, void *p)
{
    (void)t, (void)p;
    return y[0];
}

/* ---- a right-hand side that fails at t >= 0.5 ---- */
static enum mech_status bad_rhs(double t, const double *y, double *dydt, void *p)
{
    (void)p;
    dydt[0] = y[1];
    dydt[1] = -y[0];
    return t >= 0.5 ? MECH_ENUMERIC : MECH_OK;
}

static struct mech_budget big_budget(void) { return mech_budget_make(10000000, 600.0); }

/* Integrate the oscillator to t_end with method m; return x(t_end) error. */
static double ho_error(const char *name, double dt, double rtol, double t_end,
                       struct mech_ode_stats *stats_out)
{
    double w = 1.0;
    struct mech_ode_system sys = {2, ho_rhs, ho_accel, MECH_ODE_VELOCITY_FREE, &w, NULL, 1, NULL};
    double y0[2] = {1.0, 0.0};
    double ys[2 * 11];
    struct mech_ode_problem p = {0};
    p.sys = &sys;
    p.method = mech_ode_method_find(name);
    p.opt.dt = dt;
    p.opt.rtol = rtol;
    p.opt.atol = rtol * 1e-2;
    p.t0 = 0.0;
    p.t_end = t_end;
    p.y0 = y0;
    p.n_samples = 11;
    p.sample_y = ys;
    struct mech_budget b = big_budget();
    struct mech_ode_result r;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_ode_solve(&p, &b, &r, &e);
    CHECK_EQ_INT(st, MECH_OK);
    CHECK_EQ_INT(r.n_samples, 11);
    if (stats_out) *stats_out = r.stats;
    /* every sample against the closed form */
    double worst = 0.0;
    for (int i = 0; i < 11; i++) {
        double t = t_end * i / 10.0;
        worst = fmax(worst, fabs(ys[2 * i] - cos(t)));
        worst = fmax(worst, fabs(ys[2 * i + 1] + sin(t)));
    }
    return worst;
}

static void test_registry(void)
{
    /* 5 adaptive + 9 fixed-step methods, in catalog order, then
     * wisdom_holman and wisdom_holman_corrected */
    static const char *const names[] = {"rk8pd",  "rkck",     "rkf45",   "radau15",
                                        "msbdf",  "euler",    "symplectic_euler",
                                        "rk4",    "verlet",   "yoshida4", "yoshida6",
                                        "gauss4", "gauss6",   "boris",   "wisdom_holman",
                                        "wisdom_holman_corrected"};
    static const int orders[] = {8, 5, 5, -1, -1, 1, 1, 4, 2, 4, 6, 4, 6, 2, 2, 2};
    CHECK_EQ_INT(mech_ode_method_count(), 16);
    for (size_t i = 0; i < mech_ode_method_count(); i++) {
        const struct mech_integrator *m = mech_ode_method_at(i);
        CHECK(m != NULL && m->name && m->doc && strlen(m->doc) > 40);
        if (!m) continue;
        CHECK(strcmp(m->name, names[i]) == 0);
        if (orders[i] > 0) CHECK_EQ_INT(m->order, orders[i]);
        CHECK(mech_ode_method_find(m->name) == m);
        CHECK(m->order >= 1);
        CHECK(m->reference != NULL && strlen(m->reference) > 20);
        /* the citation lives in .reference, not in .doc */
        CHECK(strstr(m->doc, "Reference") == NULL);
        CHECK(m->alloc && m->reset && m->free && m->step);
        CHECK(!!(m->flags & MECH_INTEGRATOR_ADAPTIVE) == (m->evolve != NULL));
        CHECK(!!(m->flags & MECH_INTEGRATOR_ADAPTIVE) != !!(m->flags & MECH_INTEGRATOR_FIXED_STEP));
        for (size_t j = 0; j < i; j++) CHECK(strcmp(mech_ode_method_at(j)->name, m->name) != 0);
    }
    CHECK(mech_ode_method_at(99) == NULL);
    CHECK(mech_ode_method_find("leapfrog") == NULL);
    CHECK(mech_ode_method_find(NULL) == NULL);
    struct mech_ode_method_info info = mech_ode_method_describe(mech_ode_method_find("verlet"));
    CHECK(info.symplectic == 1 && info.adaptive == 0 && info.order == 2);
    CHECK(strlen(info.reference) > 20);
    info = mech_ode_method_describe(mech_ode_method_find("gauss6"));
    CHECK(info.implicit == 1 && info.symplectic == 1 && info.symmetric == 1 && info.order == 6);
    CHECK(info.second_order == 0);
    info = mech_ode_method_describe(mech_ode_method_find("boris"));
    CHECK(info.implicit == 0 && info.symmetric == 1 && info.second_order == 1);
    info = mech_ode_method_describe(mech_ode_method_find("euler"));
    CHECK(info.implicit == 0 && info.symplectic == 0 && info.order == 1);
    info = mech_ode_method_describe(mech_ode_method_find("symplectic_euler"));
    CHECK(info.implicit == 0 && info.symplectic == 1 && info.symmetric == 0 && info.order == 1);
}

static void test_oscillator(void)
{
    const double t_end = 10.0;
    /* adaptive methods at a tight tolerance agree with cos t */
    CHECK(ho_error("rk8pd", 0, 1e-12, t_end, NULL) < 1e-10);
    CHECK(ho_error("rkck", 0, 1e-11, t_end, NULL) < 1e-8);
    CHECK(ho_error("rkf45", 0, 1e-11, t_end, NULL) < 1e-8);
    /* fixed-step: observed order from dt and dt/2 */
    double e1 = ho_error("rk4", 0.02, 0, t_end, NULL);
    double e2 = ho_error("rk4", 0.01, 0, t_end, NULL);
    double order_rk4 = log2(e1 / e2);
    printf("rk4: err(0.02) = %.3e, err(0.01) = %.3e, observed order %.3f\n", e1, e2, order_rk4);
    CHECK(e2 < 1e-8);
    CHECK_CLOSE(order_rk4, 4.0, 0.03, 0);
    double v1 = ho_error("verlet", 0.02, 0, t_end, NULL);
    double v2 = ho_error("verlet", 0.01, 0, t_end, NULL);
    double order_v = log2(v1 / v2);
    printf("verlet: err(0.02) = %.3e, err(0.01) = %.3e, observed order %.3f\n", v1, v2,
           order_v);
    CHECK(v2 < 1e-4);
    CHECK_CLOSE(order_v, 2.0, 0.02, 0);
    /* step counts: fixed-step runs take exactly t_end/dt steps (10/0.01 = 1000,
     * no extra sliver step from round-off) */
    struct mech_ode_stats s;
    ho_error("rk4", 0.01, 0, t_end, &s);
    CHECK_EQ_INT(s.steps, 1000);
    ho_error("verlet", 0.01, 0, t_end, &s);
    CHECK_EQ_INT(s.steps, 1000);
}

/* Sampling must not change the main step sequence: same final state and
 * step count with 2 and with 1001 samples. */
static void test_samples_do_not_perturb(void)
{
    double w = 1.0;
    struct mech_ode_system sys = {2, ho_rhs, ho_accel, MECH_ODE_VELOCITY_FREE, &w, NULL, 1, NULL};
    double y0[2] = {1.0, 0.0};
    static double ys_many[2 * 1001];
    double ys_two[4];
    const char *names[] = {"rk8pd", "rk4", "verlet"};
    for (int k = 0; k < 3; k++) {
        struct mech_ode_problem p = {0};
        p.sys = &sys;
        p.method = mech_ode_method_find(names[k]);
        p.opt.rtol = 1e-10;
        p.opt.atol = 1e-12;
        p.opt.dt = 0.013;
        p.t_end = 7.0;
        p.y0 = y0;
        struct mech_budget b = big_budget();
        struct mech_ode_result r1, r2;
        p.n_samples = 2;
        p.sample_y = ys_two;
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r1, NULL), MECH_OK);
        p.n_samples = 1001;
        p.sample_y = ys_many;
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r2, NULL), MECH_OK);
        CHECK_EQ_INT(r1.stats.steps, r2.stats.steps);
        CHECK(ys_two[2] == ys_many[2000] && ys_two[3] == ys_many[2001]);
        CHECK(r2.stats.rhs_evaluations > r1.stats.rhs_evaluations);
        /* an interior sample, from a sub-step, still matches the closed form */
        double tol = k == 2 ? 1e-3 : 1e-8;
        CHECK_CLOSE(ys_many[2 * 500], cos(3.5), 0, tol);
    }
}

/* Free fall from h: the event z = 0 (decreasing) at t = sqrt(2h/g), v = -g t,
 * for every method (all are exact on a quadratic up to round-off, so the
 * location error is the root-finder's). */
static void test_free_fall_event(void)
{
    const double h = 100.0, t_exact = sqrt(2.0 * h / G0);
    struct mech_ode_system sys = {2, ff_rhs, ff_accel, MECH_ODE_VELOCITY_FREE, NULL, NULL, 1, NULL};
    for (size_t i = 0; i < mech_ode_method_count(); i++) {
        const struct mech_integrator *m = mech_ode_method_at(i);
        double y0[2] = {h, 0.0}, ystop[2], ts[101];
        struct mech_ode_problem p = {0};
        p.sys = &sys;
        p.method = m;
        p.opt.rtol = 1e-10;
        p.opt.atol = 1e-12;
        p.opt.dt = 0.0123;
        p.t_end = 10.0;
        p.y0 = y0;
        p.n_samples = 101;
        p.sample_t = ts;
        p.event = ff_event;
        p.event_direction = MECH_ODE_DECREASING;
        p.y_stop = ystop;
        struct mech_budget b = big_budget();
        struct mech_ode_result r;
        struct mech_error e;
        mech_error_clear(&e);
        if (m->flags & MECH_INTEGRATOR_KEPLER_SPLIT) {
            /* no central mass here: refused up front, naming the method */
            CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_EINVAL);
            CHECK(strcmp(e.param, "integrator/method") == 0 && strstr(e.text, m->name));
            continue;
        }
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_OK);
        CHECK(r.stopped == 1);
        printf("%s: stop t = %.17g (exact %.17g, rel err %.2e)\n", m->name, r.t_stop, t_exact,
               fabs(r.t_stop - t_exact) / t_exact);
        if (strcmp(m->name, "msbdf") == 0) {
            /* variable-order BDF under error control (rtol 1e-10): not exact
             * on a parabola (low-order start-up), within ~10 rtol */
            CHECK_CLOSE(r.t_stop, t_exact, 1e-9, 0);
            CHECK_CLOSE(ystop[1], -G0 * t_exact, 1e-9, 0);
            CHECK_CLOSE(ystop[0], 0.0, 0, 1e-8);
        } else if (m->order >= 2) {
            /* exact on a parabola: only the root-finder's error is left */
            CHECK_CLOSE(r.t_stop, t_exact, 1e-10, 0);
            CHECK_CLOSE(ystop[1], -G0 * t_exact, 1e-10, 0);
            CHECK_CLOSE(ystop[0], 0.0, 0, 1e-9);
        } else {
            /* euler: z_n = h - g h^2 n(n-1)/2 (falls late, by dt/2); symplectic
             * Euler: z_n = h - g h^2 n(n+1)/2 (early by dt/2): t_stop is off by
             * about dt/2 = 0.006 s, relative 1.4e-3 */
            CHECK_CLOSE(r.t_stop, t_exact, 2e-3, 0);
            CHECK_CLOSE(ystop[0], 0.0, 0, 1e-9);
            const double shift = strcmp(m->name, "euler") == 0 ? 0.5 : -0.5;
            CHECK_CLOSE(r.t_stop, t_exact + shift * p.opt.dt, 1e-4, 0);
        }
        /* samples every 0.1 s up to t_stop (4.515...): t = 0, 0.1, ..., 4.5 */
        CHECK_EQ_INT(r.n_samples, 46);
        CHECK(ts[r.n_samples - 1] <= r.t_stop);
    }
    /* increasing direction does not fire on a fall; "either" does */
    double y0[2] = {h, 0.0}, ystop[2];
    struct mech_ode_problem p = {0};
    p.sys = &sys;
    p.method = mech_ode_method_find("rk8pd");
    p.opt.rtol = 1e-10;
    p.t_end = 10.0;
    p.y0 = y0;
    p.n_samples = 3;
    p.event = ff_event;
    p.event_direction = MECH_ODE_INCREASING;
    p.y_stop = ystop;
    struct mech_budget b = big_budget();
    struct mech_ode_result r;
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_OK);
    CHECK(r.stopped == 0 && r.n_samples == 3 && isnan(r.t_stop));
    p.event_direction = MECH_ODE_EITHER;
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_OK);
    CHECK(r.stopped == 1);
    CHECK_CLOSE(r.t_stop, t_exact, 1e-12, 0);
    /* extremes: a drop from 1e-300 m (root at ~4.5e-151 s, found by Brent's
     * bisection fallback through ~500 halvings) and from a subnormal 1e-320 m */
    const double tiny[] = {1e-300, 1e-320};
    for (int k = 0; k < 2; k++) {
        double yt[2] = {tiny[k], 0.0};
        p.y0 = yt;
        p.event_direction = MECH_ODE_DECREASING;
        struct mech_error e;
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_OK);
        CHECK(r.stopped == 1 && isfinite(r.t_stop) && isfinite(ystop[0]) && isfinite(ystop[1]));
        if (k == 0) CHECK_CLOSE(r.t_stop, sqrt(2.0 * tiny[k] / G0), 1e-10, 0);
        else CHECK(r.t_stop > 0.0 && r.t_stop < 1e-150);
    }
    /* a projectile launched from the surface stops when it comes back down
     * (t = 2 v0 / g), not at its start */
    double y1[2] = {0.0, 20.0};
    p.y0 = y1;
    p.event_direction = MECH_ODE_DECREASING;
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_OK);
    CHECK(r.stopped == 1);
    CHECK_CLOSE(r.t_stop, 2.0 * 20.0 / G0, 1e-12, 0);
}

static void test_budget_and_failures(void)
{
    double w = 1.0;
    struct mech_ode_system sys = {2, ho_rhs, ho_accel, MECH_ODE_VELOCITY_FREE, &w, NULL, 1, NULL};
    double y0[2] = {1.0, 0.0}, ys[2 * 5];
    struct mech_ode_problem p = {0};
    p.sys = &sys;
    p.y0 = y0;
    p.t_end = 100.0;
    p.n_samples = 5;
    p.sample_y = ys;
    struct mech_ode_result r;
    struct mech_error e;

    /* adaptive: runs out of steps mid-way, progress says where */
    p.method = mech_ode_method_find("rk8pd");
    p.opt.rtol = 1e-12;
    p.opt.atol = 1e-14;
    struct mech_budget small = mech_budget_make(50, 600.0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &small, &r, &e), MECH_EBUDGET);
    CHECK_EQ_INT(e.code, MECH_EBUDGET);
    CHECK_EQ_INT(e.progress.steps, 51);
    CHECK(e.progress.t_reached > 0.0 && e.progress.t_reached < 100.0);
    CHECK(e.progress.t_target == 100.0);
    CHECK(r.n_samples >= 1 && r.n_samples < 5);
    CHECK(r.stats.steps == 50);

    /* fixed-step: refused up front, naming how far the budget would go */
    p.method = mech_ode_method_find("rk4");
    p.opt.dt = 0.01; /* 10000 steps > 50 */
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &small, &r, &e), MECH_EBUDGET);
    CHECK(strcmp(e.param, "integrator/dt") == 0);
    CHECK_CLOSE(e.progress.t_reached, 0.5, 1e-12, 0);
    CHECK(e.progress.t_target == 100.0);
    CHECK_EQ_INT(e.progress.steps, 0);

    /* deadline already passed */
    struct mech_budget late = mech_budget_make(1000000, -1.0);
    mech_error_clear(&e);
    p.opt.dt = 0.1;
    CHECK_EQ_INT(mech_ode_solve(&p, &late, &r, &e), MECH_EDEADLINE);
    /* cancel flag */
    volatile int cancel = 1;
    struct mech_budget cb = big_budget();
    cb.cancel = &cancel;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &cb, &r, &e), MECH_ECANCELLED);

    /* invalid options name the field */
    struct mech_budget b = big_budget();
    p.opt.dt = -1.0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "integrator/dt") == 0);
    p.method = mech_ode_method_find("rkf45");
    p.opt.rtol = 0.0;
    p.opt.atol = 0.0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "integrator/rtol") == 0);
    CHECK_EQ_INT(mech_ode_solve(&p, NULL, &r, NULL), MECH_EINVAL);
    p.n_samples = 1;
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_EINVAL);

    /* verlet needs the second-order form */
    struct mech_ode_system first_order = {2, ho_rhs, NULL, 0, &w, NULL, 0, NULL};
    p.sys = &first_order;
    p.n_samples = 5;
    p.method = mech_ode_method_find("verlet");
    p.opt.dt = 0.1;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_EINVAL);
    CHECK(strcmp(e.param, "integrator/method") == 0);

    /* a failing right-hand side stops every method with its status, through
     * GSL's GSL_EBADFUNC for the adaptive ones; the same workspace-free
     * driver then runs again cleanly */
    struct mech_ode_system bad = {2, bad_rhs, NULL, 0, NULL, NULL, 0, NULL};
    p.sys = &bad;
    p.t_end = 1.0;
    p.opt.rtol = 1e-8;
    p.opt.atol = 1e-10;
    p.opt.dt = 0.01;
    const char *names[] = {"rk8pd", "rkck", "rkf45", "rk4"};
    for (int k = 0; k < 4; k++) {
        p.method = mech_ode_method_find(names[k]);
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, &e), MECH_ENUMERIC);
        CHECK(e.progress.t_reached <= 0.5 + 1e-12);
        CHECK(r.n_samples >= 1 && r.n_samples <= 3);
    }
    p.sys = &sys;
    p.method = mech_ode_method_find("rk8pd");
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_OK);
}

/* Extremes: tiny and huge time scales answer accurately (x'' = -w^2 x with
 * w = 1e6 and 1e-6 over one period). */
static void test_scales(void)
{
    const double ws[] = {1e6, 1e-6};
    for (int k = 0; k < 2; k++) {
        double w = ws[k];
        struct mech_ode_system sys = {2, ho_rhs, ho_accel, MECH_ODE_VELOCITY_FREE, &w, NULL, 1, NULL};
        double y0[2] = {1.0, 0.0}, ys[2 * 2];
        struct mech_ode_problem p = {0};
        p.sys = &sys;
        p.method = mech_ode_method_find("rk8pd");
        p.opt.rtol = 1e-12;
        p.opt.atol = 1e-14 * w;
        p.t_end = 2.0 * MECH_PI / w;
        p.y0 = y0;
        p.n_samples = 2;
        p.sample_y = ys;
        struct mech_budget b = big_budget();
        struct mech_ode_result r;
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_OK);
        CHECK_CLOSE(ys[2], 1.0, 0, 1e-10);
        CHECK_CLOSE(ys[3] / w, 0.0, 0, 1e-10);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    test_registry();
    test_oscillator();
    test_samples_do_not_perturb();
    test_free_fall_event();
    test_budget_and_failures();
    test_scales();
    TEST_MAIN_END();
}
