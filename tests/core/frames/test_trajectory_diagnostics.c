/* test_trajectory_diagnostics.c — the error evidence mech_trajectory_integrate
 * reports, and the promises of the accuracy presets:
 *   each preset (draft 1e-3, balanced 1e-8, precise 1e-10, machine 1e-11
 *   relative) meets its promise against the exact references: Kepler e = 0.5
 *   and e = 0.9 over 10 orbits, a harmonic oscillator over 20 periods, a
 *   projectile with drag; target_error likewise; the presets' scene set (Kepler 10
 *   and 1000 orbits, oscillator 1e4 periods, falling object with Coriolis):
 *   each preset within its promise or its stated round-off floor, and the
 *   four presets four computations of rising cost (rhs evaluations);
 *   the reference report equals an independent recomputation from the samples;
 *   invariants: energy + angular momentum for a central scene, energy alone
 *   with uniform gravity, the Jacobi integral in a rotating frame;
 *   the error estimate of a scene without a reference (central gravity plus a
 *   uniform field) brackets the true error measured against a tight run;
 *   the Lorentz split used by boris agrees with the acceleration;
 *   an overflowing force stops with MECH_ENUMERIC naming t and the position.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/frames/reference.h"
#include "mech/base/constants.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

enum { NS = 401 };
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

static struct mech_force kepler_force(void)
{
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = MECH_EARTH_GM;
    return f;
}

/* Kepler orbit of eccentricity e, periapsis 7e6 m, n_orbits long. */
static struct mech_trajectory_problem kepler_problem(const struct mech_force *f, double e,
                                                     double n_orbits)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    const double gm = f->u.central_gravity.gm, q = 7e6, a = q / (1 - e);
    p.mass = 1000;
    p.position = mech_vec3_make(q, 0, 0);
    p.velocity = mech_vec3_make(0, sqrt(gm * (1 + e) / q), 0);
    p.forces = f;
    p.n_forces = 1;
    p.t_end = n_orbits * 2 * MECH_PI * sqrt(a * a * a / gm);
    p.samples = 201;
    p.closed_form_off = 1; /* these check the integrating presets */
    return p;
}

static void apply_choice(struct mech_trajectory_problem *p, double target)
{
    struct mech_trajectory_choice ch;
    CHECK_EQ_INT(mech_trajectory_choose(p, target, &ch, NULL), MECH_OK);
    p->method = ch.method;
    p->opt = ch.opt;
}

/* Each preset on scene p: the relative errors against the exact reference. */
static void check_presets(struct mech_trajectory_problem p, const char *scene)
{
    for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
        const struct mech_accuracy_preset *pr = mech_accuracy_preset_at((enum mech_accuracy)a);
        apply_choice(&p, pr->promise);
        struct mech_trajectory_result r;
        struct mech_error e;
        enum mech_status st = run(&p, &r, &e);
        CHECK_EQ_INT(st, MECH_OK);
        if (st != MECH_OK) {
            printf("%s %s: %s\n", scene, pr->name, e.text);
            continue;
        }
        CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_EXACT);
        double er = fmax(r.reference.max_relative_position_error,
                         r.reference.max_relative_velocity_error);
        printf("%-24s %-8s %-6s rtol %.1e: rel error %.3e (promise %.0e), %ld steps, %ld rhs\n",
               scene, pr->name, p.method, p.opt.rtol, er, pr->promise, r.stats.steps,
               r.stats.rhs_evaluations);
        CHECK(er <= pr->promise);
    }
}

/* Presets that mean what they say: on Kepler e = 0.5 and 0.9 over
 * 10 and 1000 orbits each preset meets its promise, or (long runs at balanced,
 * precise and machine) the selection re-states it and the error
 * stays within the stated round-off floor; and the four presets are four
 * different computations (the predictive chooser picks the cheapest method
 * predicted to meet each target: a tighter preset may be a different method
 * with fewer evaluations), and draft is cheaper than machine on every scene. */
