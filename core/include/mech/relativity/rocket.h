/* mech/relativity/rocket.h — the relativistic rocket (Ackeret 1946; e.g. Rindler,
 * "Relativity: Special, General, and Cosmological" §6.6): a rocket that
 * ejects exhaust at speed u = β_e c relative to itself, starting from rest,
 * reaches rapidity η when its rest mass has fallen by
 *   m_i/m_f = exp(η/β_e) = ((1 + β)/(1 − β))^{1/(2β_e)}
 * (the photon rocket, β_e = 1: m_i/m_f = e^η = γ(1 + β)), beside the
 * Newtonian (Tsiolkovsky) m_i/m_f = exp(β/β_e), an approximation that is too
 * small by the factor exp(−(η − β)/β_e).
 *
 * Precision: the fuel fraction 1 − m_f/m_i = −expm1(−η/β_e) and the
 * Newtonian relative error expm1(−(η − β)/β_e), with η − β = atanh β − β
 * by its series for β < 1/2, keep their digits at 1 m/s.
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_ROCKET_H
#define MECH_ROCKET_H

#include "mech/base/status.h"

struct mech_rocket {
    double log_mass_ratio;     /* ln(m_i/m_f) = η/β_e (always finite) */
    double mass_ratio;         /* m_i/m_f (+inf when beyond the double range) */
    double fuel_fraction;      /* 1 − m_f/m_i, the fraction of the initial mass spent */
    double newtonian_log_mass_ratio; /* β/β_e */
    double newtonian_mass_ratio;     /* exp(β/β_e) (+inf beyond the range) */
    double newtonian_rel_error;      /* (newtonian − exact)/exact = expm1(−(η − β)/β_e) ≤ 0 */
};

/* The rocket reaching rapidity eta ≥ 0 (speed beta = tanh eta, passed in so
 * its precise value is used) with exhaust speed exhaust_beta in (0, 1].
 * Statuses: MECH_OK; MECH_EDOMAIN param "exhaust_beta" (outside (0, 1]) or
 * "rapidity" (eta < 0 or not finite). out written only on success. */
enum mech_status mech_rocket_for_rapidity(double eta, double beta, double exhaust_beta,
                                          struct mech_rocket *out, struct mech_error *err);

/* The rapidity a mass ratio ≥ 1 gives: η = β_e ln(m_i/m_f). Statuses:
 * MECH_OK; MECH_EDOMAIN param "mass_ratio" (< 1 or not finite) or
 * "exhaust_beta". */
enum mech_status mech_rocket_rapidity(double mass_ratio, double exhaust_beta, double *eta,
                                      struct mech_error *err);

#endif
