/* ep_gr.c — general relativity (the notes' "A Little General Relativity",
 * built as Hartle, "Gravity" ch. 9 and 11; Carroll ch. 5; Schutz ch. 11):
 *   POST /v1/gr/schwarzschild — radii, clocks and red shift, circular orbits,
 *     the GPS-style clock comparison, the effective potentials;
 *   POST /v1/gr/geodesic — equatorial timelike and null geodesics with the
 *     periapsis advance and the light deflection beside their exact values.
 * The physics is core/gr/ in geometric units (M = 1): schwarzschild.c,
 * radial_infall.c, the units (gr_units.c: GM/c^2, GM/c^3), and for the geodesic
 * the set-up (geodesic_setup.c) and the run (geodesic_run.c over geodesic.c);
 * this file parses, calls them and encodes the answer in the request's units. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "integrator_block.h"
#include "mech/geodesic.h"
#include "mech/geodesic_run.h"
#include "mech/constants.h"
#include "mech/geodesic_setup.h"
#include "mech/gr_units.h"
#include "mech/radial_infall.h"
#include "mech/schwarzschild.h"
#include "trajectory_request.h"

/* Constants (documented in the routes' descriptions); c, G and the GM values
 * are mech/constants.h's, used through mech/gr_units.h. */
#define GR_ARCSEC (180.0 * 3600.0 / MECH_PI)
#define GR_CENTURY_S (36525.0 * 86400.0) /* Julian century, s */

/* ---- units ------------------------------------------------------------------------ */

/* Parse M and units; the set-up and its checks are mech_gr_units_init.
 * Returns 0 after recording an error. */
static int gr_units_read(struct api_call *c, const json_t *body, struct mech_gr_units *u)
{
    const int geometric = !strcmp(api_string_of(body, "units"), "geometric");
    const json_t *M = json_object_get(body, "M");
    enum mech_gr_mass kind = MECH_GR_MASS_NONE;
    double value = NAN;
    if (json_is_string(M)) {
        kind = !strcmp(json_string_value(M), "sun") ? MECH_GR_MASS_SUN : MECH_GR_MASS_EARTH;
    } else if (json_is_object(M)) {
        kind = MECH_GR_MASS_GM;
        value = api_number(M, "gm", 0);
    } else if (M) {
        kind = MECH_GR_MASS_KG;
        value = json_number_value(M);
    }
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_gr_units_init(geometric, kind, value, u, &e);
    if (st == MECH_EDOMAIN) api_call_domain(c, "/M", "%s", e.text);
    if (st != MECH_OK && st != MECH_EDOMAIN) api_call_invalid(c, "/M", "%s", e.text);
    return st == MECH_OK;
}

static json_t *gr_units_json(struct api_call *c, const struct mech_gr_units *u)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "system", json_string(u->geometric ? "geometric" : "SI"));
    json_object_set_new_nocheck(j, "length", json_string(u->geometric ? "GM/c^2" : "m"));
    json_object_set_new_nocheck(j, "time", json_string(u->geometric ? "GM/c^3" : "s"));
    json_object_set_new_nocheck(j, "specific_angular_momentum",
                                json_string(u->geometric ? "GM/c" : "m^2/s"));
    json_object_set_new_nocheck(j, "speed", json_string(u->geometric ? "c" : "m/s"));
    json_object_set_new_nocheck(j, "specific_energy", json_string("E/(m c^2), dimensionless"));
    json_object_set_new_nocheck(j, "angle", json_string("rad"));
    json_object_set_new_nocheck(j, "c", api_real(c, MECH_C));
    if (u->has_mass) {
        json_object_set_new_nocheck(j, "GM", api_real(c, u->GM));
        json_object_set_new_nocheck(j, "GM_over_c2", api_real(c, u->m));
        json_object_set_new_nocheck(j, "GM_over_c3", api_real(c, u->s));
        json_object_set_new_nocheck(j, "mass_kg", api_real(c, u->GM / MECH_GRAVITATIONAL_CONSTANT)); /* M = GM/G */
    }
    return j;
}

static const char *stability_name(enum mech_schw_stability s)
{
    switch (s) {
    case MECH_SCHW_ORBIT_STABLE:
        return "stable";
    case MECH_SCHW_ORBIT_UNSTABLE:
        return "unstable";
    case MECH_SCHW_ORBIT_MARGINAL:
        return "marginal";
    default:
        return "none";
    }
}

/* ===================================================================================== */
/* POST /v1/gr/schwarzschild                                                              */