static void test_presets_issue_set(void)
{
    struct mech_force f = kepler_force();
    const double es[2] = {0.5, 0.9}, ns[2] = {10, 1000};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            struct mech_trajectory_problem p = kepler_problem(&f, es[i], ns[j]);
            long rhs[MECH_ACCURACY_COUNT];
            const char *methods[MECH_ACCURACY_COUNT];
            double rtols[MECH_ACCURACY_COUNT];
            int beyonds[MECH_ACCURACY_COUNT];
            for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
                const struct mech_accuracy_preset *pr =
                    mech_accuracy_preset_at((enum mech_accuracy)a);
                struct mech_trajectory_choice ch;
                CHECK_EQ_INT(mech_trajectory_choose(&p, pr->promise, &ch, NULL), MECH_OK);
                p.method = ch.method;
                p.opt = ch.opt;
                methods[a] = ch.method;
                rtols[a] = ch.opt.rtol;
                struct mech_trajectory_result r;
                struct mech_error e;
                CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
                CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_EXACT);
                double er = fmax(r.reference.max_relative_position_error,
                                 r.reference.max_relative_velocity_error);
                /* re-stated (the reason says "beyond what the preset can keep"):
                 * within the chooser's stated factor (30) of the floor it predicted */
                const int beyond = strstr(ch.reason, "beyond what the preset can keep") != NULL;
                CHECK(beyond == (mech_selection_restated(&ch.sel) > 0.0));
                const double bound =
                    beyond ? fmax(pr->promise, 30.0 * ch.sel.roundoff_floor) : pr->promise;
                /* at the tightest setting (near the floor, re-stated or not) */
                beyonds[a] = ch.sel.beyond != 0;
                printf("kepler e=%.1f %4.0f orbits %-8s %-7s rtol %.2e: rel error %.3e (bound "
                       "%.1e%s), %ld rhs\n",
                       es[i], ns[j], pr->name, ch.method, ch.opt.rtol, er, bound,
                       beyond ? ", beyond" : "", r.stats.rhs_evaluations);
                CHECK(er <= bound);
                /* draft is kept on every scene of the set, balanced unless the
                 * answer re-states it (1000 orbits of e = 0.9: the envelope of
                 * the round-off floor there is 2.2e-8) */
                if (a == MECH_ACCURACY_DRAFT || (a == MECH_ACCURACY_BALANCED && !beyond))
                    CHECK(er <= pr->promise);
                rhs[a] = r.stats.rhs_evaluations;
            }
            /* different computations, except presets both beyond the floor */
            for (int a = 1; a < MECH_ACCURACY_COUNT; a++)
                if (!(beyonds[a] && beyonds[a - 1]))
                    CHECK(strcmp(methods[a], methods[a - 1]) != 0 || rtols[a] != rtols[a - 1]);
            CHECK(rhs[MECH_ACCURACY_DRAFT] < rhs[MECH_ACCURACY_MACHINE]);
        }
}

/* The oscillator over 1e4 periods (exact reference) and the falling object,
 * 100 m at 32 deg N with Coriolis (velocity-dependent: rkf45 / rk8pd),
 * against an independent radau15 run at its round-off floor: every preset within its promise (the oscillator's machine within
 * the stated round-off floor), draft cheaper than machine on the oscillator. */
