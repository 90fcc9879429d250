/* ep_continuum.c — the continuum chapter (the notes' last chapter is only a
 * heading; this serves its standard content at the course's level):
 *   POST /v1/continuum/string  transverse waves on a string with fixed ends
 *   POST /v1/continuum/rod     axial and bending waves of a rod / beam
 * JSON <-> core only; the physics is core/continuum_waves.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "endpoint.h"
#include "mech/constants.h"
#include "mech/continuum_waves.h"
#include "mech/torsion.h"


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
    const double L = api_number(body, "length", 1), T = api_number(body, "tension", 1);
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

static int ends_of(const char *s, enum mech_rod_ends *e)
{
    static const struct { const char *name; enum mech_rod_ends v; } t[] = {
        {"free-free", MECH_ROD_FREE_FREE},
        {"clamped-clamped", MECH_ROD_CLAMPED_CLAMPED},
        {"clamped-free", MECH_ROD_CLAMPED_FREE},
        {"pinned-pinned", MECH_ROD_PINNED_PINNED},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        if (!strcmp(s, t[i].name)) {
            *e = t[i].v;
            return 1;
        }
    return 0;
}

/* The torsional block, or NULL: with no shear modulus (not asked for), with a
 * section given by area alone (a note says what is missing), or after
 * recording an error (c->problem set). */
static json_t *torsional(struct api_call *c, const json_t *body, const json_t *sec, double E,
                         double rho, double L, enum mech_rod_ends ends, int nm, json_t *notes)
{
    const json_t *gj = json_object_get(body, "shear_modulus"), *nj = json_object_get(body, "poisson_ratio");
    if (gj && nj) {
        api_call_invalid(c, "/poisson_ratio", "give shear_modulus or poisson_ratio, not both");
        return NULL;
    }
    struct mech_error e;
    mech_error_clear(&e);
    double g = 0, j = 0, k = 0;
    enum mech_status st = MECH_OK;
    if (gj)
        g = json_number_value(gj);
    else if (nj)
        st = mech_shear_modulus(E, json_number_value(nj), &g, &e);
    if (st == MECH_OK && (gj || nj)) {
        if (json_object_get(sec, "radius")) {
            const double r = api_number_of(sec, "radius");
            j = k = 0.5 * MECH_PI * (r * r) * (r * r);
        } else if (json_object_get(sec, "width")) {
            st = mech_torsion_rectangle(api_number(sec, "width", 1), api_number(sec, "height", 1), &j,
                                        &k, &e);
            if (st != MECH_OK) snprintf(e.param, sizeof e.param, "section");
        } else if (json_object_get(sec, "polar_moment")) {
            j = api_number(sec, "polar_moment", 1);
            k = api_number(sec, "torsion_constant", j);
        } else {
            json_array_append_new(notes, json_string(
                "torsional waves need the section's polar_moment (and torsion_constant) when it "
                "is given by area and second_moment: torsional is null"));
            return NULL;
        }
    }
    if (st == MECH_OK && !gj && !nj) return NULL; /* not asked for: torsional is null */
    double ct = 0;
    if (st == MECH_OK) st = mech_torsional_wave_speed(g, rho, k, j, &ct, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        return NULL;
    }
    json_t *o = json_object(), *modes = json_array();
    if (!o || !modes) {
        json_decref(o), json_decref(modes);
        api_call_fail_core(c, MECH_ENOMEM, NULL, "");
        return NULL;
    }
    for (int n = 1; n <= nm; n++) {
        double kl;
        if (mech_rod_axial_mode(ends, n, &kl, NULL) != MECH_OK) break;
        struct mech_wave_mode m = mech_wave_mode_nondispersive(ct, L, kl);
        json_array_append_new(modes, mode_json(c, n, &m));
    }
    json_object_set_new_nocheck(o, "shear_modulus", api_real(c, g));
    json_object_set_new_nocheck(o, "polar_moment", api_real(c, j));
    json_object_set_new_nocheck(o, "torsion_constant", api_real(c, k));
    json_object_set_new_nocheck(o, "wave_speed", api_real(c, ct));
    json_object_set_new_nocheck(o, "modes", modes);
    return o;
}

