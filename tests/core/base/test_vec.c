/* test_vec.c — mech_vec3_norm (mech/base/vec.h) against long double at every
 * scale, and the trajectory force loop's fast path against its generic loop.
 *
 * mech_vec3_norm takes sqrt(x^2 + y^2 + z^2) where that sum is safely in
 * range and falls back to hypot otherwise. Checked against
 * sqrtl of the sum in long double (x87: 64-bit mantissa, exponent range to
 * 1e+-4932, so no square over/underflows for any double): random vectors
 * with independent exponents from 1e-320 to 1e300, tiny (1e-200) and huge
 * (1e200) vectors, subnormal components, the edges of the fast path's range,
 * exact Pythagorean triples scaled by 2^k, and inf / NaN / 0.
 *
 * Fast path of the force loop (core/frames/trajectory_fast.c simple_accel): a scene of
 * central gravity, uniform gravity, a spring and drag is integrated once as
 * is (fast path) and once with an extra lorentz force on an uncharged
 * particle, which contributes exactly 0 but sends the scene through the
 * generic force loop: the answers must agree bit for bit in 3-D, and to
 * round-off in a tilted plane (where the fast path projects the force
 * vectors once instead of expanding the state per evaluation).
 */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "mech/frames/trajectory.h"
#include "mech/base/constants.h"
#include "mech/base/vec.h"
#include "testlib.h"

static long double norm_ld(struct mech_vec3 a)
{
    long double x = a.x, y = a.y, z = a.z;
    return sqrtl(x * x + y * y + z * z);
}

/* |got - want| <= 2 ulp of want (want rounded to double first) */
static int norm_ok(struct mech_vec3 a)
{
    const double got = mech_vec3_norm(a);
    const long double want_ld = norm_ld(a);
    const double want = (double)want_ld;
    if (isinf(want)) return isinf(got) && got > 0;
    if (want == 0.0) return got == 0.0;
    /* for subnormal results the absolute round-off is 2^-1074 */
    const double tol = fmax(2.0 * DBL_EPSILON * want, 0x1p-1074);
    const int ok = fabsl((long double)got - want_ld) <= tol;
    if (!ok)
        fprintf(stderr, "norm(%.17g, %.17g, %.17g) = %.17g, want %.21Lg\n", a.x, a.y, a.z, got,
                want_ld);
    return ok;
}

/* xorshift64*: reproducible random numbers */
static uint64_t rng_state = 0x9e3779b97f4a7c15ull;
static double rnd01(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545f4914f6cdd1dull) >> 11) * 0x1p-53;
}
/* +-m 10^e, e uniform in [lo, hi], m in [1, 10) */
static double rnd_scaled(double lo, double hi)
{
    double e = lo + (hi - lo) * rnd01();
    double v = (1.0 + 9.0 * rnd01()) * pow(10.0, floor(e));
    return rnd01() < 0.5 ? -v : v;
}

static void test_norm_random(void)
{
    int bad = 0;
    /* components of independent scale over the whole range */
    for (int i = 0; i < 20000; i++) {
        struct mech_vec3 a = mech_vec3_make(rnd_scaled(-320, 300), rnd_scaled(-320, 300),
                                            rnd_scaled(-320, 300));
        bad += !norm_ok(a);
    }
    /* components of one scale (the common case), every decade */
    for (int e = -320; e <= 300; e += 5)
        for (int i = 0; i < 40; i++) {
            struct mech_vec3 a = mech_vec3_make(rnd_scaled(e, e + 1), rnd_scaled(e, e + 1),
                                                rnd_scaled(e, e + 1));
            bad += !norm_ok(a);
        }
    CHECK_EQ_INT(bad, 0);
}

