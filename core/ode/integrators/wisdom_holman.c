/* integrators/wisdom_holman.c — the Wisdom–Holman splitting for one body
 * moving about one central mass with small perturbations (a third body's
 * tide, a weak uniform field, weak drag): exact Kepler drifts alternating
 * with kicks of the other forces, fixed step, second order, on libmech's
 * stepper interface (integrator.h).
 *
 * Reference: J. Wisdom, M. Holman, "Symplectic maps for the n-body problem",
 * Astron. J. 102 (1991) 1528-1538; J. Wisdom, M. Holman, J. Touma, "Symplectic
 * correctors", Fields Inst. Commun. 10 (1996) 217-244; H. Rein, D. Tamayo,
 * "WHFast: a fast and unbiased implementation of a symplectic Wisdom-Holman
 * integrator for long-term gravitational simulations", MNRAS 452 (2015)
 * 376-388 (drift-kick-drift form, Kepler solver in universal variables).
 *
 * The split (mech/ode/ode.h, struct mech_ode_kepler_split): H = H_K + H_P with
 * H_K = v^2/2 - gm/|x - c| (solved exactly: mech_kepler_drift, universal
 * variables, any conic) and the perturbation P = a - a_Kepler. One step
 * (Strang / drift-kick-drift):
 *   (x, v) <- Kepler(h/2);  v <- v + h P(t + h/2, x, v);  (x, v) <- Kepler(h/2)
 * One perturbation evaluation per step. The map is the exact flow of a
 * modified Hamiltonian H + h^2 {{H_K, H_P}, ...}/24-type terms, all
 * proportional to the perturbation: for P of relative size eps the energy
 * error is bounded, O(eps (h/T)^2), with no secular drift (backward error
 * analysis, Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed.,
 * Springer 2006, IX.8), and with P = 0 the step is the Kepler flow itself,
 * exact to round-off for any h.
 *
 * Velocity-dependent perturbations (drag, q v x B): the kick is the
 * implicit midpoint rule v1 = v + h P(x, (v + v1)/2), solved by fixed-point
 * iteration from the explicit kick (contraction h |dP/dv| / 2, e.g. gamma h/2
 * for drag -gamma v) to |dv| <= 4 eps |v| in at most 50 iterations, else
 * MECH_ENUMERIC naming integrator/dt. The step stays symmetric (so second
 * order) and, for a pure magnetic-type term, keeps |v| through the kick
 * (a Cayley rotation); it is not symplectic — drag dissipates energy anyway,
 * and the error in that dissipation is O(gamma h^2).
 *
 * wisdom_holman_corrected: the same map conjugated by the third-order
 * symplectic corrector C of Wisdom, Holman & Touma (1996), with the
 * coefficients a1 = sqrt(7/40), b31 = -sqrt(10/7)/48 (to 50 digits in Rein &
 * Tamayo 2015):
 *   Z(a, b) = D(a) k(-b) D(-2a) k(b) D(a)   (D: Kepler drift, k(c): v += c P)
 *   C = Z(-a1 h, b31 h) Z(a1 h, -b31 h),   C^-1 = Z(-a1 h, -b31 h) Z(a1 h, b31 h)
 * (rightmost first). The corrector removes the O(eps h^2) part of the error
 * (which is a coordinate change, Wisdom et al. 1996), leaving O(eps^2 h^2 +
 * eps h^4). WHFast applies C once at the start and C^-1 at each output; here
 * step() must give real coordinates after every step (samples are
 * sub-steps, integrator.h), so every step is C^-1 (DKD) C: symplectic (a
 * conjugate of a symplectic map), 8 drifts and 7 perturbation evaluations
 * after merging adjacent drifts and kicks (about 4x a plain step). For
 * velocity-free perturbations only: with drag (no Hamiltonian) it refuses.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ode/integrators/integrator.h"
#include "mech/ode/kepler.h"

enum { WH_MAX_KICK_ITERATIONS = 50 };

struct wh_ws {
    size_t nd; /* 2 or 3: components of the one particle */
};

static enum mech_status wh_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                 struct mech_error *err)
{
    (void)opt;
    if (dim != 4 && dim != 6)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "wisdom_holman moves one body in 2 or 3 dimensions (a state of "
                              "4 or 6 components), got %zu",
                              dim);
    struct wh_ws *w = malloc(sizeof *w);
    if (!w) return mech_error_set(err, MECH_ENOMEM, NULL, "wisdom_holman: out of memory");
    w->nd = dim / 2;
    *ws = w;
    return MECH_OK;
}

