/* mech/hamiltonian/hamiltonian.h — Hamiltonian systems from a catalog, and their flows.
 *
 * A system is H(q, p) with n degrees of freedom; its state is y = (q, p)
 * (2n values: q_1..q_n, then p_1..p_n) and Hamilton's equations are
 * q' = dH/dp, p' = -dH/dq (Goldstein, Classical Mechanics, 3rd ed., §8.1,
 * eq. 8.18; Taylor, Classical Mechanics, §13.2, eq. 13.25). A coordinate
 * that H does not contain is cyclic and its momentum is conserved
 * (Goldstein §8.2; Taylor §13.4).
 *
 * The catalog (units SI; potentials are zero at the natural rest point):
 *   OSCILLATOR          n = 1 or 2, q = (x[, y]): H = sum p_i^2/2m + k_i q_i^2/2
 *                       (anisotropic when k_x != k_y).
 *   PENDULUM            q = theta (from the downward vertical), p = m l^2 theta':
 *                       H = p^2/(2 m l^2) + m g l (1 - cos theta).
 *   SPHERICAL_PENDULUM  q = (theta, phi), theta from the downward vertical,
 *                       p_theta = m l^2 theta', p_phi = m l^2 sin^2 theta phi':
 *                       H = p_theta^2/(2 m l^2) + p_phi^2/(2 m l^2 sin^2 theta)
 *                       + m g l (1 - cos theta); phi cyclic (notes' contents:
 *                       "Example: A spherical pendulum"; Goldstein §8.2).
 *   CYLINDER            particle on a cylinder of radius R, attracted to the
 *                       origin by F = -k r; q = (z, phi): H = p_z^2/2m +
 *                       p_phi^2/(2 m R^2) + k (R^2 + z^2)/2; phi cyclic
 *                       (notes' contents: "Particle on the Surface of a
 *                       Cylinder"; Goldstein ch. 8; Taylor §13.4).
 *   CENTRAL             plane polar q = (r, phi): H = p_r^2/2m + p_phi^2/(2 m r^2)
 *                       + K r^power (Kepler: power = -1, K = -G M m); phi cyclic
 *                       (Taylor §13.3; Goldstein §8.2, §3.6 for the apsides).
 *   HENON_HEILES        dimensionless, q = (x, y): H = (p_x^2 + p_y^2)/2 +
 *                       (x^2 + y^2)/2 + x^2 y - y^3/3 (Hénon & Heiles, Astron. J.
 *                       69 (1964) 73, eq. 7).
 *   POTENTIAL_3D        Cartesian q = (x, y, z): H = |p|^2/2m + V(q) with V one of
 *                       HARMONIC  V = (k_x x^2 + k_y y^2 + k_z z^2)/2,
 *                       POWER     V = K r^power (power != 0; Kepler: power = -1, K < 0).
 *
 * Separable systems (H = sum p_i^2/(2 M_i) + V(q), constant M_i: oscillator,
 * pendulum, cylinder, Hénon–Heiles, potential_3d) can also be integrated in
 * the second-order form y = (q, v), v_i = p_i / M_i, v' = -M^-1 dV/dq, which
 * is what verlet, yoshida4/6, symplectic_euler, boris, radau15 need: the linear,
 * constant change (q, p) -> (q, v) maps a symplectic step to a symplectic step.
 * The spherical pendulum and the central problem have a p-dependence through
 * 1/sin^2 theta and 1/r^2 and are not separable: only first-order methods
 * (gauss4/gauss6 are symplectic for any H) apply to them.
 *
 * All functions are reentrant; nothing global is written.
 */
#ifndef MECH_HAMILTONIAN_H
#define MECH_HAMILTONIAN_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"

#define MECH_HAM_MAX_DOF 3
#define MECH_HAM_MAX_DIM 6
#define MECH_HAM_MAX_CONSERVED 3

enum mech_ham_kind {
    MECH_HAM_OSCILLATOR = 0,
    MECH_HAM_PENDULUM,
    MECH_HAM_SPHERICAL_PENDULUM,
    MECH_HAM_CYLINDER,
    MECH_HAM_CENTRAL,
    MECH_HAM_HENON_HEILES,
    MECH_HAM_POTENTIAL_3D,
    MECH_HAM_KIND_COUNT
};

enum mech_ham_potential {
    MECH_HAM_POT_HARMONIC = 0, /* V = sum k_i x_i^2 / 2 */
    MECH_HAM_POT_POWER         /* V = K r^power */
};

/* One system of the catalog. Fields a kind does not use are ignored. */
struct mech_ham_system {
    enum mech_ham_kind kind;
    int dof;           /* oscillator: 1 or 2; fixed by the kind otherwise (set by check) */
    double mass;       /* kg, > 0 (Hénon–Heiles: ignored, 1) */
    double k[3];       /* oscillator, potential_3d harmonic: spring constants N/m, > 0 */
    double length;     /* pendulums: l, m, > 0 */
    double g;          /* pendulums: m/s^2, >= 0 */
    double radius;     /* cylinder: R, m, > 0 */
    double strength;   /* cylinder: k (N/m, > 0); central and power: K (J m^-power, != 0) */
    double power;      /* central, power: exponent, != 0, |power| <= 20 */
    enum mech_ham_potential potential; /* potential_3d */
};

