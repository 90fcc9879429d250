/* ep_frames_earth.c — non-inertial frames and the Earth (notes chapter 1):
 *   POST /v1/frames/effective-force  (notes §1.2: the four fictitious forces)
 *   POST /v1/earth/gravity           (notes §1.3: effective g on a rotating sphere,
 *                                     beside WGS 84 normal gravity)
 *   POST /v1/earth/tides             (notes §1.4: tidal acceleration and tide heights)
 * JSON <-> core only: the physics is in core/frames/effective_force.c,
 * earth.c and tides.c (derivations in their headers); each of the two Earth
 * answers is one call, mech_earth_gravity_answer()
 * (core/frames/earth_gravity_answer.c) and mech_tides_answer()
 * (core/frames/tides_answer.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "endpoint.h"
#include "mech/base/constants.h"
#include "mech/answers/frames/earth_gravity_answer.h"
#include "mech/frames/effective_force.h"
#include "mech/answers/frames/tides_answer.h"

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

/* "constants": the sphere used, the WGS 84 ellipsoid, their sources. */
static json_t *gr_constants(struct api_call *c, const struct mech_earth_gravity_answer *a)
{
    json_t *k = json_object();
    if (!k) return NULL;
    put(k, "gm", api_real(c, a->earth.gm));
    put(k, "radius", api_real(c, a->earth.radius));
    put(k, "omega", api_real(c, a->earth.omega));
    /* a sphere that does not turn has no day: null, not a refused answer */
    put(k, "sidereal_day", a->earth.omega > 0 ? api_real(c, a->sidereal_day) : json_null());
    put(k, "g0", api_real(c, a->g0));
    put(k, "wgs84",
        json_pack("{s:f,s:f,s:f,s:f,s:f,s:f,s:f}", "a", MECH_WGS84_A, "f", MECH_WGS84_F, "e2",
                  MECH_WGS84_E2, "gamma_e", MECH_WGS84_GAMMA_E, "gamma_p", MECH_WGS84_GAMMA_P, "k",
                  MECH_WGS84_K, "m", MECH_WGS84_M));
    put(k, "sources",
        json_string("GM, W: IERS Conventions (2010) Table 1.1 = WGS 84; R: IUGG mean radius "
                    "R1 (GRS 80, Moritz 1980); ellipsoid: NIMA TR8350.2 3rd ed. (2000) "
                    "Tables 3.1-3.4, eqs. 4-1 and 4-3"));
    return k;
}

/* An angle (rad) as {rad, deg, mrad}. */
static json_t *gr_angle(struct api_call *c, double rad)
{
    json_t *o = json_object();
    if (!o) return NULL;
    put(o, "rad", api_real(c, rad));
    put(o, "deg", api_real(c, rad * (180 / MECH_PI)));
    put(o, "mrad", api_real(c, rad * 1e3));
    return o;
}

/* "sphere": g_eff on the rotating sphere, its parts and the plumb line. */
static json_t *gr_sphere(struct api_call *c, const struct mech_earth_gravity *g)
{
    json_t *sph = json_object(), *cf = json_object(), *ge = json_object();
    json_t *dev = json_object(), *dmax = gr_angle(c, g->deviation_max);
    put(sph, "r", api_real(c, g->r));
    put(sph, "gravitation", api_real(c, g->gravitation));
    put(cf, "magnitude", api_real(c, g->centrifugal));
    put(cf, "up", api_real(c, g->centrifugal_up));
    put(cf, "north", api_real(c, g->centrifugal_north));
    put(sph, "centrifugal", cf);
    put(ge, "vector", api_vec3(c, mech_vec3_make(0, g->north, -g->radial)));
    put(ge, "magnitude", api_real(c, g->magnitude));
    put(ge, "radial", api_real(c, g->radial));
    put(ge, "horizontal", api_real(c, g->horizontal));
    put(ge, "north", api_real(c, g->north));
    put(sph, "g_effective", ge);
    put(sph, "reduction", api_real(c, g->reduction));
    put(dev, "rad", api_real(c, g->deviation));
    put(dev, "deg", api_real(c, g->deviation * (180 / MECH_PI)));
    put(dev, "tan", api_real(c, g->horizontal / g->radial));
    put(dev, "mrad", api_real(c, g->deviation * 1e3));
    put(dev, "towards", json_string(g->horizontal > 0 ? "equator" : "none"));
    put(sph, "deviation", dev);
    put(dmax, "latitude_deg", api_real(c, g->deviation_max_latitude * (180 / MECH_PI)));
    put(sph, "deviation_max", dmax);
    put(sph, "k", api_real(c, g->k));
    return sph;
}

