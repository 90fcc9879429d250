/* test_compare_sweep.c — mech/answers/frames/compare_sweep.h against closed forms and a
 * second method:
 *  - the harmonic oscillator x'' = -x (spring k = 1, m = 1, x0 = 1, v0 = 0),
 *    whose exact reference is x = cos t, v = -sin t: rk4 at h and h/2. RK4 on
 *    this linear system multiplies w = x + i v by R(-ih) per step, R(z) =
 *    1 + z + z^2/2 + z^3/6 + z^4/24, so after n steps w = R(-ih)^n exactly;
 *    each run's max position and velocity errors over the samples are
 *    computed that way here (complex arithmetic, independent of the driver)
 *    and the two runs' ratio is ~16 (fourth order). The closed-form row has
 *    no error beyond round-off and 0 steps;
 *  - the damped oscillator x'' = -x - 2 gamma x' (spring + linear drag, no
 *    exact reference, so the sweep's reference is radau15 at rtol 1e-10):
 *    rk4's error against it equals the error of the RK4 matrix
 *    R(hA) = I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24 applied n times,
 *    measured against x = e^(-gamma t)(cos wd t + gamma/wd sin wd t),
 *    wd = sqrt(1 - gamma^2); a row whose method does not apply (boris with
 *    drag) is kept as failed;
 *  - the shared budget: 100 + 200 steps in a budget of 150 keeps the first
 *    run (partial, the second not run, 100 steps in all); in a budget of 50
 *    nothing finished, so the sweep fails naming run 0; more than
 *    MECH_COMPARE_MAX_RUNS runs is EINVAL. */
#include <complex.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/answers/frames/compare_sweep.h"
#include "testlib.h"

#define T_END 10.0
#define SAMPLES 11

static struct mech_force forces[2];

static struct mech_trajectory_problem oscillator(double b)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    memset(forces, 0, sizeof forces);
    forces[0].type = MECH_FORCE_SPRING;
    forces[0].u.spring.k = 1.0;
    forces[1].type = MECH_FORCE_LINEAR_DRAG;
    forces[1].u.linear_drag.b = b;
    p.mass = 1.0;
    p.position = mech_vec3_make(1, 0, 0);
    p.velocity = mech_vec3_make(0, 0, 0);
    p.frame.type = MECH_FRAME_INERTIAL;
    p.forces = forces;
    p.n_forces = b > 0 ? 2 : 1;
    p.t_end = T_END;
    p.samples = SAMPLES;
    p.reduce_planar = 1;
    return p;
}

static struct mech_trajectory_problem fixed(struct mech_trajectory_problem p, const char *m,
                                            double dt)
{
    p.method = m;
    p.opt.dt = dt;
    return p;
}

/* RK4's max |x - cos t| (*ev: max |v + sin t|) over the samples, from the
 * amplification factor R(-ih). */
static double rk4_oscillator_error(double h, double *ev)
{
    const double complex z = -I * h;
    const double complex R = 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
    const int per = (int)lround(T_END / (SAMPLES - 1) / h);
    double ex = 0, evm = 0;
    double complex w = 1;
    for (int k = 0; k < SAMPLES; k++) {
        const double t = k * (T_END / (SAMPLES - 1));
        ex = fmax(ex, fabs(creal(w) - cos(t)));
        evm = fmax(evm, fabs(cimag(w) + sin(t)));
        for (int s = 0; s < per; s++)
            w *= R;
    }
    *ev = evm;
    return ex;
}

