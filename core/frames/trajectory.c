/* trajectory.c — the trajectory driver: a scene (mech/frames/trajectory.h) integrated
 * with mech_ode_solve through its equations of motion
 * (trajectory_equations.c, their fast path trajectory_fast.c), observed at
 * every sample and step end (trajectory_observe.c); the result's terms,
 * conserved quantities and samples; the samples compared with the scene's
 * reference solution (reference.c) or, on request, with a second run at a
 * tighter setting (the error estimate). The context the pieces share is
 * trajectory_context.h; the rest of the trajectory lives beside it: frame.c
 * (the frame's angular velocity), trajectory_problem.c (validation, planar
 * scenes, the angular-momentum centre), trajectory_choose.c (accuracy
 * presets, the chooser's profile), term_estimate.c and trajectory_model.c
 * (the auto-model).
 */
#include "trajectory_context.h"
#include "mech/frames/reference.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for error messages */
#include <stdlib.h>
#include <string.h>

static const char *force_name(enum mech_force_type t)
{
    switch (t) {
    case MECH_FORCE_UNIFORM_GRAVITY: return "uniform_gravity";
    case MECH_FORCE_CENTRAL_GRAVITY: return "central_gravity";
    case MECH_FORCE_SPRING: return "spring";
    case MECH_FORCE_LINEAR_DRAG: return "linear_drag";
    case MECH_FORCE_LORENTZ: return "lorentz";
    case MECH_FORCE_THIRD_BODY_TIDE: return "third_body_tide";
    }
    return "unknown";
}

/* Buffers of one run: samples (t, y) and the stop state. */
struct traj_run {
    double *sample_t, *sample_y; /* samples, samples * 6: (r, v) */
    double y_stop[6];
    struct mech_vec3 *sample_u;  /* special runs: the proper velocities, else NULL */
    struct mech_vec3 u_stop;
    struct mech_ode_result out;
};

