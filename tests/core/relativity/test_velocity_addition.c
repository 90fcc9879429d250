/* test_velocity_addition.c — velocity addition (core/relativity/velocity_addition.c)
 * against the notes' formulas (§3.10 u∥' = (u∥ − v)/(1 − v u∥),
 * u⊥' = u⊥/(γ(1 − v u∥))), against an independent long-double 4x4 boost of
 * the 4-velocity, collinear rapidity arithmetic at the extremes (1e-12 c,
 * 1 − β = 1e-15, γ = 1e15), light (aberration), and the Wigner rotation's
 * closed form against the polar decomposition of the 4x4 matrix product. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/velocity_addition.h"
#include "testlib.h"

static double worst_gm1, worst_dir, worst_wigner, worst_rot;

static struct mech_boost from_beta(double x, double y, double z)
{
    struct mech_boost b;
    mech_boost_from_beta(mech_vec3_make(x, y, z), &b, NULL);
    return b;
}

/* Long-double passive boost matrix of velocity tanh(eta) n (notes §3.9). */
static void ld_boost(long double eta, const long double n[3], long double M[4][4])
{
    long double g = coshl(eta), bg = sinhl(eta);
    M[0][0] = g;
    for (int i = 0; i < 3; i++) {
        M[0][i + 1] = M[i + 1][0] = -bg * n[i];
        for (int j = 0; j < 3; j++)
            M[i + 1][j + 1] = (i == j) + (g - 1) * n[i] * n[j];
    }
}

static void ld_from(const struct mech_boost *b, long double M[4][4])
{
    long double n[3] = {b->direction.x, b->direction.y, b->direction.z};
    long double len = sqrtl(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; i++)
        n[i] /= len;
    ld_boost(atanhl((long double)b->beta), n, M);
}

static void ld_mul(long double A[4][4], long double B[4][4], long double C[4][4])
{
    long double T[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            T[i][j] = 0;
            for (int k = 0; k < 4; k++)
                T[i][j] += A[i][k] * B[k][j];
        }
    memcpy(C, T, sizeof T);
}

static void test_notes_examples(void)
{
    /* 0.5c seen from a frame moving at −0.5c: (0.5 + 0.5)/(1 + 0.25) = 0.8. */
    struct mech_boost o = from_beta(0.5, 0, 0), f = from_beta(-0.5, 0, 0), r;
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    CHECK_CLOSE(r.beta_vec.x, 0.8, 2e-16, 0);
    CHECK_CLOSE(r.gamma, 5.0 / 3.0, 2e-16, 0);
    CHECK_CLOSE(r.gamma_minus_one, 2.0 / 3.0, 4e-16, 0);
    CHECK_CLOSE(r.one_minus_beta, 0.2, 1e-15, 0);
    CHECK_CLOSE(r.rapidity, log(3.0), 2e-16, 0);
    /* Transverse (notes §3.10): u = 0.6 ŷ, v = 0.8 x̂: u' = (−0.8, 0.6·0.6, 0),
     * γ' = γ_u γ_v = 1.25 · 5/3 = 25/12. */
    o = from_beta(0, 0.6, 0);
    f = from_beta(0.8, 0, 0);
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    CHECK_CLOSE(r.beta_vec.x, -0.8, 4e-16, 0);
    CHECK_CLOSE(r.beta_vec.y, 0.36, 4e-16, 0);
    CHECK(r.beta_vec.z == 0);
    CHECK_CLOSE(r.gamma, 25.0 / 12.0, 4e-16, 0);
    CHECK_CLOSE(r.gamma_minus_one, 13.0 / 12.0, 1e-15, 0);
}

/* The textbook fraction and the long-double 4x4 boost of the 4-velocity agree
 * with the rapidity form for random velocities at moderate speeds. */
