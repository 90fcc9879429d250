/* test_boost.c — Lorentz boosts (core/relativity/boost.c) against closed forms, the
 * notes' worked examples (muon §3.4, twin paradox §3.14), a second method
 * (composition of collinear boosts: rapidities add, notes §3.9/§3.10) and an
 * independent long-double evaluation. Extremes: 1 m/s, 1 − β = 1e-15,
 * η = 35, overflow; every error path. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/boost.h"
#include "mech/base/constants.h"
#include "testlib.h"

static const double C_LIGHT = MECH_C; /* m/s, exact by definition */

/* Worst figures seen, printed at the end so the report can quote them. */
static double worst_lightlike, worst_invariant, worst_normwise, worst_small;

static struct mech_vec3 ex(void)
{
    return mech_vec3_make(1, 0, 0);
}

static double max_abs4(const double *x)
{
    return fmax(fmax(fabs(x[0]), fabs(x[1])), fmax(fabs(x[2]), fabs(x[3])));
}

/* Reference boost in long double (64-bit significand), matrix form, with
 * γ and βγ from coshl/sinhl of the rapidity (independent of boost.c). */
static void ref_boost(long double eta, const long double n[3], const double x[4],
                      long double out[4])
{
    long double g = coshl(eta), bg = sinhl(eta);
    long double xp = n[0] * x[1] + n[1] * x[2] + n[2] * x[3];
    long double x0p = g * x[0] - bg * xp;
    long double xpp = g * xp - bg * x[0];
    out[0] = x0p;
    for (int i = 0; i < 3; i++)
        out[1 + i] = x[1 + i] + (xpp - xp) * n[i];
}

static void test_one_metre_per_second(void)
{
    /* β = 1/299792458: γ − 1 = β²/2 + 3β⁴/8 + 5β⁶/16 + ... (≈ 5.563e-18). The
     * naive 1/sqrt(1 − β²) − 1 gives exactly 0 here (numerics.md). */
    double b = 1.0 / C_LIGHT;
    double b2 = b * b;
    double want = b2 / 2 + 3 * b2 * b2 / 8 + 5 * b2 * b2 * b2 / 16;
    struct mech_boost k;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(b, 0, 0), &k, NULL), MECH_OK);
    CHECK_CLOSE(k.gamma_minus_one, want, 1e-15, 0);
    CHECK(1.0 / sqrt(1.0 - b * b) - 1.0 == 0.0); /* why the careful form matters */
    CHECK(k.gamma == 1.0);                       /* 1 + 5.6e-18, correctly rounded */
    CHECK_CLOSE(k.beta, b, 1e-16, 0);
    CHECK_CLOSE(k.beta_gamma, b * (1 + b2 / 2), 1e-15, 0);
    CHECK_CLOSE(k.rapidity, b + b * b2 / 3, 1e-15, 0); /* atanh β */
    CHECK_CLOSE(k.one_minus_beta, 1.0 - b, 1e-16, 0);
    worst_small = fmax(worst_small, fabs(k.gamma_minus_one - want) / want);

    /* The same speed given as a rapidity η = atanh β: γ − 1 = 2 sinh²(η/2). */
    struct mech_boost kr;
    double eta = atanhl((long double)b);
    CHECK_EQ_INT(mech_boost_from_rapidity(eta, mech_vec3_make(0, 0, 2), &kr, NULL), MECH_OK);
    CHECK_CLOSE(kr.gamma_minus_one, want, 1e-15, 0);
    worst_small = fmax(worst_small, fabs(kr.gamma_minus_one - want) / want);

    /* A clock at x = 1e-10 m, ct = 1 m: x' = γ(x − β ct) ≈ −3.3356e-9 m, each
     * component right to round-off (no cancellation is inherent here). */
    double x[4] = {1.0, 1e-10, 0.25, -3.0}, out[4];
    CHECK_EQ_INT(mech_boost_apply(&k, x, out, NULL, NULL, NULL), MECH_OK);
    long double n[3] = {1, 0, 0}, r[4];
    ref_boost(atanhl((long double)b), n, x, r);
    for (int i = 0; i < 4; i++) {
        CHECK_CLOSE(out[i], (double)r[i], 1e-15, 0);
        worst_small = fmax(worst_small, fabsl(out[i] - r[i]) / fabsl(r[i]));
    }
}

