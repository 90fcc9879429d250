/* four_vector.c — Minkowski dot product, kind and relative γ of 4-vectors
 * (see mech/relativity/four_vector.h). */
#include "mech/relativity/four_vector.h"

#include <float.h>
#include <math.h>

#include "mech/base/compensated.h"

double mech_four_dot(const double x[4], const double y[4])
{
    struct mech_csum s = {0, 0};
    mech_csum_add_product(&s, -x[0], y[0]);
    mech_csum_add_product(&s, x[1], y[1]);
    mech_csum_add_product(&s, x[2], y[2]);
    mech_csum_add_product(&s, x[3], y[3]);
    return mech_csum_value(&s);
}

enum mech_four_kind mech_four_kind_of(const double x[4])
{
    const double s2 = mech_four_dot(x, x);
    const double scale = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    if (fabs(s2) <= MECH_FOUR_VECTOR_LIGHTLIKE_ULPS * DBL_EPSILON * scale) return MECH_FOUR_LIGHTLIKE;
    return s2 < 0 ? MECH_FOUR_TIMELIKE : MECH_FOUR_SPACELIKE;
}

int mech_four_relative_gamma(const double u[4], const double v[4], double *gamma_rel)
{
    if (mech_four_kind_of(u) != MECH_FOUR_TIMELIKE || mech_four_kind_of(v) != MECH_FOUR_TIMELIKE)
        return 0;
    if (!(u[0] * v[0] > 0)) return 0;
    /* sqrt of each square separately: no overflow of the product. */
    const double g = -mech_four_dot(u, v) / (sqrt(-mech_four_dot(u, u)) * sqrt(-mech_four_dot(v, v)));
    /* γ_rel ≥ 1 exactly (reverse Cauchy–Schwarz); rounding may give 1 − ε. */
    *gamma_rel = g < 1 ? 1.0 : g;
    return 1;
}
