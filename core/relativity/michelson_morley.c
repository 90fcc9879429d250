/* michelson_morley.c — ether round-trip times and the path difference (see
 * mech/relativity/michelson_morley.h). */
#include "mech/relativity/michelson_morley.h"

#include <math.h>

enum mech_status mech_michelson_morley_compute(double arm_length, const struct mech_boost *b,
                                               double wavelength,
                                               struct mech_michelson_morley *out,
                                               struct mech_error *err)
{
    if (!isfinite(arm_length) || !(arm_length > 0))
        return mech_error_set(err, MECH_EDOMAIN, "arm_length", "an arm length is > 0 m");
    if (!isfinite(wavelength) || wavelength < 0)
        return mech_error_set(err, MECH_EDOMAIN, "wavelength", "a wavelength is > 0 m");
    const double g = b->gamma, gm1 = b->gamma_minus_one, beta = b->beta, L = arm_length;
    struct mech_michelson_morley o;
    o.time_parallel = 2 * g * g * L / MECH_C;
    o.time_perpendicular = 2 * g * L / MECH_C;
    o.path_difference = 2 * g * gm1 * L;
    o.time_difference = o.path_difference / MECH_C;
    o.path_difference_approx = beta * beta * L;
    /* β² = (γ − 1)(γ + 1)/γ², so β²L/d = (γ + 1)/(2γ³) and the relative error is
     * ((γ + 1) − 2γ³)/(2γ³) = −(γ − 1)(2γ² + 2γ + 1)/(2γ³), exact in γ − 1. */
    o.approx_rel_error = -gm1 * (2 * g * g + 2 * g + 1) / (2 * g * g * g);
    o.fringe_shift = wavelength > 0 ? 2 * o.path_difference / wavelength : 0;
    o.time_parallel_contracted = 2 * g * (L / g) * g / MECH_C;
    *out = o;
    return MECH_OK;
}
