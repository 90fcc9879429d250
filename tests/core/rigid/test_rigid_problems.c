/* test_rigid_problems.c — the rigid-body chapter's closed-form problems against
 * second methods: the free symmetric top's rates against an RK4 integration of
 * Euler's equations (the body precession period of omega) and the identity
 * omega = phi_dot L_hat + psi_dot e3; the struck ball's final speed against
 * the sliding phase under Coulomb friction solved with Newton's laws (any
 * friction coefficient); the toppling box's landing angular velocity against
 * an RK4 integration of the equation of motion from just off balance, both
 * with the edge held and on a frictionless floor; the notes' cube answer. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/rigid/rigid_problems.h"
#include "mech/base/constants.h"
#include "testlib.h"

/* Euler's equations, torque-free, I1 = I2 = ip: w' = f(w) */
static void euler_rhs(double ip, double i3, const double w[3], double d[3])
{
    d[0] = (ip - i3) / ip * w[1] * w[2];
    d[1] = (i3 - ip) / ip * w[2] * w[0];
    d[2] = 0;
}

static void check_free_top(void)
{
    const double cases[][5] = {{1, 2, 1, 0, 2}, {3, 1.2, 0.3, -0.4, 5}, {2, 3.9, -1, 2, -0.5},
                               {1, 1, 0.2, 0.3, 0.4}};
    for (size_t n = 0; n < sizeof cases / sizeof cases[0]; n++) {
        double ip = cases[n][0], i3 = cases[n][1], w[3] = {cases[n][2], cases[n][3], cases[n][4]};
        struct mech_free_symmetric_top t;
        CHECK_EQ_INT(mech_free_symmetric_top(ip, i3, w, &t, NULL), MECH_OK);
        /* L and its angle to e3 directly */
        double L[3] = {ip * w[0], ip * w[1], i3 * w[2]};
        double Lm = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
        CHECK_CLOSE(t.angular_momentum, Lm, 1e-15, 0);
        CHECK_CLOSE(cos(t.theta), L[2] / Lm, 1e-14, 1e-15);
        /* omega = phi_dot L_hat + psi_dot e3, component by component */
        for (int k = 0; k < 3; k++)
            CHECK_CLOSE(t.precession_space * L[k] / Lm + (k == 2 ? t.precession_body : 0), w[k],
                        1e-14, 1e-14);
        /* angle L-omega = space cone */
        double wm = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        double c = (L[0] * w[0] + L[1] * w[1] + L[2] * w[2]) / (Lm * wm);
        CHECK_CLOSE(cos(t.space_cone), c, 1e-14, 1e-15);
        /* RK4 of Euler's equations for one body period: omega's transverse part turns
         * by psi_dot t (its angle measured with atan2) */
        if (t.precession_body != 0) {
            double T = 2 * MECH_PI / fabs(t.precession_body), h = T / 20000, y[3] = {w[0], w[1], w[2]};
            double ang = 0, prev = atan2(y[1], y[0]);
            for (int s = 0; s < 20000 / 4; s++) { /* a quarter period */
                double k1[3], k2[3], k3[3], k4[3], z[3];
                euler_rhs(ip, i3, y, k1);
                for (int i = 0; i < 3; i++) z[i] = y[i] + h / 2 * k1[i];
                euler_rhs(ip, i3, z, k2);
                for (int i = 0; i < 3; i++) z[i] = y[i] + h / 2 * k2[i];
                euler_rhs(ip, i3, z, k3);
                for (int i = 0; i < 3; i++) z[i] = y[i] + h * k3[i];
                euler_rhs(ip, i3, z, k4);
                for (int i = 0; i < 3; i++) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
                double now = atan2(y[1], y[0]), dphi = now - prev;
                if (dphi > MECH_PI) dphi -= 2 * MECH_PI;
                if (dphi < -MECH_PI) dphi += 2 * MECH_PI;
                ang += dphi;
                prev = now;
            }
            /* Euler: d/dt(w1 + i w2) = i (i3 - ip)/ip w3 (w1 + i w2), i.e. the body sees
             * omega turn at -psi_dot */
            CHECK_CLOSE(ang, -t.precession_body * T / 4, 1e-9, 0);
        }
    }
    /* the notes' example I = (1, 1, 2), omega = (1, 0, 2): Omega = (I3 - I1)/I1 w3 = 2 */
    double w[3] = {1, 0, 2};
    struct mech_free_symmetric_top t;
    CHECK_EQ_INT(mech_free_symmetric_top(1, 2, w, &t, NULL), MECH_OK);
    CHECK_CLOSE(-t.precession_body, 2, 1e-15, 0);
    CHECK(!t.prolate);
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_free_symmetric_top(1, 2.5, w, &t, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "i3") == 0);
    double z[3] = {0, 0, 0};
    CHECK_EQ_INT(mech_free_symmetric_top(1, 1, z, &t, NULL), MECH_EINVAL);
    /* the rigid Earth (A = 8.008e37, C = 8.034e37 kg m^2, one turn per sidereal day):
     * (C - A)/A = 0.026/8.008 and the Euler period A/(C - A) sidereal days, ~308 */
    double we[3] = {0, 1e-12, MECH_EARTH_OMEGA};
    CHECK_EQ_INT(mech_free_symmetric_top(8.008e37, 8.034e37, we, &t, NULL), MECH_OK);
    CHECK_CLOSE(t.ellipticity, 0.026 / 8.008, 1e-13, 0);
    CHECK_CLOSE(2 * MECH_PI / fabs(t.precession_body),
                8.008 / 0.026 * 2 * MECH_PI / MECH_EARTH_OMEGA, 1e-13, 0);
    CHECK(t.precession_body < 0); /* oblate: omega turns against the spin */
    CHECK_CLOSE(t.precession_space, hypot(8.008e37 * 1e-12, 8.034e37 * MECH_EARTH_OMEGA) / 8.008e37,
                1e-15, 0);
    /* a star: 1e60 kg m^2 */
    CHECK_EQ_INT(mech_free_symmetric_top(1e60, 1.5e60, w, &t, NULL), MECH_OK);
    CHECK_CLOSE(t.ellipticity, 0.5, 1e-15, 0);
    CHECK_CLOSE(t.angular_momentum, hypot(1e60, 3e60), 1e-15, 0);
}

