/* mech/frames.h — every public header of the frames domain in one include:
 * a particle in inertial, rotating and Earth frames (notes chapter 1): the
 * frame, the trajectory and its references and closed forms, the chooser's
 * view of a scene, the Earth's gravity and the tides, the chapter's scenes.
 * One header per concept lives in mech/frames/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_FRAMES_ALL_H
#define MECH_FRAMES_ALL_H

#include "mech/frames/chooser_orbit.h"
#include "mech/frames/chooser_pendulum.h"
#include "mech/frames/closed_form.h"
#include "mech/frames/earth.h"
#include "mech/frames/effective_force.h"
#include "mech/frames/foucault_first_order.h"
#include "mech/frames/frame.h"
#include "mech/frames/pendulum.h"
#include "mech/frames/reference.h"
#include "mech/frames/rotating_liquid.h"
#include "mech/frames/scenes.h"
#include "mech/frames/scenes_first_order.h"
#include "mech/frames/tides.h"
#include "mech/frames/trajectory.h"
#include "mech/frames/trajectory_plan.h"
#include "mech/frames/trajectory_problem.h"

#endif
