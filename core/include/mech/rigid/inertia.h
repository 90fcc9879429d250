/* mech/rigid/inertia.h — inertia tensor of a rigid body made of simple parts, its
 * principal moments and axes, and the angular momentum and kinetic energy of a
 * rotation (notes ch. 2: §2.1-2.5).
 *
 * Units: SI (kg, m, kg m^2, rad/s, J). Tensors are in scene axes.
 * Precision (docs/design.md, "Precision by construction"): the centre of mass
 * is found relative to the first part's centre of mass and refined once; the
 * tensor about it is accumulated in centred coordinates, then moved to the
 * requested origin with the parallel axis theorem (notes §2.3), so a small
 * body far from the scene origin keeps full relative precision. Reentrant; allocations: a scratch array of n part
 * results per mech_inertia_compute*() call, the mesh edge list (mech/rigid/mesh.h) and GSL's 3x3
 * eigen-workspace inside mech_inertia_principal().
 */
#ifndef MECH_INERTIA_H
#define MECH_INERTIA_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/rigid/mesh.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Shapes. "position" is each shape's reference point, in scene axes; the body
 * axes are the rows of `orientation`. Unless said otherwise the reference point
 * is the centre of mass. Moments below are about the centre of mass, body axes
 * (standard tables; notes §2.2-2.4 for the method).
 * Append only: the numbers are not part of any external interface, but keep
 * them stable. */
enum mech_inertia_shape {
    MECH_SHAPE_POINT = 0,      /* point mass */
    MECH_SHAPE_ROD = 1,        /* thin rod, dim[0] = length, along body z */
    MECH_SHAPE_BOX = 2,        /* solid box, dim = edges [a, b, c] along body x, y, z */
    MECH_SHAPE_SPHERE = 3,     /* solid sphere, dim[0] = radius */
    MECH_SHAPE_SHELL = 4,      /* thin spherical shell, dim[0] = radius */
    MECH_SHAPE_CYLINDER = 5,   /* solid cylinder, dim[0] = radius, dim[1] = height, axis body z */
    MECH_SHAPE_CONE = 6,       /* solid right circular cone, dim[0] = base radius R, dim[1] =
                                  height h; position = the APEX, the cone opens along body +z;
                                  centre of mass 3h/4 from the apex; I_zz = 3MR^2/10,
                                  I_xx = I_yy = 3M(4R^2 + h^2)/80 */
    MECH_SHAPE_HEMISPHERE = 7, /* solid half ball, dim[0] = R; position = centre of the flat
                                  face, dome along body +z; centre of mass 3R/8 up;
                                  I_zz = 2MR^2/5, I_xx = I_yy = 83MR^2/320 */
    MECH_SHAPE_TUBE = 8,       /* thick-walled cylinder, dim[0] = inner radius a (>= 0),
                                  dim[1] = outer radius b > a, dim[2] = height h, axis body z;
                                  I_zz = M(a^2 + b^2)/2, I_xx = M(3(a^2 + b^2) + h^2)/12 */
    MECH_SHAPE_DISC = 9,       /* thin disc in the body xy plane, dim[0] = R;
                                  I_zz = MR^2/2, I_xx = I_yy = MR^2/4 */
    MECH_SHAPE_RING = 10,      /* thin hoop in the body xy plane, dim[0] = R;
                                  I_zz = MR^2, I_xx = I_yy = MR^2/2 */
    MECH_SHAPE_PLATE = 11,     /* thin rectangle in the body xy plane, dim[0] = a (along x),
                                  dim[1] = b (along y); I_xx = Mb^2/12, I_yy = Ma^2/12,
                                  I_zz = M(a^2 + b^2)/12 */
    MECH_SHAPE_TRIANGLE = 12,  /* thin triangular plate, corners `vertices` in SCENE axes;
                                  position and orientation ignored; centroid (A+B+C)/3,
                                  covariance M/12 sum_k e_k e_k^T with e_k = corner - centroid */
    MECH_SHAPE_ELLIPSOID = 13, /* solid ellipsoid, dim = semi-axes [a, b, c] along body x, y, z;
                                  I_xx = M(b^2 + c^2)/5, I_yy = M(a^2 + c^2)/5,
                                  I_zz = M(a^2 + b^2)/5 */
    MECH_SHAPE_TORUS = 14,     /* solid ring torus, dim[0] = major radius R, dim[1] = minor
                                  radius r < R, axis body z; I_zz = M(R^2 + 3r^2/4),
                                  I_xx = I_yy = M(R^2/2 + 5r^2/8) */
    MECH_SHAPE_MESH = 15,      /* closed triangle mesh of uniform density (mech/rigid/mesh.h),
                                  `mesh` vertices in BODY coordinates: scene point =
                                  position + R^T v (so position [0,0,0] and no rotation
                                  means the vertices are scene coordinates) */
    MECH_SHAPE_TENSOR = 16,    /* a part known only by its mass, its own `tensor` about its
                                  centre of mass (body axes: scene tensor R^T T R; the scene
                                  axes when orientation is the identity) and its centre of
                                  mass `position` (the parallel-axis theorem on a tensor the
                                  user has, notes §2.3); T must be symmetric (1e-12 of its
                                  largest entry) and a tensor some mass distribution has
                                  (principal moments >= 0, each at most the sum of the
                                  other two, within 1e-9 of the trace) */
    MECH_SHAPE_COUNT
};

