/* ep_relativity_waves.c — light and fields under relative motion:
 * POST /v1/relativity/doppler (Doppler shift and aberration, notes §3.14) and
 * POST /v1/relativity/fields (E and B under a boost, notes "Lorentz
 * Transformation of the Fields"). The numerics live in core/doppler.c and
 * core/em_fields.c; velocities use the shared input of velocity_request.h. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "endpoint.h"
#include "mech/constants.h"
#include "mech/doppler.h"
#include "mech/em_fields.h"
#include "velocity_request.h"


/* ======================= POST /v1/relativity/doppler ======================= */

static const char *frame_pointer(int in_source)
{
    return in_source ? "/emission_direction" : "/arrival_direction";
}

static json_t *angle_or_null(struct api_call *c, double a, double scale)
{
    return isnan(a) ? json_null() : api_real(c, a * scale);
}

json_t *api_op_relativity_doppler(struct api_call *c, const json_t *body)
{
    const json_t *emit = json_object_get(body, "emission_direction");
    const json_t *arrive = json_object_get(body, "arrival_direction");
    const json_t *fj = json_object_get(body, "frequency");
    const json_t *lj = json_object_get(body, "wavelength");
    if (emit && arrive)
        api_call_invalid(c, "/arrival_direction",
                         "give the light's direction once: emission_direction (source frame) "
                         "or arrival_direction (observer frame), not both");
    else if (!emit && !arrive)
        api_call_invalid(c, "/emission_direction",
                         "give the light's direction: emission_direction (in the source's frame) "
                         "or arrival_direction (in the observer's frame)");
    if (fj && lj)
        api_call_invalid(c, "/wavelength",
                         "give the emitted light as a frequency or as a wavelength, not both");
    struct mech_boost src, obs;
    const json_t *sv = json_object_get(body, "source_velocity");
    const json_t *ov = json_object_get(body, "observer_velocity");
    int ok = 1;
    if (sv && !api_velocity_parse(c, sv, "/source_velocity", &src)) ok = 0;
    if (ov && !api_velocity_parse(c, ov, "/observer_velocity", &obs)) ok = 0;
    if (!ok || c->problem != API_PROBLEM_NONE) return NULL;

    const int in_source = emit != NULL;
    const struct mech_vec3 dir = api_vec3_of(in_source ? emit : arrive);
    struct mech_doppler d;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_doppler_compute(
        sv ? &src : NULL, ov ? &obs : NULL, dir,
        in_source ? MECH_DOPPLER_SOURCE_FRAME : MECH_DOPPLER_OBSERVER_FRAME, &d, &e);
    if (st != MECH_OK) {
        if (!strcmp(e.param, "direction"))
            snprintf(e.param, sizeof e.param, "%s", frame_pointer(in_source) + 1);
        return api_call_fail_core(c, st, &e, "");
    }

    /* Emitted and observed light: ν_obs = D ν_emit, λ = c/ν (c exact). */
    double f_emit = 0, l_emit = 0, f_obs = 0, l_obs = 0;
    const int have_light = fj || lj;
    if (have_light) {
        if (fj) {
            f_emit = json_number_value(fj);
            l_emit = MECH_EM_C / f_emit;
        } else {
            l_emit = json_number_value(lj);
            f_emit = MECH_EM_C / l_emit;
        }
        f_obs = d.factor * f_emit;
        l_obs = l_emit / d.factor;
        if (!(isfinite(f_obs) && f_obs >= DBL_MIN && isfinite(l_obs) && l_obs >= DBL_MIN &&
              isfinite(l_emit) && isfinite(f_emit) && l_emit > 0 && f_emit > 0)) {
            mech_error_clear(&e);
            mech_error_set(&e, MECH_ENUMERIC, fj ? "frequency" : "wavelength",
                           "the observed light (Doppler factor %.6g) is outside the range of "
                           "double precision; use a less extreme frequency or wavelength",
                           d.factor);
            return api_call_fail_core(c, MECH_ENUMERIC, &e, "");
        }
    }

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "case", json_string(mech_doppler_case_name(d.kind)));
    json_object_set_new_nocheck(res, "doppler_factor", api_real(c, d.factor));
    json_object_set_new_nocheck(res, "doppler_factor_minus_one", api_real(c, d.factor_minus_one));
    /* z = lambda_obs/lambda_emit - 1 = 1/D - 1 = -(D - 1)/D, from the precise D - 1. */
    const double z = -d.factor_minus_one / d.factor;
    json_object_set_new_nocheck(res, "shift",
                                json_string(d.factor_minus_one > 0   ? "blue"
                                            : d.factor_minus_one < 0 ? "red"
                                                                     : "none"));
    json_object_set_new_nocheck(res, "redshift_z", api_real(c, z));
    if (have_light) {
        json_object_set_new_nocheck(res, "frequency_emitted", api_real(c, f_emit));
        json_object_set_new_nocheck(res, "wavelength_emitted", api_real(c, l_emit));
        json_object_set_new_nocheck(res, "frequency_observed", api_real(c, f_obs));
        json_object_set_new_nocheck(res, "wavelength_observed", api_real(c, l_obs));
        json_object_set_new_nocheck(res, "wavelength_shift", api_real(c, l_emit * z));
        json_object_set_new_nocheck(res, "frequency_shift",
                                    api_real(c, f_emit * d.factor_minus_one));
    }
    json_object_set_new_nocheck(res, "angle_source_frame_deg",
                                angle_or_null(c, d.angle_source, 180 / MECH_PI));
    json_object_set_new_nocheck(res, "angle_observer_frame_deg",
                                angle_or_null(c, d.angle_observer, 180 / MECH_PI));
    json_object_set_new_nocheck(res, "angle_source_frame_rad", angle_or_null(c, d.angle_source, 1));
    json_object_set_new_nocheck(res, "angle_observer_frame_rad",
                                angle_or_null(c, d.angle_observer, 1));
    json_object_set_new_nocheck(res, "direction_source_frame", api_vec3(c, d.direction_source));
    json_object_set_new_nocheck(res, "direction_observer_frame", api_vec3(c, d.direction_observer));

    json_t *rel = json_object();
    json_object_set_new_nocheck(rel, "gamma", api_real(c, d.gamma));
    json_object_set_new_nocheck(rel, "gamma_minus_one", api_real(c, d.gamma_minus_one));
    json_object_set_new_nocheck(rel, "beta", api_real(c, d.beta));
    json_object_set_new_nocheck(rel, "rapidity", api_real(c, d.rapidity));
    json_object_set_new_nocheck(rel, "one_minus_beta", api_real(c, d.one_minus_beta));
    json_object_set_new_nocheck(rel, "beta_gamma", api_real(c, d.beta_gamma));
    json_object_set_new_nocheck(rel, "observer_beta_in_source_frame",
                                api_vec3(c, d.observer_beta_in_source));
    json_object_set_new_nocheck(rel, "source_beta_in_observer_frame",
                                api_vec3(c, d.source_beta_in_observer));
    json_object_set_new_nocheck(res, "relative_velocity", rel);
    if (sv) {
        json_t *o = json_object();
        api_velocity_describe(c, &src, o);
        json_object_set_new_nocheck(res, "source_velocity", o);
    }
    if (ov) {
        json_t *o = json_object();
        api_velocity_describe(c, &obs, o);
        json_object_set_new_nocheck(res, "observer_velocity", o);
    }
    if (!res || !rel) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}

