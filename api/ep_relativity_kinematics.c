/* ep_relativity_kinematics.c — particle kinematics in natural units (notes §3
 * "Kinematics Problems in Electron Volts", π⁰ decay, neutron decay, Compton
 * scattering; problems 10–12, 18, 19):
 *   POST /v1/relativity/kinematics/invariant-mass
 *   POST /v1/relativity/kinematics/decay
 *   POST /v1/relativity/kinematics/compton
 *   POST /v1/relativity/kinematics/collision
 * Energies, masses (unit/c²) and momenta (unit/c) are in `energy_unit`
 * (eV … TeV, default MeV; c = 1). Particles are a name from the PDG 2024 table
 * (core/relativity/particles.c) or a mass. The numerics live in
 * core/relativity/kinematics.c; the collision's whole answer is one call,
 * mech_collision_answer (core/relativity/collision_answer.c), which this file
 * reads the request for and encodes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/answers/relativity/collision_answer.h"
#include "mech/relativity/decay_estimate.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"
#include "kin_request.h"


/* ---- shared schema fragments --------------------------------------------------- */

/* clang-format off */

/* The particle table as catalog text (names with masses in MeV/c²). */

/* A particle with an optional state of motion (none given: at rest). */
/* clang-format on */

/* ---- shared request readers -------------------------------------------------- */

/* Angle from key (radians) or key_deg (degrees), at most one. Returns 1 if
 * present (value in *rad), 0 if absent, -1 after recording an error. */
static int angle_of(struct api_call *c, const json_t *obj, const char *key, const char *ptr,
                    double *rad)
{
    char kdeg[64];
    snprintf(kdeg, sizeof kdeg, "%s_deg", key);
    const json_t *r = json_object_get(obj, key), *d = json_object_get(obj, kdeg);
    if (r && d) {
        api_call_invalid(c, ptr, "give %s (radians) or %s (degrees), not both", key, kdeg);
        return -1;
    }
    if (r) *rad = json_number_value(r);
    if (d) *rad = json_number_value(d) / 180.0 * MECH_PI;
    return r || d;
}

/* mass, energy, kinetic_energy, momentum and (massive) the precise speed. */
static json_t *describe_motion(struct api_call *c, const struct mech_kin_motion *k)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "mass", api_real(c, k->mass));
    json_object_set_new_nocheck(o, "energy", api_real(c, k->energy));
    json_object_set_new_nocheck(o, "kinetic_energy", api_real(c, k->kinetic));
    json_object_set_new_nocheck(o, "momentum", api_real(c, k->momentum));
    struct mech_boost b;
    if (k->mass > 0 && mech_kin_motion_boost(k, mech_vec3_make(0, 0, 1), &b, NULL) == MECH_OK) {
        json_object_set_new_nocheck(o, "gamma", api_real(c, b.gamma));
        json_object_set_new_nocheck(o, "gamma_minus_one", api_real(c, b.gamma_minus_one));
        json_object_set_new_nocheck(o, "beta", api_real(c, b.beta));
        json_object_set_new_nocheck(o, "one_minus_beta", api_real(c, b.one_minus_beta));
        json_object_set_new_nocheck(o, "beta_gamma", api_real(c, b.beta_gamma));
        json_object_set_new_nocheck(o, "rapidity", api_real(c, b.rapidity));
    } else if (k->mass == 0) {
        json_object_set_new_nocheck(o, "beta", json_real(1.0));
        json_object_set_new_nocheck(o, "one_minus_beta", json_real(0.0));
    }
    return o;
}

/* The CM velocity block of a system (null when the total is light-like). */
static json_t *describe_cm(struct api_call *c, const struct mech_kin_system *s)
{
    if (!s->has_rest_frame) return json_null();
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "gamma", api_real(c, s->gamma));
    json_object_set_new_nocheck(o, "gamma_minus_one", api_real(c, s->gamma_minus_one));
    json_object_set_new_nocheck(o, "beta", api_vec3(c, s->beta));
    json_object_set_new_nocheck(o, "rapidity", api_real(c, s->rapidity));
    json_object_set_new_nocheck(o, "one_minus_beta", api_real(c, s->one_minus_beta));
    json_object_set_new_nocheck(o, "beta_gamma", api_real(c, s->beta_gamma));
    return o;
}

