/* ep_frames_earth.c — non-inertial frames and the Earth (notes chapter 1):
 *   POST /v1/frames/effective-force  (notes §1.2: the four fictitious forces)
 *   POST /v1/earth/gravity           (notes §1.3: effective g on a rotating sphere,
 *                                     beside WGS 84 normal gravity)
 *   POST /v1/earth/tides             (notes §1.4: tidal acceleration and tide heights)
 * JSON <-> core only: the physics is in core/effective_force.c, core/earth.c
 * and core/tides.c (derivations in their headers). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "endpoint.h"
#include "mech/constants.h"
#include "mech/earth.h"
#include "mech/effective_force.h"
#include "mech/tides.h"


/* Set key to value (a new reference, may be NULL after an allocation failure:
 * then the key is set to null and the answer is incomplete, never a crash). */
static void put(json_t *obj, const char *key, json_t *value)
{
    json_object_set_new(obj, key, value ? value : json_null());
}

static json_t *out_of_memory(struct api_call *c, json_t *partial)
{
    struct mech_error e;
    json_decref(partial);
    mech_error_clear(&e);
    mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
    return api_call_fail_core(c, MECH_ENOMEM, &e, "");
}

/* ========================= frames/effective-force ========================== */

json_t *api_op_frames_effective_force(struct api_call *c, const json_t *body)
{
    const struct mech_vec3 zero = {0, 0, 0};
    const json_t *fj = json_object_get(body, "frame");
    const json_t *pj = json_object_get(body, "particle");
    struct mech_frame_motion fr;
    fr.omega = api_vec3_member(fj, "omega", zero);
    fr.omega_dot = api_vec3_member(fj, "omega_dot", zero);
    fr.acceleration = api_vec3_member(fj, "acceleration", zero);
    double mass = api_number(pj, "mass", 0);
    struct mech_vec3 r = api_vec3_member(pj, "position", zero);
    struct mech_vec3 v = api_vec3_member(pj, "velocity", zero);
    struct mech_vec3 F = api_vec3_member(body, "force", zero);

    struct mech_effective_force ef;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_effective_force(&fr, mass, r, v, F, &ef, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object();
    json_t *terms = json_object();
    json_t *mags = json_object();
    if (!out || !terms || !mags) {
        json_decref(terms);
        json_decref(mags);
        return out_of_memory(c, out);
    }
    put(terms, "translational", api_vec3(c, ef.translational));
    put(terms, "euler", api_vec3(c, ef.euler));
    put(terms, "coriolis", api_vec3(c, ef.coriolis));
    put(terms, "centrifugal", api_vec3(c, ef.centrifugal));
    put(mags, "translational", api_real(c, mech_vec3_norm(ef.translational)));
    put(mags, "euler", api_real(c, mech_vec3_norm(ef.euler)));
    put(mags, "coriolis", api_real(c, mech_vec3_norm(ef.coriolis)));
    put(mags, "centrifugal", api_real(c, mech_vec3_norm(ef.centrifugal)));
    put(mags, "force", api_real(c, mech_vec3_norm(F)));
    put(mags, "effective_force", api_real(c, mech_vec3_norm(ef.effective)));
    put(out, "terms", terms);
    put(out, "magnitudes", mags);
    put(out, "fictitious_total", api_vec3(c, ef.fictitious));
    put(out, "force", api_vec3(c, F));
    put(out, "effective_force", api_vec3(c, ef.effective));
    put(out, "acceleration", api_vec3(c, ef.acceleration));
    put(out, "inertial_acceleration", api_vec3(c, ef.inertial_acceleration));
    put(out, "velocity_rotation_part", api_vec3(c, mech_vec3_cross(fr.omega, r)));
    put(out, "formula",
        json_string("F_eff = F - m A - m (dw/dt) x r - 2 m w x v - m w x (w x r) "
                    "(translational, Euler, Coriolis, centrifugal; notes §1.2)"));
    return out;
}

/* ============================== earth/gravity =============================== */

/* The sphere of a request: radius, gm | g0, omega | sidereal_day (defaults:
 * IUGG mean radius, IERS GM and W). Returns 0 after reporting a field given
 * twice over. */
static int earth_sphere_from(struct api_call *c, const json_t *body, struct mech_earth_sphere *e)
{
    e->radius = api_number_of(body, "radius");
    e->gm = api_number_of(body, "gm");
    e->omega = api_number_of(body, "omega");
    if (json_object_get(body, "g0")) {
        if (api_call_given(c, "/gm")) {
            api_call_invalid(c, "/g0", "give at most one of gm and g0 (g0 sets GM = g0 R^2)");
            return 0;
        }
        e->gm = api_number(body, "g0", 0) * e->radius * e->radius;
    }
    if (json_object_get(body, "sidereal_day")) {
        if (api_call_given(c, "/omega")) {
            api_call_invalid(c, "/sidereal_day",
                             "give at most one of omega and sidereal_day (omega = 2 pi / "
                             "sidereal_day)");
            return 0;
        }
        e->omega = 2 * MECH_PI / api_number(body, "sidereal_day", 86164.0989);
    }
    return 1;
}

json_t *api_op_earth_gravity(struct api_call *c, const json_t *body)
{
    double lat = api_number(body, "latitude_deg", 0);
    double h = api_number_of(body, "height");
    struct mech_earth_sphere earth;
    if (!earth_sphere_from(c, body, &earth)) return NULL;
    struct mech_earth_gravity g;
    struct mech_normal_gravity n;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_earth_gravity_sphere(&earth, lat, h, &g, &e);
    if (st == MECH_OK) st = mech_earth_normal_gravity(lat, h, &n, &e);
    /* the rate the user set is what is too fast */
    if (st == MECH_EDOMAIN && !strcmp(e.param, "radius")) {
        if (api_call_given(c, "/omega")) snprintf(e.param, sizeof e.param, "omega");
        if (json_object_get(body, "sidereal_day"))
            snprintf(e.param, sizeof e.param, "sidereal_day");
    }
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object(), *k = json_object(), *sph = json_object(), *cf = json_object(),
           *ge = json_object(), *dev = json_object(), *dmax = json_object(), *ell = json_object(),
           *diff = json_object();
    if (!out || !k || !sph || !cf || !ge || !dev || !dmax || !ell || !diff) {
        json_decref(k);
        json_decref(sph);
        json_decref(cf);
        json_decref(ge);
        json_decref(dev);
        json_decref(dmax);
        json_decref(ell);
        json_decref(diff);
        return out_of_memory(c, out);
    }
    put(k, "gm", api_real(c, earth.gm));
    put(k, "radius", api_real(c, earth.radius));
    put(k, "omega", api_real(c, earth.omega));
    put(k, "sidereal_day", api_real(c, 2 * MECH_PI / earth.omega));
    put(k, "g0", api_real(c, earth.gm / (earth.radius * earth.radius)));
    put(k, "wgs84",
        json_pack("{s:f,s:f,s:f,s:f,s:f,s:f,s:f}", "a", MECH_WGS84_A, "f", MECH_WGS84_F, "e2",
                  MECH_WGS84_E2, "gamma_e", MECH_WGS84_GAMMA_E, "gamma_p", MECH_WGS84_GAMMA_P, "k",
                  MECH_WGS84_K, "m", MECH_WGS84_M));
    put(k, "sources",
        json_string("GM, W: IERS Conventions (2010) Table 1.1 = WGS 84; R: IUGG mean radius "
                    "R1 (GRS 80, Moritz 1980); ellipsoid: NIMA TR8350.2 3rd ed. (2000) "
                    "Tables 3.1-3.4, eqs. 4-1 and 4-3"));
    put(out, "constants", k);

    put(sph, "r", api_real(c, g.r));
    put(sph, "gravitation", api_real(c, g.gravitation));
    put(cf, "magnitude", api_real(c, g.centrifugal));
    put(cf, "up", api_real(c, g.centrifugal_up));
    put(cf, "north", api_real(c, g.centrifugal_north));
    put(sph, "centrifugal", cf);
    put(ge, "vector", api_vec3(c, mech_vec3_make(0, g.north, -g.radial)));
    put(ge, "magnitude", api_real(c, g.magnitude));
    put(ge, "radial", api_real(c, g.radial));
    put(ge, "horizontal", api_real(c, g.horizontal));
    put(ge, "north", api_real(c, g.north));
    put(sph, "g_effective", ge);
    put(sph, "reduction", api_real(c, g.reduction));
    put(dev, "rad", api_real(c, g.deviation));
    put(dev, "deg", api_real(c, g.deviation * (180 / MECH_PI)));
    put(dev, "tan", api_real(c, g.horizontal / g.radial));
    put(dev, "mrad", api_real(c, g.deviation * 1e3));
    put(dev, "towards", json_string(g.horizontal > 0 ? "equator" : "none"));
    put(sph, "deviation", dev);
    put(dmax, "rad", api_real(c, g.deviation_max));
    put(dmax, "deg", api_real(c, g.deviation_max * (180 / MECH_PI)));
    put(dmax, "mrad", api_real(c, g.deviation_max * 1e3));
    put(dmax, "latitude_deg", api_real(c, g.deviation_max_latitude * (180 / MECH_PI)));
    put(sph, "deviation_max", dmax);
    put(sph, "k", api_real(c, g.k));
    put(out, "sphere", sph);

    put(ell, "formula",
        json_string("Somigliana gamma0 = gamma_e (1 + k sin^2 L)/sqrt(1 - e^2 sin^2 L); "
                    "gamma = gamma0 [1 - 2/a (1 + f + m - 2 f sin^2 L) h + 3 h^2/a^2]"));
    put(ell, "gamma_surface", api_real(c, n.surface));
    put(ell, "free_air_correction", api_real(c, n.free_air));
    put(ell, "gamma", api_real(c, n.gamma));
    json_t *igf = json_object();
    if (igf) {
        put(igf, "gamma", api_real(c, n.igf1980));
        put(igf, "minus_somigliana", api_real(c, n.igf1980 - n.surface));
        put(igf, "formula", json_string("1980 International Gravity Formula (GRS 80 series, "
                                        "sea level): 9.780327 (1 + 0.0053024 sin^2 L - "
                                        "0.0000058 sin^2 2L) m/s^2"));
    }
    put(ell, "igf1980", igf);
    put(out, "ellipsoid", ell);

    double dg = g.magnitude - n.gamma;
    put(diff, "sphere_minus_ellipsoid", api_real(c, dg));
    put(diff, "relative", api_real(c, dg / n.gamma));
    put(diff, "explanation",
        json_string("the sphere leaves out the Earth's flattening and the equatorial bulge's "
                    "mass (J2): at the equator the real surface is farther out (weaker "
                    "gravitation) than a sphere of mean radius, at the poles closer in; the "
                    "sphere's latitude is geocentric, the ellipsoid's geodetic"));
    put(out, "difference", diff);
    return out;
}

/* =============================== earth/tides ================================ */

/* A body's properties: gm or mass (at most one), distance. */

struct td_body {
    const char *name;
    double gm, mass, distance;
    const char *source;
};

static struct td_body td_moon(void)
{
    struct td_body b = {"moon", MECH_MOON_GM, MECH_MOON_MASS, MECH_MOON_DISTANCE,
                        "GM = 4.902800118e12 m^3/s^2 (JPL DE440), mass = GM/G; mean distance "
                        "3.844e8 m (semi-major axis)"};
    return b;
}

static struct td_body td_sun(void)
{
    struct td_body b = {"sun", MECH_SUN_GM, MECH_SUN_GM / MECH_GRAVITATIONAL_CONSTANT, MECH_AU,
                        "GM = 1.32712440041279419e20 m^3/s^2 (JPL DE440), mass = GM/G; "
                        "distance 1 au = 1.495978707e11 m (IAU 2012 B2)"};
    return b;
}

/* Apply a request's {gm | mass, distance} object `o` (may be NULL) at JSON
 * pointer `ptr` to body b. Returns 0 after reporting gm and mass both given. */
static int td_body_apply(struct api_call *c, const json_t *o, const char *ptr, struct td_body *b)
{
    if (!o) return 1;
    const json_t *gm = json_object_get(o, "gm"), *mass = json_object_get(o, "mass");
    if (gm && mass) {
        api_call_invalid(c, ptr, "give at most one of gm and mass (GM = G mass)");
        return 0;
    }
    if (gm || mass) b->source = gm ? "GM as given" : "GM = G mass, G = 6.67430e-11 (CODATA 2018)";
    if (gm) {
        b->gm = api_number(o, "gm", 0);
        b->mass = b->gm / MECH_GRAVITATIONAL_CONSTANT;
    } else if (mass) {
        b->mass = api_number(o, "mass", 0);
        b->gm = MECH_GRAVITATIONAL_CONSTANT * b->mass;
    }
    b->distance = api_number(o, "distance", b->distance);
    return 1;
}

static json_t *components(struct api_call *c, const struct mech_tide_components *x)
{
    json_t *o = json_object();
    if (!o) return NULL;
    put(o, "radial", api_real(c, x->radial));
    put(o, "tangential", api_real(c, x->tangential));
    put(o, "along", api_real(c, x->along));
    put(o, "perpendicular", api_real(c, x->perpendicular));
    put(o, "magnitude", api_real(c, hypot(x->radial, x->tangential)));
    return o;
}

json_t *api_op_earth_tides(struct api_call *c, const json_t *body)
{
    const json_t *bj = json_object_get(body, "body");
    double theta = api_number_of(body, "angle_deg");
    double radius = api_number_of(body, "radius");
    double gm_earth = api_number_of(body, "gm_earth");
    struct td_body b, moon = td_moon(), sun = td_sun();
    const char *dist_pointer;
    if (!td_body_apply(c, json_object_get(body, "moon"), "/moon", &moon) ||
        !td_body_apply(c, json_object_get(body, "sun"), "/sun", &sun))
        return NULL;
    if (json_is_string(bj)) {
        int is_sun = strcmp(json_string_value(bj), "sun") == 0;
        b = is_sun ? sun : moon;
        dist_pointer = json_object_get(json_object_get(body, is_sun ? "sun" : "moon"), "distance")
                           ? (is_sun ? "/sun/distance" : "/moon/distance")
                           : "/radius";
    } else {
        b.name = "custom";
        b.gm = b.mass = 0;
        b.distance = 0;
        if (!td_body_apply(c, bj, "/body", &b)) return NULL;
        if (!(b.gm > 0)) {
            api_call_invalid(c, "/body", "give the body's gm (m^3/s^2) or its mass (kg)");
            return NULL;
        }
        dist_pointer = "/body/distance";
    }
    if (!(b.distance > radius)) {
        api_call_domain(c, dist_pointer,
                        "the body (distance %.17g m) must lie outside the sphere through the "
                        "point (radius %.17g m)",
                        b.distance, radius);
        return NULL;
    }

    struct mech_tide_acceleration a;
    struct mech_tide_height h = {0}, hm = {0}, hs = {0}, hs_q = {0};
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_tide_acceleration(b.gm, b.distance, radius, theta, &a, &e);
    if (st == MECH_OK)
        st = mech_tide_height(b.gm, gm_earth, b.distance, radius, theta, &h, &e);
    /* Moon and Sun with the standard constants, at this radius (if the radius
     * reaches the Moon, spring/neap is null) */
    int sn = radius < moon.distance && radius < sun.distance;
    if (st == MECH_OK && sn) {
        st = mech_tide_height(moon.gm, gm_earth, moon.distance, radius, theta, &hm, &e);
        if (st == MECH_OK)
            st = mech_tide_height(sun.gm, gm_earth, sun.distance, radius, theta, &hs, &e);
        /* the Sun at 90 deg from the Moon in the point's plane: angle |90 - theta| */
        if (st == MECH_OK)
            st = mech_tide_height(sun.gm, gm_earth, sun.distance, radius, fabs(90 - theta),
                                  &hs_q, &e);
    }
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object(), *bo = json_object(), *acc = json_object(), *eq = json_object();
    if (!out || !bo || !acc || !eq) {
        json_decref(bo);
        json_decref(acc);
        json_decref(eq);
        return out_of_memory(c, out);
    }
    put(bo, "name", json_string(b.name));
    put(bo, "gm", api_real(c, b.gm));
    put(bo, "mass", api_real(c, b.mass));
    put(bo, "distance", api_real(c, b.distance));
    put(bo, "source", json_string(b.source));
    put(out, "body", bo);
    put(out, "radius", api_real(c, radius));
    put(out, "angle_deg", api_real(c, theta));
    put(out, "r_over_d", api_real(c, a.u));
    put(out, "pull_at_centre", api_real(c, a.pull));
    put(out, "tidal_scale", api_real(c, a.scale));

    put(acc, "exact", components(c, &a.exact));
    put(acc, "first_order", components(c, &a.first_order));
    put(acc, "difference", components(c, &a.difference));
    put(acc, "relative_difference", api_real(c, a.relative_difference));
    put(out, "acceleration", acc);

    put(eq, "height", api_real(c, h.height));
    put(eq, "high", api_real(c, h.high));
    put(eq, "low", api_real(c, h.low));
    put(eq, "range", api_real(c, h.range));
    put(eq, "gm_earth", api_real(c, gm_earth));
    put(eq, "formula",
        json_string("h = GM r^4 (3 cos^2 theta - 1) / (2 GM_E d^3); range = "
                    "3 GM r^4 / (2 GM_E d^3) (notes: g h = 3 GM r^2 / (2 d^3))"));
    put(out, "equilibrium_tide", eq);

    if (sn) {
        json_t *s = json_object();
        if (s) {
            put(s, "moon_range", api_real(c, hm.range));
            put(s, "sun_range", api_real(c, hs.range));
            put(s, "sun_to_moon", api_real(c, hs.range / hm.range));
            put(s, "spring_range", api_real(c, hm.range + hs.range));
            put(s, "neap_range", api_real(c, fabs(hm.range - hs.range)));
            put(s, "moon_gm", api_real(c, moon.gm));
            put(s, "moon_distance", api_real(c, moon.distance));
            put(s, "sun_gm", api_real(c, sun.gm));
            put(s, "sun_distance", api_real(c, sun.distance));
            put(s, "spring_height", api_real(c, hm.height + hs.height));
            put(s, "neap_height", api_real(c, hm.height + hs_q.height));
        }
        put(out, "spring_neap", s);
    } else {
        put(out, "spring_neap", json_null());
    }
    return out;
}

