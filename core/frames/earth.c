/* earth.c — effective gravity on a rotating spherical Earth (notes §1.3) and
 * WGS 84 normal gravity (NIMA TR8350.2); formulas in mech/frames/earth.h. */
#include "mech/frames/earth.h"
#include "mech/base/constants.h"

#include <math.h>

void mech_sincos_deg(double deg, double *s, double *c)
{
    /* Reduce to [0, 360) keeping the sign of sine: sin(-x) = -sin x. */
    double sign = 1;
    double x = fmod(deg, 360.0);
    if (x < 0) {
        x = -x;
        sign = -1;
    }
    double sv, cv;
    if (x <= 45) {
        sv = sin(x * (MECH_PI / 180));
        cv = cos(x * (MECH_PI / 180));
    } else if (x <= 135) { /* 90 - x is exact here (Sterbenz) */
        double y = (90 - x) * (MECH_PI / 180);
        sv = cos(y);
        cv = sin(y);
    } else if (x <= 225) { /* 180 - x exact */
        double y = (180 - x) * (MECH_PI / 180);
        sv = sin(y);
        cv = -cos(y);
    } else if (x <= 315) { /* 270 - x exact */
        double y = (270 - x) * (MECH_PI / 180);
        sv = -cos(y);
        cv = -sin(y);
    } else {
        double y = (x - 360) * (MECH_PI / 180);
        sv = sin(y);
        cv = cos(y);
    }
    if (s) *s = sign * sv;
    if (c) *c = cv;
}

static enum mech_status check_point(double latitude_deg, double height, struct mech_error *err)
{
    if (!isfinite(latitude_deg) || latitude_deg < -90 || latitude_deg > 90)
        return mech_error_set(err, MECH_EINVAL, "latitude_deg",
                              "latitude must be in [-90, 90] degrees, got %.17g", latitude_deg);
    if (!isfinite(height) || height < MECH_EARTH_HEIGHT_MIN || height > MECH_EARTH_HEIGHT_MAX)
        return mech_error_set(err, MECH_EINVAL, "height", "height must be in [%g, %g] m, got %.17g",
                              MECH_EARTH_HEIGHT_MIN, MECH_EARTH_HEIGHT_MAX, height);
    return MECH_OK;
}

enum mech_status mech_earth_gravity_sphere(const struct mech_earth_sphere *e, double latitude_deg,
                                           double height, struct mech_earth_gravity *out,
                                           struct mech_error *err)
{
    if (!e || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no Earth or no output");
    enum mech_status st = check_point(latitude_deg, height, err);
    if (st != MECH_OK) return st;
    if (!isfinite(e->gm) || !(e->gm > 0))
        return mech_error_set(err, MECH_EINVAL, "gm", "GM must be finite and > 0");
    if (!isfinite(e->omega) || !(e->omega >= 0))
        return mech_error_set(err, MECH_EINVAL, "omega", "omega must be finite and >= 0");
    if (!isfinite(e->radius) || !(e->radius > 0) || !(e->radius + height > 0))
        return mech_error_set(err, MECH_EINVAL, "radius",
                              "radius must be finite, > 0 and exceed -height");

    double s, c;
    mech_sincos_deg(latitude_deg, &s, &c);
    double r = e->radius + height;
    double g0 = e->gm / (r * r);          /* notes §1.3: g = GM_e / r_e² */
    double w2r = e->omega * e->omega * r; /* centrifugal scale W² r */
    double k = w2r / g0;
    if (!(k < 1))
        return mech_error_set(err, MECH_EDOMAIN, "radius",
                              "the centrifugal acceleration W^2 r = %.6g m/s^2 reaches gravitation "
                              "GM/r^2 = %.6g m/s^2: nothing hangs down",
                              w2r, g0);

    out->r = r;
    out->gravitation = g0;
    out->k = k;
    out->centrifugal = w2r * c; /* |w x (w x r)| = W² r cos L */
    out->centrifugal_up = w2r * c * c;
    out->centrifugal_north = -w2r * c * s;
    /* notes §1.3: g = g0 - W² r cos² L (radial), W² r cos L sin L towards the equator */
    out->radial = g0 - out->centrifugal_up;
    out->north = out->centrifugal_north;
    out->horizontal = fabs(out->north);
    out->magnitude = hypot(out->radial, out->horizontal);
    /* g0² - |g|² = W² r c² (2 g0 - W² r), divided by g0 + |g|: no cancellation. */
    out->reduction = w2r * c * c * (2 * g0 - w2r) / (g0 + out->magnitude);
    out->deviation = atan2(out->horizontal, out->radial);
    /* max of atan(k t / (1 + t² - k)) over t = tan L: at t = sqrt(1 - k) */
    double sk = sqrt(1 - k);
    out->deviation_max_latitude = atan(sk);
    out->deviation_max = atan(k / (2 * sk));

    const double v[] = {out->gravitation, out->centrifugal, out->radial,       out->magnitude,
                        out->reduction,   out->deviation,   out->deviation_max};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i])) return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite gravity");
    return MECH_OK;
}

enum mech_status mech_earth_normal_gravity(double latitude_deg, double height,
                                           struct mech_normal_gravity *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output");
    enum mech_status st = check_point(latitude_deg, height, err);
    if (st != MECH_OK) return st;
    double s;
    mech_sincos_deg(latitude_deg, &s, NULL);
    double s2 = s * s;
    /* TR8350.2 eq. 4-1 (Somigliana) */
    double g0 = MECH_WGS84_GAMMA_E * (1 + MECH_WGS84_K * s2) / sqrt(1 - MECH_WGS84_E2 * s2);
    /* TR8350.2 eq. 4-3: gamma_h = gamma [1 - 2/a (1 + f + m - 2 f sin² L) h + 3 h²/a²] */
    const double a = MECH_WGS84_A, f = MECH_WGS84_F, m = MECH_WGS84_M;
    double factor = -2.0 / a * (1 + f + m - 2 * f * s2) * height + 3 * height * height / (a * a);
    /* IGF 1980 series; sin² 2L = 4 s² (1 - s²) */
    out->igf1980 = MECH_IGF1980_GAMMA_E *
                   (1 + MECH_IGF1980_B1 * s2 - MECH_IGF1980_B2 * 4 * s2 * (1 - s2));
    out->surface = g0;
    out->free_air = g0 * factor;
    out->gamma = g0 + out->free_air;
    return MECH_OK;
}
