/* em_fields.c — E and B under a Lorentz boost (any direction), with the
 * invariants E² − B² and E·B before and after, precise at every speed.
 *
 * Derivation (notes "Lorentz Transformation of the Fields": F'µν = Λ F Λᵀ for
 * a boost along x gives E'x = Ex, E'y = γ(Ey − βBz), E'z = γ(Ez + βBy),
 * B'x = Bx, B'y = γ(By + βEz), B'z = γ(Bz − βEy); the PDF lost the signs, so
 * they are rebuilt from x' = γ(x − βct) and checked against the field of a
 * moving charge). In vector form along any unit n:
 *   E'⊥ = γ(E⊥ + β n×B),   B'⊥ = γ(B⊥ − β n×E).
 * With P = E⊥ + n×B, M = E⊥ − n×B (note n×(n×X) = −X⊥):
 *   E'⊥ + n×B'⊥ = γ(1 + β) P = e^{η} P,  E'⊥ − n×B'⊥ = γ(1 − β) M = e^{−η} M,
 * so E'⊥ = (P' + M')/2 and B'⊥ = n×(M' − P')/2. A plane wave running along
 * +n (B = n×E) has P = 0 and its amplitude scales by e^{−η}, the Doppler
 * factor of an observer receding with the wave (notes §3.14).
 */
#include "mech/relativity/em_fields.h"
#include "mech/base/compensated.h"

#include <math.h>

/* ---- compensated arithmetic (as in boost.c, file-local) ------------------- */

/* x − (n·x) n, with n·x compensated and the subtraction fused. */
static struct mech_vec3 perp(struct mech_vec3 x, struct mech_vec3 n, double xpar)
{
    return mech_vec3_make(fma(-xpar, n.x, x.x), fma(-xpar, n.y, x.y), fma(-xpar, n.z, x.z));
}

static double sum_abs(struct mech_vec3 v)
{
    return fabs(v.x) + fabs(v.y) + fabs(v.z);
}

struct mech_em_invariants mech_em_invariants_of(struct mech_vec3 e, struct mech_vec3 b,
                                                enum mech_em_units units)
{
    struct mech_em_invariants r;
    struct mech_vec3 cb = units == MECH_EM_SI ? mech_vec3_scale(b, MECH_C) : b;
    struct mech_csum s = {0, 0};
    mech_csum_add_product(&s, e.x, e.x);
    mech_csum_add_product(&s, e.y, e.y);
    mech_csum_add_product(&s, e.z, e.z);
    mech_csum_add_product(&s, -cb.x, cb.x);
    mech_csum_add_product(&s, -cb.y, cb.y);
    mech_csum_add_product(&s, -cb.z, cb.z);
    r.e2_minus_b2 = mech_csum_value(&s);
    r.e_dot_b = mech_dot_compensated(e, b);
    return r;
}

enum mech_status mech_em_fields_boost(const struct mech_boost *boost, struct mech_vec3 e,
                                      struct mech_vec3 b, enum mech_em_units units,
                                      struct mech_em_boosted *out, struct mech_error *err)
{
    if (!boost || !out) return mech_error_set(err, MECH_EINVAL, NULL, "boost and output required");
    if (!mech_vec3_isfinite(e)) return mech_error_set(err, MECH_EINVAL, "E", "E must be finite");
    if (!mech_vec3_isfinite(b)) return mech_error_set(err, MECH_EINVAL, "B", "B must be finite");
    const int si = units == MECH_EM_SI;
    /* SI: work with cB, which transforms exactly as the Heaviside–Lorentz B. */
    const struct mech_vec3 cb = si ? mech_vec3_scale(b, MECH_C) : b;
    const struct mech_vec3 n = boost->direction;
    const double gm1 = boost->gamma_minus_one, bg = boost->beta_gamma;
    const double ep = boost->exp_rapidity, en = boost->exp_neg_rapidity;

    struct mech_em_boosted o;
    o.before = mech_em_invariants_of(e, b, units);
    o.scale2 = mech_dot_compensated(e, e) + mech_dot_compensated(cb, cb);

