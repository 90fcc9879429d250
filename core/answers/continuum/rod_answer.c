/* rod_answer.c — the POST /v1/continuum/rod answer (see mech/answers/continuum/rod_answer.h):
 * the section's A, I and r_g, the longitudinal and bending modes
 * (continuum_waves.c) and, when asked for, the torsional ones (torsion.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/continuum/rod_answer.h"
#include "mech/continuum/torsion.h"

static enum mech_status positive(double x, const char *param, const char *what,
                                 struct mech_error *err)
{
    if (isfinite(x) && x > 0) return MECH_OK;
    return mech_error_set(err, MECH_EDOMAIN, param, "%s must be finite and > 0, got %.17g", what,
                          x);
}

/* The request's numbers in range; the end conditions by name. */
static enum mech_status check_request(const struct mech_rod_request *q, enum mech_rod_ends *ends,
                                      struct mech_error *err)
{
    enum mech_status st = positive(q->length, "length", "the length", err);
    if (st == MECH_OK) st = positive(q->density, "density", "the density", err);
    if (st == MECH_OK) st = positive(q->youngs_modulus, "youngs_modulus", "Young's modulus", err);
    if (st != MECH_OK) return st;
    switch (q->section) {
    case MECH_ROD_SECTION_CIRCLE:
        st = positive(q->radius, "section/radius", "the radius", err);
        break;
    case MECH_ROD_SECTION_RECTANGLE:
        st = positive(q->width, "section/width", "the width", err);
        if (st == MECH_OK) st = positive(q->height, "section/height", "the height", err);
        break;
    case MECH_ROD_SECTION_GIVEN:
        st = positive(q->area, "section/area", "the area", err);
        if (st == MECH_OK)
            st = positive(q->second_moment, "section/second_moment", "the second moment", err);
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, NULL, "unknown section kind %d", (int)q->section);
    }
    if (st != MECH_OK) return st;
    static const struct {
        const char *name;
        enum mech_rod_ends v;
    } t[] = {
        {"free-free", MECH_ROD_FREE_FREE},
        {"clamped-clamped", MECH_ROD_CLAMPED_CLAMPED},
        {"clamped-free", MECH_ROD_CLAMPED_FREE},
        {"pinned-pinned", MECH_ROD_PINNED_PINNED},
    };
    size_t i = 0;
    while (i < sizeof t / sizeof t[0] && !(q->ends && !strcmp(q->ends, t[i].name))) i++;
    if (i == sizeof t / sizeof t[0])
        return mech_error_set(err, MECH_EINVAL, "ends", "unknown end conditions");
    *ends = t[i].v;
    if (q->modes < 1 || q->modes > MECH_ROD_ANSWER_MAX_MODES)
        return mech_error_set(err, MECH_EINVAL, "modes", "modes must be 1 to %d, got %d",
                              MECH_ROD_ANSWER_MAX_MODES, q->modes);
    return MECH_OK;
}

/* A and I of the section (the circle's and rectangle's closed forms, in
 * the order that keeps r^4 and b h^3 from overflowing early). */
static void section_moments(const struct mech_rod_request *q, double *A, double *I)
{
    if (q->section == MECH_ROD_SECTION_CIRCLE) {
        const double r = q->radius;
        *A = MECH_PI * r * r;
        *I = 0.25 * MECH_PI * (r * r) * (r * r);
    } else if (q->section == MECH_ROD_SECTION_RECTANGLE) {
        const double b = q->width, h = q->height;
        *A = b * h;
        *I = b * h * (h * h) / 12.0;
    } else {
        *A = q->area;
        *I = q->second_moment;
    }
}

/* The torsional block (mech/continuum/torsion.h) when G or ν is given: J and K of the
 * section, c_t, the modes at the axial k_n L. A section given by area alone
 * sets torsion_needs_polar_moment instead. */
