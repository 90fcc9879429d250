/* test_closed_form.c — trajectories answered from the exact solution
 * (mech/frames/closed_form.h), against independent computations:
 *   Kepler e = 0, 0.5, 0.9, 0.999, hyperbolic e = 1.5 and a radial escape
 *   against an integration at round-off tolerance (rk8pd, rtol 1e-14), the
 *   invariants and the universal Kepler residual as its evidence, 0 steps;
 *   the harmonic oscillator over 1e4 periods against cos/sin in long double
 *   (the phase must not lose n eps over n periods);
 *   uniform gravity with drag at a tiny gamma t against its Taylor series in
 *   long double (no cancellation);
 *   the stop event: a falling object with drag hitting z = 0 against the time
 *   from Newton's method on the closed form in long double; a Kepler ellipse
 *   reaching apoapsis (y = 0 decreasing) at P/2, also when t_end is 1000
 *   orbits (the scan is one period, not 1000); a radial fall stopped at r0/2
 *   against the free-fall formula; a radial fall through the centre is an
 *   error naming the time;
 *   a planar orbit and the same orbit tilted in 3-D agree after rotation;
 *   a scene without a closed form is refused.
 */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/frames/closed_form.h"
#include "mech/base/constants.h"
#include "mech/frames/reference.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

#define NS 201
static double T_[NS], T2[NS];
static struct mech_vec3 R_[NS], V_[NS], R2[NS], V2[NS];

static void result_init(struct mech_trajectory_result *r, double *t, struct mech_vec3 *p,
                        struct mech_vec3 *v)
{
    memset(r, 0, sizeof *r);
    r->t = t;
    r->position = p;
    r->velocity = v;
}

static struct mech_trajectory_problem problem(double mass, struct mech_vec3 r0, struct mech_vec3 v0,
                                              const struct mech_force *f, size_t nf, double t_end,
                                              size_t samples)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = mass;
    p.position = r0;
    p.velocity = v0;
    p.forces = f;
    p.n_forces = nf;
    p.t_end = t_end;
    p.samples = samples;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    p.opt.atol = 0.0;
    p.reduce_planar = 1;
    return p;
}

/* max over the samples of |a - b| / max |b| (positions) and the same for velocities */
static double max_rel(const struct mech_vec3 *a, const struct mech_vec3 *b, size_t n)
{
    double d = 0.0, s = 0.0;
    for (size_t i = 0; i < n; i++) {
        d = fmax(d, mech_vec3_norm(mech_vec3_sub(a[i], b[i])));
        s = fmax(s, mech_vec3_norm(b[i]));
    }
    return d / s;
}

/* Kepler orbit of eccentricity e from periapsis; closed form vs rk8pd at rtol 1e-14. */
static void kepler_vs_integration(double e, double t_end, double tol)
{
    const double gm = MECH_EARTH_GM, q = 7.0e6;
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = gm;
    struct mech_trajectory_problem p =
        problem(1.0, mech_vec3_make(q, 0, 0), mech_vec3_make(0, sqrt(gm * (1 + e) / q), 0), &f, 1,
                t_end, NS);
    struct mech_trajectory_result a, b;
    result_init(&a, T_, R_, V_);
    result_init(&b, T2, R2, V2);
    struct mech_error err;
    struct mech_closed_form_evidence ev;
    CHECK(mech_trajectory_closed_form_ex(&p, &a, &ev, NULL, &err) == MECH_OK);
    struct mech_budget bud = mech_budget_make(50000000, 600.0);
    CHECK(mech_trajectory_integrate(&p, &bud, &b, &err) == MECH_OK);
    CHECK_EQ_INT(a.n_samples, NS);
    CHECK_EQ_INT(b.n_samples, NS);
    for (size_t i = 0; i < NS; i++) CHECK(T_[i] == T2[i]);
    const double dr = max_rel(R_, R2, NS), dv = max_rel(V_, V2, NS);
    printf("kepler e = %g: closed form vs rk8pd 1e-14: position %.3g, velocity %.3g; "
           "drift E %.3g L %.3g, residual %.3g, integration steps %ld\n",
           e, dr, dv, a.invariants[0].max_relative_drift, a.invariants[1].max_relative_drift,
           ev.max_kepler_residual, b.stats.steps);
    CHECK(dr < tol);
    CHECK(dv < tol);
    /* nothing integrated: the cost is the samples */
    CHECK_EQ_INT(a.stats.steps, 0);
    CHECK_EQ_INT(a.stats.rhs_evaluations, 0);
    CHECK(!strcmp(a.method, "closed_form"));
    CHECK(a.reference.kind == MECH_REFERENCE_EXACT && !strcmp(a.reference.name, "kepler"));
    /* the evidence: energy and angular momentum at round-off, Kepler solved */
    CHECK_EQ_INT(a.n_invariants, 2);
    CHECK(a.invariants[0].max_relative_drift < 1e-13 / fmax(1e-3, fabs(1 - e)));
    /* f g - g f' = 1 cancels by ~1/(1 - e) near parabolic: 3e-13 at e = 0.999 */
    CHECK(a.invariants[1].max_relative_drift < 5e-15 + 1e-15 / fmax(1e-3, fabs(1 - e)));
    CHECK(ev.max_kepler_residual < 1e-15);
    CHECK(ev.error_bound >= ev.max_invariant_drift && ev.error_bound >= 4 * DBL_EPSILON);
    CHECK(ev.evaluations == NS);
}

