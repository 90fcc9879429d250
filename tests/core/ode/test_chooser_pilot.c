/* test_chooser_pilot.c — the chooser's pilot (core/ode/chooser_pilot.c,
 * mech/ode/chooser_pilot.h) on a synthetic system whose cost and error are known
 * in closed form: a run over fraction f of the span costs E_TRUE f
 * evaluations at the chosen method's setting (rk8pd), RKF_FACTOR times the
 * table's prediction for rkf45, and ends at y = 1e15 tol f. Checked:
 * below the 50 ms threshold nothing runs; a dry run runs nothing and says
 * "unpiloted"; the extrapolation is counted / f + the samples' sub-steps;
 * the pilot's own evaluations stay within its share; the error over the
 * pilot is the difference with the 100x tighter run and its extrapolation
 * (1/f)^b; a pilot that shows the chosen method far dearer than predicted
 * re-makes the choice; EBUDGET in a pilot keeps the table's prediction and
 * says so; EDEADLINE is returned. Deterministic: counts, never time. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/ode/chooser.h"
#include "mech/ode/chooser_pilot.h"
#include "testlib.h"

struct fake {
    double e_true;      /* rk8pd's evaluations over the whole span */
    double rkf_factor;  /* rkf45's evaluations over its table prediction */
    double rkf_table;   /* rkf45's table prediction (set after mech_choose) */
    enum mech_status fail; /* returned by every run when not MECH_OK */
    int runs;
    long steps_seen;
};

/* y_end = 1e15 tol f: the "error" of a run is proportional to its tolerance */
static enum mech_status fake_run(void *ctx, const char *method, const struct mech_ode_options *opt,
                                 double fraction, const struct mech_budget *budget,
                                 struct mech_ode_stats *stats, double *y_end, size_t *dim,
                                 struct mech_error *err)
{
    struct fake *f = ctx;
    f->runs++;
    memset(stats, 0, sizeof *stats);
    if (f->fail != MECH_OK) {
        stats->steps = 7;
        stats->rhs_evaluations = 91;
        return mech_error_set(err, f->fail, NULL, "fake failure");
    }
    const double e = !strcmp(method, "rk8pd") ? f->e_true * fraction
                                               : f->rkf_factor * f->rkf_table * fraction;
    stats->rhs_evaluations = (long)llround(e);
    stats->steps = stats->rhs_evaluations / 13;
    if (stats->steps > budget->max_steps) {
        stats->steps = budget->max_steps;
        return mech_error_set(err, MECH_EBUDGET, NULL, "fake budget");
    }
    f->steps_seen += stats->steps;
    y_end[0] = opt->rtol * fraction * 1e15;
    *dim = 1;
    return MECH_OK;
}

static int find(const struct mech_selection *sel, const char *m)
{
    for (size_t i = 0; i < sel->n; i++)
        if (!strcmp(sel->c[i].method, m)) return (int)i;
    return -1;
}

/* A first-order profile long enough for the table to predict > 50 ms. */
static struct mech_scene_profile profile(double span)
{
    struct mech_scene_profile s;
    memset(&s, 0, sizeof s);
    s.cls = MECH_SCENE_FIRST_ORDER;
    s.span = span;
    s.T = 1.0;
    s.scale = 1.0;
    s.samples = 11;
    return s;
}