/* One integration of the scene with (method, opt), observed through c. */
static enum mech_status run_scene(const struct mech_trajectory_problem *p,
                                  const struct mech_integrator *method,
                                  struct mech_ode_options opt, const struct mech_budget *budget,
                                  struct traj_ctx *c, struct traj_run *run,
                                  struct mech_error *err)
{
    const int dissipative = mech_traj_scene_has_drag(p);
    const int velocity_free = !mech_traj_scene_velocity_dependent(c);
    /* one body: its 3 (planar: 2) coordinates are one particle */
    struct mech_ode_system sys = {6, mech_traj_rhs, mech_traj_accel,
                                  velocity_free ? MECH_ODE_VELOCITY_FREE : 0u, c,
                                  dissipative || c->pn1 ? NULL : mech_traj_lorentz, 3, NULL};
    double y0[6] = {p->position.x, p->position.y, p->position.z,
                    p->velocity.x, p->velocity.y, p->velocity.z};
    if (c->special) {
        /* first order in (r, u): no second-order form, no Lorentz split */
        const struct mech_vec3 u0v = mech_trajectory_proper_velocity0(p);
        sys = (struct mech_ode_system){6, mech_traj_rel_rhs, NULL, 0u, c, NULL, 3, NULL};
        y0[3] = u0v.x;
        y0[4] = u0v.y;
        y0[5] = u0v.z;
        if (!run->sample_u) {
            run->sample_u = malloc(p->samples * sizeof *run->sample_u);
            if (!run->sample_u) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
        }
    }
    double u0[4], u_stop[4] = {0, 0, 0, 0};
    double *u_samples = NULL;
    if (c->dim2) {
        /* planar: 4 components, r = u1 e1 + u2 e2 */
        sys = (struct mech_ode_system){4, mech_traj_plane_rhs, mech_traj_plane_accel,
                                       velocity_free ? MECH_ODE_VELOCITY_FREE : 0u, c, NULL, 2,
                                       NULL};
        u0[0] = mech_vec3_dot(p->position, c->e1);
        u0[1] = mech_vec3_dot(p->position, c->e2);
        u0[2] = mech_vec3_dot(p->velocity, c->e1);
        u0[3] = mech_vec3_dot(p->velocity, c->e2);
        u_samples = malloc(p->samples * 4 * sizeof *u_samples);
        if (!u_samples) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    }
    mech_traj_fast_install(c, &sys); /* the force loop's fast path, called directly */
    struct mech_ode_kepler_split ks;
    if (c->kepler_index >= 0) { /* one central body: offer the Kepler split */
        mech_traj_kepler_split_fill(c, &ks);
        sys.kepler = &ks;
        c->kepler_exact = mech_ode_method_describe(method).kepler_split;
    }
    struct mech_ode_problem op = {
        .sys = &sys,
        .method = method,
        .opt = opt,
        .t0 = 0.0,
        .t_end = p->t_end,
        .y0 = c->dim2 ? u0 : y0,
        .n_samples = p->samples,
        .sample_t = run->sample_t,
        .sample_y = c->dim2 ? u_samples : run->sample_y,
        .event = p->has_stop ? (c->dim2 ? mech_traj_plane_event : mech_traj_event) : NULL,
        .event_direction = (int)p->stop_direction,
        .event_params = c,
        .observe = c->dim2 ? mech_traj_plane_observe : mech_traj_observe,
        .observe_params = c,
        .y_stop = c->dim2 ? u_stop : run->y_stop,
    };
    memset(&run->out, 0, sizeof run->out);
    enum mech_status st = mech_ode_solve(&op, budget, &run->out, err);
    if (c->dim2) {
        for (size_t i = 0; i < run->out.n_samples; i++)
            plane_expand(c, u_samples + 4 * i, run->sample_y + 6 * i);
        if (run->out.stopped) plane_expand(c, u_stop, run->y_stop);
        free(u_samples);
    }
    if (c->special) {
        /* (r, u) -> (r, v), the proper velocities kept beside */
        for (size_t i = 0; i <= run->out.n_samples; i++) {
            double *y = i < run->out.n_samples ? run->sample_y + 6 * i : run->y_stop;
            if (i == run->out.n_samples && !run->out.stopped) break;
            const struct mech_vec3 u = mech_vec3_make(y[3], y[4], y[5]);
            const double g = gamma_of_u(u);
            if (i < run->out.n_samples) run->sample_u[i] = u;
            else run->u_stop = u;
            y[3] = u.x / g;
            y[4] = u.y / g;
            y[5] = u.z / g;
        }
    }
    if (st == MECH_ENUMERIC && err && err->code == MECH_ENUMERIC && !strstr(err->text, "position") &&
        !strstr(err->text, "distance")) {
        /* The driver's own message (a non-finite state after a step) does not
         * say where: add the last finite state observed. */
        size_t n = strlen(err->text);
        snprintf(err->text + n, sizeof err->text - n,
                 "; last state t = %.9g s, r = [%.6g, %.6g, %.6g] m", c->t_last,
                 c->r_last.x, c->r_last.y, c->r_last.z);
    }
    return st;
}

static void run_free(struct traj_run *run)
{
    free(run->sample_t);
    free(run->sample_y);
    free(run->sample_u);
    run->sample_t = run->sample_y = NULL;
    run->sample_u = NULL;
}

static enum mech_status run_alloc(struct traj_run *run, size_t n, struct mech_error *err)
{
    memset(run, 0, sizeof *run);
    run->sample_t = malloc(n * sizeof *run->sample_t);
    run->sample_y = malloc(n * 6 * sizeof *run->sample_y);
    if (!run->sample_t || !run->sample_y) {
        run_free(run);
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    }
    return MECH_OK;
}

static struct mech_vec3 yvec(const double *y, int off)
{
    return mech_vec3_make(y[off], y[off + 1], y[off + 2]);
}

/* Errors of run against the reference at every sample and the stop point,
 * relative to the scene's scales: positions to the largest distance from the
 * reference's centre (Kepler's body, the spring's anchor; the origin for the
 * uniform fields) over the samples, the orbit's or oscillation's size;
 * velocities to the largest speed over the samples and over every step of
 * the run (speed_max), never to a value that passes through zero (a 1-D
 * oscillator sampled once a period is at rest at every sample). */