static void test_norm_extremes(void)
{
    /* tiny and huge: the naive sum of squares underflows to 0 / overflows */
    CHECK(norm_ok(mech_vec3_make(1e-200, 2e-200, -3e-200)));
    CHECK(norm_ok(mech_vec3_make(1e200, -2e200, 3e200)));
    CHECK_CLOSE(mech_vec3_norm(mech_vec3_make(1e-200, 1e-200, 1e-200)), sqrt(3.0) * 1e-200,
                2 * DBL_EPSILON, 0);
    CHECK_CLOSE(mech_vec3_norm(mech_vec3_make(1e200, 1e200, 1e200)), sqrt(3.0) * 1e200,
                2 * DBL_EPSILON, 0);
    CHECK(norm_ok(mech_vec3_make(1e200, 1e-200, 0.0)));
    CHECK(norm_ok(mech_vec3_make(1.5e154, 1.5e154, 1.5e154))); /* sum just over DBL_MAX */
    CHECK(norm_ok(mech_vec3_make(1e-154, 1e-154, 0.0)));       /* sum near DBL_MIN */
    CHECK(norm_ok(mech_vec3_make(0x1p-484, 0x1p-485, 0x1p-486))); /* sum near 2^-968 */
    CHECK(norm_ok(mech_vec3_make(0x1p-484, 0x1p-600, 0x1p-1074))); /* one subnormal square */
    /* exact: (3, 4, 12) 2^k has norm 13 2^k, at every k where it is representable */
    int inexact = 0;
    for (int k = -1070; k <= 1019; k++) {
        struct mech_vec3 a = mech_vec3_make(ldexp(3.0, k), ldexp(4.0, k), ldexp(12.0, k));
        if (mech_vec3_norm(a) != ldexp(13.0, k)) inexact++;
    }
    CHECK_EQ_INT(inexact, 0);
    CHECK(mech_vec3_norm(mech_vec3_make(DBL_MAX, 0.0, 0.0)) == DBL_MAX);
    CHECK(mech_vec3_norm(mech_vec3_make(0.0, -DBL_MAX, 0.0)) == DBL_MAX);
    CHECK(mech_vec3_norm(mech_vec3_make(0x1p-1074, 0.0, 0.0)) == 0x1p-1074);
    CHECK(mech_vec3_norm(mech_vec3_make(3 * 0x1p-1074, 4 * 0x1p-1074, 0.0)) == 5 * 0x1p-1074);
    CHECK(isinf(mech_vec3_norm(mech_vec3_make(DBL_MAX, DBL_MAX, 0.0)))); /* true norm > DBL_MAX */
    CHECK(mech_vec3_norm(mech_vec3_make(0.0, -0.0, 0.0)) == 0.0);
    CHECK(isinf(mech_vec3_norm(mech_vec3_make(INFINITY, 1.0, 0.0))));
    CHECK(isinf(mech_vec3_norm(mech_vec3_make(NAN, -INFINITY, 0.0)))); /* as hypot */
    CHECK(isnan(mech_vec3_norm(mech_vec3_make(1.0, NAN, 2.0))));
}

/* ---- the force loop's fast path against the generic loop ----------------- */

enum { NS = 41 };

static void run(const struct mech_trajectory_problem *p, struct mech_trajectory_result *r,
                struct mech_vec3 *pos, struct mech_vec3 *vel)
{
    memset(r, 0, sizeof *r);
    r->position = pos;
    r->velocity = vel;
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    struct mech_error err;
    mech_error_clear(&err);
    enum mech_status st = mech_trajectory_integrate(p, &b, r, &err);
    if (st != MECH_OK) fprintf(stderr, "integrate: %s\n", err.text);
    CHECK(st == MECH_OK);
}

/* Scene in the plane spanned by e1, e2: central gravity at the origin, a
 * spring anchored in the plane, uniform gravity in the plane, weak drag. */
