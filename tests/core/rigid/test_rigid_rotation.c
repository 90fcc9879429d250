/* test_rigid_rotation.c — mech/rotation/attitude.h and mech/rigid/rigid_rotation.h:
 * quaternion helpers against core/rotation/rotation.c; the exact torque-free solution
 * checked independently (it satisfies Euler's equations by central
 * differences, keeps L^2 and 2E, starts at w0), for both elliptic cases, the
 * separatrix, symmetric bodies (notes §2.9: Omega = (I3 - I12)/I12 w3) and
 * permuted moment orders; the numerical run against it (the quality
 * bar: 1e-9 relative over 100 flips); a constant space torque (L = L0 + G t);
 * typed errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rotation/attitude.h"
#include "mech/base/constants.h"
#include "mech/rigid/rigid_rotation.h"
#include "mech/rotation/rotation.h"
#include "testlib.h"

static double mat_diff(struct mech_mat3 a, struct mech_mat3 b)
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) d = fmax(d, fabs(a.a[i][j] - b.a[i][j]));
    return d;
}

static void test_attitude(void)
{
    double q[4] = {0.3, -0.5, 0.7, 0.2};
    struct mech_mat3 r;
    CHECK(mech_rotation_from_quaternion(q, &r, NULL) == MECH_OK);
    CHECK(mat_diff(mech_attitude_matrix(q), r) < 1e-15);
    double q2[4];
    mech_attitude_from_matrix(r, q2);
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int i = 0; i < 4; i++) CHECK_CLOSE(q2[i], q[i] / n, 0, 1e-15);
    /* Shepperd branches: turns by ~pi about each axis */
    for (int ax = 0; ax < 3; ax++) {
        struct mech_vec3 a = mech_vec3_make(ax == 0, ax == 1, ax == 2);
        CHECK(mech_rotation_from_axis_angle(a, 3.0, &r, NULL) == MECH_OK);
        mech_attitude_from_matrix(r, q2);
        CHECK(mat_diff(mech_attitude_matrix(q2), r) < 1e-15);
    }
    /* Euler z-x-z */
    double phi = 0.7, th = 1.1, psi = -2.3;
    CHECK(mech_rotation_from_euler_zxz(phi, th, psi, &r, NULL) == MECH_OK);
    mech_attitude_from_euler_zxz(phi, th, psi, q2);
    CHECK(mat_diff(mech_attitude_matrix(q2), r) < 1e-15);
    double p2, t2, s2;
    int g;
    mech_attitude_euler_zxz(q2, 0, &p2, &t2, &s2, &g);
    CHECK_CLOSE(t2, th, 0, 1e-15);
    CHECK_CLOSE(remainder(p2 - phi, 2 * MECH_PI), 0, 0, 1e-15);
    CHECK_CLOSE(remainder(s2 - psi, 2 * MECH_PI), 0, 0, 1e-15);
    CHECK(g == 0);
    /* theta = 0: only phi + psi; the hint picks psi */
    mech_attitude_from_euler_zxz(0.4, 0, 0.9, q2);
    mech_attitude_euler_zxz(q2, 0.9, &p2, &t2, &s2, &g);
    CHECK(g == 1);
    CHECK(t2 == 0);
    CHECK_CLOSE(p2, 0.4, 0, 1e-15);
    CHECK_CLOSE(s2, 0.9, 0, 1e-15);
    /* body/space vectors: the rows of R are the body axes in space axes */
    struct mech_vec3 e = mech_attitude_to_space(q, mech_vec3_make(1, 0, 0));
    struct mech_mat3 rq = mech_attitude_matrix(q);
    CHECK_CLOSE(e.x, rq.a[0][0], 0, 1e-15);
    CHECK_CLOSE(e.y, rq.a[0][1], 0, 1e-15);
    CHECK_CLOSE(e.z, rq.a[0][2], 0, 1e-15);
}

/* Euler's equations residual of the exact solution by central differences,
 * and its invariants, over [0, tmax]. Returns max relative residual. */
