/* mech/continuum.h — every public header of the continuum domain in one include:
 * continua: waves on strings and rods, torsion.
 * One header per concept lives in mech/continuum/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_CONTINUUM_ALL_H
#define MECH_CONTINUUM_ALL_H

#include "mech/continuum/continuum_waves.h"
#include "mech/continuum/torsion.h"

#endif