json_t *api_op_gr_schwarzschild(struct api_call *c, const json_t *body)
{
    struct mech_gr_units u;
    if (!gr_units_read(c, body, &u)) return NULL;
    struct mech_error e;
    mech_error_clear(&e);
    json_t *out = json_object();
    json_object_set_new_nocheck(out, "units", gr_units_json(c, &u));
    json_object_set_new_nocheck(out, "schwarzschild_radius",
                                api_real(c, mech_gr_len_out(&u, MECH_SCHW_HORIZON)));
    json_object_set_new_nocheck(out, "photon_sphere",
                                api_real(c, mech_gr_len_out(&u, MECH_SCHW_PHOTON_SPHERE)));
    json_object_set_new_nocheck(out, "isco", api_real(c, mech_gr_len_out(&u, MECH_SCHW_ISCO)));
    json_object_set_new_nocheck(out, "critical_impact_parameter",
                                api_real(c, mech_gr_len_out(&u, MECH_SCHW_CRITICAL_IMPACT)));
    json_object_set_new_nocheck(out, "isco_binding_efficiency",
                                api_real(c, MECH_SCHW_ISCO_BINDING_EFFICIENCY));

    const json_t *rj = json_object_get(body, "r"), *refj = json_object_get(body, "reference_r");
    if (refj && !rj) {
        api_call_invalid(c, "/r", "reference_r compares with a circular orbit at r: give r");
        json_decref(out);
        return NULL;
    }
    if (rj) {
        const double r = mech_gr_len_in(&u, json_number_value(rj));
        struct mech_schw_static s;
        struct mech_schw_circular co;
        if (mech_schw_static_clock(r, &s, &e) != MECH_OK ||
            mech_schw_circular_orbit(r, &co, &e) != MECH_OK) {
            api_call_domain(c, "/r",
                            "r = %.17g is not outside the horizon r_s = %.17g: no static clock or "
                            "orbit there",
                            json_number_value(rj), mech_gr_len_out(&u, 2.0));
            json_decref(out);
            return NULL;
        }
        json_t *a = json_object();
        json_object_set_new_nocheck(a, "r",
                                    api_real(c, json_number_value(rj))); /* echoed exactly */
        json_object_set_new_nocheck(a, "r_over_rs", api_real(c, r / 2.0));
        json_object_set_new_nocheck(a, "weak_field_potential", api_real(c, 1.0 / r));
        json_t *st = json_object();
        json_object_set_new_nocheck(st, "clock_rate", api_real(c, s.rate));
        json_object_set_new_nocheck(st, "clock_rate_deficit", api_real(c, s.rate_deficit));
        json_object_set_new_nocheck(st, "redshift", api_real(c, s.redshift));
        json_object_set_new_nocheck(a, "static", st);
        json_t *cj = json_object();
        json_object_set_new_nocheck(cj, "exists",
                                    json_boolean(co.stability != MECH_SCHW_ORBIT_NONE));
        json_object_set_new_nocheck(cj, "stability", json_string(stability_name(co.stability)));
        if (co.stability != MECH_SCHW_ORBIT_NONE) {
            json_object_set_new_nocheck(cj, "clock_rate", api_real(c, co.rate));
            json_object_set_new_nocheck(cj, "clock_rate_deficit", api_real(c, co.rate_deficit));
            json_object_set_new_nocheck(cj, "energy", api_real(c, co.energy));
            json_object_set_new_nocheck(cj, "binding_efficiency",
                                        api_real(c, co.binding_efficiency));
            json_object_set_new_nocheck(cj, "angular_momentum",
                                        api_real(c, mech_gr_ang_out(&u, co.angular_momentum)));
            json_object_set_new_nocheck(cj, "local_speed_over_c", api_real(c, co.local_speed));
            json_object_set_new_nocheck(cj, "angular_velocity",
                                        api_real(c, co.omega / mech_gr_time_out(&u, 1.0)));
            json_object_set_new_nocheck(cj, "period_coordinate",
                                        api_real(c, mech_gr_time_out(&u, co.period_t)));
            json_object_set_new_nocheck(cj, "period_proper",
                                        api_real(c, mech_gr_time_out(&u, co.period_tau)));
        } else {
            json_object_set_new_nocheck(cj, "why",
                                        json_string("no circular geodesic at or inside the photon "
                                                    "sphere r = 3GM/c^2"));
        }
        json_object_set_new_nocheck(a, "circular_orbit", cj);
        json_object_set_new_nocheck(out, "at_r", a);
        if (refj) {
            /* the radii as given, with GM/c^2 in their unit: r - R is formed before scaling */
            struct mech_schw_clock_compare cc;
            enum mech_status st2 = mech_schw_clock_compare(
                json_number_value(refj), json_number_value(rj), mech_gr_len_out(&u, 1.0), &cc, &e);
            if (st2 != MECH_OK) {
                api_call_fail_core(c, st2, &e, "");
                json_decref(out);
                return NULL;
            }
            const double day = 86400e6;
            json_t *k = json_object();
            json_object_set_new_nocheck(k, "reference", json_string("static clock at reference_r"));
            json_object_set_new_nocheck(k, "clock",
                                        json_string("clock on the circular orbit at r"));
            json_object_set_new_nocheck(k, "reference_r", api_real(c, json_number_value(refj)));
            json_object_set_new_nocheck(k, "r", api_real(c, json_number_value(rj)));
            json_t *f = json_object();
            json_object_set_new_nocheck(f, "gravitational", api_real(c, cc.gravitational));
            json_object_set_new_nocheck(f, "velocity", api_real(c, cc.velocity));
            json_object_set_new_nocheck(f, "net", api_real(c, cc.net));
            json_object_set_new_nocheck(k, "fractional", f);
            json_t *d = json_object();
            json_object_set_new_nocheck(d, "gravitational", api_real(c, cc.gravitational * day));
            json_object_set_new_nocheck(d, "velocity", api_real(c, cc.velocity * day));
            json_object_set_new_nocheck(d, "net", api_real(c, cc.net * day));
            json_object_set_new_nocheck(k, "microseconds_per_day", d);
            json_t *fo = json_object();
            json_object_set_new_nocheck(fo, "gravitational",
                                        api_real(c, cc.first_order_gravitational));
            json_object_set_new_nocheck(fo, "velocity", api_real(c, cc.first_order_velocity));
            json_object_set_new(fo, "net", api_real(c, cc.first_order_net));
            json_object_set_new(fo, "microseconds_per_day_net",
                                api_real(c, cc.first_order_net * day));
            json_object_set_new_nocheck(k, "first_order", fo);
            json_t *uf = json_object();
            json_object_set_new_nocheck(uf, "gravitational",
                                        api_real(c, cc.uniform_field_gravitational));
            json_object_set_new_nocheck(
                uf, "label",
                json_string("approximation: the notes' uniform-field red shift g h/c^2, g = "
                            "GM/R^2 at reference_r, h = r - R (relative error ~h/R beside "
                            "fractional.gravitational)"));
            json_object_set_new_nocheck(k, "uniform_field", uf);
            json_object_set_new_nocheck(
                k, "left_out",
                json_string("the reference's own motion (the Earth's rotation: "
                            "v^2/(2c^2) ~ 1.2e-12 at the equator, 0.1 us/day), "
                            "other masses, orbit eccentricity"));
            json_object_set_new_nocheck(out, "clock_comparison", k);
        }
    }

    const json_t *ij = json_object_get(body, "infall_from");
    if (ij) {
        struct mech_radial_infall f;
        enum mech_status sti =
            mech_radial_infall_from_rest(mech_gr_len_in(&u, json_number_value(ij)), &f, &e);
        if (sti != MECH_OK) {
            api_call_fail_core(c, sti, &e, "");
            json_decref(out);
            return NULL;
        }
        json_t *ri = json_object();
        json_object_set_new_nocheck(ri, "from", api_real(c, json_number_value(ij)));
        json_object_set_new_nocheck(ri, "proper_time_to_horizon",
                                    api_real(c, mech_gr_time_out(&u, f.to_horizon)));
        json_object_set_new_nocheck(ri, "proper_time_to_singularity",
                                    api_real(c, mech_gr_time_out(&u, f.to_singularity)));
        json_object_set_new_nocheck(ri, "proper_time_horizon_to_singularity",
                                    api_real(c, mech_gr_time_out(&u, f.horizon_to_singularity)));
        json_object_set_new_nocheck(ri, "coordinate_time_to_horizon", json_null());
        json_object_set_new_nocheck(
            ri, "note",
            json_string("a fall from rest; the coordinate (far-away) time to the horizon is "
                        "infinite, hence null; the proper time to r = 0 equals the Newtonian "
                        "free-fall time"));
        json_object_set_new_nocheck(out, "radial_infall", ri);
    }

    const json_t *ej = json_object_get(body, "effective_potential");
    if (ej) {
        const double L = mech_gr_ang_in(&u, api_number(ej, "angular_momentum", 0));
        double ru, rs;
        int ne = mech_schw_veff_extrema(L, &ru, &rs);
        const json_t *a = json_object_get(ej, "r_min"), *b = json_object_get(ej, "r_max");
        /* sampled evenly in the request's length unit, so given ends are echoed exactly */
        double rmin = a ? json_number_value(a) : mech_gr_len_out(&u, 2.0);
        double rmax = b ? json_number_value(b) : mech_gr_len_out(&u, fmax(30.0, ne ? 3.0 * rs : 0.0));
        if (!(mech_gr_len_in(&u, rmin) >= 2.0)) {
            api_call_domain(c, "/effective_potential/r_min",
                            "r_min must be at least r_s = %.17g (outside the horizon)",
                            mech_gr_len_out(&u, 2.0));
            json_decref(out);
            return NULL;
        }
        if (!(rmax > rmin) || !isfinite(rmax)) {
            api_call_invalid(c, "/effective_potential/r_max", "r_max must be above r_min");
            json_decref(out);
            return NULL;
        }
        const size_t n = (size_t)api_number_of(ej, "samples");
        double *rr = malloc(n * sizeof *rr), *vm = malloc(n * sizeof *vm),
               *vp = malloc(n * sizeof *vp);
        double *v1 = malloc(n * sizeof *v1);
        if (!rr || !vm || !vp || !v1) {
            free(rr);
            free(vm);
            free(vp);
            free(v1);
            mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
            api_call_fail_core(c, MECH_ENOMEM, &e, "");
            json_decref(out);
            return NULL;
        }
        const double inv_len2 = 1.0 / (mech_gr_len_out(&u, 1.0) * mech_gr_len_out(&u, 1.0));
        for (size_t i = 0; i < n; i++) {
            rr[i] = i + 1 == n ? rmax : rmin + (rmax - rmin) * (double)i / (double)(n - 1);
            const double r = mech_gr_len_in(&u, rr[i]), Lr = L / r;
            vm[i] = mech_schw_veff_massive(r, L);
            v1[i] = -2.0 / r + Lr * Lr - 2.0 * Lr * Lr / r; /* V - 1 without cancellation */
            vp[i] = mech_schw_veff_photon(r) * inv_len2;
        }
        json_t *v = json_object();
        json_object_set_new_nocheck(v, "angular_momentum", api_real(c, mech_gr_ang_out(&u, L)));
        json_object_set_new_nocheck(
            v, "massive_normalisation",
            json_string("(dr/dtau)^2/c^2 + V = (E/mc^2)^2, V = (1 - r_s/r)(1 + "
                        "L^2/(c^2 r^2)), dimensionless"));
        json_object_set_new_nocheck(v, "photon_normalisation",
                                    json_string(u.geometric
                                                    ? "(1/L^2)(dr/dlambda)^2 = 1/b^2 - W, W = (1 - "
                                                      "r_s/r)/r^2, (GM/c^2)^-2"
                                                    : "(1/L^2)(dr/dlambda)^2 = 1/b^2 - W, W = (1 - "
                                                      "r_s/r)/r^2, 1/m^2"));
        json_object_set_new_nocheck(v, "r", api_reals(c, rr, n));
        json_object_set_new_nocheck(v, "massive", api_reals(c, vm, n));
        json_object_set_new_nocheck(v, "massive_minus_one", api_reals(c, v1, n));
        json_object_set_new_nocheck(v, "photon", api_reals(c, vp, n));
        json_t *x = json_object();
        json_object_set_new_nocheck(x, "count", json_integer(ne));
        json_object_set_new_nocheck(x, "unstable_r",
                                    ne ? api_real(c, mech_gr_len_out(&u, ru)) : json_null());
        json_object_set_new_nocheck(x, "unstable_V",
                                    ne ? api_real(c, mech_schw_veff_massive(ru, L)) : json_null());
        json_object_set_new_nocheck(x, "stable_r",
                                    ne ? api_real(c, mech_gr_len_out(&u, rs)) : json_null());
        json_object_set_new_nocheck(x, "stable_V",
                                    ne ? api_real(c, mech_schw_veff_massive(rs, L)) : json_null());
        json_object_set_new_nocheck(v, "massive_extrema", x);
        json_t *pm = json_object();
        json_object_set_new_nocheck(pm, "r", api_real(c, mech_gr_len_out(&u, 3.0)));
        json_object_set_new_nocheck(pm, "W", api_real(c, inv_len2 / 27.0));
        json_object_set_new_nocheck(v, "photon_maximum", pm);
        json_object_set_new_nocheck(out, "effective_potential", v);
        free(rr);
        free(vm);
        free(vp);
        free(v1);
    }
    return out;
}

