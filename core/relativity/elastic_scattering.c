/* elastic_scattering.c — two-body relativistic elastic scattering off a target
 * at rest, at a given CM, lab or recoil angle (see mech/relativity/elastic_scattering.h
 * for the formulas). Every lab quantity is built from the CM half-angle
 * h = θ* / 2 through sin²h and cos²h, so nothing cancels at grazing angles
 * (the recoil: p∥ = 2γ p* sin²h, T = 2 p*² sin²h / m2) nor when an equal-mass
 * projectile almost stops (p∥ = γ p* (2 cos²h + (g − 1))). */
#include "mech/base/constants.h"
#include "mech/relativity/elastic_scattering.h"

#include <float.h>
#include <math.h>


/* The lab momentum and energy of a particle of mass m leaving the CM frame
 * (boost b along +z) with momentum p* and energy E* at CM angle 2h (h ∈ [0,
 * π/2]); `gm1` is g − 1 = β/β* − 1 of that particle, computed exactly by the
 * caller. The energy: γ(E* + β p* cos θ*), with the backward form
 * (γ m² + p*²/γ)/(E* + β p*) + βγ p* (1 + cos θ*) when cos θ* < 0. */
static void lab_of(const struct mech_boost *b, double m, double pstar, double estar, double sh,
                   double ch, double gm1, struct mech_kin_lab *out)
{
    const double s2 = 2.0 * sh * sh, c2 = 2.0 * ch * ch; /* 1 − cos θ*, 1 + cos θ* */
    const double g = b->gamma, bg = b->beta_gamma, beta = b->beta;
    double e, ppar;
    if (ch >= sh) { /* θ* ≤ 90°: cos θ* = 1 − 2 sin²h, both terms ≥ 0 */
        e = g * estar + bg * pstar * (1.0 - s2);
        ppar = g * pstar * ((1.0 - s2) + (gm1 + 1.0));
    } else {
        const double back = ((g * m) * m + pstar * (pstar / g)) / (estar + beta * pstar);
        e = back + bg * pstar * c2;
        ppar = g * pstar * (c2 + gm1);
    }
    const double pperp = pstar * (2.0 * sh * ch);
    const double p = hypot(ppar, pperp);
    out->energy = e;
    out->momentum = p;
    out->momentum_parallel = ppar;
    out->momentum_transverse = pperp;
    out->angle = atan2(pperp, ppar);
    if (m == 0)
        out->kinetic = e;
    else if (e >= 2.0 * m)
        out->kinetic = e - m;
    else
        out->kinetic = p * (p / (e + m));
}

/* The whole answer at CM half-angle h (scaled units). */
static void at_half_angle(double m1, double m2, double pstar, const double estar[2],
                          const struct mech_boost *b, double gm1, double h,
                          struct mech_elastic *o)
{
    const double sh = sin(h), ch = cos(h);
    o->cm_angle = 2.0 * h;
    lab_of(b, m1, pstar, estar[0], sh, ch, gm1, &o->projectile);
    /* The recoil leaves the CM at θ* + π: its half-angle's sine and cosine
     * swap, and for a target at rest its g is exactly 1 (β E2* = p*). The
     * transverse momentum is opposite to the projectile's. */
    lab_of(b, m2, pstar, estar[1], ch, sh, 0.0, &o->recoil);
    o->recoil.momentum_transverse = -o->recoil.momentum_transverse;
    o->recoil.angle = atan2(-o->recoil.momentum_transverse, o->recoil.momentum_parallel);
    /* T4 = −t/(2 m2) = 2 p*² sin²h / m2 exactly (the target was at rest). */
    const double t4 = 2.0 * (pstar * sh) * (pstar * sh) / m2;
    o->recoil.kinetic = t4;
    o->recoil.energy = m2 + t4;
    o->recoil.momentum = sqrt(t4 * (t4 + 2.0 * m2));
    o->t = -4.0 * (pstar * sh) * (pstar * sh);
    o->momentum_transfer = 2.0 * pstar * sh;
    const double sum = o->projectile.angle + o->recoil.angle;
    o->opening_angle = sum <= MECH_PI ? sum : 2.0 * MECH_PI - sum;
}

