/* test_reference_scales.c — the exact references seen from a rotating frame
 * and the scales the reference report divides by:
 *   the isotropic oscillator from a frame turning at 0.3 rad/s about its
 *   anchor's axis, at t = pi/2, against the state worked out by hand (the
 *   inertial ellipse x = cos t, y = 0.8 sin t turned back by 0.3 t);
 *   an rk8pd run of that scene at rtol 1e-13 agrees with the reference to
 *   1e-10 (the integrator knows nothing of the reference);
 *   the anchor off the axis, a drag force or Coriolis alone: no exact
 *   reference (those motions are not the inertial closed forms turned);
 *   a 1-D oscillator sampled once a period (at rest at every sample): the
 *   relative velocity error is against the run's speed scale (about 1),
 *   never against the sampled |v| ~ 1e-16, and stays within 10x of the
 *   position error.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/frames/closed_form.h"
#include "mech/base/constants.h"
#include "mech/frames/reference.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

enum { NS = 101 };
static double ts[NS];
static struct mech_vec3 pos[NS], vel[NS];

static enum mech_status run(const struct mech_trajectory_problem *p,
                            struct mech_trajectory_result *r, struct mech_error *e)
{
    struct mech_budget b = mech_budget_make(20000000, 600.0);
    memset(r, 0, sizeof *r);
    r->t = ts;
    r->position = pos;
    r->velocity = vel;
    mech_error_clear(e);
    return mech_trajectory_integrate(p, &b, r, e);
}

static void rotating_oscillator(struct mech_trajectory_problem *p, struct mech_force *f)
{
    memset(p, 0, sizeof *p);
    memset(f, 0, sizeof *f);
    f->type = MECH_FORCE_SPRING;
    f->u.spring.k = 1.0;
    p->mass = 1.0;
    p->position = mech_vec3_make(1, 0, 0);
    p->velocity = mech_vec3_make(0, 0.5, 0);
    p->forces = f;
    p->n_forces = 1;
    p->frame.type = MECH_FRAME_ROTATING;
    p->frame.omega = mech_vec3_make(0, 0, 0.3);
    p->fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    p->t_end = 40.0 * MECH_PI;
    p->samples = NS;
}

static void test_rotating_oscillator(void)
{
    struct mech_trajectory_problem p;
    struct mech_force f;
    rotating_oscillator(&p, &f);
    struct mech_trajectory_reference ref;
    CHECK_EQ_INT(mech_trajectory_reference_find(&p, &ref), MECH_REFERENCE_EXACT);
    CHECK(!strcmp(ref.name, "harmonic_oscillator_rotating"));
    CHECK(!mech_trajectory_has_closed_form(&p)); /* evidence only, never the answer */
    /* by hand: inertial v0 = (0, 0.5 + 0.3, 0), so r_I(pi/2) = (0, 0.8, 0),
     * v_I = (-1, 0, 0); turned back by th = 0.3 pi/2:
     * r = (0.8 sin th, 0.8 cos th, 0), v = (-0.76 cos th, 0.76 sin th, 0) */
    struct mech_vec3 r, v;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_reference_eval(&ref, MECH_PI / 2, &r, &v, NULL, &e), MECH_OK);
    const double th = 0.3 * MECH_PI / 2;
    CHECK_CLOSE(r.x, 0.8 * sin(th), 0, 1e-15);
    CHECK_CLOSE(r.y, 0.8 * cos(th), 0, 1e-15);
    CHECK_CLOSE(v.x, -0.76 * cos(th), 0, 1e-15);
    CHECK_CLOSE(v.y, 0.76 * sin(th), 0, 1e-15);
    CHECK_CLOSE(r.z, 0.0, 0, 1e-300);

    /* the integrator agrees with it */
    p.method = "rk8pd";
    p.opt.rtol = 1e-13;
    p.opt.atol = 1e-13;
    struct mech_trajectory_result res;
    CHECK_EQ_INT(run(&p, &res, &e), MECH_OK);
    CHECK_EQ_INT(res.reference.kind, MECH_REFERENCE_EXACT);
    printf("rotating oscillator, rk8pd 1e-13: rel error %.3g (position), %.3g (velocity)\n",
           res.reference.max_relative_position_error, res.reference.max_relative_velocity_error);
    CHECK(res.reference.max_relative_position_error < 1e-10);
    CHECK(res.reference.max_relative_velocity_error < 1e-10);
    /* a loose run is measured as loose (the reference is not the run) */
    p.method = "rkf45";
    p.opt.rtol = p.opt.atol = 1e-5;
    CHECK_EQ_INT(run(&p, &res, &e), MECH_OK);
    CHECK(res.reference.max_relative_position_error > 1e-6);
    CHECK(res.reference.max_relative_position_error < 1e-1);

    /* not the inertial closed form turned: no exact reference */
    struct mech_trajectory_problem q = p;
    struct mech_force g = f;
    g.u.spring.anchor = mech_vec3_make(0.5, 0, 0); /* off the axis */
    q.forces = &g;
    CHECK_EQ_INT(mech_trajectory_reference_find(&q, &ref), MECH_REFERENCE_NONE);
    q = p;
    q.fictitious = MECH_FICTITIOUS_CORIOLIS; /* centrifugal left out */
    CHECK(mech_trajectory_reference_find(&q, &ref) != MECH_REFERENCE_EXACT);
    q = p;
    struct mech_force two[2] = {f, {.type = MECH_FORCE_LINEAR_DRAG}};
    two[1].u.linear_drag.b = 0.1;
    q.forces = two;
    q.n_forces = 2;
    CHECK(mech_trajectory_reference_find(&q, &ref) != MECH_REFERENCE_EXACT);
    q = p;
    g = f;
    g.u.spring.anchor = mech_vec3_make(0, 0, 2); /* on the axis: still exact */
    q.forces = &g;
    CHECK_EQ_INT(mech_trajectory_reference_find(&q, &ref), MECH_REFERENCE_EXACT);
}

