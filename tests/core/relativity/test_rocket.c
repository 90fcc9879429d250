/* test_rocket.c — the relativistic rocket (core/relativity/rocket.c) against closed
 * forms: the photon rocket m_i/m_f = gamma (1 + beta) (= 2 at beta = 0.6),
 * exhaust at c/2 (= 4), a chemical rocket at 1 m/s (50-digit Decimal,
 * quoted), the inverse, overflow and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/rocket.h"
#include "mech/base/constants.h"
#include "testlib.h"

static void test_values(void)
{
    struct mech_rocket r;
    const double LN2 = 0.69314718055994530942;
    /* beta = 0.6: eta = atanh 0.6 = ln 2. Photon rocket: m_i/m_f = e^eta = gamma (1 + beta)
     * = 1.25 * 1.6 = 2; Tsiolkovsky exp(0.6) = 1.8221188, 8.894 % low (Decimal:
     * exp(0.6)/2 - 1 = -0.0889405998047455126). */
    CHECK_EQ_INT(mech_rocket_for_rapidity(LN2, 0.6, 1.0, &r, NULL), MECH_OK);
    CHECK_CLOSE(r.mass_ratio, 2.0, 4e-16, 0);
    CHECK_CLOSE(r.fuel_fraction, 0.5, 4e-16, 0);
    CHECK_CLOSE(r.newtonian_mass_ratio, exp(0.6), 4e-16, 0);
    CHECK_CLOSE(r.newtonian_rel_error, -0.088940599804745513, 1e-14, 0);
    /* Exhaust at c/2: (e^eta)^2 = 4; Newton exp(1.2)/4 - 1 = -0.169970769315863128. */
    CHECK_EQ_INT(mech_rocket_for_rapidity(LN2, 0.6, 0.5, &r, NULL), MECH_OK);
    CHECK_CLOSE(r.mass_ratio, 4.0, 1e-15, 0);
    CHECK_CLOSE(r.fuel_fraction, 0.75, 1e-15, 0);
    CHECK_CLOSE(r.newtonian_rel_error, -0.16997076931586313, 1e-14, 0);
    /* 1 m/s with a 4500 m/s exhaust: ln(m_i/m_f) = 2.2222222222222222e-4,
     * fuel fraction 2.2219753269308541e-4, Newton's relative error
     * -8.2418522670638398e-22 (= -(eta - beta)/beta_e: a difference the direct
     * eta - beta would lose entirely). */
    const double b = 1.0 / MECH_C, be = 4500.0 / MECH_C;
    const double eta = 3.3356409519815204e-09;
    CHECK_EQ_INT(mech_rocket_for_rapidity(eta, b, be, &r, NULL), MECH_OK);
    CHECK_CLOSE(r.log_mass_ratio, 2.2222222222222222e-4, 1e-15, 0);
    CHECK_CLOSE(r.fuel_fraction, 2.2219753269308541e-4, 1e-15, 0);
    CHECK_CLOSE(r.newtonian_rel_error, -8.2418522670638398e-22, 1e-14, 0);
    /* Overflow: eta = 300 with exhaust at 1e-3 c: ln ratio 3e5, ratio +inf, fuel all. */
    CHECK_EQ_INT(mech_rocket_for_rapidity(300, 1.0, 1e-3, &r, NULL), MECH_OK);
    CHECK_CLOSE(r.log_mass_ratio, 3e5, 1e-15, 0);
    CHECK(isinf(r.mass_ratio));
    CHECK_CLOSE(r.fuel_fraction, 1.0, 0, 0);
    /* Inverse: a photon rocket burning to m_f = m_i/2 reaches eta = ln 2. */
    double e2;
    CHECK_EQ_INT(mech_rocket_rapidity(2.0, 1.0, &e2, NULL), MECH_OK);
    CHECK_CLOSE(e2, LN2, 2e-16, 0);
}

static void test_errors(void)
{
    struct mech_rocket r;
    struct mech_error e;
    double eta;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rocket_for_rapidity(1, 0.7, 1.5, &r, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "exhaust_beta"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rocket_for_rapidity(1, 0.7, 0.0, &r, &e), MECH_EDOMAIN);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rocket_rapidity(0.5, 1.0, &eta, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass_ratio"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_values();
    test_errors();
    TEST_MAIN_END();
}
