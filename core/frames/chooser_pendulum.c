/* chooser_pendulum.c — the predictive chooser for the Foucault pendulum (see
 * mech/frames/chooser_pendulum.h): rattle and rattle_yoshida4 at the fewest steps
 * per swing predicted to meet the target, cost counted exactly. */
#include "mech/frames/chooser_pendulum.h"
#include "mech/base/constants.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PC_MARGIN 10.0    /* aim at target / 10, as the particle classes */
#define PC_N_MIN 8.0      /* the schema's steps_per_swing range */
#define PC_N_MAX 100000.0

struct pc_method {
    enum mech_pendulum_method m;
    int order, evals_per_step;
    double C, cpu_per_eval;
};
/* order 4 first: listed in the order the selection shows them */
static const struct pc_method pc_methods[] = {
    {MECH_PENDULUM_RATTLE_YOSHIDA4, 4, 3, 0.07, 5.3e-8},
    {MECH_PENDULUM_RATTLE, 2, 1, 0.07, 5.85e-8},
};

static double pc_floor(const struct mech_pendulum_profile *s)
{
    return s->turn_angle > 0.0 ? fmax(1e-14, 1e-13 / s->turn_angle) : 1e-14;
}

static const struct pc_method *pc_find(enum mech_pendulum_method m)
{
    for (size_t i = 0; i < sizeof pc_methods / sizeof *pc_methods; i++)
        if (pc_methods[i].m == m) return &pc_methods[i];
    return NULL;
}

static double pc_truncation(const struct mech_pendulum_profile *s, const struct pc_method *pm,
                            double n)
{
    return pm->C * pow((2.0 * MECH_PI) / n, pm->order) * (1.0 + 3.0 * s->amplitude * s->amplitude);
}

double mech_pendulum_predict_error(const struct mech_pendulum_profile *s,
                                   enum mech_pendulum_method method, double n)
{
    const struct pc_method *pm = pc_find(method);
    if (!s || !pm || !(n >= 1.0)) return -1.0;
    return fmax(pc_truncation(s, pm, n), pc_floor(s));
}

