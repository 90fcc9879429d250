/* test_poincare_orbits.c — mech/answers/hamiltonian/poincare_orbits.h: for the 2D oscillator with
 * omega_x = 1, omega_y = 2 every upward crossing of x = 0 comes 2 pi apart and
 * returns to the start's (y, p_y), for each of several orbits; the spherical
 * pendulum's phi in the plane reduced to [0, 2 pi) (its cos and sin those of
 * the unreduced state); the totals the sum of the orbits'; the budget spent
 * before an orbit, a refusing caller and max_crossings out of range refused. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/hamiltonian/poincare_orbits.h"
#include "testlib.h"

struct seen {
    size_t calls;
    long steps;
    size_t refuse_at; /* refuse orbit k (SIZE_MAX: never) */
    const double *starts;
    int wrap_ok;
};

static int check_oscillator(void *ctx, size_t k, const struct mech_poincare_result *r)
{
    struct seen *s = ctx;
    CHECK_EQ_INT((int)k, (int)s->calls);
    s->calls++;
    s->steps += r->stats.steps;
    CHECK_EQ_INT((int)r->n_crossings, 4);
    const double *y0 = s->starts + 4 * k;
    for (size_t i = 0; i < r->n_crossings; i++) {
        CHECK_CLOSE(r->t[i], 2.0 * MECH_PI * (double)(i + 1), 1e-10, 0);
        CHECK_CLOSE(r->u[i], y0[1], 0, 1e-10);
        CHECK_CLOSE(r->v[i], y0[3], 0, 1e-10);
    }
    return k == s->refuse_at;
}

static void test_oscillator(void)
{
    struct mech_ham_system sys;
    memset(&sys, 0, sizeof sys);
    sys.kind = MECH_HAM_OSCILLATOR;
    sys.dof = 2;
    sys.mass = 1.0;
    sys.k[0] = 1.0;
    sys.k[1] = 4.0;
    CHECK_EQ_INT(mech_ham_system_check(&sys, NULL), MECH_OK);
    /* two starts on x = 0 with p_x > 0 */
    const double starts[8] = {0.0, 0.3, 1.0, -0.2, 0.0, -0.1, 0.5, 0.7};
    struct mech_poincare_problem p = {
        &sys, {0, 0.0, 0}, NULL, 30.0, 4, mech_ode_method_find("gauss6"), {0, 0, 1e-3}};
    struct mech_budget b = mech_budget_make(100000000, 120.0);
    struct seen s = {0, 0, (size_t)-1, starts, 1};
    struct mech_poincare_totals tot;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_poincare_orbits(&p, starts, 2, &b, check_oscillator, &s, &tot, &e), MECH_OK);
    CHECK_EQ_INT((int)s.calls, 2);
    CHECK(tot.stats.steps == s.steps && s.steps > 0);
    /* the caller refuses orbit 0 */
    s = (struct seen){0, 0, 0, starts, 1};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_poincare_orbits(&p, starts, 2, &b, check_oscillator, &s, &tot, &e),
                 MECH_ENOMEM);
    CHECK_EQ_INT((int)s.calls, 1);
    /* a budget that one orbit spends: orbit 1 never starts or stops short */
    s = (struct seen){0, 0, (size_t)-1, starts, 1};
    CHECK_EQ_INT(mech_poincare_orbits(&p, starts, 1, &b, check_oscillator, &s, &tot, NULL),
                 MECH_OK);
    b = mech_budget_make(tot.stats.steps, 120.0);
    s = (struct seen){0, 0, (size_t)-1, starts, 1};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_poincare_orbits(&p, starts, 2, &b, check_oscillator, &s, &tot, &e),
                 MECH_EBUDGET);
    CHECK(strstr(e.text, "before orbit 1") != NULL);
    /* max_crossings out of range */
    p.max_crossings = 0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_poincare_orbits(&p, starts, 2, &b, check_oscillator, &s, &tot, &e),
                 MECH_EINVAL);
    CHECK(!strcmp(e.param, "max_crossings"));
    p.max_crossings = MECH_POINCARE_ORBITS_MAX_CROSSINGS + 1;
    CHECK_EQ_INT(mech_poincare_orbits(&p, starts, 2, &b, check_oscillator, &s, &tot, NULL),
                 MECH_EINVAL);
}

static int check_wrap(void *ctx, size_t k, const struct mech_poincare_result *r)
{
    struct seen *s = ctx;
    (void)k;
    s->calls++;
    for (size_t i = 0; i < r->n_crossings; i++) {
        const double phi = r->y[4 * i + 1]; /* the unreduced state */
        if (!(r->u[i] >= 0.0 && r->u[i] < 2.0 * MECH_PI)) s->wrap_ok = 0;
        if (phi > 2.0 * MECH_PI) s->steps++; /* crossings whose phi needed reducing */
        CHECK_CLOSE(cos(r->u[i]), cos(phi), 0, 1e-12);
        CHECK_CLOSE(sin(r->u[i]), sin(phi), 0, 1e-12);
    }
    CHECK(r->n_crossings == 6);
    return 0;
}

static void test_wrap(void)
{
    struct mech_ham_system sys;
    memset(&sys, 0, sizeof sys);
    sys.kind = MECH_HAM_SPHERICAL_PENDULUM;
    sys.mass = 1.0;
    sys.length = 1.0;
    sys.g = 9.81;
    CHECK_EQ_INT(mech_ham_system_check(&sys, NULL), MECH_OK);
    /* section theta = 0.5 upwards; the plane (phi, p_phi); phi winds past 2 pi */
    const double start[4] = {0.4, 0.3, 0.2, 0.7};
    struct mech_poincare_problem p = {
        &sys, {0, 0.5, 0}, NULL, 100.0, 6, mech_ode_method_find("gauss6"), {0, 0, 1e-3}};
    struct mech_budget b = mech_budget_make(100000000, 120.0);
    struct seen s = {0, 0, (size_t)-1, start, 1};
    struct mech_poincare_totals tot;
    CHECK_EQ_INT(mech_poincare_orbits(&p, start, 1, &b, check_wrap, &s, &tot, NULL), MECH_OK);
    CHECK_EQ_INT((int)s.calls, 1);
    CHECK(s.wrap_ok);
    CHECK(s.steps >= 3); /* phi wound past 2 pi, so the reduction was exercised */
}

int main(void)
{
    gsl_set_error_handler_off();
    test_oscillator();
    test_wrap();
    TEST_MAIN_END();
}
