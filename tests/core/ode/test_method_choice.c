/* test_method_choice.c — the method-choice policy for first-order systems
 * (core/ode/method_choice.c) and the accuracy presets (core/ode/accuracy.c).
 * The system is the harmonic oscillator x'' = -x as y = (x, v), exact
 * solution (cos t, -sin t): for each preset the chosen method, run with the
 * chosen settings over 100 dynamical times, meets the preset's promise
 * within the stated prediction factor (30, docs/accuracy.md) against that
 * closed form; a closed form is chosen when cheaper and never when the
 * request forbids it; the reason says which and why; the pilot's steps come
 * off the budget, a dry run pilots nothing, a failing pilot is a run error
 * (pilot_failed) while a target out of range is a request error. Counts and
 * errors only, never time. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/ode/accuracy.h"
#include "mech/ode/method_choice.h"
#include "mech/ode/ode.h"
#include "testlib.h"

#define SPAN 100.0
#define PREDICTION_FACTOR 30.0

static enum mech_status osc(double t, const double *y, double *dy, void *params)
{
    (void)t;
    (void)params;
    dy[0] = y[1];
    dy[1] = -y[0];
    return MECH_OK;
}

/* max over 101 samples of |y - (cos t, -sin t)| (the state's scale is 1). */
static double run_error(const char *method, struct mech_ode_options opt, long *steps)
{
    static const struct mech_ode_system sys = {2, osc, NULL, 0, NULL, NULL, 0, NULL};
    const double y0[2] = {1.0, 0.0};
    double ts[101], ys[202];
    struct mech_ode_problem p;
    memset(&p, 0, sizeof p);
    p.sys = &sys;
    p.method = mech_ode_method_find(method);
    p.opt = opt;
    p.t0 = 0.0;
    p.t_end = SPAN;
    p.y0 = y0;
    p.n_samples = 101;
    p.sample_t = ts;
    p.sample_y = ys;
    struct mech_ode_result r;
    struct mech_error e;
    const struct mech_budget b = mech_budget_make(10000000, 600.0);
    if (!p.method || mech_ode_solve(&p, &b, &r, &e) != MECH_OK) return INFINITY;
    double err = 0.0;
    for (size_t i = 0; i < r.n_samples; i++)
        err = fmax(err, fmax(fabs(ys[2 * i] - cos(ts[i])), fabs(ys[2 * i + 1] + sin(ts[i]))));
    *steps = r.stats.steps;
    return err;
}

static struct mech_first_order_system oscillator(void)
{
    struct mech_first_order_system s;
    memset(&s, 0, sizeof s);
    s.equations = "the harmonic oscillator x'' = -x";
    s.state = "the dimensionless state (x, v)";
    s.state_scale = 1.0;
    s.samples = 101;
    s.span = SPAN;
    s.closed_form_allowed = 1;
    return s;
}

/* A pilot whose every run takes `steps` steps or fails with `fail`. */
struct fake_pilot {
    long steps;
    enum mech_status fail;
    int runs;
};

static enum mech_status fake_run(void *ctx, const char *method, const struct mech_ode_options *opt,
                                 double fraction, const struct mech_budget *budget,
                                 struct mech_ode_stats *stats, double *y_end, size_t *dim,
                                 struct mech_error *err)
{
    (void)method;
    (void)budget;
    struct fake_pilot *f = ctx;
    f->runs++;
    memset(stats, 0, sizeof *stats);
    stats->steps = f->steps;
    stats->rhs_evaluations = 13 * f->steps;
    if (f->fail != MECH_OK) return mech_error_set(err, f->fail, NULL, "pilot ran out");
    y_end[0] = 1.0 + opt->rtol * fraction;
    *dim = 1;
    return MECH_OK;
}