static void test_kepler(void)
{
    const double gm = MECH_EARTH_GM, q = 7.0e6;
    for (int k = 0; k < 4; k++) {
        const double es[4] = {0.0, 0.5, 0.9, 0.999};
        const double tols[4] = {1e-11, 1e-11, 1e-10, 1e-8};
        const double a = q / (1 - es[k]);
        const double P = 2 * MECH_PI * sqrt(a * a * a / gm);
        kepler_vs_integration(es[k], 1.5 * P, tols[k]);
    }
    kepler_vs_integration(1.5, 20000.0, 1e-11); /* hyperbola */
}

/* Radial escape (r0 x v0 = 0, beyond escape speed) vs integration. */
static void test_kepler_radial(void)
{
    const double gm = 1.0, r0 = 1.0;
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = gm;
    struct mech_trajectory_problem p = problem(
        2.0, mech_vec3_make(r0, 0, 0), mech_vec3_make(1.2 * sqrt(2 * gm / r0), 0, 0), &f, 1, 50.0, NS);
    struct mech_trajectory_result a, b;
    result_init(&a, T_, R_, V_);
    result_init(&b, T2, R2, V2);
    struct mech_error err;
    struct mech_budget bud = mech_budget_make(50000000, 600.0);
    CHECK(mech_trajectory_closed_form(&p, &a, &err) == MECH_OK);
    CHECK(mech_trajectory_integrate(&p, &bud, &b, &err) == MECH_OK);
    const double dr = max_rel(R_, R2, NS), dv = max_rel(V_, V2, NS);
    printf("radial escape: closed form vs rk8pd: %.3g %.3g\n", dr, dv);
    CHECK(dr < 1e-12 && dv < 1e-12);
    CHECK(a.invariants[0].max_relative_drift < 1e-14);

    /* A drop from rest at r0: the free-fall time from r0 to r (notes: radial
     * Kepler, r = r0 cos^2 eta, t = sqrt(r0^3/(2 gm)) (eta + sin eta cos eta))
     * to r0/2 is sqrt(r0^3/(2 gm)) (pi/4 + 1/2); the centre is reached at
     * pi/2 sqrt(r0^3/(2 gm)). */
    p.velocity = mech_vec3_make(0, 0, 0);
    p.t_end = 3.0;
    p.has_stop = 1;
    p.stop_axis = 0;
    p.stop_value = 0.5 * r0;
    p.stop_direction = MECH_STOP_DECREASING;
    const double tau = sqrt(r0 * r0 * r0 / (2 * gm));
    CHECK(mech_trajectory_closed_form(&p, &a, &err) == MECH_OK);
    CHECK(a.stopped);
    CHECK_CLOSE(a.t_stop, tau * (MECH_PI / 4 + 0.5), 4e-16, 0);
    CHECK_CLOSE(a.stop_position.x, 0.5 * r0, 4e-16, 0);
    char want[32];
    snprintf(want, sizeof want, "t = %.9g s", tau * MECH_PI / 2);
    for (int k = 0; k < 2; k++) {
        /* no stop, or a stop never reached (x = 2 r0): the fall into the centre */
        p.has_stop = k;
        p.stop_value = 2.0 * r0;
        mech_error_clear(&err);
        CHECK(mech_trajectory_closed_form(&p, &a, &err) == MECH_ENUMERIC);
        CHECK(strstr(err.text, want) != NULL);
        if (!strstr(err.text, want)) fprintf(stderr, "  %s (want %s)\n", err.text, want);
    }
}

