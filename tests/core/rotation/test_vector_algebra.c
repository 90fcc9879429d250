/* test_vector_algebra.c — mech_vector_pair and mech_vector_triple
 * (core/rotation/vector_algebra.c) against closed forms and second methods: the notes'
 * ch. 0 homework 1 worked by hand, the antisymmetric tensor entry by entry
 * (a_i b_j - a_j b_i) and back through eps_ijk, angles of nearly parallel and
 * antiparallel vectors against atan of the exact ratio, vectors at 1e-200 and
 * 1e150 against the same vectors at unit scale, triple products against the
 * determinant (Sarrus) and b(a.c) - c(a.b), the notes' identity
 * (A x B) x (C x D) = ((A x B).D) C - ((A x B).C) D, and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rotation/vector_algebra.h"
#include "mech/base/constants.h"
#include "testlib.h"

static struct mech_vec3 v3(double x, double y, double z) { return mech_vec3_make(x, y, z); }

static void check_vec(struct mech_vec3 got, struct mech_vec3 want, double rtol, double atol)
{
    CHECK_CLOSE(got.x, want.x, rtol, atol);
    CHECK_CLOSE(got.y, want.y, rtol, atol);
    CHECK_CLOSE(got.z, want.z, rtol, atol);
}

/* Notes ch. 0 HW 1: A = x + 3y - 2z, B = 2x + y + z. By hand: A.B = 2 + 3 - 2 = 3;
 * |A| = sqrt 14, |B| = sqrt 6; A x B = (3*1 - (-2)*1, (-2)*2 - 1*1, 1*1 - 3*2) =
 * (5, -5, -5); component of B along A = 3/sqrt 14; angle = acos(3/sqrt 84)
 * (acos is accurate here, far from 0 and pi); (A + B) x (A - B) = -2 A x B. */
static void test_notes_hw1(void)
{
    struct mech_vector_pair p;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_vector_pair(v3(1, 3, -2), v3(2, 1, 1), &p, &e) == MECH_OK);
    CHECK_CLOSE(p.dot, 3, 0, 0);
    check_vec(p.cross, v3(5, -5, -5), 0, 0);
    CHECK_CLOSE(p.norm_a, sqrt(14), 1e-16, 0);
    CHECK_CLOSE(p.norm_b, sqrt(6), 1e-16, 0);
    CHECK(p.has_angle);
    CHECK_CLOSE(p.angle, acos(3 / sqrt(84)), 4e-16, 0);
    CHECK_CLOSE(p.b_along_a, 3 / sqrt(14), 4e-16, 0);
    CHECK_CLOSE(p.a_along_b, 3 / sqrt(6), 4e-16, 0);
    check_vec(p.b_on_a, v3(3.0 / 14, 9.0 / 14, -6.0 / 14), 4e-16, 0);
    check_vec(p.b_across_a, v3(2 - 3.0 / 14, 1 - 9.0 / 14, 1 + 6.0 / 14), 4e-16, 1e-16);
    /* the part across is normal to A */
    CHECK_CLOSE(mech_vec3_dot(p.b_across_a, v3(1, 3, -2)), 0, 0, 1e-15);
    /* tensor form, entry by entry, and back: L_k = eps_ijk T_ij / 2 */
    double a[3] = {1, 3, -2}, b[3] = {2, 1, 1};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_CLOSE(p.cross_tensor.a[i][j], a[i] * b[j] - a[j] * b[i], 0, 0);
    const struct mech_mat3 t = p.cross_tensor;
    CHECK_CLOSE((t.a[1][2] - t.a[2][1]) / 2, p.cross.x, 0, 0);
    CHECK_CLOSE((t.a[2][0] - t.a[0][2]) / 2, p.cross.y, 0, 0);
    CHECK_CLOSE((t.a[0][1] - t.a[1][0]) / 2, p.cross.z, 0, 0);
    struct mech_vector_pair q;
    CHECK(mech_vector_pair(v3(3, 4, -1), v3(-1, 2, -3), &q, &e) == MECH_OK);
    check_vec(q.cross, v3(-10, 10, 10), 0, 0);
}

