/* top_answer.c — the heavy symmetric top's run into arrays the answer owns,
 * with the initial angular velocity from the Euler rates (mech/answers/rigid/top_answer.h):
 * what POST /v1/rigid/top computes; the handler parses and encodes. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mech/rotation/euler_rates.h"
#include "mech/answers/rigid/top_answer.h"

#define TOP_ANSWER_MAX_SAMPLES 100000 /* mech_top_integrate's own limit */

void mech_top_answer_free(struct mech_top_answer *a)
{
    if (!a) return;
    free(a->r.t);
    free(a->r.axis);
    free(a->r.at_pole);
    a->r.t = a->r.theta = a->r.phi = a->r.psi = a->r.phi_plus_psi = NULL;
    a->r.axis = NULL;
    a->r.at_pole = NULL;
}

/* One block of 5 n doubles (t, theta, phi, psi, phi + psi), the axes and the
 * pole flags. 0 when out of memory. */
static int alloc_samples(struct mech_top_result *r, size_t n)
{
    double *buf = malloc(5 * n * sizeof *buf);
    r->t = buf;
    r->axis = malloc(n * sizeof *r->axis);
    r->at_pole = malloc(n * sizeof *r->at_pole);
    if (!buf || !r->axis || !r->at_pole) return 0;
    r->theta = buf + n;
    r->phi = buf + 2 * n;
    r->psi = buf + 3 * n;
    r->phi_plus_psi = buf + 4 * n;
    return 1;
}

static int all_finite(const double *x, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* Every number the answer reports is finite (NaN precession rates stand for
 * "none" and are not numbers the answer reports). */
static int answer_finite(const struct mech_top_answer *a)
{
    const struct mech_top_result *r = &a->r;
    const size_t n = r->n_samples;
    const double s[] = {r->omega3,
                        r->rate_scale,
                        r->p_phi0,
                        r->p_psi0,
                        r->E0,
                        r->p_phi_final,
                        r->p_psi_final,
                        r->E_final,
                        r->max_p_phi_drift,
                        r->max_p_psi_drift,
                        r->max_E_drift,
                        r->theta_min_measured,
                        r->theta_max_measured,
                        r->max_quaternion_norm_drift,
                        r->turning.theta_min,
                        r->turning.theta_max,
                        r->sleep_lhs,
                        r->sleep_rhs,
                        r->critical_omega3};
    if (!all_finite(s, sizeof s / sizeof s[0])) return 0;
    if (!all_finite(r->turning.roots, (size_t)r->turning.n_roots)) return 0;
    if (!all_finite(r->t, 5 * n)) return 0; /* t, theta, phi, psi, phi + psi: one block */
    for (size_t i = 0; i < n; i++)
        if (!mech_vec3_isfinite(r->axis[i])) return 0;
    return !a->has_initial_omega ||
           (mech_vec3_isfinite(a->initial_omega_body) &&
            mech_vec3_isfinite(a->initial_omega_space) && isfinite(a->initial_omega_magnitude));
}

enum mech_status mech_top_answer_run(const struct mech_top_problem *p,
                                     const struct mech_budget *budget, struct mech_top_answer *out,
                                     struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(out, 0, sizeof *out);
    if (!p) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    const size_t n = p->samples;
    /* out of range: no arrays, and mech_top_integrate names the field */
    if (n >= 2 && n <= TOP_ANSWER_MAX_SAMPLES && !alloc_samples(&out->r, n))
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
    enum mech_status st = mech_top_integrate(p, budget, &out->r, err);
    if (st != MECH_OK) return st;
    /* omega at t = 0 from the Euler rates (notes §2.7), the forward map */
    const double ang[3] = {p->phi, p->theta, p->psi},
                 rt[3] = {p->phi_dot, p->theta_dot, p->psi_dot};
    struct mech_euler_kinematics k;
    if (mech_euler_kinematics(ang, rt, &k, NULL) == MECH_OK) {
        out->has_initial_omega = 1;
        out->initial_omega_body = k.omega_body;
        out->initial_omega_space = k.omega_space;
        out->initial_omega_magnitude = mech_vec3_norm(k.omega_body);
    }
    if (!answer_finite(out))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the result is not finite for this input (overflow or a "
                              "singularity)");
    return MECH_OK;
}
