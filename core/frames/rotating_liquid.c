/* rotating_liquid.c — free surface of a liquid turning with its container
 * (notes §1.5 homework 2); derivation in mech/frames/rotating_liquid.h. */
#include "mech/frames/rotating_liquid.h"

#include <math.h>

static int positive(double x) { return isfinite(x) && x > 0; }

enum mech_status mech_rotating_liquid_surface(const struct mech_rotating_liquid *p,
                                              struct mech_rotating_liquid_surface *out,
                                              struct mech_error *err)
{
    if (!p || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no container or no output");
    if (!isfinite(p->omega) || p->omega < 0)
        return mech_error_set(err, MECH_EINVAL, "omega", "omega must be finite and >= 0");
    if (!positive(p->g)) return mech_error_set(err, MECH_EINVAL, "g", "g must be > 0");
    if (!positive(p->radius))
        return mech_error_set(err, MECH_EINVAL, "radius", "radius must be > 0");
    if (!positive(p->depth)) return mech_error_set(err, MECH_EINVAL, "depth", "depth must be > 0");
    if (!isfinite(p->container_height) || (p->container_height != 0 && p->container_height < p->depth))
        return mech_error_set(err, MECH_EINVAL, "container_height",
                              "the container (%.17g m) must be at least as tall as the liquid at "
                              "rest (%.17g m)",
                              p->container_height, p->depth);

    const double w = p->omega, g = p->g, R = p->radius, h0 = p->depth, H = p->container_height;
    const double w2R2 = w * w * R * R;
    out->rise = w2R2 / (2 * g);
    out->focal_length = w > 0 ? g / (2 * w * w) : INFINITY;
    out->slope_rim = w * w * R / g;
    out->omega_bottom = 2 * sqrt(g * h0) / R;
    out->bottom_exposed = w2R2 > 4 * g * h0;
    if (!out->bottom_exposed) {
        out->z_centre = h0 - w2R2 / (4 * g);
        out->centre_height = out->z_centre;
        out->rim_height = h0 + w2R2 / (4 * g);
        out->dry_radius = 0;
    } else {
        /* R² - r0² = 2 R sqrt(g h0) / w; r0² = R (R - 2 sqrt(g h0)/w) without cancellation
         * problems worse than the subtraction itself (both terms positive, r0 > 0 here) */
        double r02 = R * (R - 2 * sqrt(g * h0) / w);
        out->dry_radius = sqrt(fmax(r02, 0));
        out->z_centre = -w * w * r02 / (2 * g);
        out->centre_height = 0;
        out->rim_height = R * w * sqrt(h0 / g);
    }
    out->omega_spill = 0;
    out->spills = 0;
    if (H > 0) {
        out->omega_spill = H <= 2 * h0 ? sqrt(4 * g * (H - h0)) / R : H * sqrt(g / h0) / R;
        out->spills = out->rim_height > H;
    }
    const double v[] = {out->rise, out->z_centre, out->rim_height, out->dry_radius,
                        out->slope_rim, out->omega_bottom, out->omega_spill};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]))
            return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite surface (extreme inputs)");
    return MECH_OK;
}

double mech_rotating_liquid_height(const struct mech_rotating_liquid *p,
                                   const struct mech_rotating_liquid_surface *s, double r)
{
    r = fmin(fmax(r, 0), p->radius);
    double z = s->z_centre + p->omega * p->omega * r * r / (2 * p->g);
    return fmax(z, 0);
}