static void test_one_d_oscillator_scale(void)
{
    struct mech_trajectory_problem p;
    struct mech_force f = {.type = MECH_FORCE_SPRING};
    f.u.spring.k = 1.0;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    p.position = mech_vec3_make(1, 0, 0); /* from rest: x = cos t */
    p.forces = &f;
    p.n_forces = 1;
    p.t_end = 200.0 * MECH_PI; /* 100 periods, sampled once a period: v = -sin(2 pi k) ~ 0 */
    p.samples = NS;
    p.method = "rk8pd";
    p.opt.rtol = p.opt.atol = 1e-6;
    struct mech_trajectory_result res;
    struct mech_error e;
    CHECK_EQ_INT(run(&p, &res, &e), MECH_OK);
    const double ep = res.reference.max_relative_position_error,
                 ev = res.reference.max_relative_velocity_error;
    printf("1-D oscillator, 100 periods, rk8pd 1e-6: rel error %.3g (position), %.3g "
           "(velocity, against the speed scale %.3g)\n",
           ep, ev, res.max_speed);
    CHECK(ep > 1e-9 && ep < 1e-3);
    CHECK(ev > 1e-9 && ev < 10.0 * ep + 1e-12);
    CHECK_CLOSE(res.max_speed, 1.0, 1e-3, 0);
    /* the same oscillator about an anchor far from the origin: relative to
     * the amplitude (1), not to |r| ~ 1000 */
    f.u.spring.anchor = mech_vec3_make(1000, 0, 0);
    p.position = mech_vec3_make(1001, 0, 0);
    p.opt.atol = 1e-6;
    CHECK_EQ_INT(run(&p, &res, &e), MECH_OK);
    CHECK(res.reference.max_relative_position_error > 1e-9);
    CHECK_CLOSE(res.reference.max_relative_position_error * 1.0,
                res.reference.max_position_error, 1e-3, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_rotating_oscillator();
    test_one_d_oscillator_scale();
    TEST_MAIN_END();
}