static void test_presets_oscillator_falling(void)
{
    struct mech_force s = {.type = MECH_FORCE_SPRING};
    s.u.spring.k = 50;
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 2;
    p.position = mech_vec3_make(0.1, 0, 0);
    p.velocity = mech_vec3_make(0, 0.2, 0);
    p.forces = &s;
    p.n_forces = 1;
    p.t_end = 1e4 * 2 * MECH_PI / 5;
    p.samples = 201;
    p.closed_form_off = 1;
    long rhs[MECH_ACCURACY_COUNT];
    for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
        const struct mech_accuracy_preset *pr = mech_accuracy_preset_at((enum mech_accuracy)a);
        struct mech_trajectory_choice ch;
        CHECK_EQ_INT(mech_trajectory_choose(&p, pr->promise, &ch, NULL), MECH_OK);
        p.method = ch.method;
        p.opt = ch.opt;
        struct mech_trajectory_result r;
        struct mech_error e;
        CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
        CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_EXACT);
        double er = fmax(r.reference.max_relative_position_error,
                         r.reference.max_relative_velocity_error);
        const int beyond = strstr(ch.reason, "beyond what the preset can keep") != NULL;
        /* span = t_end / sqrt(|r0| / |a0|) = 1e4 x 2 pi */
        const double bound =
            beyond ? fmax(pr->promise, 30.0 * ch.sel.roundoff_floor) : pr->promise;
        printf("oscillator 1e4 periods %-8s %-7s rtol %.2e: rel error %.3e (bound %.1e), %ld rhs\n",
               pr->name, ch.method, ch.opt.rtol, er, bound, r.stats.rhs_evaluations);
        CHECK(er <= bound);
        rhs[a] = r.stats.rhs_evaluations;
    }
    CHECK(rhs[MECH_ACCURACY_DRAFT] < rhs[MECH_ACCURACY_MACHINE]);

    struct mech_force g = {.type = MECH_FORCE_UNIFORM_GRAVITY};
    g.u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
    memset(&p, 0, sizeof p);
    p.mass = 1;
    p.position = mech_vec3_make(0, 0, 100);
    p.forces = &g;
    p.n_forces = 1;
    p.frame.type = MECH_FRAME_EARTH;
    p.frame.latitude_deg = 32;
    p.frame.omega_magnitude = MECH_EARTH_OMEGA; /* the Earth's rate, rad/s */
    p.fictitious = MECH_FICTITIOUS_CORIOLIS;
    p.t_end = sqrt(2 * 100 / 9.80665);
    p.samples = 51;
    enum { NF = 51 };
    static struct mech_vec3 rp[NF], rv[NF];
    p.method = "radau15"; /* independent of the presets' rkf45 / rk8pd, at round-off */
    p.opt.rtol = 1e-9;
    p.opt.atol = 1e-14;
    struct mech_trajectory_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    memcpy(rp, pos, sizeof rp);
    memcpy(rv, vel, sizeof rv);
    const double vmax = 9.80665 * p.t_end;
    for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
        const struct mech_accuracy_preset *pr = mech_accuracy_preset_at((enum mech_accuracy)a);
        apply_choice(&p, pr->promise);
        CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
        double er = 0;
        for (int k = 0; k < NF; k++) {
            er = fmax(er, mech_vec3_norm(mech_vec3_sub(pos[k], rp[k])) / 100);
            er = fmax(er, mech_vec3_norm(mech_vec3_sub(vel[k], rv[k])) / vmax);
        }
        printf("falling 100 m Coriolis %-8s %-7s rtol %.2e: rel error %.3e (promise %.0e)\n",
               pr->name, p.method, p.opt.rtol, er, pr->promise);
        CHECK(er <= pr->promise);
    }
}

static void test_presets(void)
{
    struct mech_force f = kepler_force();
    check_presets(kepler_problem(&f, 0.5, 10), "kepler e=0.5 10 orbits");
    check_presets(kepler_problem(&f, 0.9, 10), "kepler e=0.9 10 orbits");
    check_presets(kepler_problem(&f, 0.0, 10), "kepler circular 10");

    struct mech_force s[2] = {{.type = MECH_FORCE_SPRING}, {.type = MECH_FORCE_UNIFORM_GRAVITY}};
    s[0].u.spring.k = 50;
    s[1].u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 2;
    p.position = mech_vec3_make(0.1, 0, -0.3);
    p.velocity = mech_vec3_make(0, 0.2, 0);
    p.forces = s;
    p.n_forces = 2;
    p.t_end = 20 * 2 * MECH_PI / 5;
    p.samples = 201;
    check_presets(p, "oscillator 20 periods");

    struct mech_force d[2] = {{.type = MECH_FORCE_UNIFORM_GRAVITY}, {.type = MECH_FORCE_LINEAR_DRAG}};
    d[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
    d[1].u.linear_drag.b = 0.02;
    memset(&p, 0, sizeof p);
    p.mass = 0.145;
    p.position = mech_vec3_make(0, 0, 1);
    p.velocity = mech_vec3_make(30, 0, 25);
    p.forces = d;
    p.n_forces = 2;
    p.t_end = 6;
    p.samples = 101;
    check_presets(p, "projectile with drag");

    /* target_error between presets, and out of range */
    struct mech_trajectory_problem k = kepler_problem(&f, 0.5, 10);
    const double targets[] = {1e-4, 1e-6, 1e-9, 1e-10, 1e-12};
    for (int i = 0; i < 5; i++) {
        apply_choice(&k, targets[i]);
        struct mech_trajectory_result r;
        struct mech_error e;
        CHECK_EQ_INT(run(&k, &r, &e), MECH_OK);
        double er = fmax(r.reference.max_relative_position_error,
                         r.reference.max_relative_velocity_error);
        printf("kepler e=0.5 target %.0e: %s rtol %.2e: rel error %.3e, %ld steps\n", targets[i],
               k.method, k.opt.rtol, er, r.stats.steps);
        CHECK(er <= targets[i]);
    }
    struct mech_trajectory_choice ch;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_choose(&k, 1e-16, &ch, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "integrator/target_error"));
    CHECK(mech_accuracy_preset_at(MECH_ACCURACY_COUNT) == NULL);
}

