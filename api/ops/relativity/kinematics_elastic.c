/* kinematics_elastic.c — POST /v1/relativity/kinematics/elastic: two-body
 * relativistic elastic scattering off a target at rest at a given CM, lab or
 * recoil angle, answered in the lab and the CM frame (notes §3 kinematics,
 * problem 16; Compton is the massless-projectile case). What it computes is
 * one call, mech_elastic_answer() (core/answers/relativity/collision_answer.c, on
 * elastic_scattering.c); the unit, masses and the projectile's motion are
 * read by api/ops/relativity/kin_request.c, as the other kinematics operations read them; this
 * file reads the request and encodes the answer. */
#include <stdio.h>

#include "run/endpoint.h"
#include "ops/relativity/kin_request.h"
#include "mech/base/constants.h"
#include "mech/answers/relativity/elastic_answer.h"

static json_t *deg_of(struct api_call *c, double rad)
{
    return api_real(c, rad * (180.0 / MECH_PI));
}

/* The projectile's lab motion (api/ops/relativity/kin_request.c's reader), which must be given
 * and nonzero; 0 after recording an error. */
static int motion_of(struct api_call *c, const json_t *obj, double m, struct mech_kin_motion *k)
{
    int given = 0;
    if (!api_kin_motion_of(c, obj, "/projectile", m, k, &given)) return 0;
    if (!given) {
        api_call_invalid(c, "/projectile", "give the projectile's energy, kinetic_energy, "
                                           "momentum or velocity: a projectile at rest does not "
                                           "reach the target");
        return 0;
    }
    if (!(k->momentum > 0)) {
        static const char *const keys[] = {"energy", "kinetic_energy", "momentum", "velocity"};
        char p[48] = "/projectile";
        for (int i = 0; i < 4; i++)
            if (json_object_get(obj, keys[i])) snprintf(p, sizeof p, "/projectile/%s", keys[i]);
        api_call_domain(c, p, "the projectile must move (momentum > 0) to reach a target at rest");
        return 0;
    }
    return 1;
}

/* Exactly one angle of the six keys (cm_angle, angle, recoil_angle, each
 * also as *_deg) into q: its kind, value and unit. 0 after recording an
 * error. */
static int angle_of(struct api_call *c, const json_t *body, struct mech_elastic_request *q)
{
    static const enum mech_elastic_angle kinds[] = {MECH_ELASTIC_CM_ANGLE, MECH_ELASTIC_LAB_ANGLE,
                                                    MECH_ELASTIC_RECOIL_ANGLE};
    const char *seen = NULL;
    for (size_t i = 0; i < 3; i++) {
        for (int d = 0; d < 2; d++) {
            const char *key = mech_elastic_angle_key(kinds[i], d);
            const json_t *v = json_object_get(body, key);
            if (!v) continue;
            if (seen) {
                char p[40];
                snprintf(p, sizeof p, "/%s", key);
                api_call_invalid(c, p, "give exactly one angle (%s was given too)", seen);
                return 0;
            }
            seen = mech_elastic_angle_key(kinds[i], 0);
            q->kind = kinds[i];
            q->angle = json_number_value(v);
            q->angle_in_degrees = d;
        }
    }
    if (!seen) {
        api_call_invalid(c, "", "give one angle: cm_angle, angle (the projectile's lab angle) or "
                                "recoil_angle (each also as *_deg)");
        return 0;
    }
    return 1;
}

/* The request as the core takes it; 0 after recording the errors (the
 * masses' and the angle's together, then the target's, then the motion's). */
static int read_request(struct api_call *c, const json_t *body, enum mech_energy_unit *u,
                        struct mech_elastic_request *q)
{
    if (!api_kin_unit_of(c, body, u)) return 0;
    const json_t *pj = json_object_get(body, "projectile");
    double m1 = 0;
    int ok = api_kin_mass_of(c, json_object_get(pj, "particle"), "/projectile/particle", *u, &m1);
    ok &= api_kin_mass_of(c, json_object_get(body, "target"), "/target", *u, &q->target_mass);
    ok &= angle_of(c, body, q);
    if (!ok || c->problem != API_PROBLEM_NONE) return 0;
    if (!(q->target_mass > 0)) {
        api_call_domain(c, "/target", "the target must have a mass > 0: a massless particle "
                                      "cannot be at rest");
        return 0;
    }
    if (!motion_of(c, pj, m1, &q->projectile)) return 0;
    /* a request number is a real; the schema allows 0 or 1 (default 0) */
    q->branch = (int)api_number_of(body, "branch");
    return 1;
}

static json_t *lab_json(struct api_call *c, const struct mech_kin_lab *l)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "energy", api_real(c, l->energy));
    json_object_set_new_nocheck(o, "kinetic_energy", api_real(c, l->kinetic));
    json_object_set_new_nocheck(o, "momentum", api_real(c, l->momentum));
    json_object_set_new_nocheck(o, "momentum_parallel", api_real(c, l->momentum_parallel));
    json_object_set_new_nocheck(o, "momentum_transverse", api_real(c, l->momentum_transverse));
    json_object_set_new_nocheck(o, "angle", api_real(c, l->angle));
    json_object_set_new_nocheck(o, "angle_deg", deg_of(c, l->angle));
    return o;
}

