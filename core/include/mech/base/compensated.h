/* mech/base/compensated.h — error-free products and compensated sums, for
 * invariants and expressions that nearly cancel (m² from (E, p), s², E² − B²,
 * cross products of nearly parallel vectors). Header-only, cannot fail.
 *
 * - TwoProduct: x·y = p + fma(x, y, −p) exactly (Ogita, Rump & Oishi,
 *   "Accurate sum and dot product", SIAM J. Sci. Comput. 26 (2005) 1955).
 * - Neumaier's compensated summation (ZAMM 54 (1974) 39): a sum of n terms is
 *   right to about one rounding of the result plus n² ε² Σ|terms|.
 * - Kahan's a·b − c·d with fma: error below 2 ulp of the result even when the
 *   products cancel (Jeannerod, Louvet & Muller, Math. Comp. 82 (2013) 2245).
 */
#ifndef MECH_COMPENSATED_H
#define MECH_COMPENSATED_H

#include <math.h>

#include "mech/base/vec.h"

/* A running sum s + c (c collects the rounding errors). Start with {0, 0}. */
struct mech_csum {
    double s, c;
};

static inline void mech_csum_add(struct mech_csum *a, double t)
{
    double s = a->s + t;
    if (fabs(a->s) >= fabs(t))
        a->c += (a->s - s) + t;
    else
        a->c += (t - s) + a->s;
    a->s = s;
}

/* a += x·y, the product split exactly into its rounded value and its error. */
static inline void mech_csum_add_product(struct mech_csum *a, double x, double y)
{
    double p = x * y;
    mech_csum_add(a, p);
    mech_csum_add(a, fma(x, y, -p));
}

static inline double mech_csum_value(const struct mech_csum *a)
{
    return a->s + a->c;
}

/* a·b − c·d (Kahan's algorithm with fma). */
static inline double mech_diff_of_products(double a, double b, double c, double d)
{
    double w = c * d;
    double e = fma(c, d, -w);
    double f = fma(a, b, -w);
    return f - e;
}

/* a · b with error-free products and a compensated sum. */
static inline double mech_dot_compensated(struct mech_vec3 a, struct mech_vec3 b)
{
    struct mech_csum s = {0, 0};
    mech_csum_add_product(&s, a.x, b.x);
    mech_csum_add_product(&s, a.y, b.y);
    mech_csum_add_product(&s, a.z, b.z);
    return mech_csum_value(&s);
}

/* a × b, each component by mech_diff_of_products. */
static inline struct mech_vec3 mech_cross_compensated(struct mech_vec3 a, struct mech_vec3 b)
{
    return mech_vec3_make(mech_diff_of_products(a.y, b.z, a.z, b.y),
                          mech_diff_of_products(a.z, b.x, a.x, b.z),
                          mech_diff_of_products(a.x, b.y, a.y, b.x));
}

#endif