static void test_reference_report(void)
{
    struct mech_force f = kepler_force();
    struct mech_trajectory_problem p = kepler_problem(&f, 0.7, 2);
    p.method = "rkf45";
    p.opt.rtol = 1e-7;
    p.opt.atol = 1e-3;
    struct mech_trajectory_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    CHECK(!strcmp(r.reference.name, "kepler"));
    /* recompute from the samples with the propagator itself */
    double mx = 0, fin = 0;
    for (size_t i = 0; i < r.n_samples; i++) {
        struct mech_vec3 rr, vv;
        CHECK_EQ_INT(mech_kepler_propagate(f.u.central_gravity.gm, p.position, p.velocity, ts[i],
                                           &rr, &vv, NULL),
                     MECH_OK);
        fin = mech_vec3_norm(mech_vec3_sub(pos[i], rr));
        mx = fmax(mx, fin);
    }
    CHECK_CLOSE(r.reference.max_position_error, mx, 1e-15, 0);
    CHECK_CLOSE(r.reference.final_position_error, fin, 1e-15, 0);
    printf("rkf45 rtol 1e-7 kepler e=0.7: max error %.3e m\n", mx);
    CHECK(mx > 1.0); /* a loose method shows a visible error */

    /* invariants: energy and angular momentum */
    CHECK_EQ_INT(r.n_invariants, 2);
    CHECK(!strcmp(r.invariants[0].name, "energy"));
    CHECK(!strcmp(r.invariants[1].name, "angular_momentum"));
    double h = p.mass * p.position.x * p.velocity.y;
    CHECK_CLOSE(r.invariants[1].initial, h, 1e-15, 0);
    CHECK_CLOSE(r.invariants[1].initial_vector.z, h, 1e-15, 0);
    CHECK(r.invariants[1].max_relative_drift > 0 && r.invariants[1].max_relative_drift < 1e-3);
    CHECK_CLOSE(r.invariant.initial, r.invariants[0].initial, 0, 0);

    /* uniform gravity: no angular momentum, exact reference */
    struct mech_force g = {.type = MECH_FORCE_UNIFORM_GRAVITY};
    g.u.uniform_gravity.g = mech_vec3_make(0, 0, -9.8);
    p.forces = &g;
    p.t_end = 3;
    p.method = "rk4";
    p.opt.dt = 0.01;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    CHECK_EQ_INT(r.n_invariants, 1);
    CHECK(!strcmp(r.reference.name, "uniform_gravity"));
    /* rk4 is exact on a quadratic: round-off only */
    CHECK(r.reference.max_position_error < 1e-8 * 7e6);

    /* rotating frame, central force at the origin (on the axis): the Jacobi
     * integral, and the inertial Kepler orbit turned back as the exact
     * reference (rk8pd at 1e-12 over 6000 s keeps it to ~1e-9) */
    p.forces = &f;
    p.frame.type = MECH_FRAME_ROTATING;
    p.frame.omega = mech_vec3_make(0, 0, 1e-4);
    p.fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    p.method = "rk8pd";
    p.opt.rtol = 1e-12;
    p.opt.atol = 0;
    p.t_end = 6000;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    CHECK_EQ_INT(r.n_invariants, 1);
    CHECK(!strcmp(r.invariants[0].name, "jacobi_integral"));
    CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_EXACT);
    CHECK(!strcmp(r.reference.name, "kepler_rotating"));
    CHECK(r.reference.max_relative_position_error < 1e-8);
    CHECK(r.reference.max_relative_position_error > 1e-16); /* compared, not copied */
    CHECK(r.invariants[0].max_relative_drift < 1e-10);
    /* the centre off the axis moves in the inertial frame: no reference */
    struct mech_force off = f;
    off.u.central_gravity.center = mech_vec3_make(1e3, 0, 0);
    p.forces = &off;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_NONE);
    p.forces = &f;
}

