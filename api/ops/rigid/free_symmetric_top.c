/* free_symmetric_top.c — POST /v1/rigid/free-symmetric-top (notes §2.9: the
 * torque-free symmetric top's cones and precession rates).
 * JSON <-> core only: physics and derivations in core/rigid/rigid_problems.c
 * and mech/rigid/rigid_problems.h. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
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