/* ===================================================================================== */
/* POST /v1/gr/geodesic                                                                   */

/* One geodesic request on its way through: parsed, set up, run. */
struct geo_call {
    struct mech_gr_units u;
    int photon;
    struct mech_geodesic_request q;
    struct mech_geodesic_setup su;
    struct mech_geodesic_problem p; /* su.problem with the integrator chosen */
    struct api_integrator_choice ch;
    struct mech_geodesic_answer ans;
};

/* The request's shape (a form that fits the kind, one run length) and its
 * numbers, in the request's units. Returns 0 after recording an error. */
static int geo_request_read(struct api_call *c, const json_t *body, struct geo_call *g)
{
    const struct mech_gr_units u = g->u;
    const int photon = g->photon = !strcmp(api_string(body, "kind", "timelike"), "null");
    const json_t *ini = json_object_get(body, "initial");
    const json_t *r0j = json_object_get(body, "r0");
    const int form_energy = json_object_get(ini, "energy") != NULL;
    const int form_local = json_object_get(ini, "local_velocity") != NULL;
    const int form_impact = json_object_get(ini, "impact_parameter") != NULL;
    const int form_turn = json_object_get(ini, "periapsis") != NULL;
    const int form_ae = json_object_get(ini, "semi_major_axis") != NULL;
    const int orbit_form = form_turn || form_ae;
    if (photon && (form_energy || orbit_form)) {
        api_call_invalid(c, form_energy ? "/initial/energy" : "/initial",
                         "light (kind null) is given by impact_parameter or local_velocity");
        return 0;
    }
    if (!photon && form_impact) {
        api_call_invalid(c, "/initial/impact_parameter",
                         "impact_parameter is for light (kind null); a massive particle takes "
                         "energy and angular_momentum, local_velocity or an orbit");
        return 0;
    }
    if (orbit_form && r0j) {
        api_call_invalid(c, "/r0",
                         "an orbit given by its turning points starts at periapsis: "
                         "omit r0");
        return 0;
    }
    if (!orbit_form && !r0j && !form_impact) {
        api_call_invalid(c, "/r0", "r0 (the start radius) is required (it has a default only "
                                   "for light given by impact_parameter, a ray from far away)");
        return 0;
    }
    const json_t *tj = json_object_get(body, "tau_end"), *oj = json_object_get(body, "orbits"),
                 *lj = json_object_get(body, "lambda_end");
    if (photon && (tj || oj)) {
        api_call_invalid(c, tj ? "/tau_end" : "/orbits",
                         "light has no proper time: give lambda_end (or nothing)");
        return 0;
    }
    if (!photon && lj) {
        api_call_invalid(c, "/lambda_end", "a massive particle runs in proper time: tau_end");
        return 0;
    }
    if (!photon && !!tj == !!oj) {
        api_call_invalid(c, "/tau_end", "give exactly one of tau_end and orbits");
        return 0;
    }

    /* the request, in its own units; the set-up is mech_geodesic_setup */
    struct mech_geodesic_request q;
    memset(&q, 0, sizeof q);
    q.units = u;
    q.kind = photon ? MECH_GEODESIC_NULL : MECH_GEODESIC_TIMELIKE;
    q.form = form_energy   ? MECH_GEODESIC_FORM_ENERGY
             : form_local  ? MECH_GEODESIC_FORM_LOCAL
             : form_impact ? MECH_GEODESIC_FORM_IMPACT
             : form_turn   ? MECH_GEODESIC_FORM_TURNING
                           : MECH_GEODESIC_FORM_AXES;
    q.has_r0 = r0j != NULL;
    q.r0 = r0j ? json_number_value(r0j) : NAN;
    q.phi0 = api_number_of(body, "phi0");
    if (form_energy || form_impact)
        q.outward = !strcmp(api_string_of(ini, "radial_direction"), "outward");
    if (form_energy) {
        q.energy = api_number(ini, "energy", 1);
        q.angular_momentum = api_number(ini, "angular_momentum", 0);
    } else if (form_local) {
        const json_t *lv = json_object_get(ini, "local_velocity");
        q.v_radial = api_number(lv, "radial", 0);
        q.v_tangential = api_number(lv, "tangential", 0);
    } else if (form_impact) {
        q.impact_parameter = api_number(ini, "impact_parameter", 0);
    } else if (form_turn) {
        q.periapsis = api_number(ini, "periapsis", 1);
        q.apoapsis = api_number(ini, "apoapsis", 1);
    } else {
        q.semi_major_axis = api_number(ini, "semi_major_axis", 1);
        q.eccentricity = api_number(ini, "eccentricity", 0);
    }
    q.has_tau_end = tj != NULL;
    q.tau_end = tj ? json_number_value(tj) : NAN;
    q.has_orbits = oj != NULL;
    q.orbits = oj ? json_number_value(oj) : NAN;
    q.has_lambda_end = lj != NULL;
    q.lambda_end = lj ? json_number_value(lj) : NAN;
    q.has_r_escape = json_object_get(body, "r_escape") != NULL;
    q.r_escape = q.has_r_escape ? api_number(body, "r_escape", 1) : NAN;
    q.constraint_bound = api_number_of(body, "constraint_bound");
    q.samples = (size_t)api_number_of(body, "samples");

    g->q = q;
    return 1;
}

