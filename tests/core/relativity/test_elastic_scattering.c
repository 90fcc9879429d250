/* test_elastic_scattering.c — relativistic elastic scattering off a target at
 * rest (core/relativity/elastic_scattering.c) against closed forms and conservation:
 * four-momentum conservation (kinetic energies too, at 1e-12 of the rest
 * energy), s and t recomputed from the outgoing lab momenta, the
 * non-relativistic equal-mass 90° opening angle and its relativistic form
 * tan θ3 tan θ4 = 2/(γ1 + 1), the notes' problem 16 (equal masses:
 * T3 = T cos²θ/(1 + T sin²θ/(2m))), Compton as m1 = 0 beside
 * mech_kin_compton, the energy-independent maximum lab angle sin θmax = m2/m1
 * of a heavy projectile, round trips through the three angle kinds, γ = 1e6,
 * and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/relativity/elastic_scattering.h"
#include "mech/relativity/kinematics.h"
#include "testlib.h"

static const double MP = 938.27208816, ME = 0.51099895;

static struct mech_kin_motion moving(double m, double t)
{
    struct mech_kin_motion k;
    mech_kin_motion_from_kinetic(m, t, &k, NULL);
    return k;
}

/* E, p conservation and the invariants recomputed from the outgoing momenta. */
static void check_conservation(const struct mech_kin_motion *in, double m2,
                               const struct mech_elastic *o, double rtol)
{
    const struct mech_kin_lab *a = &o->projectile, *b = &o->recoil;
    CHECK_CLOSE(a->kinetic + b->kinetic, in->kinetic, rtol, 0);
    CHECK_CLOSE(a->energy + b->energy, in->energy + m2, rtol, 0);
    CHECK_CLOSE(a->momentum_parallel + b->momentum_parallel, in->momentum, rtol, 0);
    CHECK_CLOSE(a->momentum_transverse + b->momentum_transverse, 0, 0, rtol * in->momentum);
    /* s = m1² + m2² + 2(E3 E4 − p3·p4), from the lab outgoing pair. */
    struct mech_kin_particle p3, p4;
    mech_kin_particle_from_mass(in->mass, mech_vec3_make(a->momentum_transverse, 0, a->momentum_parallel), &p3, NULL);
    mech_kin_particle_from_mass(m2, mech_vec3_make(b->momentum_transverse, 0, b->momentum_parallel), &p4, NULL);
    const double s_out = in->mass * in->mass + m2 * m2 + 2 * mech_kin_pair_product(&p3, &p4);
    CHECK_CLOSE(s_out, o->s, rtol, 0);
    CHECK_CLOSE(o->s, in->mass * in->mass + m2 * m2 + 2 * m2 * in->energy, 1e-15, 0);
    /* t from the target side: (p2 − p4)² = −2 m2 T4. */
    CHECK_CLOSE(o->t, -2 * m2 * b->kinetic, rtol, 0);
    /* s + t + u = 2 m1² + 2 m2². */
    CHECK_CLOSE(o->s + o->t + o->u, 2 * in->mass * in->mass + 2 * m2 * m2, rtol,
                rtol * o->s);
}