static json_t *finish(struct api_call *c, json_t *res)
{
    if (!res) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    return res;
}

/* ---- POST /v1/relativity/kinematics/invariant-mass ---------------------------- */

json_t *api_op_relativity_kinematics_invariant_mass(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    if (!api_kin_unit_of(c, body, &u)) return NULL;
    const json_t *moms = json_object_get(body, "momenta");
    size_t n = json_array_size(moms);
    struct mech_kin_particle *ps = malloc(n * sizeof *ps);
    if (!ps) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    json_t *clamped = json_array();
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        const json_t *it = json_array_get(moms, i);
        char ptr[64];
        snprintf(ptr, sizeof ptr, "/momenta/%zu", i);
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st;
        if (json_is_array(it)) {
            double p4[4];
            for (size_t k = 0; k < 4; k++)
                p4[k] = json_number_value(json_array_get(it, k));
            int cl = 0;
            st = mech_kin_particle_from_four(p4, &ps[i], &cl, &e);
            if (st == MECH_OK && cl) json_array_append_new(clamped, json_integer((json_int_t)i));
        } else {
            char pp[80];
            double m;
            snprintf(pp, sizeof pp, "%s/particle", ptr);
            if (!api_kin_mass_of(c, json_object_get(it, "particle"), pp, u, &m)) {
                bad = 1;
                continue;
            }
            st = mech_kin_particle_from_mass(
                m, api_vec3_member(it, "momentum", mech_vec3_make(0, 0, 0)), &ps[i], &e);
        }
        if (st != MECH_OK) {
            if (st == MECH_EDOMAIN)
                api_call_domain(c, ptr, "momentum %zu: %s", i, e.text);
            else
                api_call_fail_core(c, st, &e, ptr);
            bad = 1;
        }
    }
    struct mech_kin_system s;
    struct mech_error e;
    mech_error_clear(&e);
    if (bad) {
        free(ps);
        json_decref(clamped);
        return NULL;
    }
    enum mech_status st = mech_kin_invariant_mass(ps, n, &c->budget, &s, &e);
    free(ps);
    if (st != MECH_OK) {
        json_decref(clamped);
        return api_call_fail_core(c, st, &e, "");
    }
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "invariant_mass", api_real(c, s.mass));
    json_object_set_new_nocheck(res, "invariant_mass_squared", api_real(c, s.mass_squared));
    json_object_set_new_nocheck(res, "total_energy", api_real(c, s.energy));
    json_object_set_new_nocheck(res, "total_momentum", api_vec3(c, s.momentum));
    json_object_set_new_nocheck(res, "center_of_momentum", describe_cm(c, &s));
    if (!s.has_rest_frame)
        json_object_set_new_nocheck(
            res, "note",
            json_string("the total 4-momentum is light-like (M = 0): no frame "
                        "has zero total momentum"));
    if (json_array_size(clamped))
        json_object_set_new_nocheck(res, "lightlike_clamped", clamped);
    else
        json_decref(clamped);
    return finish(c, res);
}

/* ---- POST /v1/relativity/kinematics/decay ------------------------------------------ */