/* Second-order methods need q'' = a(t, q): refused by name. Returns 0 after
 * recording an error. */
static int geo_method_check(struct api_call *c, const json_t *ib)
{
    const char *mname = ib ? api_string(ib, "method", NULL) : NULL;
    if (mname) {
        const struct mech_integrator *mm = mech_ode_method_find(mname);
        if (mm && mech_ode_method_describe(mm).second_order) {
            api_call_invalid(
                c, "/integrator/method",
                "%s needs q'' = a(t, q) with q' = v; the geodesic's state (r, dr/dtau, "
                "phi, t) has phi and t as quadratures, so use rk8pd, rkck, rkf45 or "
                "msbdf (rtol/atol), or rk4, gauss4, gauss6 (symplectic) or euler (dt), "
                "or an accuracy preset",
                mname);
            return 0;
        }
    }
    return 1;
}

/* A failed integration: progress in the request's time unit, the constraint's
 * progress, the core's parameter as a pointer into the request. */
static void geo_run_fail(struct api_call *c, const struct geo_call *g, enum mech_status st,
                         struct mech_error *e0)
{
    const struct mech_gr_units u = g->u;
    const struct mech_geodesic_result r = g->ans.result;
    struct mech_error e = *e0;
    if (st == MECH_EBUDGET || st == MECH_EDEADLINE) {
        e.progress.t_reached = mech_gr_time_out(&u, e.progress.t_reached);
        e.progress.t_target = mech_gr_time_out(&u, e.progress.t_target);
    }
    if (st == MECH_ENUMERIC && !strcmp(e.param, "constraint_bound")) {
        api_call_fail_core(c, st, &e, ""); /* errors[] at /constraint_bound */
        if (!c->extra) c->extra = json_object();
        json_t *pr = json_object();
        json_object_set_new_nocheck(pr, "samples_written",
                                    json_integer((json_int_t)r.n_samples));
        json_object_set_new_nocheck(pr, "steps", json_integer(r.stats.steps));
        json_object_set_new_nocheck(c->extra, "progress", pr);
    } else {
        if (e.param[0] && strcmp(e.param, "samples") && strncmp(e.param, "integrator", 10)) {
            char ptr[128];
            snprintf(ptr, sizeof ptr, "/%s", e.param);
            e.param[0] = 0;
            api_call_fail_core(c, st, &e, ptr);
        } else {
            api_call_fail_core(c, st, &e, "");
        }
    }
}

