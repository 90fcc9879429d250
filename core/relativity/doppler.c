/* doppler.c — relativistic Doppler factor and aberration of light between a
 * moving source and a moving observer, precise from 1e-12 c to γ = 1e15.
 *
 * Derivation (notes §3.14 "The Relativistic Doppler Effect", rebuilt with the
 * passive boost of §3.3 because the PDF lost the signs): a photon of
 * frequency ν and unit direction k̂ in a frame F has 4-momentum ν(1, k̂); in a
 * frame G moving with velocity βc â relative to F, ν' = γν(1 − β k̂·â) (the
 * time component of x0' = γ(x0 − β x∥)). With α_F = ∠(k̂, â):
 *   ν_G/ν_F = γ(1 − β cos α_F) = e^{−η} + 2 sinh η sin²(α_F/2)      (1)
 *   ν_G/ν_F − 1 = (γ − 1) − sinh η cos α_F                           (2)
 * and the direction in G, measured from F's velocity as seen in G:
 *   tan(α_G/2) = e^{−η} cot(α_F/2)                                    (3)
 * ((3) is cos θ' = (cos α − β)/(1 − β cos α) in half-angle form, with
 * α_G = π − θ'). (1) has no cancellation at any speed, (2) none at small
 * speeds, (3) none anywhere. Special cases: α_S = 0 → D = e^{−η} (receding,
 * the notes' sqrt((1 − β)/(1 + β))), α_S = π → e^{η}, α_S = π/2 → γ,
 * α_O = π/2 → 1/γ (the notes' transverse red shift ν' = ν/γ).
 */
#include "mech/relativity/doppler.h"
#include "mech/base/constants.h"
#include "mech/base/compensated.h"

#include <math.h>

/* ---- accurate small vector arithmetic ------------------------------------ */

static struct mech_vec3 negated(struct mech_vec3 v)
{
    return mech_vec3_make(0.0 - v.x, 0.0 - v.y, 0.0 - v.z);
}

/* Rodrigues: rotate v about the unit axis k by the angle whose cosine and
 * sine are c and s. */
static struct mech_vec3 rotate(struct mech_vec3 v, struct mech_vec3 k, double c, double s)
{
    struct mech_vec3 kxv = mech_vec3_cross(k, v);
    double kv = mech_vec3_dot(k, v);
    return mech_vec3_make(v.x * c + kxv.x * s + k.x * kv * (1 - c),
                          v.y * c + kxv.y * s + k.y * kv * (1 - c),
                          v.z * c + kxv.z * s + k.z * kv * (1 - c));
}

const char *mech_doppler_case_name(enum mech_doppler_case c)
{
    switch (c) {
    case MECH_DOPPLER_NO_RELATIVE_MOTION:
        return "no_relative_motion";
    case MECH_DOPPLER_LONGITUDINAL_APPROACHING:
        return "longitudinal_approaching";
    case MECH_DOPPLER_LONGITUDINAL_RECEDING:
        return "longitudinal_receding";
    case MECH_DOPPLER_TRANSVERSE_SOURCE_FRAME:
        return "transverse_source_frame";
    case MECH_DOPPLER_TRANSVERSE_OBSERVER_FRAME:
        return "transverse_observer_frame";
    case MECH_DOPPLER_GENERAL:
        return "general";
    }
    return "general";
}

/* ---- relative motion ------------------------------------------------------ */