static void test_one_minus_beta(void)
{
    /* γ = 1/sqrt(ε(2 − ε)), e^{η} = sqrt((2 − ε)/ε), η = ½ log((2 − ε)/ε). */
    const double eps_list[] = {1e-15, 1e-12, 1e-8, 1e-3, 0.25, 0.5, 1.0, 1.5, 1.999999, 1e-300};
    for (size_t i = 0; i < sizeof eps_list / sizeof eps_list[0]; i++) {
        double e = eps_list[i];
        long double el = e;
        struct mech_boost k;
        CHECK_EQ_INT(mech_boost_from_one_minus_beta(e, ex(), &k, NULL), MECH_OK);
        long double omb = e <= 1 ? el : 2 - el; /* 1 − |β| */
        long double bl = 1 - omb;
        long double g = 1 / sqrtl(omb * (2 - omb));
        CHECK_CLOSE(k.gamma, (double)g, 1e-15, 0);
        CHECK_CLOSE(k.beta_gamma, (double)(bl * g), 1e-15, 0);
        CHECK_CLOSE(k.gamma_minus_one, (double)(bl * bl * g / (1 + 1 / g)), 1e-15, 0);
        CHECK_CLOSE(k.one_minus_beta, (double)omb, 1e-16, 0);
        CHECK_CLOSE(k.exp_rapidity, (double)sqrtl((2 - omb) / omb), 1e-15, 0);
        CHECK_CLOSE(k.exp_neg_rapidity, (double)sqrtl(omb / (2 - omb)), 1e-15, 0);
        CHECK_CLOSE(k.rapidity, (double)(0.5L * logl((2 - omb) / omb)), 1e-15, 1e-300);
        CHECK_CLOSE(k.direction.x, e <= 1 ? 1.0 : -1.0, 0, 0);
    }
    /* The headline case: γ at ε = 1e-15 (the double 1.00000000000000008e-15)
     * is 22360679.774997901685 (50-digit Decimal evaluation of 1/sqrt(ε(2 − ε))). */
    struct mech_boost k;
    CHECK_EQ_INT(mech_boost_from_one_minus_beta(1e-15, ex(), &k, NULL), MECH_OK);
    CHECK_CLOSE(k.gamma, 22360679.774997901685, 2.2e-16, 0);
    CHECK_CLOSE(k.beta_gamma, 22360679.774997879325, 2.2e-16, 0);
}

static void test_rapidity_35(void)
{
    struct mech_boost k;
    CHECK_EQ_INT(mech_boost_from_rapidity(35.0, ex(), &k, NULL), MECH_OK);
    CHECK_CLOSE(k.gamma, (double)coshl(35.0L), 1e-15, 0);
    CHECK_CLOSE(k.gamma_minus_one, (double)(coshl(35.0L) - 1), 1e-15, 0);
    CHECK_CLOSE(k.beta_gamma, (double)sinhl(35.0L), 1e-15, 0);
    CHECK_CLOSE(k.one_minus_beta, (double)(2 / (expl(70.0L) + 1)), 1e-15, 0);
    CHECK_CLOSE(k.exp_neg_rapidity, (double)expl(-35.0L), 1e-15, 0);
    CHECK_CLOSE(k.beta, 1.0, 1e-16, 0);
    /* γ from the rapidity, the other constructors agree at the same η. */
    struct mech_boost kg, ke;
    CHECK_EQ_INT(mech_boost_from_gamma(k.gamma, ex(), &kg, NULL), MECH_OK);
    CHECK_CLOSE(kg.rapidity, 35.0, 1e-15, 0);
    CHECK_EQ_INT(mech_boost_from_one_minus_beta(k.one_minus_beta, ex(), &ke, NULL), MECH_OK);
    CHECK_CLOSE(ke.gamma, k.gamma, 1e-15, 0);
    CHECK_CLOSE(ke.rapidity, 35.0, 1e-15, 0);
    /* Small rapidity: γ − 1 = η²/2 + η⁴/24. */
    CHECK_EQ_INT(mech_boost_from_rapidity(1e-9, ex(), &k, NULL), MECH_OK);
    CHECK_CLOSE(k.gamma_minus_one, 0.5e-18 + 1e-36 / 24, 1e-15, 0);
    CHECK_CLOSE(k.one_minus_beta, 1 - 1e-9, 1e-16, 0);
}

/* Light-like vectors along ±n: the light-cone components scale exactly,
 * (1, ±n) → e^{∓η}(1, ±n). Each component to 1e-14 relative at η = 35. */
static void test_lightlike(void)
{
    const struct mech_vec3 dirs[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0, 3, 0}};
    const double etas[] = {35.0, 20.0, 1.0, 1e-6};
    for (size_t d = 0; d < 4; d++)
        for (size_t e = 0; e < 4; e++) {
            struct mech_boost k;
            CHECK_EQ_INT(mech_boost_from_rapidity(etas[e], dirs[d], &k, NULL), MECH_OK);
            struct mech_vec3 n = k.direction;
            for (int s = -1; s <= 1; s += 2) {
                double x[4] = {2.5, 2.5 * s * n.x, 2.5 * s * n.y, 2.5 * s * n.z}, out[4];
                double ib, ia;
                CHECK_EQ_INT(mech_boost_apply(&k, x, out, &ib, &ia, NULL), MECH_OK);
                long double f = expl(-(long double)s * etas[e]);
                for (int i = 0; i < 4; i++) {
                    long double want = f * x[i];
                    if (x[i] == 0) {
                        CHECK(out[i] == 0);
                        continue;
                    }
                    CHECK_CLOSE(out[i], (double)want, 1e-14, 0);
                    worst_lightlike = fmax(worst_lightlike, fabsl(out[i] - want) / fabsl(want));
                }
                CHECK(ib == 0);
                CHECK(ia == 0);
            }
        }
    /* A light-like vector with a transverse part: (5, 3, 4, 0) along x at
     * η = 35: u = 2, v = 8 → x0' = e^{η} + 4e^{−η}, x' = 4e^{−η} − e^{η}, y' = 4. */
    struct mech_boost k;
    CHECK_EQ_INT(mech_boost_from_rapidity(35.0, ex(), &k, NULL), MECH_OK);
    double x[4] = {5, 3, 4, 0}, out[4], ib, ia;
    CHECK_EQ_INT(mech_boost_apply(&k, x, out, &ib, &ia, NULL), MECH_OK);
    CHECK_CLOSE(out[0], (double)(expl(35.0L) + 4 * expl(-35.0L)), 1e-15, 0);
    CHECK_CLOSE(out[1], (double)(4 * expl(-35.0L) - expl(35.0L)), 1e-15, 0);
    CHECK(out[2] == 4 && out[3] == 0);
    CHECK(ib == 0);
    CHECK_CLOSE(ia, 0, 0, 1e-14 * 25);
}