static void test_oscillator_two_steps(void)
{
    struct mech_trajectory_problem base = oscillator(0);
    struct mech_trajectory_problem p1 = fixed(base, "rk4", 0.1), p2 = fixed(base, "rk4", 0.05);
    struct mech_trajectory_problem p3 = base;
    const struct mech_compare_config cfg[3] = {{&p1, 0}, {&p2, 0}, {&p3, 1}};
    struct mech_compare_row rows[3];
    struct mech_compare_result out;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = mech_budget_make(100000, 3600);
    CHECK_EQ_INT(mech_compare_sweep(&base, cfg, 3, &b, rows, &out, &e), MECH_OK);
    CHECK_EQ_INT(out.reference_exact, 1);
    CHECK(out.reference_name && !strcmp(out.reference_name, "harmonic_oscillator"));
    CHECK_EQ_INT(out.partial, 0);
    CHECK(out.reference_cpu_seconds == -1.0);
    double ev1, ev2;
    const double ex1 = rk4_oscillator_error(0.1, &ev1), ex2 = rk4_oscillator_error(0.05, &ev2);
    for (int k = 0; k < 2; k++)
        CHECK_EQ_INT(rows[k].state, MECH_COMPARE_RUN_OK);
    CHECK_CLOSE(rows[0].max_position_error, ex1, 1e-6, 1e-15);
    CHECK_CLOSE(rows[1].max_position_error, ex2, 1e-6, 1e-15);
    CHECK_CLOSE(rows[0].max_velocity_error, ev1, 1e-6, 1e-15);
    CHECK_CLOSE(rows[1].max_velocity_error, ev2, 1e-6, 1e-15);
    /* max |r_ref| = 1: the relative error is the absolute one */
    CHECK_CLOSE(rows[0].max_relative_position_error, ex1, 1e-6, 1e-15);
    /* fourth order: halving h divides the error by ~2^4 */
    CHECK_CLOSE(rows[0].max_position_error / rows[1].max_position_error, 16.0, 0.05, 0);
    CHECK_EQ_INT(rows[0].stats.steps, 100);
    CHECK_EQ_INT(rows[1].stats.steps, 200);
    CHECK_EQ_INT(out.total_steps, 300);
    CHECK_EQ_INT(rows[2].state, MECH_COMPARE_RUN_OK);
    CHECK_EQ_INT(rows[2].stats.steps, 0);
    CHECK(rows[2].max_position_error < 1e-13);
    CHECK(rows[0].cpu_seconds >= 0 && rows[2].cpu_seconds >= 0);
}

/* The damped oscillator's x at t (gamma < 1). */
static double damped_x(double gamma, double t)
{
    const double wd = sqrt(1 - gamma * gamma);
    return exp(-gamma * t) * (cos(wd * t) + gamma / wd * sin(wd * t));
}

/* RK4's max |x - x_exact| over the samples, from the matrix R(hA). */
static double rk4_damped_error(double gamma, double h)
{
    const double A[2][2] = {{0, 1}, {-1, -2 * gamma}};
    double R[2][2] = {{1, 0}, {0, 1}}, term[2][2] = {{1, 0}, {0, 1}};
    for (int j = 1; j <= 4; j++) { /* term = (hA)^j / j! */
        double nt[2][2];
        for (int r = 0; r < 2; r++)
            for (int c = 0; c < 2; c++)
                nt[r][c] = h / j * (term[r][0] * A[0][c] + term[r][1] * A[1][c]);
        memcpy(term, nt, sizeof term);
        for (int r = 0; r < 2; r++)
            for (int c = 0; c < 2; c++)
                R[r][c] += term[r][c];
    }
    const int per = (int)lround(T_END / (SAMPLES - 1) / h);
    double x = 1, v = 0, err = 0;
    for (int k = 0; k < SAMPLES; k++) {
        err = fmax(err, fabs(x - damped_x(gamma, k * (T_END / (SAMPLES - 1)))));
        for (int s = 0; s < per; s++) {
            const double x1 = R[0][0] * x + R[0][1] * v, v1 = R[1][0] * x + R[1][1] * v;
            x = x1, v = v1;
        }
    }
    return err;
}

