/* sym_tensor.c — trace, invariants, isotropic/deviatoric split and principal
 * values and axes of a user-given symmetric 3x3 tensor; the eigen-solver is
 * mech_inertia_principal (core/rigid/inertia.c), not a copy of it. */
#include "mech/rigid/sym_tensor.h"

#include <math.h>
#include <stdio.h>

enum mech_status mech_sym_tensor_analyse(struct mech_mat3 t, struct mech_sym_tensor *out,
                                         struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!mech_mat3_isfinite(t))
        return mech_error_set(err, MECH_EINVAL, "tensor", "entries must be finite");
    double big = 0, asym = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) big = fmax(big, fabs(t.a[i][j]));
    for (int i = 1; i < 3; i++)
        for (int j = 0; j < i; j++) {
            double d = fabs(t.a[i][j] - t.a[j][i]);
            asym = fmax(asym, d);
            if (d > MECH_SYM_TENSOR_RTOL * big) {
                char p[32];
                snprintf(p, sizeof p, "tensor/%d/%d", i, j);
                return mech_error_set(err, MECH_EINVAL, p,
                                      "the tensor is not symmetric: entry [%d][%d] = %.17g but "
                                      "[%d][%d] = %.17g (they may differ by %.0e of the "
                                      "largest entry)",
                                      i, j, t.a[i][j], j, i, t.a[j][i], MECH_SYM_TENSOR_RTOL);
            }
        }
    struct mech_sym_tensor r;
    r.asymmetry = asym;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.tensor.a[i][j] = 0.5 * (t.a[i][j] + t.a[j][i]);
    /* invariants on the tensor scaled by 2^-e (exact), largest entry in [0.5, 1) */
    int e = 0;
    if (big > 0) frexp(big, &e);
    double s[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) s[i][j] = ldexp(r.tensor.a[i][j], -e);
    double i1 = s[0][0] + s[1][1] + s[2][2];
    double i2 = s[0][0] * s[1][1] - s[0][1] * s[1][0] + s[1][1] * s[2][2] - s[1][2] * s[2][1] +
                s[0][0] * s[2][2] - s[0][2] * s[2][0];
    double i3 = s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) -
                s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
                s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
    r.invariants[0] = r.trace = ldexp(i1, e);
    r.invariants[1] = ldexp(i2, 2 * e);
    r.invariants[2] = ldexp(i3, 3 * e);
    if (!isfinite(r.invariants[0]) || !isfinite(r.invariants[1]) || !isfinite(r.invariants[2]))
        return mech_error_set(err, MECH_ENUMERIC, "tensor",
                              "an invariant (up to max|entry|^3 ~ 2^%d) is beyond the double "
                              "range; scale the units",
                              3 * e);
    r.isotropic = ldexp(i1 / 3, e);
    r.deviator = r.tensor;
    for (int k = 0; k < 3; k++) r.deviator.a[k][k] = ldexp(s[k][k] - i1 / 3, e);
    enum mech_status st = mech_inertia_principal(r.tensor, &r.principal, err);
    if (st != MECH_OK) return st;
    *out = r;
    return MECH_OK;
}