    const double epar = mech_dot_compensated(n, e), bpar = mech_dot_compensated(n, cb);
    const struct mech_vec3 eperp = perp(e, n, epar), bperp = perp(cb, n, bpar);
    const struct mech_vec3 nxb = mech_cross_compensated(n, cb), nxe = mech_cross_compensated(n, e);

    /* Light-cone form: P' = e^{η}(E⊥ + n×B), M' = e^{−η}(E⊥ − n×B). */
    const struct mech_vec3 pp = mech_vec3_scale(mech_vec3_add(eperp, nxb), ep);
    const struct mech_vec3 mp = mech_vec3_scale(mech_vec3_sub(eperp, nxb), en);
    const struct mech_vec3 eperp_lc = mech_vec3_scale(mech_vec3_add(pp, mp), 0.5);
    const struct mech_vec3 bperp_lc = mech_cross_compensated(n, mech_vec3_scale(mech_vec3_sub(mp, pp), 0.5));
    const double err_lc = 0.5 * (sum_abs(pp) + sum_abs(mp));

    /* γ − 1 form: X' = X⊥ + [(γ − 1) X⊥ ± βγ n×Y], accurate at small η. */
    const struct mech_vec3 eperp_m = mech_vec3_make(eperp.x + fma(gm1, eperp.x, bg * nxb.x),
                                                    eperp.y + fma(gm1, eperp.y, bg * nxb.y),
                                                    eperp.z + fma(gm1, eperp.z, bg * nxb.z));
    const struct mech_vec3 bperp_m = mech_vec3_make(bperp.x + fma(gm1, bperp.x, -(bg * nxe.x)),
                                                    bperp.y + fma(gm1, bperp.y, -(bg * nxe.y)),
                                                    bperp.z + fma(gm1, bperp.z, -(bg * nxe.z)));
    const double err_me = gm1 * sum_abs(eperp) + bg * sum_abs(nxb);
    const double err_mb = gm1 * sum_abs(bperp) + bg * sum_abs(nxe);

    const struct mech_vec3 ep_new = err_me <= err_lc ? eperp_m : eperp_lc;
    const struct mech_vec3 bp_new = err_mb <= err_lc ? bperp_m : bperp_lc;
    o.e = mech_vec3_make(fma(epar, n.x, ep_new.x), fma(epar, n.y, ep_new.y),
                         fma(epar, n.z, ep_new.z));
    const struct mech_vec3 cb_new = mech_vec3_make(
        fma(bpar, n.x, bp_new.x), fma(bpar, n.y, bp_new.y), fma(bpar, n.z, bp_new.z));
    o.b = si ? mech_vec3_scale(cb_new, 1.0 / MECH_C) : cb_new;

    /* Invariants of the boosted fields from the boosted light-cone vectors:
     * E'⊥² − B'⊥² = P'·M' and E'⊥·B'⊥ = ½ n·(M'×P'), never from the large
     * rounded components (which would cancel at large γ). */
    struct mech_csum s = {0, 0};
    mech_csum_add_product(&s, epar, epar);
    mech_csum_add_product(&s, -bpar, bpar);
    mech_csum_add_product(&s, pp.x, mp.x);
    mech_csum_add_product(&s, pp.y, mp.y);
    mech_csum_add_product(&s, pp.z, mp.z);
    o.after.e2_minus_b2 = mech_csum_value(&s);
    const struct mech_vec3 mxp = mech_cross_compensated(mp, pp);
    struct mech_csum d = {0, 0};
    mech_csum_add_product(&d, epar, bpar);
    mech_csum_add_product(&d, 0.5 * n.x, mxp.x);
    mech_csum_add_product(&d, 0.5 * n.y, mxp.y);
    mech_csum_add_product(&d, 0.5 * n.z, mxp.z);
    o.after.e_dot_b = mech_csum_value(&d);
    if (si) o.after.e_dot_b /= MECH_C; /* E·(cB)/c */

    if (!mech_vec3_isfinite(o.e) || !mech_vec3_isfinite(o.b) || !isfinite(o.scale2) ||
        !isfinite(o.before.e2_minus_b2) || !isfinite(o.before.e_dot_b) ||
        !isfinite(o.after.e2_minus_b2) || !isfinite(o.after.e_dot_b))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "boosted fields or their invariants overflow (gamma %.3g)",
                              boost->gamma);
    *out = o;
    return MECH_OK;
}