static void test_equal_masses(void)
{
    struct mech_elastic o;
    /* Non-relativistic limit: T = 1e-9 m, the opening angle is 90° to O(T/m). */
    struct mech_kin_motion k = moving(MP, 1e-9 * MP);
    for (double th = 10; th < 180; th += 40) {
        CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, th * MECH_PI / 180, 0, &o, NULL),
                     MECH_OK);
        CHECK_CLOSE(o.opening_angle, MECH_PI / 2, 1e-9, 0);
        CHECK_CLOSE(o.projectile.angle, th * MECH_PI / 360, 1e-9, 0); /* θ3 = θ* / 2 */
        check_conservation(&k, MP, &o, 1e-13);
    }
    /* Relativistic: tan θ3 tan θ4 = 2/(γ1 + 1) (γ_cm² = (γ1 + 1)/2): T = 1 GeV, 10 GeV. */
    for (double t = 1000; t <= 1e4; t *= 10) {
        k = moving(MP, t);
        const double g1 = 1 + t / MP;
        for (double th = 15; th < 180; th += 30) {
            CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, th * MECH_PI / 180, 0, &o, NULL),
                         MECH_OK);
            CHECK_CLOSE(tan(o.projectile.angle) * tan(o.recoil.angle), 2 / (g1 + 1), 1e-13, 0);
            CHECK(o.opening_angle < MECH_PI / 2);
            check_conservation(&k, MP, &o, 1e-13);
        }
    }
    /* Notes problem 16: equal masses, projectile's lab angle θ, T3 = T cos²θ/(1 + T sin²θ/(2m)). */
    const double t = 500, th3[] = {1e-6, 0.1, 0.5236, 1.0, 1.5};
    k = moving(MP, t);
    for (size_t i = 0; i < 5; i++) {
        CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_LAB_ANGLE, th3[i], 0, &o, NULL), MECH_OK);
        const double c = cos(th3[i]), s = sin(th3[i]);
        CHECK_CLOSE(o.projectile.kinetic, t * c * c / (1 + t * s * s / (2 * MP)), 1e-13, 0);
        CHECK_CLOSE(o.projectile.angle, th3[i], 1e-13, 0);
        CHECK_EQ_INT(o.n_solutions, 1);
    }
    /* Equal masses: no lab angle of 90° or more. */
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_LAB_ANGLE, MECH_PI / 2, 0, &o, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "angle"));
    /* Equal masses: T1 = 2p*²/m and T4 = 2p*² sin²(θ* / 2)/m, so T3 = T1 cos²(θ* / 2)
     * exactly; near θ* = π that is T1 − T4 with T4 ≈ T1 (2.5e-17 T1 left at
     * θ* = π − 1e-8): it must come from cos²(θ* / 2), not the difference. */
    for (double d = 1e-4; d >= 1e-12; d *= 1e-4) {
        const double th = MECH_PI - d;
        CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, th, 0, &o, NULL), MECH_OK);
        const double c = cos(th / 2);
        CHECK_CLOSE(o.projectile.kinetic, t * c * c, 1e-12, 0);
    }
    /* Head-on (θ* = π): the projectile stops, the target takes all of T. */
    CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, MECH_PI, 0, &o, NULL), MECH_OK);
    CHECK_CLOSE(o.recoil.kinetic, t, 1e-15, 0);
    CHECK_CLOSE(o.projectile.kinetic, 0, 0, 1e-28);
    CHECK_CLOSE(o.recoil.angle, 0, 0, 1e-15);
}

static void test_compton_limit(void)
{
    /* m1 = 0: a photon of 1 MeV off an electron, against mech_kin_compton. */
    struct mech_kin_motion k;
    mech_kin_motion_from_energy(0, 1.0, &k, NULL);
    const double angles[] = {1e-8, 0.3, MECH_PI / 2, 2.5, MECH_PI};
    for (size_t i = 0; i < 5; i++) {
        struct mech_elastic o;
        struct mech_kin_compton c;
        CHECK_EQ_INT(mech_elastic_scatter(&k, ME, MECH_ELASTIC_LAB_ANGLE, angles[i], 0, &o, NULL),
                     MECH_OK);
        CHECK_EQ_INT(mech_kin_compton(1.0, ME, angles[i], &c, NULL), MECH_OK);
        CHECK_CLOSE(o.projectile.energy, c.energy_out, 1e-14, 0);
        CHECK_CLOSE(o.recoil.kinetic, c.recoil_kinetic, 1e-13, 0);
        CHECK_CLOSE(o.recoil.momentum, c.recoil_momentum, 1e-13, 0);
        if (angles[i] > 0 && angles[i] < MECH_PI) CHECK_CLOSE(o.recoil.angle, c.recoil_angle, 1e-13, 0);
        check_conservation(&k, ME, &o, 1e-13);
    }
}

static void test_heavy_projectile(void)
{
    /* A proton on an electron at rest: sin θmax = m2/m1 at every energy
     * (γ_cm² (g² − 1) = (m1² − m2²)/m2²), two CM solutions below it. */
    const double ts[] = {1e-6, 100, 1e5};
    for (size_t i = 0; i < 3; i++) {
        struct mech_kin_motion k = moving(MP, ts[i]);
        struct mech_elastic o, o2;
        CHECK_EQ_INT(mech_elastic_scatter(&k, ME, MECH_ELASTIC_CM_ANGLE, 1.0, 0, &o, NULL), MECH_OK);
        CHECK(o.has_max_angle);
        CHECK_CLOSE(o.max_angle, asin(ME / MP), 1e-13, 0);
        check_conservation(&k, ME, &o, 1e-12);
        const double th = 0.5 * asin(ME / MP);
        CHECK_EQ_INT(mech_elastic_scatter(&k, ME, MECH_ELASTIC_LAB_ANGLE, th, 0, &o, NULL), MECH_OK);
        CHECK_EQ_INT(mech_elastic_scatter(&k, ME, MECH_ELASTIC_LAB_ANGLE, th, 1, &o2, NULL), MECH_OK);
        CHECK_EQ_INT(o.n_solutions, 2);
        CHECK(o.cm_angle_solutions[0] < o.cm_angle_solutions[1]);
        CHECK_CLOSE(o.projectile.angle, th, 1e-12, 0);
        CHECK_CLOSE(o2.projectile.angle, th, 1e-12, 0);
        CHECK(o.projectile.energy > o2.projectile.energy);
        struct mech_error e;
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_elastic_scatter(&k, ME, MECH_ELASTIC_LAB_ANGLE, 2 * asin(ME / MP), 0, &o, &e),
                     MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "angle"));
    }
}

