/* test_inertia.c — mech/rigid/inertia.h against the notes' worked examples (ch. 2:
 * dumbbell, cube about its centre and about a corner), the textbook closed
 * forms of every shape, rotated bodies, extreme scales, degenerate tensors,
 * angular momentum / kinetic energy by hand, and typed errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rigid/inertia.h"
#include "mech/base/constants.h"
#include "mech/rotation/rotation.h"
#include "testlib.h"

static unsigned long rnd_state = 987654321UL;
static double rnd(void)
{
    rnd_state = rnd_state * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(rnd_state >> 11) / 9007199254740992.0;
}

static struct mech_budget budget(void)
{
    return mech_budget_make(1000000, 60.0);
}

static struct mech_inertia_part part(enum mech_inertia_shape s, double m, struct mech_vec3 pos,
                                     double d0, double d1, double d2)
{
    struct mech_inertia_part p;
    memset(&p, 0, sizeof p);
    p.shape = s;
    p.mass = m;
    p.position = pos;
    p.orientation = mech_mat3_identity();
    p.dim[0] = d0;
    p.dim[1] = d1;
    p.dim[2] = d2;
    return p;
}

static double mat_diff(struct mech_mat3 a, struct mech_mat3 b)
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(a.a[i][j] - b.a[i][j]));
    return d;
}

static struct mech_mat3 diag(double a, double b, double c)
{
    struct mech_mat3 m = {{{a, 0, 0}, {0, b, 0}, {0, 0, c}}};
    return m;
}

static double mat_max_abs_t(struct mech_mat3 m)
{
    return mat_diff(m, diag(0, 0, 0));
}

static struct mech_vec3 row(struct mech_mat3 m, int k)
{
    return mech_vec3_make(m.a[k][0], m.a[k][1], m.a[k][2]);
}

static double worst_axes;  /* largest orthonormality / handedness defect seen */
static double worst_resid; /* largest |I e - lambda e| / lambda_max seen */

/* Axes orthonormal, right-handed, eigenvectors of t; sign rule for rows 0, 1. */
static void check_axes(struct mech_mat3 t, const struct mech_inertia_principal *p)
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(mech_vec3_dot(row(p->axes, i), row(p->axes, j)) - (i == j)));
    struct mech_vec3 c = mech_vec3_cross(row(p->axes, 0), row(p->axes, 1));
    d = fmax(d, mech_vec3_norm(mech_vec3_sub(c, row(p->axes, 2))));
    worst_axes = fmax(worst_axes, d);
    CHECK(d <= 1e-15);
    double top = fmax(fabs(p->moments[0]), fabs(p->moments[2]));
    for (int k = 0; k < 3; k++) {
        struct mech_vec3 e = row(p->axes, k);
        struct mech_vec3 r =
            mech_vec3_sub(mech_mat3_mul_vec(t, e), mech_vec3_scale(e, p->moments[k]));
        double res = top > 0 ? mech_vec3_norm(r) / top : mech_vec3_norm(r);
        /* a pair treated as degenerate (split <= MECH_INERTIA_DEGENERATE_RTOL) gets
         * a canonical basis of its plane: residual up to the actual split there */
        if (!p->degenerate) worst_resid = fmax(worst_resid, res);
        CHECK(res <= (p->degenerate ? MECH_INERTIA_DEGENERATE_RTOL : 1e-13));
    }
    CHECK(p->moments[0] <= p->moments[1] && p->moments[1] <= p->moments[2]);
    for (int k = 0; k < 2; k++) {
        struct mech_vec3 e = row(p->axes, k);
        double c3[3] = {e.x, e.y, e.z}, mx = 0;
        int im = 0;
        for (int i = 0; i < 3; i++)
            if (fabs(c3[i]) > mx * (1 + 1e-12)) {
                mx = fabs(c3[i]);
                im = i;
            }
        CHECK(c3[im] > 0);
    }
}

static int compute(const struct mech_inertia_part *p, size_t n, const struct mech_vec3 *origin,
                   struct mech_inertia *out)
{
    struct mech_budget b = budget();
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_inertia_compute(p, n, origin, &b, out, &e);
    if (st != MECH_OK) fprintf(stderr, "compute failed: %s %s\n", e.param, e.text);
    CHECK(st == MECH_OK);
    if (st == MECH_OK) check_axes(out->tensor, &out->principal);
    return st == MECH_OK;
}

/* Independent tensor of point masses straight from the definition (notes
 * §2.2), I_ij = sum m (r^2 delta_ij - r_i r_j), about `o`. */
static struct mech_mat3 points_direct(const double *m, const struct mech_vec3 *r, int n,
                                      struct mech_vec3 o)
{
    struct mech_mat3 t = {{{0}}};
    for (int k = 0; k < n; k++) {
        double v[3] = {r[k].x - o.x, r[k].y - o.y, r[k].z - o.z};
        double r2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                t.a[i][j] += m[k] * ((i == j) * r2 - v[i] * v[j]);
    }
    return t;
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_inertia res;
    const struct mech_vec3 zero = {0, 0, 0};

