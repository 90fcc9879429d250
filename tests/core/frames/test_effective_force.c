/* test_effective_force.c — the fictitious forces of notes §1.2 against
 * (1) the notes' two puck experiments on a rotating table (§1.1), in closed
 * form; (2) an independent kinematic computation: a particle with a known
 * inertial trajectory is re-expressed in a frame whose origin and axes move
 * along arbitrary analytic paths, x_A(t) = Q(t)^T (x_I(t) - X(t)); its frame
 * acceleration, the frame's omega, omega_dot and origin acceleration are all
 * taken by 8th-order finite differences of those paths, and m a_A must equal
 * the effective force; (3) directions of each term, and the refused inputs. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/frames/effective_force.h"
#include "mech/base/constants.h"
#include "testlib.h"

#define CHECK_VEC(got, want, rtol, atol)                                                           \
    do {                                                                                           \
        struct mech_vec3 g_ = (got), w_ = (want);                                                  \
        CHECK_CLOSE(g_.x, w_.x, rtol, atol);                                                       \
        CHECK_CLOSE(g_.y, w_.y, rtol, atol);                                                       \
        CHECK_CLOSE(g_.z, w_.z, rtol, atol);                                                       \
    } while (0)

/* ---- an arbitrary moving frame and inertial trajectory ---------------------- */

static const double MASS = 2.5;

static struct mech_mat3 rot_z(double a)
{
    struct mech_mat3 m = {{{cos(a), -sin(a), 0}, {sin(a), cos(a), 0}, {0, 0, 1}}};
    return m;
}
static struct mech_mat3 rot_x(double a)
{
    struct mech_mat3 m = {{{1, 0, 0}, {0, cos(a), -sin(a)}, {0, sin(a), cos(a)}}};
    return m;
}

/* Columns of Q(t) are the frame's unit vectors in inertial components. */
static struct mech_mat3 frame_axes(double t)
{
    double p1 = 0.4 + 1.3 * t + 0.2 * t * t, p2 = 0.7 + 0.5 * sin(t), p3 = -0.3 + 2 * t;
    return mech_mat3_mul(rot_z(p1), mech_mat3_mul(rot_x(p2), rot_z(p3)));
}
static struct mech_vec3 frame_origin(double t)
{
    return mech_vec3_make(3 * sin(0.7 * t), 0.3 * t * t - 1, 2 * cos(1.1 * t));
}
static struct mech_vec3 inertial_position(double t)
{
    /* constant-jerk motion: F(t) = m (a0 + j t) */
    return mech_vec3_make(1 + 2 * t - 0.5 * t * t + 0.1 * t * t * t, -0.5 + 0.3 * t + 1.5 * t * t,
                          0.2 - 1.0 * t + 0.25 * t * t - 0.05 * t * t * t);
}
static struct mech_vec3 inertial_force(double t)
{
    return mech_vec3_scale(mech_vec3_make(-1 + 0.6 * t, 3, 0.5 - 0.3 * t), MASS);
}
static struct mech_vec3 frame_position(double t)
{
    return mech_mat3_mul_vec(mech_mat3_transpose(frame_axes(t)),
                             mech_vec3_sub(inertial_position(t), frame_origin(t)));
}

static const double D1[9] = {1.0 / 280, -4.0 / 105, 1.0 / 5,   -4.0 / 5,  0,
                             4.0 / 5,   -1.0 / 5,   4.0 / 105, -1.0 / 280};
static const double D2[9] = {-1.0 / 560, 8.0 / 315, -1.0 / 5,  8.0 / 5,   -205.0 / 72,
                             8.0 / 5,    -1.0 / 5,  8.0 / 315, -1.0 / 560};

static struct mech_vec3 fd_vec(struct mech_vec3 (*f)(double), double t, double h, const double *w,
                               double scale)
{
    struct mech_vec3 s = {0, 0, 0};
    for (int k = -4; k <= 4; k++)
        s = mech_vec3_add(s, mech_vec3_scale(f(t + k * h), w[k + 4]));
    return mech_vec3_scale(s, 1 / scale);
}

/* omega in frame axes from Q^T dQ/dt = [omega]x (dQ/dt by finite differences). */
static struct mech_vec3 frame_omega(double t)
{
    const double h = 1e-3;
    struct mech_mat3 dq = {{{0}}};
    for (int k = -4; k <= 4; k++) {
        struct mech_mat3 q = frame_axes(t + k * h);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                dq.a[i][j] += D1[k + 4] * q.a[i][j] / h;
    }
    struct mech_mat3 w = mech_mat3_mul(mech_mat3_transpose(frame_axes(t)), dq);
    return mech_vec3_make(0.5 * (w.a[2][1] - w.a[1][2]), 0.5 * (w.a[0][2] - w.a[2][0]),
                          0.5 * (w.a[1][0] - w.a[0][1]));
}

