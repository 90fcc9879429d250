/* ep_relativity_frames.c — changing frames in special relativity:
 *   POST /v1/relativity/velocity-addition  (notes §3.9, §3.10; Wigner rotation)
 *   POST /v1/relativity/interval           (notes §3.5, §3.6)
 *   POST /v1/relativity/worldline          (notes §3.14, §3.15: the twin paradox)
 * The numerics live in core/velocity_addition.c, core/interval.c and
 * core/worldline.c; every velocity input is the shared form of
 * api/velocity_request.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "mech/boost.h"
#include "mech/interval.h"
#include "mech/velocity_addition.h"
#include "mech/telescope.h"
#include "mech/worldline.h"
#include "velocity_request.h"

#define FR_DIR3                                                                                    \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\","            \
    "\"minimum\":-1e150,\"maximum\":1e150},\"description\":\"a direction; any nonzero length\"}"

/* ======================= velocity addition ================================= */

#define VA_LIGHT                                                                                   \
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"light\"],"                \
    "\"properties\":{\"light\":" FR_DIR3 "},\"description\":\"light (|beta| = 1) moving along "    \
    "this direction, e.g. a photon\"}"

static const char va_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"properties\":{"
    "\"velocity\":{\"description\":\"the object's velocity in the original frame: a velocity, "
    "or {\\\"light\\\": direction} for light\",\"oneOf\":[" API_VELOCITY_SCHEMA "," VA_LIGHT "]},"
    "\"frame_velocity\":" API_VELOCITY_SCHEMA ","
    "\"compose\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":1000,"
    "\"items\":" API_VELOCITY_SCHEMA
    ",\"description\":\"boosts applied in order: the first is the velocity "
    "of frame 1 in the original frame, each next one the velocity of the next frame relative "
    "to the previous one, in the previous frame's axes\"}"
    "}}";

static const char va_example[] =
    "{\"velocity\": {\"beta\": [0, 0.6, 0]}, \"frame_velocity\": {\"beta\": [0.8, 0, 0]}, "
    "\"compose\": [{\"beta\": [0.6, 0, 0]}, {\"beta\": [0, 0.6, 0]}]}";

static const char va_description[] =
    "Relativistic velocity addition (notes §3.10) and composition of boosts (§3.9). "
    "With `velocity` (the object's velocity in the original frame) and `frame_velocity` (the "
    "velocity of the new frame, same axes), answers `velocity_in_frame`: the object's velocity "
    "in the new frame (u_par' = (u_par - v)/(1 - v u_par), u_perp' = u_perp/(gamma(1 - v "
    "u_par))) as gamma, gamma_minus_one, beta (vector), rapidity, one_minus_beta, all computed "
    "from rapidities and 4-velocities without cancellation: gamma' - 1 = 2 sinh^2((eta_o - "
    "eta_f)/2) + sinh(eta_o) sinh(eta_f)(1 - cos theta), so nearly equal velocities, 1e-12 c "
    "and gamma = 1e15 keep full precision and collinear rapidities subtract exactly. The "
    "object may be light, {\"light\": direction}: light stays light; the answer gives its "
    "direction in the new frame (aberration), beta (unit vector), one_minus_beta = 0 and "
    "frequency_ratio nu'/nu = gamma(1 - beta cos theta) (Doppler, notes §3.14). "
    "`object_velocity` and `frame_velocity` echo the inputs in every form (one_minus_beta "
    "states the 1 - beta actually used when beta was typed as a decimal). "
    "With `compose` (a list of boosts applied in order, each velocity measured in the previous "
    "frame's axes), answers `composition`: Lambda = B(v_n)...B(v_1) = R B(total), with "
    "`velocity` the total boost (the last frame's velocity in the first frame; collinear "
    "rapidities add), and `wigner_rotation`: the last frame's axes are the pure boost's axes "
    "turned by `angle` (rad; also `angle_deg`) about the unit `axis` (right-hand rule; null "
    "when the angle is 0; for two boosts the axis is v2 x v1), `quaternion` [w, x, y, z] of "
    "that turn, `matrix` the passive R (rows = the last frame's axes in the pure boost's axes), "
    "and `lorentz_matrix` the 4x4 Lambda (x' = Lambda x, x0 = ct). Closed form for two boosts: "
    "tan(angle/2) = sin(theta) t1 t2/(1 + cos(theta) t1 t2), t_i = tanh(eta_i/2), theta the "
    "angle between v1 and v2 (checked against the polar decomposition of the 4x4 product). "
    "A relative rapidity beyond 350 (gamma ~ 5e151) is a 422.";

