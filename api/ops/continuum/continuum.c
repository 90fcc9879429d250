/* continuum.c — the continuum chapter (the notes' last chapter is only a
 * heading; this serves its standard content at the course's level):
 *   POST /v1/continuum/string  transverse waves on a string with fixed ends
 *   POST /v1/continuum/rod     axial and bending waves of a rod / beam
 * JSON <-> core only; the physics is core/continuum/continuum_waves.c, and
 * the rod's answer is one call, mech_rod_answer() (core/answers/continuum/rod_answer.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/continuum/continuum_waves.h"
#include "mech/answers/continuum/rod_answer.h"


static json_t *mode_json(struct api_call *c, int n, const struct mech_wave_mode *m)
{
    json_t *o = json_object();
    if (!o) return NULL;
    json_object_set_new_nocheck(o, "n", json_integer(n));
    json_object_set_new_nocheck(o, "wavenumber", api_real(c, m->wavenumber));
    json_object_set_new_nocheck(o, "wavelength", api_real(c, m->wavelength));
    json_object_set_new_nocheck(o, "frequency", api_real(c, m->frequency));
    json_object_set_new_nocheck(o, "angular_frequency", api_real(c, m->angular_frequency));
    return o;
}

json_t *api_op_continuum_string(struct api_call *c, const json_t *body)
{
    const json_t *mu_j = json_object_get(body, "linear_density"), *m_j = json_object_get(body, "mass");
    if (mu_j && m_j) {
        api_call_invalid(c, "/mass", "give linear_density or mass, not both");
        return NULL;
    }
    if (!mu_j && !m_j) {
        api_call_invalid(c, "", "give the string's linear_density (kg/m) or its mass (kg)");
        return NULL;
    }
    const double L = api_number_of(body, "length"), T = api_number_of(body, "tension");
    const double mu = mu_j ? json_number_value(mu_j) : json_number_value(m_j) / L;
    const int nm = (int)api_number_of(body, "modes");
    double cw;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_string_wave_speed(T, mu, &cw, &e);
    if (st != MECH_OK) {
        if (!mu_j && !strcmp(e.param, "linear_density")) snprintf(e.param, sizeof e.param, "mass");
        return api_call_fail_core(c, st, &e, "");
    }
    json_t *out = json_object(), *modes = json_array();
    if (!out || !modes) {
        json_decref(out);
        json_decref(modes);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    json_object_set_new_nocheck(out, "linear_density", api_real(c, mu));
    json_object_set_new_nocheck(out, "wave_speed", api_real(c, cw));
    struct mech_wave_mode m1 = mech_wave_mode_nondispersive(cw, L, MECH_PI);
    json_object_set_new_nocheck(out, "fundamental_frequency", api_real(c, m1.frequency));
    for (int n = 1; n <= nm; n++) {
        struct mech_wave_mode m = mech_wave_mode_nondispersive(cw, L, n * MECH_PI);
        json_array_append_new(modes, mode_json(c, n, &m));
    }
    json_object_set_new_nocheck(out, "modes", modes);
    return out;
}

/* ---- rods --------------------------------------------------------------------- */

/* The rod request as the core takes it (schema-validated: the section is
 * one of its three shapes). */
static void rod_read(const json_t *body, struct mech_rod_request *q)
{
    q->length = api_number_of(body, "length");
    q->density = api_number_of(body, "density");
    q->youngs_modulus = api_number_of(body, "youngs_modulus");
    const json_t *sec = json_object_get(body, "section");
    if (json_object_get(sec, "radius")) {
        q->section = MECH_ROD_SECTION_CIRCLE;
        q->radius = api_number_of(sec, "radius");
    } else if (json_object_get(sec, "width")) {
        q->section = MECH_ROD_SECTION_RECTANGLE;
        q->width = api_number_of(sec, "width");
        q->height = api_number_of(sec, "height");
    } else {
        q->section = MECH_ROD_SECTION_GIVEN;
        q->area = api_number_of(sec, "area");
        q->second_moment = api_number_of(sec, "second_moment");
        const json_t *jj = json_object_get(sec, "polar_moment"),
                     *kj = json_object_get(sec, "torsion_constant");
        q->has_polar_moment = jj != NULL;
        q->polar_moment = json_number_value(jj);
        q->has_torsion_constant = kj != NULL; /* absent: K = J (a circle or tube) */
        q->torsion_constant = json_number_value(kj);
    }
    q->ends = api_string_of(body, "ends");
    q->modes = (int)api_number_of(body, "modes");
    const json_t *gj = json_object_get(body, "shear_modulus"), *nj = json_object_get(body, "poisson_ratio");
    q->has_shear_modulus = gj != NULL;
    q->shear_modulus = json_number_value(gj);
    q->has_poisson_ratio = nj != NULL;
    q->poisson_ratio = json_number_value(nj);
}

