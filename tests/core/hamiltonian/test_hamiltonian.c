/* test_hamiltonian.c — the catalog of mech/hamiltonian/hamiltonian.h and its flow against
 * closed forms: oscillator, pendulum period (complete elliptic integral),
 * spherical pendulum's conical motion, the cylinder, circular Kepler and
 * power-law orbits (also at solar-system scale); the variational equations
 * against central differences; typed errors at the singularities; the
 * second-order form's grouping of coordinates into points for radau15. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/hamiltonian/hamiltonian.h"
#include "mech/base/constants.h"
#include "testlib.h"

static struct mech_budget budget(void)
{
    return mech_budget_make(50000000, 120.0);
}

/* Run a flow; returns the status, fills y_end (q, p) and the result. */
static enum mech_status run(const struct mech_ham_system *s, const double *y0, double t_end,
                            const char *method, double dt, double *y_end,
                            struct mech_ham_flow_result *r, struct mech_error *e)
{
    struct mech_ham_system chk = *s;
    mech_ham_system_check(&chk, NULL);
    const size_t dim = 2u * (size_t)chk.dof, ns = 11;
    double t[11], y[11 * MECH_HAM_MAX_DIM];
    struct mech_ham_flow_problem p = {s, y0, t_end, ns, mech_ode_method_find(method), {0, 0, dt}};
    memset(r, 0, sizeof *r);
    r->t = t;
    r->y = y;
    mech_error_clear(e);
    struct mech_budget b = budget();
    enum mech_status st = mech_ham_flow(&p, &b, r, e);
    if (st == MECH_OK && y_end) memcpy(y_end, y + (ns - 1) * dim, dim * sizeof *y);
    return st;
}

static void test_oscillator(void)
{
    struct mech_ham_system s = {.kind = MECH_HAM_OSCILLATOR, .dof = 1, .mass = 2.0, .k = {8.0}};
    const double w = 2.0, q0 = 0.3, p0 = 0.4, T = 10 * MECH_PI; /* 10 periods */
    const double y0[2] = {q0, p0};
    const char *methods[] = {"gauss6", "yoshida6", "gauss4"};
    const double dts[] = {0.01, 0.01, 0.002};
    for (int m = 0; m < 3; m++) {
        double y[2];
        struct mech_ham_flow_result r;
        struct mech_error e;
        CHECK_EQ_INT(run(&s, y0, T, methods[m], dts[m], y, &r, &e), MECH_OK);
        const double qx = q0 * cos(w * T) + p0 / (2.0 * w) * sin(w * T);
        const double px = -2.0 * w * q0 * sin(w * T) + p0 * cos(w * T);
        CHECK_CLOSE(y[0], qx, 0, 1e-10);
        CHECK_CLOSE(y[1], px, 0, 1e-10);
        CHECK_CLOSE(r.energy.initial, p0 * p0 / 4.0 + 4.0 * q0 * q0, 1e-15, 0);
        CHECK(r.energy.max_rel < 1e-11);
        CHECK_EQ_INT(r.second_order, m == 1);
        CHECK_EQ_INT(r.n_conserved, 0);
    }
    /* anisotropic 2D has no L_z; isotropic 2D conserves it */
    struct mech_ham_system s2 = {.kind = MECH_HAM_OSCILLATOR, .dof = 2, .mass = 1.0, .k = {1.0, 1.0}};
    const double y2[4] = {1.0, 0.0, 0.0, 0.5};
    struct mech_ham_flow_result r;
    struct mech_error e;
    double y[4];
    CHECK_EQ_INT(run(&s2, y2, 20.0, "gauss6", 0.01, y, &r, &e), MECH_OK);
    CHECK_EQ_INT(r.n_conserved, 1);
    CHECK(!strcmp(r.conserved[0].name, "L_z"));
    CHECK_CLOSE(r.conserved_drift[0].initial, 0.5, 1e-15, 0);
    CHECK(r.conserved_drift[0].max_rel < 1e-13);
    s2.k[1] = 4.0;
    CHECK_EQ_INT(run(&s2, y2, 20.0, "verlet", 0.01, y, &r, &e), MECH_OK);
    CHECK_EQ_INT(r.n_conserved, 0);
    CHECK_CLOSE(y[0], cos(20.0), 0, 1e-3); /* verlet: second order */
}

