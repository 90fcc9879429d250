/* rotating_liquid.c — POST /v1/frames/rotating-liquid: the free surface of a
 * liquid turning with its container (notes §1.5 homework 2). JSON <-> core only;
 * the physics and its derivation are in core/frames/rotating_liquid.c and
 * mech/frames/rotating_liquid.h. */
#include <math.h>
#include <stdio.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/frames/rotating_liquid.h"


json_t *api_op_frames_rotating_liquid(struct api_call *c, const json_t *body)
{
    struct mech_rotating_liquid p = {api_number_of(body, "omega"), api_number_of(body, "g"),
                                     api_number_of(body, "radius"), api_number(body, "depth", 0),
                                     api_number(body, "container_height", 0)};
    const json_t *radii = json_object_get(body, "radii");
    size_t i;
    const json_t *rj;
    json_array_foreach(radii, i, rj) {
        if (json_number_value(rj) > p.radius) {
            char ptr[32];
            snprintf(ptr, sizeof ptr, "/radii/%zu", i);
            api_call_invalid(c, ptr, "radius %.17g m is outside the container (radius %.17g m)",
                             json_number_value(rj), p.radius);
            return NULL;
        }
    }
    struct mech_rotating_liquid_surface s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rotating_liquid_surface(&p, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object();
    if (!out) return NULL;
    json_object_set_new(out, "formula",
                        json_string("z(r) = z0 + omega^2 r^2 / (2 g): equipotential of "
                                    "g z - omega^2 r^2 / 2 (notes §1.2, §1.5 HW 2)"));
    json_object_set_new(out, "rise", api_real(c, s.rise));
    json_object_set_new(out, "focal_length",
                        isfinite(s.focal_length) ? api_real(c, s.focal_length) : json_null());
    json_object_set_new(out, "z_vertex", api_real(c, s.z_centre));
    json_object_set_new(out, "centre_height", api_real(c, s.centre_height));
    json_object_set_new(out, "rim_height", api_real(c, s.rim_height));
    json_object_set_new(out, "bottom_exposed", json_boolean(s.bottom_exposed));
    json_object_set_new(out, "dry_radius", api_real(c, s.dry_radius));
    json_object_set_new(out, "slope_rim", api_real(c, s.slope_rim));
    json_object_set_new(out, "slope_rim_deg", api_real(c, atan(s.slope_rim) * (180 / MECH_PI)));
    json_object_set_new(out, "omega_bottom_exposed", api_real(c, s.omega_bottom));
    if (p.container_height > 0) {
        json_object_set_new(out, "spills", json_boolean(s.spills));
        json_object_set_new(out, "omega_spill", api_real(c, s.omega_spill));
    }
    if (radii) {
        json_t *arr = json_array();
        json_array_foreach(radii, i, rj) {
            double r = json_number_value(rj);
            double h = mech_rotating_liquid_height(&p, &s, r);
            json_t *pt = json_object();
            if (!pt) continue;
            json_object_set_new(pt, "r", api_real(c, r));
            json_object_set_new(pt, "height", api_real(c, h));
            json_object_set_new(pt, "slope", api_real(c, h > 0 ? p.omega * p.omega * r / p.g : 0));
            json_array_append_new(arr, pt);
        }
        json_object_set_new(out, "surface", arr ? arr : json_null());
    }
    return out;
}

