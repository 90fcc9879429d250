/* test_worldline_answer.c — one /v1/relativity/worldline answer
 * (core/answers/relativity/worldline_answer.c) against closed forms:
 *   - constant proper acceleration from rest (hyperbolic motion, notes §3.12,
 *     §3.15): t = (c/a) sinh(aτ/c), equivalently τ = (c/a) asinh(a t/c),
 *     x = (c²/a)(cosh(aτ/c) − 1), βγ = sinh(aτ/c), in long double; the same
 *     leg in g and in ly/yr² (g = 9.80665 m/s² × 31557600 s / c); one second
 *     at 1 g, where t − τ = τ x²/6 (1 + x²/20), x = aτ/c ≈ 3.3e-8;
 *   - the notes' twin paradox (8 ly at 0.8c out and back): 12 and 20 years,
 *     ticks 2 and 18 seen by the traveller at rates 1/3 and 3 =
 *     sqrt((1 ∓ β)/(1 ± β)), 6 + 6 seen at home, and the home telescope at
 *     t = 9, 19, 20 (emission at t_e + |x_e| = t, worked by hand below);
 *   - an accelerated round trip (+g τ0, −g 2τ0, −g τ0 braking) that returns
 *     home: τ = 4τ0, t = 4 (c/a) sinh(aτ0/c), path 4 (c²/a)(cosh(aτ0/c) − 1);
 *   - every request check, the telescope's field index, and a tick so small
 *     that the ticks overflow (MECH_ENUMERIC, no arrays left). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/relativity/worldline_answer.h"
#include "testlib.h"

static struct mech_budget bud;

static struct mech_worldline_leg_request accel(double a, int in_g, double tau, double dx)
{
    struct mech_worldline_leg_request l;
    memset(&l, 0, sizeof l);
    l.leg.kind = MECH_LEG_ACCELERATE;
    l.leg.acceleration = a;
    l.leg.amount = tau;
    l.leg.direction = mech_vec3_make(dx, 0, 0);
    l.acceleration_in_g = in_g;
    return l;
}

static struct mech_worldline_leg_request coast_distance(double beta_x, double d)
{
    struct mech_worldline_leg_request l;
    memset(&l, 0, sizeof l);
    l.leg.kind = MECH_LEG_COAST_DISTANCE;
    mech_boost_from_beta(mech_vec3_make(beta_x, 0, 0), &l.leg.velocity, NULL);
    l.leg.amount = d;
    return l;
}

static struct mech_worldline_request request(const struct mech_worldline_leg_request *legs,
                                             size_t n, enum mech_worldline_units u)
{
    struct mech_worldline_request q = {.units = u, .tick_interval = 1, .legs = legs, .n = n};
    return q;
}

static void test_hyperbolic(void)
{
    /* One Julian year at 1 g from rest, SI. */
    const long double c = 299792458.0L, a = 9.80665L, tau = 31557600.0L, x = a * tau / c;
    struct mech_worldline_leg_request leg = accel(1, 1, (double)tau, 1);
    struct mech_worldline_request q = request(&leg, 1, MECH_WORLDLINE_SECONDS);
    struct mech_worldline_answer A;
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, &A, NULL), MECH_OK);
    CHECK_CLOSE(A.c, 299792458.0, 0, 0);
    CHECK_CLOSE(A.g, 9.80665, 0, 0);
    CHECK_EQ_INT(A.n, 1);
    CHECK_EQ_INT(A.legs[0].accelerated, 1);
    const double t = A.legs[0].r.coordinate_time;
    CHECK_CLOSE(t, (double)(c / a * sinhl(x)), 4e-16, 0);
    /* The same statement solved for τ: τ = (c/a) asinh(a t/c). */
    CHECK_CLOSE((double)(c / a * asinhl(a * (long double)t / c)), (double)tau, 4e-16, 0);
    CHECK_CLOSE(A.legs[0].r.displacement.x, (double)(c * c / a * (coshl(x) - 1)), 1e-15, 0);
    CHECK_CLOSE(A.legs[0].r.distance, (double)(c * c / a * (coshl(x) - 1)), 1e-15, 0);
    CHECK_CLOSE(A.legs[0].r.age_difference, (double)(c / a * sinhl(x) - tau), 2e-15, 0);
    CHECK_CLOSE(A.total.final_velocity.beta_gamma, (double)sinhl(x), 4e-16, 0);
    CHECK_CLOSE(A.legs[0].proper_time_ct, (double)(c * tau), 2e-16, 0);
    CHECK_CLOSE(A.total_proper_time_ct, (double)(c * tau), 2e-16, 0);
    CHECK_EQ_INT(A.returned, 0);
    /* Home sees the traveller's clock run at the receding rate: over the leg,
     * traveller time τ per home time t + x/c (the end's light arrives then). */
    CHECK_CLOSE(A.legs[0].home_sees_traveller.rate,
                (double)(tau / (c / a * sinhl(x) + (coshl(x) - 1) * c / a)), 1e-15, 0);
    CHECK_CLOSE(A.total_traveller_ticks, (double)tau, 0, 0);
    mech_worldline_answer_free(&A);

    /* Years: g in ly/yr² from its definition, and the leg in g or in ly/yr² alike. */
    const long double g_ly = 9.80665L * 31557600.0L / 299792458.0L;
    struct mech_worldline_leg_request lg = accel(1, 1, 1, 1), ll = accel((double)g_ly, 0, 1, 1);
    struct mech_worldline_answer B, C;
    q = request(&lg, 1, MECH_WORLDLINE_YEARS);
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, &B, NULL), MECH_OK);
    q = request(&ll, 1, MECH_WORLDLINE_YEARS);
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, &C, NULL), MECH_OK);
    CHECK_CLOSE(B.g, (double)g_ly, 4e-16, 0); /* two roundings */
    CHECK_CLOSE(B.c, 1, 0, 0);
    CHECK_CLOSE(B.total.coordinate_time, (double)(sinhl(g_ly) / g_ly), 4e-16, 0);
    CHECK_CLOSE(B.total.coordinate_time, C.total.coordinate_time, 4e-16, 0);
    CHECK_CLOSE(B.legs[0].r.displacement.x, (double)((coshl(g_ly) - 1) / g_ly), 4e-16, 0);
    mech_worldline_answer_free(&B);
    mech_worldline_answer_free(&C);

    /* One second at 1 g: t − τ = τ (x²/6 + x⁴/120 + ...), x = aτ/c ≈ 3.3e-8, kept
     * to round-off (the direct difference of t and τ would keep no digit). */
    struct mech_worldline_leg_request l1 = accel(1, 1, 1, 1);
    q = request(&l1, 1, MECH_WORLDLINE_SECONDS);
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, &A, NULL), MECH_OK);
    const double x1 = 9.80665 / 299792458.0;
    CHECK_CLOSE(A.total.age_difference, x1 * x1 / 6 * (1 + x1 * x1 / 20), 1e-14, 0);
    /* t = 1 + 1.8e-16 rounds to the double after 1. */
    CHECK_CLOSE(A.total.coordinate_time, 1 + x1 * x1 / 6, 0, 0);
    mech_worldline_answer_free(&A);
}

