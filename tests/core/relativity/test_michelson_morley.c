/* test_michelson_morley.c — the ether analysis of Michelson–Morley
 * (core/relativity/michelson_morley.c) against 50-digit Decimal closed forms for the
 * notes' numbers (L = 11 m, beta = 1e-4: d = 2 gamma (gamma - 1) L =
 * 110.000001375 nm beside the notes' beta^2 L = 110 nm), the contracted arm
 * (no shift), 1 m/s (gamma - 1 = 5.6e-18 keeps its digits) and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/michelson_morley.h"
#include "mech/base/constants.h"
#include "testlib.h"

static void test_notes(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(1e-4, 0, 0), &b, NULL), MECH_OK);
    struct mech_michelson_morley m;
    CHECK_EQ_INT(mech_michelson_morley_compute(11, &b, 5.5e-7, &m, NULL), MECH_OK);
    CHECK_CLOSE(m.path_difference, 1.1000000137500003e-07, 1e-14, 0);
    CHECK_CLOSE(m.path_difference_approx, 1.1000000000000001e-07, 1e-15, 0);
    CHECK_CLOSE(m.approx_rel_error, -1.2499999981250001e-08, 1e-9, 0);
    CHECK_CLOSE(m.time_parallel, 7.3384101677434468e-08, 1e-15, 0);
    CHECK_CLOSE(m.time_perpendicular, 7.3384101310513958e-08, 1e-15, 0);
    CHECK_CLOSE(m.fringe_shift, 0.40000000500000009, 1e-14, 0);
    CHECK_CLOSE(m.time_parallel_contracted, m.time_perpendicular, 1e-15, 0);
    /* 1 m/s: d = 2 gamma (gamma - 1) L = L beta^2 (1 + ...) = 11/c^2 m. */
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(1 / MECH_C, 0, 0), &b, NULL), MECH_OK);
    CHECK_EQ_INT(mech_michelson_morley_compute(11, &b, 0, &m, NULL), MECH_OK);
    CHECK_CLOSE(m.path_difference, 11.0 / (MECH_C * MECH_C), 1e-15, 0);
    CHECK_CLOSE(m.fringe_shift, 0.0, 0, 0);
}

static void test_errors(void)
{
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(1e-4, 0, 0), &b, NULL), MECH_OK);
    struct mech_michelson_morley m;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_michelson_morley_compute(0, &b, 5e-7, &m, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "arm_length"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_notes();
    test_errors();
    TEST_MAIN_END();
}