static void test_pendulum_period(void)
{
    /* T = 4 sqrt(l/g) K(k), k = sin(theta0/2) (Taylor §4.5) */
    struct mech_ham_system s = {.kind = MECH_HAM_PENDULUM, .mass = 1.0, .length = 2.0, .g = 9.81};
    const double th0 = 1.0;
    const double T = 4.0 * sqrt(2.0 / 9.81) * gsl_sf_ellint_Kcomp(sin(th0 / 2), GSL_PREC_DOUBLE);
    const double y0[2] = {th0, 0.0};
    double y[2];
    struct mech_ham_flow_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&s, y0, T, "gauss6", T / 1000, y, &r, &e), MECH_OK);
    CHECK_CLOSE(y[0], th0, 0, 1e-11);
    CHECK_CLOSE(y[1], 0.0, 0, 1e-10);
    /* E = m g l (1 - cos theta0), positive: relative drift defined */
    CHECK_CLOSE(r.energy.initial, 9.81 * 2.0 * (1.0 - cos(th0)), 1e-14, 0);
    CHECK(r.energy.max_rel < 1e-12);
    CHECK_EQ_INT(run(&s, y0, T, "yoshida6", T / 1000, y, &r, &e), MECH_OK);
    CHECK_CLOSE(y[0], th0, 0, 1e-10);
}

static void test_spherical_conical(void)
{
    /* theta'' = 0 needs p_phi^2 cos/(M sin^3) = m g l sin: phi' = sqrt(g / (l cos theta0)) */
    struct mech_ham_system s = {.kind = MECH_HAM_SPHERICAL_PENDULUM, .mass = 1.5, .length = 0.8,
                                .g = 9.81};
    const double th0 = 0.7, M = 1.5 * 0.64, wphi = sqrt(9.81 / (0.8 * cos(th0)));
    const double y0[4] = {th0, 0.0, 0.0, M * sin(th0) * sin(th0) * wphi};
    double y[4];
    struct mech_ham_flow_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&s, y0, 5.0, "gauss6", 1e-3, y, &r, &e), MECH_OK);
    CHECK_CLOSE(y[0], th0, 0, 1e-12);
    CHECK_CLOSE(y[1], wphi * 5.0, 1e-12, 0);
    CHECK_CLOSE(y[2], 0.0, 0, 1e-12);
    CHECK_EQ_INT(r.n_conserved, 1);
    CHECK(r.conserved[0].cyclic);
    CHECK(r.conserved_drift[0].max_abs == 0.0); /* p_phi' = 0 exactly */
    CHECK(r.energy.max_rel < 1e-13);
    /* second-order methods need a separable H */
    CHECK_EQ_INT(run(&s, y0, 5.0, "yoshida4", 1e-3, y, &r, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "integrator/method"));
    /* the pole with p_phi != 0: infinite energy */
    const double bad[4] = {0.0, 0.0, 0.0, 0.1};
    CHECK_EQ_INT(run(&s, bad, 1.0, "gauss6", 1e-3, y, &r, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "p/1"));
}

