/* boost.c — Lorentz boosts of 4-vectors with rapidity, γ − 1 and light-cone
 * components, so that 1 m/s, β = 1 − 1e-15 and η = 35 all keep full precision.
 *
 * Conventions (notes §3.3, §3.9): passive boost by velocity βc n,
 *   x0' = γ(x0 − β x∥),  x∥' = γ(x∥ − β x0),  x⊥' = x⊥,
 * with γ = cosh η, βγ = sinh η. In light-cone components u = x0 − x∥,
 * v = x0 + x∥ this is u' = γ(1 + β) u = e^{η} u, v' = γ(1 − β) v = e^{−η} v
 * (check: the event (ct, 0) goes to (γct, −βγct), as x' = γ(x − βct) says).
 * Precision recipes: notes/numerics.md "Special relativity in floating point".
 */
#include "mech/relativity/boost.h"
#include "mech/base/compensated.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

/* Unit vector along d, scaled first so hypot cannot overflow or lose
 * subnormal digits. Returns 0 if d is zero or not finite. */
static int unit_direction(struct mech_vec3 d, struct mech_vec3 *n)
{
    if (!mech_vec3_isfinite(d)) return 0;
    double m = fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
    if (m == 0) return 0;
    struct mech_vec3 s = mech_vec3_make(d.x / m, d.y / m, d.z / m);
    double len = mech_vec3_norm(s);
    *n = mech_vec3_make(s.x / len, s.y / len, s.z / len);
    return 1;
}

/* −v without producing −0 (so equal boosts compare equal bytewise). */
static struct mech_vec3 negated(struct mech_vec3 v)
{
    return mech_vec3_make(0.0 - v.x, 0.0 - v.y, 0.0 - v.z);
}

/* Fill every derived quantity from a speed b ≥ 0 given together with the
 * accurately known 1 − b and 1 + b (each exact or correctly rounded from the
 * caller's own number). 1 − β² = (1 − b)(1 + b) is never formed by
 * subtraction, so nothing cancels:
 *   s = sqrt(1 − b) sqrt(1 + b) = 1/γ; βγ = b/s;
 *   γ − 1 = b²/(s(1 + s))                      (numerics.md, exact rewrite of 1/s − 1)
 *   e^{±η} = sqrt((1 ± b)/(1 ∓ b));  η = atanh b = ½ log1p(2b/(1 − b)). */
static void from_speed(double b, double omb, double opb, struct mech_boost *o)
{
    double s = sqrt(omb) * sqrt(opb);
    o->beta = b;
    o->one_minus_beta = omb;
    o->beta_gamma = b / s;
    o->gamma_minus_one = (b / s) * (b / (1.0 + s));
    /* γ = 1 + (γ − 1) is correctly rounded while γ − 1 is small; 1/s is not. */
    o->gamma = o->gamma_minus_one < 1.0 ? 1.0 + o->gamma_minus_one : 1.0 / s;
    o->exp_rapidity = sqrt(opb / omb);
    o->exp_neg_rapidity = sqrt(omb / opb);
    o->rapidity = 0.5 * log1p(2.0 * b / omb);
}

static enum mech_status check_range(const struct mech_boost *o, const char *param,
                                    struct mech_error *err)
{
    if (!(o->rapidity <= MECH_BOOST_RAPIDITY_MAX) || !isfinite(o->gamma) ||
        !isfinite(o->exp_rapidity) || !(o->one_minus_beta >= DBL_MIN))
        return mech_error_set(err, MECH_EINVAL, param,
                              "rapidity %.17g is beyond the supported %g (gamma %.3g)", o->rapidity,
                              MECH_BOOST_RAPIDITY_MAX, o->gamma);
    return MECH_OK;
}

