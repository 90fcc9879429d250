/* hamiltonian_request.c — the request readers and answer encoders the
 * integrating Hamiltonian operations share (api/ops/hamiltonian/hamiltonian_request.h):
 * the catalog system and its state, the system's description, the
 * integrator block and its selection and diagnostics, the drift objects.
 * The systems and their checks are core/hamiltonian/hamiltonian.c; the
 * state's scale is core/hamiltonian/state_scale.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ops/hamiltonian/hamiltonian_request.h"
#include "mech/hamiltonian/state_scale.h"

/* ---- the system ---------------------------------------------------------------- */

/* The catalog's names, in enum mech_ham_kind's order (the schema's enum). */
static const char *const kind_names[MECH_HAM_KIND_COUNT] = {
    "oscillator", "pendulum",     "spherical_pendulum", "cylinder",
    "central",    "henon_heiles", "potential_3d"};

static const char *hamiltonian_text(const struct mech_ham_system *s, const char *potential)
{
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
        return "H = sum_i p_i^2/(2m) + k_i q_i^2/2";
    case MECH_HAM_PENDULUM:
        return "H = p_theta^2/(2 m l^2) + m g l (1 - cos theta), theta from the downward vertical";
    case MECH_HAM_SPHERICAL_PENDULUM:
        return "H = p_theta^2/(2 m l^2) + p_phi^2/(2 m l^2 sin^2 theta) + m g l (1 - cos theta), "
               "theta from the downward vertical";
    case MECH_HAM_CYLINDER:
        return "H = p_z^2/(2m) + p_phi^2/(2 m R^2) + k (R^2 + z^2)/2";
    case MECH_HAM_CENTRAL:
        return "H = p_r^2/(2m) + p_phi^2/(2 m r^2) + k r^n";
    case MECH_HAM_HENON_HEILES:
        return "H = (p_x^2 + p_y^2)/2 + (x^2 + y^2)/2 + x^2 y - y^3/3 (dimensionless)";
    default:
        if (!strcmp(potential, "harmonic"))
            return "H = |p|^2/(2m) + (k_x x^2 + k_y y^2 + k_z z^2)/2";
        if (!strcmp(potential, "kepler")) return "H = |p|^2/(2m) - G M m / r";
        return "H = |p|^2/(2m) + k r^n";
    }
}

/* Parse /system (schema-validated) and the dof for the oscillator. */
int api_ham_system_read(struct api_call *c, const json_t *js, size_t n_q, struct mech_ham_system *s)
{
    memset(s, 0, sizeof *s);
    const char *name = api_string_of(js, "name");
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
    case MECH_HAM_CYLINDER:
        s->strength = api_number_of(js, "k");
        break;
    case MECH_HAM_CENTRAL:
        s->strength = api_number_of(js, "k");
        s->power = api_number_of(js, "n");
        break;
    case MECH_HAM_POTENTIAL_3D: {
        const char *pot = api_string(js, "potential", "harmonic");
        if (!strcmp(pot, "harmonic")) {
            s->potential = MECH_HAM_POT_HARMONIC;
            const json_t *k = json_object_get(js, "k");
            for (size_t i = 0; i < 3; i++)
                s->k[i] = json_number_value(json_array_get(k, i));
        } else if (!strcmp(pot, "kepler")) {
            s->potential = MECH_HAM_POT_POWER;
            s->power = -1.0;
            s->strength = -api_number_of(js, "gm") * s->mass;
        } else {
            s->potential = MECH_HAM_POT_POWER;
            s->strength = api_number_of(js, "k");
            s->power = api_number_of(js, "n");
        }
        break;
    }
    default:
        break;
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
int api_ham_state_read(struct api_call *c, const json_t *obj, const char *prefix,
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

json_t *api_ham_system_json(const struct mech_ham_system *s, const json_t *js)
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
        if (cl[k].cyclic)
            json_array_append_new(cyc, json_string(mech_ham_coordinate_name(s, cl[k].index)));
    json_object_set_new_nocheck(o, "cyclic_coordinates", cyc);
    json_object_set_new_nocheck(o, "separable", json_boolean(mech_ham_separable(s, NULL)));
    return o;
}

/* ---- integrator choice ---------------------------------------------------------- */

/* Parse an integrator block for system s: second-order methods for separable
 * systems are accepted here; others go to the shared parser. Without a block:
 * def_method at dt = tau / def_div. Returns 0 after recording an error. */
int api_ham_integrator_read(struct api_call *c, const json_t *block, const char *pointer,
                            const struct mech_ham_system *s, const double *y0, double tau,
                            double span, const char *def_method, double def_div,
                            const struct mech_pilot_system *pilot, struct api_ham_integ *out)
{
    /* pilot: the flow's hook (mech_ham_pilot_run), NULL elsewhere */
    const struct api_integrator_hooks hooks = {0.0, 0.0, 0.0, pilot, mech_ham_error_gain(s, y0)};
    memset(out, 0, sizeof *out);
    /* Chosen settings scale atol to the smallest scale of the state's SI
     * components, so a 1e-15 m oscillator is not integrated at atol 1e-13. */
    const struct api_integrator_system hs = {
        "Hamilton's equations q' = dH/dp, p' = -dH/dq",
        "the SI state: the smallest scale of its components (|q_i|, |p_i|, tau |p_i|/M_i, "
        "M_i |q_i|/tau at the start)",
        mech_ham_state_scale(s, y0, tau), 0, 0.0,
        s->kind == MECH_HAM_PENDULUM ? "hamiltonian_pendulum" : "hamiltonian_flow",
        mech_ham_separable(s, NULL)};
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
            out->ch.opt = api_integrator_settings(block);
            snprintf(out->reason, sizeof out->reason,
                     "method and settings given in the request; integrated in the second-order "
                     "form (q, v = p/M) of the separable H");
        } else if (!api_integrator_block_parse_hooks(c, block, pointer, span, &hs, NULL, &hooks,
                                                     &out->ch)) {
            return 0;
        }
    } else if (!api_integrator_block_parse_hooks(c, block, pointer, span, &hs, NULL, &hooks,
                                                 &out->ch)) {
        return 0;
    }
    out->m = mech_ode_method_find(out->ch.method);
    if (!out->m) {
        api_call_invalid(c, pointer, "unknown method");
        return 0;
    }
    return 1;
}