/* The clock at rest at the origin of the old frame: (ct, 0) → (γct, −βγct). */
static void test_rest_vector(void)
{
    struct mech_boost k;
    /* β = 0.6 is not a double; with the stored b, γ = 1/sqrt((1−b)(1+b)). */
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &k, NULL), MECH_OK);
    long double b = 0.6, g = 1 / sqrtl((1 - b) * (1 + b));
    double x[4] = {2, 0, 0, 0}, out[4], ib, ia;
    CHECK_EQ_INT(mech_boost_apply(&k, x, out, &ib, &ia, NULL), MECH_OK);
    CHECK_CLOSE(out[0], (double)(2 * g), 2e-16, 0);
    CHECK_CLOSE(out[1], (double)(-2 * b * g), 2e-16, 0);
    CHECK(out[2] == 0 && out[3] == 0);
    CHECK_CLOSE(out[0], 2.5, 1e-15, 0);  /* γ = 1.25 for β = 3/5 */
    CHECK_CLOSE(out[1], -1.5, 1e-15, 0); /* βγ = 0.75 */
    CHECK_CLOSE(ib, -4, 1e-16, 0);
    CHECK_CLOSE(ia, -4, 1e-15, 0);
    /* η = 35: (1, 0) → (cosh 35, −sinh 35), invariant −1 kept exactly. */
    CHECK_EQ_INT(mech_boost_from_rapidity(35.0, ex(), &k, NULL), MECH_OK);
    double y[4] = {1, 0, 0, 0};
    CHECK_EQ_INT(mech_boost_apply(&k, y, out, &ib, &ia, NULL), MECH_OK);
    CHECK_CLOSE(out[0], (double)coshl(35.0L), 1e-15, 0);
    CHECK_CLOSE(out[1], (double)-sinhl(35.0L), 1e-15, 0);
    CHECK_CLOSE(ia, -1, 1e-15, 0);
    /* The naive invariant from the boosted components is garbage there. */
    CHECK(fabs(-out[0] * out[0] + out[1] * out[1] + 1) > 1e-3);
}

/* Deterministic pseudo-random numbers in [-1, 1). */
static unsigned long long lcg_state = 12345;
static double rnd(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) / 9007199254740992.0 * 2 - 1;
}

/* Generic vectors and directions, η from 1e-9 to 35: the invariant after the
 * boost equals the one before to 1e-13 of the largest input component
 * squared; the invariant before matches long double; the components match a
 * long-double matrix boost normwise (error ≤ 1e-14 of the largest output or
 * input component, the best a rounded e^{±η} allows). */
static void test_invariants_and_normwise(void)
{
    const double etas[] = {1e-9, 1e-4, 0.3, 1.0, 5.0, 12.0, 35.0};
    for (size_t e = 0; e < sizeof etas / sizeof etas[0]; e++)
        for (int trial = 0; trial < 200; trial++) {
            struct mech_vec3 d = mech_vec3_make(rnd(), rnd(), rnd());
            if (trial % 4 == 0) d = mech_vec3_make(0, 0, 1);
            struct mech_boost k;
            if (mech_boost_from_rapidity(etas[e], d, &k, NULL) != MECH_OK) {
                CHECK(0);
                continue;
            }
            double scale = pow(10.0, 40 * rnd());
            double x[4] = {scale * rnd(), scale * rnd(), scale * rnd(), scale * rnd()}, out[4];
            if (trial % 3 == 0) { /* near the light cone */
                x[0] = sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
            }
            double ib, ia;
            CHECK_EQ_INT(mech_boost_apply(&k, x, out, &ib, &ia, NULL), MECH_OK);
            double m2 = max_abs4(x) * max_abs4(x);
            long double ibl = -(long double)x[0] * x[0] + (long double)x[1] * x[1] +
                              (long double)x[2] * x[2] + (long double)x[3] * x[3];
            CHECK_CLOSE(ib, (double)ibl, 1e-15, 1e-18 * m2);
            CHECK_CLOSE(ia, ib, 0, 1e-13 * m2);
            worst_invariant = fmax(worst_invariant, fabs(ia - ib) / m2);

            long double n[3] = {k.direction.x, k.direction.y, k.direction.z}, r[4];
            ref_boost(k.rapidity, n, x, r);
            double big = fmax(max_abs4(out), max_abs4(x));
            for (int i = 0; i < 4; i++) {
                CHECK_CLOSE(out[i], (double)r[i], 0, 1e-14 * big);
                worst_normwise = fmax(worst_normwise, (double)(fabsl(out[i] - r[i]) / big));
            }
        }
}

