/* mech/hamiltonian/coupled_oscillations.h — normal modes of a linear system with n
 * degrees of freedom, M q'' + K q = 0 (Landau & Lifshitz, Mechanics §23; Goldstein
 * ch. 6 — the course notes do not treat several degrees of freedom): the generalised symmetric eigenproblem K v = w^2 M v with
 * mass-normalised modes (v^T M v = 1), the standard set-ups built from their
 * parts (a chain of masses and springs, the double pendulum, two pendulums
 * joined by a spring), and the motion from given initial conditions as a sum
 * of modes.
 *
 * Units: the caller's generalised coordinates q (m, rad, ...); M in kg (or
 * kg m^2 for angles), K in N/m (N m/rad); w in rad/s. Pure, reentrant; the
 * eigen-solver allocates GSL workspaces inside mech_coupled_modes().
 */
#ifndef MECH_COUPLED_OSCILLATIONS_H
#define MECH_COUPLED_OSCILLATIONS_H

#include <stddef.h>

#include "mech/base/status.h"

/* At most this many degrees of freedom (the eigen-solver's cost grows as n^3). */
#define MECH_COUPLED_MAX_DOF 64

/* Two squared frequencies belong to one degenerate cluster when they differ by
 * at most this times the largest |w^2| (the rule of mech_inertia_principal). */
#define MECH_COUPLED_DEGENERATE_RTOL 1e-10

enum mech_mode_kind {
    MECH_MODE_OSCILLATING = 0, /* w^2 > 0: cos/sin at w */
    MECH_MODE_ZERO = 1,        /* w^2 = 0 within round-off: free motion a + b t (a
                                  translation of a free chain, a free rotation) */
    MECH_MODE_UNSTABLE = 2     /* w^2 < 0: K not positive semi-definite, cosh/sinh at
                                  sqrt(-w^2) */
};

struct mech_coupled_modes {
    size_t n;                                 /* degrees of freedom */
    double omega2[MECH_COUPLED_MAX_DOF];      /* w^2, ascending (a zero mode exactly 0) */
    double omega[MECH_COUPLED_MAX_DOF];       /* sqrt(w^2) (oscillating), 0 otherwise */
    double growth[MECH_COUPLED_MAX_DOF];      /* sqrt(-w^2) (unstable), 0 otherwise */
    enum mech_mode_kind kind[MECH_COUPLED_MAX_DOF];
    int degenerate_mode[MECH_COUPLED_MAX_DOF]; /* 1: shares its w^2 with another mode */
    /* vectors[k][i]: component i of mode k, mass-normalised (v_k^T M v_l = delta_kl).
     * Signs: the component of largest magnitude is positive (the first within 1e-12
     * relative of the largest, so ties resolve the same way every time). Within a
     * degenerate cluster the basis is fixed by the coordinates, not by the solver:
     * each next vector is the cluster's projection (in the M inner product) of the
     * coordinate unit vector e_j with the largest M-norm relative to sqrt(M_jj)
     * once the vectors already chosen are removed (ties within 1e-9 to the lowest
     * j); its w^2 is then the Rayleigh quotient v^T K v. */
    double vectors[MECH_COUPLED_MAX_DOF][MECH_COUPLED_MAX_DOF];
    int degenerate;   /* 1 if any cluster has two or more modes */
    int zero_modes;   /* how many modes are MECH_MODE_ZERO */
    int stable;       /* 1 if no mode is MECH_MODE_UNSTABLE */
    double zero_tol;  /* |w^2| at or below this is a zero mode: 256 n eps ||K||_inf /
                         mu_min(M), the round-off of the Cholesky-reduced problem */
    double mass_min_eigenvalue; /* mu_min, the smallest eigenvalue of M (> 0) */
};

/* Normal modes of M q'' + K q = 0 for n x n matrices m and k (row-major,
 * n*n doubles each, borrowed), 1 <= n <= MECH_COUPLED_MAX_DOF. M must be
 * symmetric positive definite, K symmetric (any definiteness). Both are
 * scaled by powers of two before the solve (exact), so entries anywhere in
 * the double range work as long as the results are representable. Method:
 * GSL's gsl_eigen_gensymmv (Cholesky M = L L^T, then the symmetric problem
 * L^-1 K L^-T u = w^2 u, v = L^-T u), vectors then mass-normalised in full
 * precision; w^2 accurate to about eps ||K|| / mu_min(M) absolutely.
 * Returns MECH_OK; MECH_EINVAL with param "mass_matrix/<i>/<j>" or
 * "stiffness_matrix/<i>/<j>" for a non-finite entry or for a pair
 * (i > j) whose |a_ij - a_ji| exceeds 1e-12 of the largest entry, or with
 * param "mass_matrix" when n is 0 or above the maximum; MECH_EDOMAIN with
 * param "mass_matrix" when M is not positive definite (its smallest
 * eigenvalue <= 1e-14 of its largest: a massless coordinate has no
 * dynamics); MECH_ENOMEM, MECH_ENUMERIC (solver failure, a non-finite
 * result). out (caller-owned, large: allocate it) holds the answer only on
 * MECH_OK. */
