/* test_charged_motion.c — the exact motion of a charge in uniform fields
 * (core/relativity/charged_motion.c) against independent forms:
 *  - the helix in B: radius |u|/Omega = gamma m v/(q B), lab period
 *    2 pi gamma/Omega = 2 pi gamma m/(q B), proper time t/gamma, at
 *    beta = 1e-6, 0.8 and gamma = 1e6 (a proton in 1 T);
 *  - motion in E alone: u(t) = u0 + eps t exactly, r_par = (c^2/a)(gamma - gamma0)
 *    (with gamma - gamma0 = (u^2 - u0^2)/c^2/(gamma + gamma0)), r_perp from
 *    the asinh integral of u_perp/gamma, tau = (c/a) asinh(a t/c) from rest;
 *  - the E x B drift from rest: at lab time 2 pi gamma_w^3/Omega back at rest,
 *    displaced by w t, w = E/B; halfway, the speed 2w/(1 + w^2/c^2);
 *  - crossed fields with |E| > c|B|, parallel fields and a general field:
 *    the equation of motion du/dt = eps + v x Omega and dr/dt = v checked by
 *    central differences, dtau/dt = 1/gamma, lab and proper time agreeing;
 *  - null fields refused. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/relativity/charged_motion.h"
#include "mech/base/constants.h"
#include "testlib.h"

#define QP 1.602176634e-19     /* C, exact SI */
#define MP 1.67262192369e-27   /* kg, CODATA 2018 */

static const double c = MECH_C;

static struct mech_vec3 V(double x, double y, double z) { return mech_vec3_make(x, y, z); }

static struct mech_charged_motion_state at_t(const struct mech_charged_motion *m, double t)
{
    struct mech_charged_motion_state s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_charged_motion_at_lab_time(m, t, &s, &e);
    CHECK(st == MECH_OK);
    if (st != MECH_OK) fprintf(stderr, "  error: %s\n", e.text);
    return s;
}

static void check_vec_close(struct mech_vec3 got, struct mech_vec3 want, double atol)
{
    CHECK_CLOSE(got.x, want.x, 0, atol);
    CHECK_CLOSE(got.y, want.y, 0, atol);
    CHECK_CLOSE(got.z, want.z, 0, atol);
}

/* A proton in B = 1 T along z with speed given by its proper speed u
 * (along x): gyration radius u/Omega, lab period 2 pi gamma/Omega. */
static void helix(double u, double tol)
{
    const double Om = QP * 1.0 / MP;
    struct mech_charged_motion m;
    CHECK(mech_charged_motion_init(V(0, 0, 0), V(0, 0, Om), V(0, 0, 0), V(u, 0, 0.25 * u), &m,
                                   NULL) == MECH_OK);
    CHECK_EQ_INT(m.kind, MECH_CHARGED_MAGNETIC);
    const double gamma = sqrt(1.0 + 1.0625 * u * u / (c * c));
    const double R = u / Om, T = 2.0 * MECH_PI * gamma / Om;
    /* u x Omega: v along +x, Omega along +z -> force along -y: the centre is
     * at (0, -R); a quarter period later the particle is at (R, -R) */
    struct mech_charged_motion_state s = at_t(&m, 0.25 * T);
    CHECK_CLOSE(s.r.x, R, tol, 0);
    CHECK_CLOSE(s.r.y, -R, tol, 0);
    CHECK_CLOSE(s.r.z, 0.25 * u / gamma * 0.25 * T, tol, 0);
    CHECK_CLOSE(s.u.y, -u, tol, 0);
    CHECK_CLOSE(s.u.x, 0, 0, tol * u);
    CHECK_CLOSE(s.tau, 0.25 * T / gamma, tol, 0);
    CHECK_CLOSE(s.gamma, gamma, 1e-15, 0);
    /* gamma - 1 without cancellation: u^2/c^2 / (gamma + 1) */
    CHECK_CLOSE(s.gamma_minus_1, 1.0625 * u * u / (c * c) / (gamma + 1.0), 1e-14, 0);
    /* one period: back over the start, moved along B by v_z T */
    s = at_t(&m, T);
    CHECK_CLOSE(s.r.x, 0, 0, tol * R);
    CHECK_CLOSE(s.r.y, 0, 0, tol * R);
    CHECK_CLOSE(s.u.x, u, tol, 0);
}

