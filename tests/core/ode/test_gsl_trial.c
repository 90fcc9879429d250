/* test_gsl_trial.c — the GSL adapters (rk8pd, rkck, rkf45, msbdf) reject a
 * trial step whose right-hand side is non-finite and shrink the step, and
 * stop with MECH_ENUMERIC only when the accepted state itself is bad
 * (a non-finite trial is a rejected step, not a failed run;
 * ode/integrators/gsl_rhs.h).
 *
 * Scene: x' = 1 - x, x(0) = 0, exact x = 1 - exp(-t), with the right-hand
 * side non-finite for x > 1 (a region the solution approaches but never
 * enters). Once x is within atol of 1 the error control lets the step grow
 * far beyond 1, and an explicit stage x + c h (1 - x) (or a BDF predictor)
 * overshoots past 1: a trial in the forbidden region. The run must finish
 * with the exact answer, and at least one trial must have been non-finite
 * (counted by the rhs, so the test cannot pass vacuously).
 * Second scene: x' = 1, non-finite for x > 1, t_end = 2: the solution
 * itself reaches the forbidden region, so the run must fail with
 * MECH_ENUMERIC (not succeed, not hang). Third: non-finite at the start:
 * MECH_ENUMERIC at once.
 */
#include <math.h>
#include <stdio.h>

#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "testlib.h"

struct cliff {
    double slope; /* 1: x' = 1 - x; 0: x' = 1 */
    double x_max; /* rhs non-finite for x > x_max */
    long nan_calls;
};

static enum mech_status cliff_rhs(double t, const double *y, double *dydt, void *p)
{
    (void)t;
    struct cliff *c = p;
    if (y[0] > c->x_max) {
        c->nan_calls++;
        dydt[0] = NAN;
        return MECH_OK;
    }
    dydt[0] = 1.0 - c->slope * y[0];
    return MECH_OK;
}

static enum mech_status run(const char *method, struct cliff *c, double x0, double t_end,
                            double *x_end, struct mech_ode_result *res, struct mech_error *e)
{
    struct mech_ode_system sys = {1, cliff_rhs, NULL, 0, c, NULL, 0, NULL};
    struct mech_ode_problem p = {0};
    double y0[1] = {x0}, ys[2];
    p.sys = &sys;
    p.method = mech_ode_method_find(method);
    p.opt.rtol = 1e-10;
    p.opt.atol = 1e-10;
    p.t0 = 0.0;
    p.t_end = t_end;
    p.y0 = y0;
    p.n_samples = 2;
    p.sample_y = ys;
    struct mech_budget b = mech_budget_make(1000000, 60.0);
    mech_error_clear(e);
    enum mech_status st = mech_ode_solve(&p, &b, res, e);
    *x_end = ys[1];
    return st;
}

int main(void)
{
    static const char *const methods[] = {"rk8pd", "rkck", "rkf45", "msbdf"};
    for (size_t m = 0; m < sizeof methods / sizeof *methods; m++) {
        struct mech_ode_result res;
        struct mech_error e;
        double x;
        /* 1: trials overshoot into x > 1; the solution never does */
        struct cliff c = {1.0, 1.0, 0};
        const double t_end = 1e4;
        enum mech_status st = run(methods[m], &c, 0.0, t_end, &x, &res, &e);
        printf("%s: approach: status %s (%s), x(t_end) - 1 = %.3g, non-finite trials %ld, "
               "rejected steps %ld, steps %ld\n",
               methods[m], mech_status_name(st), e.text, x - 1.0, c.nan_calls,
               res.stats.rejected_steps, res.stats.steps);
        CHECK(st == MECH_OK);
        CHECK(c.nan_calls > 0); /* the scene really exercises a non-finite trial */
        CHECK(isfinite(x) && fabs(x - (1.0 - exp(-t_end))) <= 1e-8);
        CHECK(res.stats.rejected_steps > 0);

        /* 2: the solution itself runs into the forbidden region at t = 1 */
        struct cliff w = {0.0, 1.0, 0};
        st = run(methods[m], &w, 0.0, 2.0, &x, &res, &e);
        printf("%s: wall: status %s (%s)\n", methods[m], mech_status_name(st), e.text);
        CHECK(st == MECH_ENUMERIC);

        /* 3: non-finite at the initial (accepted) state */
        struct cliff s = {0.0, 1.0, 0};
        st = run(methods[m], &s, 1.5, 2.0, &x, &res, &e);
        printf("%s: start: status %s (%s), calls %ld\n", methods[m], mech_status_name(st), e.text,
               s.nan_calls);
        CHECK(st == MECH_ENUMERIC);
    }
    TEST_MAIN_END();
}