static void wh_reset(void *ws) { (void)ws; /* stateless between steps */ }

static void wh_free(void *ws) { free(ws); }

/* The perturbing acceleration at (t, q, v), counted as one evaluation and
 * checked finite. */
static enum mech_status wh_perturbation(const struct mech_ode_system *sys, size_t nd, double t,
                                        const double *q, const double *v, double *a,
                                        struct mech_ode_stats *stats, struct mech_error *err)
{
    if (stats) stats->rhs_evaluations++;
    enum mech_status st = sys->kepler->perturbation(t, q, v, a, sys->params);
    if (st != MECH_OK)
        return mech_error_set(err, st, NULL, "the perturbing force failed at t = %.9g s", t);
    for (size_t i = 0; i < nd; i++)
        if (!isfinite(a[i]))
            return mech_error_set(err, MECH_ENUMERIC, NULL,
                                  "non-finite perturbing acceleration at t = %.9g s", t);
    return MECH_OK;
}

/* Kepler drift of (x, v) (relative to the centre, 3 components, x[2] =
 * v[2] = 0 for a planar system) by h. */
static enum mech_status wh_drift(const struct mech_ode_system *sys, double *x, double *v, double h,
                                 double t, struct mech_error *err)
{
    enum mech_status st = mech_kepler_drift(sys->kepler->gm, x, v, h, x, v, NULL, err);
    if (st == MECH_OK) return MECH_OK;
    return mech_error_set(err, st, "integrator/method",
                          "the Kepler drift of wisdom_holman failed near t = %.9g s (the body "
                          "fell onto the central mass?)",
                          t);
}

/* Implicit-midpoint kick for a velocity-dependent perturbation:
 * v1 = v + h P(t, q, (v + v1)/2). vm = (v + v1)/2 by fixed-point iteration. */
static enum mech_status wh_kick_implicit(const struct mech_ode_system *sys, size_t nd, double t,
                                         double h, const double *q, double *v,
                                         struct mech_ode_stats *stats, struct mech_error *err)
{
    double vm[3], a[3], vn[3];
    enum mech_status st = wh_perturbation(sys, nd, t, q, v, a, stats, err);
    if (st != MECH_OK) return st;
    for (size_t i = 0; i < nd; i++) vm[i] = v[i] + 0.5 * h * a[i];
    for (int it = 0; it < WH_MAX_KICK_ITERATIONS; it++) {
        if ((st = wh_perturbation(sys, nd, t, q, vm, a, stats, err)) != MECH_OK) return st;
        double dmax = 0.0, vmax = 0.0;
        for (size_t i = 0; i < nd; i++) {
            vn[i] = v[i] + 0.5 * h * a[i];
            dmax = fmax(dmax, fabs(vn[i] - vm[i]));
            vmax = fmax(vmax, fabs(vn[i]));
            vm[i] = vn[i];
        }
        if (dmax <= 4.0 * DBL_EPSILON * vmax) {
            for (size_t i = 0; i < nd; i++) v[i] = 2.0 * vm[i] - v[i];
            return MECH_OK;
        }
    }
    return mech_error_set(err, MECH_ENUMERIC, "integrator/dt",
                          "wisdom_holman: the velocity-dependent perturbation (drag or magnetic "
                          "force) is too strong for dt = %.6g s (its implicit kick did not "
                          "converge at t = %.9g s); use a smaller dt or an adaptive method",
                          fabs(h), t);
}

static enum mech_status wh_step(void *ws, const struct mech_ode_system *sys, double t, double h,
                                double *y, struct mech_ode_stats *stats, struct mech_error *err)
{
    const struct wh_ws *w = ws;
    const size_t nd = w->nd;
    const struct mech_ode_kepler_split *k = sys->kepler;
    if (!k || !k->perturbation)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "wisdom_holman needs a Kepler split (one central_gravity in an "
                              "inertial frame)");
    double x[3] = {0, 0, 0}, v[3] = {0, 0, 0}, q[3], a[3];
    for (size_t i = 0; i < nd; i++) {
        x[i] = y[i] - k->center[i];
        v[i] = y[nd + i];
    }
    enum mech_status st = wh_drift(sys, x, v, 0.5 * h, t, err);
    if (st != MECH_OK) return st;
    const double tm = t + 0.5 * h;
    for (size_t i = 0; i < nd; i++) q[i] = x[i] + k->center[i];
    if (k->velocity_dependent) {
        st = wh_kick_implicit(sys, nd, tm, h, q, v, stats, err);
    } else {
        st = wh_perturbation(sys, nd, tm, q, v, a, stats, err);
        if (st == MECH_OK)
            for (size_t i = 0; i < nd; i++) v[i] += h * a[i];
    }
    if (st != MECH_OK) return st;
    if ((st = wh_drift(sys, x, v, 0.5 * h, tm, err)) != MECH_OK) return st;
    for (size_t i = 0; i < nd; i++) {
        y[i] = x[i] + k->center[i];
        y[nd + i] = v[i];
    }
    return MECH_OK;
}

