/* tides.c — tidal acceleration exact and to first order, and the equilibrium
 * tide (notes §1.4); the rearrangement that avoids cancellation is derived in
 * mech/frames/tides.h. */
#include "mech/frames/tides.h"

#include <math.h>

#include "mech/frames/earth.h"

/* Largest number of binomial-series terms; |q| < 1/4 needs about 30. */
#define TIDE_SERIES_MAX_TERMS 100

static enum mech_status check_geometry(double gm, double distance, double radius, double theta_deg,
                                       struct mech_error *err)
{
    if (!isfinite(gm) || !(gm > 0))
        return mech_error_set(err, MECH_EINVAL, "gm", "GM must be finite and > 0, got %.17g", gm);
    if (!isfinite(radius) || !(radius > 0))
        return mech_error_set(err, MECH_EINVAL, "radius",
                              "radius must be finite and > 0, got %.17g", radius);
    if (!isfinite(distance) || !(distance > 0))
        return mech_error_set(err, MECH_EINVAL, "distance",
                              "distance must be finite and > 0, got %.17g", distance);
    if (!isfinite(theta_deg) || theta_deg < 0 || theta_deg > 180)
        return mech_error_set(err, MECH_EINVAL, "angle_deg",
                              "angle must be in [0, 180] degrees, got %.17g", theta_deg);
    if (!(distance > radius))
        return mech_error_set(err, MECH_EDOMAIN, "distance",
                              "the body (distance %.17g m) must be outside the sphere through the "
                              "point (radius %.17g m)",
                              distance, radius);
    return MECH_OK;
}

/* R(q) = (1 + q)^(-3/2) - 1 + 3/2 q for |q| < 1/4: the binomial series
 * sum_{k >= 2} C(-3/2, k) q^k, C_{k+1} = C_k (-3/2 - k)/(k + 1). */
static double binomial_tail(double q)
{
    double term = 1.875 * q * q; /* C(-3/2, 2) = 15/8 */
    double sum = 0;
    for (int k = 2; k < TIDE_SERIES_MAX_TERMS; k++) {
        sum += term;
        if (fabs(term) <= 1e-18 * fabs(sum)) break;
        term *= (-1.5 - k) / (k + 1) * q;
    }
    return sum;
}

enum mech_status mech_tide_acceleration(double gm, double distance, double radius, double theta_deg,
                                        struct mech_tide_acceleration *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output");
    enum mech_status st = check_geometry(gm, distance, radius, theta_deg, err);
    if (st != MECH_OK) return st;

    double s, c;
    mech_sincos_deg(theta_deg, &s, &c);
    double u = radius / distance;
    double pull = gm / distance / distance; /* GM/d² */
    double scale = pull * u;                /* GM r/d³ */

    /* |d e - r|² = d² (1 + q), q = u (u - 2c) */
    double q = u * (u - 2 * c);
    struct mech_tide_components f, d, x;
    /* first order (notes §1.4): GM r/d³ [2 cos e_x - sin e_y] */
    f.radial = scale * fma(3 * c, c, -1);
    f.tangential = -3 * scale * s * c;
    f.along = 2 * scale * c;
    f.perpendicular = -scale * s;
    if (fabs(q) < 0.5) {
        /* far: exact = first + rest, the rest computed directly (mech/frames/tides.h) */
        double E = expm1(-1.5 * log1p(q)); /* (1 + q)^(-3/2) - 1 */
        double R = fabs(q) < 0.25 ? binomial_tail(q) : E + 1.5 * q;
        double D = R - 1.5 * u * u; /* = E - 3 u c, exactly in exact arithmetic */
        d.radial = pull * (c * D - u * E);
        d.tangential = -pull * s * D;
        d.along = pull * (D - u * c * E);
        d.perpendicular = -pull * u * s * E;
        x.radial = f.radial + d.radial;
        x.tangential = f.tangential + d.tangential;
        x.along = f.along + d.along;
        x.perpendicular = f.perpendicular + d.perpendicular;
    } else {
        /* near (u > 0.2): the first-order part is no longer dominant; compute
         * GM/d² [P (d - r c)/d - 1, -u s P] with P = (1 + q)^(-3/2) and
         * 1 + q = ((d - r)/d)² + 4 u sin²(theta/2), a sum of non-negatives that
         * stays exact in relative terms even when the point nearly touches the
         * body (d - r and d - r c are exact or one rounding). */
        double sh;
        mech_sincos_deg(0.5 * theta_deg, &sh, NULL);
        double gap = (distance - radius) / distance;
        double w = gap * gap + 4 * u * sh * sh;
        double P = 1 / (w * sqrt(w));
        double a1 = fma(-radius, c, distance) / distance; /* (d - r c)/d */
        x.along = pull * (P * a1 - 1);
        x.perpendicular = -pull * u * s * P;
        x.radial = x.along * c + x.perpendicular * s;
        x.tangential = -x.along * s + x.perpendicular * c;
        d.radial = x.radial - f.radial;
        d.tangential = x.tangential - f.tangential;
        d.along = x.along - f.along;
        d.perpendicular = x.perpendicular - f.perpendicular;
    }

    out->u = u;
    out->pull = pull;
    out->scale = scale;
    out->first_order = f;
    out->difference = d;
    out->exact = x;
    out->magnitude = hypot(x.radial, x.tangential);
    out->magnitude_first_order = scale * sqrt(1 + 3 * c * c);
    out->relative_difference = hypot(d.radial, d.tangential) / out->magnitude_first_order;
    const double v[] = {x.radial, x.tangential, x.along,        x.perpendicular,
                        d.radial, d.tangential, out->magnitude, out->relative_difference,
                        pull,     scale};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]))
            return mech_error_set(
                err, MECH_ENUMERIC, NULL,
                "tidal acceleration overflows (the point nearly touches the body)");
    return MECH_OK;
}

enum mech_status mech_tide_height(double gm, double gm_earth, double distance, double radius,
                                  double theta_deg, struct mech_tide_height *out,
                                  struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output");
    if (!isfinite(gm_earth) || !(gm_earth > 0))
        return mech_error_set(err, MECH_EINVAL, "gm_earth",
                              "GM of the Earth must be finite and > 0");
    enum mech_status st = check_geometry(gm, distance, radius, theta_deg, err);
    if (st != MECH_OK) return st;
    double c;
    mech_sincos_deg(theta_deg, NULL, &c);
    double u = radius / distance;
    /* notes §1.4: g dh = 3 GM r² / (2 d³) with g = GM_E / r², i.e.
     * dh = (3/2)(GM/GM_E) r u³; h(theta) = (GM/GM_E) r u³ (3c² - 1)/2 */
    double base = gm / gm_earth * radius * u * u * u;
    out->range = 1.5 * base;
    out->high = base;
    out->low = -0.5 * base;
    out->height = 0.5 * base * fma(3 * c, c, -1);
    if (!isfinite(out->range) || !isfinite(out->height))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "tide height overflows");
    return MECH_OK;
}
