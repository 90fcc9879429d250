/* worldline.c — the twin paradox (notes §3.15) for any chain of legs:
 * proper time by leg, the stay-at-home time, and the Doppler bookkeeping of
 * what each twin sees of the other's clock (notes §3.14), all without the
 * cancellations that ruin T − τ at 1 m/s or t − |x|/c at β = 1 − 1e-15.
 *
 * Hyperbolic motion (constant proper acceleration a along e, from rapidity
 * η0): η(τ) = η0 + aτ/c, ct = (c²/a)(sinh η − sinh η0),
 * x·e = (c²/a)(cosh η − cosh η0). With h = aτ/(2c), m = η0 + h these are
 * ct = K cosh m, x·e = K sinh m, K = (c²/a) 2 sinh h = cτ sinh(h)/h
 * (sinh A − sinh B = 2 cosh((A+B)/2) sinh((A−B)/2), same for cosh), exact as
 * aτ/c → 0, and ct − |x·e| = K e^{−|m|} (light-cone form, never a difference).
 * From rest (η0 = 0): t = (c/a) sinh(aτ/c), x = (c²/a)(cosh(aτ/c) − 1).
 */
#include "mech/relativity/worldline.h"
#include "mech/base/constants.h"
#include "mech/base/compensated.h"

#include <math.h>
#include <stdio.h>

static double cosh_m1(double x)
{
    double sh = sinh(0.5 * x);
    return 2.0 * sh * sh;
}

/* sinh(h)/h − 1 = h²/3! + h⁴/5! + ... (series below 1, where the direct
 * difference would cancel; 14 terms reach round-off at h = 1). */
static double sinhc_m1(double h)
{
    if (fabs(h) >= 1.0) return sinh(h) / h - 1.0;
    double h2 = h * h, term = h2 / 6.0, sum = 0;
    for (int k = 1; k <= 14 && term != 0; k++) {
        sum += term;
        term *= h2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    }
    return sum;
}

/* |x| − x·e and |x| + x·e for a unit e, the smaller one as |x × e|²/(the larger). */
static void radial_parts(struct mech_vec3 x, struct mech_vec3 e, double *minus, double *plus)
{
    double r = mech_vec3_norm(x), p = mech_vec3_dot(x, e);
    struct mech_vec3 w = mech_vec3_cross(x, e);
    double w2 = mech_vec3_dot(w, w);
    if (p >= 0) {
        *plus = r + p;
        *minus = *plus > 0 ? w2 / *plus : 0.0;
    } else {
        *minus = r - p;
        *plus = w2 / *minus;
    }
}

static enum mech_status leg_error(struct mech_error *err, enum mech_status st, size_t k,
                                  const char *field, const char *text)
{
    char param[64];
    if (field)
        snprintf(param, sizeof param, "legs/%zu/%s", k, field);
    else
        snprintf(param, sizeof param, "legs/%zu", k);
    return mech_error_set(err, st, param, "leg %zu: %s", k, text);
}

enum mech_status mech_worldline_run(const struct mech_leg *legs, size_t n, double c,
                                    const struct mech_budget *budget, struct mech_leg_result *out,
                                    struct mech_worldline_total *total, struct mech_error *err)
{
    if (!legs || !out || !total || n == 0)
        return mech_error_set(err, MECH_EINVAL, "legs", "at least one leg is required");
    if (!(c > 0) || !isfinite(c))
        return mech_error_set(err, MECH_EINVAL, "units", "the speed of light must be > 0");
    struct mech_boost cur;
    mech_boost_from_beta(mech_vec3_make(0, 0, 0), &cur, NULL);
    struct mech_csum t = {0, 0}, tau = {0, 0}, age = {0, 0}, dist = {0, 0}, te = {0, 0}, tr = {0, 0};
    struct mech_vec3 x = mech_vec3_make(0, 0, 0);
    char text[200];

