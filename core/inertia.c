/* inertia.c — inertia tensor of a body made of simple parts, principal axes,
 * angular momentum and kinetic energy (notes ch. 2). See mech/inertia.h. */
#include "mech/inertia.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include "mech/rotation.h"

/* Below this the tensor's smaller entries would be subnormal: 2^-968 = DBL_MIN * 2^54. */
#define TINY_TENSOR 0x1p-968

static int mat3_max_abs(struct mech_mat3 m, double *out)
{
    double s = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (!isfinite(m.a[i][j])) return 0;
            s = fmax(s, fabs(m.a[i][j]));
        }
    *out = s;
    return 1;
}

static int dim_ok(double d)
{
    return isfinite(d) && d > 0;
}

/* Point-mass term m (r^2 delta_ij - r_i r_j) added to t (notes §2.2), with the
 * diagonal written as m (y^2 + z^2) etc. so that nothing cancels. */
static void add_point(struct mech_mat3 *t, double m, struct mech_vec3 r)
{
    double x2 = r.x * r.x, y2 = r.y * r.y, z2 = r.z * r.z;
    t->a[0][0] += m * (y2 + z2);
    t->a[1][1] += m * (x2 + z2);
    t->a[2][2] += m * (x2 + y2);
    double xy = -m * r.x * r.y, xz = -m * r.x * r.z, yz = -m * r.y * r.z;
    t->a[0][1] += xy;
    t->a[1][0] += xy;
    t->a[0][2] += xz;
    t->a[2][0] += xz;
    t->a[1][2] += yz;
    t->a[2][1] += yz;
}

