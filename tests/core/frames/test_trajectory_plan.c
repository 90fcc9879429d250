/* test_trajectory_plan.c — a trajectory's model → choose pipeline
 * (core/frames/trajectory_plan.c). Scene: a projectile in a frame that
 * accelerates at A (no rotation), exact r = v0 t + (g - A) t^2/2. Planned
 * with "auto": at 1e-3 the translational term (|A| t^2/2 ~ 3e-5 of the
 * path) is left out, at 1e-8 it is carried, and the planned run meets each
 * target against the exact path (within the prediction factor 30, relative
 * to the path's size); the first pass's steps come off the budget; a dry run
 * keeps every term and runs nothing; a given method is kept; the closed
 * form is chosen where the scene has one unless closed_form_off; a target
 * out of range fails in the choice stage, a budget too small for the first
 * pass in the model stage. */
#include <math.h>
#include <string.h>

#include "mech/frames/trajectory.h"
#include "mech/frames/trajectory_plan.h"
#include "testlib.h"

#define NS 61
static double ts[NS];
static struct mech_vec3 pos[NS], vel[NS];
static struct mech_force forces[1];

static const struct mech_vec3 A_FRAME = {1e-4, 0, 2e-4};

static struct mech_trajectory_problem scene(void)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    p.frame.type = MECH_FRAME_ROTATING; /* omega = 0: an accelerating frame */
    p.frame.acceleration = A_FRAME;
    forces[0].type = MECH_FORCE_UNIFORM_GRAVITY;
    forces[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
    p.forces = forces;
    p.n_forces = 1;
    p.velocity = mech_vec3_make(20, 0, 30);
    p.t_end = 6.0;
    p.samples = NS;
    p.reduce_planar = 1;
    p.closed_form_off = 1;
    return p;
}

/* max |r(t_i) - (v0 t + (g - A) t^2/2)| over the run's samples. */
static double path_error(const struct mech_trajectory_problem *p, size_t n)
{
    const struct mech_vec3 ga = mech_vec3_sub(forces[0].u.uniform_gravity.g, A_FRAME);
    double err = 0.0;
    for (size_t i = 0; i < n; i++) {
        struct mech_vec3 ex = mech_vec3_add(mech_vec3_scale(p->velocity, ts[i]),
                                            mech_vec3_scale(ga, 0.5 * ts[i] * ts[i]));
        err = fmax(err, mech_vec3_norm(mech_vec3_sub(pos[i], ex)));
    }
    return err;
}

static void plan_and_run(double target, unsigned want_mask)
{
    struct mech_trajectory_problem p = scene();
    const struct mech_trajectory_plan_request q = {1, 0, target, 1, target};
    struct mech_budget b = mech_budget_make(1000000, 600.0);
    struct mech_trajectory_plan plan;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_plan(&p, &q, &b, &plan, &e), MECH_OK);
    CHECK(plan.modelled && plan.chosen && !plan.closed_form);
    CHECK_EQ_INT((int)p.fictitious, (int)want_mask);
    CHECK(plan.model.first_pass_done && plan.model.first_pass_stats.steps > 0);
    CHECK(b.max_steps == 1000000 - plan.model.first_pass_stats.steps);
    CHECK(p.method == plan.choice.method && p.opt.rtol == plan.choice.opt.rtol);
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r);
    r.t = ts;
    r.position = pos;
    r.velocity = vel;
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, &e), MECH_OK);
    /* the path's size: |v0| t_end ~ 216 m */
    const double L = mech_vec3_norm(p.velocity) * p.t_end;
    const double rel = path_error(&p, r.n_samples) / L;
    printf("target %.0e: fictitious 0x%x, %s rtol %.3g, error %.3g of the path\n", target,
           p.fictitious, p.method, p.opt.rtol, rel);
    CHECK(rel <= 30.0 * target);
}