static json_t *velocity_in_frame(struct api_call *c, const json_t *vel, const struct mech_boost *f)
{
    struct mech_error e;
    mech_error_clear(&e);
    json_t *res = json_object();
    const json_t *light = json_object_get(vel, "light");
    if (light) {
        struct mech_vec3 k, d = api_vec3_of(light);
        double ratio;
        if (mech_vec3_norm(d) == 0) {
            api_call_invalid(c, "/velocity/light", "the direction of the light must be nonzero");
            json_decref(res);
            return NULL;
        }
        if (mech_velocity_add_light(d, f, &k, &ratio, &e) != MECH_OK) {
            json_decref(res);
            return api_call_fail_core(c, MECH_ENUMERIC, &e, "");
        }
        json_object_set_new_nocheck(res, "light", json_true());
        json_object_set_new_nocheck(res, "direction", api_vec3(c, k));
        json_object_set_new_nocheck(res, "beta", api_vec3(c, k));
        json_object_set_new_nocheck(res, "one_minus_beta", api_real(c, 0.0));
        json_object_set_new_nocheck(res, "frequency_ratio", api_real(c, ratio));
        return res;
    }
    struct mech_boost o, r;
    if (!api_velocity_parse(c, vel, "/velocity", &o)) {
        json_decref(res);
        return NULL;
    }
    if (mech_velocity_add(&o, f, &r, &e) != MECH_OK) {
        api_call_domain(c, "/velocity",
                        "the object's velocity in that frame is too close to the speed of light "
                        "to represent: %s",
                        e.text);
        json_decref(res);
        return NULL;
    }
    api_velocity_describe(c, &r, res);
    json_t *given = json_object();
    api_velocity_describe(c, &o, given);
    json_object_set_new_nocheck(res, "object_velocity", given);
    return res;
}

static json_t *composition(struct api_call *c, const json_t *list)
{
    size_t n = json_array_size(list);
    struct mech_boost *b = malloc(n * sizeof *b);
    if (!b) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    int ok = 1;
    for (size_t i = 0; i < n; i++) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/compose/%zu", i);
        if (!api_velocity_parse(c, json_array_get(list, i), ptr, &b[i])) ok = 0;
    }
    struct mech_boost_composition comp;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = ok ? mech_boost_compose(b, n, &c->budget, &comp, &e) : MECH_EINVAL;
    free(b);
    if (!ok) return NULL;
    if (st == MECH_ENUMERIC && strncmp(e.param, "boosts/", 7) == 0) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/compose/%ld", strtol(e.param + 7, NULL, 10));
        api_call_domain(c, ptr,
                        "the composed velocity up to this boost has a rapidity beyond %g "
                        "(gamma about 5e151), which this server does not represent",
                        MECH_BOOST_RAPIDITY_MAX);
        return NULL;
    }
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *res = json_object();
    json_t *v = json_object();
    api_velocity_describe(c, &comp.total, v);
    json_object_set_new_nocheck(res, "velocity", v);
    json_t *w = json_object();
    json_object_set_new_nocheck(w, "angle", api_real(c, comp.angle));
    json_object_set_new_nocheck(w, "angle_deg",
                                api_real(c, comp.angle * (180.0 / 3.14159265358979323846)));
    json_object_set_new_nocheck(w, "axis", comp.angle > 0 ? api_vec3(c, comp.axis) : json_null());
    json_object_set_new_nocheck(w, "quaternion", api_reals(c, comp.quaternion, 4));
    json_object_set_new_nocheck(w, "matrix", api_mat3(c, comp.rotation));
    json_object_set_new_nocheck(res, "wigner_rotation", w);
    /* Λ = R B(total): B's rows (notes §3.9, boost in an arbitrary direction). */
    const struct mech_boost *t = &comp.total;
    double B[4][4], n3[3] = {t->direction.x, t->direction.y, t->direction.z};
    B[0][0] = t->gamma;
    for (int i = 0; i < 3; i++) {
        B[0][i + 1] = B[i + 1][0] = -t->beta_gamma * n3[i];
        for (int j = 0; j < 3; j++)
            B[i + 1][j + 1] = (i == j) + t->gamma_minus_one * n3[i] * n3[j];
    }
    json_t *L = json_array();
    json_array_append_new(L, api_reals(c, B[0], 4));
    for (int i = 0; i < 3; i++) {
        double row[4];
        for (int nu = 0; nu < 4; nu++)
            row[nu] = comp.rotation.a[i][0] * B[1][nu] + comp.rotation.a[i][1] * B[2][nu] +
                      comp.rotation.a[i][2] * B[3][nu];
        json_array_append_new(L, api_reals(c, row, 4));
    }
    json_object_set_new_nocheck(res, "lorentz_matrix", L);
    return res;
}