/* Third-order corrector coefficients (Wisdom, Holman & Touma 1996; the
 * values tabulated in Rein & Tamayo 2015, WHFast). */
static const double WH_CORR_A1 = 0.41833001326703777398908601289259374469640768464934;
static const double WH_CORR_B31 = -0.024900596027799867499350357910273437184309981229127;

/* v += c P(t, x + centre) for the relative state (x, v). */
static enum mech_status wh_kick(const struct mech_ode_system *sys, size_t nd, double t, double c,
                                const double *x, double *v, struct mech_ode_stats *stats,
                                struct mech_error *err)
{
    const struct mech_ode_kepler_split *k = sys->kepler;
    double q[3] = {0, 0, 0}, a[3];
    for (size_t i = 0; i < nd; i++) q[i] = x[i] + k->center[i];
    enum mech_status st = wh_perturbation(sys, nd, t, q, v, a, stats, err);
    if (st != MECH_OK) return st;
    for (size_t i = 0; i < nd; i++) v[i] += c * a[i];
    return MECH_OK;
}

/* One leg of the corrector, merged (see the header): with a = a1 h,
 * b = b31 h and sign = +1 for C, -1 for C^-1:
 *   D(a) k(sign b) D(-2a) k(-2 sign b) D(2a) k(sign b) D(-a)
 * without its final D(-a), which the caller merges into the next drift. */
static enum mech_status wh_corrector(const struct mech_ode_system *sys, size_t nd, double t,
                                     double h, double sign, double *x, double *v,
                                     struct mech_ode_stats *stats, struct mech_error *err)
{
    const double a = WH_CORR_A1 * h, b = sign * WH_CORR_B31 * h;
    enum mech_status st;
    if ((st = wh_drift(sys, x, v, a, t, err)) != MECH_OK) return st;
    if ((st = wh_kick(sys, nd, t, b, x, v, stats, err)) != MECH_OK) return st;
    if ((st = wh_drift(sys, x, v, -2.0 * a, t, err)) != MECH_OK) return st;
    if ((st = wh_kick(sys, nd, t, -2.0 * b, x, v, stats, err)) != MECH_OK) return st;
    if ((st = wh_drift(sys, x, v, 2.0 * a, t, err)) != MECH_OK) return st;
    return wh_kick(sys, nd, t, b, x, v, stats, err);
}

static enum mech_status wh_corrected_step(void *ws, const struct mech_ode_system *sys, double t,
                                          double h, double *y, struct mech_ode_stats *stats,
                                          struct mech_error *err)
{
    const struct wh_ws *w = ws;
    const size_t nd = w->nd;
    const struct mech_ode_kepler_split *k = sys->kepler;
    if (!k || !k->perturbation)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "wisdom_holman_corrected needs a Kepler split (one "
                              "central_gravity in an inertial frame)");
    if (k->velocity_dependent)
        return mech_error_set(err, MECH_EINVAL, "integrator/method",
                              "wisdom_holman_corrected's correctors need velocity-free "
                              "perturbations (no drag or magnetic force); use wisdom_holman");
    const double a = WH_CORR_A1 * h;
    double x[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    for (size_t i = 0; i < nd; i++) {
        x[i] = y[i] - k->center[i];
        v[i] = y[nd + i];
    }
    enum mech_status st;
    /* C, its last D(-a) merged into the first half drift */
    if ((st = wh_corrector(sys, nd, t, h, 1.0, x, v, stats, err)) != MECH_OK) return st;
    if ((st = wh_drift(sys, x, v, 0.5 * h - a, t, err)) != MECH_OK) return st;
    if ((st = wh_kick(sys, nd, t + 0.5 * h, h, x, v, stats, err)) != MECH_OK) return st;
    /* the second half drift merged with C^-1's first D(a) */
    if ((st = wh_drift(sys, x, v, 0.5 * h + a, t + 0.5 * h, err)) != MECH_OK) return st;
    {
        const double b = -WH_CORR_B31 * h;
        if ((st = wh_kick(sys, nd, t + h, b, x, v, stats, err)) != MECH_OK) return st;
        if ((st = wh_drift(sys, x, v, -2.0 * a, t + h, err)) != MECH_OK) return st;
        if ((st = wh_kick(sys, nd, t + h, -2.0 * b, x, v, stats, err)) != MECH_OK) return st;
        if ((st = wh_drift(sys, x, v, 2.0 * a, t + h, err)) != MECH_OK) return st;
        if ((st = wh_kick(sys, nd, t + h, b, x, v, stats, err)) != MECH_OK) return st;
        if ((st = wh_drift(sys, x, v, -a, t + h, err)) != MECH_OK) return st;
    }
    for (size_t i = 0; i < nd; i++) {
        y[i] = x[i] + k->center[i];
        y[nd + i] = v[i];
    }
    return MECH_OK;
}