/* units, kind, conserved quantities, r0, motion, the orbit's shape and periods */
static void geo_encode_start(struct api_call *c, json_t *out, const struct geo_call *g)
{
    const struct mech_gr_units u = g->u;
    const int photon = g->photon;
    const struct mech_geodesic_answer ans = g->ans;
    const struct mech_geodesic_init in = g->su.problem.init;
    const struct mech_geodesic_bound bd = g->su.bd;
    const int bound = g->su.bound;
    const double Ttau = g->su.period_tau;
    const double Tt = g->su.period_t;
    json_object_set_new_nocheck(out, "units", gr_units_json(c, &u));
    json_object_set_new_nocheck(out, "kind", json_string(photon ? "null" : "timelike"));
    json_t *cons = json_object();
    if (photon) {
        json_object_set_new_nocheck(cons, "impact_parameter", api_real(c, mech_gr_len_out(&u, in.L)));
        json_object_set_new_nocheck(cons, "normalisation",
                                    json_string("E = 1: dt/dlambda = 1/(1 - r_s/r)"));
    } else {
        json_object_set_new_nocheck(cons, "energy", api_real(c, in.E));
        json_object_set_new_nocheck(cons, "energy_minus_one", api_real(c, in.E2m1 / (1.0 + in.E)));
        json_object_set_new_nocheck(cons, "angular_momentum", api_real(c, mech_gr_ang_out(&u, in.L)));
    }
    json_object_set_new_nocheck(out, "conserved", cons);
    json_object_set_new_nocheck(out, "r0", api_real(c, mech_gr_len_out(&u, in.r0)));
    json_object_set_new_nocheck(out, "motion", json_string(ans.motion));
    if (bound) {
        const double rp = 1.0 / bd.u2, ra = 1.0 / bd.u1;
        json_t *o = json_object();
        json_object_set_new_nocheck(o, "periapsis", api_real(c, mech_gr_len_out(&u, rp)));
        json_object_set_new_nocheck(o, "apoapsis", api_real(c, mech_gr_len_out(&u, ra)));
        json_object_set_new_nocheck(o, "semi_major_axis",
                                    api_real(c, mech_gr_len_out(&u, 0.5 * (rp + ra))));
        json_object_set_new_nocheck(o, "eccentricity", api_real(c, (ra - rp) / (ra + rp)));
        json_object_set_new_nocheck(o, "radial_period_proper", api_real(c, mech_gr_time_out(&u, Ttau)));
        json_object_set_new_nocheck(o, "radial_period_coordinate",
                                    api_real(c, mech_gr_time_out(&u, Tt)));
        json_object_set_new_nocheck(out, "orbit", o);
    }
}

