/* kinematics.c — relativistic particle kinematics in natural units (c = 1):
 * invariant masses, two- and three-body decays, Compton scattering and
 * collision energies (notes §3: "Kinematics Problems in Electron Volts",
 * "π⁰ Decay", "Neutron Decay", "Compton Scattering"; end-of-chapter problems
 * 10, 11, 12, 18, 19). Every formula is written in a form whose terms are all
 * non-negative, or whose one difference is exact (Sterbenz) or compensated, so
 * massless, nearly collinear, nonrelativistic (1e-12 c) and ultra-relativistic
 * (γ = 1e6 and beyond) cases keep full relative precision.
 *
 * Why one file of ~800 lines: every section (motion, momentum differences,
 * invariant masses, decays, Compton, collisions) is built on the same
 * file-local compensated arithmetic and single-particle motion, which stay
 * private here rather than becoming a header of their own.
 */
#include "mech/relativity/kinematics.h"
#include "mech/base/constants.h"
#include "mech/base/compensated.h"

#include <float.h>
#include <math.h>

/* ---- compensated arithmetic (Neumaier sums, fma products) ------------------ */

static double sum3(double a, double b, double c)
{
    struct mech_csum s = {0, 0};
    mech_csum_add(&s, a);
    mech_csum_add(&s, b);
    mech_csum_add(&s, c);
    return mech_csum_value(&s);
}

/* ---- single-particle motion ------------------------------------------------ */

static enum mech_status check_mass(double m, struct mech_error *err)
{
    if (!isfinite(m))
        return mech_error_set(err, MECH_EINVAL, "mass", "mass must be a finite number");
    if (m < 0)
        return mech_error_set(
            err, MECH_EDOMAIN, "mass",
            "a mass cannot be negative (the rest energy m c^2 is >= 0), got %.17g", m);
    return MECH_OK;
}

static enum mech_status massless_at_rest(const char *param, struct mech_error *err)
{
    return mech_error_set(err, MECH_EDOMAIN, param,
                          "a massless particle always moves at c: it needs a positive energy "
                          "(it cannot be at rest)");
}

enum mech_status mech_kin_motion_from_momentum(double m, double p, struct mech_kin_motion *out,
                                               struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (!isfinite(p) || p < 0)
        return mech_error_set(err, MECH_EDOMAIN, "momentum",
                              "the momentum here is a magnitude and must be >= 0, got %.17g", p);
    if (m == 0 && p == 0) return massless_at_rest("momentum", err);
    struct mech_kin_motion k;
    k.mass = m;
    k.momentum = p;
    k.energy = hypot(m, p);
    k.kinetic = p == 0 ? 0.0 : p * (p / (k.energy + m)); /* T = p²/(E + m) */
    k.given = MECH_KIN_GIVEN_MOMENTUM;
    *out = k;
    return MECH_OK;
}

enum mech_status mech_kin_motion_from_energy(double m, double e, struct mech_kin_motion *out,
                                             struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (!isfinite(e) || e < m)
        return mech_error_set(
            err, MECH_EDOMAIN, "energy",
            "the total energy %.17g is below the rest energy m = %.17g: a free "
            "particle has E = sqrt(m^2 + p^2) >= m (did you mean kinetic_energy?)",
            e, m);
    if (m == 0 && e == 0) return massless_at_rest("energy", err);
    struct mech_kin_motion k;
    k.mass = m;
    k.energy = e;
    k.kinetic = e - m; /* exact for e ≤ 2m (Sterbenz), relative ε above */
    k.momentum = sqrt(k.kinetic) * sqrt(k.kinetic + 2.0 * m);
    k.given = MECH_KIN_GIVEN_ENERGY;
    *out = k;
    return MECH_OK;
}

enum mech_status mech_kin_motion_from_kinetic(double m, double t, struct mech_kin_motion *out,
                                              struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (!isfinite(t) || t < 0)
        return mech_error_set(err, MECH_EDOMAIN, "kinetic_energy",
                              "kinetic energy cannot be negative, got %.17g", t);
    if (m == 0 && t == 0) return massless_at_rest("kinetic_energy", err);
    struct mech_kin_motion k;
    k.mass = m;
    k.kinetic = t;
    k.energy = m + t;
    k.momentum = sqrt(t) * sqrt(t + 2.0 * m); /* p² = T(T + 2m) */
    k.given = MECH_KIN_GIVEN_KINETIC;
    *out = k;
    return MECH_OK;
}

enum mech_status mech_kin_motion_at_rest(double m, struct mech_kin_motion *out,
                                         struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (m == 0) return massless_at_rest("mass", err);
    struct mech_kin_motion k = {m, 0.0, m, 0.0, MECH_KIN_GIVEN_MOMENTUM};
    *out = k;
    return MECH_OK;
}

