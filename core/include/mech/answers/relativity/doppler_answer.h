/* mech/answers/relativity/doppler_answer.h — one POST /v1/relativity/doppler answer: the
 * Doppler factor and aberration of mech_doppler_compute (mech/relativity/doppler.h),
 * the shift's sense and redshift z, and, when the emitted light is given as
 * a frequency or a wavelength, the emitted and observed light with both
 * shifts. The API's handler parses, calls mech_doppler_answer once and
 * encodes. SI units (Hz, m; c = MECH_C exact). Pure; thread-safe; no
 * allocation. */
#ifndef MECH_DOPPLER_ANSWER_H
#define MECH_DOPPLER_ANSWER_H

#include "mech/relativity/doppler.h"

/* How the emitted light is given. */
enum mech_doppler_light {
    MECH_DOPPLER_LIGHT_NONE = 0,  /* not given: factor, z and angles only */
    MECH_DOPPLER_LIGHT_FREQUENCY, /* light_value is ν_emit (Hz) */
    MECH_DOPPLER_LIGHT_WAVELENGTH /* light_value is λ_emit (m) */
};

struct mech_doppler_request {
    const struct mech_boost *source;   /* velocity relative to the lab; NULL: at rest; borrowed */
    const struct mech_boost *observer; /* the same for the observer */
    struct mech_vec3 direction;        /* the light's propagation direction, nonzero, finite */
    enum mech_doppler_frame frame;     /* the frame direction is given in */
    enum mech_doppler_light light;
    double light_value; /* Hz or m, finite, > 0 (unused for LIGHT_NONE) */
};

/* The sense of the shift: the sign of D − 1. */
enum mech_doppler_shift {
    MECH_DOPPLER_SHIFT_NONE = 0,
    MECH_DOPPLER_SHIFT_BLUE = 1, /* D > 1 */
    MECH_DOPPLER_SHIFT_RED = -1  /* D < 1 */
};

struct mech_doppler_answer {
    struct mech_doppler d;
    enum mech_doppler_shift shift;
    double redshift_z; /* λ_obs/λ_emit − 1 = −(D − 1)/D, from the precise D − 1 */
    int has_light;     /* the request gave the light; the members below are set */
    double frequency_emitted, wavelength_emitted;   /* Hz, m (λ = c/ν) */
    double frequency_observed, wavelength_observed; /* D ν_emit, λ_emit / D */
    double wavelength_shift;                        /* λ_emit z */
    double frequency_shift;                         /* ν_emit (D − 1) */
};

/* Answer `req`. Statuses (param is the request's field as a JSON-pointer path
 * without the leading '/'):
 *   MECH_EINVAL (no param) for a NULL pointer or an unknown light kind;
 *   MECH_EINVAL "emission_direction" (source frame) or "arrival_direction"
 *     (observer frame): the direction is zero or not finite;
 *   MECH_ENUMERIC "frequency" or "wavelength": the emitted or observed light
 *     is not a finite normal positive double (the text gives D), or the
 *     given value is not finite and > 0;
 *   MECH_ENUMERIC (no param) when a number of the answer is not finite, the
 *     text "the result is not finite for this input (overflow or a
 *     singularity)".
 * out is written only on success. err may be NULL. */
enum mech_status mech_doppler_answer(const struct mech_doppler_request *req,
                                     struct mech_doppler_answer *out, struct mech_error *err);

/* Stable name of a shift: "blue", "red" or "none". Never NULL. */
const char *mech_doppler_shift_name(enum mech_doppler_shift s);

#endif