/* "bending": a = sqrt(EI/(rho A)) and the modes with their roots. */
static json_t *rod_bending(struct api_call *c, const struct mech_rod_answer *a)
{
    json_t *ben = json_object(), *bm = json_array();
    for (int n = 1; n <= a->n_modes; n++) {
        const struct mech_rod_mode *m = &a->modes[n - 1];
        json_t *o = mode_json(c, n, &m->bending);
        json_object_set_new_nocheck(o, "beta_L", api_real(c, m->beta_L));
        json_object_set_new_nocheck(o, "sigma", api_real(c, m->sigma));
        json_object_set_new_nocheck(o, "phase_speed", api_real(c, m->bending.phase_speed));
        json_object_set_new_nocheck(o, "group_speed", api_real(c, m->bending.group_speed));
        json_object_set_new_nocheck(o, "k_radius_of_gyration", api_real(c, m->k_radius_of_gyration));
        json_array_append_new(bm, o);
    }
    json_object_set_new_nocheck(ben, "stiffness_ratio", api_real(c, a->stiffness_ratio));
    json_object_set_new_nocheck(ben, "modes", bm);
    return ben;
}

/* "longitudinal" (torsional = 0) or "torsional" (1): the wave speed and modes. */
static json_t *rod_axial(struct api_call *c, const struct mech_rod_answer *a, int torsional)
{
    json_t *o = json_object(), *modes = json_array();
    for (int n = 1; n <= a->n_modes; n++)
        json_array_append_new(modes, mode_json(c, n, torsional ? &a->modes[n - 1].torsional
                                                               : &a->modes[n - 1].longitudinal));
    if (torsional) {
        json_object_set_new_nocheck(o, "shear_modulus", api_real(c, a->torsion.shear_modulus));
        json_object_set_new_nocheck(o, "polar_moment", api_real(c, a->torsion.polar_moment));
        json_object_set_new_nocheck(o, "torsion_constant", api_real(c, a->torsion.torsion_constant));
    }
    json_object_set_new_nocheck(o, "wave_speed", api_real(c, torsional ? a->torsion.wave_speed
                                                                       : a->longitudinal_speed));
    json_object_set_new_nocheck(o, "modes", modes);
    return o;
}

/* "notes": what the answer leaves out, in the order the flags are met. */
static json_t *rod_notes(const struct mech_rod_answer *a)
{
    json_t *notes = json_array();
    if (a->torsion_needs_polar_moment)
        json_array_append_new(notes, json_string(
            "torsional waves need the section's polar_moment (and torsion_constant) when it "
            "is given by area and second_moment: torsional is null"));
    if (a->thick)
        json_array_append_new(notes, json_string(
            "some bending modes have k r_g > 0.1: their wavelength is not long against the "
            "section, so Euler-Bernoulli frequencies are too high by about (k r_g)^2 "
            "(shear and rotary inertia, Timoshenko theory, not modelled)"));
    if (a->ends == MECH_ROD_FREE_FREE)
        json_array_append_new(notes, json_string(
            "free-free: the rigid-body modes (one translation along the rod, two in bending) "
            "have omega = 0 and are not listed"));
    return notes;
}

json_t *api_op_continuum_rod(struct api_call *c, const json_t *body)
{
    struct mech_rod_request q = {0};
    rod_read(body, &q);
    struct mech_rod_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rod_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object();
    json_object_set_new_nocheck(out, "area", api_real(c, a.area));
    json_object_set_new_nocheck(out, "second_moment", api_real(c, a.second_moment));
    json_object_set_new_nocheck(out, "radius_of_gyration", api_real(c, a.radius_of_gyration));
    json_object_set_new_nocheck(out, "longitudinal", rod_axial(c, &a, 0));
    json_object_set_new_nocheck(out, "bending", rod_bending(c, &a));
    json_object_set_new_nocheck(out, "torsional", a.has_torsion ? rod_axial(c, &a, 1) : json_null());
    json_object_set_new_nocheck(out, "notes", rod_notes(&a));
    mech_rod_answer_free(&a);
    return out;
}