static void check_against_kinematics(double t0)
{
    const double h = 1e-3;
    struct mech_mat3 qt = mech_mat3_transpose(frame_axes(t0));
    struct mech_frame_motion fr;
    fr.omega = frame_omega(t0);
    fr.omega_dot = fd_vec(frame_omega, t0, h, D1, h);
    fr.acceleration = mech_mat3_mul_vec(qt, fd_vec(frame_origin, t0, h, D2, h * h));
    struct mech_vec3 r = frame_position(t0);
    struct mech_vec3 v = fd_vec(frame_position, t0, h, D1, h);
    struct mech_vec3 a = fd_vec(frame_position, t0, h, D2, h * h);
    struct mech_vec3 F = mech_mat3_mul_vec(qt, inertial_force(t0));
    struct mech_effective_force out;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_effective_force(&fr, MASS, r, v, F, &out, &e), MECH_OK);
    struct mech_vec3 ma = mech_vec3_scale(a, MASS);
    double scale = mech_vec3_norm(out.effective) + mech_vec3_norm(out.centrifugal) +
                   mech_vec3_norm(out.coriolis);
    double err = mech_vec3_norm(mech_vec3_sub(out.effective, ma)) / scale;
    printf("t0 = %.2f: |F_eff - m a_A| / scale = %.3g (finite differences, h = 1e-3)\n", t0, err);
    CHECK(err < 1e-9);
    /* each term matters here: dropping any one breaks the balance */
    CHECK(mech_vec3_norm(out.euler) > 1e-3 * scale);
    CHECK(mech_vec3_norm(out.translational) > 1e-3 * scale);
    CHECK(mech_vec3_norm(out.coriolis) > 1e-3 * scale);
    CHECK(mech_vec3_norm(out.centrifugal) > 1e-3 * scale);
    /* flipping the sign of one term (the PDF's lost minus signs) fails by far */
    struct mech_vec3 wrong = mech_vec3_sub(out.effective, mech_vec3_scale(out.euler, 2));
    CHECK(mech_vec3_norm(mech_vec3_sub(wrong, ma)) / scale > 1e-3);
    CHECK_VEC(out.acceleration, a, 1e-8, 1e-8 * mech_vec3_norm(a));
}

/* ---- the notes' rotating table (§1.1, §1.2) --------------------------------- */

static void check_pucks(void)
{
    const double m = 0.3, w = 2.0, r1 = 0.5;
    struct mech_frame_motion fr = {{0, 0, w}, {0, 0, 0}, {0, 0, 0}};
    struct mech_effective_force out;
    /* Puck 1 through the origin: at t = 0 it is at r1 e_y moving inward at
     * 2 w r1/pi (a diameter during half a turn). Rotating-frame velocity
     * v' = v - w x r = -(2 w r1/pi) e_y + w r1 e_x. Effective force
     * -m w² r1 (e_y + (4/pi) e_x): centrifugal +m w² r1 e_y, Coriolis
     * -(4/pi) m w² r1 e_x - 2 m w² r1 e_y. */
    struct mech_vec3 r = {0, r1, 0};
    struct mech_vec3 v = {w * r1, -2 * w * r1 / MECH_PI, 0};
    CHECK_EQ_INT(mech_effective_force(&fr, m, r, v, mech_vec3_make(0, 0, 0), &out, NULL), MECH_OK);
    double f0 = m * w * w * r1;
    CHECK_VEC(out.centrifugal, mech_vec3_make(0, f0, 0), 1e-15, 1e-16);
    CHECK_VEC(out.coriolis, mech_vec3_make(-4 / MECH_PI * f0, -2 * f0, 0), 1e-15, 1e-16);
    CHECK_VEC(out.effective, mech_vec3_make(-4 / MECH_PI * f0, -f0, 0), 1e-15, 1e-16);
    CHECK_VEC(out.euler, mech_vec3_make(0, 0, 0), 0, 0);
    CHECK_VEC(out.translational, mech_vec3_make(0, 0, 0), 0, 0);
    /* Puck 2 at rest in the inertial frame: seen circling at -w: v' = w r1 e_x,
     * F_eff = -m w² r1 e_y, the centripetal force of that circle; the Coriolis
     * force is twice the centrifugal and opposite. */
    v = mech_vec3_make(w * r1, 0, 0);
    CHECK_EQ_INT(mech_effective_force(&fr, m, r, v, mech_vec3_make(0, 0, 0), &out, NULL), MECH_OK);
    CHECK_VEC(out.coriolis, mech_vec3_make(0, -2 * f0, 0), 1e-15, 1e-16);
    CHECK_VEC(out.effective, mech_vec3_make(0, -f0, 0), 1e-15, 1e-16);
    CHECK_CLOSE(mech_vec3_norm(out.acceleration), w * w * r1, 1e-15, 0); /* v'^2 / r1 */
}

/* ---- directions and sizes of each term ------------------------------------- */

