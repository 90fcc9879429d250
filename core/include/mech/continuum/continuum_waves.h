/* mech/continuum/continuum_waves.h — waves on strings and rods, the standard content
 * of a mechanics course's continuum chapter (the notes' last chapter is only
 * a heading): the wave speeds, the normal modes of a string with fixed ends,
 * the longitudinal and torsional modes of a rod, and the bending (flexural)
 * modes of an Euler–Bernoulli beam, whose characteristic equations
 * cos x cosh x = ±1 are solved here robustly for any mode number.
 *
 * Units: SI (N, kg/m, Pa, kg/m³, m², m⁴, m, Hz, rad/s).
 * Sources: string and rod waves, e.g. Fetter & Walecka, "Theoretical
 * Mechanics of Particles and Continua" ch. 7, 12; beam modes, Blevins,
 * "Formulas for Natural Frequency and Mode Shape" (1979) Table 8-1.
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_CONTINUUM_WAVES_H
#define MECH_CONTINUUM_WAVES_H

#include "mech/base/status.h"

/* Largest mode number served (an index, and the bound of a root search). */
#define MECH_CONTINUUM_MODE_MAX 100000

/* Transverse wave speed on a string, c = sqrt(T/μ) (m/s), for tension T > 0
 * (N) and linear density μ > 0 (kg/m). Statuses: MECH_OK; MECH_EDOMAIN param
 * "tension" or "linear_density" (≤ 0 or not finite). */
enum mech_status mech_string_wave_speed(double tension, double linear_density, double *c,
                                        struct mech_error *err);

/* End conditions of a rod or beam. For axial (longitudinal, torsional)
 * waves "clamped" is a fixed end and "free" a stress-free end; for bending,
 * clamped is w = w' = 0, free is w'' = w''' = 0, pinned is w = w'' = 0. */
enum mech_rod_ends {
    MECH_ROD_FREE_FREE = 0,
    MECH_ROD_CLAMPED_CLAMPED = 1,
    MECH_ROD_CLAMPED_FREE = 2,  /* a cantilever */
    MECH_ROD_PINNED_PINNED = 3, /* simply supported */
};

/* Axial mode n ≥ 1 of a rod of length L with wave speed c: the wavenumber
 * k_n L = nπ (free-free, clamped-clamped: both ends alike) or (n − ½)π
 * (clamped-free); a pinned end holds the rod axially, so pinned-pinned is
 * fixed-fixed, nπ. (Free-free also has the rigid translation, ω = 0, not
 * counted.)
 * Returns k_n L in *kl. Statuses: MECH_OK; MECH_EINVAL param "modes" or "ends". */
enum mech_status mech_rod_axial_mode(enum mech_rod_ends ends, int n, double *kl,
                                     struct mech_error *err);

/* Bending mode n ≥ 1 of a uniform Euler–Bernoulli beam: x_n = β_n L, the
 * n-th positive root of the characteristic equation
 *   free-free and clamped-clamped: cos x cosh x = 1   (4.7300407448627, …)
 *   clamped-free:                   cos x cosh x = −1  (1.8751040687120, …)
 *   pinned-pinned:                  sin x = 0          (nπ)
 * (free-free also has two rigid-body modes with ω = 0, not counted). The
 * equation is solved as cos x = ±sech x, which never overflows; the n-th
 * root is bracketed in [nπ, (n + 1)π] (resp. [(n − 1)π, nπ]) where the
 * function is monotone, and found by bisection to the last bit, so every
 * mode number up to MECH_CONTINUUM_MODE_MAX is served with relative error
 * ~1e-16 (roots approach (n + ½)π, (n − ½)π with a gap ~2e^{−x}).
 * The mode's frequency is ω_n = x_n² sqrt(EI/(ρA)) / L².
 * *sigma (may be NULL) receives the mode-shape ratio of the clamped and free
 * cases, w(ξ) ∝ cosh x_n ξ ± cos x_n ξ − σ (sinh x_n ξ ± sin x_n ξ), ξ = s/L,
 * σ = (cosh x − cos x)/(sinh x − sin x) (clamped-clamped, free-free) or
 * (sinh x − sin x)/(cosh x + cos x) (clamped-free), computed with e^{−x}
 * factored out; 0 for pinned-pinned (w ∝ sin nπξ).
 * Statuses: MECH_OK; MECH_EINVAL param "modes" (n < 1 or n > MAX) or "ends". */
enum mech_status mech_beam_bending_root(enum mech_rod_ends ends, int n, double *x, double *sigma,
                                        struct mech_error *err);

/* One normal mode: wavenumber k = (kL)/L (rad/m), angular frequency ω
 * (rad/s), frequency f = ω/2π (Hz), wavelength λ = 2π/k (m), phase speed
 * ω/k and group speed dω/dk (m/s). */
struct mech_wave_mode {
    double wavenumber, angular_frequency, frequency, wavelength, phase_speed, group_speed;
};

/* A mode of a non-dispersive wave (string, axial rod waves: ω = c k) with
 * kL = kl on a length L > 0. Cannot fail for positive finite inputs. */
struct mech_wave_mode mech_wave_mode_nondispersive(double c, double length, double kl);

/* A bending mode of an Euler–Bernoulli beam (ω = a k², a = sqrt(EI/(ρA)) in
 * m²/s) with kL = x on a length L > 0: phase speed a k, group speed 2 a k. */
struct mech_wave_mode mech_wave_mode_bending(double a, double length, double x);

#endif