enum mech_status mech_choose_pendulum(const struct mech_pendulum_profile *s, double target,
                                      struct mech_selection *out,
                                      enum mech_pendulum_method *method,
                                      double *steps_per_swing, struct mech_error *err)
{
    if (!s || !out || !method || !steps_per_swing)
        return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(out, 0, sizeof *out);
    out->chosen = out->integrating = -1;
    if (!(target >= 1e-15 && target <= 0.1))
        return mech_error_set(err, MECH_EINVAL, "target_error",
                              "target_error must be in [1e-15, 0.1], got %.17g", target);
    if (!(s->period > 0.0 && isfinite(s->period)) || !(s->swings >= 0.0 && isfinite(s->swings)) ||
        !(s->amplitude >= 0.0 && s->amplitude <= 1.5707963267948966) ||
        !(s->turn_angle >= 0.0 && isfinite(s->turn_angle)))
        return mech_error_set(err, MECH_EINVAL, NULL, "invalid pendulum profile");
    out->target = target;
    out->cls = MECH_SCENE_CONSTRAINED_PENDULUM;
    out->span = s->swings;
    out->roundoff_floor = pc_floor(s);
    snprintf(out->model, sizeof out->model,
             "measured law (bench/bench_calibrate_chooser --pendulum): error = C (2 pi / n)^p "
             "(1 + 3 alpha^2) on the period and the rate / W, n steps per swing; evaluations "
             "counted exactly; span in swings");
    const double aim = target / PC_MARGIN;
    if (out->roundoff_floor > aim) out->beyond = 1;
    double n_of[2];
    for (size_t k = 0; k < 2; k++) {
        const struct pc_method *pm = &pc_methods[k];
        struct mech_candidate *c = &out->c[out->n++];
        c->method = mech_pendulum_method_name(pm->m);
        c->adaptive = 0;
        c->has_settings = 1;
        /* invert the truncation law C (2 pi / n)^p (1 + 3 alpha^2) = aim,
         * round up to whole steps per swing */
        const double k_amp = pm->C * (1.0 + 3.0 * s->amplitude * s->amplitude);
        /* no finer than a tenth of the round-off floor: beyond it more
         * steps buy nothing */
        double n = 2.0 * MECH_PI * pow(k_amp / fmax(aim, 0.1 * out->roundoff_floor), 1.0 / pm->order);
        if (!(n >= PC_N_MIN)) n = PC_N_MIN; /* also NaN */
        n = ceil(n - 1e-9);
        if (n > PC_N_MAX) n = PC_N_MAX;
        n_of[k] = n;
        c->opt.dt = s->period / n;
        c->predicted_error = mech_pendulum_predict_error(s, pm->m, n);
        const double steps = fmax(1.0, ceil(s->swings * n - 1e-9));
        c->predicted_evaluations = steps * pm->evals_per_step + 1.0;
        /* the error estimate: the same run at (steps + 1) / 2 steps */
        if (s->error_estimate)
            c->predicted_evaluations += floor((steps + 1.0) / 2.0) * pm->evals_per_step + 1.0;
        c->predicted_cpu_s =
            c->predicted_evaluations * pm->cpu_per_eval + MECH_CHOOSER_REQUEST_CPU_S;
        c->predicted = 1;
        c->verdict = c->predicted_error <= aim * 1.0001 ? MECH_VERDICT_COSTLIER
                                                        : MECH_VERDICT_MISSES_TARGET;
    }
    int best = -1;
    for (size_t i = 0; i < out->n; i++)
        if (out->c[i].verdict == MECH_VERDICT_COSTLIER &&
            (best < 0 || out->c[i].predicted_cpu_s < out->c[best].predicted_cpu_s))
            best = (int)i;
    if (best < 0) {
        /* the cheapest of the most accurate (within 2x), as mech_choose */
        double emin = INFINITY;
        for (size_t i = 0; i < out->n; i++) emin = fmin(emin, out->c[i].predicted_error);
        for (size_t i = 0; i < out->n; i++)
            if (out->c[i].predicted_error <= 2.0 * emin &&
                (best < 0 || out->c[i].predicted_cpu_s < out->c[best].predicted_cpu_s))
                best = (int)i;
        out->beyond = out->c[best].predicted_error > target ? 2 : 1;
    }
    out->chosen = out->integrating = best;
    for (size_t i = 0; i < out->n; i++) {
        struct mech_candidate *c = &out->c[i];
        if ((int)i == best) {
            c->verdict = MECH_VERDICT_CHOSEN;
            snprintf(c->why, sizeof c->why,
                     c->predicted_error > aim
                         ? "no candidate is predicted within the safety margin of the target: "
                           "the most accurate (%.0f steps per swing, predicted %.2g)"
                         : "the cheapest predicted to meet the target (%.0f steps per swing, "
                           "predicted %.2g)",
                     n_of[i], c->predicted_error);
        } else if (c->verdict == MECH_VERDICT_COSTLIER) {
            snprintf(c->why, sizeof c->why,
                     "meets the target (%.0f steps per swing, predicted %.2g) at %.3gx the "
                     "chosen method's predicted CPU",
                     n_of[i], c->predicted_error,
                     c->predicted_cpu_s / fmax(out->c[best].predicted_cpu_s, 1e-300));
        } else {
            snprintf(c->why, sizeof c->why,
                     "predicted %.2g, not within the safety margin (target / %g) at its "
                     "tightest setting (%.0f steps per swing)",
                     c->predicted_error, PC_MARGIN, n_of[i]);
        }
    }
    *method = pc_methods[best].m;
    *steps_per_swing = n_of[best];
    return MECH_OK;
}
