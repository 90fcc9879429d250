/* mech/rigid/mesh.h — volume, centroid and second moments of a solid bounded by a
 * closed triangle mesh of uniform density (used by mech/rigid/inertia.h for the
 * "mesh" part).
 *
 * Method: the divergence theorem, as a sum of signed tetrahedra (reference
 * point, a, b, c) over the faces (a, b, c): volume a.(b x c)/6, first moment
 * V (a + b + c)/4 and second moment V/20 (a a^T + b b^T + c c^T + s s^T),
 * s = a + b + c (F. Tonon, "Explicit exact formulas for the 3-D tetrahedron
 * inertia tensor in terms of its vertex coordinates", J. Math. Stat. 1 (2005)
 * 8-11; D. Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools,
 * 2002). Precision: every vertex is first taken relative to the centre of the
 * bounding box of the referenced vertices (an exact subtraction for a body far
 * from the origin: Sterbenz), volume and centroid are summed there, then the
 * second moments are summed in a second pass relative to the centroid itself,
 * so a mesh 1e6 m from the origin keeps the digits of a mesh at the origin.
 *
 * Validation: every index in range, no face repeating a vertex, and every
 * undirected edge shared by exactly two faces that traverse it in opposite
 * directions (closed, edge-manifold, consistently oriented). Faces may be
 * oriented outwards (counter-clockwise seen from outside, the usual
 * convention) or all inwards: an inside-out mesh negates every volume integral
 * together, so it is accepted and reported with `inverted` = 1.
 * Reentrant; allocates one scratch array of 3 * n_faces edges per call.
 */
#ifndef MECH_MESH_H
#define MECH_MESH_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

#define MECH_MESH_MAX_VERTICES 100000
#define MECH_MESH_MAX_FACES 200000

/* A triangle mesh; both arrays borrowed, read only. */
struct mech_mesh {
    const struct mech_vec3 *vertices; /* m, n_vertices points */
    size_t n_vertices;                /* 4 .. MECH_MESH_MAX_VERTICES */
    const size_t *faces;              /* 3 * n_faces vertex indices, face k = faces[3k..3k+2] */
    size_t n_faces;                   /* 4 .. MECH_MESH_MAX_FACES */
};

struct mech_mesh_properties {
    double volume;               /* m^3, > 0 */
    struct mech_vec3 centroid;   /* m, in the mesh's coordinates */
    struct mech_mat3 covariance; /* m^5: integral of (r - c)(r - c)^T dV about the centroid c */
    int inverted;                /* 1 if the faces were oriented inwards (signed volume < 0) */
};

/* Volume, centroid and second-moment (covariance) matrix of the solid bounded
 * by `mesh`. A uniform body of mass M then has the inertia tensor about its
 * centroid I = (M/V)(tr(C) 1 - C) (notes §2.2, I_ij = sum m (r^2 delta_ij - r_i r_j)).
 * Budget: three steps per face (validation, two integration passes), checked
 * with mech_budget_check against the running count *steps (in: steps already
 * spent; out: advanced; steps may be NULL for a count starting at 0); budget
 * required.
 * Returns MECH_OK; MECH_EINVAL with param
 *   "vertices"            too few / too many vertices, or a non-finite one,
 *   "faces"               too few / too many faces, an open edge (used by one
 *                         face), a non-manifold edge (used by more than two), two
 *                         faces traversing an edge the same way (inconsistent
 *                         orientation, e.g. one flipped face), or a mesh that
 *                         encloses no volume (|V| <= 1e-12 of the sum of |tetrahedra|),
 *   "faces/<k>"           face k names an index >= n_vertices or repeats a vertex
 * (the text says which face and edge); MECH_EBUDGET/EDEADLINE/ECANCELLED from
 * the budget; MECH_ENOMEM for the edge scratch array; MECH_ENUMERIC if a result
 * overflows. *out is written only on success. Thread-safe. */
enum mech_status mech_mesh_properties(const struct mech_mesh *mesh,
                                      const struct mech_budget *budget, long *steps,
                                      struct mech_mesh_properties *out, struct mech_error *err);

#endif