/* Collinear boosts compose by adding rapidities (notes §3.9–3.10). */
static void test_composition(void)
{
    struct mech_boost k1, k2, k12;
    struct mech_vec3 d = mech_vec3_make(1, 2, -2);
    CHECK_EQ_INT(mech_boost_from_rapidity(0.3, d, &k1, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_rapidity(0.45, d, &k2, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_rapidity(0.75, d, &k12, NULL), MECH_OK);
    double x[4] = {3.0, -1.0, 0.5, 2.0}, mid[4], a[4], b[4];
    CHECK_EQ_INT(mech_boost_apply(&k1, x, mid, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&k2, mid, a, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&k12, x, b, NULL, NULL, NULL), MECH_OK);
    for (int i = 0; i < 4; i++)
        CHECK_CLOSE(a[i], b[i], 0, 1e-15 * max_abs4(b) * 4);

    /* Velocity addition from β: 0.6 ⊕ 0.8 = 1.4/1.48 (γ = 1.25·5/3·1.48 = 37/12). */
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &k1, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.8, 0, 0), &k2, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(1.4 / 1.48, 0, 0), &k12, NULL), MECH_OK);
    CHECK_CLOSE(k1.rapidity + k2.rapidity, k12.rapidity, 1e-15, 0);
    CHECK_CLOSE(k12.gamma, 37.0 / 12.0, 1e-15, 0);
    CHECK_EQ_INT(mech_boost_apply(&k1, x, mid, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&k2, mid, a, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&k12, x, b, NULL, NULL, NULL), MECH_OK);
    for (int i = 0; i < 4; i++)
        CHECK_CLOSE(a[i], b[i], 0, 1e-14 * max_abs4(b));

    /* At η = 17.5 + 17.5 = 35, on the light cone, composition stays exact. */
    CHECK_EQ_INT(mech_boost_from_rapidity(17.5, ex(), &k1, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_rapidity(35, ex(), &k12, NULL), MECH_OK);
    double l[4] = {1, 1, 0, 0};
    CHECK_EQ_INT(mech_boost_apply(&k1, l, mid, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&k1, mid, a, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&k12, l, b, NULL, NULL, NULL), MECH_OK);
    CHECK_CLOSE(a[0], b[0], 1e-15, 0);
    CHECK_CLOSE(a[1], b[1], 1e-15, 0);
}

static void test_inverse(void)
{
    const double etas[] = {1e-9, 0.5, 3.0};
    for (size_t e = 0; e < 3; e++) {
        struct mech_boost k;
        CHECK_EQ_INT(mech_boost_from_rapidity(etas[e], mech_vec3_make(0.3, -0.4, 1.2), &k, NULL),
                     MECH_OK);
        struct mech_boost ki = mech_boost_inverse(&k);
        double x[4] = {1.5, -0.7, 2.25, 0.1}, y[4], z[4];
        CHECK_EQ_INT(mech_boost_apply(&k, x, y, NULL, NULL, NULL), MECH_OK);
        CHECK_EQ_INT(mech_boost_apply(&ki, y, z, NULL, NULL, NULL), MECH_OK);
        /* The intermediate is e^{η} larger; round-off scales with it twice. */
        double tol = 1e-15 * exp(2 * etas[e]) * max_abs4(x) * 8;
        for (int i = 0; i < 4; i++)
            CHECK_CLOSE(z[i], x[i], 0, tol);
    }
    /* Light-like at η = 35 comes back to relative round-off. */
    struct mech_boost k;
    CHECK_EQ_INT(mech_boost_from_rapidity(35, ex(), &k, NULL), MECH_OK);
    struct mech_boost ki = mech_boost_inverse(&k);
    CHECK_CLOSE(ki.beta_vec.x, -k.beta, 0, 0);
    double l[4] = {1, 1, 0, 0}, y[4], z[4];
    CHECK_EQ_INT(mech_boost_apply(&k, l, y, NULL, NULL, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&ki, y, z, NULL, NULL, NULL), MECH_OK);
    CHECK_CLOSE(z[0], 1, 1e-15, 0);
    CHECK_CLOSE(z[1], 1, 1e-15, 0);
}

/* Notes §3.4: a muon with τ = 2 µs at β = 0.9999 lives γτ ≈ 140 µs in the
 * earth frame and travels βγcτ ≈ 42 km. In its rest frame the earth moves at
 * −βc, so the boost to the earth frame has β = (−0.9999, 0, 0), and the decay
 * event (cτ, 0, 0, 0) → (γcτ, βγcτ, 0, 0); (ct)² − x² = (cτ)² is kept. */
