/* falling_object.c — POST /v1/scenes/falling-object (notes §1.4): a body
 * dropped from a height on the rotating Earth and its eastward deflection.
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

json_t *api_op_scenes_falling_object(struct api_call *c, const json_t *body)
{
    double target = api_scene_target(c, body);
    if (!(target > 0.0)) return NULL;
    struct mech_scene_ballistic s;
    if (!api_scene_earth_params(c, body, &s)) return NULL;
    const double h = api_number(body, "height", 0);
    s.r0 = mech_vec3_make(0, 0, h);
    json_t *par = json_object();
    json_object_set_new_nocheck(par, "height", api_real(c, h));
    json_object_set_new_nocheck(par, "latitude_deg", api_real(c, s.latitude_deg));
    json_object_set_new_nocheck(par, "g", api_real(c, s.g));
    json_object_set_new_nocheck(par, "omega_magnitude", api_real(c, s.omega));
    json_object_set_new_nocheck(par, "target_error", api_real(c, target));
    json_t *f = json_string("x_east = (W cos(lat) / 3) sqrt(8 h^3 / g), t = sqrt(2 h / g), no "
                            "north-south deflection (notes §1.4)");
    return api_scene_run_ballistic(c, body, "falling-object", &s, par, f, 1, NULL, target);
}
