/* gravity.c — POST /v1/earth/gravity (notes §1.3: effective g on a rotating
 * sphere, beside WGS 84 normal gravity). JSON <-> core only: the answer is one
 * call, mech_earth_gravity_answer() (core/answers/frames/earth_gravity_answer.c; the
 * physics is core/frames/earth.c, derivations in its header). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/answers/frames/earth_gravity_answer.h"

/* Set key to value (a new reference, may be NULL after an allocation failure:
 * then the key is set to null and the answer is incomplete, never a crash). */
static void put(json_t *obj, const char *key, json_t *value)
{
    json_object_set_new(obj, key, value ? value : json_null());
}

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
        return api_call_out_of_memory(c, out);
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
