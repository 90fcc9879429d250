/* charged_motion.c — exact special-relativistic motion of a charge in
 * uniform static fields (mech/relativity/charged_motion.h): boost to the frame where
 * E and B are parallel, the hyperbolic-plus-circular motion there in proper
 * time, the displacement boosted back; lab time inverted to proper time. */
#include "mech/relativity/charged_motion.h"

#include <float.h>
#include <math.h>

#include "mech/base/constants.h"

const char *mech_charged_field_kind_name(enum mech_charged_field_kind k)
{
    switch (k) {
    case MECH_CHARGED_FREE: return "free";
    case MECH_CHARGED_MAGNETIC: return "magnetic";
    case MECH_CHARGED_ELECTRIC: return "electric";
    case MECH_CHARGED_PARALLEL: return "parallel";
    case MECH_CHARGED_CROSSED_MAGNETIC: return "crossed_magnetic";
    case MECH_CHARGED_CROSSED_ELECTRIC: return "crossed_electric";
    case MECH_CHARGED_GENERAL: return "general";
    }
    return "unknown";
}

/* sinh(x)/x and sin(x)/x without cancellation near 0 (series to x^4 below
 * 1e-3: the next term is x^6/5040 < 2e-22). */
static double sinhc(double x)
{
    if (fabs(x) < 1e-3) {
        const double x2 = x * x;
        return 1.0 + x2 / 6.0 * (1.0 + x2 / 20.0);
    }
    return sinh(x) / x;
}
static double sinc(double x)
{
    if (fabs(x) < 1e-3) {
        const double x2 = x * x;
        return 1.0 - x2 / 6.0 * (1.0 - x2 / 20.0);
    }
    return sin(x) / x;
}

/* Boost the 4-vector (x0, x) into the frame moving with velocity beta*c
 * along the unit b (sign = +1), or back out of it (sign = -1):
 *   x0' = gamma (x0 - s beta b.x),  x' = x + ((gamma - 1) b.x - s gamma beta x0) b,
 * gamma - 1 = gamma^2 beta^2 / (gamma + 1) (no cancellation for small beta). */
static void boost4(double beta, double gamma, struct mech_vec3 b, double sign, double *x0,
                   struct mech_vec3 *x)
{
    const double bx = mech_vec3_dot(b, *x);
    const double gm1 = gamma * gamma * beta * beta / (gamma + 1.0);
    const double t0 = gamma * (*x0 - sign * beta * bx);
    *x = mech_vec3_add(*x, mech_vec3_scale(b, gm1 * bx - sign * gamma * beta * *x0));
    *x0 = t0;
}

static int finite_vec(struct mech_vec3 v) { return mech_vec3_isfinite(v); }

