/* test_coupled_oscillations.c — core/hamiltonian/coupled_oscillations.c
 * against closed forms and a second method: the chain of equal masses between
 * walls (w_j = 2 sqrt(k/m) sin(j pi/(2(N + 1))), modes sin(i j pi/(N + 1))),
 * the free chain (a zero mode, w_j = 2 sqrt(k/m) sin(j pi/(2N))), the double
 * pendulum (roots of det(K - w^2 M) = 0), coupled pendulums (g/l and
 * g/l + 2k/m), the ring of three (a degenerate pair whose basis the rule
 * fixes), mass-orthonormality, extreme scales, an unstable K, the motion as a
 * sum of modes against a Runge-Kutta integration of M q'' = -K q with
 * energy conservation, and the errors. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/hamiltonian/coupled_oscillations.h"
#include "testlib.h"

#define NM MECH_COUPLED_MAX_DOF

static double mm[NM * NM], kk[NM * NM];

static double mdot(size_t n, const double *m, const double *x, const double *y)
{
    double s = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) s += x[i] * m[i * n + j] * y[j];
    return s;
}

/* v_a^T M v_b = delta_ab and v_a^T K v_b = w_a^2 delta_ab */
static void check_orthonormal(const struct mech_coupled_modes *r, const double *m,
                              const double *k, double tol)
{
    size_t n = r->n;
    double top = 0;
    for (size_t a = 0; a < n; a++) top = fmax(top, fabs(r->omega2[a]));
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            CHECK_CLOSE(mdot(n, m, r->vectors[a], r->vectors[b]), a == b, 0, tol);
            CHECK_CLOSE(mdot(n, k, r->vectors[a], r->vectors[b]), a == b ? r->omega2[a] : 0, 0,
                        tol * top);
        }
}

static void test_chain_between_walls(void)
{
    struct mech_coupled_modes *r = malloc(sizeof *r);
    struct mech_error e;
    mech_error_clear(&e);
    const size_t sizes[] = {1, 2, 3, 5, 10, 64};
    for (int t = 0; t < 6; t++) {
        size_t n = sizes[t];
        double masses[NM], springs[NM + 1], m = 0.25, k = 40;
        for (size_t i = 0; i < n; i++) masses[i] = m;
        for (size_t i = 0; i <= n; i++) springs[i] = k;
        CHECK(mech_coupled_chain(n, masses, springs, n + 1, 1, 1, mm, kk, &e) == MECH_OK);
        CHECK(mech_coupled_modes(n, mm, kk, r, &e) == MECH_OK);
        CHECK(!r->degenerate && r->zero_modes == 0 && r->stable);
        for (size_t j = 1; j <= n; j++) {
            double w = 2 * sqrt(k / m) * sin(j * MECH_PI / (2.0 * (n + 1)));
            CHECK_CLOSE(r->omega[j - 1], w, 2e-14 * (n > 10 ? 10 : 1), 0);
            /* shape: v_i = sqrt(2/(m (n+1))) sin(i j pi/(n+1)) up to the sign rule */
            double amp = sqrt(2 / (m * (n + 1))), sgn = 0, top = 0;
            for (size_t i = 0; i < n; i++) {
                double want = amp * sin((i + 1.0) * j * MECH_PI / (n + 1));
                if (fabs(want) > top) {
                    top = fabs(want);
                    sgn = (r->vectors[j - 1][i] * want > 0) ? 1 : -1;
                }
            }
            for (size_t i = 0; i < n; i++) {
                double want = amp * sin((i + 1.0) * j * MECH_PI / (n + 1));
                CHECK_CLOSE(r->vectors[j - 1][i], sgn * want, 0, 1e-12 * amp * n);
            }
        }
        check_orthonormal(r, mm, kk, 1e-13 * n);
    }
    free(r);
}

