/* mech/ode/ode.h — every public header of the ode domain in one include:
 * time integration: the initial-value driver and its integrators, the Kepler
 * propagator, the accuracy presets, the predictive method chooser and its pilot
 * runs, the method-choice policy for first-order systems.
 * One header per concept lives in mech/ode/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_ODE_ALL_H
#define MECH_ODE_ALL_H

#include "mech/ode/accuracy.h"
#include "mech/ode/chooser.h"
#include "mech/ode/chooser_pilot.h"
#include "mech/ode/kepler.h"
#include "mech/ode/method_choice.h"
#include "mech/ode/ode.h"

#endif
