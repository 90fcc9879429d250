/* test_circular_orbit.c — circular orbits of a given angular momentum
 * (core/hamiltonian/circular_orbit.c) against closed forms and a second method: Kepler
 * r = L²/(m k) with ω_r = ω_φ and E = −k/(2r); the isotropic oscillator
 * r = sqrt(L/(m ω)), ω_r = 2ω, apsidal angle π/2; V = k r^n for several n
 * (apsidal angle π/sqrt(n + 2), independent of L; Bertrand: only n = −1 and
 * n = 2 close every orbit, i.e. give ω_r/ω_φ = 1 or 2 exactly); the
 * logarithmic potential; n < −2 unstable; a Kepler term plus an attractive
 * 1/r³ term (the Schwarzschild-like effective potential) with its two
 * circular orbits r = [L²/m ± sqrt(L⁴/m² − 12 k h)]/(2k), none below the
 * merging L; a three-term potential against a golden-section minimum of
 * V_eff and a finite-difference V_eff''; extreme L; the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/hamiltonian/circular_orbit.h"
#include "testlib.h"


static void test_kepler_and_oscillator(void)
{
    struct mech_circular_orbits o;
    /* Kepler, the Earth about the Sun: m = 5.9722e24, K = GM m, L = m r v. */
    const double m = 5.9722e24, gm = 1.32712440018e20, k = gm * m;
    const double ls[] = {1e-3, 1.0, 2.66e40, 1e60};
    for (size_t i = 0; i < 4; i++) {
        struct mech_potential_term t = {-k, -1};
        CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 1, m, ls[i], &o, NULL), MECH_OK);
        const double r = (ls[i] / m) * (ls[i] / k);
        if (!(r > 1e-300) || !(r < 1e300)) continue;
        CHECK_EQ_INT(o.count, 1);
        CHECK(o.closed_form);
        CHECK_CLOSE(o.radius[0], r, 4e-16, 0);
        CHECK_CLOSE(o.orbit[0].omega_r, o.orbit[0].omega_phi, 1e-14, 0);
        CHECK_CLOSE(o.orbit[0].apsidal_angle, MECH_PI, 1e-14, 0);
        CHECK_CLOSE(o.orbit[0].energy, -k / (2 * r), 1e-14, 0);
        CHECK_CLOSE(o.residual[0], 0, 0, 1e-15);
        CHECK(o.orbit[0].stable);
    }
    /* r = 2e-110 m (L = 1e-20): r³ underflows in the frequencies: a typed error, no crash. */
    {
        struct mech_potential_term t = {-k, -1};
        struct mech_error e;
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 1, m, 1e-20, &o, &e), MECH_ENUMERIC);
        CHECK(!strcmp(e.param, "angular_momentum"));
    }
    /* One year: L = m sqrt(GM r) at r = 1 au gives r back and ω_φ = sqrt(GM/r³). */
    const double au = 1.495978707e11, lau = m * sqrt(gm * au);
    struct mech_potential_term t = {-k, -1};
    CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 1, m, lau, &o, NULL), MECH_OK);
    CHECK_CLOSE(o.radius[0], au, 1e-15, 0);
    CHECK_CLOSE(2 * MECH_PI / o.orbit[0].omega_phi / 86400, 365.25689832, 1e-9, 0);
    /* Oscillator V = m ω² r²/2: r = sqrt(L/(m ω)), ω_r = 2 ω, apsidal π/2. */
    const double mo = 2.0, w = 3.0;
    struct mech_potential_term h = {0.5 * mo * w * w, 2};
    CHECK_EQ_INT(mech_circular_orbits_for_l(&h, 1, mo, 5.0, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 1);
    CHECK_CLOSE(o.radius[0], sqrt(5.0 / (mo * w)), 4e-16, 0);
    CHECK_CLOSE(o.orbit[0].omega_phi, w, 1e-15, 0);
    CHECK_CLOSE(o.orbit[0].omega_r, 2 * w, 1e-15, 0);
    CHECK_CLOSE(o.orbit[0].apsidal_angle, MECH_PI / 2, 1e-15, 0);
    CHECK_CLOSE(o.orbit[0].energy, 5.0 * w, 1e-15, 0); /* E = L ω for the circular orbit */
}