static void test_random_directions(void)
{
    unsigned s = 12345;
    for (int trial = 0; trial < 300; trial++) {
        double v[6];
        for (int i = 0; i < 6; i++) {
            s = s * 1103515245u + 12345u;
            v[i] = ((s >> 8) & 0xffff) / 65536.0 * 1.1 - 0.55;
        }
        struct mech_boost o = from_beta(v[0], v[1], v[2]), f = from_beta(v[3], v[4], v[5]), r;
        if (o.beta >= 0.95 || f.beta >= 0.95) continue;
        CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
        long double M[4][4], u[4], up[4] = {0, 0, 0, 0};
        ld_from(&f, M);
        long double go = 1.0L / sqrtl(1.0L - (long double)o.beta * o.beta);
        long double n[3] = {o.direction.x, o.direction.y, o.direction.z};
        u[0] = go;
        for (int i = 0; i < 3; i++)
            u[i + 1] = go * (long double)o.beta * n[i];
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 4; k++)
                up[i] += M[i][k] * u[k];
        long double p2 = up[1] * up[1] + up[2] * up[2] + up[3] * up[3];
        long double gm1 = p2 / (up[0] + 1);
        CHECK_CLOSE(r.gamma_minus_one, (double)gm1, 4e-15, 0);
        worst_gm1 = fmax(worst_gm1, fabs(r.gamma_minus_one - (double)gm1) / (double)gm1);
        for (int i = 0; i < 3; i++) {
            double want = (double)(up[i + 1] / up[0]);
            double got = mech_vec3_get(r.beta_vec, i);
            CHECK_CLOSE(got, want, 0, 1e-15);
            worst_dir = fmax(worst_dir, fabs(got - want));
        }
        /* Notes §3.10 along the frame's direction: the fraction form. */
        double vv = f.beta, ux = mech_vec3_dot(o.beta_vec, f.direction);
        double par = mech_vec3_dot(r.beta_vec, f.direction);
        CHECK_CLOSE(par, (ux - vv) / (1 - vv * ux), 1e-14, 1e-15);
    }
}

static void test_collinear_extremes(void)
{
    struct mech_boost o, f, r;
    struct mech_vec3 x = mech_vec3_make(1, 0, 0), mx = mech_vec3_make(-1, 0, 0);
    /* Rapidities subtract exactly: 20 and 20 + 1e-12 (both doubles; their
     * difference is exact by Sterbenz) give η' = the double difference. */
    double a = 20.000000000001, b = 20.0;
    mech_boost_from_rapidity(a, x, &o, NULL);
    mech_boost_from_rapidity(b, x, &f, NULL);
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    double d = a - b;
    CHECK_CLOSE(r.rapidity, d, 1e-15, 0);
    CHECK_CLOSE(r.gamma_minus_one, 2 * sinh(d / 2) * sinh(d / 2), 1e-15, 0);
    CHECK_CLOSE(r.beta_vec.x, tanh(d), 1e-15, 0);
    worst_gm1 = fmax(worst_gm1, fabs(r.gamma_minus_one / (2 * sinh(d / 2) * sinh(d / 2)) - 1));
    /* Opposite directions: rapidities add; γ = 1e15 each: η' = 2 acosh(1e15). */
    mech_boost_from_gamma(1e15, x, &o, NULL);
    mech_boost_from_gamma(1e15, mx, &f, NULL);
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    long double eta = 2 * acoshl(1e15L);
    CHECK_CLOSE(r.rapidity, (double)eta, 1e-15, 0);
    CHECK_CLOSE(r.gamma, (double)coshl(eta), 2e-15, 0);
    CHECK_CLOSE(r.one_minus_beta, (double)(2 / (expl(2 * eta) + 1)), 4e-15, 0);
    CHECK(r.beta_vec.x > 0 && r.beta_vec.x <= 1);
    /* 1e-12 c seen from −1e-12 c: β' = 2e-12/(1 + 1e-24); γ' − 1 = 2 sinh²(η'/2),
     * η' = 2 atanh(1e-12) — the naive form gives 0. */
    o = from_beta(1e-12, 0, 0);
    f = from_beta(-1e-12, 0, 0);
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    long double e2 = 2 * atanhl(1e-12L);
    double want = (double)(2 * sinhl(e2 / 2) * sinhl(e2 / 2));
    CHECK_CLOSE(r.gamma_minus_one, want, 1e-15, 0);
    CHECK_CLOSE(r.beta_vec.x, 2e-12 / (1 + 1e-24), 1e-15, 0);
    worst_gm1 = fmax(worst_gm1, fabs(r.gamma_minus_one - want) / want);
    /* 1 − β = 1e-15 seen from a frame at 0.5c along it: η' = η − atanh(0.5). */
    mech_boost_from_one_minus_beta(1e-15, x, &o, NULL);
    f = from_beta(0.5, 0, 0);
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    long double eo = 0.5L * logl((2 - 1e-15L) / 1e-15L), ep = eo - atanhl(0.5L);
    CHECK_CLOSE(r.rapidity, (double)ep, 1e-15, 0);
    CHECK_CLOSE(r.one_minus_beta, (double)(2 / (expl(2 * ep) + 1)), 4e-15, 0);
    CHECK_CLOSE(r.gamma_minus_one, (double)(coshl(ep) - 1), 2e-15, 0);
    /* γ = 1e15 both, directions 1e-8 rad apart: γ' − 1 = sinh²η (1 − cos θ)
     * (the first term vanishes): about 5e13, a huge cancellation for the naive
     * γγ(1 − β·β). */
    double th = 1e-8;
    struct mech_vec3 d2 = mech_vec3_make(cos(th), sin(th), 0);
    mech_boost_from_gamma(1e15, x, &o, NULL);
    mech_boost_from_gamma(1e15, d2, &f, NULL);
    CHECK_EQ_INT(mech_velocity_add(&o, &f, &r, NULL), MECH_OK);
    long double thl = atan2l((long double)sin(th), (long double)cos(th));
    long double sh2 = 1e30L - 1; /* sinh²η = γ² − 1 */
    long double wantl = sh2 * 2 * sinl(thl / 2) * sinl(thl / 2);
    CHECK_CLOSE(r.gamma_minus_one, (double)wantl, 1e-14, 0);
    worst_gm1 = fmax(worst_gm1, fabs(r.gamma_minus_one - (double)wantl) / (double)wantl);
    /* Same velocity: at rest exactly. */
    mech_boost_from_beta(mech_vec3_make(0.3, -0.2, 0.1), &o, NULL);
    CHECK_EQ_INT(mech_velocity_add(&o, &o, &r, NULL), MECH_OK);
    CHECK(r.gamma_minus_one == 0 && r.beta == 0);
}

