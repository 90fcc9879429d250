/* test_wisdom_holman.c — the Wisdom–Holman splitting (integrators/
 * wisdom_holman.c) and its Kepler drift (mech_kepler_drift, core/ode/kepler.c):
 *   the drift against an independent solution of Kepler's equation in long
 *   double (E - e sin E = M, e sinh H - H = M) at e = 0, 0.5, 0.9, 0.99, a
 *   hyperbola and a near-radial ellipse, for short, long and backward steps;
 *   with no perturbation, wisdom_holman is the Kepler closed form to
 *   round-off for any dt;
 *   its order, measured from two step sizes (error ratio ~4 on halving dt) on
 *   a tidally perturbed Kepler orbit against rk8pd at rtol 1e-14, in 3-D, in
 *   the plane and with weak drag (implicit-midpoint kick);
 *   its energy error over 1e4 orbits of Kepler + a weak central spring:
 *   bounded (the last 1000 orbits no worse than ~2x the first 1000) and
 *   proportional to the field;
 *   wisdom_holman_corrected: the symplectic corrector's gain over the plain
 *   map, its bounded energy error, drag refused;
 *   a scene without the Kepler split is refused naming integrator/method.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/frames/reference.h"
#include "mech/base/constants.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

/* ---- an independent Kepler solution (perifocal frame, long double) ------- */

/* State at time t after pericentre of the conic with semi-major axis a > 0
 * (for a hyperbola, a = |a|), eccentricity e != 1, gm: perifocal x towards
 * pericentre, y along the motion at pericentre. */
static void kepler_classic(long double gm, long double a, long double e, long double t,
                           long double r[2], long double v[2])
{
    const long double n = sqrtl(gm / (a * a * a)), M = n * t;
    if (e < 1.0L) {
        const long double twopi = 2.0L * MECH_PI_L;
        long double Mr = fmodl(M, twopi); /* to (-pi, pi]: E - Mr is periodic */
        if (Mr > twopi / 2) Mr -= twopi;
        if (Mr <= -twopi / 2) Mr += twopi;
        const long double shift = M - Mr;
        long double E = e < 0.8L ? Mr : (Mr >= 0 ? twopi / 2 : -twopi / 2); /* Danby's start */
        for (int i = 0; i < 100; i++) {
            long double d = (E - e * sinl(E) - Mr) / (1.0L - e * cosl(E));
            E -= d;
            if (fabsl(d) < 1e-19L * (1.0L + fabsl(E))) break;
        }
        (void)shift; /* the state depends on E mod 2 pi only */
        const long double b = a * sqrtl(1.0L - e * e), Ed = n / (1.0L - e * cosl(E));
        r[0] = a * (cosl(E) - e);
        r[1] = b * sinl(E);
        v[0] = -a * sinl(E) * Ed;
        v[1] = b * cosl(E) * Ed;
    } else {
        long double H = asinhl(M / e);
        for (int i = 0; i < 200; i++) {
            long double d = (e * sinhl(H) - H - M) / (e * coshl(H) - 1.0L);
            H -= d;
            if (fabsl(d) < 1e-19L * (1.0L + fabsl(H))) break;
        }
        const long double b = a * sqrtl(e * e - 1.0L), Hd = n / (e * coshl(H) - 1.0L);
        r[0] = a * (e - coshl(H));
        r[1] = b * sinhl(H);
        v[0] = -a * sinhl(H) * Hd;
        v[1] = b * coshl(H) * Hd;
    }
}

/* Relative error of (r, v) against the long-double state (R, V). */
static double rel_err(const double r[3], const double v[3], const long double R[2],
                      const long double V[2])
{
    const double rn = (double)sqrtl(R[0] * R[0] + R[1] * R[1]);
    const double vn = (double)sqrtl(V[0] * V[0] + V[1] * V[1]);
    const double dr = hypot(r[0] - (double)R[0], r[1] - (double)R[1]);
    const double dv = hypot(v[0] - (double)V[0], v[1] - (double)V[1]);
    return fmax(dr / rn + fabs(r[2]) / rn, dv / vn + fabs(v[2]) / vn);
}