static void test_twin_paradox(void)
{
    struct mech_worldline_leg_request legs[2] = {coast_distance(0.8, 8), coast_distance(-0.8, 8)};
    const double times[3] = {9, 19, 20};
    struct mech_worldline_request q = request(legs, 2, MECH_WORLDLINE_YEARS);
    q.telescope_home_times = times;
    q.n_views = 3;
    struct mech_worldline_answer A;
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, &A, NULL), MECH_OK);
    CHECK_CLOSE(A.total.proper_time, 12, 4e-16, 0);
    CHECK_CLOSE(A.total.coordinate_time, 20, 2e-16, 0);
    CHECK_CLOSE(A.total.age_difference, 8, 1e-15, 0);
    CHECK_EQ_INT(A.returned, 1);
    CHECK_EQ_INT(A.legs[0].accelerated, 0);
    /* sqrt((1 − β)/(1 + β)) = 1/3 out, 3 back. */
    CHECK_CLOSE(A.legs[0].traveller_sees_home.ticks, 2, 2e-15, 0);
    CHECK_CLOSE(A.legs[0].traveller_sees_home.rate, 1.0 / 3, 2e-15, 0);
    CHECK_CLOSE(A.legs[1].traveller_sees_home.ticks, 18, 2e-15, 0);
    CHECK_CLOSE(A.legs[1].traveller_sees_home.rate, 3, 2e-15, 0);
    CHECK_CLOSE(A.legs[0].home_sees_traveller.ticks, 6, 4e-16, 0);
    CHECK_CLOSE(A.legs[0].home_sees_traveller.rate, 1.0 / 3, 2e-15, 0);
    CHECK_CLOSE(A.legs[0].home_sees_traveller.to, 18, 2e-15, 0);
    CHECK_CLOSE(A.legs[1].home_sees_traveller.rate, 3, 4e-15, 0);
    CHECK_CLOSE(A.total_home_ticks_seen, 20, 2e-15, 0);
    CHECK_CLOSE(A.total_traveller_ticks, 12, 4e-16, 0);
    /* Telescope. t = 9: t_e + 0.8 t_e = 9, t_e = 5, τ = 0.6·5 = 3, light 4 yr.
     * t = 19: x_e = 8 − 0.8 (t_e − 10), t_e + x_e = 19, t_e = 15, τ = 6 + 3 = 9.
     * t = 20: the return home, τ = 12, no light time. */
    CHECK_EQ_INT(A.n_views, 3);
    CHECK_CLOSE(A.views[0].traveller_clock, 3, 1e-14, 0);
    CHECK_CLOSE(A.views[0].light_time, 4, 1e-14, 0);
    CHECK_EQ_INT(A.views[0].leg, 0);
    CHECK_CLOSE(A.views[1].traveller_clock, 9, 1e-14, 0);
    CHECK_CLOSE(A.views[1].emission[0], 15, 1e-14, 0);
    CHECK_EQ_INT(A.views[1].leg, 1);
    CHECK_CLOSE(A.views[2].traveller_clock, 12, 1e-14, 0);
    CHECK_CLOSE(A.views[2].light_time, 0, 0, 1e-13);
    mech_worldline_answer_free(&A);
}

