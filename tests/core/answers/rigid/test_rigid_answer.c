/* test_rigid_answer.c — mech/answers/rigid/rigid_answer.h against the symmetric top's
 * closed form: I = (1, 1, 2) kg m^2, omega0 = (a, 0, w3). Euler's equations
 * I1 w1' = (I2 - I3) w2 w3, I2 w2' = (I3 - I1) w3 w1 give w1' = -w3 w2,
 * w2' = w3 w1, w3 constant: w1 = a cos(w3 t), w2 = a sin(w3 t). Both paths
 * (the closed form, and rk8pd at rtol 1e-12) must give those samples, the
 * kinetic energy (I1 a^2 + I3 w3^2)/2 and |L| = sqrt(a^2 + 4 w3^2) at every
 * sample; the closed form takes 0 steps and counts its evaluations. A sample
 * count whose arrays would overflow is EINVAL "samples", and the answer is
 * freeable on every path (twice, too). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "mech/answers/rigid/rigid_answer.h"
#include "testlib.h"

#define A 0.3
#define W3 1.0

static struct mech_rigid_problem top(void)
{
    struct mech_rigid_problem p;
    memset(&p, 0, sizeof p);
    p.moments[0] = p.moments[1] = 1.0;
    p.moments[2] = 2.0;
    p.omega = mech_vec3_make(A, 0, W3);
    p.q0[0] = 1.0;
    p.t_end = 10.0;
    p.samples = 21;
    p.method = "rk8pd";
    p.opt.rtol = 1e-12;
    p.opt.atol = 1e-12;
    return p;
}

static void check_top(int closed_form)
{
    struct mech_rigid_problem p = top();
    struct mech_rigid_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = mech_budget_make(1000000, 3600);
    CHECK_EQ_INT(mech_rigid_answer_run(&p, closed_form, &b, &a, &e), MECH_OK);
    CHECK_EQ_INT(a.closed, closed_form);
    CHECK_EQ_INT(a.r.n_samples, 21);
    const double T = 0.5 * (A * A + 2 * W3 * W3), L = sqrt(A * A + 4 * W3 * W3);
    for (size_t i = 0; i < a.r.n_samples; i++) {
        const double t = a.r.t[i];
        CHECK_CLOSE(t, 0.5 * (double)i, 1e-15, 1e-15);
        CHECK_CLOSE(a.r.omega[i].x, A * cos(W3 * t), 0, 1e-9);
        CHECK_CLOSE(a.r.omega[i].y, A * sin(W3 * t), 0, 1e-9);
        CHECK_CLOSE(a.r.omega[i].z, W3, 0, 1e-12);
        CHECK_CLOSE(a.r.kinetic_energy[i], T, 1e-11, 0);
        CHECK_CLOSE(mech_vec3_norm(a.r.angular_momentum[i]), L, 1e-11, 0);
        const double *q = a.r.quaternion + 4 * i;
        CHECK_CLOSE(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-13, 0);
    }
    CHECK_EQ_INT(a.r.torque_free, 1);
    if (closed_form) {
        CHECK_EQ_INT(a.r.stats.steps, 0);
        CHECK(a.ev.evaluations > 0);
    } else {
        CHECK(a.r.stats.steps > 0);
    }
    mech_rigid_answer_free(&a);
    mech_rigid_answer_free(&a);
}

static void test_errors(void)
{
    struct mech_rigid_problem p = top();
    p.samples = SIZE_MAX / 8;
    struct mech_rigid_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = mech_budget_make(1000, 3600);
    CHECK_EQ_INT(mech_rigid_answer_run(&p, 0, &b, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "samples"));
    mech_rigid_answer_free(&a);
    /* an unphysical body: the core's own check, naming moments */
    p = top();
    p.moments[2] = 3.0; /* 3 > 1 + 1 */
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rigid_answer_run(&p, 0, &b, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "moments"));
    mech_rigid_answer_free(&a);
    mech_rigid_answer_free(NULL);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_top(1);
    check_top(0);
    test_errors();
    TEST_MAIN_END();
}