static enum mech_status reference_report(const struct mech_trajectory_problem *p,
                                         const struct traj_run *run, double speed_max,
                                         struct mech_trajectory_reference_report *rep,
                                         struct mech_error *err)
{
    struct mech_trajectory_reference ref;
    memset(rep, 0, sizeof *rep);
    rep->name = "";
    if (mech_trajectory_reference_find(p, &ref) == MECH_REFERENCE_NONE) return MECH_OK;
    double rmax = 0.0, vmax = isfinite(speed_max) ? speed_max : 0.0;
    const int centred = !strncmp(ref.name, "kepler", 6) || !strncmp(ref.name, "harmonic", 8);
    const size_t n = run->out.n_samples;
    for (size_t i = 0; i <= n; i++) {
        const double *y;
        double t;
        if (i < n) {
            y = run->sample_y + 6 * i;
            t = run->sample_t[i];
        } else if (run->out.stopped) {
            y = run->y_stop;
            t = run->out.t_stop;
        } else {
            break;
        }
        struct mech_vec3 rr, vr;
        double so;
        enum mech_status st = mech_trajectory_reference_eval(&ref, t, &rr, &vr, &so, err);
        if (st != MECH_OK) return st;
        double de = mech_vec3_norm(mech_vec3_sub(yvec(y, 0), rr));
        double dv = mech_vec3_norm(mech_vec3_sub(yvec(y, 3), vr));
        rep->max_position_error = fmax(rep->max_position_error, de);
        rep->max_velocity_error = fmax(rep->max_velocity_error, dv);
        rep->final_position_error = de;
        rep->truncation_estimate = fmax(rep->truncation_estimate, so);
        rmax = fmax(rmax, mech_vec3_norm(centred ? mech_vec3_sub(rr, ref.center) : rr));
        vmax = fmax(vmax, mech_vec3_norm(vr));
    }
    rep->kind = (int)ref.kind;
    rep->name = ref.name;
    rep->max_relative_position_error = rmax > 0.0 ? rep->max_position_error / rmax : 0.0;
    rep->max_relative_velocity_error = vmax > 0.0 ? rep->max_velocity_error / vmax : 0.0;
    return MECH_OK;
}