static void test_light(void)
{
    struct mech_boost f = from_beta(0.6, 0, 0);
    struct mech_vec3 k;
    double ratio;
    /* Light along y, frame at 0.6 x: k' = (−β, 1/γ, 0), ν'/ν = γ. */
    CHECK_EQ_INT(mech_velocity_add_light(mech_vec3_make(0, 2, 0), &f, &k, &ratio, NULL), MECH_OK);
    CHECK_CLOSE(k.x, -0.6, 4e-16, 0);
    CHECK_CLOSE(k.y, 0.8, 4e-16, 0);
    CHECK_CLOSE(ratio, 1.25, 4e-16, 0);
    /* Along the motion: ν'/ν = sqrt((1 − β)/(1 + β)) = 0.5 (notes §3.14). */
    CHECK_EQ_INT(mech_velocity_add_light(mech_vec3_make(1, 0, 0), &f, &k, &ratio, NULL), MECH_OK);
    CHECK_CLOSE(ratio, 0.5, 4e-16, 0);
    CHECK(k.x == 1 && k.y == 0 && k.z == 0);
    /* Approaching × receding = 1, and at γ = 1e15 the redshift e^{−η} keeps
     * full relative precision. */
    struct mech_boost g;
    mech_boost_from_gamma(1e15, mech_vec3_make(0, 0, 1), &g, NULL);
    double r1, r2;
    CHECK_EQ_INT(mech_velocity_add_light(mech_vec3_make(0, 0, 1), &g, &k, &r1, NULL), MECH_OK);
    CHECK_EQ_INT(mech_velocity_add_light(mech_vec3_make(0, 0, -1), &g, &k, &r2, NULL), MECH_OK);
    long double bgl = sqrtl(1e30L - 1);
    CHECK_CLOSE(r1, (double)(1 / (1e15L + bgl)), 4e-16, 0);
    CHECK_CLOSE(r2, (double)(1e15L + bgl), 4e-16, 0);
    CHECK_CLOSE(r1 * r2, 1.0, 4e-16, 0);
    CHECK(k.z == -1);
    CHECK_EQ_INT(mech_velocity_add_light(mech_vec3_make(0, 0, 0), &g, &k, &r1, NULL), MECH_EINVAL);
}

