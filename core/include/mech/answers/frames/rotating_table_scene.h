/* mech/answers/frames/rotating_table_scene.h — one POST /v1/scenes/rotating-table
 * computation (notes §1.1, the puck experiments): the request's experiment
 * checked (custom needs position, velocity and t_end; the others refuse
 * them; the table must turn), the sample buffers allocated, and the run of
 * mech_scene_table_run (mech/frames/scenes.h): the inertial straight line, its image
 * in the table's axes and the rotating-frame integration with "auto" terms.
 * The API's handler parses, calls mech_rotating_table_scene() once, encodes
 * and frees.
 *
 * Units SI. Reentrant; the answer and its buffers are one allocation owned
 * by the caller (mech_rotating_table_scene_free). */
#ifndef MECH_ROTATING_TABLE_SCENE_H
#define MECH_ROTATING_TABLE_SCENE_H

#include "mech/base/budget.h"
#include "mech/frames/scenes.h"
#include "mech/base/status.h"

struct mech_rotating_table_request {
    /* experiment, omega, radius, mass, samples, dry_run in the ranges of
     * struct mech_scene_table (checked by mech_scene_table_run); r0, v0 and
     * t_end are read only for MECH_TABLE_CUSTOM */
    struct mech_scene_table scene;
    int has_position, has_velocity, has_t_end; /* what the request gave (r0, v0, t_end) */
    double target; /* relative accuracy asked for, [1e-15, 0.1] (the chooser's range) */
};

struct mech_rotating_table_scene {
    const char *experiment;        /* "through_center", "at_rest" or "custom" (static) */
    struct mech_scene_table scene; /* as run */
    double target;
    /* the run: t, inertial, rotating and rotating_exact point into this
     * allocation, result.n_samples entries each (none after a dry run, where
     * only problem and choice are set) */
    struct mech_scene_table_result result;
};

/* The request's name of an experiment (static; "custom" for an unknown one). */
const char *mech_table_experiment_name(enum mech_table_experiment x);

/* Run request q under budget; on MECH_OK *out is a new answer the caller
 * frees with mech_rotating_table_scene_free, on any error *out is NULL and
 * nothing is allocated. Statuses, err->param naming the request's field:
 *   MECH_EINVAL for a NULL pointer; no param when a custom experiment lacks
 *     position, velocity or t_end ("experiment \"custom\" needs ..."); the
 *     first of "position", "velocity", "t_end" given to another experiment;
 *   MECH_EDOMAIN "omega" for omega == 0 (the table must rotate);
 *   MECH_ENOMEM when the buffers cannot be allocated;
 *   those of mech_scene_table_run ("omega", "mass", "samples", "radius",
 *     "position", "t_end"; the run's budget, deadline, numerical failures).
 * err may be NULL. */
enum mech_status mech_rotating_table_scene(const struct mech_rotating_table_request *q,
                                           const struct mech_budget *budget,
                                           struct mech_rotating_table_scene **out,
                                           struct mech_error *err);

/* Free an answer of mech_rotating_table_scene (NULL is a no-op). */
void mech_rotating_table_scene_free(struct mech_rotating_table_scene *s);

#endif