enum mech_status mech_boost_from_beta(struct mech_vec3 beta, struct mech_boost *out,
                                      struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output boost given");
    if (!mech_vec3_isfinite(beta))
        return mech_error_set(err, MECH_EINVAL, "beta", "beta must be finite");
    struct mech_boost o;
    double b = mech_vec3_norm(beta);
    if (!(b < 1.0))
        return mech_error_set(err, MECH_EDOMAIN, "beta",
                              "|beta| must be < 1 (the frame cannot reach the speed of light), "
                              "got %.17g",
                              b);
    if (b == 0) {
        o.direction = mech_vec3_make(1, 0, 0);
    } else if (!unit_direction(beta, &o.direction)) {
        return mech_error_set(err, MECH_EINVAL, "beta", "beta direction is undefined");
    }
    /* 1 − b is exact for b ≥ ½ (Sterbenz) and correctly rounded below. */
    from_speed(b, 1.0 - b, 1.0 + b, &o);
    o.beta_vec = beta;
    enum mech_status st = check_range(&o, "beta", err);
    if (st != MECH_OK) return st;
    *out = o;
    return MECH_OK;
}

enum mech_status mech_boost_from_rapidity(double eta, struct mech_vec3 direction,
                                          struct mech_boost *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output boost given");
    if (!isfinite(eta) || fabs(eta) > MECH_BOOST_RAPIDITY_MAX)
        return mech_error_set(err, MECH_EINVAL, "rapidity",
                              "rapidity must be finite with |rapidity| <= %g, got %.17g",
                              MECH_BOOST_RAPIDITY_MAX, eta);
    struct mech_boost o;
    if (!unit_direction(direction, &o.direction))
        return mech_error_set(err, MECH_EINVAL, "direction",
                              "direction must be a nonzero finite vector");
    if (eta < 0) o.direction = negated(o.direction);
    double a = fabs(eta);
    /* notes §3.9: tanh φ = β, cosh φ = γ, sinh φ = βγ. */
    o.rapidity = a;
    o.exp_rapidity = exp(a);
    o.exp_neg_rapidity = exp(-a);
    o.gamma = cosh(a);
    o.beta_gamma = sinh(a);
    o.beta = tanh(a);
    /* cosh η − 1 = 2 sinh²(η/2) below γ = 2; above, γ − 1 of the (correctly
     * rounded) cosh is exact and one rounding better. */
    double sh = sinh(0.5 * a);
    o.gamma_minus_one = o.gamma < 2.0 ? 2.0 * sh * sh : o.gamma - 1.0;
    o.one_minus_beta = o.exp_neg_rapidity / o.gamma; /* 1 − tanh η = e^{−η}/cosh η */
    o.beta_vec = mech_vec3_scale(o.direction, o.beta);
    enum mech_status st = check_range(&o, "rapidity", err);
    if (st != MECH_OK) return st;
    *out = o;
    return MECH_OK;
}

enum mech_status mech_boost_from_gamma(double gamma, struct mech_vec3 direction,
                                       struct mech_boost *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output boost given");
    if (!isfinite(gamma)) return mech_error_set(err, MECH_EINVAL, "gamma", "gamma must be finite");
    if (!(gamma >= 1.0))
        return mech_error_set(err, MECH_EDOMAIN, "gamma",
                              "gamma must be >= 1 (gamma = 1/sqrt(1 - beta^2)), got %.17g", gamma);
    struct mech_boost o;
    if (!unit_direction(direction, &o.direction))
        return mech_error_set(err, MECH_EINVAL, "direction",
                              "direction must be a nonzero finite vector");
    /* γ − 1 exact for γ ≤ 2 (Sterbenz); βγ = sqrt((γ − 1)(γ + 1)) without
     * forming γ² − 1; e^{η} = γ + βγ, e^{−η} = 1/(γ + βγ) (γ − βγ would cancel). */
    double gm1 = gamma - 1.0;
    double bg = sqrt(gm1) * sqrt(gamma + 1.0);
    double ep = gamma + bg;
    o.gamma = gamma;
    o.gamma_minus_one = gm1;
    o.beta_gamma = bg;
    o.beta = bg / gamma;
    o.exp_rapidity = ep;
    o.exp_neg_rapidity = 1.0 / ep;
    o.rapidity = log1p(gm1 + bg);
    /* 1 − β = (1 − β²)/(1 + β) = 1/(γ² (1 + β)) = 1/(γ e^{η}). */
    o.one_minus_beta = (1.0 / gamma) / ep;
    o.beta_vec = mech_vec3_scale(o.direction, o.beta);
    enum mech_status st = check_range(&o, "gamma", err);
    if (st != MECH_OK) return st;
    *out = o;
    return MECH_OK;
}