/* Nearly parallel and antiparallel: a = x, b = (+-1, d, 0): the angle is
 * atan(d) resp. pi - atan(d); acos(a.b/|a||b|) would give 0 for d = 1e-12. */
static void test_near_parallel(void)
{
    struct mech_vector_pair p;
    struct mech_error e;
    for (double d = 1e-3; d > 1e-300; d *= 1e-7) {
        CHECK(mech_vector_pair(v3(1, 0, 0), v3(1, d, 0), &p, &e) == MECH_OK);
        CHECK_CLOSE(p.angle, atan(d), 2e-16, 0);
        CHECK(mech_vector_pair(v3(2, 0, 0), v3(-1, d, 0), &p, &e) == MECH_OK);
        CHECK_CLOSE(p.angle, MECH_PI - atan(d), 2e-16, 0);
    }
    CHECK(mech_vector_pair(v3(1, 1, 1), v3(1, 1, 1 + 0x1p-52), &p, &e) == MECH_OK);
    /* |a x b| = 2^-52 sqrt 2, a.b = 3 + 2^-52: angle = atan(2^-52 sqrt2/(3 + 2^-52)) */
    CHECK_CLOSE(p.angle, 0x1p-52 * sqrt(2) / 3, 1e-15, 0);
}

/* Scale invariance far outside the naive range: (1,2,-2) and (3,0,4) times s. */
static void test_extremes(void)
{
    const double s[] = {1e-200, 1e-150, 1e150, 1e-300};
    struct mech_vector_pair ref, p;
    struct mech_error e;
    CHECK(mech_vector_pair(v3(1, 2, -2), v3(3, 0, 4), &ref, &e) == MECH_OK);
    CHECK_CLOSE(ref.dot, -5, 0, 0);
    check_vec(ref.cross, v3(8, -10, -6), 0, 0);
    for (int k = 0; k < 4; k++) {
        CHECK(mech_vector_pair(v3(s[k], 2 * s[k], -2 * s[k]), v3(3 * s[k], 0, 4 * s[k]), &p, &e) ==
              MECH_OK);
        CHECK(p.has_angle);
        CHECK_CLOSE(p.angle, ref.angle, 4e-16, 0);
        CHECK_CLOSE(p.norm_a / s[k], 3, 4e-16, 0);
        CHECK_CLOSE(p.norm_b / s[k], 5, 4e-16, 0);
        CHECK_CLOSE(p.b_along_a / s[k], -5.0 / 3, 4e-16, 0);
        CHECK_CLOSE(p.b_on_a.y / s[k], -10.0 / 9, 4e-16, 0);
    }
    CHECK(mech_vector_pair(v3(1e150, 2e150, -2e150), v3(3e150, 0, 4e150), &p, &e) == MECH_OK);
    CHECK_CLOSE(p.dot, -5e300, 4e-16, 0);
    check_vec(p.cross, v3(8e300, -10e300, -6e300), 4e-16, 0);
    /* mixed: a tiny, b huge: the products are ordinary numbers */
    CHECK(mech_vector_pair(v3(1e-200, 2e-200, -2e-200), v3(3e200, 0, 4e200), &p, &e) == MECH_OK);
    CHECK_CLOSE(p.dot, -5, 4e-16, 0);
    check_vec(p.cross, v3(8, -10, -6), 4e-16, 0);
}

static double det3(struct mech_vec3 a, struct mech_vec3 b, struct mech_vec3 c)
{ /* Sarrus */
    return a.x * b.y * c.z + a.y * b.z * c.x + a.z * b.x * c.y - a.z * b.y * c.x -
           a.y * b.x * c.z - a.x * b.z * c.y;
}

