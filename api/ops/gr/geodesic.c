/* geodesic.c — POST /v1/gr/geodesic: equatorial timelike and null
 * geodesics of the Schwarzschild geometry with the periapsis advance and the
 * light deflection beside their exact values (the notes' "A Little General
 * Relativity", built as Hartle, "Gravity" ch. 9 and 11; Carroll ch. 5).
 * The physics is core/gr/ in geometric units (M = 1): the set-up from the
 * request's initial-condition form (geodesic_setup.c) and the run with its
 * references (geodesic_run.c over geodesic.c); this file parses the request
 * (its units with api/ops/gr/gr_units.c), calls them and encodes the answer in
 * the request's units. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "ops/gr/gr_units.h"
#include "request/integrator_block.h"
#include "mech/base/constants.h"
#include "mech/gr/geodesic.h"
#include "mech/answers/gr/geodesic_run.h"
#include "mech/answers/gr/geodesic_setup.h"
#include "mech/gr/gr_units.h"
#include "request/trajectory_request.h"

/* Constants (documented in the route's description). */
#define GR_ARCSEC (180.0 * 3600.0 / MECH_PI)
#define GR_CENTURY_S (36525.0 * 86400.0) /* Julian century, s */

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
    json_object_set_new_nocheck(out, "units", api_gr_units_json(c, &u));
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
        /* a period the problem gives (Mercury's sidereal 87.969 d) or the orbit's own */
        const json_t *pgiven = c->body ? json_object_get(c->body, "orbital_period") : NULL;
        const double period = pgiven ? json_number_value(pgiven) : mech_gr_time_out(&u, Tt);
        const double per_century = GR_CENTURY_S / period * GR_ARCSEC;
        json_t *ac = json_object();
        json_object_set_new_nocheck(ac, "period_used", api_real(c, period));
        json_object_set_new_nocheck(ac, "period_source",
                                    json_string(pgiven ? "given (orbital_period)"
                                                       : "the orbit's radial period in "
                                                         "coordinate time"));
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
    json_object_set_new_nocheck(
        dj, "which_to_use",
        json_string("exact: the geometry's deflection for this impact parameter, by "
                    "quadrature; measured is the integrated ray's (a check on the "
                    "integration, within its tolerance of exact)"));
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
    /* the error evidence: the exact deflection or periapsis advance, as an
     * angle relative to the angle the run sweeps (pi + delta for light,
     * 2 pi + advance per radial period), the scale of phi */
    double err = -1.0;
    const char *ev = NULL;
    int bound_adv = 0; /* the advance's error: a lower bound of the samples' (it can cancel) */
    if (ch.chosen && g->ans.scatter && isfinite(r.measured_deflection) &&
        isfinite(g->ans.deflection_exact)) {
        err = fabs(r.measured_deflection - g->ans.deflection_exact) /
              (MECH_PI + g->ans.deflection_exact);
        ev = "the exact deflection (deflection.exact): |measured - exact| / (pi + exact), "
             "the angle the ray sweeps";
    } else if (ch.chosen && g->su.bound && r.n_periapses >= 2 && isfinite(r.measured_advance) &&
               isfinite(g->su.adv_exact)) {
        /* the advance's error is the phase drift per radial period: over the
         * run the samples' phase drifts by that times the periods between
         * the first and last periapsis */
        err = fabs(r.measured_advance - g->su.adv_exact) * (double)(r.n_periapses - 1) /
              (2.0 * MECH_PI + g->su.adv_exact);
        bound_adv = 1;
        ev = "the larger of the calibrated law at the setting run and the exact periapsis "
             "advance's error (precession.exact_per_orbit): |measured - exact| x the radial "
             "periods between the first and last periapsis / (2 pi + exact), the phase drift "
             "over the run relative to the angle of one radial period";
    }
    json_object_set_new_nocheck(
        d, "selection",
        ch.chosen ? api_integrator_block_selection_run(c, &ch, ev ? err : -1.0, ev, bound_adv)
                  : api_integrator_block_selection(c, &ch));
    json_object_set_new_nocheck(out, "diagnostics", d);
    json_object_set_new_nocheck(out, "cost", json_object());
}

/* Light coming in from its start radius (it passes a periapsis or is captured). */
static int photon_in(const struct mech_geodesic_problem *p)
{
    return p->init.kind == MECH_GEODESIC_NULL && p->init.rdot0 < 0.0;
}

json_t *api_op_gr_geodesic(struct api_call *c, const json_t *body)
{
    struct geo_call g;
    memset(&g, 0, sizeof g);
    if (!api_gr_units_read(c, body, &g.u)) return NULL;
    if (g.u.geometric && json_object_get(body, "orbital_period")) {
        api_call_invalid(c, "/orbital_period",
                         "a period in seconds needs SI units (the rates per century are SI only)");
        return NULL;
    }
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
    struct api_integrator_system geodesic_eqs = {
        "the geodesic equations with r, dr/dtau, phi and t carried together",
        "the state in geometric units (G = c = M = 1)", 1.0, 0, 0.0, "geodesic", 0};
    if (g.photon) geodesic_eqs.rows = "geodesic_null"; /* light's own measured rows */
    /* a pilot for long runs in strong field (core/answers/gr/geodesic_run.c) */
    const struct mech_pilot_system pilot = {mech_geodesic_pilot_run, &g.p};
    /* light coming in and scattering: its winding's error gain and its cost
     * (mech_geodesic_error_gain, core/answers/gr/geodesic_run.c) */
    const double span = g.p.param_end / T;
    const int scatter = photon_in(&g.p);
    const struct api_integrator_hooks hooks = {
        scatter ? MECH_GEODESIC_SCATTER_COST_FACTOR * span : 0.0, 0.0, 0.0,
        mech_geodesic_pilot_applies(&g.su) ? &pilot : NULL,
        scatter ? mech_geodesic_error_gain(fabs(g.p.init.L)) : 0.0};
    if (!api_integrator_block_parse_hooks(c, ib, "/integrator", span, &geodesic_eqs,
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
