/* rotating_table_scene.c — one POST /v1/scenes/rotating-table computation
 * (mech/answers/frames/rotating_table_scene.h): the experiment's fields checked, the
 * answer and its sample buffers allocated, and scenes.c's table run. Moved
 * from api/ops/scenes/scene_request.c (a handler only parses, calls core once and encodes)
 * check for check, so the API's answers stay byte-identical. */
#include "mech/answers/frames/rotating_table_scene.h"

#include <math.h>
#include <stdlib.h>

#include "mech/frames/trajectory_problem.h"

const char *mech_table_experiment_name(enum mech_table_experiment x)
{
    switch (x) {
    case MECH_TABLE_THROUGH_CENTER:
        return "through_center";
    case MECH_TABLE_AT_REST:
        return "at_rest";
    case MECH_TABLE_CUSTOM:
        return "custom";
    }
    return "custom";
}

/* custom needs position, velocity and t_end; the others take none of them. */
static enum mech_status check_fields(const struct mech_rotating_table_request *q,
                                     struct mech_error *err)
{
    static const char *const field[] = {"position", "velocity", "t_end"};
    const int has[] = {q->has_position, q->has_velocity, q->has_t_end};
    const int custom = q->scene.experiment == MECH_TABLE_CUSTOM;
    for (int i = 0; i < 3; i++) {
        if (custom && !has[i])
            return mech_error_set(err, MECH_EINVAL, NULL, "experiment \"custom\" needs %s",
                                  field[i]);
        if (!custom && has[i])
            return mech_error_set(err, MECH_EINVAL, field[i], "only for experiment \"custom\"");
    }
    if (q->scene.omega == 0.0)
        return mech_error_set(err, MECH_EDOMAIN, "omega", "the table must rotate: omega != 0");
    return MECH_OK;
}

/* The answer with room for n samples in one allocation (n outside the run's
 * range: no buffers, and the run refuses n). NULL when out of memory. */
static struct mech_rotating_table_scene *scene_alloc(size_t n)
{
    const int fits = n >= MECH_TRAJECTORY_MIN_SAMPLES && n <= MECH_TRAJECTORY_MAX_SAMPLES;
    const size_t bytes = sizeof(struct mech_rotating_table_scene) +
                         (fits ? n * (sizeof(double) + 3 * sizeof(struct mech_vec3)) : 0);
    struct mech_rotating_table_scene *s = calloc(1, bytes);
    if (!s || !fits) return s;
    /* vec3 arrays first (their alignment), then the times */
    struct mech_vec3 *v = (struct mech_vec3 *)(s + 1);
    s->result.inertial = v;
    s->result.rotating = v + n;
    s->result.rotating_exact = v + 2 * n;
    s->result.t = (double *)(v + 3 * n);
    return s;
}

enum mech_status mech_rotating_table_scene(const struct mech_rotating_table_request *q,
                                           const struct mech_budget *budget,
                                           struct mech_rotating_table_scene **out,
                                           struct mech_error *err)
{
    if (out) *out = NULL;
    if (!q || !budget || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    enum mech_status st = check_fields(q, err);
    if (st != MECH_OK) return st;
    struct mech_rotating_table_scene *s = scene_alloc(q->scene.samples);
    if (!s) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    s->experiment = mech_table_experiment_name(q->scene.experiment);
    s->scene = q->scene;
    s->target = q->target;
    st = mech_scene_table_run(&s->scene, q->target, budget, &s->result, err);
    if (st != MECH_OK) {
        free(s);
        return st;
    }
    *out = s;
    return MECH_OK;
}

void mech_rotating_table_scene_free(struct mech_rotating_table_scene *s)
{
    free(s);
}