enum mech_status mech_boost_from_one_minus_beta(double one_minus_beta, struct mech_vec3 direction,
                                                struct mech_boost *out, struct mech_error *err)
{
    double e = one_minus_beta;
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output boost given");
    if (!isfinite(e))
        return mech_error_set(err, MECH_EINVAL, "one_minus_beta", "one_minus_beta must be finite");
    if (!(e > 0.0 && e < 2.0))
        return mech_error_set(err, MECH_EDOMAIN, "one_minus_beta",
                              "one_minus_beta must be in (0, 2) so that |beta| < 1, got %.17g", e);
    struct mech_boost o;
    if (!unit_direction(direction, &o.direction))
        return mech_error_set(err, MECH_EINVAL, "direction",
                              "direction must be a nonzero finite vector");
    double b, omb;
    if (e > 1.0) {
        /* β = 1 − ε < 0: speed ε − 1 along −n; both ε − 1 and 2 − ε are exact. */
        o.direction = negated(o.direction);
        b = e - 1.0;
        omb = 2.0 - e;
    } else {
        b = 1.0 - e; /* the double nearest β; exact for ε ≥ ½ */
        omb = e;     /* the caller's 1 − β, carried exactly */
    }
    from_speed(b, omb, 2.0 - omb, &o); /* 1 + β = 2 − (1 − β) */
    o.beta_vec = mech_vec3_scale(o.direction, o.beta);
    enum mech_status st = check_range(&o, "one_minus_beta", err);
    if (st != MECH_OK) return st;
    *out = o;
    return MECH_OK;
}

