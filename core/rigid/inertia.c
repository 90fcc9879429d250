/* inertia.c — inertia tensor of a body made of simple parts, principal axes,
 * angular momentum and kinetic energy (notes ch. 2). See mech/rigid/inertia.h. */
#include "mech/rigid/inertia.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include "mech/rotation/rotation.h"

/* Below this the tensor's largest entry is itself subnormal and loses relative
 * precision: DBL_MIN. (Smaller entries may be subnormal above it: their
 * absolute error 2^-1074 is still below round-off of the largest. Point masses
 * of 1e-300 kg a metre apart, 2e-300 kg m^2, are answered.) */
#define TINY_TENSOR 0x1p-1022

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

/* Body-frame description of a shaped part (not point, triangle or mesh):
 * principal moments d[] about the centre of mass in body axes, the centre of
 * mass at position + cz * (body z), and the form of the tensor:
 * 0 general (R^T diag(d) R), 1 axial (d[0] = d[1], symmetry axis body z),
 * 2 isotropic (orientation ignored). Sources: standard tables (e.g. Goldstein,
 * Classical Mechanics, and the notes §2.2-2.4 for the method); the cone,
 * hemisphere and torus entries are derived in tests/core/rigid/test_inertia.c's
 * comments and checked there against an independent mesh integration. */