/* the samples (converted in place) and where the run ended */
static void geo_encode_samples(struct api_call *c, json_t *out, const struct geo_call *g)
{
    const struct mech_gr_units u = g->u;
    const int photon = g->photon;
    const struct mech_geodesic_result r = g->ans.result;
    const double rs_esc = g->su.problem.r_escape;
    const size_t ns = r.n_samples;
    double *sp = r.param, *st_ = r.t, *sr = r.r, *sf = r.phi; /* converted in place */
    for (size_t i = 0; i < ns; i++) {
        sp[i] = mech_gr_time_out(&u, sp[i]);
        st_[i] = mech_gr_time_out(&u, st_[i]);
        sr[i] = mech_gr_len_out(&u, sr[i]);
    }
    json_t *sj = json_object();
    json_object_set_new(sj, photon ? "lambda" : "tau", api_reals(c, sp, ns));
    json_object_set_new_nocheck(sj, "t", api_reals(c, st_, ns));
    json_object_set_new_nocheck(sj, "r", api_reals(c, sr, ns));
    json_object_set_new_nocheck(sj, "phi", api_reals(c, sf, ns));
    json_object_set_new_nocheck(out, "samples", sj);
    json_t *en = json_object();
    json_object_set_new_nocheck(en, "reason",
                                json_string(r.captured  ? "captured"
                                            : r.escaped ? "escaped"
                                            : photon    ? "lambda_end"
                                                        : "tau_end"));
    json_object_set_new_nocheck(en, "captured", json_boolean(r.captured));
    json_object_set_new_nocheck(en, "escaped", json_boolean(r.escaped));
    json_object_set_new(en, photon ? "lambda" : "tau", api_real(c, mech_gr_time_out(&u, r.end_param)));
    json_object_set_new_nocheck(en, "t", api_real(c, mech_gr_time_out(&u, r.end_t)));
    json_object_set_new_nocheck(en, "r", api_real(c, mech_gr_len_out(&u, r.end_r)));
    json_object_set_new_nocheck(en, "phi", api_real(c, r.end_phi));
    if (r.captured)
        json_object_set_new(
            en, "capture_radius",
            api_real(c, mech_gr_len_out(&u, 2.0 * (1.0 + MECH_GEODESIC_CAPTURE_MARGIN))));
    if (r.escaped) json_object_set_new_nocheck(en, "r_escape", api_real(c, mech_gr_len_out(&u, rs_esc)));
    json_object_set_new_nocheck(out, "end", en);

}