static void test_error_estimate(void)
{
    /* Central gravity plus a uniform field: no reference. The estimate (rtol/100
     * rerun) should be within a factor of a few of the true error, measured
     * here against an rk8pd run at rtol 1e-14. */
    struct mech_force f[2] = {kepler_force(), {.type = MECH_FORCE_UNIFORM_GRAVITY}};
    f[1].u.uniform_gravity.g = mech_vec3_make(0.05, 0, 0);
    struct mech_trajectory_problem p = kepler_problem(&f[0], 0.3, 3);
    p.forces = f;
    p.n_forces = 2;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    p.opt.atol = 0;
    struct mech_trajectory_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    static struct mech_vec3 truth[NS];
    memcpy(truth, pos, sizeof truth);
    CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_NONE);
    CHECK_EQ_INT(r.error_estimate.done, 0);

    const char *methods[] = {"rkf45", "rk8pd", "rk4"};
    for (int m = 0; m < 3; m++) {
        p.method = methods[m];
        p.opt.rtol = 1e-8;
        p.opt.atol = 0;
        p.opt.dt = 20;
        p.error_estimate = 1;
        CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
        double err = 0;
        for (size_t i = 0; i < r.n_samples; i++)
            err = fmax(err, mech_vec3_norm(mech_vec3_sub(pos[i], truth[i])));
        CHECK(r.error_estimate.done);
        double est = r.error_estimate.max_position_error_estimate;
        printf("error estimate %s: estimate %.3e m, true %.3e m (ratio %.2f), steps %ld + %ld\n",
               methods[m], est, err, est / err, r.stats.steps, r.error_estimate.stats.steps);
        CHECK(est > 0.3 * err && est < 3 * err);
        CHECK_EQ_INT(r.total_steps, r.stats.steps + r.error_estimate.stats.steps);
    }
    /* radau15 at its eps floor: the estimate uses rk8pd at rtol 1e-14 instead
     * (a second radau15 run would repeat the first bit for bit) */
    p.method = "radau15";
    p.opt.rtol = 1e-10;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    {
        double err = 0;
        for (size_t i = 0; i < r.n_samples; i++)
            err = fmax(err, mech_vec3_norm(mech_vec3_sub(pos[i], truth[i])));
        CHECK(!strcmp(r.error_estimate.method, "rk8pd"));
        printf("error estimate radau15 at round-off: estimate %.3e m vs rk8pd 1e-14, true %.3e m\n",
               r.error_estimate.max_position_error_estimate, err);
        CHECK(r.error_estimate.max_position_error_estimate > 0);
        CHECK(r.error_estimate.max_position_error_estimate < 1e-3); /* 1e-10 of 7e6 m */
    }
    /* The estimate shares the budget: a budget the first run fits in but not both. */
    p.method = "rk4";
    p.opt.dt = 20;
    struct mech_budget b = mech_budget_make((long)ceil(p.t_end / 20) + 10, 60);
    memset(&r, 0, sizeof r);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, &e), MECH_EBUDGET);
}

/* boris runs on the Lorentz split (e = forces/m + centrifugal, w = 2W): in a
 * rotating frame with both fictitious terms and a central force its answer
 * converges to rk8pd's at second order (dt -> dt/2: error / 4). */
static void test_boris_split(void)
{
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = 1.0;
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1;
    p.position = mech_vec3_make(1, 0, 0.1);
    p.velocity = mech_vec3_make(0, 0.8, 0);
    p.frame.type = MECH_FRAME_ROTATING;
    p.frame.omega = mech_vec3_make(0, 0.1, 0.5);
    p.fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    p.forces = &f;
    p.n_forces = 1;
    p.t_end = 5;
    p.samples = 11;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    struct mech_trajectory_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_OK);
    struct mech_vec3 want = pos[10];
    double errs[2];
    for (int k = 0; k < 2; k++) {
        p.method = "boris";
        p.opt.dt = k ? 5e-4 : 1e-3;
        enum mech_status st = run(&p, &r, &e);
        CHECK_EQ_INT(st, MECH_OK);
        if (st != MECH_OK) {
            printf("boris: %s\n", e.text);
            return;
        }
        errs[k] = mech_vec3_norm(mech_vec3_sub(pos[10], want));
    }
    printf("boris rotating frame: error %.3e (dt 1e-3), %.3e (dt 5e-4), ratio %.2f\n", errs[0],
           errs[1], errs[0] / errs[1]);
    CHECK(errs[0] < 1e-4);
    CHECK(errs[0] / errs[1] > 3.5 && errs[0] / errs[1] < 4.5);
    /* with drag there is no split: boris is refused with a typed error */
    struct mech_force fd[2] = {f, {.type = MECH_FORCE_LINEAR_DRAG}};
    fd[1].u.linear_drag.b = 0.1;
    p.forces = fd;
    p.n_forces = 2;
    enum mech_status st = run(&p, &r, &e);
    printf("boris with drag: %s (%s)\n", mech_status_name(st), e.text);
    CHECK(st != MECH_OK && st != MECH_EINTERNAL);
}

