/* mech/frames/scenes.h — the notes' classic scenes of chapter 1, computed two ways:
 * numerically (mech_trajectory_integrate with the fictitious terms chosen by
 * mech_trajectory_model_select, i.e. "auto") and by the notes' first-order
 * formula, with the size of the second-order terms the formula neglects.
 *
 *   ballistic scenes in the local Earth frame (notes §1.3, axes x east,
 *   y north, z up, w = W (0, cos lat, sin lat)): the falling object
 *   ("Deflection of a Falling Object"), the vertical shot (problem 3 of
 *   §1.5), the cannonball ("Deflection of Cannon Balls", problems 4 and 5);
 *   the rotating table (§1.1, the puck experiments) seen from both frames.
 *
 * Perturbation series used for the second-order terms (derived from
 * r'' = g - 2 w x r' - w x (w x r), expanding r = r_0 + r_1 + r_2 in w,
 * mech_coriolis_first_order in mech/frames/reference.h):
 *   r_0 = r0 + v0 t + g t^2/2,
 *   r_1 = -w x (v0 t^2 + g t^3/3),
 *   r_2 = 2 w x (w x (v0 t^3/3 + g t^4/12))                  (Coriolis twice)
 *         - w x (w x (r0 t^2/2 + v0 t^3/6 + g t^4/24))         (centrifugal of
 *                                                                the displacement).
 * The first-order landing point linearises the landing time too:
 * T0 = zeroth-order flight time, dt1 = -z_1(T0) / z_0'(T0), landing =
 * r_0(T0) + r_1(T0) + v0_h dt1 (horizontal). The second-order terms are the
 * landing point of r_0 + r_1 + r_2 (its landing time solved exactly) minus
 * the first-order one: what the formula neglects, to second order in w.
 *
 * Units SI. Reentrant, no globals; sample buffers are caller-owned.
 */
#ifndef MECH_SCENES_H
#define MECH_SCENES_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory.h"
#include "mech/base/vec.h"

/* Which fictitious terms a ballistic scene's run models. */
enum mech_scene_model {
    MECH_SCENE_MODEL_AUTO = 0,             /* the terms that matter at the target accuracy
                                              (mech_trajectory_model_select) */
    MECH_SCENE_MODEL_CORIOLIS,             /* Coriolis only: r'' = g - 2 w x r', as most
                                              textbooks solve these scenes (g the effective g) */
    MECH_SCENE_MODEL_CORIOLIS_CENTRIFUGAL, /* Coriolis and the centrifugal term of the
                                              displacement: r'' = g - 2 w x r' - w x (w x r) */
};

/* The request name of a model ("auto", "coriolis", "coriolis_centrifugal");
 * NULL for a value outside the enum. */
const char *mech_scene_model_name(enum mech_scene_model m);

/* A projectile near the Earth (local axes east, north, up; origin on the
 * ground, which is z = 0). */
struct mech_scene_ballistic {
    double latitude_deg; /* [-90, 90] */
    double g;            /* local effective g (m/s^2), (0, 1e3]; along -z */
    double omega;        /* Earth rotation rate W (rad/s), [0, 1e-2] */
    struct mech_vec3 r0; /* m; r0.z >= 0 */
    struct mech_vec3 v0; /* m/s; the projectile must reach z = 0 going down */
    int dry_run;         /* 1: stop after the choice (problem, choice set; every applicable
                            fictitious term assumed, no first pass, nothing integrated) */
    enum mech_scene_model model; /* the terms the run models (0: auto) */
};

/* A landing point: time and position. */
struct mech_scene_landing {
    double t;
    struct mech_vec3 r;
};

struct mech_scene_ballistic_result {
    /* the run (copies: problem.forces points into `forces`; call
     * mech_scene_ballistic_fix after copying the struct) */
    struct mech_trajectory_problem problem;
    struct mech_force forces[1];
    struct mech_trajectory_model model;     /* the "auto" choice */
    struct mech_trajectory_choice choice;   /* method and tolerances for the target */
    struct mech_trajectory_result run;      /* no sample buffers */
    struct mech_scene_landing numerical;    /* the stop point of the run */
    struct mech_scene_landing zeroth;       /* no rotation: r_0 at T0 */
    struct mech_scene_landing first_order;  /* the linearised first-order landing */
    struct mech_scene_landing series;       /* r_0 + r_1 + r_2 landing (exact time) */
    struct mech_scene_landing second_order; /* series - first_order (what the formula neglects) */
    struct mech_scene_landing second_coriolis;    /* its Coriolis-twice part */
    struct mech_scene_landing second_centrifugal; /* its centrifugal part (0 if not modelled) */
    struct mech_scene_landing difference;         /* numerical - first_order */
    struct mech_scene_landing unexplained;        /* difference - second_order: third-order terms
                                                     and integration error */
    double integration_tolerance;                 /* m: target x the position scale */
};

