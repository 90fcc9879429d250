/* trajectory_choose.c — choosing by accuracy for a trajectory
 * (mech/frames/trajectory.h): the accuracy presets and the scene's profile handed
 * to the predictive chooser (mech/ode/chooser.h), which picks the method and its
 * setting ({"accuracy": ...} / {"target_error": ...}). */
#include "mech/frames/trajectory.h"
#include "mech/ode/chooser.h"
#include "mech/frames/chooser_orbit.h"
#include "mech/frames/closed_form.h"
#include "mech/frames/reference.h"
#include "trajectory_scene.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for the reason text */
#include <string.h>

/* The pericentre dynamical time sqrt(q^3 / GM) of the two-body orbit through
 * the initial state about each central body (q = h^2 / (GM (1 + e)), any
 * eccentricity), the shortest over the bodies; +inf when there is none or
 * the state is degenerate (at the centre, or radial: q = 0 is left to
 * sqrt(|r0| / |a0|)). */
static double kepler_pericentre_time(const struct mech_trajectory_problem *p)
{
    double T = INFINITY;
    for (size_t i = 0; i < p->n_forces; i++) {
        if (p->forces[i].type != MECH_FORCE_CENTRAL_GRAVITY) continue;
        const double gm = p->forces[i].u.central_gravity.gm;
        const struct mech_vec3 r = mech_vec3_sub(p->position, p->forces[i].u.central_gravity.center);
        const double rn = mech_vec3_norm(r);
        if (!(gm > 0.0) || !(rn > 0.0)) continue;
        const double h = mech_vec3_norm(mech_vec3_cross(r, p->velocity));
        const double v2 = mech_vec3_dot(p->velocity, p->velocity);
        const double energy = 0.5 * v2 - gm / rn;
        const double e2 = 1.0 + 2.0 * energy * h * h / (gm * gm);
        const double q = h * h / (gm * (1.0 + sqrt(fmax(e2, 0.0))));
        if (q > 0.0 && isfinite(q)) T = fmin(T, sqrt(q * q * q / gm));
    }
    return T;
}

/* The chooser's profile of a trajectory scene: its class, its dynamical time
 * T = min(t_end, sqrt(|r0| / |a0|), the pericentre time of a central body's
 * orbit, the gyration time m / |q B|), span = t_end / T, and the scale S of positions and velocities
 * (atol = rtol x S). */
static void traj_profile(const struct mech_trajectory_problem *p,
                         struct mech_scene_profile *s, double *L_out, double *V_out)
{
    memset(s, 0, sizeof *s);
    double a0[3] = {0, 0, 0};
    struct mech_vec3 acc = mech_vec3_make(0, 0, 0);
    if (mech_trajectory_start_acceleration(p, a0) == MECH_OK)
        acc = mech_vec3_make(a0[0], a0[1], a0[2]);
    const double an = mech_vec3_norm(acc), vn = mech_vec3_norm(p->velocity);
    const double rn = mech_vec3_norm(p->position);
    double T = p->t_end;
    if (an > 0.0 && rn > 0.0) T = fmin(T, sqrt(rn / an));
    /* a central body: the orbit's pericentre time sqrt(q^3 / GM), wherever
     * the run starts (from apocentre, sqrt(r0 / a0) would call an e = 0.9
     * orbit 80x shorter in dynamical times than the same orbit from
     * pericentre, and under-predict its round-off floor ~700x) */
    T = fmin(T, kepler_pericentre_time(p));
    /* a magnetic field: the gyration time m / |q B| (radians, as sqrt(r0 / a0)
     * counts them on the calibration's charge in B), wherever the run starts
     * (from the origin |r0| = 0 said nothing: an E x B drift over 9.5
     * gyrations was one dynamical time and missed precise 150x) */
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LORENTZ && p->mass > 0.0) {
            const double w = fabs(p->charge) * mech_vec3_norm(p->forces[i].u.lorentz.B) / p->mass;
            if (w > 0.0 && isfinite(w)) T = fmin(T, 1.0 / w);
        }
    if (!(T > 0.0 && isfinite(T))) T = p->t_end > 0.0 ? p->t_end : 1.0;
    double L = fmax(rn, fmax(vn * T, 0.5 * an * T * T));
    double V = fmax(vn, an * T);
    double S = L > 0.0 && V > 0.0 ? fmin(L, V) : fmax(L, V);
    if (!(S > 0.0 && isfinite(S))) S = 1.0;
    *L_out = L;
    *V_out = V;
    int central = 0, spring = 0;
    double drag_rate = 0.0;
    for (size_t i = 0; i < p->n_forces; i++) {
        if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) central = 1;
        if (p->forces[i].type == MECH_FORCE_SPRING && p->forces[i].u.spring.k > 0.0) spring = 1;
        if (p->forces[i].type == MECH_FORCE_LINEAR_DRAG && p->mass > 0.0)
            drag_rate += p->forces[i].u.linear_drag.b / p->mass;
    }
    /* uniform_field only for uniform gravity (and a frame whose rotation
     * bends the fall little over the run): motion close to a polynomial;
     * drag, magnetic fields, tides and rotating frames are "general" */
    int only_uniform = 1;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type != MECH_FORCE_UNIFORM_GRAVITY) only_uniform = 0;
    const double w_run = mech_vec3_norm(mech_frame_omega(&p->frame)) * p->t_end;
    if (p->frame.type != MECH_FRAME_INERTIAL && !(w_run < 1e-2)) only_uniform = 0;
    /* a frame that turns appreciably over the run, its rotation terms
     * modelled: general whatever the forces (Coriolis makes radau15 iterate
     * its stages on the velocity: ~166 evaluations per dynamical time on the
     * rotating oscillator against the inertial oscillator's ~33, so the
     * inertial classes' rows mispredict it 3-4x) */
    const int turning = p->frame.type != MECH_FRAME_INERTIAL && !(w_run < 1e-2) &&
                        (p->fictitious & (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL));
    s->cls = turning        ? MECH_SCENE_GENERAL
           : central        ? MECH_SCENE_CENTRAL_GRAVITY
           : spring         ? MECH_SCENE_OSCILLATOR
           : only_uniform   ? MECH_SCENE_UNIFORM_FIELD
                            : MECH_SCENE_GENERAL;
    s->T = T;
    s->span = p->t_end / T;
    s->scale = S;
    s->samples = p->samples;
    s->second_order = 1;
    s->velocity_dependent = mech_trajectory_velocity_dependent(p);
    /* stiff: a damping time far shorter than the dynamical time and the run */
    s->stiff = drag_rate * fmin(T, p->t_end) > 1e2;
    struct mech_trajectory_reference ref;
    s->closed_form = mech_trajectory_has_closed_form(p); /* a rotated reference is
                                                            evidence, not an answer */
    mech_trajectory_reference_find(p, &ref);
    s->closed_form_name = s->closed_form ? ref.name : NULL;
    s->closed_form_allowed = !p->closed_form_off;
    mech_chooser_profile_orbit(s, p); /* core/frames/chooser_orbit.c */
    if (p->relativity & MECH_RELATIVITY_SPECIAL) {
        /* integrated as (r, u = gamma v): first order, no Kepler split */
        s->second_order = 0;
        s->perturbation = -1.0;
    } else if (p->relativity) {
        s->perturbation = -1.0; /* the 1PN term is integrated whole */
    }
}

