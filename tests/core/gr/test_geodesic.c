/* test_geodesic.c — mech/gr/geodesic.h: exact references against 40-digit
 * quadratures (mpmath) — the periapsis advance of r_p = 10, r_a = 30 and of
 * Mercury, light deflection at b = 6 ... 1e6 GM/c^2 and the Sun's limb —
 * the elliptic and quadrature routes against each other; integrations: a
 * circular orbit (r constant, phi = L tau / r^2, t = E tau / (1 - 2/r)),
 * radial infall from rest against the cycloid tau = sqrt(r0^3/8)(eta + sin eta)
 * (MTW eq. 31.10), the precession of r_p = 10 measured from the run within
 * 1e-8 of the exact value, Mercury's, a photon's deflection measured beside
 * the exact one, capture and escape, and the typed errors (horizon start,
 * E < V, constraint blow-up). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/gr/geodesic.h"
#include "mech/base/constants.h"
#include "mech/gr/schwarzschild.h"
#include "testlib.h"

enum { NS = 2001 };
static double sp[NS], st[NS], sr[NS], sphi[NS];

static struct mech_geodesic_problem problem(struct mech_geodesic_init in, double end)
{
    struct mech_geodesic_problem p;
    memset(&p, 0, sizeof p);
    p.init = in;
    p.param_end = end;
    p.r_escape = 1e3 * in.r0;
    p.constraint_bound = 1e-3;
    p.samples = NS;
    p.method = "rk8pd";
    p.opt.rtol = 1e-13;
    p.opt.atol = 1e-13;
    return p;
}

static struct mech_geodesic_result result(void)
{
    struct mech_geodesic_result r;
    memset(&r, 0, sizeof r);
    r.param = sp;
    r.t = st;
    r.r = sr;
    r.phi = sphi;
    return r;
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_budget B = mech_budget_make(10000000, 60);
    struct mech_error e;
    struct mech_geodesic_init in;
    struct mech_geodesic_bound bd;
    enum mech_geodesic_class cls;
    double adv, adv_q, Ttau, Tt;

    /* ---- exact precession: r_p = 10, r_a = 30 (mpmath: 1.8472766561752028130) */
    CHECK(mech_geodesic_init_orbit(10, 30, 0, &in, NULL) == MECH_OK);
    CHECK(mech_geodesic_classify(&in, &cls, &bd, NULL) == MECH_OK);
    CHECK(cls == MECH_GEODESIC_BOUND);
    CHECK_CLOSE(bd.u1, 1.0 / 30, 1e-12, 0);
    CHECK_CLOSE(bd.u2, 1.0 / 10, 1e-12, 0);
    CHECK(mech_geodesic_precession_exact(&bd, &adv, NULL) == MECH_OK);
    CHECK_CLOSE(adv, 1.8472766561752028130, 1e-14, 0);
    CHECK(mech_geodesic_precession_quadrature(&bd, in.E, in.L, &adv_q, &Ttau, &Tt, NULL) ==
          MECH_OK);
    CHECK_CLOSE(adv_q, 1.8472766561752028130, 1e-13, 0);

    /* ---- the run: 10 radial periods, periapses by the driver's events */
    {
        struct mech_geodesic_problem p = problem(in, 10 * Ttau);
        struct mech_geodesic_result r = result();
        mech_error_clear(&e);
        CHECK(mech_geodesic_integrate(&p, &B, &r, &e) == MECH_OK);
        CHECK(!r.captured && !r.escaped);
        CHECK(r.n_periapses >= 10);
        CHECK_CLOSE(r.measured_advance, adv, 1e-9, 0);
        printf("r_p = 10: measured advance %.17g, exact %.17g, rel err %.3g, periapses %ld, "
               "constraint %.3g, steps %ld\n",
               r.measured_advance, adv, fabs(r.measured_advance / adv - 1), r.n_periapses,
               r.constraint_max_relative, r.stats.steps);
        CHECK(r.constraint_max_relative < 1e-11);
        /* the samples stay between the turning points */
        double rmin = 1e300, rmax = 0;
        for (size_t i = 0; i < r.n_samples; i++) {
            rmin = fmin(rmin, sr[i]);
            rmax = fmax(rmax, sr[i]);
        }
        CHECK(rmin >= 10 * (1 - 1e-10) && rmax <= 30 * (1 + 1e-10));
        /* the radial period in tau: the last periapsis at 10 T_tau (or 9) */
        CHECK_CLOSE(r.last_periapsis_param / (double)(r.n_periapses - 1), Ttau, 1e-10, 0);
        CHECK_CLOSE((r.last_periapsis_t - r.first_periapsis_t) / (double)(r.n_periapses - 1), Tt,
                    1e-10, 0);
    }

    /* ---- Mercury: a = 5.7909050e10 m, e = 0.20563593, GM_sun = 1.32712440018e20 */
    {
        const double c = MECH_C, m = 1.32712440018e20 / (c * c);
        const double a = 5.7909050e10, ecc = 0.20563593;
        CHECK(mech_geodesic_init_orbit(a * (1 - ecc) / m, a * (1 + ecc) / m, 0, &in, NULL) ==
              MECH_OK);
        CHECK(mech_geodesic_classify(&in, &cls, &bd, NULL) == MECH_OK);
        CHECK(mech_geodesic_precession_exact(&bd, &adv, NULL) == MECH_OK);
        /* mpmath: 5.0186763413969306e-7 rad per orbit; 1PN 5.0186757386863958e-7 */
        CHECK_CLOSE(adv, 5.0186763413969306e-7, 1e-13, 0);
        CHECK(mech_geodesic_precession_quadrature(&bd, in.E, in.L, &adv_q, &Ttau, &Tt, NULL) ==
              MECH_OK);
        CHECK_CLOSE(adv_q, 5.0186763413969306e-7, 1e-12, 0);
        /* coordinate-time radial period: 87.969070394566615 days */
        CHECK_CLOSE(Tt * m / c / 86400, 87.969070394566615, 1e-13, 0);
        CHECK_CLOSE(in.E - 1, -1.2749518512313795e-8, 1e-8, 0);
        struct mech_geodesic_problem p = problem(in, 20 * Ttau);
        struct mech_geodesic_result r = result();
        mech_error_clear(&e);
        CHECK(mech_geodesic_integrate(&p, &B, &r, &e) == MECH_OK);
        CHECK(r.n_periapses >= 20);
        printf("Mercury: measured %.10g rad/orbit, exact %.10g, rel err %.3g (%ld periapses, "
               "%ld steps)\n",
               r.measured_advance, adv, fabs(r.measured_advance / adv - 1), r.n_periapses,
               r.stats.steps);
        CHECK_CLOSE(r.measured_advance, adv, 1e-5, 0);
    }

    /* ---- weak field from local velocities: a low Earth orbit (r = 6771 km, 7700 m/s
     * tangential): the cubic's small roots come from the Newtonian quadratic, polished;
     * exact advance = 1PN 3 pi (u1 + u2) to O(GM/c^2 r) ~ 1e-9 */
    {
        const double c = MECH_C, m = MECH_EARTH_GM / (c * c);
        CHECK(mech_geodesic_init_local(MECH_GEODESIC_TIMELIKE, 6771000 / m, 0, 0, 7700 / c, &in,
                                       NULL) == MECH_OK);
        CHECK(mech_geodesic_classify(&in, &cls, &bd, NULL) == MECH_OK);
        CHECK(cls == MECH_GEODESIC_BOUND);
        /* the start is the periapsis: u2 = m / r0 */
        CHECK_CLOSE(bd.u2, m / 6771000, 1e-12, 0);
        /* Newtonian apoapsis from the vis-viva energy and L (GM, r0, v): r_a = L^2/(GM (1 - e)) */
        const double GM = MECH_EARTH_GM, r0 = 6771000, v = 7700;
        const double e_n = r0 * v * v / GM - 1, ra = r0 * (1 + e_n) / (1 - e_n);
        CHECK_CLOSE(1 / bd.u1 * m, ra, 1e-8, 0);
        CHECK(mech_geodesic_precession_exact(&bd, &adv, NULL) == MECH_OK);
        CHECK_CLOSE(adv, 3 * MECH_PI * (bd.u1 + bd.u2), 1e-8, 0);
        CHECK(mech_geodesic_precession_quadrature(&bd, in.E, in.L, &adv_q, NULL, NULL, NULL) ==
              MECH_OK);
        CHECK_CLOSE(adv_q, adv, 1e-12, 0);
    }

    /* ---- light deflection: elliptic vs quadrature vs mpmath */
    {
        const double b[5] = {6, 10, 1000, 1e6, 471141.95004055270};
        const double want[5] = {1.7193883102301686, 0.59039578760582732, 0.0040118238099253647,
                                4.0000117810151178e-6, 8.490063355623990e-6};
        for (int i = 0; i < 5; i++) {
            double d1, d2, rmin;
            CHECK(mech_geodesic_deflection_exact(b[i], &d1, &rmin, NULL) == MECH_OK);
            CHECK(mech_geodesic_deflection_quadrature(b[i], &d2, NULL) == MECH_OK);
            CHECK_CLOSE(d1, want[i], 5e-10, 0);
            CHECK_CLOSE(d2, want[i], 1e-13, 0);
        }
        double d, rmin;
        CHECK(mech_geodesic_deflection_exact(1000, &d, &rmin, NULL) == MECH_OK);
        CHECK_CLOSE(rmin, 998.99849598682681, 1e-13, 0);
        /* weak field: 4/b + 15 pi/(4 b^2) + 128/(3 b^3) (Keeton & Petters 2005) */
        CHECK(mech_geodesic_deflection_quadrature(1e7, &d, NULL) == MECH_OK);
        CHECK_CLOSE(d, 4e-7 + 15 * MECH_PI / 4e14 + 128.0 / 3e21, 1e-13, 0);
        mech_error_clear(&e);
        CHECK(mech_geodesic_deflection_exact(5.0, &d, &rmin, &e) == MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "impact_parameter"));
        CHECK(mech_geodesic_deflection_quadrature(5.19, &d, NULL) == MECH_EDOMAIN);
        /* extreme weak field: b = 1e20 and 1e40 GM/c^2, the quadrature keeps 4/b exactly
         * (the elliptic form's "- pi" cancels everything there) */
        CHECK(mech_geodesic_deflection_quadrature(1e20, &d, NULL) == MECH_OK);
        CHECK_CLOSE(d, 4e-20, 1e-14, 0);
        CHECK(mech_geodesic_deflection_quadrature(1e40, &d, NULL) == MECH_OK);
        CHECK_CLOSE(d, 4e-40, 1e-14, 0);
        /* near critical: b = 3 sqrt 3 (1 + 1e-6): finite, large, both routes agree */
        double dn1, dn2;
        CHECK(mech_geodesic_deflection_exact(3 * sqrt(3.0) * (1 + 1e-6), &dn1, &rmin, NULL) ==
              MECH_OK);
        CHECK(mech_geodesic_deflection_quadrature(3 * sqrt(3.0) * (1 + 1e-6), &dn2, NULL) ==
              MECH_OK);
        CHECK(dn1 > 10 && isfinite(dn1));
        CHECK_CLOSE(dn2, dn1, 1e-7, 0);
        CHECK_CLOSE(rmin, 3.0, 1e-2, 0);
    }

    /* ---- a photon: b = 1000 from r0 = 1e5 inward, measured vs exact */
    {
        CHECK(mech_geodesic_init_impact(1e5, 0, 1000, -1, &in, NULL) == MECH_OK);
        struct mech_geodesic_problem p = problem(in, 1e7);
        p.r_escape = 2e5;
        struct mech_geodesic_result r = result();
        mech_error_clear(&e);
        CHECK(mech_geodesic_integrate(&p, &B, &r, &e) == MECH_OK);
        CHECK(r.escaped && !r.captured);
        CHECK_CLOSE(r.end_r, 2e5, 1e-12, 0);
        printf(
            "photon b = 1000: measured deflection %.17g, exact 0.0040118238099253647, rel %.3g\n",
            r.measured_deflection, fabs(r.measured_deflection / 0.0040118238099253647 - 1));
        CHECK_CLOSE(r.measured_deflection, 0.0040118238099253647, 1e-8, 0);
        CHECK(r.constraint_max_relative < 1e-12);
    }
    /* photon below the critical impact parameter: captured, never NaN */
    {
        CHECK(mech_geodesic_init_impact(100, 0, 5.0, -1, &in, NULL) == MECH_OK);
        struct mech_geodesic_problem p = problem(in, 1e4);
        struct mech_geodesic_result r = result();
        CHECK(mech_geodesic_integrate(&p, &B, &r, NULL) == MECH_OK);
        CHECK(r.captured && !r.escaped);
        CHECK_CLOSE(r.end_r, 2 * (1 + MECH_GEODESIC_CAPTURE_MARGIN), 1e-12, 0);
        CHECK(isfinite(r.end_t) && isfinite(r.end_phi));
        CHECK(isnan(r.measured_deflection));
    }
    /* local direction form: a photon sent tangentially at r = 3 stays (unstable) near 3 */
    CHECK(mech_geodesic_init_local(MECH_GEODESIC_NULL, 3.0, 0, 0, 1, &in, NULL) == MECH_OK);
    CHECK_CLOSE(in.L, 3 * sqrt(3.0), 1e-15, 0);

    /* ---- circular orbit at r = 10 from its E and L */
    {
        struct mech_schw_circular co;
        CHECK(mech_schw_circular_orbit(10, &co, NULL) == MECH_OK);
        CHECK(mech_geodesic_init_energy(10, 0, co.energy, co.angular_momentum, -1, &in, NULL) ==
              MECH_OK);
        CHECK(fabs(in.rdot0) < 1e-7);
        struct mech_geodesic_problem p = problem(in, 2000);
        struct mech_geodesic_result r = result();
        CHECK(mech_geodesic_integrate(&p, &B, &r, NULL) == MECH_OK);
        double dev = 0;
        for (size_t i = 0; i < r.n_samples; i++)
            dev = fmax(dev, fabs(sr[i] - 10));
        CHECK(dev < 1e-6);
        size_t l = r.n_samples - 1;
        CHECK_CLOSE(sphi[l], co.angular_momentum / 100 * sp[l], 1e-7, 0);
        CHECK_CLOSE(st[l], sp[l] / co.rate, 1e-7, 0);
    }

    /* ---- radial infall from rest at r0 = 10: the cycloid */
    {
        CHECK(mech_geodesic_init_local(MECH_GEODESIC_TIMELIKE, 10, 0, 0, 0, &in, NULL) == MECH_OK);
        CHECK(mech_geodesic_classify(&in, &cls, &bd, NULL) == MECH_OK);
        CHECK(cls == MECH_GEODESIC_PLUNGE);
        struct mech_geodesic_problem p = problem(in, 1000);
        struct mech_geodesic_result r = result();
        CHECK(mech_geodesic_integrate(&p, &B, &r, NULL) == MECH_OK);
        CHECK(r.captured);
        const double rc = 2 * (1 + MECH_GEODESIC_CAPTURE_MARGIN);
        const double eta = acos(2 * rc / 10 - 1);
        CHECK_CLOSE(r.end_param, sqrt(1000.0 / 8) * (eta + sin(eta)), 1e-11, 0);
        CHECK(isfinite(r.end_t) && r.end_t > r.end_param);
    }

    /* ---- escape: outward from r = 10 faster than escape speed */
    {
        CHECK(mech_geodesic_init_local(MECH_GEODESIC_TIMELIKE, 10, 0, 0.6, 0.2, &in, NULL) ==
              MECH_OK);
        CHECK(mech_geodesic_classify(&in, &cls, &bd, NULL) == MECH_OK);
        CHECK(cls == MECH_GEODESIC_UNBOUND);
        struct mech_geodesic_problem p = problem(in, 1e7);
        p.r_escape = 1000;
        struct mech_geodesic_result r = result();
        mech_error_clear(&e);
        CHECK(mech_geodesic_integrate(&p, &B, &r, &e) == MECH_OK);
        if (e.code) printf("escape: %s %s\n", e.param, e.text);
        CHECK(r.escaped && !r.captured);
        CHECK_CLOSE(r.end_r, 1000, 1e-12, 0);
        /* E conserved: dr/dtau at the end from E^2 - V */
        double V = mech_schw_veff_massive(1000, in.L);
        CHECK_CLOSE(r.end_rdot, sqrt(in.E * in.E - V), 1e-10, 0);
    }

    /* ---- typed errors */
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_energy(1.5, 0, 0.9, 3, -1, &in, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "r0"));
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_energy(-1, 0, 0.9, 3, -1, &in, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "r0"));
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_energy(10, 0, 0.9, 4, -1, &in, &e) ==
          MECH_EDOMAIN); /* V(10) = 0.9216 > 0.81 */
    CHECK(!strcmp(e.param, "energy"));
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_local(MECH_GEODESIC_TIMELIKE, 10, 0, 0.8, 0.6, &in, &e) ==
          MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "local_velocity"));
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_impact(10, 0, 20, -1, &in, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "impact_parameter"));
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_orbit(4, 30, 0, &in, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "periapsis"));
    mech_error_clear(&e);
    CHECK(mech_geodesic_init_orbit(10, 8, 0, &in, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "apoapsis"));
    /* constraint blow-up: Euler at a coarse step */
    {
        CHECK(mech_geodesic_init_orbit(10, 30, 0, &in, NULL) == MECH_OK);
        struct mech_geodesic_problem p = problem(in, 5000);
        p.method = "euler";
        p.opt.dt = 0.05;
        struct mech_geodesic_result r = result();
        mech_error_clear(&e);
        CHECK(mech_geodesic_integrate(&p, &B, &r, &e) == MECH_ENUMERIC);
        CHECK(!strcmp(e.param, "constraint_bound"));
        CHECK(r.n_samples < NS);
        for (size_t i = 0; i < r.n_samples; i++)
            CHECK(isfinite(sr[i]) && isfinite(st[i]));
    }
    /* budget */
    {
        CHECK(mech_geodesic_init_orbit(10, 30, 0, &in, NULL) == MECH_OK);
        struct mech_geodesic_problem p = problem(in, 1e6);
        struct mech_budget small = mech_budget_make(50, 60);
        struct mech_geodesic_result r = result();
        mech_error_clear(&e);
        CHECK(mech_geodesic_integrate(&p, &small, &r, &e) == MECH_EBUDGET);
        if (e.code != MECH_EBUDGET) printf("budget: %d %s %s\n", e.code, e.param, e.text);
        CHECK(e.progress.t_reached > 0 && e.progress.t_reached < 1e6);
    }
    TEST_MAIN_END();
}
