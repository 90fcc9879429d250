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
#include "mech/earth.h"
#include "mech/effective_force.h"
#include "mech/tides.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A 3-vector schema with each component in [-lim, lim]. */
#define FE_VEC3(lim, desc)                                                                         \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\","            \
    "\"minimum\":-" lim ",\"maximum\":" lim "},\"description\":\"" desc "\"}"

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

/* clang-format off */
static const char ef_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"frame\",\"particle\"],\"properties\":{"
    "\"frame\":{\"type\":\"object\",\"additionalProperties\":false,\"properties\":{"
    "\"omega\":" FE_VEC3("1e6", "angular velocity of the frame's axes relative to an inertial "
                               "frame, rad/s, components on the frame's axes; default [0,0,0]") ","
    "\"omega_dot\":" FE_VEC3("1e9", "its time derivative, rad/s^2 (the same seen from either "
                                   "frame); default [0,0,0]") ","
    "\"acceleration\":" FE_VEC3("1e15", "acceleration of the frame's origin relative to an "
                                       "inertial frame, m/s^2, components on the frame's axes; "
                                       "default [0,0,0]")
    "},\"description\":\"how the frame moves (at the instant considered)\"},"
    "\"particle\":{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"mass\",\"position\"],\"properties\":{"
    "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,\"description\":\"kg\"},"
    "\"position\":" FE_VEC3("1e15", "m, measured from the frame's origin on the frame's axes") ","
    "\"velocity\":" FE_VEC3("3e8", "m/s, the velocity seen in the frame (Newtonian); default "
                                  "[0,0,0]")
    "}},"
    "\"force\":" FE_VEC3("1e30", "the real (inertial) force on the particle, N, components on "
                                "the frame's axes; default [0,0,0]")
    "}}";
/* clang-format on */

static const char ef_description[] =
    "The effective force in an accelerating, rotating frame, term by term (notes §1.2, "
    "\"a more general derivation\"). Writing the inertial position as x_I = X + x_j u_j "
    "(X the frame's origin, u_j its axes, du_j/dt = w x u_j) and differentiating twice gives "
    "a_I = A + a + 2 w x v + (dw/dt) x r + w x (w x r), so the force seen in the frame is "
    "F_eff = m a = F - m A - m (dw/dt) x r - 2 m w x v - m w x (w x r): the real force F plus "
    "the translational (-m A), Euler (-m (dw/dt) x r), Coriolis (-2 m w x v) and centrifugal "
    "(-m w x (w x r) = m (w^2 r - (w.r) w), away from the axis) forces. (The notes' PDF text "
    "lost these minus signs; the signs here are rebuilt from the derivation and checked "
    "against an independent kinematic computation in tests/core/test_effective_force.c.) "
    "Input: `frame` {omega (rad/s), omega_dot (rad/s^2), acceleration of the origin (m/s^2)}, "
    "`particle` {mass (kg), position r (m), velocity v (m/s), both measured in the frame} and "
    "the real `force` F (N); every vector has components on the frame's axes at this "
    "instant. Answer (N unless stated, frame axes): `terms` {translational, euler, coriolis, "
    "centrifugal}; `magnitudes` of each term; `fictitious_total` (their sum); `force` (F); "
    "`effective_force` (F + the sum); `acceleration` (effective_force / m, m/s^2: the "
    "acceleration seen in the frame); `inertial_acceleration` (F / m, m/s^2); "
    "`velocity_rotation_part` (w x r, m/s: what the frame's rotation adds to v in the inertial "
    "frame, v_I = v + w x r + the origin's velocity). Sums are compensated, so the total is "
    "right to about one rounding even when terms cancel. Example: the notes' puck at rest on "
    "the inertial floor above a table turning at w is seen circling; Coriolis (-2 m w^2 r) "
    "plus centrifugal (+m w^2 r) leave the centripetal -m w^2 r. Refused (422, naming the "
    "field): unknown keys, a vector without 3 components, mass <= 0, components out of range "
    "(|omega| <= 1e6 rad/s, |omega_dot| <= 1e9, |A| <= 1e15, |r| <= 1e15 m, |v| <= 3e8 m/s, "
    "|F| <= 1e30 N).";

