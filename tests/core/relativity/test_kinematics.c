/* test_kinematics.c — relativistic particle kinematics (core/relativity/kinematics.c)
 * against closed forms evaluated independently in 60-digit decimal arithmetic
 * (Python decimal; the values are quoted with their derivation), the notes'
 * worked examples and end-of-chapter problems (π⁰ decay, neutron decay,
 * Compton shift, problems 10, 11, 12, 18, 19), boost invariance through
 * mech/relativity/boost.h, and the extremes: massless daughters, nearly collinear
 * photons, γ = 1e6 parents, a parent at 1e-12 c, thresholds, unphysical input. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>

#include "mech/relativity/boost.h"
#include "mech/base/constants.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"
#include "testlib.h"

static const double M_PI0 = 134.9768, M_PIC = 139.57039, M_MU = 105.6583755;
static const double M_P = 938.27208816, M_N = 939.5654205, M_E = 0.51099895000;

static double worst_invariant, worst_decay, worst_compton, worst_collision;

static double rel(double got, double want)
{
    return want == 0 ? fabs(got) : fabs(got - want) / fabs(want);
}

static void note(double *worst, double got, double want)
{
    double r = rel(got, want);
    if (r > *worst) *worst = r;
}

static struct mech_boost parent_boost(double m, double p)
{
    struct mech_kin_motion k;
    struct mech_boost b;
    CHECK_EQ_INT(mech_kin_motion_from_momentum(m, p, &k, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_boost(&k, mech_vec3_make(0, 0, 1), &b, NULL), MECH_OK);
    return b;
}

/* notes §3 "π⁰ Decay": at rest, two back-to-back photons of m/2 each; problem
 * 11: E = 40 GeV, equal lab energies ⇒ θ* = 90°, opening angle 2 asin(m/E). */
