/* trajectory_scene.h — private to core/frames: what the trajectory's
 * equations of motion (trajectory_equations.c) tell the chooser's profile of a scene
 * (trajectory_choose.c) without handing out their context. */
#ifndef MECH_FRAMES_TRAJECTORY_SCENE_H
#define MECH_FRAMES_TRAJECTORY_SCENE_H

#include "mech/base/status.h"
#include "mech/frames/trajectory_problem.h"

/* The particle's acceleration a[3] (m/s^2, frame axes) at t = 0, from the
 * position and velocity of p with the fictitious terms p models, exactly as
 * the integration's first right-hand side evaluates it. p must be valid
 * (mech_trajectory_check). Statuses: MECH_OK; MECH_ENUMERIC when a force is
 * singular there (r at a central mass) or the result is not finite (a is
 * then unspecified). No error record is written. */
enum mech_status mech_trajectory_start_acceleration(const struct mech_trajectory_problem *p,
                                                    double a[3]);

/* 1 if the modelled acceleration of p depends on the velocity (drag,
 * Coriolis in a frame that turns, a magnetic field on a charge), else 0. */
int mech_trajectory_velocity_dependent(const struct mech_trajectory_problem *p);

#endif