/* One part of a body. Zero-initialise (memset) and fill what the shape uses. */
struct mech_inertia_part {
    enum mech_inertia_shape shape;
    double mass;                  /* kg, finite, > 0: for a hole, the mass its volume
                                     would have had (density x volume, the caller's job) */
    struct mech_vec3 position;    /* m, the part's reference point in scene axes (see the
                                     shapes above; the centre unless said otherwise) */
    struct mech_mat3 orientation; /* passive R (mech/rotation/rotation.h): scene -> body
                                     components, rows = body axes in scene axes;
                                     must be a rotation; ignored for point, sphere, shell
                                     and triangle */
    double dim[3];                /* m, finite, > 0 where the shape uses it (see above) */
    int hole;                     /* nonzero: the part is removed material; its mass, first
                                     moment and tensor enter every sum with a minus sign */
    struct mech_vec3 vertices[3]; /* m, triangle corners, scene axes (triangle only) */
    struct mech_mesh mesh;        /* mesh only: borrowed vertices and faces */
    struct mech_mat3 tensor;      /* kg m^2, tensor part only: about its centre of mass,
                                     body axes */
};

/* A part's own contribution, for auditing the sums. */
struct mech_inertia_part_props {
    double mass;                     /* kg, signed: negative for a hole */
    struct mech_vec3 center_of_mass; /* m, scene axes: where the part's own mass sits */
    struct mech_mat3 tensor;         /* kg m^2, about center_of_mass, scene axes;
                                        negative (minus the material's) for a hole */
    double volume;                   /* m^3 for a mesh part, 0 otherwise */
    int inverted;                    /* mesh part whose faces pointed inwards (accepted) */
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

/* Tensor of one part's material about its own centre of mass, in scene axes:
 * I_scene = R^T I_body R (notes §2.2, "Transforming the Inertia Tensor", for
 * the passive R). Body tensors: see enum mech_inertia_shape (point 0; rod
 * M L^2/12 (x, y), 0 (z); box M(b^2+c^2)/12, M(a^2+c^2)/12, M(a^2+b^2)/12;
 * sphere 2/5 M R^2; shell 2/3 M R^2; cylinder M(3R^2+h^2)/12 (x, y), M R^2/2
 * (z); and the shapes added since). The hole flag is ignored here (the
 * material's own, positive tensor). Mesh parts need a budget: use
 * mech_inertia_part_properties (MECH_EINVAL "shape" here).
 * Returns MECH_OK; MECH_EDOMAIN with param "mass" for mass <= 0 or non-finite,
 * "inner_radius" for a tube with inner >= outer radius, "minor_radius" for a
 * torus with r >= R (not a ring torus); MECH_EINVAL with param "position",
 * "length", "size", "radius", "height", "inner_radius", "outer_radius",
 * "semi_axes", "major_radius", "minor_radius", "tensor" (a tensor part's tensor not
 * finite or not symmetric; MECH_EDOMAIN "tensor" when no mass distribution has
 * it), "vertices" (a triangle's corners
 * not finite, or collinear / zero area: |AB x AC| <= 1e-14 |AB| |AC|) or
 * "orientation" for a non-finite position, a dimension that is not finite and
 * > 0, or an orientation that is not a rotation within 1e-9; MECH_ENUMERIC if
 * the result overflows. out must not be NULL. */
enum mech_status mech_inertia_part_tensor(const struct mech_inertia_part *part,
                                          struct mech_mat3 *out, struct mech_error *err);

/* Mass (signed), centre of mass and tensor about it (signed) of one part,
 * every shape including meshes (mech_mesh_properties: three budget steps per
 * face, counted on *steps as there; steps may be NULL). Errors as
 * mech_inertia_part_tensor, plus mech_mesh_properties' params "vertices",
 * "faces", "faces/<k>" for a mesh, MECH_ENOMEM and the budget's statuses. */
enum mech_status mech_inertia_part_properties(const struct mech_inertia_part *part,
                                              const struct mech_budget *budget, long *steps,
                                              struct mech_inertia_part_props *out,
                                              struct mech_error *err);

/* Mass, centre of mass, tensors about the centre of mass and about `origin`
 * (NULL: the centre of mass), and the principal moments/axes of the latter,
 * for parts[0..n-1] (1 <= n; parts borrowed, read only). Holes count with
 * negative mass; the total mass must stay > 0 (more than 1e-12 of the sum of
 * the parts' |mass|, so that rounding cannot decide its sign). Holes are not
 * checked to lie inside material beyond the positivity test below. Budget: one step per part per
 * pass (three passes) plus mech_mesh_properties' steps for mesh parts, checked
 * with mech_budget_check (budget required). If part_out is not NULL it must
 * hold n entries and receives each part's own contribution (so that
 * tensor_cm = sum_i [part_out[i].tensor + m_i (d_i^2 1 - d_i d_i^T)] with
 * d_i = part_out[i].center_of_mass - center_of_mass, m_i signed); it is
 * written only on success.
 * Returns MECH_OK; MECH_EINVAL/MECH_EDOMAIN with param "bodies/<i>/<field>"
 * (as mech_inertia_part_properties) for part i, param "bodies" when n == 0,
 * MECH_EDOMAIN "bodies" when the holes leave a total mass <= 0 (as above) or a tensor
 * about the centre of mass that no positive mass distribution has (a principal
 * moment larger than the sum of the other two by more than 1e-9 of the trace:
 * a hole sticking out of the material), "origin" for a non-finite origin;
 * MECH_EBUDGET/EDEADLINE/ECANCELLED from the budget; MECH_ENUMERIC if a result
 * is not finite or the tensor's largest entry is so small (< 2^-968) that its
 * digits would be lost to underflow; MECH_ENOMEM from the scratch array or the
 * eigen-solver. *out is written only on success. */
enum mech_status mech_inertia_compute_parts(const struct mech_inertia_part *parts, size_t n,
                                            const struct mech_vec3 *origin,
                                            const struct mech_budget *budget,
                                            struct mech_inertia *out,
                                            struct mech_inertia_part_props *part_out,
                                            struct mech_error *err);

/* mech_inertia_compute_parts without the per-part output. */
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