static void test_free_chain(void)
{
    struct mech_coupled_modes *r = malloc(sizeof *r);
    struct mech_error e;
    mech_error_clear(&e);
    for (size_t n = 2; n <= 8; n++) {
        double masses[NM], springs[NM], m = 3, k = 7;
        for (size_t i = 0; i < n; i++) masses[i] = m;
        for (size_t i = 0; i + 1 < n; i++) springs[i] = k;
        CHECK(mech_coupled_chain(n, masses, springs, n - 1, 0, 0, mm, kk, &e) == MECH_OK);
        CHECK(mech_coupled_modes(n, mm, kk, r, &e) == MECH_OK);
        CHECK_EQ_INT(r->zero_modes, 1);
        CHECK(r->kind[0] == MECH_MODE_ZERO && r->omega2[0] == 0 && r->omega[0] == 0);
        CHECK(r->stable && !r->degenerate);
        for (size_t i = 0; i < n; i++)
            CHECK_CLOSE(r->vectors[0][i], 1 / sqrt(n * m), 1e-14, 0); /* translation */
        for (size_t j = 1; j < n; j++)
            CHECK_CLOSE(r->omega[j], 2 * sqrt(k / m) * sin(j * MECH_PI / (2.0 * n)), 1e-14, 0);
    }
    free(r);
}

static void test_double_pendulum(void)
{
    struct mech_coupled_modes r;
    struct mech_error e;
    mech_error_clear(&e);
    double m[4], k[4];
    /* equal bobs and rods: w^2 = (g/l)(2 -+ sqrt 2) */
    CHECK(mech_coupled_double_pendulum(1, 1, 1, 1, 9.81, m, k, &e) == MECH_OK);
    CHECK(mech_coupled_modes(2, m, k, &r, &e) == MECH_OK);
    CHECK_CLOSE(r.omega2[0], 9.81 * (2 - sqrt(2.0)), 1e-15, 0);
    CHECK_CLOSE(r.omega2[1], 9.81 * (2 + sqrt(2.0)), 1e-15, 0);
    /* slow mode in phase: theta2/theta1 = sqrt 2; fast: -sqrt 2 */
    CHECK_CLOSE(r.vectors[0][1] / r.vectors[0][0], sqrt(2.0), 1e-14, 0);
    CHECK_CLOSE(r.vectors[1][1] / r.vectors[1][0], -sqrt(2.0), 1e-14, 0);
    /* general: det(K - w^2 M) = a w^4 - b w^2 + c, roots by the stable formula */
    const double cases[][5] = {{2, 0.5, 1.5, 0.7, 9.80665}, {0.1, 10, 3, 0.2, 1.62},
                               {5, 5e-3, 1, 1, 9.81}, {1e-300, 1e-300, 1e3, 1e-3, 9.81}};
    for (int t = 0; t < 4; t++) {
        const double *p = cases[t];
        CHECK(mech_coupled_double_pendulum(p[0], p[1], p[2], p[3], p[4], m, k, &e) == MECH_OK);
        CHECK(mech_coupled_modes(2, m, k, &r, &e) == MECH_OK);
        /* divide by m2 l1^2 l2^2 (exact in the ratios): mu = m1/m2 */
        double mu = p[0] / p[1], g = p[4], l1 = p[2], l2 = p[3];
        double a = mu, b = (mu + 1) * g * (1 / l1 + 1 / l2), c = (mu + 1) * g * g / (l1 * l2);
        double big = (b + sqrt(b * b - 4 * a * c)) / (2 * a), small = c / (a * big);
        CHECK_CLOSE(r.omega2[0], small, 1e-13, 0);
        CHECK_CLOSE(r.omega2[1], big, 1e-13, 0);
        check_orthonormal(&r, m, k, 1e-13);
    }
}

