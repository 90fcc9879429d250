/* test_elastic_answer.c — one /v1/relativity/kinematics/elastic answer
 * (core/answers/relativity/collision_answer.c) against closed forms: for equal masses
 * the relativistic opening-angle rule tan θ3 tan θ4 = 2/(γ + 1), γ the
 * projectile's lab Lorentz factor (→ θ3 + θ4 = 90° only as γ → 1); the
 * outgoing pair's energy and momentum conserved to 1e-14 and each on its
 * mass shell (T (E + m) = p²); Compton's E' = E/(1 + (E/m)(1 − cos θ)); a
 * heavy projectile's largest lab angle sin θmax = m2/m1 (exact at any
 * energy: γ_cm² (g² − 1) = (m1² − m2²)/m2²) and its two CM solutions, each
 * checked by scattering at it; angles in degrees; every error at the
 * request's key. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/relativity/elastic_answer.h"
#include "testlib.h"

static const double M_P = 938.27208816, M_E = 0.51099895, M_MU = 105.6583755; /* MeV */

static struct mech_elastic_request request(double m1, double kinetic, double m2,
                                           enum mech_elastic_angle kind, double angle, int deg)
{
    struct mech_elastic_request q = {0};
    CHECK_EQ_INT(mech_kin_motion_from_kinetic(m1, kinetic, &q.projectile, NULL), MECH_OK);
    q.target_mass = m2;
    q.kind = kind;
    q.angle = angle;
    q.angle_in_degrees = deg;
    return q;
}

/* E, p∥, p⊥ of the outgoing pair equal the incoming ones; each on shell. */
static void check_conserved(const struct mech_elastic_request *q, const struct mech_elastic *o)
{
    const struct mech_kin_lab *a = &o->projectile, *b = &o->recoil;
    const double p1 = q->projectile.momentum, m1 = q->projectile.mass, m2 = q->target_mass;
    CHECK_CLOSE(a->energy + b->energy, q->projectile.energy + m2, 1e-14, 0);
    CHECK_CLOSE(a->momentum_parallel + b->momentum_parallel, p1, 1e-14, 0);
    CHECK_CLOSE(a->momentum_transverse + b->momentum_transverse, 0, 0, 1e-14 * p1);
    CHECK_CLOSE(a->kinetic * (a->energy + m1), a->momentum * a->momentum, 1e-14, 0);
    CHECK_CLOSE(b->kinetic * (b->energy + m2), b->momentum * b->momentum, 1e-14, 0);
}

static void test_equal_masses(void)
{
    const double T = 1000.0, g = 1 + T / M_P;
    const double cm_deg[] = {1, 30, 60, 90, 137, 179};
    for (int i = 0; i < 6; i++) {
        struct mech_elastic_request q =
            request(M_P, T, M_P, MECH_ELASTIC_CM_ANGLE, cm_deg[i], 1);
        struct mech_elastic_answer a;
        CHECK_EQ_INT(mech_elastic_answer(&q, &a, NULL), MECH_OK);
        const struct mech_elastic *o = &a.scatter;
        CHECK_CLOSE(o->cm_angle, cm_deg[i] * MECH_PI / 180, 4e-16, 0);
        CHECK_CLOSE(tan(o->projectile.angle) * tan(o->recoil.angle), 2 / (g + 1), 1e-14, 0);
        CHECK_CLOSE(o->opening_angle, o->projectile.angle + o->recoil.angle, 4e-16, 0);
        CHECK(o->opening_angle < MECH_PI / 2); /* relativity closes the 90 degrees */
        CHECK_CLOSE(o->velocity_ratio, 1.0, 4e-16, 0);
        CHECK(!o->has_max_angle);
        check_conserved(&q, o);
        CHECK(a.has_projectile_boost);
        CHECK_CLOSE(a.projectile_boost.gamma, g, 4e-16, 0);
        CHECK_EQ_INT(a.branch, 0);
    }
    /* the projectile's lab angle given (30 degrees, and in radians) */
    struct mech_elastic_request q = request(M_P, T, M_P, MECH_ELASTIC_LAB_ANGLE, 30, 1);
    struct mech_elastic_answer a;
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.scatter.projectile.angle, MECH_PI / 6, 1e-15, 0);
    CHECK_CLOSE(tan(a.scatter.recoil.angle), 2 / (g + 1) / tan(MECH_PI / 6), 1e-14, 0);
    check_conserved(&q, &a.scatter);
    q = request(M_P, T, M_P, MECH_ELASTIC_RECOIL_ANGLE, 0.5, 0);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.scatter.recoil.angle, 0.5, 1e-15, 0);
    CHECK_CLOSE(tan(a.scatter.projectile.angle), 2 / (g + 1) / tan(0.5), 1e-14, 0);
    /* near rest the rule is the classical right angle: tan tan = 2/(g + 1) -> 1 */
    q = request(M_P, 1e-6, M_P, MECH_ELASTIC_CM_ANGLE, 1.0, 0);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, NULL), MECH_OK);
    CHECK_CLOSE(a.scatter.opening_angle, MECH_PI / 2, 1e-9, 0);
    check_conserved(&q, &a.scatter);
}