/* The drift from the state at t0 after pericentre by dt, for one conic. */
static double drift_case(double a, double e, double t0, double dt, int *iterations)
{
    const long double gm = 1.0L;
    long double R0[2], V0[2], R1[2], V1[2];
    kepler_classic(gm, a, e, t0, R0, V0);
    kepler_classic(gm, a, e, t0 + dt, R1, V1);
    double r0[3] = {(double)R0[0], (double)R0[1], 0.0}, v0[3] = {(double)V0[0], (double)V0[1], 0.0};
    double r[3], v[3];
    struct mech_error err;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(1.0, r0, v0, dt, r, v, iterations, &err), MECH_OK);
    /* the rounding of the start state alone moves the end by ~1e-16 times
     * the orbit's sensitivity; compare with the exact continuation of the
     * rounded start instead: propagate R0 rounded in long double */
    return rel_err(r, v, R1, V1);
}

static void test_kepler_drift(void)
{
    struct {
        const char *name;
        double a, e, tol;
    } conics[] = {
        {"circle e=0", 1.0, 0.0, 2e-14},       {"ellipse e=0.5", 1.0, 0.5, 5e-14},
        {"ellipse e=0.9", 1.0, 0.9, 2e-13},    {"ellipse e=0.99", 1.0, 0.99, 5e-12},
        {"hyperbola e=1.5", 1.0, 1.5, 1e-13},  {"near-radial e=0.999999", 1.0, 0.999999, 1e-8},
    };
    for (size_t i = 0; i < sizeof conics / sizeof conics[0]; i++) {
        const double a = conics[i].a, e = conics[i].e;
        const double P = 2.0 * MECH_PI * sqrt(a * a * a);
        /* starts: near apocentre (or before pericentre for the hyperbola), at
         * a generic phase; steps: 1/100 orbit, 0.37 orbit, 3.7 orbits
         * (ellipses), backwards; across the pericentre */
        const double starts[] = {e < 1.0 ? 0.45 * P : -2.0, 0.13 * P};
        const double steps[] = {P / 100.0, -P / 100.0, 0.37 * P, e < 1.0 ? 3.7 * P : 7.0,
                                e < 1.0 ? 0.1 * P : 4.0};
        double worst = 0.0;
        int newton_small = 0;
        for (size_t s = 0; s < 2; s++)
            for (size_t k = 0; k < 5; k++) {
                int it = 0;
                double err = drift_case(a, e, starts[s], steps[k], &it);
                worst = fmax(worst, err);
                if (k == 0) newton_small = it > newton_small ? it : newton_small;
            }
        printf("kepler drift %-24s worst relative error %.2e (tol %.0e), Newton iterations at "
               "P/100: %d\n",
               conics[i].name, worst, conics[i].tol, newton_small);
        CHECK(worst < conics[i].tol);
        /* a step of 1/100 orbit converges on the fast path (not the fallback) */
        if (e < 0.99) CHECK(newton_small >= 1 && newton_small <= 5);
    }
    /* bad arguments and a radial infall through the centre: a status */
    double r0[3] = {1, 0, 0}, v0[3] = {0, 0, 0}, r[3], v[3];
    struct mech_error err;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(1.0, r0, v0, 10.0, r, v, NULL, &err), MECH_ENUMERIC);
    /* dropped from rest at r = 1 (gm = 1): it reaches the centre at
     * t = pi / (2 sqrt 2) = 1.1107 (half the period of the degenerate ellipse
     * a = 1/2); just before, r(t) from r = a (1 - cos E), t = (E - sin E)/n
     * measured from the collision (E = 2 pi - E' on the way in) */
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(1.0, r0, v0, 1.0, r, v, NULL, &err), MECH_OK);
    {
        const double n = 1.0 / sqrt(0.125), tc = MECH_PI / n; /* P/2 */
        double E = MECH_PI;                                   /* solve (E - sin E)/n = tc - 1 */
        for (int i = 0; i < 100; i++) E -= (E - sin(E) - n * (tc - 1.0)) / (1.0 - cos(E));
        CHECK_CLOSE(r[0], 0.5 * (1.0 - cos(E)), 1e-12, 0);
        CHECK(r[0] > 0.0 && fabs(r[1]) + fabs(r[2]) == 0.0 && v[0] < 0.0);
    }
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(1.0, r0, v0, 1.12, r, v, NULL, &err), MECH_ENUMERIC);
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(1.0, r0, v0, -1.12, r, v, NULL, &err), MECH_ENUMERIC);
    double z[3] = {0, 0, 0};
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(1.0, z, v0, 1.0, r, v, NULL, &err), MECH_EINVAL);
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_kepler_drift(-1.0, r0, v0, 1.0, r, v, NULL, &err), MECH_EINVAL);
}

