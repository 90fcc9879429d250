/* stability.c — linear stability of torque-free spin about a principal axis
 * (notes §2.10); the derivation is in mech/rigid/stability.h. */
#include "mech/rigid/stability.h"

#include <math.h>
#include <stdio.h>

enum mech_status mech_stability_principal(const double moments[3], int axis, double spin,
                                          struct mech_stability *out, struct mech_error *err)
{
    if (!moments || !out) return mech_error_set(err, MECH_EINVAL, "moments", "no moments given");
    char param[32];
    for (int i = 0; i < 3; i++) {
        snprintf(param, sizeof param, "moments/%d", i);
        if (!isfinite(moments[i])) return mech_error_set(err, MECH_EINVAL, param, "must be finite");
        if (!(moments[i] > 0))
            return mech_error_set(err, MECH_EDOMAIN, param,
                                  "a principal moment must be > 0, got %.17g", moments[i]);
    }
    for (int i = 0; i < 3; i++) {
        double others = moments[(i + 1) % 3] + moments[(i + 2) % 3];
        if (moments[i] > others * (1 + MECH_STABILITY_TRIANGLE_TOL)) {
            snprintf(param, sizeof param, "moments/%d", i);
            return mech_error_set(err, MECH_EDOMAIN, param,
                                  "no rigid body has I%d = %.17g > I%d + I%d = %.17g "
                                  "(triangle inequality of principal moments)",
                                  i + 1, moments[i], (i + 1) % 3 + 1, (i + 2) % 3 + 1, others);
        }
    }
    if (axis < 1 || axis > 3) return mech_error_set(err, MECH_EINVAL, "axis", "must be 1, 2 or 3");
    if (!isfinite(spin)) return mech_error_set(err, MECH_EINVAL, "spin", "must be finite");

    int a = axis - 1, b = (a + 1) % 3, c = (a + 2) % 3;
    double ia = moments[a], ib = moments[b], ic = moments[c];
    /* notes §2.10 (axis 1): I2 eps' + (I1 - I3) w1 eta = 0, I3 eta' + (I2 - I1) w1 eps = 0 */
    double ca = (ic - ia) / ib * spin, cb = (ia - ib) / ic * spin;
    double k = ca * cb;
    out->k = k + 0.0;
    out->coupling[0] = ca + 0.0;
    out->coupling[1] = cb + 0.0;
    out->perturbation_axes[0] = b + 1;
    out->perturbation_axes[1] = c + 1;
    out->kind =
        k < 0 ? MECH_STABILITY_STABLE : (k > 0 ? MECH_STABILITY_UNSTABLE : MECH_STABILITY_MARGINAL);
    out->frequency = k < 0 ? sqrt(-k) : 0;
    out->growth_rate = k > 0 ? sqrt(k) : 0;
    if (ia == ib || ia == ic)
        out->role = MECH_AXIS_DEGENERATE;
    else if (ia < ib && ia < ic)
        out->role = MECH_AXIS_SMALLEST;
    else if (ia > ib && ia > ic)
        out->role = MECH_AXIS_LARGEST;
    else
        out->role = MECH_AXIS_INTERMEDIATE;
    out->intermediate_axis = 0;
    if (moments[0] != moments[1] && moments[1] != moments[2] && moments[0] != moments[2])
        for (int i = 0; i < 3; i++) {
            double x = moments[i], y = moments[(i + 1) % 3], z = moments[(i + 2) % 3];
            if ((y < x && x < z) || (z < x && x < y)) out->intermediate_axis = i + 1;
        }
    if (!isfinite(out->k) || !isfinite(out->frequency) || !isfinite(out->growth_rate))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite stability coefficient");
    return MECH_OK;
}
