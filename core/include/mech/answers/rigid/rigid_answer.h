/* mech/answers/rigid/rigid_answer.h — one POST /v1/rigid/rotate run: the torque-free
 * body's closed form (mech/rigid/rigid_closed_form.h) or Euler's equations with a
 * quaternion attitude integrated (mech/rigid/rigid_rotation.h), into sample
 * arrays this call allocates. SI units (kg m^2, rad/s, s, J). Thread-safe. */
#ifndef MECH_RIGID_ANSWER_H
#define MECH_RIGID_ANSWER_H

#include "mech/base/budget.h"
#include "mech/rigid/rigid_closed_form.h"
#include "mech/rigid/rigid_rotation.h"
#include "mech/base/status.h"

struct mech_rigid_answer {
    /* r.t, r.omega, r.quaternion (4 per sample), r.angular_momentum and
     * r.kinetic_energy: arrays of problem.samples entries owned by the answer
     * (free with mech_rigid_answer_free), filled up to r.n_samples */
    struct mech_rigid_result r;
    int closed;                                /* 1: answered from the closed form */
    struct mech_rigid_closed_form_evidence ev; /* closed: its evidence (zero otherwise) */
};

/* Run p (method and opt set by the caller; samples >= 2, t_end > 0, as
 * mech_rigid_rotate checks) from the closed form when closed_form is 1 (the
 * chooser picked it: torque-free, off the separatrix), else by integration,
 * within *budget (mandatory). Statuses: EINVAL "samples" when the arrays'
 * size would overflow; ENOMEM "out of memory for N samples"; those of
 * mech_rigid_closed_form or mech_rigid_rotate (EINVAL/EDOMAIN naming the
 * field, EBUDGET, EDEADLINE, ECANCELLED, ENUMERIC, ENOMEM). out is always
 * initialised; the caller frees it with mech_rigid_answer_free on every
 * path. err may be NULL. */
enum mech_status mech_rigid_answer_run(const struct mech_rigid_problem *p, int closed_form,
                                       const struct mech_budget *budget,
                                       struct mech_rigid_answer *out, struct mech_error *err);

/* Free the answer's arrays (NULL-safe, idempotent). */
void mech_rigid_answer_free(struct mech_rigid_answer *a);

#endif
