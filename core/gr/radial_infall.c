/* radial_infall.c — proper times of a radial fall from rest in the
 * Schwarzschild geometry (see mech/gr/radial_infall.h). */
#include "mech/gr/radial_infall.h"
#include "mech/base/constants.h"

#include <math.h>

/* asin s − s sqrt(1 − s²) = 2 Σ_k C(2k, k)/4^k s^{2k+3}/(2k + 3) (the integral
 * of 2t²/sqrt(1 − t²)), summed for s ≤ 1/2 where the closed form cancels. */
static double asin_minus(double s)
{
    if (s > 0.5) return asin(s) - s * sqrt(1.0 - s * s);
    const double s2 = s * s;
    double c = 1.0, p = s2 * s, sum = 0.0; /* c = C(2k, k)/4^k, p = s^{2k+3} */
    for (int k = 0; k < 200; k++) {
        const double term = c * p / (2 * k + 3);
        sum += term;
        if (term < 1e-18 * sum) break;
        c *= (2.0 * k + 1.0) / (2.0 * k + 2.0);
        p *= s2;
    }
    return 2.0 * sum;
}

enum mech_status mech_radial_infall_from_rest(double r0, struct mech_radial_infall *out,
                                              struct mech_error *err)
{
    if (!isfinite(r0) || !(r0 >= 2.0 * (1 - 1e-12)) || r0 > 1e200)
        return mech_error_set(err, MECH_EDOMAIN, "infall_from",
                              "a fall from rest starts at or outside the horizon, 2 <= r0 <= "
                              "1e200 GM/c^2; got %.17g",
                              r0);
    out->on_horizon = r0 <= 2.0;
    if (out->on_horizon) r0 = 2.0; /* the limit from outside; s = 1 below is exact */
    /* r = r0 cos²(η/2): the horizon at η_h = 2 acos(s), s = sqrt(2/r0), sin η_h =
     * 2 s sqrt(1 − s²); τ = A (η + sin η) with A = sqrt(r0³/8) = r0 sqrt(r0/8). */
    const double A = r0 * sqrt(r0 / 8.0), s = sqrt(2.0 / r0), cs = sqrt(1.0 - s * s);
    out->to_singularity = MECH_PI * A;
    out->to_horizon = A * (2.0 * acos(s) + 2.0 * s * cs);
    out->horizon_to_singularity = A * 2.0 * asin_minus(s);
    return MECH_OK;
}
