/* relativity_model.c — which relativistic corrections a trajectory needs at
 * the accuracy asked for ("relativity": "auto", mech/frames/trajectory.h,
 * mech_trajectory_relativity_select): each correction's acceleration,
 * measured along a run of the scene, goes through the auto-model's rule
 * (term_estimate.c); a correction that is needed and cannot be modelled is
 * an error naming it, never a silently Newtonian answer. */
#include "mech/frames/trajectory.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for the reason text */
#include <string.h>

/* The 1PN term's size relative to Newtonian gravity at the pericentre of
 * the two-body orbit through p's initial state about force f (n.v = 0
 * there): |4 gm / q - v_q^2| / c^2, q = h^2 / (gm (1 + e)), v_q = h / q;
 * 0 for a radial start (h = 0: that orbit meets the centre, refused there). */
static double pericentre_1pn(const struct mech_trajectory_problem *p, const struct mech_force *f)
{
    const double gm = f->u.central_gravity.gm;
    const struct mech_vec3 r = mech_vec3_sub(p->position, f->u.central_gravity.center);
    const double rn = mech_vec3_norm(r);
    const double h = mech_vec3_norm(mech_vec3_cross(r, p->velocity));
    if (!(h > 0.0) || !(rn > 0.0)) return 0.0;
    const double energy = 0.5 * mech_vec3_dot(p->velocity, p->velocity) - gm / rn;
    const double e2 = 1.0 + 2.0 * energy * h * h / (gm * gm);
    const double e = e2 > 0.0 ? sqrt(e2) : 0.0;
    const double q = h * h / (gm * (1.0 + e)), vq = h / q;
    return fabs(4.0 * gm / q - vq * vq) / (MECH_C * MECH_C);
}

/* The estimate of one correction: its relative size eps (against the
 * acceleration it corrects) over the run, whose phase V T / L (L, V the
 * largest |r| and |v|, T the duration: radians of an orbit or a gyration,
 * ~2 for a fall from rest) it shifts by ~eps per radian, so the positions
 * and velocities move by ~eps (1 + V T / L) relative. (The quadratic bound
 * |a| T^2/2 of the fictitious terms would call a 1e-12 precession over
 * 1e4 orbits a 4e-7 effect.) */
static void correction_estimate(const char *term, double accel, double eps,
                                const struct mech_relativity_model *m,
                                struct mech_term_estimate *te)
{
    memset(te, 0, sizeof *te);
    te->term = term;
    te->applicable = 1;
    const double L = m->position_scale, V = m->velocity_scale, T = m->time_scale;
    const double phase = L > 0.0 ? V * T / L : 0.0;
    te->accel_bound = accel;
    te->relative_effect = eps * (1.0 + phase);
    te->position_effect = te->relative_effect * L;
    te->velocity_effect = te->relative_effect * V;
    te->included = te->relative_effect > m->target / m->safety;
    snprintf(te->reason, sizeof te->reason,
             "estimated effect %.3g relative %s target %.3g / safety %g: up to %.3g of the "
             "acceleration it corrects (|a| <= %.3g m/s^2) over a phase V T / L = %.4g "
             "(eps (1 + V T / L))",
             te->relative_effect, te->included ? ">" : "<=", m->target, m->safety, eps, accel,
             phase);
}

/* A Kepler closed form is sampled, not stepped: its samples may all sit
 * near the pericentre (3 samples of whole orbits) and miss the orbit's size.
 * For a bound orbit take at least |centre| + the apocentre distance as L and
 * the pericentre speed as V (both exact for the two-body orbit). */
static void kepler_scales(const struct mech_trajectory_problem *p,
                          const struct mech_trajectory_result *run, struct mech_relativity_model *m)
{
    if (!run->method || strcmp(run->method, "closed_form") || !run->reference.name ||
        strcmp(run->reference.name, "kepler"))
        return;
    const struct mech_force *f = NULL;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) f = &p->forces[i];
    if (!f) return;
    const double gm = f->u.central_gravity.gm;
    const struct mech_vec3 r = mech_vec3_sub(p->position, f->u.central_gravity.center);
    const double rn = mech_vec3_norm(r), v2 = mech_vec3_dot(p->velocity, p->velocity);
    const double h = mech_vec3_norm(mech_vec3_cross(r, p->velocity));
    const double energy = 0.5 * v2 - gm / rn;
    if (!(energy < 0.0) || !(h > 0.0)) return;
    const double e2 = 1.0 + 2.0 * energy * h * h / (gm * gm);
    const double e = e2 > 0.0 ? sqrt(e2) : 0.0;
    const double a = -gm / (2.0 * energy);
    const double q = h * h / (gm * (1.0 + e));
    m->position_scale =
        fmax(m->position_scale, mech_vec3_norm(f->u.central_gravity.center) + a * (1.0 + e));
    m->velocity_scale = fmax(m->velocity_scale, h / q);
}

/* Prefix the estimate's reason with `lead` (the estimate's numbers kept). */
static void reason_lead(struct mech_term_estimate *te, const char *lead)
{
    char tmp[sizeof te->reason];
    memcpy(tmp, te->reason, sizeof tmp);
    const size_t n = strlen(lead) < sizeof tmp - 1 ? strlen(lead) : sizeof tmp - 1;
    memcpy(te->reason, lead, n);
    const size_t rest = sizeof tmp - 1 - n, tl = strnlen(tmp, sizeof tmp - 1);
    memcpy(te->reason + n, tmp, tl < rest ? tl : rest);
    te->reason[n + (tl < rest ? tl : rest)] = '\0';
}