static void test_muon(void)
{
    const double tau = 2e-6, b = 0.9999;
    struct mech_boost k;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(-b, 0, 0), &k, NULL), MECH_OK);
    long double bl = b, g = 1 / sqrtl((1 - bl) * (1 + bl));
    CHECK_CLOSE(k.gamma, (double)g, 1e-15, 0);
    CHECK_CLOSE(k.gamma, 70.71244595, 1e-9, 0); /* 1/sqrt(1 − 0.9999²) */
    double x[4] = {C_LIGHT * tau, 0, 0, 0}, out[4], ib, ia;
    CHECK_EQ_INT(mech_boost_apply(&k, x, out, &ib, &ia, NULL), MECH_OK);
    CHECK_CLOSE(out[0] / C_LIGHT, (double)(g * tau), 1e-15, 0);
    CHECK_CLOSE(out[1], (double)(bl * g * C_LIGHT * tau), 1e-15, 0);
    CHECK_CLOSE(out[0] / C_LIGHT, 140e-6, 0.02, 0); /* the notes' "about 140 µs" */
    CHECK_CLOSE(out[1], 42e3, 0.02, 0);             /* the notes' "42 kilometers" */
    CHECK_CLOSE(ia, -(C_LIGHT * tau) * (C_LIGHT * tau), 1e-15, 0);
    CHECK_CLOSE(ib, ia, 1e-15, 0);
}

/* Notes §3.14: 8 light years at 0.8c; the earth twin ages 20 years, the
 * astronaut 12. Each leg (10 y, ±8 ly) seen from the ship's frame is
 * (6 y, 0): the astronaut's clock sits at the origin of that frame. Units:
 * years and light years (c = 1). Doppler factor e^{−η} = sqrt(0.2/1.8) = 1/3. */
static void test_twin(void)
{
    struct mech_boost out_leg, back_leg;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.8, 0, 0), &out_leg, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(-0.8, 0, 0), &back_leg, NULL), MECH_OK);
    CHECK_CLOSE(out_leg.gamma, 5.0 / 3.0, 1e-15, 0);
    CHECK_CLOSE(out_leg.exp_neg_rapidity, 1.0 / 3.0, 1e-15, 0);
    double leg1[4] = {10, 8, 0, 0}, leg2[4] = {10, -8, 0, 0}, a[4], b[4], ia1, ia2;
    CHECK_EQ_INT(mech_boost_apply(&out_leg, leg1, a, NULL, &ia1, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply(&back_leg, leg2, b, NULL, &ia2, NULL), MECH_OK);
    CHECK_CLOSE(a[0], 6, 1e-15, 0);
    CHECK_CLOSE(a[1], 0, 0, 1e-14);
    CHECK_CLOSE(b[0], 6, 1e-15, 0);
    CHECK_CLOSE(b[1], 0, 0, 1e-14);
    CHECK_CLOSE(a[0] + b[0], 12, 1e-15, 0);   /* astronaut ages 12 years */
    CHECK_CLOSE(leg1[0] + leg2[0], 20, 0, 0); /* earth twin ages 20 */
    CHECK_CLOSE(ia1, -36, 1e-15, 0);          /* proper time² of a leg */
    CHECK_CLOSE(ia2, -36, 1e-15, 0);
}

/* β, (η, n), (γ, n) and (1 − β, n) describing the same boost agree; the
 * inputs are rounded, so they agree to that rounding times γ² at most. */
