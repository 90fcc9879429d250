/* mech/hamiltonian/hamiltonian.h — every public header of the hamiltonian domain in one include:
 * Hamiltonian mechanics: Hamilton's equations, Liouville's theorem and
 * phase areas, Poincare sections, rotating systems, small and coupled
 * oscillations, circular orbits, steady motion and apsides, state scales.
 * One header per concept lives in mech/hamiltonian/; include those where a file needs
 * one or two of them (faster builds, visible dependencies). */
#ifndef MECH_HAMILTONIAN_ALL_H
#define MECH_HAMILTONIAN_ALL_H

#include "mech/hamiltonian/apsides.h"
#include "mech/hamiltonian/circular_orbit.h"
#include "mech/hamiltonian/coupled_oscillations.h"
#include "mech/hamiltonian/hamiltonian.h"
#include "mech/hamiltonian/liouville.h"
#include "mech/hamiltonian/phase_area.h"
#include "mech/hamiltonian/poincare.h"
#include "mech/hamiltonian/rotating_hamiltonian.h"
#include "mech/hamiltonian/small_oscillations.h"
#include "mech/hamiltonian/state_scale.h"
#include "mech/hamiltonian/steady_motion.h"

#endif
