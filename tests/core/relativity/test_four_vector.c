/* test_four_vector.c — the Minkowski dot product, kinds and relative γ
 * (core/relativity/four_vector.c) against exact rational arithmetic (Python Fraction of
 * the binary inputs, quoted) and the velocity-addition closed form. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

#include "mech/relativity/four_vector.h"
#include "testlib.h"

static void test_dot(void)
{
    const double a[4] = {1, 2, 3, 4}, b[4] = {5, 6, 7, 8};
    CHECK_CLOSE(mech_four_dot(a, b), -5 + 12 + 21 + 32, 0, 0);
    CHECK_CLOSE(mech_four_dot(a, a), -1 + 4 + 9 + 16, 0, 0);
    /* Cancellation: products near 1e16 whose difference is 2e7. Exact value of
     * the binary inputs (Fraction): -19999998.807907104; the naive sum of
     * rounded products gives -20000000.0 (6e-8 relative off). */
    const double c[4] = {100000000.1, 100000000.0, 0, 0}, d[4] = {100000000.0, 99999999.9, 0, 0};
    CHECK_CLOSE(mech_four_dot(c, d), -19999998.807907104, 1e-16, 0);
    CHECK_CLOSE(mech_four_dot(d, c), -19999998.807907104, 1e-16, 0);
    /* Symmetric and bilinear on exact inputs: (2a)·b = 2 (a·b). */
    const double a2[4] = {2, 4, 6, 8};
    CHECK_CLOSE(mech_four_dot(a2, b), 2 * 60.0, 0, 0);
    /* Large components (1e150) stay finite: −1e300 + 1e300·0.5. */
    const double big[4] = {1e150, 1e150, 0, 0}, big2[4] = {1e150, 0.5e150, 0, 0};
    CHECK_CLOSE(mech_four_dot(big, big2), -0.5e300, 1e-15, 0);
}

static void test_kinds(void)
{
    const double light[4] = {1, 0.6, 0.8, 0}, time[4] = {1, 0, 0, 0}, space[4] = {0, 1, 0, 0};
    const double zero[4] = {0, 0, 0, 0}, nearly[4] = {1, 1 - 1e-12, 0, 0};
    CHECK_EQ_INT(mech_four_kind_of(light), MECH_FOUR_LIGHTLIKE);
    CHECK_EQ_INT(mech_four_kind_of(time), MECH_FOUR_TIMELIKE);
    CHECK_EQ_INT(mech_four_kind_of(space), MECH_FOUR_SPACELIKE);
    CHECK_EQ_INT(mech_four_kind_of(zero), MECH_FOUR_LIGHTLIKE);
    CHECK_EQ_INT(mech_four_kind_of(nearly), MECH_FOUR_TIMELIKE); /* s² = −2e-12, not rounding */
}

/* u = (5/4, 3/4, 0, 0) and v = (5/4, −3/4, 0, 0) are 4-velocities at β = ±0.6:
 * v seen from u moves at (0.6 + 0.6)/(1 + 0.36) = 15/17, γ = 17/8 = 2.125, and
 * −u·v = 25/16 + 9/16 = 2.125. Against the rest 4-velocity: γ = 5/4. */
static void test_relative_gamma(void)
{
    const double u[4] = {1.25, 0.75, 0, 0}, v[4] = {1.25, -0.75, 0, 0}, rest[4] = {1, 0, 0, 0};
    double g = 0;
    CHECK_EQ_INT(mech_four_relative_gamma(u, v, &g), 1);
    CHECK_CLOSE(g, 2.125, 2e-16, 0);
    CHECK_EQ_INT(mech_four_relative_gamma(rest, u, &g), 1);
    CHECK_CLOSE(g, 1.25, 2e-16, 0);
    /* Momenta (scale does not matter): p = m u with m = 938 and 0.511. */
    const double pu[4] = {938 * 1.25, 938 * 0.75, 0, 0}, pv[4] = {0.511 * 1.25, -0.511 * 0.75, 0, 0};
    CHECK_EQ_INT(mech_four_relative_gamma(pu, pv, &g), 1);
    CHECK_CLOSE(g, 2.125, 4e-16, 0);
    const double past[4] = {-1, 0, 0, 0}, light[4] = {1, 1, 0, 0};
    CHECK_EQ_INT(mech_four_relative_gamma(rest, past, &g), 0);
    CHECK_EQ_INT(mech_four_relative_gamma(rest, light, &g), 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_dot();
    test_kinds();
    test_relative_gamma();
    TEST_MAIN_END();
}