/* A conserved momentum (of a cyclic coordinate) or a symmetry invariant. */
struct mech_ham_conserved {
    const char *name;   /* "p_phi", "L_z", ... (static) */
    int cyclic;         /* 1: momentum of a cyclic coordinate; 0: from a symmetry */
    size_t index;       /* cyclic: index of the coordinate in q */
};

/* Validate the parameters and fill s->dof for fixed kinds. EDOMAIN with
 * param "system/<field>" (e.g. "system/mass") or EINVAL for an unknown kind. */
enum mech_status mech_ham_system_check(struct mech_ham_system *s, struct mech_error *err);

/* 2 * dof. */
size_t mech_ham_dim(const struct mech_ham_system *s);

/* Names of coordinate i ("theta", "phi", "x", ...) and of its momentum ("p_theta"). Static. */
const char *mech_ham_coordinate_name(const struct mech_ham_system *s, size_t i);
const char *mech_ham_momentum_name(const struct mech_ham_system *s, size_t i);

/* Is y = (q, p) an admissible state? EDOMAIN with param "q/<i>" or "p/<i>":
 * r <= 0 (central, power), sin theta = 0 with p_phi != 0 (spherical pendulum:
 * infinite energy); EDOMAIN "q" for a non-finite value. */
enum mech_status mech_ham_state_check(const struct mech_ham_system *s, const double *y,
                                      struct mech_error *err);

/* H(y), J. MECH_ENUMERIC when y is outside the domain (r <= 0, ...) or the value
 * is not finite. */
enum mech_status mech_ham_energy(const struct mech_ham_system *s, const double *y, double *E,
                                 struct mech_error *err);

/* Potential energy part V(q) for separable systems and the pendulums (the terms
 * without p), J. Never fails for admissible q; NaN outside the domain. */
double mech_ham_potential_energy(const struct mech_ham_system *s, const double *q);

/* Hamilton's equations: dydt = (dH/dp, -dH/dq). If v (2n values) is not NULL,
 * also dv = D(dydt)(y) v, the variational (tangent) equations
 * d(dq) = H_pq dq + H_pp dp, d(dp) = -H_qq dq - H_qp dp. MECH_ENUMERIC when y
 * leaves the domain (r <= 0 — the orbit hit the centre —, a pole with p_phi != 0)
 * or a value is not finite (text says which). */
enum mech_status mech_ham_rhs(const struct mech_ham_system *s, const double *y, double *dydt,
                              const double *v, double *dv, struct mech_error *err);

/* 1 and the constant masses M_i (H = sum p_i^2/(2 M_i) + V(q)) if separable, else 0.
 * M may be NULL. */
int mech_ham_separable(const struct mech_ham_system *s, double *M);

/* Conserved momenta: of cyclic coordinates (spherical pendulum, cylinder,
 * central: p_phi) and symmetry invariants in Cartesian coordinates (isotropic
 * 2D oscillator: L_z = x p_y - y p_x; potential_3d power: L_x, L_y, L_z;
 * harmonic with k_x = k_y: L_z). Fills out[0..count-1], returns count
 * (<= MECH_HAM_MAX_CONSERVED). */
size_t mech_ham_conserved_list(const struct mech_ham_system *s,
                               struct mech_ham_conserved out[MECH_HAM_MAX_CONSERVED]);
/* Value of conserved quantity c at y. */
double mech_ham_conserved_value(const struct mech_ham_system *s,
                                const struct mech_ham_conserved *c, const double *y);

/* A dynamical time of the system at state y (s): 1/omega with omega the sum
 * of the small-oscillation (or circular-orbit) rate and the coordinate rates
 * |q_i'| / scale_i at y. Finite and > 0 for admissible y. */
double mech_ham_time_scale(const struct mech_ham_system *s, const double *y);

/* ---- ensembles: many trajectories (and tangent vectors) as one ODE ----------
 * n_traj trajectories of the same system, each carrying n_tan tangent vectors
 * (the variational equations, integrated by the same method as the
 * trajectory, so for a Runge–Kutta method they give exactly the derivative of
 * the numerical flow). Layout of the ODE state (dim = 2 n n_traj (1 + n_tan)):
 * the q-half first — for each trajectory j its q (n values) then its n_tan
 * tangent q-parts — then the p-half in the same order. In second-order form
 * (separable systems, methods that need q'' = a) the p-half holds v = M^-1 p
 * and M^-1 dp. Pack/unpack convert. */
struct mech_ham_ensemble {
    const struct mech_ham_system *sys; /* borrowed */
    size_t n_traj, n_tan;
    int second_order;                  /* 1: p-half holds velocities */
    double M[MECH_HAM_MAX_DOF];        /* masses when second_order */
    struct mech_error *err;            /* where the rhs records its errors (may be NULL) */
};

