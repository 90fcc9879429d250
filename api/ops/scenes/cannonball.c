/* cannonball.c — POST /v1/scenes/cannonball: a shot fired at an elevation and
 * azimuth on the rotating Earth and its deflection from the aimed line.
 * The run (fictitious terms chosen by "auto" at the requested accuracy) and
 * the answer beside the notes' first-order formula are
 * api/ops/scenes/scene_request.c's; the closed forms are
 * core/frames/scenes_first_order.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/frames/scenes.h"
#include "mech/frames/scenes_first_order.h"
#include "ops/scenes/scene_request.h"

json_t *api_op_scenes_cannonball(struct api_call *c, const json_t *body)
{
    double target = api_scene_target(c, body);
    if (!(target > 0.0)) return NULL;
    struct mech_scene_ballistic s;
    if (!api_scene_earth_params(c, body, &s)) return NULL;
    const double v0 = api_number(body, "speed", 0);
    const double g = s.g, W = s.omega;
    struct mech_scene_cannonball_first_order fo;
    mech_scene_cannonball_first_order(v0, api_number(body, "elevation_deg", 0),
                                      api_number_of(body, "azimuth_deg"), g, W, s.latitude_deg,
                                      &fo);
    const struct mech_vec3 fwd = fo.forward;
    s.v0 = fo.velocity;
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "speed", api_real(c, v0));
    json_object_set_new_nocheck(par, "elevation_deg", api_real(c, fo.elevation * 180.0 / MECH_PI));
    json_object_set_new_nocheck(par, "azimuth_deg", api_real(c, fo.azimuth * 180.0 / MECH_PI));
    json_object_set_new_nocheck(par, "latitude_deg", api_real(c, s.latitude_deg));
    json_object_set_new_nocheck(par, "g", api_real(c, g));
    json_object_set_new_nocheck(par, "omega_magnitude", api_real(c, W));
    json_object_set_new_nocheck(par, "target_error", api_real(c, target));
    json_object_set_new_nocheck(par, "velocity", api_vec3(c, s.v0));
    json_t *f = json_string("r_1(T0) - v_h z_1(T0) / z_0'(T0) with r_1 = -w x (v0 t^2 + g t^3/3), "
                            "T0 = 2 v0 sin(alpha) / g (notes §1.4, homework §1.5 problems 4-5)");
    json_t *res = api_scene_run_ballistic(c, body, "cannonball", &s, par, f, 0, &fwd, target);
    if (!res) return NULL;
    /* the no-rotation landing and the notes' due-east formulas (core) */
    json_t *z = json_object();
    json_object_set_new_nocheck(z, "t", api_real(c, fo.t0));
    json_object_set_new_nocheck(z, "range", api_real(c, fo.range));
    json_object_set_new_nocheck(res, "zeroth_order", z);
    json_t *ne = json_object();
    json_object_set_new_nocheck(ne, "south_deflection", api_real(c, fo.south_due_east));
    json_object_set_new_nocheck(ne, "range_increase", api_real(c, fo.range_increase_due_east));
    json_object_set_new_nocheck(
        ne, "formula",
        json_string("notes §1.5 problems 4-5 (firing due east): d = 4 v0^3 W "
                    "sin(lat) sin^2(alpha) cos(alpha) / g^2 south; dR = W cos(lat) "
                    "sqrt(2 R^3 / g) (cot^1/2 alpha - tan^3/2 alpha / 3)"));
    json_object_set_new_nocheck(res, "notes_due_east", ne);
    return res;
}
