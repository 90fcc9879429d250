/* mech/base.h — every public header of the base domain in one include:
 * what every domain stands on: status codes and the error record, the compute
 * budget, small vectors and matrices, compensated sums and the physical constants.
 * One header per concept lives in mech/base/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_BASE_ALL_H
#define MECH_BASE_ALL_H

#include "mech/base/budget.h"
#include "mech/base/compensated.h"
#include "mech/base/constants.h"
#include "mech/base/named_bodies.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

#endif
