/* test_schwarzschild_answer.c — mech/answers/gr/schwarzschild_answer.h against closed
 * forms: the radii r_s = 2, photon sphere 3, ISCO 6, b_c = 3 sqrt(3) GM/c^2;
 * circular orbits E = (1 - 2M/r)/sqrt(1 - 3M/r), L = sqrt(M r)/sqrt(1 - 3M/r),
 * Omega^2 = GM/r^3 in coordinate time (Kepler's third law, exact in t), the
 * marginally bound orbit at 4GM/c^2 (E = 1), the ISCO's E = sqrt(8/9); the
 * static clock sqrt(1 - 2M/r); the radial infall's (pi/2) sqrt(r0^3/(2GM));
 * the potential's extrema r = (L^2/2)(1 +- sqrt(1 - 12/L^2)) and W(3M) =
 * 1/(27 M^2), V - 1 beside V computed in long double; the clock comparison's
 * net = 0 at r = 1.5 R; every error with its field, and a non-finite answer
 * refused. SI through the Sun's GM. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/gr/schwarzschild_answer.h"
#include "testlib.h"

static struct mech_schw_request geometric(void)
{
    struct mech_schw_request q;
    memset(&q, 0, sizeof q);
    mech_gr_units_init(1, MECH_GR_MASS_NONE, NAN, &q.units, NULL);
    return q;
}

static void test_radii(void)
{
    struct mech_schw_request q = geometric();
    struct mech_schw_answer a;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.schwarzschild_radius, 2.0, 0, 0);
    CHECK_CLOSE(a.photon_sphere, 3.0, 0, 0);
    CHECK_CLOSE(a.isco, 6.0, 0, 0);
    CHECK_CLOSE(a.critical_impact_parameter, 3.0 * sqrt(3.0), 1e-15, 0);
    CHECK_CLOSE(a.isco_binding_efficiency, 1.0 - sqrt(8.0 / 9.0), 1e-14, 0);
    CHECK(!a.has_at_r && !a.has_clock && !a.has_infall && !a.has_potential);
    mech_schw_answer_free(&a);
    /* the Sun: r_s = 2953.25 m */
    mech_gr_units_init(0, MECH_GR_MASS_SUN, NAN, &q.units, NULL);
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.schwarzschild_radius, 2.0 * MECH_SUN_GM / (MECH_C * MECH_C), 1e-15, 0);
    CHECK_CLOSE(a.isco, 6.0 * MECH_SUN_GM / (MECH_C * MECH_C), 1e-15, 0);
    mech_schw_answer_free(&a);
}

/* circular orbits at r (geometric) against the closed forms */
static void check_circular(double r, enum mech_schw_stability want)
{
    struct mech_schw_request q = geometric();
    q.has_r = 1;
    q.r = r;
    struct mech_schw_answer a;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    const struct mech_schw_circular *co = &a.at_r.circ;
    CHECK_EQ_INT(co->stability, want);
    CHECK_CLOSE(a.at_r.r, r, 0, 0);
    CHECK_CLOSE(a.at_r.r_over_rs, r / 2.0, 1e-15, 0);
    CHECK_CLOSE(a.at_r.weak_field_potential, 1.0 / r, 1e-15, 0);
    CHECK_CLOSE(a.at_r.stat.rate, sqrt(1.0 - 2.0 / r), 1e-15, 0);
    /* z = 1/sqrt(1 - x) - 1 = x / (sqrt(1 - x)(1 + sqrt(1 - x))), x = 2/r, no cancellation */
    const double x = 2.0 / r, a1 = sqrt(1.0 - x);
    CHECK_CLOSE(a.at_r.stat.redshift, x / (a1 * (1.0 + a1)), 1e-15, 0);
    const double s = sqrt(1.0 - 3.0 / r);
    CHECK_CLOSE(co->energy, (1.0 - 2.0 / r) / s, 1e-15, 0);
    CHECK_CLOSE(co->angular_momentum, sqrt(r) / s, 1e-15, 0);
    CHECK_CLOSE(co->omega * co->omega, 1.0 / (r * r * r), 1e-15, 0);
    CHECK_CLOSE(co->period_t, 2.0 * MECH_PI * pow(r, 1.5), 1e-15, 0);
    CHECK_CLOSE(co->period_tau, 2.0 * MECH_PI * pow(r, 1.5) * s, 1e-15, 0);
    CHECK_CLOSE(co->local_speed, 1.0 / sqrt(r - 2.0), 1e-15, 0);
    mech_schw_answer_free(&a);
}