enum mech_status mech_kin_motion_from_boost(double m, const struct mech_boost *b,
                                            struct mech_kin_motion *out, struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (m == 0)
        return mech_error_set(err, MECH_EDOMAIN, "mass",
                              "a massless particle moves at c: give its energy or momentum, "
                              "not a velocity");
    struct mech_kin_motion k;
    k.mass = m;
    k.kinetic = m * b->gamma_minus_one;
    k.momentum = m * b->beta_gamma;
    k.energy = b->gamma_minus_one < 1.0 ? m + k.kinetic : m * b->gamma;
    k.given = MECH_KIN_GIVEN_MOMENTUM;
    if (!isfinite(k.energy) || !isfinite(k.momentum))
        return mech_error_set(err, MECH_ENUMERIC, "velocity",
                              "energy overflows (mass %.3g, gamma %.3g)", m, b->gamma);
    *out = k;
    return MECH_OK;
}

/* ---- difference of two momenta --------------------------------------------- */

/* x + y = *s + *e exactly (Knuth's TwoSum). */
static void two_sum(double x, double y, double *s, double *e)
{
    double t = x + y, z = t - x;
    *e = (x - (t - z)) + (y - z);
    *s = t;
}

/* Σ t[0..n-1] as if in K-fold precision, then rounded (Ogita, Rump & Oishi 2005,
 * SumK: K − 1 error-free sweeps, then a plain sum). t is overwritten. */
static double sum_k(double *t, int n, int k)
{
    for (int pass = 1; pass < k; pass++)
        for (int i = 1; i < n; i++) two_sum(t[i], t[i - 1], &t[i], &t[i - 1]);
    double s = 0;
    for (int i = 0; i < n - 1; i++) s += t[i];
    return s + t[n - 1];
}

/* Append ±x·y as two exact terms. */
static int add_product(double *t, int n, double sign, double x, double y)
{
    double p = x * y;
    t[n] = sign * p;
    t[n + 1] = sign * fma(x, y, -p);
    return n + 2;
}

/* Append ±p² (scaled by 2^-2e) as exact terms of the motion's own input. */
static int add_momentum_squared(double *t, int n, double sign, const struct mech_kin_motion *k,
                                int e)
{
    double m = ldexp(k->mass, -e);
    switch (k->given) {
    case MECH_KIN_GIVEN_ENERGY: {
        double en = ldexp(k->energy, -e);
        n = add_product(t, n, sign, en, en);
        return add_product(t, n, -sign, m, m);
    }
    case MECH_KIN_GIVEN_KINETIC: {
        double tk = ldexp(k->kinetic, -e);
        n = add_product(t, n, sign, tk, tk);
        return add_product(t, n, sign, 2.0 * m, tk);
    }
    default: {
        double p = ldexp(k->momentum, -e);
        return add_product(t, n, sign, p, p);
    }
    }
}

double mech_kin_momentum_difference(const struct mech_kin_motion *a,
                                    const struct mech_kin_motion *b)
{
    double den = a->momentum + b->momentum;
    if (!(den > 0)) return 0.0;
    double big = fmax(fmax(fmax(a->energy, b->energy), fmax(a->momentum, b->momentum)),
                      fmax(a->mass, b->mass));
    int e;
    frexp(big, &e); /* big < 2^e: the scaled inputs are below 1, their squares below 4 */
    double t[8];
    int n = add_momentum_squared(t, 0, 1.0, a, e);
    n = add_momentum_squared(t, n, -1.0, b, e);
    double d2 = sum_k(t, n, 3); /* (p_a² − p_b²) 2^-2e */
    return ldexp(d2 / (ldexp(a->momentum, -e) + ldexp(b->momentum, -e)), e); /* den may overflow */
}

static int unit_direction(struct mech_vec3 d, struct mech_vec3 *n)
{
    if (!mech_vec3_isfinite(d)) return 0;
    double s = fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
    if (s == 0) return 0;
    struct mech_vec3 u = mech_vec3_scale(d, 1.0 / s);
    *n = mech_vec3_unit(u);
    return 1;
}

