/* trajectory_plan.c — a trajectory's model → choose pipeline
 * (mech/frames/trajectory_plan.h). */
#include "mech/frames/trajectory_plan.h"

#include <string.h>

#include "mech/frames/closed_form.h"

enum mech_status mech_trajectory_plan(struct mech_trajectory_problem *p,
                                      const struct mech_trajectory_plan_request *q,
                                      struct mech_budget *budget,
                                      struct mech_trajectory_plan *out, struct mech_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!p || !q || !budget || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    enum mech_status st;
    if (q->auto_model) {
        p->fictitious = MECH_FICTITIOUS_ALL;
        if (!q->dry_run) {
            st = mech_trajectory_model_select(p, q->model_target, budget, &out->model, err);
            if (st != MECH_OK) {
                out->failed = MECH_PLAN_MODEL;
                return st;
            }
            out->modelled = 1;
            p->fictitious = out->model.fictitious;
            const long used = out->model.first_pass_stats.steps;
            if (used > 0)
                budget->max_steps = budget->max_steps - used > 1 ? budget->max_steps - used : 1;
        }
    }
    if (q->by_accuracy) {
        st = mech_trajectory_choose(p, q->target, &out->choice, err);
        if (st != MECH_OK) {
            out->failed = MECH_PLAN_CHOICE;
            return st;
        }
        out->chosen = 1;
        p->method = out->choice.method;
        p->opt = out->choice.opt;
        out->closed_form = out->choice.closed_form && mech_trajectory_has_closed_form(p);
    }
    return MECH_OK;
}