static json_t *velocity_addition_op(struct api_call *c, const json_t *body)
{
    const json_t *vel = json_object_get(body, "velocity");
    const json_t *fv = json_object_get(body, "frame_velocity");
    const json_t *list = json_object_get(body, "compose");
    if (vel && !fv)
        api_call_invalid(c, "/frame_velocity",
                         "give frame_velocity (the velocity of the new frame) with velocity");
    if (fv && !vel)
        api_call_invalid(c, "/velocity",
                         "give velocity (the object's velocity in the original frame) with "
                         "frame_velocity");
    if (!vel && !fv && !list)
        api_call_invalid(c, "", "give velocity and frame_velocity, or compose, or both");
    if (c->problem != API_PROBLEM_NONE) return NULL;

    json_t *res = json_object();
    if (vel) {
        struct mech_boost f;
        if (!api_velocity_parse(c, fv, "/frame_velocity", &f)) {
            json_decref(res);
            return NULL;
        }
        json_t *vin = velocity_in_frame(c, vel, &f);
        if (!vin) {
            json_decref(res);
            return NULL;
        }
        json_t *given = json_object_get(vin, "object_velocity");
        if (given) {
            json_object_set(res, "object_velocity", given);
            json_object_del(vin, "object_velocity");
        }
        json_object_set_new_nocheck(res, "velocity_in_frame", vin);
        json_t *fd = json_object();
        api_velocity_describe(c, &f, fd);
        json_object_set_new_nocheck(res, "frame_velocity", fd);
    }
    if (list) {
        json_t *comp = composition(c, list);
        if (!comp) {
            json_decref(res);
            return NULL;
        }
        json_object_set_new_nocheck(res, "composition", comp);
    }
    return res;
}

const struct api_route api_route_relativity_velocity_addition = {
    "POST",
    "/v1/relativity/velocity-addition",
    "Relativistic velocity addition in any directions, composition of boosts, and the Wigner "
    "(Thomas) rotation",
    va_description,
    va_schema,
    va_example,
    velocity_addition_op,
    0,
    1, /* quick */
};

/* ======================= interval ========================================= */

#define IV_VEC4                                                                                    \
    "{\"type\":\"array\",\"minItems\":4,\"maxItems\":4,\"items\":{\"type\":\"number\","            \
    "\"minimum\":-1e150,\"maximum\":1e150},\"description\":\"an event [ct, x, y, z]\"}"

static const char iv_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"events\"],"
    "\"properties\":{"
    "\"events\":{\"type\":\"array\",\"minItems\":2,\"maxItems\":2,\"items\":" IV_VEC4 ","
    "\"description\":\"two events [ct, x, y, z], all four coordinates in one length unit\"},"
    "\"units\":{\"enum\":[\"metres\",\"years\"],\"default\":\"metres\","
    "\"description\":\"metres: coordinates in m, proper_time in s; years: coordinates in "
    "light-years (ct in light-years = years, c = 1), proper_time in years\"}"
    "}}";

static const char iv_example[] = "{\"events\": [[0, 0, 0, 0], [0.6, 1, 0, 0]]}";