static void test_pi0(void)
{
    struct mech_kin_two_body tb;
    CHECK_EQ_INT(mech_kin_two_body_rest(M_PI0, 0, 0, &tb, NULL), MECH_OK);
    CHECK_CLOSE(tb.momentum, M_PI0 / 2, 1e-16, 0);
    CHECK_CLOSE(tb.energy[0], M_PI0 / 2, 1e-16, 0);
    CHECK_CLOSE(tb.kinetic[1], M_PI0 / 2, 1e-16, 0);

    struct mech_kin_motion k;
    struct mech_boost b;
    CHECK_EQ_INT(mech_kin_motion_from_energy(M_PI0, 40000, &k, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_boost(&k, mech_vec3_make(0, 0, 1), &b, NULL), MECH_OK);
    struct mech_kin_lab l1, l2;
    mech_kin_decay_lab(&b, 0, tb.momentum, tb.energy[0], MECH_PI / 2, 0, &l1);
    mech_kin_decay_lab(&b, 0, tb.momentum, tb.energy[1], MECH_PI / 2, 1, &l2);
    CHECK_CLOSE(l1.energy, 20000, 1e-15, 0);
    CHECK_CLOSE(l2.energy, 20000, 1e-15, 0);
    /* 2 asin(134.9768/40000), decimal: 0.00674885280791332589 */
    const double open40 = 0.0067488528079133259;
    CHECK_CLOSE(l1.angle + l2.angle, open40, 2e-15, 0);
    note(&worst_decay, l1.angle + l2.angle, open40);
    double ms[2] = {0, 0}, es[2] = {tb.energy[0], tb.energy[1]}, a, at;
    mech_kin_decay_min_opening(&b, ms, tb.momentum, es, &a, &at);
    CHECK_CLOSE(a, open40, 2e-15, 0);
    CHECK_CLOSE(at, MECH_PI / 2, 1e-6, 0); /* argmin only to ~sqrt(eps) */
    note(&worst_decay, a, open40);

    /* Ultra-relativistic: βγ = 1e6. Forward photon E*(γ + βγ), backward
     * E* / (γ + βγ) (decimal: 134976800.0000337442, 3.37441999999915640e-5),
     * minimum opening 2 asin(1/γ) = 1.99999999999933333e-6. */
    b = parent_boost(M_PI0, M_PI0 * 1e6);
    mech_kin_decay_lab(&b, 0, tb.momentum, tb.energy[0], 0.0, 0, &l1);
    mech_kin_decay_lab(&b, 0, tb.momentum, tb.energy[0], 0.0, 1, &l2);
    CHECK_CLOSE(l1.energy, 134976800.0000337442, 1e-15, 0);
    CHECK_CLOSE(l2.energy, 3.3744199999991564e-05, 4e-15, 0);
    note(&worst_decay, l2.energy, 3.3744199999991564e-05);
    CHECK_CLOSE(l2.angle, MECH_PI, 1e-16, 0);
    mech_kin_decay_min_opening(&b, ms, tb.momentum, es, &a, &at);
    CHECK_CLOSE(a, 1.9999999999993333e-06, 4e-15, 0);
    note(&worst_decay, a, 1.9999999999993333e-06);
}

/* A parent at 1e-12 c: lab kinetic energy of a daughter emitted forward is
 * T* + (βγ p* + (γ − 1)E*) to first order; checked against the exact
 * γE* + βγp* − m written with γ − 1 and βγ (no cancellation in the reference). */
static void test_slow_parent(void)
{
    double bg = 1e-12;
    struct mech_boost b = parent_boost(M_PIC, M_PIC * bg);
    CHECK_CLOSE(b.gamma_minus_one, 0.5e-24, 1e-15, 0);
    struct mech_kin_two_body tb;
    CHECK_EQ_INT(mech_kin_two_body_rest(M_PIC, M_MU, 0, &tb, NULL), MECH_OK);
    /* p* = (mπ² − mμ²)/(2mπ), decimal 29.7921409098774451730 */
    CHECK_CLOSE(tb.momentum, 29.792140909877445, 4e-16, 0);
    note(&worst_decay, tb.momentum, 29.792140909877445);
    CHECK_CLOSE(tb.energy[0], 109.77824909012255, 4e-16, 0);
    struct mech_kin_lab l;
    mech_kin_decay_lab(&b, M_MU, tb.momentum, tb.energy[0], 0.0, 0, &l);
    double gm1 = b.gamma_minus_one;
    double want = tb.kinetic[0] + gm1 * tb.energy[0] + bg * tb.momentum;
    CHECK_CLOSE(l.kinetic, want, 4e-16, 0);
    note(&worst_decay, l.kinetic, want);
    /* The muon kinetic energy at rest, T* = p*²/(E* + m): 4.11982359 MeV. */
    CHECK_CLOSE(tb.kinetic[0], 109.77824909012255 - M_MU, 1e-14, 0);
}

/* Problem 19: π⁺ (T = 500 GeV) → μ⁺ ν; neutrinos within 1e-3 rad of the beam.
 * Massless ν: E(θ) = p* mπ/((E − P) + 2P sin²(θ/2)) (decimal):
 * E(0) = 213515.606935991943 MeV, E(1e-3) = 15426.4144085652669 MeV. The
 * muon's maximum lab angle is asin((p* / mμ)/(βγ)) = 7.86864363688135e-5 rad <
 * 1e-3, so every muon is in the cone: [286623.963454008, 500139.566233060]. */
static void test_pion_beam(void)
{
    struct mech_kin_motion k;
    struct mech_boost b;
    CHECK_EQ_INT(mech_kin_motion_from_kinetic(M_PIC, 500000, &k, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_boost(&k, mech_vec3_make(1, 0, 0), &b, NULL), MECH_OK);
    CHECK_CLOSE(b.gamma, 3583.4217443255693, 1e-15, 0);
    struct mech_kin_two_body tb;
    CHECK_EQ_INT(mech_kin_two_body_rest(M_PIC, M_MU, 0, &tb, NULL), MECH_OK);
    double r[2][2], edges[2];
    int n = mech_kin_decay_cone(&b, 0, tb.momentum, tb.energy[1], 1e-3, r, edges);
    CHECK_EQ_INT(n, 1);
    CHECK_CLOSE(r[0][1], 213515.60693599194, 2e-15, 0);
    CHECK_CLOSE(r[0][0], 15426.414408565267, 1e-13, 0);
    note(&worst_decay, r[0][0], 15426.414408565267);
    note(&worst_decay, r[0][1], 213515.60693599194);
    double tmax;
    CHECK(mech_kin_decay_max_angle(&b, M_MU, tb.momentum, &tmax));
    CHECK_CLOSE(tmax, 7.8686436368813508e-05, 1e-14, 0);
    CHECK(!mech_kin_decay_max_angle(&b, 0, tb.momentum, &tmax));
    n = mech_kin_decay_cone(&b, M_MU, tb.momentum, tb.energy[0], 1e-3, r, edges);
    CHECK_EQ_INT(n, 1);
    CHECK_CLOSE(r[0][0], 286623.96345400806, 1e-14, 0);
    CHECK_CLOSE(r[0][1], 500139.56623305956, 1e-15, 0);
    /* A cone narrower than the muon's maximum angle: two energy bands whose
     * inner edges are exactly at the cone's lab angle. */
    double half = 0.5 * tmax;
    n = mech_kin_decay_cone(&b, M_MU, tb.momentum, tb.energy[0], half, r, edges);
    CHECK_EQ_INT(n, 2);
    struct mech_kin_lab l;
    mech_kin_decay_lab(&b, M_MU, tb.momentum, tb.energy[0], edges[0], 0, &l);
    CHECK_CLOSE(l.angle, half, 1e-12, 0);
    CHECK_CLOSE(l.energy, r[0][0], 1e-15, 0);
    mech_kin_decay_lab(&b, M_MU, tb.momentum, tb.energy[0], edges[1], 0, &l);
    CHECK_CLOSE(l.angle, half, 1e-12, 0);
    CHECK(r[1][1] < r[0][0] && r[1][0] < r[1][1]);
}

/* notes §3 "Neutron Decay": electron endpoint. Exact: T_max = Q(M − m_e + m_p)/(2M)
 * = 0.78158219770194928 MeV for the decimal PDG masses, below Q = 0.78233339 MeV
 * by the proton recoil; the notes' nonrelativistic-proton approximation gives
 * 0.78158197942, 2.2e-7 MeV lower. Problem 12 (120° apart): p = 0.5456259594 MeV
 * each. The references below are evaluated (60 digits) from the binary doubles
 * nearest the PDG decimals, since Q = M − Σm magnifies their 1e-16 representation
 * error 1200-fold (Q = 0.78233339000000634566... for the doubles). */
static void test_neutron(void)
{
    double m[3] = {M_P, M_E, 0};
    CHECK_CLOSE(mech_kin_q_value(M_N, m, 3), 0.78233339000000634566, 1e-16, 0);
    CHECK_CLOSE(mech_kin_q_value(M_N, m, 3), 0.78233339, 1e-14, 0);
    double e, t, p;
    CHECK_EQ_INT(mech_kin_endpoint(M_N, m, 3, 1, &e, &t, &p, NULL), MECH_OK);
    CHECK_CLOSE(t, 0.7815821977019556, 2e-16, 0);
    CHECK_CLOSE(e, 1.2925811477019555, 2e-16, 0);
    CHECK_CLOSE(p, 1.1872851790927916, 2e-16, 0);
    note(&worst_decay, t, 0.7815821977019556);
    CHECK_CLOSE(t, 0.78158219770194928, 1e-14, 0); /* the decimal-mass value */
    CHECK_EQ_INT(mech_kin_endpoint(M_N, m, 3, 0, &e, &t, &p, NULL), MECH_OK);
    CHECK_CLOSE(t, 0.0007511922980507292, 2e-16, 0);
    note(&worst_decay, t, 0.0007511922980507292);
    CHECK_EQ_INT(mech_kin_endpoint(M_N, m, 3, 2, &e, &t, &p, NULL), MECH_OK);
    CHECK_CLOSE(t, 0.782007683285096, 2e-16, 0);
    CHECK_CLOSE(p, t, 0, 0); /* massless: p = T exactly */

    double mom[3], en[3], ke[3];
    CHECK_EQ_INT(mech_kin_three_body_planar(M_N, m, 2 * MECH_PI / 3, 2 * MECH_PI / 3, mom, en, ke, NULL),
                 MECH_OK);
    for (int i = 0; i < 3; i++)
        CHECK_CLOSE(mom[i], 0.5456259593574906, 4e-15, 0);
    note(&worst_decay, mom[1], 0.5456259593574906);
    CHECK_CLOSE(ke[0], 0.00015864676468198375, 8e-15, 0);
    CHECK_CLOSE(ke[1], 0.23654878387783373, 4e-15, 0);
    note(&worst_decay, ke[1], 0.23654878387783373);
    CHECK_CLOSE(ke[0] + ke[1] + ke[2], 0.78233339000000634566, 4e-16, 0);
    /* Endpoint configuration: neutrino at rest (θ12 = 180°, θ23 = 90°):
     * the electron gets the endpoint energy. */
    CHECK_EQ_INT(mech_kin_three_body_planar(M_N, m, MECH_PI, MECH_PI / 2, mom, en, ke, NULL), MECH_OK);
    CHECK_CLOSE(ke[1], 0.7815821977019556, 4e-15, 0);
    CHECK_CLOSE(mom[2], 0, 0, 1e-15);

    /* Below threshold: a proton cannot decay into a neutron + e⁺ + ν. */
    struct mech_error err;
    mech_error_clear(&err);
    double mb[3] = {M_N, M_E, 0};
    CHECK_EQ_INT(mech_kin_endpoint(M_P, mb, 3, 1, &e, &t, &p, &err), MECH_EDOMAIN);
    CHECK(err.param[0] == 'd');
    struct mech_kin_two_body tb;
    CHECK_EQ_INT(mech_kin_two_body_rest(M_MU, M_PIC, 0, &tb, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_three_body_planar(M_N, m, MECH_PI / 3, MECH_PI / 3, mom, en, ke, NULL),
                 MECH_EDOMAIN);
    /* Exactly at threshold: everything at rest. */
    CHECK_EQ_INT(mech_kin_two_body_rest(2.0, 1.0, 1.0, &tb, NULL), MECH_OK);
    CHECK(tb.momentum == 0);
    /* Just above: p* = sqrt(Q(M + m1 + m2)(M − m1 + m2)(M + m1 − m2))/(2M)
     * with Q = 2^-40 exact: p* ≈ sqrt(2^-40 · 4 · 2 · 2)/4 = 2^-19. */
    CHECK_EQ_INT(mech_kin_two_body_rest(2.0 + ldexp(1, -40), 1.0, 1.0, &tb, NULL), MECH_OK);
    double mm = 2.0 + ldexp(1, -40);
    double pw = sqrt(ldexp(1, -40) * (mm + 2) * mm * mm) / (2 * mm);
    CHECK_CLOSE(tb.momentum, pw, 4e-16, 0);
}

/* Invariant mass: two photons at angle θ have M = 2 sqrt(E1E2) sin(θ/2),
 * exact even at θ = 1e-9 (the naive E² − p² is all round-off there). */
/* Rounding never puts a massive particle at or beyond c, nor a system below
 * rest: the LHC beam seen from a proton at rest (sqrt(s) = 14 TeV: p/E rounds
 * to 1 + 2^-52 although 1 - beta = 4e-17 is exact enough) keeps beta <= 1,
 * equal to 1 - (1 - beta) rounded; a system whose E/M rounds below 1 keeps
 * gamma = 1 + (gamma - 1) >= 1 and 1 - beta <= 1. */
static void test_bounds_under_rounding(void)
{
    const double sqrt_s = 14e6; /* MeV */
    const double e_beam = (sqrt_s * sqrt_s - 2 * M_P * M_P) / (2 * M_P);
    struct mech_kin_motion k;
    struct mech_boost b;
    CHECK_EQ_INT(mech_kin_motion_from_energy(M_P, e_beam, &k, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_boost(&k, mech_vec3_make(0, 0, 1), &b, NULL), MECH_OK);
    CHECK(b.beta <= 1.0);
    CHECK(b.beta == 1.0 - b.one_minus_beta);
    /* 1 - beta = m^2/(E(E + p)) ~ 1/(2 gamma^2) */
    CHECK_CLOSE(b.one_minus_beta, 1.0 / (2 * b.gamma * b.gamma), 1e-12, 0);
    struct mech_budget bud = mech_budget_make(1000, 3600.0);
    const double a4[4] = {1.0, 0, 0, 1.0000000000000002}, b4[4] = {2.0, 0, 0, -1.0};
    struct mech_kin_particle ps[2];
    int cl;
    CHECK_EQ_INT(mech_kin_particle_from_four(a4, &ps[0], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_particle_from_four(b4, &ps[1], &cl, NULL), MECH_OK);
    struct mech_kin_system s;
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 2, &bud, &s, NULL), MECH_OK);
    CHECK(s.gamma >= 1.0 && s.gamma == 1.0 + s.gamma_minus_one);
    CHECK(s.one_minus_beta <= 1.0 && mech_vec3_norm(s.beta) <= 1.0);
}

static void test_invariant_mass(void)
{
    struct mech_budget bud = mech_budget_make(1000, 10.0);
    double th = 1e-9, e1 = 3.0, e2 = 5.0;
    double a4[4] = {e1, e1, 0, 0}, b4[4] = {e2, e2, e2 * th, 0};
    /* the second photon's true angle is atan(1e-9) and its energy is exactly
     * |p| only to rounding: give it as mass 0 + momentum instead. */
    struct mech_kin_particle ps[2];
    int cl;
    CHECK_EQ_INT(mech_kin_particle_from_four(a4, &ps[0], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_particle_from_mass(0, mech_vec3_make(b4[1], b4[2], b4[3]), &ps[1], NULL),
                 MECH_OK);
    struct mech_kin_system s;
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 2, &bud, &s, NULL), MECH_OK);
    double ang = atan(th);
    double want = 2 * sqrt(e1 * ps[1].energy) * sin(ang / 2);
    CHECK_CLOSE(s.mass, want, 2e-15, 0);
    note(&worst_invariant, s.mass, want);
    double naive = sqrt(fmax(0, (e1 + ps[1].energy) * (e1 + ps[1].energy) - (e1 + e2) * (e1 + e2) -
                                    (e2 * th) * (e2 * th)));
    CHECK(rel(naive, want) > 1e-3); /* why the careful form matters */

    /* π⁰ → γγ back in: M of the two lab photons is m_π0 again (βγ = 1e6). */
    struct mech_boost b = parent_boost(M_PI0, M_PI0 * 1e6);
    struct mech_kin_lab l1, l2;
    mech_kin_decay_lab(&b, 0, M_PI0 / 2, M_PI0 / 2, 1.0, 0, &l1);
    mech_kin_decay_lab(&b, 0, M_PI0 / 2, M_PI0 / 2, 1.0, 1, &l2);
    CHECK_EQ_INT(
        mech_kin_particle_from_mass(
            0, mech_vec3_make(l1.momentum_transverse, 0, l1.momentum_parallel), &ps[0], NULL),
        MECH_OK);
    CHECK_EQ_INT(
        mech_kin_particle_from_mass(
            0, mech_vec3_make(l2.momentum_transverse, 0, l2.momentum_parallel), &ps[1], NULL),
        MECH_OK);
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 2, &bud, &s, NULL), MECH_OK);
    CHECK_CLOSE(s.mass, M_PI0, 1e-14, 0);
    note(&worst_invariant, s.mass, M_PI0);
    CHECK_CLOSE(s.beta_gamma, 1e6, 1e-14, 0);
    CHECK_CLOSE(s.gamma_minus_one, sqrt(1 + 1e12) - 1, 1e-14, 0);

    /* Single particle: its own mass; CM velocity = its velocity. */
    double mu4[4] = {sqrt(M_MU * M_MU + 200.0 * 200.0), 0, 200.0, 0};
    CHECK_EQ_INT(mech_kin_particle_from_four(mu4, &ps[0], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 1, &bud, &s, NULL), MECH_OK);
    CHECK_CLOSE(s.mass, M_MU, 1e-14, 0);
    CHECK_CLOSE(s.beta.y, 200.0 / mu4[0], 1e-15, 0);

    /* Light-like rounding is clamped, a truly spacelike vector is refused. */
    double ph[4] = {1.0, 0.6, 0.8, 0};
    CHECK_EQ_INT(mech_kin_particle_from_four(ph, &ps[0], &cl, NULL), MECH_OK);
    CHECK(ps[0].mass <= 2e-8);
    double sp[4] = {1.0, 1.0, 1e-4, 0};
    struct mech_error err;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kin_particle_from_four(sp, &ps[0], &cl, &err), MECH_EDOMAIN);
    CHECK(err.text[0] != 0);
    double neg[4] = {-1.0, 0, 0, 0};
    CHECK_EQ_INT(mech_kin_particle_from_four(neg, &ps[0], &cl, NULL), MECH_EDOMAIN);

    /* Two photons head-on along one line: light-like parts, M = 2 sqrt(E1E2). */
    double h1[4] = {2, 2, 0, 0}, h2[4] = {8, -8, 0, 0};
    CHECK_EQ_INT(mech_kin_particle_from_four(h1, &ps[0], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_particle_from_four(h2, &ps[1], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 2, &bud, &s, NULL), MECH_OK);
    CHECK_CLOSE(s.mass, 8.0, 1e-16, 0);
    CHECK_CLOSE(s.rapidity, 0.5 * log(16.0 / 4.0), 1e-15, 0); /* η = ½ ln((E + P)/(E − P)) */
    /* Collinear photons: light-like total, no rest frame. */
    double c1[4] = {2, 0, 0, 2}, c2[4] = {5, 0, 0, 5};
    CHECK_EQ_INT(mech_kin_particle_from_four(c1, &ps[0], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_particle_from_four(c2, &ps[1], &cl, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 2, &bud, &s, NULL), MECH_OK);
    CHECK(s.mass == 0 && !s.has_rest_frame);
}

/* Boost invariance through mech/relativity/boost.h: boost a system and recompute M. */
static void test_boost_invariance(void)
{
    struct mech_budget bud = mech_budget_make(1000, 10.0);
    const double mass[4] = {M_P, M_PIC, 0.0, M_E};
    const double mom[4][3] = {{100, -30, 250}, {-50, 20, -10}, {-10, 40, 7}, {3, 0.5, -1}};
    struct mech_kin_particle ps[4], qs[4];
    for (int i = 0; i < 4; i++)
        mech_kin_particle_from_mass(mass[i], mech_vec3_make(mom[i][0], mom[i][1], mom[i][2]),
                                    &ps[i], NULL);
    struct mech_kin_system s0, s1;
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 4, &bud, &s0, NULL), MECH_OK);
    /* Reference M² = (ΣE)² − |Σp|² in long double (no large cancellation here). */
    long double E = 0, px = 0, py = 0, pz = 0;
    for (int i = 0; i < 4; i++) {
        E += sqrtl((long double)mass[i] * mass[i] + (long double)mom[i][0] * mom[i][0] +
                   (long double)mom[i][1] * mom[i][1] + (long double)mom[i][2] * mom[i][2]);
        px += mom[i][0];
        py += mom[i][1];
        pz += mom[i][2];
    }
    double mref = (double)sqrtl(E * E - px * px - py * py - pz * pz);
    CHECK_CLOSE(s0.mass, mref, 1e-15, 0);
    note(&worst_invariant, s0.mass, mref);

    /* Boosts: β = 0.6 (4-vector input) and rapidity 14.5 (γ ≈ 1e6, mass +
     * boosted momentum input: the 4-vector form cannot carry m at γ = 1e6,
     * numerics.md — each rounded E' loses εγ²). */
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.36, -0.48, 0), &b, NULL), MECH_OK);
    for (int i = 0; i < 4; i++) {
        double x[4] = {ps[i].energy, mom[i][0], mom[i][1], mom[i][2]}, y[4];
        CHECK_EQ_INT(mech_boost_apply(&b, x, y, NULL, NULL, NULL), MECH_OK);
        int cl;
        CHECK_EQ_INT(mech_kin_particle_from_four(y, &qs[i], &cl, NULL), MECH_OK);
        if (mass[i] == 0) mech_kin_particle_from_mass(0, qs[i].momentum, &qs[i], NULL);
    }
    CHECK_EQ_INT(mech_kin_invariant_mass(qs, 4, &bud, &s1, NULL), MECH_OK);
    CHECK_CLOSE(s1.mass, s0.mass, 1e-14, 0);
    note(&worst_invariant, s1.mass, s0.mass);

    double etas[3] = {14.5, -14.5, 30.0};
    for (int k = 0; k < 3; k++) {
        CHECK_EQ_INT(mech_boost_from_rapidity(etas[k], mech_vec3_make(1, 2, 2), &b, NULL), MECH_OK);
        for (int i = 0; i < 4; i++) {
            double x[4] = {ps[i].energy, mom[i][0], mom[i][1], mom[i][2]}, y[4];
            CHECK_EQ_INT(mech_boost_apply(&b, x, y, NULL, NULL, NULL), MECH_OK);
            mech_kin_particle_from_mass(mass[i], mech_vec3_make(y[1], y[2], y[3]), &qs[i], NULL);
        }
        CHECK_EQ_INT(mech_kin_invariant_mass(qs, 4, &bud, &s1, NULL), MECH_OK);
        CHECK_CLOSE(s1.mass, s0.mass, 1e-14, 0);
        note(&worst_invariant, s1.mass, s0.mass);
    }
    /* Budget: 4 particles, 2 steps allowed. */
    struct mech_budget tiny = mech_budget_make(2, 10.0);
    struct mech_error err;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kin_invariant_mass(ps, 4, &tiny, &s1, &err), MECH_EBUDGET);
}