/* Motion in E alone (eps along x) from u0 = (ux, uy, 0). */
static void electric(double a, double ux, double uy, double t, double tol)
{
    struct mech_charged_motion m;
    CHECK(mech_charged_motion_init(V(a, 0, 0), V(0, 0, 0), V(1, 2, 3), V(ux, uy, 0), &m, NULL) ==
          MECH_OK);
    CHECK_EQ_INT(m.kind, MECH_CHARGED_ELECTRIC);
    struct mech_charged_motion_state s = at_t(&m, t);
    const double uxt = ux + a * t;
    check_vec_close(s.u, V(uxt, uy, 0), tol * fmax(fabs(uxt), fabs(uy)));
    const double g0 = sqrt(1.0 + (ux * ux + uy * uy) / (c * c));
    const double g1 = sqrt(1.0 + (uxt * uxt + uy * uy) / (c * c));
    const double dg = (uxt - ux) * (uxt + ux) / (c * c) / (g1 + g0);
    CHECK_CLOSE(s.r.x - 1.0, c * c / a * dg, tol, 4e-16); /* r0.x = 1: its ulp */
    const double A = sqrt(c * c + uy * uy);
    const double yint = c / a * (asinh(uxt / A) - asinh(ux / A)); /* int dt / gamma */
    CHECK_CLOSE(s.r.y - 2.0, uy * yint, tol, 8e-16);
    CHECK_CLOSE(s.tau, yint, tol, 0);
    CHECK_CLOSE(s.r.z, 3.0, 0, 0);
}

/* Central-difference check of the equation of motion at lab time t. */
static void eom_residual(const struct mech_charged_motion *m, double t, double h, double tol)
{
    struct mech_charged_motion_state s0 = at_t(m, t), sm = at_t(m, t - h), sp = at_t(m, t + h);
    const struct mech_vec3 dudt = mech_vec3_scale(mech_vec3_sub(sp.u, sm.u), 0.5 / h);
    const struct mech_vec3 drdt = mech_vec3_scale(mech_vec3_sub(sp.r, sm.r), 0.5 / h);
    const struct mech_vec3 want = mech_vec3_add(m->eps, mech_vec3_cross(s0.v, m->omega));
    const double scale = mech_vec3_norm(m->eps) + c * mech_vec3_norm(m->omega);
    check_vec_close(dudt, want, tol * scale);
    check_vec_close(drdt, s0.v, tol * c);
    CHECK_CLOSE((sp.tau - sm.tau) / (2.0 * h), 1.0 / s0.gamma, tol, 0);
    /* the proper-time evaluation gives back the lab time */
    struct mech_charged_motion_state q;
    CHECK(mech_charged_motion_at_proper_time(m, s0.tau, &q, NULL) == MECH_OK);
    CHECK_CLOSE(q.t, t, 1e-13, 0);
    check_vec_close(q.r, s0.r, 1e-12 * (mech_vec3_norm(s0.r) + c * t));
}

