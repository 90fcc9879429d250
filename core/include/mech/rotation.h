/* mech/rotation/rotation.h — every public header of the rotation domain in one include:
 * orientation: rotation matrices, Euler angles, axis-angle and quaternions,
 * attitude kinematics, Euler-angle rates, vector algebra.
 * One header per concept lives in mech/rotation/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_ROTATION_ALL_H
#define MECH_ROTATION_ALL_H

#include "mech/rotation/attitude.h"
#include "mech/rotation/euler_rates.h"
#include "mech/rotation/rotation.h"
#include "mech/rotation/vector_algebra.h"

#endif