    for (size_t k = 0; k < n; k++) {
        enum mech_status st = mech_budget_check(budget, (long)k + 1, k == 0, err);
        if (st != MECH_OK) return st;
        const struct mech_leg *L = &legs[k];
        struct mech_leg_result *o = &out[k];
        double T, ptau, agek, path, lc; /* lc = cT − |Δx| ≥ 0 (length) */
        struct mech_vec3 disp;
        struct mech_boost fin;
        if (!(L->amount > 0) || !isfinite(L->amount))
            return leg_error(err, MECH_EINVAL, k, NULL,
                             "the leg's duration or distance must be > 0");

        if (L->kind != MECH_LEG_ACCELERATE) {
            const struct mech_boost *v = &L->velocity;
            double g = v->gamma, b = v->beta;
            if (L->kind == MECH_LEG_COAST_TIME) {
                T = L->amount;
                ptau = T / g;
                path = b * c * T;
            } else if (L->kind == MECH_LEG_COAST_DISTANCE) {
                if (!(b > 0))
                    return leg_error(err, MECH_EDOMAIN, k, "velocity",
                                     "a leg given by its distance needs a nonzero speed "
                                     "(at rest the distance is never covered)");
                path = L->amount;
                T = path / (b * c);
                ptau = path / (v->beta_gamma * c); /* τ = T/γ = D/(βγc) */
            } else {
                ptau = L->amount;
                T = g * ptau;
                path = v->beta_gamma * c * ptau;
            }
            /* T − τ = T (γ − 1)/γ: no cancellation at 1 m/s. */
            agek = T * (v->gamma_minus_one / g);
            lc = c * T * v->one_minus_beta; /* cT − βcT = cT(1 − β) */
            disp = mech_vec3_scale(v->direction, path);
            fin = *v;
        } else {
            double a = L->acceleration;
            if (!(a != 0) || !isfinite(a))
                return leg_error(err, MECH_EINVAL, k, "proper_acceleration",
                                 "the proper acceleration must be nonzero; use a constant-"
                                 "velocity leg to coast");
            struct mech_vec3 e = L->direction;
            double em = mech_vec3_norm(e);
            if (!(em > 0)) {
                if (cur.beta == 0)
                    return leg_error(err, MECH_EDOMAIN, k, "direction",
                                     "the traveller is at rest at the start of this leg, so "
                                     "the acceleration needs a direction");
                e = cur.direction;
            } else {
                e = mech_vec3_scale(e, 1.0 / em);
            }
            if (a < 0) {
                e = mech_vec3_scale(e, -1.0);
                a = -a;
            }
            double eta0 = 0;
            if (cur.beta > 0) {
                double cr = mech_vec3_norm(mech_vec3_cross(cur.direction, e));
                if (cr > 1e-9) {
                    snprintf(text, sizeof text,
                             "the acceleration must be along or against the current velocity "
                             "(they are %.3g degrees apart); sideways acceleration is not "
                             "supported",
                             atan2(cr, mech_vec3_dot(cur.direction, e)) *
                                 (180.0 / MECH_PI));
                    return leg_error(err, MECH_EDOMAIN, k, "direction", text);
                }
                eta0 = mech_vec3_dot(cur.direction, e) > 0 ? cur.rapidity : -cur.rapidity;
            }
            ptau = L->amount;
            double phi = a * ptau / c, eta1 = eta0 + phi;
            if (!(fabs(eta1) <= MECH_BOOST_RAPIDITY_MAX)) {
                snprintf(text, sizeof text,
                         "the traveller's rapidity would reach %.6g (gamma about e^%.4g/2), "
                         "beyond the %g this server represents: shorten the leg or lower "
                         "the acceleration",
                         eta1, fabs(eta1), MECH_BOOST_RAPIDITY_MAX);
                return leg_error(err, MECH_EDOMAIN, k, "proper_time", text);
            }
            double h = 0.5 * phi, m = eta0 + h;
            double shc = h > 0 ? sinh(h) / h : 1.0;
            double K = c * ptau * shc; /* (c²/a) 2 sinh h */
            T = ptau * shc * cosh(m);
            double de = K * sinh(m);
            /* T − τ = τ [shc (cosh m − 1) + (shc − 1)] */
            agek = ptau * (shc * cosh_m1(m) + sinhc_m1(h));
            lc = K * exp(-fabs(m));
            if (eta0 < 0 && eta1 > 0) /* turns round at η = 0 */
                path = (c * ptau / phi) * (cosh_m1(eta0) + cosh_m1(eta1));
            else
                path = fabs(de);
            disp = mech_vec3_scale(e, de);
            struct mech_error e1;
            mech_error_clear(&e1);
            if (mech_boost_from_rapidity(eta1, e, &fin, &e1) != MECH_OK)
                return leg_error(err, MECH_ENUMERIC, k, NULL, e1.text);
        }
        if (!isfinite(T) || !isfinite(ptau) || !isfinite(agek) || !isfinite(path) ||
            !isfinite(lc) || !mech_vec3_isfinite(disp))
            return leg_error(err, MECH_ENUMERIC, k, NULL, "the leg's times or distances overflow");

        /* Telescopes (notes §3.15): home light seen at event (t, x) left home at
         * t − |x|/c; the event is seen at home at t + |x|/c. Over the leg,
         * cΔ(t ∓ |x|) = (cΔt − |d|) + |d| (1 ∓ q), 1 ∓ q = ((|x_s| ∓ x_s·e) + (|x_e| ∓
         * x_e·e))/(|x_s| + |x_e|), d = x_e − x_s = |d| e: sums of terms ≥ 0. */
        struct mech_vec3 xe = mech_vec3_add(x, disp);
        double dlen = mech_vec3_norm(disp);
        double dte = lc / c, dtr = lc / c;
        if (dlen > 0) {
            struct mech_vec3 eh = mech_vec3_scale(disp, 1.0 / dlen);
            double ps, qs, pe, qe;
            radial_parts(x, eh, &ps, &qs);
            radial_parts(xe, eh, &pe, &qe);
            double den = mech_vec3_norm(x) + mech_vec3_norm(xe);
            dte = (lc + dlen * ((ps + pe) / den)) / c;
            dtr = (lc + dlen * ((qs + qe) / den)) / c;
        }

        o->proper_time = ptau;
        o->coordinate_time = T;
        o->age_difference = agek;
        o->distance = path;
        o->displacement = disp;
        o->start[0] = mech_csum_value(&t);
        o->start[1] = x.x;
        o->start[2] = x.y;
        o->start[3] = x.z;
        o->home_clock_seen_start = mech_csum_value(&te);
        o->home_receives_start = mech_csum_value(&tr);
        o->home_clock_seen = dte;
        o->home_receives = dtr;
        mech_csum_add(&t, T);
        mech_csum_add(&tau, ptau);
        mech_csum_add(&age, agek);
        mech_csum_add(&dist, path);
        mech_csum_add(&te, dte);
        mech_csum_add(&tr, dtr);
        x = xe;
        o->end[0] = mech_csum_value(&t);
        o->end[1] = x.x;
        o->end[2] = x.y;
        o->end[3] = x.z;
        o->home_clock_seen_end = mech_csum_value(&te);
        o->home_receives_end = mech_csum_value(&tr);
        o->final_velocity = fin;
        cur = fin;
    }
    total->proper_time = mech_csum_value(&tau);
    total->coordinate_time = mech_csum_value(&t);
    total->age_difference = mech_csum_value(&age);
    total->distance = mech_csum_value(&dist);
    total->end[0] = total->coordinate_time;
    total->end[1] = x.x;
    total->end[2] = x.y;
    total->end[3] = x.z;
    total->final_velocity = cur;
    total->home_clock_seen_end = mech_csum_value(&te);
    total->home_receives_end = mech_csum_value(&tr);
    if (!isfinite(total->coordinate_time) || !isfinite(total->home_receives_end) ||
        !mech_vec3_isfinite(x))
        return mech_error_set(err, MECH_ENUMERIC, "legs", "the trip's totals overflow");
    return MECH_OK;
}