enum mech_status mech_trajectory_choose(const struct mech_trajectory_problem *p, double target,
                                        struct mech_trajectory_choice *out,
                                        struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    if (!(target >= 1e-15 && target <= 0.1))
        return mech_error_set(err, MECH_EINVAL, "integrator/target_error",
                              "target_error must be in [1e-15, 0.1], got %.17g", target);
    memset(out, 0, sizeof *out);
    double L, V;
    traj_profile(p, &out->profile, &L, &V);
    enum mech_status st = mech_choose(&out->profile, target, &out->sel, err);
    if (st != MECH_OK) return st;
    if (out->sel.chosen < 0 || out->sel.integrating < 0)
        return mech_error_set(err, MECH_EINTERNAL, NULL, "no candidate method applies");
    /* method/opt are always an integrator's (the best integrating candidate),
     * so callers that only integrate (scenes, the auto-model's first pass)
     * can; closed_form says the closed form was chosen over it */
    out->closed_form = out->sel.integrating != out->sel.chosen;
    const struct mech_candidate *ch = &out->sel.c[out->sel.integrating];
    out->method = ch->method;
    out->opt = ch->opt;
    out->target = target;
    const double span = out->profile.span;
    char beyond[320];
    mech_selection_beyond_text(&out->sel, beyond, sizeof beyond);
    if (out->closed_form) {
        snprintf(out->reason, sizeof out->reason,
                 "%s %s scene over %.3g dynamical times: the exact %s solution is the cheapest "
                 "candidate meeting %.0e relative (predicted error %.2g, %.2g s CPU for %zu "
                 "samples): answered from it, nothing integrated; the best integrator would "
                 "be %s at %s %.3g (predicted error %.2g, %.3g evaluations, %.2g s CPU)",
                 out->profile.velocity_dependent ? "velocity-dependent" : "velocity-free",
                 mech_scene_class_name(out->profile.cls), span,
                 out->profile.closed_form_name ? out->profile.closed_form_name : "closed-form",
                 target, out->sel.c[out->sel.chosen].predicted_error,
                 out->sel.c[out->sel.chosen].predicted_cpu_s, out->profile.samples, ch->method,
                 ch->adaptive ? "rtol" : "dt", ch->adaptive ? ch->opt.rtol : ch->opt.dt,
                 ch->predicted_error, ch->predicted_evaluations, ch->predicted_cpu_s);
        return MECH_OK;
    }
    snprintf(out->reason, sizeof out->reason,
             "%s %s scene over %.3g dynamical times (T = %.4g s): %s at %s %.3g is the "
             "cheapest candidate predicted to meet %.0e relative (predicted error %.2g, %.3g "
             "evaluations, %.2g s CPU)%s; atol = rtol x %.3g (the smaller of the position "
             "scale %.3g m and the velocity scale %.3g m/s)",
             out->profile.velocity_dependent ? "velocity-dependent" : "velocity-free",
             mech_scene_class_name(out->profile.cls), span, out->profile.T, ch->method,
             ch->adaptive ? "rtol" : "dt", ch->adaptive ? ch->opt.rtol : ch->opt.dt, target,
             ch->predicted_error, ch->predicted_evaluations, ch->predicted_cpu_s, beyond,
             out->profile.scale, L, V);
    return MECH_OK;
}