static void test_power_laws(void)
{
    /* V = k r^n (k n > 0): r = (L²/(m k n))^(1/(n + 2)); apsidal π/sqrt(n + 2)
     * for every L (Bertrand: ω_r/ω_φ = sqrt(n + 2) is 1 or 2 only for n = −1, 2). */
    const double ns[] = {-1.9, -1.5, -1, -0.5, 0.5, 1, 2, 3, 7, 20};
    for (size_t i = 0; i < 10; i++) {
        const double n = ns[i], k = n > 0 ? 0.7 : -0.7, m = 1.3;
        for (double l = 0.01; l < 1e3; l *= 31) {
            struct mech_potential_term t = {k, n};
            struct mech_circular_orbits o;
            CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 1, m, l, &o, NULL), MECH_OK);
            CHECK_EQ_INT(o.count, 1);
            CHECK_CLOSE(o.radius[0], pow(l * l / (m * k * n), 1 / (n + 2)), 2e-15, 0);
            CHECK_CLOSE(o.orbit[0].apsidal_angle, MECH_PI / sqrt(n + 2), 1e-14, 0);
            CHECK_CLOSE(o.orbit[0].omega_r / o.orbit[0].omega_phi, sqrt(n + 2), 1e-14, 0);
        }
    }
    /* Logarithmic V = k ln r: r = L/sqrt(m k), apsidal π/sqrt(2). */
    struct mech_potential_term lg = {2.0, 0};
    struct mech_circular_orbits o;
    CHECK_EQ_INT(mech_circular_orbits_for_l(&lg, 1, 0.5, 3.0, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 1);
    CHECK_CLOSE(o.radius[0], 3.0 / sqrt(0.5 * 2.0), 4e-16, 0);
    CHECK_CLOSE(o.orbit[0].apsidal_angle, MECH_PI / sqrt(2.0), 1e-15, 0);
    /* n = −3, k < 0 (V = −|k|/r³): a circular orbit exists but is unstable. */
    struct mech_potential_term u = {-1.0, -3};
    CHECK_EQ_INT(mech_circular_orbits_for_l(&u, 1, 1.0, 2.0, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 1);
    CHECK_CLOSE(o.radius[0], 3.0 / 4.0, 4e-16, 0); /* 3|k|/r = L²/m */
    CHECK(!o.orbit[0].stable);
    CHECK(o.orbit[0].growth_rate > 0);
    /* Repulsive V = +1/r: no circular orbit at any L. */
    struct mech_potential_term rep = {1.0, -1};
    CHECK_EQ_INT(mech_circular_orbits_for_l(&rep, 1, 1.0, 2.0, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 0);
    /* Kepler plus a 1/r² term (n = −2 joins the constant): k r = L²/m + 2h. */
    struct mech_potential_term kp[2] = {{-3.0, -1}, {-0.5, -2}};
    CHECK_EQ_INT(mech_circular_orbits_for_l(kp, 2, 1.0, 2.0, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 1);
    CHECK_CLOSE(o.radius[0], (4.0 - 1.0) / 3.0, 4e-16, 0);
}

static void test_two_orbits(void)
{
    /* V = −k/r − h/r³: k r² − (L²/m) r + 3h = 0. */
    const double k = 1.0, h = 0.05, m = 1.0;
    struct mech_potential_term t[2] = {{-k, -1}, {-h, -3}};
    struct mech_circular_orbits o;
    const double l = 1.2, a = l * l / m, d = sqrt(a * a - 12 * k * h);
    CHECK_EQ_INT(mech_circular_orbits_for_l(t, 2, m, l, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 2);
    CHECK(!o.closed_form);
    CHECK_CLOSE(o.radius[0], 6 * h / (a + d), 1e-15, 0); /* (a − d)/(2k) without cancellation */
    CHECK_CLOSE(o.radius[1], (a + d) / (2 * k), 1e-15, 0);
    CHECK(!o.orbit[0].stable);
    CHECK(o.orbit[1].stable);
    /* Below the merging L (L⁴/m² = 12 k h): none. */
    CHECK_EQ_INT(mech_circular_orbits_for_l(t, 2, m, 0.98 * pow(12 * k * h, 0.25), &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 0);
}

/* V_eff(r) = L²/(2 m r²) + Σ k r^n */
static double veff(const struct mech_potential_term *t, size_t n, double m, double l, double r)
{
    double v = l * l / (2 * m * r * r);
    for (size_t i = 0; i < n; i++) v += t[i].n == 0 ? t[i].k * log(r) : t[i].k * pow(r, t[i].n);
    return v;
}

static void test_second_method(void)
{
    /* Kepler + oscillator + quartic: golden-section minimum of V_eff. */
    struct mech_potential_term t[3] = {{-2.0, -1}, {0.3, 2}, {0.01, 4}};
    const double m = 0.7, l = 1.1;
    struct mech_circular_orbits o;
    CHECK_EQ_INT(mech_circular_orbits_for_l(t, 3, m, l, &o, NULL), MECH_OK);
    CHECK_EQ_INT(o.count, 1);
    double a = 1e-3, b = 1e3;
    const double gr = (sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 200; it++) {
        const double c = b - gr * (b - a), d = a + gr * (b - a);
        if (veff(t, 3, m, l, c) < veff(t, 3, m, l, d)) b = d;
        else a = c;
    }
    const double rmin = 0.5 * (a + b);
    CHECK_CLOSE(o.radius[0], rmin, 1e-7, 0); /* golden section: ~sqrt(eps) */
    CHECK_CLOSE(o.residual[0], 0, 0, 1e-14);
    /* m ω_r² = V_eff''(r0), central difference. */
    const double r0 = o.radius[0], hh = 1e-4 * r0;
    const double d2 = (veff(t, 3, m, l, r0 + hh) - 2 * veff(t, 3, m, l, r0) + veff(t, 3, m, l, r0 - hh)) / (hh * hh);
    CHECK_CLOSE(m * o.orbit[0].omega_r * o.orbit[0].omega_r, d2, 1e-6, 0);
    CHECK_CLOSE(o.orbit[0].energy, veff(t, 3, m, l, r0), 1e-14, 0);
    /* Coefficients 1e-200 apart in scale: still found (logs, no overflow). */
    struct mech_potential_term w[3] = {{-1e-150, -1}, {1e150, 2}, {1e-100, 3}};
    CHECK_EQ_INT(mech_circular_orbits_for_l(w, 3, 1.0, 1.0, &o, NULL), MECH_OK);
    CHECK(o.count >= 1);
    for (size_t i = 0; i < o.count; i++) CHECK_CLOSE(o.residual[i], 0, 0, 1e-12);
}

static void test_errors(void)
{
    struct mech_potential_term t = {-1, -1}, bad = {NAN, -1};
    struct mech_circular_orbits o;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 1, 0, 1, &o, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "mass"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 1, 1, 0, &o, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "angular_momentum"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_circular_orbits_for_l(&bad, 1, 1, 1, &o, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "terms/0/k"));
    CHECK_EQ_INT(mech_circular_orbits_for_l(&t, 0, 1, 1, &o, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_kepler_and_oscillator();
    test_power_laws();
    test_two_orbits();
    test_second_method();
    test_errors();
    TEST_MAIN_END();
}