/* Kepler ellipse: apoapsis (y crosses 0 decreasing) at exactly P/2, even when
 * t_end is 1000 orbits; the event search costs a period's grid, not 1000. */
static void test_kepler_event(void)
{
    const double gm = 1.0, a0 = 1.0, e = 0.5, q = a0 * (1 - e), vq = sqrt(gm * (1 + e) / q);
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = gm;
    /* the orbit of the state as given (vq rounded): vis-viva in long double */
    const long double al = 1.0L / (2.0L / q - (long double)vq * vq);
    const double P = (double)(2 * MECH_PI_L * sqrtl(al * al * al));
    struct mech_trajectory_problem p = problem(
        1.0, mech_vec3_make(q, 0, 0), mech_vec3_make(0, vq, 0), &f, 1, 1000 * P, 101);
    p.has_stop = 1;
    p.stop_axis = 1;
    p.stop_value = 0.0;
    p.stop_direction = MECH_STOP_DECREASING;
    struct mech_trajectory_result r;
    result_init(&r, T_, R_, V_);
    struct mech_error err;
    struct mech_closed_form_evidence ev;
    CHECK(mech_trajectory_closed_form_ex(&p, &r, &ev, NULL, &err) == MECH_OK);
    CHECK(r.stopped);
    CHECK_CLOSE(r.t_stop, P / 2, 4e-16, 0);
    CHECK_CLOSE(r.stop_position.x, (double)(-(2 * al - q)), 4e-16, 0);
    CHECK_EQ_INT(r.n_samples, 1); /* only t = 0 precedes P/2 on a 1000-orbit grid */
    printf("kepler apoapsis event: t_stop - P/2 = %.3g, %d evaluations\n", r.t_stop - P / 2,
           ev.evaluations);
    CHECK(ev.evaluations < 400);
    /* never crossing (y < -2a): no stop, all samples */
    p.stop_value = -3.0;
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_OK);
    CHECK(!r.stopped && r.n_samples == 101 && isnan(r.t_stop));
}

/* 1e4 periods of the oscillator against long-double cos/sin. */
static void test_oscillator_long(void)
{
    const double k = 3.7, m = 1.3;
    struct mech_force f = {.type = MECH_FORCE_SPRING};
    f.u.spring.k = k;
    const long double w = sqrtl((long double)k / (long double)m);
    const double T = (double)(2.0L * MECH_PI_L / w);
    const struct mech_vec3 r0 = mech_vec3_make(0.8, -0.3, 0.5), v0 = mech_vec3_make(0.1, 0.7, -0.2);
    struct mech_trajectory_problem p = problem(m, r0, v0, &f, 1, 1e4 * T, NS);
    struct mech_trajectory_result r;
    result_init(&r, T_, R_, V_);
    struct mech_error err;
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_OK);
    double worst = 0.0;
    for (size_t i = 0; i < NS; i++) {
        const long double t = T_[i], c = cosl(w * t), s = sinl(w * t);
        const double x[3] = {r0.x, r0.y, r0.z}, u[3] = {v0.x, v0.y, v0.z};
        const double got[3] = {R_[i].x, R_[i].y, R_[i].z}, gv[3] = {V_[i].x, V_[i].y, V_[i].z};
        for (int j = 0; j < 3; j++) {
            const long double xr = x[j] * c + u[j] * s / w;
            const long double vr = -x[j] * w * s + u[j] * c;
            worst = fmax(worst, fabs((double)(got[j] - xr)));
            worst = fmax(worst, fabs((double)(gv[j] - vr)) / (double)w);
        }
    }
    printf("oscillator 1e4 periods: max error %.3g (amplitude ~1)\n", worst);
    CHECK(worst < 2e-14);
    CHECK_EQ_INT(r.stats.steps, 0);
    CHECK(r.invariants[0].max_relative_drift < 1e-14);
    CHECK(r.n_invariants == 2 && r.invariants[1].max_relative_drift < 1e-14);
}

