/* test_collision_answer.c — mech/answers/relativity/collision_answer.h (notes §3, problems 10
 * and 18) against closed forms derived here (c = 1, MeV):
 *  - p p -> p p p pbar on protons at rest: threshold sqrt(s) = 4 m_p, and
 *    s = 2 m^2 + 2 m E = 16 m^2 gives E_lab = 7 m_p (kinetic 6 m_p); the
 *    inverse problem (sqrt_s = 4 m_p) gives the same beam;
 *  - two photons: s = 2 E1 E2 (1 - cos alpha), alpha = pi - chi, so
 *    M = 2 sqrt(E1 E2) cos(chi / 2); head-on E1 = 1, E2 = 4: M = 4, the CM
 *    moving at beta = -3/5 (gamma 5/4, rapidity -ln 2); nearly collinear
 *    photons (chi = pi - 1e-6) against 2 sqrt(E1 E2) sin(delta / 2) with delta
 *    = pi - chi taken exactly;
 *  - a slow fixed-target collision (T = 1e-12 m): s - (m1 + m2)^2 = 2 m2 T,
 *    the available energy against the series M (x/2 - x^2/8), x = 2 m2 T / M^2,
 *    p* = m2 p_lab / sqrt(s);
 *  - nearly symmetric proton beams (E2 = E1 (1 + 1e-10)): the CM beta_z =
 *    (E1 - E2) / (p1 + p2), exact differences, where p1 - p2 of the rounded
 *    momenta would keep ~6 digits; symmetric beams at a crossing angle:
 *    s = 4 E^2 - 4 p^2 sin^2(chi / 2), P = (p sin chi, 0, 2 p sin^2(chi / 2));
 *  - typed errors and overflow. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/answers/relativity/collision_answer.h"
#include "mech/base/constants.h"
#include "mech/relativity/particles.h"
#include "testlib.h"

static double m_p;

static struct mech_kin_motion rest(double m)
{
    struct mech_kin_motion k;
    CHECK_EQ_INT(mech_kin_motion_at_rest(m, &k, NULL), MECH_OK);
    return k;
}

static struct mech_kin_motion with_energy(double m, double e)
{
    struct mech_kin_motion k;
    CHECK_EQ_INT(mech_kin_motion_from_energy(m, e, &k, NULL), MECH_OK);
    return k;
}

static struct mech_kin_motion with_kinetic(double m, double t)
{
    struct mech_kin_motion k;
    CHECK_EQ_INT(mech_kin_motion_from_kinetic(m, t, &k, NULL), MECH_OK);
    return k;
}

static enum mech_status answer(const struct mech_collision_request *q,
                               struct mech_collision_answer *a, struct mech_error *e)
{
    mech_error_clear(e);
    return mech_collision_answer(q, a, e);
}

static void test_antiproton_threshold(void)
{
    const double fs[4] = {m_p, m_p, m_p, m_p};
    struct mech_collision_request q;
    memset(&q, 0, sizeof q);
    q.beam = with_kinetic(m_p, 6 * m_p);
    q.target = rest(m_p);
    q.final_masses = fs;
    q.n_final = 4;
    struct mech_collision_answer a;
    struct mech_error e;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.threshold.sqrt_s, 4 * m_p, 1e-15, 0);
    CHECK(a.threshold.has_fixed_target);
    CHECK_CLOSE(a.threshold.fixed_target_beam_energy, 7 * m_p, 1e-15, 0);
    CHECK_CLOSE(a.threshold.fixed_target_beam_kinetic, 6 * m_p, 1e-15, 0);
    /* p = sqrt(E^2 - m^2) = sqrt(49 - 1) m_p */
    CHECK_CLOSE(a.threshold.fixed_target_beam_momentum, sqrt(48.0) * m_p, 1e-15, 0);
    CHECK(a.threshold.has_symmetric_collider);
    CHECK_CLOSE(a.threshold.symmetric_collider_beam_energy, 2 * m_p, 1e-15, 0);
    /* the beam at exactly 6 m_p kinetic is the threshold: sqrt(s) = 4 m_p */
    CHECK_CLOSE(a.sqrt_s, 4 * m_p, 1e-15, 0);
    CHECK_CLOSE(a.s, 16 * m_p * m_p, 1e-15, 0);
    CHECK_CLOSE(a.available_energy, 2 * m_p, 1e-15, 0);
    CHECK_CLOSE(a.fixed_target_beam_kinetic, 6 * m_p, 1e-15, 0);
    CHECK_CLOSE(a.cm.gamma, 2, 1e-15, 0); /* (E + m) / sqrt(s) = 8 m / 4 m */
    /* just below: not reached */
    q.beam = with_kinetic(m_p, 6 * m_p * (1 - 1e-9));
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK(!a.threshold.reached);
    /* the inverse problem: sqrt_s = 4 m_p on a proton at rest */
    memset(&q, 0, sizeof q);
    q.beam.mass = m_p;
    q.beam_from_sqrt_s = 1;
    q.sqrt_s = 4 * m_p;
    q.target = rest(m_p);
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.beam.energy, 7 * m_p, 1e-15, 0);
    CHECK_CLOSE(a.beam.kinetic, 6 * m_p, 1e-15, 0);
    CHECK_CLOSE(a.beam.momentum, sqrt(48.0) * m_p, 1e-15, 0); /* 49 m^2 - m^2 */
    CHECK_CLOSE(a.sqrt_s, 4 * m_p, 1e-15, 0);
}

