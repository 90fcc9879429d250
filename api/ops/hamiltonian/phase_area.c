/* phase_area.c — POST /v1/hamiltonian/phase-area: the
 * phase-space area enclosed by an energy contour of a 1-D system and the
 * period as its energy derivative (notes "Phase Space and Liouville's
 * Theorem"). JSON <-> core only; the physics is core/hamiltonian/phase_area.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/hamiltonian/phase_area.h"


json_t *api_op_hamiltonian_phase_area(struct api_call *c, const json_t *body)
{
    const int pend = !strcmp(api_string(body, "system", "oscillator"), "pendulum");
    const char *own = pend ? "length" : "omega", *other = pend ? "omega" : "length";
    char ptr[32];
    if (json_object_get(body, other) || (!pend && json_object_get(body, "g"))) {
        snprintf(ptr, sizeof ptr, "/%s", json_object_get(body, other) ? other : "g");
        api_call_invalid(c, ptr, "%s does not belong to the %s", ptr + 1,
                         pend ? "pendulum" : "oscillator");
        return NULL;
    }
    if (!json_object_get(body, own)) {
        snprintf(ptr, sizeof ptr, "/%s", own);
        api_call_invalid(c, ptr, "the %s needs %s", pend ? "pendulum" : "oscillator", own);
        return NULL;
    }
    const double m = api_number_of(body, "mass"), en = api_number(body, "energy", 0);
    struct mech_phase_area p;
    struct mech_error e;
    mech_error_clear(&e);
    double w0 = 0;
    enum mech_status st;
    if (pend) {
        const double l = api_number(body, "length", 1), g = api_number(body, "g", 9.80665);
        w0 = sqrt(g / l);
        st = mech_phase_area_pendulum(m, l, g, en, &p, &e);
    } else {
        st = mech_phase_area_oscillator(m, api_number(body, "omega", 1), en, &p, &e);
    }
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    static const char *const motions[] = {"libration", "rotation", "separatrix"};
    json_t *out = json_object();
    if (!out) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    const int fin = isfinite(p.period);
    json_object_set_new_nocheck(out, "motion", json_string(motions[p.motion]));
    json_object_set_new_nocheck(out, "area", api_real(c, p.area));
    json_object_set_new_nocheck(out, "action", api_real(c, p.area / (2 * MECH_PI)));
    json_object_set_new_nocheck(out, "period", fin ? api_real(c, p.period) : json_null());
    json_object_set_new_nocheck(out, "angular_frequency",
                                fin ? api_real(c, 2 * MECH_PI / p.period) : json_real(0.0));
    json_object_set_new_nocheck(out, "amplitude",
                                isnan(p.amplitude) ? json_null() : api_real(c, p.amplitude));
    if (pend) {
        json_object_set_new_nocheck(out, "modulus", api_real(c, p.modulus));
        json_t *sa = json_object();
        json_object_set_new_nocheck(sa, "area", api_real(c, 2 * MECH_PI * en / w0));
        json_object_set_new_nocheck(sa, "period", api_real(c, 2 * MECH_PI / w0));
        json_object_set_new_nocheck(
            sa, "label",
            json_string("approximation: the harmonic (small-amplitude) pendulum, A = 2 pi E/"
                        "omega0, T = 2 pi/omega0, beside the exact area and period"));
        json_object_set_new_nocheck(out, "small_amplitude", sa);
    }
    return out;
}