int main(void)
{
    gsl_set_error_handler_off();

    /* helix: beta = 1e-6, 0.8 (u = beta gamma c = 4c/3) and gamma = 1e6 */
    helix(1e-6 * c / sqrt(1.0 - 1e-12), 1e-12);
    helix(4.0 / 3.0 * c, 1e-12);
    helix(sqrt(1e12 - 1.0) * c, 1e-11);

    /* E alone: a = q E / m for E = 1 MV/m on a proton (a = 9.58e13 m/s^2)
     * from rest to beta = 1e-6 (t = 3.1e-12 s), to gamma ~ 1.67 and to
     * gamma ~ 1e6 (t = c 1e6 / a = 3.1 ms); and with a transverse start */
    const double a = QP * 1e6 / MP;
    electric(a, 0, 0, 1e-6 * c / a, 1e-12);
    electric(a, 0, 0, 4.0 / 3.0 * c / a, 1e-12);
    electric(a, 0, 0, 1e6 * c / a, 1e-11);
    electric(a, -2.0 * c, 0.5 * c, 3.0 * c / a, 1e-11);
    {   /* from rest: tau = (c/a) asinh(a t/c) */
        struct mech_charged_motion m;
        CHECK(mech_charged_motion_init(V(a, 0, 0), V(0, 0, 0), V(0, 0, 0), V(0, 0, 0), &m,
                                       NULL) == MECH_OK);
        const double t = 1e6 * c / a;
        struct mech_charged_motion_state s = at_t(&m, t);
        CHECK_CLOSE(s.tau, c / a * asinh(a * t / c), 1e-13, 0);
        CHECK_CLOSE(s.gamma, sqrt(1.0 + 1e12), 1e-13, 0);
    }

    /* E x B drift from rest: E = beta_w c B along y, B along z -> w along x */
    const double betas[] = {1e-6, 0.8};
    for (int i = 0; i < 2; i++) {
        const double bw = betas[i], Om = QP / MP, eps = bw * c * Om;
        struct mech_charged_motion m;
        CHECK(mech_charged_motion_init(V(0, eps, 0), V(0, 0, Om), V(0, 0, 0), V(0, 0, 0), &m,
                                       NULL) == MECH_OK);
        CHECK_EQ_INT(m.kind, MECH_CHARGED_CROSSED_MAGNETIC);
        CHECK_CLOSE(m.beta_w.x, bw, 1e-15, 0);
        CHECK_CLOSE(m.a_prime, 0, 0, 0);
        const double gw = 1.0 / sqrt(1.0 - bw * bw);
        CHECK_CLOSE(m.omega_prime, Om / gw, 1e-14, 0); /* B' = B/gamma_w */
        const double T = 2.0 * MECH_PI * gw * gw * gw / Om;
        struct mech_charged_motion_state s = at_t(&m, T);
        CHECK_CLOSE(s.r.x, bw * c * T, 1e-11, 0);
        CHECK_CLOSE(s.r.y, 0, 0, 1e-11 * bw * c * T);
        CHECK_CLOSE(mech_vec3_norm(s.u), 0, 0, 1e-11 * bw * c);
        s = at_t(&m, 0.5 * T);
        const double vmax = 2.0 * bw * c / (1.0 + bw * bw);
        CHECK_CLOSE(mech_vec3_norm(s.v), vmax, 1e-11, 0);
        eom_residual(&m, 0.3 * T, 1e-6 * T, 1e-7);
    }

    /* crossed fields with |E| > c|B|: B vanishes in the frame moving at c^2 B/E */
    {
        const double Om = 1e3, eps = 2.0 * c * Om;
        struct mech_charged_motion m;
        CHECK(mech_charged_motion_init(V(0, eps, 0), V(0, 0, Om), V(0, 0, 0), V(1e7, 0, 3e7), &m,
                                       NULL) == MECH_OK);
        CHECK_EQ_INT(m.kind, MECH_CHARGED_CROSSED_ELECTRIC);
        CHECK_CLOSE(m.beta_w.x, 0.5, 1e-15, 0);
        CHECK_CLOSE(m.a_prime, sqrt(eps * eps - c * c * Om * Om), 1e-15, 0);
        CHECK_CLOSE(m.omega_prime, 0, 0, 0);
        eom_residual(&m, 2e-3, 1e-8, 1e-6);
    }
    /* parallel E and B; a general field (neither parallel nor crossed) */
    {
        struct mech_charged_motion m;
        CHECK(mech_charged_motion_init(V(0, 0, 3e14), V(0, 0, 1e8), V(1, 0, 0), V(2e8, 0, 1e8),
                                       &m, NULL) == MECH_OK);
        CHECK_EQ_INT(m.kind, MECH_CHARGED_PARALLEL);
        eom_residual(&m, 1e-7, 1e-12, 1e-6);
        /* proper-time helix: the transverse proper speed keeps its size */
        struct mech_charged_motion_state s;
        CHECK(mech_charged_motion_at_proper_time(&m, 3e-8, &s, NULL) == MECH_OK);
        CHECK_CLOSE(hypot(s.u.x, s.u.y), 2e8, 1e-14, 0);
        CHECK_CLOSE(atan2(s.u.y, s.u.x), -1e8 * 3e-8, 1e-13, 0);

        CHECK(mech_charged_motion_init(V(1e14, 2e14, 0), V(0.3e6, 0, 1e6), V(0, 0, 0),
                                       V(1e8, -1e8, 5e7), &m, NULL) == MECH_OK);
        CHECK_EQ_INT(m.kind, MECH_CHARGED_GENERAL);
        /* in S' the fields are parallel: invariants kept */
        const double I1 = 5e28 - c * c * 1.09e12, I2 = 0.3e20;
        CHECK_CLOSE(m.a_prime * m.a_prime - c * c * m.omega_prime * m.omega_prime, I1, 1e-12, 0);
        CHECK_CLOSE(m.a_prime * m.omega_prime, I2, 1e-12, 0);
        eom_residual(&m, 2e-6, 1e-11, 1e-6);
        eom_residual(&m, 5e-5, 1e-10, 1e-6);
    }
    /* null fields: E perpendicular to B, |E| = c|B| */
    {
        struct mech_charged_motion m;
        struct mech_error e;
        mech_error_clear(&e);
        CHECK(mech_charged_motion_init(V(0, c * 10.0, 0), V(0, 0, 10.0), V(0, 0, 0), V(0, 0, 0),
                                       &m, &e) == MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "fields"));
        CHECK(mech_charged_motion_init(V(NAN, 0, 0), V(0, 0, 0), V(0, 0, 0), V(0, 0, 0), &m,
                                       NULL) == MECH_EINVAL);
    }
    TEST_MAIN_END();
}
