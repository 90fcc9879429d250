/* ep_hamiltonian.c — POST /v1/hamiltonian/flow, /liouville and /poincare:
 * Hamilton's equations for a catalog of systems (core/hamiltonian.c), the
 * phase-space area of a closed curve of initial conditions beside the tangent
 * map's determinant, symplectic and non-symplectic side by side
 * (core/liouville.c), and Poincaré sections with crossings located by
 * root-finding (core/poincare.c). Physics sources: Goldstein ch. 8–9,
 * Taylor ch. 13 (the notes stop before their Hamiltonian chapter).
 *
 * Integrators: the shared block (api/integrator_block.h). Without a block the
 * flow and sections use the symplectic gauss6 at dt = (time scale) / 50 (the
 * time scale is 1 / (small-oscillation rate + coordinate rates) at the start,
 * mech_ham_time_scale), Liouville runs gauss4 at time scale / 20 beside rk4
 * at time scale / 2. Methods that need the second-order form (verlet,
 * yoshida4/6, symplectic_euler, boris, radau15) are accepted for separable
 * H = sum p_i^2/(2 M_i) + V(q) only and refused with a 422 at
 * <block>/method for the others. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "mech/constants.h"
#include "integrator_block.h"
#include "mech/hamiltonian.h"
#include "mech/liouville.h"
#include "mech/poincare.h"
#include "trajectory_request.h"


/* ---- the system ---------------------------------------------------------------- */

static const char *const kind_names[MECH_HAM_KIND_COUNT] = {
    "oscillator", "pendulum", "spherical_pendulum", "cylinder", "central", "henon_heiles",
    "potential_3d"};

static const char *hamiltonian_text(const struct mech_ham_system *s, const char *potential)
{
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR: return "H = sum_i p_i^2/(2m) + k_i q_i^2/2";
    case MECH_HAM_PENDULUM:
        return "H = p_theta^2/(2 m l^2) + m g l (1 - cos theta), theta from the downward vertical";
    case MECH_HAM_SPHERICAL_PENDULUM:
        return "H = p_theta^2/(2 m l^2) + p_phi^2/(2 m l^2 sin^2 theta) + m g l (1 - cos theta), "
               "theta from the downward vertical";
    case MECH_HAM_CYLINDER: return "H = p_z^2/(2m) + p_phi^2/(2 m R^2) + k (R^2 + z^2)/2";
    case MECH_HAM_CENTRAL: return "H = p_r^2/(2m) + p_phi^2/(2 m r^2) + k r^n";
    case MECH_HAM_HENON_HEILES:
        return "H = (p_x^2 + p_y^2)/2 + (x^2 + y^2)/2 + x^2 y - y^3/3 (dimensionless)";
    default:
        if (!strcmp(potential, "harmonic")) return "H = |p|^2/(2m) + (k_x x^2 + k_y y^2 + k_z z^2)/2";
        if (!strcmp(potential, "kepler")) return "H = |p|^2/(2m) - G M m / r";
        return "H = |p|^2/(2m) + k r^n";
    }
}

/* Parse /system (schema-validated) and the dof for the oscillator. */
static int parse_system(struct api_call *c, const json_t *js, size_t n_q,
                        struct mech_ham_system *s)
{
    memset(s, 0, sizeof *s);
    const char *name = api_string(js, "name", "");
    int kind = -1;
    for (int k = 0; k < MECH_HAM_KIND_COUNT; k++)
        if (!strcmp(name, kind_names[k])) kind = k;
    if (kind < 0) {
        api_call_invalid(c, "/system/name", "unknown system \"%s\"", name);
        return 0;
    }
    s->kind = (enum mech_ham_kind)kind;
    s->mass = api_number(js, "mass", 1.0);
    s->length = api_number(js, "length", 1.0);
    s->g = api_number(js, "g", 9.80665);
    s->radius = api_number(js, "radius", 1.0);
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR: {
        const json_t *k = json_object_get(js, "k"), *w = json_object_get(js, "omega");
        if (!k == !w) {
            api_call_invalid(c, "/system", "give exactly one of k (N/m) and omega (rad/s)");
            return 0;
        }
        const json_t *a = k ? k : w;
        if (n_q < 1 || n_q > 2) {
            api_call_invalid(c, "/q", "the oscillator has 1 or 2 degrees of freedom, got %zu", n_q);
            return 0;
        }
        s->dof = (int)n_q;
        if (json_array_size(a) != 1 && json_array_size(a) != n_q) {
            api_call_invalid(c, k ? "/system/k" : "/system/omega",
                             "give one value (isotropic) or one per degree of freedom (%zu)", n_q);
            return 0;
        }
        for (size_t i = 0; i < n_q; i++) {
            const double v = json_number_value(json_array_get(a, json_array_size(a) == 1 ? 0 : i));
            s->k[i] = k ? v : s->mass * v * v;
        }
        break;
    }
    case MECH_HAM_CYLINDER: s->strength = api_number(js, "k", 0.0); break;
    case MECH_HAM_CENTRAL:
        s->strength = api_number(js, "k", 0.0);
        s->power = api_number(js, "n", 0.0);
        break;
    case MECH_HAM_POTENTIAL_3D: {
        const char *pot = api_string(js, "potential", "harmonic");
        if (!strcmp(pot, "harmonic")) {
            s->potential = MECH_HAM_POT_HARMONIC;
            const json_t *k = json_object_get(js, "k");
            for (size_t i = 0; i < 3; i++) s->k[i] = json_number_value(json_array_get(k, i));
        } else if (!strcmp(pot, "kepler")) {
            s->potential = MECH_HAM_POT_POWER;
            s->power = -1.0;
            s->strength = -api_number(js, "gm", 0.0) * s->mass;
        } else {
            s->potential = MECH_HAM_POT_POWER;
            s->strength = api_number(js, "k", 0.0);
            s->power = api_number(js, "n", 0.0);
        }
        break;
    }
    default: break;
    }
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_ham_system_check(s, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        return 0;
    }
    return 1;
}