/* ---- through mech_trajectory_integrate ----------------------------------- */

enum { NS_MAX = 100001 };
static double ts[NS_MAX];
static struct mech_vec3 pos[NS_MAX], vel[NS_MAX];

/* Kepler gm = 1, a = 1, e from pericentre (0.5 for e = 0.5), period 2 pi. */
static struct mech_trajectory_problem kepler_problem(double e, struct mech_force *forces,
                                                     size_t n_forces)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    p.frame.type = MECH_FRAME_INERTIAL;
    p.position = mech_vec3_make(1.0 - e, 0.0, 0.0);
    p.velocity = mech_vec3_make(0.0, sqrt((1.0 + e) / (1.0 - e)), 0.0);
    forces[0].type = MECH_FORCE_CENTRAL_GRAVITY;
    forces[0].u.central_gravity.gm = 1.0;
    forces[0].u.central_gravity.center = mech_vec3_make(0, 0, 0);
    p.forces = forces;
    p.n_forces = n_forces;
    p.samples = 11;
    p.method = "wisdom_holman";
    return p;
}

static enum mech_status run(const struct mech_trajectory_problem *p,
                            struct mech_trajectory_result *r, struct mech_error *e)
{
    struct mech_budget b = mech_budget_make(50000000, 600.0);
    memset(r, 0, sizeof *r);
    r->t = ts;
    r->position = pos;
    r->velocity = vel;
    mech_error_clear(e);
    return mech_trajectory_integrate(p, &b, r, e);
}

/* With only the central mass, every step is two exact Kepler drifts: the
 * Kepler closed form to round-off whatever dt (down to 1/1000 orbit, up to
 * several orbits per step). */
static void test_zero_perturbation(void)
{
    const double dts[] = {2.0 * MECH_PI / 1000.0, 0.37, 2.0 * MECH_PI * 0.43, 2.0 * MECH_PI * 3.3};
    for (int ei = 0; ei < 4; ei++) {
        const char *method = ei < 2 ? "wisdom_holman" : "wisdom_holman_corrected";
        const double e = ei % 2 ? 0.9 : 0.5;
        for (size_t k = 0; k < sizeof dts / sizeof dts[0]; k++) {
            struct mech_force f[2];
            memset(f, 0, sizeof f);
            struct mech_trajectory_problem p = kepler_problem(e, f, 1);
            p.method = method;
            p.t_end = 10.0 * 2.0 * MECH_PI;
            p.samples = 101;
            p.opt.dt = dts[k];
            p.reduce_planar = k % 2;
            struct mech_trajectory_result r;
            struct mech_error err;
            CHECK_EQ_INT(run(&p, &r, &err), MECH_OK);
            CHECK(strcmp(r.reference.name, "kepler") == 0);
            printf("%s, no perturbation, e = %.1f, dt = %.4g (%s): max relative "
                   "error %.2e (position) %.2e (velocity), %ld steps\n",
                   method, e, dts[k], p.reduce_planar ? "planar" : "3-D",
                   r.reference.max_relative_position_error,
                   r.reference.max_relative_velocity_error, r.stats.steps);
            /* round-off: each drift is good to a few ulp (test_kepler_drift),
             * but an ulp of velocity at pericentre is v_p^2 / |2E| = 19 ulp
             * of energy at e = 0.9 (3 at e = 0.5), and an energy error
             * turns into a phase error growing with time: the bounds are
             * that amplification over 10 orbits. Any error of the splitting
             * itself would be O(dt^2) here: O(1) at dt = 0.37. The corrected
             * method makes 8 drifts per step (round-off x sqrt(4)). */
            const double tol = e < 0.6 ? 1e-11 : 5e-10;
            CHECK(r.reference.max_relative_position_error < tol);
            CHECK(r.reference.max_relative_velocity_error < tol);
        }
    }
}

