/* ep_hamiltonian_phase_area.c — POST /v1/hamiltonian/phase-area: the
 * phase-space area enclosed by an energy contour of a 1-D system and the
 * period as its energy derivative (notes "Phase Space and Liouville's
 * Theorem"). JSON <-> core only; the physics is core/phase_area.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "endpoint.h"
#include "mech/phase_area.h"

static const double PI = 3.14159265358979323846;

/* clang-format off */
#define PA_POS(desc)                                                                               \
    "{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,\"description\":\"" desc "\"}"
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"system\",\"mass\","
    "\"energy\"],\"properties\":{"
    "\"system\":{\"enum\":[\"oscillator\",\"pendulum\"],\"description\":\"oscillator: H = "
    "p^2/2m + m omega^2 q^2/2; pendulum: H = p^2/(2 m l^2) + m g l (1 - cos theta)\"},"
    "\"mass\":" PA_POS("mass m, kg") ","
    "\"omega\":" PA_POS("oscillator's angular frequency, rad/s (oscillator only)") ","
    "\"length\":" PA_POS("pendulum length l, m (pendulum only)") ","
    "\"g\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"
    "\"description\":\"gravity, m/s^2 (pendulum only; absent: 9.80665, not a schema default "
    "because an oscillator must not receive it)\"},"
    "\"energy\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e30,\"description\":\"energy "
    "above the minimum of the potential, J\"}}}";
/* clang-format on */

static const char description[] =
    "The phase-space area A(E) = closed integral of p dq enclosed by the energy contour H = E "
    "of a one-dimensional system (notes, Hamiltonian mechanics: phase space and Liouville's "
    "theorem), the action J = A/(2 pi) and the period as its energy derivative T = dA/dE. "
    "oscillator (mass, omega): A = 2 pi E/omega, T = 2 pi/omega. pendulum (mass, length, g): "
    "with omega0 = sqrt(g/l) and E = 2 m g l k^2, a libration (k < 1, amplitude 2 asin k) "
    "encloses A = 16 m l^2 omega0 [E(k) - (1 - k^2) K(k)] with T = 4 K(k)/omega0; a rotation "
    "(k > 1) bounds A = 8 m l^2 omega0 k E(1/k) between its p > 0 branch and p = 0 over one "
    "turn, with T = 2 K(1/k)/(k omega0) per turn; the separatrix (k = 1) encloses 16 m l^2 "
    "omega0 and its period is infinite (null). K, E: complete elliptic integrals (GSL; for k^2 "
    "< 1/2 the libration area is summed as a series, exact to round-off at tiny amplitudes). "
    "For the pendulum, small_amplitude gives the harmonic approximation 2 pi E/omega0 and "
    "2 pi/omega0, labelled, beside the exact values.";

static const char example[] =
    "{\"system\": \"pendulum\", \"mass\": 1, \"length\": 1, \"energy\": 5}";

static json_t *phase_area_op(struct api_call *c, const json_t *body)
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
    const double m = api_number(body, "mass", 1), en = api_number(body, "energy", 0);
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
    json_object_set_new_nocheck(out, "action", api_real(c, p.area / (2 * PI)));
    json_object_set_new_nocheck(out, "period", fin ? api_real(c, p.period) : json_null());
    json_object_set_new_nocheck(out, "angular_frequency",
                                fin ? api_real(c, 2 * PI / p.period) : json_real(0.0));
    json_object_set_new_nocheck(out, "amplitude",
                                isnan(p.amplitude) ? json_null() : api_real(c, p.amplitude));
    if (pend) {
        json_object_set_new_nocheck(out, "modulus", api_real(c, p.modulus));
        json_t *sa = json_object();
        json_object_set_new_nocheck(sa, "area", api_real(c, 2 * PI * en / w0));
        json_object_set_new_nocheck(sa, "period", api_real(c, 2 * PI / w0));
        json_object_set_new_nocheck(
            sa, "label",
            json_string("approximation: the harmonic (small-amplitude) pendulum, A = 2 pi E/"
                        "omega0, T = 2 pi/omega0, beside the exact area and period"));
        json_object_set_new_nocheck(out, "small_amplitude", sa);
    }
    return out;
}

const struct api_route api_route_hamiltonian_phase_area = {
    "POST",
    "/v1/hamiltonian/phase-area",
    "Phase-space area enclosed by an energy contour of the oscillator or the pendulum, the "
    "action, and the period as dA/dE",
    description,
    schema,
    example,
    phase_area_op,
    0,
    1, /* quick */
};