static const char ef_example[] =
    "{\"frame\": {\"omega\": [0, 0, 2], \"omega_dot\": [0, 0, 0.1], \"acceleration\": "
    "[0.5, 0, 0]}, \"particle\": {\"mass\": 0.3, \"position\": [0, 0.5, 0], \"velocity\": "
    "[1, -0.6366197723675814, 0]}, \"force\": [0, 0, -2.94]}";

static json_t *effective_force(struct api_call *c, const json_t *body)
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

const struct api_route api_route_frames_effective_force = {
    "POST",
    "/v1/frames/effective-force",
    "The fictitious forces in an accelerating, rotating frame, term by term (translational, "
    "Euler, Coriolis, centrifugal), and the effective force and acceleration seen in the frame",
    ef_description,
    ef_schema,
    ef_example,
    effective_force,
    0,
    1, /* quick */
};

/* ============================== earth/gravity =============================== */

/* clang-format off */
static const char gr_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"latitude_deg\"],\"properties\":{"
    "\"latitude_deg\":{\"type\":\"number\",\"minimum\":-90,\"maximum\":90,\"description\":"
    "\"degrees, north positive: geocentric on the sphere, geodetic on the ellipsoid\"},"
    "\"height\":{\"type\":\"number\",\"minimum\":-12000,\"maximum\":100000,\"default\":0,"
    "\"description\":\"m above the sphere / the ellipsoid, from the deepest trench to 100 km\"},"
    "\"radius\":{\"type\":\"number\",\"minimum\":1e6,\"maximum\":1e7,\"default\":6371008.8,"
    "\"description\":\"m, radius of the spherical model; default the IUGG mean radius "
    "6371008.8 m (use 6378137 for the equatorial radius)\"},"
    "\"gm\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e18,\"default\":3.986004418e14,"
    "\"description\":\"m^3/s^2, the sphere's GM (default IERS 2010 / WGS 84); at most one of gm, "
    "g0\"},"
    "\"g0\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1000,"
    "\"description\":\"m/s^2, gravitation GM/R^2 at the sphere's surface (radius R, without the "
    "centrifugal part): sets GM = g0 R^2; at most one of gm, g0\"},"
    "\"omega\":{\"type\":\"number\",\"minimum\":0,\"maximum\":0.01,\"default\":7.292115e-05,"
    "\"description\":\"rad/s, the rotation rate (default IERS 2010 / WGS 84, the one default of "
    "every operation); at most one of omega, sidereal_day\"},"
    "\"sidereal_day\":{\"type\":\"number\",\"minimum\":1000,\"maximum\":1e10,"
    "\"description\":\"s, the rotation period relative to the stars: sets omega = 2 pi / "
    "sidereal_day; at most one of omega, sidereal_day\"}"
    "}}";
/* clang-format on */