/* Final-position error of a run against the round-off reference run. */
static double final_error(const struct mech_trajectory_problem *p, const struct mech_vec3 *rref)
{
    struct mech_trajectory_result r;
    struct mech_error err;
    CHECK_EQ_INT(run(p, &r, &err), MECH_OK);
    if (r.n_samples != p->samples) return NAN;
    return mech_vec3_norm(mech_vec3_sub(pos[p->samples - 1], *rref));
}

/* Order 2: halving dt divides the error by ~4, on Kepler e = 0.5 perturbed by
 * a third body's tide of relative size ~1e-4 (gm3 = 0.4 at distance ~20:
 * 2 gm3 / d^3 = 1e-4), against rk8pd at rtol 1e-14; in 3-D (the tide-raiser
 * out of the plane), in the plane, and in the plane with weak drag (the
 * implicit-midpoint kick keeps the step symmetric, so still order 2). */
static void test_order(void)
{
    for (int variant = 0; variant < 3; variant++) {
        struct mech_force f[3];
        memset(f, 0, sizeof f);
        f[1].type = MECH_FORCE_THIRD_BODY_TIDE;
        f[1].u.third_body_tide.gm = 0.4;
        f[1].u.third_body_tide.position =
            variant == 0 ? mech_vec3_make(12.0, 6.0, 14.7) : mech_vec3_make(19.0, 6.24, 0.0);
        f[2].type = MECH_FORCE_LINEAR_DRAG;
        f[2].u.linear_drag.b = 1e-4;
        struct mech_trajectory_problem p = kepler_problem(0.5, f, variant == 2 ? 3 : 2);
        p.t_end = 10.0 * 2.0 * MECH_PI;
        p.reduce_planar = variant > 0;
        p.method = "rk8pd";
        p.opt.rtol = 1e-14;
        p.opt.atol = 0.0;
        struct mech_trajectory_result r;
        struct mech_error err;
        CHECK_EQ_INT(run(&p, &r, &err), MECH_OK);
        const struct mech_vec3 rref = pos[p.samples - 1];
        CHECK(r.dimensions == (variant == 0 ? 3 : 2));
        p.method = "wisdom_holman";
        p.opt.dt = 2.0 * MECH_PI / 64.0;
        const double e1 = final_error(&p, &rref);
        CHECK_EQ_INT(run(&p, &r, &err), MECH_OK);
        CHECK(r.dimensions == (variant == 0 ? 3 : 2));
        p.opt.dt = 2.0 * MECH_PI / 128.0;
        const double e2 = final_error(&p, &rref);
        /* and the unsplit leapfrog (verlet) at the finer dt, for scale */
        p.method = "verlet";
        const double ev = final_error(&p, &rref);
        printf("wisdom_holman order (%s): error at 10 orbits %.3e (dt = T/64), %.3e (T/128), "
               "ratio %.3f; verlet at T/128: %.3e\n",
               variant == 0 ? "3-D tide" : variant == 1 ? "planar tide" : "planar tide + drag",
               e1, e2, e1 / e2, ev);
        CHECK(e1 / e2 > 3.6 && e1 / e2 < 4.4);
        /* the perturbation's size sets the error: far below an unsplit
         * second-order method's at the same step */
        CHECK(e2 < 1e-2 * ev);
    }
}

/* max |E - E0| / |E0| over samples [i0, i1) of a run of Kepler + a spring
 * of stiffness k (unit mass) anchored at the centre, E = v^2/2 - gm/r +
 * k r^2/2. */
static double energy_error(double k, size_t i0, size_t i1)
{
    double e0 = 0.0, worst = 0.0;
    for (size_t i = 0; i < i1; i++) {
        const double r2 = mech_vec3_dot(pos[i], pos[i]);
        const double E = 0.5 * mech_vec3_dot(vel[i], vel[i]) - 1.0 / sqrt(r2) + 0.5 * k * r2;
        if (i == 0) e0 = E;
        if (i >= i0) worst = fmax(worst, fabs(E - e0) / fabs(e0));
    }
    return worst;
}

