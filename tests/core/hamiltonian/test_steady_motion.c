/* test_steady_motion.c — mech/hamiltonian/steady_motion.h checked by a second method:
 * Hamilton's equations themselves (mech_ham_rhs) at the steady state must
 * give p_theta' = 0 (conical pendulum) and p_r' = 0 (circular orbit), with
 * phi' the answer's rate; Kepler's third law T = 2 pi sqrt(m r^3 / |k|) for
 * n = -1; stability n > -2; the cases without a steady motion refused. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/hamiltonian/steady_motion.h"
#include "testlib.h"

static struct mech_ham_system sys(enum mech_ham_kind kind)
{
    struct mech_ham_system s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.mass = 2.0;
    s.length = 0.5;
    s.g = 9.81;
    s.strength = -3.0;
    s.power = -1.0;
    CHECK_EQ_INT(mech_ham_system_check(&s, NULL), MECH_OK);
    return s;
}

static void test_conical(void)
{
    const struct mech_ham_system s = sys(MECH_HAM_SPHERICAL_PENDULUM);
    const double th[3] = {1e-6, 0.6, 1.5};
    for (int i = 0; i < 3; i++) {
        struct mech_ham_conical m;
        CHECK_EQ_INT(mech_ham_conical_motion(&s, th[i], &m), 1);
        const double y[4] = {th[i], 0.0, 0.0, m.p_phi};
        double dy[4];
        CHECK_EQ_INT(mech_ham_rhs(&s, y, dy, NULL, NULL, NULL), MECH_OK);
        /* theta' = 0, phi' = the rate, p_theta' = 0 against its terms' size m g l sin */
        CHECK_CLOSE(dy[0], 0.0, 0, 0);
        CHECK_CLOSE(dy[1], m.phi_dot, 1e-14, 0);
        CHECK_CLOSE(dy[2], 0.0, 0, 1e-13 * s.mass * s.g * s.length * sin(th[i]));
        CHECK(m.has_period);
        CHECK_CLOSE(m.period * m.phi_dot, 2.0 * MECH_PI, 1e-15, 0);
    }
    /* the small-angle limit: phi' -> sqrt(g/l) */
    struct mech_ham_conical m;
    CHECK_EQ_INT(mech_ham_conical_motion(&s, 1e-6, &m), 1);
    CHECK_CLOSE(m.phi_dot, sqrt(9.81 / 0.5), 1e-11, 0);
    /* none on the vertical, at or above the horizontal, or for another system */
    CHECK_EQ_INT(mech_ham_conical_motion(&s, 0.0, &m), 0);
    CHECK_EQ_INT(mech_ham_conical_motion(&s, 0.5 * MECH_PI, &m), 0);
    CHECK_EQ_INT(mech_ham_conical_motion(&s, 2.0, &m), 0);
    CHECK_EQ_INT(mech_ham_conical_motion(&s, NAN, &m), 0);
    const struct mech_ham_system p = sys(MECH_HAM_PENDULUM);
    CHECK_EQ_INT(mech_ham_conical_motion(&p, 0.6, &m), 0);
    /* no gravity: the rate is 0 and there is no period */
    struct mech_ham_system z = s;
    z.g = 0.0;
    CHECK_EQ_INT(mech_ham_conical_motion(&z, 0.6, &m), 1);
    CHECK_CLOSE(m.phi_dot, 0.0, 0, 0);
    CHECK(!m.has_period && isnan(m.period));
}

static void test_circular(void)
{
    struct mech_ham_system s = sys(MECH_HAM_CENTRAL); /* V = -3/r, m = 2 */
    const double r[3] = {1e-3, 1.7, 1e6};
    for (int i = 0; i < 3; i++) {
        struct mech_ham_central_circular c;
        CHECK_EQ_INT(mech_ham_central_circular(&s, r[i], &c), 1);
        const double y[4] = {r[i], 0.0, 0.0, c.p_phi};
        double dy[4];
        CHECK_EQ_INT(mech_ham_rhs(&s, y, dy, NULL, NULL, NULL), MECH_OK);
        /* p_r' = p_phi^2/(m r^3) - |k|/r^2 = 0 against either term */
        CHECK_CLOSE(dy[2], 0.0, 0, 1e-14 * 3.0 / (r[i] * r[i]));
        CHECK_CLOSE(c.period * dy[1], 2.0 * MECH_PI, 1e-14, 0);
        /* Kepler's third law */
        CHECK_CLOSE(c.period, 2.0 * MECH_PI * sqrt(2.0 * r[i] * r[i] * r[i] / 3.0), 1e-14, 0);
        CHECK(c.stable);
    }
    /* n = -3 attractive (k < 0): circular but unstable; harmonic n = 2 stable */
    struct mech_ham_central_circular c;
    s.power = -3.0;
    CHECK_EQ_INT(mech_ham_central_circular(&s, 1.0, &c), 1);
    CHECK(!c.stable);
    s.power = 2.0;
    s.strength = 0.5;
    CHECK_EQ_INT(mech_ham_central_circular(&s, 2.0, &c), 1);
    CHECK(c.stable);
    CHECK_CLOSE(c.period, 2.0 * MECH_PI * sqrt(2.0 / (2.0 * 0.5)), 1e-15, 0); /* 2 pi sqrt(m/2k) */
    /* repulsive (k n < 0): none; another system: none */
    s.strength = -0.5;
    CHECK_EQ_INT(mech_ham_central_circular(&s, 2.0, &c), 0);
    const struct mech_ham_system o = sys(MECH_HAM_HENON_HEILES);
    CHECK_EQ_INT(mech_ham_central_circular(&o, 2.0, &c), 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_conical();
    test_circular();
    TEST_MAIN_END();
}