/* Read (q, p) from obj's "q" and "p" arrays (dof values each) into y. */
static int parse_state(struct api_call *c, const json_t *obj, const char *prefix,
                       const struct mech_ham_system *s, double *y)
{
    const json_t *q = json_object_get(obj, "q"), *p = json_object_get(obj, "p");
    const size_t n = (size_t)s->dof;
    char ptr[96];
    if (json_array_size(q) != n) {
        snprintf(ptr, sizeof ptr, "%s/q", prefix);
        api_call_invalid(c, ptr, "%s has %zu degrees of freedom: q needs %zu values, got %zu",
                         kind_names[s->kind], n, n, json_array_size(q));
        return 0;
    }
    if (json_array_size(p) != n) {
        snprintf(ptr, sizeof ptr, "%s/p", prefix);
        api_call_invalid(c, ptr, "%s has %zu degrees of freedom: p needs %zu values, got %zu",
                         kind_names[s->kind], n, n, json_array_size(p));
        return 0;
    }
    for (size_t i = 0; i < n; i++) {
        y[i] = json_number_value(json_array_get(q, i));
        y[n + i] = json_number_value(json_array_get(p, i));
    }
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_ham_state_check(s, y, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, prefix);
        return 0;
    }
    return 1;
}

static json_t *names_array(const struct mech_ham_system *s, int momenta)
{
    json_t *a = json_array();
    for (size_t i = 0; i < (size_t)s->dof; i++)
        json_array_append_new(a, json_string(momenta ? mech_ham_momentum_name(s, i)
                                                     : mech_ham_coordinate_name(s, i)));
    return a;
}

static json_t *system_info(const struct mech_ham_system *s, const json_t *js)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "name", json_string(kind_names[s->kind]));
    if (s->kind == MECH_HAM_POTENTIAL_3D)
        json_object_set_new_nocheck(o, "potential",
                                    json_string(api_string(js, "potential", "harmonic")));
    json_object_set_new_nocheck(o, "hamiltonian",
                                json_string(hamiltonian_text(s, api_string(js, "potential", ""))));
    json_object_set_new_nocheck(o, "degrees_of_freedom", json_integer(s->dof));
    json_object_set_new_nocheck(o, "coordinates", names_array(s, 0));
    json_object_set_new_nocheck(o, "momenta", names_array(s, 1));
    json_t *cyc = json_array();
    struct mech_ham_conserved cl[MECH_HAM_MAX_CONSERVED];
    const size_t nc = mech_ham_conserved_list(s, cl);
    for (size_t k = 0; k < nc; k++)
        if (cl[k].cyclic) json_array_append_new(cyc, json_string(mech_ham_coordinate_name(s, cl[k].index)));
    json_object_set_new_nocheck(o, "cyclic_coordinates", cyc);
    json_object_set_new_nocheck(o, "separable", json_boolean(mech_ham_separable(s, NULL)));
    return o;
}

/* ---- integrator choice ---------------------------------------------------------- */

struct ham_integ {
    struct api_integrator_choice ch;
    const struct mech_integrator *m;
    int own;          /* 1: our default (no block) or a second-order method we accepted */
    char reason[400];
};

/* The smallest scale among the state's components at y0: for each degree of
 * freedom |q_i|, |p_i| and their dynamical counterparts tau |p_i| / M_i and
 * M_i |q_i| / tau, with M_i = 1 / (d2H/dp_i^2) at y0; 1 if all vanish. */
static double state_scale(const struct mech_ham_system *s, const double *y0, double tau)
{
    const size_t n = (size_t)s->dof;
    double sc = INFINITY;
    for (size_t i = 0; i < n; i++) {
        double f[MECH_HAM_MAX_DIM], dv[MECH_HAM_MAX_DIM], ev[MECH_HAM_MAX_DIM] = {0};
        ev[n + i] = 1.0;
        double M = s->mass;
        if (mech_ham_rhs(s, y0, f, ev, dv, NULL) == MECH_OK && dv[i] > 0.0 && isfinite(dv[i]))
            M = 1.0 / dv[i];
        const double q = fabs(y0[i]), p = fabs(y0[n + i]);
        const double cand[4] = {q, p, tau * p / M, M * q / tau};
        for (int k = 0; k < 4; k++)
            if (cand[k] > 0.0 && isfinite(cand[k]) && cand[k] < sc) sc = cand[k];
    }
    return isfinite(sc) ? sc : 1.0;
}

/* Parse an integrator block for system s: second-order methods for separable
 * systems are accepted here; others go to the shared parser. Without a block:
 * def_method at dt = tau / def_div. Returns 0 after recording an error. */
