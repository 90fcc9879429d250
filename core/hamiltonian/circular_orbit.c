/* circular_orbit.c — circular orbits of a given angular momentum in a sum of
 * power-law central potentials (see mech/hamiltonian/circular_orbit.h). The equation
 * m r³ V'(r) = L² is solved in x = ln r on the scaled exponential sum
 * Σ s_j exp(l_j + a_j x − max), so no term overflows whatever r. */
#include "mech/hamiltonian/circular_orbit.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#define MAX_EXP 18 /* 16 terms + the constant, merged */

struct expsum {
    size_t n;
    double a[MAX_EXP];  /* exponent of e^{a x} */
    double l[MAX_EXP];  /* log |coefficient| */
    int s[MAX_EXP];     /* sign of the coefficient */
};

/* sign of Σ s_j e^{l_j + a_j x}, evaluated relative to its largest term. */
static double scaled(const struct expsum *e, double x)
{
    double mx = -INFINITY;
    for (size_t j = 0; j < e->n; j++) {
        const double t = e->l[j] + e->a[j] * x;
        if (t > mx) mx = t;
    }
    double sum = 0;
    for (size_t j = 0; j < e->n; j++) sum += e->s[j] * exp(e->l[j] + e->a[j] * x - mx);
    return sum;
}

static void add(struct expsum *e, double a, double c)
{
    if (c == 0) return;
    e->a[e->n] = a;
    e->l[e->n] = log(fabs(c));
    e->s[e->n] = c > 0 ? 1 : -1;
    e->n++;
}

/* Newton polish of a root in r itself, m r³V'(r)/m − L²/m = Σ c_j r^{a_j} − L²/m
 * with pow (accurate for exact arguments), where every term is finite: the
 * root from logarithms carries an error of about ε |ln r| relative. */
static double polish(const double *ca, const double *cc, size_t m, double lsq, double r)
{
    for (int it = 0; it < 3; it++) {
        double g = -lsq, dg = 0;
        for (size_t j = 0; j < m; j++) {
            const double t = cc[j] * pow(r, ca[j]);
            g += t;
            dg += ca[j] * t / r;
        }
        const double rn = r - g / dg;
        if (!isfinite(g) || !isfinite(dg) || dg == 0 || !isfinite(rn) || !(rn > 0) ||
            fabs(rn - r) > 1e-6 * r)
            return r;
        if (rn == r) break;
        r = rn;
    }
    return r;
}