/* 1e4 orbits of Kepler e = 0.5 perturbed by a weak spring to the same centre
 * (k r^3 / gm = eps = 1e-4 and 1e-3: a central perturbation, so the orbit
 * keeps its shape and only precesses; a uniform field or a fixed tide would
 * drive the eccentricity towards 1 over such times — the Stark problem — and
 * change what is being compared), dt = T/50: the energy error of the last
 * 1000 orbits is not larger than ~2x that of the first 1000 (no secular
 * drift; a non-symplectic method drifts linearly), and it is proportional
 * to eps. */
static void test_energy_bounded(void)
{
    double amp[2];
    for (int j = 0; j < 2; j++) {
        const double eps = j ? 1e-3 : 1e-4;
        struct mech_force f[2];
        memset(f, 0, sizeof f);
        f[1].type = MECH_FORCE_SPRING;
        f[1].u.spring.k = eps;
        struct mech_trajectory_problem p = kepler_problem(0.5, f, 2);
        const size_t per_orbit = 5, orbits = 10000;
        p.t_end = (double)orbits * 2.0 * MECH_PI;
        p.samples = per_orbit * orbits + 1;
        p.opt.dt = 2.0 * MECH_PI / 50.0;
        p.reduce_planar = 1;
        struct mech_trajectory_result r;
        struct mech_error err;
        CHECK_EQ_INT(run(&p, &r, &err), MECH_OK);
        CHECK(r.n_samples == p.samples);
        const double first = energy_error(eps, 0, per_orbit * 1000 + 1);
        const double last = energy_error(eps, per_orbit * (orbits - 1000), p.samples);
        amp[j] = fmax(first, last);
        printf("wisdom_holman energy, Kepler e = 0.5 + central spring eps = %.0e, dt = T/50: "
               "max |dE/E| first 1000 orbits %.3e, last 1000 of 1e4 %.3e (ratio %.2f); "
               "driver's max drift %.3e\n",
               eps, first, last, last / first, r.invariant.max_relative_drift);
        CHECK(first > 0.0 && last <= 2.0 * first);
        CHECK(r.invariant.max_relative_drift < 4.0 * first);
    }
    printf("energy error amplitude ratio eps 1e-3 / 1e-4: %.2f (want ~10)\n", amp[1] / amp[0]);
    CHECK(amp[1] / amp[0] > 7.0 && amp[1] / amp[0] < 14.0);
}

/* wisdom_holman_corrected: the corrector removes the O(eps dt^2) error term
 * (Wisdom, Holman & Touma 1996), leaving O(eps^2 dt^2 + eps dt^4): on the
 * tidally perturbed Kepler orbit (eps ~ 1e-4) of test_order, at dt = T/64
 * and T/128 over 10 orbits, the error is at least 30x below the plain
 * method's and falls faster than dt^2 (the dt^4 term dominates at this
 * eps); the energy error over 1e4 orbits of the spring scene stays bounded
 * and far below the plain method's; drag (no Hamiltonian) is refused. */