/* The *_deg companion of an angle in radians (the description's promise). */
static json_t *deg_of(struct api_call *c, double rad)
{
    return api_real(c, rad * (180.0 / MECH_PI));
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

static json_t *two_body(struct api_call *c, const json_t *body, const struct mech_boost *b,
                        double mp, const double m[2], json_t *res)
{
    struct mech_kin_two_body tb;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_kin_two_body_rest(mp, m[0], m[1], &tb, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    double theta_star = 0, half = 0;
    int has_ts = angle_of(c, body, "theta_star", "/theta_star", &theta_star);
    const json_t *cone = json_object_get(body, "cone");
    int has_cone = 0;
    if (cone) {
        has_cone = angle_of(c, cone, "half_angle", "/cone/half_angle", &half);
        if (has_cone == 0) {
            api_call_invalid(c, "/cone", "the cone needs half_angle or half_angle_deg");
            has_cone = -1;
        } else if (has_cone == 1 && !(half > 0)) {
            api_call_domain(c, "/cone/half_angle", "the cone's half-angle must be > 0");
            has_cone = -1;
        }
    }
    if (json_object_get(body, "angles") || json_object_get(body, "angles_deg"))
        api_call_invalid(c, json_object_get(body, "angles") ? "/angles" : "/angles_deg",
                         "angles describe a three-body decay; this one has two daughters");
    if (has_ts < 0 || has_cone < 0 || c->problem != API_PROBLEM_NONE) return NULL;

    json_object_set_new_nocheck(res, "q_value", api_real(c, tb.q_value));
    json_t *rf = json_object();
    json_object_set_new_nocheck(rf, "momentum", api_real(c, tb.momentum));
    json_object_set_new_nocheck(rf, "energies", api_reals(c, tb.energy, 2));
    json_object_set_new_nocheck(rf, "kinetic_energies", api_reals(c, tb.kinetic, 2));
    json_object_set_new_nocheck(res, "rest_frame", rf);

    json_t *ranges = json_array(), *maxang = json_array(), *maxdeg = json_array();
    for (int i = 0; i < 2; i++) {
        struct mech_kin_lab fw, bw;
        mech_kin_decay_lab(b, m[i], tb.momentum, tb.energy[i], 0.0, 0, &fw);
        mech_kin_decay_lab(b, m[i], tb.momentum, tb.energy[i], MECH_PI, 0, &bw);
        double r[2] = {bw.energy, fw.energy};
        json_array_append_new(ranges, api_reals(c, r, 2));
        double tm;
        const int has_max = mech_kin_decay_max_angle(b, m[i], tb.momentum, &tm);
        json_array_append_new(maxang, has_max ? api_real(c, tm) : json_null());
        json_array_append_new(maxdeg, has_max ? deg_of(c, tm) : json_null());
    }
    json_object_set_new_nocheck(res, "lab_energy_ranges", ranges);
    json_object_set_new_nocheck(res, "maximum_lab_angles", maxang);
    json_object_set_new_nocheck(res, "maximum_lab_angles_deg", maxdeg);
    double a, at;
    mech_kin_decay_min_opening(b, m, tb.momentum, tb.energy, &a, &at);
    json_t *mo = json_object();
    json_object_set_new_nocheck(mo, "angle", api_real(c, a));
    json_object_set_new_nocheck(mo, "angle_deg", deg_of(c, a));
    json_object_set_new_nocheck(mo, "theta_star", api_real(c, at));
    json_object_set_new_nocheck(mo, "theta_star_deg", deg_of(c, at));
    json_object_set_new_nocheck(res, "minimum_opening_angle", mo);

    if (has_ts == 1) {
        struct mech_kin_lab l1, l2;
        mech_kin_decay_lab(b, m[0], tb.momentum, tb.energy[0], theta_star, 0, &l1);
        mech_kin_decay_lab(b, m[1], tb.momentum, tb.energy[1], theta_star, 1, &l2);
        double open = l1.angle + l2.angle;
        if (open > MECH_PI) open = 2 * MECH_PI - open;
        json_t *o = json_object(), *ds = json_array();
        json_object_set_new_nocheck(o, "theta_star", api_real(c, theta_star));
        json_object_set_new_nocheck(o, "theta_star_deg", deg_of(c, theta_star));
        json_array_append_new(ds, lab_json(c, &l1));
        json_array_append_new(ds, lab_json(c, &l2));
        json_object_set_new_nocheck(o, "daughters", ds);
        json_object_set_new_nocheck(o, "opening_angle", api_real(c, open));
        json_object_set_new_nocheck(o, "opening_angle_deg", deg_of(c, open));
        json_object_set_new_nocheck(res, "at_theta_star", o);
    }
    if (has_cone == 1) {
        int i = (int)api_number(cone, "daughter", 0);
        double r[2][2], edges[2];
        int nr = mech_kin_decay_cone(b, m[i], tb.momentum, tb.energy[i], half, r, edges);
        json_t *o = json_object(), *rs = json_array();
        json_object_set_new_nocheck(o, "daughter", json_integer(i));
        json_object_set_new_nocheck(o, "half_angle", api_real(c, half));
        json_object_set_new_nocheck(o, "half_angle_deg", deg_of(c, half));
        for (int k = 0; k < nr; k++)
            json_array_append_new(rs, api_reals(c, r[k], 2));
        json_object_set_new_nocheck(o, "energy_ranges", rs);
        json_object_set_new_nocheck(o, "theta_star_edges", api_reals(c, edges, (size_t)nr));
        json_object_set_new_nocheck(res, "cone", o);
    }
    return res;
}

/* The notes' estimate of daughter i's endpoint (notes §3.16 Neutron Decay)
 * beside the exact one, labelled; null when the others are all massless. */
static json_t *notes_estimate_json(struct api_call *c, double mp, const double m[3], size_t i)
{
    struct mech_decay_estimate d;
    if (mech_decay_endpoint_estimate(mp, m, 3, i, &d, NULL) != MECH_OK) return json_null();
    json_t *o = json_object(), *mid = json_object();
    json_object_set_new_nocheck(
        o, "label",
        json_string("approximation (notes 3.16, Neutron Decay): the other daughters recoil as "
                    "one body of mass recoil_mass taking no kinetic energy, E ~ M - recoil_mass, "
                    "p ~ sqrt((M - recoil_mass)^2 - m^2), T ~ Q; good when recoil_mass >> Q; "
                    "the exact endpoint is beside it"));
    json_object_set_new_nocheck(o, "recoil_mass", api_real(c, d.recoil_mass));
    json_object_set_new_nocheck(o, "energy", api_real(c, d.energy));
    json_object_set_new_nocheck(o, "kinetic_energy", api_real(c, d.kinetic));
    json_object_set_new_nocheck(o, "momentum", api_real(c, d.momentum));
    json_object_set_new_nocheck(o, "kinetic_energy_minus_exact", api_real(c, d.kinetic_minus_exact));
    json_object_set_new_nocheck(o, "momentum_minus_exact", api_real(c, d.momentum_minus_exact));
    json_object_set_new_nocheck(
        mid, "label",
        json_string("the notes' step before: the recoil non-relativistic, p^2 (1 + (M - "
                    "recoil_mass)/recoil_mass) = (M - recoil_mass)^2 - m^2 (its p^4 term dropped)"));
    json_object_set_new_nocheck(mid, "momentum", api_real(c, d.mid_momentum));
    json_object_set_new_nocheck(mid, "kinetic_energy", api_real(c, d.mid_kinetic));
    json_object_set_new_nocheck(mid, "kinetic_energy_minus_exact",
                                api_real(c, d.mid_kinetic_minus_exact));
    json_object_set_new_nocheck(mid, "momentum_minus_exact", api_real(c, d.mid_momentum_minus_exact));
    json_object_set_new_nocheck(o, "intermediate", mid);
    return o;
}

static json_t *three_body(struct api_call *c, const json_t *body, const struct mech_boost *b,
                          double mp, const double m[3], json_t *res)
{
    static const char *const two_only[] = {"theta_star", "theta_star_deg", "cone"};
    for (int i = 0; i < 3; i++) {
        if (json_object_get(body, two_only[i])) {
            char p[40];
            snprintf(p, sizeof p, "/%s", two_only[i]);
            api_call_invalid(c, p, "%s is for two-body decays; this one has three daughters",
                             two_only[i]);
        }
    }
    const json_t *ar = json_object_get(body, "angles"), *ad = json_object_get(body, "angles_deg");
    if (ar && ad) api_call_invalid(c, "/angles", "give angles or angles_deg, not both");
    if (c->problem != API_PROBLEM_NONE) return NULL;
    json_t *ends = json_array();
    json_object_set_new_nocheck(res, "q_value", api_real(c, mech_kin_q_value(mp, m, 3)));
    json_object_set_new_nocheck(res, "maximum_energies", ends);
    json_t *labmax = b->beta > 0 ? json_array() : NULL;
    for (size_t i = 0; i < 3; i++) {
        double em, tm, pm;
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st = mech_kin_endpoint(mp, m, 3, i, &em, &tm, &pm, &e);
        if (st != MECH_OK) {
            json_decref(labmax);
            return api_call_fail_core(c, st, &e, "");
        }
        json_t *o = json_object();
        json_object_set_new_nocheck(o, "energy", api_real(c, em));
        json_object_set_new_nocheck(o, "kinetic_energy", api_real(c, tm));
        json_object_set_new_nocheck(o, "momentum", api_real(c, pm));
        json_object_set_new_nocheck(o, "notes_estimate", notes_estimate_json(c, mp, m, i));
        json_array_append_new(ends, o);
        if (labmax) {
            struct mech_kin_lab l;
            mech_kin_decay_lab(b, m[i], pm, em, 0.0, 0, &l);
            json_array_append_new(labmax, api_real(c, l.energy));
        }
    }
    if (labmax) json_object_set_new_nocheck(res, "lab_maximum_energies", labmax);
    if (ar || ad) {
        const json_t *a = ar ? ar : ad;
        double t01 = json_number_value(json_array_get(a, 0));
        double t12 = json_number_value(json_array_get(a, 1));
        t01 = ar ? t01 : t01 / 180.0 * MECH_PI;
        t12 = ar ? t12 : t12 / 180.0 * MECH_PI;
        double mom[3], en[3], ke[3];
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st = mech_kin_three_body_planar(mp, m, t01, t12, mom, en, ke, &e);
        if (st != MECH_OK) {
            if (!strcmp(e.param, "angles") && ad) snprintf(e.param, sizeof e.param, "angles_deg");
            return api_call_fail_core(c, st, &e, "");
        }
        json_t *o = json_object();
        json_object_set_new_nocheck(o, "momenta", api_reals(c, mom, 3));
        json_object_set_new_nocheck(o, "energies", api_reals(c, en, 3));
        json_object_set_new_nocheck(o, "kinetic_energies", api_reals(c, ke, 3));
        json_object_set_new_nocheck(res, "planar", o);
    }
    return res;
}

json_t *api_op_relativity_kinematics_decay(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    if (!api_kin_unit_of(c, body, &u)) return NULL;
    const json_t *parent = json_object_get(body, "parent");
    const json_t *ds = json_object_get(body, "daughters");
    double mp = 0, m[3] = {0, 0, 0};
    int ok = api_kin_mass_of(c, json_object_get(parent, "particle"), "/parent/particle", u, &mp);
    size_t n = json_array_size(ds);
    for (size_t i = 0; i < n; i++) {
        char p[40];
        snprintf(p, sizeof p, "/daughters/%zu", i);
        ok &= api_kin_mass_of(c, json_array_get(ds, i), p, u, &m[i]);
    }
    if (!ok) return NULL;
    if (!(mp > 0)) {
        api_call_domain(c, "/parent/particle",
                        "a massless particle cannot decay: it has no rest frame (it always "
                        "moves at c)");
        return NULL;
    }
    struct mech_kin_motion k;
    int given;
    if (!api_kin_motion_of(c, parent, "/parent", mp, &k, &given)) return NULL;
    struct mech_boost b;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_kin_motion_boost(&k, mech_vec3_make(0, 0, 1), &b, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "/parent");

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "parent", describe_motion(c, &k));
    json_t *out = n == 2 ? two_body(c, body, &b, mp, m, res) : three_body(c, body, &b, mp, m, res);
    if (!out) {
        json_decref(res);
        return NULL;
    }
    return finish(c, out);
}

/* ---- POST /v1/relativity/kinematics/compton ---------------------------------------- */

json_t *api_op_relativity_kinematics_compton(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    if (!api_kin_unit_of(c, body, &u)) return NULL;
    const json_t *je = json_object_get(body, "energy"), *jw = json_object_get(body, "wavelength");
    if (je && jw) api_call_invalid(c, "/wavelength", "give energy or wavelength, not both");
    if (!je && !jw) api_call_invalid(c, "", "give the photon's energy or wavelength");
    double theta = 0;
    int ha = angle_of(c, body, "angle", "/angle", &theta);
    if (ha == 0) api_call_invalid(c, "", "give the scattering angle as angle or angle_deg");
    double m = 0;
    const json_t *jt = json_object_get(body, "target");
    int okm = 1;
    if (jt)
        okm = api_kin_mass_of(c, jt, "/target", u, &m);
    else
        m = mech_energy_convert(mech_particle_find("electron")->mass, MECH_MEV, u);
    if (!okm || c->problem != API_PROBLEM_NONE) return NULL;
    double hc = mech_energy_hc(u);
    double lambda = jw ? json_number_value(jw) : 0;
    double e = jw ? hc / lambda : json_number_value(je);
    if (!(m > 0)) {
        api_call_domain(c, "/target",
                        "the target must have a mass: a massless particle cannot be at rest");
        return NULL;
    }
    struct mech_kin_compton r;
    struct mech_error err;
    mech_error_clear(&err);
    enum mech_status st = mech_kin_compton(e, m, theta, &r, &err);
    if (st != MECH_OK) {
        if (!strcmp(err.param, "energy") && jw) snprintf(err.param, sizeof err.param, "wavelength");
        return api_call_fail_core(c, st, &err, "");
    }
    double lc = hc / m, dl = lc * r.one_minus_cos;
    if (!jw) lambda = hc / e;
    double lambda_out = jw ? lambda + dl : hc / r.energy_out;

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "target_mass", api_real(c, m));
    json_object_set_new_nocheck(res, "angle", api_real(c, theta));
    json_object_set_new_nocheck(res, "angle_deg", deg_of(c, theta));
    json_t *in = json_object(), *sc = json_object(), *rc = json_object();
    json_object_set_new_nocheck(in, "energy", api_real(c, e));
    json_object_set_new_nocheck(in, "wavelength", api_real(c, lambda));
    json_object_set_new_nocheck(res, "incident", in);
    json_object_set_new_nocheck(sc, "energy", api_real(c, r.energy_out));
    json_object_set_new_nocheck(sc, "wavelength", api_real(c, lambda_out));
    json_object_set_new_nocheck(res, "scattered", sc);
    json_object_set_new_nocheck(res, "wavelength_shift", api_real(c, dl));
    json_object_set_new_nocheck(res, "compton_wavelength", api_real(c, lc));
    json_object_set_new_nocheck(rc, "kinetic_energy", api_real(c, r.recoil_kinetic));
    json_object_set_new_nocheck(rc, "energy", api_real(c, m + r.recoil_kinetic));
    json_object_set_new_nocheck(rc, "momentum", api_real(c, r.recoil_momentum));
    json_object_set_new_nocheck(rc, "angle", api_real(c, r.recoil_angle));
    json_object_set_new_nocheck(rc, "angle_deg", deg_of(c, r.recoil_angle));
    json_object_set_new_nocheck(res, "recoil", rc);
    return finish(c, res);
}

