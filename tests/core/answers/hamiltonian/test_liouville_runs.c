/* test_liouville_runs.c — mech/answers/hamiltonian/liouville_runs.h on the linear flow of the
 * harmonic oscillator (m = k = 1), where everything has a closed form: the
 * ellipse's area pi a b; the symplectic gauss4 keeps det Phi = 1 and the
 * area; rk4's one-step map has det |R(ih)|^2 = 1 - h^6/72 + h^8/576 (R the
 * stability polynomial 1 + z + z^2/2 + z^3/6 + z^4/24), so after N steps
 * det Phi = (1 - h^6/72 + h^8/576)^N, and a linear map scales every area by
 * its determinant: area(t) = det Phi(t) * pi a b. The reference start (the
 * vertex mean, the centre, the given point), the budget shared by the runs
 * (the failing run named) and the run count refused outside 1..2. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/hamiltonian/liouville_runs.h"
#include "testlib.h"

static struct mech_ham_system oscillator(void)
{
    struct mech_ham_system s;
    memset(&s, 0, sizeof s);
    s.kind = MECH_HAM_OSCILLATOR;
    s.dof = 1;
    s.mass = 1.0;
    s.k[0] = 1.0;
    CHECK_EQ_INT(mech_ham_system_check(&s, NULL), MECH_OK);
    return s;
}

static const double CTR[2] = {0.3, -0.2}, U[2] = {0.5, 0.0}, W[2] = {0.0, 2.0};

static struct mech_liouville_problem ellipse(const struct mech_ham_system *s)
{
    struct mech_liouville_problem p;
    memset(&p, 0, sizeof p);
    p.sys = s;
    p.t_end = 10.0;
    p.n_samples = 3;
    p.shape = MECH_LIOUVILLE_ELLIPSE;
    p.center = CTR;
    p.axis_u = U;
    p.axis_w = W;
    p.tol = 1e-10;
    p.max_intervals = 4096;
    return p;
}

static void test_linear_flow(void)
{
    const struct mech_ham_system s = oscillator();
    const struct mech_liouville_problem p = ellipse(&s);
    const double h = 0.1;
    const struct mech_integrator *m[2] = {mech_ode_method_find("gauss4"),
                                          mech_ode_method_find("rk4")};
    const struct mech_ode_options o[2] = {{0, 0, h}, {0, 0, h}};
    struct mech_budget b = mech_budget_make(100000000, 120.0);
    struct mech_liouville_runs r;
    size_t failed = 9;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_liouville_runs(&p, 2, m, o, &b, &r, &failed, &e), MECH_OK);
    CHECK_EQ_INT((int)failed, 0);
    CHECK_EQ_INT((int)r.n_runs, 2);
    const double A0 = MECH_PI * 0.5 * 2.0;
    const double step_det = 1.0 - pow(h, 6) / 72.0 + pow(h, 8) / 576.0;
    for (int k = 0; k < 2; k++)
        CHECK_CLOSE(r.run[k].area0, A0, 1e-14, 0);
    for (size_t i = 0; i < 3; i++) {
        CHECK_CLOSE(r.run[0].t[i], 5.0 * (double)i, 1e-15, 0);
        /* symplectic: det 1 and the area kept */
        CHECK_CLOSE(r.run[0].det[i], 1.0, 0, 1e-12);
        CHECK_CLOSE(r.run[0].area[i], A0, 1e-10, 0);
        /* rk4: det (|R(ih)|^2)^N with N = 50 i steps, deviating 1.4e-6 at t = 10 */
        const double want = pow(step_det, 50.0 * (double)i);
        CHECK_CLOSE(r.run[1].det[i] - 1.0, want - 1.0, 1e-6, 1e-15);
        CHECK_CLOSE(r.run[1].area[i], want * A0, 1e-10, 0);
    }
    CHECK(1.0 - r.run[1].det[2] > 1e-6); /* the non-symplectic loss is visible */
    /* the reference orbit starts at the centre and follows x = x0 cos t + p0 sin t,
     * within gauss4's phase error h^4/720 per unit time (1.4e-6 rad at t = 10, times
     * the amplitude 0.36) */
    CHECK_CLOSE(r.run[0].reference_y[0], CTR[0], 0, 0);
    CHECK_CLOSE(r.run[0].reference_y[4], CTR[0] * cos(10.0) + CTR[1] * sin(10.0), 0, 1e-6);
    mech_liouville_runs_free(&r);
    CHECK(r.buf == NULL);
}

static void test_reference_start(void)
{
    const struct mech_ham_system s = oscillator();
    struct mech_liouville_problem p = ellipse(&s);
    double y[2];
    mech_liouville_reference_start(&p, y);
    CHECK(y[0] == CTR[0] && y[1] == CTR[1]);
    const double v[8] = {0, 0, 1, 0, 1, 3, 0, 3};
    p.shape = MECH_LIOUVILLE_POLYGON;
    p.vertices = v;
    p.n_vertices = 4;
    mech_liouville_reference_start(&p, y);
    CHECK_CLOSE(y[0], 0.5, 1e-15, 0);
    CHECK_CLOSE(y[1], 1.5, 1e-15, 0);
    const double ref[2] = {7.0, -8.0};
    p.reference = ref;
    mech_liouville_reference_start(&p, y);
    CHECK(y[0] == 7.0 && y[1] == -8.0);
}

static void test_errors(void)
{
    const struct mech_ham_system s = oscillator();
    const struct mech_liouville_problem p = ellipse(&s);
    const struct mech_integrator *m[2] = {mech_ode_method_find("gauss4"),
                                          mech_ode_method_find("rk4")};
    const struct mech_ode_options o[2] = {{0, 0, 0.1}, {0, 0, 0.1}};
    struct mech_budget b = mech_budget_make(100000000, 120.0);
    struct mech_liouville_runs r;
    size_t failed;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_liouville_runs(&p, 0, m, o, &b, &r, &failed, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "integrators"));
    mech_liouville_runs_free(&r);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_liouville_runs(&p, 3, m, o, &b, &r, &failed, &e), MECH_EINVAL);
    mech_liouville_runs_free(&r);
    /* the budget: run 0 alone fits, run 1 gets what run 0 left */
    CHECK_EQ_INT(mech_liouville_runs(&p, 1, m, o, &b, &r, &failed, NULL), MECH_OK);
    const long steps0 = r.run[0].stats.steps;
    mech_liouville_runs_free(&r);
    b = mech_budget_make(steps0 + 10, 120.0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_liouville_runs(&p, 2, m, o, &b, &r, &failed, &e), MECH_EBUDGET);
    CHECK_EQ_INT((int)failed, 1);
    mech_liouville_runs_free(&r);
    b = mech_budget_make(10, 120.0);
    CHECK_EQ_INT(mech_liouville_runs(&p, 2, m, o, &b, &r, &failed, NULL), MECH_EBUDGET);
    CHECK_EQ_INT((int)failed, 0);
    mech_liouville_runs_free(&r);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_linear_flow();
    test_reference_start();
    test_errors();
    TEST_MAIN_END();
}