/* notes §3 "Compton Scattering": λ' − λ = (h/mc)(1 − cos θ). Mo Kα 70.9 pm at
 * 90°: λ' = 73.3263102386649 pm, E = 17.4871930089140 keV → 16.9085554734245
 * keV, recoil T = 578.637535489465 eV at φ = 0.768576812407528 rad (decimal). */
static void test_compton(void)
{
    double hc = mech_energy_hc(MECH_MEV);
    double e = hc / 7.09e-11;
    struct mech_kin_compton c;
    CHECK_EQ_INT(mech_kin_compton(e, M_E, MECH_PI / 2, &c, NULL), MECH_OK);
    CHECK_CLOSE(e, 0.017487193008914000, 2e-16, 0);
    CHECK_CLOSE(c.energy_out, 0.016908555473424536, 1e-15, 0);
    CHECK_CLOSE(c.recoil_kinetic, 0.00057863753548946450, 1e-15, 0);
    CHECK_CLOSE(c.recoil_angle, 0.76857681240752840, 1e-15, 0);
    CHECK_CLOSE(hc / c.energy_out, 7.3326310238664879e-11, 1e-15, 0);
    CHECK_CLOSE(hc / M_E * c.one_minus_cos, 2.4263102386648791e-12, 1e-15, 0);
    note(&worst_compton, c.energy_out, 0.016908555473424536);
    note(&worst_compton, c.recoil_kinetic, 0.00057863753548946450);
    note(&worst_compton, c.recoil_angle, 0.76857681240752840);
    /* Identities: 1/E' − 1/E = (1 − cos θ)/m; energy and momentum conserved. */
    double ths[4] = {1e-9, 0.3, 2.0, MECH_PI};
    double es[3] = {1e-6, 0.5, 5e4};
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 3; j++) {
            CHECK_EQ_INT(mech_kin_compton(es[j], M_E, ths[i], &c, NULL), MECH_OK);
            /* 1/E' − 1/E = (E − E')/(E E') = T/(E E') */
            double lhs = c.recoil_kinetic / (es[j] * c.energy_out);
            double want = 2 * sin(ths[i] / 2) * sin(ths[i] / 2) / M_E;
            CHECK_CLOSE(lhs, want, 1e-14, 0);
            CHECK_CLOSE(c.energy_out + c.recoil_kinetic, es[j], 1e-15, 0);
            /* momentum along the beam and across it */
            double pz = c.energy_out * cos(ths[i]) + c.recoil_momentum * cos(c.recoil_angle);
            double px = c.energy_out * sin(ths[i]) - c.recoil_momentum * sin(c.recoil_angle);
            CHECK_CLOSE(pz, es[j], 1e-13, 0);
            CHECK_CLOSE(px, 0, 0, 1e-13 * es[j]);
        }
    }
    /* θ = 1e-9, E = 0.5 MeV: T = E k/(1 + k), k = (E/m) 2 sin²(θ/2): tiny and exact. */
    CHECK_EQ_INT(mech_kin_compton(0.5, M_E, 1e-9, &c, NULL), MECH_OK);
    double k = 0.5 / M_E * 2 * sin(0.5e-9) * sin(0.5e-9);
    CHECK_CLOSE(c.recoil_kinetic, 0.5 * k / (1 + k), 1e-15, 0);
    CHECK(c.recoil_kinetic > 0);
    /* A proton target; errors. */
    CHECK_EQ_INT(mech_kin_compton(1.0, M_P, MECH_PI, &c, NULL), MECH_OK);
    CHECK_CLOSE(c.energy_out, 1.0 / (1 + 2.0 / M_P), 1e-15, 0);
    CHECK_EQ_INT(mech_kin_compton(1.0, 0.0, 1.0, &c, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_compton(1.0, M_E, 4.0, &c, NULL), MECH_EINVAL);
}