enum mech_status mech_elastic_scatter(const struct mech_kin_motion *projectile, double m2,
                                      enum mech_elastic_angle kind, double angle, int branch,
                                      struct mech_elastic *out, struct mech_error *err)
{
    if (!projectile || !out)
        return mech_error_set(err, MECH_EINVAL, NULL, "projectile and out must not be NULL");
    if (!isfinite(m2) || !(m2 > 0))
        return mech_error_set(err, MECH_EDOMAIN, "target",
                              "the target must have a mass > 0 to be at rest, got %.17g", m2);
    const double m1r = projectile->mass, p1r = projectile->momentum, e1r = projectile->energy;
    if (!isfinite(m1r) || !isfinite(p1r) || !isfinite(e1r) || m1r < 0 || !(e1r >= m1r))
        return mech_error_set(err, MECH_EDOMAIN, "projectile",
                              "the projectile's mass, momentum and energy must be finite with "
                              "E >= m >= 0");
    if (!(p1r > 0))
        return mech_error_set(err, MECH_EDOMAIN, "projectile",
                              "the projectile is at rest: with the target at rest too, nothing "
                              "collides (give its energy, kinetic energy, momentum or velocity)");
    if (!isfinite(angle) || angle < 0 || angle > MECH_PI ||
        (kind == MECH_ELASTIC_RECOIL_ANGLE && angle > 0.5 * MECH_PI))
        return mech_error_set(err, MECH_EINVAL, "angle",
                              "the angle must be in [0, %s] radians, got %.17g",
                              kind == MECH_ELASTIC_RECOIL_ANGLE ? "pi/2" : "pi", angle);
    if (branch != 0 && branch != 1)
        return mech_error_set(err, MECH_EINVAL, "branch", "branch is 0 or 1, got %d", branch);

    /* Scale by a power of two near the largest energy: exact, and keeps the
     * squares below from overflowing or underflowing. */
    const double big = e1r > m2 ? e1r : m2;
    const double sc = ldexp(1.0, ilogb(big));
    const double m1 = m1r / sc, p1 = p1r / sc, e1 = e1r / sc;
    const double mt = m2 / sc;

    struct mech_elastic o = {0};
    const double etot = e1 + mt;
    const double s = m1 * m1 + mt * mt + 2.0 * mt * e1; /* all terms ≥ 0 */
    const double w = sqrt(s);
    const double pstar = p1 * (mt / w);
    double estar[2];
    estar[0] = (m1 * m1 + mt * e1) / w;
    estar[1] = mt * (etot / w);
    /* CM frame: a "particle" of mass W, momentum p1, energy E1 + m2, kinetic
     * E − W = p1²/(E + W). */
    struct mech_kin_motion cmm = {w, p1, etot, p1 * (p1 / (etot + w)), MECH_KIN_GIVEN_MOMENTUM};
    enum mech_status st = mech_kin_motion_boost(&cmm, mech_vec3_make(0, 0, 1), &o.cm, err);
    if (st != MECH_OK) return st;
    /* g = β/β1* = (m1² + m2 E1)/(m2 (E1 + m2)); g − 1 = (m1 − m2)(m1 + m2)/(m2 (E1 + m2)). */
    const double g = (m1 * m1 + mt * e1) / (mt * etot);
    const double gm1 = ((m1 - mt) * (m1 + mt)) / (mt * etot);
    const double gam = o.cm.gamma;

    o.has_max_angle = gm1 > 0;
    if (o.has_max_angle) o.max_angle = atan2(1.0, gam * sqrt(gm1 * (gm1 + 2.0)));