int main(void)
{
    const struct mech_budget budget = mech_budget_make(100000000, 600.0);
    struct mech_selection sel;
    struct mech_pilot_report rep;
    struct mech_error err;
    mech_error_clear(&err);

    /* below the threshold: not considered, nothing run */
    struct mech_scene_profile s = profile(100.0);
    struct fake fk = {1e6, 1.0, 0, MECH_OK, 0, 0};
    struct mech_pilot_system sys = {fake_run, &fk};
    CHECK(mech_choose(&s, 1e-8, &sel, &err) == MECH_OK);
    CHECK(sel.c[sel.chosen].predicted_cpu_s < MECH_PILOT_THRESHOLD_S);
    CHECK(mech_choose_pilot(&s, 1e-3, &sel, &sys, 0, &budget, &rep, &err) == MECH_OK);
    CHECK(!rep.considered && !rep.run && fk.runs == 0);

    /* long: considered; a dry run runs nothing and says unpiloted */
    s = profile(1e5);
    CHECK(mech_choose(&s, 1e-3, &sel, &err) == MECH_OK);
    const int ch = sel.chosen;
    CHECK(ch >= 0 && !strcmp(sel.c[ch].method, "rk8pd"));
    CHECK(sel.c[ch].predicted_cpu_s > MECH_PILOT_THRESHOLD_S);
    const double table = sel.c[ch].predicted_evaluations;
    struct mech_chooser_row_info ri;
    CHECK(mech_chooser_row_info(&s, "rk8pd", &ri));
    fk.rkf_table = find(&sel, "rkf45") >= 0 ? sel.c[find(&sel, "rkf45")].predicted_evaluations : 0;
    struct mech_selection dry = sel;
    CHECK(mech_choose_pilot(&s, 1e-3, &dry, &sys, 1, &budget, &rep, &err) == MECH_OK);
    CHECK(rep.considered && rep.dry_run && !rep.run && fk.runs == 0);
    CHECK(strstr(rep.why, "unpiloted") != NULL);
    CHECK(dry.c[ch].predicted_evaluations == table);

    /* a real run: the table predicted `table`; the truth is 1.5x that */
    fk.e_true = 1.5 * table;
    struct mech_selection real = sel;
    CHECK(mech_choose_pilot(&s, 1e-3, &real, &sys, 0, &budget, &rep, &err) == MECH_OK);
    CHECK(rep.run && rep.fraction > 0 && rep.fraction <= MECH_PILOT_COST_FRACTION);
    const double f = rep.fraction;
    const double want = llround(fk.e_true * f) / f + ri.per_sample * 11.0;
    printf("pilot: f = %.4g, %d runs, %.0f evaluations (%.2f%% of the true run), predicted %.6g "
           "(want %.6g, truth %.6g, table %.6g)\n",
           f, fk.runs, rep.evaluations, 100.0 * rep.evaluations / fk.e_true,
           real.c[real.integrating].predicted_evaluations, want, fk.e_true, table);
    const int k8 = find(&real, "rk8pd");
    CHECK(fabs(real.c[k8].predicted_evaluations - want) <= 1e-9 * want);
    CHECK(rep.table_evaluations == table);
    /* its own cost within its share of the (piloted) run */
    CHECK(rep.evaluations <= 1.0001 * MECH_PILOT_COST_FRACTION * fk.e_true);
    CHECK(rep.steps == fk.steps_seen);
    /* the error over the pilot: |y(rtol) - y(rtol / 100)| / max(|y(rtol / 100)|, 1),
     * extrapolated with (1/f)^b */
    const double rt = sel.c[ch].opt.rtol, rt2 = fmax(rt / 100.0, 1e-14);
    const double e_pilot = (rt - rt2) * f * 1e15 / fmax(rt2 * f * 1e15, 1.0);
    printf("pilot error %.6g (want %.6g), extrapolated %.6g\n", rep.error, e_pilot,
           rep.error_extrapolated);
    CHECK(fabs(rep.error - e_pilot) <= 1e-9 * e_pilot);
    CHECK(fabs(rep.error_extrapolated - e_pilot * pow(1.0 / f, fmax(ri.span_exponent, 1.0))) <=
          1e-9 * rep.error_extrapolated);
    CHECK(strstr(real.model, "pilot") != NULL);

    /* the choice re-made: rk8pd piloted 30x dearer than its table, rkf45 as
     * predicted: rkf45 (if it meets the target) becomes the cheaper */
    const int kf = find(&sel, "rkf45");
    if (kf >= 0 && (sel.c[kf].verdict == MECH_VERDICT_COSTLIER) &&
        sel.c[kf].predicted_cpu_s <= 3.0 * sel.c[ch].predicted_cpu_s) {
        fk.e_true = 30.0 * table;
        fk.rkf_factor = 1.0;
        fk.runs = 0;
        real = sel;
        CHECK(mech_choose_pilot(&s, 1e-3, &real, &sys, 0, &budget, &rep, &err) == MECH_OK);
        printf("re-choice: now %s\n", real.c[real.chosen].method);
        CHECK(!strcmp(real.c[real.chosen].method, "rkf45"));
        CHECK(real.c[k8].verdict == MECH_VERDICT_COSTLIER);
    } else {
        printf("re-choice not exercised: rkf45 is not a contender at this target\n");
    }

    /* a pilot that stops on its budget: the table's prediction stands */
    fk.e_true = table;
    fk.fail = MECH_EBUDGET;
    real = sel;
    CHECK(mech_choose_pilot(&s, 1e-3, &real, &sys, 0, &budget, &rep, &err) == MECH_OK);
    CHECK(real.c[ch].predicted_evaluations == table);
    CHECK(strstr(rep.why, "table prediction stands") != NULL);
    CHECK(rep.evaluations > 0); /* what it spent is still counted */
    /* a deadline in the pilot is the request's */
    fk.fail = MECH_EDEADLINE;
    real = sel;
    mech_error_clear(&err);
    CHECK(mech_choose_pilot(&s, 1e-3, &real, &sys, 0, &budget, &rep, &err) == MECH_EDEADLINE);
    /* a run far beyond the step budget is not piloted */
    fk.fail = MECH_OK;
    fk.runs = 0;
    const struct mech_budget tiny = mech_budget_make(10, 600.0);
    real = sel;
    CHECK(mech_choose_pilot(&s, 1e-3, &real, &sys, 0, &tiny, &rep, &err) == MECH_OK);
    CHECK(rep.considered && !rep.run && fk.runs == 0);
    /* NULLs */
    CHECK(mech_choose_pilot(NULL, 1e-8, &real, &sys, 0, &budget, &rep, NULL) == MECH_EINVAL);
    CHECK(mech_choose_pilot(&s, 1e-3, &real, NULL, 0, &budget, &rep, NULL) == MECH_OK &&
          !rep.considered);
    TEST_MAIN_END();
}
