/* mech/inertia.h — inertia tensor of a rigid body made of simple parts, its
 * principal moments and axes, and the angular momentum and kinetic energy of a
 * rotation (notes ch. 2: §2.1-2.5).
 *
 * Units: SI (kg, m, kg m^2, rad/s, J). Tensors are in scene axes.
 * Precision (DESIGN.md "Numerics"): the centre of mass is found relative to the
 * first part's position and refined once; the tensor about it is accumulated
 * in centred coordinates, then moved to the requested origin with the parallel
 * axis theorem (notes §2.3), so a small body far from the scene origin keeps
 * full relative precision. Reentrant; the only allocation is GSL's 3x3
 * eigen-workspace inside mech_inertia_principal().
 */
#ifndef MECH_INERTIA_H
#define MECH_INERTIA_H

#include <stddef.h>

#include "mech/budget.h"
#include "mech/status.h"
#include "mech/vec.h"

enum mech_inertia_shape {
    MECH_SHAPE_POINT = 0,    /* point mass */
    MECH_SHAPE_ROD = 1,      /* thin rod, dim[0] = length, along body z */
    MECH_SHAPE_BOX = 2,      /* solid box, dim = edges [a, b, c] along body x, y, z */
    MECH_SHAPE_SPHERE = 3,   /* solid sphere, dim[0] = radius */
    MECH_SHAPE_SHELL = 4,    /* thin spherical shell, dim[0] = radius */
    MECH_SHAPE_CYLINDER = 5, /* solid cylinder, dim[0] = radius, dim[1] = height, axis body z */
    MECH_SHAPE_COUNT
};

/* One part of a body. */
struct mech_inertia_part {
    enum mech_inertia_shape shape;
    double mass;                  /* kg, finite, > 0 */
    struct mech_vec3 position;    /* m, the part's centre in scene axes */
    struct mech_mat3 orientation; /* passive R (mech/rotation.h): scene -> body
                                     components, rows = body axes in scene axes;
                                     must be a rotation; ignored for point, sphere, shell */
    double dim[3];                /* m, finite, > 0 where the shape uses it (see above) */
};

/* Two principal moments agree ("degenerate") when they differ by at most this
 * times the largest moment. */
#define MECH_INERTIA_DEGENERATE_RTOL 1e-10

struct mech_inertia_principal {
    double moments[3];     /* kg m^2, ascending */
    struct mech_mat3 axes; /* row k = unit principal axis of moments[k], scene axes */
    int degenerate;        /* 1 if two (or three) moments agree within
                              MECH_INERTIA_DEGENERATE_RTOL of the largest, or all are 0 */
};

struct mech_inertia {
    double mass;                             /* kg, total */
    struct mech_vec3 center_of_mass;         /* m */
    struct mech_vec3 origin;                 /* m, where `tensor` is taken */
    struct mech_mat3 tensor;                 /* kg m^2, about origin */
    struct mech_mat3 tensor_cm;              /* kg m^2, about the centre of mass */
    struct mech_inertia_principal principal; /* of `tensor` (about origin) */
};

/* Tensor of one part about its own centre, in scene axes: I_scene = R^T I_body R
 * (notes §2.2, "Transforming the Inertia Tensor", for the passive R). Body
 * tensors (principal, about the centre): point 0; rod M L^2/12 (x, y), 0 (z);
 * box M(b^2+c^2)/12, M(a^2+c^2)/12, M(a^2+b^2)/12; sphere 2/5 M R^2; shell
 * 2/3 M R^2; cylinder M(3R^2+h^2)/12 (x, y), M R^2/2 (z).
 * Returns MECH_OK; MECH_EDOMAIN with param "mass" for mass <= 0 or non-finite,
 * MECH_EINVAL with param "position", "length", "size", "radius", "height" or
 * "orientation" for a non-finite position, a dimension that is not finite and
 * > 0, or an orientation that is not a rotation within 1e-9; MECH_ENUMERIC if
 * the result overflows. out must not be NULL. */
enum mech_status mech_inertia_part_tensor(const struct mech_inertia_part *part,
                                          struct mech_mat3 *out, struct mech_error *err);

/* Mass, centre of mass, tensors about the centre of mass and about `origin`
 * (NULL: the centre of mass), and the principal moments/axes of the latter,
 * for parts[0..n-1] (1 <= n; parts borrowed, read only). Three budget steps per
 * part (three passes), checked with mech_budget_check (budget required).
 * Returns MECH_OK; MECH_EINVAL/MECH_EDOMAIN with param "bodies/<i>/<field>"
 * (as mech_inertia_part_tensor) for part i, param "bodies" when n == 0,
 * "origin" for a non-finite origin; MECH_EBUDGET/EDEADLINE/ECANCELLED from the
 * budget; MECH_ENUMERIC if a result is not finite or the tensor's largest entry
 * is so small (< 2^-968) that its digits would be lost to underflow;
 * MECH_ENOMEM from the eigen-solver. *out is written only on success. */
enum mech_status mech_inertia_compute(const struct mech_inertia_part *parts, size_t n,
                                      const struct mech_vec3 *origin,
                                      const struct mech_budget *budget, struct mech_inertia *out,
                                      struct mech_error *err);

/* Principal moments (ascending) and axes of a symmetric tensor `t` (t is
 * symmetrised first, (t + t^T)/2).
 * Solved with GSL's gsl_eigen_symmv on the tensor scaled by a power of two;
 * moments right to about 1e-15 of the largest (measured: 2e-16 for the notes'
 * cube about a corner; eigen-residuals |I e - l e| <= 1.5e-15 of the largest).
 * Axis signs, deterministic: in axes row 0 and row 1 the component of largest
 * magnitude (the first one within 1e-12 relative of the largest, on ties) is
 * positive; row 2 = row 0 x row 1, so the set is right-handed.
 * Degenerate subspaces (see MECH_INERTIA_DEGENERATE_RTOL) have no unique axes;
 * a canonical orthonormal basis is chosen instead: all three equal -> the scene
 * axes; a pair -> the unique axis u, and in the plane normal to u the
 * projection of the scene axis least aligned with u (smallest |u_k|, the lowest
 * k among those within 1e-12 of the smallest), then u x that; then the sign
 * rule above.
 * Returns MECH_OK; MECH_EINVAL (param "tensor") for non-finite entries;
 * MECH_ENOMEM if GSL's workspace cannot be allocated; MECH_ENUMERIC if GSL
 * fails. */
enum mech_status mech_inertia_principal(struct mech_mat3 t, struct mech_inertia_principal *out,
                                        struct mech_error *err);

/* Angular momentum L = I omega (kg m^2/s) and kinetic energy T = omega.I.omega/2
 * (J) of a rotation with angular velocity omega (rad/s, scene axes) about the
 * point the tensor I is taken about, that point being at rest (notes §2.1-2.2).
 * Either output may be NULL. MECH_EINVAL (param "omega") for a non-finite omega;
 * MECH_ENUMERIC on overflow. */
enum mech_status mech_inertia_spin(struct mech_mat3 tensor, struct mech_vec3 omega,
                                   struct mech_vec3 *angular_momentum, double *kinetic_energy,
                                   struct mech_error *err);

#endif