static enum mech_status body_form(const struct mech_inertia_part *p, double d[3], double *cz,
                                  int *form, struct mech_error *err)
{
    const double m = p->mass;
    const double *x = p->dim;
    *cz = 0;
    *form = 0;
    switch (p->shape) {
    case MECH_SHAPE_ROD: /* thin rod along z: M L^2/12 about any perpendicular axis */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "length", "must be finite and > 0");
        d[0] = d[1] = m * x[0] * x[0] / 12.0;
        d[2] = 0;
        *form = 1;
        return MECH_OK;
    case MECH_SHAPE_BOX: { /* M (b^2 + c^2)/12, M (a^2 + c^2)/12, M (a^2 + b^2)/12 */
        for (int i = 0; i < 3; i++)
            if (!dim_ok(x[i]))
                return mech_error_set(err, MECH_EINVAL, "size", "edges must be finite and > 0");
        double a2 = x[0] * x[0], b2 = x[1] * x[1], c2 = x[2] * x[2];
        d[0] = m * (b2 + c2) / 12.0;
        d[1] = m * (a2 + c2) / 12.0;
        d[2] = m * (a2 + b2) / 12.0;
        return MECH_OK;
    }
    case MECH_SHAPE_SPHERE: /* solid: 2/5 M R^2 */
    case MECH_SHAPE_SHELL:  /* thin spherical shell: 2/3 M R^2 */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        d[0] = d[1] = d[2] = (p->shape == MECH_SHAPE_SPHERE ? 0.4 : 2.0 / 3.0) * m * x[0] * x[0];
        *form = 2;
        return MECH_OK;
    case MECH_SHAPE_CYLINDER: /* M (3 R^2 + h^2)/12 across, M R^2/2 about the axis */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        if (!dim_ok(x[1]))
            return mech_error_set(err, MECH_EINVAL, "height", "must be finite and > 0");
        d[0] = d[1] = m * (3.0 * x[0] * x[0] + x[1] * x[1]) / 12.0;
        d[2] = 0.5 * m * x[0] * x[0];
        *form = 1;
        return MECH_OK;
    case MECH_SHAPE_CONE:
        /* Apex at the reference point, axis +z. About the apex I_zz = 3MR^2/10,
         * I_xx = 3M(R^2/4 + h^2)/5; the centre of mass is 3h/4 up, so about it
         * I_xx = 3M(R^2/4 + h^2)/5 - 9Mh^2/16 = 3M(4R^2 + h^2)/80. */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        if (!dim_ok(x[1]))
            return mech_error_set(err, MECH_EINVAL, "height", "must be finite and > 0");
        d[0] = d[1] = 3.0 * m * (4.0 * x[0] * x[0] + x[1] * x[1]) / 80.0;
        d[2] = 0.3 * m * x[0] * x[0];
        *cz = 0.75 * x[1];
        *form = 1;
        return MECH_OK;
    case MECH_SHAPE_HEMISPHERE:
        /* Flat face centre at the reference point, dome +z. About that point every
         * axis gives 2MR^2/5 (half a ball); centre of mass 3R/8 up, so across it
         * I_xx = 2MR^2/5 - 9MR^2/64 = 83MR^2/320. */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        d[0] = d[1] = 83.0 * m * x[0] * x[0] / 320.0;
        d[2] = 0.4 * m * x[0] * x[0];
        *cz = 0.375 * x[0];
        *form = 1;
        return MECH_OK;
    case MECH_SHAPE_TUBE: { /* M(a^2 + b^2)/2 about the axis, M(3(a^2 + b^2) + h^2)/12 across */
        if (!(isfinite(x[0]) && x[0] >= 0))
            return mech_error_set(err, MECH_EINVAL, "inner_radius", "must be finite and >= 0");
        if (!dim_ok(x[1]))
            return mech_error_set(err, MECH_EINVAL, "outer_radius", "must be finite and > 0");
        if (!dim_ok(x[2]))
            return mech_error_set(err, MECH_EINVAL, "height", "must be finite and > 0");
        if (!(x[0] < x[1]))
            return mech_error_set(err, MECH_EDOMAIN, "inner_radius",
                                  "must be < outer_radius (%.17g), got %.17g", x[1], x[0]);
        double s2 = x[0] * x[0] + x[1] * x[1];
        d[0] = d[1] = m * (3.0 * s2 + x[2] * x[2]) / 12.0;
        d[2] = 0.5 * m * s2;
        *form = 1;
        return MECH_OK;
    }
    case MECH_SHAPE_DISC: /* thin disc: MR^2/2 about the axis, MR^2/4 across */
    case MECH_SHAPE_RING: /* thin hoop: MR^2 about the axis, MR^2/2 across */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "radius", "must be finite and > 0");
        d[2] = (p->shape == MECH_SHAPE_DISC ? 0.5 : 1.0) * m * x[0] * x[0];
        d[0] = d[1] = 0.5 * d[2];
        *form = 1;
        return MECH_OK;
    case MECH_SHAPE_PLATE: /* thin a x b rectangle in xy: Mb^2/12, Ma^2/12, M(a^2 + b^2)/12 */
        if (!dim_ok(x[0]) || !dim_ok(x[1]))
            return mech_error_set(err, MECH_EINVAL, "size", "edges must be finite and > 0");
        d[0] = m * x[1] * x[1] / 12.0;
        d[1] = m * x[0] * x[0] / 12.0;
        d[2] = m * (x[0] * x[0] + x[1] * x[1]) / 12.0;
        return MECH_OK;
    case MECH_SHAPE_ELLIPSOID: /* M(b^2 + c^2)/5, M(a^2 + c^2)/5, M(a^2 + b^2)/5 */
        for (int i = 0; i < 3; i++)
            if (!dim_ok(x[i]))
                return mech_error_set(err, MECH_EINVAL, "semi_axes", "must be finite and > 0");
        d[0] = m * (x[1] * x[1] + x[2] * x[2]) / 5.0;
        d[1] = m * (x[0] * x[0] + x[2] * x[2]) / 5.0;
        d[2] = m * (x[0] * x[0] + x[1] * x[1]) / 5.0;
        return MECH_OK;
    case MECH_SHAPE_TORUS:
        /* Solid ring torus (R > r), axis z: I_zz = M(R^2 + 3r^2/4),
         * I_xx = M(R^2/2 + 5r^2/8) (Pappus-style integration over the tube's
         * circular section; checked against a mesh in the tests). */
        if (!dim_ok(x[0]))
            return mech_error_set(err, MECH_EINVAL, "major_radius", "must be finite and > 0");
        if (!dim_ok(x[1]))
            return mech_error_set(err, MECH_EINVAL, "minor_radius", "must be finite and > 0");
        if (!(x[1] < x[0]))
            return mech_error_set(err, MECH_EDOMAIN, "minor_radius",
                                  "must be < major_radius (%.17g) for a ring torus, got %.17g",
                                  x[0], x[1]);
        d[0] = d[1] = m * (0.5 * x[0] * x[0] + 0.625 * x[1] * x[1]);
        d[2] = m * (x[0] * x[0] + 0.75 * x[1] * x[1]);
        *form = 1;
        return MECH_OK;
    default:
        return mech_error_set(err, MECH_EINVAL, "shape", "unknown shape %d", (int)p->shape);
    }
}

/* I = tr(C) 1 - C for a covariance C (integral of m r r^T), the diagonal
 * written as C_yy + C_zz etc. so that nothing cancels (notes §2.2). */