json_t *api_op_continuum_rod(struct api_call *c, const json_t *body)
{
    const double L = api_number(body, "length", 1), rho = api_number(body, "density", 1);
    const double E = api_number(body, "youngs_modulus", 1);
    const json_t *sec = json_object_get(body, "section");
    double A, I;
    if (json_object_get(sec, "radius")) {
        const double r = api_number_of(sec, "radius");
        A = MECH_PI * r * r;
        I = 0.25 * MECH_PI * (r * r) * (r * r);
    } else if (json_object_get(sec, "width")) {
        const double b = api_number(sec, "width", 1), h = api_number(sec, "height", 1);
        A = b * h;
        I = b * h * (h * h) / 12.0;
    } else {
        A = api_number(sec, "area", 1);
        I = api_number(sec, "second_moment", 1);
    }
    enum mech_rod_ends ends;
    if (!ends_of(api_string_of(body, "ends"), &ends)) {
        api_call_invalid(c, "/ends", "unknown end conditions");
        return NULL;
    }
    const int nm = (int)api_number_of(body, "modes");
    /* c = sqrt(E/rho) and a = sqrt(EI/(rho A)) as products of square roots:
     * no overflow or underflow of the quotients at the schema's extremes. */
    const double cl = sqrt(E) / sqrt(rho);
    const double a = cl * sqrt(I) / sqrt(A), rg = sqrt(I) / sqrt(A);

    json_t *out = json_object(), *lon = json_object(), *ben = json_object();
    json_t *lm = json_array(), *bm = json_array(), *notes = json_array();
    if (!out || !lon || !ben || !lm || !bm || !notes) {
        json_decref(out), json_decref(lon), json_decref(ben);
        json_decref(lm), json_decref(bm), json_decref(notes);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    json_object_set_new_nocheck(out, "area", api_real(c, A));
    json_object_set_new_nocheck(out, "second_moment", api_real(c, I));
    json_object_set_new_nocheck(out, "radius_of_gyration", api_real(c, rg));
    int thick = 0;
    for (int n = 1; n <= nm; n++) {
        double kl, x, sg;
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st = mech_rod_axial_mode(ends, n, &kl, &e);
        if (st == MECH_OK) st = mech_beam_bending_root(ends, n, &x, &sg, &e);
        if (st != MECH_OK) {
            json_decref(out), json_decref(lon), json_decref(ben);
            json_decref(lm), json_decref(bm), json_decref(notes);
            return api_call_fail_core(c, st, &e, "");
        }
        struct mech_wave_mode m = mech_wave_mode_nondispersive(cl, L, kl);
        json_array_append_new(lm, mode_json(c, n, &m));
        m = mech_wave_mode_bending(a, L, x);
        json_t *o = mode_json(c, n, &m);
        json_object_set_new_nocheck(o, "beta_L", api_real(c, x));
        json_object_set_new_nocheck(o, "sigma", api_real(c, sg));
        json_object_set_new_nocheck(o, "phase_speed", api_real(c, m.phase_speed));
        json_object_set_new_nocheck(o, "group_speed", api_real(c, m.group_speed));
        json_object_set_new_nocheck(o, "k_radius_of_gyration", api_real(c, m.wavenumber * rg));
        if (m.wavenumber * rg > 0.1) thick = 1;
        json_array_append_new(bm, o);
    }
    json_object_set_new_nocheck(lon, "wave_speed", api_real(c, cl));
    json_object_set_new_nocheck(lon, "modes", lm);
    json_object_set_new_nocheck(ben, "stiffness_ratio", api_real(c, a));
    json_object_set_new_nocheck(ben, "modes", bm);
    json_object_set_new_nocheck(out, "longitudinal", lon);
    json_object_set_new_nocheck(out, "bending", ben);
    json_t *tor = torsional(c, body, sec, E, rho, L, ends, nm, notes);
    if (!tor && c->problem != API_PROBLEM_NONE) {
        json_decref(out), json_decref(notes);
        return NULL;
    }
    json_object_set_new_nocheck(out, "torsional", tor ? tor : json_null());
    if (thick)
        json_array_append_new(notes, json_string(
            "some bending modes have k r_g > 0.1: their wavelength is not long against the "
            "section, so Euler-Bernoulli frequencies are too high by about (k r_g)^2 "
            "(shear and rotary inertia, Timoshenko theory, not modelled)"));
    if (ends == MECH_ROD_FREE_FREE)
        json_array_append_new(notes, json_string(
            "free-free: the rigid-body modes (one translation along the rod, two in bending) "
            "have omega = 0 and are not listed"));
    json_object_set_new_nocheck(out, "notes", notes);
    return out;
}

