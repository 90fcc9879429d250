/* test_rotation.c — the four orientation forms of mech/rotation.h agree on the
 * passive convention of the notes (ch. 0, §2.6), and bad input gets typed errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rotation.h"
#include "testlib.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double max_diff(struct mech_mat3 a, struct mech_mat3 b)
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(a.a[i][j] - b.a[i][j]));
    return d;
}

static double orth_err(struct mech_mat3 r)
{
    struct mech_mat3 p = mech_mat3_mul(r, mech_mat3_transpose(r));
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(p.a[i][j] - (i == j)));
    return d;
}

/* Elementary passive rotations of the notes (ch. 0, §2.6). */
static struct mech_mat3 rz(double a)
{
    struct mech_mat3 m = {{{cos(a), sin(a), 0}, {-sin(a), cos(a), 0}, {0, 0, 1}}};
    return m;
}
static struct mech_mat3 rx(double a)
{
    struct mech_mat3 m = {{{1, 0, 0}, {0, cos(a), sin(a)}, {0, -sin(a), cos(a)}}};
    return m;
}

/* Hamilton product p q. */
static void qmul(const double p[4], const double q[4], double r[4])
{
    r[0] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
    r[1] = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2];
    r[2] = p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1];
    r[3] = p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0];
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_mat3 r, r2;
    struct mech_error e;

    /* 1. 120 degrees about (1,1,1): the notes' homework 0.5/6. The axes turn
     * x -> y -> z -> x, so the new x axis is the old y, etc.: R = [[0,1,0],[0,0,1],[1,0,0]].
     * Euler: row 2 = (sin th sin ph, -sin th cos ph, cos th) = (1,0,0) -> th = ph = pi/2;
     * row 0, col 2 = sin ps sin th = 0 -> ps = 0. Quaternion (cos 60, sin 60 (1,1,1)/sqrt3) =
     * (1,1,1,1)/2. */
    {
        struct mech_mat3 want = {{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}};
        CHECK(mech_rotation_from_matrix(want, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        CHECK(mech_rotation_from_euler_zxz(M_PI / 2, M_PI / 2, 0, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(1, 1, 1), 2 * M_PI / 3, &r, NULL) ==
              MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        double q[4] = {0.5, 0.5, 0.5, 0.5};
        CHECK(mech_rotation_from_quaternion(q, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        double qs[4] = {-3, -3, -3, -3}; /* -q and any length: same rotation */
        CHECK(mech_rotation_from_quaternion(qs, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        /* passive: the old y axis (0,1,0) has components (1,0,0) in the new axes */
        struct mech_vec3 v = mech_mat3_mul_vec(want, mech_vec3_make(0, 1, 0));
        CHECK(v.x == 1 && v.y == 0 && v.z == 0);
    }

    /* 2. A general turn given four ways. Euler (0.3, 1.1, -0.7): product of the
     * notes' elementary matrices R_psi R_theta R_phi; the same turn as the
     * quaternion q_z(phi) q_x(theta) q_z(psi) (intrinsic turns compose on the
     * right) and its axis-angle 2 atan2(|v|, w) about v. */
    {
        double ph = 0.3, th = 1.1, ps = -0.7;
        struct mech_mat3 want = mech_mat3_mul(rz(ps), mech_mat3_mul(rx(th), rz(ph)));
        double qa[4] = {cos(ph / 2), 0, 0, sin(ph / 2)}, qb[4] = {cos(th / 2), sin(th / 2), 0, 0};
        double qc[4] = {cos(ps / 2), 0, 0, sin(ps / 2)}, t[4], q[4];
        qmul(qa, qb, t);
        qmul(t, qc, q);
        double vn = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        double ang = 2 * atan2(vn, q[0]);
        CHECK(mech_rotation_from_euler_zxz(ph, th, ps, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        CHECK(mech_rotation_from_quaternion(q, &r2, NULL) == MECH_OK);
        CHECK(max_diff(r2, want) <= 1e-15);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(q[1], q[2], q[3]), ang, &r2, NULL) ==
              MECH_OK);
        CHECK(max_diff(r2, want) <= 1e-15);
        CHECK(mech_rotation_from_matrix(want, &r2, NULL) == MECH_OK);
        CHECK(max_diff(r2, want) <= 1e-15);
        CHECK(orth_err(r) <= 4e-16);
        /* det +1 */
        double det = r.a[0][0] * (r.a[1][1] * r.a[2][2] - r.a[1][2] * r.a[2][1]) -
                     r.a[0][1] * (r.a[1][0] * r.a[2][2] - r.a[1][2] * r.a[2][0]) +
                     r.a[0][2] * (r.a[1][0] * r.a[2][1] - r.a[1][1] * r.a[2][0]);
        CHECK_CLOSE(det, 1.0, 0, 4e-16);
    }

    /* 3. Single elementary turns: about z by phi equals the notes' R_phi; about
     * x equals R_theta; euler (phi, 0, 0) equals R_phi. */
    {
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(0, 0, 2.5), 0.4, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, rz(0.4)) <= 1e-16);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(1e-300, 0, 0), -1.3, &r, NULL) ==
              MECH_OK); /* tiny axis normalises without underflow */
        CHECK(max_diff(r, rx(-1.3)) <= 4e-16);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(1e300, 0, 0), -1.3, &r, NULL) ==
              MECH_OK); /* huge axis: no overflow */
        CHECK(max_diff(r, rx(-1.3)) <= 4e-16);
        CHECK(mech_rotation_from_euler_zxz(0.4, 0, 0, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, rz(0.4)) <= 1e-16);
        /* theta = 0: only phi + psi matters (gimbal lock), still a rotation */
        CHECK(mech_rotation_from_euler_zxz(0.25, 0, 0.15, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, rz(0.4)) <= 2e-16);
        /* tiny angle: 1 - cos computed as 2 sin^2(a/2) */
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(1, 1, 0), 1e-9, &r, NULL) == MECH_OK);
        CHECK_CLOSE(r.a[0][1], 0.5 * 2 * sin(0.5e-9) * sin(0.5e-9), 1e-15, 0);
        CHECK_CLOSE(r.a[0][2], -1e-9 / sqrt(2.0), 1e-15, 0);
    }

    /* 4. Matrix validation: polish of a 1e-10-perturbed rotation; refusals. */
    {
        struct mech_mat3 m = rz(0.7);
        m.a[0][0] += 1e-10;
        CHECK(mech_rotation_from_matrix(m, &r, NULL) == MECH_OK);
        CHECK(orth_err(r) <= 3e-16);
        CHECK(max_diff(r, rz(0.7)) <= 1e-10);

        struct mech_mat3 bad = rz(0.7);
        bad.a[1][1] += 1e-6;
        mech_error_clear(&e);
        CHECK(mech_rotation_from_matrix(bad, &r, &e) == MECH_EINVAL);
        CHECK(e.code == MECH_EINVAL && strcmp(e.param, "matrix") == 0);

        struct mech_mat3 refl = {{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}};
        mech_error_clear(&e);
        CHECK(mech_rotation_from_matrix(refl, &r, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "matrix") == 0);

        struct mech_mat3 nan = mech_mat3_identity();
        nan.a[2][1] = NAN;
        mech_error_clear(&e);
        CHECK(mech_rotation_from_matrix(nan, &r, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "matrix") == 0);

        struct mech_mat3 zero = {{{0}}};
        CHECK(mech_rotation_from_matrix(zero, &r, NULL) == MECH_EINVAL);
    }

    /* 5. Other typed errors. */
    {
        mech_error_clear(&e);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(0, 0, 0), 1, &r, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "axis") == 0);
        mech_error_clear(&e);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(1, 0, 0), INFINITY, &r, &e) ==
              MECH_EINVAL);
        CHECK(strcmp(e.param, "angle") == 0);
        mech_error_clear(&e);
        double qz[4] = {0, 0, 0, 0};
        CHECK(mech_rotation_from_quaternion(qz, &r, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "quaternion") == 0);
        mech_error_clear(&e);
        CHECK(mech_rotation_from_euler_zxz(NAN, 0, 0, &r, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "euler_zxz") == 0);
        double qt[4] = {1e-300, 0, 0, 1e-300}; /* tiny quaternion: 90 degrees about z */
        CHECK(mech_rotation_from_quaternion(qt, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, rz(M_PI / 2)) <= 2e-16);
    }

    /* 6. Many random turns: all four forms agree, orthonormal to round-off. */
    {
        double worst = 0, worst_orth = 0;
        unsigned long s = 12345;
        for (int k = 0; k < 2000; k++) {
            double u[3];
            for (int i = 0; i < 3; i++) {
                s = s * 6364136223846793005UL + 1442695040888963407UL;
                u[i] = (double)(s >> 11) / 9007199254740992.0;
            }
            double ph = 2 * M_PI * u[0] - M_PI, th = M_PI * u[1], ps = 2 * M_PI * u[2] - M_PI;
            struct mech_mat3 want = mech_mat3_mul(rz(ps), mech_mat3_mul(rx(th), rz(ph)));
            double qa[4] = {cos(ph / 2), 0, 0, sin(ph / 2)};
            double qb[4] = {cos(th / 2), sin(th / 2), 0, 0};
            double qc[4] = {cos(ps / 2), 0, 0, sin(ps / 2)}, t[4], q[4];
            qmul(qa, qb, t);
            qmul(t, qc, q);
            double vn = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            mech_rotation_from_euler_zxz(ph, th, ps, &r, NULL);
            worst = fmax(worst, max_diff(r, want));
            worst_orth = fmax(worst_orth, orth_err(r));
            mech_rotation_from_quaternion(q, &r, NULL);
            worst = fmax(worst, max_diff(r, want));
            worst_orth = fmax(worst_orth, orth_err(r));
            if (vn > 1e-3) {
                mech_rotation_from_axis_angle(mech_vec3_make(q[1], q[2], q[3]), 2 * atan2(vn, q[0]),
                                              &r, NULL);
                worst = fmax(worst, max_diff(r, want));
                worst_orth = fmax(worst_orth, orth_err(r));
            }
        }
        printf("random turns: max |R_form - R_euler| = %.3g, max |R R^T - 1| = %.3g\n", worst,
               worst_orth);
        CHECK(worst <= 1e-15);
        CHECK(worst_orth <= 2e-15);
    }
    TEST_MAIN_END();
}
