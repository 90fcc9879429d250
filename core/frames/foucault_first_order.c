/* foucault_first_order.c — the Foucault pendulum's closed forms
 * (mech/frames/foucault_first_order.h).
 *
 * First order (notes §1.4): the Coriolis force's horizontal part, -2 W sin(lat)
 * z x r', turns the swing plane at -W sin(lat) (clockwise in the north).
 * Airy: a spherical pendulum whose path is an ellipse of semi-axes a, b
 * precesses at (3/8) omega0 a b / l^2 in the sense it is traversed; its
 * measured mean is added to the first-order rate, and the next terms are of
 * relative size alpha^2 / 4 (amplitude) and W^2 / omega0^2 (rotation).
 * Centrifugal term of the displacement, c = -w x (w x r): its horizontal
 * part is anisotropic (east softer by eps = W^2 cos^2 lat), which wobbles the
 * swing line at eps / (4 omega0) and changes the ellipse's h by (eps a^2 / 4)
 * per radian of precession, so the Airy rate by (3/8) dh / l^2, dh capped at
 * one precession (1 / |W sin lat|) or the run; its isotropic part and the
 * anisotropy shift the period by W^2 (1 + sin^2 lat) / (4 omega0^2).
 * The expressions are the ones the API has always answered, kept operation
 * for operation so its answers stay byte-identical.
 */
#include "mech/frames/foucault_first_order.h"
#include "mech/base/constants.h"

#include <math.h>

static int scales_input_ok(const struct mech_foucault_problem *p)
{
    return p->length > 0.0 && p->length <= 1e7 && p->g > 0.0 && p->g <= 1e4 &&
           p->latitude_deg >= -90.0 && p->latitude_deg <= 90.0 && p->omega_magnitude >= 0.0 &&
           p->omega_magnitude <= 1.0 && p->amplitude_deg > 0.0 && p->amplitude_deg < 90.0 &&
           isfinite(p->azimuth_deg);
}

void mech_foucault_scales(const struct mech_foucault_problem *p, struct mech_foucault_scales *out)
{
    if (!scales_input_ok(p)) {
        const double n = NAN;
        *out = (struct mech_foucault_scales){n, n, n, n, {n, n, n}, n, n, n, n, {n, n, n}, n};
        return;
    }
    const double deg = MECH_PI / 180.0;
    const double lat = p->latitude_deg * deg, alpha = p->amplitude_deg * deg;
    const double W = p->omega_magnitude;
    double wz = W * sin(lat);
    /* sin(pi/2 as a double) is 1 but cos is 6e-17: the poles exactly */
    if (p->latitude_deg == 90.0 || p->latitude_deg == -90.0) wz = copysign(W, p->latitude_deg);
    const double coslat = fabs(p->latitude_deg) == 90.0 ? 0.0 : cos(lat);
    out->latitude = lat;
    out->alpha = alpha;
    out->omega_vertical = wz;
    out->cos_latitude = coslat;
    out->omega = mech_vec3_make(0.0, W * coslat, wz);
    out->omega0 = sqrt(p->g / p->length);
    out->period = mech_pendulum_period(p->length, p->g, alpha);
    out->small_amplitude_period = 2.0 * MECH_PI / out->omega0;
    const double a = p->length * sin(alpha);
    out->amplitude = a;
    out->release_position =
        mech_vec3_make(a * cos(p->azimuth_deg * deg), a * sin(p->azimuth_deg * deg),
                       2.0 * p->length * sin(0.5 * alpha) * sin(0.5 * alpha));
    out->first_order_rate = -wz;
}

void mech_foucault_centrifugal_effect(const struct mech_foucault_scales *s, double omega_magnitude,
                                      double length, double t_end,
                                      struct mech_foucault_centrifugal_effect *out)
{
    const double W = omega_magnitude, wz = s->omega_vertical, coslat = s->cos_latitude;
    if (!(W >= 0.0 && W <= 1.0 && length > 0.0 && length <= 1e7 && t_end > 0.0 &&
          isfinite(t_end) && isfinite(wz) && isfinite(coslat) && s->omega0 > 0.0 &&
          isfinite(s->amplitude))) {
        out->rate = out->relative_rate = out->relative_period = out->relative = NAN;
        return;
    }
    const double eps = W * W * coslat * coslat;
    const double a = s->amplitude;
    const double dh = 0.25 * eps * a * a * (fabs(wz) > 0.0 ? fmin(1.0 / fabs(wz), t_end) : t_end);
    out->rate = eps / (4.0 * s->omega0) + 0.375 * dh / (length * length);
    out->relative_period = W * W * (1.0 + sin(s->latitude) * sin(s->latitude)) /
                           (4.0 * s->omega0 * s->omega0);
    out->relative_rate = W > 0.0 ? out->rate / W : 0.0;
    out->relative = fmax(out->relative_rate, out->relative_period);
}

double mech_foucault_expected_rate(const struct mech_foucault_scales *s, double omega_magnitude,
                                   double airy_rate, double *next_order)
{
    const double W = omega_magnitude;
    if (next_order)
        *next_order = isfinite(airy_rate) ? fabs(airy_rate) * (s->alpha * s->alpha / 4.0 +
                                                                W * W / (s->omega0 * s->omega0))
                                          : NAN;
    return isfinite(airy_rate) ? s->first_order_rate + airy_rate : NAN;
}

double mech_foucault_full_precession_time(double rate)
{
    if (!isfinite(rate)) return NAN;
    return fabs(rate) > 0.0 ? 2.0 * MECH_PI / fabs(rate) : INFINITY;
}