/* bound orbits: the periapsis advance beside its exact and first-order values */
static void geo_encode_precession(struct api_call *c, json_t *out, const struct geo_call *g)
{
    const struct mech_gr_units u = g->u;
    const struct mech_geodesic_result r = g->ans.result;
    const struct mech_geodesic_answer ans = g->ans;
    const double adv_exact = g->su.adv_exact;
    const double adv_quad = g->su.adv_quad;
    const double Tt = g->su.period_t;
    const double first = ans.advance_first_order; /* 6 pi M/(a(1-e^2)) */
    json_t *pj = json_object();
    json_object_set_new_nocheck(pj, "periapses_found", json_integer(r.n_periapses));
    json_object_set_new_nocheck(pj, "orbits_measured",
                                json_integer(r.n_periapses > 0 ? r.n_periapses - 1 : 0));
    int has = r.n_periapses >= 2 && isfinite(r.measured_advance);
    json_object_set_new_nocheck(pj, "measured_per_orbit",
                                has ? api_real(c, r.measured_advance) : json_null());
    json_object_set_new_nocheck(pj, "exact_per_orbit", api_real(c, adv_exact));
    json_object_set_new_nocheck(pj, "exact_per_orbit_quadrature", api_real(c, adv_quad));
    json_object_set_new_nocheck(pj, "first_order_per_orbit", api_real(c, first));
    json_object_set_new_nocheck(pj, "measured_minus_exact",
                                has ? api_real(c, r.measured_advance - adv_exact)
                                    : json_null());
    json_object_set_new_nocheck(
        pj, "relative_error",
        has ? api_real(c, fabs(r.measured_advance - adv_exact) / adv_exact) : json_null());
    json_object_set_new(
        pj, "first_order_formula",
        json_string("6 pi GM/(c^2 a (1 - e^2)), a(1 - e^2) = 2 r_p r_a/(r_p + r_a)"));
    if (!u.geometric) {
        const double per_century = GR_CENTURY_S / mech_gr_time_out(&u, Tt) * GR_ARCSEC;
        json_t *ac = json_object();
        json_object_set_new_nocheck(
            ac, "measured", has ? api_real(c, r.measured_advance * per_century) : json_null());
        json_object_set_new_nocheck(ac, "exact", api_real(c, adv_exact * per_century));
        json_object_set_new_nocheck(ac, "first_order", api_real(c, first * per_century));
        json_object_set_new_nocheck(ac, "orbits_per_century",
                                    api_real(c, per_century / GR_ARCSEC));
        json_object_set_new_nocheck(pj, "arcsec_per_century", ac);
    }
    json_object_set_new_nocheck(out, "precession", pj);
}

/* scattered light: the deflection beside its exact and weak-field values */
static void geo_encode_deflection(struct api_call *c, json_t *out, const struct geo_call *g)
{
    const struct mech_gr_units u = g->u;
    const struct mech_geodesic_result r = g->ans.result;
    const struct mech_geodesic_answer ans = g->ans;
    const double dx = ans.deflection_elliptic, dq = ans.deflection_exact;
    const int has = isfinite(r.measured_deflection);
    json_t *dj = json_object();
    json_object_set_new_nocheck(dj, "measured",
                                has ? api_real(c, r.measured_deflection) : json_null());
    if (!has)
        json_object_set_new_nocheck(
            dj, "why_not_measured",
            json_string("measured only for light that starts inward and "
                        "escapes within the run"));
    /* the quadrature keeps full relative precision for tiny deflections; the
     * elliptic form loses ~eps pi / delta to the final "- pi" */
    json_object_set_new_nocheck(dj, "exact", api_real(c, dq));
    const double ell_prec = ans.elliptic_precision;
    json_object_set_new_nocheck(dj, "exact_elliptic",
                                ell_prec < 1e-3 ? api_real(c, dx) : json_null());
    json_object_set_new_nocheck(dj, "exact_elliptic_relative_precision", api_real(c, ell_prec));
    json_object_set_new_nocheck(
        dj, "exact_method",
        json_string("exact: quadrature of the deflection integral in a form "
                    "without cancellation; exact_elliptic: Byrd & Friedman "
                    "233.00 with gsl_sf_ellint_F, whose final - pi cancels "
                    "(relative precision ~4e-16 pi / delta; null beyond "
                    "1e-3)"));
    json_object_set_new_nocheck(dj, "first_order", api_real(c, ans.deflection_first_order));
    json_object_set_new_nocheck(dj, "second_order", api_real(c, ans.deflection_second_order));
    json_object_set_new_nocheck(dj, "measured_minus_exact",
                                has ? api_real(c, r.measured_deflection - dq) : json_null());
    json_object_set_new_nocheck(dj, "closest_approach", api_real(c, mech_gr_len_out(&u, ans.closest_approach)));
    json_t *as = json_object();
    json_object_set_new_nocheck(
        as, "measured", has ? api_real(c, r.measured_deflection * GR_ARCSEC) : json_null());
    json_object_set_new_nocheck(as, "exact", api_real(c, dq * GR_ARCSEC));
    json_object_set_new_nocheck(as, "first_order", api_real(c, ans.deflection_first_order * GR_ARCSEC));
    json_object_set_new_nocheck(dj, "arcsec", as);
    json_object_set_new_nocheck(out, "deflection", dj);
}