/* Set up e and sys_out for method m: second-order form when m needs it (then
 * the system must be separable: else EINVAL with param "integrator/method"),
 * with particle_dim = dof where q are one point's Cartesian coordinates
 * (oscillator, henon_heiles, potential_3d), else 1. e must outlive sys_out. */
enum mech_status mech_ham_ensemble_init(struct mech_ham_ensemble *e,
                                        const struct mech_ham_system *s, size_t n_traj,
                                        size_t n_tan, const struct mech_integrator *m,
                                        struct mech_ode_system *sys_out, struct mech_error *err);
size_t mech_ham_ensemble_dim(const struct mech_ham_ensemble *e);
/* Trajectory j's state (q, p) into y (ODE layout), and tangent k (2n values) of j. */
void mech_ham_ensemble_put(const struct mech_ham_ensemble *e, double *Y, size_t j,
                           const double *y, const double *const *tangents);
/* Read trajectory j's (q, p) (y, may be NULL) and its tangent k (tan, may be NULL) from Y. */
void mech_ham_ensemble_get(const struct mech_ham_ensemble *e, const double *Y, size_t j,
                           double *y, size_t k, double *tan);

/* ---- the flow ---------------------------------------------------------------- */

struct mech_ham_flow_problem {
    const struct mech_ham_system *sys;  /* checked by mech_ham_system_check */
    const double *y0;                   /* (q, p), 2 dof values; borrowed */
    double t_end;                       /* s, > 0 */
    size_t n_samples;                   /* >= 2, evenly spaced from 0 to t_end */
    const struct mech_integrator *method;
    struct mech_ode_options opt;
};

struct mech_ham_drift {
    double initial, final;
    double max_abs;  /* max over every accepted step and sample of |X - X0| */
    double max_rel;  /* max_abs / |X0|, NaN when X0 = 0 */
};

struct mech_ham_flow_result {
    double *t;                /* caller-owned [n_samples] */
    double *y;                /* caller-owned [n_samples * 2 dof], (q, p) rows */
    size_t n_samples;         /* written */
    struct mech_ham_drift energy;
    size_t n_conserved;
    struct mech_ham_conserved conserved[MECH_HAM_MAX_CONSERVED];
    struct mech_ham_drift conserved_drift[MECH_HAM_MAX_CONSERVED];
    int second_order;         /* integrated in the (q, v) form */
    struct mech_ode_stats stats;
};

/* Integrate Hamilton's equations from y0 over [0, t_end]. Energy and the
 * conserved momenta are checked at every accepted step (observer).
 * Statuses: MECH_OK; MECH_EINVAL (NULLs, n_samples < 2, a second-order method
 * for a non-separable system: "integrator/method"); MECH_EDOMAIN (the
 * parameters or y0 — see mech_ham_state_check, params "q/i", "p/i");
 * MECH_ENUMERIC (the orbit reached a singularity: r = 0, a pole; non-finite
 * values; implicit stages not converging); MECH_EBUDGET/EDEADLINE/ECANCELLED;
 * MECH_ENOMEM. res holds what was written so far on failure. */
enum mech_status mech_ham_flow(const struct mech_ham_flow_problem *p,
                               const struct mech_budget *budget,
                               struct mech_ham_flow_result *res, struct mech_error *err);

/* The chooser's pilot hook (mech/ode/chooser_pilot.h, struct
 * mech_pilot_system's run with ctx = a const struct mech_ham_flow_problem *
 * whose sys, y0 and t_end are the flow's; its n_samples, method and opt are
 * ignored): the flow over the first `fraction` of t_end with the registry
 * method named `method` at *opt, two samples; y_end = (q, p) at the end (SI),
 * *dim = 2 dof. Statuses as mech_ham_flow; MECH_EINVAL for an unknown method. */
enum mech_status mech_ham_pilot_run(void *ctx, const char *method,
                                    const struct mech_ode_options *opt, double fraction,
                                    const struct mech_budget *budget,
                                    struct mech_ode_stats *stats, double *y_end, size_t *dim,
                                    struct mech_error *err);

/* The chooser's error gain of a flow (mech_scene_profile.error_gain, >= 1):
 * how much more the flow from y0 (q, p; SI) amplifies an error than the
 * first-order calibration systems. A one-degree-of-freedom oscillation whose
 * frequency depends on its energy turns an energy error into a phase error
 * that grows with time; for the plane pendulum the twist
 * S = |d ln(omega) / d ln(E)| (E above the bottom; K(m), E(m) complete
 * elliptic integrals, m = E / 2 m g l, 1/m over the top) sets it: measured
 * with rk8pd at the presets over 100 s (l = 1 m, g = 9.80665) against the
 * Jacobi-elliptic solution, the error was 3.5x the first-order law at
 * theta0 = 1 rad (S = 0.072), 80x at 2.5 rad (S = 1.64), 400x at 3.0 rad
 * (S = 24): gain = 1 + 40 S^0.8 (capped at 1e6, the separatrix). 1 for
 * the other systems (their laws are the calibration's). */
double mech_ham_error_gain(const struct mech_ham_system *s, const double *y0);

#endif
