/* decay_estimate.c — the notes' neutron-decay estimate of a daughter's largest
 * energy beside the exact endpoint (see mech/relativity/decay_estimate.h for the
 * derivation and the cancellation-free differences). */
#include "mech/relativity/decay_estimate.h"

#include <math.h>

#include "mech/relativity/kinematics.h"

enum mech_status mech_decay_endpoint_estimate(double parent, const double *m, size_t n, size_t i,
                                              struct mech_decay_estimate *out,
                                              struct mech_error *err)
{
    if (!m || !out || n < 2 || i >= n)
        return mech_error_set(err, MECH_EINVAL, "daughters", "need at least two daughters");
    double s = 0;
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(m[j]) || m[j] < 0)
            return mech_error_set(err, MECH_EINVAL, "daughters",
                                  "daughter %zu has mass %.17g: masses are finite and >= 0", j,
                                  m[j]);
        if (j != i) s += m[j];
    }
    double e_max, t, p;
    enum mech_status st = mech_kin_endpoint(parent, m, n, i, &e_max, &t, &p, err);
    if (st != MECH_OK) return st;
    if (!(s > 0))
        return mech_error_set(err, MECH_EDOMAIN, "daughters",
                              "the other daughters are massless: there is no heavy recoil for "
                              "the notes' estimate");
    const double mi = m[i], q = mech_kin_q_value(parent, m, n);
    struct mech_decay_estimate o;
    o.recoil_mass = s;
    o.kinetic = q;
    o.energy = mi + q;
    o.momentum = sqrt(q) * sqrt(q + 2.0 * mi);
    o.kinetic_minus_exact = q * ((q + 2.0 * mi) / (2.0 * parent));
    /* p_est² − p² = (Q − T)(Q + T + 2 m_i) */
    const double dp2 = o.kinetic_minus_exact * (q + t + 2.0 * mi);
    o.momentum_minus_exact = (o.momentum + p) > 0 ? dp2 / (o.momentum + p) : 0.0;
    /* intermediate: p_mid² = Q (Q + 2 m_i) S/M; exact p² = p_mid² (1 + x) */
    const double pm2 = q * (q + 2.0 * mi) * (s / parent);
    const double x = q * (q + 2.0 * mi) / (4.0 * parent * s);
    o.mid_momentum = sqrt(pm2);
    const double emid = hypot(mi, o.mid_momentum);
    o.mid_kinetic = pm2 / (emid + mi);
    /* p_mid − p = p_mid (1 − sqrt(1 + x)) = −p_mid x/(1 + sqrt(1 + x));
     * T_mid − T = E_mid − E = (p_mid² − p²)/(E_mid + E) = −p_mid² x/(E_mid + E). */
    o.mid_momentum_minus_exact = -o.mid_momentum * x / (1.0 + sqrt(1.0 + x));
    o.mid_kinetic_minus_exact = -pm2 * x / (emid + e_max);
    const double chk[] = {o.energy, o.momentum, o.kinetic_minus_exact, o.momentum_minus_exact,
                          o.mid_momentum, o.mid_kinetic, o.mid_momentum_minus_exact,
                          o.mid_kinetic_minus_exact};
    for (size_t k = 0; k < sizeof chk / sizeof chk[0]; k++)
        if (!isfinite(chk[k]))
            return mech_error_set(err, MECH_ENUMERIC, "daughters",
                                  "the notes' estimate is not finite for these masses");
    *out = o;
    return MECH_OK;
}
