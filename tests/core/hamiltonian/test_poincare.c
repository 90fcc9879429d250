/* test_poincare.c — Poincaré sections of mech/hamiltonian/poincare.h: Hénon–Heiles
 * crossings on x = 0 (on the section, on the energy surface, and the same
 * points from an independent adaptive method), the spherical pendulum's
 * conical motion (every crossing of phi = 0 at theta0, p_theta = 0, at
 * t_k = 2 pi k / phi'), Kepler pericentres one period apart and 2 pi apart,
 * power-law apsidal angles pi / sqrt(n + 2), typed errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/hamiltonian/poincare.h"
#include "mech/base/constants.h"
#include "testlib.h"

enum { MAXC = 400 };

struct pc_out {
    double t[MAXC], u[MAXC], v[MAXC], y[4 * MAXC];
    struct mech_poincare_result r;
    struct mech_error e;
    enum mech_status st;
};

static void run(const struct mech_ham_system *s, struct mech_poincare_section sec, const double *y0,
                double t_max, size_t n, const char *method, double dt, double rtol,
                struct pc_out *o, long max_steps)
{
    memset(o, 0, sizeof *o);
    struct mech_poincare_problem p = {s, sec, y0, t_max, n, mech_ode_method_find(method),
                                      {rtol, rtol, dt}};
    o->r.t = o->t;
    o->r.u = o->u;
    o->r.v = o->v;
    o->r.y = o->y;
    mech_error_clear(&o->e);
    struct mech_budget b = mech_budget_make(max_steps, 120.0);
    o->st = mech_poincare_run(&p, &b, &o->r, &o->e);
}

static void test_henon_heiles(void)
{
    struct mech_ham_system s = {.kind = MECH_HAM_HENON_HEILES};
    const struct mech_poincare_section sec = {0, 0.0, 0};
    const double E = 1.0 / 12.0;
    double y0[4];
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_poincare_start(&s, &sec, E, 0.1, 0.05, 1, y0, &e), MECH_OK);
    CHECK(y0[0] == 0.0 && y0[2] > 0.0);
    CHECK_CLOSE(0.5 * (y0[2] * y0[2] + 0.05 * 0.05) + 0.5 * 0.01 - 0.001 / 3.0, E, 1e-15, 0);
    static struct pc_out a, b;
    run(&s, sec, y0, 1e4, 200, "gauss6", 0.02, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_OK);
    CHECK_EQ_INT(a.r.n_crossings, 200);
    CHECK(a.r.complete);
    CHECK(a.r.max_section_residual < 1e-12); /* t located to a few ulp: |x'| 4 ulp(t) */
    fprintf(stderr, "HH residual %.3g, energy drift %.3g\n", a.r.max_section_residual, a.r.energy.max_rel);
    CHECK(a.r.energy.max_rel < 1e-10);
    int ok = 1;
    for (size_t k = 0; k < a.r.n_crossings; k++) {
        const double *y = a.y + 4 * k;
        const double H = 0.5 * (y[2] * y[2] + y[3] * y[3]) + 0.5 * (y[0] * y[0] + y[1] * y[1]) +
                         y[0] * y[0] * y[1] - y[1] * y[1] * y[1] / 3.0;
        if (!(y[2] > 0.0 && fabs(H - E) < 1e-11 && a.u[k] == y[1] && a.v[k] == y[3])) ok = 0;
        if (k > 0 && !(a.t[k] > a.t[k - 1])) ok = 0;
    }
    CHECK(ok);
    /* the same crossings from an independent adaptive method (rk8pd, rtol 1e-13) */
    run(&s, sec, y0, 1e4, 20, "rk8pd", 0, 1e-13, &b, 10000000);
    CHECK_EQ_INT(b.st, MECH_OK);
    for (size_t k = 0; k < 20; k++) {
        CHECK_CLOSE(b.t[k], a.t[k], 1e-9, 0);
        CHECK_CLOSE(b.u[k], a.u[k], 0, 1e-9);
        CHECK_CLOSE(b.v[k], a.v[k], 0, 1e-9);
    }
    /* E below the potential at the start: V(0, 0.5) = 0.125 - 0.125/3 > 0.01 */
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_poincare_start(&s, &sec, 0.01, 0.5, 0.0, 1, y0, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "energy"));
    /* t_max first: not complete, still OK */
    mech_poincare_start(&s, &sec, E, 0.1, 0.05, 1, y0, &e);
    run(&s, sec, y0, 30.0, 200, "gauss6", 0.02, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_OK);
    CHECK(!a.r.complete);
    CHECK(a.r.n_crossings >= 3 && a.r.n_crossings < 10);
    CHECK_CLOSE(a.r.t_reached, 30.0, 1e-15, 0);
    /* budget: stops with the crossings so far */
    run(&s, sec, y0, 1e4, 200, "gauss6", 0.02, 0, &a, 3000);
    CHECK_EQ_INT(a.st, MECH_EBUDGET);
    CHECK(a.r.n_crossings > 0 && a.r.n_crossings < 200);
    fprintf(stderr, "budget: %zu crossings, %s\n", a.r.n_crossings, a.e.text);
    /* yoshida works on this separable H */
    run(&s, sec, y0, 1e4, 50, "yoshida6", 0.02, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_OK);
    CHECK(a.r.second_order);
    CHECK(a.r.energy.max_rel < 1e-8);
}