int main(void)
{
    /* |A| t^2/2 = 3.6e-3 m over ~216 m: 1.7e-5 — negligible at 1e-3, not at 1e-8 */
    plan_and_run(1e-3, 0u);
    plan_and_run(1e-8, MECH_FICTITIOUS_TRANSLATIONAL);

    struct mech_trajectory_plan plan;
    struct mech_error e;
    mech_error_clear(&e);
    /* a dry run: every applicable term, nothing run, the budget untouched */
    {
        struct mech_trajectory_problem p = scene();
        const struct mech_trajectory_plan_request q = {1, 1, 1e-8, 1, 1e-8};
        struct mech_budget b = mech_budget_make(1000, 600.0);
        CHECK_EQ_INT(mech_trajectory_plan(&p, &q, &b, &plan, &e), MECH_OK);
        CHECK(!plan.modelled && plan.chosen && p.fictitious == MECH_FICTITIOUS_ALL);
        CHECK(b.max_steps == 1000);
    }
    /* a given method: kept, terms as given, nothing chosen */
    {
        struct mech_trajectory_problem p = scene();
        p.method = "rk4";
        p.opt.dt = 0.01;
        p.fictitious = MECH_FICTITIOUS_TRANSLATIONAL;
        const struct mech_trajectory_plan_request q = {0, 0, 1e-8, 0, 0.0};
        struct mech_budget b = mech_budget_make(1000, 600.0);
        CHECK_EQ_INT(mech_trajectory_plan(&p, &q, &b, &plan, &e), MECH_OK);
        CHECK(!plan.modelled && !plan.chosen && !strcmp(p.method, "rk4") && p.opt.dt == 0.01);
        CHECK(p.fictitious == MECH_FICTITIOUS_TRANSLATIONAL && b.max_steps == 1000);
    }
    /* the closed form: an inertial projectile has one; closed_form_off keeps it out */
    {
        struct mech_trajectory_problem p = scene();
        p.frame.type = MECH_FRAME_INERTIAL;
        p.frame.acceleration = mech_vec3_make(0, 0, 0);
        p.closed_form_off = 0;
        const struct mech_trajectory_plan_request q = {0, 0, 1e-8, 1, 1e-8};
        struct mech_budget b = mech_budget_make(1000, 600.0);
        CHECK_EQ_INT(mech_trajectory_plan(&p, &q, &b, &plan, &e), MECH_OK);
        CHECK(plan.chosen && plan.closed_form && plan.choice.closed_form);
        CHECK(p.method && strcmp(p.method, "closed_form") != 0); /* the best integrator's */
        p.closed_form_off = 1;
        CHECK_EQ_INT(mech_trajectory_plan(&p, &q, &b, &plan, &e), MECH_OK);
        CHECK(plan.chosen && !plan.closed_form);
    }
    /* the stages of a failure */
    {
        struct mech_trajectory_problem p = scene();
        const struct mech_trajectory_plan_request bad = {0, 0, 1e-8, 1, 0.5};
        struct mech_budget b = mech_budget_make(1000, 600.0);
        CHECK_EQ_INT(mech_trajectory_plan(&p, &bad, &b, &plan, &e), MECH_EINVAL);
        CHECK(plan.failed == MECH_PLAN_CHOICE);
        p = scene();
        const struct mech_trajectory_plan_request q = {1, 0, 1e-8, 1, 1e-8};
        struct mech_budget tiny = mech_budget_make(2, 600.0);
        CHECK_EQ_INT(mech_trajectory_plan(&p, &q, &tiny, &plan, &e), MECH_EBUDGET);
        CHECK(plan.failed == MECH_PLAN_MODEL && !plan.modelled);
        CHECK_EQ_INT(mech_trajectory_plan(NULL, &q, &tiny, &plan, &e), MECH_EINVAL);
        CHECK_EQ_INT(mech_trajectory_plan(&p, &q, NULL, &plan, &e), MECH_EINVAL);
    }
    TEST_MAIN_END();
}
