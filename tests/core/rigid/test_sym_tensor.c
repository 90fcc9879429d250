/* test_sym_tensor.c — mech_sym_tensor_analyse (core/rigid/sym_tensor.c): the notes'
 * cube about a corner (eigenvalues M a^2 (1/6, 11/12, 11/12), the degenerate
 * pair compared as a subspace: normal to (1,1,1)); tensors built as
 * Q diag(l) Q^T from a known rotation and known eigenvalues, some negative;
 * for random symmetric tensors T v = l v, orthonormal right-handed axes and the
 * invariants against the eigenvalues' elementary symmetric functions and the
 * determinant by the permutation sum; scaling to 1e100 and 1e-100; the
 * isotropic/deviatoric split; and the errors (asymmetric entry named, NaN). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rotation/rotation.h"
#include "mech/rigid/sym_tensor.h"
#include "testlib.h"

static double det_perm(struct mech_mat3 m)
{
    static const int p[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    double s = 0;
    for (int k = 0; k < 6; k++)
        s += (k < 3 ? 1 : -1) * m.a[0][p[k][0]] * m.a[1][p[k][1]] * m.a[2][p[k][2]];
    return s;
}

static void check_eigen(const struct mech_sym_tensor *r, struct mech_mat3 t, double tol)
{
    double big = fmax(fabs(r->principal.moments[0]), fabs(r->principal.moments[2]));
    for (int k = 0; k < 3; k++) {
        struct mech_vec3 v = mech_vec3_make(r->principal.axes.a[k][0], r->principal.axes.a[k][1],
                                            r->principal.axes.a[k][2]);
        struct mech_vec3 tv = mech_mat3_mul_vec(t, v);
        struct mech_vec3 res = mech_vec3_sub(tv, mech_vec3_scale(v, r->principal.moments[k]));
        CHECK(mech_vec3_norm(res) <= tol * big);
        for (int j = 0; j < 3; j++) {
            struct mech_vec3 w = mech_vec3_make(r->principal.axes.a[j][0],
                                                r->principal.axes.a[j][1],
                                                r->principal.axes.a[j][2]);
            CHECK_CLOSE(mech_vec3_dot(v, w), j == k, 0, 1e-15);
        }
    }
    CHECK_CLOSE(det_perm(r->principal.axes), 1, 0, 1e-15); /* right-handed */
    const double *l = r->principal.moments;
    CHECK(l[0] <= l[1] && l[1] <= l[2]);
    CHECK_CLOSE(r->invariants[0], l[0] + l[1] + l[2], 0, tol * big);
    CHECK_CLOSE(r->invariants[1], l[0] * l[1] + l[1] * l[2] + l[0] * l[2], 0, 3 * tol * big * big);
    CHECK_CLOSE(r->invariants[2], l[0] * l[1] * l[2], 0, 3 * tol * big * big * big);
    CHECK_CLOSE(r->invariants[2], det_perm(t), 0, 4e-16 * 6 * big * big * big);
}

/* Notes ch. 2, "Example: Cube Rotating about a Corner": about a corner the
 * tensor is M a^2 [[2/3, -1/4, -1/4], [-1/4, 2/3, -1/4], [-1/4, -1/4, 2/3]];
 * eigenvalues M a^2/6 (axis the diagonal) and 11 M a^2/12 twice. */
static void test_cube_corner(void)
{
    struct mech_mat3 t = {{{2.0 / 3, -0.25, -0.25}, {-0.25, 2.0 / 3, -0.25}, {-0.25, -0.25, 2.0 / 3}}};
    struct mech_sym_tensor r;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_sym_tensor_analyse(t, &r, &e) == MECH_OK);
    CHECK_CLOSE(r.principal.moments[0], 1.0 / 6, 1e-15, 0);
    CHECK_CLOSE(r.principal.moments[1], 11.0 / 12, 1e-15, 0);
    CHECK_CLOSE(r.principal.moments[2], 11.0 / 12, 1e-15, 0);
    CHECK(r.principal.degenerate);
    double s = 1 / sqrt(3);
    for (int j = 0; j < 3; j++) CHECK_CLOSE(r.principal.axes.a[0][j], s, 1e-15, 0);
    /* the degenerate pair spans the plane normal to the diagonal */
    for (int k = 1; k < 3; k++)
        CHECK_CLOSE(r.principal.axes.a[k][0] + r.principal.axes.a[k][1] + r.principal.axes.a[k][2],
                    0, 0, 1e-15);
    CHECK_CLOSE(r.trace, 2, 1e-15, 0);
    /* I2 = 3 (4/9 - 1/16), I3 = (1/6)(11/12)^2 */
    CHECK_CLOSE(r.invariants[1], 3 * (4.0 / 9 - 1.0 / 16), 1e-15, 0);
    CHECK_CLOSE(r.invariants[2], (1.0 / 6) * (121.0 / 144), 1e-15, 0);
    check_eigen(&r, t, 4e-15);
    CHECK_CLOSE(r.isotropic, 2.0 / 3, 1e-15, 0);
    CHECK_CLOSE(r.deviator.a[0][0], 0, 0, 1e-16);
    CHECK_CLOSE(r.deviator.a[0][1], -0.25, 0, 0);
}

