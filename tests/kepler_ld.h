/* kepler_ld.h — the test suite's independent Kepler reference: the orbit
 * (GM = 1) through the pericentre state (q, 0, 0), (0, u, 0), its elements
 * formed from those doubles in long double (a = 1 / (2/q - u^2), e = 1 - q/a,
 * not the nominal a and e: the rounding of q and u moves the mean motion by
 * ~1e-15 relative at e = 0.9, ~5e-10 over 1000 orbits), Kepler's equation
 * solved by Newton in long double. Shared by tests/core/frames/test_reference.c and
 * tests/api/scene_set.h (and through it bench/bench_workprecision.c).
 * Header-only. */
#ifndef MECHD_TESTS_KEPLER_LD_H
#define MECHD_TESTS_KEPLER_LD_H

#include "mech/base/constants.h"
#include <math.h>

/* The planar state at time t (s, GM = 1): r[0..1], v[0..1]. */
static inline void kepler_ld_pericentre(double q, double u, double t, double r[2], double v[2])
{
    const long double two_pi = MECH_TWO_PI_L;
    long double a = 1.0L / (2.0L / q - (long double)u * u), e = 1.0L - q / a;
    long double n = 1.0L / (a * sqrtl(a));
    long double M = fmodl(n * (long double)t, two_pi), E = M + e * sinl(M);
    for (int i = 0; i < 60; i++) {
        long double d = (E - e * sinl(E) - M) / (1 - e * cosl(E));
        E -= d;
        if (fabsl(d) < 1e-19L) break;
    }
    long double b = sqrtl(1 - e * e), den = 1 - e * cosl(E);
    r[0] = (double)(a * (cosl(E) - e));
    r[1] = (double)(a * b * sinl(E));
    v[0] = (double)(-a * n * sinl(E) / den);
    v[1] = (double)(a * n * b * cosl(E) / den);
}

#endif