    /* 1. Every shape alone, body axes = scene axes: the textbook forms. */
    {
        double M = 2.5, L = 3.0, a = 0.4, b = 1.1, c = 2.3, R = 0.7, h = 1.9;
        struct {
            struct mech_inertia_part p;
            struct mech_mat3 want;
        } cases[] = {
            {part(MECH_SHAPE_POINT, M, zero, 0, 0, 0), diag(0, 0, 0)},
            {part(MECH_SHAPE_ROD, M, zero, L, 0, 0), diag(M * L * L / 12, M * L * L / 12, 0)},
            {part(MECH_SHAPE_BOX, M, zero, a, b, c),
             diag(M * (b * b + c * c) / 12, M * (a * a + c * c) / 12, M * (a * a + b * b) / 12)},
            {part(MECH_SHAPE_SPHERE, M, zero, R, 0, 0),
             diag(0.4 * M * R * R, 0.4 * M * R * R, 0.4 * M * R * R)},
            {part(MECH_SHAPE_SHELL, M, zero, R, 0, 0),
             diag(2 * M * R * R / 3, 2 * M * R * R / 3, 2 * M * R * R / 3)},
            {part(MECH_SHAPE_CYLINDER, M, zero, R, h, 0),
             diag(M * (3 * R * R + h * h) / 12, M * (3 * R * R + h * h) / 12, M * R * R / 2)},
        };
        for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
            if (!compute(&cases[k].p, 1, NULL, &res)) continue;
            double scale = fmax(cases[k].want.a[0][0], cases[k].want.a[2][2]);
            CHECK(mat_diff(res.tensor, cases[k].want) <= 1e-15 * scale);
            CHECK(mat_diff(res.tensor_cm, cases[k].want) <= 1e-15 * scale);
            CHECK_CLOSE(res.mass, M, 0, 0);
        }
        /* the box's principal moments in ascending order, axes = scene axes (a < b < c:
         * I_x > I_y > I_z, so ascending = z, y, x) */
        struct mech_inertia_part bx = part(MECH_SHAPE_BOX, M, zero, a, b, c);
        if (compute(&bx, 1, NULL, &res)) {
            CHECK_CLOSE(res.principal.moments[0], M * (a * a + b * b) / 12, 1e-15, 0);
            CHECK_CLOSE(res.principal.moments[1], M * (a * a + c * c) / 12, 1e-15, 0);
            CHECK_CLOSE(res.principal.moments[2], M * (b * b + c * c) / 12, 1e-15, 0);
            CHECK(res.principal.degenerate == 0);
            CHECK_CLOSE(fabs(res.principal.axes.a[0][2]), 1, 0, 1e-15);
            CHECK_CLOSE(fabs(res.principal.axes.a[1][1]), 1, 0, 1e-15);
            CHECK_CLOSE(fabs(res.principal.axes.a[2][0]), 1, 0, 1e-15);
        }
    }

    /* 2. Notes §2.4: cube of mass M, side s, about its centre: I = M s^2/6 1. */
    double M = 3.0, s = 0.5;
    {
        struct mech_inertia_part cube = part(MECH_SHAPE_BOX, M, mech_vec3_make(1, 2, 3), s, s, s);
        if (compute(&cube, 1, NULL, &res)) {
            CHECK(mat_diff(res.tensor, diag(M * s * s / 6, M * s * s / 6, M * s * s / 6)) <=
                  1e-16 * M * s * s);
            CHECK(res.principal.degenerate == 1);
            CHECK(mat_diff(res.principal.axes, mech_mat3_identity()) == 0);
            CHECK(res.center_of_mass.x == 1 && res.center_of_mass.y == 2 &&
                  res.center_of_mass.z == 3);
        }
    }

    /* 3. Notes §2.4-2.5: the cube about a corner. Parallel axes with a = (s/2)(1,1,1):
     * I_ij = M s^2/6 delta_ij + M (3 s^2/4 delta_ij - s^2/4) = M s^2 (11/12 delta_ij - 1/4),
     * i.e. 2/3 M s^2 on the diagonal and -1/4 M s^2 off it;
     * principal moments M s^2 {1/6, 11/12, 11/12}; the 1/6 axis along the body
     * diagonal (1,1,1)/sqrt3, the 11/12 pair spanning the plane normal to it. */
    {
        struct mech_inertia_part cube =
            part(MECH_SHAPE_BOX, M, mech_vec3_make(s / 2, s / 2, s / 2), s, s, s);
        if (compute(&cube, 1, &zero, &res)) {
            double ms2 = M * s * s, err = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    err = fmax(err, fabs(res.tensor.a[i][j] - ms2 * ((i == j) * 11.0 / 12 - 0.25)));
            printf("cube about a corner: max tensor error / (M s^2) = %.3g\n", err / ms2);
            CHECK(err <= 1e-15 * ms2);
            double me = fmax(fabs(res.principal.moments[0] - ms2 / 6),
                             fmax(fabs(res.principal.moments[1] - 11 * ms2 / 12),
                                  fabs(res.principal.moments[2] - 11 * ms2 / 12)));
            printf("cube about a corner: max moment error / largest = %.3g\n",
                   me / (11 * ms2 / 12));
            CHECK(me <= 1e-13 * 11 * ms2 / 12);
            CHECK(res.principal.degenerate == 1);
            struct mech_vec3 diagv = mech_vec3_scale(mech_vec3_make(1, 1, 1), 1 / sqrt(3.0));
            /* sign rule: the diagonal comes out as +(1,1,1)/sqrt3 */
            CHECK(mech_vec3_norm(mech_vec3_sub(row(res.principal.axes, 0), diagv)) <= 1e-15);
            /* the degenerate pair as a subspace: both orthogonal to the diagonal */
            CHECK(fabs(mech_vec3_dot(row(res.principal.axes, 1), diagv)) <= 1e-15);
            CHECK(fabs(mech_vec3_dot(row(res.principal.axes, 2), diagv)) <= 1e-15);
            /* the tensor about the centre of mass is still M s^2/6 1 */
            CHECK(mat_diff(res.tensor_cm, diag(ms2 / 6, ms2 / 6, ms2 / 6)) <= 1e-16 * ms2);
        }
    }

    /* 4. Notes §2.2: dumbbell, masses m at +-l/2 (cos phi, sin phi, 0):
     * I = m l^2/2 [[1 - cos^2, -cos sin, 0], [-cos sin, 1 - sin^2, 0], [0, 0, 1]]. */
    {
        double m = 0.8, l = 1.7;
        for (int k = 0; k < 12; k++) {
            double phi = k * MECH_PI / 6 + 0.1;
            struct mech_vec3 u = mech_vec3_make(cos(phi), sin(phi), 0);
            struct mech_inertia_part pp[2] = {
                part(MECH_SHAPE_POINT, m, mech_vec3_scale(u, l / 2), 0, 0, 0),
                part(MECH_SHAPE_POINT, m, mech_vec3_scale(u, -l / 2), 0, 0, 0)};
            if (!compute(pp, 2, NULL, &res)) continue;
            double f = m * l * l / 2, c = cos(phi), sn = sin(phi);
            struct mech_mat3 want = {{{f * (1 - c * c), -f * c * sn, 0},
                                      {-f * c * sn, f * (1 - sn * sn), 0},
                                      {0, 0, f}}};
            CHECK(mat_diff(res.tensor, want) <= 1e-15 * f);
            CHECK(mech_vec3_norm(res.center_of_mass) <= 1e-16 * l);
            /* principal: 0 along the rod, f twice (degenerate pair) */
            CHECK_CLOSE(res.principal.moments[0], 0, 0, 1e-15 * f);
            CHECK_CLOSE(res.principal.moments[1], f, 1e-15, 0);
            CHECK_CLOSE(res.principal.moments[2], f, 1e-15, 0);
            CHECK(res.principal.degenerate == 1);
            CHECK_CLOSE(fabs(mech_vec3_dot(row(res.principal.axes, 0), u)), 1, 0, 1e-15);
        }
        /* with omega: phi = 30 deg, omega = (1, 2, 3) rad/s. By hand:
         * I = f [[1/4, -sqrt3/4, 0], [-sqrt3/4, 3/4, 0], [0, 0, 1]], f = m l^2/2;
         * L = f (1/4 - sqrt3/2, -sqrt3/4 + 3/2, 3); T = omega.L/2. */
        double phi = MECH_PI / 6, f = m * l * l / 2, r3 = sqrt(3.0);
        struct mech_vec3 u = mech_vec3_make(cos(phi), sin(phi), 0);
        struct mech_inertia_part pp[2] = {
            part(MECH_SHAPE_POINT, m, mech_vec3_scale(u, l / 2), 0, 0, 0),
            part(MECH_SHAPE_POINT, m, mech_vec3_scale(u, -l / 2), 0, 0, 0)};
        if (compute(pp, 2, NULL, &res)) {
            struct mech_vec3 L;
            double T;
            CHECK(mech_inertia_spin(res.tensor, mech_vec3_make(1, 2, 3), &L, &T, NULL) == MECH_OK);
            struct mech_vec3 Lw = mech_vec3_make(f * (0.25 - r3 / 2), f * (1.5 - r3 / 4), 3 * f);
            double Tw = 0.5 * (Lw.x + 2 * Lw.y + 3 * Lw.z);
            CHECK_CLOSE(L.x, Lw.x, 1e-14, 0);
            CHECK_CLOSE(L.y, Lw.y, 1e-14, 0);
            CHECK_CLOSE(L.z, Lw.z, 1e-14, 0);
            CHECK_CLOSE(T, Tw, 1e-14, 0);
            /* T = f/2 (omega_perp to rod)^2: |omega|^2 - (omega.u)^2 = 14 - (sqrt3/2 + 1)^2 */
            double wu = r3 / 2 + 1.0;
            CHECK_CLOSE(T, 0.5 * f * (14 - wu * wu), 1e-14, 0);
        }
    }

    /* 5. Rotated bodies: I_scene = R^T I_body R; trace invariant; principal
     * moments = body moments; principal axes = rows of R (up to sign). */
    {
        double Mb = 1.3, a = 0.3, b = 0.9, c = 1.6;
        struct mech_mat3 r;
        mech_rotation_from_euler_zxz(0.4, 1.2, -2.1, &r, NULL);
        struct mech_inertia_part bx = part(MECH_SHAPE_BOX, Mb, mech_vec3_make(-1, 5, 2), a, b, c);
        bx.orientation = r;
        double d0 = Mb * (b * b + c * c) / 12, d1 = Mb * (a * a + c * c) / 12,
               d2 = Mb * (a * a + b * b) / 12;
        if (compute(&bx, 1, NULL, &res)) {
            struct mech_mat3 want =
                mech_mat3_mul(mech_mat3_transpose(r), mech_mat3_mul(diag(d0, d1, d2), r));
            CHECK(mat_diff(res.tensor, want) <= 2e-16 * d0);
            double tr = res.tensor.a[0][0] + res.tensor.a[1][1] + res.tensor.a[2][2];
            CHECK_CLOSE(tr, d0 + d1 + d2, 2e-16, 0);
            CHECK_CLOSE(res.principal.moments[0], d2, 1e-15, 0);
            CHECK_CLOSE(res.principal.moments[1], d1, 1e-15, 0);
            CHECK_CLOSE(res.principal.moments[2], d0, 1e-15, 0);
            CHECK_CLOSE(fabs(mech_vec3_dot(row(res.principal.axes, 0), row(r, 2))), 1, 0, 1e-15);
            CHECK_CLOSE(fabs(mech_vec3_dot(row(res.principal.axes, 1), row(r, 1))), 1, 0, 1e-15);
            CHECK_CLOSE(fabs(mech_vec3_dot(row(res.principal.axes, 2), row(r, 0))), 1, 0, 1e-15);
        }
        /* tilted cylinder: pair degenerate (across), the unique axis = body z = row 2 of R */
        struct mech_inertia_part cy = part(MECH_SHAPE_CYLINDER, Mb, zero, 0.5, 2.0, 0);
        cy.orientation = r;
        if (compute(&cy, 1, NULL, &res)) {
            CHECK(res.principal.degenerate == 1);
            CHECK_CLOSE(res.principal.moments[0], Mb * 0.25 / 2, 1e-15, 0);
            CHECK_CLOSE(res.principal.moments[2], Mb * (0.75 + 4) / 12, 1e-15, 0);
            CHECK_CLOSE(fabs(mech_vec3_dot(row(res.principal.axes, 0), row(r, 2))), 1, 0, 1e-15);
        }
        /* the same box rotated four ways gives the same tensor */
        struct mech_mat3 rq, ra, rm;
        double q[4] = {0.3, -0.5, 0.7, 0.2};
        mech_rotation_from_quaternion(q, &rq, NULL);
        double vn = sqrt(0.25 + 0.49 + 0.04);
        mech_rotation_from_axis_angle(mech_vec3_make(-0.5, 0.7, 0.2), 2 * atan2(vn, 0.3), &ra,
                                      NULL);
        mech_rotation_from_matrix(rq, &rm, NULL);
        struct mech_inertia r1, r2, r3;
        bx.orientation = rq;
        compute(&bx, 1, NULL, &r1);
        bx.orientation = ra;
        compute(&bx, 1, NULL, &r2);
        bx.orientation = rm;
        compute(&bx, 1, NULL, &r3);
        CHECK(mat_diff(r1.tensor, r2.tensor) <= 1e-15 * d0);
        CHECK(mat_diff(r1.tensor, r3.tensor) <= 1e-15 * d0);
    }

    /* 6. Far away: a cube centred at (1e8, 0, 0) m still gives M s^2/6 (to 1e-12
     * relative; exact here), and a dumbbell at 1e8 m keeps m l^2/2. */
    {
        struct mech_inertia_part cube = part(MECH_SHAPE_BOX, M, mech_vec3_make(1e8, 0, 0), s, s, s);
        if (compute(&cube, 1, NULL, &res)) {
            double e = mat_diff(res.tensor, diag(M * s * s / 6, M * s * s / 6, M * s * s / 6));
            printf("cube at 1e8 m: max tensor error / (M s^2/6) = %.3g\n", e / (M * s * s / 6));
            CHECK(e <= 1e-12 * M * s * s / 6);
            CHECK(res.center_of_mass.x == 1e8);
        }
        /* the same cube as 8 point masses M/8 at the corners of a cube of side s:
         * I = 8 (M/8) (2 (s/2)^2) = M s^2/2 on the diagonal about the centre */
        struct mech_inertia_part pts[8];
        for (int k = 0; k < 8; k++)
            pts[k] =
                part(MECH_SHAPE_POINT, M / 8,
                     mech_vec3_make(1e8 + (k & 1 ? s / 2 : -s / 2), -3e7 + (k & 2 ? s / 2 : -s / 2),
                                    2e8 + (k & 4 ? s / 2 : -s / 2)),
                     0, 0, 0);
        if (compute(pts, 8, NULL, &res)) {
            double e = mat_diff(res.tensor, diag(M * s * s / 2, M * s * s / 2, M * s * s / 2));
            printf("8 points at 1e8 m: max tensor error / (M s^2/2) = %.3g\n", e / (M * s * s / 2));
            CHECK(e <= 1e-12 * M * s * s / 2);
            CHECK_CLOSE(res.center_of_mass.x, 1e8, 1e-16, 0);
        }
        /* a cube at 1e8 about the scene origin: I = I_cm + M (a^2 1 - a a^T) */
        if (compute(&cube, 1, &zero, &res)) {
            CHECK_CLOSE(res.tensor.a[0][0], M * s * s / 6, 1e-15, 0);
            CHECK_CLOSE(res.tensor.a[1][1], M * s * s / 6 + M * 1e16, 1e-15, 0);
            CHECK_CLOSE(res.tensor.a[2][2], M * s * s / 6 + M * 1e16, 1e-15, 0);
            CHECK_CLOSE(res.tensor_cm.a[0][0], M * s * s / 6, 1e-15, 0);
        }
    }

    /* 6b. A rotated box and a sphere, both about 1e8 m out, 1 m apart: the tensor
     * about their common centre of mass matches R^T D R + the sphere's 2/5 M R^2
     * + point-mass terms about the centre of mass computed by hand near the origin. */
    {
        struct mech_mat3 r;
        mech_rotation_from_euler_zxz(0.7, 0.4, 1.9, &r, NULL);
        double mb = 2.0, ms = 1.0, a = 0.3, b = 0.5, c = 0.9, rs = 0.2;
        struct mech_inertia_part pp[2] = {
            part(MECH_SHAPE_BOX, mb, mech_vec3_make(1e8, 2e8, -1e8), a, b, c),
            part(MECH_SHAPE_SPHERE, ms, mech_vec3_make(1e8 + 1, 2e8, -1e8), rs, 0, 0)};
        pp[0].orientation = r;
        struct mech_mat3 d =
            diag(mb * (b * b + c * c) / 12, mb * (a * a + c * c) / 12, mb * (a * a + b * b) / 12);
        struct mech_mat3 want = mech_mat3_mul(mech_mat3_transpose(r), mech_mat3_mul(d, r));
        /* centre of mass 1/3 m from the box towards the sphere: box at x = -1/3,
         * sphere at x = +2/3: sum m x^2 = 2/9 + 4/9 = 2/3 on the yy and zz entries */
        double is = 0.4 * ms * rs * rs;
        want.a[0][0] += is;
        want.a[1][1] += is + 2.0 / 3;
        want.a[2][2] += is + 2.0 / 3;
        if (compute(pp, 2, NULL, &res)) {
            double e = mat_diff(res.tensor, want);
            printf("rotated box + sphere at 1e8 m: max tensor error / largest = %.3g\n",
                   e / want.a[1][1]);
            CHECK(e <= 1e-12 * want.a[1][1]);
            CHECK_CLOSE(res.center_of_mass.x, 1e8 + 1.0 / 3, 1e-16, 0);
        }
    }

    /* 7. Tiny and huge scales (cube about a corner, exact closed form). */
    {
        double scales[][2] = {{1e-9, 1.0}, {1e-9, 1e-20}, {1e15, 1e30}, {1e12, 1e-25}};
        for (size_t k = 0; k < sizeof scales / sizeof scales[0]; k++) {
            double ss = scales[k][0], mm = scales[k][1], ms2 = mm * ss * ss;
            struct mech_inertia_part cube =
                part(MECH_SHAPE_BOX, mm, mech_vec3_make(ss / 2, ss / 2, ss / 2), ss, ss, ss);
            if (!compute(&cube, 1, &zero, &res)) continue;
            double err = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    err = fmax(err, fabs(res.tensor.a[i][j] - ms2 * ((i == j) * 11.0 / 12 - 0.25)));
            CHECK(err <= 1e-15 * ms2);
            CHECK_CLOSE(res.principal.moments[0], ms2 / 6, 1e-13 * 11 / 2, 0);
            CHECK_CLOSE(res.principal.moments[2], 11 * ms2 / 12, 1e-13, 0);
            CHECK(res.principal.degenerate == 1);
        }
    }

    /* 8. Spheres and shells are fully degenerate: scene axes come back. */
    {
        struct mech_inertia_part sp[2] = {part(MECH_SHAPE_SPHERE, 2, zero, 0.3, 0, 0),
                                          part(MECH_SHAPE_SHELL, 1, zero, 0.6, 0, 0)};
        if (compute(sp, 2, NULL, &res)) {
            double want = 0.4 * 2 * 0.09 + 2.0 / 3 * 0.36;
            for (int k = 0; k < 3; k++)
                CHECK_CLOSE(res.principal.moments[k], want, 1e-15, 0);
            CHECK(res.principal.degenerate == 1);
            CHECK(mat_diff(res.principal.axes, mech_mat3_identity()) == 0);
        }
    }

    /* 9. A cylinder with h = sqrt3 R: M (3R^2 + h^2)/12 = M R^2/2 = I_axis, so all
     * three moments agree (degenerate) even when tilted. */
    {
        double Rc = 0.8, Mc = 5;
        struct mech_inertia_part cy = part(MECH_SHAPE_CYLINDER, Mc, zero, Rc, sqrt(3.0) * Rc, 0);
        mech_rotation_from_axis_angle(mech_vec3_make(1, 2, 3), 0.9, &cy.orientation, NULL);
        if (compute(&cy, 1, NULL, &res)) {
            for (int k = 0; k < 3; k++)
                CHECK_CLOSE(res.principal.moments[k], Mc * Rc * Rc / 2, 1e-15, 0);
            CHECK(res.principal.degenerate == 1);
        }
        /* a rod is degenerate across (0, ML^2/12, ML^2/12) */
        struct mech_inertia_part rod = part(MECH_SHAPE_ROD, 2, zero, 3, 0, 0);
        if (compute(&rod, 1, NULL, &res)) {
            CHECK(res.principal.degenerate == 1);
            CHECK_CLOSE(res.principal.moments[1], 1.5, 1e-15, 0);
        }
        /* a single point: zero tensor, degenerate, scene axes */
        struct mech_inertia_part pt = part(MECH_SHAPE_POINT, 2, mech_vec3_make(1, 1, 1), 0, 0, 0);
        if (compute(&pt, 1, NULL, &res)) {
            CHECK(res.principal.degenerate == 1);
            CHECK(res.principal.moments[2] == 0);
        }
        /* slightly split moments (1e-6 relative) are not degenerate */
        struct mech_inertia_part bx = part(MECH_SHAPE_BOX, 1, zero, 1, 1 + 1e-6, 1 + 2e-6);
        if (compute(&bx, 1, NULL, &res)) CHECK(res.principal.degenerate == 0);
    }

    /* 10. Random bodies of many parts: axes orthonormal & right-handed, moments
     * satisfy the invariants (trace, second invariant, determinant) of the
     * tensor; the tensor matches the definition evaluated point by point. */
    {
        double worst_inv = 0, worst_def = 0;
        for (int trial = 0; trial < 300; trial++) {
            struct mech_inertia_part pp[7];
            double m[7];
            struct mech_vec3 r[7];
            int n = 2 + trial % 6;
            for (int k = 0; k < n; k++) {
                m[k] = 0.1 + rnd();
                double x = rnd() - 0.5, y = rnd() - 0.5, z = rnd() - 0.5;
                r[k] = mech_vec3_make(x, y, z);
                pp[k] = part(MECH_SHAPE_POINT, m[k], r[k], 0, 0, 0);
            }
            double ox = rnd(), oy = rnd(), oz = rnd();
            struct mech_vec3 o = mech_vec3_make(ox, oy, oz);
            if (!compute(pp, (size_t)n, &o, &res)) continue;
            struct mech_mat3 want = points_direct(m, r, n, o);
            double scale = res.principal.moments[2];
            worst_def = fmax(worst_def, mat_diff(res.tensor, want) / scale);
            struct mech_mat3 t = res.tensor;
            double *l = res.principal.moments;
            double tr = t.a[0][0] + t.a[1][1] + t.a[2][2];
            double i2 = t.a[0][0] * t.a[1][1] + t.a[1][1] * t.a[2][2] + t.a[0][0] * t.a[2][2] -
                        t.a[0][1] * t.a[1][0] - t.a[1][2] * t.a[2][1] - t.a[0][2] * t.a[2][0];
            double det = t.a[0][0] * (t.a[1][1] * t.a[2][2] - t.a[1][2] * t.a[2][1]) -
                         t.a[0][1] * (t.a[1][0] * t.a[2][2] - t.a[1][2] * t.a[2][0]) +
                         t.a[0][2] * (t.a[1][0] * t.a[2][1] - t.a[1][1] * t.a[2][0]);
            worst_inv = fmax(worst_inv, fabs(l[0] + l[1] + l[2] - tr) / scale);
            worst_inv = fmax(worst_inv,
                             fabs(l[0] * l[1] + l[1] * l[2] + l[0] * l[2] - i2) / (scale * scale));
            worst_inv = fmax(worst_inv, fabs(l[0] * l[1] * l[2] - det) / (scale * scale * scale));
        }
        printf("random bodies: tensor vs definition %.3g, invariants %.3g (relative to the "
               "largest moment)\n",
               worst_def, worst_inv);
        CHECK(worst_def <= 1e-14);
        CHECK(worst_inv <= 1e-14);
    }

    /* 11. Typed errors. */
    {
        struct mech_budget b = budget();
        struct mech_error e;
        struct mech_inertia_part pp[3] = {part(MECH_SHAPE_SPHERE, 1, zero, 1, 0, 0),
                                          part(MECH_SHAPE_POINT, 0, zero, 0, 0, 0),
                                          part(MECH_SHAPE_BOX, 1, zero, 1, -1, 1)};
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, NULL, &b, &res, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "bodies/1/mass") == 0);
        pp[1].mass = 1;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/2/size") == 0);
        pp[2].dim[1] = 1;
        pp[2].orientation.a[0][0] = 2; /* not a rotation */
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/2/orientation") == 0);
        pp[2].orientation = mech_mat3_identity();
        pp[0].position.y = NAN;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/position") == 0);
        pp[0].position.y = 0;
        pp[0].dim[0] = INFINITY;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/radius") == 0);
        pp[0].dim[0] = 1;
        struct mech_inertia_part cyl = part(MECH_SHAPE_CYLINDER, 1, zero, 1, 0, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&cyl, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/height") == 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 0, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies") == 0);
        struct mech_vec3 bad = mech_vec3_make(0, INFINITY, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, &bad, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "origin") == 0);
        CHECK(mech_inertia_compute(pp, 3, NULL, NULL, &res, NULL) == MECH_EINVAL);
        struct mech_budget small = mech_budget_make(2, 60.0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 3, NULL, &small, &res, &e) == MECH_EBUDGET);
        volatile int cancel = 1;
        struct mech_budget cb = budget();
        cb.cancel = &cancel;
        CHECK(mech_inertia_compute(pp, 3, NULL, &cb, &res, NULL) == MECH_ECANCELLED);
        /* overflow and underflow: typed numerical failures, never inf or 0 */
        struct mech_inertia_part huge = part(MECH_SHAPE_SPHERE, 1e300, zero, 1e300, 0, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&huge, 1, NULL, &b, &res, &e) == MECH_ENUMERIC);
        struct mech_inertia_part tiny = part(MECH_SHAPE_SPHERE, 1e-300, zero, 1e-300, 0, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&tiny, 1, NULL, &b, &res, &e) == MECH_ENUMERIC);
        /* tiny but representable: two 1e-300 kg points at +-1 m on x: I = diag(0, 2e-300,
         * 2e-300) kg m^2, all normal doubles */
        struct mech_inertia_part specks[2] = {
            part(MECH_SHAPE_POINT, 1e-300, mech_vec3_make(1, 0, 0), 0, 0, 0),
            part(MECH_SHAPE_POINT, 1e-300, mech_vec3_make(-1, 0, 0), 0, 0, 0)};
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(specks, 2, NULL, &b, &res, &e) == MECH_OK);
        CHECK_CLOSE(res.tensor.a[1][1], 2e-300, 1e-15, 0);
        CHECK_CLOSE(res.tensor.a[2][2], 2e-300, 1e-15, 0);
        CHECK(res.tensor.a[0][0] == 0);
        CHECK_CLOSE(res.principal.moments[2], 2e-300, 1e-15, 0);
        CHECK(res.principal.moments[0] == 0);
                struct mech_inertia_part far2[2] = {
            part(MECH_SHAPE_POINT, 1, zero, 0, 0, 0),
            part(MECH_SHAPE_POINT, 1, mech_vec3_make(1e200, 0, 0), 0, 0, 0)};
        CHECK(mech_inertia_compute(far2, 2, NULL, &b, &res, NULL) == MECH_ENUMERIC);
        struct mech_mat3 nant = diag(1, NAN, 1);
        struct mech_inertia_principal pr;
        CHECK(mech_inertia_principal(nant, &pr, NULL) == MECH_EINVAL);
        CHECK(mech_inertia_spin(diag(1, 1, 1), mech_vec3_make(NAN, 0, 0), NULL, NULL, NULL) ==
              MECH_EINVAL);
        CHECK(mech_inertia_spin(diag(1e300, 1, 1), mech_vec3_make(1e300, 0, 0), NULL, NULL, NULL) ==
              MECH_ENUMERIC);
    }

    /* 12. The later shapes, alone, body axes = scene axes: closed
     * forms about the centre of mass and the reference point's offset.
     * cone (apex at position, opens +z): about the apex I_xx = 3M(R^2/4 + h^2)/5,
     *   centre of mass 3h/4 up, so about it 3M(R^2/4 + h^2)/5 - 9Mh^2/16
     *   = 3M(4R^2 + h^2)/80; I_zz = 3MR^2/10 (the "3M(R^2/4 + h^2)/80" is
     *   not this: it would not give the degenerate h = 2R cone of the notes);
     * hemisphere (flat-face centre at position, dome +z): 2MR^2/5 about the axis,
     *   2MR^2/5 - M(3R/8)^2 = 83MR^2/320 across, centre of mass 3R/8 up;
     * tube M(3(a^2+b^2)+h^2)/12, M(a^2+b^2)/2; disc MR^2/4, MR^2/2; ring MR^2/2,
     * MR^2; plate Mb^2/12, Ma^2/12, M(a^2+b^2)/12; ellipsoid M(b^2+c^2)/5 ...;
     * torus M(R^2/2 + 5r^2/8), M(R^2 + 3r^2/4). (Each solid is also checked
     * against an independent mesh integration in test_mesh.c.) */
    {
        double Mm = 1.7, R = 0.6, h = 1.3, a = 0.25, b = 0.8, c = 1.4, Rt = 2.0, rt = 0.3;
        struct mech_vec3 p = mech_vec3_make(-1.5, 2.5, 0.75);
        struct {
            struct mech_inertia_part p;
            struct mech_mat3 want;
            double cz; /* centre of mass - position along body z */
        } cases[] = {
            {part(MECH_SHAPE_CONE, Mm, p, R, h, 0),
             diag(3 * Mm * (4 * R * R + h * h) / 80, 3 * Mm * (4 * R * R + h * h) / 80,
                  3 * Mm * R * R / 10),
             0.75 * h},
            {part(MECH_SHAPE_HEMISPHERE, Mm, p, R, 0, 0),
             diag(83 * Mm * R * R / 320, 83 * Mm * R * R / 320, 2 * Mm * R * R / 5), 3 * R / 8},
            {part(MECH_SHAPE_TUBE, Mm, p, a, b, h),
             diag(Mm * (3 * (a * a + b * b) + h * h) / 12, Mm * (3 * (a * a + b * b) + h * h) / 12,
                  Mm * (a * a + b * b) / 2),
             0},
            {part(MECH_SHAPE_DISC, Mm, p, R, 0, 0),
             diag(Mm * R * R / 4, Mm * R * R / 4, Mm * R * R / 2), 0},
            {part(MECH_SHAPE_RING, Mm, p, R, 0, 0),
             diag(Mm * R * R / 2, Mm * R * R / 2, Mm * R * R), 0},
            {part(MECH_SHAPE_PLATE, Mm, p, a, b, 0),
             diag(Mm * b * b / 12, Mm * a * a / 12, Mm * (a * a + b * b) / 12), 0},
            {part(MECH_SHAPE_ELLIPSOID, Mm, p, a, b, c),
             diag(Mm * (b * b + c * c) / 5, Mm * (a * a + c * c) / 5, Mm * (a * a + b * b) / 5), 0},
            {part(MECH_SHAPE_TORUS, Mm, p, Rt, rt, 0),
             diag(Mm * (Rt * Rt / 2 + 5 * rt * rt / 8), Mm * (Rt * Rt / 2 + 5 * rt * rt / 8),
                  Mm * (Rt * Rt + 3 * rt * rt / 4)),
             0},
        };
        struct mech_mat3 r;
        mech_rotation_from_euler_zxz(0.3, -1.1, 2.4, &r, NULL);
        double worst = 0;
        for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
            if (!compute(&cases[k].p, 1, NULL, &res)) continue;
            double scale = fmax(cases[k].want.a[0][0], cases[k].want.a[2][2]);
            worst = fmax(worst, mat_diff(res.tensor_cm, cases[k].want) / scale);
            CHECK(mat_diff(res.tensor_cm, cases[k].want) <= 1e-15 * scale);
            CHECK(res.center_of_mass.x == p.x && res.center_of_mass.y == p.y);
            CHECK_CLOSE(res.center_of_mass.z, p.z + cases[k].cz, 1e-16, 0);
            CHECK_CLOSE(res.mass, Mm, 0, 0);
            /* tilted: R^T D R about the centre of mass, which sits at p + cz R^T e_z */
            struct mech_inertia_part q = cases[k].p;
            q.orientation = r;
            if (!compute(&q, 1, NULL, &res)) continue;
            struct mech_mat3 want =
                mech_mat3_mul(mech_mat3_transpose(r), mech_mat3_mul(cases[k].want, r));
            worst = fmax(worst, mat_diff(res.tensor_cm, want) / scale);
            CHECK(mat_diff(res.tensor_cm, want) <= 1e-14 * scale);
            struct mech_vec3 cw = mech_vec3_add(p, mech_vec3_scale(row(r, 2), cases[k].cz));
            CHECK(mech_vec3_norm(mech_vec3_sub(res.center_of_mass, cw)) <= 1e-15 * 4);
        }
        printf("new shapes vs closed forms (plain and tilted): worst rel. error %.3g\n", worst);
        /* the cone with h = 2R is degenerate (notes, numerics.md) */
        struct mech_inertia_part cone = part(MECH_SHAPE_CONE, Mm, p, R, 2 * R, 0);
        if (compute(&cone, 1, NULL, &res)) {
            CHECK(res.principal.degenerate == 1);
            for (int k = 0; k < 3; k++)
                CHECK_CLOSE(res.principal.moments[k], 0.3 * Mm * R * R, 1e-15, 0);
        }
    }

    /* 13. Shapes against one another (independent of the closed forms above):
     * two hemispheres back to back = a sphere; an ellipsoid with a = b = c = a
     * sphere; a disc = the h -> 0 cylinder; a plate = the c -> 0 box; a ring =
     * the h -> 0, a -> b tube; a square plate = two right triangles. */
    {
        double Mm = 2.4, R = 0.7;
        struct mech_vec3 p = mech_vec3_make(1e3, -2e3, 0.5);
        struct mech_inertia_part hh[2] = {part(MECH_SHAPE_HEMISPHERE, Mm / 2, p, R, 0, 0),
                                          part(MECH_SHAPE_HEMISPHERE, Mm / 2, p, R, 0, 0)};
        mech_rotation_from_axis_angle(mech_vec3_make(1, 1, 0), MECH_PI, &hh[1].orientation, NULL);
        if (compute(hh, 2, NULL, &res)) {
            CHECK(mat_diff(res.tensor_cm, diag(0.4 * Mm * R * R, 0.4 * Mm * R * R,
                                               0.4 * Mm * R * R)) <= 1e-14 * Mm * R * R);
            CHECK(mech_vec3_norm(mech_vec3_sub(res.center_of_mass, p)) <= 1e-16 * 2e3 * 4);
        }
        struct mech_inertia_part el = part(MECH_SHAPE_ELLIPSOID, Mm, p, R, R, R);
        if (compute(&el, 1, NULL, &res))
            CHECK(mat_diff(res.tensor_cm, diag(0.4 * Mm * R * R, 0.4 * Mm * R * R,
                                               0.4 * Mm * R * R)) <= 1e-15 * Mm * R * R);
        struct mech_inertia disc, cyl;
        struct mech_inertia_part d = part(MECH_SHAPE_DISC, Mm, p, R, 0, 0);
        struct mech_inertia_part cy = part(MECH_SHAPE_CYLINDER, Mm, p, R, 1e-9, 0);
        if (compute(&d, 1, NULL, &disc) && compute(&cy, 1, NULL, &cyl))
            CHECK(mat_diff(disc.tensor_cm, cyl.tensor_cm) <= 1e-15 * Mm * R * R);
        struct mech_inertia_part pl = part(MECH_SHAPE_PLATE, Mm, p, 0.3, 0.9, 0);
        struct mech_inertia_part bx = part(MECH_SHAPE_BOX, Mm, p, 0.3, 0.9, 1e-9);
        struct mech_inertia rp, rbx;
        if (compute(&pl, 1, NULL, &rp) && compute(&bx, 1, NULL, &rbx))
            CHECK(mat_diff(rp.tensor_cm, rbx.tensor_cm) <= 1e-15 * Mm);
        struct mech_inertia_part rg = part(MECH_SHAPE_RING, Mm, p, R, 0, 0);
        struct mech_inertia_part tb = part(MECH_SHAPE_TUBE, Mm, p, R * (1 - 1e-9), R, 1e-9);
        if (compute(&rg, 1, NULL, &rp) && compute(&tb, 1, NULL, &rbx))
            CHECK(mat_diff(rp.tensor_cm, rbx.tensor_cm) <= 2e-9 * Mm * R * R);
        /* square plate of side s in a tilted plane, 1e3 m out, as two triangles */
        double sd = 0.8;
        struct mech_mat3 r;
        mech_rotation_from_euler_zxz(1.0, 0.6, -0.4, &r, NULL);
        struct mech_vec3 o = mech_vec3_make(1e3, 3e2, -2e3), ex = row(r, 0), ey = row(r, 1);
        struct mech_vec3 cn[4];
        for (int k = 0; k < 4; k++)
            cn[k] = mech_vec3_add(o, mech_vec3_add(mech_vec3_scale(ex, (k & 1 ? sd : 0) - sd / 2),
                                                   mech_vec3_scale(ey, (k & 2 ? sd : 0) - sd / 2)));
        struct mech_inertia_part tri[2];
        tri[0] = part(MECH_SHAPE_TRIANGLE, Mm / 2, zero, 0, 0, 0);
        tri[1] = tri[0];
        tri[0].vertices[0] = cn[0];
        tri[0].vertices[1] = cn[1];
        tri[0].vertices[2] = cn[3];
        tri[1].vertices[0] = cn[0];
        tri[1].vertices[1] = cn[3];
        tri[1].vertices[2] = cn[2];
        struct mech_inertia_part sq = part(MECH_SHAPE_PLATE, Mm, o, sd, sd, 0);
        sq.orientation = r;
        if (compute(tri, 2, NULL, &rp) && compute(&sq, 1, NULL, &rbx)) {
            double e = mat_diff(rp.tensor_cm, rbx.tensor_cm) / (Mm * sd * sd / 6);
            printf("square plate at 1e3 m as two triangles: rel. error %.3g\n", e);
            CHECK(e <= 1e-12); /* corners rounded to ulp(2e3) = 2.3e-13 m */
            CHECK(mech_vec3_norm(mech_vec3_sub(rp.center_of_mass, o)) <= 1e-12);
        }
        /* the same triangle 1e8 m out and moved back to the origin (exact
         * subtraction): distance costs nothing */
        struct mech_inertia_part t0 = tri[0];
        for (int k = 0; k < 3; k++) {
            tri[0].vertices[k] = mech_vec3_add(tri[0].vertices[k], mech_vec3_make(1e8, 3e7, -2e8));
            t0.vertices[k] = mech_vec3_sub(tri[0].vertices[k], mech_vec3_make(1e8, 3e7, -2e8));
        }
        if (compute(&tri[0], 1, NULL, &rp) && compute(&t0, 1, NULL, &rbx)) {
            double e = mat_diff(rp.tensor_cm, rbx.tensor_cm) / mat_max_abs_t(rbx.tensor_cm);
            printf("triangle at 1e8 m vs the same triangle at the origin: rel. error %.3g\n", e);
            CHECK(e <= 1e-15);
        }
        /* right triangle, legs a (x) and b (y) from the origin: about its centroid
         * (a/3, b/3): I_xx = Mb^2/18, I_yy = Ma^2/18, I_zz = M(a^2 + b^2)/18 and
         * I_xy = -M<(x - a/3)(y - b/3)> = +Mab/36 */
        double ta = 0.9, tbb = 0.4;
        struct mech_inertia_part rt = part(MECH_SHAPE_TRIANGLE, Mm, zero, 0, 0, 0);
        rt.vertices[1] = mech_vec3_make(ta, 0, 0);
        rt.vertices[2] = mech_vec3_make(0, tbb, 0);
        if (compute(&rt, 1, NULL, &rp)) {
            struct mech_mat3 want = {{{Mm * tbb * tbb / 18, Mm * ta * tbb / 36, 0},
                                      {Mm * ta * tbb / 36, Mm * ta * ta / 18, 0},
                                      {0, 0, Mm * (ta * ta + tbb * tbb) / 18}}};
            CHECK(mat_diff(rp.tensor_cm, want) <= 1e-15 * Mm);
            CHECK_CLOSE(rp.center_of_mass.x, ta / 3, 1e-15, 0);
            CHECK_CLOSE(rp.center_of_mass.y, tbb / 3, 1e-15, 0);
        }
    }

    /* 14. Holes. (a) A tube = a cylinder of radius b with a coaxial cylindrical
     * hole of radius a (masses in proportion to the areas). (b) A box a x b x c
     * (mass Mb) with a cylindrical hole of radius rh along z through x = dx:
     * hole mass mh = Mb pi rh^2/(a b); about the body's centre of mass
     * (x_cm = -mh dx/(Mb - mh)), by the parallel-axis theorem:
     * I_zz = Mb(a^2+b^2)/12 + Mb x_cm^2 - [mh rh^2/2 + mh (dx - x_cm)^2],
     * I_yy = Mb(a^2+c^2)/12 + Mb x_cm^2 - [mh(3rh^2 + c^2)/12 + mh (dx - x_cm)^2],
     * I_xx = Mb(b^2+c^2)/12 - mh(3rh^2 + c^2)/12. */
    {
        double a = 0.3, b = 0.5, h = 1.2, Mt = 2.0;
        double mb = Mt * b * b / (b * b - a * a), ma = Mt * a * a / (b * b - a * a);
        struct mech_inertia_part tp[2] = {part(MECH_SHAPE_CYLINDER, mb, zero, b, h, 0),
                                          part(MECH_SHAPE_CYLINDER, ma, zero, a, h, 0)};
        tp[1].hole = 1;
        struct mech_inertia_part tube = part(MECH_SHAPE_TUBE, Mt, zero, a, b, h);
        struct mech_inertia rt;
        if (compute(tp, 2, NULL, &res) && compute(&tube, 1, NULL, &rt)) {
            CHECK(mat_diff(res.tensor_cm, rt.tensor_cm) <= 1e-15 * 4 * rt.tensor_cm.a[0][0]);
            CHECK_CLOSE(res.mass, Mt, 1e-15, 0);
        }
        double ba = 0.6, bb = 0.4, bc = 0.25, Mb = 5.0, rh = 0.08, dx = 0.12;
        double mh = Mb * MECH_PI * rh * rh / (ba * bb);
        struct mech_vec3 o = mech_vec3_make(7, -3, 1e6);
        struct mech_inertia_part bh[2] = {
            part(MECH_SHAPE_BOX, Mb, o, ba, bb, bc),
            part(MECH_SHAPE_CYLINDER, mh, mech_vec3_add(o, mech_vec3_make(dx, 0, 0)), rh, bc, 0)};
        bh[1].hole = 1;
        struct mech_inertia_part_props pp[2];
        struct mech_budget bu = budget();
        struct mech_error e;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute_parts(bh, 2, NULL, &bu, &res, pp, &e) == MECH_OK);
        double xc = -mh * dx / (Mb - mh), dh = dx - xc;
        double izz =
            Mb * (ba * ba + bb * bb) / 12 + Mb * xc * xc - (mh * rh * rh / 2 + mh * dh * dh);
        double iyy = Mb * (ba * ba + bc * bc) / 12 + Mb * xc * xc -
                     (mh * (3 * rh * rh + bc * bc) / 12 + mh * dh * dh);
        double ixx = Mb * (bb * bb + bc * bc) / 12 - mh * (3 * rh * rh + bc * bc) / 12;
        double eh = mat_diff(res.tensor_cm, diag(ixx, iyy, izz)) / izz;
        printf("box with an off-centre cylindrical hole at 1e6 m: rel. error %.3g\n", eh);
        CHECK(eh <= 1e-14);
        CHECK_CLOSE(res.mass, Mb - mh, 1e-15, 0);
        CHECK_CLOSE(res.center_of_mass.x, o.x + xc, 1e-15, 0);
        CHECK(res.center_of_mass.z == o.z);
        /* the parts: signed mass and tensor for the hole */
        CHECK_CLOSE(pp[1].mass, -mh, 0, 0);
        CHECK_CLOSE(pp[1].tensor.a[2][2], -mh * rh * rh / 2, 1e-15, 0);
        CHECK(pp[0].mass == Mb && pp[0].tensor.a[2][2] > 0);

        /* (c) typed errors: a hole heavier than the body; a hole reaching outside
         * (a negative point mass 1 m from a small sphere: no positive density fits) */
        bh[1].mass = 2 * Mb;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(bh, 2, NULL, &bu, &res, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "bodies") == 0);
        bh[1].mass = Mb; /* exactly all of it */
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(bh, 2, NULL, &bu, &res, &e) == MECH_EDOMAIN);
        struct mech_inertia_part out2[2] = {
            part(MECH_SHAPE_SPHERE, 1, zero, 0.1, 0, 0),
            part(MECH_SHAPE_POINT, 0.1, mech_vec3_make(1, 0, 0), 0, 0, 0)};
        out2[1].hole = 1;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(out2, 2, NULL, &bu, &res, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "bodies") == 0);
        printf("hole outside: %s\n", e.text);
    }

    /* 15. The parts add up: tensor_cm = sum_i [T_i + m_i (d_i^2 1 - d_i d_i^T)],
     * mass = sum m_i, centre of mass = sum m_i c_i / M, for a body of every kind
     * of part (a hole among them), tilted, 1e5 m from the origin. */
    {
        struct mech_mat3 r;
        mech_rotation_from_euler_zxz(0.2, 0.9, -0.7, &r, NULL);
        struct mech_vec3 o = mech_vec3_make(1e5, 2e5, -1e5);
        struct mech_inertia_part pp[14];
        int np = 0;
        pp[np++] = part(MECH_SHAPE_BOX, 10, o, 1.0, 0.8, 0.6);
        pp[np++] =
            part(MECH_SHAPE_SPHERE, 0.3, mech_vec3_add(o, mech_vec3_make(0.1, 0, 0)), 0.05, 0, 0);
        pp[np - 1].hole = 1;
        pp[np++] =
            part(MECH_SHAPE_CONE, 1.2, mech_vec3_add(o, mech_vec3_make(0, 0, 0.3)), 0.2, 0.5, 0);
        pp[np++] = part(MECH_SHAPE_HEMISPHERE, 0.7, mech_vec3_add(o, mech_vec3_make(0.5, 0, 0)),
                        0.3, 0, 0);
        pp[np++] = part(MECH_SHAPE_TUBE, 0.4, mech_vec3_add(o, mech_vec3_make(-0.5, 0.2, 0)), 0.1,
                        0.2, 0.4);
        pp[np++] =
            part(MECH_SHAPE_DISC, 0.2, mech_vec3_add(o, mech_vec3_make(0, 0.4, 0)), 0.3, 0, 0);
        pp[np++] =
            part(MECH_SHAPE_RING, 0.1, mech_vec3_add(o, mech_vec3_make(0, -0.4, 0)), 0.3, 0, 0);
        pp[np++] =
            part(MECH_SHAPE_PLATE, 0.3, mech_vec3_add(o, mech_vec3_make(0, 0, -0.3)), 0.5, 0.2, 0);
        pp[np++] = part(MECH_SHAPE_ELLIPSOID, 0.9, mech_vec3_add(o, mech_vec3_make(0.2, 0.2, 0.2)),
                        0.1, 0.2, 0.3);
        pp[np++] = part(MECH_SHAPE_TORUS, 0.5, mech_vec3_add(o, mech_vec3_make(-0.2, 0, 0.4)), 0.3,
                        0.05, 0);
        pp[np++] =
            part(MECH_SHAPE_ROD, 0.2, mech_vec3_add(o, mech_vec3_make(0.4, 0.4, 0)), 1, 0, 0);
        pp[np++] =
            part(MECH_SHAPE_POINT, 0.05, mech_vec3_add(o, mech_vec3_make(0.6, 0.6, 0.6)), 0, 0, 0);
        pp[np] = part(MECH_SHAPE_TRIANGLE, 0.15, zero, 0, 0, 0);
        pp[np].vertices[0] = mech_vec3_add(o, mech_vec3_make(0.5, 0, 0.5));
        pp[np].vertices[1] = mech_vec3_add(o, mech_vec3_make(0, 0.5, 0.5));
        pp[np].vertices[2] = mech_vec3_add(o, mech_vec3_make(0.5, 0.5, 0.7));
        np++;
        for (int k = 0; k < np; k++)
            if (k % 2) pp[k].orientation = r;
        struct mech_inertia_part_props props[14];
        struct mech_budget bu = budget();
        struct mech_error e;
        mech_error_clear(&e);
        CHECK(mech_inertia_compute_parts(pp, (size_t)np, NULL, &bu, &res, props, &e) == MECH_OK);
        double msum = 0;
        struct mech_vec3 csum = {0, 0, 0};
        struct mech_mat3 tsum = {{{0}}};
        for (int k = 0; k < np; k++) {
            msum += props[k].mass;
            csum = mech_vec3_add(
                csum, mech_vec3_scale(mech_vec3_sub(props[k].center_of_mass, o), props[k].mass));
            struct mech_vec3 dd = mech_vec3_sub(props[k].center_of_mass, res.center_of_mass);
            double dv[3] = {dd.x, dd.y, dd.z}, d2 = mech_vec3_dot(dd, dd);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    tsum.a[i][j] +=
                        props[k].tensor.a[i][j] + props[k].mass * ((i == j) * d2 - dv[i] * dv[j]);
        }
        CHECK(props[1].mass == -0.3);
        CHECK_CLOSE(msum, res.mass, 1e-15, 0);
        CHECK(mech_vec3_norm(mech_vec3_sub(mech_vec3_scale(csum, 1 / msum),
                                           mech_vec3_sub(res.center_of_mass, o))) <= 1e-10);
        double es = mat_diff(tsum, res.tensor_cm) / res.principal.moments[2];
        printf("parts add up to the total: rel. error %.3g\n", es);
        CHECK(es <= 1e-10); /* offsets of ~1 m recomputed from coordinates of 2e5 m */
    }

    /* 16. Typed errors of the new shapes. */
    {
        struct mech_budget b = budget();
        struct mech_error e;
        struct mech_inertia_part tb = part(MECH_SHAPE_TUBE, 1, zero, 0.5, 0.5, 1);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&tb, 1, NULL, &b, &res, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "bodies/0/inner_radius") == 0);
        tb.dim[0] = 0; /* a = 0 is a cylinder */
        if (compute(&tb, 1, NULL, &res)) CHECK_CLOSE(res.tensor_cm.a[2][2], 0.125, 1e-15, 0);
        struct mech_inertia_part to = part(MECH_SHAPE_TORUS, 1, zero, 0.5, 0.5, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&to, 1, NULL, &b, &res, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "bodies/0/minor_radius") == 0);
        struct mech_inertia_part tr = part(MECH_SHAPE_TRIANGLE, 1, zero, 0, 0, 0);
        tr.vertices[0] = mech_vec3_make(1e6, 1e6, 1e6);
        tr.vertices[1] = mech_vec3_make(1e6 + 1, 1e6 + 2, 1e6 + 3);
        tr.vertices[2] = mech_vec3_make(1e6 + 2, 1e6 + 4, 1e6 + 6); /* collinear */
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&tr, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/vertices") == 0);
        tr.vertices[2] = tr.vertices[1]; /* coincident */
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&tr, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        struct mech_inertia_part cn = part(MECH_SHAPE_CONE, 1, zero, 1, 0, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&cn, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/height") == 0);
        struct mech_inertia_part el = part(MECH_SHAPE_ELLIPSOID, 1, zero, 1, NAN, 1);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&el, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/semi_axes") == 0);
        struct mech_inertia_part pl = part(MECH_SHAPE_PLATE, 1, zero, 1, 0, 0);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&pl, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/size") == 0);
        struct mech_inertia_part bad = part((enum mech_inertia_shape)99, 1, zero, 1, 1, 1);
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(&bad, 1, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/0/shape") == 0);
    }

    printf("axes: worst orthonormality/handedness defect %.3g; worst eigen-residual / largest "
           "moment (non-degenerate tensors) %.3g\n",
           worst_axes, worst_resid);
    TEST_MAIN_END();
}
