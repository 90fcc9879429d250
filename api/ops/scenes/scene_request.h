/* scene_request.h — the request readers and the ballistic run the chapter-1
 * scenes share (POST /v1/scenes/falling-object, /vertical-shot, /cannonball,
 * /rotating-table; api/ops/scenes/scene_request.c). */
#ifndef API_SCENE_REQUEST_H
#define API_SCENE_REQUEST_H

#include <jansson.h>

#include "run/endpoint.h"
#include "mech/frames/scenes.h"
#include "mech/frames/trajectory.h"
#include "request/trajectory_request.h"

/* The relative accuracy asked for: "target_error", else the named
 * "accuracy" preset's. 0 after recording an error (both given). */
double api_scene_target(struct api_call *c, const json_t *body);

/* The "accuracy" preset's name, or NULL when "target_error" was given. Borrowed
 * from body. */
const char *api_scene_accuracy_name(const json_t *body);

/* A request-like view *rq of a core scene run (problem p, model m, choice ch,
 * accuracy name or NULL), for the trajectory's model and diagnostics encoders
 * (api/request/trajectory_request.h). */
void api_scene_rq(struct api_traj_request *rq, const struct mech_trajectory_problem *p,
                  const struct mech_trajectory_model *m, const struct mech_trajectory_choice *ch,
                  const char *accuracy);

/* The Earth's parameters of a ballistic scene into *s (zeroed first): latitude_deg,
 * g, the model (auto, coriolis or coriolis_centrifugal: the schema's enum) and
 * the rotation rate (omega_magnitude or sidereal_day, not both). 1 on
 * success, 0 after recording an error. */
int api_scene_earth_params(struct api_call *c, const json_t *body, struct mech_scene_ballistic *s);

/* Run the ballistic scene s (r0, v0 set by the caller) at relative accuracy
 * target and answer it: the numerical result beside the first-order formula
 * (parameters and formula: new references, always consumed); each landing
 * point as t, east, north, plus "south" when south is set, plus "range" and
 * "right" along the firing direction fwd when fwd is not NULL. A dry run answers the
 * selection only. Returns a new reference, or NULL after recording why. */
json_t *api_scene_run_ballistic(struct api_call *c, const json_t *body, const char *scene,
                                const struct mech_scene_ballistic *s, json_t *parameters,
                                json_t *formula, int south, const struct mech_vec3 *fwd,
                                double target);

#endif