static const char iv_description[] =
    "The interval between two events (notes §3.5, §3.6), metric (-,+,+,+): s2 = -(c dt)^2 + "
    "dx^2 + dy^2 + dz^2 with d = second - first. The coordinate differences are formed exactly "
    "and squared with error-free products and compensated sums, so s2 is right to about "
    "2e-16 relative plus 1e-31 (dct^2 + |dx|^2) for the binary inputs, however far from the "
    "origin the events are. What limits it is the inputs: `s2_input_uncertainty` is how much "
    "s2 moves if every coordinate moves by half an ulp (the rounding of a decimal input). "
    "`kind` is lightlike when |s2| <= `lightlike_tolerance` = 4 eps (dct^2 + |dx|^2) + "
    "s2_input_uncertainty (eps = 2.2e-16), else timelike (s2 < 0) or spacelike (s2 > 0). "
    "Timelike: `proper_time` = sqrt(-s2)/c (s; years with units years) and `proper_time_ct`; "
    "spacelike: `proper_length` = sqrt(s2). All three keys are always present: a quantity "
    "that does not exist is null (spacelike: proper_time and proper_time_ct; timelike: "
    "proper_length); lightlike: all three are 0. `time_order` is the order in the given frame and "
    "`time_order_reversible` is true exactly for spacelike separation (some boost makes the "
    "second event come first). `example_frame`: the velocity of a frame in which the events "
    "happen at the same place (timelike, beta = dx/(c dt)) or at the same time (spacelike, "
    "beta = c dt dx/|dx|^2), with 1 - beta = |s2|/(big (big + small)) from s2, so it stays "
    "precise next to the light cone; null when lightlike. `coincident` is true when the two "
    "events are the same event (then kind lightlike).";

static json_t *interval_op(struct api_call *c, const json_t *body)
{
    const json_t *ev = json_object_get(body, "events");
    double e1[4], e2[4];
    for (size_t k = 0; k < 4; k++) {
        e1[k] = json_number_value(json_array_get(json_array_get(ev, 0), k));
        e2[k] = json_number_value(json_array_get(json_array_get(ev, 1), k));
    }
    const int ly = strcmp(api_string(body, "units", "metres"), "years") == 0;
    const double c_light = ly ? 1.0 : 299792458.0;
    struct mech_interval iv;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_interval_compute(e1, e2, &iv, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    static const char *const kinds[] = {"timelike", "spacelike", "lightlike"};
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "delta", api_reals(c, iv.delta, 4));
    json_object_set_new_nocheck(res, "s2", api_real(c, iv.s2));
    json_object_set_new_nocheck(res, "kind", json_string(kinds[iv.kind]));
    json_object_set_new_nocheck(res, "lightlike_tolerance", api_real(c, iv.tolerance));
    json_object_set_new_nocheck(res, "s2_input_uncertainty", api_real(c, iv.input_error));
    json_object_set_new_nocheck(res, "coincident", json_boolean(iv.coincident));
    /* Every key always present: null where the quantity does not exist (a
     * spacelike pair has no proper time, a timelike one no proper length);
     * light-like pairs have both, and both are 0. */
    const int has_time = iv.kind != MECH_INTERVAL_SPACELIKE;
    const int has_length = iv.kind != MECH_INTERVAL_TIMELIKE;
    json_object_set_new_nocheck(res, "proper_time",
                                has_time ? api_real(c, iv.proper / c_light) : json_null());
    json_object_set_new_nocheck(res, "proper_time_ct",
                                has_time ? api_real(c, iv.proper) : json_null());
    json_object_set_new_nocheck(res, "proper_length",
                                has_length ? api_real(c, iv.proper) : json_null());
    json_object_set_new_nocheck(res, "time_order",
                                json_string(iv.delta[0] > 0   ? "first_before_second"
                                            : iv.delta[0] < 0 ? "second_before_first"
                                                              : "simultaneous"));
    json_object_set_new_nocheck(res, "time_order_reversible",
                                json_boolean(iv.time_order_reversible));
    if (iv.has_frame) {
        json_t *f = json_object();
        json_object_set_new(
            f, "makes_events",
            json_string(iv.kind == MECH_INTERVAL_TIMELIKE ? "co-located" : "simultaneous"));
        json_t *v = json_object();
        api_velocity_describe(c, &iv.frame, v);
        json_object_set_new_nocheck(f, "velocity", v);
        json_object_set_new_nocheck(res, "example_frame", f);
    } else {
        json_object_set_new_nocheck(res, "example_frame", json_null());
    }
    return res;
}

