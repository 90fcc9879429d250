/* ep_rotating_liquid.c — POST /v1/frames/rotating-liquid: the free surface of a
 * liquid turning with its container (notes §1.5 homework 2). JSON <-> core only;
 * the physics and its derivation are in core/rotating_liquid.c and
 * mech/rotating_liquid.h. */
#include <math.h>
#include <stdio.h>

#include "endpoint.h"
#include "mech/rotating_liquid.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* clang-format off */
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"omega\",\"radius\",\"depth\"],\"properties\":{"
    "\"omega\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e4,"
    "\"description\":\"rad/s, the container's rotation rate about its vertical axis\"},"
    "\"g\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e4,\"default\":9.80665,"
    "\"description\":\"m/s^2, gravity (default standard gravity)\"},"
    "\"radius\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e4,"
    "\"description\":\"m, inner radius R of the cylindrical container\"},"
    "\"depth\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e4,"
    "\"description\":\"m, depth h0 of the liquid at rest\"},"
    "\"container_height\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e4,"
    "\"description\":\"m, height H of the wall (optional): answers whether the liquid spills "
    "and the rate at which it starts to; must be >= depth\"},"
    "\"radii\":{\"type\":\"array\",\"maxItems\":100,\"items\":{\"type\":\"number\",\"minimum\":0,"
    "\"maximum\":1e4},\"description\":\"m, radii (each <= radius) at which to give the "
    "surface's height above the bottom and its slope\"}"
    "}}";
/* clang-format on */

static const char description[] =
    "The free surface of a liquid at rest in a container turning at w about its vertical axis "
    "(notes §1.5, homework 2; the centrifugal force of notes §1.2). In the rotating frame the "
    "potential per unit mass is g z - w^2 r^2 / 2; the free surface is an equipotential, so "
    "z(r) = z0 + w^2 r^2 / (2 g): a paraboloid of revolution, slope dz/dr = w^2 r / g (the "
    "effective gravity (w^2 r, -g) is normal to it), focal length g / (2 w^2) (the "
    "liquid-mirror telescope). The volume fixes z0: a cylinder of radius R filled to h0 at "
    "rest keeps its bottom covered while w^2 R^2 <= 4 g h0, with z0 = h0 - w^2 R^2/(4 g) and "
    "the rim at h0 + w^2 R^2/(4 g) (the centre falls as much as the rim rises); faster, a dry "
    "disc of radius r0 opens, R^2 - r0^2 = 2 R sqrt(g h0)/w, and the rim stands at R w "
    "sqrt(h0/g). With container_height H the liquid spills once the rim reaches H, at w = "
    "sqrt(4 g (H - h0))/R (H <= 2 h0) or H sqrt(g/h0)/R (H > 2 h0). Answer (m, rad/s): "
    "`formula`; `rise` (w^2 R^2/(2 g), rim minus vertex of the paraboloid); `focal_length` "
    "(null at w = 0); `z_vertex` (z0, negative when the vertex lies below the bottom); "
    "`centre_height`, `rim_height`; `bottom_exposed`, `dry_radius`; `slope_rim` (tan of the "
    "surface's angle at the wall) and `slope_rim_deg`; `omega_bottom_exposed` (2 sqrt(g h0)/R); "
    "with container_height `spills` and `omega_spill`; with radii `surface` [{r, height, slope}]. "
    "Refused (422, naming the field): unknown keys, omega < 0, g, radius, depth or "
    "container_height <= 0 or above 1e4, container_height < depth, a radius in radii beyond "
    "the container's, more than 100 radii.";

static const char example[] =
    "{\"omega\": 10, \"radius\": 0.1, \"depth\": 0.05, \"container_height\": 0.1, "
    "\"radii\": [0, 0.05, 0.1]}";

static json_t *rotating_liquid(struct api_call *c, const json_t *body)
{
    struct mech_rotating_liquid p = {api_number(body, "omega", 0), api_number(body, "g", 9.80665),
                                     api_number(body, "radius", 0), api_number(body, "depth", 0),
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
    json_object_set_new(out, "slope_rim_deg", api_real(c, atan(s.slope_rim) * (180 / M_PI)));
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

const struct api_route api_route_frames_rotating_liquid = {
    "POST",
    "/v1/frames/rotating-liquid",
    "The free surface of a liquid turning with its container: the paraboloid z = z0 + "
    "omega^2 r^2/(2g), its centre and rim heights at fixed volume, the dry disc, spilling",
    description,
    schema,
    example,
    rotating_liquid,
    0,
    1, /* quick */
};