static void test_coupled_pendulums(void)
{
    struct mech_coupled_modes r;
    struct mech_error e;
    mech_error_clear(&e);
    double m[4], k[4];
    double mass = 0.3, l = 0.8, s = 2.5, g = 9.80665;
    CHECK(mech_coupled_pendulums(mass, l, s, l, g, m, k, &e) == MECH_OK);
    CHECK(mech_coupled_modes(2, m, k, &r, &e) == MECH_OK);
    CHECK_CLOSE(r.omega2[0], g / l, 1e-15, 0);
    CHECK_CLOSE(r.omega2[1], g / l + 2 * s / mass, 1e-15, 0);
    double v = 1 / sqrt(2 * mass * l * l);
    CHECK_CLOSE(r.vectors[0][0], v, 1e-15, 0);
    CHECK_CLOSE(r.vectors[0][1], v, 1e-15, 0);
    CHECK_CLOSE(r.vectors[1][0], v, 1e-15, 0); /* sign rule: first of the tie positive */
    CHECK_CLOSE(r.vectors[1][1], -v, 1e-15, 0);
    /* spring half-way down: 2 s a^2/(m l^2) */
    CHECK(mech_coupled_pendulums(mass, l, s, l / 2, g, m, k, &e) == MECH_OK);
    CHECK(mech_coupled_modes(2, m, k, &r, &e) == MECH_OK);
    CHECK_CLOSE(r.omega2[1], g / l + s / (2 * mass), 1e-15, 0);
    /* no spring: degenerate, the basis the coordinates themselves */
    CHECK(mech_coupled_pendulums(mass, l, 0, l, g, m, k, &e) == MECH_OK);
    CHECK(mech_coupled_modes(2, m, k, &r, &e) == MECH_OK);
    CHECK(r.degenerate && r.degenerate_mode[0] && r.degenerate_mode[1]);
    CHECK_CLOSE(r.vectors[0][0], 1 / (l * sqrt(mass)), 1e-15, 0);
    CHECK_CLOSE(r.vectors[0][1], 0, 0, 1e-15);
    CHECK_CLOSE(r.vectors[1][1], 1 / (l * sqrt(mass)), 1e-15, 0);
    CHECK_CLOSE(r.vectors[1][0], 0, 0, 1e-15);
}

/* Three equal masses on a ring, equal springs: a zero mode (rotation) and a
 * degenerate pair at w^2 = 3k/m. The rule picks e_0's projection
 * (2, -1, -1)/sqrt(6 m), then (0, 1, -1)/sqrt(2 m). */
static void test_ring_degenerate(void)
{
    struct mech_coupled_modes r;
    struct mech_error e;
    mech_error_clear(&e);
    double m = 2, s = 5;
    double mr[9] = {m, 0, 0, 0, m, 0, 0, 0, m};
    double kr[9] = {2 * s, -s, -s, -s, 2 * s, -s, -s, -s, 2 * s};
    CHECK(mech_coupled_modes(3, mr, kr, &r, &e) == MECH_OK);
    CHECK_EQ_INT(r.zero_modes, 1);
    CHECK(r.degenerate && !r.degenerate_mode[0] && r.degenerate_mode[1] && r.degenerate_mode[2]);
    CHECK_CLOSE(r.omega2[1], 3 * s / m, 1e-15, 0);
    CHECK_CLOSE(r.omega2[2], 3 * s / m, 1e-15, 0);
    double a = 1 / sqrt(6 * m), b = 1 / sqrt(2 * m);
    CHECK_CLOSE(r.vectors[1][0], 2 * a, 1e-14, 0);
    CHECK_CLOSE(r.vectors[1][1], -a, 1e-14, 0);
    CHECK_CLOSE(r.vectors[1][2], -a, 1e-14, 0);
    CHECK_CLOSE(r.vectors[2][0], 0, 0, 1e-14);
    CHECK_CLOSE(r.vectors[2][1], b, 1e-14, 0);
    CHECK_CLOSE(r.vectors[2][2], -b, 1e-14, 0);
    check_orthonormal(&r, mr, kr, 1e-14);
    /* a perturbation below the degeneracy tolerance turns the solver's basis
     * of the pair anywhere; the rule gives the same vectors */
    double kr2[9] = {2 * s * (1 + 3e-14), -s, -s, -s, 2 * s, -s, -s, -s, 2 * s * (1 - 2e-14)};
    CHECK(mech_coupled_modes(3, mr, kr2, &r, &e) == MECH_OK);
    CHECK(r.degenerate_mode[1] && r.degenerate_mode[2]);
    CHECK_CLOSE(r.vectors[1][0], 2 * a, 1e-12, 0);
    CHECK_CLOSE(r.vectors[2][1], b, 1e-12, 0);
    CHECK_CLOSE(r.vectors[2][2], -b, 1e-12, 0);
}

