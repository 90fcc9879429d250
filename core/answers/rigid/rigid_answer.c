/* rigid_answer.c — a rigid body's rotation into arrays the answer owns, from
 * the closed form or by integration (mech/answers/rigid/rigid_answer.h): what
 * POST /v1/rigid/rotate computes; the handler parses and encodes. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mech/answers/rigid/rigid_answer.h"

void mech_rigid_answer_free(struct mech_rigid_answer *a)
{
    if (!a) return;
    free(a->r.t);
    free(a->r.quaternion);
    free(a->r.kinetic_energy);
    free(a->r.omega);
    free(a->r.angular_momentum);
    a->r.t = a->r.quaternion = a->r.kinetic_energy = NULL;
    a->r.omega = a->r.angular_momentum = NULL;
}

enum mech_status mech_rigid_answer_run(const struct mech_rigid_problem *p, int closed_form,
                                       const struct mech_budget *budget,
                                       struct mech_rigid_answer *out, struct mech_error *err)
{
    memset(out, 0, sizeof *out);
    const size_t n = p->samples;
    if (n > SIZE_MAX / (4 * sizeof(double)))
        return mech_error_set(err, MECH_EINVAL, "samples", "%zu samples cannot be stored", n);
    struct mech_rigid_result *r = &out->r;
    r->t = malloc(n * sizeof *r->t);
    r->quaternion = malloc(4 * n * sizeof *r->quaternion);
    r->kinetic_energy = malloc(n * sizeof *r->kinetic_energy);
    r->omega = malloc(n * sizeof *r->omega);
    r->angular_momentum = malloc(n * sizeof *r->angular_momentum);
    if (!r->t || !r->quaternion || !r->kinetic_energy || !r->omega || !r->angular_momentum)
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
    out->closed = closed_form;
    return closed_form ? mech_rigid_closed_form(p, r, &out->ev, budget, err)
                       : mech_rigid_rotate(p, budget, r, err);
}