static void check_terms(void)
{
    struct mech_frame_motion fr = {{0.3, -0.2, 1.1}, {0.05, 0.4, -0.1}, {1.5, -2, 0.25}};
    struct mech_vec3 r = {2, -1, 0.5}, v = {-0.4, 3, 1}, F = {0.1, 0.2, -9.81};
    double m = 1.7;
    struct mech_effective_force out;
    CHECK_EQ_INT(mech_effective_force(&fr, m, r, v, F, &out, NULL), MECH_OK);
    struct mech_vec3 w = fr.omega;
    /* centrifugal = m (w² r - (w.r) w): outward, perpendicular to w, size m w² r_perp */
    struct mech_vec3 cf = mech_vec3_scale(mech_vec3_sub(mech_vec3_scale(r, mech_vec3_dot(w, w)),
                                                        mech_vec3_scale(w, mech_vec3_dot(w, r))),
                                          m);
    CHECK_VEC(out.centrifugal, cf, 1e-14, 1e-15);
    CHECK(fabs(mech_vec3_dot(out.centrifugal, w)) < 1e-14);
    CHECK(mech_vec3_dot(out.centrifugal, r) > 0);
    CHECK(fabs(mech_vec3_dot(out.coriolis, v)) < 1e-14);
    CHECK(fabs(mech_vec3_dot(out.coriolis, w)) < 1e-14);
    CHECK(fabs(mech_vec3_dot(out.euler, r)) < 1e-14);
    CHECK_VEC(out.translational, mech_vec3_scale(fr.acceleration, -m), 0, 0);
    struct mech_vec3 sum = mech_vec3_add(mech_vec3_add(out.translational, out.euler),
                                         mech_vec3_add(out.coriolis, out.centrifugal));
    CHECK_VEC(out.fictitious, sum, 1e-15, 1e-15);
    CHECK_VEC(out.effective, mech_vec3_add(sum, F), 1e-15, 1e-15);
    CHECK_VEC(out.acceleration, mech_vec3_scale(out.effective, 1 / m), 1e-15, 1e-16);
    CHECK_VEC(out.inertial_acceleration, mech_vec3_scale(F, 1 / m), 1e-15, 0);

    /* compensated sum: a force that cancels the fictitious terms to one part in
     * 1e16 leaves exactly the small remainder */
    struct mech_vec3 tiny = {3e-17, -2e-17, 1e-17};
    struct mech_vec3 F2 = mech_vec3_add(mech_vec3_scale(out.fictitious, -1), tiny);
    CHECK_EQ_INT(mech_effective_force(&fr, m, r, v, F2, &out, NULL), MECH_OK);
    CHECK(mech_vec3_norm(out.effective) < 1e-15);
}

static void check_extremes(void)
{
    struct mech_frame_motion fr = {{0, 0, 1e6}, {0, 0, 0}, {0, 0, 0}};
    struct mech_effective_force out;
    struct mech_error e;
    /* tiny mass, fast spin, big radius: still finite and exact */
    CHECK_EQ_INT(mech_effective_force(&fr, 1e-30, mech_vec3_make(1e15, 0, 0),
                                      mech_vec3_make(0, 0, 0), mech_vec3_make(0, 0, 0), &out, NULL),
                 MECH_OK);
    CHECK_CLOSE(out.centrifugal.x, 1e-30 * 1e12 * 1e15, 1e-15, 0);
    CHECK_CLOSE(out.acceleration.x, 1e27, 1e-15, 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_effective_force(&fr, 0, mech_vec3_make(1, 0, 0), mech_vec3_make(0, 0, 0),
                                      mech_vec3_make(0, 0, 0), &out, &e),
                 MECH_EDOMAIN);
    CHECK(strcmp(e.param, "particle/mass") == 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_effective_force(&fr, 1, mech_vec3_make(NAN, 0, 0), mech_vec3_make(0, 0, 0),
                                      mech_vec3_make(0, 0, 0), &out, &e),
                 MECH_EINVAL);
    CHECK(strcmp(e.param, "particle/position") == 0);
    mech_error_clear(&e);
    fr.omega = mech_vec3_make(0, 0, 1e200);
    CHECK_EQ_INT(mech_effective_force(&fr, 1, mech_vec3_make(1e200, 0, 0), mech_vec3_make(0, 0, 0),
                                      mech_vec3_make(0, 0, 0), &out, &e),
                 MECH_ENUMERIC);
    CHECK_EQ_INT(mech_effective_force(NULL, 1, mech_vec3_make(1, 0, 0), mech_vec3_make(0, 0, 0),
                                      mech_vec3_make(0, 0, 0), &out, NULL),
                 MECH_EINVAL);
    /* a subnormal mass: a = F/m overflows and is refused, never inf */
    fr.omega = mech_vec3_make(0, 0, 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_effective_force(&fr, 1e-310, mech_vec3_make(0, 0, 0), mech_vec3_make(0, 0, 0),
                                      mech_vec3_make(1e10, 0, 0), &out, &e),
                 MECH_ENUMERIC);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_pucks();
    check_terms();
    check_extremes();
    check_against_kinematics(0.37);
    check_against_kinematics(-1.2);
    check_against_kinematics(2.9);
    TEST_MAIN_END();
}