/* "ellipsoid": WGS 84 normal gravity and the 1980 formula. */
static json_t *gr_ellipsoid(struct api_call *c, const struct mech_normal_gravity *n)
{
    json_t *ell = json_object(), *igf = json_object();
    put(ell, "formula",
        json_string("Somigliana gamma0 = gamma_e (1 + k sin^2 L)/sqrt(1 - e^2 sin^2 L); "
                    "gamma = gamma0 [1 - 2/a (1 + f + m - 2 f sin^2 L) h + 3 h^2/a^2]"));
    put(ell, "gamma_surface", api_real(c, n->surface));
    put(ell, "free_air_correction", api_real(c, n->free_air));
    put(ell, "gamma", api_real(c, n->gamma));
    put(igf, "gamma", api_real(c, n->igf1980));
    put(igf, "minus_somigliana", api_real(c, n->igf1980 - n->surface));
    put(igf, "formula",
        json_string("1980 International Gravity Formula (GRS 80 series, "
                    "sea level): 9.780327 (1 + 0.0053024 sin^2 L - "
                    "0.0000058 sin^2 2L) m/s^2"));
    put(ell, "igf1980", igf);
    return ell;
}

json_t *api_op_earth_gravity(struct api_call *c, const json_t *body)
{
    struct mech_earth_gravity_request q = {0};
    q.latitude_deg = api_number(body, "latitude_deg", 0); /* no schema default */
    q.height = api_number_of(body, "height");
    q.radius = api_number_of(body, "radius");
    q.gm = api_number_of(body, "gm");
    q.omega = api_number_of(body, "omega");
    q.gm_given = api_call_given(c, "/gm") != NULL;
    q.omega_given = api_call_given(c, "/omega") != NULL;
    q.has_g0 = json_object_get(body, "g0") != NULL;
    q.g0 = api_number(body, "g0", 0);
    q.has_sidereal_day = json_object_get(body, "sidereal_day") != NULL;
    q.sidereal_day = api_number(body, "sidereal_day", 0);
    struct mech_earth_gravity_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_earth_gravity_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object(), *diff = json_object();
    if (!out || !diff) {
        json_decref(diff);
        return out_of_memory(c, out);
    }
    put(out, "constants", gr_constants(c, &a));
    put(out, "sphere", gr_sphere(c, &a.sphere));
    put(out, "ellipsoid", gr_ellipsoid(c, &a.ellipsoid));
    put(diff, "sphere_minus_ellipsoid", api_real(c, a.difference));
    put(diff, "relative", api_real(c, a.relative_difference));
    put(diff, "explanation",
        json_string("the sphere leaves out the Earth's flattening and the equatorial bulge's "
                    "mass (J2): at the equator the real surface is farther out (weaker "
                    "gravitation) than a sphere of mean radius, at the poles closer in; the "
                    "sphere's latitude is geocentric, the ellipsoid's geodetic"));
    put(out, "difference", diff);
    return out;
}

/* =============================== earth/tides ================================ */