static void test_cylinder(void)
{
    /* z'' = -(k/m) z, phi' = p_phi / (m R^2) */
    struct mech_ham_system s = {.kind = MECH_HAM_CYLINDER, .mass = 0.5, .radius = 0.3,
                                .strength = 2.0};
    const double w = 2.0, z0 = 0.1, pz0 = -0.2, pphi = 0.09, T = 7.0;
    const double y0[4] = {z0, 0.25, pz0, pphi};
    const char *methods[] = {"gauss6", "yoshida6"};
    for (int m = 0; m < 2; m++) {
        double y[4];
        struct mech_ham_flow_result r;
        struct mech_error e;
        CHECK_EQ_INT(run(&s, y0, T, methods[m], 1e-3, y, &r, &e), MECH_OK);
        CHECK_CLOSE(y[0], z0 * cos(w * T) + pz0 / (0.5 * w) * sin(w * T), 0, 1e-12);
        CHECK_CLOSE(y[1], 0.25 + pphi / (0.5 * 0.09) * T, 1e-13, 0);
        CHECK_CLOSE(y[3], pphi, 1e-15, 0);
        CHECK(r.conserved_drift[0].max_rel < 1e-14);
        CHECK_CLOSE(r.energy.initial,
                    pz0 * pz0 / 1.0 + pphi * pphi / (2 * 0.5 * 0.09) + 1.0 * (0.09 + z0 * z0),
                    1e-14, 0);
    }
}

static void test_central(void)
{
    /* circular orbit: p_phi^2 = m K n r0^(n+2), period 2 pi m r0^2 / p_phi */
    const double ns[] = {-1.0, 2.0, 1.0, -1.5};
    for (int i = 0; i < 4; i++) {
        const double n = ns[i], K = n > 0 ? 0.7 : -0.7, m = 1.3, r0 = 2.0;
        struct mech_ham_system s = {.kind = MECH_HAM_CENTRAL, .mass = m, .strength = K, .power = n};
        const double pphi = sqrt(m * K * n * pow(r0, n + 2.0));
        const double T = 2.0 * MECH_PI * m * r0 * r0 / pphi;
        const double y0[4] = {r0, 0.0, 0.0, pphi};
        double y[4];
        struct mech_ham_flow_result r;
        struct mech_error e;
        CHECK_EQ_INT(run(&s, y0, T, "gauss6", T / 2000, y, &r, &e), MECH_OK);
        CHECK_CLOSE(y[0], r0, 1e-12, 0);
        CHECK_CLOSE(y[1], 2.0 * MECH_PI, 1e-12, 0);
        CHECK(r.conserved_drift[0].max_abs == 0.0);
    }
    /* Earth around the Sun, SI: one sidereal year for a circular 1 au orbit */
    const double GM = MECH_SUN_GM, me = MECH_EARTH_MASS, au = MECH_AU;
    struct mech_ham_system s = {.kind = MECH_HAM_CENTRAL, .mass = me, .strength = -GM * me,
                                .power = -1.0};
    const double pphi = me * sqrt(GM * au), T = 2.0 * MECH_PI * sqrt(au * au * au / GM);
    const double y0[4] = {au, 0.0, 0.0, pphi};
    double y[4];
    struct mech_ham_flow_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&s, y0, T, "gauss6", T / 1000, y, &r, &e), MECH_OK);
    CHECK_CLOSE(y[0], au, 1e-12, 0);
    CHECK_CLOSE(y[1], 2.0 * MECH_PI, 1e-12, 0);
    CHECK(r.energy.max_rel < 1e-13);
    CHECK(isfinite(mech_ham_time_scale(&s, y0)));
    /* r <= 0 at the start: a domain error; a radial fall: a typed numerical error */
    const double y_bad[4] = {0.0, 0.0, 0.0, 1.0};
    s = (struct mech_ham_system){.kind = MECH_HAM_CENTRAL, .mass = 1, .strength = -1, .power = -1};
    CHECK_EQ_INT(run(&s, y_bad, 1.0, "gauss6", 1e-3, y, &r, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "q/0"));
    const double y_fall[4] = {1.0, 0.0, 0.0, 0.0};
    CHECK_EQ_INT(run(&s, y_fall, 10.0, "gauss6", 1e-2, y, &r, &e), MECH_ENUMERIC);
    CHECK_EQ_INT(run(&s, y_fall, 10.0, "rk8pd", 0, y, &r, &e) != MECH_OK, 1);
    /* parameters */
    s.power = 0.0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_ham_system_check(&s, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "system/n"));
}