static struct mech_mat3 tensor_of_covariance(struct mech_mat3 c)
{
    struct mech_mat3 t;
    t.a[0][0] = c.a[1][1] + c.a[2][2];
    t.a[1][1] = c.a[0][0] + c.a[2][2];
    t.a[2][2] = c.a[0][0] + c.a[1][1];
    t.a[0][1] = t.a[1][0] = -c.a[0][1];
    t.a[0][2] = t.a[2][0] = -c.a[0][2];
    t.a[1][2] = t.a[2][1] = -c.a[1][2];
    return t;
}

/* R^T T R for a symmetric T, mirrored so the result is exactly symmetric. */
static struct mech_mat3 to_scene(struct mech_mat3 r, struct mech_mat3 t)
{
    struct mech_mat3 tr = mech_mat3_mul(t, r), out;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++)
            out.a[i][j] = out.a[j][i] =
                r.a[0][i] * tr.a[0][j] + r.a[1][i] * tr.a[1][j] + r.a[2][i] * tr.a[2][j];
    return out;
}

static enum mech_status check_orientation(const struct mech_inertia_part *p, struct mech_mat3 *r,
                                          struct mech_error *err)
{
    struct mech_error e2;
    mech_error_clear(&e2);
    if (mech_rotation_from_matrix(p->orientation, r, &e2) != MECH_OK)
        return mech_error_set(err, MECH_EINVAL, "orientation", "%s", e2.text);
    return MECH_OK;
}

/* Thin uniform triangle (corners in scene axes): centroid g = (A + B + C)/3 and
 * covariance about it (M/12) sum_k e_k e_k^T, e_k = corner_k - g (the second
 * moment of a triangle, integral of x x^T dA = A/12 (sum v v^T + s s^T),
 * s = sum v, which is (A/12) sum e e^T about the centroid). Corners are taken
 * relative to A first, so a triangle far from the origin keeps its digits. */
static enum mech_status triangle_props(const struct mech_inertia_part *p, struct mech_vec3 *com,
                                       struct mech_mat3 *t, struct mech_error *err)
{
    const struct mech_vec3 *v = p->vertices;
    for (int k = 0; k < 3; k++)
        if (!mech_vec3_isfinite(v[k]))
            return mech_error_set(err, MECH_EINVAL, "vertices", "corner %d is not finite", k);
    struct mech_vec3 ab = mech_vec3_sub(v[1], v[0]), ac = mech_vec3_sub(v[2], v[0]);
    double cn = mech_vec3_norm(mech_vec3_cross(ab, ac));
    if (!(cn > 1e-14 * mech_vec3_norm(ab) * mech_vec3_norm(ac)))
        return mech_error_set(err, MECH_EINVAL, "vertices",
                              "the three corners are collinear or coincide: the triangle has "
                              "no area");
    struct mech_vec3 ga = mech_vec3_scale(mech_vec3_add(ab, ac), 1.0 / 3.0); /* g - A */
    struct mech_vec3 e[3] = {mech_vec3_scale(ga, -1.0), mech_vec3_sub(ab, ga),
                             mech_vec3_sub(ac, ga)};
    struct mech_mat3 c = {{{0}}};
    for (int k = 0; k < 3; k++) {
        double u[3] = {e[k].x, e[k].y, e[k].z};
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                c.a[i][j] += u[i] * u[j];
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c.a[i][j] *= p->mass / 12.0;
    *com = mech_vec3_add(v[0], ga);
    *t = tensor_of_covariance(c);
    return MECH_OK;
}

/* A tensor part's own tensor (body axes), checked: finite, symmetric within
 * 1e-12 of its largest entry (then symmetrised), and realisable by a mass
 * distribution (principal moments >= 0 and each at most the sum of the other
 * two, within 1e-9 of the trace). */
static enum mech_status tensor_part(const struct mech_inertia_part *p, struct mech_mat3 *out,
                                    struct mech_error *err)
{
    const struct mech_mat3 t = p->tensor;
    if (!mech_mat3_isfinite(t))
        return mech_error_set(err, MECH_EINVAL, "tensor", "entries must be finite");
    double big = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) big = fmax(big, fabs(t.a[i][j]));
    struct mech_mat3 s;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (fabs(t.a[i][j] - t.a[j][i]) > 1e-12 * big)
                return mech_error_set(err, MECH_EINVAL, "tensor",
                                      "not symmetric: [%d][%d] = %.17g but [%d][%d] = %.17g", i,
                                      j, t.a[i][j], j, i, t.a[j][i]);
            s.a[i][j] = 0.5 * (t.a[i][j] + t.a[j][i]);
        }
    struct mech_inertia_principal pc;
    enum mech_status st = mech_inertia_principal(s, &pc, err);
    if (st != MECH_OK) return st;
    const double *l = pc.moments;
    double tr = l[0] + l[1] + l[2];
    double worst = fmax(l[2] - l[0] - l[1], -l[0]);
    if (worst > 1e-9 * fabs(tr) || (tr == 0 && big > 0))
        return mech_error_set(err, MECH_EDOMAIN, "tensor",
                              "no mass distribution has this tensor: principal moments %.6g, "
                              "%.6g, %.6g kg m^2 (each must be >= 0 and at most the sum of "
                              "the other two)",
                              l[0], l[1], l[2]);
    *out = s;
    return MECH_OK;
}

