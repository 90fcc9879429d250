/* trajectory_relativity.h — the relativistic corrections of POST
 * /v1/trajectory: the request's "relativity" ("auto", the default, or the
 * list of corrections to model) and particle.proper_velocity, the judgement
 * of a finished run (core's mech_trajectory_relativity_select) that may ask
 * for the scene to run again with a correction added, and model.relativity
 * in the answer. Not thread-shared: each call owns its request. */
#ifndef API_TRAJECTORY_RELATIVITY_H
#define API_TRAJECTORY_RELATIVITY_H

#include "request/trajectory_request.h"

/* Read "relativity" and particle.proper_velocity of a schema-validated body
 * into rq (rq->p.relativity, rq->rel_*; a given list is modelled from the
 * start, a proper velocity forces "relativistic"). `prefix` is prepended to
 * error pointers. Returns 0 after recording an error in c. */
int api_traj_relativity_parse(struct api_call *c, const json_t *body, const char *prefix,
                              struct api_traj_request *rq);

/* Judge the finished answer r of rq (rq->rel_model gets the decision). When
 * the decision differs from what r was run with, rq->p is set up for the
 * run again (the corrections, the chooser's method and closed-form flag for
 * the new scene, c's step budget less r's steps) and 1 is returned; else 0.
 * *st is MECH_OK or the failure (e filled: a correction needed that cannot
 * be modelled, or the new scene's chooser). */
int api_traj_relativity_judge(struct api_call *c, struct api_traj_request *rq,
                              const struct mech_trajectory_result *r, enum mech_status *st,
                              struct mech_error *e);

/* model.relativity: mode, every correction with included, its largest
 * acceleration along the answer's run, the estimated effect and the reason,
 * the rule and scales, and the first run when the scene ran again. New
 * reference, or NULL on allocation failure. r may be NULL (dry run). */
json_t *api_traj_relativity_json(struct api_call *c, const struct api_traj_request *rq,
                                 const struct mech_trajectory_result *r);

#endif