static void check_exact(const double I[3], struct mech_vec3 w0, double tmax, int want_kind)
{
    struct mech_rigid_exact ex;
    CHECK(mech_rigid_exact_init(I, w0, &ex, NULL) == MECH_OK);
    CHECK_EQ_INT(ex.kind, want_kind);
    struct mech_vec3 w;
    CHECK(mech_rigid_exact_omega(&ex, 0, &w, NULL) == MECH_OK);
    double wn = mech_vec3_norm(w0);
    CHECK_CLOSE(w.x, w0.x, 0, 1e-14 * wn);
    CHECK_CLOSE(w.y, w0.y, 0, 1e-14 * wn);
    CHECK_CLOSE(w.z, w0.z, 0, 1e-14 * wn);
    double L2 = I[0] * I[0] * w0.x * w0.x + I[1] * I[1] * w0.y * w0.y + I[2] * I[2] * w0.z * w0.z;
    double E2 = I[0] * w0.x * w0.x + I[1] * w0.y * w0.y + I[2] * w0.z * w0.z;
    double worst = 0, winv = 0;
    for (int k = 1; k <= 200; k++) {
        double t = tmax * k / 200.0, h = 1e-4 / wn;
        struct mech_vec3 a, b, c;
        CHECK(mech_rigid_exact_omega(&ex, t - h, &a, NULL) == MECH_OK);
        CHECK(mech_rigid_exact_omega(&ex, t, &b, NULL) == MECH_OK);
        CHECK(mech_rigid_exact_omega(&ex, t + h, &c, NULL) == MECH_OK);
        double d[3] = {(c.x - a.x) / (2 * h), (c.y - a.y) / (2 * h), (c.z - a.z) / (2 * h)};
        double f[3] = {(I[1] - I[2]) * b.y * b.z / I[0], (I[2] - I[0]) * b.z * b.x / I[1],
                       (I[0] - I[1]) * b.x * b.y / I[2]};
        for (int i = 0; i < 3; i++) worst = fmax(worst, fabs(d[i] - f[i]) / (wn * wn));
        double l2 = I[0] * I[0] * b.x * b.x + I[1] * I[1] * b.y * b.y + I[2] * I[2] * b.z * b.z;
        double e2 = I[0] * b.x * b.x + I[1] * b.y * b.y + I[2] * b.z * b.z;
        winv = fmax(winv, fmax(fabs(l2 - L2) / L2, fabs(e2 - E2) / E2));
    }
    CHECK(worst < 1e-7); /* central difference O(h^2) with h = 1e-4 / |w| */
    CHECK(winv < 1e-13);
    if (worst >= 1e-7 || winv >= 1e-13)
        fprintf(stderr, "  exact: residual %.3g invariants %.3g (I = %g %g %g)\n", worst, winv,
                I[0], I[1], I[2]);
}

