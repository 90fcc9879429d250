/* torsion.c — torsion constants and torsional wave speeds of rods (see
 * mech/continuum/torsion.h for the formulas and sources). */
#include "mech/base/constants.h"
#include "mech/continuum/torsion.h"

#include <math.h>

/* (31/32) ζ(5) = Σ_{n odd} 1/n⁵; ζ(5) = 1.0369277551433699263 (DLMF 25.6). */
static const double ODD_ZETA5 = 1.0045237627951396161;

static int pos(double x)
{
    return isfinite(x) && x > 0;
}

enum mech_status mech_torsion_rectangle(double width, double height, double *polar_moment,
                                        double *torsion_constant, struct mech_error *err)
{
    if (!pos(width))
        return mech_error_set(err, MECH_EDOMAIN, "width", "must be finite and > 0, got %.17g",
                              width);
    if (!pos(height))
        return mech_error_set(err, MECH_EDOMAIN, "height", "must be finite and > 0, got %.17g",
                              height);
    const double b = width >= height ? width : height, h = width >= height ? height : width;
    const double r = h / b; /* ≤ 1 */
    /* Σ_{n odd} (1 − tanh(nπ/(2r)))/n⁵, each term 2/(e^{nπ/r} + 1)/n⁵ */
    double tail = 0;
    for (int n = 1; n < 200; n += 2) {
        const double t = 2.0 / (exp(n * MECH_PI / r) + 1.0) / pow((double)n, 5);
        tail += t;
        if (t < 1e-18 * ODD_ZETA5) break;
    }
    const double s = ODD_ZETA5 - tail;
    const double k = (b * h) * (h * h) / 3.0 * (1.0 - (192.0 / pow(MECH_PI, 5)) * r * s);
    const double j = (b * h) * (b * b + h * h) / 12.0;
    if (!pos(k) || !pos(j))
        return mech_error_set(err, MECH_ENUMERIC, "width",
                              "the section's torsion constant is not a finite positive double");
    if (polar_moment) *polar_moment = j;
    if (torsion_constant) *torsion_constant = k;
    return MECH_OK;
}

enum mech_status mech_shear_modulus(double youngs_modulus, double poisson_ratio, double *g,
                                    struct mech_error *err)
{
    if (!pos(youngs_modulus))
        return mech_error_set(err, MECH_EDOMAIN, "youngs_modulus", "must be finite and > 0");
    if (!isfinite(poisson_ratio) || !(poisson_ratio > -1.0) || poisson_ratio > 0.5)
        return mech_error_set(err, MECH_EDOMAIN, "poisson_ratio",
                              "an isotropic solid has -1 < nu <= 1/2, got %.17g", poisson_ratio);
    *g = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
    return MECH_OK;
}

enum mech_status mech_torsional_wave_speed(double shear_modulus, double density,
                                           double torsion_constant, double polar_moment,
                                           double *c, struct mech_error *err)
{
    if (!pos(shear_modulus))
        return mech_error_set(err, MECH_EDOMAIN, "shear_modulus", "must be finite and > 0");
    if (!pos(density))
        return mech_error_set(err, MECH_EDOMAIN, "density", "must be finite and > 0");
    if (!pos(torsion_constant))
        return mech_error_set(err, MECH_EDOMAIN, "section/torsion_constant",
                              "must be finite and > 0");
    if (!pos(polar_moment))
        return mech_error_set(err, MECH_EDOMAIN, "section/polar_moment", "must be finite and > 0");
    if (torsion_constant > polar_moment)
        return mech_error_set(err, MECH_EDOMAIN, "section/torsion_constant",
                              "a torsion constant K = %.6g m^4 above the polar moment J = %.6g "
                              "m^4 is impossible (K = J for a circle or tube, less otherwise)",
                              torsion_constant, polar_moment);
    const double v = sqrt(shear_modulus) / sqrt(density) *
                     (sqrt(torsion_constant) / sqrt(polar_moment));
    if (!pos(v))
        return mech_error_set(err, MECH_ENUMERIC, "shear_modulus",
                              "the torsional wave speed is not a finite positive double");
    *c = v;
    return MECH_OK;
}