static void check_struck_ball(void)
{
    const double m = 0.17, R = 0.028575, k2 = 0.4 * R * R, J = 0.5, g = 9.81;
    struct mech_struck_ball s;
    CHECK_EQ_INT(mech_struck_ball(m, R, k2, J, k2 / R, &s, NULL), MECH_OK);
    CHECK_CLOSE(s.rolling_height, 0.4 * R, 1e-15, 0);         /* 2R/5 */
    CHECK_CLOSE(s.rolling_height_floor, 1.4 * R, 1e-15, 0);   /* 7R/5 */
    CHECK_CLOSE(s.slip_velocity, 0, 0, 1e-15);
    CHECK_CLOSE(s.v_final, J / m, 1e-15, 0);
    CHECK_CLOSE(s.energy_lost_fraction, 0, 0, 1e-16);
    /* elsewhere: Newton with kinetic friction mu m g against the slip, for two mu */
    const double hs[] = {-0.8 * R, 0, 0.2 * R, 0.9 * R};
    for (size_t i = 0; i < 4; i++) {
        CHECK_EQ_INT(mech_struck_ball(m, R, k2, J, hs[i], &s, NULL), MECH_OK);
        for (double mu = 0.1; mu < 0.5; mu += 0.3) {
            double v = J / m, w = J * hs[i] / (m * k2), slip = v - w * R;
            double sg = slip > 0 ? 1 : -1;
            /* v' = -sg mu g, w' = +sg mu g R / k2: slip' = -sg mu g (1 + R^2/k2) */
            double ts = fabs(slip) / (mu * g * (1 + R * R / k2));
            double vf = v - sg * mu * g * ts, wf = w + sg * mu * g * R / k2 * ts;
            CHECK_CLOSE(s.v_final, vf, 1e-13, 0);
            CHECK_CLOSE(vf, wf * R, 1e-12, 0); /* it rolls then */
            double ke0 = 0.5 * m * v * v + 0.5 * m * k2 * w * w;
            double ke1 = 0.5 * m * vf * vf + 0.5 * m * k2 * wf * wf;
            CHECK_CLOSE(s.energy_lost_fraction, 1 - ke1 / ke0, 1e-9, 1e-15);
        }
    }
    CHECK_EQ_INT(mech_struck_ball(m, R, k2, J, 1.1 * R, &s, NULL), MECH_EINVAL);
}

/* theta'' for the falling box, theta from the balanced position; held edge or
 * frictionless floor (x_cm fixed): (I + m d^2 s^2 [free]) theta'' + m d^2 s c theta'^2
 * [free] = m g d s. Integrated by RK4 until theta reaches atan(a/b) (the base lands),
 * the last step cut by linear interpolation in theta. */
