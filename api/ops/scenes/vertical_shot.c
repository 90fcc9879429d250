/* vertical_shot.c — POST /v1/scenes/vertical-shot (notes §1.5 problem 3): a
 * body shot straight up on the rotating Earth and its westward deflection.
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

json_t *api_op_scenes_vertical_shot(struct api_call *c, const json_t *body)
{
    double target = api_scene_target(c, body);
    if (!(target > 0.0)) return NULL;
    struct mech_scene_ballistic s;
    if (!api_scene_earth_params(c, body, &s)) return NULL;
    const int has_v = json_object_get(body, "speed") != NULL;
    const int has_h = json_object_get(body, "height") != NULL;
    if (has_v == has_h) {
        api_call_invalid(c, "", "give exactly one of speed and height");
        return NULL;
    }
    const double v0 = has_v ? api_number(body, "speed", 0)
                            : mech_scene_vertical_shot_speed(api_number(body, "height", 0), s.g);
    struct mech_scene_vertical_shot_first_order fo;
    mech_scene_vertical_shot_first_order(v0, s.g, s.omega, s.latitude_deg, &fo);
    s.v0 = mech_vec3_make(0, 0, v0);
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "speed", api_real(c, v0));
    json_object_set_new_nocheck(par, "height", api_real(c, fo.height));
    json_object_set_new_nocheck(par, "latitude_deg", api_real(c, s.latitude_deg));
    json_object_set_new_nocheck(par, "g", api_real(c, s.g));
    json_object_set_new_nocheck(par, "omega_magnitude", api_real(c, s.omega));
    json_object_set_new_nocheck(par, "target_error", api_real(c, target));
    json_object_set_new_nocheck(par, "drop_deflection_east", api_real(c, fo.drop_east));
    json_t *f = json_string("x_west = (4/3) W cos(lat) sqrt(8 h^3 / g), t = 2 v0 / g (notes §1.5 "
                            "problem 3): 4 x the drop's eastward deflection for the same height");
    return api_scene_run_ballistic(c, body, "vertical-shot", &s, par, f, 0, NULL, target);
}