void mech_doppler_relative_motion(const struct mech_boost *frame, const struct mech_boost *body,
                                  struct mech_vec3 *w, struct mech_vec3 *direction, double *gamma,
                                  double *gamma_minus_one)
{
    struct mech_vec3 dir;
    if (body->rapidity == 0 || frame->rapidity == 0) {
        /* One rests in the lab: a body at rest is seen from F moving with −β_F
         * (notes §3.3); from the lab, the body moves with its own β. */
        const int body_rests = body->rapidity == 0;
        const struct mech_boost *m = body_rests ? frame : body;
        dir = body_rests ? negated(frame->direction) : body->direction;
        *w = mech_vec3_scale(dir, m->beta_gamma);
        if (direction) *direction = dir;
        *gamma = m->gamma;
        *gamma_minus_one = m->gamma_minus_one;
        return;
    }
    const struct mech_vec3 n = frame->direction, m = body->direction;
    const double sh = body->beta_gamma, ch = body->gamma;
    if (n.x == m.x && n.y == m.y && n.z == m.z && sh == frame->beta_gamma && ch == frame->gamma) {
        /* The same velocity: one rest frame, exactly. */
        *w = mech_vec3_make(0, 0, 0);
        if (direction) *direction = n;
        *gamma = 1;
        *gamma_minus_one = 0;
        return;
    }
    /* Body 4-velocity U = (cosh η_M, sinh η_M m); split along n (angle φ). */
    const double cphi = mech_dot_compensated(m, n);
    const struct mech_vec3 mperp = mech_cross_compensated(n, mech_cross_compensated(m, n)); /* m − (m·n) n */
    const struct mech_vec3 dm = mech_vec3_sub(m, n), sm = mech_vec3_add(m, n);
    const double s2 = 0.25 * mech_vec3_dot(dm, dm); /* sin²(φ/2), from the chord */
    const double c2 = 0.25 * mech_vec3_dot(sm, sm); /* cos²(φ/2) */
    /* Light-cone components u = U0 − U∥ and v = U0 + U∥ as sums of positive
     * terms: cosh η ∓ sinh η cos φ = e^{−η} + 2 sinh η {sin², cos²}(φ/2).
     * The passive boost scales them by e^{±η_F} exactly (boost.h). */
    const double u = body->exp_neg_rapidity + 2.0 * sh * s2;
    const double v = body->exp_neg_rapidity + 2.0 * sh * c2;
    const double up = frame->exp_rapidity * u, vp = frame->exp_neg_rapidity * v;
    const double wpar_lc = 0.5 * (vp - up);
    const double err_lc = 0.5 * (up + vp);
    /* γ − 1 form: U∥' = U∥ + [(γ_F − 1) U∥ − β_Fγ_F U0], better at small η_F. */
    const double upar = sh * cphi;
    const double wpar_m = upar + fma(frame->gamma_minus_one, upar, -(frame->beta_gamma * ch));
    const double err_m = frame->gamma_minus_one * fabs(upar) + frame->beta_gamma * ch;
    const double wpar = err_m <= err_lc ? wpar_m : wpar_lc;
    *w = mech_vec3_add(mech_vec3_scale(n, wpar), mech_vec3_scale(mperp, sh));
    /* Collinear motion keeps the frame's own axis bit for bit. */
    if (mperp.x == 0 && mperp.y == 0 && mperp.z == 0)
        dir = wpar >= 0 ? n : negated(n);
    else if (!mech_vec3_unit_checked(*w, &dir))
        dir = n;
    if (direction) *direction = dir;
    /* γ and γ − 1 from |w| = βγ: γ − 1 = |w|²/(1 + γ) (no cancellation). */
    const double nw = mech_vec3_norm(*w);
    const double g = hypot(1.0, nw);
    const double gm1 = nw * (nw / (1.0 + g));
    *gamma_minus_one = gm1;
    *gamma = gm1 < 1.0 ? 1.0 + gm1 : g;
}

/* ---- the Doppler factor ---------------------------------------------------- */

