/* test_umbrella_headers.c — the ten umbrella headers of core/include/mech/
 * (one per domain: mech/base.h ... mech/answers.h) compile together in one
 * translation unit, each self-contained and without clashing names; that
 * each umbrella names every header of its folder is lint/includes' check.
 * The values checked are definitions and exact closed forms, one per domain
 * whose types they touch. */
#include "mech/answers.h"
#include "mech/base.h"
#include "mech/continuum.h"
#include "mech/frames.h"
#include "mech/gr.h"
#include "mech/hamiltonian/hamiltonian.h"
#include "mech/ode/ode.h"
#include "mech/relativity.h"
#include "mech/rigid.h"
#include "mech/rotation/rotation.h"
#include "testlib.h"

int main(void)
{
    /* the SI definition of the metre fixes c exactly */
    CHECK(MECH_C == 299792458.0);
    /* a Pythagorean quadruple: |(2, 3, 6)| = 7 exactly */
    CHECK(mech_vec3_norm(mech_vec3_make(2.0, 3.0, 6.0)) == 7.0);
    /* every integrator the driver lists is found by its own name */
    CHECK(mech_ode_method_find("rk8pd") != NULL);
    TEST_MAIN_END();
}