enum mech_status mech_kin_motion_boost(const struct mech_kin_motion *k, struct mech_vec3 direction,
                                       struct mech_boost *out, struct mech_error *err)
{
    if (!(k->mass > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass",
                              "a massless particle has no rest frame (it moves at c)");
    struct mech_boost b;
    if (!unit_direction(direction, &b.direction)) {
        if (k->momentum > 0)
            return mech_error_set(err, MECH_EINVAL, "direction",
                                  "direction must be a nonzero finite vector");
        b.direction = mech_vec3_make(1, 0, 0);
    }
    const double m = k->mass, e = k->energy, p = k->momentum;
    b.gamma_minus_one = k->kinetic / m;
    b.beta_gamma = p / m;
    b.one_minus_beta = (m / e) * (m / (e + p)); /* (E − p)/E = m²/(E(E + p)) */
    /* near c, p/E may round above 1 (and E/m below 1 near rest): then from
     * the accurate 1 − β and γ − 1, so β <= 1 and γ >= 1 */
    b.beta = p / e;
    if (b.beta > 1.0) b.beta = 1.0 - b.one_minus_beta;
    b.gamma = e / m;
    if (b.gamma < 1.0) b.gamma = 1.0 + b.gamma_minus_one;
    b.exp_rapidity = (e + p) / m;
    b.exp_neg_rapidity = m / (e + p);
    b.rapidity = log1p(b.beta_gamma + b.gamma_minus_one); /* e^η = γ + βγ */
    b.beta_vec = mech_vec3_scale(b.direction, b.beta);
    if (!isfinite(b.exp_rapidity) || !(b.rapidity <= MECH_BOOST_RAPIDITY_MAX) ||
        !(b.one_minus_beta >= DBL_MIN))
        return mech_error_set(err, MECH_ENUMERIC, "mass",
                              "the Lorentz factor E/m = %.3g is beyond what doubles can carry",
                              b.gamma);
    *out = b;
    return MECH_OK;
}

/* ---- invariant mass ---------------------------------------------------------- */

enum mech_status mech_kin_particle_from_four(const double p4[4], struct mech_kin_particle *out,
                                             int *clamped, struct mech_error *err)
{
    if (clamped) *clamped = 0;
    for (int i = 0; i < 4; i++)
        if (!isfinite(p4[i]))
            return mech_error_set(err, MECH_EINVAL, NULL, "4-momentum must be finite");
    struct mech_vec3 p = mech_vec3_make(p4[1], p4[2], p4[3]);
    double e = p4[0], pn = mech_vec3_norm(p);
    if (e < 0)
        return mech_error_set(err, MECH_EDOMAIN, NULL,
                              "energy %.17g is negative: a physical particle has E >= |p| >= 0", e);
    double m2 = -mech_minkowski_square(p4); /* E² − |p|², compensated */
    if (m2 < 0) {
        if (-m2 > 8.0 * DBL_EPSILON * e * e)
            return mech_error_set(
                err, MECH_EDOMAIN, NULL,
                "unphysical 4-momentum: its energy E = %.17g is smaller than its "
                "momentum |p| = %.17g (a real particle has E^2 = m^2 + p^2 >= p^2)",
                e, pn);
        m2 = 0;
        if (clamped) *clamped = 1;
    }
    out->mass = sqrt(m2);
    out->energy = e;
    out->momentum = p;
    return MECH_OK;
}

enum mech_status mech_kin_particle_from_mass(double m, struct mech_vec3 p,
                                             struct mech_kin_particle *out, struct mech_error *err)
{
    enum mech_status st = check_mass(m, err);
    if (st != MECH_OK) return st;
    if (!mech_vec3_isfinite(p))
        return mech_error_set(err, MECH_EINVAL, "momentum", "momentum must be finite");
    out->mass = m;
    out->momentum = p;
    out->energy = hypot(m, mech_vec3_norm(p));
    return MECH_OK;
}

/* (m_a² E_b² + P_a² m_b²)/(E_a E_b + P_a P_b) = E_a E_b − P_a P_b, since
 * E_a²E_b² − P_a²P_b² = m_a²E_b² + P_a²m_b² when E² = m² + P². */
static double collinear_part(double ma, double ea, double pa, double mb, double eb, double pb)
{
    double den = ea * eb + pa * pb;
    if (!(den > 0)) return 0.0;
    double x = ma * eb, y = pa * mb;
    return (x * x + y * y) / den;
}

double mech_kin_pair_product(const struct mech_kin_particle *a, const struct mech_kin_particle *b)
{
    struct mech_vec3 u = a->momentum, v = b->momentum;
    double pa = mech_vec3_norm(u), pb = mech_vec3_norm(v);
    double base = collinear_part(a->mass, a->energy, pa, b->mass, b->energy, pb);
    if (pa == 0 || pb == 0) return base;
    /* θ between the momenta from atan2(|u × v|, u·v), both fma-accurate, then
     * 1 − cos θ = 2 sin²(θ/2): right to round-off for θ near 0 and near π. */
    struct mech_vec3 cr =
        mech_vec3_make(mech_diff_of_products(u.y, v.z, u.z, v.y), mech_diff_of_products(u.z, v.x, u.x, v.z),
                       mech_diff_of_products(u.x, v.y, u.y, v.x));
    struct mech_csum d = {0, 0};
    double t;
    t = u.x * v.x;
    mech_csum_add(&d, t);
    mech_csum_add(&d, fma(u.x, v.x, -t));
    t = u.y * v.y;
    mech_csum_add(&d, t);
    mech_csum_add(&d, fma(u.y, v.y, -t));
    t = u.z * v.z;
    mech_csum_add(&d, t);
    mech_csum_add(&d, fma(u.z, v.z, -t));
    double theta = atan2(mech_vec3_norm(cr), mech_csum_value(&d));
    double sh = sin(0.5 * theta);
    return base + pa * pb * (2.0 * sh * sh);
}

double mech_kin_pair_product_angle(const struct mech_kin_motion *a, const struct mech_kin_motion *b,
                                   double one_minus_cos)
{
    return collinear_part(a->mass, a->energy, a->momentum, b->mass, b->energy, b->momentum) +
           a->momentum * b->momentum * one_minus_cos;
}

void mech_kin_system_finish(struct mech_kin_system *o)
{
    double m = o->mass, e = o->energy;
    double p = mech_vec3_norm(o->momentum);
    o->momentum_norm = p;
    o->has_rest_frame = m > 0 && e > 0;
    if (!o->has_rest_frame) {
        o->beta = mech_vec3_make(0, 0, 0);
        o->gamma = o->gamma_minus_one = o->beta_gamma = o->one_minus_beta = o->rapidity = NAN;
        return;
    }
    /* γ = E/M; γ − 1 = (E² − M²)/(M(E + M)) = P²/(M(E + M)); 1 − β = M²/(E(E + P)). */
    o->gamma_minus_one = (p / m) * (p / (e + m));
    o->beta_gamma = p / m;
    o->one_minus_beta = (m / e) * (m / (e + p));
    o->rapidity = log1p(o->beta_gamma + o->gamma_minus_one);
    /* E/M and P/E round across 1 when the system is nearly at rest or
     * nearly lightlike: from γ − 1 and 1 − β there, so γ >= 1 and |β| <= 1 */
    o->gamma = e / m;
    if (o->gamma < 1.0) o->gamma = 1.0 + o->gamma_minus_one;
    if (o->one_minus_beta > 1.0) o->one_minus_beta = 1.0 - p / e;
    o->beta = mech_vec3_scale(o->momentum, p > e ? (1.0 - o->one_minus_beta) / p : 1.0 / e);
}

enum mech_status mech_kin_invariant_mass(const struct mech_kin_particle *ps, size_t n,
                                         const struct mech_budget *budget,
                                         struct mech_kin_system *out, struct mech_error *err)
{
    if (!ps || n == 0 || !out || !budget)
        return mech_error_set(err, MECH_EINVAL, NULL, "particles, output and budget are required");
    double emax = 0;
    struct mech_csum se = {0, 0}, sx = {0, 0}, sy = {0, 0}, sz = {0, 0};
    for (size_t i = 0; i < n; i++) {
        emax = fmax(emax, ps[i].energy);
        mech_csum_add(&se, ps[i].energy);
        mech_csum_add(&sx, ps[i].momentum.x);
        mech_csum_add(&sy, ps[i].momentum.y);
        mech_csum_add(&sz, ps[i].momentum.z);
    }
    /* One power of two brings the largest energy near 1 (exact scaling), so
     * squares and products of energies cannot overflow or underflow. */
    double scale = emax > 0 ? ldexp(1.0, -ilogb(emax)) : 1.0;
    struct mech_csum m2 = {0, 0};
    for (size_t i = 0; i < n; i++) {
        enum mech_status st = mech_budget_check(budget, (long)i + 1, i == 0, err);
        if (st != MECH_OK) {
            if (err && err->code == st) err->progress.steps = (long)i;
            return st;
        }
        struct mech_kin_particle a = {ps[i].mass * scale, ps[i].energy * scale,
                                      mech_vec3_scale(ps[i].momentum, scale)};
        mech_csum_add(&m2, a.mass * a.mass);
        for (size_t j = i + 1; j < n; j++) {
            struct mech_kin_particle b = {ps[j].mass * scale, ps[j].energy * scale,
                                          mech_vec3_scale(ps[j].momentum, scale)};
            mech_csum_add(&m2, 2.0 * mech_kin_pair_product(&a, &b));
        }
    }
    double msq = mech_csum_value(&m2);
    out->mass = sqrt(msq) / scale;
    out->mass_squared = (msq / scale) / scale;
    out->energy = mech_csum_value(&se);
    out->momentum = mech_vec3_make(mech_csum_value(&sx), mech_csum_value(&sy), mech_csum_value(&sz));
    mech_kin_system_finish(out);
    if (!isfinite(out->mass) || !isfinite(out->mass_squared) || !isfinite(out->energy) ||
        !mech_vec3_isfinite(out->momentum))
        return mech_error_set(err, MECH_ENUMERIC, "momenta", "the total 4-momentum overflows");
    return MECH_OK;
}

/* ---- decays -------------------------------------------------------------------- */

double mech_kin_q_value(double parent, const double *m, size_t n)
{
    struct mech_csum q = {0, 0};
    mech_csum_add(&q, parent);
    for (size_t i = 0; i < n; i++)
        mech_csum_add(&q, -m[i]);
    return mech_csum_value(&q);
}

static enum mech_status below_threshold(double parent, const double *m, size_t n,
                                        struct mech_error *err)
{
    double q = mech_kin_q_value(parent, m, n);
    return mech_error_set(err, MECH_EDOMAIN, "daughters",
                          "this decay cannot happen: the parent's mass %.10g is smaller than the "
                          "sum of the daughters' masses %.10g (short by %.6g); energy conservation "
                          "in the parent's rest frame needs M >= m1 + m2 + ...",
                          parent, parent - q, -q);
}

enum mech_status mech_kin_two_body_rest(double parent, double m1, double m2,
                                        struct mech_kin_two_body *out, struct mech_error *err)
{
    if (!(parent > 0) || !isfinite(parent))
        return mech_error_set(err, MECH_EDOMAIN, "parent/particle",
                              "a decaying parent needs a positive mass, got %.17g", parent);
    double ms[2] = {m1, m2};
    double q = mech_kin_q_value(parent, ms, 2);
    if (q < 0) return below_threshold(parent, ms, 2, err);
    /* λ(M², m1², m2²) = (M − m1 − m2)(M + m1 + m2)(M − m1 + m2)(M + m1 − m2). */
    double f2 = parent + m1 + m2;
    double f3 = sum3(parent, -m1, m2), f4 = sum3(parent, m1, -m2);
    double p = sqrt(q * f2) * sqrt(f3 * f4) / (2.0 * parent);
    out->q_value = q;
    out->momentum = p;
    for (int i = 0; i < 2; i++) {
        out->energy[i] = hypot(ms[i], p);
        out->kinetic[i] = p == 0 ? 0.0 : p * (p / (out->energy[i] + ms[i]));
    }
    return MECH_OK;
}

void mech_kin_decay_lab(const struct mech_boost *b, double m, double pstar, double estar,
                        double theta_star, int partner, struct mech_kin_lab *out)
{
    double sh = sin(0.5 * theta_star), ch = cos(0.5 * theta_star);
    double c = cos(theta_star), s = sin(theta_star);
    double omc = 2.0 * sh * sh, opc = 2.0 * ch * ch; /* 1 − cos θ*, 1 + cos θ* */
    if (theta_star == MECH_PI) { /* the double nearest π stands for exactly backward */
        c = -1.0;
        s = 0.0;
        omc = 2.0;
        opc = 0.0;
    }
    if (partner) {
        c = -c;
        s = -s;
        double t = omc;
        omc = opc;
        opc = t;
    }
    const double g = b->gamma, bg = b->beta_gamma, beta = b->beta;
    double e;
    if (c >= 0) {
        e = g * estar + bg * pstar * c; /* both terms ≥ 0 */
    } else {
        /* γ(E* + βp* cos θ*) = γ(E* − βp*) + βγ p* (1 + cos θ*), and
         * γ(E* − βp*) = γ(E*² − β²p*²)/(E* + βp*) = (γ m² + p*²/γ)/(E* + βp*). */
        double back = ((g * m) * m + pstar * (pstar / g)) / (estar + beta * pstar);
        e = back + bg * pstar * opc;
    }
    (void)omc;
    double ppar = fma(g * pstar, c, bg * estar);
    double pperp = pstar * s;
    double p = hypot(ppar, pperp);
    out->energy = e;
    out->momentum = p;
    out->momentum_parallel = ppar;
    out->momentum_transverse = pperp;
    out->angle = atan2(fabs(pperp), ppar);
    if (m == 0)
        out->kinetic = e;
    else if (e >= 2.0 * m)
        out->kinetic = e - m;
    else
        out->kinetic = p * (p / (e + m));
}

int mech_kin_decay_max_angle(const struct mech_boost *b, double m, double pstar, double *theta_max)
{
    if (!(m > 0) || !(b->beta_gamma > 0)) return 0;
    double r = (pstar / m) / b->beta_gamma; /* β*γ* / (βγ) */
    if (!(r < 1.0)) return 0;
    if (theta_max) *theta_max = asin(r);
    return 1;
}

static double opening_at(const struct mech_boost *b, const double m[2], double pstar,
                         const double estar[2], double t)
{
    struct mech_kin_lab l1, l2;
    mech_kin_decay_lab(b, m[0], pstar, estar[0], t, 0, &l1);
    mech_kin_decay_lab(b, m[1], pstar, estar[1], t, 1, &l2);
    double sum = l1.angle + l2.angle; /* the two lie on opposite sides of the axis */
    return sum <= MECH_PI ? sum : 2.0 * MECH_PI - sum;
}

void mech_kin_decay_min_opening(const struct mech_boost *b, const double m[2], double pstar,
                                const double estar[2], double *angle, double *at_theta_star)
{
    enum { N = 512 };
    if (!(b->beta > 0) || pstar == 0) {
        *angle = pstar == 0 ? 0.0 : MECH_PI;
        *at_theta_star = 0.5 * MECH_PI;
        return;
    }
    int kbest = 0;
    double fbest = INFINITY;
    for (int k = 0; k <= N; k++) {
        double f = opening_at(b, m, pstar, estar, MECH_PI * k / N);
        if (f < fbest) {
            fbest = f;
            kbest = k;
        }
    }
    /* Golden-section refinement inside the neighbouring grid cells. */
    double lo = MECH_PI * (kbest > 0 ? kbest - 1 : 0) / N;
    double hi = MECH_PI * (kbest < N ? kbest + 1 : N) / N;
    const double r = 0.6180339887498949;
    double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
    double f1 = opening_at(b, m, pstar, estar, x1), f2 = opening_at(b, m, pstar, estar, x2);
    double tbest = MECH_PI * kbest / N;
    for (int it = 0; it < 120 && hi - lo > 4 * DBL_EPSILON * hi; it++) {
        if (f1 <= f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - r * (hi - lo);
            f1 = opening_at(b, m, pstar, estar, x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + r * (hi - lo);
            f2 = opening_at(b, m, pstar, estar, x2);
        }
    }
    if (f1 < fbest) {
        fbest = f1;
        tbest = x1;
    }
    if (f2 < fbest) {
        fbest = f2;
        tbest = x2;
    }
    *angle = fbest;
    *at_theta_star = tbest;
}

static double lab_angle(const struct mech_boost *b, double m, double pstar, double estar, double t)
{
    struct mech_kin_lab l;
    mech_kin_decay_lab(b, m, pstar, estar, t, 0, &l);
    return l.angle;
}

static double lab_energy(const struct mech_boost *b, double m, double pstar, double estar, double t)
{
    struct mech_kin_lab l;
    mech_kin_decay_lab(b, m, pstar, estar, t, 0, &l);
    return l.energy;
}

/* θ* in [lo, hi] where the lab angle crosses `target`; `rising` tells whether
 * the lab angle increases with θ* on that piece. */
static double bisect_angle(const struct mech_boost *b, double m, double pstar, double estar,
                           double lo, double hi, double target, int rising)
{
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        int below = lab_angle(b, m, pstar, estar, mid) < target;
        if (below == rising)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

int mech_kin_decay_cone(const struct mech_boost *b, double m, double pstar, double estar,
                        double half_angle, double ranges[2][2], double edges[2])
{
    double e0 = lab_energy(b, m, pstar, estar, 0.0), epi = lab_energy(b, m, pstar, estar, MECH_PI);
    if (!(b->beta > 0) || pstar == 0) {
        /* At rest (or no rest-frame momentum): every direction has energy E*. */
        ranges[0][0] = ranges[0][1] = e0;
        edges[0] = half_angle;
        return 1;
    }
    double tmax;
    if (mech_kin_decay_max_angle(b, m, pstar, &tmax)) {
        if (half_angle >= tmax) {
            ranges[0][0] = epi;
            ranges[0][1] = e0;
            edges[0] = MECH_PI;
            return 1;
        }
        /* The lab angle rises to θ_max at cos θ* = −β* / β, then falls back to 0. */
        double cm = -(pstar / estar) / b->beta;
        double tm = acos(fmax(-1.0, fmin(1.0, cm)));
        double t1 = bisect_angle(b, m, pstar, estar, 0.0, tm, half_angle, 1);
        double t2 = bisect_angle(b, m, pstar, estar, tm, MECH_PI, half_angle, 0);
        ranges[0][0] = lab_energy(b, m, pstar, estar, t1);
        ranges[0][1] = e0;
        ranges[1][0] = epi;
        ranges[1][1] = lab_energy(b, m, pstar, estar, t2);
        edges[0] = t1;
        edges[1] = t2;
        return 2;
    }
    /* The lab angle rises monotonically with θ* (to π, or to π/2 when the
     * daughter's rest-frame speed equals the parent's). */
    if (half_angle >= MECH_PI || half_angle >= lab_angle(b, m, pstar, estar, MECH_PI)) {
        ranges[0][0] = epi;
        ranges[0][1] = e0;
        edges[0] = MECH_PI;
        return 1;
    }
    double t1 = bisect_angle(b, m, pstar, estar, 0.0, MECH_PI, half_angle, 1);
    ranges[0][0] = lab_energy(b, m, pstar, estar, t1);
    ranges[0][1] = e0;
    edges[0] = t1;
    return 1;
}

enum mech_status mech_kin_endpoint(double parent, const double *m, size_t n, size_t i,
                                   double *e_max, double *t_max, double *p_max,
                                   struct mech_error *err)
{
    if (!m || n < 2 || i >= n)
        return mech_error_set(err, MECH_EINVAL, "daughters", "need at least two daughters");
    if (!(parent > 0) || !isfinite(parent))
        return mech_error_set(err, MECH_EDOMAIN, "parent/particle",
                              "a decaying parent needs a positive mass, got %.17g", parent);
    double q = mech_kin_q_value(parent, m, n);
    if (q < 0) return below_threshold(parent, m, n, err);
    struct mech_csum s = {0, 0};
    for (size_t j = 0; j < n; j++)
        if (j != i) mech_csum_add(&s, m[j]);
    double si = mech_csum_value(&s);
    /* T_max = ((M − m_i)² − S_i²)/(2M) = Q (M − m_i + S_i)/(2M): no cancellation. */
    double t = q * (sum3(parent, -m[i], si) / (2.0 * parent));
    if (e_max) *e_max = m[i] + t;
    if (t_max) *t_max = t;
    if (p_max) *p_max = sqrt(t) * sqrt(t + 2.0 * m[i]);
    return MECH_OK;
}

static double kinetic_of(double m, double p)
{
    if (p == 0) return 0.0;
    return p * (p / (hypot(m, p) + m));
}

enum mech_status mech_kin_three_body_planar(double parent, const double m[3], double theta12,
                                            double theta23, double momentum[3], double energy[3],
                                            double kinetic[3], struct mech_error *err)
{
    if (!(parent > 0) || !isfinite(parent))
        return mech_error_set(err, MECH_EDOMAIN, "parent/particle",
                              "a decaying parent needs a positive mass, got %.17g", parent);
    double q = mech_kin_q_value(parent, m, 3);
    if (q < 0) return below_threshold(parent, m, 3, err);
    double theta31 = 2.0 * MECH_PI - theta12 - theta23;
    if (!(theta12 > 0 && theta12 <= MECH_PI && theta23 > 0 && theta23 <= MECH_PI && theta31 > 0 &&
          theta31 <= MECH_PI + 4 * DBL_EPSILON))
        return mech_error_set(err, MECH_EDOMAIN, "angles",
                              "three momenta that add up to zero lie in a plane with each angle "
                              "between two of them in (0, 180] degrees; the third angle "
                              "360 - theta12 - theta23 is %.10g degrees",
                              theta31 * 180.0 / MECH_PI);
    /* Sine rule of the closed momentum triangle: p_i ∝ sin(angle between the
     * other two momenta); sin θ31 = sin(θ12 + θ23) up to sign. */
    double r[3] = {sin(theta23), fabs(sin(theta12 + theta23)), sin(theta12)};
    double rmax = fmax(r[0], fmax(r[1], r[2]));
    if (!(rmax > 8 * DBL_EPSILON) && q > 0)
        return mech_error_set(err, MECH_EDOMAIN, "angles",
                              "collinear configuration: the angles do not fix the momenta");
    /* Scale k with p_i = k r_i: Σ T_i(k) = Q, T_i increasing in k. */
    double lo = 0, hi = parent / rmax;
    for (int it = 0; q > 0 && it < 300; it++) {
        double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        struct mech_csum t = {0, 0};
        for (int i = 0; i < 3; i++)
            mech_csum_add(&t, kinetic_of(m[i], mid * r[i]));
        if (mech_csum_value(&t) < q)
            lo = mid;
        else
            hi = mid;
    }
    double k = q > 0 ? 0.5 * (lo + hi) : 0.0;
    for (int i = 0; i < 3; i++) {
        momentum[i] = k * r[i];
        energy[i] = hypot(m[i], momentum[i]);
        kinetic[i] = kinetic_of(m[i], momentum[i]);
    }
    return MECH_OK;
}

/* ---- Compton scattering ---------------------------------------------------------- */

enum mech_status mech_kin_compton(double e, double m, double theta, struct mech_kin_compton *out,
                                  struct mech_error *err)
{
    if (!(m > 0) || !isfinite(m))
        return mech_error_set(err, MECH_EDOMAIN, "target",
                              "the target must have a positive mass to be at rest, got %.17g", m);
    if (!(e > 0) || !isfinite(e))
        return mech_error_set(err, MECH_EDOMAIN, "energy",
                              "the photon energy must be positive, got %.17g", e);
    if (!(theta >= 0 && theta <= MECH_PI))
        return mech_error_set(err, MECH_EINVAL, "angle",
                              "the scattering angle must be in [0, pi] rad, got %.17g", theta);
    /* notes §3 Compton: 1/E' − 1/E = (1 − cos θ)/m, with 1 − cos θ = 2 sin²(θ/2). */
    double sh = sin(0.5 * theta), ch = cos(0.5 * theta);
    double omc = 2.0 * sh * sh;
    double r = e / m;
    double k = r * omc;
    out->one_minus_cos = omc;
    out->energy_out = e / (1.0 + k);
    out->recoil_kinetic = e * (k / (1.0 + k));
    out->recoil_momentum = sqrt(out->recoil_kinetic) * sqrt(out->recoil_kinetic + 2.0 * m);
    /* cot φ = (1 + E/m) tan(θ/2) */
    out->recoil_angle = atan2(ch, (1.0 + r) * sh);
    if (!isfinite(out->energy_out) || !isfinite(out->recoil_momentum))
        return mech_error_set(err, MECH_ENUMERIC, "energy", "Compton kinematics overflowed");
    return MECH_OK;
}

/* ---- collisions -------------------------------------------------------------------- */

void mech_kin_collision_s(const struct mech_kin_motion *a, const struct mech_kin_motion *b,
                          double one_minus_cos, double *s, double *s_minus_threshold)
{
    double q = mech_kin_pair_product_angle(a, b, one_minus_cos);
    double m1 = a->mass, m2 = b->mass;
    *s = (m1 * m1 + m2 * m2) + 2.0 * q;
    double d;
    if (one_minus_cos >= 1.0) {
        /* E1E2 − m1m2 = T1E2 + m1T2; −p1·p2 = p1p2(1 − cos α − 1) ≥ 0. */
        d = a->kinetic * b->energy + m1 * b->kinetic +
            a->momentum * b->momentum * (one_minus_cos - 1.0);
    } else if (m1 > 0 && m2 > 0) {
        /* E1E2 − p1p2 − m1m2 = m1m2 (cosh(η1 − η2) − 1), with no rapidity difference
         * (asinh(p1/m1) − asinh(p2/m2) keeps only ε η/Δη of Δη for nearly equal
         * velocities): with C = E1E2 − p1p2 (collinear_part) and
         * Δ = m1m2 sinh(η1 − η2) = p1E2 − p2E1, C² − m1²m2² = Δ², so
         * C − m1m2 = Δ²/(C + m1m2), and
         * Δ = (p1²E2² − p2²E1²)/(p1E2 + p2E1) = (p1m2 − p2m1)(p1m2 + p2m1)/(p1E2 + p2E1),
         * whose one difference p1m2 − p2m1 is formed with fma to one rounding. */
        const double p1 = a->momentum, p2 = b->momentum;
        const double c0 = collinear_part(m1, a->energy, p1, m2, b->energy, p2);
        const double den = p1 * b->energy + p2 * a->energy;
        const double delta =
            den > 0 ? mech_diff_of_products(p1, m2, p2, m1) * ((p1 * m2 + p2 * m1) / den) : 0.0;
        d = delta * (delta / (c0 + m1 * m2)) + p1 * p2 * one_minus_cos;
    } else {
        d = q;
    }
    *s_minus_threshold = 2.0 * d;
}

double mech_kin_cm_momentum(double sqrt_s, double d, double m1, double m2)
{
    if (!(sqrt_s > 0) || !(d > 0)) return 0.0;
    return sqrt(d) * sqrt(d + 4.0 * m1 * m2) / (2.0 * sqrt_s);
}

enum mech_status mech_kin_fixed_target_kinetic(double w, double m1, double m2, double *kinetic,
                                               struct mech_error *err)
{
    if (!(m2 > 0))
        return mech_error_set(err, MECH_EDOMAIN, "target/particle",
                              "a fixed target must have a mass: a massless particle cannot be at "
                              "rest");
    double a = sum3(w, -m1, -m2);
    if (a < 0)
        return mech_error_set(
            err, MECH_EDOMAIN, "sqrt_s",
            "sqrt(s) = %.10g is below m1 + m2 = %.10g: even with the beam at rest "
            "the two particles carry more energy than that",
            w, m1 + m2);
    *kinetic = a * ((w + m1 + m2) / (2.0 * m2));
    return MECH_OK;
}