static const char gr_description[] =
    "Effective gravity on a rotating spherical Earth (notes §1.3, \"Motion Near the Earth\") "
    "beside the WGS 84 normal gravity of the ellipsoid. Sphere: GM = 3.986004418e14 m^3/s^2 "
    "(IERS Conventions 2010 / WGS 84), radius R = 6371008.8 m (IUGG mean radius; `radius` "
    "overrides it), W = 7.292115e-5 rad/s (IERS / WGS 84 nominal rotation rate relative to "
    "inertial space, 2 pi/W = 86164.0989 s; the default of every operation). Any of them can "
    "be set: `gm` or `g0` (gravitation GM/R^2 at the radius R, so GM = g0 R^2), `omega` or "
    "`sidereal_day` (W = 2 pi / sidereal_day), `radius`, so the notes' problems that give g "
    "and w can be posed; `constants` echoes what was used. The point is "
    "at r = R + height. Gravitation g0 = GM/r^2 points to the centre; the centrifugal "
    "acceleration -w x (w x r) has magnitude W^2 r cos L away from the axis, so in local axes "
    "(east, north, up) g_eff = (0, -W^2 r cos L sin L, -(g0 - W^2 r cos^2 L)): radial "
    "(downward) component g0 - W^2 r cos^2 L (the notes' g = g0 - w^2 r cos^2 L) and "
    "horizontal component W^2 r cos L |sin L| towards the equator. The plumb line hangs along "
    "g_eff, deviating from the direction to the centre by alpha = atan(horizontal / radial); "
    "over latitude it peaks where tan L = sqrt(1 - k) (k = W^2 r / g0, so just below 45 deg) "
    "at tan alpha = k / (2 sqrt(1 - k)), about W^2 R/(2 g) = 0.0017 rad = 0.099 deg; the "
    "deviation is answered in rad, mrad (the notes' HW 6 asks for milliradians), deg and as "
    "tan (horizontal / radial). At the "
    "equator the reduction g0 - |g_eff| is exactly W^2 r (0.0339 m/s^2). Ellipsoid: WGS 84 "
    "normal gravity by Somigliana's closed formula gamma0 = gamma_e (1 + k sin^2 L) / "
    "sqrt(1 - e^2 sin^2 L) (NIMA TR8350.2, 3rd ed. 2000, eq. 4-1; gamma_e = 9.7803253359, "
    "gamma_p = 9.8321849378 m/s^2, k = 0.00193185265241, e^2 = 6.69437999014e-3) and the "
    "free-air series gamma = gamma0 [1 - 2/a (1 + f + m - 2 f sin^2 L) h + 3 h^2/a^2] "
    "(TR8350.2 eq. 4-3; a = 6378137 m, f = 1/298.257223563, m = 0.00344978650684), about "
    "-0.3086 mGal per metre. Beside it the 1980 International Gravity Formula (GRS 80 series, "
    "IAG 1980; sea level): igf1980 = 9.780327 (1 + 0.0053024 sin^2 L - 0.0000058 sin^2 2L), "
    "within 1e-6 m/s^2 of the closed formula (0.1 mGal, the series' truncation; WGS 84 and "
    "GRS 80 ellipsoids differ by less). Answer: `constants`; `sphere` {r, gravitation, centrifugal "
    "{magnitude, up, north}, g_effective {vector (east, north, up), magnitude, radial, "
    "horizontal, north}, reduction (g0 - |g_eff|, computed without cancellation), deviation "
    "{rad, mrad, deg, tan, towards}, deviation_max {rad, mrad, deg, latitude_deg}, k}; `ellipsoid` {gamma_surface, "
    "free_air_correction, gamma, igf1980 {gamma, minus_somigliana, formula}}; `difference` {sphere_minus_ellipsoid (|g_eff| - gamma, "
    "m/s^2), relative, explanation}. The two differ by up to 0.12 %: the sphere leaves out the "
    "Earth's flattening (the equator is 21 km farther from the centre than the poles) and the "
    "equatorial bulge's mass (J2), which the ellipsoid's normal field includes; the latitude "
    "is geocentric on the sphere but geodetic on the ellipsoid (they differ by up to 0.19 "
    "deg). Refused (422, naming the field): latitude outside [-90, 90], height outside "
    "[-12000, 100000] m, radius outside [1e6, 1e7] m, gm outside (0, 1e18], g0 outside (0, 1000], omega outside "
    "[0, 0.01], sidereal_day outside [1000, 1e10] s, both gm and g0 or both omega and "
    "sidereal_day, a rotation so fast that W^2 r >= GM/r^2 (at /omega), unknown keys.";

static const char gr_example[] = "{\"latitude_deg\": 45, \"height\": 100}";

/* The sphere of a request: radius, gm | g0, omega | sidereal_day (defaults:
 * IUGG mean radius, IERS GM and W). Returns 0 after reporting a field given
 * twice over. */
static int earth_sphere_from(struct api_call *c, const json_t *body, struct mech_earth_sphere *e)
{
    e->radius = api_number(body, "radius", MECH_EARTH_RADIUS_MEAN);
    e->gm = api_number(body, "gm", MECH_EARTH_GM);
    e->omega = api_number(body, "omega", MECH_EARTH_OMEGA);
    if (json_object_get(body, "g0")) {
        if (json_object_get(body, "gm")) {
            api_call_invalid(c, "/g0", "give at most one of gm and g0 (g0 sets GM = g0 R^2)");
            return 0;
        }
        e->gm = api_number(body, "g0", 0) * e->radius * e->radius;
    }
    if (json_object_get(body, "sidereal_day")) {
        if (json_object_get(body, "omega")) {
            api_call_invalid(c, "/sidereal_day",
                             "give at most one of omega and sidereal_day (omega = 2 pi / "
                             "sidereal_day)");
            return 0;
        }
        e->omega = 2 * M_PI / api_number(body, "sidereal_day", 86164.0989);
    }
    return 1;
}