/* ---- POST /v1/relativity/kinematics/collision -------------------------------------- */

/* The request as the core takes it (mf: room for the final masses); 0 after
 * recording every error found (masses, the crossing angle, the motions, and
 * what cannot go together: a crossing angle with a target at rest, sqrt_s
 * with a beam energy or a moving target). */
static int collision_read(struct api_call *c, const json_t *body, enum mech_energy_unit u,
                          struct mech_collision_request *q, double mf[MECH_COLLISION_MAX_FINAL])
{
    memset(q, 0, sizeof *q);
    const json_t *jb = json_object_get(body, "beam"), *jt = json_object_get(body, "target");
    const json_t *jw = json_object_get(body, "sqrt_s"), *jf = json_object_get(body, "final_state");
    double m1 = 0, m2 = 0;
    int ok = api_kin_mass_of(c, json_object_get(jb, "particle"), "/beam/particle", u, &m1);
    ok &= api_kin_mass_of(c, json_object_get(jt, "particle"), "/target/particle", u, &m2);
    q->n_final = json_array_size(jf); /* the schema's maxItems is the core's limit */
    for (size_t i = 0; i < q->n_final && i < MECH_COLLISION_MAX_FINAL; i++) {
        char p[40];
        snprintf(p, sizeof p, "/final_state/%zu", i);
        ok &= api_kin_mass_of(c, json_array_get(jf, i), p, u, &mf[i]);
    }
    q->final_masses = mf;
    const int hx = angle_of(c, body, "crossing_angle", "/crossing_angle", &q->crossing_angle);
    int gt = 0, gb = 0;
    if (!ok || hx < 0 || !api_kin_motion_of(c, jt, "/target", m2, &q->target, &gt)) return 0;
    if (hx && !gt)
        api_call_invalid(
            c, json_object_get(body, "crossing_angle") ? "/crossing_angle" : "/crossing_angle_deg",
            "a crossing angle needs a moving target (a second beam)");
    if (jw) {
        static const char *const keys[] = {"energy", "kinetic_energy", "momentum", "velocity"};
        for (int i = 0; i < 4; i++)
            if (json_object_get(jb, keys[i]))
                api_call_invalid(c, "/sqrt_s", "give either the beam's %s or sqrt_s, not both",
                                 keys[i]);
        if (gt)
            api_call_invalid(c, "/sqrt_s",
                             "sqrt_s is solved for a target at rest; give the "
                             "target no motion");
        q->beam_from_sqrt_s = 1;
        q->sqrt_s = json_number_value(jw);
        q->beam.mass = m1;
    } else if (!api_kin_motion_of(c, jb, "/beam", m1, &q->beam, &gb)) {
        return 0;
    }
    return c->problem == API_PROBLEM_NONE;
}

