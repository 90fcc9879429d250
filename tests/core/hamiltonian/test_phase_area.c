/* test_phase_area.c — phase-space area of an energy contour and the period
 * as dA/dE (core/hamiltonian/phase_area.c): the pendulum against an independent
 * quadrature of ∮ p dθ and ∮ dθ/θ' (scipy quad, quoted), the period against
 * a finite difference of the area (the notes' T = dA/dE, a second method),
 * the small-amplitude limit 2πE/ω0 at k = 1e-10 (where the closed form
 * E − (1 − k²)K cancels completely), the oscillator, the separatrix and the
 * errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/hamiltonian/phase_area.h"
#include "mech/base/constants.h"
#include "testlib.h"

static void test_pendulum(void)
{
    const double m = 2.0, l = 1.5, g = 9.81, w0 = sqrt(g / l);
    const struct { double e, area, period; int motion; } t[] = {
        {1.0, 2.4621711382268994, 2.467456237564437, MECH_PHASE_LIBRATION},
        {30.0, 79.65478578876166, 2.9129728042015404, MECH_PHASE_LIBRATION},
        {80.0, 130.93994835013913, 1.4300084061009974, MECH_PHASE_ROTATION},
    };
    for (int i = 0; i < 3; i++) {
        struct mech_phase_area p, hi, lo;
        CHECK_EQ_INT(mech_phase_area_pendulum(m, l, g, t[i].e, &p, NULL), MECH_OK);
        CHECK_EQ_INT(p.motion, t[i].motion);
        CHECK_CLOSE(p.area, t[i].area, 1e-12, 0);
        CHECK_CLOSE(p.period, t[i].period, 1e-12, 0);
        /* T = dA/dE by a central difference (h = 1e-4 E: error ~h² A''' ~ 1e-9). */
        const double h = 1e-4 * t[i].e;
        CHECK_EQ_INT(mech_phase_area_pendulum(m, l, g, t[i].e + h, &hi, NULL), MECH_OK);
        CHECK_EQ_INT(mech_phase_area_pendulum(m, l, g, t[i].e - h, &lo, NULL), MECH_OK);
        CHECK_CLOSE((hi.area - lo.area) / (2 * h), p.period, 1e-7, 0);
    }
    /* Tiny amplitude: A = (2πE/ω0)(1 + k²/8 + ...), k² = E/(2mgl) ~ 1e-20. */
    struct mech_phase_area p;
    const double e = 2 * m * g * l * 1e-20;
    CHECK_EQ_INT(mech_phase_area_pendulum(m, l, g, e, &p, NULL), MECH_OK);
    CHECK_CLOSE(p.area, 2 * MECH_PI * e / w0, 1e-15, 0);
    CHECK_CLOSE(p.period, 2 * MECH_PI / w0, 1e-15, 0);
    CHECK_CLOSE(p.amplitude, 2e-10, 1e-15, 0);
    /* Separatrix: A = 16 m l² ω0 (scipy: 184.12865067663967), T infinite. */
    CHECK_EQ_INT(mech_phase_area_pendulum(m, l, g, 2 * m * g * l, &p, NULL), MECH_OK);
    CHECK_EQ_INT(p.motion, MECH_PHASE_SEPARATRIX);
    CHECK_CLOSE(p.area, 184.12865067663967, 1e-15, 0);
    CHECK(isinf(p.period));
}

static void test_oscillator(void)
{
    struct mech_phase_area p;
    /* m = 2, ω = 3, E = 9: an ellipse of semi-axes sqrt(2mE) = 6 and sqrt(2E/m)/ω = 1,
     * area 6π = 2πE/ω; T = 2π/3; amplitude 1. */
    CHECK_EQ_INT(mech_phase_area_oscillator(2, 3, 9, &p, NULL), MECH_OK);
    CHECK_CLOSE(p.area, 6 * MECH_PI, 1e-15, 0);
    CHECK_CLOSE(p.period, 2 * MECH_PI / 3, 1e-15, 0);
    CHECK_CLOSE(p.amplitude, 1.0, 1e-15, 0);
}

static void test_errors(void)
{
    struct mech_phase_area p;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_phase_area_pendulum(1, 1, 9.81, -1, &p, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "energy"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_phase_area_pendulum(1, 0, 9.81, 1, &p, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "length"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_phase_area_oscillator(1, 0, 1, &p, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "omega"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_pendulum();
    test_oscillator();
    test_errors();
    TEST_MAIN_END();
}