enum mech_status mech_trajectory_relativity_select(const struct mech_trajectory_problem *p,
                                                   const struct mech_trajectory_result *run,
                                                   double target, unsigned forced_on,
                                                   unsigned forced_off,
                                                   struct mech_relativity_model *m,
                                                   struct mech_error *err)
{
    if (!p || !run || !m) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(m, 0, sizeof *m);
    if (!(target >= 1e-15 && target <= 0.1))
        return mech_error_set(err, MECH_EINVAL, "integrator/target_error",
                              "target_error must be in [1e-15, 0.1], got %.17g", target);
    m->judged = 1;
    m->target = target;
    m->safety = MECH_TRAJECTORY_AUTO_SAFETY;
    m->forced_on = forced_on;
    m->forced_off = forced_off;
    m->time_scale = run->stopped ? run->t_stop : p->t_end;
    if (!(m->time_scale > 0.0)) m->time_scale = p->t_end;
    m->position_scale = run->max_radius;
    m->velocity_scale = run->max_speed;
    kepler_scales(p, run, m);
    const int inertial = p->frame.type == MECH_FRAME_INERTIAL;
    size_t n_central = 0, n_other = 0;
    const struct mech_force *central = NULL;
    for (size_t i = 0; i < p->n_forces; i++) {
        if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) {
            n_central++;
            central = &p->forces[i];
        } else {
            n_other++;
        }
    }

    /* the two accelerations and their sizes relative to what they correct */
    double a[MECH_TRAJECTORY_N_RELATIVITY], eps[MECH_TRAJECTORY_N_RELATIVITY];
    a[0] = run->relativity_terms[0].max_acceleration;
    eps[0] = run->relativity_ratio[0];
    if (inertial && n_central == 1) {
        a[1] = run->relativity_terms[1].max_acceleration;
        eps[1] = run->relativity_ratio[1];
        if (run->method && !strcmp(run->method, "closed_form"))
            eps[1] = fmax(eps[1], pericentre_1pn(p, central));
    } else {
        /* a bound from each mass's largest pull gm/d^2 and the top speed:
         * |a_1PN| / (gm/d^2) <= 4 gm/(c^2 d) + 5 beta^2 */
        const double beta = fmin(1.0, m->velocity_scale / MECH_C);
        a[1] = eps[1] = 0.0;
        for (size_t i = 0; i < p->n_forces && i < run->n_terms; i++) {
            if (p->forces[i].type != MECH_FORCE_CENTRAL_GRAVITY) continue;
            const double ai = run->terms[i].max_acceleration, gm = p->forces[i].u.central_gravity.gm;
            if (!(ai > 0.0)) continue;
            const double d = sqrt(gm / ai);
            const double e = 4.0 * gm / (MECH_C * MECH_C * d) + 5.0 * beta * beta;
            a[1] += ai * e;
            eps[1] = fmax(eps[1], e);
        }
    }
    static const char *const names[MECH_TRAJECTORY_N_RELATIVITY] = {"relativistic",
                                                                    "schwarzschild_1pn"};
    static const unsigned bits[MECH_TRAJECTORY_N_RELATIVITY] = {
        MECH_RELATIVITY_SPECIAL, MECH_RELATIVITY_SCHWARZSCHILD_1PN};
    const int applicable[MECH_TRAJECTORY_N_RELATIVITY] = {!(n_central > 0 && n_other == 0),
                                                          n_central > 0};
    const char *const not_applicable[MECH_TRAJECTORY_N_RELATIVITY] = {
        "not applicable: every force is gravity about a mass, whose relativistic correction is "
        "schwarzschild_1pn (it holds the special-relativistic kinematics to order v^2/c^2); ",
        "not applicable: no central mass; "};
    const char *const why_not_modellable[MECH_TRAJECTORY_N_RELATIVITY] = {
        !inertial ? "inertial frames only" : NULL,
        !inertial ? "inertial frames only" : n_central > 1 ? "one central mass only" : NULL};
    for (int k = 0; k < MECH_TRAJECTORY_N_RELATIVITY; k++) {
        struct mech_term_estimate *te = &m->terms[k];
        correction_estimate(names[k], a[k], eps[k], m, te);
        te->applicable = applicable[k];
        if (forced_on & bits[k]) {
            te->included = 1;
            reason_lead(te, "included as requested; ");
        } else if (forced_off & bits[k]) {
            te->included = 0;
            reason_lead(te, "left out as requested; ");
        } else if (!applicable[k]) {
            te->included = 0;
            snprintf(te->reason, sizeof te->reason,
                     "%sits size: up to %.3g of the acceleration it would correct, estimated "
                     "effect %.3g relative",
                     not_applicable[k], eps[k], te->relative_effect);
        }
        if (te->included) {
            if (why_not_modellable[k])
                return mech_error_set(err, MECH_EDOMAIN, "relativity",
                                      "%s is needed (estimated effect %.2g > %.2g / %g) and "
                                      "cannot be modelled here (%s); \"relativity\": [] asks for "
                                      "the Newtonian model",
                                      names[k], te->relative_effect, target, m->safety,
                                      why_not_modellable[k]);
            m->relativity |= bits[k];
        }
    }
    if ((m->relativity & MECH_RELATIVITY_SPECIAL) &&
        (m->relativity & MECH_RELATIVITY_SCHWARZSCHILD_1PN))
        return mech_error_set(err, MECH_EDOMAIN, "relativity",
                              "both relativistic (%.3g) and schwarzschild_1pn (%.3g) are needed "
                              "and cannot be modelled together (a charge or force near a mass "
                              "at relativistic speed)",
                              m->terms[0].relative_effect, m->terms[1].relative_effect);
    return MECH_OK;
}