enum mech_status mech_inertia_part_tensor(const struct mech_inertia_part *p, struct mech_mat3 *out,
                                          struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no part given");
    if (!(isfinite(p->mass) && p->mass > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "must be finite and > 0, got %.17g",
                              p->mass);
    if (!mech_vec3_isfinite(p->position))
        return mech_error_set(err, MECH_EINVAL, "position", "must be finite");
    double m = p->mass;
    double d[3] = {0, 0, 0}; /* principal moments in body axes (notes §2.2; standard tables) */
    int isotropic = 0, axial = 0;
    switch (p->shape) {
    case MECH_SHAPE_POINT:
        *out = (struct mech_mat3){{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
        return MECH_OK;
    case MECH_SHAPE_ROD: /* thin rod along z: M L^2/12 about any perpendicular axis */
        if (!dim_ok(p->dim[0]))
            return mech_error_set(err, MECH_EINVAL, "length", "must be finite and > 0");
        d[0] = d[1] = m * p->dim[0] * p->dim[0] / 12.0;
        d[2] = 0;
        axial = 1;
        break;
    case MECH_SHAPE_BOX: { /* M (b^2 + c^2)/12, M (a^2 + c^2)/12, M (a^2 + b^2)/12 */
        for (int i = 0; i < 3; i++)
            if (!dim_ok(p->dim[i]))
                return mech_error_set(err, MECH_EINVAL, "size", "edges must be finite and > 0");
        double a2 = p->dim[0] * p->dim[0], b2 = p->dim[1] * p->dim[1], c2 = p->dim[2] * p->dim[2];
        d[0] = m * (b2 + c2) / 12.0;
        d[1] = m * (a2 + c2) / 12.0;
        d[2] = m * (a2 + b2) / 12.0;
        break;
    }
    case MECH_SHAPE_SPHERE: /* solid: 2/5 M R^2 */
        if (!dim_ok(p->dim[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        d[0] = d[1] = d[2] = 0.4 * m * p->dim[0] * p->dim[0];
        isotropic = 1;
        break;
    case MECH_SHAPE_SHELL: /* thin spherical shell: 2/3 M R^2 */
        if (!dim_ok(p->dim[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        d[0] = d[1] = d[2] = 2.0 * m * p->dim[0] * p->dim[0] / 3.0;
        isotropic = 1;
        break;
    case MECH_SHAPE_CYLINDER: /* M (3 R^2 + h^2)/12 across, M R^2/2 about the axis */
        if (!dim_ok(p->dim[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        if (!dim_ok(p->dim[1]))
            return mech_error_set(err, MECH_EINVAL, "height", "must be finite and > 0");
        d[0] = d[1] = m * (3.0 * p->dim[0] * p->dim[0] + p->dim[1] * p->dim[1]) / 12.0;
        d[2] = 0.5 * m * p->dim[0] * p->dim[0];
        axial = 1;
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, "shape", "unknown shape %d", (int)p->shape);
    }
    struct mech_mat3 t;
    if (isotropic) {
        t = (struct mech_mat3){{{d[0], 0, 0}, {0, d[0], 0}, {0, 0, d[0]}}};
    } else {
        struct mech_mat3 r;
        struct mech_error e2;
        mech_error_clear(&e2);
        if (mech_rotation_from_matrix(p->orientation, &r, &e2) != MECH_OK)
            return mech_error_set(err, MECH_EINVAL, "orientation", "%s", e2.text);
        if (axial) {
            /* I = d_perp 1 + (d_axis - d_perp) z z^T with z = body z in scene
             * axes (row 2 of R): exact trace, exactly symmetric. */
            double zv[3] = {r.a[2][0], r.a[2][1], r.a[2][2]};
            double k = d[2] - d[0];
            for (int i = 0; i < 3; i++)
                for (int j = i; j < 3; j++)
                    t.a[i][j] = t.a[j][i] = k * zv[i] * zv[j] + (i == j ? d[0] : 0.0);
        } else {
            /* I_scene = R^T diag(d) R: (I)_ij = sum_k R_ki d_k R_kj (notes §2.2). */
            for (int i = 0; i < 3; i++)
                for (int j = i; j < 3; j++) /* upper triangle, mirrored: exactly symmetric */
                    t.a[i][j] = t.a[j][i] = r.a[0][i] * d[0] * r.a[0][j] +
                                            r.a[1][i] * d[1] * r.a[1][j] +
                                            r.a[2][i] * d[2] * r.a[2][j];
        }
    }
    if (!mech_mat3_isfinite(t))
        return mech_error_set(err, MECH_ENUMERIC, "mass", "inertia of the part overflows");
    *out = t;
    return MECH_OK;
}

/* Largest length that sets the part's own scale (0 for a point). */
static double part_size(const struct mech_inertia_part *p)
{
    switch (p->shape) {
    case MECH_SHAPE_BOX:
        return fmax(p->dim[0], fmax(p->dim[1], p->dim[2]));
    case MECH_SHAPE_CYLINDER:
        return fmax(p->dim[0], p->dim[1]);
    case MECH_SHAPE_POINT:
        return 0;
    default:
        return p->dim[0];
    }
}

static enum mech_status part_error(struct mech_error *err, size_t i, const struct mech_error *e)
{
    char param[160];
    snprintf(param, sizeof param, "bodies/%zu%s%s", i, e->param[0] ? "/" : "", e->param);
    return mech_error_set(err, e->code, param, "%s", e->text);
}

enum mech_status mech_inertia_compute(const struct mech_inertia_part *parts, size_t n,
                                      const struct mech_vec3 *origin,
                                      const struct mech_budget *budget, struct mech_inertia *out,
                                      struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!parts || n == 0)
        return mech_error_set(err, MECH_EINVAL, "bodies", "at least one part is required");
    if (origin && !mech_vec3_isfinite(*origin))
        return mech_error_set(err, MECH_EINVAL, "origin", "must be finite");
    enum mech_status st = mech_budget_check(budget, 0, 1, err);
    if (st != MECH_OK) return st;

    /* Pass 1: validate, total mass and first moment relative to p0 = the first
     * part's position, so far-away bodies do not lose digits. */
    struct mech_vec3 p0 = parts[0].position;
    double mass = 0;
    struct mech_vec3 s1 = {0, 0, 0};
    int sized = 0;
    for (size_t i = 0; i < n; i++) {
        if ((st = mech_budget_check(budget, (long)i + 1, 0, err)) != MECH_OK) return st;
        const struct mech_inertia_part *p = &parts[i];
        struct mech_error e;
        mech_error_clear(&e);
        struct mech_mat3 ti;
        if (mech_inertia_part_tensor(p, &ti, &e) != MECH_OK) return part_error(err, i, &e);
        if (part_size(p) > 0) sized = 1;
        mass += p->mass;
        s1 = mech_vec3_add(s1, mech_vec3_scale(mech_vec3_sub(p->position, p0), p->mass));
    }
    struct mech_vec3 c = mech_vec3_scale(s1, 1.0 / mass);
    /* Refine once: the residual first moment about p0 + c (removes the rounding
     * of the first pass when offsets are large compared with the body). */
    struct mech_vec3 s2 = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        if ((st = mech_budget_check(budget, (long)(n + i) + 1, 0, err)) != MECH_OK) return st;
        struct mech_vec3 r = mech_vec3_sub(mech_vec3_sub(parts[i].position, p0), c);
        s2 = mech_vec3_add(s2, mech_vec3_scale(r, parts[i].mass));
    }
    c = mech_vec3_add(c, mech_vec3_scale(s2, 1.0 / mass));
    struct mech_vec3 com = mech_vec3_add(p0, c);

    /* Pass 2: tensor about the centre of mass in centred coordinates r = (p - p0) - c. */
    struct mech_mat3 tcm = {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
    for (size_t i = 0; i < n; i++) {
        if ((st = mech_budget_check(budget, (long)(2 * n + i) + 1, 0, err)) != MECH_OK) return st;
        const struct mech_inertia_part *p = &parts[i];
        struct mech_mat3 ti;
        struct mech_error e;
        mech_error_clear(&e);
        if (mech_inertia_part_tensor(p, &ti, &e) != MECH_OK) return part_error(err, i, &e);
        struct mech_vec3 r = mech_vec3_sub(mech_vec3_sub(p->position, p0), c);
        if (mech_vec3_norm(r) > 0) sized = 1;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                tcm.a[a][b] += ti.a[a][b];
        add_point(&tcm, p->mass, r); /* parallel axis theorem, notes §2.3 */
    }

    /* Parallel-axis shift to the origin: I_O = I_cm + M (a^2 delta - a a^T), a = com - origin. */
    struct mech_vec3 o = origin ? *origin : com;
    struct mech_mat3 t = tcm;
    if (origin) add_point(&t, mass, mech_vec3_sub(com, o));

    double big;
    if (!isfinite(mass) || !mech_vec3_isfinite(com) || !mat3_max_abs(tcm, &big) ||
        !mat3_max_abs(t, &big))
        return mech_error_set(err, MECH_ENUMERIC, "bodies",
                              "the mass, centre of mass or inertia tensor overflows");
    double bigcm = 0;
    mat3_max_abs(tcm, &bigcm);
    if ((sized && bigcm < TINY_TENSOR) || (big > 0 && big < TINY_TENSOR))
        return mech_error_set(err, MECH_ENUMERIC, "bodies",
                              "the inertia tensor underflows double precision; "
                              "choose larger units");

    struct mech_inertia res;
    res.mass = mass;
    res.center_of_mass = com;
    res.origin = o;
    res.tensor = t;
    res.tensor_cm = tcm;
    if ((st = mech_inertia_principal(t, &res.principal, err)) != MECH_OK) return st;
    *out = res;
    return MECH_OK;
}

/* Make the component of largest magnitude positive (the first within 1e-12
 * relative of the largest, so near-ties resolve the same way every time). */
static struct mech_vec3 sign_fix(struct mech_vec3 v)
{
    double c[3] = {v.x, v.y, v.z};
    double mx = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
    for (int i = 0; i < 3; i++)
        if (fabs(c[i]) >= mx * (1 - 1e-12)) return c[i] < 0 ? mech_vec3_scale(v, -1.0) : v;
    return v;
}

static struct mech_vec3 normalise(struct mech_vec3 v)
{
    return mech_vec3_scale(v, 1.0 / mech_vec3_norm(v));
}

/* Orthonormal pair spanning the plane normal to the unit vector u: the
 * projection of the first scene axis least aligned with u (ties within 1e-12
 * go to the lowest index), then u x that. */
static void plane_basis(struct mech_vec3 u, struct mech_vec3 *v, struct mech_vec3 *w)
{
    double uc[3] = {u.x, u.y, u.z};
    double mn = fmin(fabs(uc[0]), fmin(fabs(uc[1]), fabs(uc[2])));
    int k = 0; /* the first within 1e-12 of the smallest, so round-off cannot flip ties */
    while (k < 2 && fabs(uc[k]) > mn + 1e-12)
        k++;
    struct mech_vec3 e = mech_vec3_make(k == 0, k == 1, k == 2);
    *v = normalise(mech_vec3_sub(e, mech_vec3_scale(u, uc[k])));
    *w = mech_vec3_cross(u, *v);
}

enum mech_status mech_inertia_principal(struct mech_mat3 t, struct mech_inertia_principal *out,
                                        struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, "tensor", "no output given");
    double big;
    if (!mat3_max_abs(t, &big))
        return mech_error_set(err, MECH_EINVAL, "tensor", "entries must be finite");
    struct mech_inertia_principal res;
    if (big == 0) {
        res.moments[0] = res.moments[1] = res.moments[2] = 0;
        res.axes = mech_mat3_identity();
        res.degenerate = 1;
        *out = res;
        return MECH_OK;
    }
    /* Scale by a power of two (exact) so the solver works near 1. */
    int ex;
    frexp(big, &ex);
    double a[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            a[3 * i + j] = ldexp(0.5 * (t.a[i][j] + t.a[j][i]), -ex);
    double evalv[3], evecv[9];
    gsl_matrix_view am = gsl_matrix_view_array(a, 3, 3);
    gsl_vector_view ev = gsl_vector_view_array(evalv, 3);
    gsl_matrix_view evm = gsl_matrix_view_array(evecv, 3, 3);
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc(3);
    if (!w) return mech_error_set(err, MECH_ENOMEM, NULL, "eigen-solver workspace");
    int gs = gsl_eigen_symmv(&am.matrix, &ev.vector, &evm.matrix, w);
    gsl_eigen_symmv_free(w);
    if (gs != GSL_SUCCESS)
        return mech_error_set(err, MECH_ENUMERIC, "tensor", "eigen-solver failed: %s",
                              gsl_strerror(gs));
    gs = gsl_eigen_symmv_sort(&ev.vector, &evm.matrix, GSL_EIGEN_SORT_VAL_ASC);
    if (gs != GSL_SUCCESS)
        return mech_error_set(err, MECH_ENUMERIC, "tensor", "eigen-sort failed: %s",
                              gsl_strerror(gs));
    struct mech_vec3 e[3];
    for (int k = 0; k < 3; k++) {
        res.moments[k] = ldexp(evalv[k], ex);
        e[k] = mech_vec3_make(evecv[0 * 3 + k], evecv[1 * 3 + k], evecv[2 * 3 + k]);
    }
    double top = fmax(fabs(res.moments[0]), fabs(res.moments[2]));
    double tol = MECH_INERTIA_DEGENERATE_RTOL * top;
    int d01 = res.moments[1] - res.moments[0] <= tol;
    int d12 = res.moments[2] - res.moments[1] <= tol;
    res.degenerate = d01 || d12;
    if (d01 && d12) {
        e[0] = mech_vec3_make(1, 0, 0);
        e[1] = mech_vec3_make(0, 1, 0);
    } else if (d01) {
        plane_basis(normalise(e[2]), &e[0], &e[1]);
    } else if (d12) {
        e[0] = sign_fix(normalise(e[0]));
        plane_basis(e[0], &e[1], &e[2]);
    }
    /* Sign rule, Gram-Schmidt, right-handed completion. */
    e[0] = sign_fix(normalise(e[0]));
    e[1] = mech_vec3_sub(e[1], mech_vec3_scale(e[0], mech_vec3_dot(e[0], e[1])));
    e[1] = sign_fix(normalise(e[1]));
    e[2] = normalise(mech_vec3_cross(e[0], e[1]));
    for (int k = 0; k < 3; k++) {
        res.axes.a[k][0] = e[k].x;
        res.axes.a[k][1] = e[k].y;
        res.axes.a[k][2] = e[k].z;
    }
    if (!mech_mat3_isfinite(res.axes) || !isfinite(res.moments[0]) || !isfinite(res.moments[1]) ||
        !isfinite(res.moments[2]))
        return mech_error_set(err, MECH_ENUMERIC, "tensor", "principal axes are not finite");
    *out = res;
    return MECH_OK;
}

enum mech_status mech_inertia_spin(struct mech_mat3 tensor, struct mech_vec3 omega,
                                   struct mech_vec3 *angular_momentum, double *kinetic_energy,
                                   struct mech_error *err)
{
    if (!mech_vec3_isfinite(omega))
        return mech_error_set(err, MECH_EINVAL, "omega", "must be finite");
    if (!mech_mat3_isfinite(tensor))
        return mech_error_set(err, MECH_EINVAL, "tensor", "entries must be finite");
    /* notes §2.2: L_i = I_ij w_j, T = w_i I_ij w_j / 2. */
    struct mech_vec3 l = mech_mat3_mul_vec(tensor, omega);
    double ke = 0.5 * mech_vec3_dot(omega, l);
    if (!mech_vec3_isfinite(l) || !isfinite(ke))
        return mech_error_set(err, MECH_ENUMERIC, "omega",
                              "angular momentum or kinetic energy overflows");
    if (angular_momentum) *angular_momentum = l;
    if (kinetic_energy) *kinetic_energy = ke;
    return MECH_OK;
}