/* A request's {gm | mass, distance} object (may be NULL: nothing given). */
static struct mech_tides_body_given td_given(const json_t *o)
{
    struct mech_tides_body_given g = {0};
    g.has_gm = json_object_get(o, "gm") != NULL;
    g.has_mass = json_object_get(o, "mass") != NULL;
    g.has_distance = json_object_get(o, "distance") != NULL;
    g.gm = api_number(o, "gm", 0);
    g.mass = api_number(o, "mass", 0);
    g.distance = api_number(o, "distance", 0);
    return g;
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

/* "spring_neap": the Moon and the Sun together, or null. */
static json_t *td_spring_neap(struct api_call *c, const struct mech_tides_answer *a)
{
    json_t *s = a->has_spring_neap ? json_object() : NULL;
    if (!s) return json_null();
    put(s, "moon_range", api_real(c, a->moon_height.range));
    put(s, "sun_range", api_real(c, a->sun_height.range));
    put(s, "sun_to_moon", api_real(c, a->sun_to_moon));
    put(s, "spring_range", api_real(c, a->spring_range));
    put(s, "neap_range", api_real(c, a->neap_range));
    put(s, "moon_gm", api_real(c, a->moon.gm));
    put(s, "moon_distance", api_real(c, a->moon.distance));
    put(s, "sun_gm", api_real(c, a->sun.gm));
    put(s, "sun_distance", api_real(c, a->sun.distance));
    put(s, "spring_height", api_real(c, a->spring_height));
    put(s, "neap_height", api_real(c, a->neap_height));
    return s;
}

json_t *api_op_earth_tides(struct api_call *c, const json_t *body)
{
    const json_t *bj = json_object_get(body, "body");
    struct mech_tides_request q = {0};
    q.body = !json_is_string(bj)                     ? MECH_TIDES_BODY_CUSTOM
             : !strcmp(json_string_value(bj), "sun") ? MECH_TIDES_BODY_SUN
                                                     : MECH_TIDES_BODY_MOON;
    q.custom = td_given(json_is_object(bj) ? bj : NULL);
    q.moon = td_given(json_object_get(body, "moon"));
    q.sun = td_given(json_object_get(body, "sun"));
    q.angle_deg = api_number_of(body, "angle_deg");
    q.radius = api_number_of(body, "radius");
    q.gm_earth = api_number_of(body, "gm_earth");
    struct mech_tides_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_tides_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    json_t *out = json_object(), *bo = json_object(), *acc = json_object(), *eq = json_object();
    if (!out || !bo || !acc || !eq) {
        json_decref(bo);
        json_decref(acc);
        json_decref(eq);
        return out_of_memory(c, out);
    }
    put(bo, "name", json_string(a.body.name));
    put(bo, "gm", api_real(c, a.body.gm));
    put(bo, "mass", api_real(c, a.body.mass));
    put(bo, "distance", api_real(c, a.body.distance));
    put(bo, "source", json_string(a.body.source));
    put(out, "body", bo);
    put(out, "radius", api_real(c, q.radius));
    put(out, "angle_deg", api_real(c, q.angle_deg));
    put(out, "r_over_d", api_real(c, a.acceleration.u));
    put(out, "pull_at_centre", api_real(c, a.acceleration.pull));
    put(out, "tidal_scale", api_real(c, a.acceleration.scale));
    put(acc, "exact", components(c, &a.acceleration.exact));
    put(acc, "first_order", components(c, &a.acceleration.first_order));
    put(acc, "difference", components(c, &a.acceleration.difference));
    put(acc, "relative_difference", api_real(c, a.acceleration.relative_difference));
    put(out, "acceleration", acc);
    put(eq, "height", api_real(c, a.height.height));
    put(eq, "high", api_real(c, a.height.high));
    put(eq, "low", api_real(c, a.height.low));
    put(eq, "range", api_real(c, a.height.range));
    put(eq, "gm_earth", api_real(c, q.gm_earth));
    put(eq, "formula",
        json_string("h = GM r^4 (3 cos^2 theta - 1) / (2 GM_E d^3); range = "
                    "3 GM r^4 / (2 GM_E d^3) (notes: g h = 3 GM r^2 / (2 d^3))"));
    put(out, "equilibrium_tide", eq);
    put(out, "spring_neap", td_spring_neap(c, &a));
    return out;
}