static double fall(double a, double b, double g, int free_floor)
{
    const double m = 1, d = 0.5 * hypot(a, b);
    double I = free_floor ? m * (a * a + b * b) / 12 : m * (a * a + b * b) / 3;
    double th = 1e-7, om = 0, thf = atan2(a, b), h = 1e-5;
    for (long it = 0; it < 100000000; it++) {
        double y[2] = {th, om}, k[4][2];
        for (int st = 0; st < 4; st++) {
            double t = y[0], o = y[1];
            if (st > 0) {
                double f = st == 3 ? 1 : 0.5;
                t = th + f * h * k[st - 1][0];
                o = om + f * h * k[st - 1][1];
            }
            double s = sin(t), c = cos(t);
            double M = I + (free_floor ? m * d * d * s * s : 0);
            k[st][0] = o;
            k[st][1] = (m * g * d * s - (free_floor ? m * d * d * s * c * o * o : 0)) / M;
        }
        double nth = th + h / 6 * (k[0][0] + 2 * k[1][0] + 2 * k[2][0] + k[3][0]);
        double nom = om + h / 6 * (k[0][1] + 2 * k[1][1] + 2 * k[2][1] + k[3][1]);
        if (nth >= thf) return om + (nom - om) * (thf - th) / (nth - th);
        th = nth;
        om = nom;
    }
    return NAN;
}

static void check_topple(void)
{
    const double l = 0.1, g = 9.81;
    struct mech_topple t;
    CHECK_EQ_INT(mech_topple_box(2, l, l, g, &t, NULL), MECH_OK);
    /* notes §2.11 HW 4: w = sqrt(3g/(2l) (sqrt 2 - 1)) with the edge held */
    CHECK_CLOSE(t.omega_held, sqrt(3 * g / (2 * l) * (sqrt(2) - 1)), 1e-15, 0);
    CHECK_CLOSE(t.omega_free, sqrt(12 * g / (5 * l) * (sqrt(2) - 1)), 1e-15, 0);
    CHECK_CLOSE(t.drop, l * (sqrt(2) - 1) / 2, 1e-15, 0);
    const double boxes[][2] = {{0.1, 0.1}, {0.05, 0.3}, {0.4, 0.1}};
    for (size_t i = 0; i < 3; i++) {
        double a = boxes[i][0], b = boxes[i][1];
        CHECK_EQ_INT(mech_topple_box(1, a, b, g, &t, NULL), MECH_OK);
        double wh = fall(a, b, g, 0), wf = fall(a, b, g, 1);
        printf("box %g x %g: held %.12f (RK4 %.12f), frictionless %.12f (RK4 %.12f) rad/s\n", a, b,
               t.omega_held, wh, t.omega_free, wf);
        CHECK_CLOSE(wh, t.omega_held, 1e-6, 0);
        CHECK_CLOSE(wf, t.omega_free, 1e-6, 0);
    }
    CHECK_EQ_INT(mech_topple_box(1, -1, 1, g, &t, NULL), MECH_EINVAL);
}

/* Rolling down an incline: a = g sin(a)/(1 + k) for the ball (k = 2/5: 5/7 g sin a),
 * the cylinder (1/2: 2/3), the hoop (1: 1/2) and a sliding block (k = 0: g sin a);
 * second method: energy, m g L sin(a) = m v^2 (1 + k)/2 at the bottom. */
static void check_rolling(void)
{
    const double ks[] = {0.4, 0.5, 1.0, 0.0}, frac[] = {5.0 / 7, 2.0 / 3, 0.5, 1.0};
    const double m = 2.5, R = 0.12, g = 9.81, a = 0.4, L = 3.0;
    for (int i = 0; i < 4; i++) {
        struct mech_rolling_incline r;
        CHECK_EQ_INT(mech_rolling_incline(m, ks[i] * m * R * R, R, a, g, L, &r, NULL), MECH_OK);
        CHECK_CLOSE(r.k, ks[i], 1e-15, 0);
        CHECK_CLOSE(r.acceleration, frac[i] * g * sin(a), 1e-15, 0);
        CHECK_CLOSE(0.5 * m * r.speed * r.speed * (1 + ks[i]), m * g * L * sin(a), 1e-14, 0);
        CHECK_CLOSE(0.5 * r.acceleration * r.time * r.time, L, 1e-14, 0);
        CHECK_CLOSE(r.angular_speed * R, r.speed, 1e-15, 0);
        /* friction: m g sin a - f = m a_cm */
        CHECK_CLOSE(m * g * sin(a) - r.friction_force, m * r.acceleration, 1e-14, 1e-15);
        CHECK_CLOSE(r.min_friction_coefficient, r.friction_force / (m * g * cos(a)), 1e-14,
                    1e-16);
    }
    struct mech_rolling_incline r;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rolling_incline(1, 1, 1, 1.6, 9.81, 1, &r, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "angle"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rolling_incline(1, 1, 0, 0.5, 9.81, 1, &r, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "radius"));
    /* a planet-sized ball: nothing overflows on the way (I/m/R/R) */
    CHECK_EQ_INT(mech_rolling_incline(6e24, 0.4 * 6e24 * 6.4e6 * 6.4e6, 6.4e6, 0.5, 9.81, 10,
                                      &r, NULL),
                 MECH_OK);
    CHECK_CLOSE(r.k, 0.4, 1e-15, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_free_top();
    check_struck_ball();
    check_topple();
    check_rolling();
    TEST_MAIN_END();
}