static void test_forms_agree(void)
{
    const double etas[] = {1e-6, 0.4, 2.5, 18.0};
    struct mech_vec3 d = mech_vec3_make(2, -1, 2); /* |d| = 3 */
    for (size_t e = 0; e < 4; e++) {
        double eta = etas[e];
        struct mech_boost kr, kb, kg, ke;
        CHECK_EQ_INT(mech_boost_from_rapidity(eta, d, &kr, NULL), MECH_OK);
        double b = tanh(eta);
        CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(2 * b / 3, -b / 3, 2 * b / 3), &kb, NULL),
                     MECH_OK);
        CHECK_EQ_INT(mech_boost_from_gamma(cosh(eta), d, &kg, NULL), MECH_OK);
        CHECK_EQ_INT(mech_boost_from_one_minus_beta(2 / (exp(2 * eta) + 1), d, &ke, NULL), MECH_OK);
        double g2 = kr.gamma * kr.gamma;
        const struct mech_boost *ks[3] = {&kb, &kg, &ke};
        for (int j = 0; j < 3; j++) {
            /* β from a rounded tanh only resolves η to ε/(1 − β²) = εγ²; a
             * rounded γ or 1 − β near 1 resolves small η only coarsely. */
            int coarse = (j == 0 && eta > 15) || (j >= 1 && eta < 1e-3);
            if (!coarse) {
                CHECK_CLOSE(ks[j]->rapidity, eta, 1e-15 * g2, 0);
                CHECK_CLOSE(ks[j]->gamma, kr.gamma, 1e-15 * g2, 0);
                CHECK_CLOSE(ks[j]->exp_rapidity, kr.exp_rapidity, 1e-15 * g2, 0);
                /* γ − 1 = γ − 1 of a rounded γ carries that rounding. */
                CHECK_CLOSE(ks[j]->gamma_minus_one, kr.gamma_minus_one, 1e-15 * g2,
                            j == 1 ? 2.3e-16 * kr.gamma : 0);
            } else {
                /* β = tanh 18 rounds to 1 − 4ε: γ is then 2 % off (numerics.md). */
                CHECK_CLOSE(ks[j]->gamma, kr.gamma, j == 0 ? 0.05 : 1e-15, 0);
            }
            CHECK_CLOSE(ks[j]->direction.x, kr.direction.x, 2e-16, 0);
            CHECK_CLOSE(ks[j]->direction.y, kr.direction.y, 2e-16, 0);
            CHECK_CLOSE(ks[j]->direction.z, kr.direction.z, 2e-16, 0);
        }
        CHECK_CLOSE(kr.direction.x, 2.0 / 3.0, 2e-16, 0);
        CHECK_CLOSE(kr.beta_vec.y, -b / 3, 4e-16, 0);
    }
    /* Negative rapidity = the opposite direction. */
    struct mech_boost kn, kp;
    CHECK_EQ_INT(mech_boost_from_rapidity(-1.5, ex(), &kn, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_from_rapidity(1.5, mech_vec3_make(-4, 0, 0), &kp, NULL), MECH_OK);
    CHECK(memcmp(&kn, &kp, sizeof kn) == 0);
    CHECK(kn.rapidity == 1.5 && kn.direction.x == -1);
    /* β = 0 is the identity. */
    struct mech_boost k0;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0, 0, 0), &k0, NULL), MECH_OK);
    double x[4] = {1, 2, 3, 4}, y[4];
    CHECK_EQ_INT(mech_boost_apply(&k0, x, y, NULL, NULL, NULL), MECH_OK);
    CHECK(memcmp(x, y, sizeof x) == 0);
    CHECK(k0.gamma == 1 && k0.gamma_minus_one == 0 && k0.rapidity == 0 && k0.one_minus_beta == 1);
}

static void expect_error(enum mech_status got, const struct mech_error *e, enum mech_status want,
                         const char *param)
{
    CHECK_EQ_INT(got, want);
    CHECK_EQ_INT(e->code, want);
    if (strcmp(e->param, param) != 0) {
        tl_failed++;
        fprintf(stderr, "error param '%s', want '%s'\n", e->param, param);
    } else {
        tl_passed++;
    }
    CHECK(e->text[0] != '\0');
}

