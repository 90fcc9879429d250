/* charged_motion_answer.c — one /v1/relativity/charge-in-fields answer
 * (mech/answers/relativity/charged_motion_answer.h) from the exact motion of charged_motion.c. */
#include "mech/answers/relativity/charged_motion_answer.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for parameter paths */
#include <string.h>

#include "mech/base/constants.h"

static enum mech_status times_check(const double *x, size_t n, const char *name,
                                    struct mech_error *err)
{
    if (n > MECH_CHARGED_MAX_TIMES || (n && !x))
        return mech_error_set(err, MECH_EINVAL, name, "at most %d times",
                              MECH_CHARGED_MAX_TIMES);
    for (size_t i = 0; i < n; i++) {
        if (!(isfinite(x[i]) && x[i] >= 0.0)) {
            char p[48];
            snprintf(p, sizeof p, "%s/%zu", name, i);
            return mech_error_set(err, isfinite(x[i]) ? MECH_EDOMAIN : MECH_EINVAL, p,
                                  "times are from the start: finite and >= 0, got %.17g", x[i]);
        }
    }
    return MECH_OK;
}

enum mech_status mech_charged_answer(const struct mech_charged_question *q,
                                     struct mech_charged_answer *a,
                                     struct mech_charged_motion_state *states_t,
                                     struct mech_charged_motion_state *states_tau,
                                     struct mech_error *err)
{
    if (!q || !a) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(a, 0, sizeof *a);
    if (!isfinite(q->mass)) return mech_error_set(err, MECH_EINVAL, "mass", "must be finite");
    if (!(q->mass > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "mass must be > 0, got %.17g", q->mass);
    if (!isfinite(q->charge)) return mech_error_set(err, MECH_EINVAL, "charge", "must be finite");
    const struct { struct mech_vec3 v; const char *name; } vs[] = {
        {q->E, "E"}, {q->B, "B"}, {q->force, "force"}, {q->position, "position"},
        {q->proper_velocity, "proper_velocity"}};
    for (size_t i = 0; i < sizeof vs / sizeof vs[0]; i++)
        if (!mech_vec3_isfinite(vs[i].v))
            return mech_error_set(err, MECH_EINVAL, vs[i].name, "components must be finite");
    enum mech_status st;
    if ((st = times_check(q->t, q->n_t, "times", err)) != MECH_OK) return st;
    if ((st = times_check(q->tau, q->n_tau, "proper_times", err)) != MECH_OK) return st;
    if ((q->n_t && !states_t) || (q->n_tau && !states_tau))
        return mech_error_set(err, MECH_EINVAL, NULL, "NULL state buffer");

    const double c = MECH_C, qm = q->charge / q->mass;
    const struct mech_vec3 eps =
        mech_vec3_add(mech_vec3_scale(q->E, qm), mech_vec3_scale(q->force, 1.0 / q->mass));
    const struct mech_vec3 om = mech_vec3_scale(q->B, qm);
    st = mech_charged_motion_init(eps, om, q->position, q->proper_velocity, &a->motion, err);
    if (st != MECH_OK) {
        /* name the request's field: q E/m or q B/m overflowing is the field's (or
         * the charge-to-mass ratio's) doing */
        static const char *const map[][2] = {
            {"fields", "E"}, {"eps", "E"}, {"omega", "B"}, {"u0", "proper_velocity"},
            {"r0", "position"}};
        for (size_t i = 0; err && i < sizeof map / sizeof map[0]; i++)
            if (!strcmp(err->param, map[i][0])) {
                snprintf(err->param, sizeof err->param, "%s", map[i][1]);
                break;
            }
        return st;
    }
    const struct mech_charged_motion *m = &a->motion;

    /* invariants of the effective field, from the fields as given */
    if (q->charge != 0.0) {
        const struct mech_vec3 Ee = mech_vec3_add(q->E, mech_vec3_scale(q->force, 1.0 / q->charge));
        const double en = mech_vec3_norm(Ee), cb = c * mech_vec3_norm(q->B);
        a->e2_minus_c2b2 = (en - cb) * (en + cb);
        a->e_dot_b = mech_vec3_dot(Ee, q->B);
    } else {
        const double en = mech_vec3_norm(eps), cw = c * mech_vec3_norm(om);
        a->e2_minus_c2b2 = (en - cw) * (en + cw);
        a->e_dot_b = mech_vec3_dot(eps, om);
    }
    a->frame_velocity = mech_vec3_scale(m->beta_w, c);
    a->frame_beta = m->beta_w_norm;
    a->frame_gamma = m->gamma_w;
    a->has_frame_fields = q->charge != 0.0;
    if (a->has_frame_fields) {
        a->frame_E = mech_vec3_scale(m->n, m->a_prime / qm);
        a->frame_B = mech_vec3_scale(m->n, m->omega_prime / qm);
    }
    a->vanishes = m->a_prime == 0.0 && m->omega_prime == 0.0 ? "both"
                  : m->a_prime == 0.0                        ? "E"
                  : m->omega_prime == 0.0                    ? "B"
                                                             : "neither";
    if (m->omega_prime != 0.0) {
        const double w = fabs(m->omega_prime);
        a->has_helix = 1;
        a->omega_proper = m->omega_prime;
        a->radius = mech_vec3_norm(m->uperp0p) / w;
        a->proper_period = 2.0 * MECH_PI / w;
        if (m->a_prime == 0.0) {
            const double gp = m->U00p / c;
            a->has_pitch = 1;
            a->period = a->proper_period * gp;
            a->pitch = 2.0 * MECH_PI * m->un0p / w;
            a->speed_along = m->un0p / gp;
        }
    }
    if (m->a_prime != 0.0) {
        a->has_hyperbolic = 1;
        a->accel_proper = m->a_prime;
    }
    for (size_t i = 0; i < q->n_t; i++) {
        st = mech_charged_motion_at_lab_time(m, q->t[i], &states_t[i], err);
        if (st != MECH_OK) {
            if (err) snprintf(err->param, sizeof err->param, "times/%zu", i);
            return st;
        }
    }
    for (size_t i = 0; i < q->n_tau; i++) {
        st = mech_charged_motion_at_proper_time(m, q->tau[i], &states_tau[i], err);
        if (st != MECH_OK) {
            if (err) snprintf(err->param, sizeof err->param, "proper_times/%zu", i);
            return st;
        }
    }
    return MECH_OK;
}
