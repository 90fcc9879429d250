/* mech/gr.h — every public header of the gr domain in one include:
 * general relativity: the Schwarzschild metric, its geodesics, radial infall
 * and the unit conversions.
 * One header per concept lives in mech/gr/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_GR_ALL_H
#define MECH_GR_ALL_H

#include "mech/gr/geodesic.h"
#include "mech/gr/gr_units.h"
#include "mech/gr/radial_infall.h"
#include "mech/gr/schwarzschild.h"

#endif