static json_t *earth_gravity(struct api_call *c, const json_t *body)
{
    double lat = api_number(body, "latitude_deg", 0);
    double h = api_number(body, "height", 0);
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
        if (json_object_get(body, "omega")) snprintf(e.param, sizeof e.param, "omega");
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
    put(k, "sidereal_day", api_real(c, 2 * M_PI / earth.omega));
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
    put(dev, "deg", api_real(c, g.deviation * (180 / M_PI)));
    put(dev, "tan", api_real(c, g.horizontal / g.radial));
    put(dev, "mrad", api_real(c, g.deviation * 1e3));
    put(dev, "towards", json_string(g.horizontal > 0 ? "equator" : "none"));
    put(sph, "deviation", dev);
    put(dmax, "rad", api_real(c, g.deviation_max));
    put(dmax, "deg", api_real(c, g.deviation_max * (180 / M_PI)));
    put(dmax, "mrad", api_real(c, g.deviation_max * 1e3));
    put(dmax, "latitude_deg", api_real(c, g.deviation_max_latitude * (180 / M_PI)));
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

const struct api_route api_route_earth_gravity = {
    "POST",
    "/v1/earth/gravity",
    "Effective gravity on a rotating spherical Earth at a latitude and height (magnitude, "
    "radial and horizontal parts, plumb-line deviation), beside the WGS 84 ellipsoid's normal "
    "gravity",
    gr_description,
    gr_schema,
    gr_example,
    earth_gravity,
    0,
    1, /* quick */
};

/* =============================== earth/tides ================================ */

/* A body's properties: gm or mass (at most one), distance. */
#define TD_BODY_PROPS                                                                              \
    "{\"gm\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e22,"                  \
    "\"description\":\"m^3/s^2, the body's GM (the precisely known quantity); at most one of gm, "  \
    "mass\"},"                                                                                     \
    "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e32,"                     \
    "\"description\":\"kg; GM = G mass, G = 6.67430e-11\"},"                                      \
    "\"distance\":{\"type\":\"number\",\"minimum\":1,\"maximum\":1e16,"                          \
    "\"description\":\"m, from the Earth's centre; must exceed radius\"}}"

/* clang-format off */
static const char td_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"body\"],\"properties\":{"
    "\"body\":{\"description\":\"the tide-raising body: \\\"moon\\\", \\\"sun\\\" or "
    "{gm (m^3/s^2) or mass (kg), distance (m, centre to centre)}\",\"oneOf\":["
    "{\"type\":\"string\",\"enum\":[\"moon\",\"sun\"]},"
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"distance\"],"
    "\"properties\":" TD_BODY_PROPS "}]},"
    "\"moon\":{\"type\":\"object\",\"additionalProperties\":false,\"properties\":" TD_BODY_PROPS ","
    "\"description\":\"the Moon used by body \\\"moon\\\" and by spring_neap: any of gm or mass, "
    "distance; default DE440 GM, 3.844e8 m\"},"
    "\"sun\":{\"type\":\"object\",\"additionalProperties\":false,\"properties\":" TD_BODY_PROPS ","
    "\"description\":\"the Sun used by body \\\"sun\\\" and by spring_neap: any of gm or mass, "
    "distance; default DE440 GM, 1 au\"},"
    "\"gm_earth\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e22,"
    "\"default\":3.986004418e14,\"description\":\"m^3/s^2, the Earth's GM in the tide height "
    "(g = GM_E / r^2); default IERS 2010\"},"
    "\"angle_deg\":{\"type\":\"number\",\"minimum\":0,\"maximum\":180,\"default\":0,"
    "\"description\":\"degrees, angle at the Earth's centre between the body and the point\"},"
    "\"radius\":{\"type\":\"number\",\"minimum\":1,\"maximum\":1e12,"
    "\"default\":6371008.8,\"description\":\"m, distance of the point from the Earth's centre\"}"
    "}}";
/* clang-format on */

static const char td_description[] =
    "Tides (notes §1.4). The Earth falls freely towards the body, so what is left at a point "
    "is the difference between the body's pull there and at the centre: a = GM [(d e - r) / "
    "|d e - r|^3 - e / d^2], e the unit vector to the body, d its distance, r the point at "
    "radius r and angle theta from e. `acceleration.exact` is computed without the "
    "cancellation a direct subtraction suffers (it loses log10(d/r) digits, 10 at r/d = "
    "1e-10): with u = r/d, q = u (u - 2 cos theta) and E = (1+q)^(-3/2) - 1 = "
    "expm1(-3/2 log1p(q)), a = GM/d^2 [E e - u (1+E) r_hat], and the departure from first "
    "order uses R = E + 3/2 q (a binomial series) and E - 3u cos theta = R - 3/2 u^2, so "
    "`acceleration.difference` (exact - first order) keeps full relative precision too "
    "(tests: against the Legendre series of the tidal potential, 2e-16 at r/d = 1e-10). "
    "`acceleration.first_order` is the notes' GM r/d^3 [2 cos theta along e, -sin theta "
    "perpendicular]: radial GM r/d^3 (3 cos^2 theta - 1), tangential -(3/2) GM r/d^3 sin "
    "2theta. Components, m/s^2: radial (up, along r_hat), tangential (along increasing theta, "
    "i.e. away from the point below the body; negative values pull water towards it), along "
    "(towards the body), perpendicular (in the plane of e and the point, towards the point's "
    "side); plus magnitude and relative_difference = |exact - first| / |first| (about r/d). "
    "`equilibrium_tide` (notes §1.4, after Taylor's equipotential surface): h(theta) = GM r^4 "
    "(3 cos^2 theta - 1) / (2 GM_E d^3) above the undisturbed sphere, high water h(0) and low "
    "water h(90 deg), range = high - low = 3 GM r^4 / (2 GM_E d^3), i.e. the notes' "
    "g h = 3 GM r^2 / (2 d^3): 0.535 m for the Moon, 0.246 m for the Sun (the notes: 0.54 "
    "and 0.25). `spring_neap` combines Moon and Sun (the built-in ones or `moon`/`sun` as given): "
    "spring range = sum of the ranges (new and full Moon, aligned), neap range = |difference| "
    "(quarter Moon, at 90 deg), their ratio, and the heights at this angle with the Sun "
    "aligned (spring) or at 90 deg (neap); `moon` and `sun` objects (gm or mass, distance) "
    "replace the built-in ones there and for body \"moon\"/\"sun\". Constants: G = 6.67430e-11 "
    "(CODATA 2018); GM_moon = 4.902800118e12 m^3/s^2 (JPL DE440; mass GM/G = 7.3458e22 kg), "
    "mean distance 3.844e8 m; GM_sun = 1.32712440041279419e20 m^3/s^2 (JPL DE440; mass GM/G = "
    "1.98841e30 kg), distance 1 au = 1.495978707e11 m (IAU 2012); GM_E = 3.986004418e14 "
    "m^3/s^2 (IERS 2010, TT-compatible; DE440's 3.98600435507e14 is the same in TDB units; "
    "`gm_earth` overrides it); radius default 6371008.8 m (IUGG mean). A body is given by "
    "its gm (the precisely known quantity) or its mass (GM = G mass). Refused (422, naming the field): unknown body "
    "or keys, mass (0, 1e32] kg, distance [1, 1e16] m or radius [1, 1e12] m out of range, angle "
    "outside [0, 180], a body not outside the point's sphere (distance <= radius), both gm and "
    "mass for one body, a custom body with neither.";

static const char td_example[] = "{\"body\": \"moon\", \"angle_deg\": 30}";

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

static json_t *earth_tides(struct api_call *c, const json_t *body)
{
    const json_t *bj = json_object_get(body, "body");
    double theta = api_number(body, "angle_deg", 0);
    double radius = api_number(body, "radius", MECH_EARTH_RADIUS_MEAN);
    double gm_earth = api_number(body, "gm_earth", MECH_EARTH_GM);
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

const struct api_route api_route_earth_tides = {
    "POST",
    "/v1/earth/tides",
    "Tidal acceleration of the Moon, the Sun or any body, exact (without cancellation) and to "
    "first order in r/d, equilibrium tide heights, spring and neap tides",
    td_description,
    td_schema,
    td_example,
    earth_tides,
    0,
    0,
};
