/* collision_answer.c — what POST /v1/relativity/kinematics/collision
 * computes (mech/answers/relativity/collision_answer.h): the beam solved from sqrt(s) when
 * asked, s and s - (m1 + m2)^2 of the two motions at their angle, the CM
 * system, the fixed-target and collider equivalents and a final state's
 * threshold, from the cancellation-free pieces of kinematics.c; and what POST
 * /v1/relativity/kinematics/elastic computes (mech/answers/relativity/elastic_answer.h):
 * the angle as given turned into radians, the scattering (elastic_scattering.c),
 * the projectile's boost (kinematics.c). */
#include <math.h>
#include <string.h>

#include "mech/answers/relativity/collision_answer.h"
#include "mech/base/constants.h"
#include <stdio.h>
#include "mech/answers/relativity/elastic_answer.h"

static int bad_mass(double m)
{
    return !(isfinite(m) && m >= 0);
}

static enum mech_status check(const struct mech_collision_request *q, struct mech_error *err)
{
    if (bad_mass(q->beam.mass))
        return mech_error_set(err, MECH_EDOMAIN, "beam/particle",
                              "a mass must be finite and >= 0, got %.17g", q->beam.mass);
    if (bad_mass(q->target.mass))
        return mech_error_set(err, MECH_EDOMAIN, "target/particle",
                              "a mass must be finite and >= 0, got %.17g", q->target.mass);
    if (!(q->crossing_angle >= 0 && q->crossing_angle <= MECH_PI))
        return mech_error_set(err, MECH_EINVAL, "crossing_angle",
                              "the crossing angle must be in [0, pi] rad, got %.17g",
                              q->crossing_angle);
    if (q->n_final > MECH_COLLISION_MAX_FINAL || (q->n_final && !q->final_masses))
        return mech_error_set(err, MECH_EINVAL, "final_state",
                              "a final state has 1 to %d particles", MECH_COLLISION_MAX_FINAL);
    for (size_t i = 0; i < q->n_final; i++)
        if (bad_mass(q->final_masses[i]))
            return mech_error_set(err, MECH_EDOMAIN, "final_state",
                                  "final mass %zu must be finite and >= 0, got %.17g", i,
                                  q->final_masses[i]);
    if (q->beam_from_sqrt_s && !isfinite(q->sqrt_s))
        return mech_error_set(err, MECH_EDOMAIN, "sqrt_s", "sqrt_s must be finite");
    if (q->beam_from_sqrt_s && q->target.momentum > 0)
        return mech_error_set(err, MECH_EINVAL, "sqrt_s",
                              "sqrt_s is solved for a target at rest; give the target no motion");
    return MECH_OK;
}

/* The beam a target of mass m2 at rest needs for sqrt(s) = w:
 * T = (w - m1 - m2)(w + m1 + m2) / (2 m2) (mech_kin_fixed_target_kinetic).
 * Every failure but a massless target is the sqrt_s field's. */
static enum mech_status beam_from_sqrt_s(double w, double m1, double m2,
                                         struct mech_kin_motion *beam, struct mech_error *err)
{
    struct mech_error e;
    mech_error_clear(&e);
    double t;
    enum mech_status st = mech_kin_fixed_target_kinetic(w, m1, m2, &t, &e);
    if (st == MECH_OK) st = mech_kin_motion_from_kinetic(m1, t, beam, &e);
    if (st == MECH_OK) return MECH_OK;
    const char *param = strcmp(e.param, "target/particle") ? "sqrt_s" : e.param;
    return mech_error_set(err, st, param, "%s", e.text);
}

/* A final state's threshold (notes problem 18: p p -> p p p pbar). */
static void threshold(const struct mech_collision_request *q, double w,
                      struct mech_collision_threshold *th)
{
    const double m1 = q->beam.mass, m2 = q->target.mass;
    const double sum = -mech_kin_q_value(0.0, q->final_masses, q->n_final);
    memset(th, 0, sizeof *th);
    th->sqrt_s = sum;
    th->reached = w >= sum;
    if (m2 > 0) {
        double t = 0;
        const double mi[2] = {m1, m2};
        if (mech_kin_q_value(sum, mi, 2) > 0) mech_kin_fixed_target_kinetic(sum, m1, m2, &t, NULL);
        th->has_fixed_target = 1;
        th->fixed_target_beam_energy = m1 + t;
        th->fixed_target_beam_kinetic = t;
        th->fixed_target_beam_momentum = sqrt(t * (t + 2 * m1));
    }
    if (m1 == m2 && sum / 2 >= m1) {
        th->has_symmetric_collider = 1;
        th->symmetric_collider_beam_energy = sum / 2;
    }
}

static int finite_motion(const struct mech_kin_motion *k)
{
    return isfinite(k->mass) && isfinite(k->energy) && isfinite(k->kinetic) &&
           isfinite(k->momentum);
}

/* Every number the answer reports is finite (the CM velocity only when
 * there is a rest frame). */