const struct mech_integrator mech_integrator_wisdom_holman = {
    .name = "wisdom_holman",
    .order = 2,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_SYMMETRIC |
             MECH_INTEGRATOR_SECOND_ORDER | MECH_INTEGRATOR_KEPLER_SPLIT,
    .doc = "Wisdom-Holman splitting for one body about one central mass with small "
           "perturbations (a third body's tide, a weak uniform field, weak drag): exact Kepler "
           "drifts (universal variables, any conic) of dt/2 around a kick of the other forces "
           "of dt. Fixed step dt, one perturbation evaluation per step, global error "
           "O(eps dt^2) for a perturbation eps times the central force, so it can take "
           "steps far longer than a method that must resolve the orbit itself; with no "
           "perturbation it is the Kepler solution to round-off for any dt. Symplectic and "
           "time-symmetric for velocity-free perturbations: the energy error is bounded, of "
           "order eps (dt/T)^2 for orbital period T, with no secular drift. A "
           "velocity-dependent perturbation (drag, a magnetic force) gets an implicit-midpoint "
           "kick: still symmetric and second order, not symplectic. Needs exactly one "
           "central_gravity in an inertial frame.",
    .reference = "J. Wisdom, M. Holman, Astron. J. 102 (1991) 1528-1538; J. Wisdom, M. Holman, "
                 "J. Touma, Fields Inst. Commun. 10 (1996) 217-244; H. Rein, D. Tamayo, MNRAS "
                 "452 (2015) 376-388 (WHFast).",
    .alloc = wh_alloc,
    .reset = wh_reset,
    .free = wh_free,
    .step = wh_step,
    .evolve = NULL,
};

const struct mech_integrator mech_integrator_wisdom_holman_corrected = {
    .name = "wisdom_holman_corrected",
    .order = 2,
    .flags = MECH_INTEGRATOR_FIXED_STEP | MECH_INTEGRATOR_SYMPLECTIC | MECH_INTEGRATOR_EXPLICIT |
             MECH_INTEGRATOR_SECOND_ORDER | MECH_INTEGRATOR_KEPLER_SPLIT,
    .doc = "wisdom_holman with the third-order symplectic corrector of Wisdom, Holman & Touma "
           "applied around every step: the O(eps dt^2) error of the splitting, a change of "
           "coordinates, is removed, leaving O(eps^2 dt^2 + eps dt^4) for a perturbation eps "
           "times the central force (orders of magnitude smaller when eps is small) at about "
           "4x the cost of a plain step (8 Kepler drifts, 7 perturbation evaluations). "
           "Symplectic, bounded energy error; velocity-free perturbations only (not drag). "
           "Needs exactly one central_gravity in an inertial frame.",
    .reference = "J. Wisdom, M. Holman, J. Touma, Fields Inst. Commun. 10 (1996) 217-244; "
                 "J. Wisdom, M. Holman, Astron. J. 102 (1991) 1528-1538; H. Rein, D. Tamayo, "
                 "MNRAS 452 (2015) 376-388 (corrector coefficients).",
    .alloc = wh_alloc,
    .reset = wh_reset,
    .free = wh_free,
    .step = wh_corrected_step,
    .evolve = NULL,
};