const struct api_route api_route_relativity_interval = {
    "POST",
    "/v1/relativity/interval",
    "The interval between two events: s2, timelike/spacelike/lightlike, proper time or length, "
    "whether the time order can be reversed",
    iv_description,
    iv_schema,
    iv_example,
    interval_op,
    0,
    1, /* quick */
};

/* ======================= worldline ========================================= */

#define WL_POS "{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30}"
#define WL_ACC "{\"type\":\"number\",\"minimum\":-1e30,\"maximum\":1e30}"
#define WL_LEG_COAST(key, what)                                                                    \
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"velocity\",\"" key        \
    "\"],\"description\":\"constant velocity for a " what "\",\"properties\":{"                    \
    "\"velocity\":" API_VELOCITY_SCHEMA ",\"" key "\":" WL_POS "}}"
#define WL_LEG_ACCEL(key, what)                                                                    \
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"" key                     \
    "\",\"proper_time\"],\"description\":\"constant proper acceleration (" what ") for a "         \
    "proper time\",\"properties\":{\"" key "\":" WL_ACC ",\"proper_time\":" WL_POS ","             \
    "\"direction\":" FR_DIR3 "}}"

static const char wl_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"legs\"],"
    "\"properties\":{"
    "\"legs\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":1000,\"items\":{"
    "\"oneOf\":[" WL_LEG_COAST("coordinate_time", "coordinate (stay-at-home) time") "," WL_LEG_COAST("distance", "coordinate distance") "," WL_LEG_COAST(
        "proper_time",
        "proper (traveller) time") "," WL_LEG_ACCEL("proper_acceleration",
                                                    "m/s^2, or ly/yr^2 in years "
                                                    "units") "," WL_LEG_ACCEL("proper"
                                                                              "_accel"
                                                                              "eratio"
                                                                              "n_g",
                                                                              "in "
                                                                              "units "
                                                                              "of g "
                                                                              "= "
                                                                              "9."
                                                                              "80665 "
                                                                              "m/s^2") "]}},"
                                                                                       "\"units\":{"
                                                                                       "\"enum\":["
                                                                                       "\"seconds\""
                                                                                       ",\"years\"]"
                                                                                       ",\"default"
                                                                                       "\":"
                                                                                       "\"seconds\""
                                                                                       ","
                                                                                       "\"descripti"
                                                                                       "on\":"
                                                                                       "\"seconds: "
                                                                                       "times in "
                                                                                       "s, lengths "
                                                                                       "in m, c = "
                                                                                       "299792458 "
                                                                                       "m/s; "
                                                                                       "years: "
                                                                                       "times in "
                                                                                       "Julian "
                                                                                       "years, "
                                                                                       "lengths in "
                                                                                       "light-"
                                                                                       "years, c = "
                                                                                       "1\"},"
                                                                                       "\"tick_"
                                                                                       "interval\":"
                                                                                       "{\"type\":"
                                                                                       "\"number\","
                                                                                       "\"exclusive"
                                                                                       "Minimum\":"
                                                                                       "0,"
                                                                                       "\"maximum\""
                                                                                       ":1e30,"
                                                                                       "\"default\""
                                                                                       ":1,"
                                                                                       "\"descripti"
                                                                                       "on\":"
                                                                                       "\"each "
                                                                                       "twin's "
                                                                                       "clock "
                                                                                       "ticks once "
                                                                                       "per this "
                                                                                       "proper "
                                                                                       "time "
                                                                                       "(default 1 "
                                                                                       "s or 1 "
                                                                                       "year)\"},"
    "\"telescope_home_times\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":20,\"items\":"
    "{\"type\":\"number\",\"minimum\":0,\"maximum\":1e30},\"description\":\"home times "
    "at which the stay-at-home twin reads the traveller's clock through a telescope (the "
    "light arriving then); up to the time the trip's end is seen\"}}}";

static const char wl_example[] =
    "{\"units\": \"years\", \"legs\": [{\"velocity\": {\"beta\": [0.8, 0, 0]}, \"distance\": 8}, "
    "{\"velocity\": {\"beta\": [-0.8, 0, 0]}, \"distance\": 8}]}";