static void scene(struct mech_force *f, struct mech_vec3 e1, struct mech_vec3 e2,
                  struct mech_trajectory_problem *p, const char *method, int planar)
{
    memset(f, 0, 5 * sizeof *f);
    f[0].type = MECH_FORCE_CENTRAL_GRAVITY;
    f[0].u.central_gravity.gm = 1.0;
    f[1].type = MECH_FORCE_SPRING;
    f[1].u.spring.k = 0.01;
    f[1].u.spring.rest_length = 0.3;
    f[1].u.spring.anchor = mech_vec3_add(mech_vec3_scale(e1, 0.2), mech_vec3_scale(e2, -0.1));
    f[2].type = MECH_FORCE_UNIFORM_GRAVITY;
    f[2].u.uniform_gravity.g = mech_vec3_add(mech_vec3_scale(e1, 0.001), mech_vec3_scale(e2, 0.002));
    f[3].type = MECH_FORCE_LINEAR_DRAG;
    f[3].u.linear_drag.b = 1e-3;
    /* f[4]: a lorentz force on an uncharged particle: exactly 0 */
    f[4].type = MECH_FORCE_LORENTZ;
    f[4].u.lorentz.E = mech_vec3_make(0.3, -0.2, 0.1);
    f[4].u.lorentz.B = mech_vec3_make(0.0, 0.5, 0.0);
    memset(p, 0, sizeof *p);
    p->mass = 1.0;
    p->charge = 0.0;
    p->position = mech_vec3_scale(e1, 0.5);
    p->velocity = mech_vec3_scale(e2, 1.6);
    p->frame.type = MECH_FRAME_INERTIAL;
    p->forces = f;
    p->n_forces = 4;
    p->t_end = 5 * 2 * MECH_PI;
    p->samples = NS;
    p->method = method;
    p->opt.rtol = 1e-10;
    p->opt.atol = 1e-12;
    p->opt.dt = 0.01; /* verlet */
    p->reduce_planar = planar;
}

static void test_fast_path_matches_generic(const char *method, int planar, struct mech_vec3 e1,
                                           struct mech_vec3 e2, double rel)
{
    struct mech_force f[5];
    struct mech_trajectory_problem p;
    scene(f, e1, e2, &p, method, planar);
    static struct mech_vec3 pa[NS], va[NS], pb[NS], vb[NS];
    struct mech_trajectory_result fast, generic;
    run(&p, &fast, pa, va);
    p.n_forces = 5; /* + the zero lorentz force: not a fast-path scene */
    run(&p, &generic, pb, vb);
    CHECK_EQ_INT(fast.dimensions, planar ? 2 : 3);
    CHECK_EQ_INT(generic.dimensions, planar ? 2 : 3);
    CHECK_EQ_INT(fast.stats.steps, generic.stats.steps);
    CHECK_EQ_INT(fast.n_samples, NS);
    double worst = 0.0;
    for (int i = 0; i < NS; i++)
        worst = fmax(worst, fmax(mech_vec3_norm(mech_vec3_sub(pa[i], pb[i])),
                                 mech_vec3_norm(mech_vec3_sub(va[i], vb[i]))));
    if (rel == 0.0) CHECK(worst == 0.0);
    else CHECK(worst <= rel);
    if (!(rel == 0.0 ? worst == 0.0 : worst <= rel))
        fprintf(stderr, "%s planar=%d: fast vs generic differ by %.3g\n", method, planar, worst);
    /* the observer's figures: term sizes, drift. In the plane they are
     * maxima over the step ends, and the step sizes move with the error
     * estimate's round-off (h ~ err^(-1/8), err ~1e-10 computed to ~1e-16:
     * ~1e-7 relative), so they agree to that, not to the samples' 1e-9. */
    for (int k = 0; k < 4; k++)
        CHECK_CLOSE(fast.terms[k].max_acceleration, generic.terms[k].max_acceleration,
                    rel == 0.0 ? 0.0 : 1e-5, 0.0);
    CHECK_CLOSE(fast.invariant.max_relative_drift, generic.invariant.max_relative_drift,
                rel == 0.0 ? 0.0 : 1e-3, rel == 0.0 ? 0.0 : 1e-14);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_norm_random();
    test_norm_extremes();
    const struct mech_vec3 ex = mech_vec3_make(1, 0, 0), ey = mech_vec3_make(0, 1, 0);
    /* a tilted plane: e1, e2 orthonormal, no coordinate axis in it */
    const struct mech_vec3 t1 = mech_vec3_make(2.0 / 3.0, 2.0 / 3.0, 1.0 / 3.0);
    const struct mech_vec3 t2 = mech_vec3_make(-2.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0);
    const char *methods[] = {"rk8pd", "radau15", "verlet", "rkf45"};
    for (int m = 0; m < 4; m++) {
        test_fast_path_matches_generic(methods[m], 0, ex, ey, 0.0); /* 3-D: bit for bit */
        test_fast_path_matches_generic(methods[m], 0, t1, t2, 0.0);
        test_fast_path_matches_generic(methods[m], 1, t1, t2, 1e-9); /* plane: round-off */
    }
    TEST_MAIN_END();
}
