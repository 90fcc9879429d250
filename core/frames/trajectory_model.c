/* trajectory_model.c — the auto-model, "fictitious": "auto"
 * (mech_trajectory_model_select, mech/frames/trajectory.h): which fictitious terms
 * a scene needs at the accuracy asked for, judged from a cheap first pass
 * with every applicable term: model only what the scene requires, and say
 * what was left out with its size (docs/design.md). */
#include "mech/frames/trajectory.h"

#include <stdio.h> /* snprintf only, for the reason text */
#include <string.h>

enum mech_status mech_trajectory_model_select(const struct mech_trajectory_problem *p,
                                              double target, const struct mech_budget *budget,
                                              struct mech_trajectory_model *m,
                                              struct mech_error *err)
{
    if (!p || !m) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(m, 0, sizeof *m);
    if (!(target >= 1e-15 && target <= 0.1))
        return mech_error_set(err, MECH_EINVAL, "integrator/target_error",
                              "target_error must be in [1e-15, 0.1], got %.17g", target);
    enum mech_status st = mech_trajectory_check(p, err);
    if (st != MECH_OK) return st;
    m->target = target;
    m->safety = MECH_TRAJECTORY_AUTO_SAFETY;
    static const char *const names[MECH_TRAJECTORY_N_FICTITIOUS] = {"coriolis", "centrifugal",
                                                                    "euler", "translational"};
    static const unsigned bits[MECH_TRAJECTORY_N_FICTITIOUS] = {
        MECH_FICTITIOUS_CORIOLIS, MECH_FICTITIOUS_CENTRIFUGAL, MECH_FICTITIOUS_EULER,
        MECH_FICTITIOUS_TRANSLATIONAL};
    /* 1. applicability: which terms are not identically zero in this frame */
    const struct mech_vec3 w = mech_frame_omega(&p->frame);
    const int rotating_frame = p->frame.type == MECH_FRAME_ROTATING;
    const struct mech_vec3 wdot = rotating_frame ? p->frame.omega_dot : mech_vec3_make(0, 0, 0);
    const struct mech_vec3 A = rotating_frame ? p->frame.acceleration : mech_vec3_make(0, 0, 0);
    const int rotates = mech_vec3_norm(w) > 0.0 || mech_vec3_norm(wdot) > 0.0;
    const int applicable[MECH_TRAJECTORY_N_FICTITIOUS] = {
        p->frame.type != MECH_FRAME_INERTIAL && rotates,
        p->frame.type != MECH_FRAME_INERTIAL && rotates, mech_vec3_norm(wdot) > 0.0,
        mech_vec3_norm(A) > 0.0};
    static const char *const why_not[MECH_TRAJECTORY_N_FICTITIOUS] = {
        "not carried: the frame does not rotate (omega = 0, omega_dot = 0)",
        "not carried: the frame does not rotate (omega = 0, omega_dot = 0)",
        "not carried: the frame's angular velocity is constant (omega_dot = 0)",
        "not carried: the frame's origin does not accelerate (acceleration = 0)"};
    unsigned all = 0;
    for (int k = 0; k < MECH_TRAJECTORY_N_FICTITIOUS; k++) {
        m->terms[k].term = names[k];
        if (applicable[k]) {
            all |= bits[k];
        } else {
            snprintf(m->terms[k].reason, sizeof m->terms[k].reason, "%s",
                     p->frame.type == MECH_FRAME_INERTIAL ? "not carried: inertial frame"
                                                           : why_not[k]);
        }
    }
    if (!all) return MECH_OK;

    /* 2. the cheap first pass with every applicable term, draft accuracy */
    struct mech_trajectory_problem q = *p;
    q.fictitious = all;
    q.error_estimate = 0;
    q.reduce_planar = 0;
    if (q.samples > 101) q.samples = 101;
    struct mech_trajectory_choice ch;
    st = mech_trajectory_choose(&q, mech_accuracy_preset_at(MECH_ACCURACY_DRAFT)->promise, &ch,
                                err);
    if (st != MECH_OK) return st;
    q.method = ch.method;
    q.opt = ch.opt;
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r); /* no sample buffers: bounds come from the observer */
    st = mech_trajectory_integrate(&q, budget, &r, err);
    if (st != MECH_OK) return st;
    m->first_pass_done = 1;
    m->first_pass_method = r.method;
    m->first_pass_opt = q.opt;
    m->first_pass_stats = r.stats;
    m->time_scale = r.stopped ? r.t_stop : p->t_end;
    if (!(m->time_scale > 0.0)) m->time_scale = p->t_end;
    /* scales: the largest |r| and |v| seen at every step end and sample */
    m->position_scale = r.max_radius;
    m->velocity_scale = r.max_speed;

    /* 3. judge each applicable term */
    for (int k = 0; k < MECH_TRAJECTORY_N_FICTITIOUS; k++) {
        if (!applicable[k]) continue;
        double a = r.terms[p->n_forces + (size_t)k].max_acceleration;
        mech_term_effect_estimate(names[k], a, m->time_scale, m->position_scale,
                                  m->velocity_scale, target, m->safety, &m->terms[k]);
        if (m->terms[k].included) m->fictitious |= bits[k];
    }
    return MECH_OK;
}