static enum mech_status torsion(const struct mech_rod_request *q, struct mech_rod_answer *a,
                                struct mech_error *err)
{
    if (q->has_shear_modulus && q->has_poisson_ratio)
        return mech_error_set(err, MECH_EINVAL, "poisson_ratio",
                              "give shear_modulus or poisson_ratio, not both");
    if (!q->has_shear_modulus && !q->has_poisson_ratio) return MECH_OK; /* not asked for */
    double g = q->shear_modulus, j, k;
    enum mech_status st = MECH_OK;
    if (!q->has_shear_modulus) st = mech_shear_modulus(q->youngs_modulus, q->poisson_ratio, &g, err);
    if (st != MECH_OK) return st;
    if (q->section == MECH_ROD_SECTION_CIRCLE) {
        const double r = q->radius;
        j = k = 0.5 * MECH_PI * (r * r) * (r * r); /* a circle twists without warping: K = J */
    } else if (q->section == MECH_ROD_SECTION_RECTANGLE) {
        st = mech_torsion_rectangle(q->width, q->height, &j, &k, err);
        if (st != MECH_OK) {
            if (err) snprintf(err->param, sizeof err->param, "section");
            return st;
        }
    } else if (q->has_polar_moment) {
        j = q->polar_moment;
        k = q->has_torsion_constant ? q->torsion_constant : j;
    } else {
        a->torsion_needs_polar_moment = 1;
        return MECH_OK;
    }
    double ct;
    st = mech_torsional_wave_speed(g, q->density, k, j, &ct, err);
    if (st != MECH_OK) return st;
    a->has_torsion = 1;
    a->torsion = (struct mech_rod_torsion){g, j, k, ct};
    for (int n = 1; n <= a->n_modes; n++) {
        double kl;
        if (mech_rod_axial_mode(a->ends, n, &kl, NULL) != MECH_OK) break; /* as the axial modes */
        a->modes[n - 1].torsional = mech_wave_mode_nondispersive(ct, q->length, kl);
    }
    return MECH_OK;
}

static int mode_finite(const struct mech_wave_mode *m)
{
    return isfinite(m->wavenumber) && isfinite(m->angular_frequency) && isfinite(m->frequency) &&
           isfinite(m->wavelength) && isfinite(m->phase_speed) && isfinite(m->group_speed);
}

/* Every number the answer states is finite. */
static int answer_finite(const struct mech_rod_answer *a)
{
    if (!isfinite(a->area) || !isfinite(a->second_moment) || !isfinite(a->radius_of_gyration) ||
        !isfinite(a->longitudinal_speed) || !isfinite(a->stiffness_ratio))
        return 0;
    const struct mech_rod_torsion *t = &a->torsion;
    if (a->has_torsion && (!isfinite(t->shear_modulus) || !isfinite(t->polar_moment) ||
                           !isfinite(t->torsion_constant) || !isfinite(t->wave_speed)))
        return 0;
    for (int n = 0; n < a->n_modes; n++) {
        const struct mech_rod_mode *m = &a->modes[n];
        if (!mode_finite(&m->longitudinal) || !mode_finite(&m->bending) || !isfinite(m->beta_L) ||
            !isfinite(m->sigma) || !isfinite(m->k_radius_of_gyration) ||
            (a->has_torsion && !mode_finite(&m->torsional)))
            return 0;
    }
    return 1;
}

static enum mech_status compute(const struct mech_rod_request *q, struct mech_rod_answer *a,
                                struct mech_error *err)
{
    enum mech_status st = check_request(q, &a->ends, err);
    if (st != MECH_OK) return st;
    double A, I;
    section_moments(q, &A, &I);
    /* c = sqrt(E/rho) and a = sqrt(EI/(rho A)) as products of square roots:
     * no overflow or underflow of the quotients at the schema's extremes. */
    const double cl = sqrt(q->youngs_modulus) / sqrt(q->density);
    a->area = A;
    a->second_moment = I;
    a->radius_of_gyration = sqrt(I) / sqrt(A);
    a->longitudinal_speed = cl;
    a->stiffness_ratio = cl * sqrt(I) / sqrt(A);
    a->modes = calloc((size_t)q->modes, sizeof *a->modes);
    if (!a->modes) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    a->n_modes = q->modes;
    for (int n = 1; n <= a->n_modes; n++) {
        struct mech_rod_mode *m = &a->modes[n - 1];
        double kl;
        st = mech_rod_axial_mode(a->ends, n, &kl, err);
        if (st == MECH_OK) st = mech_beam_bending_root(a->ends, n, &m->beta_L, &m->sigma, err);
        if (st != MECH_OK) return st;
        m->longitudinal = mech_wave_mode_nondispersive(cl, q->length, kl);
        m->bending = mech_wave_mode_bending(a->stiffness_ratio, q->length, m->beta_L);
        m->k_radius_of_gyration = m->bending.wavenumber * a->radius_of_gyration;
        if (m->k_radius_of_gyration > 0.1) a->thick = 1;
    }
    st = torsion(q, a, err);
    if (st != MECH_OK) return st;
    if (!answer_finite(a))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the result is not finite for this input (overflow or a singularity)");
    return MECH_OK;
}

enum mech_status mech_rod_answer(const struct mech_rod_request *q, struct mech_rod_answer *out,
                                 struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(out, 0, sizeof *out);
    if (!q) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    enum mech_status st = compute(q, out, err);
    if (st != MECH_OK) mech_rod_answer_free(out);
    return st;
}

void mech_rod_answer_free(struct mech_rod_answer *a)
{
    if (!a) return;
    free(a->modes);
    a->modes = NULL;
    a->n_modes = 0;
}