static void test_accelerated_round_trip(void)
{
    const double tau0 = 2; /* years, at 1 g each */
    struct mech_worldline_leg_request legs[3] = {accel(1, 1, tau0, 1), accel(-1, 1, 2 * tau0, 0),
                                                 accel(-1, 1, tau0, 0)};
    struct mech_worldline_request q = request(legs, 3, MECH_WORLDLINE_YEARS);
    struct mech_worldline_answer A;
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, &A, NULL), MECH_OK);
    const long double g = 9.80665L * 31557600.0L / 299792458.0L, x = g * tau0;
    CHECK_CLOSE(A.total.proper_time, 4 * tau0, 2e-16, 0);
    CHECK_CLOSE(A.total.coordinate_time, (double)(4 * sinhl(x) / g), 1e-15, 0);
    CHECK_CLOSE(A.total.distance, (double)(4 * (coshl(x) - 1) / g), 1e-15, 0);
    CHECK_EQ_INT(A.returned, 1);
    CHECK_CLOSE(A.total.final_velocity.beta_gamma, 0, 0, 1e-14);
    /* Back home, each twin has seen all of the other's ticks. */
    CHECK_CLOSE(A.total.home_clock_seen_end, A.total.coordinate_time, 1e-14, 0);
    CHECK_CLOSE(A.total.home_receives_end, A.total.coordinate_time, 1e-14, 0);
    mech_worldline_answer_free(&A);
}

static void test_errors(void)
{
    struct mech_worldline_leg_request legs[2] = {coast_distance(0.5, 1), coast_distance(0, 1)};
    struct mech_worldline_request q = request(legs, 1, MECH_WORLDLINE_SECONDS);
    struct mech_worldline_answer A;
    struct mech_error e;
#define EXPECT(call, status, field)                                                                \
    do {                                                                                           \
        mech_error_clear(&e);                                                                      \
        CHECK_EQ_INT(call, status);                                                                \
        CHECK(strcmp(e.param, field) == 0);                                                        \
        if (strcmp(e.param, field)) fprintf(stderr, "  param %s: %s\n", e.param, e.text);        \
        CHECK(A.legs == NULL && A.views == NULL && A.n == 0);                                      \
    } while (0)
    EXPECT(mech_worldline_answer(NULL, &bud, &A, &e), MECH_EINVAL, "");
    EXPECT(mech_worldline_answer(&q, NULL, &A, &e), MECH_EINVAL, "");
    CHECK_EQ_INT(mech_worldline_answer(&q, &bud, NULL, NULL), MECH_EINVAL);
    q.n = 0;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EINVAL, "legs");
    q.n = MECH_WORLDLINE_MAX_LEGS + 1;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EINVAL, "legs");
    q.n = 1;
    q.n_views = MECH_WORLDLINE_MAX_VIEWS + 1;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EINVAL, "telescope_home_times");
    q.n_views = 0;
    q.units = (enum mech_worldline_units)7;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EINVAL, "units");
    q.units = MECH_WORLDLINE_SECONDS;
    const double bad_ticks[3] = {0, -1, NAN};
    for (int i = 0; i < 3; i++) {
        q.tick_interval = bad_ticks[i];
        EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EINVAL, "tick_interval");
    }
    /* A distance at zero speed: mech_worldline_run's error, named by leg. */
    q.tick_interval = 1;
    q.n = 2;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EDOMAIN, "legs/1/velocity");
    /* The second home time is after the trip's end is seen at 1/(0.5c) + 1/c = 1.0e-8 s. */
    q.n = 1;
    const double times[2] = {5e-9, 2e-8};
    q.telescope_home_times = times;
    q.n_views = 2;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_EDOMAIN, "telescope_home_times/1");
    /* Ticks of 1e-300 s over 1e30 s overflow: a typed error, no arrays kept. */
    legs[0] = coast_distance(0.5, 1e30);
    q.n_views = 0;
    q.tick_interval = 1e-300;
    EXPECT(mech_worldline_answer(&q, &bud, &A, &e), MECH_ENUMERIC, "");
    /* A budget of one step cannot run two legs. */
    struct mech_budget one = mech_budget_make(1, 3600);
    legs[1] = coast_distance(-0.5, 1);
    q.n = 2;
    q.tick_interval = 1;
    mech_error_clear(&e);
    CHECK(mech_worldline_answer(&q, &one, &A, &e) != MECH_OK);
    CHECK(A.legs == NULL);
    mech_worldline_answer_free(&A); /* safe after a failure */
    mech_worldline_answer_free(NULL);
#undef EXPECT
}

int main(void)
{
    gsl_set_error_handler_off();
    bud = mech_budget_make(1000000, 3600);
    test_hyperbolic();
    test_twin_paradox();
    test_accelerated_round_trip();
    test_errors();
    TEST_MAIN_END();
}