static void test_potential_3d_and_hh(void)
{
    /* Kepler 3D (power -1): an inclined circular orbit keeps L and closes after T */
    struct mech_ham_system s = {.kind = MECH_HAM_POTENTIAL_3D, .mass = 1.0,
                                .potential = MECH_HAM_POT_POWER, .strength = -1.0, .power = -1.0};
    const double c = cos(0.4), sn = sin(0.4);
    const double y0[6] = {1.0, 0.0, 0.0, 0.0, c, sn};
    double y[6];
    struct mech_ham_flow_result r;
    struct mech_error e;
    CHECK_EQ_INT(run(&s, y0, 2.0 * MECH_PI, "yoshida6", 2.0 * MECH_PI / 4000, y, &r, &e), MECH_OK);
    for (int i = 0; i < 6; i++) CHECK_CLOSE(y[i], y0[i], 0, 1e-10);
    CHECK_EQ_INT(r.n_conserved, 3);
    CHECK(r.conserved_drift[2].max_rel < 1e-13);
    /* anisotropic harmonic: each axis on its own */
    s = (struct mech_ham_system){.kind = MECH_HAM_POTENTIAL_3D, .mass = 2.0,
                                 .potential = MECH_HAM_POT_HARMONIC, .k = {2.0, 8.0, 18.0}};
    const double z0[6] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.0};
    CHECK_EQ_INT(run(&s, z0, 3.0, "gauss6", 1e-3, y, &r, &e), MECH_OK);
    CHECK_CLOSE(y[0], cos(3.0), 0, 1e-12);
    CHECK_CLOSE(y[1], cos(6.0), 0, 1e-12);
    CHECK_CLOSE(y[2], cos(9.0), 0, 1e-12);
    CHECK_EQ_INT(r.n_conserved, 0);
    /* Hénon–Heiles at E = 1/8: energy kept by the symplectic method */
    s = (struct mech_ham_system){.kind = MECH_HAM_HENON_HEILES};
    const double h0[4] = {0.0, 0.1, 0.45, 0.05};
    CHECK_EQ_INT(run(&s, h0, 200.0, "gauss6", 0.02, y, &r, &e), MECH_OK);
    CHECK_CLOSE(r.energy.initial, 0.5 * (0.45 * 0.45 + 0.05 * 0.05) + 0.005 - 0.001 / 3.0, 1e-15,
                0);
    CHECK(r.energy.max_rel < 1e-11);
}

