/* mech/rotation/vector_algebra.h — the vector algebra of notes ch. 0 (§0.1 "Vector
 * Identities", §0.2 "Cross Products and Axial Vectors"): dot and cross
 * products, norms, the angle between two vectors, the component and
 * projection of one vector along another, the scalar and vector triple
 * products, and the antisymmetric tensor form of a cross product
 * (L_ij = r_i p_j - r_j p_i, L_k = eps_ijk L_ij / 2).
 *
 * Units: whatever the caller's vectors carry (a product carries the product
 * of the units). Precision: every vector is first scaled by a power of two
 * (exact), so no intermediate overflows or underflows however large or small
 * the components (1e-300 .. 1e300); a result is lost only when it is itself
 * outside the double range. Angles use atan2(|a x b|, a.b), never acos, so
 * angles near 0 and pi keep their relative digits.
 * Pure functions: no allocation, no global state, thread-safe.
 */
#ifndef MECH_VECTOR_ALGEBRA_H
#define MECH_VECTOR_ALGEBRA_H

#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Unit vector along a (finite components, any magnitude, to ~1 ulp) in *u.
 * Returns 1; 0 (and *u untouched) when a is the zero vector or not finite. */
int mech_vector_unit(struct mech_vec3 a, struct mech_vec3 *u);

/* What two vectors a, b give. */
struct mech_vector_pair {
    double norm_a, norm_b;           /* |a|, |b| */
    double dot;                      /* a . b */
    struct mech_vec3 cross;          /* a x b (an axial vector; r x p = L) */
    struct mech_mat3 cross_tensor;   /* T_ij = a_i b_j - a_j b_i, antisymmetric: T_xy = (a x b)_z,
                                        T_yz = (a x b)_x, T_zx = (a x b)_y (notes §0.2) */
    int has_angle;                   /* 0 when a or b is the zero vector: then angle, the
                                        components and projections below are undefined (0) */
    double angle;                    /* rad, in [0, pi]: atan2(|a x b|, a . b) */
    double b_along_a, a_along_b;     /* signed components: a.b/|a|, a.b/|b| */
    struct mech_vec3 b_on_a;         /* projection of b on a: (a.b/|a|^2) a */
    struct mech_vec3 b_across_a;     /* b - b_on_a: the part of b normal to a */
    struct mech_vec3 difference;     /* a - b (each component rounded once) */
    struct mech_vec3 sum;            /* a + b */
    double distance;                 /* |a - b|, from the rounded difference */
};

/* Everything in struct mech_vector_pair for a and b (finite components, any
 * magnitude). Accuracy: norms ~1 ulp; dot and cross to round-off of
 * |a||b| (absolute), angle to a few ulp relative for any angle, including
 * ones near 0 and pi (near-parallel vectors).
 * Returns MECH_OK; MECH_EINVAL with param "a" or "b" for a non-finite
 * component; MECH_EDOMAIN with param "b" when |a||b|, a + b or a - b exceeds
 * the double range (a product or a sum would overflow). out must not be
 * NULL; written only on success. */
enum mech_status mech_vector_pair(struct mech_vec3 a, struct mech_vec3 b,
                                  struct mech_vector_pair *out, struct mech_error *err);

/* Scalar triple product a . (b x c) (= the determinant of the rows a, b, c)
 * and vector triple product a x (b x c) (= b (a.c) - c (a.b)), each to
 * round-off of |a||b||c| (absolute). Either output may be NULL.
 * Returns MECH_OK; MECH_EINVAL with param "a", "b" or "c" for a non-finite
 * component; MECH_EDOMAIN with param "c" when |a||b||c| exceeds the double
 * range. Outputs written only on success. */
enum mech_status mech_vector_triple(struct mech_vec3 a, struct mech_vec3 b, struct mech_vec3 c,
                                    double *scalar, struct mech_vec3 *vector,
                                    struct mech_error *err);

#endif