/* Drag at tiny gamma t: the closed form against its Taylor series. */
static void test_drag_small(void)
{
    const double m = 2.0, b = 2e-9, t_end = 10.0; /* gamma t = 1e-8 */
    struct mech_force f[2] = {{.type = MECH_FORCE_UNIFORM_GRAVITY}, {.type = MECH_FORCE_LINEAR_DRAG}};
    f[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
    f[1].u.linear_drag.b = b;
    const struct mech_vec3 r0 = mech_vec3_make(1, 2, 3), v0 = mech_vec3_make(30, -4, 50);
    struct mech_trajectory_problem p = problem(m, r0, v0, f, 2, t_end, 11);
    struct mech_trajectory_result r;
    result_init(&r, T_, R_, V_);
    struct mech_error err;
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_OK);
    const long double gam = (long double)b / m;
    double worst = 0.0;
    for (size_t i = 0; i < 11; i++) {
        const long double t = T_[i], x = gam * t;
        /* E1 = (1 - e^-x)/x = 1 - x/2 + x^2/6; E2 = (x - 1 + e^-x)/x^2 = 1/2 - x/6 + x^2/24 */
        const long double e1 = 1 - x / 2 + x * x / 6, e2 = 0.5L - x / 6 + x * x / 24;
        const long double z = r0.z + v0.z * t * e1 + (-9.80665L) * t * t * e2;
        const long double vz = v0.z * (1 - x * e1) + (-9.80665L) * t * e1;
        const long double xx = r0.x + v0.x * t * e1;
        worst = fmax(worst, fabs((double)(R_[i].z - z)) / 500.0);
        worst = fmax(worst, fabs((double)(R_[i].x - xx)) / 300.0);
        worst = fmax(worst, fabs((double)(V_[i].z - vz)) / 50.0);
    }
    printf("drag gamma t = 1e-8: max relative error vs series %.3g\n", worst);
    CHECK(worst < 4e-16);
    CHECK(!r.invariants[0].conserved);
    CHECK(r.invariants[0].final < r.invariants[0].initial);
}

/* A falling object with drag hits z = 0: t_stop against Newton's method on
 * z(t) = z0 + (v0 - vt)(1 - e^{-gt})/g + vt t (vt = -g0/gamma) in long double,
 * and an rk8pd integration's event. */
static void test_drag_event(void)
{
    const double m = 0.5, b = 0.2, z0 = 100.0, vz0 = 5.0, g0 = 9.80665;
    struct mech_force f[2] = {{.type = MECH_FORCE_UNIFORM_GRAVITY}, {.type = MECH_FORCE_LINEAR_DRAG}};
    f[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -g0);
    f[1].u.linear_drag.b = b;
    struct mech_trajectory_problem p =
        problem(m, mech_vec3_make(0, 0, z0), mech_vec3_make(3, 0, vz0), f, 2, 100.0, 101);
    p.has_stop = 1;
    p.stop_axis = 2;
    p.stop_value = 0.0;
    p.stop_direction = MECH_STOP_DECREASING;
    struct mech_trajectory_result r, ri;
    result_init(&r, T_, R_, V_);
    result_init(&ri, T2, R2, V2);
    struct mech_error err;
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_OK);
    CHECK(r.stopped);
    const long double gam = (long double)b / m, vt = -(long double)g0 / gam;
    long double t = 5.0L;
    for (int i = 0; i < 60; i++) {
        const long double ex = expl(-gam * t);
        const long double z = z0 + (vz0 - vt) * (1 - ex) / gam + vt * t;
        const long double dz = (vz0 - vt) * ex + vt;
        t -= z / dz;
    }
    printf("drag fall: t_stop %.17g, independent %.17Lg, diff %.3g\n", r.t_stop, t,
           (double)(r.t_stop - t));
    CHECK_CLOSE(r.t_stop, (double)t, 4e-16, 0);
    CHECK(fabs(r.stop_position.z) < 1e-13);
    CHECK(r.n_samples == (size_t)floor((double)t / 1.0) + 1);
    struct mech_budget bud = mech_budget_make(50000000, 600.0);
    p.opt.rtol = 1e-13;
    CHECK(mech_trajectory_integrate(&p, &bud, &ri, &err) == MECH_OK);
    CHECK(ri.stopped);
    CHECK_CLOSE(ri.t_stop, r.t_stop, 1e-11, 0);
    /* thrown up from z = 0: the start is no crossing; it lands later */
    p.position = mech_vec3_make(0, 0, 0);
    p.velocity = mech_vec3_make(0, 0, 20);
    p.stop_direction = MECH_STOP_EITHER;
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_OK);
    CHECK(r.stopped && r.t_stop > 1.0);
    CHECK(fabs(r.stop_position.z) < 1e-13);
}