json_t *api_ham_selection(struct api_call *c, const struct api_ham_integ *hi)
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
    if (hi->ch.chosen) json_object_set_new_nocheck(sel, "target_error", api_real(c, hi->ch.mc.target));
    json_object_set_new_nocheck(sel, "reason", json_string(hi->reason));
    return sel;
}

json_t *api_ham_diagnostics(struct api_call *c, const struct api_ham_integ *hi,
                            const struct mech_ode_stats *st, int second_order, double tau)
{
    json_t *d = json_object();
    api_integrator_block_stats(c, d, &hi->ch, st);
    json_object_set_new_nocheck(d, "symplectic",
                                json_boolean(mech_ode_method_describe(hi->m).symplectic));
    json_object_set_new_nocheck(
        d, "form", json_string(second_order ? "second-order (q, v = p/M)" : "first-order (q, p)"));
    json_object_set_new_nocheck(d, "time_scale", api_real(c, tau));
    json_object_set_new_nocheck(d, "selection",
                                hi->own ? api_ham_selection(c, hi)
                                        : api_integrator_block_selection_run(c, &hi->ch, -1.0,
                                                                             NULL, 0));
    return d;
}

static json_t *real_or_null(struct api_call *c, double x)
{
    return isfinite(x) ? api_real(c, x) : json_null();
}

json_t *api_ham_drift_json(struct api_call *c, const struct mech_ham_drift *d)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "initial", api_real(c, d->initial));
    json_object_set_new_nocheck(o, "final", api_real(c, d->final));
    json_object_set_new_nocheck(o, "max_abs_drift", api_real(c, d->max_abs));
    json_object_set_new_nocheck(o, "max_rel_drift", real_or_null(c, d->max_rel));
    return o;
}

json_t *api_ham_conserved_json(struct api_call *c, const struct mech_ham_system *s, size_t n,
                               const struct mech_ham_conserved *cl, const struct mech_ham_drift *dr)
{
    json_t *a = json_array();
    for (size_t k = 0; k < n; k++) {
        json_t *o = api_ham_drift_json(c, &dr[k]);
        json_object_set_new_nocheck(o, "name", json_string(cl[k].name));
        json_object_set_new_nocheck(o, "kind", json_string(cl[k].cyclic ? "cyclic" : "symmetry"));
        json_object_set_new_nocheck(
            o, "coordinate",
            cl[k].cyclic ? json_string(mech_ham_coordinate_name(s, cl[k].index)) : json_null());
        json_array_append_new(a, o);
    }
    return a;
}

const char *api_ham_kind_name(const struct mech_ham_system *s)
{
    return kind_names[s->kind];
}