static void test_errors(void)
{
    struct mech_boost k;
    struct mech_error e;
    struct mech_vec3 zero = mech_vec3_make(0, 0, 0);
#define TRY(call, want, param)                                                                     \
    do {                                                                                           \
        mech_error_clear(&e);                                                                      \
        expect_error((call), &e, (want), (param));                                                 \
    } while (0)
    TRY(mech_boost_from_beta(mech_vec3_make(1, 0, 0), &k, &e), MECH_EDOMAIN, "beta");
    TRY(mech_boost_from_beta(mech_vec3_make(0.6, 0.8, 0), &k, &e), MECH_EDOMAIN, "beta");
    TRY(mech_boost_from_beta(mech_vec3_make(0, -1.5, 0), &k, &e), MECH_EDOMAIN, "beta");
    TRY(mech_boost_from_beta(mech_vec3_make(NAN, 0, 0), &k, &e), MECH_EINVAL, "beta");
    TRY(mech_boost_from_gamma(0.5, ex(), &k, &e), MECH_EDOMAIN, "gamma");
    TRY(mech_boost_from_gamma(-3, ex(), &k, &e), MECH_EDOMAIN, "gamma");
    TRY(mech_boost_from_gamma(INFINITY, ex(), &k, &e), MECH_EINVAL, "gamma");
    TRY(mech_boost_from_gamma(1e200, ex(), &k, &e), MECH_EINVAL, "gamma");
    TRY(mech_boost_from_gamma(2, zero, &k, &e), MECH_EINVAL, "direction");
    TRY(mech_boost_from_one_minus_beta(0, ex(), &k, &e), MECH_EDOMAIN, "one_minus_beta");
    TRY(mech_boost_from_one_minus_beta(-1e-15, ex(), &k, &e), MECH_EDOMAIN, "one_minus_beta");
    TRY(mech_boost_from_one_minus_beta(2, ex(), &k, &e), MECH_EDOMAIN, "one_minus_beta");
    TRY(mech_boost_from_one_minus_beta(1e-310, ex(), &k, &e), MECH_EINVAL, "one_minus_beta");
    TRY(mech_boost_from_one_minus_beta(0.5, zero, &k, &e), MECH_EINVAL, "direction");
    TRY(mech_boost_from_rapidity(1, zero, &k, &e), MECH_EINVAL, "direction");
    TRY(mech_boost_from_rapidity(1, mech_vec3_make(NAN, 1, 0), &k, &e), MECH_EINVAL, "direction");
    TRY(mech_boost_from_rapidity(351, ex(), &k, &e), MECH_EINVAL, "rapidity");
    TRY(mech_boost_from_rapidity(NAN, ex(), &k, &e), MECH_EINVAL, "rapidity");
    /* NULL error record is allowed. */
    CHECK_EQ_INT(mech_boost_from_gamma(0.5, ex(), &k, NULL), MECH_EDOMAIN);

    /* Extreme but valid: the largest boost and the tiniest direction. */
    CHECK_EQ_INT(mech_boost_from_rapidity(350, mech_vec3_make(0, 1e-320, 0), &k, NULL), MECH_OK);
    CHECK(k.direction.y == 1 && k.one_minus_beta > 0 && isfinite(k.gamma));
    CHECK_EQ_INT(mech_boost_from_rapidity(1, mech_vec3_make(1e308, 1e308, -1e308), &k, NULL),
                 MECH_OK);
    CHECK_CLOSE(k.direction.x, 1 / sqrt(3.0), 2e-16, 0);

    /* Overflow of a result is a typed error naming the vector. */
    double xs[12] = {1, 0, 0, 0, 1e150, 1e150, 0, 0, -1e300, 1e300, 0, 0}, out[12];
    double ib[3], ia[3];
    struct mech_budget bud = mech_budget_make(1000, 10.0);
    CHECK_EQ_INT(mech_boost_from_rapidity(350, ex(), &k, NULL), MECH_OK);
    TRY(mech_boost_apply_batch(&k, xs, out, ib, ia, 3, &bud, &e), MECH_ENUMERIC, "vectors/2");
    double bad[4] = {NAN, 0, 0, 0};
    TRY(mech_boost_apply(&k, bad, out, NULL, NULL, &e), MECH_ENUMERIC, "vectors");

    /* Batch: same as one at a time; budget exhaustion is reported. */
    CHECK_EQ_INT(mech_boost_from_rapidity(0.7, mech_vec3_make(1, 1, 0), &k, NULL), MECH_OK);
    double ys[12] = {1, 2, 3, 4, -1, 0.5, 0, 2, 7, 7, 0, 0}, one[4], ib1, ia1;
    CHECK_EQ_INT(mech_boost_apply_batch(&k, ys, out, ib, ia, 3, &bud, NULL), MECH_OK);
    for (int i = 0; i < 3; i++) {
        CHECK_EQ_INT(mech_boost_apply(&k, ys + 4 * i, one, &ib1, &ia1, NULL), MECH_OK);
        CHECK(memcmp(one, out + 4 * i, sizeof one) == 0 && ib1 == ib[i] && ia1 == ia[i]);
    }
    CHECK_EQ_INT(mech_boost_apply_batch(&k, ys, ys, NULL, NULL, 3, &bud, NULL), MECH_OK);
    CHECK(memcmp(ys, out, sizeof ys) == 0); /* in place */
    struct mech_budget small = mech_budget_make(2, 10.0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_boost_apply_batch(&k, xs, out, NULL, NULL, 3, &small, &e), MECH_EBUDGET);
    CHECK_EQ_INT(e.progress.steps, 2);
    volatile int cancel = 1;
    struct mech_budget cancelled = mech_budget_make(1000, 10.0);
    cancelled.cancel = &cancel;
    CHECK_EQ_INT(mech_boost_apply_batch(&k, xs, out, NULL, NULL, 3, &cancelled, NULL),
                 MECH_ECANCELLED);
    CHECK_EQ_INT(mech_boost_apply_batch(&k, xs, out, NULL, NULL, 3, NULL, NULL), MECH_EINVAL);
    CHECK_EQ_INT(mech_boost_apply_batch(&k, NULL, NULL, NULL, NULL, 0, &bud, NULL), MECH_OK);
#undef TRY
}

/* The batch is built twice (with and without FMA instructions, chosen at load
 * time) and checks its budget only every 256 vectors: neither may change a
 * bit. Compare it with mech_boost_apply (plain build, libm's fma) over 4000
 * vectors of every scale, oblique directions and rapidities from 1e-8 to 35;
 * and the step budget must still stop it after exactly max_steps vectors. */
