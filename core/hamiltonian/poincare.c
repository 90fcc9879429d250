/* poincare.c — Poincaré sections by repeated stop events of the ODE driver
 * (see mech/hamiltonian/poincare.h): integrate to the next crossing, record it, restart
 * from it with the event masked at the restart point. Fixed-step runs go in
 * segments of at most 4096 steps (and never more than the budget has left),
 * because the driver refuses up front a fixed-step run longer than its
 * budget, while a section run usually stops long before t_max.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ode/integrators/integrator.h"
#include "mech/hamiltonian/poincare.h"

enum { PC_FIXED_SEGMENT_STEPS = 4096 };

struct pc_ctx {
    const struct mech_ham_ensemble *e;
    const struct mech_poincare_section *sec;
    double dir;     /* +1 / -1: crossing direction (angles: sign of p_c) */
    int masked;     /* 1: g is forced positive at t == t_mask (the restart point) */
    double t_mask;
    struct mech_poincare_result *res;
    struct mech_error *err;
};

static double section_g(const struct pc_ctx *c, const double *y)
{
    const double d = y[c->sec->index] - c->sec->value;
    return c->sec->angle ? c->dir * sin(d) : d;
}

static double pc_event(double t, const double *Y, void *params)
{
    const struct pc_ctx *c = params;
    if (c->masked && t == c->t_mask) return 1.0;
    double y[MECH_HAM_MAX_DIM];
    mech_ham_ensemble_get(c->e, Y, 0, y, 0, NULL);
    return section_g(c, y);
}

static void drift_update(struct mech_ham_drift *d, double x)
{
    const double a = fabs(x - d->initial);
    if (a > d->max_abs) d->max_abs = a;
    d->final = x;
}

static enum mech_status pc_observe(double t, const double *Y, void *params)
{
    (void)t;
    struct pc_ctx *c = params;
    double y[MECH_HAM_MAX_DIM], E;
    mech_ham_ensemble_get(c->e, Y, 0, y, 0, NULL);
    enum mech_status st = mech_ham_energy(c->e->sys, y, &E, c->err);
    if (st != MECH_OK) return st;
    drift_update(&c->res->energy, E);
    for (size_t k = 0; k < c->res->n_conserved; k++)
        drift_update(&c->res->conserved_drift[k],
                     mech_ham_conserved_value(c->e->sys, &c->res->conserved[k], y));
    return MECH_OK;
}

enum mech_status mech_poincare_start(const struct mech_ham_system *system,
                                     const struct mech_poincare_section *sec, double E, double u,
                                     double v, int sign, double *y, struct mech_error *err)
{
    if (!system || !sec || !y)
        return mech_error_set(err, MECH_EINVAL, NULL, "a system and a section are needed");
    struct mech_ham_system s = *system;
    enum mech_status st = mech_ham_system_check(&s, err);
    if (st != MECH_OK) return st;
    const struct mech_ham_system *sys = &s;
    if (sys->dof != 2 || sec->index > 1)
        return mech_error_set(err, MECH_EINVAL, NULL,
                              "a 2-dof system and a coordinate section are needed");
    if (!isfinite(E))
        return mech_error_set(err, MECH_EDOMAIN, "energy", "the energy must be finite");
    const size_t c = sec->index, o = 1 - c;
    y[c] = sec->value;
    y[o] = u;
    y[2 + o] = v;
    y[2 + c] = 0.0;
    double H0;
    if (mech_ham_state_check(sys, y, NULL) != MECH_OK || mech_ham_energy(sys, y, &H0, NULL) != MECH_OK)
        return mech_error_set(err, MECH_EDOMAIN, "section_start",
                              "the point (%.6g, %.6g) on the section is outside the system's "
                              "domain",
                              u, v);
    if (!(E >= H0))
        return mech_error_set(err, MECH_EDOMAIN, "energy",
                              "E = %.17g is below H = %.17g at this point of the section with "
                              "p_%s = 0 (E < V + the other kinetic terms): no real momentum",
                              E, H0, mech_ham_coordinate_name(sys, c));
    /* d2H/dp_c^2 from the tangent equations: d(dq_c) = Hpp[c][c] for dy = e_{p_c} */
    double f[MECH_HAM_MAX_DIM], dv[MECH_HAM_MAX_DIM], ev[MECH_HAM_MAX_DIM] = {0};
    ev[2 + c] = 1.0;
    if ((st = mech_ham_rhs(sys, y, f, ev, dv, err)) != MECH_OK) return st;
    const double Hpp = dv[c];
    if (!(Hpp > 0.0 && isfinite(Hpp)))
        return mech_error_set(err, MECH_EDOMAIN, "section_start",
                              "the kinetic energy is degenerate at this point of the section");
    y[2 + c] = (sign < 0 ? -1.0 : 1.0) * sqrt(2.0 * (E - H0) / Hpp);
    return MECH_OK;
}

