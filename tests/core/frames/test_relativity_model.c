/* test_relativity_model.c — the rule of mech_trajectory_relativity_select
 * on both sides of its threshold, with runs whose measured sizes are set
 * here (so the expected estimate is computed by hand):
 *   estimate eps (1 + V T / L) against target / 10, for relativistic and for
 *   schwarzschild_1pn; forced in and out; not applicable (gravity alone: no
 *   relativistic term; no mass: no 1PN term); needed but not modellable (a
 *   rotating frame, two masses, both at once) is MECH_EDOMAIN at "relativity";
 *   the Kepler closed form's 1PN size taken at least at the pericentre. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

static struct mech_force lorentz_b(void)
{
    struct mech_force f;
    memset(&f, 0, sizeof f);
    f.type = MECH_FORCE_LORENTZ;
    f.u.lorentz.B = mech_vec3_make(0, 0, 1);
    return f;
}

static struct mech_force central(double gm, double x)
{
    struct mech_force f;
    memset(&f, 0, sizeof f);
    f.type = MECH_FORCE_CENTRAL_GRAVITY;
    f.u.central_gravity.gm = gm;
    f.u.central_gravity.center = mech_vec3_make(x, 0, 0);
    return f;
}

static struct mech_trajectory_problem scene(const struct mech_force *f, size_t n)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    p.charge = 1.0;
    p.position = mech_vec3_make(0, 1, 0);
    p.velocity = mech_vec3_make(1, 0, 0);
    p.frame.type = MECH_FRAME_INERTIAL;
    p.forces = f;
    p.n_forces = n;
    p.t_end = 10.0;
    p.samples = 2;
    return p;
}

/* A finished run: L = 2, V = 3, T = t_end = 10, so V T / L = 15 and the
 * estimate is eps (1 + 15) = 16 eps. */
static struct mech_trajectory_result run_with(double eps_rel, double eps_pn)
{
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r);
    r.method = "rk8pd";
    r.max_radius = 2.0;
    r.max_speed = 3.0;
    r.n_terms = 1;
    r.terms[0].max_acceleration = 1.0;
    r.relativity_terms[0].max_acceleration = eps_rel;
    r.relativity_terms[1].max_acceleration = eps_pn;
    r.relativity_ratio[0] = eps_rel;
    r.relativity_ratio[1] = eps_pn;
    return r;
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_relativity_model m;
    struct mech_error e;
    const double target = 1e-6; /* threshold 1e-7: eps = 1e-7/16 = 6.25e-9 */

    /* relativistic: a charge in B */
    const struct mech_force fb = lorentz_b();
    struct mech_trajectory_problem p = scene(&fb, 1);
    struct mech_trajectory_result r = run_with(6.0e-9, 0.0);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_OK);
    CHECK_CLOSE(m.terms[0].relative_effect, 16.0 * 6.0e-9, 1e-15, 0);
    CHECK(!m.terms[0].included);
    CHECK_EQ_INT(m.relativity, 0);
    CHECK(!m.terms[1].applicable);
    r = run_with(6.5e-9, 0.0);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_OK);
    CHECK(m.terms[0].included);
    CHECK_EQ_INT(m.relativity, MECH_RELATIVITY_SPECIAL);
    /* forced either way */
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, MECH_RELATIVITY_SPECIAL, &m, &e) ==
          MECH_OK);
    CHECK(!m.terms[0].included && !strncmp(m.terms[0].reason, "left out as requested", 21));
    r = run_with(1e-20, 0.0);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, MECH_RELATIVITY_SPECIAL, 0, &m, &e) ==
          MECH_OK);
    CHECK(m.terms[0].included && m.relativity == MECH_RELATIVITY_SPECIAL);
    /* needed in a rotating frame: not modellable */
    p.frame.type = MECH_FRAME_ROTATING;
    r = run_with(1e-3, 0.0);
    mech_error_clear(&e);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "relativity") && strstr(e.text, "relativistic"));
    /* ... and not needed there: fine */
    r = run_with(1e-12, 0.0);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_OK);

    /* schwarzschild_1pn: one mass; relativistic not applicable with gravity alone */
    const struct mech_force fg = central(1.0, 0.0);
    p = scene(&fg, 1);
    r = run_with(1.0, 6.0e-9); /* even a large special-relativistic size: not applicable */
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_OK);
    CHECK(!m.terms[0].applicable && !m.terms[0].included);
    CHECK(!m.terms[1].included);
    CHECK_CLOSE(m.terms[1].relative_effect, 16.0 * 6.0e-9, 1e-15, 0);
    r = run_with(0.0, 6.5e-9);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_OK);
    CHECK(m.terms[1].included && m.relativity == MECH_RELATIVITY_SCHWARZSCHILD_1PN);
    /* a Kepler closed form's samples may miss the pericentre: at least its
     * value there, |4 gm/q - v_q^2|/c^2 = 3 gm/(c^2 r) for the circular start */
    p.position = mech_vec3_make(1e-10, 0, 0);
    p.velocity = mech_vec3_make(0, sqrt(1e10), 0);
    r = run_with(0.0, 0.0);
    r.method = "closed_form";
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_OK);
    CHECK_CLOSE(m.terms[1].relative_effect, 16.0 * 3.0 * 1e10 / (MECH_C * MECH_C), 1e-9, 0);

    /* two masses: the 1PN bound 4 gm/(c^2 d) + 5 beta^2, d = sqrt(gm / max pull) */
    struct mech_force two[2] = {central(1e20, 1e10), central(1e20, -1e10)};
    p = scene(two, 2);
    r = run_with(0.0, 0.0);
    r.n_terms = 2;
    r.terms[0].max_acceleration = r.terms[1].max_acceleration = 1e20 / 1e22; /* d = 1e11 */
    const double eps2 = 4.0 * 1e20 / (MECH_C * MECH_C * 1e11) + 5.0 * 9.0 / (MECH_C * MECH_C);
    mech_error_clear(&e);
    CHECK(mech_trajectory_relativity_select(&p, &r, 1e-9, 0, 0, &m, &e) == MECH_EDOMAIN);
    CHECK(strstr(e.text, "schwarzschild_1pn") != NULL);
    CHECK(mech_trajectory_relativity_select(&p, &r, 1e-3, 0, 0, &m, &e) == MECH_OK);
    CHECK_CLOSE(m.terms[1].relative_effect, 16.0 * eps2, 1e-12, 0);

    /* both needed at once: not modelled together */
    struct mech_force mix[2] = {central(1.0, 5.0), lorentz_b()};
    p = scene(mix, 2);
    r = run_with(1e-3, 1e-3);
    mech_error_clear(&e);
    CHECK(mech_trajectory_relativity_select(&p, &r, target, 0, 0, &m, &e) == MECH_EDOMAIN);
    CHECK(strstr(e.text, "together") != NULL);
    /* bad target */
    CHECK(mech_trajectory_relativity_select(&p, &r, 0.5, 0, 0, &m, &e) == MECH_EINVAL);
    TEST_MAIN_END();
}