static void test_batch_equals_single(void)
{
    enum { N = 4000 };
    static double x[4 * N], out[4 * N];
    double ib[N], ia[N], one[4], ib1, ia1;
    unsigned long long s = 88172645463325252ULL;
    for (int i = 0; i < 4 * N; i++) {
        s ^= s << 13, s ^= s >> 7, s ^= s << 17; /* xorshift64 */
        double u = (double)(s >> 11) / 9007199254740992.0 - 0.5;
        x[i] = u * pow(10.0, (double)((int)(s % 41) - 20));
    }
    const double etas[] = {1e-8, 0.7, 5.0, 35.0};
    struct mech_budget bud = mech_budget_make(10 * N, 60.0);
    for (int k = 0; k < 4; k++) {
        struct mech_boost b;
        CHECK_EQ_INT(mech_boost_from_rapidity(etas[k], mech_vec3_make(0.3, -0.8, 0.52), &b, NULL),
                     MECH_OK);
        CHECK_EQ_INT(mech_boost_apply_batch(&b, x, out, ib, ia, N, &bud, NULL), MECH_OK);
        int same = 1;
        for (int i = 0; i < N; i++) {
            CHECK_EQ_INT(mech_boost_apply(&b, x + 4 * i, one, &ib1, &ia1, NULL), MECH_OK);
            same &= memcmp(one, out + 4 * i, sizeof one) == 0 &&
                    memcmp(&ib1, ib + i, sizeof ib1) == 0 && memcmp(&ia1, ia + i, sizeof ia1) == 0;
        }
        CHECK(same);
    }
    struct mech_boost b;
    CHECK_EQ_INT(mech_boost_from_rapidity(0.7, mech_vec3_make(1, 0, 0), &b, NULL), MECH_OK);
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget small = mech_budget_make(300, 60.0);
    CHECK_EQ_INT(mech_boost_apply_batch(&b, x, out, NULL, NULL, N, &small, &e), MECH_EBUDGET);
    CHECK_EQ_INT(e.progress.steps, 300);
    small.max_steps = 256; /* exactly at a periodic check: all 256 fit */
    CHECK_EQ_INT(mech_boost_apply_batch(&b, x, out, NULL, NULL, 256, &small, NULL), MECH_OK);
    CHECK_EQ_INT(mech_boost_apply_batch(&b, x, out, NULL, NULL, 257, &small, NULL), MECH_EBUDGET);
}

/* The Lorentz matrix (notes §3 "A Boost in an Arbitrary Direction"):
 * β = (0.6, 0, 0): [[1.25, -0.75, 0, 0], [-0.75, 1.25, 0, 0], I] exactly;
 * an oblique β = (0.3, -0.4, 0.5): Λ x equals mech_boost_apply's x', Λ
 * preserves the metric (Λᵀ η Λ = η) and Λ(β) Λ(−β) = I to round-off; at
 * 1 m/s, Λ01 = −βγ = −3.3356409519815205e-9 (decimal) to round-off. */
static void test_matrix(void)
{
    struct mech_boost b;
    double m[4][4];
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &b, NULL), MECH_OK);
    mech_boost_matrix(&b, m);
    const double want[4][4] = {{1.25, -0.75, 0, 0}, {-0.75, 1.25, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) CHECK_CLOSE(m[i][j], want[i][j], 4e-16, 1e-16);

    struct mech_boost o, inv;
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(0.3, -0.4, 0.5), &o, NULL), MECH_OK);
    inv = mech_boost_inverse(&o);
    double L[4][4], Li[4][4];
    mech_boost_matrix(&o, L);
    mech_boost_matrix(&inv, Li);
    const double x[4] = {2.0, -1.0, 0.5, 3.0};
    double xp[4];
    CHECK_EQ_INT(mech_boost_apply(&o, x, xp, NULL, NULL, NULL), MECH_OK);
    const double eta[4] = {-1, 1, 1, 1};
    for (int i = 0; i < 4; i++) {
        double y = 0;
        for (int k = 0; k < 4; k++) y += L[i][k] * x[k];
        CHECK_CLOSE(y, xp[i], 0, 1e-14);
        for (int j = 0; j < 4; j++) {
            double g = 0, id = 0;
            for (int k = 0; k < 4; k++) {
                g += L[k][i] * eta[k] * L[k][j];
                id += L[i][k] * Li[k][j];
            }
            CHECK_CLOSE(g, i == j ? eta[i] : 0.0, 0, 1e-14);
            CHECK_CLOSE(id, i == j ? 1.0 : 0.0, 0, 1e-14);
        }
    }
    CHECK_EQ_INT(mech_boost_from_beta(mech_vec3_make(1.0 / MECH_C, 0, 0), &b, NULL), MECH_OK);
    mech_boost_matrix(&b, m);
    CHECK_CLOSE(b.gamma_minus_one, 5.5632502802680922e-18, 1e-15, 0);
    CHECK_CLOSE(m[0][1], -3.3356409519815205e-09, 1e-15, 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_one_metre_per_second();
    test_one_minus_beta();
    test_rapidity_35();
    test_lightlike();
    test_rest_vector();
    test_invariants_and_normwise();
    test_composition();
    test_inverse();
    test_muon();
    test_twin();
    test_forms_agree();
    test_errors();
    test_batch_equals_single();
    test_matrix();
    printf("worst: gamma-1/components at 1 m/s %.3g rel; light-like at eta<=35 %.3g rel; "
           "|inv_after - inv_before| %.3g of max|x|^2; components vs long double %.3g of "
           "max component\n",
           worst_small, worst_lightlike, worst_invariant, worst_normwise);
    TEST_MAIN_END();
}