/* Bisection of a bracketed sign change in [lo, hi] to adjacent doubles. */
static double bisect(const struct expsum *e, double lo, double hi, double flo)
{
    for (int it = 0; it < 400; it++) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        const double fm = scaled(e, mid);
        if (fm == 0) return mid;
        if ((fm > 0) == (flo > 0)) {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

enum mech_status mech_circular_orbits_for_l(const struct mech_potential_term *terms, size_t n,
                                            double mass, double angular_momentum,
                                            struct mech_circular_orbits *out,
                                            struct mech_error *err)
{
    if (!terms || n == 0 || n > 16 || !out)
        return mech_error_set(err, MECH_EINVAL, "terms", "give 1 to 16 terms");
    if (!isfinite(mass) || !(mass > 0))
        return mech_error_set(err, MECH_EINVAL, "mass", "must be finite and > 0, got %.17g", mass);
    if (!isfinite(angular_momentum) || !(angular_momentum > 0))
        return mech_error_set(err, MECH_EINVAL, "angular_momentum",
                              "must be finite and > 0 (L = 0 has no circular orbit), got %.17g",
                              angular_momentum);
    /* c_i = k n (k for the logarithm) multiplies e^{(n + 2) x}; terms with
     * equal exponents are summed into one coefficient. */
    double ca[16], cc[16];
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        const double k = terms[i].k, e = terms[i].n;
        if (!isfinite(k) || !isfinite(e)) {
            char p[48];
            snprintf(p, sizeof p, "terms/%zu/%s", i, isfinite(k) ? "n" : "k");
            return mech_error_set(err, MECH_EINVAL, p, "must be finite");
        }
        const double c = e == 0 ? k : k * e, a = e + 2.0;
        size_t j = 0;
        while (j < m && ca[j] != a) j++;
        if (j == m) {
            ca[m] = a;
            cc[m++] = c;
        } else {
            cc[j] += c;
        }
    }
    /* The constant: −L²/m plus the n = −2 terms (their r³V' = −2k). Kept as
     * log L² − log m so L = 1e200 does not overflow. */
    struct expsum es = {0};
    double c0 = 0;
    for (size_t j = 0; j < m; j++)
        if (ca[j] == 0) c0 = cc[j];
    const double l_lsq = 2.0 * log(angular_momentum) - log(mass);
    if (c0 == 0) {
        es.a[0] = 0;
        es.l[0] = l_lsq;
        es.s[0] = -1;
        es.n = 1;
    } else {
        /* c0 − L²/m in the scale of the larger of the two */
        const double lsq = exp(l_lsq);
        add(&es, 0.0, c0 - lsq);
        if (!isfinite(c0 - lsq))
            return mech_error_set(err, MECH_ENUMERIC, "angular_momentum",
                                  "L^2/m overflows beside the n = -2 terms");
    }
    for (size_t j = 0; j < m; j++)
        if (ca[j] != 0) add(&es, ca[j], cc[j]);

    struct mech_circular_orbits o = {0};
    double xs[MAX_EXP];
    size_t nx = 0;
    if (es.n == 2) {
        o.closed_form = 1;
        if (es.s[0] != es.s[1]) xs[nx++] = (es.l[0] - es.l[1]) / (es.a[1] - es.a[0]);
    } else if (es.n > 2) {
        /* Outside [lo, hi] one term outweighs the sum of all others. */
        double lo = INFINITY, hi = -INFINITY, mind = INFINITY;
        for (size_t i = 0; i < es.n; i++)
            for (size_t j = i + 1; j < es.n; j++) {
                const double d = es.a[i] - es.a[j];
                const double xb = (es.l[j] - es.l[i]) / d;
                if (xb < lo) lo = xb;
                if (xb > hi) hi = xb;
                if (fabs(d) < mind) mind = fabs(d);
            }
        const double margin = log((double)es.n + 1.0) / mind + 1.0;
        lo -= margin;
        hi += margin;
        enum { GRID = 4096 };
        double xprev = lo, fprev = scaled(&es, lo);
        for (int k = 1; k <= GRID && nx < MAX_EXP; k++) {
            const double x = lo + (hi - lo) * k / GRID;
            const double f = scaled(&es, x);
            if (fprev == 0) {
                xs[nx++] = xprev;
            } else if (f != 0 && (f > 0) != (fprev > 0)) {
                xs[nx++] = bisect(&es, xprev, x, fprev);
            }
            xprev = x;
            fprev = f;
        }
        if (fprev == 0 && nx < MAX_EXP) xs[nx++] = xprev;
    }
    for (size_t k = 0; k < nx; k++) {
        const double r = polish(ca, cc, m, (angular_momentum / mass) * angular_momentum, exp(xs[k]));
        if (!isfinite(r) || !(r > 0) || r < DBL_MIN) {
            o.out_of_range++;
            continue;
        }
        struct mech_orbit_oscillation osc;
        struct mech_error e2;
        mech_error_clear(&e2);
        enum mech_status st = mech_orbit_oscillation(terms, n, mass, r, &osc, &e2);
        if (st == MECH_EDOMAIN) { /* V'(r) <= 0 at a rounding-level root: not an orbit */
            o.out_of_range++;
            continue;
        }
        if (st != MECH_OK)
            return mech_error_set(err, MECH_ENUMERIC, "angular_momentum",
                                  "the circular orbit at r = %.17g has no finite energy or "
                                  "frequencies (%s)",
                                  r, e2.text);
        const double q = osc.angular_momentum / angular_momentum;
        o.radius[o.count] = r;
        o.residual[o.count] = (q - 1.0) * (q + 1.0);
        o.orbit[o.count] = osc;
        o.count++;
    }
    *out = o;
    return MECH_OK;
}