enum mech_status mech_charged_motion_init(struct mech_vec3 eps, struct mech_vec3 omega,
                                          struct mech_vec3 r0, struct mech_vec3 u0,
                                          struct mech_charged_motion *m, struct mech_error *err)
{
    if (!m) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    *m = (struct mech_charged_motion){0};
    if (!finite_vec(eps)) return mech_error_set(err, MECH_EINVAL, "eps", "must be finite");
    if (!finite_vec(omega)) return mech_error_set(err, MECH_EINVAL, "omega", "must be finite");
    if (!finite_vec(r0)) return mech_error_set(err, MECH_EINVAL, "r0", "must be finite");
    if (!finite_vec(u0)) return mech_error_set(err, MECH_EINVAL, "u0", "must be finite");
    const double c = MECH_C;
    m->eps = eps;
    m->omega = omega;
    m->r0 = r0;
    m->u0 = u0;
    const double u2c2 = mech_vec3_dot(u0, u0) / (c * c);
    m->gamma0 = sqrt(1.0 + u2c2);
    m->gamma_w = 1.0;
    const double en = mech_vec3_norm(eps), wn = mech_vec3_norm(omega), cw = c * wn;
    const struct mech_vec3 P = mech_vec3_cross(eps, omega);
    const double pn = mech_vec3_norm(P);
    const double I2 = mech_vec3_dot(eps, omega);
    struct mech_vec3 eps_p = eps, omega_p = omega;
    if (en == 0.0 && wn == 0.0) {
        m->kind = MECH_CHARGED_FREE;
        m->n = mech_vec3_make(0, 0, 1);
    } else if (en == 0.0) {
        m->kind = MECH_CHARGED_MAGNETIC;
    } else if (wn == 0.0) {
        m->kind = MECH_CHARGED_ELECTRIC;
    } else if (pn <= 4.0 * DBL_EPSILON * en * wn) {
        m->kind = MECH_CHARGED_PARALLEL; /* parallel to round-off: the residue is dropped */
    } else {
        const int crossed = fabs(I2) <= 4.0 * DBL_EPSILON * en * wn;
        if (crossed && fabs(en - cw) <= 1e-12 * (en + cw))
            return mech_error_set(err, MECH_EDOMAIN, "fields",
                                  "null fields: E perpendicular to B with |E| = c|B| (%.17g V/m "
                                  "per unit q/m against %.17g): no frame makes them parallel",
                                  en, cw);
        m->kind = !crossed     ? MECH_CHARGED_GENERAL
                  : en < cw    ? MECH_CHARGED_CROSSED_MAGNETIC
                               : MECH_CHARGED_CROSSED_ELECTRIC;
        /* (w/c)/(1 + w^2/c^2) = s = c|P|/S: w/c = 2 c |P| / (S + R) with
         * R = sqrt(I1^2 + 4 c^2 I2^2) = S sqrt(1 - 4 s^2) from the invariants */
        const double S = en * en + cw * cw;
        const double I1 = (en - cw) * (en + cw);
        const double R = hypot(I1, 2.0 * c * (crossed ? 0.0 : I2));
        const double beta = 2.0 * c * pn / (S + R);
        m->boosted = 1;
        m->beta_w_norm = beta;
        m->gamma_w = 1.0 / sqrt((1.0 - beta) * (1.0 + beta));
        const struct mech_vec3 bh = mech_vec3_scale(P, 1.0 / pn);
        m->beta_w = mech_vec3_scale(bh, beta);
        /* the fields in S' (eps.bh = Omega.bh = 0: only the perpendicular law) */
        const double g = m->gamma_w;
        eps_p = mech_vec3_scale(mech_vec3_add(eps, mech_vec3_scale(mech_vec3_cross(bh, omega),
                                                                  beta * c)),
                                g);
        omega_p = mech_vec3_scale(
            mech_vec3_sub(omega, mech_vec3_scale(mech_vec3_cross(bh, eps), beta / c)), g);
        /* their sizes from the invariants, never from the cancelling sums */
        double a2, cw2;
        if (I1 >= 0.0) {
            a2 = 0.5 * (I1 + R);
            cw2 = (I1 + R) > 0.0 ? 2.0 * c * c * I2 * I2 / (I1 + R) : 0.0;
        } else {
            cw2 = 0.5 * (R - I1);
            a2 = 2.0 * c * c * I2 * I2 / (R - I1);
        }
        if (crossed) {
            if (m->kind == MECH_CHARGED_CROSSED_MAGNETIC) a2 = 0.0;
            else cw2 = 0.0;
        }
        m->a_prime = sqrt(a2);
        const double wp = sqrt(cw2) / c;
        const double sgn = I2 < 0.0 ? -1.0 : 1.0;
        const double epn = mech_vec3_norm(eps_p), wpn = mech_vec3_norm(omega_p);
        if (m->kind == MECH_CHARGED_CROSSED_MAGNETIC || (m->kind == MECH_CHARGED_GENERAL &&
                                                         c * wpn > epn)) {
            m->n = mech_vec3_scale(omega_p, (m->kind == MECH_CHARGED_GENERAL ? sgn : 1.0) / wpn);
            m->omega_prime = m->kind == MECH_CHARGED_GENERAL ? sgn * wp : wp;
        } else {
            m->n = mech_vec3_scale(eps_p, 1.0 / epn);
            m->omega_prime = sgn * wp;
        }
    }
    if (!m->boosted) {
        if (m->kind == MECH_CHARGED_MAGNETIC) {
            m->n = mech_vec3_scale(omega, 1.0 / wn);
            m->omega_prime = wn;
        } else if (m->kind != MECH_CHARGED_FREE) { /* electric, parallel */
            m->n = mech_vec3_scale(eps, 1.0 / en);
            m->a_prime = en;
            m->omega_prime = mech_vec3_dot(omega, m->n);
        }
    }
    /* the initial 4-velocity in S' (the initial event is the origin of the
     * displacements, so only the velocity is boosted) */
    double U0 = c * m->gamma0;
    struct mech_vec3 U = u0;
    if (m->boosted)
        boost4(m->beta_w_norm, m->gamma_w, mech_vec3_scale(m->beta_w, 1.0 / m->beta_w_norm), 1.0,
               &U0, &U);
    m->U00p = U0;
    m->un0p = mech_vec3_dot(U, m->n);
    m->uperp0p = mech_vec3_sub(U, mech_vec3_scale(m->n, m->un0p));
    m->nxuperp0p = mech_vec3_cross(m->n, m->uperp0p);
    if (!isfinite(m->gamma0) || !isfinite(U0) || !finite_vec(U) || !finite_vec(m->n))
        return mech_error_set(err, MECH_ENUMERIC, "fields",
                              "the boost to the frame of parallel fields overflows (gamma_w = "
                              "%.3g)",
                              m->gamma_w);
    return MECH_OK;
}

