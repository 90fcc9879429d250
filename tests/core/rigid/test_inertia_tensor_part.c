/* test_inertia_tensor_part.c — MECH_SHAPE_TENSOR parts of mech_inertia_compute
 * (core/rigid/inertia.c): a box given by its own tensor (from the table formula),
 * turned and placed, against the same box given as a box part (a second
 * route through the code: body_form and R^T diag R); a dumbbell of two tensor
 * parts against the parallel-axis theorem by hand; and the errors (asymmetric,
 * unrealisable, NaN). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/budget.h"
#include "mech/rigid/inertia.h"
#include "mech/rotation/rotation.h"
#include "testlib.h"

static struct mech_budget budget(void)
{
    return mech_budget_make(1000000, 60);
}

static void test_box_two_ways(void)
{
    const double m = 3, a = 0.4, b = 0.3, c = 0.2;
    struct mech_mat3 r;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_rotation_from_euler_zxz(0.5, 0.3, -1.1, &r, &e) == MECH_OK);
    struct mech_inertia_part box, ten;
    memset(&box, 0, sizeof box);
    memset(&ten, 0, sizeof ten);
    box.shape = MECH_SHAPE_BOX;
    box.mass = m;
    box.dim[0] = a, box.dim[1] = b, box.dim[2] = c;
    box.position = mech_vec3_make(1, -2, 0.5);
    box.orientation = r;
    ten.shape = MECH_SHAPE_TENSOR;
    ten.mass = m;
    ten.position = box.position;
    ten.orientation = r;
    ten.tensor = (struct mech_mat3){{{m * (b * b + c * c) / 12, 0, 0},
                                     {0, m * (a * a + c * c) / 12, 0},
                                     {0, 0, m * (a * a + b * b) / 12}}};
    struct mech_budget bu = budget();
    struct mech_inertia i1, i2;
    struct mech_vec3 o = mech_vec3_make(0, 0, 0);
    CHECK(mech_inertia_compute(&box, 1, &o, &bu, &i1, &e) == MECH_OK);
    CHECK(mech_inertia_compute(&ten, 1, &o, &bu, &i2, &e) == MECH_OK);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            CHECK_CLOSE(i2.tensor.a[i][j], i1.tensor.a[i][j], 0, 1e-15);
            CHECK_CLOSE(i2.tensor_cm.a[i][j], i1.tensor_cm.a[i][j], 0, 1e-16);
        }
}

/* Two parts of mass 2 at (0, 0, +-1), each with its own tensor diag(0.1, 0.2,
 * 0.3): about the common centre, I = 2 diag(0.1, 0.2, 0.3) + 2 * 2 * (1, 1, 0)
 * (parallel axis, d = (0, 0, +-1): d^2 1 - d d^T = diag(1, 1, 0)). */
static void test_dumbbell(void)
{
    struct mech_inertia_part p[2];
    memset(p, 0, sizeof p);
    for (int k = 0; k < 2; k++) {
        p[k].shape = MECH_SHAPE_TENSOR;
        p[k].mass = 2;
        p[k].position = mech_vec3_make(0, 0, k ? 1 : -1);
        p[k].orientation = mech_mat3_identity();
        p[k].tensor = (struct mech_mat3){{{0.1, 0, 0}, {0, 0.2, 0}, {0, 0, 0.3}}};
    }
    struct mech_budget bu = budget();
    struct mech_inertia in;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_inertia_compute(p, 2, NULL, &bu, &in, &e) == MECH_OK);
    CHECK_CLOSE(in.tensor.a[0][0], 0.2 + 4, 1e-15, 0);
    CHECK_CLOSE(in.tensor.a[1][1], 0.4 + 4, 1e-15, 0);
    CHECK_CLOSE(in.tensor.a[2][2], 0.6, 1e-15, 0);
    CHECK_CLOSE(in.tensor.a[0][1], 0, 0, 0);
}

static void test_errors(void)
{
    struct mech_inertia_part p;
    memset(&p, 0, sizeof p);
    p.shape = MECH_SHAPE_TENSOR;
    p.mass = 1;
    p.orientation = mech_mat3_identity();
    struct mech_budget bu = budget();
    struct mech_inertia in;
    struct mech_error e;
    p.tensor = (struct mech_mat3){{{1, 0.1, 0}, {0.2, 1, 0}, {0, 0, 1}}};
    mech_error_clear(&e);
    CHECK(mech_inertia_compute(&p, 1, NULL, &bu, &in, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "bodies/0/tensor"));
    p.tensor = (struct mech_mat3){{{1, 0, 0}, {0, 1, 0}, {0, 0, 5}}}; /* 5 > 1 + 1 */
    mech_error_clear(&e);
    CHECK(mech_inertia_compute(&p, 1, NULL, &bu, &in, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "bodies/0/tensor"));
    p.tensor = (struct mech_mat3){{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    mech_error_clear(&e);
    CHECK(mech_inertia_compute(&p, 1, NULL, &bu, &in, &e) == MECH_EDOMAIN);
    p.tensor = (struct mech_mat3){{{1, 0, 0}, {0, NAN, 0}, {0, 0, 1}}};
    mech_error_clear(&e);
    CHECK(mech_inertia_compute(&p, 1, NULL, &bu, &in, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "bodies/0/tensor"));
    /* a rod's tensor (0 along its axis) is realisable: the bound holds with equality */
    p.tensor = (struct mech_mat3){{{1, 0, 0}, {0, 1, 0}, {0, 0, 0}}};
    CHECK(mech_inertia_compute(&p, 1, NULL, &bu, &in, &e) == MECH_OK);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_box_two_ways();
    test_dumbbell();
    test_errors();
    TEST_MAIN_END();
}