/* Closed-form Wigner angle/axis against the polar decomposition of the long
 * double 4x4 product, and a chain of three boosts against the full product. */
static void test_wigner(void)
{
    unsigned s = 777;
    for (int trial = 0; trial < 200; trial++) {
        double v[9];
        for (int i = 0; i < 9; i++) {
            s = s * 1103515245u + 12345u;
            v[i] = ((s >> 8) & 0xffff) / 65536.0 * 1.1 - 0.55;
        }
        int n = 2 + trial % 2;
        struct mech_boost b[3];
        for (int i = 0; i < 3; i++)
            b[i] = from_beta(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        if (b[0].beta > 0.95 || b[1].beta > 0.95 || b[2].beta > 0.95) continue;
        struct mech_boost_composition comp;
        struct mech_budget bud = mech_budget_make(100, 10);
        CHECK_EQ_INT(mech_boost_compose(b, (size_t)n, &bud, &comp, NULL), MECH_OK);
        long double L[4][4], M[4][4];
        ld_from(&b[0], L);
        for (int i = 1; i < n; i++) {
            ld_from(&b[i], M);
            ld_mul(M, L, L);
        }
        /* Λ = R B(β_t): the first row of Λ is B's: γ_t, −γ_t β_t. */
        long double gt = L[0][0], bt[3], btn = 0;
        for (int i = 0; i < 3; i++) {
            bt[i] = -L[0][i + 1] / gt;
            btn += bt[i] * bt[i];
        }
        btn = sqrtl(btn);
        for (int i = 0; i < 3; i++) {
            CHECK_CLOSE(comp.total.beta_vec.x * (i == 0) + comp.total.beta_vec.y * (i == 1) +
                            comp.total.beta_vec.z * (i == 2),
                        (double)bt[i], 0, 1e-15);
        }
        CHECK_CLOSE(comp.total.gamma, (double)gt, 1e-15, 0);
        long double nt[3] = {bt[0] / btn, bt[1] / btn, bt[2] / btn};
        ld_boost(-atanhl(btn), nt, M); /* B(β_t)^{-1} */
        ld_mul(L, M, M);               /* R = Λ B^{-1} */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                CHECK_CLOSE(comp.rotation.a[i][j], (double)M[i + 1][j + 1], 0, 1e-14);
                worst_rot = fmax(worst_rot, fabs(comp.rotation.a[i][j] - (double)M[i + 1][j + 1]));
            }
        /* Angle from the trace of the long-double R, and the axis from its
         * antisymmetric part (A = R^T turns the axes). */
        long double tr = M[1][1] + M[2][2] + M[3][3];
        long double ang = acosl((tr - 1) / 2);
        CHECK_CLOSE(comp.angle, (double)ang, 1e-9, 1e-13);
        if (n == 2) {
            double eps;
            struct mech_vec3 ax;
            CHECK_EQ_INT(mech_wigner_rotation(&b[0], &b[1], &eps, &ax, NULL), MECH_OK);
            CHECK_CLOSE(eps, comp.angle, 1e-14, 1e-16);
            worst_wigner = fmax(worst_wigner, fabs(eps - (double)ang) / (double)ang);
            long double ax_ld[3] = {(M[2][3] - M[3][2]) / (2 * sinl(ang)),
                                    (M[3][1] - M[1][3]) / (2 * sinl(ang)),
                                    (M[1][2] - M[2][1]) / (2 * sinl(ang))};
            CHECK_CLOSE(ax.x, (double)ax_ld[0], 0, 1e-10);
            CHECK_CLOSE(ax.y, (double)ax_ld[1], 0, 1e-10);
            CHECK_CLOSE(ax.z, (double)ax_ld[2], 0, 1e-10);
        }
    }
    /* Small velocities: ε → ½ |β1 × β2| (Thomas precession limit); here
     * ε = 2 atan(t1 t2) with t = tanh(atanh(1e-6)/2), to relative precision. */
    struct mech_boost a = from_beta(1e-6, 0, 0), b = from_beta(0, 1e-6, 0);
    double eps;
    struct mech_vec3 ax;
    CHECK_EQ_INT(mech_wigner_rotation(&a, &b, &eps, &ax, NULL), MECH_OK);
    long double t = tanhl(atanhl(1e-6L) / 2);
    CHECK_CLOSE(eps, (double)(2 * atanl(t * t)), 1e-15, 0);
    CHECK(ax.x == 0 && ax.y == 0 && ax.z == -1); /* second × first = ŷ × x̂ = −ẑ */
    struct mech_boost pair[2] = {a, b};
    struct mech_boost_composition comp;
    struct mech_budget bud = mech_budget_make(100, 10);
    CHECK_EQ_INT(mech_boost_compose(pair, 2, &bud, &comp, NULL), MECH_OK);
    CHECK_CLOSE(comp.angle, (double)(2 * atanl(t * t)), 1e-12, 0);
}