/* A 1 MeV photon off an electron at 90 degrees: E' = E/(1 + E/m). */
static void test_compton(void)
{
    struct mech_elastic_request q = request(0.0, 1.0, M_E, MECH_ELASTIC_LAB_ANGLE, 90, 1);
    struct mech_elastic_answer a;
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, NULL), MECH_OK);
    const double e1 = 1.0 / (1.0 + 1.0 / M_E);
    CHECK_CLOSE(a.scatter.projectile.energy, e1, 1e-15, 0);
    CHECK_CLOSE(a.scatter.recoil.kinetic, 1.0 - e1, 1e-14, 0);
    CHECK(!a.has_projectile_boost); /* no rest frame */
    check_conserved(&q, &a.scatter);
}

/* A muon (p = 1 GeV) off an electron: sin θmax = m_e/m_mu; below it two CM
 * angles give one lab angle. */
static void test_heavy_on_light(void)
{
    struct mech_kin_motion k;
    CHECK_EQ_INT(mech_kin_motion_from_momentum(M_MU, 1000.0, &k, NULL), MECH_OK);
    struct mech_elastic_request q = {k, M_E, MECH_ELASTIC_LAB_ANGLE, 0.1, 1, 1};
    struct mech_elastic_answer a;
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, NULL), MECH_OK);
    const struct mech_elastic *o = &a.scatter;
    CHECK(o->has_max_angle);
    CHECK_CLOSE(o->max_angle, asin(M_E / M_MU), 1e-14, 0);
    CHECK_EQ_INT(o->n_solutions, 2);
    CHECK_EQ_INT(a.branch, 1);
    CHECK_CLOSE(o->cm_angle, o->cm_angle_solutions[1], 0, 0);
    check_conserved(&q, o);
    for (int b = 0; b < 2; b++) { /* each solution scatters back to 0.1 degrees */
        struct mech_elastic_request r = {k, M_E, MECH_ELASTIC_CM_ANGLE, o->cm_angle_solutions[b], 0, 0};
        struct mech_elastic_answer x;
        CHECK_EQ_INT(mech_elastic_answer(&r, &x, NULL), MECH_OK);
        CHECK_CLOSE(x.scatter.projectile.angle, 0.1 * MECH_PI / 180, 1e-12, 0);
        CHECK_EQ_INT(x.branch, 0);
    }
}

static void test_errors(void)
{
    struct mech_kin_motion k;
    CHECK_EQ_INT(mech_kin_motion_from_momentum(M_MU, 1000.0, &k, NULL), MECH_OK);
    struct mech_elastic_answer a;
    struct mech_error e;
    struct mech_elastic_request q = {k, M_E, MECH_ELASTIC_LAB_ANGLE, 5.0, 1, 0};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, &e), MECH_EDOMAIN); /* above 0.277 degrees */
    CHECK(!strcmp(e.param, "angle_deg"));
    q = (struct mech_elastic_request){k, M_E, MECH_ELASTIC_RECOIL_ANGLE, 90.0, 1, 0};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "recoil_angle_deg"));
    q = (struct mech_elastic_request){k, M_E, MECH_ELASTIC_CM_ANGLE, NAN, 0, 0};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "cm_angle"));
    q = (struct mech_elastic_request){k, 0.0, MECH_ELASTIC_CM_ANGLE, 1.0, 0, 0};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "target"));
    q = (struct mech_elastic_request){k, M_E, MECH_ELASTIC_CM_ANGLE, 1.0, 0, 2};
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "branch"));
    CHECK_EQ_INT(mech_elastic_answer(NULL, &a, NULL), MECH_EINVAL);
    CHECK(!strcmp(mech_elastic_angle_key(MECH_ELASTIC_RECOIL_ANGLE, 0), "recoil_angle"));
    CHECK(!strcmp(mech_elastic_angle_key((enum mech_elastic_angle)5, 1), "angle"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_equal_masses();
    test_compton();
    test_heavy_on_light();
    test_errors();
    TEST_MAIN_END();
}