static const char wl_description[] =
    "With telescope_home_times: home_telescope, for each home time t the traveller's clock "
    "reading the stay-at-home twin sees through a telescope (notes §3.15), from the event "
    "where the light left (t_e + |x_e|/c = t, found by bisection along the trip), with that "
    "emission event, the leg and the light travel time. "
    "A trip as legs, starting from the stay-at-home twin at the origin, at rest, at t = 0 (the "
    "twin paradox, notes §3.15). Legs: constant `velocity` (the shared velocity forms, in the "
    "home frame; the velocity changes instantly, as in the notes) for a `coordinate_time`, a "
    "`distance` or a `proper_time`; or constant proper acceleration (`proper_acceleration` in "
    "m/s^2 or ly/yr^2, or `proper_acceleration_g` in g = 9.80665 m/s^2) for a `proper_time`, "
    "along `direction` (default: the current velocity; a negative acceleration points the "
    "other way, to brake), which must be along or against the current velocity (hyperbolic "
    "motion: rapidity grows by a tau/c, t = (c/a) sinh(a tau/c), x = (c^2/a)(cosh(a tau/c) - "
    "1) from rest, evaluated as K cosh m, K sinh m with K = c tau sinh(h)/h, h = a tau/2c, "
    "precise for small a tau/c). `units`: seconds (s, m, c = 299792458 m/s) or years (Julian "
    "years of 365.25 d, light-years, c = 1; g = 1.0323 ly/yr^2). Per leg and in total: "
    "`proper_time` with `proper_time_ct` (c times it: m, or ly with years - a muon's c tau "
    "beside its tau), `coordinate_time`, `age_difference` (coordinate - proper, without "
    "cancellation: right at 1 m/s), `distance` (path length, including a turnaround inside an "
    "accelerated leg), `displacement`, `start`/`end` events [t, x, y, z], `final_velocity`; "
    "the total's `stay_at_home_time` is the home twin's age at the traveller's last event and "
    "`returned` says whether the traveller is back home (|end| <= 1e-12 of the path). "
    "Telescopes (notes §3.14, §3.15): home light seen by the traveller at (t, x) left home at "
    "t - |x|/c; the traveller's event is seen at home at t + |x|/c. Per leg, "
    "`traveller_sees_home` gives the home clock readings seen at the leg's start and end, the "
    "`ticks` seen (their difference / tick_interval) and the `rate` (home time seen per "
    "traveller time: sqrt((1-beta)/(1+beta)) receding radially); `home_sees_traveller` gives "
    "the home times when the leg's start and end are seen, the leg's ticks, and the rate "
    "(traveller time seen per home time). These differences are computed in light-cone form "
    "(c dt (1 - beta), never t - |x|/c of large numbers), so 1 - beta = 1e-15 keeps its digits, "
    "and each leg's from the leg itself (never the difference of the running readings), so a "
    "day's leg after years keeps its digits too.";

static const double G_STANDARD = 9.80665;     /* m/s², exact by definition */
static const double JULIAN_YEAR = 31557600.0; /* s */
static const double C_SI = 299792458.0;       /* m/s */

static json_t *telescope(struct api_call *c, const char *from_key, double from, const char *to_key,
                         double to, double ticks, double rate)
{
    json_t *o = json_object();
    json_object_set_new(o, from_key, api_real(c, from));
    json_object_set_new(o, to_key, api_real(c, to));
    json_object_set_new_nocheck(o, "ticks", api_real(c, ticks));
    json_object_set_new_nocheck(o, "rate", api_real(c, rate));
    return o;
}