static void test_exact(void)
{
    const double I123[3] = {1, 2, 3};
    check_exact(I123, mech_vec3_make(0.3, 0.5, 1.0), 20, MECH_RIGID_EXACT_ELLIPTIC); /* D2 > 0 */
    check_exact(I123, mech_vec3_make(1.0, 0.5, 0.2), 20, MECH_RIGID_EXACT_ELLIPTIC); /* D2 < 0 */
    check_exact(I123, mech_vec3_make(-0.01, 1.0, 0.02), 60, MECH_RIGID_EXACT_ELLIPTIC);
    const double Iodd[3] = {2, 1, 3}, Icyc[3] = {3, 1, 2};
    check_exact(Iodd, mech_vec3_make(0.5, 0.3, -1.0), 20, MECH_RIGID_EXACT_ELLIPTIC);
    check_exact(Icyc, mech_vec3_make(0.2, -1.0, 0.5), 20, MECH_RIGID_EXACT_ELLIPTIC);
    /* separatrix: D2 = -u1^2 + 3 u3^2 = 0 */
    check_exact(I123, mech_vec3_make(sqrt(3.0) * 0.1, 0.3, 0.1), 10, MECH_RIGID_EXACT_SEPARATRIX);
    /* symmetric: notes §2.9, Omega = (I3 - I12)/I12 w3 = (2 - 1)/1 * 2 = 2 */
    const double Is[3] = {1, 1, 2};
    check_exact(Is, mech_vec3_make(1, 0, 2), 10, MECH_RIGID_EXACT_SYMMETRIC);
    struct mech_rigid_exact ex;
    CHECK(mech_rigid_exact_init(Is, mech_vec3_make(1, 0, 2), &ex, NULL) == MECH_OK);
    CHECK_CLOSE(ex.lambda, 2.0, 1e-15, 0);
    struct mech_vec3 w;
    CHECK(mech_rigid_exact_omega(&ex, 0.3, &w, NULL) == MECH_OK);
    CHECK_CLOSE(w.x, cos(0.6), 0, 1e-15);
    CHECK_CLOSE(w.y, sin(0.6), 0, 1e-15);
    CHECK_CLOSE(w.z, 2, 0, 1e-15);
    const double Is1[3] = {2, 3, 3}; /* symmetric about axis 1 */
    check_exact(Is1, mech_vec3_make(1.5, 0.2, -0.3), 10, MECH_RIGID_EXACT_SYMMETRIC);
    /* principal-axis rotations are steady */
    check_exact(I123, mech_vec3_make(0, 0, 2), 5, MECH_RIGID_EXACT_STEADY);
    check_exact(I123, mech_vec3_make(2, 0, 0), 5, MECH_RIGID_EXACT_STEADY);
    check_exact(I123, mech_vec3_make(0, 2, 0), 5, MECH_RIGID_EXACT_STEADY);
    /* tiny and huge scales */
    const double Itiny[3] = {1e-20, 2e-20, 3e-20}, Ihuge[3] = {1e20, 2e20, 3e20};
    check_exact(Itiny, mech_vec3_make(3e5, 5e5, 1e6), 1e-4, MECH_RIGID_EXACT_ELLIPTIC);
    check_exact(Ihuge, mech_vec3_make(3e-5, 5e-5, 1e-4), 2e5, MECH_RIGID_EXACT_ELLIPTIC);
    /* the period against SciPy's ellipk: I = (1, 2, 3), w0 = (0.05, 1, 0.05),
     * 4 K(m) / lambda = 27.906063758174824 s (rigid_rotate_intermediate_flip) */
    struct mech_rigid_exact e2;
    CHECK(mech_rigid_exact_init(I123, mech_vec3_make(0.05, 1, 0.05), &e2, NULL) == MECH_OK);
    CHECK_CLOSE(e2.period, 27.906063758174824, 1e-13, 0);
}

static struct mech_rigid_problem problem(const double I[3], struct mech_vec3 w, double t_end)
{
    struct mech_rigid_problem p;
    memset(&p, 0, sizeof p);
    memcpy(p.moments, I, sizeof p.moments);
    p.omega = w;
    p.q0[0] = 1;
    p.t_end = t_end;
    p.samples = 2001;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    p.opt.atol = 1e-14;
    return p;
}