static void test_corrected(void)
{
    struct mech_force f[3];
    memset(f, 0, sizeof f);
    f[1].type = MECH_FORCE_THIRD_BODY_TIDE;
    f[1].u.third_body_tide.gm = 0.4;
    f[1].u.third_body_tide.position = mech_vec3_make(12.0, 6.0, 14.7);
    struct mech_trajectory_problem p = kepler_problem(0.5, f, 2);
    p.t_end = 10.0 * 2.0 * MECH_PI;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    struct mech_trajectory_result r;
    struct mech_error err;
    CHECK_EQ_INT(run(&p, &r, &err), MECH_OK);
    const struct mech_vec3 rref = pos[p.samples - 1];
    double plain[2], corr[2];
    for (int k = 0; k < 2; k++) {
        p.opt.dt = 2.0 * MECH_PI / (k ? 128.0 : 64.0);
        p.method = "wisdom_holman";
        plain[k] = final_error(&p, &rref);
        p.method = "wisdom_holman_corrected";
        corr[k] = final_error(&p, &rref);
    }
    printf("wisdom_holman_corrected (3-D tide, 10 orbits): error %.3e (T/64), %.3e (T/128), "
           "ratio %.2f; plain %.3e, %.3e: corrector gains x%.0f, x%.0f\n",
           corr[0], corr[1], corr[0] / corr[1], plain[0], plain[1], plain[0] / corr[0],
           plain[1] / corr[1]);
    CHECK(corr[0] * 30.0 < plain[0] && corr[1] * 30.0 < plain[1]);
    CHECK(corr[0] / corr[1] > 6.0);

    /* energy over 1e4 orbits, spring eps = 1e-4, dt = T/50 */
    struct mech_force g[2];
    memset(g, 0, sizeof g);
    g[1].type = MECH_FORCE_SPRING;
    g[1].u.spring.k = 1e-4;
    struct mech_trajectory_problem q = kepler_problem(0.5, g, 2);
    const size_t per_orbit = 5, orbits = 10000;
    q.t_end = (double)orbits * 2.0 * MECH_PI;
    q.samples = per_orbit * orbits + 1;
    q.opt.dt = 2.0 * MECH_PI / 50.0;
    q.reduce_planar = 1;
    q.method = "wisdom_holman_corrected";
    CHECK_EQ_INT(run(&q, &r, &err), MECH_OK);
    const double first = energy_error(1e-4, 0, per_orbit * 1000 + 1);
    const double last = energy_error(1e-4, per_orbit * (orbits - 1000), q.samples);
    printf("wisdom_holman_corrected energy, spring eps = 1e-4, dt = T/50: max |dE/E| first 1000 "
           "orbits %.3e, last 1000 of 1e4 %.3e (ratio %.2f)\n",
           first, last, last / first);
    CHECK(first > 0.0 && last <= 2.0 * first);
    CHECK(first < 1.76e-7 / 30.0); /* plain wisdom_holman: 1.76e-7 (test_energy_bounded) */

    /* drag: refused */
    f[2].type = MECH_FORCE_LINEAR_DRAG;
    f[2].u.linear_drag.b = 1e-4;
    p.n_forces = 3;
    p.t_end = 1.0;
    p.opt.dt = 0.01;
    CHECK_EQ_INT(run(&p, &r, &err), MECH_EINVAL);
    CHECK(strcmp(err.param, "integrator/method") == 0 && strstr(err.text, "velocity-free"));
}

/* Without one central_gravity in an inertial frame: refused, naming
 * integrator/method and what is missing. */
static void test_needs_split(void)
{
    struct mech_force f[2];
    memset(f, 0, sizeof f);
    struct mech_trajectory_problem p = kepler_problem(0.5, f, 2);
    f[1] = f[0];
    f[1].u.central_gravity.center = mech_vec3_make(10, 0, 0);
    p.t_end = 1.0;
    p.opt.dt = 0.01;
    struct mech_trajectory_result r;
    struct mech_error err;
    CHECK_EQ_INT(run(&p, &r, &err), MECH_EINVAL);
    CHECK(strcmp(err.param, "integrator/method") == 0);
    CHECK(strstr(err.text, "one central_gravity") && strstr(err.text, "more than one"));
    CHECK(strlen(err.text) + 1 < sizeof err.text); /* not truncated */
    p.n_forces = 1;
    p.frame.type = MECH_FRAME_ROTATING;
    p.frame.omega = mech_vec3_make(0, 0, 0.1);
    p.fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    CHECK_EQ_INT(run(&p, &r, &err), MECH_EINVAL);
    CHECK(strcmp(err.param, "integrator/method") == 0 && strstr(err.text, "not inertial"));
    f[0].type = MECH_FORCE_UNIFORM_GRAVITY;
    p.frame.type = MECH_FRAME_INERTIAL;
    CHECK_EQ_INT(run(&p, &r, &err), MECH_EINVAL);
    CHECK(strcmp(err.param, "integrator/method") == 0 && strstr(err.text, "no central_gravity"));
}

int main(void)
{
    test_kepler_drift();
    test_zero_perturbation();
    test_order();
    test_energy_bounded();
    test_corrected();
    test_needs_split();
    TEST_MAIN_END();
}