enum mech_status mech_trajectory_integrate(const struct mech_trajectory_problem *p,
                                           const struct mech_budget *budget,
                                           struct mech_trajectory_result *res,
                                           struct mech_error *err)
{
    if (!p || !res) return mech_error_set(err, MECH_EINVAL, NULL, "NULL problem or result");
    res->n_samples = 0;
    res->stopped = 0;
    res->t_stop = NAN;
    enum mech_status st = mech_trajectory_check(p, err);
    if (st != MECH_OK) return st;
    const struct mech_integrator *method = mech_ode_method_find(p->method);
    if (!method)
        return mech_error_set(err, MECH_EINVAL, "integrator/method", "unknown method \"%s\"",
                              p->method ? p->method : "(null)");
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "no compute budget given");
    const struct mech_ode_method_info mi = mech_ode_method_describe(method);
    if ((p->relativity & MECH_RELATIVITY_SPECIAL) && mi.second_order)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "%s integrates q'' = a(q, v); special-relativistic dynamics are "
                              "first order in (r, u = gamma v): use rk8pd, rkf45, rkck, gauss6 "
                              "or choose by accuracy",
                              mi.name);
    const char *no_split = NULL;
    if (mi.kepler_split && mech_traj_kepler_split_index(p, &no_split) < 0)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "%s needs exactly one central_gravity force in an inertial "
                              "frame, the other forces being small perturbations; %s",
                              mi.name, no_split);

    struct traj_ctx c;
    mech_traj_ctx_init(&c, p, mi.adaptive ? 0.0 : p->opt.dt, err);
    mech_traj_ctx_plane(&c, &mi);
    const int dissipative = mech_traj_scene_has_drag(p);

    struct traj_run run;
    if ((st = run_alloc(&run, p->samples, err)) != MECH_OK) return st;
    st = run_scene(p, method, p->opt, budget, &c, &run, err);
    /* Samples written so far are returned on every path. */
    const size_t ns = run.out.n_samples;
    res->n_samples = ns;
    for (size_t i = 0; i < ns; i++) {
        const double *y = run.sample_y + 6 * i;
        if (res->t) res->t[i] = run.sample_t[i];
        if (res->position) res->position[i] = yvec(y, 0);
        if (res->velocity) res->velocity[i] = yvec(y, 3);
        if (res->proper_velocity && run.sample_u) res->proper_velocity[i] = run.sample_u[i];
    }
    if (st != MECH_OK) {
        run_free(&run);
        return st;
    }

    res->stopped = run.out.stopped;
    if (run.out.stopped) {
        res->t_stop = run.out.t_stop;
        res->stop_position = yvec(run.y_stop, 0);
        res->stop_velocity = yvec(run.y_stop, 3);
        res->stop_proper_velocity = c.special ? run.u_stop : mech_vec3_make(0, 0, 0);
    }
    res->n_terms = p->n_forces + MECH_TRAJECTORY_N_FICTITIOUS;
    res->dimensions = c.dim2 ? 2 : 3;
    res->max_radius = c.rmax;
    res->max_speed = c.vmax;
    res->plane_normal = c.dim2 ? mech_vec3_cross(c.e1, c.e2) : mech_vec3_make(0, 0, 0);
    for (size_t i = 0; i < p->n_forces; i++) {
        res->terms[i].term = force_name(p->forces[i].type);
        res->terms[i].force_index = (int)i;
        res->terms[i].included = 1;
        res->terms[i].max_acceleration = c.term_max[i];
    }
    res->terms[p->n_forces] = (struct mech_trajectory_term){"coriolis", -1, c.coriolis,
                                                            c.term_max[p->n_forces]};
    res->terms[p->n_forces + 1] = (struct mech_trajectory_term){"centrifugal", -1, c.centrifugal,
                                                                c.term_max[p->n_forces + 1]};
    res->terms[p->n_forces + 2] = (struct mech_trajectory_term){"euler", -1, c.euler,
                                                                c.term_max[p->n_forces + 2]};
    res->terms[p->n_forces + 3] = (struct mech_trajectory_term){
        "translational", -1, c.translational, c.term_max[p->n_forces + 3]};
    res->relativity_terms[0] =
        (struct mech_trajectory_term){"relativistic", -1, c.special, c.rel_max};
    res->relativity_terms[1] =
        (struct mech_trajectory_term){"schwarzschild_1pn", -1, c.pn1, c.pn1_max};
    res->relativity_ratio[0] = c.rel_ratio;
    res->relativity_ratio[1] = c.pn1_ratio;
    res->relativistic = c.special;
    res->method = mi.name;
    res->stats = run.out.stats;
    res->total_steps = run.out.stats.steps;

    struct mech_trajectory_invariant *inv = &res->invariants[0];
    memset(res->invariants, 0, sizeof res->invariants);
    inv->name = c.noninertial ? "jacobi_integral" : "energy";
    const int time_dependent = mech_traj_scene_time_dependent(&c);
    inv->conserved = !dissipative && !time_dependent;
    inv->note = time_dependent
                    ? "not conserved: the frame's angular velocity changes with time (omega_dot), "
                      "so the equations depend on t and no energy-like integral exists"
                : dissipative ? "not conserved: linear drag dissipates it"
                : c.noninertial
                    ? "conserved: 1/2 m v^2 + U - 1/2 m |w x r|^2 (if centrifugal modelled) + m A.r "
                      "(if translational modelled); Coriolis and q v x B do no work"
                : c.special
                    ? "conserved: (gamma - 1) m c^2 + U, gamma - 1 = (u/c)^2/(gamma + 1) (q v x B "
                      "does no work; U includes -q E.r)"
                : c.pn1
                    ? "conserved: the 1PN energy 1/2 m v^2 + U + m (3 v^4/8 + 3 gm v^2/(2 d) + "
                      "gm^2/(2 d^2))/c^2 (harmonic coordinates)"
                    : "conserved: 1/2 m v^2 + U (q v x B does no work; U includes -q E.r)";
    inv->initial = c.inv0;
    inv->final = c.inv_last;
    double denom = c.inv0 != 0.0 ? fabs(c.inv0) : c.scale_max;
    inv->max_relative_drift = denom > 0.0 ? c.drift_max / denom : 0.0;
    res->n_invariants = 1;
    if (c.track_l) {
        struct mech_trajectory_invariant *l = &res->invariants[1];
        l->name = "angular_momentum";
        l->conserved = 1;
        l->note = c.special ? "conserved: r x p with p = gamma m v; every force is central about "
                              "one point"
                  : c.pn1 ? "conserved: the 1PN angular momentum m (r x v) (1 + v^2/(2 c^2) + "
                            "3 gm/(c^2 d)); every force is central about one point"
                          : "conserved: every force is central about one point";
        l->is_vector = 1;
        l->initial_vector = c.l0;
        l->final_vector = c.l_last;
        l->initial = mech_vec3_norm(c.l0);
        l->final = mech_vec3_norm(c.l_last);
        double ld = l->initial > 0.0 ? l->initial : c.lscale_max;
        l->max_relative_drift = ld > 0.0 ? c.ldrift_max / ld : 0.0;
        res->n_invariants = 2;
    }
    res->invariant = res->invariants[0];

    st = reference_report(p, &run, res->max_speed, &res->reference, err);
    memset(&res->error_estimate, 0, sizeof res->error_estimate);
    if (st == MECH_OK && p->error_estimate && res->reference.kind == MECH_REFERENCE_NONE) {
        /* Second run at a tighter setting with what is left of the budget. */
        struct mech_trajectory_error_estimate *ee = &res->error_estimate;
        struct mech_ode_options o2 = p->opt;
        const struct mech_integrator *method2 = method;
        if (mi.adaptive && !strcmp(mi.name, "radau15") && p->opt.rtol / 100.0 < 1e-10) {
            /* radau15 floors its eps at 1e-10 (round-off): a tighter radau15
             * run would repeat this one bit for bit. */
            method2 = mech_ode_method_find("rk8pd");
            o2.rtol = 1e-14;
            o2.atol = 0.0;
            ee->rule = "radau15 is at its round-off floor: compared with rk8pd at rtol 1e-14";
        } else if (mi.adaptive && p->opt.rtol / 100.0 < 1e-13) {
            /* GSL's methods gain nothing below rtol ~1e-13: compare with radau15 */
            method2 = mech_ode_method_find("radau15");
            o2.rtol = 1e-10;
            o2.atol = 0.0;
            ee->rule = "rtol/100 is below what the method resolves: compared with radau15 at "
                       "its round-off setting (rtol 1e-10)";
        } else if (mi.adaptive) {
            o2.rtol = p->opt.rtol / 100.0;
            o2.atol = p->opt.atol / 100.0;
            ee->rule = "same method, rtol/100 and atol/100";
        } else {
            o2.dt = p->opt.dt / 2.0;
            ee->rule = "same method, dt/2; the estimate is the difference times 2^p/(2^p - 1)";
        }
        struct mech_budget b2 = *budget;
        b2.max_steps = budget->max_steps - run.out.stats.steps;
        struct traj_run run2;
        struct traj_ctx c2;
        mech_traj_ctx_init(&c2, p, mi.adaptive ? 0.0 : o2.dt, err);
        {
            const struct mech_ode_method_info mi2 =
                method2 ? mech_ode_method_describe(method2) : mi;
            mech_traj_ctx_plane(&c2, &mi2);
        }
        if (b2.max_steps <= 0) {
            st = mech_error_set(err, MECH_EBUDGET, NULL,
                                "no steps left in the budget for the error estimate's second run");
        } else if ((st = run_alloc(&run2, p->samples, err)) == MECH_OK) {
            st = method2 ? run_scene(p, method2, o2, &b2, &c2, &run2, err)
                         : mech_error_set(err, MECH_EINTERNAL, NULL, "estimate method missing");
            if (st == MECH_OK) {
                size_t n = run.out.n_samples < run2.out.n_samples ? run.out.n_samples
                                                                  : run2.out.n_samples;
                for (size_t i = 0; i < n; i++) {
                    const double *a = run.sample_y + 6 * i, *b = run2.sample_y + 6 * i;
                    double dr = mech_vec3_norm(mech_vec3_sub(yvec(a, 0), yvec(b, 0)));
                    double dv = mech_vec3_norm(mech_vec3_sub(yvec(a, 3), yvec(b, 3)));
                    ee->max_position_difference = fmax(ee->max_position_difference, dr);
                    ee->max_velocity_difference = fmax(ee->max_velocity_difference, dv);
                    ee->final_position_difference = dr;
                }
                if (run.out.stopped && run2.out.stopped) {
                    double dr = mech_vec3_norm(
                        mech_vec3_sub(yvec(run.y_stop, 0), yvec(run2.y_stop, 0)));
                    ee->max_position_difference = fmax(ee->max_position_difference, dr);
                    ee->final_position_difference = dr;
                }
                double f = 1.0;
                if (!mi.adaptive) {
                    double q = ldexp(1.0, mi.order);
                    f = q / (q - 1.0);
                }
                ee->max_position_error_estimate = f * ee->max_position_difference;
                ee->done = 1;
                ee->method = mech_ode_method_describe(method2).name;
                ee->opt = o2;
                ee->stats = run2.out.stats;
                res->total_steps += run2.out.stats.steps;
            }
            run_free(&run2);
        }
    }
    run_free(&run);
    return st;
}