static void test_numeric(void)
{
    struct mech_budget b = mech_budget_make(10000000, 120);
    /* quality bar: 100 flips near the intermediate axis of an asymmetric body */
    const double I[3] = {1, 2, 3};
    struct mech_vec3 w0 = mech_vec3_make(0.05, 1.0, 0.05);
    struct mech_rigid_exact ex;
    CHECK(mech_rigid_exact_init(I, w0, &ex, NULL) == MECH_OK);
    struct mech_rigid_problem p = problem(I, w0, 50 * ex.period); /* 2 flips per period */
    p.samples = 20001;
    struct mech_rigid_result r;
    memset(&r, 0, sizeof r);
    CHECK(mech_rigid_rotate(&p, &b, &r, NULL) == MECH_OK);
    CHECK(r.has_exact);
    CHECK(r.flips >= 100);
    printf("100 flips: period %.6g, max rel omega error %.3g, |L| drift %.3g, T drift %.3g, "
           "L vec %.3g, |q| %.3g, steps %ld, flips %ld, measured period %.12g\n",
           ex.period, r.max_relative_omega_error, r.max_L_norm_drift, r.max_T_drift,
           r.max_L_vector_drift, r.max_quaternion_norm_drift, r.stats.steps, r.flips,
           r.measured_period);
    CHECK(r.max_relative_omega_error < 1e-9);
    CHECK(r.max_T_drift < 1e-11);
    CHECK(r.max_L_vector_drift < 1e-9);
    CHECK_CLOSE(r.measured_period, ex.period, 1e-5, 0);

    /* symmetric top: w precesses about the symmetry axis at Omega (notes §2.9) */
    const double Is[3] = {1, 1, 2};
    p = problem(Is, mech_vec3_make(1, 0, 2), 10);
    memset(&r, 0, sizeof r);
    struct mech_vec3 wout[2001];
    r.omega = wout;
    CHECK(mech_rigid_rotate(&p, &b, &r, NULL) == MECH_OK);
    CHECK(r.max_relative_omega_error < 1e-11);
    CHECK_CLOSE(wout[2000].x, cos(20.0), 0, 1e-11);
    CHECK_CLOSE(wout[2000].y, sin(20.0), 0, 1e-11);

    /* constant space torque: L(t) = L0 + G t exactly; an odd moment order */
    const double Io[3] = {2, 1, 2.5};
    p = problem(Io, mech_vec3_make(0.3, -0.4, 1.2), 5);
    p.torque_frame = MECH_RIGID_TORQUE_SPACE;
    p.torque = mech_vec3_make(0.1, 0.2, -0.05);
    memset(&r, 0, sizeof r);
    CHECK(mech_rigid_rotate(&p, &b, &r, NULL) == MECH_OK);
    CHECK(!r.has_exact);
    CHECK(r.max_L_vector_drift < 1e-11);
    CHECK(r.max_quaternion_norm_drift < 1e-11);

    /* body torque along axis 3 of a symmetric body about that axis: w3 = w3(0) + G t / I3 */
    p = problem(Is, mech_vec3_make(0, 0, 1), 4);
    p.torque_frame = MECH_RIGID_TORQUE_BODY;
    p.torque = mech_vec3_make(0, 0, 0.5);
    memset(&r, 0, sizeof r);
    r.omega = wout;
    CHECK(mech_rigid_rotate(&p, &b, &r, NULL) == MECH_OK);
    CHECK_CLOSE(wout[2000].z, 1 + 0.5 * 4 / 2.0, 1e-13, 0);

    /* attitude: steady rotation about body z by w -> q = (cos(wt/2), 0, 0, sin(wt/2)) */
    double qs[4 * 2001];
    p = problem(I, mech_vec3_make(0, 0, 0.7), 3);
    memset(&r, 0, sizeof r);
    r.quaternion = qs;
    CHECK(mech_rigid_rotate(&p, &b, &r, NULL) == MECH_OK);
    CHECK_CLOSE(qs[4 * 2000 + 0], cos(0.7 * 3 / 2), 0, 1e-13);
    CHECK_CLOSE(qs[4 * 2000 + 3], sin(0.7 * 3 / 2), 0, 1e-13);

    /* fixed-step rk4 runs with dt in seconds */
    p = problem(I, mech_vec3_make(0.3, 0.5, 1.0), 10);
    p.method = "rk4";
    p.opt.dt = 1e-3;
    memset(&r, 0, sizeof r);
    CHECK(mech_rigid_rotate(&p, &b, &r, NULL) == MECH_OK);
    CHECK(r.max_relative_omega_error < 1e-9);
    CHECK_EQ_INT(r.stats.steps, 10000);

    /* errors */
    struct mech_error e;
    mech_error_clear(&e);
    p.method = "verlet";
    CHECK(mech_rigid_rotate(&p, &b, &r, &e) == MECH_EINVAL);
    CHECK(strcmp(e.param, "integrator/method") == 0);
    const double Ibad[3] = {1, 1, 3};
    p = problem(Ibad, mech_vec3_make(1, 0, 0), 1);
    mech_error_clear(&e);
    CHECK(mech_rigid_rotate(&p, &b, &r, &e) == MECH_EDOMAIN);
    CHECK(strcmp(e.param, "moments") == 0);
    p = problem(I, mech_vec3_make(1, 2, 3), 1000);
    struct mech_budget small = mech_budget_make(50, 60);
    mech_error_clear(&e);
    CHECK(mech_rigid_rotate(&p, &small, &r, &e) == MECH_EBUDGET);
    CHECK(e.progress.t_reached > 0 && e.progress.t_reached < 1000);
    CHECK_CLOSE(e.progress.t_target, 1000, 1e-15, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_attitude();
    test_exact();
    test_numeric();
    TEST_MAIN_END();
}
