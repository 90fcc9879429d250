/* doppler.c — POST /v1/relativity/doppler: Doppler shift and aberration of
 * light under relative motion (notes §3.14). The answer is one call of
 * mech_doppler_answer (core/answers/relativity/doppler_answer.c); velocities use the
 * shared input of api/ops/relativity/velocity_request.h. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/answers/relativity/doppler_answer.h"
#include "ops/relativity/velocity_request.h"

static json_t *angle_or_null(struct api_call *c, double a, double scale)
{
    return isnan(a) ? json_null() : api_real(c, a * scale);
}

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

/* The one-of rules the schema cannot state: one direction, at most one of
 * frequency and wavelength. Returns 0 when the request is invalid. */
static int check_choices(struct api_call *c, const json_t *body)
{
    const int emit = json_object_get(body, "emission_direction") != NULL;
    const int arrive = json_object_get(body, "arrival_direction") != NULL;
    const int dir = json_object_get(body, "direction") != NULL;
    if (emit + arrive + dir > 1)
        api_call_invalid(c, dir ? "/direction" : "/arrival_direction",
                         "give the light's direction once: direction {vector, frame}, or the "
                         "older emission_direction (source frame) or arrival_direction (observer "
                         "frame), not two of them");
    else if (!emit && !arrive && !dir)
        /* the pointer of the field this error named before direction existed */
        api_call_invalid(c, "/emission_direction",
                         "give the light's direction: direction {vector, frame: source or "
                         "observer} (or emission_direction, arrival_direction)");
    if (json_object_get(body, "frequency") && json_object_get(body, "wavelength"))
        api_call_invalid(c, "/wavelength",
                         "give the emitted light as a frequency or as a wavelength, not both");
    return c->problem == API_PROBLEM_NONE;
}

static json_t *relative_json(struct api_call *c, const struct mech_doppler *d)
{
    json_t *rel = json_object();
    set(rel, "gamma", api_real(c, d->gamma));
    set(rel, "gamma_minus_one", api_real(c, d->gamma_minus_one));
    set(rel, "beta", api_real(c, d->beta));
    set(rel, "rapidity", api_real(c, d->rapidity));
    set(rel, "one_minus_beta", api_real(c, d->one_minus_beta));
    set(rel, "beta_gamma", api_real(c, d->beta_gamma));
    set(rel, "gamma_one_minus_beta", api_real(c, exp(-d->rapidity)));
    set(rel, "gamma_one_plus_beta", api_real(c, exp(d->rapidity)));
    set(rel, "observer_beta_in_source_frame", api_vec3(c, d->observer_beta_in_source));
    set(rel, "source_beta_in_observer_frame", api_vec3(c, d->source_beta_in_observer));
    return rel;
}

static void light_json(struct api_call *c, json_t *res, const struct mech_doppler_answer *a)
{
    set(res, "frequency_emitted", api_real(c, a->frequency_emitted));
    set(res, "wavelength_emitted", api_real(c, a->wavelength_emitted));
    set(res, "frequency_observed", api_real(c, a->frequency_observed));
    set(res, "wavelength_observed", api_real(c, a->wavelength_observed));
    set(res, "wavelength_shift", api_real(c, a->wavelength_shift));
    set(res, "frequency_shift", api_real(c, a->frequency_shift));
}

static void velocity_json(struct api_call *c, json_t *res, const char *key,
                          const struct mech_boost *b)
{
    if (!b) return;
    json_t *o = json_object();
    api_velocity_describe(c, b, o);
    set(res, key, o);
}

json_t *api_op_relativity_doppler(struct api_call *c, const json_t *body)
{
    const json_t *emit = json_object_get(body, "emission_direction");
    const json_t *dir = json_object_get(body, "direction");
    const int source_frame = dir ? !strcmp(api_string_of(dir, "frame"), "source") : emit != NULL;
    const json_t *fj = json_object_get(body, "frequency"), *lj = json_object_get(body, "wavelength");
    const json_t *sv = json_object_get(body, "source_velocity");
    const json_t *ov = json_object_get(body, "observer_velocity");
    struct mech_boost src, obs;
    int ok = check_choices(c, body);
    if (sv && !api_velocity_parse(c, sv, "/source_velocity", &src)) ok = 0;
    if (ov && !api_velocity_parse(c, ov, "/observer_velocity", &obs)) ok = 0;
    if (!ok) return NULL;
    const struct mech_doppler_request q = {
        .source = sv ? &src : NULL,
        .observer = ov ? &obs : NULL,
        .direction = api_vec3_of(dir    ? json_object_get(dir, "vector")
                                 : emit ? emit
                                        : json_object_get(body, "arrival_direction")),
        .frame = source_frame ? MECH_DOPPLER_SOURCE_FRAME : MECH_DOPPLER_OBSERVER_FRAME,
        .light = fj ? MECH_DOPPLER_LIGHT_FREQUENCY
                 : lj ? MECH_DOPPLER_LIGHT_WAVELENGTH
                      : MECH_DOPPLER_LIGHT_NONE,
        .light_value = json_number_value(fj ? fj : lj)};
    struct mech_doppler_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_doppler_answer(&q, &a, &e);
    if (st != MECH_OK) {
        if (dir && (!strcmp(e.param, "emission_direction") || !strcmp(e.param, "arrival_direction")))
            strcpy(e.param, "direction/vector");
        return api_call_fail_core(c, st, &e, "");
    }

    const struct mech_doppler *d = &a.d;
    json_t *res = json_object();
    set(res, "case", json_string(mech_doppler_case_name(d->kind)));
    set(res, "doppler_factor", api_real(c, d->factor));
    set(res, "doppler_factor_minus_one", api_real(c, d->factor_minus_one));
    set(res, "doppler_factor_inverse", api_real(c, 1 / d->factor));
    set(res, "direction_frame", json_string(source_frame ? "source" : "observer"));
    set(res, "shift", json_string(mech_doppler_shift_name(a.shift)));
    set(res, "redshift_z", api_real(c, a.redshift_z));
    if (a.has_light) light_json(c, res, &a);
    set(res, "angle_source_frame_deg", angle_or_null(c, d->angle_source, 180 / MECH_PI));
    set(res, "angle_observer_frame_deg", angle_or_null(c, d->angle_observer, 180 / MECH_PI));
    set(res, "angle_source_frame_rad", angle_or_null(c, d->angle_source, 1));
    set(res, "angle_observer_frame_rad", angle_or_null(c, d->angle_observer, 1));
    set(res, "direction_source_frame", api_vec3(c, d->direction_source));
    set(res, "direction_observer_frame", api_vec3(c, d->direction_observer));
    set(res, "relative_velocity", relative_json(c, d));
    velocity_json(c, res, "source_velocity", q.source);
    velocity_json(c, res, "observer_velocity", q.observer);
    if (!res || !json_object_get(res, "relative_velocity")) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}
