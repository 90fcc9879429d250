/* kinematics_decay.c — POST /v1/relativity/kinematics/decay: two- and
 * three-body decays in the parent's rest frame and the lab (notes §3: π⁰
 * decay, neutron decay; problems 10–12).
 * Energies, masses (unit/c²) and momenta (unit/c) are in `energy_unit`
 * (eV … TeV, default MeV; c = 1); particles are a name from the PDG 2024 table
 * (core/relativity/particles.c) or a mass. The numerics live in
 * core/relativity/kinematics.c; the readers and encoders the kinematics
 * operations share are api/ops/relativity/kin_request.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"
#include "ops/relativity/kin_request.h"
#include "mech/relativity/decay_estimate.h"


static json_t *lab_json(struct api_call *c, const struct mech_kin_lab *l)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "energy", api_real(c, l->energy));
    json_object_set_new_nocheck(o, "kinetic_energy", api_real(c, l->kinetic));
    json_object_set_new_nocheck(o, "momentum", api_real(c, l->momentum));
    json_object_set_new_nocheck(o, "momentum_parallel", api_real(c, l->momentum_parallel));
    json_object_set_new_nocheck(o, "momentum_transverse", api_real(c, l->momentum_transverse));
    json_object_set_new_nocheck(o, "angle", api_real(c, l->angle));
    json_object_set_new_nocheck(o, "angle_deg", api_kin_deg_of(c, l->angle));
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
    int has_ts = api_kin_angle_of(c, body, "theta_star", "/theta_star", &theta_star);
    const json_t *cone = json_object_get(body, "cone");
    int has_cone = 0;
    if (cone) {
        has_cone = api_kin_angle_of(c, cone, "half_angle", "/cone/half_angle", &half);
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
        json_array_append_new(maxdeg, has_max ? api_kin_deg_of(c, tm) : json_null());
    }
    json_object_set_new_nocheck(res, "lab_energy_ranges", ranges);
    json_object_set_new_nocheck(res, "maximum_lab_angles", maxang);
    json_object_set_new_nocheck(res, "maximum_lab_angles_deg", maxdeg);
    double a, at;
    mech_kin_decay_min_opening(b, m, tb.momentum, tb.energy, &a, &at);
    json_t *mo = json_object();
    json_object_set_new_nocheck(mo, "angle", api_real(c, a));
    json_object_set_new_nocheck(mo, "angle_deg", api_kin_deg_of(c, a));
    json_object_set_new_nocheck(mo, "theta_star", api_real(c, at));
    json_object_set_new_nocheck(mo, "theta_star_deg", api_kin_deg_of(c, at));
    json_object_set_new_nocheck(res, "minimum_opening_angle", mo);

    if (has_ts == 1) {
        struct mech_kin_lab l1, l2;
        mech_kin_decay_lab(b, m[0], tb.momentum, tb.energy[0], theta_star, 0, &l1);
        mech_kin_decay_lab(b, m[1], tb.momentum, tb.energy[1], theta_star, 1, &l2);
        double open = l1.angle + l2.angle;
        if (open > MECH_PI) open = 2 * MECH_PI - open;
        json_t *o = json_object(), *ds = json_array();
        json_object_set_new_nocheck(o, "theta_star", api_real(c, theta_star));
        json_object_set_new_nocheck(o, "theta_star_deg", api_kin_deg_of(c, theta_star));
        json_array_append_new(ds, lab_json(c, &l1));
        json_array_append_new(ds, lab_json(c, &l2));
        json_object_set_new_nocheck(o, "daughters", ds);
        json_object_set_new_nocheck(o, "opening_angle", api_real(c, open));
        json_object_set_new_nocheck(o, "opening_angle_deg", api_kin_deg_of(c, open));
        json_object_set_new_nocheck(res, "at_theta_star", o);
    }
    if (has_cone == 1) {
        int i = (int)api_number(cone, "daughter", 0);
        double r[2][2], edges[2];
        int nr = mech_kin_decay_cone(b, m[i], tb.momentum, tb.energy[i], half, r, edges);
        json_t *o = json_object(), *rs = json_array();
        json_object_set_new_nocheck(o, "daughter", json_integer(i));
        json_object_set_new_nocheck(o, "half_angle", api_real(c, half));
        json_object_set_new_nocheck(o, "half_angle_deg", api_kin_deg_of(c, half));
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
    json_object_set_new_nocheck(res, "parent", api_kin_describe_motion(c, &k));
    json_t *out = n == 2 ? two_body(c, body, &b, mp, m, res) : three_body(c, body, &b, mp, m, res);
    if (!out) {
        json_decref(res);
        return NULL;
    }
    return api_kin_finish(c, out);
}