static json_t *worldline_op(struct api_call *c, const json_t *body)
{
    const json_t *jl = json_object_get(body, "legs");
    const int years = strcmp(api_string(body, "units", "seconds"), "years") == 0;
    const double cl = years ? 1.0 : C_SI;
    const double g = years ? G_STANDARD * JULIAN_YEAR / C_SI : G_STANDARD;
    const double tick = api_number(body, "tick_interval", 1.0);
    size_t n = json_array_size(jl);
    struct mech_leg *legs = calloc(n, sizeof *legs);
    struct mech_leg_result *out = calloc(n, sizeof *out);
    if (!legs || !out) {
        free(legs);
        free(out);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    for (size_t k = 0; k < n; k++) {
        const json_t *L = json_array_get(jl, k);
        struct mech_leg *l = &legs[k];
        char ptr[64];
        const json_t *v = json_object_get(L, "velocity");
        if (v) {
            snprintf(ptr, sizeof ptr, "/legs/%zu/velocity", k);
            api_velocity_parse(c, v, ptr, &l->velocity);
            if (json_object_get(L, "coordinate_time")) {
                l->kind = MECH_LEG_COAST_TIME;
                l->amount = api_number(L, "coordinate_time", 0);
            } else if (json_object_get(L, "distance")) {
                l->kind = MECH_LEG_COAST_DISTANCE;
                l->amount = api_number(L, "distance", 0);
            } else {
                l->kind = MECH_LEG_COAST_PROPER_TIME;
                l->amount = api_number(L, "proper_time", 0);
            }
        } else {
            l->kind = MECH_LEG_ACCELERATE;
            l->amount = api_number(L, "proper_time", 0);
            const int in_g = json_object_get(L, "proper_acceleration_g") != NULL;
            const char *key = in_g ? "proper_acceleration_g" : "proper_acceleration";
            double a = api_number(L, key, 0);
            if (a == 0) {
                snprintf(ptr, sizeof ptr, "/legs/%zu/%s", k, key);
                api_call_invalid(c, ptr,
                                 "the proper acceleration must be nonzero; to coast, give a "
                                 "leg with a velocity instead");
            }
            l->acceleration = in_g ? a * g : a;
            l->direction = api_vec3_member(L, "direction", mech_vec3_make(0, 0, 0));
            if (json_object_get(L, "direction") && mech_vec3_norm(l->direction) == 0) {
                snprintf(ptr, sizeof ptr, "/legs/%zu/direction", k);
                api_call_invalid(c, ptr, "the direction must be a nonzero vector");
            }
        }
    }
    if (c->problem != API_PROBLEM_NONE) {
        free(legs);
        free(out);
        return NULL;
    }
    struct mech_worldline_total tot;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_worldline_run(legs, n, cl, &c->budget, out, &tot, &e);
    json_t *views = NULL;
    const json_t *tj = json_object_get(body, "telescope_home_times");
    if (st == MECH_OK && tj) {
        struct mech_leg *sl = calloc(n, sizeof *sl);
        struct mech_leg_result *sr = calloc(n, sizeof *sr);
        views = json_array();
        if (!sl || !sr || !views) st = mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        for (size_t i = 0; st == MECH_OK && i < json_array_size(tj); i++) {
            struct mech_telescope_view v;
            st = mech_telescope_home_view(legs, out, n, cl, json_number_value(json_array_get(tj, i)),
                                          sl, sr, &c->budget, &v, &e);
            if (st != MECH_OK) {
                if (!strcmp(e.param, "telescope_home_times"))
                    snprintf(e.param, sizeof e.param, "telescope_home_times/%zu", i);
                break;
            }
            json_t *o = json_object();
            json_object_set_new_nocheck(o, "home_time", api_real(c, v.home_time));
            json_object_set_new_nocheck(o, "traveller_clock", api_real(c, v.traveller_clock));
            json_object_set_new_nocheck(o, "leg", v.leg < 0 ? json_null() : json_integer(v.leg));
            json_object_set_new_nocheck(o, "emission_event", api_reals(c, v.emission, 4));
            json_object_set_new_nocheck(o, "light_travel_time", api_real(c, v.light_time));
            json_array_append_new(views, o);
        }
        free(sl);
        free(sr);
    }
    free(legs);
    if (st != MECH_OK) {
        free(out);
        json_decref(views);
        return api_call_fail_core(c, st, &e, "");
    }

    json_t *res = json_object();
    json_t *u = json_object();
    json_object_set_new_nocheck(u, "time", json_string(years ? "yr" : "s"));
    json_object_set_new_nocheck(u, "length", json_string(years ? "ly" : "m"));
    json_object_set_new_nocheck(u, "c", api_real(c, cl));
    json_object_set_new_nocheck(u, "g", api_real(c, g));
    json_object_set_new_nocheck(u, "tick_interval", api_real(c, tick));
    json_object_set_new_nocheck(res, "units", u);
    json_t *arr = json_array();
    for (size_t k = 0; k < n; k++) {
        const struct mech_leg_result *r = &out[k];
        json_t *o = json_object();
        json_object_set_new_nocheck(o, "kind",
                                    json_string(json_object_get(json_array_get(jl, k), "velocity")
                                                    ? "coast"
                                                    : "accelerate"));
        json_object_set_new_nocheck(o, "proper_time", api_real(c, r->proper_time));
        json_object_set_new_nocheck(o, "proper_time_ct", api_real(c, r->proper_time * cl));
        json_object_set_new_nocheck(o, "coordinate_time", api_real(c, r->coordinate_time));
        json_object_set_new_nocheck(o, "age_difference", api_real(c, r->age_difference));
        json_object_set_new_nocheck(o, "distance", api_real(c, r->distance));
        json_object_set_new_nocheck(o, "displacement", api_vec3(c, r->displacement));
        json_object_set_new_nocheck(o, "start", api_reals(c, r->start, 4));
        json_object_set_new_nocheck(o, "end", api_reals(c, r->end, 4));
        json_t *fv = json_object();
        api_velocity_describe(c, &r->final_velocity, fv);
        json_object_set_new_nocheck(o, "final_velocity", fv);
        double seen = r->home_clock_seen, recv = r->home_receives; /* the leg's own intervals */
        json_object_set_new_nocheck(o, "traveller_sees_home",
                                    telescope(c, "home_clock_from", r->home_clock_seen_start,
                                              "home_clock_to", r->home_clock_seen_end, seen / tick,
                                              seen / r->proper_time));
        json_object_set_new_nocheck(o, "home_sees_traveller",
                                    telescope(c, "home_time_from", r->home_receives_start,
                                              "home_time_to", r->home_receives_end,
                                              r->proper_time / tick, r->proper_time / recv));
        json_array_append_new(arr, o);
    }
    free(out);
    json_object_set_new_nocheck(res, "legs", arr);
    if (views) json_object_set_new_nocheck(res, "home_telescope", views);
    json_t *t = json_object();
    json_object_set_new_nocheck(t, "proper_time", api_real(c, tot.proper_time));
    json_object_set_new_nocheck(t, "proper_time_ct", api_real(c, tot.proper_time * cl));
    json_object_set_new_nocheck(t, "coordinate_time", api_real(c, tot.coordinate_time));
    json_object_set_new_nocheck(t, "stay_at_home_time", api_real(c, tot.coordinate_time));
    json_object_set_new_nocheck(t, "age_difference", api_real(c, tot.age_difference));
    json_object_set_new_nocheck(t, "distance", api_real(c, tot.distance));
    json_object_set_new_nocheck(t, "end", api_reals(c, tot.end, 4));
    double far = mech_vec3_norm(mech_vec3_make(tot.end[1], tot.end[2], tot.end[3]));
    json_object_set_new_nocheck(t, "returned", json_boolean(far <= 1e-12 * tot.distance));
    json_t *fv = json_object();
    api_velocity_describe(c, &tot.final_velocity, fv);
    json_object_set_new_nocheck(t, "final_velocity", fv);
    json_t *ts = json_object();
    json_object_set_new_nocheck(ts, "ticks", api_real(c, tot.home_clock_seen_end / tick));
    json_object_set_new_nocheck(ts, "home_clock_to", api_real(c, tot.home_clock_seen_end));
    json_object_set_new_nocheck(t, "traveller_sees_home", ts);
    json_t *hs = json_object();
    json_object_set_new_nocheck(hs, "ticks", api_real(c, tot.proper_time / tick));
    json_object_set_new_nocheck(hs, "home_time_to", api_real(c, tot.home_receives_end));
    json_object_set_new_nocheck(t, "home_sees_traveller", hs);
    json_object_set_new_nocheck(res, "total", t);
    return res;
}

const struct api_route api_route_relativity_worldline = {
    "POST",
    "/v1/relativity/worldline",
    "A trip as legs of constant velocity or constant proper acceleration: proper times, the "
    "stay-at-home time, and the Doppler ticks each twin sees",
    wl_description,
    wl_schema,
    wl_example,
    worldline_op,
    0,
    0,
};
