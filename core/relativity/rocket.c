/* rocket.c — the relativistic rocket's mass ratio (see mech/relativity/rocket.h). */
#include "mech/relativity/rocket.h"

#include <math.h>

static enum mech_status check_exhaust(double b, struct mech_error *err)
{
    if (!isfinite(b) || !(b > 0) || b > 1)
        return mech_error_set(err, MECH_EDOMAIN, "exhaust_beta",
                              "the exhaust speed over c is in (0, 1] (1: a photon rocket), got "
                              "%.17g",
                              b);
    return MECH_OK;
}

/* atanh(β) − β = Σ_{k≥1} β^{2k+1}/(2k + 1), summed for β < 1/2. */
static double atanh_minus(double beta, double eta)
{
    if (beta >= 0.5) return eta - beta;
    const double b2 = beta * beta;
    double p = beta * b2, sum = 0;
    for (int k = 1; k < 200; k++) {
        const double t = p / (2 * k + 1);
        sum += t;
        if (t <= 1e-18 * sum) break;
        p *= b2;
    }
    return sum;
}

enum mech_status mech_rocket_for_rapidity(double eta, double beta, double exhaust_beta,
                                          struct mech_rocket *out, struct mech_error *err)
{
    enum mech_status st = check_exhaust(exhaust_beta, err);
    if (st != MECH_OK) return st;
    if (!isfinite(eta) || eta < 0)
        return mech_error_set(err, MECH_EDOMAIN, "rapidity", "a final rapidity is >= 0, got %.17g",
                              eta);
    out->log_mass_ratio = eta / exhaust_beta;
    out->mass_ratio = exp(out->log_mass_ratio);
    out->fuel_fraction = -expm1(-out->log_mass_ratio);
    out->newtonian_log_mass_ratio = beta / exhaust_beta;
    out->newtonian_mass_ratio = exp(out->newtonian_log_mass_ratio);
    out->newtonian_rel_error = expm1(-atanh_minus(beta, eta) / exhaust_beta);
    return MECH_OK;
}

enum mech_status mech_rocket_rapidity(double mass_ratio, double exhaust_beta, double *eta,
                                      struct mech_error *err)
{
    enum mech_status st = check_exhaust(exhaust_beta, err);
    if (st != MECH_OK) return st;
    if (!isfinite(mass_ratio) || !(mass_ratio >= 1))
        return mech_error_set(err, MECH_EDOMAIN, "mass_ratio",
                              "the mass ratio m_i/m_f is >= 1 (the rocket loses mass), got %.17g",
                              mass_ratio);
    *eta = exhaust_beta * log(mass_ratio);
    return MECH_OK;
}