/* The same orbit in the xy plane and tilted about x by 30 degrees. */
static void test_planar_vs_3d(void)
{
    const double gm = 1.0, c = cos(MECH_PI / 6), s = sin(MECH_PI / 6);
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = gm;
    struct mech_trajectory_problem p =
        problem(1.0, mech_vec3_make(1, 0.2, 0), mech_vec3_make(-0.1, 1.1, 0), &f, 1, 30.0, NS);
    struct mech_trajectory_result a, b;
    result_init(&a, T_, R_, V_);
    result_init(&b, T2, R2, V2);
    struct mech_error err;
    CHECK(mech_trajectory_closed_form(&p, &a, &err) == MECH_OK);
    p.position = mech_vec3_make(1, 0.2 * c, 0.2 * s);
    p.velocity = mech_vec3_make(-0.1, 1.1 * c, 1.1 * s);
    CHECK(mech_trajectory_closed_form(&p, &b, &err) == MECH_OK);
    double worst = 0.0;
    for (size_t i = 0; i < NS; i++) {
        struct mech_vec3 rot = mech_vec3_make(R_[i].x, R_[i].y * c, R_[i].y * s);
        worst = fmax(worst, mech_vec3_norm(mech_vec3_sub(rot, R2[i])));
    }
    CHECK(worst < 1e-14);
}

static void test_refusals(void)
{
    struct mech_force f = {.type = MECH_FORCE_THIRD_BODY_TIDE};
    f.u.third_body_tide.gm = 1.0;
    f.u.third_body_tide.position = mech_vec3_make(10, 0, 0);
    struct mech_trajectory_problem p =
        problem(1.0, mech_vec3_make(1, 0, 0), mech_vec3_make(0, 1, 0), &f, 1, 1.0, 11);
    struct mech_trajectory_result r;
    result_init(&r, T_, R_, V_);
    struct mech_error err;
    CHECK(!mech_trajectory_has_closed_form(&p));
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_EINVAL);
    p.n_forces = 0; /* the free particle */
    CHECK(mech_trajectory_has_closed_form(&p));
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_OK);
    CHECK_CLOSE(R_[10].y, 1.0, 0, 0);
    p.mass = -1.0;
    mech_error_clear(&err);
    CHECK(mech_trajectory_closed_form(&p, &r, &err) == MECH_EDOMAIN);
    CHECK(!strcmp(err.param, "particle/mass"));
    if (strcmp(err.param, "particle/mass")) fprintf(stderr, "  [%s] %s\n", err.param, err.text);
}

/* A budget's deadline and cancel flag stop the samples; its step limit does
 * not (nothing is integrated). */
static void test_budget(void)
{
    struct mech_force f = {.type = MECH_FORCE_CENTRAL_GRAVITY};
    f.u.central_gravity.gm = 1.0;
    struct mech_trajectory_problem p =
        problem(1.0, mech_vec3_make(1, 0, 0), mech_vec3_make(0, 1, 0), &f, 1, 100.0, NS);
    struct mech_trajectory_result a;
    result_init(&a, T_, R_, V_);
    struct mech_error err;
    mech_error_clear(&err);
    struct mech_budget b = mech_budget_make(1, -1.0);
    CHECK_EQ_INT(mech_trajectory_closed_form_ex(&p, &a, NULL, &b, &err), MECH_EDEADLINE);
    CHECK(err.progress.t_target == 100.0);
    volatile int cancel = 1;
    b = mech_budget_make(1, 60.0);
    b.cancel = &cancel;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_trajectory_closed_form_ex(&p, &a, NULL, &b, &err), MECH_ECANCELLED);
    cancel = 0;
    mech_error_clear(&err);
    CHECK_EQ_INT(mech_trajectory_closed_form_ex(&p, &a, NULL, &b, &err), MECH_OK);
    CHECK_EQ_INT((int)a.n_samples, NS);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_budget();
    test_kepler();
    test_kepler_radial();
    test_kepler_event();
    test_oscillator_long();
    test_drag_small();
    test_drag_event();
    test_planar_vs_3d();
    test_refusals();
    TEST_MAIN_END();
}