/* "projectile": its lab motion, and γ, β, η when it has a rest frame. */
static json_t *projectile_json(struct api_call *c, const struct mech_elastic_request *q,
                               const struct mech_elastic_answer *a)
{
    const struct mech_kin_motion *k = &q->projectile;
    json_t *in = json_object();
    json_object_set_new_nocheck(in, "mass", api_real(c, k->mass));
    json_object_set_new_nocheck(in, "energy", api_real(c, k->energy));
    json_object_set_new_nocheck(in, "kinetic_energy", api_real(c, k->kinetic));
    json_object_set_new_nocheck(in, "momentum", api_real(c, k->momentum));
    if (a->has_projectile_boost) {
        json_object_set_new_nocheck(in, "gamma", api_real(c, a->projectile_boost.gamma));
        json_object_set_new_nocheck(in, "beta", api_real(c, a->projectile_boost.beta));
        json_object_set_new_nocheck(in, "rapidity", api_real(c, a->projectile_boost.rapidity));
    }
    return in;
}

/* "cm": the CM frame's velocity, the momentum, energies and angles there. */
static json_t *cm_json(struct api_call *c, const struct mech_elastic *o)
{
    json_t *cm = json_object(), *vel = json_object();
    json_object_set_new_nocheck(vel, "beta", api_real(c, o->cm.beta));
    json_object_set_new_nocheck(vel, "gamma", api_real(c, o->cm.gamma));
    json_object_set_new_nocheck(vel, "gamma_minus_one", api_real(c, o->cm.gamma_minus_one));
    json_object_set_new_nocheck(vel, "beta_gamma", api_real(c, o->cm.beta_gamma));
    json_object_set_new_nocheck(vel, "rapidity", api_real(c, o->cm.rapidity));
    json_object_set_new_nocheck(vel, "one_minus_beta", api_real(c, o->cm.one_minus_beta));
    json_object_set_new_nocheck(cm, "velocity", vel);
    json_object_set_new_nocheck(cm, "momentum", api_real(c, o->cm_momentum));
    json_object_set_new_nocheck(cm, "energies", api_reals(c, o->cm_energy, 2));
    json_object_set_new_nocheck(cm, "kinetic_energies", api_reals(c, o->cm_kinetic, 2));
    json_object_set_new_nocheck(cm, "angle", api_real(c, o->cm_angle));
    json_object_set_new_nocheck(cm, "angle_deg", deg_of(c, o->cm_angle));
    json_object_set_new_nocheck(cm, "recoil_angle", api_real(c, MECH_PI - o->cm_angle));
    json_object_set_new_nocheck(cm, "recoil_angle_deg",
                                api_real(c, 180.0 - o->cm_angle * (180.0 / MECH_PI)));
    return cm;
}

/* "solutions": every CM angle giving the requested angle, the branch used. */
static json_t *solutions_json(struct api_call *c, const struct mech_elastic_answer *a)
{
    const struct mech_elastic *o = &a->scatter;
    json_t *sol = json_object();
    double degs[2] = {0, 0};
    for (size_t i = 0; i < o->n_solutions && i < 2; i++)
        degs[i] = o->cm_angle_solutions[i] * (180.0 / MECH_PI);
    json_object_set_new_nocheck(sol, "count", json_integer((json_int_t)o->n_solutions));
    json_object_set_new_nocheck(sol, "branch", json_integer(a->branch));
    json_object_set_new_nocheck(sol, "cm_angles", api_reals(c, o->cm_angle_solutions, o->n_solutions));
    json_object_set_new_nocheck(sol, "cm_angles_deg", api_reals(c, degs, o->n_solutions));
    return sol;
}

json_t *api_op_relativity_kinematics_elastic(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    struct mech_elastic_request q = {0};
    if (!read_request(c, body, &u, &q)) return NULL;
    struct mech_elastic_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_elastic_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    const struct mech_elastic *o = &a.scatter;
    json_t *res = json_object(), *lab = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "projectile", projectile_json(c, &q, &a));
    json_object_set_new_nocheck(res, "target_mass", api_real(c, q.target_mass));
    json_object_set_new_nocheck(res, "s", api_real(c, o->s));
    json_object_set_new_nocheck(res, "sqrt_s", api_real(c, o->sqrt_s));
    json_object_set_new_nocheck(res, "t", api_real(c, o->t));
    json_object_set_new_nocheck(res, "u", api_real(c, o->u));
    json_object_set_new_nocheck(res, "momentum_transfer", api_real(c, o->momentum_transfer));
    json_object_set_new_nocheck(res, "cm", cm_json(c, o));
    json_object_set_new_nocheck(lab, "projectile", lab_json(c, &o->projectile));
    json_object_set_new_nocheck(lab, "recoil", lab_json(c, &o->recoil));
    json_object_set_new_nocheck(lab, "opening_angle", api_real(c, o->opening_angle));
    json_object_set_new_nocheck(lab, "opening_angle_deg", deg_of(c, o->opening_angle));
    json_object_set_new_nocheck(res, "lab", lab);
    json_object_set_new_nocheck(res, "velocity_ratio", api_real(c, o->velocity_ratio));
    json_object_set_new_nocheck(res, "max_lab_angle",
                                o->has_max_angle ? api_real(c, o->max_angle) : json_null());
    json_object_set_new_nocheck(res, "max_lab_angle_deg",
                                o->has_max_angle ? deg_of(c, o->max_angle) : json_null());
    json_object_set_new_nocheck(res, "solutions", solutions_json(c, &a));
    return res;
}