static int answer_finite(const struct mech_collision_answer *a)
{
    const struct mech_kin_system *cm = &a->cm;
    const struct mech_collision_threshold *th = &a->threshold;
    const double x[] = {a->s,
                        a->sqrt_s,
                        a->s_minus_threshold,
                        a->available_energy,
                        a->cm_momentum,
                        a->fixed_target_beam_energy,
                        a->fixed_target_beam_kinetic,
                        a->symmetric_collider_beam_energy,
                        th->sqrt_s,
                        th->fixed_target_beam_energy,
                        th->fixed_target_beam_kinetic,
                        th->fixed_target_beam_momentum,
                        th->symmetric_collider_beam_energy,
                        cm->energy};
    for (size_t i = 0; i < sizeof x / sizeof x[0]; i++)
        if (!isfinite(x[i])) return 0;
    if (!finite_motion(&a->beam) || !finite_motion(&a->target)) return 0;
    if (!mech_vec3_isfinite(cm->momentum)) return 0;
    return !cm->has_rest_frame || (isfinite(cm->gamma) && isfinite(cm->gamma_minus_one) &&
                                   isfinite(cm->rapidity) && isfinite(cm->one_minus_beta) &&
                                   isfinite(cm->beta_gamma) && mech_vec3_isfinite(cm->beta));
}

enum mech_status mech_collision_answer(const struct mech_collision_request *q,
                                       struct mech_collision_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    enum mech_status st = check(q, err);
    if (st != MECH_OK) return st;
    memset(out, 0, sizeof *out);
    const double m1 = q->beam.mass, m2 = q->target.mass;
    out->target = q->target;
    out->beam = q->beam;
    if (q->beam_from_sqrt_s) {
        st = beam_from_sqrt_s(q->sqrt_s, m1, m2, &out->beam, err);
        if (st != MECH_OK) return st;
    }
    const struct mech_kin_motion *kb = &out->beam, *kt = &out->target;
    /* Geometry: beam along +z; a moving target along (sin chi, 0, -cos chi).
     * The angle alpha between the momenta is pi - chi:
     * 1 - cos alpha = 1 + cos chi = 2 cos^2(chi / 2). */
    const double chi = q->crossing_angle, ch = cos(0.5 * chi), sh = sin(0.5 * chi);
    double s, d;
    mech_kin_collision_s(kb, kt, 2.0 * ch * ch, &s, &d);
    const double w = sqrt(s);
    out->s = s;
    out->sqrt_s = w;
    out->s_minus_threshold = d;
    out->available_energy = d / (w + m1 + m2);
    out->cm_momentum = mech_kin_cm_momentum(w, d, m1, m2);
    struct mech_kin_system *cm = &out->cm;
    cm->mass = w;
    cm->mass_squared = s;
    cm->energy = kb->energy + kt->energy;
    /* P_z = p1 - p2 cos chi = (p1 - p2) + p2 2 sin^2(chi / 2), p1 - p2 from the
     * beams' own inputs (not of the rounded momenta: nearly symmetric beams
     * keep the CM velocity's digits). */
    cm->momentum =
        mech_vec3_make(kt->momentum * sin(chi), 0,
                       mech_kin_momentum_difference(kb, kt) + kt->momentum * 2.0 * sh * sh);
    mech_kin_system_finish(cm);
    if (m2 > 0) {
        const double t = d / (2.0 * m2); /* s - (m1 + m2)^2 = 2 m2 T on a fixed target */
        out->has_fixed_target = 1;
        out->fixed_target_beam_energy = m1 + t;
        out->fixed_target_beam_kinetic = t;
    }
    if (m1 == m2 && w / 2 >= m1) {
        out->has_symmetric_collider = 1;
        out->symmetric_collider_beam_energy = w / 2;
    }
    out->has_threshold = q->n_final > 0;
    if (out->has_threshold) threshold(q, w, &out->threshold);
    if (!answer_finite(out))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the result is not finite for this input (overflow or a "
                              "singularity)");
    return MECH_OK;
}

const char *mech_elastic_angle_key(enum mech_elastic_angle kind, int in_degrees)
{
    static const char *const keys[3][2] = {
        {"cm_angle", "cm_angle_deg"},
        {"angle", "angle_deg"},
        {"recoil_angle", "recoil_angle_deg"},
    };
    if ((int)kind < 0 || (int)kind > 2) return "angle";
    return keys[kind][in_degrees ? 1 : 0];
}

enum mech_status mech_elastic_answer(const struct mech_elastic_request *q,
                                     struct mech_elastic_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    struct mech_elastic_answer a;
    const double rad = q->angle_in_degrees ? q->angle / 180.0 * MECH_PI : q->angle;
    enum mech_status st =
        mech_elastic_scatter(&q->projectile, q->target_mass, q->kind, rad, q->branch, &a.scatter, err);
    if (st != MECH_OK) {
        if (err && !strcmp(err->param, "angle"))
            snprintf(err->param, sizeof err->param, "%s",
                     mech_elastic_angle_key(q->kind, q->angle_in_degrees));
        return st;
    }
    /* the projectile's own velocity, when it has a rest frame (m1 > 0) */
    a.has_projectile_boost =
        q->projectile.mass > 0 &&
        mech_kin_motion_boost(&q->projectile, mech_vec3_make(0, 0, 1), &a.projectile_boost, NULL) ==
            MECH_OK;
    a.branch = q->branch < (int)a.scatter.n_solutions ? q->branch : 0;
    *out = a;
    return MECH_OK;
}