/* The variational equations against central differences of Hamilton's equations. */
static void test_tangent(void)
{
    struct mech_ham_system ss[] = {
        {.kind = MECH_HAM_OSCILLATOR, .dof = 2, .mass = 1.3, .k = {2.0, 3.0}},
        {.kind = MECH_HAM_PENDULUM, .mass = 1.1, .length = 0.7, .g = 9.8},
        {.kind = MECH_HAM_SPHERICAL_PENDULUM, .mass = 1.1, .length = 0.7, .g = 9.8},
        {.kind = MECH_HAM_CYLINDER, .mass = 1.1, .radius = 0.7, .strength = 2.0},
        {.kind = MECH_HAM_CENTRAL, .mass = 1.1, .strength = -2.0, .power = -1.3},
        {.kind = MECH_HAM_HENON_HEILES},
        {.kind = MECH_HAM_POTENTIAL_3D, .mass = 1.1, .potential = MECH_HAM_POT_POWER,
         .strength = 0.4, .power = 2.5},
        {.kind = MECH_HAM_POTENTIAL_3D, .mass = 1.1, .potential = MECH_HAM_POT_HARMONIC,
         .k = {1, 2, 3}},
    };
    const double y[6] = {0.9, 0.4, -0.3, 0.35, -0.2, 0.6};
    const double v[6] = {0.3, -0.7, 0.5, 0.2, 0.9, -0.4};
    for (size_t k = 0; k < sizeof ss / sizeof ss[0]; k++) {
        struct mech_ham_system *s = &ss[k];
        CHECK_EQ_INT(mech_ham_system_check(s, NULL), MECH_OK);
        const size_t dim = mech_ham_dim(s);
        double yy[6], f[6], dv[6], fp[6], fm[6], yp[6], ym[6];
        memcpy(yy, y, sizeof yy);
        CHECK_EQ_INT(mech_ham_rhs(s, yy, f, v, dv, NULL), MECH_OK);
        const double h = 1e-5;
        for (size_t i = 0; i < dim; i++) {
            yp[i] = yy[i] + h * v[i];
            ym[i] = yy[i] - h * v[i];
        }
        CHECK_EQ_INT(mech_ham_rhs(s, yp, fp, NULL, NULL, NULL), MECH_OK);
        CHECK_EQ_INT(mech_ham_rhs(s, ym, fm, NULL, NULL, NULL), MECH_OK);
        for (size_t i = 0; i < dim; i++) CHECK_CLOSE(dv[i], (fp[i] - fm[i]) / (2 * h), 1e-8, 1e-8);
        /* Hamilton's equations against central differences of H */
        for (size_t i = 0; i < dim; i++) {
            double a[6], b[6], Ea, Eb;
            memcpy(a, yy, sizeof a);
            memcpy(b, yy, sizeof b);
            a[i] += h;
            b[i] -= h;
            mech_ham_energy(s, a, &Ea, NULL);
            mech_ham_energy(s, b, &Eb, NULL);
            const double dH = (Ea - Eb) / (2 * h);
            const size_t n = dim / 2;
            const double want = i < n ? -f[n + i] : f[i - n];
            CHECK_CLOSE(dH, want, 1e-8, 1e-9);
        }
    }
}

/* The second-order form tells radau15 which coordinates are one point
 * (mech_ode_system.particle_dim): x, y (, z) of the 2-D oscillator,
 * Hénon–Heiles and potential_3d as one vector, so its step control sees |a|
 * and not a coordinate passing through 0; the pendulum's angle and the
 * cylinder's (z, phi), of different units, each on its own. */
static void test_radau15_grouping(void)
{
    const struct {
        struct mech_ham_system s;
        size_t want;
    } cases[] = {
        {{.kind = MECH_HAM_OSCILLATOR, .dof = 2, .mass = 1.0, .k = {1.0, 1.0}}, 2},
        {{.kind = MECH_HAM_OSCILLATOR, .dof = 1, .mass = 1.0, .k = {1.0}}, 1},
        {{.kind = MECH_HAM_HENON_HEILES}, 2},
        {{.kind = MECH_HAM_POTENTIAL_3D, .mass = 1.0, .potential = MECH_HAM_POT_HARMONIC,
          .k = {1.0, 1.0, 1.0}},
         3},
        {{.kind = MECH_HAM_PENDULUM, .mass = 1.0, .length = 1.0, .g = 9.8}, 1},
        {{.kind = MECH_HAM_CYLINDER, .mass = 1.0, .radius = 1.0, .strength = 1.0}, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        struct mech_ham_system s = cases[i].s;
        CHECK_EQ_INT(mech_ham_system_check(&s, NULL), MECH_OK);
        struct mech_ham_ensemble e;
        struct mech_ode_system ode;
        CHECK_EQ_INT(mech_ham_ensemble_init(&e, &s, 2, 1, mech_ode_method_find("radau15"), &ode,
                                            NULL),
                     MECH_OK);
        CHECK_EQ_INT((long)ode.particle_dim, (long)cases[i].want);
        CHECK((ode.dim / 2) % ode.particle_dim == 0);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    test_oscillator();
    test_pendulum_period();
    test_spherical_conical();
    test_cylinder();
    test_central();
    test_potential_3d_and_hh();
    test_tangent();
    test_radau15_grouping();
    TEST_MAIN_END();
}
