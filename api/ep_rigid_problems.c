/* ep_rigid_problems.c — the rigid-body chapter's closed-form problems:
 *   POST /v1/rigid/free-symmetric-top  (notes §2.9: cones and precession rates)
 *   POST /v1/rigid/struck-ball         (notes §2.11 HW 3: rolling without slipping)
 *   POST /v1/rigid/topple              (notes §2.11 HW 4: a box falling off its edge)
 * JSON <-> core only: physics and derivations in core/rigid/rigid_problems.c and
 * mech/rigid/rigid_problems.h. */
#include <math.h>
#include <string.h>

#include "endpoint.h"
#include "mech/base/constants.h"
#include "mech/rigid/rigid_problems.h"


static void set_real(struct api_call *c, json_t *o, const char *k, double x)
{
    json_object_set_new(o, k, api_real(c, x));
}

static void set_angle(struct api_call *c, json_t *o, const char *k, double rad)
{
    json_t *a = json_object();
    if (!a) return;
    set_real(c, a, "rad", rad);
    set_real(c, a, "deg", rad * (180 / MECH_PI));
    json_object_set_new(o, k, a);
}

/* ============================ free symmetric top ============================ */

static json_t *period_or_null(struct api_call *c, double rate)
{
    return rate != 0 ? api_real(c, 2 * MECH_PI / fabs(rate)) : json_null();
}

json_t *api_op_rigid_free_symmetric_top(struct api_call *c, const json_t *body)
{
    const json_t *mo = json_object_get(body, "moments"), *wj = json_object_get(body, "omega");
    double ip = json_number_value(json_array_get(mo, 0)), i3 = json_number_value(json_array_get(mo, 1));
    double w[3];
    for (int k = 0; k < 3; k++) w[k] = json_number_value(json_array_get(wj, (size_t)k));
    struct mech_free_symmetric_top t;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_free_symmetric_top(ip, i3, w, &t, &e);
    if (st != MECH_OK) {
        const char *p = !strcmp(e.param, "i_perp") ? "/moments/0"
                        : !strcmp(e.param, "i3")   ? "/moments/1"
                                                   : "/omega";
        if (st == MECH_EDOMAIN) api_call_domain(c, p, "%s", e.text);
        else api_call_invalid(c, p, "%s", e.text);
        return NULL;
    }
    json_t *out = json_object();
    if (!out) return NULL;
    set_real(c, out, "angular_momentum", t.angular_momentum);
    set_real(c, out, "omega_magnitude", t.omega_magnitude);
    set_angle(c, out, "theta", t.theta);
    set_angle(c, out, "body_cone", t.alpha);
    set_angle(c, out, "space_cone", t.space_cone);
    set_angle(c, out, "angle_L_omega", t.space_cone);
    set_real(c, out, "precession_space", t.precession_space);
    json_object_set_new(out, "precession_space_period", period_or_null(c, t.precession_space));
    set_real(c, out, "precession_body", t.precession_body);
    json_object_set_new(out, "precession_body_period", period_or_null(c, t.precession_body));
    set_real(c, out, "notes_omega", -t.precession_body);
    json_object_set_new(out, "precession_body_sense",
                        json_string(t.precession_body == 0 ? "none"
                                    : (t.precession_body > 0) == (w[2] > 0) ? "with_spin"
                                                                            : "against_spin"));
    set_real(c, out, "dynamical_ellipticity", t.ellipticity);
    json_object_set_new(out, "free_precession_period", period_or_null(c, t.precession_body));
    json_object_set_new(out, "free_precession_period_in_spin_periods",
                        t.ellipticity != 0 ? api_real(c, 1 / fabs(t.ellipticity)) : json_null());
    json_object_set_new(out, "shape", json_string(t.prolate ? "prolate"
                                                  : i3 > ip ? "oblate"
                                                            : "spherical"));
    json_object_set_new(out, "formula",
                        json_string("tan theta = I_perp w_perp/(I3 w3), tan alpha = w_perp/w3, "
                                    "phi_dot = |L|/I_perp, psi_dot = (I_perp - I3) w3/I_perp "
                                    "(notes §2.9)"));
    return out;
}

/* ================================ struck ball =============================== */

json_t *api_op_rigid_struck_ball(struct api_call *c, const json_t *body)
{
    double r = api_number_of(body, "radius"), m = api_number_of(body, "mass");
    const char *shape = api_string_of(body, "shape");
    double f = !strcmp(shape, "spherical_shell") ? 2.0 / 3 : !strcmp(shape, "solid_cylinder") ? 0.5
               : !strcmp(shape, "hoop")          ? 1.0
                                                 : 0.4;
    double k2 = json_object_get(body, "moment_of_inertia")
                    ? api_number(body, "moment_of_inertia", 0) / m
                    : f * r * r;
    double h = api_number(body, "height", k2 / r);
    struct mech_struck_ball s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_struck_ball(m, r, k2, api_number_of(body, "impulse"), h, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object();
    if (!out) return NULL;
    set_real(c, out, "k2_over_R2", k2 / (r * r));
    set_real(c, out, "rolling_height", s.rolling_height);
    set_real(c, out, "rolling_height_floor", s.rolling_height_floor);
    set_real(c, out, "height", h);
    set_real(c, out, "v0", s.v0);
    set_real(c, out, "w0", s.w0);
    set_real(c, out, "slip_velocity", s.slip_velocity);
    json_object_set_new(out, "rolls_at_once", json_boolean(fabs(s.slip_velocity) <= 1e-14 * s.v0));
    set_real(c, out, "v_final", s.v_final);
    set_real(c, out, "w_final", s.v_final / r);
    set_real(c, out, "energy_lost_fraction", s.energy_lost_fraction);
    return out;
}

/* ================================== topple ================================== */

json_t *api_op_rigid_topple(struct api_call *c, const json_t *body)
{
    double a = api_number(body, "width", 0);
    struct mech_topple t;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_topple_box(api_number_of(body, "mass"), a, api_number(body, "height", a),
                                          api_number_of(body, "g"), &t, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *held = json_object(), *free_ = json_object(),
           *ih = json_object(), *ifr = json_object();
    if (!out || !held || !free_ || !ih || !ifr) {
        json_decref(out);
        json_decref(held);
        json_decref(free_);
        json_decref(ih);
        json_decref(ifr);
        return NULL;
    }
    set_real(c, out, "drop", t.drop);
    set_real(c, held, "omega", t.omega_held);
    set_real(c, ih, "horizontal", t.impulse_held[0]);
    set_real(c, ih, "vertical", t.impulse_held[1]);
    set_real(c, ih, "magnitude", hypot(t.impulse_held[0], t.impulse_held[1]));
    json_object_set_new(held, "impulse", ih);
    set_real(c, free_, "omega", t.omega_free);
    set_real(c, ifr, "vertical", t.impulse_free);
    json_object_set_new(free_, "impulse", ifr);
    json_object_set_new(out, "edge_held", held);
    json_object_set_new(out, "frictionless", free_);
    json_object_set_new(out, "formula",
                        json_string("held: m g (d - b/2) = I_edge w^2/2, I_edge = m(a^2+b^2)/3; "
                                    "frictionless: m g (d - b/2) = (I_cm + m a^2/4) w^2/2"));
    return out;
}