static void test_two_photons(void)
{
    struct mech_collision_request q;
    memset(&q, 0, sizeof q);
    q.beam = with_energy(0, 1);
    q.target = with_energy(0, 4);
    struct mech_collision_answer a;
    struct mech_error e;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.sqrt_s, 4, 1e-15, 0);
    CHECK_CLOSE(a.s, 16, 1e-15, 0);
    CHECK_CLOSE(a.cm_momentum, 2, 1e-15, 0); /* massless: p* = sqrt(s) / 2 */
    CHECK(a.cm.has_rest_frame);
    CHECK_CLOSE(a.cm.beta.z, -0.6, 1e-15, 0);
    CHECK_CLOSE(a.cm.gamma, 1.25, 1e-15, 0);
    CHECK_CLOSE(a.cm.rapidity, log(2.0), 1e-15, 0); /* |eta|: the speed's */
    CHECK(!a.has_fixed_target);                     /* a photon cannot be at rest */
    /* at 90 degrees: s = 2 E1 E2 */
    q.crossing_angle = MECH_PI / 2;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.s, 8, 1e-15, 0);
    /* nearly collinear: delta = pi - chi with pi's double's own error added */
    q.crossing_angle = MECH_PI - 1e-6;
    const double delta = (MECH_PI - q.crossing_angle) + 1.2246467991473532e-16;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.sqrt_s, 2 * sqrt(4.0) * sin(0.5 * delta), 1e-14, 0);
    CHECK_CLOSE(a.cm_momentum, 0.5 * a.sqrt_s, 1e-15, 0);
    /* two photons reach an e+ e- pair when sqrt(s) >= 2 m_e */
    const double pair[2] = {0.51099895, 0.51099895};
    q.final_masses = pair;
    q.n_final = 2;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK(!a.threshold.reached);          /* 2e-6 MeV < 1.02 MeV */
    CHECK(!a.threshold.has_fixed_target); /* a photon target cannot be at rest */
    /* head-on photons of m_e each make the pair at rest */
    CHECK(a.threshold.has_symmetric_collider);
    CHECK_CLOSE(a.threshold.symmetric_collider_beam_energy, 0.51099895, 1e-15, 0);
}

static void test_slow_fixed_target(void)
{
    const double m1 = 2.0, m2 = 3.0, M = m1 + m2, t = 1e-12 * m1;
    struct mech_collision_request q;
    memset(&q, 0, sizeof q);
    q.beam = with_kinetic(m1, t);
    q.target = rest(m2);
    struct mech_collision_answer a;
    struct mech_error e;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.s_minus_threshold, 2 * m2 * t, 1e-15, 0);
    const double x = 2 * m2 * t / (M * M);
    CHECK_CLOSE(a.available_energy, M * (0.5 * x - 0.125 * x * x), 1e-15, 0);
    CHECK_CLOSE(a.available_energy, m2 / M * t, 1e-11, 0); /* the non-relativistic mu/m1 T */
    const double p_lab = sqrt(t * (t + 2 * m1));
    CHECK_CLOSE(a.cm_momentum, m2 * p_lab / a.sqrt_s, 1e-15, 0);
    CHECK_CLOSE(a.fixed_target_beam_kinetic, t, 1e-15, 0);
    CHECK(!a.has_symmetric_collider);
    CHECK_CLOSE(a.cm.beta.z, p_lab / (m1 + t + m2), 1e-15, 0);
}

