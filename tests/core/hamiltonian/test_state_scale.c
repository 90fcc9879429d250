/* test_state_scale.c — mech/hamiltonian/state_scale.h against hand-worked cases:
 * the oscillator's inertia is m, so the scale is min(|q|, |p|, tau|p|/m,
 * m|q|/tau); the central system's p_phi has inertia m r^2 (d2H/dp_phi^2 =
 * 1/(m r^2)); zero components are skipped; a state at rest at the origin has
 * scale 1. */
#include <math.h>
#include <string.h>

#include "mech/hamiltonian/state_scale.h"
#include "testlib.h"

int main(void)
{
    struct mech_ham_system s;
    memset(&s, 0, sizeof s);
    s.kind = MECH_HAM_OSCILLATOR;
    s.dof = 1;
    s.mass = 2.0;
    s.k[0] = 8.0;
    CHECK_EQ_INT(mech_ham_system_check(&s, NULL), MECH_OK);
    const double y1[2] = {3.0, 5.0};
    CHECK_CLOSE(mech_ham_state_scale(&s, y1, 0.1), 0.1 * 5.0 / 2.0, 1e-15, 0);
    CHECK_CLOSE(mech_ham_state_scale(&s, y1, 1e3), 2.0 * 3.0 / 1e3, 1e-15, 0);
    const double ytiny[2] = {1e-15, 0.0};
    CHECK_CLOSE(mech_ham_state_scale(&s, ytiny, 1.0), 1e-15, 1e-15, 0);
    const double y0[2] = {0.0, 0.0};
    CHECK_CLOSE(mech_ham_state_scale(&s, y0, 1.0), 1.0, 0, 0);

    memset(&s, 0, sizeof s);
    s.kind = MECH_HAM_CENTRAL;
    s.mass = 1.0;
    s.strength = -1.0;
    s.power = -1.0;
    CHECK_EQ_INT(mech_ham_system_check(&s, NULL), MECH_OK);
    /* r = 2, p_phi = 4, tau = 1: r gives 2 (q) and 2 (m q/tau); p_phi gives 4 and
     * tau p_phi/(m r^2) = 1 */
    const double yc[4] = {2.0, 0.0, 0.0, 4.0};
    CHECK_CLOSE(mech_ham_state_scale(&s, yc, 1.0), 1.0, 1e-15, 0);
    TEST_MAIN_END();
}