static void test_extremes_and_unstable(void)
{
    struct mech_coupled_modes r;
    struct mech_error e;
    mech_error_clear(&e);
    /* tiny and huge scales: two masses 1e-300 kg joined by 1e-290 N/m springs to
     * walls: w^2 = k/m (1, 3 for the chain of two) */
    const double scales[][2] = {{1e-300, 1e-290}, {1e30, 1e40}, {1e100, 1e-100}};
    for (int t = 0; t < 3; t++) {
        double m = scales[t][0], k = scales[t][1];
        double masses[2] = {m, m}, springs[3] = {k, k, k}, ms[4], ks[4];
        CHECK(mech_coupled_chain(2, masses, springs, 3, 1, 1, ms, ks, &e) == MECH_OK);
        CHECK(mech_coupled_modes(2, ms, ks, &r, &e) == MECH_OK);
        CHECK_CLOSE(r.omega2[0], k / m, 1e-15, 0);
        CHECK_CLOSE(r.omega2[1], 3 * k / m, 1e-15, 0);
        CHECK_CLOSE(r.vectors[0][0], 1 / sqrt(2 * m), 1e-15, 0);
    }
    /* inverted pendulum pair: K = -diag(1, 4), M = 1: growth rates 2 and 1 */
    double m1[4] = {1, 0, 0, 1}, k1[4] = {-1, 0, 0, -4};
    CHECK(mech_coupled_modes(2, m1, k1, &r, &e) == MECH_OK);
    CHECK(!r.stable && r.kind[0] == MECH_MODE_UNSTABLE && r.kind[1] == MECH_MODE_UNSTABLE);
    CHECK_CLOSE(r.growth[0], 2, 1e-15, 0);
    CHECK_CLOSE(r.growth[1], 1, 1e-15, 0);
    double a[2], b[2], q[2], qd[2], q0[2] = {0.1, 0.2}, v0[2] = {0, 0.3};
    mech_coupled_project(&r, m1, q0, v0, a, b, NULL);
    CHECK(mech_coupled_at(&r, a, b, 2.0, q, qd, &e) == MECH_OK);
    CHECK_CLOSE(q[0], 0.1 * cosh(2.0), 1e-14, 0);
    CHECK_CLOSE(q[1], 0.2 * cosh(4.0) + 0.3 * sinh(4.0) / 2, 1e-14, 0);
    CHECK_CLOSE(qd[1], 0.4 * sinh(4.0) + 0.3 * cosh(4.0), 1e-14, 0);
    CHECK(mech_coupled_at(&r, a, b, 1e3, q, qd, &e) == MECH_ENUMERIC);
    CHECK(!strcmp(e.param, "initial/times"));
}

struct sys {
    size_t n;
    const double *minv_k; /* M^-1 K, n x n */
};

static int rhs(double t, const double y[], double f[], void *p)
{
    (void)t;
    const struct sys *s = p;
    size_t n = s->n;
    for (size_t i = 0; i < n; i++) {
        f[i] = y[n + i];
        double acc = 0;
        for (size_t j = 0; j < n; j++) acc -= s->minv_k[i * n + j] * y[j];
        f[n + i] = acc;
    }
    return GSL_SUCCESS;
}

/* Unequal chain with one wall (a 3 x 3 problem with a dense M^-1 K): the modal
 * sum against rk8pd at rtol 1e-13, and the modal energies summing to the
 * total. M is diagonal here, so M^-1 K is exact row scaling. */