static void test_circular(void)
{
    check_circular(6.0, MECH_SCHW_ORBIT_MARGINAL);
    check_circular(4.5, MECH_SCHW_ORBIT_UNSTABLE);
    check_circular(1e6, MECH_SCHW_ORBIT_STABLE);
    struct mech_schw_request q = geometric();
    struct mech_schw_answer a;
    q.has_r = 1;
    /* the ISCO: E = sqrt(8/9), L = sqrt(12) */
    q.r = 6.0;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.at_r.circ.energy, sqrt(8.0 / 9.0), 1e-15, 0);
    CHECK_CLOSE(a.at_r.circ.angular_momentum, sqrt(12.0), 1e-15, 0);
    CHECK_CLOSE(a.at_r.circ.binding_efficiency, a.isco_binding_efficiency, 1e-14, 0);
    mech_schw_answer_free(&a);
    /* marginally bound at 4GM/c^2: E = 1 exactly, binding efficiency 0 */
    q.r = 4.0;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.at_r.circ.energy, 1.0, 1e-15, 0);
    CHECK_CLOSE(a.at_r.circ.binding_efficiency, 0.0, 0, 1e-16);
    mech_schw_answer_free(&a);
    /* far out: 1 - E -> 1/(2r) (Newtonian binding), kept to full precision */
    q.r = 1e12;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.at_r.circ.binding_efficiency, 0.5e-12, 1e-11, 0);
    mech_schw_answer_free(&a);
    /* at and inside the photon sphere: no orbit, the clock still there */
    q.r = 3.0;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_EQ_INT(a.at_r.circ.stability, MECH_SCHW_ORBIT_NONE);
    CHECK_CLOSE(a.at_r.stat.rate, sqrt(1.0 / 3.0), 1e-15, 0);
    mech_schw_answer_free(&a);
    q.r = 2.0000001;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_EQ_INT(a.at_r.circ.stability, MECH_SCHW_ORBIT_NONE);
    mech_schw_answer_free(&a);
}

/* SI: 1 AU around the Sun; Omega^2 = GM/r^3 in coordinate time */
static void test_si_orbit(void)
{
    struct mech_schw_request q;
    memset(&q, 0, sizeof q);
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_SUN, NAN, &q.units, NULL), MECH_OK);
    q.has_r = 1;
    q.r = MECH_AU;
    struct mech_schw_answer a;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    const double GM = MECH_SUN_GM, r = MECH_AU, c2 = MECH_C * MECH_C;
    const double s = sqrt(1.0 - 3.0 * GM / (c2 * r));
    const struct mech_schw_circular *co = &a.at_r.circ;
    CHECK_CLOSE(co->omega * co->omega, GM / (r * r * r), 1e-14, 0);
    CHECK_CLOSE(co->period_t, 2.0 * MECH_PI * sqrt(r * r * r / GM), 1e-14, 0);
    CHECK_CLOSE(co->period_tau, 2.0 * MECH_PI * sqrt(r * r * r / GM) * s, 1e-14, 0);
    CHECK_CLOSE(co->angular_momentum, sqrt(GM * r) / s, 1e-14, 0);
    CHECK_CLOSE(a.at_r.weak_field_potential, GM / (r * c2), 1e-14, 0);
    /* the static clock's deficit GM/(r c^2) + ..., not lost to cancellation */
    const double x = 2.0 * GM / (c2 * r);
    CHECK_CLOSE(a.at_r.stat.rate_deficit, x / (1.0 + sqrt(1.0 - x)), 1e-14, 0);
    mech_schw_answer_free(&a);
}

static void test_clock(void)
{
    struct mech_schw_request q = geometric();
    q.has_r = q.has_reference_r = 1;
    q.reference_r = 1e4;
    q.r = 1.5e4; /* net = 0 exactly at r = 1.5 R */
    struct mech_schw_answer a;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK(a.has_clock);
    CHECK_CLOSE(a.clock.net, 0.0, 0, 1e-20);
    /* gravitational: ratio of static rates minus one, computed in long double */
    const long double g = sqrtl(1.0L - 2.0L / 1.5e4L) / sqrtl(1.0L - 2.0L / 1e4L) - 1.0L;
    CHECK_CLOSE(a.clock.gravitational, (double)g, 1e-12, 0);
    /* first order: m (1/R - 1/r) and -m/(2r) */
    CHECK_CLOSE(a.clock.first_order_gravitational, 1.0 / 1e4 - 1.0 / 1.5e4, 1e-14, 0);
    CHECK_CLOSE(a.clock.first_order_velocity, -0.5 / 1.5e4, 1e-14, 0);
    mech_schw_answer_free(&a);
}

