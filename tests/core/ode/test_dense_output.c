/* test_dense_output.c — samples inside an accepted step taken from the
 * driver's Hermite interpolant (mech/ode/ode.h, "dense output") instead of a
 * sub-step, for second-order systems under rk8pd, rkck and rkf45:
 *   - the same problem given without its second-order form (rhs only) is
 *     sampled by sub-steps: both runs take the same accepted steps and end
 *     bit-identical, the dense run spends fewer evaluations (counts,
 *     deterministic), and each interpolated sample agrees with the
 *     sub-stepped one within the run's tolerance;
 *   - against exact references (Kepler's equation in long double,
 *     tests/kepler_ld.h; cos/sin; a parabola), the worst sample error of the
 *     dense run is no worse than the sub-stepped run's beyond the tolerance;
 *   - a parabola (uniform gravity) is reproduced to round-off: the
 *     interpolant is exact on polynomials of its degree;
 *   - an interior stop event still lands on its closed-form time, with the
 *     samples before it interpolated.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "kepler_ld.h"
#include "mech/base/constants.h"
#include "mech/ode/ode.h"
#include "testlib.h"

static const char *const METHODS[] = {"rk8pd", "rkck", "rkf45"};
enum { N_METHODS = 3 };

/* ---- Kepler through the pericentre state (q, 0, 0), (0, u, 0), GM = 1 ---- */
static const double KQ = 0.5, KU = 1.7320508075688772;

static enum mech_status kep_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)v, (void)p;
    const double r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    const double f = -1.0 / (r2 * sqrt(r2));
    for (int i = 0; i < 3; i++) a[i] = f * q[i];
    return MECH_OK;
}
static enum mech_status kep_rhs(double t, const double *y, double *dydt, void *p)
{
    for (int i = 0; i < 3; i++) dydt[i] = y[3 + i];
    return kep_accel(t, y, y + 3, dydt + 3, p);
}
static void kep_exact(double t, double *y)
{
    double r[2], v[2];
    kepler_ld_pericentre(KQ, KU, t, r, v);
    y[0] = r[0], y[1] = r[1], y[2] = 0.0;
    y[3] = v[0], y[4] = v[1], y[5] = 0.0;
}

/* ---- uniform gravity, y = (z, w): z = 10 + 3 t - 4.9 t^2 ---- */
static enum mech_status fall_accel(double t, const double *q, const double *v, double *a, void *p)
{
    (void)t, (void)q, (void)v, (void)p;
    a[0] = -9.8;
    return MECH_OK;
}
static enum mech_status fall_rhs(double t, const double *y, double *dydt, void *p)
{
    dydt[0] = y[1];
    return fall_accel(t, y, y + 1, dydt + 1, p);
}
static double fall_event(double t, const double *y, void *p)
{
    (void)t, (void)p;
    return y[0];
}

struct run {
    struct mech_ode_result res;
    double ys[6 * 401];
    double yend[6];
};

static void solve(const struct mech_ode_system *sys, const char *method, double rtol,
                  double t_end, const double *y0, size_t n, struct run *r)
{
    struct mech_ode_problem p = {0};
    p.sys = sys;
    p.method = mech_ode_method_find(method);
    p.opt.rtol = rtol;
    p.opt.atol = rtol;
    p.t_end = t_end;
    p.y0 = y0;
    p.n_samples = n;
    p.sample_y = r->ys;
    p.dense_output = 1;
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    struct mech_error err;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_ode_solve(&p, &b, &r->res, &err), MECH_OK);
    memcpy(r->yend, r->ys + (n - 1) * sys->dim, sys->dim * sizeof *r->yend);
}

/* Kepler e = 0.5, 3 orbits, 401 samples: dense against sub-stepped. */
static void test_kepler(void)
{
    const struct mech_ode_system dense = {6, kep_rhs, kep_accel, MECH_ODE_VELOCITY_FREE, NULL,
                                          NULL, 3, NULL};
    const struct mech_ode_system sub = {6, kep_rhs, NULL, 0u, NULL, NULL, 0, NULL};
    const double y0[6] = {KQ, 0, 0, 0, KU, 0}, t_end = 6.0 * MECH_PI;
    static const double RTOL[] = {1e-5, 1e-8, 1e-11};
    for (int m = 0; m < N_METHODS; m++)
        for (int k = 0; k < 3; k++) {
            static struct run a, b, two;
            solve(&dense, METHODS[m], RTOL[k], t_end, y0, 401, &a);
            solve(&sub, METHODS[m], RTOL[k], t_end, y0, 401, &b);
            solve(&dense, METHODS[m], RTOL[k], t_end, y0, 2, &two);
            /* the same steps, the same end, bit for bit */
            CHECK_EQ_INT(a.res.stats.steps, b.res.stats.steps);
            CHECK(memcmp(a.yend, b.yend, sizeof a.yend) == 0);
            CHECK(memcmp(a.yend, two.yend, sizeof a.yend) == 0);
            /* evaluations: the steps' own, plus a sub-step for each sample the
             * interpolant declined; never more than sub-stepping all */
            const long steps_only = two.res.stats.rhs_evaluations;
            const long dense_extra = a.res.stats.rhs_evaluations - steps_only;
            const long sub_extra = b.res.stats.rhs_evaluations - steps_only;
            CHECK(dense_extra >= 0 && dense_extra < sub_extra);
            double worst_a = 0, worst_b = 0, worst_ab = 0;
            for (int i = 0; i < 401; i++) {
                double ye[6];
                kep_exact(t_end * i / 400.0, ye);
                for (int c = 0; c < 6; c++) {
                    const double *ya = a.ys + 6 * i, *yb = b.ys + 6 * i;
                    worst_a = fmax(worst_a, fabs(ya[c] - ye[c]));
                    worst_b = fmax(worst_b, fabs(yb[c] - ye[c]));
                    /* within the run's tolerance of the sub-step (which has
                     * its own local error of that size) */
                    const double tol = RTOL[k] * (1.0 + fabs(yb[c]));
                    worst_ab = fmax(worst_ab, fabs(ya[c] - yb[c]) / tol);
                }
            }
            printf("%-5s rtol %.0e: steps %ld, evaluations %ld (sub-stepped: %ld, steps only %ld); "
                   "worst sample error %.2e (sub-stepped %.2e); |dense - sub| <= %.2f tol\n",
                   METHODS[m], RTOL[k], a.res.stats.steps, a.res.stats.rhs_evaluations,
                   b.res.stats.rhs_evaluations, steps_only, worst_a, worst_b, worst_ab);
            CHECK(worst_ab <= 4.0);
            CHECK(worst_a <= worst_b + 4.0 * RTOL[k] * 3.0);
        }
    /* at small steps every sample after the first two steps is interpolated:
     * rkck at 1e-11 takes far more steps than there are samples */
    static struct run a, two;
    solve(&dense, "rkck", 1e-11, t_end, y0, 401, &a);
    solve(&dense, "rkck", 1e-11, t_end, y0, 2, &two);
    CHECK(a.res.stats.rhs_evaluations - two.res.stats.rhs_evaluations <= 4 * 7);
}