/* Everything but the sign of a hole; mesh parts need the budget. */
static enum mech_status material_props(const struct mech_inertia_part *p,
                                       const struct mech_budget *budget, long *steps,
                                       struct mech_inertia_part_props *out, struct mech_error *err)
{
    if (!(isfinite(p->mass) && p->mass > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "must be finite and > 0, got %.17g",
                              p->mass);
    out->mass = p->mass;
    out->volume = 0;
    out->inverted = 0;
    enum mech_status st;
    if (p->shape == MECH_SHAPE_TRIANGLE)
        return triangle_props(p, &out->center_of_mass, &out->tensor, err);
    if (!mech_vec3_isfinite(p->position))
        return mech_error_set(err, MECH_EINVAL, "position", "must be finite");
    if (p->shape == MECH_SHAPE_POINT) {
        out->center_of_mass = p->position;
        out->tensor = (struct mech_mat3){{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
        return MECH_OK;
    }
    struct mech_mat3 r;
    if (p->shape == MECH_SHAPE_TENSOR) {
        if ((st = tensor_part(p, &out->tensor, err)) != MECH_OK) return st;
        if ((st = check_orientation(p, &r, err)) != MECH_OK) return st;
        out->tensor = to_scene(r, out->tensor);
        out->center_of_mass = p->position;
    } else if (p->shape == MECH_SHAPE_MESH) {
        if (!budget)
            return mech_error_set(err, MECH_EINVAL, "shape",
                                  "a mesh part needs a budget: use mech_inertia_part_properties");
        if ((st = check_orientation(p, &r, err)) != MECH_OK) return st;
        struct mech_mesh_properties mp;
        if ((st = mech_mesh_properties(&p->mesh, budget, steps, &mp, err)) != MECH_OK) return st;
        /* uniform density M/V: covariance (M/V) C, tensor tr - C (notes §2.2) */
        struct mech_mat3 c = mp.covariance;
        double rho = p->mass / mp.volume;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                c.a[i][j] *= rho;
        out->tensor = to_scene(r, tensor_of_covariance(c));
        out->center_of_mass =
            mech_vec3_add(p->position, mech_mat3_mul_vec(mech_mat3_transpose(r), mp.centroid));
        out->volume = mp.volume;
        out->inverted = mp.inverted;
    } else {
        double d[3] = {0, 0, 0}, cz = 0;
        int form = 0;
        if ((st = body_form(p, d, &cz, &form, err)) != MECH_OK) return st;
        struct mech_mat3 t;
        if (form == 2) {
            t = (struct mech_mat3){{{d[0], 0, 0}, {0, d[0], 0}, {0, 0, d[0]}}};
            out->center_of_mass = p->position;
        } else {
            if ((st = check_orientation(p, &r, err)) != MECH_OK) return st;
            double zv[3] = {r.a[2][0], r.a[2][1], r.a[2][2]}; /* body z in scene axes */
            if (form == 1) {
                /* I = d_perp 1 + (d_axis - d_perp) z z^T: exact trace, exactly symmetric. */
                double k = d[2] - d[0];
                for (int i = 0; i < 3; i++)
                    for (int j = i; j < 3; j++)
                        t.a[i][j] = t.a[j][i] = k * zv[i] * zv[j] + (i == j ? d[0] : 0.0);
            } else {
                /* I_scene = R^T diag(d) R: (I)_ij = sum_k R_ki d_k R_kj (notes §2.2). */
                for (int i = 0; i < 3; i++)
                    for (int j = i; j < 3; j++)
                        t.a[i][j] = t.a[j][i] = r.a[0][i] * d[0] * r.a[0][j] +
                                                r.a[1][i] * d[1] * r.a[1][j] +
                                                r.a[2][i] * d[2] * r.a[2][j];
            }
            out->center_of_mass =
                mech_vec3_add(p->position, mech_vec3_make(cz * zv[0], cz * zv[1], cz * zv[2]));
        }
        out->tensor = t;
    }
    if (!mech_mat3_isfinite(out->tensor) || !mech_vec3_isfinite(out->center_of_mass))
        return mech_error_set(err, MECH_ENUMERIC, "mass", "inertia of the part overflows");
    return MECH_OK;
}

enum mech_status mech_inertia_part_tensor(const struct mech_inertia_part *p, struct mech_mat3 *out,
                                          struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no part given");
    if (p->shape == MECH_SHAPE_MESH)
        return mech_error_set(err, MECH_EINVAL, "shape",
                              "a mesh part needs a budget: use mech_inertia_part_properties");
    struct mech_inertia_part_props pr;
    enum mech_status st = material_props(p, NULL, NULL, &pr, err);
    if (st == MECH_OK) *out = pr.tensor;
    return st;
}

enum mech_status mech_inertia_part_properties(const struct mech_inertia_part *p,
                                              const struct mech_budget *budget, long *steps,
                                              struct mech_inertia_part_props *out,
                                              struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no part given");
    if (!budget) return mech_error_set(err, MECH_EINVAL, NULL, "no budget given");
    long own = 0;
    struct mech_inertia_part_props pr;
    enum mech_status st = material_props(p, budget, steps ? steps : &own, &pr, err);
    if (st != MECH_OK) return st;
    if (p->hole) { /* removed material: every integral changes sign */
        pr.mass = -pr.mass;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                pr.tensor.a[i][j] = -pr.tensor.a[i][j];
    }
    *out = pr;
    return MECH_OK;
}

static enum mech_status part_error(struct mech_error *err, size_t i, const struct mech_error *e)
{
    char param[160];
    snprintf(param, sizeof param, "bodies/%zu%s%s", i, e->param[0] ? "/" : "", e->param);
    enum mech_status st = mech_error_set(err, e->code, param, "%s", e->text);
    if (err && err->code == e->code) err->progress = e->progress;
    return st;
}

enum mech_status mech_inertia_compute(const struct mech_inertia_part *parts, size_t n,
                                      const struct mech_vec3 *origin,
                                      const struct mech_budget *budget, struct mech_inertia *out,
                                      struct mech_error *err)
{
    return mech_inertia_compute_parts(parts, n, origin, budget, out, NULL, err);
}

static enum mech_status compute_into(const struct mech_inertia_part *parts, size_t n,
                                     const struct mech_vec3 *origin,
                                     const struct mech_budget *budget, struct mech_inertia *out,
                                     struct mech_inertia_part_props *pp, struct mech_error *err)
{
    long steps = 0;
    enum mech_status st = mech_budget_check(budget, steps, 1, err);
    if (st != MECH_OK) return st;

    /* Pass 1: each part's own mass, centre of mass and tensor; total mass and
     * first moment relative to p0 = the first part's centre of mass, so
     * far-away bodies do not lose digits. Holes enter with negative mass. */
    struct mech_vec3 p0 = {0, 0, 0};
    double mass = 0, absmass = 0;
    struct mech_vec3 s1 = {0, 0, 0};
    int sized = 0, holes = 0;
    for (size_t i = 0; i < n; i++) {
        if ((st = mech_budget_check(budget, ++steps, 0, err)) != MECH_OK) return st;
        struct mech_error e;
        mech_error_clear(&e);
        if (mech_inertia_part_properties(&parts[i], budget, &steps, &pp[i], &e) != MECH_OK)
            return part_error(err, i, &e);
        if (i == 0) p0 = pp[0].center_of_mass;
        if (parts[i].shape != MECH_SHAPE_POINT) sized = 1;
        holes |= parts[i].hole != 0;
        mass += pp[i].mass;
        absmass += fabs(pp[i].mass);
        s1 =
            mech_vec3_add(s1, mech_vec3_scale(mech_vec3_sub(pp[i].center_of_mass, p0), pp[i].mass));
    }
    if (!(mass > 1e-12 * absmass))
        return mech_error_set(err, MECH_EDOMAIN, "bodies",
                              "the holes remove all the mass: total %.17g kg (must be > 0, and "
                              "more than 1e-12 of the parts' %.17g kg)",
                              mass, absmass);
    struct mech_vec3 c = mech_vec3_scale(s1, 1.0 / mass);
    /* Refine once: the residual first moment about p0 + c (removes the rounding
     * of the first pass when offsets are large compared with the body). */
    struct mech_vec3 s2 = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        if ((st = mech_budget_check(budget, ++steps, 0, err)) != MECH_OK) return st;
        struct mech_vec3 r = mech_vec3_sub(mech_vec3_sub(pp[i].center_of_mass, p0), c);
        s2 = mech_vec3_add(s2, mech_vec3_scale(r, pp[i].mass));
    }
    c = mech_vec3_add(c, mech_vec3_scale(s2, 1.0 / mass));
    struct mech_vec3 com = mech_vec3_add(p0, c);

    /* Pass 3: tensor about the centre of mass in centred coordinates r = (p - p0) - c. */
    struct mech_mat3 tcm = {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
    for (size_t i = 0; i < n; i++) {
        if ((st = mech_budget_check(budget, ++steps, 0, err)) != MECH_OK) return st;
        struct mech_vec3 r = mech_vec3_sub(mech_vec3_sub(pp[i].center_of_mass, p0), c);
        if (mech_vec3_norm(r) > 0) sized = 1;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                tcm.a[a][b] += pp[i].tensor.a[a][b];
        add_point(&tcm, pp[i].mass, r); /* parallel axis theorem, notes §2.3 */
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
    if (holes) {
        /* A positive mass distribution has a positive semi-definite covariance:
         * every principal moment at most the sum of the other two. */
        struct mech_inertia_principal pc;
        if ((st = mech_inertia_principal(tcm, &pc, err)) != MECH_OK) return st;
        double *l = pc.moments, tr = l[0] + l[1] + l[2];
        double worst = fmax(l[2] - l[0] - l[1], fmax(l[1] - l[0] - l[2], -l[0]));
        if (!(tr > 0) || worst > 1e-9 * tr)
            return mech_error_set(err, MECH_EDOMAIN, "bodies",
                                  "no body of positive density has this inertia: principal "
                                  "moments about the centre of mass %.6g, %.6g, %.6g kg m^2 "
                                  "(a hole reaches outside the material?)",
                                  l[0], l[1], l[2]);
    }

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

enum mech_status mech_inertia_compute_parts(const struct mech_inertia_part *parts, size_t n,
                                            const struct mech_vec3 *origin,
                                            const struct mech_budget *budget,
                                            struct mech_inertia *out,
                                            struct mech_inertia_part_props *part_out,
                                            struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!parts || n == 0)
        return mech_error_set(err, MECH_EINVAL, "bodies", "at least one part is required");
    if (origin && !mech_vec3_isfinite(*origin))
        return mech_error_set(err, MECH_EINVAL, "origin", "must be finite");
    if (n > ((size_t)-1) / sizeof *part_out)
        return mech_error_set(err, MECH_ENOMEM, "bodies", "too many parts");
    /* scratch (or the caller's array, written only on success) */
    struct mech_inertia_part_props *pp = malloc(n * sizeof *pp);
    if (!pp) return mech_error_set(err, MECH_ENOMEM, NULL, "scratch for %zu parts", n);
    enum mech_status st = compute_into(parts, n, origin, budget, out, pp, err);
    if (st == MECH_OK && part_out) memcpy(part_out, pp, n * sizeof *pp);
    free(pp);
    return st;
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
    *v = mech_vec3_unit(mech_vec3_sub(e, mech_vec3_scale(u, uc[k])));
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
        plane_basis(mech_vec3_unit(e[2]), &e[0], &e[1]);
    } else if (d12) {
        e[0] = sign_fix(mech_vec3_unit(e[0]));
        plane_basis(e[0], &e[1], &e[2]);
    }
    /* Sign rule, Gram-Schmidt, right-handed completion. */
    e[0] = sign_fix(mech_vec3_unit(e[0]));
    e[1] = mech_vec3_sub(e[1], mech_vec3_scale(e[0], mech_vec3_dot(e[0], e[1])));
    e[1] = sign_fix(mech_vec3_unit(e[1]));
    e[2] = mech_vec3_unit(mech_vec3_cross(e[0], e[1]));
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
