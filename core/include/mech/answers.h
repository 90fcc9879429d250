/* mech/answers.h — every public header of the answers domain in one include:
 * the answer-shaped layer: one operation's computation each, from a
 * request's parsed form to the arrays and figures its answer holds
 * (continuum, frames, gr, hamiltonian, relativity, rigid); the physics
 * underneath lives in the domains above.
 * One header per concept lives in mech/answers/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_ANSWERS_ALL_H
#define MECH_ANSWERS_ALL_H

#include "mech/answers/continuum/rod_answer.h"
#include "mech/answers/frames/compare_sweep.h"
#include "mech/answers/frames/earth_gravity_answer.h"
#include "mech/answers/frames/foucault_scene.h"
#include "mech/answers/frames/rotating_table_scene.h"
#include "mech/answers/frames/tides_answer.h"
#include "mech/answers/gr/geodesic_run.h"
#include "mech/answers/gr/geodesic_setup.h"
#include "mech/answers/gr/schwarzschild_answer.h"
#include "mech/answers/hamiltonian/liouville_runs.h"
#include "mech/answers/hamiltonian/poincare_orbits.h"
#include "mech/answers/relativity/charged_motion_answer.h"
#include "mech/answers/relativity/collision_answer.h"
#include "mech/answers/relativity/doppler_answer.h"
#include "mech/answers/relativity/elastic_answer.h"
#include "mech/answers/relativity/particle_answer.h"
#include "mech/answers/relativity/rocket_answer.h"
#include "mech/answers/relativity/worldline_answer.h"
#include "mech/answers/rigid/rigid_answer.h"
#include "mech/answers/rigid/top_answer.h"

#endif
