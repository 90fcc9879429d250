/* chooser_pilot.c — the chooser's pilot run (see mech/ode/chooser_pilot.h): a
 * small fraction of an expensive, uncertain run integrated with each
 * plausible candidate, its evaluations extrapolated to the whole span, the
 * chosen candidate's error measured against a tighter run over the same
 * fraction, and the choice re-made on the piloted costs. */
#include "mech/ode/chooser_pilot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The error estimate's run tightens an adaptive tolerance by this factor. */
#define PILOT_TIGHTER 100.0

/* snprintf whose truncation is accepted (the result is always terminated) */
#define PILOT_TEXT(buf, ...) ((void)(snprintf((buf), sizeof(buf), __VA_ARGS__) < 0 ? (buf)[0] = 0 : 0))
/* Its cost relative to the chosen run's at the same fraction: rk8pd's
 * evaluations grow as tol^-0.12 (first-order class), 100^0.12 = 1.7; 2
 * leaves room. */
#define PILOT_TIGHT_COST 2.0
/* The fewest evaluations an adaptive first-order step takes (rkf45: 6). */
#define PILOT_MIN_EVALS_PER_STEP 6.0
/* Candidates piloted beside the chosen one: those meeting the target within
 * this factor of its predicted CPU (the others cannot win on a 2x error). */
#define PILOT_CONTENDERS 3.0

static int meets(const struct mech_candidate *c)
{
    return c->verdict == MECH_VERDICT_CHOSEN || c->verdict == MECH_VERDICT_COSTLIER;
}

/* max_i |a_i - b_i| / max(|b_i|, scale) */
static double state_error(const double *a, const double *b, size_t n, double scale)
{
    double e = 0.0;
    for (size_t i = 0; i < n; i++) e = fmax(e, fabs(a[i] - b[i]) / fmax(fabs(b[i]), scale));
    return e;
}

/* Append "; text" to a candidate's why (truncated to fit: the return value
 * of snprintf is taken so that -Wformat-truncation knows it is meant). */
static void why_append(struct mech_candidate *c, const char *text)
{
    char buf[sizeof c->why];
    if (snprintf(buf, sizeof buf, "%s; %s", c->why, text) >= (int)sizeof buf)
        buf[sizeof buf - 1] = '\0'; /* truncated: what fits */
    memcpy(c->why, buf, sizeof c->why);
}