int main(void)
{
    struct mech_method_choice mc;
    struct mech_error e;
    mech_error_clear(&e);

    /* the presets: one table, looked up by name; unknown or NULL names fall
     * back to "balanced" for the target and are NULL for the lookup */
    CHECK(mech_accuracy_preset_named("draft")->promise == 1e-3);
    CHECK(mech_accuracy_preset_named("machine")->promise == 1e-11);
    CHECK(mech_accuracy_preset_named("exact") == NULL && mech_accuracy_preset_named(NULL) == NULL);
    const struct mech_accuracy_preset *pr = NULL;
    CHECK(mech_accuracy_target(0, 0.0, "precise", &pr) == 1e-10 && pr &&
          !strcmp(pr->name, "precise"));
    CHECK(mech_accuracy_target(0, 0.0, "", &pr) == 1e-8 && !strcmp(pr->name, "balanced"));
    CHECK(mech_accuracy_target(1, 3e-7, "draft", &pr) == 3e-7 && pr == NULL);

    /* each preset's promise kept, within the prediction factor, by the
     * chosen method at its chosen settings, against the closed form */
    const char *presets[] = {"draft", "balanced", "precise"};
    for (int i = 0; i < 3; i++) {
        const struct mech_first_order_system s = oscillator();
        const double target = mech_accuracy_target(0, 0.0, presets[i], NULL);
        CHECK_EQ_INT(mech_choose_first_order(&s, target, 0, NULL, &mc, &e), MECH_OK);
        CHECK(!mc.closed_form && mc.method && mc.target == target);
        CHECK(fabs(mc.opt.atol - mc.opt.rtol * 1.0) <= 1e-12 * mc.opt.rtol ||
              mc.opt.dt > 0.0);
        long steps = 0;
        const double err = run_error(mc.method, mc.opt, &steps);
        printf("%-9s target %.0e: %s rtol %.3g -> error %.3g (%ld steps), predicted %.3g\n",
               presets[i], target, mc.method, mc.opt.rtol, err, steps,
               mc.sel.c[mc.sel.chosen].predicted_error);
        CHECK(err <= PREDICTION_FACTOR * target);
        CHECK(strstr(mc.reason, "the harmonic oscillator x'' = -x over 100 dynamical times") != NULL);
        CHECK(strstr(mc.reason, "cheapest candidate predicted to meet") != NULL);
        CHECK(strstr(mc.reason, "no integrator block") == NULL);
    }
    /* tighter targets cost more steps: draft's run is the cheapest */
    {
        const struct mech_first_order_system s = oscillator();
        long sd = 0, sp = 0;
        CHECK(mech_choose_first_order(&s, 1e-3, 0, NULL, &mc, &e) == MECH_OK);
        run_error(mc.method, mc.opt, &sd);
        CHECK(mech_choose_first_order(&s, 1e-10, 0, NULL, &mc, &e) == MECH_OK);
        run_error(mc.method, mc.opt, &sp);
        CHECK(sd < sp);
    }

    /* the closed form: chosen when cheaper (its cost is the samples'), the
     * best integrator still named; never when the request says false */
    {
        struct mech_first_order_system s = oscillator();
        s.closed_form_name = "harmonic oscillator";
        s.defaulted = 1;
        CHECK(mech_choose_first_order(&s, 1e-8, 0, NULL, &mc, &e) == MECH_OK);
        CHECK(mc.closed_form && mc.method && strcmp(mc.method, "closed_form") != 0);
        CHECK(!strcmp(mc.sel.c[mc.sel.chosen].method, "closed_form"));
        CHECK(strstr(mc.reason, "no integrator block: accuracy \"balanced\" by default; ") ==
              mc.reason);
        CHECK(strstr(mc.reason, "the exact harmonic oscillator solution") != NULL);
        CHECK(strstr(mc.reason, "nothing integrated") != NULL);
        s.closed_form_allowed = 0;
        CHECK(mech_choose_first_order(&s, 1e-8, 0, NULL, &mc, &e) == MECH_OK);
        CHECK(!mc.closed_form && mc.sel.chosen == mc.sel.integrating);
    }

    /* request errors: out-of-range target, NULLs */
    {
        const struct mech_first_order_system s = oscillator();
        CHECK_EQ_INT(mech_choose_first_order(&s, 0.5, 0, NULL, &mc, &e), MECH_EINVAL);
        CHECK(!mc.pilot_failed && e.text[0] != '\0');
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-16, 0, NULL, &mc, &e), MECH_EINVAL);
        CHECK_EQ_INT(mech_choose_first_order(NULL, 1e-8, 0, NULL, &mc, &e), MECH_EINVAL);
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-8, 0, NULL, NULL, &e), MECH_EINVAL);
    }

    /* the pilot: a long, expensive run is piloted; its steps come off the
     * budget; a dry run pilots nothing; a failing pilot is a run error */
    {
        struct mech_first_order_system s = oscillator();
        s.span = 1e6;
        s.samples = 11;
        struct fake_pilot fp = {400, MECH_OK, 0};
        const struct mech_pilot_system ps = {fake_run, &fp};
        s.pilot = &ps;
        struct mech_budget b = mech_budget_make(1000000, 600.0);
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-3, 0, &b, &mc, &e), MECH_OK);
        CHECK(mc.pilot.considered && mc.pilot.run && fp.runs > 0);
        CHECK(mc.pilot.steps == 400L * fp.runs);
        CHECK(b.max_steps == 1000000 - mc.pilot.steps);
        /* a budget smaller than the pilot's steps leaves one step, never 0 */
        fp.runs = 0;
        b = mech_budget_make(1000000, 600.0);
        fp.steps = 999999;
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-3, 0, &b, &mc, &e), MECH_OK);
        CHECK(b.max_steps == (mc.pilot.steps >= 1000000 ? 1 : 1000000 - mc.pilot.steps));
        /* dry run */
        fp.runs = 0;
        fp.steps = 400;
        b = mech_budget_make(1000000, 600.0);
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-3, 1, &b, &mc, &e), MECH_OK);
        CHECK(mc.pilot.considered && mc.pilot.dry_run && !mc.pilot.run && fp.runs == 0);
        CHECK(b.max_steps == 1000000);
        /* a deadline in the pilot: returned, and said to be the pilot's */
        fp.fail = MECH_EDEADLINE;
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-3, 0, &b, &mc, &e), MECH_EDEADLINE);
        CHECK(mc.pilot_failed);
        /* a pilot without a budget is refused */
        CHECK_EQ_INT(mech_choose_first_order(&s, 1e-3, 0, NULL, &mc, &e), MECH_EINVAL);
    }
    TEST_MAIN_END();
}