static int ham_integrator(struct api_call *c, const json_t *block, const char *pointer,
                          const struct mech_ham_system *s, const double *y0, double tau,
                          double span, const char *def_method, double def_div,
                          const struct mech_pilot_system *pilot, struct ham_integ *out)
{
    /* pilot: the flow's hook (mech_ham_pilot_run), NULL elsewhere */
    const struct api_integrator_hooks hooks = {0.0, 0.0, 0.0, pilot};
    memset(out, 0, sizeof *out);
    /* Chosen settings scale atol to the smallest scale of the state's SI
     * components, so a 1e-15 m oscillator is not integrated at atol 1e-13. */
    const struct api_integrator_system hs = {
        "Hamilton's equations q' = dH/dp, p' = -dH/dq",
        "the SI state: the smallest scale of its components (|q_i|, |p_i|, tau |p_i|/M_i, "
        "M_i |q_i|/tau at the start)",
        state_scale(s, y0, tau), 0, 0.0};
    const char *method = block ? api_string(block, "method", NULL) : NULL;
    if (!block) {
        out->own = 1;
        out->ch.method = def_method;
        out->ch.opt.dt = tau / def_div;
        snprintf(out->reason, sizeof out->reason,
                 "no integrator block: %s (%s) at dt = time scale / %g = %.6g s; the time scale "
                 "%.6g s is 1 / (small-oscillation or circular-orbit rate + coordinate rates) at "
                 "the start",
                 def_method,
                 strncmp(def_method, "gauss", 5) ? "not symplectic: shown for contrast"
                                                 : "Gauss-Legendre, symplectic for any H",
                 def_div, out->ch.opt.dt, tau);
    } else if (method) {
        const struct mech_integrator *m = mech_ode_method_find(method);
        if (m && mech_ode_method_describe(m).second_order) {
            char ptr[128];
            snprintf(ptr, sizeof ptr, "%s/method", pointer);
            if (!mech_ham_separable(s, NULL)) {
                api_call_invalid(c, ptr,
                                 "%s needs the second-order form q'' = a(q), which exists only for "
                                 "separable H = sum p_i^2/(2 M_i) + V(q) (oscillator, pendulum, "
                                 "cylinder, henon_heiles, potential_3d); the kinetic energy of "
                                 "%s depends on q: use gauss4 or gauss6 (symplectic for any H), "
                                 "rk4, or an adaptive method",
                                 method, kind_names[s->kind]);
                return 0;
            }
            out->own = 1;
            out->ch.method = method;
            out->ch.requested = api_call_as_given(c, block, pointer);
            out->ch.opt.rtol = api_number(block, "rtol", 1e-10);
            out->ch.opt.atol = api_number(block, "atol", 1e-12);
            out->ch.opt.dt = api_number(block, "dt", 0);
            snprintf(out->reason, sizeof out->reason,
                     "method and settings given in the request; integrated in the second-order "
                     "form (q, v = p/M) of the separable H");
        } else if (!api_integrator_block_parse_hooks(c, block, pointer, span, &hs, NULL, &hooks, &out->ch)) {
            return 0;
        }
    } else if (!api_integrator_block_parse_hooks(c, block, pointer, span, &hs, NULL, &hooks, &out->ch)) {
        return 0;
    }
    out->m = mech_ode_method_find(out->ch.method);
    if (!out->m) {
        api_call_invalid(c, pointer, "unknown method");
        return 0;
    }
    return 1;
}

static json_t *ham_selection(struct api_call *c, const struct ham_integ *hi)
{
    if (!hi->own) return api_integrator_block_selection(c, &hi->ch);
    json_t *sel = json_object();
    json_object_set_new_nocheck(sel, "requested",
                                hi->ch.requested ? json_deep_copy(hi->ch.requested) : json_null());
    json_object_set_new_nocheck(sel, "method", json_string(hi->ch.method));
    if (mech_ode_method_describe(hi->m).adaptive) {
        json_object_set_new_nocheck(sel, "rtol", api_real(c, hi->ch.opt.rtol));
        json_object_set_new_nocheck(sel, "atol", api_real(c, hi->ch.opt.atol));
    } else {
        json_object_set_new_nocheck(sel, "dt", api_real(c, hi->ch.opt.dt));
    }
    if (hi->ch.chosen) json_object_set_new_nocheck(sel, "target_error", api_real(c, hi->ch.target));
    json_object_set_new_nocheck(sel, "reason", json_string(hi->reason));
    return sel;
}

static json_t *ham_diagnostics(struct api_call *c, const struct ham_integ *hi,
                               const struct mech_ode_stats *st, int second_order, double tau)
{
    json_t *d = json_object();
    api_integrator_block_stats(c, d, &hi->ch, st);
    json_object_set_new_nocheck(d, "symplectic",
                                json_boolean(mech_ode_method_describe(hi->m).symplectic));
    json_object_set_new_nocheck(
        d, "form", json_string(second_order ? "second-order (q, v = p/M)" : "first-order (q, p)"));
    json_object_set_new_nocheck(d, "time_scale", api_real(c, tau));
    json_object_set_new_nocheck(d, "selection", ham_selection(c, hi));
    return d;
}

static json_t *real_or_null(struct api_call *c, double x)
{
    return isfinite(x) ? api_real(c, x) : json_null();
}

static json_t *drift_json(struct api_call *c, const struct mech_ham_drift *d)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "initial", api_real(c, d->initial));
    json_object_set_new_nocheck(o, "final", api_real(c, d->final));
    json_object_set_new_nocheck(o, "max_abs_drift", api_real(c, d->max_abs));
    json_object_set_new_nocheck(o, "max_rel_drift", real_or_null(c, d->max_rel));
    return o;
}

static json_t *conserved_json(struct api_call *c, const struct mech_ham_system *s, size_t n,
                              const struct mech_ham_conserved *cl,
                              const struct mech_ham_drift *dr)
{
    json_t *a = json_array();
    for (size_t k = 0; k < n; k++) {
        json_t *o = drift_json(c, &dr[k]);
        json_object_set_new_nocheck(o, "name", json_string(cl[k].name));
        json_object_set_new_nocheck(o, "kind", json_string(cl[k].cyclic ? "cyclic" : "symmetry"));
        json_object_set_new_nocheck(
            o, "coordinate",
            cl[k].cyclic ? json_string(mech_ham_coordinate_name(s, cl[k].index)) : json_null());
        json_array_append_new(a, o);
    }
    return a;
}

/* ---- /v1/hamiltonian/flow ------------------------------------------------------------ */