static void test_triple(void)
{
    struct mech_error e;
    unsigned long s = 12345;
    for (int n = 0; n < 200; n++) {
        double r[9];
        for (int k = 0; k < 9; k++) {
            s = s * 6364136223846793005UL + 1442695040888963407UL;
            r[k] = (double)(s >> 11) / 9007199254740992.0 * 2 - 1;
        }
        struct mech_vec3 a = v3(r[0], r[1], r[2]), b = v3(r[3], r[4], r[5]), c = v3(r[6], r[7], r[8]);
        double sc, sc2;
        struct mech_vec3 vt;
        CHECK(mech_vector_triple(a, b, c, &sc, &vt, &e) == MECH_OK);
        CHECK_CLOSE(sc, det3(a, b, c), 0, 1e-15);
        CHECK(mech_vector_triple(b, c, a, &sc2, NULL, &e) == MECH_OK);
        CHECK_CLOSE(sc2, sc, 0, 1e-15);
        struct mech_vec3 bac = mech_vec3_sub(mech_vec3_scale(b, mech_vec3_dot(a, c)),
                                             mech_vec3_scale(c, mech_vec3_dot(a, b)));
        check_vec(vt, bac, 0, 2e-15);
    }
    /* notes ch. 0 HW 4: (A x B) x (C x D) = ((A x B).D) C - ((A x B).C) D */
    struct mech_vec3 A = v3(1, 3, -2), B = v3(2, 1, 1), C = v3(0, 1, 4), D = v3(-3, 2, 1);
    struct mech_vec3 AB = mech_vec3_cross(A, B), vt;
    CHECK(mech_vector_triple(AB, C, D, NULL, &vt, &e) == MECH_OK);
    check_vec(vt, mech_vec3_sub(mech_vec3_scale(C, mech_vec3_dot(AB, D)),
                                mech_vec3_scale(D, mech_vec3_dot(AB, C))), 0, 0);
    /* huge and tiny: determinant of diag(1e100, 1e100, 1e100) and of 1e-150 rows */
    double sc;
    CHECK(mech_vector_triple(v3(1e100, 0, 0), v3(0, 1e100, 0), v3(0, 0, 1e100), &sc, NULL, &e) ==
          MECH_OK);
    CHECK_CLOSE(sc, 1e300, 4e-16, 0);
    CHECK(mech_vector_triple(v3(1e-150, 0, 0), v3(0, 2e150, 0), v3(1, 1, 3), &sc, NULL, &e) ==
          MECH_OK);
    CHECK_CLOSE(sc, 6, 4e-16, 0);
}

static void test_errors(void)
{
    struct mech_vector_pair p;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_vector_pair(v3(NAN, 0, 0), v3(1, 0, 0), &p, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "a"));
    mech_error_clear(&e);
    CHECK(mech_vector_pair(v3(1, 0, 0), v3(0, INFINITY, 0), &p, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "b"));
    mech_error_clear(&e);
    CHECK(mech_vector_pair(v3(1e200, 0, 0), v3(1e200, 0, 0), &p, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "b"));
    mech_error_clear(&e);
    CHECK(mech_vector_triple(v3(1e150, 0, 0), v3(0, 1e150, 0), v3(0, 0, 1e150), NULL, NULL, &e) ==
          MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "c"));
    /* the zero vector: no angle, no component, but dot and cross are 0 */
    CHECK(mech_vector_pair(v3(0, 0, 0), v3(1, 2, 3), &p, &e) == MECH_OK);
    CHECK(!p.has_angle);
    CHECK(p.dot == 0 && p.cross.x == 0 && p.norm_a == 0);
}

/* a - b, a + b and |a - b|: the 3-4-5 triangle at 1, 1e-300 (where squaring
 * the components underflows) and 1e150 */
static void test_difference(void)
{
    const double scales[] = {1, 1e-300, 1e150};
    for (int i = 0; i < 3; i++) {
        double k = scales[i];
        struct mech_vector_pair p;
        struct mech_error e;
        mech_error_clear(&e);
        CHECK(mech_vector_pair(mech_vec3_make(3 * k, 1 * k, 0), mech_vec3_make(0, 5 * k, 0), &p,
                               &e) == MECH_OK);
        CHECK_CLOSE(p.difference.x, 3 * k, 1e-16, 0);
        CHECK_CLOSE(p.difference.y, -4 * k, 1e-16, 0);
        CHECK(p.difference.z == 0);
        CHECK_CLOSE(p.sum.y, 6 * k, 2e-16, 0);
        CHECK_CLOSE(p.distance, 5 * k, 2e-16, 0);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    test_notes_hw1();
    test_near_parallel();
    test_extremes();
    test_triple();
    test_difference();
    test_errors();
    TEST_MAIN_END();
}
