/* mech/hamiltonian/poincare.h — Poincaré sections of 2-degree-of-freedom Hamiltonian
 * systems: the points where an orbit crosses a surface y_c = value (y_c a
 * coordinate q_c or a momentum p_c) upwards, recorded in the plane of the
 * other pair (q_o, p_o), o = 1 - (c mod 2). A momentum section p_r = 0 finds
 * the apsides of a central orbit.
 *
 * Crossings are located by root-finding: the ODE driver's stop event
 * (mech_ode_solve: Brent's method on the sub-step solution, to a few ulp of
 * t) fires at a crossing, the point is recorded, and the integration restarts
 * from it (the event is masked at the restart point only, so the same
 * crossing is never counted twice). A cyclic angle coordinate (phi) is cut
 * modulo 2 pi in the direction of rotation, sign(p_phi) (phi is monotonic
 * because phi' = p_phi / (positive), and g = sign(p_phi) sin(phi - value)
 * rises through 0 only at phi = value mod 2 pi). Two crossings inside one
 * step are not seen: keep dt below the time between crossings.
 *
 * Sources: Hénon & Heiles, Astron. J. 69 (1964) 73 (the x = 0, p_x > 0 section);
 * Goldstein ch. 11 (Poincaré maps; the Hénon–Heiles Hamiltonian); Taylor ch. 12
 * (Poincaré sections).
 *
 * Reentrant; nothing global is written.
 */
#ifndef MECH_POINCARE_H
#define MECH_POINCARE_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/hamiltonian/hamiltonian.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"

struct mech_poincare_section {
    size_t index;      /* c: the section is y_c = value, y = (q, p), 0 <= c < 4 */
    double value;
    int angle;         /* 1: y_c (c < 2) is an angle cut modulo 2 pi, direction sign(p_c) */
};

struct mech_poincare_problem {
    const struct mech_ham_system *sys; /* dof = 2 */
    struct mech_poincare_section section;
    const double *y0;                  /* (q, p), 4 values; borrowed */
    double t_max;                      /* s, > 0: stop there at the latest */
    size_t max_crossings;              /* >= 1: stop after this many */
    const struct mech_integrator *method;
    struct mech_ode_options opt;
};

struct mech_poincare_result {
    double *t;         /* caller-owned [max_crossings]: crossing times */
    double *u, *v;     /* caller-owned [max_crossings]: q_o and p_o at the crossings */
    double *y;         /* caller-owned [max_crossings * 4] full states, or NULL */
    size_t n_crossings;
    double t_reached;
    int complete;      /* 1: max_crossings reached; 0: t_max reached first */
    double max_section_residual; /* max |y_c - value| (angles: |sin|) at the crossings */
    struct mech_ham_drift energy;
    size_t n_conserved;
    struct mech_ham_conserved conserved[MECH_HAM_MAX_CONSERVED];
    struct mech_ham_drift conserved_drift[MECH_HAM_MAX_CONSERVED];
    int second_order;
    long segments;     /* mech_ode_solve calls */
    struct mech_ode_stats stats;
};

/* A start on a coordinate section (c < 2) at energy E: q_c = value, (q_o, p_o) = (u, v), and
 * p_c > 0 (angles: p_c with the sign `sign`, +1 or -1) from H = E, with
 * p_c^2 = 2 (E - H(p_c = 0)) / (d2H/dp_c^2) (every catalog H is quadratic in
 * p with no cross terms). MECH_EDOMAIN "energy" when E < H(p_c = 0) (the energy
 * is below the potential there), or the point is outside the domain. */
enum mech_status mech_poincare_start(const struct mech_ham_system *sys,
                                     const struct mech_poincare_section *sec, double E, double u,
                                     double v, int sign, double *y, struct mech_error *err);

/* Integrate and record crossings. Statuses: MECH_OK (also when t_max came
 * before max_crossings: complete = 0); MECH_EINVAL (NULLs, dof != 2,
 * index > 3, t_max <= 0, max_crossings = 0, a second-order method for a
 * non-separable system: "integrator/method"); MECH_EDOMAIN (parameters, y0);
 * MECH_ENUMERIC; MECH_EBUDGET / EDEADLINE / ECANCELLED (max_steps counts all
 * segments together; res holds the crossings found so far); MECH_ENOMEM. */
enum mech_status mech_poincare_run(const struct mech_poincare_problem *p,
                                   const struct mech_budget *budget,
                                   struct mech_poincare_result *res, struct mech_error *err);

#endif
