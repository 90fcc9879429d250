/* ep_rigid_problems.c — the rigid-body chapter's closed-form problems:
 *   POST /v1/rigid/free-symmetric-top  (notes §2.9: cones and precession rates)
 *   POST /v1/rigid/struck-ball         (notes §2.11 HW 3: rolling without slipping)
 *   POST /v1/rigid/topple              (notes §2.11 HW 4: a box falling off its edge)
 * JSON <-> core only: physics and derivations in core/rigid_problems.c and
 * mech/rigid_problems.h. */
#include <math.h>
#include <string.h>

#include "endpoint.h"
#include "mech/rigid_problems.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define RP_POS(max, desc)                                                                          \
    "{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":" max ",\"description\":\"" desc "\"}"

static void set_real(struct api_call *c, json_t *o, const char *k, double x)
{
    json_object_set_new(o, k, api_real(c, x));
}

static void set_angle(struct api_call *c, json_t *o, const char *k, double rad)
{
    json_t *a = json_object();
    if (!a) return;
    set_real(c, a, "rad", rad);
    set_real(c, a, "deg", rad * (180 / M_PI));
    json_object_set_new(o, k, a);
}

/* ============================ free symmetric top ============================ */

/* clang-format off */
static const char ft_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"moments\",\"omega\"],\"properties\":{"
    "\"moments\":{\"type\":\"array\",\"minItems\":2,\"maxItems\":2,\"items\":" RP_POS("1e30", "kg m^2")
    ",\"description\":\"[I_perp, I3]: the two equal principal moments and the one about the "
    "symmetry axis, kg m^2\"},"
    "\"omega\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\","
    "\"minimum\":-1e6,\"maximum\":1e6},\"description\":\"rad/s, body components (w1, w2, w3), "
    "w3 along the symmetry axis; not all zero\"}"
    "}}";
/* clang-format on */

static const char ft_description[] =
    "The torque-free symmetric top in closed form (notes §2.9 \"Symmetric Top with no "
    "Torque\", HW 10). With I1 = I2 = I_perp, I3 and body angular velocity (w1, w2, w3), "
    "w_perp = |(w1, w2)|: L = I omega is fixed in space, and L, omega and the symmetry axis "
    "e3 lie in one plane. Answers: angular_momentum |L|; theta (e3 to L, tan theta = I_perp "
    "w_perp / (I3 w3)); body_cone (omega to e3, tan alpha = w_perp / w3: the cone omega traces "
    "in the body); space_cone (omega to L, |theta - alpha|: the cone omega traces in space); "
    "angle_L_omega (= space_cone); precession_space = |L| / I_perp (e3 and omega go round L: "
    "phi_dot in Euler angles with z along L); precession_body = psi_dot = (I_perp - I3) w3 / "
    "I_perp (omega round e3 seen in the body; the notes' Omega = (I3 - I1) w3 / I1 is the "
    "same rate with the opposite sign convention, given as notes_omega); omega = phi_dot L_hat "
    "+ psi_dot e3 exactly; shape prolate (I3 < I_perp: the body cone rolls on the outside of "
    "the space cone) or oblate (I3 > I_perp: the space cone inside the body cone) or "
    "spherical; the periods 2 pi / rate (null for a zero rate). Angles {rad, deg}. Refused "
    "(422, naming the field): moments <= 0, I3 > 2 I_perp (no body: I3 <= I1 + I2), omega "
    "zero or components beyond 1e6 rad/s, unknown keys.";

static const char ft_example[] = "{\"moments\": [1, 2], \"omega\": [1, 0, 2]}";

static json_t *period_or_null(struct api_call *c, double rate)
{
    return rate != 0 ? api_real(c, 2 * M_PI / fabs(rate)) : json_null();
}

static json_t *free_top(struct api_call *c, const json_t *body)
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
    json_object_set_new(out, "shape", json_string(t.prolate ? "prolate"
                                                  : i3 > ip ? "oblate"
                                                            : "spherical"));
    json_object_set_new(out, "formula",
                        json_string("tan theta = I_perp w_perp/(I3 w3), tan alpha = w_perp/w3, "
                                    "phi_dot = |L|/I_perp, psi_dot = (I_perp - I3) w3/I_perp "
                                    "(notes §2.9)"));
    return out;
}

const struct api_route api_route_rigid_free_symmetric_top = {
    "POST",
    "/v1/rigid/free-symmetric-top",
    "The torque-free symmetric top in closed form: space and body precession rates, the body "
    "and space cones, the angle between L and omega",
    ft_description,
    ft_schema,
    ft_example,
    free_top,
    0,
    1, /* quick */
};

/* ================================ struck ball =============================== */

/* clang-format off */
static const char sb_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"radius\"],\"properties\":{"
    "\"radius\":" RP_POS("1e6", "m, the ball's radius R (the contact point is R below the centre)") ","
    "\"shape\":{\"enum\":[\"solid_sphere\",\"spherical_shell\",\"solid_cylinder\",\"hoop\"],"
    "\"default\":\"solid_sphere\",\"description\":\"I_cm/(m R^2) = 2/5, 2/3, 1/2, 1; "
    "moment_of_inertia overrides it\"},"
    "\"moment_of_inertia\":" RP_POS("1e30", "kg m^2, I_cm about the rolling axis (instead of shape)") ","
    "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,\"default\":1,"
    "\"description\":\"kg\"},"
    "\"impulse\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,\"default\":1,"
    "\"description\":\"N s, the horizontal impulse of the strike\"},"
    "\"height\":{\"type\":\"number\",\"minimum\":-1e6,\"maximum\":1e6,\"description\":\"m, where "
    "the strike hits above the centre (|height| <= radius); default the rolling height\"}"
    "}}";