static void test_motion_against_integration(void)
{
    struct mech_coupled_modes r;
    struct mech_error e;
    mech_error_clear(&e);
    const size_t n = 3;
    double masses[3] = {1.0, 2.5, 0.7}, springs[3] = {30, 12, 45}, m[9], k[9], mk[9];
    CHECK(mech_coupled_chain(n, masses, springs, 3, 1, 0, m, k, &e) == MECH_OK);
    CHECK(mech_coupled_modes(n, m, k, &r, &e) == MECH_OK);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) mk[i * n + j] = k[i * n + j] / masses[i];
    double q0[3] = {0.01, -0.02, 0.05}, v0[3] = {0.3, 0, -0.1}, a[3], b[3], en[3];
    mech_coupled_project(&r, m, q0, v0, a, b, en);
    double total = 0.5 * (mdot(n, m, v0, v0) + mdot(n, k, q0, q0));
    CHECK_CLOSE(en[0] + en[1] + en[2], total, 1e-14, 0);
    double q[3], qd[3];
    CHECK(mech_coupled_at(&r, a, b, 0, q, qd, &e) == MECH_OK);
    for (size_t i = 0; i < n; i++) {
        CHECK_CLOSE(q[i], q0[i], 1e-14, 1e-16);
        CHECK_CLOSE(qd[i], v0[i], 1e-14, 1e-16);
    }
    struct sys s = {n, mk};
    gsl_odeiv2_system sysd = {rhs, NULL, 2 * n, &s};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sysd, gsl_odeiv2_step_rk8pd, 1e-3, 1e-14, 1e-14);
    gsl_odeiv2_driver_set_nmax(d, 1000000);
    double y[6] = {q0[0], q0[1], q0[2], v0[0], v0[1], v0[2]}, t = 0;
    for (int step = 1; step <= 5; step++) {
        double t1 = 2.0 * step;
        CHECK(gsl_odeiv2_driver_apply(d, &t, t1, y) == GSL_SUCCESS);
        CHECK(mech_coupled_at(&r, a, b, t1, q, qd, &e) == MECH_OK);
        for (size_t i = 0; i < n; i++) {
            CHECK_CLOSE(q[i], y[i], 0, 1e-10);
            CHECK_CLOSE(qd[i], y[n + i], 0, 1e-9);
        }
        CHECK_CLOSE(0.5 * (mdot(n, m, qd, qd) + mdot(n, k, q, q)), total, 1e-13, 0);
    }
    gsl_odeiv2_driver_free(d);
    /* a free chain: the zero mode drifts at the centre-of-mass velocity */
    double fm[4], fk[4], fs[1] = {4}, fmass[2] = {1, 3};
    CHECK(mech_coupled_chain(2, fmass, fs, 1, 0, 0, fm, fk, &e) == MECH_OK);
    CHECK(mech_coupled_modes(2, fm, fk, &r, &e) == MECH_OK);
    double fq0[2] = {0, 0}, fv0[2] = {1, 0}, fa[2], fb[2], fq[2];
    mech_coupled_project(&r, fm, fq0, fv0, fa, fb, NULL);
    double w = sqrt(4 * (1 + 1.0 / 3)), tt = 1.7;
    CHECK(mech_coupled_at(&r, fa, fb, tt, fq, NULL, &e) == MECH_OK);
    /* centre of mass moves at 1/4; the relative coordinate x1 - x0 = -(1/w) sin w t */
    CHECK_CLOSE((fq[0] + 3 * fq[1]) / 4, tt / 4, 1e-14, 0);
    CHECK_CLOSE(fq[1] - fq[0], -sin(w * tt) / w, 1e-14, 1e-16);
}

static void test_errors(void)
{
    struct mech_coupled_modes r;
    struct mech_error e;
    double m[4] = {1, 0, 0, 1}, k[4] = {2, -1, -1.5, 2};
    mech_error_clear(&e);
    CHECK(mech_coupled_modes(2, m, k, &r, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "stiffness_matrix/1/0"));
    double mbad[4] = {1, 2, 2, 1}, kok[4] = {1, 0, 0, 1};
    mech_error_clear(&e);
    CHECK(mech_coupled_modes(2, mbad, kok, &r, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "mass_matrix"));
    double msing[4] = {1, 1, 1, 1};
    mech_error_clear(&e);
    CHECK(mech_coupled_modes(2, msing, kok, &r, &e) == MECH_EDOMAIN);
    double mnan[4] = {1, 0, 0, NAN};
    mech_error_clear(&e);
    CHECK(mech_coupled_modes(2, mnan, kok, &r, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "mass_matrix/1/1"));
    mech_error_clear(&e);
    CHECK(mech_coupled_modes(0, m, k, &r, &e) == MECH_EINVAL);
    mech_error_clear(&e);
    CHECK(mech_coupled_modes(NM + 1, m, k, &r, &e) == MECH_EINVAL);
    double masses[2] = {1, 1}, springs[3] = {1, 1, 1};
    mech_error_clear(&e);
    CHECK(mech_coupled_chain(2, masses, springs, 2, 1, 1, mm, kk, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "springs"));
    springs[1] = 0;
    mech_error_clear(&e);
    CHECK(mech_coupled_chain(2, masses, springs, 3, 1, 1, mm, kk, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "springs/1"));
    mech_error_clear(&e);
    CHECK(mech_coupled_double_pendulum(1, 1, 0, 1, 9.8, m, k, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "l1"));
    mech_error_clear(&e);
    CHECK(mech_coupled_pendulums(1, 1, 1, 1.5, 9.8, m, k, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "attach"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_chain_between_walls();
    test_free_chain();
    test_double_pendulum();
    test_coupled_pendulums();
    test_ring_degenerate();
    test_extremes_and_unstable();
    test_motion_against_integration();
    test_errors();
    TEST_MAIN_END();
}