enum mech_status mech_coupled_modes(size_t n, const double *m, const double *k,
                                    struct mech_coupled_modes *out, struct mech_error *err);

/* Modal coordinates of the initial state: a_k = v_k^T M q0, b_k = v_k^T M q0'
 * (q0, q0' of length modes->n, borrowed; a, b written, length n), and each
 * mode's energy e_k = (b_k^2 + w_k^2 a_k^2)/2 (may be NULL), whose sum is the
 * total energy q0'^T M q0'/2 + q0^T K q0/2. m is the mass matrix the modes
 * came from. Cannot fail for finite input; non-finite input gives non-finite
 * output (the caller checks). */
void mech_coupled_project(const struct mech_coupled_modes *modes, const double *m,
                          const double *q0, const double *v0, double *a, double *b,
                          double *energy);

/* The motion at time t (s, finite) from modal coordinates a, b:
 * q(t) = sum_k v_k c_k(t), c_k = a_k cos w t + b_k sin(w t)/w (oscillating),
 * a_k + b_k t (zero), a_k cosh g t + b_k sinh(g t)/g (unstable); q and
 * q' (length n, written; qdot may be NULL). Returns MECH_OK; MECH_ENUMERIC
 * with param "initial/times" if a value overflows (an unstable mode grown
 * beyond the double range). */
enum mech_status mech_coupled_at(const struct mech_coupled_modes *modes, const double *a,
                                 const double *b, double t, double *q, double *qdot,
                                 struct mech_error *err);

/* A chain of n point masses (masses[i] kg, finite, > 0) on a line joined by
 * springs (springs[j] N/m, finite, > 0), with a wall at the left end and/or
 * at the right end: springs run wall-mass 0 (if left_wall), mass i - mass i+1,
 * mass n-1-wall (if right_wall), so n_springs = n - 1 + left_wall + right_wall.
 * Coordinates: each mass's displacement from equilibrium (m). Writes the
 * diagonal M and the tridiagonal K (n*n row-major each). For equal masses m
 * and springs k between two walls, w_j = 2 sqrt(k/m) sin(j pi/(2(n + 1))).
 * Returns MECH_OK; MECH_EINVAL with param "masses" (n = 0 or above the
 * maximum), "springs" (n_springs wrong), "masses/<i>", "springs/<j>"
 * (not finite and > 0). */
enum mech_status mech_coupled_chain(size_t n, const double *masses, const double *springs,
                                    size_t n_springs, int left_wall, int right_wall, double *m,
                                    double *k, struct mech_error *err);

/* The double pendulum (bob m1 on a massless rod l1 from a fixed pivot, bob m2
 * on a rod l2 from m1) linearised about hanging straight down (its Lagrangian: Landau & Lifshitz
 * §5, problem 1): coordinates the angles theta1, theta2 from the downward
 * vertical (rad); T = (m1 + m2) l1^2 t1'^2/2 + m2 l1 l2 t1' t2' + m2 l2^2 t2'^2/2,
 * V = (m1 + m2) g l1 t1^2/2 + m2 g l2 t2^2/2, so
 * M = [[(m1 + m2) l1^2, m2 l1 l2], [m2 l1 l2, m2 l2^2]] (kg m^2),
 * K = diag((m1 + m2) g l1, m2 g l2) (N m/rad); 2 x 2 row-major.
 * Returns MECH_OK; MECH_EINVAL with param "m1", "m2", "l1", "l2", "g" (not
 * finite and > 0). */
enum mech_status mech_coupled_double_pendulum(double m1, double m2, double l1, double l2,
                                              double g, double *m, double *k,
                                              struct mech_error *err);

/* Two equal simple pendulums (bob mass kg, rod length m, > 0) whose rods are
 * joined by a spring (stiffness N/m, >= 0) at the distance `attach` from the
 * pivots (m, 0 < attach <= length; the bobs when attach = length), the spring
 * at its natural length when both hang down: coordinates the angles (rad),
 * M = m l^2 1, K = [[m g l + s a^2, -s a^2], [-s a^2, m g l + s a^2]]:
 * w^2 = g/l (in phase) and g/l + 2 s a^2/(m l^2) (in antiphase; 2s/m at the bobs).
 * Returns MECH_OK; MECH_EINVAL with param "mass", "length", "g", "k" (not
 * finite and >= 0) or "attach" (not in (0, length]). */
enum mech_status mech_coupled_pendulums(double mass, double length, double spring,
                                        double attach, double g, double *m, double *k,
                                        struct mech_error *err);

#endif
