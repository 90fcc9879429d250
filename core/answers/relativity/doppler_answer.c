/* doppler_answer.c — one POST /v1/relativity/doppler answer (notes §3.14):
 * mech_doppler_compute for the factor D and the aberration, then the sense of
 * the shift, z = λ_obs/λ_emit − 1 = 1/D − 1 = −(D − 1)/D (from the precise
 * D − 1, so 1 m/s keeps its digits), and the light: ν_obs = D ν_emit,
 * λ = c/ν with c exact. The physics is in doppler.c; this is the
 * orchestration, so the handler only parses and encodes. */
#include "mech/answers/relativity/doppler_answer.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"

const char *mech_doppler_shift_name(enum mech_doppler_shift s)
{
    return s == MECH_DOPPLER_SHIFT_BLUE ? "blue" : s == MECH_DOPPLER_SHIFT_RED ? "red" : "none";
}

/* A light quantity is kept when it is finite and at least the smallest
 * normal double (a subnormal frequency has lost its digits). */
static int usable(double x)
{
    return isfinite(x) && x >= DBL_MIN;
}

/* Emitted and observed light from the given frequency or wavelength. */
static enum mech_status light(const struct mech_doppler_request *q, struct mech_doppler_answer *a,
                              struct mech_error *err)
{
    const int by_f = q->light == MECH_DOPPLER_LIGHT_FREQUENCY;
    if (by_f) {
        a->frequency_emitted = q->light_value;
        a->wavelength_emitted = MECH_C / a->frequency_emitted;
    } else {
        a->wavelength_emitted = q->light_value;
        a->frequency_emitted = MECH_C / a->wavelength_emitted;
    }
    a->frequency_observed = a->d.factor * a->frequency_emitted;
    a->wavelength_observed = a->wavelength_emitted / a->d.factor;
    if (!(usable(a->frequency_observed) && usable(a->wavelength_observed) &&
          isfinite(a->wavelength_emitted) && isfinite(a->frequency_emitted) &&
          a->wavelength_emitted > 0 && a->frequency_emitted > 0))
        return mech_error_set(err, MECH_ENUMERIC, by_f ? "frequency" : "wavelength",
                              "the observed light (Doppler factor %.6g) is outside the range of "
                              "double precision; use a less extreme frequency or wavelength",
                              a->d.factor);
    a->wavelength_shift = a->wavelength_emitted * a->redshift_z;
    a->frequency_shift = a->frequency_emitted * a->d.factor_minus_one;
    a->has_light = 1;
    return MECH_OK;
}

enum mech_status mech_doppler_answer(const struct mech_doppler_request *req,
                                     struct mech_doppler_answer *out, struct mech_error *err)
{
    if (!req || !out || req->light < MECH_DOPPLER_LIGHT_NONE ||
        req->light > MECH_DOPPLER_LIGHT_WAVELENGTH)
        return mech_error_set(err, MECH_EINVAL, NULL, "NULL request or answer, or unknown light");
    struct mech_doppler_answer a;
    memset(&a, 0, sizeof a);
    enum mech_status st =
        mech_doppler_compute(req->source, req->observer, req->direction, req->frame, &a.d, err);
    if (st != MECH_OK) {
        if (err && !strcmp(err->param, "direction"))
            snprintf(err->param, sizeof err->param, "%s",
                     req->frame == MECH_DOPPLER_SOURCE_FRAME ? "emission_direction"
                                                             : "arrival_direction");
        return st;
    }
    a.shift = a.d.factor_minus_one > 0   ? MECH_DOPPLER_SHIFT_BLUE
              : a.d.factor_minus_one < 0 ? MECH_DOPPLER_SHIFT_RED
                                         : MECH_DOPPLER_SHIFT_NONE;
    a.redshift_z = -a.d.factor_minus_one / a.d.factor;
    if (req->light != MECH_DOPPLER_LIGHT_NONE && (st = light(req, &a, err)) != MECH_OK) return st;
    if (!isfinite(a.redshift_z) || !isfinite(a.wavelength_shift) || !isfinite(a.frequency_shift))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the result is not finite for this input (overflow or a singularity)");
    *out = a;
    return MECH_OK;
}