/* The state at proper time tau, with the lab time; *u0lab = gamma c there. */
static enum mech_status state_at(const struct mech_charged_motion *m, double tau,
                                 struct mech_charged_motion_state *s, double *ct_lab, double *u0lab,
                                 const char *param, struct mech_error *err)
{
    const double c = MECH_C;
    const double k = m->a_prime / c, x = k * tau;
    const double sh = sinh(x), ch = cosh(x);
    const double Sk = tau * sinhc(x), Ck = tau * (0.5 * x) * sinhc(0.5 * x) * sinhc(0.5 * x);
    const double y = m->omega_prime * tau;
    const double cy = cos(y), sy = sin(y);
    const double Sw = tau * sinc(y), Cw = tau * (0.5 * y) * sinc(0.5 * y) * sinc(0.5 * y);
    /* displacement and 4-velocity in S' */
    double dct = m->U00p * Sk + m->un0p * Ck;
    struct mech_vec3 dr = mech_vec3_add(
        mech_vec3_scale(m->n, m->un0p * Sk + m->U00p * Ck),
        mech_vec3_sub(mech_vec3_scale(m->uperp0p, Sw), mech_vec3_scale(m->nxuperp0p, Cw)));
    double U0 = m->U00p * ch + m->un0p * sh;
    struct mech_vec3 U = mech_vec3_add(
        mech_vec3_scale(m->n, m->un0p * ch + m->U00p * sh),
        mech_vec3_sub(mech_vec3_scale(m->uperp0p, cy), mech_vec3_scale(m->nxuperp0p, sy)));
    if (m->boosted) {
        const struct mech_vec3 bh = mech_vec3_scale(m->beta_w, 1.0 / m->beta_w_norm);
        boost4(m->beta_w_norm, m->gamma_w, bh, -1.0, &dct, &dr);
        boost4(m->beta_w_norm, m->gamma_w, bh, -1.0, &U0, &U);
    }
    s->tau = tau;
    s->t = dct / c;
    s->r = mech_vec3_add(m->r0, dr);
    s->u = U;
    const double u2c2 = mech_vec3_dot(U, U) / (c * c);
    s->gamma = sqrt(1.0 + u2c2);
    s->gamma_minus_1 = u2c2 / (s->gamma + 1.0);
    s->v = mech_vec3_scale(U, 1.0 / s->gamma);
    *ct_lab = dct;
    *u0lab = U0;
    if (!isfinite(dct) || !isfinite(U0) || !finite_vec(s->r) || !finite_vec(U) ||
        !isfinite(s->gamma))
        return mech_error_set(err, MECH_ENUMERIC, param,
                              "the state overflows at proper time %.6g s (k tau = %.3g)", tau, x);
    return MECH_OK;
}

