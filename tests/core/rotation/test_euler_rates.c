/* test_euler_rates.c — mech_euler_kinematics and mech_euler_rates_from_omega
 * (core/rotation/euler_rates.c): ch. 0 HW 7 (a turn about z at rate w: dR/dt(0) =
 * w [[0,1,0],[-1,0,0],[0,0,0]], omega = w z); for random angles and rates,
 * dR/dt against a Richardson-extrapolated central difference of R(t) built by
 * mech_rotation_from_euler_zxz (an independent construction), omega_body read
 * off that difference as -dR/dt R^T, omega_space = R^T omega_body; the inverse
 * map recovering the rates; gimbal lock at theta = 0 and pi (finite answers,
 * the combination phi' +- psi', the impossible omega refused) and near it. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rotation/euler_rates.h"
#include "mech/base/constants.h"
#include "mech/rotation/rotation.h"
#include "testlib.h"

static struct mech_mat3 r_at(const double a[3], const double d[3], double t)
{
    struct mech_mat3 r;
    struct mech_error e;
    mech_rotation_from_euler_zxz(a[0] + d[0] * t, a[1] + d[1] * t, a[2] + d[2] * t, &r, &e);
    return r;
}

static struct mech_mat3 fd(const double a[3], const double d[3], double h)
{
    struct mech_mat3 p = r_at(a, d, h), m = r_at(a, d, -h), out;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) out.a[i][j] = (p.a[i][j] - m.a[i][j]) / (2 * h);
    return out;
}

static void test_hw7(void)
{
    const double w = 2.5, a[3] = {0, 0, 0}, d[3] = {w, 0, 0};
    struct mech_euler_kinematics k;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK(mech_euler_kinematics(a, d, &k, &e) == MECH_OK);
    const double want[3][3] = {{0, w, 0}, {-w, 0, 0}, {0, 0, 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK_CLOSE(k.rotation_rate.a[i][j], want[i][j], 0, 1e-15);
    CHECK_CLOSE(k.omega_space.z, w, 0, 0);
    CHECK_CLOSE(k.omega_body.z, w, 0, 0);
    CHECK_CLOSE(k.omega_cross_space.a[1][0], w, 0, 0); /* [w z]x has (1,0) = w */
    CHECK(k.gimbal_lock);
}

static void test_random(void)
{
    unsigned long s = 99;
    struct mech_error e;
    for (int n = 0; n < 200; n++) {
        double r[6];
        for (int k = 0; k < 6; k++) {
            s = s * 6364136223846793005UL + 1442695040888963407UL;
            r[k] = (double)(s >> 11) / 9007199254740992.0 * 2 - 1;
        }
        double a[3] = {3 * r[0], 0.2 + 1.3 * (r[1] + 1), 3 * r[2]}, d[3] = {r[3], r[4], r[5]};
        struct mech_euler_kinematics k;
        CHECK(mech_euler_kinematics(a, d, &k, &e) == MECH_OK);
        struct mech_mat3 r0 = r_at(a, d, 0), d1 = fd(a, d, 1e-3), d2 = fd(a, d, 5e-4);
        double worst = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                CHECK_CLOSE(k.rotation.a[i][j], r0.a[i][j], 0, 1e-15);
                double rich = (4 * d2.a[i][j] - d1.a[i][j]) / 3;
                worst = fmax(worst, fabs(k.rotation_rate.a[i][j] - rich));
            }
        CHECK(worst < 1e-11);
        /* omega_body from the difference quotient alone: [w]x = -Rdot R^T */
        struct mech_mat3 rich;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) rich.a[i][j] = (4 * d2.a[i][j] - d1.a[i][j]) / 3;
        struct mech_mat3 wx = mech_mat3_mul(rich, mech_mat3_transpose(r0));
        CHECK_CLOSE(k.omega_body.x, -wx.a[2][1], 0, 1e-11);
        CHECK_CLOSE(k.omega_body.y, -wx.a[0][2], 0, 1e-11);
        CHECK_CLOSE(k.omega_body.z, -wx.a[1][0], 0, 1e-11);
        struct mech_vec3 ws = mech_mat3_mul_vec(mech_mat3_transpose(r0), k.omega_body);
        CHECK_CLOSE(k.omega_space.x, ws.x, 0, 1e-15);
        CHECK_CLOSE(k.omega_space.y, ws.y, 0, 1e-15);
        CHECK_CLOSE(k.omega_space.z, ws.z, 0, 1e-15);
        CHECK(k.residual < 1e-15);
        CHECK(!k.gimbal_lock);
        /* inverse, from body and from space components */
        struct mech_euler_kinematics kb, ks;
        CHECK(mech_euler_rates_from_omega(a, k.omega_body, 1, &kb, NULL, &e) == MECH_OK);
        CHECK(mech_euler_rates_from_omega(a, k.omega_space, 0, &ks, NULL, &e) == MECH_OK);
        for (int j = 0; j < 3; j++) {
            CHECK_CLOSE(kb.rates[j], d[j], 0, 1e-14);
            CHECK_CLOSE(ks.rates[j], d[j], 0, 1e-14);
        }
    }
}

static void test_lock(void)
{
    struct mech_euler_kinematics k, ki;
    struct mech_error e;
    double comb = -1;
    mech_error_clear(&e);
    /* theta = pi: w3 = psi' - phi' = 3 - 1 = 2 */
    const double a[3] = {0.3, MECH_PI, 0.2}, d[3] = {1, 0.5, 3};
    CHECK(mech_euler_kinematics(a, d, &k, &e) == MECH_OK);
    CHECK(k.gimbal_lock);
    CHECK_CLOSE(k.omega_body.z, 2, 0, 1e-15);
    CHECK(mech_euler_rates_from_omega(a, k.omega_body, 1, &ki, &comb, &e) == MECH_OK);
    CHECK(ki.gimbal_lock);
    CHECK_CLOSE(comb, 2, 0, 1e-15);
    CHECK_CLOSE(ki.rates[1], 0.5, 0, 1e-15);
    CHECK_CLOSE(ki.omega_body.x, k.omega_body.x, 0, 1e-15);
    CHECK_CLOSE(ki.omega_body.y, k.omega_body.y, 0, 1e-15);
    /* theta = 0: omega along the line normal to the nodes cannot be reached */
    const double a0[3] = {0, 0, MECH_PI / 2};
    CHECK(mech_euler_rates_from_omega(a0, mech_vec3_make(1, 0, 0), 1, &ki, &comb, &e) ==
          MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "omega_body"));
    /* near the lock: finite and consistent */
    const double an[3] = {0.1, 1e-9, 0.4};
    CHECK(mech_euler_rates_from_omega(an, mech_vec3_make(0.3, -0.2, 1), 1, &ki, NULL, &e) ==
          MECH_OK);
    CHECK(!ki.gimbal_lock);
    CHECK_CLOSE(ki.omega_body.x, 0.3, 0, 1e-15);
    CHECK_CLOSE(ki.omega_body.y, -0.2, 0, 1e-15);
    CHECK_CLOSE(ki.omega_body.z, 1, 0, 1e-15);
    /* errors */
    const double bad[3] = {0, NAN, 0};
    mech_error_clear(&e);
    CHECK(mech_euler_kinematics(bad, d, &k, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "euler_zxz"));
    const double badr[3] = {0, INFINITY, 0};
    mech_error_clear(&e);
    CHECK(mech_euler_kinematics(a, badr, &k, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "rates"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_hw7();
    test_random();
    test_lock();
    TEST_MAIN_END();
}
