/* phase_area.c — phase-space area and period of an energy contour (see
 * mech/hamiltonian/phase_area.h). */
#include "mech/hamiltonian/phase_area.h"
#include "mech/base/constants.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>

static enum mech_status positive(double x, const char *name, struct mech_error *err)
{
    if (!isfinite(x) || !(x > 0))
        return mech_error_set(err, MECH_EDOMAIN, name, "must be a finite number > 0, got %.17g", x);
    return MECH_OK;
}

enum mech_status mech_phase_area_oscillator(double m, double omega, double energy,
                                            struct mech_phase_area *out, struct mech_error *err)
{
    enum mech_status st;
    if ((st = positive(m, "mass", err)) != MECH_OK) return st;
    if ((st = positive(omega, "omega", err)) != MECH_OK) return st;
    if (!isfinite(energy) || energy < 0)
        return mech_error_set(err, MECH_EDOMAIN, "energy",
                              "the energy above the minimum is >= 0, got %.17g", energy);
    out->motion = MECH_PHASE_LIBRATION;
    out->area = 2 * MECH_PI * energy / omega; /* an ellipse of semi-axes sqrt(2mE), sqrt(2E/m)/ω */
    out->period = 2 * MECH_PI / omega;
    out->modulus = 0;
    out->amplitude = sqrt(2 * energy / m) / omega;
    return MECH_OK;
}

/* E(k) − (1 − k²) K(k) for m = k² < 1/2 by its series (no cancellation). */
static double e_minus_k_series(double m)
{
    double a = 1.0, p = m, sum = 0.0; /* a = a_{n−1}, p = m^n */
    for (int n = 1; n < 400; n++) {
        const double t = a * p / (2 * n);
        sum += t;
        if (t < 1e-18 * sum) break;
        a *= ((2.0 * n - 1) / (2.0 * n)) * ((2.0 * n - 1) / (2.0 * n));
        p *= m;
    }
    return 0.5 * MECH_PI * sum;
}

enum mech_status mech_phase_area_pendulum(double m, double l, double g, double energy,
                                          struct mech_phase_area *out, struct mech_error *err)
{
    enum mech_status st;
    if ((st = positive(m, "mass", err)) != MECH_OK) return st;
    if ((st = positive(l, "length", err)) != MECH_OK) return st;
    if ((st = positive(g, "g", err)) != MECH_OK) return st;
    if (!isfinite(energy) || energy < 0)
        return mech_error_set(err, MECH_EDOMAIN, "energy",
                              "the energy above the bottom is >= 0, got %.17g", energy);
    const double w0 = sqrt(g / l), scale = 8 * m * l * l * w0;
    const double k2 = energy / (2 * m * g * l), k = sqrt(k2);
    gsl_sf_result rk, re;
    out->modulus = k;
    if (k2 == 1) {
        out->motion = MECH_PHASE_SEPARATRIX;
        out->area = 2 * scale; /* 16 m l² ω0 */
        out->period = INFINITY;
        out->amplitude = MECH_PI;
        return MECH_OK;
    }
    if (k2 < 1) {
        out->motion = MECH_PHASE_LIBRATION;
        double d;
        if (k2 < 0.5) {
            d = e_minus_k_series(k2);
            if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &rk) != GSL_SUCCESS)
                return mech_error_set(err, MECH_ENUMERIC, "energy", "elliptic integral failed");
        } else {
            if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &rk) != GSL_SUCCESS ||
                gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &re) != GSL_SUCCESS)
                return mech_error_set(err, MECH_ENUMERIC, "energy", "elliptic integral failed");
            d = re.val - (1 - k2) * rk.val;
        }
        out->area = 2 * scale * d; /* both branches p = ±...: 16 m l² ω0 [E − (1 − k²)K] */
        out->period = 4 * rk.val / w0;
        out->amplitude = 2 * asin(k);
        return MECH_OK;
    }
    const double kap = 1 / k;
    if (gsl_sf_ellint_Kcomp_e(kap, GSL_PREC_DOUBLE, &rk) != GSL_SUCCESS ||
        gsl_sf_ellint_Ecomp_e(kap, GSL_PREC_DOUBLE, &re) != GSL_SUCCESS)
        return mech_error_set(err, MECH_ENUMERIC, "energy", "elliptic integral failed");
    out->motion = MECH_PHASE_ROTATION;
    out->area = scale * k * re.val;
    out->period = 2 * rk.val / (k * w0);
    out->amplitude = NAN;
    return MECH_OK;
}