/* the integrator's statistics, the constraint's drift, the selection */
static void geo_encode_diagnostics(struct api_call *c, json_t *out, const struct geo_call *g)
{
    const struct mech_gr_units u = g->u;
    const int photon = g->photon;
    const struct mech_geodesic_result r = g->ans.result;
    const double T = g->su.time_unit;
    const struct mech_geodesic_problem p = g->p;
    const struct api_integrator_choice ch = g->ch;
    json_t *d = json_object();
    api_integrator_block_stats(c, d, &ch, &r.stats);
    json_t *cj = json_object();
    json_object_set_new_nocheck(
        cj, "definition",
        json_string(photon ? "g(k,k) = 0 with E = 1: residual (dr/dlambda)^2 + (1 - "
                             "r_s/r) L^2/r^2 - E^2"
                           : "g(u,u) = -c^2: residual (dr/dtau)^2/c^2 + V(r) - E^2"));
    json_object_set_new_nocheck(cj, "bound", api_real(c, p.constraint_bound));
    json_object_set_new_nocheck(cj, "max_relative", api_real(c, r.constraint_max_relative));
    json_object_set_new_nocheck(cj, "final_relative", api_real(c, r.constraint_final_relative));
    json_object_set_new(cj, photon ? "max_abs_g_kk" : "max_abs_g_uu_plus_1",
                        api_real(c, r.constraint_max_abs));
    json_object_set_new_nocheck(d, "constraint", cj);
    json_object_set_new_nocheck(d, "time_unit_of_the_scaled_state",
                                api_real(c, mech_gr_time_out(&u, T)));
    json_object_set_new_nocheck(d, "selection", api_integrator_block_selection(c, &ch));
    json_object_set_new_nocheck(out, "diagnostics", d);
    json_object_set_new_nocheck(out, "cost", json_object());
}

json_t *api_op_gr_geodesic(struct api_call *c, const json_t *body)
{
    struct geo_call g;
    memset(&g, 0, sizeof g);
    if (!gr_units_read(c, body, &g.u)) return NULL;
    if (!geo_request_read(c, body, &g)) return NULL;

    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_geodesic_setup(&g.q, &g.su, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    g.p = g.su.problem;
    const double T = g.su.time_unit;

    /* integrator: the shared block; second-order methods do not apply */
    const json_t *ib = json_object_get(body, "integrator");
    if (!geo_method_check(c, ib)) return NULL;
    static const struct api_integrator_system geodesic_eqs = {
        "the geodesic equations with r, dr/dtau, phi and t carried together",
        "the state in geometric units (G = c = M = 1)", 1.0, 0, 0.0};
    /* a pilot for long runs in strong field (core/gr/geodesic_run.c) */
    const struct mech_pilot_system pilot = {mech_geodesic_pilot_run, &g.p};
    const struct api_integrator_hooks hooks = {
        0.0, 0.0, 0.0, mech_geodesic_pilot_applies(&g.su) ? &pilot : NULL};
    if (!api_integrator_block_parse_hooks(c, ib, "/integrator", g.p.param_end / T, &geodesic_eqs,
                                          NULL, &hooks, &g.ch))
        return NULL;
    if (api_dry_run_requested(body))
        return api_dry_run_answer(c, api_integrator_block_selection(c, &g.ch));
    g.p.method = g.ch.method;
    g.p.opt = g.ch.opt;
    if (g.ch.opt.dt > 0) g.p.opt.dt = mech_gr_time_in(&g.u, g.ch.opt.dt) / T;

    st = mech_geodesic_run(&g.su, &g.p, &c->budget, &g.ans, &e);
    json_t *out = NULL;
    if (st != MECH_OK && g.ans.integrated) {
        api_call_fail_core(c, st, &e, ""); /* a reference of the deflection failed */
    } else if (st != MECH_OK) {
        geo_run_fail(c, &g, st, &e);
    } else {
        out = json_object();
        geo_encode_start(c, out, &g);
        geo_encode_samples(c, out, &g);
        if (g.su.bound) geo_encode_precession(c, out, &g);
        if (g.ans.scatter) geo_encode_deflection(c, out, &g);
        geo_encode_diagnostics(c, out, &g);
    }
    mech_geodesic_answer_free(&g.ans);
    return out;
}