/* The threshold block of a final state. */
static json_t *threshold_json(struct api_call *c, const struct mech_collision_threshold *t)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "sqrt_s", api_real(c, t->sqrt_s));
    json_object_set_new_nocheck(o, "reached", json_boolean(t->reached));
    if (t->has_fixed_target) {
        json_object_set_new_nocheck(o, "fixed_target_beam_energy",
                                    api_real(c, t->fixed_target_beam_energy));
        json_object_set_new_nocheck(o, "fixed_target_beam_kinetic_energy",
                                    api_real(c, t->fixed_target_beam_kinetic));
        json_object_set_new_nocheck(o, "fixed_target_beam_momentum",
                                    api_real(c, t->fixed_target_beam_momentum));
    }
    if (t->has_symmetric_collider)
        json_object_set_new_nocheck(o, "symmetric_collider_beam_energy",
                                    api_real(c, t->symmetric_collider_beam_energy));
    return o;
}

json_t *api_op_relativity_kinematics_collision(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    struct mech_collision_request q;
    double mf[MECH_COLLISION_MAX_FINAL];
    if (!api_kin_unit_of(c, body, &u) || !collision_read(c, body, u, &q, mf)) return NULL;
    struct mech_collision_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_collision_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "sqrt_s", api_real(c, a.sqrt_s));
    json_object_set_new_nocheck(res, "s", api_real(c, a.s));
    json_object_set_new_nocheck(res, "available_energy", api_real(c, a.available_energy));
    json_object_set_new_nocheck(res, "cm_momentum", api_real(c, a.cm_momentum));
    json_object_set_new_nocheck(res, "beam", describe_motion(c, &a.beam));
    json_object_set_new_nocheck(res, "target", describe_motion(c, &a.target));
    json_object_set_new_nocheck(res, "center_of_momentum", describe_cm(c, &a.cm));
    if (a.has_fixed_target) {
        json_object_set_new_nocheck(res, "fixed_target_beam_energy",
                                    api_real(c, a.fixed_target_beam_energy));
        json_object_set_new_nocheck(res, "fixed_target_beam_kinetic_energy",
                                    api_real(c, a.fixed_target_beam_kinetic));
    }
    if (a.has_symmetric_collider)
        json_object_set_new_nocheck(res, "symmetric_collider_beam_energy",
                                    api_real(c, a.symmetric_collider_beam_energy));
    if (a.has_threshold)
        json_object_set_new_nocheck(res, "threshold", threshold_json(c, &a.threshold));
    return finish(c, res);
}

/* ---- routes ------------------------------------------------------------------------ */

/* ---- GET /v1/relativity/particles ------------------------------------------ */

json_t *api_op_relativity_particles(struct api_call *c, const json_t *body)
{
    (void)body;
    json_t *list = json_array();
    for (size_t i = 0; list && i < mech_particle_count(); i++) {
        const struct mech_particle *p = mech_particle_at(i);
        json_array_append_new(list, json_pack("{s:s,s:o,s:s}", "name", p->name, "mass_mev",
                                              api_real(c, p->mass), "source", p->source));
    }
    return json_pack("{s:s,s:s,s:o}", "edition", MECH_PARTICLE_EDITION, "mass_unit", "MeV/c^2",
                     "particles", list);
}