/* Run a ballistic scene at relative accuracy `target` ([1e-15, 0.1]):
 * the terms of s->model (auto: the selection by
 * mech_trajectory_model_select), method by mech_trajectory_choose, stop at
 * z = 0 going down, t_end = 2 T0 + 1 s. The centrifugal term enters the
 * series only when the run models it, so `unexplained` compares like with
 * like.
 * Statuses: MECH_OK; MECH_EDOMAIN (param "latitude_deg", "g", "omega",
 * "r0", "v0": out of range, or a projectile that never comes down; "model":
 * not one of the enum);
 * MECH_EINVAL (target); those of mech_trajectory_integrate (budget...);
 * MECH_ENUMERIC if the run does not land before t_end. */
enum mech_status mech_scene_ballistic_run(const struct mech_scene_ballistic *s, double target,
                                          const struct mech_budget *budget,
                                          struct mech_scene_ballistic_result *out,
                                          struct mech_error *err);

/* Re-point out->problem.forces at out->forces (after a struct copy). */
void mech_scene_ballistic_fix(struct mech_scene_ballistic_result *out);

/* The first-order and series landings only (no integration): fills
 * zeroth, first_order, series (with the centrifugal part iff centrifugal),
 * second_order, second_coriolis, second_centrifugal of out.
 * Statuses: MECH_OK, MECH_EDOMAIN (never lands). */
enum mech_status mech_scene_ballistic_formulas(const struct mech_scene_ballistic *s,
                                               int centrifugal,
                                               struct mech_scene_ballistic_result *out,
                                               struct mech_error *err);

/* ---- the rotating table (notes §1.1) ------------------------------------- */

enum mech_table_experiment {
    MECH_TABLE_THROUGH_CENTER = 0, /* the first puck: from r1 e_y straight through the centre,
                                      inertial speed 2 r1 w / pi, for half a turn */
    MECH_TABLE_AT_REST,            /* the second puck: at rest in the inertial frame at r1 e_y,
                                      for a full turn (a circle in the rotating frame) */
    MECH_TABLE_CUSTOM,             /* given inertial r0, v0 (z = 0 plane or not), t_end */
};

struct mech_scene_table {
    enum mech_table_experiment experiment;
    double omega;            /* table rate about +z (rad/s), != 0, |omega| <= 1e6 */
    double radius;           /* r1 (m), > 0 (first two experiments) */
    double mass;             /* kg, > 0 */
    struct mech_vec3 r0, v0; /* CUSTOM: inertial position and velocity at t = 0 */
    double t_end;            /* CUSTOM: s, > 0; else set by the experiment */
    size_t samples;          /* 2..MECH_TRAJECTORY_MAX_SAMPLES */
    int dry_run;             /* 1: stop after the choice, as mech_scene_ballistic.dry_run */
};

struct mech_scene_table_result {
    /* caller-owned buffers, `samples` entries each, any may be NULL */
    double *t;
    struct mech_vec3 *inertial;       /* the straight line r0 + v0 t */
    struct mech_vec3 *rotating;       /* the integrated rotating-frame path */
    struct mech_vec3 *rotating_exact; /* the straight line in the rotating axes */
    /* filled */
    size_t n_samples;
    double t_end;
    struct mech_vec3 r0_inertial, v0_inertial, r0_rotating, v0_rotating;
    /* the effective forces at t = 0 in the rotating frame (N) */
    struct mech_vec3 centrifugal, coriolis, total;
    double max_position_error;              /* m: max |rotating - rotating_exact| */
    double max_relative_position_error;     /* over max |r| */
    struct mech_vec3 end_rotating;          /* numerical rotating-frame position at t_end */
    struct mech_trajectory_problem problem; /* the rotating-frame run (no forces) */
    struct mech_trajectory_model model;
    struct mech_trajectory_choice choice;
    struct mech_trajectory_result run;
};

/* Run the table experiment: the inertial straight line (exact), its image in
 * the rotating axes (passive rotation by w t about z), and the rotating-frame
 * equations of motion integrated with "auto" terms at `target`, compared.
 * Statuses: MECH_OK; MECH_EDOMAIN (param "omega", "radius", "mass", "t_end",
 * "samples"); those of the run. */
enum mech_status mech_scene_table_run(const struct mech_scene_table *s, double target,
                                      const struct mech_budget *budget,
                                      struct mech_scene_table_result *out, struct mech_error *err);

#endif
