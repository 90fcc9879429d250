/* mech/relativity.h — every public header of the relativity domain in one include:
 * special relativity: boosts, four-vectors, intervals, velocity addition,
 * Doppler, fields, kinematics of collisions and decays, particles, the
 * relativistic force and rocket, world lines, the telescope and
 * Michelson-Morley, a charge's Lagrangian and motion.
 * One header per concept lives in mech/relativity/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_RELATIVITY_ALL_H
#define MECH_RELATIVITY_ALL_H

#include "mech/relativity/boost.h"
#include "mech/relativity/charged_lagrangian.h"
#include "mech/relativity/charged_motion.h"
#include "mech/relativity/decay_estimate.h"
#include "mech/relativity/doppler.h"
#include "mech/relativity/elastic_scattering.h"
#include "mech/relativity/em_fields.h"
#include "mech/relativity/four_vector.h"
#include "mech/relativity/interval.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/mass_energy.h"
#include "mech/relativity/michelson_morley.h"
#include "mech/relativity/particle_state.h"
#include "mech/relativity/particles.h"
#include "mech/relativity/relativistic_force.h"
#include "mech/relativity/rocket.h"
#include "mech/relativity/telescope.h"
#include "mech/relativity/velocity_addition.h"
#include "mech/relativity/worldline.h"

#endif