static void test_infall(void)
{
    struct mech_schw_request q;
    memset(&q, 0, sizeof q);
    mech_gr_units_init(0, MECH_GR_MASS_SUN, NAN, &q.units, NULL);
    q.has_infall_from = 1;
    q.infall_from = 7e8; /* the Sun's radius, m */
    struct mech_schw_answer a;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    const double r0 = q.infall_from, GM = MECH_SUN_GM;
    /* the Newtonian free-fall time (pi/2) sqrt(r0^3/(2GM)), exactly */
    CHECK_CLOSE(a.infall.to_singularity, 0.5 * MECH_PI * sqrt(r0 * r0 * r0 / (2.0 * GM)), 1e-13, 0);
    /* horizon to r = 0 from far away: (4/3) GM/c^3 */
    CHECK_CLOSE(a.infall.horizon_to_singularity, 4.0 / 3.0 * GM / (MECH_C * MECH_C * MECH_C), 1e-5,
                0);
    CHECK_CLOSE(a.infall.to_horizon + a.infall.horizon_to_singularity, a.infall.to_singularity,
                1e-14, 0);
    mech_schw_answer_free(&a);
}

static void test_potential(void)
{
    struct mech_schw_request q = geometric();
    q.has_potential = 1;
    q.potential_L = 4.0; /* extrema at 8 (1 +- 1/2): 4 and 12 */
    q.samples = 200;
    struct mech_schw_answer a;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    const struct mech_schw_potential *v = &a.potential;
    CHECK_EQ_INT(v->n_extrema, 2);
    CHECK_CLOSE(v->unstable_r, 4.0, 1e-15, 0);
    CHECK_CLOSE(v->stable_r, 12.0, 1e-15, 0);
    CHECK_CLOSE(v->unstable_V, 1.0, 1e-15, 0);       /* (1/2)(1 + 1) */
    CHECK_CLOSE(v->stable_V, 25.0 / 27.0, 1e-15, 0); /* (5/6)(1 + 1/9) */
    CHECK_CLOSE(v->photon_max_r, 3.0, 0, 0);
    CHECK_CLOSE(v->photon_max_W, 1.0 / 27.0, 1e-15, 0);
    /* default range: r_s to max(30, 3 r_stable) = 36 */
    CHECK_EQ_INT((int)v->n, 200);
    CHECK_CLOSE(v->r[0], 2.0, 0, 0);
    CHECK_CLOSE(v->r[199], 36.0, 0, 0);
    for (size_t i = 0; i < v->n; i++) {
        const long double r = v->r[i], L = 4.0L;
        const long double V = (1.0L - 2.0L / r) * (1.0L + L * L / (r * r));
        CHECK_CLOSE(v->massive[i], (double)V, 1e-14, 0);
        CHECK_CLOSE(v->massive_minus_one[i], (double)(V - 1.0L), 1e-12, 1e-15);
        CHECK_CLOSE(v->photon[i], (double)((1.0L - 2.0L / r) / (r * r)), 1e-14, 0);
    }
    mech_schw_answer_free(&a);
    /* L^2 just above 12 (12 itself is not a double's square): the two extrema
     * r = 6 (1 +- sqrt(1 - 12/L^2)) merge at the ISCO; given ends kept exactly */
    q.potential_L = sqrt(12.0) * (1.0 + 1e-10);
    q.has_r_min = q.has_r_max = 1;
    q.r_min = 2.5;
    q.r_max = 1e8;
    q.samples = 2;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    CHECK_EQ_INT(a.potential.n_extrema, 2);
    CHECK_CLOSE(a.potential.stable_r, 6.0 * (1.0 + sqrt(2e-10)), 1e-9, 0);
    CHECK_CLOSE(a.potential.unstable_r, 6.0 * (1.0 - sqrt(2e-10)), 1e-9, 0);
    CHECK_CLOSE(a.potential.r[0], 2.5, 0, 0);
    CHECK_CLOSE(a.potential.r[1], 1e8, 0, 0);
    /* far out V - 1 = -2/r + L^2/r^2 - 2L^2/r^3 keeps its digits where V - 1 cannot */
    CHECK_CLOSE(a.potential.massive_minus_one[1], -2e-8 + 12e-16 - 24e-24, 1e-15, 0);
    mech_schw_answer_free(&a);
    /* L = 0: no extrema, V = 1 - 2/r; SI photon W(3M) = 1/(27 (GM/c^2)^2) */
    q = (struct mech_schw_request){0};
    mech_gr_units_init(0, MECH_GR_MASS_SUN, NAN, &q.units, NULL);
    q.has_potential = 1;
    q.potential_L = 0.0;
    q.samples = 3;
    CHECK_EQ_INT(mech_schw_answer(&q, &a, NULL), MECH_OK);
    const double m = MECH_SUN_GM / (MECH_C * MECH_C);
    CHECK_EQ_INT(a.potential.n_extrema, 0);
    CHECK(isnan(a.potential.stable_r));
    CHECK_CLOSE(a.potential.r[2], 30.0 * m, 1e-15, 0);
    CHECK_CLOSE(a.potential.photon_max_W, 1.0 / (27.0 * m * m), 1e-14, 0);
    CHECK_CLOSE(a.potential.massive[1], 1.0 - 2.0 * m / a.potential.r[1], 1e-14, 0);
    mech_schw_answer_free(&a);
}

