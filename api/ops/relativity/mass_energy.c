/* mass_energy.c — POST /v1/relativity/mass-energy: E = m c^2
 * either way, and the rest mass a luminosity carries away, L / c^2 (the Sun's
 * mass loss from its luminosity or from the solar constant at 1 AU). What it
 * computes is one call, mech_mass_energy() (core/relativity/mass_energy.c);
 * this file reads the request and encodes the answer. */
#include <stdio.h>

#include "run/endpoint.h"
#include "mech/relativity/mass_energy.h"

static const struct {
    const char *key;
    enum mech_mass_energy_form form;
} forms[] = {
    {"mass", MECH_MASS_ENERGY_MASS},
    {"energy", MECH_MASS_ENERGY_ENERGY},
    {"luminosity", MECH_MASS_ENERGY_LUMINOSITY},
    {"flux", MECH_MASS_ENERGY_FLUX},
};
#define N_FORMS (sizeof forms / sizeof forms[0])

/* Exactly one of the forms (a flux with its distance); 0 after recording
 * the error. */
static int read_request(struct api_call *c, const json_t *body, struct mech_mass_energy_request *q)
{
    size_t which = N_FORMS;
    for (size_t i = 0; i < N_FORMS; i++) {
        if (!json_object_get(body, forms[i].key)) continue;
        if (which != N_FORMS) {
            char ptr[32];
            snprintf(ptr, sizeof ptr, "/%s", forms[i].key);
            api_call_invalid(c, ptr, "give exactly one of mass, energy, luminosity and flux (%s "
                                     "was given too)", forms[which].key);
            return 0;
        }
        which = i;
    }
    if (which == N_FORMS) {
        api_call_invalid(c, "", "give one of mass (kg), energy (J), luminosity (W) or flux "
                                "(W/m^2) with distance (m)");
        return 0;
    }
    const int flux = forms[which].form == MECH_MASS_ENERGY_FLUX;
    if (flux != (json_object_get(body, "distance") != NULL)) {
        api_call_invalid(c, "/distance", flux ? "a flux needs the distance it was measured at"
                                              : "distance goes with a flux only");
        return 0;
    }
    q->form = forms[which].form;
    q->value = api_number_of(body, forms[which].key);
    q->distance = flux ? api_number_of(body, "distance") : 0.0;
    q->has_duration = json_object_get(body, "duration") != NULL;
    q->duration = q->has_duration ? api_number_of(body, "duration") : 0.0;
    return 1;
}

json_t *api_op_relativity_mass_energy(struct api_call *c, const json_t *body)
{
    struct mech_mass_energy_request q = {0};
    if (!read_request(c, body, &q)) return NULL;
    struct mech_mass_energy_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_mass_energy(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object();
    if (!a.rate) {
        json_object_set_new_nocheck(out, "mass", api_real(c, a.mass));
        json_object_set_new_nocheck(out, "energy", api_real(c, a.energy));
        json_object_set_new_nocheck(out, "formula", json_string("E = m c^2"));
        return out;
    }
    json_object_set_new_nocheck(out, "luminosity", api_real(c, a.luminosity));
    json_object_set_new_nocheck(out, "mass_loss_rate", api_real(c, a.mass_loss_rate));
    json_object_set_new_nocheck(out, "mass_loss_per_year", api_real(c, a.mass_loss_per_year));
    if (q.has_duration) json_object_set_new_nocheck(out, "mass_lost", api_real(c, a.mass_lost));
    json_object_set_new_nocheck(
        out, "formula",
        json_string(q.form == MECH_MASS_ENERGY_FLUX
                        ? "L = 4 pi d^2 F (isotropic emission), dm/dt = L / c^2"
                        : "dm/dt = L / c^2"));
    return out;
}