enum mech_status mech_poincare_run(const struct mech_poincare_problem *p,
                                   const struct mech_budget *budget,
                                   struct mech_poincare_result *res, struct mech_error *err)
{
    if (!p || !p->sys || !p->y0 || !p->method || !res || !res->t || !res->u || !res->v || !budget)
        return mech_error_set(err, MECH_EINVAL, NULL, "incomplete Poincaré problem");
    struct mech_ham_system sys = *p->sys;
    enum mech_status st = mech_ham_system_check(&sys, err);
    if (st != MECH_OK) return st;
    if (sys.dof != 2)
        return mech_error_set(err, MECH_EINVAL, "system",
                              "a Poincaré section needs 2 degrees of freedom");
    if (p->section.index > 3 || (p->section.angle && p->section.index > 1))
        return mech_error_set(err, MECH_EINVAL, "section",
                              "the section index must be 0..3 (angles: 0 or 1)");
    if (!(p->t_max > 0.0 && isfinite(p->t_max)))
        return mech_error_set(err, MECH_EINVAL, "t_max", "t_max must be finite and > 0");
    if (p->max_crossings == 0)
        return mech_error_set(err, MECH_EINVAL, "max_crossings", "max_crossings must be >= 1");
    if ((st = mech_ham_state_check(&sys, p->y0, err)) != MECH_OK) return st;

    memset(&res->energy, 0, sizeof res->energy);
    res->n_crossings = 0;
    res->t_reached = 0.0;
    res->complete = 0;
    res->max_section_residual = 0.0;
    res->segments = 0;
    res->stats = (struct mech_ode_stats){0, 0, 0};
    double E0;
    if ((st = mech_ham_energy(&sys, p->y0, &E0, err)) != MECH_OK) return st;
    res->energy = (struct mech_ham_drift){E0, E0, 0.0, NAN};
    res->n_conserved = mech_ham_conserved_list(&sys, res->conserved);
    for (size_t k = 0; k < res->n_conserved; k++) {
        const double x = mech_ham_conserved_value(&sys, &res->conserved[k], p->y0);
        res->conserved_drift[k] = (struct mech_ham_drift){x, x, 0.0, NAN};
    }

    struct mech_ham_ensemble e;
    struct mech_ode_system ode;
    if ((st = mech_ham_ensemble_init(&e, &sys, 1, 0, p->method, &ode, err)) != MECH_OK) return st;
    res->second_order = e.second_order;
    struct pc_ctx c = {&e, &p->section, 1.0, 0, 0.0, res, err};
    if (p->section.angle) {
        const double pc = p->y0[2 + p->section.index];
        if (pc == 0.0)
            return mech_error_set(err, MECH_EDOMAIN, "p",
                                  "p_%s = 0: the angle %s never changes, so the orbit never "
                                  "crosses the section",
                                  mech_ham_coordinate_name(&sys, p->section.index),
                                  mech_ham_coordinate_name(&sys, p->section.index));
        c.dir = pc > 0.0 ? 1.0 : -1.0;
    }
    const int fixed = (p->method->flags & MECH_INTEGRATOR_ADAPTIVE) == 0;

