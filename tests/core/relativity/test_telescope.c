/* test_telescope.c — what the stay-at-home twin sees of the traveller's
 * clock (core/relativity/telescope.c), against the notes' twin paradox in closed form:
 * out at beta = 0.8 for 4 ly (5 yr home time, 3 yr aboard), back the same
 * way. Home sees the outbound clock run at sqrt((1 - b)/(1 + b)) = 1/3 until
 * the turnaround's light arrives at t = 5 + 4 = 9 yr (reading 3 yr), then at
 * 3x until the return at t = 10 (reading 6 yr). An accelerated leg (the
 * image of its end is its last instant) checks the bisection on hyperbolic
 * motion against the leg's own end. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/telescope.h"
#include "testlib.h"

static void test_twin(void)
{
    struct mech_leg legs[2];
    memset(legs, 0, sizeof legs);
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.8, 0, 0), &legs[0].velocity, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(-0.8, 0, 0), &legs[1].velocity, NULL), MECH_OK);
    legs[0].kind = legs[1].kind = MECH_LEG_COAST_DISTANCE;
    legs[0].amount = legs[1].amount = 4.0;
    struct mech_leg_result run[2], sr[2];
    struct mech_leg sl[2];
    struct mech_worldline_total tot;
    const struct mech_budget b = mech_budget_make(10000000, 60.0);
    CHECK_EQ_INT(mech_worldline_run(legs, 2, 1.0, &b, run, &tot, NULL), MECH_OK);
    const double t[5] = {0, 4.5, 9, 9.5, 10}, want[5] = {0, 1.5, 3, 4.5, 6};
    const double dist[5] = {0, 2, 4, 2, 0};
    for (int i = 0; i < 5; i++) {
        struct mech_telescope_view v;
        CHECK_EQ_INT(mech_telescope_home_view(legs, run, 2, 1.0, t[i], sl, sr, &b, &v, NULL), MECH_OK);
        CHECK_CLOSE(v.traveller_clock, want[i], 4e-15, 4e-15);
        CHECK_CLOSE(v.light_time, dist[i], 4e-15, 4e-15);
        CHECK_CLOSE(v.emission[0] + v.light_time, t[i], 4e-15, 4e-15);
    }
    struct mech_telescope_view v;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_telescope_home_view(legs, run, 2, 1.0, 10.5, sl, sr, &b, &v, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "telescope_home_times"));
}

static void test_accelerated(void)
{
    /* 1 ly/yr^2 for 2 yr proper time from rest along x: at the leg's end the
     * traveller's clock reads 2 and home sees that when end[0] + end[1] arrives. */
    struct mech_leg leg;
    memset(&leg, 0, sizeof leg);
    leg.kind = MECH_LEG_ACCELERATE;
    leg.amount = 2.0;
    leg.acceleration = 1.0;
    leg.direction = mech_vec3_make(1, 0, 0);
    struct mech_leg_result run[1], sr[1];
    struct mech_leg sl[1];
    struct mech_worldline_total tot;
    const struct mech_budget b = mech_budget_make(10000000, 60.0);
    CHECK_EQ_INT(mech_worldline_run(&leg, 1, 1.0, &b, run, &tot, NULL), MECH_OK);
    /* Hyperbolic motion: t = sinh(tau), x = cosh(tau) - 1; arrival t + x = e^tau - 1. */
    const double tau = 1.3, home = exp(tau) - 1;
    struct mech_telescope_view v;
    CHECK_EQ_INT(mech_telescope_home_view(&leg, run, 1, 1.0, home, sl, sr, &b, &v, NULL), MECH_OK);
    CHECK_CLOSE(v.traveller_clock, tau, 1e-14, 0);
    CHECK_CLOSE(v.emission[0], sinh(tau), 1e-14, 0);
    CHECK_CLOSE(v.emission[1], cosh(tau) - 1, 1e-14, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_twin();
    test_accelerated();
    TEST_MAIN_END();
}
