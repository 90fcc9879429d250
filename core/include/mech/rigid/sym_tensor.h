/* mech/rigid/sym_tensor.h — a symmetric rank-2 tensor given by the user (an inertia
 * tensor, a stress, a quadratic form): its trace, its three invariants, its
 * isotropic and deviatoric parts and its eigen-decomposition (notes ch. 2,
 * "Principal Axes"; "Proof: Principal Axes Orthogonal", "Roots are Real").
 * The eigen-decomposition is mech_inertia_principal's (mech/rigid/inertia.h): the
 * same ascending order, degeneracy flag and deterministic axis signs as the
 * inertia tensor's principal axes.
 *
 * Units: the caller's (invariant k carries the k-th power of the entries' unit).
 * Pure computation apart from GSL's 3x3 eigen-workspace; thread-safe.
 */
#ifndef MECH_SYM_TENSOR_H
#define MECH_SYM_TENSOR_H

#include "mech/rigid/inertia.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Two entries t_ij and t_ji may differ by this times the largest |entry|
 * (round-off in a tensor computed elsewhere); more is not a symmetric tensor. */
#define MECH_SYM_TENSOR_RTOL 1e-12

struct mech_sym_tensor {
    struct mech_mat3 tensor;        /* the input, symmetrised: (t + t^T)/2 */
    double trace;                   /* I1 = t_11 + t_22 + t_33 */
    double invariants[3];           /* I1; I2 = sum of the principal 2x2 minors
                                       = (I1^2 - tr(t^2))/2; I3 = det t */
    double isotropic;               /* I1/3: t = isotropic 1 + deviator */
    struct mech_mat3 deviator;      /* t - (I1/3) 1, traceless */
    double asymmetry;               /* max |t_ij - t_ji| of the input */
    struct mech_inertia_principal principal; /* eigenvalues ascending in moments[],
                                                unit eigenvectors as rows of axes */
};

/* Analyse the symmetric tensor t (row-major; finite entries; invariants
 * computed on t scaled by a power of two, so the only loss for huge or tiny
 * entries is a result itself outside the double range: with |entries| <=
 * 1e100 none is). Eigenvalues right to ~1e-15 of the largest |eigenvalue|;
 * I2, I3 to round-off of max|t|^2, max|t|^3.
 * Returns MECH_OK; MECH_EINVAL with param "tensor" for a non-finite entry,
 * "tensor/<i>/<j>" (i > j, 0-based) when |t_ij - t_ji| > MECH_SYM_TENSOR_RTOL
 * max|t| (the first such pair, row by row); MECH_ENUMERIC if an invariant
 * overflows; MECH_ENOMEM/ENUMERIC from the eigen-solver. out must not be NULL;
 * written only on success. */
enum mech_status mech_sym_tensor_analyse(struct mech_mat3 t, struct mech_sym_tensor *out,
                                         struct mech_error *err);

#endif
