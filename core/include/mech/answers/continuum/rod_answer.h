/* mech/answers/continuum/rod_answer.h — one POST /v1/continuum/rod answer, from the request as
 * read to everything the answer states: the section's area, second moment
 * and radius of gyration, the lowest longitudinal and bending
 * (Euler–Bernoulli) modes for the end conditions, and the torsional modes
 * when a shear modulus or Poisson's ratio is given (mech/continuum/continuum_waves.h,
 * mech/continuum/torsion.h), with the flags the answer's notes state. The API's
 * handler parses, calls mech_rod_answer() once and encodes.
 *
 * Units: SI (m, kg/m³, Pa, m², m⁴, m/s, rad/m, rad/s, Hz). Thread-safe;
 * allocates the modes (freed by mech_rod_answer_free). */
#ifndef MECH_ROD_ANSWER_H
#define MECH_ROD_ANSWER_H

#include "mech/continuum/continuum_waves.h"
#include "mech/base/status.h"

/* The most modes one answer lists (the request schema's bound). */
#define MECH_ROD_ANSWER_MAX_MODES 1000

/* How the request gives the cross-section. */
enum mech_rod_section {
    MECH_ROD_SECTION_CIRCLE = 0, /* radius r: A = π r², I = π r⁴/4, J = K = π r⁴/2 */
    MECH_ROD_SECTION_RECTANGLE,  /* width b, height h in the bending plane: A = b h,
                                    I = b h³/12, J and K from mech_torsion_rectangle */
    MECH_ROD_SECTION_GIVEN       /* area, second_moment, and for torsion polar_moment
                                    (and torsion_constant, default J) */
};

struct mech_rod_request {
    double length, density, youngs_modulus; /* L m, ρ kg/m³, E Pa: finite, > 0 */
    enum mech_rod_section section;
    double radius;                           /* CIRCLE */
    double width, height;                    /* RECTANGLE */
    double area, second_moment;              /* GIVEN */
    int has_polar_moment, has_torsion_constant; /* GIVEN, for torsion */
    double polar_moment, torsion_constant;
    const char *ends;  /* "free-free", "clamped-clamped", "clamped-free", "pinned-pinned" */
    int modes;         /* how many, 1 .. MECH_ROD_ANSWER_MAX_MODES */
    int has_shear_modulus, has_poisson_ratio; /* at most one: torsion asked for */
    double shear_modulus, poisson_ratio;      /* G Pa; ν in (−1, ½] */
};

/* Mode n (1-based: modes[n - 1]) of each kind; torsional only when the
 * answer has_torsion. */
struct mech_rod_mode {
    struct mech_wave_mode longitudinal; /* k_n L = nπ or (n − ½)π, ω = c k */
    struct mech_wave_mode bending;      /* k_n L = beta_L, ω = a k² */
    double beta_L;                      /* the characteristic equation's n-th root */
    double sigma;                       /* the mode shape's ratio (0 for pinned-pinned) */
    double k_radius_of_gyration;        /* k r_g: Euler–Bernoulli wants it below ~0.1 */
    struct mech_wave_mode torsional;    /* the axial k_n L, ω = c_t k */
};

struct mech_rod_torsion {
    double shear_modulus;    /* G, given or E/(2(1 + ν)) */
    double polar_moment;     /* J, m⁴ */
    double torsion_constant; /* K ≤ J, m⁴ */
    double wave_speed;       /* c_t = sqrt(G K/(ρ J)) */
};

struct mech_rod_answer {
    enum mech_rod_ends ends;
    double area, second_moment, radius_of_gyration; /* A, I, r_g = sqrt(I/A) */
    double longitudinal_speed;                      /* c = sqrt(E/ρ) */
    double stiffness_ratio;                         /* a = sqrt(E I/(ρ A)) = c r_g, m²/s */
    int n_modes;
    struct mech_rod_mode *modes; /* n_modes, owned by the answer */
    int has_torsion;             /* torsion asked for and the section gives J (and K) */
    int torsion_needs_polar_moment; /* asked for, but a GIVEN section without polar_moment:
                                       has_torsion is 0 (the answer says what is missing) */
    struct mech_rod_torsion torsion;
    int thick; /* some bending mode has k r_g > 0.1 (shear and rotary inertia matter) */
};

/* Compute *out for request q. Statuses, err->param naming the request's field:
 *   MECH_EINVAL (no param) for a NULL pointer or an unknown section kind;
 *   MECH_EDOMAIN "length", "density", "youngs_modulus", "section/radius",
 *     "section/width", "section/height", "section/area",
 *     "section/second_moment" (not finite and > 0);
 *   MECH_EINVAL "ends" ("unknown end conditions"), "modes" (outside 1 ..
 *     MECH_ROD_ANSWER_MAX_MODES), "poisson_ratio" (both it and shear_modulus);
 *   for the torsion: mech_shear_modulus's ("poisson_ratio"), any of
 *     mech_torsion_rectangle's at "section", mech_torsional_wave_speed's
 *     ("shear_modulus", "density", "section/torsion_constant",
 *     "section/polar_moment");
 *   MECH_ENOMEM for the modes;
 *   MECH_ENUMERIC (no param) when a number of the answer is not finite (a
 *     section so small that r² or b h underflows), the text "the result is
 *     not finite for this input (overflow or a singularity)".
 * out is always initialised (safe to free); on failure it holds no modes.
 * err may be NULL. */
enum mech_status mech_rod_answer(const struct mech_rod_request *q, struct mech_rod_answer *out,
                                 struct mech_error *err);

/* Free the modes of an answer (safe on a zeroed or failed one). */
void mech_rod_answer_free(struct mech_rod_answer *a);

#endif