enum mech_status mech_charged_motion_at_proper_time(const struct mech_charged_motion *m,
                                                    double tau, struct mech_charged_motion_state *s,
                                                    struct mech_error *err)
{
    if (!m || !s) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    if (!(isfinite(tau) && tau >= 0.0))
        return mech_error_set(err, MECH_EINVAL, "tau", "tau must be finite and >= 0, got %.17g",
                              tau);
    double ct, u0;
    return state_at(m, tau, s, &ct, &u0, "tau", err);
}

/* Proper time at lab time t with no boost and an electric part (k > 0):
 * k c t = U0 sinh x + u_n (cosh x - 1), x = k tau, is a quadratic in
 * X = e^x: (U0 + u_n) X^2 - 2 (u_n + K) X - (U0 - u_n) = 0, K = a t; its
 * positive root written as X - 1 = K (D+ + U+) / ((D + U0) U+) with
 * D = sqrt((u_n + K)^2 + c^2 + u_perp^2), D+ = D + u_n + K and U+ = U0 + u_n,
 * each taken from its conjugate when the sum would cancel. */
static double tau_electric(const struct mech_charged_motion *m, double t)
{
    const double c = MECH_C, U0 = m->U00p, un = m->un0p;
    const double K = m->a_prime * t;
    const double rest2 = c * c + mech_vec3_dot(m->uperp0p, m->uperp0p); /* U0^2 - un^2 */
    const double yv = un + K;
    const double D = sqrt(yv * yv + rest2);
    const double Dp = yv >= 0.0 ? D + yv : rest2 / (D - yv);
    const double Up = un >= 0.0 ? U0 + un : rest2 / (U0 - un);
    const double Xm1 = K * (Dp + Up) / ((D + U0) * Up);
    return log1p(Xm1) / (m->a_prime / c);
}

enum mech_status mech_charged_motion_at_lab_time(const struct mech_charged_motion *m, double t,
                                                 struct mech_charged_motion_state *s,
                                                 struct mech_error *err)
{
    if (!m || !s) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    if (!(isfinite(t) && t >= 0.0))
        return mech_error_set(err, MECH_EINVAL, "t", "t must be finite and >= 0, got %.17g", t);
    const double c = MECH_C;
    double ct, u0;
    enum mech_status st;
    if (!m->boosted) {
        const double tau = m->a_prime > 0.0 ? tau_electric(m, t) : t / m->gamma0;
        st = state_at(m, tau, s, &ct, &u0, "t", err);
        if (st == MECH_OK) s->t = t;
        return st;
    }
    /* Newton on c t(tau) - c t (increasing, slope gamma c >= c), kept inside
     * the bracket [lo, hi] (tau <= t since gamma >= 1) by bisection */
    double lo = 0.0, hi = t, tau = t / m->gamma0;
    for (int it = 0; it < 200; it++) {
        st = state_at(m, tau, s, &ct, &u0, "t", err);
        if (st != MECH_OK) {
            /* an overflow beyond the root: shrink the bracket */
            if (tau > lo) {
                hi = tau;
                tau = 0.5 * (lo + hi);
                continue;
            }
            return st;
        }
        const double f = ct - c * t;
        if (f == 0.0) break;
        if (f < 0.0) lo = tau;
        else hi = tau;
        double next = tau - f / u0;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (fabs(next - tau) <= 2.0 * DBL_EPSILON * fmax(tau, next) || hi - lo <= 2.0 * DBL_EPSILON * hi) {
            tau = next;
            break;
        }
        tau = next;
    }
    st = state_at(m, tau, s, &ct, &u0, "t", err);
    if (st == MECH_OK) s->t = t;
    return st;
}