enum mech_status mech_choose_pilot(const struct mech_scene_profile *s, double target,
                                   struct mech_selection *sel,
                                   const struct mech_pilot_system *sys, int dry_run,
                                   const struct mech_budget *budget,
                                   struct mech_pilot_report *rep, struct mech_error *err)
{
    if (!s || !sel || !rep) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(rep, 0, sizeof *rep);
    rep->error = rep->error_extrapolated = -1.0;
    if (!sys || !sys->run || sel->integrating < 0 || (size_t)sel->integrating >= sel->n ||
        sel->chosen != sel->integrating)
        return MECH_OK;
    struct mech_candidate *ch = &sel->c[sel->integrating];
    if (!ch->predicted || !(ch->predicted_cpu_s > MECH_PILOT_THRESHOLD_S)) return MECH_OK;
    rep->considered = 1;
    rep->table_evaluations = ch->predicted_evaluations;
    if (dry_run) {
        rep->dry_run = 1;
        PILOT_TEXT(rep->why,
                 "unpiloted: a dry run integrates nothing, so this prediction is the "
                 "calibrated table's alone (%.3g s CPU predicted, above the %g s at which a real "
                 "run pilots %g%% of its cost to check it)",
                 ch->predicted_cpu_s, MECH_PILOT_THRESHOLD_S, 100.0 * MECH_PILOT_COST_FRACTION);
        return MECH_OK;
    }
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "NULL budget");
    /* a run far beyond what the step budget can hold (13 evaluations a step
     * at most, rk8pd; 4x for the table's scatter) will stop on it whatever
     * the pilot says: not piloted */
    if (ch->predicted_evaluations / 13.0 > 4.0 * (double)budget->max_steps) {
        PILOT_TEXT(rep->why,
                 "not piloted: the table predicts about %.3g steps, beyond the request's step "
                 "budget of %ld",
                 ch->predicted_evaluations / 13.0, budget->max_steps);
        return MECH_OK;
    }
    /* each pilot run within a share of the budget: a pilot that cannot
     * finish in it leaves the table's prediction */
    struct mech_budget pb = *budget;
    pb.max_steps = budget->max_steps / 20 > 1000 ? budget->max_steps / 20 : 1000;
    if (pb.max_steps > budget->max_steps) pb.max_steps = budget->max_steps;
    budget = &pb;
    /* the candidates to pilot, the chosen one first, and the fraction their
     * runs can afford */
    int idx[MECH_CHOOSER_MAX_CANDIDATES];
    size_t n = 0;
    idx[n++] = sel->integrating;
    double sum = (1.0 + PILOT_TIGHT_COST) * ch->predicted_evaluations;
    for (size_t i = 0; i < sel->n; i++) {
        const struct mech_candidate *k = &sel->c[i];
        if ((int)i == sel->integrating || !k->predicted || !k->has_settings || !meets(k) ||
            !k->adaptive || !(k->predicted_cpu_s <= PILOT_CONTENDERS * ch->predicted_cpu_s))
            continue;
        idx[n++] = (int)i;
        sum += k->predicted_evaluations;
    }
    if (!ch->adaptive || !ch->has_settings || !(sum > 0.0)) {
        PILOT_TEXT(rep->why,
                 "not piloted: %s is not an adaptive method (its cost is counted, not "
                 "predicted)", ch->method);
        return MECH_OK;
    }
    const double f = fmin(MECH_PILOT_COST_FRACTION * ch->predicted_evaluations / sum, 1.0);
    rep->fraction = f;
    const double old_cpu = ch->predicted_cpu_s, table_ch = ch->predicted_evaluations;
    double y_ch[MECH_PILOT_MAX_DIM], y_tight[MECH_PILOT_MAX_DIM], cpu_spent = 0.0;
    double allowance = INFINITY, e_ch = 0.0;
    size_t dim_ch = 0;
    char failed[160] = "", skipped[120] = "";
    for (size_t j = 0; j < n; j++) {
        struct mech_candidate *k = &sel->c[idx[j]];
        struct mech_chooser_row_info ri;
        if (!mech_chooser_row_info(s, k->method, &ri)) continue;
        /* a contender runs only while the pilot stays within its share of
         * the chosen run's piloted cost (the table may have under-predicted) */
        if (j > 0 && rep->evaluations + e_ch * k->predicted_evaluations / table_ch > allowance) {
            if (!skipped[0])
                PILOT_TEXT(skipped,
                         "%s not piloted (the pilot's share of the cost was spent)", k->method);
            continue;
        }
        /* and within what is left of that share, in steps of at least
         * PILOT_MIN_EVALS_PER_STEP evaluations: one that cannot finish in
         * it keeps the table's prediction */
        struct mech_budget kb = *budget;
        if (j > 0) {
            const double left = (allowance - rep->evaluations) / PILOT_MIN_EVALS_PER_STEP;
            if (left < (double)kb.max_steps) kb.max_steps = left > 1.0 ? (long)left : 1;
        }
        struct mech_ode_stats st;
        memset(&st, 0, sizeof st);
        double y[MECH_PILOT_MAX_DIM];
        size_t dim = 0;
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status rs = sys->run(sys->ctx, k->method, &k->opt, f, &kb, &st, y, &dim, &e);
        rep->steps += st.steps;
        rep->evaluations += (double)st.rhs_evaluations;
        cpu_spent += (double)st.rhs_evaluations * ri.cpu_per_eval;
        if (rs == MECH_EDEADLINE || rs == MECH_ECANCELLED) {
            if (err) *err = e;
            return rs;
        }
        if (rs != MECH_OK || st.rhs_evaluations <= 0) {
            if (!failed[0])
                PILOT_TEXT(failed, "%s's pilot stopped (%s): its table prediction "
                         "stands", k->method, mech_status_name(rs));
            if (j == 0) break; /* no rate for the chosen one: nothing to compare with */
            continue;
        }
        const double before = k->predicted_evaluations;
        k->predicted_evaluations =
            (double)st.rhs_evaluations / f + ri.per_sample * (double)s->samples;
        k->predicted_cpu_s = k->predicted_evaluations * ri.cpu_per_eval + MECH_CHOOSER_REQUEST_CPU_S;
        char t[200];
        PILOT_TEXT(t,
                 "piloted: %ld evaluations over %.3g%% of the run, extrapolated to %.4g (the "
                 "table said %.4g)",
                 st.rhs_evaluations, 100.0 * f, k->predicted_evaluations, before);
        why_append(k, t);
        if (j > 0) continue;
        e_ch = (double)st.rhs_evaluations;
        allowance = MECH_PILOT_COST_FRACTION * e_ch / f;
        if (!(dim > 0 && dim <= MECH_PILOT_MAX_DIM)) continue;
        memcpy(y_ch, y, dim * sizeof *y);
        dim_ch = dim;
        /* the chosen candidate's error over the pilot: against a 100x
         * tighter run over the same fraction */
        struct mech_ode_options tight = ch->opt;
        tight.rtol = fmax(ch->opt.rtol / PILOT_TIGHTER, 1e-14);
        tight.atol = ch->opt.atol * (tight.rtol / ch->opt.rtol);
        if (!(tight.rtol < ch->opt.rtol)) continue;
        memset(&st, 0, sizeof st);
        size_t dim2 = 0;
        mech_error_clear(&e);
        rs = sys->run(sys->ctx, ch->method, &tight, f, budget, &st, y_tight, &dim2, &e);
        rep->steps += st.steps;
        rep->evaluations += (double)st.rhs_evaluations;
        cpu_spent += (double)st.rhs_evaluations * ri.cpu_per_eval;
        if (rs == MECH_EDEADLINE || rs == MECH_ECANCELLED) {
            if (err) *err = e;
            return rs;
        }
        if (rs == MECH_OK && dim2 == dim_ch) {
            rep->error = state_error(y_ch, y_tight, dim_ch, s->scale > 0.0 ? s->scale : 1.0);
            rep->error_extrapolated = rep->error * pow(1.0 / f, fmax(ri.span_exponent, 1.0));
        }
    }
    rep->run = 1;
    rep->predicted_cpu_s = cpu_spent;
    /* the choice re-made on the piloted costs, among those meeting the target */
    int best = sel->integrating;
    for (size_t i = 0; i < sel->n; i++) {
        const struct mech_candidate *k = &sel->c[i];
        if (!meets(k) || !k->has_settings || !k->predicted) continue;
        if (k->predicted_cpu_s < sel->c[best].predicted_cpu_s) best = (int)i;
    }
    if (best != sel->integrating) {
        sel->c[sel->integrating].verdict = MECH_VERDICT_COSTLIER;
        why_append(&sel->c[sel->integrating], "no longer the cheapest after the pilot");
        sel->c[best].verdict = MECH_VERDICT_CHOSEN;
        why_append(&sel->c[best], "the cheapest after the pilot");
        sel->integrating = sel->chosen = best;
    }
    const struct mech_candidate *nb = &sel->c[best];
    PILOT_TEXT(rep->why,
             "the table predicted %.3g s CPU (above %g s) for a system whose step count it "
             "does not model in closed form: piloted %.3g%% of the run (%.0f evaluations, "
             "%.2g s predicted), %s now predicted at %.4g evaluations (%.3g s, was %.3g s)%s%s%s%s",
             old_cpu, MECH_PILOT_THRESHOLD_S, 100.0 * f, rep->evaluations, cpu_spent, nb->method,
             nb->predicted_evaluations, nb->predicted_cpu_s, old_cpu, failed[0] ? "; " : "",
             failed, skipped[0] ? "; " : "", skipped);
    if (e_ch > 0.0)
        PILOT_TEXT(sel->model,
             "calibrated table (bench/bench_calibrate_chooser, class %s) for the error; "
             "evaluations extrapolated from a pilot over %.3g%% of the run",
             mech_scene_class_name(s->cls), 100.0 * f);
    (void)target;
    return MECH_OK;
}