static void test_compose_identities(void)
{
    struct mech_budget bud = mech_budget_make(100, 10);
    struct mech_boost_composition comp;
    /* Collinear: rapidities add (notes §3.9): 1.5 + 2.25 − 0.75 = 3. */
    struct mech_vec3 d = mech_vec3_make(1, 2, -2);
    struct mech_boost b[3];
    mech_boost_from_rapidity(1.5, d, &b[0], NULL);
    mech_boost_from_rapidity(2.25, d, &b[1], NULL);
    mech_boost_from_rapidity(-0.75, d, &b[2], NULL);
    CHECK_EQ_INT(mech_boost_compose(b, 3, &bud, &comp, NULL), MECH_OK);
    CHECK_CLOSE(comp.total.rapidity, 3.0, 2e-16, 0);
    CHECK_CLOSE(comp.total.gamma_minus_one, cosh(3.0) - 1, 4e-16, 0);
    CHECK(comp.angle == 0);
    CHECK_CLOSE(comp.total.direction.y, 2.0 / 3.0, 4e-16, 0);
    /* Large collinear: 17.5 + 17.5 = 35 (γ ≈ 8e14). */
    mech_boost_from_rapidity(17.5, d, &b[0], NULL);
    b[1] = b[0];
    CHECK_EQ_INT(mech_boost_compose(b, 2, &bud, &comp, NULL), MECH_OK);
    CHECK_CLOSE(comp.total.rapidity, 35.0, 4e-16, 0);
    CHECK_CLOSE(comp.total.one_minus_beta, 2 / (exp(70.0) + 1), 2e-15, 0);
    /* There and back: identity (exactly zero γ − 1 and angle). */
    b[0] = from_beta(0.3, -0.5, 0.7);
    b[1] = mech_boost_inverse(&b[0]);
    CHECK_EQ_INT(mech_boost_compose(b, 2, &bud, &comp, NULL), MECH_OK);
    CHECK(comp.total.gamma_minus_one == 0);
    CHECK(comp.angle == 0);
    CHECK(comp.rotation.a[0][0] == 1 && comp.rotation.a[1][1] == 1 && comp.rotation.a[0][1] == 0);
    /* Beyond rapidity 350: a typed error naming the boost. */
    mech_boost_from_rapidity(300, d, &b[0], NULL);
    b[1] = b[0];
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_boost_compose(b, 2, &bud, &comp, &e), MECH_ENUMERIC);
    CHECK(strcmp(e.param, "boosts/1") == 0);
    /* Budget: 1 step allowed, 3 boosts → EBUDGET. */
    struct mech_budget small = mech_budget_make(1, 10);
    b[0] = b[1] = b[2] = from_beta(0.1, 0, 0);
    CHECK_EQ_INT(mech_boost_compose(b, 3, &small, &comp, NULL), MECH_EBUDGET);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_notes_examples();
    test_random_directions();
    test_collinear_extremes();
    test_light();
    test_wigner();
    test_compose_identities();
    printf("worst relative gamma-1 error %.3g, worst beta component error %.3g, "
           "worst Wigner angle relative error %.3g, worst rotation element error %.3g\n",
           worst_gm1, worst_dir, worst_wigner, worst_rot);
    TEST_MAIN_END();
}
