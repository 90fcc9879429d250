/* test_rotation.c — the four orientation forms of mech/rotation/rotation.h agree on the
 * passive convention of the notes (ch. 0, §2.6), and bad input gets typed errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rotation/rotation.h"
#include "mech/base/constants.h"
#include "testlib.h"

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

/* ---- sequences, conversions, composition ---------------------------------- */

/* Elementary ACTIVE rotation about axis ax (0 = x, 1 = y, 2 = z), built here
 * independently of the library: the vector is turned right-handedly. */
static struct mech_mat3 act(int ax, double a)
{
    double c = cos(a), s = sin(a);
    struct mech_mat3 m = mech_mat3_identity();
    int i = (ax + 1) % 3, j = (ax + 2) % 3;
    m.a[i][i] = c;
    m.a[i][j] = -s;
    m.a[j][i] = s;
    m.a[j][j] = c;
    return m;
}

/* Passive matrix of a sequence from elementary matrices (rotation.h convention). */
static struct mech_mat3 seq_passive(const char *name, int intrinsic, const double ang[3])
{
    struct mech_mat3 a = mech_mat3_identity();
    for (int m = 0; m < 3; m++) {
        struct mech_mat3 e = act(name[m] - 'X', ang[m]);
        a = intrinsic ? mech_mat3_mul(a, e) : mech_mat3_mul(e, a);
    }
    return mech_mat3_transpose(a);
}