/* Apsides of a central orbit: pericentres located as p_r = 0 crossings upwards. */
static json_t *apsides(struct api_call *c, const struct mech_ham_system *s, const double *y0,
                       double t_end, const struct ham_integ *hi, long used, int *failed)
{
    enum { MAXP = 1000 };
    json_t *o = json_object();
    if (y0[3] == 0.0) {
        json_object_set_new_nocheck(o, "note", json_string("p_phi = 0: radial motion, no apsides"));
        return o;
    }
    double *buf = malloc(7 * MAXP * sizeof *buf);
    if (!buf) { /* the server's failure (500), never an answer without its apsides */
        struct mech_error e;
        mech_error_clear(&e);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for the apsides");
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        *failed = 1;
        json_decref(o);
        return NULL;
    }
    struct mech_poincare_problem pp = {s, {2, 0.0, 0}, y0, t_end, MAXP, hi->m, hi->ch.opt};
    struct mech_poincare_result pr;
    memset(&pr, 0, sizeof pr);
    pr.t = buf;
    pr.u = buf + MAXP;
    pr.v = buf + 2 * MAXP;
    pr.y = buf + 3 * MAXP;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = c->budget; /* what the flow left */
    b.max_steps -= used;
    enum mech_status st = b.max_steps > 0
                              ? mech_poincare_run(&pp, &b, &pr, &e)
                              : mech_error_set(&e, MECH_EBUDGET, NULL,
                                               "the step budget is exhausted before the apsides "
                                               "are located");
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        *failed = 1;
        free(buf);
        json_decref(o);
        return NULL;
    }
    json_t *jt = json_array(), *jr = json_array(), *jp = json_array();
    for (size_t k = 0; k < pr.n_crossings; k++) {
        json_array_append_new(jt, api_real(c, pr.t[k]));
        json_array_append_new(jr, api_real(c, pr.y[4 * k]));
        json_array_append_new(jp, api_real(c, pr.y[4 * k + 1]));
    }
    json_t *pc = json_object();
    json_object_set_new_nocheck(pc, "t", jt);
    json_object_set_new_nocheck(pc, "r", jr);
    json_object_set_new_nocheck(pc, "phi", jp);
    json_object_set_new_nocheck(o, "pericentres", pc);
    const size_t n = pr.n_crossings;
    json_object_set_new_nocheck(
        o, "apsidal_angle_measured",
        n >= 2 ? api_real(c, (pr.y[4 * (n - 1) + 1] - pr.y[1]) / (2.0 * (double)(n - 1)))
               : json_null());
    json_object_set_new_nocheck(o, "apsidal_angle_near_circular",
                                s->power > -2.0 ? api_real(c, MECH_PI / sqrt(s->power + 2.0))
                                                : json_null());
    json_object_set_new_nocheck(
        o, "note",
        json_string("pericentres are p_r = 0 crossings upwards, located by "
                    "root-finding with the flow's method; the measured apsidal "
                    "angle is the mean pericentre-to-pericentre angle / 2; "
                    "pi/sqrt(n+2) is its limit for near-circular orbits "
                    "(Goldstein §3.6)"));
    free(buf);
    return o;
}

json_t *api_op_hamiltonian_flow(struct api_call *c, const json_t *body)
{
    const json_t *js = json_object_get(body, "system");
    struct mech_ham_system s;
    double y0[MECH_HAM_MAX_DIM];
    if (!parse_system(c, js, json_array_size(json_object_get(body, "q")), &s)) return NULL;
    if (!parse_state(c, body, "", &s, y0)) return NULL;
    const double t_end = api_number(body, "t_end", 1.0);
    const size_t ns = (size_t)api_number_of(body, "samples"), n = (size_t)s.dof, dim = 2 * n;
    const double tau = mech_ham_time_scale(&s, y0);
    struct ham_integ hi;
    const struct mech_ham_flow_problem pp = {.sys = &s, .y0 = y0, .t_end = t_end, .n_samples = 2};
    const struct mech_pilot_system pilot = {mech_ham_pilot_run, (void *)&pp};
    if (!ham_integrator(c, json_object_get(body, "integrator"), "/integrator", &s, y0, tau,
                        t_end / tau, "gauss6", 50.0, &pilot, &hi))
        return NULL;
    if (api_dry_run_requested(body)) return api_dry_run_answer(c, ham_selection(c, &hi));

    double *t = malloc(ns * sizeof *t), *y = malloc(ns * dim * sizeof *y);
    json_t *out = NULL;
    struct mech_error e;
    mech_error_clear(&e);
    if (!t || !y) {
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for %zu samples", ns);
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        goto done;
    }
    struct mech_ham_flow_problem p = {&s, y0, t_end, ns, hi.m, hi.ch.opt};
    struct mech_ham_flow_result r;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.y = y;
    enum mech_status st = mech_ham_flow(&p, &c->budget, &r, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        goto done;
    }
    out = json_object();
    json_object_set_new_nocheck(out, "system", system_info(&s, js));
    json_object_set_new_nocheck(out, "t", api_reals(c, t, r.n_samples));
    json_t *jq = json_array(), *jp = json_array();
    for (size_t i = 0; i < r.n_samples; i++) {
        json_array_append_new(jq, api_reals(c, y + i * dim, n));
        json_array_append_new(jp, api_reals(c, y + i * dim + n, n));
    }
    json_object_set_new_nocheck(out, "q", jq);
    json_object_set_new_nocheck(out, "p", jp);
    json_object_set_new_nocheck(out, "energy", drift_json(c, &r.energy));
    json_object_set_new_nocheck(
        out, "conserved", conserved_json(c, &s, r.n_conserved, r.conserved, r.conserved_drift));
    if (s.kind == MECH_HAM_SPHERICAL_PENDULUM && y0[0] > 0.0 && y0[0] < 0.5 * MECH_PI) {
        /* theta'' = 0: p_phi^2 cos/(m l^2 sin^3) = m g l sin -> phi' = sqrt(g/(l cos theta0)) */
        const double wphi = sqrt(s.g / (s.length * cos(y0[0])));
        const double sn = sin(y0[0]);
        json_t *co = json_object();
        json_object_set_new_nocheck(co, "theta", api_real(c, y0[0]));
        json_object_set_new_nocheck(co, "phi_dot", api_real(c, wphi));
        json_object_set_new_nocheck(co, "p_phi",
                                    api_real(c, s.mass * s.length * s.length * sn * sn * wphi));
        json_object_set_new_nocheck(co, "period",
                                    wphi > 0.0 ? api_real(c, 2.0 * MECH_PI / wphi) : json_null());
        json_object_set_new_nocheck(co, "note",
                                    json_string("conical motion at this theta: start with "
                                                "p_theta = 0 and this p_phi and theta stays "
                                                "constant, phi' = sqrt(g/(l cos theta))"));
        json_object_set_new_nocheck(out, "conical_motion", co);
    }
    if (s.kind == MECH_HAM_CENTRAL) {
        const double Kn = s.strength * s.power, r0 = y0[0];
        if (Kn > 0.0) {
            /* dH/dr = 0 with p_r = 0: p_phi^2 = m k n r^(n+2); period 2 pi m r^2 / p_phi */
            const double pc = sqrt(s.mass * Kn * pow(r0, s.power + 2.0));
            json_t *co = json_object();
            json_object_set_new_nocheck(co, "r", api_real(c, r0));
            json_object_set_new_nocheck(co, "p_phi", api_real(c, pc));
            json_object_set_new_nocheck(co, "period",
                                        api_real(c, 2.0 * MECH_PI * s.mass * r0 * r0 / pc));
            json_object_set_new_nocheck(co, "stable", json_boolean(s.power > -2.0));
            json_object_set_new_nocheck(out, "circular_orbit", co);
        }
        int failed = 0;
        json_t *ap = apsides(c, &s, y0, t_end, &hi, r.stats.steps, &failed);
        if (failed) {
            json_decref(out);
            out = NULL;
            goto done;
        }
        if (ap) json_object_set_new_nocheck(out, "apsides", ap);
    }
    json_object_set_new_nocheck(out, "diagnostics",
                                ham_diagnostics(c, &hi, &r.stats, r.second_order, tau));
    json_object_set_new_nocheck(out, "cost", json_object());
done:
    free(t);
    free(y);
    return out;
}