/* Extremes: t_end tiny, solar-system scale, e -> 1 and a hyperbolic flyby,
 * each with the default (balanced) choice, against the exact Kepler solution. */
static void test_extremes(void)
{
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    struct mech_trajectory_problem p;
    struct mech_trajectory_result r;
    struct mech_error e;
    const struct {
        const char *what;
        double gm, q, ecc, t_end;
    } sc[] = {
        {"t_end 1e-9 s", MECH_EARTH_GM, 7e6, 0.1, 1e-9},
        {"sun-earth, 1 year", 1.32712440018e20, 1.471e11, 0.0167, 3.15581e7},
        {"e = 0.999, 1 orbit", 1.0, 1.0, 0.999, 2 * MECH_PI * pow(1.0 / 0.001, 1.5)},
        {"hyperbolic e = 3", MECH_EARTH_GM, 7e6, 3.0, 5e4},
        {"micro scale", 1e-20, 1e-9, 0.6, 2 * MECH_PI * sqrt(pow(1e-9 / 0.4, 3) / 1e-20) * 3},
    };
    for (size_t k = 0; k < sizeof sc / sizeof sc[0]; k++) {
        f.u.central_gravity.gm = sc[k].gm;
        memset(&p, 0, sizeof p);
        p.mass = 1;
        p.position = mech_vec3_make(sc[k].q, 0, 0);
        p.velocity = mech_vec3_make(0, sqrt(sc[k].gm * (1 + sc[k].ecc) / sc[k].q), 0);
        p.forces = &f;
        p.n_forces = 1;
        p.t_end = sc[k].t_end;
        p.samples = 101;
        apply_choice(&p, mech_accuracy_preset_at(MECH_ACCURACY_BALANCED)->promise);
        enum mech_status st = run(&p, &r, &e);
        CHECK_EQ_INT(st, MECH_OK);
        if (st != MECH_OK) {
            printf("%s: %s\n", sc[k].what, e.text);
            continue;
        }
        double er = fmax(r.reference.max_relative_position_error,
                         r.reference.max_relative_velocity_error);
        printf("extreme %-20s %s: rel error %.3e, %ld steps\n", sc[k].what, p.method, er,
               r.stats.steps);
        CHECK(!strcmp(r.reference.name, "kepler"));
        /* Known limit: at e = 0.999 the orbit is ill-conditioned (round-off in
         * the state grows by ~2/(1 - e) through the periapsis passage, where
         * t = P puts the last sample); measured over one orbit: radau15 4e-8
         * relative (velocity) at balanced, 2.3e-8 even at machine, rk8pd at
         * rtol 1e-14 4e-7. Balanced keeps 2e-7 here, not 1e-8. */
        CHECK(er <= (sc[k].ecc > 0.99 && sc[k].ecc < 1 ? 2e-7 : 1e-8));
    }
}

static void test_nonfinite(void)
{
    /* A stiff spring integrated with a far too long fixed step overflows. */
    struct mech_force s = {.type = MECH_FORCE_SPRING};
    s.u.spring.k = 1e30;
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1e-3;
    p.position = mech_vec3_make(1, 0, 0);
    p.forces = &s;
    p.n_forces = 1;
    p.t_end = 100;
    p.samples = 11;
    p.method = "rk4";
    p.opt.dt = 1;
    struct mech_trajectory_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&p, &r, &e), MECH_ENUMERIC);
    printf("overflow: %s\n", e.text);
    CHECK(strstr(e.text, "t = ") != NULL);
    CHECK(strstr(e.text, "position") != NULL || strstr(e.text, "r = [") != NULL);
    for (size_t i = 0; i < r.n_samples; i++) CHECK(mech_vec3_isfinite(pos[i]));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_presets();
    test_presets_issue_set();
    test_presets_oscillator_falling();
    test_reference_report();
    test_error_estimate();
    test_boris_split();
    test_extremes();
    test_nonfinite();
    TEST_MAIN_END();
}