static double urand(unsigned long *s)
{
    *s = *s * 6364136223846793005UL + 1442695040888963407UL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static double qdiff(const double a[4], const double b[4])
{
    double d = 0;
    for (int i = 0; i < 4; i++)
        d = fmax(d, fabs(a[i] - b[i]));
    return d;
}

static double angdiff(double a, double b)
{
    double d = fmod(fabs(a - b), 2 * MECH_PI);
    return fmin(d, 2 * MECH_PI - d);
}

static void test_issue4(void)
{
    struct mech_mat3 r;
    struct mech_error e;
    unsigned long seed = 777;

    /* 7. All 24 sequences against products of elementary matrices, and the
     * notes' z-x-z equals ZXZ intrinsic; extrinsic (i,j,k) = intrinsic (k,j,i)
     * with the angles reversed. */
    {
        double worst = 0, worst_rt = 0, worst_ang = 0;
        for (int k = 0; k < 200; k++) {
            double ang[3] = {2 * MECH_PI * urand(&seed) - MECH_PI, 0, 2 * MECH_PI * urand(&seed) - MECH_PI};
            for (int sq = 0; sq < MECH_EULER_SEQUENCE_COUNT; sq++) {
                const char *nm = mech_euler_sequence_name((enum mech_euler_sequence)sq);
                int proper = nm[0] == nm[2];
                ang[1] = proper ? MECH_PI * urand(&seed) : MECH_PI * urand(&seed) - MECH_PI / 2;
                for (int intr = 0; intr < 2; intr++) {
                    struct mech_mat3 want = seq_passive(nm, intr, ang);
                    CHECK(mech_rotation_from_euler((enum mech_euler_sequence)sq, intr, ang, &r,
                                                   NULL) == MECH_OK);
                    worst = fmax(worst, max_diff(r, want));
                    /* back to angles: the same angles (they are in the canonical ranges) */
                    double q[4];
                    struct mech_euler_angles ea;
                    CHECK(mech_quaternion_from_matrix(want, MECH_ROTATION_PASSIVE, q, NULL) ==
                          MECH_OK);
                    CHECK(mech_quaternion_to_euler(q, (enum mech_euler_sequence)sq, intr, &ea,
                                                   NULL) == MECH_OK);
                    struct mech_mat3 back = seq_passive(nm, intr, ea.angles);
                    worst_rt = fmax(worst_rt, max_diff(back, want));
                    /* individual angles are ill-conditioned like 1/lock_distance */
                    double cond = fmax(1.0, 1.0 / sin(ea.lock_distance));
                    for (int m = 0; m < 3; m++)
                        worst_ang = fmax(worst_ang, angdiff(ea.angles[m], ang[m]) / cond);
                    CHECK(!ea.gimbal_lock);
                }
            }
        }
        double zxz[3] = {0.3, 1.1, -0.7};
        struct mech_mat3 a, b;
        mech_rotation_from_euler_zxz(zxz[0], zxz[1], zxz[2], &a, NULL);
        mech_rotation_from_euler(MECH_EULER_ZXZ, 1, zxz, &b, NULL);
        CHECK(max_diff(a, b) <= 6e-16);
        double rev[3] = {zxz[2], zxz[1], zxz[0]};
        mech_rotation_from_euler(MECH_EULER_ZXZ, 0, rev, &b, NULL);
        CHECK(max_diff(a, b) <= 6e-16);
        double xyz[3] = {0.4, -0.2, 1.3}, zyx[3] = {1.3, -0.2, 0.4};
        mech_rotation_from_euler(MECH_EULER_XYZ, 0, xyz, &a, NULL);
        mech_rotation_from_euler(MECH_EULER_ZYX, 1, zyx, &b, NULL);
        CHECK(max_diff(a, b) <= 6e-16);
        printf("24 sequences: |R - elementary product| = %.3g, round trip |R' - R| = %.3g, "
               "angle error x sin(lock distance) = %.3g\n",
               worst, worst_rt, worst_ang);
        CHECK(worst <= 1e-15);
        CHECK(worst_rt <= 2e-15);
        CHECK(worst_ang <= 4e-15);
    }

    /* 8. Shepperd: matrix -> quaternion everywhere, including 180 degrees and the
     * identity; the active sense gives the same quaternion from R^T. */
    {
        double worst = 0;
        for (int k = 0; k < 3000; k++) {
            double q[4] = {urand(&seed) - 0.5, urand(&seed) - 0.5, urand(&seed) - 0.5,
                           urand(&seed) - 0.5};
            if (k % 3 == 0) q[0] = 0;               /* exactly 180 degrees */
            if (k % 3 == 1) q[0] *= 1e-9;           /* near 180 degrees */
            if (k % 7 == 0) q[1] = q[2] = q[3] = 0; /* identity */
            if (k % 7 == 0 && q[0] == 0) q[0] = 1;
            double qc[4] = {q[0], q[1], q[2], q[3]}, q2[4], q3[4];
            CHECK(mech_quaternion_canonical(qc, NULL) == MECH_OK);
            CHECK(mech_rotation_from_quaternion(q, &r, NULL) == MECH_OK);
            CHECK(mech_quaternion_from_matrix(r, MECH_ROTATION_PASSIVE, q2, NULL) == MECH_OK);
            CHECK(mech_quaternion_from_matrix(mech_mat3_transpose(r), MECH_ROTATION_ACTIVE, q3,
                                              NULL) == MECH_OK);
            worst = fmax(worst, fmax(qdiff(q2, qc), qdiff(q3, qc)));
            CHECK(q2[0] >= 0);
        }
        printf("Shepperd round trip: max |q' - q| = %.3g\n", worst);
        CHECK(worst <= 1e-15);
        /* tie rule at w = 0: first non-zero of x, y, z positive */
        double qt[4] = {0, 0, -3, 4};
        CHECK(mech_quaternion_canonical(qt, NULL) == MECH_OK);
        CHECK(qt[0] == 0 && qt[1] == 0 && qt[2] == 0.6 && qt[3] == -0.8);
        /* a rotation by pi about (0, -1, 0) given as a matrix: w = 0 exactly */
        struct mech_mat3 ry = {{{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}};
        double q[4];
        CHECK(mech_quaternion_from_matrix(ry, MECH_ROTATION_PASSIVE, q, NULL) == MECH_OK);
        CHECK(q[0] == 0 && q[1] == 0 && q[2] == 1 && q[3] == 0);
        /* refusals carry param "matrix" */
        struct mech_mat3 refl = {{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}};
        mech_error_clear(&e);
        CHECK(mech_quaternion_from_matrix(refl, MECH_ROTATION_PASSIVE, q, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "matrix") == 0);
    }

    /* 9. Axis-angle and rotation vector. */
    {
        double q[4], ang;
        struct mech_vec3 ax;
        CHECK(mech_quaternion_from_axis_angle(mech_vec3_make(2, 2, 2), 2 * MECH_PI / 3, q, NULL) ==
              MECH_OK);
        CHECK(qdiff(q, (double[4]){0.5, 0.5, 0.5, 0.5}) <= 2e-16);
        CHECK(mech_quaternion_to_axis_angle(q, &ax, &ang, NULL) == MECH_OK);
        CHECK_CLOSE(ang, 2 * MECH_PI / 3, 2e-16, 0);
        CHECK_CLOSE(ax.x, 1 / sqrt(3.0), 2e-16, 0);
        /* negative angle: the same turn as |angle| about -axis; angle in [0, pi] */
        CHECK(mech_quaternion_from_axis_angle(mech_vec3_make(0, 0, 1), -0.5, q, NULL) == MECH_OK);
        CHECK(mech_quaternion_to_axis_angle(q, &ax, &ang, NULL) == MECH_OK);
        CHECK_CLOSE(ang, 0.5, 2e-16, 0);
        CHECK(ax.x == 0 && ax.y == 0 && ax.z == -1);
        /* angle 0: axis arbitrary, [0, 0, 1] */
        double id[4] = {1, 0, 0, 0};
        CHECK(mech_quaternion_to_axis_angle(id, &ax, &ang, NULL) == MECH_OK);
        CHECK(ang == 0 && ax.z == 1);
        /* tiny rotation vector keeps full relative precision */
        CHECK(mech_quaternion_from_rotation_vector(mech_vec3_make(3e-9, -4e-9, 0), q, NULL) ==
              MECH_OK);
        CHECK(mech_quaternion_to_axis_angle(q, &ax, &ang, NULL) == MECH_OK);
        CHECK_CLOSE(ang, 5e-9, 1e-15, 0);
        CHECK_CLOSE(ax.x, 0.6, 1e-15, 0);
        CHECK_CLOSE(ax.y, -0.8, 1e-15, 0);
        /* rotation vector (0, 0, pi/2) passive = the notes' R_phi with phi = pi/2 */
        CHECK(mech_quaternion_from_rotation_vector(mech_vec3_make(0, 0, MECH_PI / 2), q, NULL) ==
              MECH_OK);
        mech_rotation_matrix_of_quaternion(q, MECH_ROTATION_PASSIVE, &r, NULL);
        CHECK(max_diff(r, rz(MECH_PI / 2)) <= 2e-16);
        mech_rotation_matrix_of_quaternion(q, MECH_ROTATION_ACTIVE, &r, NULL);
        CHECK(max_diff(r, act(2, MECH_PI / 2)) <= 2e-16);
        /* angle near pi keeps accuracy: 2 atan2(|v|, w) */
        CHECK(mech_quaternion_from_axis_angle(mech_vec3_make(1, 0, 0), MECH_PI - 1e-9, q, NULL) ==
              MECH_OK);
        CHECK(mech_quaternion_to_axis_angle(q, &ax, &ang, NULL) == MECH_OK);
        CHECK_CLOSE(ang, MECH_PI - 1e-9, 2e-16, 0);
        mech_error_clear(&e);
        CHECK(mech_quaternion_from_rotation_vector(mech_vec3_make(NAN, 0, 0), q, &e) ==
              MECH_EINVAL);
        CHECK(strcmp(e.param, "rotation_vector") == 0);
    }

    /* 10. Gimbal lock, z-x-z: near it (theta = 1e-9, pi - 1e-9) the three angles
     * come back from the Euler input to round-off; at it (theta = 0, pi) the
     * lock is flagged with the branch psi = 0 and the combination phi + psi
     * (resp. phi - psi); the combination is continuous through the lock. */
    {
        double q[4];
        struct mech_euler_angles ea;
        double near[2] = {1e-9, MECH_PI - 1e-9};
        for (int n = 0; n < 2; n++) {
            double in[3] = {0.7, near[n], -0.4};
            mech_quaternion_from_euler(MECH_EULER_ZXZ, 1, in, q, NULL);
            CHECK(mech_quaternion_to_euler(q, MECH_EULER_ZXZ, 1, &ea, NULL) == MECH_OK);
            CHECK(!ea.gimbal_lock);
            CHECK_CLOSE(ea.angles[0], 0.7, 4e-15, 0);
            CHECK_CLOSE(ea.angles[1], near[n], 1e-15, 0);
            CHECK_CLOSE(ea.angles[2], -0.4, 4e-15, 0);
            CHECK_CLOSE(ea.lock_distance, 1e-9, 1e-6, 0); /* pi - (pi - 1e-9) rounds */
            CHECK_EQ_INT(ea.combination_sign, n == 0 ? 1 : -1);
            CHECK_CLOSE(ea.combination, n == 0 ? 0.3 : 1.1, 4e-15, 0);
            /* from the matrix instead: the combination stays exact, the matrix is
             * reproduced; the individual angles lose ~1e-16/1e-9 */
            mech_rotation_from_euler_zxz(in[0], in[1], in[2], &r, NULL);
            mech_quaternion_from_matrix(r, MECH_ROTATION_PASSIVE, q, NULL);
            mech_quaternion_to_euler(q, MECH_EULER_ZXZ, 1, &ea, NULL);
            CHECK_CLOSE(ea.combination, n == 0 ? 0.3 : 1.1, 4e-15, 0);
            struct mech_mat3 back;
            mech_rotation_from_euler_zxz(ea.angles[0], ea.angles[1], ea.angles[2], &back, NULL);
            CHECK(max_diff(back, r) <= 1e-15);
            CHECK(fabs(ea.angles[0] - 0.7) <= 1e-6);
        }
        double at[2] = {0, MECH_PI};
        for (int n = 0; n < 2; n++) {
            double in[3] = {0.7, at[n], -0.4};
            mech_quaternion_from_euler(MECH_EULER_ZXZ, 1, in, q, NULL);
            CHECK(mech_quaternion_to_euler(q, MECH_EULER_ZXZ, 1, &ea, NULL) == MECH_OK);
            CHECK(ea.gimbal_lock);
            CHECK(ea.angles[2] == 0);
            CHECK_CLOSE(ea.angles[0], n == 0 ? 0.3 : 1.1, 4e-15, 0);
            CHECK_CLOSE(ea.angles[1], at[n], 1e-15, 0);
            struct mech_mat3 back, want;
            mech_rotation_from_euler_zxz(ea.angles[0], ea.angles[1], ea.angles[2], &back, NULL);
            mech_rotation_from_euler_zxz(in[0], in[1], in[2], &want, NULL);
            CHECK(max_diff(back, want) <= 1e-15);
        }
        /* continuity in phi + psi as theta -> 0 through the lock threshold */
        double worst = 0;
        for (double th = 1e-3; th > 1e-18; th *= 0.1) {
            double in[3] = {2.0, th, 1.5};
            mech_quaternion_from_euler(MECH_EULER_ZXZ, 1, in, q, NULL);
            mech_quaternion_to_euler(q, MECH_EULER_ZXZ, 1, &ea, NULL);
            worst = fmax(worst, angdiff(ea.combination, 3.5));
            CHECK(ea.gimbal_lock == (th <= MECH_EULER_LOCK_TOL));
        }
        printf("phi + psi through the lock: max error %.3g\n", worst);
        CHECK(worst <= 4e-15);
    }

    /* 11. Every sequence at both of its locks: the flagged combination is the
     * one the matrix determines (built independently), and the branch
     * reproduces the matrix. */
    {
        double worst = 0;
        for (int sq = 0; sq < MECH_EULER_SEQUENCE_COUNT; sq++) {
            const char *nm = mech_euler_sequence_name((enum mech_euler_sequence)sq);
            int proper = nm[0] == nm[2];
            double locks[2] = {proper ? 0 : MECH_PI / 2, proper ? MECH_PI : -MECH_PI / 2};
            for (int intr = 0; intr < 2; intr++)
                for (int l = 0; l < 2; l++) {
                    double a0[3] = {0.3, locks[l], 0.5};
                    double plus[3] = {0.5, locks[l], 0.3};  /* same a0 + a2 */
                    double minus[3] = {0.5, locks[l], 0.7}; /* same a0 - a2 */
                    struct mech_mat3 m0 = seq_passive(nm, intr, a0);
                    int sign = max_diff(seq_passive(nm, intr, plus), m0) < 1e-12 ? 1 : -1;
                    CHECK(max_diff(seq_passive(nm, intr, sign > 0 ? plus : minus), m0) < 1e-12);
                    double q[4];
                    struct mech_euler_angles ea;
                    mech_quaternion_from_matrix(m0, MECH_ROTATION_PASSIVE, q, NULL);
                    CHECK(mech_quaternion_to_euler(q, (enum mech_euler_sequence)sq, intr, &ea,
                                                   NULL) == MECH_OK);
                    CHECK(ea.gimbal_lock);
                    CHECK_EQ_INT(ea.combination_sign, sign);
                    CHECK_CLOSE(ea.combination, sign > 0 ? 0.8 : -0.2, 0, 1e-15);
                    CHECK(ea.angles[2] == 0);
                    worst = fmax(worst, max_diff(seq_passive(nm, intr, ea.angles), m0));
                }
        }
        printf("24 sequences at their locks: branch reproduces R to %.3g\n", worst);
        CHECK(worst <= 1e-15);
    }

    /* 12. Composition. Passive, "first the first": turning the axes by phi about
     * z, then theta about the new x, then psi about the new z is the notes' z-x-z
     * R = R_psi R_theta R_phi. Active: turning a vector about fixed axes, first
     * A1 then A2, is A2 A1. */
    {
        double ph = 0.3, th = 1.1, ps = -0.7, qs[3][4], out[4];
        struct mech_budget bud = mech_budget_make(100000, 10);
        mech_quaternion_from_axis_angle(mech_vec3_make(0, 0, 1), ph, qs[0], NULL);
        mech_quaternion_from_axis_angle(mech_vec3_make(1, 0, 0), th, qs[1], NULL);
        mech_quaternion_from_axis_angle(mech_vec3_make(0, 0, 1), ps, qs[2], NULL);
        CHECK(mech_rotation_compose((const double(*)[4])qs, 3, MECH_ROTATION_PASSIVE, out, &bud,
                                    NULL) == MECH_OK);
        struct mech_mat3 want;
        mech_rotation_matrix_of_quaternion(out, MECH_ROTATION_PASSIVE, &r, NULL);
        mech_rotation_from_euler_zxz(ph, th, ps, &want, NULL);
        CHECK(max_diff(r, want) <= 1e-15);
        CHECK(max_diff(r, mech_mat3_mul(rz(ps), mech_mat3_mul(rx(th), rz(ph)))) <= 1e-15);
        CHECK(mech_rotation_compose((const double(*)[4])qs, 3, MECH_ROTATION_ACTIVE, out, &bud,
                                    NULL) == MECH_OK);
        mech_rotation_matrix_of_quaternion(out, MECH_ROTATION_ACTIVE, &r, NULL);
        want = mech_mat3_mul(act(2, ps), mech_mat3_mul(act(0, th), act(2, ph)));
        CHECK(max_diff(r, want) <= 1e-15);
        /* 100000 turns of 1e-5 rad about z: 1 rad, no drift off the unit sphere */
        static double many[100000][4];
        for (int k = 0; k < 100000; k++)
            mech_quaternion_from_axis_angle(mech_vec3_make(0, 0, 1), 1e-5, many[k], NULL);
        CHECK(mech_rotation_compose((const double(*)[4])many, 100000, MECH_ROTATION_PASSIVE, out,
                                    &bud, NULL) == MECH_OK);
        double ang;
        struct mech_vec3 ax;
        mech_quaternion_to_axis_angle(out, &ax, &ang, NULL);
        printf("100000 small turns: angle error %.3g\n", fabs(ang - 1.0));
        CHECK_CLOSE(ang, 1.0, 1e-11, 0);
        struct mech_budget tiny = mech_budget_make(10, 10);
        mech_error_clear(&e);
        CHECK(mech_rotation_compose((const double(*)[4])many, 100, MECH_ROTATION_PASSIVE, out,
                                    &tiny, &e) == MECH_EBUDGET);
        double bad[2][4] = {{1, 0, 0, 0}, {0, 0, 0, 0}};
        mech_error_clear(&e);
        CHECK(mech_rotation_compose((const double(*)[4])bad, 2, MECH_ROTATION_PASSIVE, out, &bud,
                                    &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "rotations/1") == 0);
    }

    /* 13. Residuals and tensor rotation. */
    {
        double orth, det;
        mech_rotation_residuals(mech_mat3_identity(), &orth, &det);
        CHECK(orth == 0 && det == 0);
        struct mech_mat3 s = {{{2, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        mech_rotation_residuals(s, &orth, &det);
        CHECK(orth == 3 && det == 1);
        /* R diag(1,2,3) R^T for R = the notes' R_phi: closed form */
        struct mech_mat3 t = {{{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}};
        double f = 0.4, c = cos(f), sn = sin(f);
        struct mech_mat3 tp = mech_rotation_apply_tensor(rz(f), t);
        CHECK_CLOSE(tp.a[0][0], c * c + 2 * sn * sn, 1e-15, 0);
        CHECK_CLOSE(tp.a[0][1], -c * sn + 2 * sn * c, 1e-15, 0);
        CHECK_CLOSE(tp.a[1][1], sn * sn + 2 * c * c, 1e-15, 0);
        CHECK(tp.a[2][2] == 3);
    }

    /* 14. Every form round-trips through the quaternion (random turns). */
    {
        double worst = 0;
        for (int k = 0; k < 1000; k++) {
            double q[4] = {urand(&seed) - 0.5, urand(&seed) - 0.5, urand(&seed) - 0.5,
                           urand(&seed) - 0.5},
                   q2[4], ang;
            mech_quaternion_canonical(q, NULL);
            struct mech_vec3 ax;
            mech_quaternion_to_axis_angle(q, &ax, &ang, NULL);
            mech_quaternion_from_axis_angle(ax, ang, q2, NULL);
            worst = fmax(worst, qdiff(q, q2));
            mech_quaternion_from_rotation_vector(mech_vec3_scale(ax, ang), q2, NULL);
            worst = fmax(worst, qdiff(q, q2));
            for (int sq = 0; sq < MECH_EULER_SEQUENCE_COUNT; sq++)
                for (int intr = 0; intr < 2; intr++) {
                    struct mech_euler_angles ea;
                    mech_quaternion_to_euler(q, (enum mech_euler_sequence)sq, intr, &ea, NULL);
                    mech_quaternion_from_euler((enum mech_euler_sequence)sq, intr, ea.angles, q2,
                                               NULL);
                    worst = fmax(worst, qdiff(q, q2));
                }
        }
        printf("forms round trip: max |q' - q| = %.3g\n", worst);
        CHECK(worst <= 2e-15);
        enum mech_euler_sequence sq;
        mech_error_clear(&e);
        CHECK(mech_euler_sequence_find("ZXZ", &sq, NULL) == MECH_OK && sq == MECH_EULER_ZXZ);
        CHECK(mech_euler_sequence_find("zxz", &sq, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "sequence") == 0);
        CHECK(mech_euler_sequence_find("ZXZZ", &sq, NULL) == MECH_EINVAL);
        CHECK(mech_euler_sequence_find("ZZX", &sq, NULL) == MECH_EINVAL);
    }
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
        CHECK(mech_rotation_from_euler_zxz(MECH_PI / 2, MECH_PI / 2, 0, &r, NULL) == MECH_OK);
        CHECK(max_diff(r, want) <= 1e-15);
        CHECK(mech_rotation_from_axis_angle(mech_vec3_make(1, 1, 1), 2 * MECH_PI / 3, &r, NULL) ==
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
        CHECK(max_diff(r, rz(MECH_PI / 2)) <= 2e-16);
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
            double ph = 2 * MECH_PI * u[0] - MECH_PI, th = MECH_PI * u[1], ps = 2 * MECH_PI * u[2] - MECH_PI;
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
    test_issue4();
    TEST_MAIN_END();
}