    /* The CM half-angles that give the requested angle. */
    double hs[2];
    size_t nh = 0;
    if (kind == MECH_ELASTIC_CM_ANGLE) {
        hs[nh++] = 0.5 * angle;
    } else if (kind == MECH_ELASTIC_RECOIL_ANGLE) {
        if (angle >= 0.5 * MECH_PI)
            return mech_error_set(err, MECH_EDOMAIN, "angle",
                                  "a target at rest always recoils forward, below 90 degrees");
        /* tan θ4 = cot(θ* / 2)/γ  ⇒  θ* / 2 = atan2(cos θ4, γ sin θ4). */
        hs[nh++] = atan2(cos(angle), gam * sin(angle));
    } else {
        if (gm1 == 0 && angle >= 0.5 * MECH_PI)
            return mech_error_set(err, MECH_EDOMAIN, "angle",
                                  "with equal masses the projectile's lab angle is below 90 "
                                  "degrees (90 is the limit where it stops), got %.17g degrees",
                                  angle * 180.0 / MECH_PI);
        /* sin θ* cos θ3 − γ sin θ3 cos θ* = g γ sin θ3, i.e. R sin(θ* − δ) = g B. */
        const double a = cos(angle), bb = gam * sin(angle);
        const double r = hypot(a, bb), delta = atan2(bb, a);
        double x = g * (bb / r);
        if (x > 1.0) {
            if (x > 1.0 + 8.0 * DBL_EPSILON)
                return mech_error_set(err, MECH_EDOMAIN, "angle",
                                      "the projectile (heavier than the target) cannot be "
                                      "deflected by more than %.17g degrees in the lab, got "
                                      "%.17g degrees",
                                      o.max_angle * 180.0 / MECH_PI, angle * 180.0 / MECH_PI);
            x = 1.0;
        }
        const double as = asin(x);
        const double cand[2] = {delta + as, delta + MECH_PI - as};
        for (int k = 0; k < 2; k++) {
            double th = cand[k];
            if (th < -1e-12 || th > MECH_PI + 1e-12) continue;
            th = th < 0 ? 0 : th > MECH_PI ? MECH_PI : th;
            if (nh == 1 && fabs(2.0 * hs[0] - th) <= 1e-12) continue;
            /* keep it only if the lab momentum really points at the angle (the
             * squared equation also holds for the opposite direction). */
            struct mech_elastic trial = o;
            at_half_angle(m1, mt, pstar, estar, &o.cm, gm1, 0.5 * th, &trial);
            if (!(trial.projectile.momentum > 1e-12 * p1) ||
                fabs(trial.projectile.angle - angle) > 1e-6)
                continue;
            hs[nh++] = 0.5 * th;
        }
        if (nh == 2 && hs[1] < hs[0]) {
            const double tmp = hs[0];
            hs[0] = hs[1];
            hs[1] = tmp;
        }
        if (nh == 0)
            return mech_error_set(err, MECH_EDOMAIN, "angle",
                                  "no scattering sends the projectile to %.17g degrees in the lab",
                                  angle * 180.0 / MECH_PI);
    }
    if ((size_t)branch >= nh) branch = (int)nh - 1;
    at_half_angle(m1, mt, pstar, estar, &o.cm, gm1, hs[branch], &o);
    o.n_solutions = nh;
    for (size_t k = 0; k < nh; k++) o.cm_angle_solutions[k] = 2.0 * hs[k];

    /* Back to the caller's unit. */
    o.s = s * sc * sc;
    o.sqrt_s = w * sc;
    o.t *= sc * sc;
    /* u = 2m1² + 2m2² − s − t, written as m1² + m2² − 2(E1*E2* + p*² cos θ*) with
     * E1*E2* + p*² cos θ* = X + 2 p*² cos²(θ* / 2), X = E1*E2* − p*² =
     * (m1²m2² + p*²(m1² + m2²))/(E1*E2* + p*²) ≥ 0. */
    {
        const double ch = cos(hs[branch]);
        const double x = (m1 * m1 * mt * mt + pstar * pstar * (m1 * m1 + mt * mt)) /
                         (estar[0] * estar[1] + pstar * pstar);
        o.u = (m1 * m1 + mt * mt - 2.0 * (x + 2.0 * pstar * pstar * ch * ch)) * sc * sc;
    }
    o.momentum_transfer *= sc;
    o.cm_momentum = pstar * sc;
    o.cm_energy[0] = estar[0] * sc;
    o.cm_energy[1] = estar[1] * sc;
    o.cm_kinetic[0] = pstar * (pstar / (estar[0] + m1)) * sc;
    o.cm_kinetic[1] = pstar * (pstar / (estar[1] + mt)) * sc;
    o.velocity_ratio = fabs(gm1) < 0.5 ? 1.0 + gm1 : g; /* exactly 1 for equal masses */
    struct mech_kin_lab *ls[2] = {&o.projectile, &o.recoil};
    for (int k = 0; k < 2; k++) {
        ls[k]->energy *= sc;
        ls[k]->kinetic *= sc;
        ls[k]->momentum *= sc;
        ls[k]->momentum_parallel *= sc;
        ls[k]->momentum_transverse *= sc;
    }
    const double chk[] = {o.s,
                          o.t,
                          o.u,
                          o.cm_momentum,
                          o.cm_energy[0],
                          o.cm_energy[1],
                          o.projectile.energy,
                          o.projectile.kinetic,
                          o.projectile.momentum,
                          o.projectile.angle,
                          o.recoil.energy,
                          o.recoil.kinetic,
                          o.recoil.momentum,
                          o.recoil.angle,
                          o.opening_angle,
                          o.cm.gamma};
    for (size_t k = 0; k < sizeof chk / sizeof chk[0]; k++)
        if (!isfinite(chk[k]))
            return mech_error_set(err, MECH_ENUMERIC, NULL,
                                  "elastic scattering: a result is not finite (energies beyond "
                                  "what doubles carry)");
    *out = o;
    return MECH_OK;
}
