/* interval.c — the invariant interval of two events (notes §3.5: s² =
 * −c²Δt² + Δx² + Δy² + Δz²; §3.6: light cone and causality), computed from
 * exactly formed coordinate differences with compensated arithmetic, so far
 * events with a tiny interval keep their digits. */
#include "mech/relativity/interval.h"
#include "mech/base/compensated.h"

#include <float.h>
#include <math.h>

/* sign · (hi + lo)² = sign · (hi² + 2 hi lo + lo²), hi² split exactly. */
static void csum_add_square(struct mech_csum *a, double sign, double hi, double lo)
{
    double p = hi * hi;
    mech_csum_add(a, sign * p);
    mech_csum_add(a, sign * fma(hi, hi, -p));
    mech_csum_add(a, sign * (2.0 * hi * lo + lo * lo));
}

enum mech_status mech_interval_compute(const double e1[4], const double e2[4],
                                       struct mech_interval *out, struct mech_error *err)
{
    if (!e1 || !e2 || !out)
        return mech_error_set(err, MECH_EINVAL, "events", "two events are required");
    for (int i = 0; i < 4; i++)
        if (!isfinite(e1[i]) || !isfinite(e2[i]))
            return mech_error_set(err, MECH_EINVAL, "events", "event coordinates must be finite");
    struct mech_interval o;
    struct mech_csum acc = {0, 0};
    double scale = 0, in_err = 0;
    const double u = 0.5 * DBL_EPSILON; /* unit round-off 2^-53 */
    for (int i = 0; i < 4; i++) {
        /* TwoSum: hi + lo = e2 − e1 exactly. */
        double a = e2[i], b = -e1[i];
        double hi = a + b;
        double bv = hi - a;
        double lo = (a - (hi - bv)) + (b - bv);
        o.delta[i] = hi;
        csum_add_square(&acc, i == 0 ? -1.0 : 1.0, hi, lo);
        scale += hi * hi;
        /* d(s²)/d(e_k) = ±2Δ_k; each input may be off by u|e|. */
        in_err += 2.0 * fabs(hi) * u * (fabs(e1[i]) + fabs(e2[i]));
    }
    o.s2 = acc.s + acc.c;
    o.scale = scale;
    o.input_error = in_err;
    o.tolerance = MECH_INTERVAL_LIGHTLIKE_ULPS * DBL_EPSILON * scale + in_err;
    o.coincident = scale == 0;
    if (fabs(o.s2) <= o.tolerance)
        o.kind = MECH_INTERVAL_LIGHTLIKE;
    else
        o.kind = o.s2 < 0 ? MECH_INTERVAL_TIMELIKE : MECH_INTERVAL_SPACELIKE;
    o.proper = o.kind == MECH_INTERVAL_LIGHTLIKE ? 0.0 : sqrt(fabs(o.s2));
    o.time_order_reversible = o.kind == MECH_INTERVAL_SPACELIKE;
    o.has_frame = 0;

    if (o.kind != MECH_INTERVAL_LIGHTLIKE) {
        /* Timelike: the frame moving with Δx/Δct (co-located);
         * spacelike: with Δct Δx/|Δx|² (simultaneous: Δct' = γ(Δct − β·Δx) = 0).
         * 1 − |β| = (big − small)/big = |s²| / (big (big + small)), big and small
         * being |Δct| and |Δx|; never the difference of the two. */
        double t = fabs(o.delta[0]);
        struct mech_vec3 dx = mech_vec3_make(o.delta[1], o.delta[2], o.delta[3]);
        double r = mech_vec3_norm(dx);
        double big = o.kind == MECH_INTERVAL_TIMELIKE ? t : r;
        double small = o.kind == MECH_INTERVAL_TIMELIKE ? r : t;
        struct mech_vec3 dir = mech_vec3_scale(dx, o.delta[0] < 0 ? -1.0 : 1.0);
        enum mech_status st;
        if (small == 0) {
            st = mech_boost_from_beta(mech_vec3_make(0, 0, 0), &o.frame, NULL);
        } else {
            double eps = fabs(o.s2) / big / (big + small);
            if (eps > 1.0) eps = 1.0;
            st = mech_boost_from_one_minus_beta(eps, dir, &o.frame, NULL);
        }
        o.has_frame = st == MECH_OK;
    }
    *out = o;
    return MECH_OK;
}
