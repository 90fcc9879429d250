/* top_nutation.c — the heavy top's nutation period and its precession rate
 * averaged over one nutation, from the turning-point cubic in closed form
 * (complete elliptic integrals; Goldstein, Classical Mechanics, §5.7 for the
 * cubic, Byrd & Friedman 233.00 and 233.02 for the reductions). */
#include "mech/rigid/top.h"

#include <math.h>

#include <gsl/gsl_mode.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_result.h>

#include "mech/base/constants.h"

/* GSL's complete integral of the third kind,
 * Pi(k, n) = int_0^{pi/2} dt / ((1 + n sin^2 t) sqrt(1 - k^2 sin^2 t)) (note +n),
 * or NaN when GSL refuses. */
static double pi3(double k, double n)
{
    gsl_sf_result r;
    if (gsl_sf_ellint_Pcomp_e(k, n, GSL_PREC_DOUBLE, &r) != 0) return NAN;
    return r.val;
}

static double k1(double k)
{
    gsl_sf_result r;
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r) != 0) return NAN;
    return r.val;
}

void mech_top_nutation(struct mech_top_turning *t)
{
    const double *c = t->cubic, lo = t->x_lo, hi = t->x_hi, dd = t->phi_d, cc = t->phi_c;
    const double p0 = 0.5 * dd, p2 = cc + 0.5 * dd; /* phi' = p0 / x + p2 / (2 - x) */
    t->nutation_period = t->precession_mean = NAN;
    if (c[3] == 0) {
        /* x'^2 = c2 (x - lo)(x - hi), c2 < 0: x oscillates harmonically at sqrt(-c2);
         * int dx / ((x - p) sqrt(f)) over [lo, hi] = pi / sqrt(-c2 (lo - p)(hi - p)) */
        if (!(c[2] < 0)) return;
        t->nutation_period = 2 * MECH_PI / sqrt(-c[2]);
        double m = 0;
        if (p0 != 0 && lo > 0) m += p0 / sqrt(lo * hi);
        if (p2 != 0 && hi < 2) m += p2 / sqrt((2 - lo) * (2 - hi));
        t->precession_mean = m;
        return;
    }
    /* The third root: Vieta's product x1 x2 x3 = -c0 / c3, else the sum. */
    double x3 = (lo > 0 && hi > 0 && c[0] != 0) ? -c[0] / (c[3] * lo * hi)
                                                 : -c[2] / c[3] - lo - hi;
    /* Substitute x = s + delta sin^2 w from the end s far from x3 (Byrd & Friedman
     * 233.00): dx / sqrt(f) = 2 dw / sqrt(|c3| d (1 - k^2 sin^2 w)). */
    double s, delta, d;
    if (x3 >= hi) {
        s = lo;
        delta = hi - lo;
        d = x3 - lo;
    } else {
        s = hi;
        delta = lo - hi;
        d = hi - x3;
    }
    if (!(d > 0) || !(fabs(delta) <= d)) return;
    double kk = sqrt(fabs(delta) / d), scale = sqrt(fabs(c[3]) * d);
    double K = k1(kk);
    t->nutation_period = 4 * K / scale;
    /* int dx / ((x - p) sqrt f) = 2 Pi(k, delta/(s - p)) / ((s - p) scale); the mean rate is
     * that over the half period 2 K / scale */
    double m = 0;
    /* a term's coefficient vanishes when the motion reaches its pole (x = 0 needs
     * f(0) = -phi_d^2 = 0); skip it there rather than divide 0 by 0 */
    if (p0 != 0 && s > 0) m += p0 * pi3(kk, delta / s) / s;
    if (p2 != 0 && s < 2) m += p2 * pi3(kk, -delta / (2 - s)) / (2 - s);
    t->precession_mean = m / K;
}
