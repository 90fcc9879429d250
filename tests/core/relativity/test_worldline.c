/* test_worldline.c — trips as legs (core/relativity/worldline.c): the notes' twin
 * paradox (§3.15: 8 ly at 0.8c, 20 and 12 years, Doppler ticks 2/18 and
 * 6-over-18 / 6-over-2) and exercise 7 (11 ly at 0.6c), the muon (§3.4),
 * hyperbolic motion against t = (c/a) sinh(aτ/c), x = (c²/a)(cosh(aτ/c) − 1)
 * in long double, a fully accelerated round trip (returns home, both telescope
 * clocks agree at the end), a turnaround inside one leg, the 1 m/s twin and
 * β = 1 − 1e-15, and every error path. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/worldline.h"
#include "mech/base/constants.h"
#include "testlib.h"

static struct mech_budget bud;

static struct mech_leg coast(int kind, double bx, double amount)
{
    struct mech_leg l;
    memset(&l, 0, sizeof l);
    l.kind = (enum mech_leg_kind)kind;
    mech_boost_from_beta(mech_vec3_make(bx, 0, 0), &l.velocity, NULL);
    l.amount = amount;
    return l;
}

static struct mech_leg accel(double a, double tau, double dx)
{
    struct mech_leg l;
    memset(&l, 0, sizeof l);
    l.kind = MECH_LEG_ACCELERATE;
    l.acceleration = a;
    l.amount = tau;
    l.direction = mech_vec3_make(dx, 0, 0);
    return l;
}

static void test_notes_twins(void)
{
    /* Years and light-years, c = 1. Out 8 ly at 0.8c, back the same. */
    struct mech_leg legs[2] = {coast(MECH_LEG_COAST_DISTANCE, 0.8, 8),
                               coast(MECH_LEG_COAST_DISTANCE, -0.8, 8)};
    struct mech_leg_result r[2];
    struct mech_worldline_total tot;
    CHECK_EQ_INT(mech_worldline_run(legs, 2, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(r[0].coordinate_time, 10, 2e-16, 0);
    CHECK_CLOSE(r[0].proper_time, 6, 4e-16, 0);
    CHECK_CLOSE(tot.coordinate_time, 20, 2e-16, 0);
    CHECK_CLOSE(tot.proper_time, 12, 4e-16, 0);
    CHECK_CLOSE(tot.age_difference, 8, 1e-15, 0);
    CHECK_CLOSE(tot.distance, 16, 2e-16, 0);
    CHECK_CLOSE(tot.end[1], 0, 0, 1e-15);
    /* Traveller sees 2 home ticks out, 18 back (one tick a year). */
    CHECK_CLOSE(r[0].home_clock_seen_end - r[0].home_clock_seen_start, 2, 2e-15, 0);
    CHECK_CLOSE(r[1].home_clock_seen_end - r[1].home_clock_seen_start, 18, 2e-15, 0);
    /* Home sees the 6 outbound ticks over 18 years and the 6 return ticks over 2. */
    CHECK_CLOSE(r[0].home_receives_end - r[0].home_receives_start, 18, 2e-15, 0);
    CHECK_CLOSE(r[1].home_receives_end - r[1].home_receives_start, 2, 4e-15, 0);
    /* Rates: sqrt((1 − β)/(1 + β)) = 1/3 receding, 3 approaching; product 1. */
    double rec = (r[0].home_clock_seen_end - r[0].home_clock_seen_start) / r[0].proper_time;
    double app = (r[1].home_clock_seen_end - r[1].home_clock_seen_start) / r[1].proper_time;
    CHECK_CLOSE(rec, 1.0 / 3.0, 4e-16, 0);
    CHECK_CLOSE(app, 3.0, 4e-16, 0);
    CHECK_CLOSE(rec * app, 1.0, 1e-15, 0);
    CHECK_CLOSE(tot.home_clock_seen_end, 20, 2e-16, 0);
    CHECK_CLOSE(tot.home_receives_end, 20, 2e-16, 0);

    /* Exercise 7: 11 ly at 0.6c each way: home 2·11/0.6 = 36.67 y, traveller ×0.8. */
    legs[0] = coast(MECH_LEG_COAST_DISTANCE, 0.6, 11);
    legs[1] = coast(MECH_LEG_COAST_DISTANCE, -0.6, 11);
    CHECK_EQ_INT(mech_worldline_run(legs, 2, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(tot.coordinate_time, 22 / 0.6, 4e-16, 0);
    CHECK_CLOSE(tot.proper_time, 0.8 * 22 / 0.6, 4e-16, 0);
}

static void test_muon(void)
{
    /* Notes §3.4: τ = 2 µs at β = 0.9999: γτ ≈ 141.4 µs, βγcτ ≈ 42.39 km. */
    struct mech_leg l = coast(MECH_LEG_COAST_PROPER_TIME, 0.9999, 2e-6);
    struct mech_leg_result r;
    struct mech_worldline_total tot;
    CHECK_EQ_INT(mech_worldline_run(&l, 1, MECH_C, &bud, &r, &tot, NULL), MECH_OK);
    double g = 1 / sqrt((1 - 0.9999) * (1 + 0.9999));
    CHECK_CLOSE(r.coordinate_time, g * 2e-6, 4e-16, 0);
    CHECK_CLOSE(r.distance, 0.9999 * g * MECH_C * 2e-6, 4e-16, 0);
    CHECK_CLOSE(r.displacement.x, 42393.876154631258, 1e-15, 0);
}

static void test_hyperbolic(void)
{
    /* 1 g for one (Julian) year from rest, SI units. */
    const double a = 9.80665, tau = 31557600.0;
    struct mech_leg l = accel(a, tau, 1);
    struct mech_leg_result r;
    struct mech_worldline_total tot;
    CHECK_EQ_INT(mech_worldline_run(&l, 1, MECH_C, &bud, &r, &tot, NULL), MECH_OK);
    long double phi = (long double)a * tau / MECH_C;
    long double t = MECH_C / (long double)a * sinhl(phi);
    long double x = (long double)MECH_C * MECH_C / a * (coshl(phi) - 1);
    CHECK_CLOSE(r.coordinate_time, (double)t, 2e-15, 0);
    CHECK_CLOSE(r.displacement.x, (double)x, 2e-15, 0);
    CHECK_CLOSE(r.distance, (double)x, 2e-15, 0);
    CHECK_CLOSE(r.final_velocity.rapidity, (double)phi, 2e-16, 0);
    CHECK_CLOSE(r.age_difference, (double)(t - tau), 1e-14, 0);
    /* Home clock the traveller sees at the end: t − x/c = (c/a)(1 − e^{−φ}). */
    CHECK_CLOSE(r.home_clock_seen_end, (double)(MECH_C / (long double)a * -expm1l(-phi)), 2e-15, 0);
    CHECK_CLOSE(r.home_receives_end, (double)(MECH_C / (long double)a * expm1l(phi)), 2e-15, 0);

    /* Tiny aτ/c = 3.3e-12: x = ½aτ²(1 + φ²/12), T − τ = τ φ²/6 (1 + φ²/20). */
    l = accel(1e-3, 1.0, 1);
    CHECK_EQ_INT(mech_worldline_run(&l, 1, MECH_C, &bud, &r, &tot, NULL), MECH_OK);
    double p = 1e-3 / MECH_C;
    CHECK_CLOSE(r.displacement.x, 0.5e-3 * (1 + p * p / 12), 2e-16, 0);
    CHECK_CLOSE(r.age_difference, p * p / 6, 2e-15, 0);
    CHECK_CLOSE(r.coordinate_time, 1.0, 2e-16, 0);
}

static void test_accelerated_round_trip(void)
{
    /* Years: a = 1 ly/y², τ1 = 1 y per quarter: speed up, slow down (a < 0
     * means against the current velocity), come back, stop. */
    struct mech_leg legs[4] = {accel(1, 1, 1), accel(-1, 1, 0), accel(1, 1, -1), accel(-1, 1, 0)};
    struct mech_leg_result r[4];
    struct mech_worldline_total tot;
    CHECK_EQ_INT(mech_worldline_run(legs, 4, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(tot.proper_time, 4, 2e-16, 0);
    CHECK_CLOSE(tot.coordinate_time, 4 * sinh(1.0), 4e-16, 0);
    CHECK_CLOSE(r[1].end[1], 2 * (cosh(1.0) - 1), 4e-16, 0);
    CHECK_CLOSE(tot.end[1], 0, 0, 1e-15);
    CHECK(tot.final_velocity.beta < 1e-15);
    CHECK_CLOSE(tot.distance, 4 * (cosh(1.0) - 1), 4e-16, 0);
    CHECK_CLOSE(tot.home_clock_seen_end, tot.coordinate_time, 1e-15, 0);
    CHECK_CLOSE(tot.home_receives_end, tot.coordinate_time, 1e-15, 0);
    CHECK_CLOSE(tot.age_difference, 4 * (sinh(1.0) - 1), 1e-15, 0);

    /* Turnaround inside one leg: moving at 0.6c, a = −1 for τ = 2 atanh(0.6):
     * ends at −0.6c where it started, path 2(cosh η0 − 1) = 0.5, T = 2 sinh η0 = 1.5. */
    struct mech_leg two[2] = {coast(MECH_LEG_COAST_TIME, 0.6, 1), accel(-1, 2 * atanh(0.6), 0)};
    CHECK_EQ_INT(mech_worldline_run(two, 2, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(r[1].coordinate_time, 1.5, 4e-16, 0);
    CHECK_CLOSE(r[1].distance, 0.5, 4e-15, 0);
    CHECK_CLOSE(r[1].displacement.x, 0, 0, 1e-16);
    CHECK_CLOSE(r[1].final_velocity.beta_vec.x, -0.6, 4e-16, 0);
}

static void test_extremes(void)
{
    struct mech_leg_result r[2];
    struct mech_worldline_total tot;
    /* 1 m/s for 1e6 s out and back: T − τ = 2e6 (γ − 1)/γ ≈ 2e6 (β²/2 + β⁴/8). */
    double b = 1 / MECH_C;
    struct mech_leg slow[2] = {coast(MECH_LEG_COAST_TIME, b, 1e6),
                               coast(MECH_LEG_COAST_TIME, -b, 1e6)};
    CHECK_EQ_INT(mech_worldline_run(slow, 2, MECH_C, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(tot.age_difference, 2e6 * (b * b / 2 + b * b * b * b / 8), 1e-15, 0);
    CHECK(tot.coordinate_time - tot.proper_time == 0); /* what subtraction would give */
    /* 1 − β = 1e-15 for 1 year out and back (c = 1): the traveller sees the
     * home clock read T(1 − β) = 1e-15 y at the far end; home sees the far end
     * at 1 + (1 − 1e-15). */
    struct mech_leg fast[2];
    memset(fast, 0, sizeof fast);
    fast[0].kind = fast[1].kind = MECH_LEG_COAST_TIME;
    fast[0].amount = fast[1].amount = 1;
    mech_boost_from_one_minus_beta(1e-15, mech_vec3_make(1, 0, 0), &fast[0].velocity, NULL);
    mech_boost_from_one_minus_beta(1e-15, mech_vec3_make(-1, 0, 0), &fast[1].velocity, NULL);
    CHECK_EQ_INT(mech_worldline_run(fast, 2, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(r[0].home_clock_seen_end, 1e-15, 1e-15, 0);
    CHECK_CLOSE(r[0].home_receives_end, 2 - 1e-15, 2e-16, 0);
    double g = 1 / sqrt(1e-15 * (2 - 1e-15));
    CHECK_CLOSE(tot.proper_time, 2 / g, 1e-15, 0);
    CHECK_CLOSE(tot.home_clock_seen_end, 2, 2e-16, 0);
    /* γ = 1e15 for a proper year: T = 1e15 y. */
    struct mech_leg huge;
    memset(&huge, 0, sizeof huge);
    huge.kind = MECH_LEG_COAST_PROPER_TIME;
    huge.amount = 1;
    mech_boost_from_gamma(1e15, mech_vec3_make(0, 1, 0), &huge.velocity, NULL);
    CHECK_EQ_INT(mech_worldline_run(&huge, 1, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(tot.coordinate_time, 1e15, 2e-16, 0);
    CHECK_CLOSE(tot.age_difference, 1e15 - 1, 2e-16, 0);
    CHECK_CLOSE(r[0].home_clock_seen_end, 1 / (1e15 + sqrt(1e30 - 1)), 1e-15, 0);
}

static void test_errors(void)
{
    struct mech_leg_result r[2];
    struct mech_worldline_total tot;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_leg l = coast(MECH_LEG_COAST_DISTANCE, 0, 1);
    CHECK_EQ_INT(mech_worldline_run(&l, 1, 1.0, &bud, r, &tot, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "legs/0/velocity") == 0);
    mech_error_clear(&e);
    l = accel(1, 1, 0);
    CHECK_EQ_INT(mech_worldline_run(&l, 1, 1.0, &bud, r, &tot, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "legs/0/direction") == 0);
    mech_error_clear(&e);
    struct mech_leg side[2] = {coast(MECH_LEG_COAST_TIME, 0.5, 1), accel(1, 1, 0)};
    side[1].direction = mech_vec3_make(0, 1, 0);
    CHECK_EQ_INT(mech_worldline_run(side, 2, 1.0, &bud, r, &tot, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "legs/1/direction") == 0);
    mech_error_clear(&e);
    l = accel(1, 400, 1);
    CHECK_EQ_INT(mech_worldline_run(&l, 1, 1.0, &bud, r, &tot, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "legs/0/proper_time") == 0);
    struct mech_budget one = mech_budget_make(1, 10);
    struct mech_leg two[2] = {coast(MECH_LEG_COAST_TIME, 0.5, 1),
                              coast(MECH_LEG_COAST_TIME, 0.5, 1)};
    CHECK_EQ_INT(mech_worldline_run(two, 2, 1.0, &one, r, &tot, NULL), MECH_EBUDGET);
}

/* Per-leg telescope intervals of a short leg late in a long trip
 * (no answer is a difference of nearly equal numbers): 10 years out at 0.6c, then one day (1/365.25 yr) further out and one
 * day back. Radially receding the traveller sees home time T(1 − β) pass and
 * home sees the leg over T(1 + β); approaching, the other way round. Exact
 * rationals of the same doubles (Python fractions): T(1 − β) =
 * 0.0010951403148528405, T(1 + β) = 0.004380561259411362. The differences of
 * the running totals (≈ 4 and 16 years) were off by 2e-13 relative. */
static void test_short_leg_late(void)
{
    const double day = 1 / 365.25, lo = 0.0010951403148528405, hi = 0.004380561259411362;
    struct mech_leg legs[3] = {coast(MECH_LEG_COAST_TIME, 0.6, 10),
                               coast(MECH_LEG_COAST_TIME, 0.6, day),
                               coast(MECH_LEG_COAST_TIME, -0.6, day)};
    struct mech_leg_result r[3];
    struct mech_worldline_total tot;
    CHECK_EQ_INT(mech_worldline_run(legs, 3, 1.0, &bud, r, &tot, NULL), MECH_OK);
    CHECK_CLOSE(r[1].home_clock_seen, lo, 1e-15, 0);
    CHECK_CLOSE(r[1].home_receives, hi, 1e-15, 0);
    CHECK_CLOSE(r[2].home_clock_seen, hi, 1e-15, 0);
    CHECK_CLOSE(r[2].home_receives, lo, 1e-15, 0);
    /* The first leg's intervals, and the totals 10 (1 ∓ β) + T(1 − β) + T(1 + β). */
    CHECK_CLOSE(r[0].home_clock_seen, 4, 2e-16, 0);
    CHECK_CLOSE(r[0].home_receives, 16, 2e-16, 0);
    CHECK_CLOSE(tot.home_clock_seen_end, 4.005475701574264, 4e-16, 0);
    CHECK_CLOSE(tot.home_receives_end, 16.005475701574262, 4e-16, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    bud = mech_budget_make(1000, 10);
    test_notes_twins();
    test_short_leg_late();
    test_muon();
    test_hyperbolic();
    test_accelerated_round_trip();
    test_extremes();
    test_errors();
    TEST_MAIN_END();
}
