/* mech/relativity/four_vector.h — the Minkowski dot product of two 4-vectors (notes §3
 * "Summary of 4-Vectors": x·y = −x0 y0 + x1 y1 + x2 y2 + x3 y3, metric
 * (−,+,+,+), x0 = ct or E/c), the kind of a 4-vector from its square, and the
 * relative Lorentz factor of two timelike vectors, −u·v/sqrt(u·u v·v).
 *
 * Precision: error-free products (fma) and a compensated sum, so a dot
 * product that cancels (two nearly parallel light-like vectors, a momentum
 * at γ = 1e8) is right to about one rounding of the result plus
 * 1e-31 Σ|x_i y_i|, not ε Σ|x_i y_i|. Components up to 1e150 in magnitude.
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_FOUR_VECTOR_H
#define MECH_FOUR_VECTOR_H

#include "mech/base/status.h"

/* Light-like tolerance in units of DBL_EPSILON: x is light-like when
 * |x·x| ≤ 4 ε Σ x_i² (the rounding a decimal input like [1, 0.6, 0.8, 0] has). */
#define MECH_FOUR_VECTOR_LIGHTLIKE_ULPS 4.0

enum mech_four_kind {
    MECH_FOUR_TIMELIKE = 0,
    MECH_FOUR_SPACELIKE = 1,
    MECH_FOUR_LIGHTLIKE = 2, /* includes the zero vector */
};

/* −x0 y0 + x·y, compensated (see above). Cannot fail; non-finite input gives
 * a non-finite result. */
double mech_four_dot(const double x[4], const double y[4]);

/* Kind of x from its square x·x and the tolerance above. */
enum mech_four_kind mech_four_kind_of(const double x[4]);

/* Relative Lorentz factor γ_rel = −u·v / sqrt((−u·u)(−v·v)) ≥ 1 of two
 * timelike vectors pointing the same way in time (u0 v0 > 0): the γ of v's
 * motion seen from u's rest frame (e.g. E of particle v in u's rest frame is
 * m_v γ_rel). Returns 1 and sets *gamma_rel; 0 when either vector is not
 * timelike or they point opposite ways in time (no relative velocity). */
int mech_four_relative_gamma(const double u[4], const double v[4], double *gamma_rel);

#endif