/* Collisions: problem 18 (LHC 14 TeV on a fixed proton), problem 10 (LEP,
 * 104 GeV each: √s = 208 GeV exactly, 1 − β = 1.2071002538030625e-11),
 * antiproton threshold T = 6 m_p = 5629.63252896 MeV. */
static void test_collisions(void)
{
    struct mech_kin_motion a, b;
    double s, d, t;
    CHECK_EQ_INT(mech_kin_fixed_target_kinetic(14e6, M_P, M_P, &t, NULL), MECH_OK);
    CHECK_CLOSE(t, 104447312752.82209, 1e-15, 0);
    note(&worst_collision, t, 104447312752.82209);
    CHECK_EQ_INT(mech_kin_motion_from_kinetic(M_P, t, &a, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_at_rest(M_P, &b, NULL), MECH_OK);
    mech_kin_collision_s(&a, &b, 2.0, &s, &d);
    CHECK_CLOSE(sqrt(s), 14e6, 1e-15, 0);
    note(&worst_collision, sqrt(s), 14e6);

    double mf[4] = {M_P, M_P, M_P, M_P};
    double w = -mech_kin_q_value(0, mf, 4);
    CHECK_EQ_INT(mech_kin_fixed_target_kinetic(w, M_P, M_P, &t, NULL), MECH_OK);
    CHECK_CLOSE(t, 6 * M_P, 1e-15, 0);
    CHECK_CLOSE(t, 5629.63252896, 1e-15, 0);

    CHECK_EQ_INT(mech_kin_motion_from_energy(M_E, 104000, &a, NULL), MECH_OK);
    b = a;
    mech_kin_collision_s(&a, &b, 2.0, &s, &d);
    CHECK_CLOSE(sqrt(s), 208000, 3e-16, 0);
    struct mech_boost bb;
    CHECK_EQ_INT(mech_kin_motion_boost(&a, mech_vec3_make(0, 0, 1), &bb, NULL), MECH_OK);
    CHECK_CLOSE(bb.one_minus_beta, 1.2071002538030625e-11, 1e-15, 0);
    note(&worst_collision, bb.one_minus_beta, 1.2071002538030625e-11);
    /* CM momentum of a fixed-target collision is P1 m2/√s exactly. */
    CHECK_EQ_INT(mech_kin_motion_from_momentum(M_PIC, 1000, &a, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_at_rest(M_P, &b, NULL), MECH_OK);
    mech_kin_collision_s(&a, &b, 2.0, &s, &d);
    CHECK_CLOSE(mech_kin_cm_momentum(sqrt(s), d, M_PIC, M_P), 1000 * M_P / sqrt(s), 1e-15, 0);
    /* Slow collisions keep s − (m1 + m2)²: two protons at 1e-12 c head-on:
     * d = 2(T1E2 + m1T2 + p1p2) with T = m(γ − 1), p = mβγ. */
    CHECK_EQ_INT(mech_kin_motion_from_momentum(M_P, M_P * 1e-12, &a, NULL), MECH_OK);
    mech_kin_collision_s(&a, &a, 2.0, &s, &d);
    double want = 2 * (2 * a.kinetic * M_P + 2 * a.kinetic * a.kinetic + a.momentum * a.momentum);
    CHECK_CLOSE(d, want, 1e-15, 0);
    CHECK_CLOSE(d, 4 * M_P * M_P * 1e-24, 1e-12, 0);
    /* Co-moving (same direction): d from 2 m1 m2 sinh²(Δη/2). */
    CHECK_EQ_INT(mech_kin_motion_from_momentum(M_P, 2 * M_P, &a, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_from_momentum(M_P, 3 * M_P, &b, NULL), MECH_OK);
    mech_kin_collision_s(&a, &b, 0.0, &s, &d);
    double de = asinh(2.0) - asinh(3.0);
    CHECK_CLOSE(d, 4 * M_P * M_P * sinh(de / 2) * sinh(de / 2), 1e-14, 0);
    /* Co-moving with nearly equal velocities: d = 2(E1E2 - p1p2 - m1m2),
     * E = sqrt(m^2 + p^2), by Python's decimal at 80 digits from the same doubles (the
     * direct form loses ~12 of the 80 digits here). The old rapidity difference
     * asinh(p1/m1) - asinh(p2/m2) was off by 2.2e-5 relative at p2 = p1 (1 + 2^-40) and
     * by 3e-10 at p2 = p1 (1 + 1e-6). */
    {
        static const struct {
            double m1, p1, m2, p2, d;
        } co[] = {
            {M_P, 1000.0, M_P, 1000.001, 4.6818514160311871e-07},
            {M_P, 1000.0, M_P, 1000.0000000009095, 3.8727387819544282e-19},
            {M_P, 1876.54417632, 139.57039, 279.1407802791408, 1.0476402080115861e-13},
            {M_P, 1000000.0, M_P, 1000001.0, 8.803528560446622e-07},
        };
        for (size_t i = 0; i < sizeof co / sizeof co[0]; i++) {
            CHECK_EQ_INT(mech_kin_motion_from_momentum(co[i].m1, co[i].p1, &a, NULL), MECH_OK);
            CHECK_EQ_INT(mech_kin_motion_from_momentum(co[i].m2, co[i].p2, &b, NULL), MECH_OK);
            mech_kin_collision_s(&a, &b, 0.0, &s, &d);
            CHECK_CLOSE(d, co[i].d, 1e-14, 0);
            mech_kin_collision_s(&b, &a, 0.0, &s, &d); /* symmetric in the two */
            CHECK_CLOSE(d, co[i].d, 1e-14, 0);
        }
        /* the same velocity: exactly at threshold */
        CHECK_EQ_INT(mech_kin_motion_from_momentum(M_P, 1000.0, &a, NULL), MECH_OK);
        mech_kin_collision_s(&a, &a, 0.0, &s, &d);
        CHECK(d == 0.0);
    }
    /* Errors */
    CHECK_EQ_INT(mech_kin_fixed_target_kinetic(1000, M_P, M_P, &t, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_fixed_target_kinetic(1000, M_P, 0, &t, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_motion_from_energy(M_P, 900, &a, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_motion_from_kinetic(-1, 900, &a, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_motion_from_momentum(0, 0, &a, NULL), MECH_EDOMAIN);
    CHECK_EQ_INT(mech_kin_motion_at_rest(0, &a, NULL), MECH_EDOMAIN);
}

/* p_a − p_b of nearly equal beams (the CM velocity of nearly
 * symmetric head-on beams): expected values by Python's decimal at 80 digits
 * from the same doubles, sqrt(E² − m²), sqrt(T² + 2mT) or p for each beam, then
 * subtracted (the direct form loses at most 14 of the 80 digits here). The
 * difference of the two rounded momenta is off by up to ε p/|p_a − p_b|:
 * 1e-9 for 7 TeV beams 1 part in 1e7 apart, 1e-3 at 1 + 2^-40. */
static void test_momentum_difference(void)
{
    enum { E, T, P };
    static const struct {
        double ma;
        int fa;
        double xa, mb;
        int fb;
        double xb, want;
    } cs[] = {
        {M_P, E, 7e6, M_P, E, 7000000.7, -7.00000006474510439e-01},
        {M_P, E, 7e6, M_P, E, 7000000.0000063665, -6.36652117726320363e-06},
        {M_P, T, 1000.0, M_P, T, 1000.0001, -1.14282363680820622e-04},
        {M_P, T, 1e-3, M_P, T, 1.000000001e-3, -6.84935610182744775e-10},
        /* LEP's 104 GeV electron by E against one by T: p differs by 5e-17 relative */
        {M_E, E, 104000.0, M_E, T, 103999.48900105, 5.15976150700769833e-12},
        {M_P, E, 1000.0, M_PIC, P, 345.0, 8.98089876011422983e-01},
        {M_P, P, 1000.0, M_P, P, 1000.0000001, -9.99999656414729543e-08},
        /* scaled by a power of two: E², and p_a + p_b for the second, would overflow */
        {1e307, P, 1e308, 1e307, P, 9e307, 9.999999999999996e+306}, /* exact difference */
        {1e200, E, 3e200, 1e200, E, 3.0000000030000002e+200, -3.18198082846005358e+191},
    };
    double worst = 0;
    for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        struct mech_kin_motion k[2];
        for (int j = 0; j < 2; j++) {
            double m = j ? cs[i].mb : cs[i].ma, x = j ? cs[i].xb : cs[i].xa;
            int f = j ? cs[i].fb : cs[i].fa;
            enum mech_status st = f == E   ? mech_kin_motion_from_energy(m, x, &k[j], NULL)
                                  : f == T ? mech_kin_motion_from_kinetic(m, x, &k[j], NULL)
                                           : mech_kin_motion_from_momentum(m, x, &k[j], NULL);
            CHECK_EQ_INT(st, MECH_OK);
        }
        double d = mech_kin_momentum_difference(&k[0], &k[1]);
        CHECK_CLOSE(d, cs[i].want, 1e-14, 0);
        CHECK_CLOSE(mech_kin_momentum_difference(&k[1], &k[0]), -cs[i].want, 1e-14, 0);
        if (rel(d, cs[i].want) > worst) worst = rel(d, cs[i].want);
    }
    printf("momentum difference: worst relative error %.3g\n", worst);
    /* At rest: 0, and p_a against a particle at rest. */
    struct mech_kin_motion a, b;
    CHECK_EQ_INT(mech_kin_motion_at_rest(M_P, &a, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_motion_at_rest(M_E, &b, NULL), MECH_OK);
    CHECK_EQ_INT(mech_kin_momentum_difference(&a, &b) == 0.0, 1);
    CHECK_EQ_INT(mech_kin_motion_from_energy(M_E, 104000, &b, NULL), MECH_OK);
    /* sqrt(104000² − m_e²) by decimal at 80 digits */
    CHECK_CLOSE(mech_kin_momentum_difference(&b, &a), 1.03999999998744621e+05, 1e-15, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_pi0();
    test_slow_parent();
    test_pion_beam();
    test_neutron();
    test_invariant_mass();
    test_boost_invariance();
    test_compton();
    test_collisions();
    test_momentum_difference();
    test_bounds_under_rounding();
    printf("worst relative errors: invariant mass %.3g, decays %.3g, Compton %.3g, "
           "collisions %.3g\n",
           worst_invariant, worst_decay, worst_compton, worst_collision);
    TEST_MAIN_END();
}
