/* mech/hamiltonian/liouville.h — Liouville's theorem measured: the phase-space area
 * enclosed by a closed curve of initial conditions carried by a Hamiltonian
 * flow, and the determinant of the flow's tangent map along a reference orbit.
 *
 * What is measured (precisely):
 * - A = (1/2) sum_i oint (q_i dp_i - p_i dq_i) over the image of a closed curve
 *   (Poincaré's integral invariant, equal to -oint p.dq for a closed curve;
 *   Goldstein §9.9; Arnold,
 *   Mathematical Methods of Classical Mechanics, §44). For one degree of freedom
 *   it is the oriented area enclosed in the (q, p) plane (counter-clockwise
 *   positive); for n > 1 it is the sum of the oriented areas of the curve's
 *   projections on the (q_i, p_i) planes, which a symplectic map preserves
 *   (each projection alone is not conserved). Liouville's theorem (volume
 *   preservation, Taylor §13.7) follows from it.
 * - The curve's image is never approximated by a polygon: each edge (or arc)
 *   is split into parameter intervals, each carrying the 15 Gauss–Kronrod
 *   nodes (QUADPACK qk15) whose trajectories are integrated WITH their tangent
 *   vectors dy/ds (variational equations, same method), so the integrand
 *   (1/2) sum (q_i dp_i/ds - p_i dq_i/ds) is known exactly at each node of the
 *   image; the Kronrod sum is the area, |Kronrod - Gauss(7)| its error bound.
 *   Intervals are halved (re-integrated from t = 0) until that bound, summed,
 *   is <= tol |A0| at every sample, or max_intervals is reached (then
 *   converged = 0 and the bound is what it is). For a symplectic method the
 *   discrete map is symplectic, so the exact area of the image under the
 *   discrete map equals A0: what remains is the quadrature bound and round-off.
 * - The polygon's vertex images with the shoelace formula (compensated sums,
 *   mech/base/compensated.h), for comparison: their polygon is not the image of the
 *   polygon once the edges bend.
 * - A CLOUD of N >= d + 1 points (d = 2 dof) is measured by its covariance
 *   volume sqrt(det C) (C the d x d covariance of the points; it is conserved
 *   exactly when the flow is linear and volume-preserving, since C -> A C A^T),
 *   and, when N = d + 1, by the volume |det(x_i - x_0)| / d! of the simplex of
 *   its images. Neither is the volume of the image region under a nonlinear
 *   flow: for a small cloud they differ from it at O(size / flow scale); the
 *   exact statement of Liouville's theorem is det Phi = 1, reported along the
 *   reference orbit (the cloud's mean). Non-symplectic methods change both.
 * - Along a reference orbit, the full tangent map Phi = dy(t)/dy(0)
 *   (variational equations with the same method): det Phi (Liouville: 1) and
 *   the symplecticity defect max |Phi^T J Phi - J|.
 *
 * All functions are reentrant; nothing global is written.
 */
#ifndef MECH_LIOUVILLE_H
#define MECH_LIOUVILLE_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/hamiltonian/hamiltonian.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"

enum mech_liouville_shape {
    MECH_LIOUVILLE_POLYGON = 0, /* vertices, straight edges, closed (last joins first) */
    MECH_LIOUVILLE_ELLIPSE,     /* y(s) = c + u cos(2 pi s) + w sin(2 pi s), s in [0, 1) */
    MECH_LIOUVILLE_CLOUD        /* n_vertices >= dim + 1 points (vertices): see below */
};

struct mech_liouville_problem {
    const struct mech_ham_system *sys;
    const struct mech_integrator *method;
    struct mech_ode_options opt;
    double t_end;             /* s, > 0 */
    size_t n_samples;         /* >= 2: t_i = t_end i / (n_samples - 1) */
    enum mech_liouville_shape shape;
    size_t n_vertices;        /* polygon: >= 3; cloud: >= dim + 1 points */
    const double *vertices;   /* polygon, cloud: [n_vertices * dim] (q, p) rows; borrowed */
    const double *center;     /* ellipse: [dim] */
    const double *axis_u;     /* ellipse: [dim] */
    const double *axis_w;     /* ellipse: [dim] */
    const double *reference;  /* [dim] start of the reference orbit; NULL: the vertex mean / centre */
    double tol;               /* relative area tolerance of the quadrature, in [1e-15, 1e-2] */
    size_t max_intervals;     /* refinement cap, >= the initial count (edges; ellipse: 8) */
};

/* Caller-owned arrays of n_samples values each (any may be NULL except t and area). */
struct mech_liouville_result {
    double *t;
    double *area;             /* A(t), quadrature on the image curve; cloud: sqrt(det C) */
    double *area_bound;       /* summed |Kronrod - Gauss| at t */
    double *vertex_area;      /* polygon: shoelace of the vertex images (NaN for an ellipse);
                                 cloud: the simplex volume when N = dim + 1, else NaN */
    double *det;              /* det Phi(t) along the reference orbit */
    double *symplectic_defect;/* max |Phi^T J Phi - J| at t */
    double *reference_y;      /* [n_samples * dim] the reference orbit, or NULL */
    size_t n_samples;
    double area0;             /* exact initial area: shoelace of the vertices (exact for straight
                                 edges), or pi * omega(u, w) for the ellipse; cloud: sqrt(det C0) */
    double max_rel_area_drift;   /* max_t |A(t) - area0| / |area0| */
    double max_det_drift;        /* max_t |det - 1| */
    double max_symplectic_defect;
    double max_area_bound_rel;   /* max_t area_bound / |area0| */
    int converged;               /* 1: the bound met tol at every sample */
    size_t n_intervals;
    long trajectories;           /* node trajectories integrated (refinement included) */
    int second_order;
    struct mech_ode_stats stats; /* summed over every integration */
};

/* Run it. Statuses: MECH_OK; MECH_EINVAL (NULLs, n_samples < 2, fewer than 3
 * vertices, tol or max_intervals out of range: params "curve", "tol",
 * "max_intervals"; a second-order method for a non-separable system:
 * "integrator/method"); MECH_EDOMAIN (parameters; a vertex or the reference
 * outside the domain, params "curve/vertices/<i>", "reference"; a curve of zero
 * enclosed area or a cloud that spans fewer than dim dimensions: "curve"); MECH_ENUMERIC; MECH_EBUDGET / EDEADLINE /
 * ECANCELLED (max_steps counts the steps of all integrations together);
 * MECH_ENOMEM. */
enum mech_status mech_liouville_run(const struct mech_liouville_problem *p,
                                    const struct mech_budget *budget,
                                    struct mech_liouville_result *res, struct mech_error *err);

/* Oriented area (1/2) sum_i sum_j (q_i,j p_i,j+1 - q_i,j+1 p_i,j) of a closed
 * polygon of n points in 2 dof dimensions, compensated (Neumaier sums of
 * error-free products). Cannot fail. */
double mech_liouville_shoelace(const double *pts, size_t n, size_t dof);

/* Determinant of the d x d row-major matrix a (d <= 6) by Gaussian elimination
 * with partial pivoting (a is not modified). Cannot fail. */
double mech_liouville_det(const double *a, size_t d);

#endif