    double Y[2 * MECH_HAM_MAX_DIM], Ys[4 * MECH_HAM_MAX_DIM], Ystop[2 * MECH_HAM_MAX_DIM], ts[2];
    mech_ham_ensemble_put(&e, Y, 0, p->y0, NULL);
    double t = 0.0;
    while (res->n_crossings < p->max_crossings && t < p->t_max) {
        struct mech_budget b = *budget;
        b.max_steps = budget->max_steps - res->stats.steps;
        if (b.max_steps <= 0) {
            st = mech_error_set(err, MECH_EBUDGET, NULL,
                                "the step budget (%ld steps) is exhausted at t = %.9g s after %zu "
                                "crossings",
                                budget->max_steps, t, res->n_crossings);
            if (err && err->code == MECH_EBUDGET) {
                err->progress.steps = res->stats.steps;
                err->progress.t_reached = t;
                err->progress.t_target = p->t_max;
            }
            break;
        }
        double t_end = p->t_max;
        if (fixed) {
            const long k = b.max_steps < PC_FIXED_SEGMENT_STEPS ? b.max_steps : PC_FIXED_SEGMENT_STEPS;
            if (t + (double)k * p->opt.dt < t_end) t_end = t + (double)k * p->opt.dt;
        }
        if (!(t_end > t)) break;
        struct mech_ode_problem op = {
            .sys = &ode, .method = p->method, .opt = p->opt, .t0 = t, .t_end = t_end, .y0 = Y,
            .n_samples = 2, .sample_t = ts, .sample_y = Ys, .event = pc_event,
            .event_direction = MECH_ODE_INCREASING, .event_params = &c, .observe = pc_observe,
            .observe_params = &c, .y_stop = Ystop,
        };
        struct mech_ode_result r;
        memset(&r, 0, sizeof r);
        st = mech_ode_solve(&op, &b, &r, err);
        res->segments++;
        res->stats.steps += r.stats.steps;
        res->stats.rejected_steps += r.stats.rejected_steps;
        res->stats.rhs_evaluations += r.stats.rhs_evaluations;
        if (st != MECH_OK) {
            if (err && (st == MECH_EBUDGET || st == MECH_EDEADLINE || st == MECH_ECANCELLED)) {
                err->progress.steps = res->stats.steps;
                err->progress.t_target = p->t_max;
            }
            break;
        }
        if (r.stopped) {
            double y[MECH_HAM_MAX_DIM];
            mech_ham_ensemble_get(&e, Ystop, 0, y, 0, NULL);
            const size_t k = res->n_crossings++, o = 1 - p->section.index % 2;
            res->t[k] = r.t_stop;
            res->u[k] = y[o];
            res->v[k] = y[2 + o];
            if (res->y) memcpy(res->y + 4 * k, y, 4 * sizeof *y);
            res->max_section_residual = fmax(res->max_section_residual, fabs(section_g(&c, y)));
            memcpy(Y, Ystop, ode.dim * sizeof *Y);
            t = r.t_stop;
            c.masked = 1;
            c.t_mask = t;
        } else {
            memcpy(Y, Ys + ode.dim, ode.dim * sizeof *Y);
            t = t_end;
            c.masked = 0;
        }
    }
    res->t_reached = t;
    res->complete = res->n_crossings >= p->max_crossings;
    res->energy.max_rel = E0 != 0.0 ? res->energy.max_abs / fabs(E0) : NAN;
    for (size_t k = 0; k < res->n_conserved; k++) {
        struct mech_ham_drift *d = &res->conserved_drift[k];
        d->max_rel = d->initial != 0.0 ? d->max_abs / fabs(d->initial) : NAN;
    }
    return st;
}
