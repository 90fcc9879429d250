/* test_decay_estimate.c — the notes' neutron-decay estimate (core/
 * decay_estimate.c) against the notes' own formulas evaluated literally in
 * 50-digit Decimal (python3; quoted): p ≈ sqrt(Δm² − m_e²), T ≈ Δm − m_e, the
 * intermediate p² = (Δm² − m_e²)/(1 + Δm/m_p), and the exact endpoint
 * E = (M² + m² − S²)/(2M); the differences are checked to a few ulp of
 * themselves (they are formed without subtracting the endpoints). Also
 * Λ → p π⁻ (a light recoil: the estimate is poor, 17 % high), and the
 * errors (no massive recoil, below threshold). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/decay_estimate.h"
#include "testlib.h"

static void test_neutron(void)
{
    const double m[3] = {938.27208816, 0.51099895, 0};
    struct mech_decay_estimate o;
    CHECK_EQ_INT(mech_decay_endpoint_estimate(939.5654205, m, 3, 1, &o, NULL), MECH_OK);
    CHECK_CLOSE(o.recoil_mass, 938.27208816, 0, 0);
    CHECK_CLOSE(o.kinetic, 0.78233339, 1e-13, 0);
    CHECK_CLOSE(o.energy, 0.78233339 + 0.51099895, 1e-14, 0);
    CHECK_CLOSE(o.momentum, 1.1881029478916265613, 1e-13, 0);
    CHECK_CLOSE(o.kinetic_minus_exact, 7.511922980507205139e-4, 1e-13, 0);
    CHECK_CLOSE(o.momentum_minus_exact, 8.177687988418276859e-4, 1e-13, 0);
    CHECK_CLOSE(o.mid_momentum, 1.1872849414540375061, 1e-14, 0);
    CHECK_CLOSE(o.mid_kinetic, 0.78158197942168219520, 1e-13, 0);
    CHECK_CLOSE(o.mid_kinetic_minus_exact, -2.182802670842893583e-7, 1e-12, 0);
    CHECK_CLOSE(o.mid_momentum_minus_exact, -2.376387472275513897e-7, 1e-12, 0);
}

static void test_two_body_light_recoil(void)
{
    /* Λ → p π⁻, the pion's endpoint against a proton recoil: S = m_p is
     * not ≫ Q = 37.8 MeV, and the estimate is 5.4 MeV (17 %) high. */
    const double m[2] = {938.27208816, 139.57039};
    struct mech_decay_estimate o;
    CHECK_EQ_INT(mech_decay_endpoint_estimate(1115.683, m, 2, 1, &o, NULL), MECH_OK);
    CHECK_CLOSE(o.kinetic_minus_exact, 5.3755134187525274588, 1e-13, 0);
    CHECK_CLOSE(o.momentum_minus_exact, 8.9407484425696321546, 1e-13, 0);
    CHECK_CLOSE(o.mid_momentum, 100.43599156024730999, 1e-14, 0);
    CHECK_CLOSE(o.mid_kinetic_minus_exact, -0.084003645159166215093, 1e-12, 0);
    CHECK_CLOSE(o.mid_momentum_minus_exact, -0.14375066056600905096, 1e-12, 0);
}

static void test_errors(void)
{
    struct mech_decay_estimate o;
    struct mech_error e;
    const double mu[3] = {0.51099895, 0, 0};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_decay_endpoint_estimate(105.6583755, mu, 3, 0, &o, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "daughters"));
    const double heavy[2] = {1000, 1000};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_decay_endpoint_estimate(1500, heavy, 2, 0, &o, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "daughters"));
    const double bad[2] = {1, NAN};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_decay_endpoint_estimate(10, bad, 2, 0, &o, &e), MECH_EINVAL);
    CHECK_EQ_INT(mech_decay_endpoint_estimate(10, bad, 1, 0, &o, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_neutron();
    test_two_body_light_recoil();
    test_errors();
    TEST_MAIN_END();
}
