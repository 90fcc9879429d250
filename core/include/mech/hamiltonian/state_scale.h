/* mech/hamiltonian/state_scale.h — the smallest scale among a Hamiltonian state's
 * components, the absolute scale an integrator's atol is measured against
 * (so a 1e-15 m oscillator is not integrated at atol 1e-13).
 * Pure; thread-safe; no allocation. */
#ifndef MECH_HAM_STATE_SCALE_H
#define MECH_HAM_STATE_SCALE_H

#include "mech/hamiltonian/hamiltonian.h"

/* The smallest positive finite value among, for each degree of freedom i at
 * y0 (q..., p..., SI): |q_i|, |p_i|, tau |p_i| / M_i and M_i |q_i| / tau, with
 * the inertia M_i = 1 / (d2H/dp_i^2) at y0 (the system's mass where that
 * derivative is not positive and finite). tau: the system's time scale, s
 * (mech_ham_time_scale). Returns 1 when every candidate vanishes (a state at
 * rest at the origin) or none is finite. Never fails; s checked by
 * mech_ham_system_check, y0 of s->dof * 2 values. */
double mech_ham_state_scale(const struct mech_ham_system *s, const double *y0, double tau);

#endif