/* clang-format on */

static const char sb_description[] =
    "Where to strike a ball so that it rolls without slipping at once (notes §2.11 HW 3), "
    "and what happens if it is struck elsewhere. A horizontal impulse J at height h above "
    "the centre gives v0 = J/m and w0 = J h / I_cm = J h / (m k^2) (k^2 = I_cm/m); rolling "
    "needs v0 = w0 R, i.e. h = k^2/R: 2R/5 above the centre for a solid sphere, so a billiard "
    "cushion belongs at 7R/5 above the cloth (rolling_height_floor). Struck elsewhere it "
    "slides until friction makes it roll; angular momentum about the contact line is kept "
    "(friction acts there), so it rolls at v_final = v0 R (R + h)/(R^2 + k^2), whatever the "
    "friction coefficient, losing energy_lost_fraction of its kinetic energy. Answer (SI): "
    "k2_over_R2 (I_cm/(m R^2)), rolling_height, rolling_height_floor, height (used), v0, w0, "
    "slip_velocity (v0 - w0 R: > 0 the bottom slides forward, backspin side), rolls_at_once, "
    "v_final, w_final = v_final/R, energy_lost_fraction. Refused (422, naming the field): "
    "|height| > radius, non-positive radius, mass, impulse or moment_of_inertia, unknown keys.";

static const char sb_example[] = "{\"radius\": 0.028575, \"mass\": 0.17, \"impulse\": 0.5}";

static json_t *struck_ball(struct api_call *c, const json_t *body)
{
    double r = api_number(body, "radius", 0), m = api_number(body, "mass", 1);
    const char *shape = api_string(body, "shape", "solid_sphere");
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
    enum mech_status st = mech_struck_ball(m, r, k2, api_number(body, "impulse", 1), h, &s, &e);
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

const struct api_route api_route_rigid_struck_ball = {
    "POST",
    "/v1/rigid/struck-ball",
    "The height at which a struck ball rolls without slipping (2R/5 above the centre for a "
    "solid sphere), and the rolling speed and energy lost when struck elsewhere",
    sb_description,
    sb_schema,
    sb_example,
    struck_ball,
    0,
    1, /* quick */
};

/* ================================== topple ================================== */

/* clang-format off */
static const char tp_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"width\"],\"properties\":{"
    "\"width\":" RP_POS("1e6", "m, the box's side a in the plane of the fall (a cube: its side)") ","
    "\"height\":" RP_POS("1e6", "m, the side b that ends vertical; default width (a cube)") ","
    "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,\"default\":1,"
    "\"description\":\"kg (scales the impulses only)\"},"
    "\"g\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e4,\"default\":9.80665,"
    "\"description\":\"m/s^2\"}"
    "}}";
/* clang-format on */

static const char tp_description[] =
    "A uniform box balanced on one edge, its centre of mass above the edge, falls onto its "
    "base (notes §2.11 HW 4, for a cube). Its centre of mass drops from d = sqrt(a^2 + b^2)/2 "
    "to b/2. Edge held (no slip): energy m g (d - b/2) = I_edge w^2/2, I_edge = m (a^2 + "
    "b^2)/3; for a cube w = sqrt((3g/(2l)) (sqrt 2 - 1)), the notes' answer. Frictionless "
    "floor: no horizontal force, so the centre of mass falls straight down; when the base "
    "lands the edge is a/2 from it, v_cm = w a/2 and m g (d - b/2) = (I_cm + m a^2/4) w^2/2, "
    "I_cm = m (a^2 + b^2)/12; for a cube w = sqrt((12g/(5l)) (sqrt 2 - 1)) (the edge is "
    "assumed to stay on the floor). The impulse the floor gives to stop the box as it lands "
    "(no bounce) is m v_cm: edge held {horizontal m w b/2, vertical m w a/2}, frictionless "
    "{vertical m w a/2}. Answer: drop (m), edge_held {omega, impulse {horizontal, vertical, "
    "magnitude}}, frictionless {omega, impulse {vertical}}, formula. Refused (422, naming the "
    "field): non-positive width, height, mass or g, unknown keys.";

static const char tp_example[] = "{\"width\": 0.1}";

static json_t *topple(struct api_call *c, const json_t *body)
{
    double a = api_number(body, "width", 0);
    struct mech_topple t;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_topple_box(api_number(body, "mass", 1), a, api_number(body, "height", a),
                                          api_number(body, "g", 9.80665), &t, &e);
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

const struct api_route api_route_rigid_topple = {
    "POST",
    "/v1/rigid/topple",
    "A box balanced on an edge falls onto its base: the angular velocity as it lands with the "
    "edge held or on a frictionless floor, and the floor's impulse that stops it",
    tp_description,
    tp_schema,
    tp_example,
    topple,
    0,
    1, /* quick */
};