/* ======================= POST /v1/relativity/fields ======================== */

static json_t *invariants_json(struct api_call *c, const struct mech_em_invariants *v)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "E2_minus_B2", api_real(c, v->e2_minus_b2));
    json_object_set_new_nocheck(o, "E_dot_B", api_real(c, v->e_dot_b));
    return o;
}

json_t *api_op_relativity_fields(struct api_call *c, const json_t *body)
{
    struct mech_boost b;
    if (!api_velocity_parse(c, json_object_get(body, "velocity"), "/velocity", &b)) return NULL;
    const char *units = api_string_of(body, "units");
    const int si = !strcmp(units, "si");
    const struct mech_vec3 e = api_vec3_member(body, "E", mech_vec3_make(0, 0, 0));
    const struct mech_vec3 bf = api_vec3_member(body, "B", mech_vec3_make(0, 0, 0));
    struct mech_em_boosted r;
    struct mech_error err;
    mech_error_clear(&err);
    enum mech_status st =
        mech_em_fields_boost(&b, e, bf, si ? MECH_EM_SI : MECH_EM_HEAVISIDE_LORENTZ, &r, &err);
    if (st != MECH_OK) return api_call_fail_core(c, st, &err, "");

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "units", json_string(si ? "si" : "heaviside_lorentz"));
    json_object_set_new(
        res, "convention",
        json_string(si ? "passive boost into the frame moving with velocity v = beta c: "
                         "E'par = Epar, B'par = Bpar, E'perp = gamma (E + v x B)perp, "
                         "B'perp = gamma (B - v x E / c^2)perp; E in V/m, B in T"
                       : "passive boost into the frame moving with velocity beta (c = 1): "
                         "E'par = Epar, B'par = Bpar, E'perp = gamma (E + beta x B)perp, "
                         "B'perp = gamma (B - beta x E)perp"));
    json_object_set_new_nocheck(res, "E", api_vec3(c, r.e));
    json_object_set_new_nocheck(res, "B", api_vec3(c, r.b));
    api_velocity_describe(c, &b, res);
    json_object_set_new_nocheck(res, "invariants_before", invariants_json(c, &r.before));
    json_object_set_new_nocheck(res, "invariants_after", invariants_json(c, &r.after));
    json_object_set_new_nocheck(res, "field_scale_squared", api_real(c, r.scale2));
    json_t *diff = json_object();
    const double s2 = r.scale2 > 0 ? r.scale2 : 1.0;
    const double k = si ? MECH_EM_C : 1.0;
    json_object_set_new_nocheck(diff, "E2_minus_B2",
                                api_real(c, fabs(r.after.e2_minus_b2 - r.before.e2_minus_b2) / s2));
    json_object_set_new_nocheck(diff, "E_dot_B",
                                api_real(c, fabs(r.after.e_dot_b - r.before.e_dot_b) * k / s2));
    json_object_set_new_nocheck(res, "invariants_difference", diff);
    if (!res || !diff) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}