static void test_colliding_beams(void)
{
    const double e1 = 6.8e6, e2 = e1 * (1 + 1e-10); /* MeV */
    struct mech_collision_request q;
    memset(&q, 0, sizeof q);
    q.beam = with_energy(m_p, e1);
    q.target = with_energy(m_p, e2);
    struct mech_collision_answer a;
    struct mech_error e;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    const double p1 = sqrt((e1 - m_p) * (e1 + m_p)), p2 = sqrt((e2 - m_p) * (e2 + m_p));
    /* e1 - e2 is exact (Sterbenz); beta_z = (E1^2 - E2^2) / ((p1 + p2)(E1 + E2)) */
    CHECK_CLOSE(a.cm.beta.z, (e1 - e2) / (p1 + p2), 1e-12, 0);
    CHECK_CLOSE(a.cm.momentum.z, (e1 - e2) * (e1 + e2) / (p1 + p2), 1e-12, 0);
    /* the rounded momenta's difference keeps only a few digits: the check bites */
    CHECK(!(fabs((p1 - p2) / (e1 + e2) / ((e1 - e2) / (p1 + p2)) - 1) <= 1e-12));
    /* symmetric beams at a crossing angle (LHC-like, 285 urad) */
    const double chi = 285e-6, p = sqrt((e1 - m_p) * (e1 + m_p)), sh = sin(0.5 * chi);
    q.target = q.beam;
    q.crossing_angle = chi;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.s, 4 * e1 * e1 - 4 * p * p * sh * sh, 1e-15, 0);
    CHECK_CLOSE(a.cm.momentum.x, p * sin(chi), 1e-15, 0);
    CHECK_CLOSE(a.cm.momentum.z, 2 * p * sh * sh, 1e-13, 0);
    CHECK(a.has_symmetric_collider);
    CHECK_CLOSE(a.symmetric_collider_beam_energy, 0.5 * a.sqrt_s, 0, 0);
    /* head-on and equal: the CM is the lab */
    q.crossing_angle = 0;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_OK);
    CHECK_CLOSE(a.sqrt_s, 2 * e1, 1e-15, 0);
    CHECK_CLOSE(a.cm_momentum, p, 1e-15, 0);
    CHECK(a.cm.beta.z == 0);
    CHECK_CLOSE(a.cm.gamma, 1, 1e-15, 0);
}

static void test_errors(void)
{
    struct mech_collision_request q;
    struct mech_collision_answer a;
    struct mech_error e;
    memset(&q, 0, sizeof q);
    q.beam.mass = m_p;
    q.beam_from_sqrt_s = 1;
    q.sqrt_s = 1.5 * m_p; /* below 2 m_p */
    q.target = rest(m_p);
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "sqrt_s"));
    q.target = with_energy(m_p, 2 * m_p); /* sqrt_s is for a target at rest */
    q.sqrt_s = 5 * m_p;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "sqrt_s"));
    /* a massless target at rest (the API never builds one): the field's own error */
    memset(&q.target, 0, sizeof q.target);
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "target/particle"));
    memset(&q, 0, sizeof q);
    q.beam = with_energy(m_p, 2 * m_p);
    q.target = rest(m_p);
    q.crossing_angle = 4;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "crossing_angle"));
    q.crossing_angle = 0;
    double many[MECH_COLLISION_MAX_FINAL + 1] = {0};
    q.final_masses = many;
    q.n_final = MECH_COLLISION_MAX_FINAL + 1;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "final_state"));
    many[3] = -1;
    q.n_final = 5;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "final_state"));
    q.n_final = 0;
    q.beam.mass = NAN;
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "beam/particle"));
    /* s = (m1 + m2)^2 = 4e320 overflows: a typed error, not an inf */
    q.beam = rest(1e160);
    q.target = rest(1e160);
    CHECK_EQ_INT(answer(&q, &a, &e), MECH_ENUMERIC);
    CHECK_EQ_INT(mech_collision_answer(NULL, &a, NULL), MECH_EINVAL);
    CHECK_EQ_INT(mech_collision_answer(&q, NULL, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    m_p = mech_particle_find("proton")->mass;
    CHECK_CLOSE(m_p, 938.27208816, 0, 0); /* PDG 2024 */
    test_antiproton_threshold();
    test_two_photons();
    test_slow_fixed_target();
    test_colliding_beams();
    test_errors();
    TEST_MAIN_END();
}