static void expect_error(const struct mech_schw_request *q, enum mech_status st, const char *param)
{
    struct mech_schw_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_schw_answer(q, &a, &e), st);
    CHECK(!strcmp(e.param, param));
    CHECK(e.text[0] != 0);
    CHECK(a.potential.r == NULL);
    mech_schw_answer_free(&a);
}

static void test_errors(void)
{
    struct mech_schw_request q = geometric();
    q.has_reference_r = 1;
    q.reference_r = 10.0;
    expect_error(&q, MECH_EINVAL, "r"); /* reference_r without r */
    const double bad_r[4] = {2.0, 1.0, NAN, -INFINITY};
    for (int i = 0; i < 4; i++) {
        q = geometric();
        q.has_r = 1;
        q.r = bad_r[i];
        expect_error(&q, MECH_EDOMAIN, "r");
    }
    q = geometric();
    q.has_r = 1;
    q.r = 2.5; /* no circular orbit to compare with */
    q.has_reference_r = 1;
    q.reference_r = 10.0;
    expect_error(&q, MECH_EDOMAIN, "r");
    q.r = 10.0;
    q.reference_r = 2.0; /* a static reference at the horizon */
    expect_error(&q, MECH_EDOMAIN, "reference_r");
    q = geometric();
    q.has_infall_from = 1;
    q.infall_from = 1.99; /* inside the horizon (the horizon itself is answered as a limit) */
    expect_error(&q, MECH_EDOMAIN, "infall_from");
    q = geometric();
    q.has_potential = 1;
    q.potential_L = 4.0;
    q.samples = 10;
    q.has_r_min = 1;
    q.r_min = 1.99;
    expect_error(&q, MECH_EDOMAIN, "effective_potential/r_min");
    q.r_min = 40.0; /* above the default r_max 36 */
    expect_error(&q, MECH_EINVAL, "effective_potential/r_max");
    q.has_r_max = 1;
    q.r_min = 3.0;
    q.r_max = NAN;
    expect_error(&q, MECH_EINVAL, "effective_potential/r_max");
    q.r_max = INFINITY;
    expect_error(&q, MECH_EINVAL, "effective_potential/r_max");
    q.r_max = 10.0;
    q.samples = 1;
    expect_error(&q, MECH_EINVAL, "effective_potential/samples");
    q.samples = MECH_SCHW_POTENTIAL_MAX_SAMPLES + 1;
    expect_error(&q, MECH_EINVAL, "effective_potential/samples");
    q.samples = (size_t)-1;
    expect_error(&q, MECH_EINVAL, "effective_potential/samples");
    /* a mass so small the period in geometric units overflows: refused, not inf */
    q = (struct mech_schw_request){0};
    CHECK_EQ_INT(mech_gr_units_init(0, MECH_GR_MASS_KG, 1e-250, &q.units, NULL), MECH_OK);
    q.has_r = 1;
    q.r = 1e20;
    expect_error(&q, MECH_ENUMERIC, "");
    q.has_r = 0;
    q.has_potential = 1;
    q.potential_L = 1.0; /* r_stable ~ L^2 overflows: the default r_max is not finite */
    q.samples = 3;
    expect_error(&q, MECH_EINVAL, "effective_potential/r_max");
    q.potential_L = 0.0; /* W in 1/m^2 = W(r) / (GM/c^2)^2 overflows */
    q.has_r_min = q.has_r_max = 1;
    q.r_min = 1e-270;
    q.r_max = 1e-269;
    expect_error(&q, MECH_ENUMERIC, "");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_radii();
    test_circular();
    test_si_orbit();
    test_clock();
    test_infall();
    test_potential();
    test_errors();
    TEST_MAIN_END();
}