/* ---- /v1/hamiltonian/liouville ------------------------------------------------------- */

static int read_point(struct api_call *c, const json_t *a, size_t dim, const char *ptr, double *y)
{
    if (json_array_size(a) != dim) {
        api_call_invalid(c, ptr, "a phase-space point of this system has %zu values (q..., p...), "
                                 "got %zu",
                         dim, json_array_size(a));
        return 0;
    }
    for (size_t i = 0; i < dim; i++) y[i] = json_number_value(json_array_get(a, i));
    return 1;
}

/* A core error of run k: "integrator/..." params belong to /integrators/k. */
static void fail_run(struct api_call *c, enum mech_status st, struct mech_error *e, size_t k,
                     int explicit_blocks)
{
    if (!strncmp(e->param, "integrator", 10) && explicit_blocks) {
        char tmp[96];
        snprintf(tmp, sizeof tmp, "integrators/%zu%s", k, e->param + 10);
        snprintf(e->param, sizeof e->param, "%s", tmp);
    } else if (!strncmp(e->param, "integrator", 10)) {
        e->param[0] = 0;
    }
    api_call_fail_core(c, st, e, "");
}

json_t *api_op_hamiltonian_liouville(struct api_call *c, const json_t *body)
{
    const json_t *js = json_object_get(body, "system"), *cv = json_object_get(body, "curve");
    const char *type = api_string(cv, "type", "polygon");
    const int polygon = !strcmp(type, "polygon");
    /* the dof: from the system, or (oscillator) from the curve's points */
    const int cloud = !strcmp(type, "cloud");
    const json_t *pt0 = polygon ? json_array_get(json_object_get(cv, "vertices"), 0)
                        : cloud ? json_array_get(json_object_get(cv, "points"), 0)
                                : json_object_get(cv, "center");
    struct mech_ham_system s;
    if (!parse_system(c, js, json_array_size(pt0) / 2, &s)) return NULL;
    const size_t dim = 2 * (size_t)s.dof;
    const double t_end = api_number(body, "t_end", 1.0);
    const size_t ns = (size_t)api_number_of(body, "samples");

    struct mech_liouville_problem p;
    memset(&p, 0, sizeof p);
    p.sys = &s;
    p.t_end = t_end;
    p.n_samples = ns;
    p.tol = api_number_of(body, "tol");
    p.max_intervals = (size_t)api_number_of(body, "max_intervals");
    double *verts = NULL, ctr[MECH_HAM_MAX_DIM], u[MECH_HAM_MAX_DIM], w[MECH_HAM_MAX_DIM],
           ref[MECH_HAM_MAX_DIM];
    double *buf = NULL;
    json_t *out = NULL, *runs = NULL;
    if (polygon || cloud) {
        const json_t *vs = json_object_get(cv, polygon ? "vertices" : "points");
        p.shape = polygon ? MECH_LIOUVILLE_POLYGON : MECH_LIOUVILLE_CLOUD;
        p.n_vertices = json_array_size(vs);
        verts = malloc(p.n_vertices * dim * sizeof *verts);
        if (!verts) goto nomem;
        for (size_t j = 0; j < p.n_vertices; j++) {
            char ptr[64];
            snprintf(ptr, sizeof ptr, "/curve/%s/%zu", polygon ? "vertices" : "points", j);
            if (!read_point(c, json_array_get(vs, j), dim, ptr, verts + j * dim)) goto done;
        }
        if (cloud && p.n_vertices < dim + 1) {
            api_call_invalid(c, "/curve/points",
                             "a cloud in the %zu-dimensional phase space needs at least %zu points, "
                             "got %zu",
                             dim, dim + 1, p.n_vertices);
            goto done;
        }
        if (polygon && p.max_intervals < p.n_vertices) {
            api_call_invalid(c, "/max_intervals",
                             "max_intervals (%zu) must be at least the number of edges (%zu)",
                             p.max_intervals, p.n_vertices);
            goto done;
        }
        p.vertices = verts;
    } else {
        p.shape = MECH_LIOUVILLE_ELLIPSE;
        if (!read_point(c, json_object_get(cv, "center"), dim, "/curve/center", ctr)) goto done;
        const json_t *sa = json_object_get(cv, "semi_axes");
        const json_t *ju = json_object_get(cv, "u"), *jw = json_object_get(cv, "w");
        if (sa) {
            if (ju || jw || s.dof != 1) {
                api_call_invalid(c, "/curve/semi_axes",
                                 "semi_axes [a, b] (an ellipse with axes along q and p) is for "
                                 "1 degree of freedom and excludes u and w; give u and w "
                                 "otherwise");
                goto done;
            }
            u[0] = json_number_value(json_array_get(sa, 0));
            u[1] = 0.0;
            w[0] = 0.0;
            w[1] = json_number_value(json_array_get(sa, 1));
        } else {
            if (!ju || !jw) {
                api_call_invalid(c, "/curve", "an ellipse needs semi_axes, or u and w");
                goto done;
            }
            if (!read_point(c, ju, dim, "/curve/u", u) || !read_point(c, jw, dim, "/curve/w", w))
                goto done;
        }
        p.center = ctr;
        p.axis_u = u;
        p.axis_w = w;
    }
    const json_t *jr = json_object_get(body, "reference");
    if (jr) {
        if (!read_point(c, jr, dim, "/reference", ref)) goto done;
        p.reference = ref;
    }
    /* time scale at the reference start (the vertex mean / the centre) */
    double y_ref[MECH_HAM_MAX_DIM] = {0};
    if (jr) memcpy(y_ref, ref, dim * sizeof *ref);
    else if (polygon || cloud)
        for (size_t j = 0; j < p.n_vertices; j++)
            for (size_t i = 0; i < dim; i++) y_ref[i] += verts[j * dim + i] / (double)p.n_vertices;
    else memcpy(y_ref, ctr, dim * sizeof *ctr);
    const double tau = mech_ham_time_scale(&s, y_ref);

    const json_t *blocks = json_object_get(body, "integrators");
    const size_t nrun = blocks ? json_array_size(blocks) : 2;
    struct ham_integ hi[2];
    for (size_t k = 0; k < nrun; k++) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/integrators/%zu", k);
        if (!ham_integrator(c, blocks ? json_array_get(blocks, k) : NULL, ptr, &s, y_ref, tau,
                            t_end / tau,
                            k == 0 ? "gauss4" : "rk4", k == 0 ? 20.0 : 2.0, NULL, &hi[k]))
            goto done;
    }
    if (api_dry_run_requested(body)) {
        /* the first block's selection; every block's in selections */
        json_t *sels = json_array();
        for (size_t k = 0; sels && k < nrun; k++) json_array_append_new(sels, ham_selection(c, &hi[k]));
        out = api_dry_run_answer(c, ham_selection(c, &hi[0]));
        if (out) json_object_set_new_nocheck(json_object_get(out, "diagnostics"), "selections", sels);
        else json_decref(sels);
        goto done;
    }
    const size_t per = 6 * ns + ns * dim;
    buf = malloc(nrun * per * sizeof *buf);
    if (!buf) goto nomem;
    struct mech_liouville_result r[2];
    for (size_t k = 0; k < nrun; k++) {
        double *b = buf + k * per;
        memset(&r[k], 0, sizeof r[k]);
        r[k].t = b;
        r[k].area = b + ns;
        r[k].area_bound = b + 2 * ns;
        r[k].vertex_area = b + 3 * ns;
        r[k].det = b + 4 * ns;
        r[k].symplectic_defect = b + 5 * ns;
        r[k].reference_y = b + 6 * ns;
        p.method = hi[k].m;
        p.opt = hi[k].ch.opt;
        struct mech_error e;
        mech_error_clear(&e);
        struct mech_budget bud = c->budget;
        if (k > 0) bud.max_steps -= r[0].stats.steps;
        enum mech_status st = mech_liouville_run(&p, &bud, &r[k], &e);
        if (st != MECH_OK) {
            fail_run(c, st, &e, k, blocks != NULL);
            goto done;
        }
    }
    out = json_object();
    json_object_set_new_nocheck(out, "system", system_info(&s, js));
    json_object_set_new_nocheck(
        out, "measured",
        json_string("A = (1/2) sum_i oint (q_i dp_i - p_i dq_i) over the image of "
                    "the closed curve (Poincare's integral invariant; 1 degree of "
                    "freedom: the enclosed (q, p) area, counter-clockwise "
                    "positive; more: the sum of the oriented areas of the "
                    "projections on the (q_i, p_i) planes). Each edge / arc is "
                    "split into intervals carrying 15 Gauss-Kronrod nodes whose "
                    "orbits are integrated with their tangent vectors "
                    "(variational equations, same method), so the image curve is "
                    "never approximated by a polygon; intervals are halved until "
                    "the summed |Kronrod - Gauss| bound is below tol |A0|. "
                    "vertex_polygon_area: the shoelace area of the vertex images "
                    "(compensated), which changes as the edges bend. The tangent "
                    "map Phi = dy(t)/dy(0) along the reference orbit comes from "
                    "the variational equations with the same method: det Phi = 1 "
                    "is Liouville's theorem, Phi^T J Phi = J symplecticity."));
    if (cloud)
        json_object_set_new_nocheck(
            out, "measured",
            json_string("a cloud: its covariance volume sqrt(det C) (C the "
                        "covariance of the points in phase space; conserved "
                        "exactly by linear volume-preserving maps, C -> A C A^T) "
                        "and, for dim + 1 points, the volume |det(x_i - x_0)|/dim! "
                        "of their simplex. Under a nonlinear flow neither is the "
                        "volume of the image region (they differ at O(cloud size "
                        "/ flow scale)); Liouville's theorem itself is det Phi = 1 "
                        "along the reference orbit (the cloud's mean), from the "
                        "variational equations with the same method."));
    json_object_set_new(out, cloud ? "covariance_volume_initial" : "area_initial",
                        api_real(c, r[0].area0));
    json_object_set_new_nocheck(out, "t", api_reals(c, r[0].t, ns));
    json_object_set_new_nocheck(out, "reference_start", api_reals(c, y_ref, dim));
    runs = json_array();
    for (size_t k = 0; k < nrun; k++) {
        json_t *o = json_object();
        const struct mech_liouville_result *x = &r[k];
        json_object_set_new_nocheck(o, "method", json_string(hi[k].ch.method));
        json_object_set_new_nocheck(o, "symplectic",
                                    json_boolean(mech_ode_method_describe(hi[k].m).symplectic));
        if (cloud) {
            json_object_set_new_nocheck(o, "covariance_volume", api_reals(c, x->area, ns));
            if (p.n_vertices == dim + 1)
                json_object_set_new_nocheck(o, "simplex_volume", api_reals(c, x->vertex_area, ns));
            json_object_set_new_nocheck(o, "max_relative_covariance_volume_drift",
                                        api_real(c, x->max_rel_area_drift));
        } else {
            json_object_set_new_nocheck(o, "area", api_reals(c, x->area, ns));
            json_object_set_new_nocheck(o, "area_quadrature_bound",
                                        api_reals(c, x->area_bound, ns));
            if (polygon)
                json_object_set_new_nocheck(o, "vertex_polygon_area",
                                            api_reals(c, x->vertex_area, ns));
            json_object_set_new_nocheck(o, "max_relative_area_drift",
                                        api_real(c, x->max_rel_area_drift));
        }
        json_object_set_new_nocheck(o, "det_tangent_map", api_reals(c, x->det, ns));
        json_object_set_new_nocheck(o, "symplectic_defect", api_reals(c, x->symplectic_defect, ns));
        json_object_set_new_nocheck(o, "max_det_drift", api_real(c, x->max_det_drift));
        json_object_set_new_nocheck(o, "max_symplectic_defect",
                                    api_real(c, x->max_symplectic_defect));
        if (!cloud) {
            json_object_set_new_nocheck(o, "quadrature_converged", json_boolean(x->converged));
            json_object_set_new_nocheck(o, "max_relative_quadrature_bound",
                                        api_real(c, x->max_area_bound_rel));
            json_object_set_new_nocheck(o, "intervals", json_integer((json_int_t)x->n_intervals));
        }
        json_object_set_new_nocheck(o, "node_trajectories", json_integer(x->trajectories));
        json_t *ro = json_array();
        for (size_t i = 0; i < ns; i++) json_array_append_new(ro, api_reals(c, x->reference_y + i * dim, dim));
        json_object_set_new_nocheck(o, "reference_orbit", ro);
        json_object_set_new_nocheck(o, "diagnostics",
                                    ham_diagnostics(c, &hi[k], &x->stats, x->second_order, tau));
        json_array_append_new(runs, o);
    }
    json_object_set_new_nocheck(out, "runs", runs);
    json_object_set_new_nocheck(out, "cost", json_object());
    goto done;
