/* mech/answers/rigid/top_answer.h — one POST /v1/rigid/top answer: the heavy symmetric top
 * run (mech/rigid/top.h: the closed forms of the initial state, the nutation's
 * turning points, the integration with its conserved quantities) into sample
 * arrays this call allocates, and the body and space angular velocity of
 * the initial Euler rates (mech/rotation/euler_rates.h). SI units (kg m^2, kg, m,
 * m/s^2, rad, rad/s, s, J). Thread-safe. */
#ifndef MECH_TOP_ANSWER_H
#define MECH_TOP_ANSWER_H

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/rigid/top.h"
#include "mech/base/vec.h"

struct mech_top_answer {
    /* r.t, r.theta, r.phi, r.psi, r.phi_plus_psi, r.axis and r.at_pole:
     * arrays of problem.samples entries owned by the answer (free with
     * mech_top_answer_free), filled up to r.n_samples; the rest of r as
     * mech_top_integrate fills it (NaN precession rates mean "none") */
    struct mech_top_result r;
    /* omega at t = 0 from (phi, theta, psi) and their rates (notes §2.7),
     * rad/s; valid when has_initial_omega (the forward map succeeded) */
    int has_initial_omega;
    struct mech_vec3 initial_omega_body, initial_omega_space;
    double initial_omega_magnitude; /* |omega_body| */
};

/* Run p (method and opt set by the caller, e.g. by the chooser) within
 * *budget (mandatory). Arrays are allocated only for 2 <= samples <= 100000
 * (otherwise mech_top_integrate reports the samples field). Statuses:
 * MECH_OK; MECH_ENOMEM "out of memory for N samples"; those of
 * mech_top_integrate (EDOMAIN/EINVAL naming the field, EBUDGET, EDEADLINE,
 * ECANCELLED with progress in s, ENUMERIC, ENOMEM); MECH_ENUMERIC "the
 * result is not finite for this input (overflow or a singularity)" when a
 * reported number of a finished run overflows. out is always initialised;
 * the caller frees it with mech_top_answer_free on every path. err may be
 * NULL. */
enum mech_status mech_top_answer_run(const struct mech_top_problem *p,
                                     const struct mech_budget *budget, struct mech_top_answer *out,
                                     struct mech_error *err);

/* Free the answer's arrays (NULL-safe, idempotent). */
void mech_top_answer_free(struct mech_top_answer *a);

#endif