static void test_damped_numerical_reference(void)
{
    const double gamma = 0.1; /* b = 2 gamma m */
    struct mech_trajectory_problem base = oscillator(2 * gamma);
    struct mech_trajectory_problem p1 = fixed(base, "rk4", 0.1), p2 = fixed(base, "boris", 0.1);
    const struct mech_compare_config cfg[2] = {{&p1, 0}, {&p2, 0}};
    struct mech_compare_row rows[2];
    struct mech_compare_result out;
    struct mech_budget b = mech_budget_make(1000000, 3600);
    CHECK_EQ_INT(mech_compare_sweep(&base, cfg, 2, &b, rows, &out, NULL), MECH_OK);
    CHECK_EQ_INT(out.reference_exact, 0);
    CHECK(out.reference_name && !strcmp(out.reference_name, "radau15"));
    CHECK(out.reference_stats.steps > 0 && out.reference_cpu_seconds >= 0);
    CHECK_EQ_INT(rows[0].state, MECH_COMPARE_RUN_OK);
    /* the reference's own error (~1e-10) is far below rk4's (~1e-5) */
    CHECK_CLOSE(rows[0].max_position_error, rk4_damped_error(gamma, 0.1), 1e-3, 0);
    CHECK_EQ_INT(rows[1].state, MECH_COMPARE_RUN_FAILED);
    CHECK(rows[1].status == MECH_EINVAL || rows[1].status == MECH_EDOMAIN);
    CHECK(rows[1].cpu_seconds == 0.0);
    CHECK_EQ_INT(out.total_steps, out.reference_stats.steps + 100);
}

static void test_shared_budget(void)
{
    struct mech_trajectory_problem base = oscillator(0);
    struct mech_trajectory_problem p1 = fixed(base, "rk4", 0.1), p2 = fixed(base, "rk4", 0.05);
    const struct mech_compare_config cfg[3] = {{&p1, 0}, {&p2, 0}, {&p1, 0}};
    struct mech_compare_row rows[3];
    struct mech_compare_result out;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = mech_budget_make(150, 3600);
    CHECK_EQ_INT(mech_compare_sweep(&base, cfg, 3, &b, rows, &out, &e), MECH_OK);
    CHECK_EQ_INT(out.partial, 1);
    CHECK_EQ_INT(out.stopped_run, 1);
    CHECK_EQ_INT(rows[0].state, MECH_COMPARE_RUN_OK);
    CHECK_EQ_INT(rows[1].state, MECH_COMPARE_RUN_NOT_RUN);
    CHECK_EQ_INT(rows[1].status, MECH_EBUDGET);
    CHECK_EQ_INT(rows[1].err.progress.steps, 0); /* refused before its first step */
    CHECK_EQ_INT(rows[2].state, MECH_COMPARE_RUN_NOT_RUN);
    CHECK(rows[2].cpu_seconds == 0.0);
    CHECK_EQ_INT(out.total_steps, 100);

    /* nothing finished: the sweep fails, naming run 0 */
    b = mech_budget_make(50, 3600);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_compare_sweep(&base, cfg, 3, &b, rows, &out, &e), MECH_EBUDGET);
    CHECK_EQ_INT(out.failed_run, 0);
    CHECK_EQ_INT(e.code, MECH_EBUDGET);

    /* too many runs */
    static struct mech_compare_config many[MECH_COMPARE_MAX_RUNS + 1];
    static struct mech_compare_row many_rows[MECH_COMPARE_MAX_RUNS + 1];
    for (int k = 0; k <= MECH_COMPARE_MAX_RUNS; k++)
        many[k] = cfg[0];
    mech_error_clear(&e);
    CHECK_EQ_INT(
        mech_compare_sweep(&base, many, MECH_COMPARE_MAX_RUNS + 1, &b, many_rows, &out, &e),
        MECH_EINVAL);
    CHECK_EQ_INT(out.failed_run, -2);
    CHECK(!strcmp(e.param, "runs"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_oscillator_two_steps();
    test_damped_numerical_reference();
    test_shared_budget();
    TEST_MAIN_END();
}