nomem : {
    struct mech_error e;
    mech_error_clear(&e);
    mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
    api_call_fail_core(c, MECH_ENOMEM, &e, "");
}
done:
    free(verts);
    free(buf);
    return out;
}

/* ---- /v1/hamiltonian/poincare --------------------------------------------------------- */

json_t *api_op_hamiltonian_poincare(struct api_call *c, const json_t *body)
{
    const json_t *js = json_object_get(body, "system"), *orbits = json_object_get(body, "orbits");
    /* the oscillator's dof from the first orbit with q */
    size_t nq = 2;
    struct mech_ham_system s;
    if (!parse_system(c, js, nq, &s)) return NULL;
    if (s.dof != 2) {
        api_call_invalid(c, "/system", "a Poincaré section needs 2 degrees of freedom; %s has %d",
                         kind_names[s.kind], s.dof);
        return NULL;
    }
    /* the section: default x = 0 (Hénon–Heiles, oscillator) or phi = 0 (spherical pendulum,
     * cylinder, central) */
    const json_t *sj = json_object_get(body, "section");
    const char *coord = sj ? api_string(sj, "coordinate", "x")
                           : (s.kind == MECH_HAM_HENON_HEILES || s.kind == MECH_HAM_OSCILLATOR) ? "x"
                                                                                                  : "phi";
    struct mech_poincare_section sec = {0, sj ? api_number(sj, "value", 0.0) : 0.0, 0};
    int found = 0;
    for (size_t i = 0; i < 2; i++)
        if (!strcmp(coord, mech_ham_coordinate_name(&s, i))) {
            sec.index = i;
            found = 1;
        }
    if (!found) {
        api_call_invalid(c, "/section/coordinate", "%s has coordinates %s and %s, not %s",
                         kind_names[s.kind], mech_ham_coordinate_name(&s, 0),
                         mech_ham_coordinate_name(&s, 1), coord);
        return NULL;
    }
    sec.angle = !strcmp(coord, "phi");
    const size_t o = 1 - sec.index;
    const double t_max = api_number(body, "t_max", 1.0);
    const size_t maxc = (size_t)api_number_of(body, "max_crossings");
    const size_t no = json_array_size(orbits);

    /* starts */
    double *y0 = malloc(no * 4 * sizeof *y0);
    double *buf = malloc(7 * maxc * sizeof *buf);
    json_t *out = NULL, *jorb = NULL;
    struct mech_error e;
    mech_error_clear(&e);
    if (!y0 || !buf) {
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        goto done;
    }
    for (size_t k = 0; k < no; k++) {
        const json_t *ok = json_array_get(orbits, k);
        char prefix[48];
        snprintf(prefix, sizeof prefix, "/orbits/%zu", k);
        if (json_object_get(ok, "q")) {
            if (!parse_state(c, ok, prefix, &s, y0 + 4 * k)) goto done;
        } else {
            const json_t *os = json_object_get(ok, "on_section");
            enum mech_status st =
                mech_poincare_start(&s, &sec, api_number(ok, "energy", 0.0),
                                    json_number_value(json_array_get(os, 0)),
                                    json_number_value(json_array_get(os, 1)), 1, y0 + 4 * k, &e);
            if (st != MECH_OK) {
                if (!strcmp(e.param, "section_start")) snprintf(e.param, sizeof e.param, "on_section");
                api_call_fail_core(c, st, &e, prefix);
                goto done;
            }
        }
    }
    const double tau = mech_ham_time_scale(&s, y0);
    struct ham_integ hi;
    if (!ham_integrator(c, json_object_get(body, "integrator"), "/integrator", &s, y0, tau,
                        t_max / tau, "gauss6", 50.0, NULL, &hi))
        goto done;
    if (api_dry_run_requested(body)) {
        out = api_dry_run_answer(c, ham_selection(c, &hi));
        goto done;
    }

    jorb = json_array();
    struct mech_ode_stats total = {0, 0, 0};
    int second_order = 0;
    for (size_t k = 0; k < no; k++) {
        struct mech_poincare_problem pp = {&s, sec, y0 + 4 * k, t_max, maxc, hi.m, hi.ch.opt};
        struct mech_poincare_result r;
        memset(&r, 0, sizeof r);
        r.t = buf;
        r.u = buf + maxc;
        r.v = buf + 2 * maxc;
        r.y = buf + 3 * maxc;
        struct mech_budget b = c->budget;
        b.max_steps -= total.steps;
        mech_error_clear(&e);
        enum mech_status st = b.max_steps > 0 ? mech_poincare_run(&pp, &b, &r, &e)
                                              : mech_error_set(&e, MECH_EBUDGET, NULL,
                                                               "the step budget is exhausted "
                                                               "before orbit %zu",
                                                               k);
        if (st != MECH_OK) {
            api_call_fail_core(c, st, &e, "");
            goto done;
        }
        total.steps += r.stats.steps;
        total.rejected_steps += r.stats.rejected_steps;
        total.rhs_evaluations += r.stats.rhs_evaluations;
        second_order = r.second_order;
        json_t *jo = json_object();
        json_t *st0 = json_object();
        json_object_set_new_nocheck(st0, "q", api_reals(c, y0 + 4 * k, 2));
        json_object_set_new_nocheck(st0, "p", api_reals(c, y0 + 4 * k + 2, 2));
        json_object_set_new_nocheck(jo, "start", st0);
        json_object_set_new_nocheck(jo, "t", api_reals(c, r.t, r.n_crossings));
        json_t *pts = json_array();
        const int wrap = !strcmp(mech_ham_coordinate_name(&s, o), "phi");
        for (size_t i = 0; i < r.n_crossings; i++) {
            double uv[2] = {r.u[i], r.v[i]};
            if (wrap) { /* the plane's angle, reduced to [0, 2 pi) */
                uv[0] = fmod(uv[0], 2.0 * MECH_PI);
                if (uv[0] < 0.0) uv[0] += 2.0 * MECH_PI;
            }
            json_array_append_new(pts, api_reals(c, uv, 2));
        }
        json_object_set_new_nocheck(jo, "points", pts);
        json_object_set_new_nocheck(jo, "crossings", json_integer((json_int_t)r.n_crossings));
        json_object_set_new_nocheck(jo, "complete", json_boolean(r.complete));
        json_object_set_new_nocheck(jo, "t_reached", api_real(c, r.t_reached));
        json_object_set_new_nocheck(jo, "max_section_residual",
                                    api_real(c, r.max_section_residual));
        json_object_set_new_nocheck(jo, "energy", drift_json(c, &r.energy));
        json_object_set_new_nocheck(
            jo, "conserved", conserved_json(c, &s, r.n_conserved, r.conserved, r.conserved_drift));
        json_object_set_new_nocheck(jo, "steps", json_integer(r.stats.steps));
        json_array_append_new(jorb, jo);
    }
    out = json_object();
    json_object_set_new_nocheck(out, "system", system_info(&s, js));
    json_t *sj_out = json_object();
    json_object_set_new_nocheck(sj_out, "coordinate",
                                json_string(mech_ham_coordinate_name(&s, sec.index)));
    json_object_set_new_nocheck(sj_out, "value", api_real(c, sec.value));
    json_object_set_new_nocheck(sj_out, "direction",
                                json_string(sec.angle
                                                ? "in the direction of rotation (sign of p_phi), "
                                                  "phi taken modulo 2 pi"
                                                : "increasing (its momentum > 0)"));
    json_t *plane = json_array();
    json_array_append_new(plane, json_string(mech_ham_coordinate_name(&s, o)));
    json_array_append_new(plane, json_string(mech_ham_momentum_name(&s, o)));
    json_object_set_new_nocheck(sj_out, "plane", plane);
    json_object_set_new_nocheck(out, "section", sj_out);
    json_object_set_new_nocheck(out, "orbits", jorb);
    jorb = NULL;
    json_object_set_new_nocheck(out, "diagnostics",
                                ham_diagnostics(c, &hi, &total, second_order, tau));
    json_object_set_new_nocheck(out, "cost", json_object());
done:
    json_decref(jorb);
    free(y0);
    free(buf);
    return out;
}