/* Q diag(l) Q^T with Q from z-x-z (0.3, 1.1, -0.7): eigenvalues l ascending, the
 * eigenvector of l_k is row k of Q^T's transpose, i.e. column k of Q, up to sign;
 * then the same tensor times 1e100 and 1e-100. */
static void test_known(void)
{
    struct mech_mat3 q;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_rotation_from_euler_zxz(0.3, 1.1, -0.7, &q, &e) == MECH_OK);
    const double l[3] = {-3, 1, 7};
    const double scale[3] = {1, 1e100, 1e-100};
    for (int sc = 0; sc < 3; sc++) {
        struct mech_mat3 t;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double s = 0;
                for (int k = 0; k < 3; k++) s += q.a[i][k] * l[k] * q.a[j][k];
                t.a[i][j] = s * scale[sc];
            }
        for (int i = 0; i < 3; i++) /* exactly symmetric input */
            for (int j = 0; j < i; j++) t.a[i][j] = t.a[j][i];
        struct mech_sym_tensor r;
        CHECK(mech_sym_tensor_analyse(t, &r, &e) == MECH_OK);
        for (int k = 0; k < 3; k++) {
            CHECK_CLOSE(r.principal.moments[k], l[k] * scale[sc], 0, 1e-14 * scale[sc]);
            double d = 0;
            for (int j = 0; j < 3; j++) d += r.principal.axes.a[k][j] * q.a[j][k];
            CHECK_CLOSE(fabs(d), 1, 0, 1e-14);
        }
        CHECK(!r.principal.degenerate);
        CHECK_CLOSE(r.trace, 5 * scale[sc], 1e-14, 0);
        CHECK_CLOSE(r.invariants[1], (-3 + 7 - 21) * scale[sc] * scale[sc], 1e-14, 0);
        CHECK_CLOSE(r.invariants[2], -21 * scale[sc] * scale[sc] * scale[sc], 1e-14, 0);
        check_eigen(&r, t, 4e-15);
    }
}

static void test_random(void)
{
    unsigned long s = 777;
    struct mech_error e;
    for (int n = 0; n < 300; n++) {
        struct mech_mat3 t;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j <= i; j++) {
                s = s * 6364136223846793005UL + 1442695040888963407UL;
                t.a[i][j] = t.a[j][i] = (double)(s >> 11) / 9007199254740992.0 * 2 - 1;
            }
        struct mech_sym_tensor r;
        CHECK(mech_sym_tensor_analyse(t, &r, &e) == MECH_OK);
        check_eigen(&r, t, 8e-15);
    }
}

static void test_degenerate_and_errors(void)
{
    struct mech_sym_tensor r;
    struct mech_error e;
    struct mech_mat3 iso = {{{5, 0, 0}, {0, 5, 0}, {0, 0, 5}}};
    mech_error_clear(&e);
    CHECK(mech_sym_tensor_analyse(iso, &r, &e) == MECH_OK);
    CHECK(r.principal.degenerate);
    CHECK(r.principal.axes.a[0][0] == 1 && r.principal.axes.a[1][1] == 1);
    CHECK(r.deviator.a[0][0] == 0 && r.isotropic == 5);
    struct mech_mat3 zero = {{{0}}};
    CHECK(mech_sym_tensor_analyse(zero, &r, &e) == MECH_OK);
    CHECK(r.principal.degenerate && r.invariants[2] == 0);
    struct mech_mat3 asym = {{{1, 2, 0}, {2.001, 1, 0}, {0, 0, 1}}};
    CHECK(mech_sym_tensor_analyse(asym, &r, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "tensor/1/0"));
    struct mech_mat3 asym2 = {{{1, 2, 3}, {2, 1, 0}, {3, 1e-6, 1}}};
    mech_error_clear(&e);
    CHECK(mech_sym_tensor_analyse(asym2, &r, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "tensor/2/1"));
    struct mech_mat3 nan = {{{1, 0, 0}, {0, NAN, 0}, {0, 0, 1}}};
    mech_error_clear(&e);
    CHECK(mech_sym_tensor_analyse(nan, &r, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "tensor"));
    /* round-off asymmetry is accepted and reported */
    struct mech_mat3 near = {{{1, 2, 0}, {2 + 4e-16, 1, 0}, {0, 0, 1}}};
    CHECK(mech_sym_tensor_analyse(near, &r, &e) == MECH_OK);
    CHECK(r.asymmetry > 0 && r.asymmetry < 1e-15);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_cube_corner();
    test_known();
    test_random();
    test_degenerate_and_errors();
    TEST_MAIN_END();
}
