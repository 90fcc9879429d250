/* test_apsides.c — mech/hamiltonian/apsides.h: the pericentres of a Kepler orbit
 * (H = p_r^2/2 + p_phi^2/(2 r^2) - 1/r) started at its apocentre r = a(1 + e)
 * lie at r = a(1 - e), phi = pi + 2 pi k, t = T/2 + k T with T = 2 pi a^(3/2),
 * and the apsidal angle is pi; the isotropic oscillator's (n = 2) is pi/2 for
 * any orbit (Bertrand); radial motion has none; the budget and the system
 * refused with their statuses. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/hamiltonian/apsides.h"
#include "mech/base/constants.h"
#include "testlib.h"

static struct mech_ham_system central(double k, double n)
{
    struct mech_ham_system s;
    memset(&s, 0, sizeof s);
    s.kind = MECH_HAM_CENTRAL;
    s.mass = 1.0;
    s.strength = k;
    s.power = n;
    CHECK_EQ_INT(mech_ham_system_check(&s, NULL), MECH_OK);
    return s;
}

static void test_kepler(void)
{
    const struct mech_ham_system s = central(-1.0, -1.0);
    /* L = 0.9 from r = 1 at rest radially: p = L^2 = 0.81, 1 = p/(1 - e) -> e = 0.19 */
    const double L = 0.9, e = 1.0 - L * L, a = 1.0 / (1.0 + e);
    const double T = 2.0 * MECH_PI * pow(a, 1.5);
    const double y0[4] = {1.0, 0.0, 0.0, L};
    struct mech_ode_options opt = {0, 0, T / 2000.0};
    struct mech_budget b = mech_budget_make(10000000, 120.0);
    struct mech_apsides ap;
    struct mech_error err;
    mech_error_clear(&err);
    CHECK_EQ_INT(
        mech_apsides_find(&s, y0, 4.9 * T, mech_ode_method_find("gauss6"), opt, &b, 0, &ap, &err),
        MECH_OK);
    CHECK(!ap.radial);
    CHECK_EQ_INT((int)ap.n, 5);
    for (size_t k = 0; k < ap.n; k++) {
        CHECK_CLOSE(ap.r[k], a * (1.0 - e), 1e-10, 0);
        CHECK_CLOSE(ap.phi[k], MECH_PI * (2.0 * (double)k + 1.0), 1e-10, 0);
        CHECK_CLOSE(ap.t[k], T * ((double)k + 0.5), 1e-10, 0);
    }
    CHECK(ap.has_measured && ap.has_near_circular);
    CHECK_CLOSE(ap.angle_measured, MECH_PI, 1e-10, 0);
    CHECK_CLOSE(ap.angle_near_circular, MECH_PI, 1e-15, 0);
    mech_apsides_free(&ap);
    /* one pericentre only: no measured angle */
    CHECK_EQ_INT(
        mech_apsides_find(&s, y0, 0.9 * T, mech_ode_method_find("gauss6"), opt, &b, 0, &ap, &err),
        MECH_OK);
    CHECK_EQ_INT((int)ap.n, 1);
    CHECK(!ap.has_measured && isnan(ap.angle_measured));
    mech_apsides_free(&ap);
}

/* the isotropic oscillator V = k r^2: closed ellipses centred on the origin,
 * two pericentres per turn, apsidal angle pi/2 for any eccentricity */
static void test_oscillator(void)
{
    const struct mech_ham_system s = central(0.5, 2.0); /* omega^2 = 2k/m = 1 */
    const double y0[4] = {1.0, 0.0, 0.0, 0.4};
    struct mech_ode_options opt = {0, 0, 1e-3};
    struct mech_budget b = mech_budget_make(10000000, 120.0);
    struct mech_apsides ap;
    CHECK_EQ_INT(
        mech_apsides_find(&s, y0, 20.0, mech_ode_method_find("gauss6"), opt, &b, 0, &ap, NULL),
        MECH_OK);
    CHECK(ap.n >= 5);
    CHECK_CLOSE(ap.angle_measured, 0.5 * MECH_PI, 1e-10, 0);
    CHECK_CLOSE(ap.angle_near_circular, 0.5 * MECH_PI, 1e-15, 0);
    /* the pericentre r = 0.4 (semi-minor axis = |L|/omega for r0 = 1 at rest radially),
     * half a period apart: t = pi/2 + k pi */
    for (size_t k = 0; k < ap.n; k++) {
        CHECK_CLOSE(ap.r[k], 0.4, 1e-10, 0);
        CHECK_CLOSE(ap.t[k], 0.5 * MECH_PI * (2.0 * (double)k + 1.0), 1e-9, 0);
    }
    mech_apsides_free(&ap);
}

static void test_edges(void)
{
    struct mech_ham_system s = central(-1.0, -1.0);
    struct mech_ode_options opt = {0, 0, 1e-2};
    struct mech_budget b = mech_budget_make(1000, 120.0);
    struct mech_apsides ap;
    struct mech_error e;
    /* radial motion */
    const double yr[4] = {1.0, 0.0, 0.1, 0.0};
    mech_error_clear(&e);
    CHECK_EQ_INT(
        mech_apsides_find(&s, yr, 1.0, mech_ode_method_find("gauss6"), opt, &b, 0, &ap, &e),
        MECH_OK);
    CHECK(ap.radial && ap.n == 0 && ap.t == NULL);
    mech_apsides_free(&ap);
    /* the flow spent the budget */
    const double y0[4] = {1.0, 0.0, 0.0, 0.9};
    mech_error_clear(&e);
    CHECK_EQ_INT(
        mech_apsides_find(&s, y0, 1.0, mech_ode_method_find("gauss6"), opt, &b, 1000, &ap, &e),
        MECH_EBUDGET);
    CHECK(strstr(e.text, "before the apsides") != NULL);
    CHECK(ap.t == NULL);
    mech_apsides_free(&ap);
    /* too few steps for the run */
    mech_error_clear(&e);
    CHECK_EQ_INT(
        mech_apsides_find(&s, y0, 100.0, mech_ode_method_find("gauss6"), opt, &b, 990, &ap, &e),
        MECH_EBUDGET);
    mech_apsides_free(&ap);
    /* not a central potential */
    s.kind = MECH_HAM_HENON_HEILES;
    mech_error_clear(&e);
    CHECK_EQ_INT(
        mech_apsides_find(&s, y0, 1.0, mech_ode_method_find("gauss6"), opt, &b, 0, &ap, &e),
        MECH_EINVAL);
    CHECK(!strcmp(e.param, "system"));
    mech_apsides_free(&ap);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_kepler();
    test_oscillator();
    test_edges();
    TEST_MAIN_END();
}