/* A parabola is reproduced to round-off (the interpolant's degree is 8), and
 * the stop at z = 0 lands on its closed form t = (3 + sqrt(9 + 196)) / 9.8. */
static void test_parabola_and_event(void)
{
    const struct mech_ode_system sys = {2, fall_rhs, fall_accel, MECH_ODE_VELOCITY_FREE, NULL,
                                        NULL, 1, NULL};
    const double y0[2] = {10.0, 3.0}, t_stop = (3.0 + sqrt(9.0 + 196.0)) / 9.8;
    for (int m = 0; m < N_METHODS; m++) {
        static double ys[2 * 201], ts[201];
        double ystop[2];
        struct mech_ode_problem p = {0};
        p.sys = &sys;
        p.method = mech_ode_method_find(METHODS[m]);
        p.opt.rtol = 1e-6;
        p.opt.atol = 1e-6;
        p.t_end = 4.0;
        p.y0 = y0;
        p.n_samples = 201;
        p.sample_y = ys;
        p.sample_t = ts;
        p.event = fall_event;
        p.event_direction = MECH_ODE_DECREASING;
        p.y_stop = ystop;
        p.dense_output = 1;
        struct mech_ode_result r, r2;
        struct mech_budget b = mech_budget_make(1000000, 60.0);
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r, NULL), MECH_OK);
        CHECK(r.stopped);
        CHECK_CLOSE(r.t_stop, t_stop, 1e-12, 0.0);
        double worst = 0;
        for (size_t i = 0; i < r.n_samples; i++) {
            const double t = ts[i];
            worst = fmax(worst, fabs(ys[2 * i] - (10.0 + 3.0 * t - 4.9 * t * t)) / 20.0);
            worst = fmax(worst, fabs(ys[2 * i + 1] - (3.0 - 9.8 * t)) / 40.0);
        }
        /* a sub-step for every sample would cost more */
        p.n_samples = 2;
        CHECK_EQ_INT(mech_ode_solve(&p, &b, &r2, NULL), MECH_OK);
        printf("%-5s parabola: %zu samples before the stop, worst relative error %.2e, "
               "evaluations %ld (2 samples: %ld)\n",
               METHODS[m], r.n_samples, worst, r.stats.rhs_evaluations,
               r2.stats.rhs_evaluations);
        CHECK(worst <= 1e-13);
        CHECK_EQ_INT(r.n_samples, 89); /* t_i = 4 i / 200 <= 1.767 */
    }
}

/* The oscillator at a loose tolerance (long steps): whatever the
 * interpolant declines is sub-stepped, and every sample stays within the
 * global error the steps themselves make. */
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
static void test_oscillator_loose(void)
{
    const struct mech_ode_system sys = {2, ho_rhs, ho_accel, MECH_ODE_VELOCITY_FREE, NULL, NULL,
                                        1, NULL};
    const struct mech_ode_system sub = {2, ho_rhs, NULL, 0u, NULL, NULL, 0, NULL};
    const double y0[2] = {1.0, 0.0}, t_end = 20.0 * MECH_PI;
    for (int m = 0; m < N_METHODS; m++) {
        static struct run a, b;
        solve(&sys, METHODS[m], 1e-4, t_end, y0, 301, &a);
        solve(&sub, METHODS[m], 1e-4, t_end, y0, 301, &b);
        double worst_a = 0, worst_b = 0;
        for (int i = 0; i < 301; i++) {
            const double t = t_end * i / 300.0;
            worst_a = fmax(worst_a, fmax(fabs(a.ys[2 * i] - cos(t)), fabs(a.ys[2 * i + 1] + sin(t))));
            worst_b = fmax(worst_b, fmax(fabs(b.ys[2 * i] - cos(t)), fabs(b.ys[2 * i + 1] + sin(t))));
        }
        printf("%-5s oscillator rtol 1e-4: worst sample error %.2e (sub-stepped %.2e), "
               "evaluations %ld (sub-stepped %ld)\n",
               METHODS[m], worst_a, worst_b, a.res.stats.rhs_evaluations,
               b.res.stats.rhs_evaluations);
        CHECK(worst_a <= worst_b + 4e-4);
        CHECK(a.res.stats.rhs_evaluations <= b.res.stats.rhs_evaluations);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    test_kepler();
    test_parabola_and_event();
    test_oscillator_loose();
    TEST_MAIN_END();
}