enum mech_status mech_doppler_compute(const struct mech_boost *source,
                                      const struct mech_boost *observer, struct mech_vec3 direction,
                                      enum mech_doppler_frame frame, struct mech_doppler *out,
                                      struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    struct mech_vec3 dn;
    if (!mech_vec3_unit_checked(direction, &dn))
        return mech_error_set(err, MECH_EINVAL, "direction",
                              "the light's direction must be a nonzero finite vector");
    struct mech_boost rest;
    enum mech_status st = mech_boost_from_beta(mech_vec3_make(0, 0, 0), &rest, err);
    if (st != MECH_OK) return st;
    if (!source) source = &rest;
    if (!observer) observer = &rest;

    /* F: the frame the direction is given in; G: the other one. */
    const int in_source = frame == MECH_DOPPLER_SOURCE_FRAME;
    const struct mech_boost *bf = in_source ? source : observer;
    const struct mech_boost *bg = in_source ? observer : source;
    struct mech_vec3 wf, wg, af, ag;
    double gf, gm1f, gg, gm1g;
    mech_doppler_relative_motion(bf, bg, &wf, &af, &gf, &gm1f); /* G's 4-velocity in F */
    mech_doppler_relative_motion(bg, bf, &wg, &ag, &gg, &gm1g); /* F's 4-velocity in G */

    struct mech_doppler o;
    const double nw = mech_vec3_norm(wf);
    o.gamma = gf;
    o.gamma_minus_one = gm1f;
    o.beta_gamma = nw;
    o.beta = nw / gf;
    double en = 1.0 / (gf + nw); /* e^{−η} = 1/(γ(1 + β)) */
    o.rapidity = log1p(gm1f + nw);
    o.one_minus_beta = en / gf; /* 1 − tanh η = e^{−η}/cosh η */
    if (bf->rapidity == 0 || bg->rapidity == 0) {
        /* One of the two rests in the lab: the relative motion is the other's
         * boost, whose quantities were built from the caller's own form. */
        const struct mech_boost *m = bf->rapidity == 0 ? bg : bf;
        o.gamma = m->gamma;
        o.gamma_minus_one = m->gamma_minus_one;
        o.beta_gamma = m->beta_gamma;
        o.beta = m->beta;
        o.rapidity = m->rapidity;
        o.one_minus_beta = m->one_minus_beta;
        en = m->exp_neg_rapidity;
    }
    const struct mech_vec3 bfv = mech_vec3_scale(wf, 1.0 / gf), bgv = mech_vec3_scale(wg, 1.0 / gg);
    o.observer_beta_in_source = in_source ? bfv : bgv;
    o.source_beta_in_observer = in_source ? bgv : bfv;

    double r, rm1, alpha_f, alpha_g;
    struct mech_vec3 ng;
    if (nw == 0) {
        /* Same velocity: one frame, no shift, no aberration. */
        o.kind = MECH_DOPPLER_NO_RELATIVE_MOTION;
        r = 1;
        rm1 = 0;
        alpha_f = alpha_g = NAN;
        ng = dn;
    } else {
        if (mech_vec3_norm(wg) == 0) ag = negated(af);
        /* α_F from atan2 of |k̂ × â| and k̂·â; its supplement separately, so the
         * half-angles sin(α/2), cos(α/2) are accurate at both ends. */
        const double sf = mech_vec3_norm(mech_cross_compensated(dn, af));
        const double cf = fmax(-1.0, fmin(1.0, mech_dot_compensated(dn, af)));
        alpha_f = atan2(sf, cf);
        const double alpha_f_sup = atan2(sf, -cf);
        double shf, chf;
        if (alpha_f <= 0.5 * MECH_PI) {
            shf = sin(0.5 * alpha_f);
            chf = cos(0.5 * alpha_f);
        } else {
            shf = cos(0.5 * alpha_f_sup);
            chf = sin(0.5 * alpha_f_sup);
        }
        const double bgr = o.beta_gamma, gm1 = o.gamma_minus_one, gam = o.gamma;
        /* (1); where β cos α_F ≤ ½ the direct γ − βγ cos α_F has no
         * cancellation either and is exact for α_F = π/2 (D = γ). */
        if (bgr * cf <= 0.5 * gam)
            r = fma(-bgr, cf, gam);
        else
            r = en + 2.0 * bgr * shf * shf;
        const double rm1_t = fma(-bgr, cf, gm1); /* (2) */
        const double err_t = gm1 + bgr * fabs(cf);
        rm1 = err_t <= fmax(r, 1.0) ? rm1_t : r - 1.0;
        alpha_g = 2.0 * atan2(en * chf, shf); /* (3) */
        const double alpha_g_sup = 2.0 * atan2(shf, en * chf);
        /* sin α_G = sin α_F/r (positive terms); cos α_G = γ(β − cos α_F)/r when
         * that does not cancel (exact β at α_F = π/2), else from the angle. */
        const double sg = fmin(1.0, sf / r);
        double cg;
        if (bgr + gam * fabs(cf) <= r)
            cg = fma(-gam, cf, bgr) / r;
        else
            cg = alpha_g <= 0.5 * MECH_PI ? cos(alpha_g) : -cos(alpha_g_sup);
        /* The light's direction in G: cos α_G â_G + sin α_G R ê⊥, where ê⊥ is
         * the unit part of k̂ perpendicular to â_F (a boost along â_F keeps
         * it) and R is the Wigner rotation between F's and G's axes: it fixes
         * c = β_F × β_G (perpendicular to both boosts, so the same vector in
         * the lab, F and G) and takes â_F to −â_G. Collinear motion: R = 1. */
        struct mech_vec3 eperp = mech_vec3_make(0, 0, 0);
        if (sf > 0 && mech_vec3_unit_checked(mech_cross_compensated(af, mech_cross_compensated(dn, af)), &eperp)) {
            struct mech_vec3 axis;
            if (mech_vec3_unit_checked(mech_cross_compensated(source->direction, observer->direction), &axis) &&
                source->rapidity > 0 && observer->rapidity > 0) {
                const struct mech_vec3 b = negated(ag);
                const double so = mech_vec3_dot(axis, mech_cross_compensated(af, b));
                const double co = mech_dot_compensated(af, b);
                const double om = atan2(so, co);
                eperp = rotate(eperp, axis, cos(om), sin(om));
            }
        }
        if (!mech_vec3_unit_checked(mech_vec3_add(mech_vec3_scale(ag, cg), mech_vec3_scale(eperp, sg)), &ng)) ng = ag;

        /* Name the case (MECH_DOPPLER_CASE_TOL); α_S < π/2 means the light
         * runs along the observer's velocity: the observer recedes. */
        const double alpha_s = in_source ? alpha_f : alpha_g;
        if (sf <= MECH_DOPPLER_CASE_TOL)
            o.kind = alpha_s < 0.5 * MECH_PI ? MECH_DOPPLER_LONGITUDINAL_RECEDING
                                          : MECH_DOPPLER_LONGITUDINAL_APPROACHING;
        else if (fabs(cf) <= MECH_DOPPLER_CASE_TOL)
            o.kind = in_source ? MECH_DOPPLER_TRANSVERSE_SOURCE_FRAME
                               : MECH_DOPPLER_TRANSVERSE_OBSERVER_FRAME;
        else if (fabs(cg) <= MECH_DOPPLER_CASE_TOL)
            o.kind = in_source ? MECH_DOPPLER_TRANSVERSE_OBSERVER_FRAME
                               : MECH_DOPPLER_TRANSVERSE_SOURCE_FRAME;
        else
            o.kind = MECH_DOPPLER_GENERAL;
    }

    /* r = ν_G/ν_F; D = ν_obs/ν_emit is r when F is the source, 1/r otherwise. */
    if (in_source) {
        o.factor = r;
        o.factor_minus_one = rm1;
        o.direction_source = dn;
        o.direction_observer = ng;
        o.angle_source = alpha_f;
        o.angle_observer = alpha_g;
    } else {
        o.factor = 1.0 / r;
        o.factor_minus_one = -rm1 / r;
        o.direction_source = ng;
        o.direction_observer = dn;
        o.angle_source = alpha_g;
        o.angle_observer = alpha_f;
    }
    if (!isfinite(o.factor) || !(o.factor > 0) || !isfinite(o.factor_minus_one) ||
        !isfinite(o.gamma) || !isfinite(o.rapidity) || !mech_vec3_isfinite(o.direction_source) ||
        !mech_vec3_isfinite(o.direction_observer) ||
        !mech_vec3_isfinite(o.observer_beta_in_source) ||
        !mech_vec3_isfinite(o.source_beta_in_observer))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the Doppler factor is beyond double precision (relative rapidity "
                              "%.6g)",
                              o.rapidity);
    *out = o;
    return MECH_OK;
}