static void test_spherical_pendulum(void)
{
    struct mech_ham_system s = {.kind = MECH_HAM_SPHERICAL_PENDULUM, .mass = 1.0, .length = 1.0,
                                .g = 9.81};
    const double th0 = 0.5, w = sqrt(9.81 / cos(th0));
    const double y0[4] = {th0, 0.3, 0.0, sin(th0) * sin(th0) * w};
    const struct mech_poincare_section sec = {1, 0.0, 1}; /* phi = 0 mod 2 pi */
    static struct pc_out a;
    run(&s, sec, y0, 1e3, 30, "gauss6", 1e-3, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_OK);
    CHECK_EQ_INT(a.r.n_crossings, 30);
    for (size_t k = 0; k < 30; k++) {
        CHECK_CLOSE(a.t[k], (2.0 * MECH_PI * (double)(k + 1) - 0.3) / w, 1e-12, 0);
        CHECK_CLOSE(a.u[k], th0, 0, 1e-12);
        CHECK_CLOSE(a.v[k], 0.0, 0, 1e-12);
    }
    CHECK(a.r.conserved_drift[0].max_abs == 0.0);
    /* retrograde rotation: phi decreasing, same section */
    const double y1[4] = {th0, 0.3, 0.0, -y0[3]};
    run(&s, sec, y1, 1e3, 5, "gauss6", 1e-3, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_OK);
    CHECK_CLOSE(a.t[0], 0.3 / w, 1e-12, 0);
    /* p_phi = 0: the section is never crossed */
    const double y2[4] = {th0, 0.3, 0.1, 0.0};
    run(&s, sec, y2, 1e3, 5, "gauss6", 1e-3, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_EDOMAIN);
    /* not separable */
    run(&s, sec, y0, 1e3, 5, "verlet", 1e-3, 0, &a, 10000000);
    CHECK_EQ_INT(a.st, MECH_EINVAL);
    CHECK(!strcmp(a.e.param, "integrator/method"));
}

static void test_apsides(void)
{
    /* Kepler, K = -1, m = 1: r0 = 1, p_phi = 1.1 > circular: pericentre at the start.
     * E = p_phi^2/2 - 1, a = -K/(2E) = 1/(2|E|), T = 2 pi sqrt(a^3 m / |K|). */
    struct mech_ham_system s = {.kind = MECH_HAM_CENTRAL, .mass = 1.0, .strength = -1.0,
                                .power = -1.0};
    const double y0[4] = {1.0, 0.0, 0.0, 1.1};
    const double E = 0.5 * 1.21 - 1.0, a = 1.0 / (2.0 * fabs(E)), T = 2.0 * MECH_PI * sqrt(a * a * a);
    const struct mech_poincare_section peri = {2, 0.0, 0}; /* p_r = 0 rising: pericentre */
    static struct pc_out o;
    run(&s, peri, y0, 1e4, 10, "gauss6", T / 2000, 0, &o, 10000000);
    CHECK_EQ_INT(o.st, MECH_OK);
    for (size_t k = 0; k < 10; k++) {
        CHECK_CLOSE(o.t[k], T * (double)(k + 1), 1e-11, 0);
        CHECK_CLOSE(o.y[4 * k + 1], 2.0 * MECH_PI * (double)(k + 1), 1e-11, 0);
        CHECK_CLOSE(o.y[4 * k], 1.0, 1e-11, 0);
    }
    /* near-circular power laws: pericentre to pericentre 2 pi / sqrt(n + 2) (Goldstein §3.6) */
    const double ns[] = {2.0, 1.0, -1.5, 0.5};
    for (int i = 0; i < 4; i++) {
        const double n = ns[i], K = n > 0 ? 1.0 : -1.0, r0 = 1.0;
        struct mech_ham_system c = {.kind = MECH_HAM_CENTRAL, .mass = 1.0, .strength = K,
                                    .power = n};
        const double pc = sqrt(K * n * pow(r0, n + 2.0));
        const double y[4] = {r0, 0.0, 1e-5, pc}; /* a small radial kick: e ~ 1e-5 */
        const double Tphi = 2.0 * MECH_PI * r0 * r0 / pc;
        run(&c, peri, y, 1e4, 3, "gauss6", Tphi / 2000, 0, &o, 10000000);
        CHECK_EQ_INT(o.st, MECH_OK);
        const double dphi = (o.y[4 * 2 + 1] - o.y[4 * 0 + 1]) / 2.0;
        CHECK_CLOSE(dphi / 2.0, MECH_PI / sqrt(n + 2.0), 1e-8, 0);
        fprintf(stderr, "n = %g: apsidal angle %.15g, pi/sqrt(n+2) = %.15g\n", n, dphi / 2.0,
                MECH_PI / sqrt(n + 2.0));
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    test_henon_heiles();
    test_spherical_pendulum();
    test_apsides();
    TEST_MAIN_END();
}