static void test_round_trips_and_extremes(void)
{
    /* Light projectile (g < 1): alpha on gold-ish, electron on proton; γ = 1e6. */
    struct { double m1, m2, t; } sc[] = {{3727.379, 183473.0, 5.0}, {ME, MP, 1e-7}, {ME, MP, 1e6 * ME},
                                          {MP, 2 * MP, 1e-12 * MP}};
    for (size_t i = 0; i < 4; i++) {
        struct mech_kin_motion k = moving(sc[i].m1, sc[i].t);
        for (double th = 0.05; th < MECH_PI; th += 0.5) {
            struct mech_elastic o, back, rec;
            CHECK_EQ_INT(mech_elastic_scatter(&k, sc[i].m2, MECH_ELASTIC_CM_ANGLE, th, 0, &o, NULL), MECH_OK);
            check_conservation(&k, sc[i].m2, &o, 2e-12);
            CHECK_EQ_INT(mech_elastic_scatter(&k, sc[i].m2, MECH_ELASTIC_LAB_ANGLE, o.projectile.angle,
                                              0, &back, NULL),
                         MECH_OK);
            CHECK_CLOSE(back.cm_angle, th, 1e-10, 0);
            CHECK_EQ_INT(mech_elastic_scatter(&k, sc[i].m2, MECH_ELASTIC_RECOIL_ANGLE, o.recoil.angle, 0,
                                              &rec, NULL),
                         MECH_OK);
            CHECK_CLOSE(rec.cm_angle, th, 1e-12, 0);
            /* NR reference for the recoil: T4 = T1 4 m1 m2/(m1 + m2)² sin²(θ* / 2). */
            if (sc[i].t < 1e-6 * sc[i].m1) {
                const double m1 = sc[i].m1, m2 = sc[i].m2, sh = sin(th / 2);
                CHECK_CLOSE(o.recoil.kinetic, sc[i].t * 4 * m1 * m2 / ((m1 + m2) * (m1 + m2)) * sh * sh,
                            1e-6, 0);
            }
        }
    }
    /* Grazing: θ* = 1e-10 keeps T4 = 2p*² sin²(θ* / 2)/m2 to round-off. */
    struct mech_kin_motion k = moving(MP, 1000);
    struct mech_elastic o;
    CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, 1e-10, 0, &o, NULL), MECH_OK);
    CHECK_CLOSE(o.recoil.kinetic, 2 * o.cm_momentum * o.cm_momentum * 0.25e-20 / MP, 1e-14, 0);
    CHECK_CLOSE(o.recoil.momentum_parallel, 2 * o.cm.gamma * o.cm_momentum * 0.25e-20, 1e-14, 0);
    /* Huge and tiny units: energies 1e55 and 1e-250 scale. */
    k = moving(1e50, 1e55);
    CHECK_EQ_INT(mech_elastic_scatter(&k, 3e50, MECH_ELASTIC_CM_ANGLE, 1.0, 0, &o, NULL), MECH_OK);
    k = moving(1e-250, 1e-251);
    CHECK_EQ_INT(mech_elastic_scatter(&k, 3e-250, MECH_ELASTIC_CM_ANGLE, 1.0, 0, &o, NULL), MECH_OK);
    CHECK(o.recoil.kinetic > 0);
}

static void test_errors(void)
{
    struct mech_kin_motion k = moving(MP, 10), rest = moving(MP, 0);
    struct mech_elastic o;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_scatter(&k, 0, MECH_ELASTIC_CM_ANGLE, 1, 0, &o, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "target"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_scatter(&rest, MP, MECH_ELASTIC_CM_ANGLE, 1, 0, &o, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "projectile"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, NAN, 0, &o, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "angle"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_RECOIL_ANGLE, MECH_PI / 2, 0, &o, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "angle"));
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_elastic_scatter(&k, MP, MECH_ELASTIC_CM_ANGLE, 1, 2, &o, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "branch"));
    CHECK_EQ_INT(mech_elastic_scatter(NULL, MP, MECH_ELASTIC_CM_ANGLE, 1, 0, &o, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_equal_masses();
    test_compton_limit();
    test_heavy_projectile();
    test_round_trips_and_extremes();
    test_errors();
    TEST_MAIN_END();
}