enum mech_status mech_boost_from_gamma_minus_one(double gamma_minus_one,
                                                 struct mech_vec3 direction,
                                                 struct mech_boost *out, struct mech_error *err)
{
    double gm1 = gamma_minus_one;
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output boost given");
    if (!isfinite(gm1))
        return mech_error_set(err, MECH_EINVAL, "gamma_minus_one", "gamma - 1 must be finite");
    if (!(gm1 >= 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "gamma_minus_one",
                              "gamma - 1 must be >= 0, got %.17g", gm1);
    struct mech_boost o;
    if (gm1 == 0.0) {
        if (!unit_direction(direction, &o.direction)) o.direction = mech_vec3_make(1, 0, 0);
    } else if (!unit_direction(direction, &o.direction)) {
        return mech_error_set(err, MECH_EINVAL, "direction",
                              "direction must be a nonzero finite vector");
    }
    /* βγ = sqrt(γ² − 1) = sqrt((γ − 1)(γ + 1)), never γ² − 1 by subtraction;
     * e^{η} = γ + βγ; 1 − β = 1/(γ² (1 + β)) = 1/(γ e^{η}) (as in from_gamma). */
    double bg = sqrt(gm1) * sqrt(gm1 + 2.0);
    o.gamma_minus_one = gm1;
    o.gamma = 1.0 + gm1;
    o.beta_gamma = bg;
    o.beta = bg / o.gamma;
    o.exp_rapidity = o.gamma + bg;
    o.exp_neg_rapidity = 1.0 / o.exp_rapidity;
    o.rapidity = log1p(gm1 + bg);
    o.one_minus_beta = (1.0 / o.gamma) / o.exp_rapidity;
    o.beta_vec = mech_vec3_scale(o.direction, o.beta);
    enum mech_status st = check_range(&o, "gamma_minus_one", err);
    if (st != MECH_OK) return st;
    *out = o;
    return MECH_OK;
}

struct mech_boost mech_boost_inverse(const struct mech_boost *b)
{
    struct mech_boost r = *b;
    r.direction = negated(b->direction);
    r.beta_vec = negated(b->beta_vec);
    return r;
}

/* ---- compensated arithmetic for invariants --------------------------------
 * Each product a·b is split exactly into hi + lo with fma (TwoProduct), and the
 * terms are added with Neumaier's compensated summation, so the sum is right
 * to about one rounding of the result plus n² ε² Σ|terms|. */

static inline __attribute__((always_inline)) double minkowski_square(const double x[4])
{
    struct mech_csum a = {0, 0};
    mech_csum_add_product(&a, -x[0], x[0]);
    mech_csum_add_product(&a, x[1], x[1]);
    mech_csum_add_product(&a, x[2], x[2]);
    mech_csum_add_product(&a, x[3], x[3]);
    return mech_csum_value(&a);
}

void mech_boost_matrix(const struct mech_boost *b, double m[4][4])
{
    const double n[3] = {b->direction.x, b->direction.y, b->direction.z};
    m[0][0] = b->gamma;
    for (int i = 0; i < 3; i++) {
        m[0][i + 1] = m[i + 1][0] = -b->beta_gamma * n[i];
        for (int j = 0; j < 3; j++)
            m[i + 1][j + 1] = (i == j ? 1.0 : 0.0) + b->gamma_minus_one * (n[i] * n[j]);
    }
}

double mech_minkowski_square(const double x[4])
{
    return minkowski_square(x);
}

/* ---- applying a boost ------------------------------------------------------ */

/* The boost of one 4-vector (no argument checks: the callers make them).
 * Returns 0 when done, 1 if the input is not finite, 2 if the result or an
 * invariant overflows; out and the invariants are written only on 0. Inline
 * so that a batch pays no call or error-record cost per vector. */
static inline __attribute__((always_inline)) int boost_one(const struct mech_boost *b, const double *x, double *out,
                            double *inv_before, double *inv_after)
{
    const double x0 = x[0];
    const struct mech_vec3 r = mech_vec3_make(x[1], x[2], x[3]);
    const struct mech_vec3 n = b->direction;
    if (!isfinite(x0) || !mech_vec3_isfinite(r)) return 1;
    const double gm1 = b->gamma_minus_one, bg = b->beta_gamma;
    const double ep = b->exp_rapidity, en = b->exp_neg_rapidity;

    /* Split r = x∥ n + x⊥, with x∥ = n·r as an unevaluated sum xp + xp_lo
     * (error-free products, compensated sum): near the light cone u = x0 − x∥
     * is small and later multiplied by e^{η}, so an ordinary dot product's
     * error ε|r| would be amplified. For n along an axis everything is exact. */
    struct mech_csum dot = {0, 0};
    mech_csum_add_product(&dot, n.x, r.x);
    mech_csum_add_product(&dot, n.y, r.y);
    mech_csum_add_product(&dot, n.z, r.z);
    const double xp = dot.s + dot.c;
    const double xp_lo = dot.c - (xp - dot.s);
    const struct mech_vec3 xperp =
        mech_vec3_make(fma(-xp, n.x, r.x) - xp_lo * n.x, fma(-xp, n.y, r.y) - xp_lo * n.y,
                       fma(-xp, n.z, r.z) - xp_lo * n.z);
    double before = 0;
    if (inv_before) before = minkowski_square(x);

    /* Light-cone form: u and v are (nearly) correctly rounded, and u' = e^{η}u,
     * v' = e^{−η}v keep that relative accuracy (numerics.md: they scale
     * exactly). Its error in x0' and x∥' is a few ulp of (|u'| + |v'|)/2
     * = max(|x0'|, |x∥'|): it cancels only where the answer itself is small
     * compared with the other boosted component. */
    const double u = (x0 - xp) - xp_lo, v = (x0 + xp) + xp_lo;
    const double up = ep * u, vp = en * v;
    const double x0_lc = 0.5 * (up + vp), xp_lc = 0.5 * (vp - up);
    const double err_lc = 0.5 * (fabs(up) + fabs(vp));

    /* γ − 1 form (notes §3.3 rewritten): x0' = x0 + [(γ − 1)x0 − βγ x∥],
     * x∥' = x∥ + [(γ − 1)x∥ − βγ x0]; its error is a few ulp of
     * (γ − 1)|own| + βγ|other| + |result|: far better at small η, where the
     * light-cone form would lose x∥ ≪ x0 in u and v. Per component, take the
     * form with the smaller error bound. */
    const double t0 = fma(gm1, x0, -(bg * xp));
    const double t1 = fma(gm1, xp, -(bg * x0));
    const double err_m0 = gm1 * fabs(x0) + bg * fabs(xp);
    const double err_m1 = gm1 * fabs(xp) + bg * fabs(x0);

    const double x0_new = err_m0 <= err_lc ? x0 + t0 : x0_lc;
    struct mech_vec3 r_new;
    if (err_m1 <= err_lc) {
        /* r' = r + (x∥' − x∥) n: each component is its input plus a small shift. */
        r_new = mech_vec3_make(fma(t1, n.x, r.x), fma(t1, n.y, r.y), fma(t1, n.z, r.z));
    } else {
        r_new = mech_vec3_make(fma(xp_lc, n.x, xperp.x), fma(xp_lc, n.y, xperp.y),
                               fma(xp_lc, n.z, xperp.z));
    }

    double after = 0;
    if (inv_after) {
        /* −x0'² + x∥'² + x⊥'² = −u'v' + |x⊥|² (notes §3.5; numerics.md: never from
         * the large boosted components). */
        struct mech_csum a = {0, 0};
        mech_csum_add_product(&a, -up, vp);
        mech_csum_add_product(&a, xperp.x, xperp.x);
        mech_csum_add_product(&a, xperp.y, xperp.y);
        mech_csum_add_product(&a, xperp.z, xperp.z);
        after = mech_csum_value(&a);
    }
    if (!isfinite(x0_new) || !mech_vec3_isfinite(r_new) || !isfinite(before) || !isfinite(after))
        return 2;
    out[0] = x0_new;
    out[1] = r_new.x;
    out[2] = r_new.y;
    out[3] = r_new.z;
    if (inv_before) *inv_before = before;
    if (inv_after) *inv_after = after;
    return 0;
}

/* The error record for a boost_one() failure code. */
static enum mech_status boost_one_error(const struct mech_boost *b, int code, const char *param,
                                        const char *prefix, struct mech_error *err)
{
    if (code == 1)
        return mech_error_set(err, MECH_ENUMERIC, param, "%s4-vector is not finite", prefix);
    return mech_error_set(err, MECH_ENUMERIC, param,
                          "%sboosted 4-vector or its invariant overflows (gamma %.3g)", prefix,
                          b->gamma);
}

enum mech_status mech_boost_apply(const struct mech_boost *b, const double x[4], double out[4],
                                  double *inv_before, double *inv_after, struct mech_error *err)
{
    if (!b || !x || !out)
        return mech_error_set(err, MECH_EINVAL, NULL, "boost, input and output are required");
    int code = boost_one(b, x, out, inv_before, inv_after);
    return code ? boost_one_error(b, code, "vectors", "", err) : MECH_OK;
}

/* Built twice, with and without the FMA instructions, and chosen when the
 * program loads (target_clones): boost_one calls fma() about 15
 * times, which without them is a libm call each. fma() is exact either way
 * and ISO C mode does not contract other expressions, so both clones give
 * the same bits. */
/* GCC only: Clang 14 names the dispatcher "<name>.ifunc" and calls from other
 * files then fail to link. Not under ASan or TSan: the loader runs the clone
 * resolver before the sanitizer runtime is set up, and an instrumented
 * resolver crashes. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) &&                             \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define BOOST_CLONES __attribute__((target_clones("fma", "default")))
#else
#define BOOST_CLONES
#endif

BOOST_CLONES
enum mech_status mech_boost_apply_batch(const struct mech_boost *b, const double *x, double *out,
                                        double *inv_before, double *inv_after, size_t n,
                                        const struct mech_budget *budget, struct mech_error *err)
{
    if (!b || (n > 0 && (!x || !out)))
        return mech_error_set(err, MECH_EINVAL, NULL, "boost, input and output are required");
    /* The budget is consulted where mech_budget_check would act anyway (the first
     * vector, every 256th, and past the step limit), so the answer is the same as
     * checking every vector, without a call per vector. */
    const long max_steps = budget ? budget->max_steps : 0;
    for (size_t i = 0; i < n; i++) {
        const long steps = (long)i + 1;
        if (i == 0 || (steps & 255) == 0 || steps > max_steps) {
            enum mech_status st = mech_budget_check(budget, steps, i == 0, err);
            if (st != MECH_OK) {
                if (err && err->code == st) err->progress.steps = (long)i; /* vectors done */
                return st;
            }
        }
        int code = boost_one(b, x + 4 * i, out + 4 * i, inv_before ? inv_before + i : NULL,
                             inv_after ? inv_after + i : NULL);
        if (code) {
            char param[32], prefix[40];
            snprintf(param, sizeof param, "vectors/%zu", i);
            snprintf(prefix, sizeof prefix, "vector %zu: ", i);
            return boost_one_error(b, code, param, prefix, err);
        }
    }
    return MECH_OK;
}
