/* poincare.c — POST /v1/hamiltonian/poincare: Poincaré
 * sections of 2-degree-of-freedom catalog systems (Hénon–Heiles, the
 * spherical pendulum, ...) with crossings located by root-finding
 * (core/hamiltonian/poincare.c; several orbits in one budget in
 * poincare_orbits.c). Physics sources: Hénon & Heiles 1964, Goldstein §11.
 * Integrators: the shared block through api/ops/hamiltonian/hamiltonian_request.c; without
 * one the symplectic gauss6 at dt = (time scale) / 50. This file parses the
 * section and the starts, calls the core and encodes each orbit as the core
 * hands it over. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "ops/hamiltonian/hamiltonian_request.h"
#include "mech/answers/hamiltonian/poincare_orbits.h"

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

/* The section: default x = 0 (Hénon–Heiles, oscillator) or phi = 0 (spherical
 * pendulum, cylinder, central). Returns 0 after recording an error. */
static int read_section(struct api_call *c, const json_t *sj, const struct mech_ham_system *s,
                        struct mech_poincare_section *sec)
{
    const char *coord = sj ? api_string(sj, "coordinate", "x")
                        : (s->kind == MECH_HAM_HENON_HEILES || s->kind == MECH_HAM_OSCILLATOR)
                            ? "x"
                            : "phi";
    *sec = (struct mech_poincare_section){0, sj ? api_number(sj, "value", 0.0) : 0.0, 0};
    int found = 0;
    for (size_t i = 0; i < 2; i++)
        if (!strcmp(coord, mech_ham_coordinate_name(s, i))) {
            sec->index = i;
            found = 1;
        }
    if (!found) {
        api_call_invalid(c, "/section/coordinate", "%s has coordinates %s and %s, not %s",
                         api_ham_kind_name(s), mech_ham_coordinate_name(s, 0),
                         mech_ham_coordinate_name(s, 1), coord);
        return 0;
    }
    sec->angle = !strcmp(coord, "phi");
    return 1;
}

/* Each orbit's start: (q, p), or {energy, on_section: [u, v]}. Returns 0
 * after recording an error. */
static int read_starts(struct api_call *c, const json_t *orbits, const struct mech_ham_system *s,
                       const struct mech_poincare_section *sec, double *y0)
{
    for (size_t k = 0; k < json_array_size(orbits); k++) {
        const json_t *ok = json_array_get(orbits, k);
        char prefix[48];
        snprintf(prefix, sizeof prefix, "/orbits/%zu", k);
        if (json_object_get(ok, "q")) {
            if (!api_ham_state_read(c, ok, prefix, s, y0 + 4 * k)) return 0;
            continue;
        }
        const json_t *os = json_object_get(ok, "on_section");
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st = mech_poincare_start(
            s, sec, api_number(ok, "energy", 0.0), json_number_value(json_array_get(os, 0)),
            json_number_value(json_array_get(os, 1)), 1, y0 + 4 * k, &e);
        if (st != MECH_OK) {
            if (!strcmp(e.param, "section_start")) snprintf(e.param, sizeof e.param, "on_section");
            api_call_fail_core(c, st, &e, prefix);
            return 0;
        }
    }
    return 1;
}

/* The orbits' array, filled as the core hands each orbit over. */
struct orbit_sink {
    struct api_call *c;
    const struct mech_ham_system *s;
    const double *y0;
    json_t *orbits;
};

static int orbit_json(void *ctx, size_t k, const struct mech_poincare_result *r)
{
    struct orbit_sink *o = ctx;
    struct api_call *c = o->c;
    json_t *jo = json_object(), *st0 = json_object(), *pts = json_array();
    set(st0, "q", api_reals(c, o->y0 + 4 * k, 2));
    set(st0, "p", api_reals(c, o->y0 + 4 * k + 2, 2));
    set(jo, "start", st0);
    set(jo, "t", api_reals(c, r->t, r->n_crossings));
    for (size_t i = 0; i < r->n_crossings; i++) {
        const double uv[2] = {r->u[i], r->v[i]};
        json_array_append_new(pts, api_reals(c, uv, 2));
    }
    set(jo, "points", pts);
    set(jo, "crossings", json_integer((json_int_t)r->n_crossings));
    set(jo, "complete", json_boolean(r->complete));
    set(jo, "t_reached", api_real(c, r->t_reached));
    set(jo, "max_section_residual", api_real(c, r->max_section_residual));
    set(jo, "energy", api_ham_drift_json(c, &r->energy));
    set(jo, "conserved",
        api_ham_conserved_json(c, o->s, r->n_conserved, r->conserved, r->conserved_drift));
    set(jo, "steps", json_integer(r->stats.steps));
    json_array_append_new(o->orbits, jo);
    return 0;
}

static json_t *section_json(struct api_call *c, const struct mech_ham_system *s,
                            const struct mech_poincare_section *sec)
{
    const size_t o = 1 - sec->index;
    json_t *sj = json_object(), *plane = json_array();
    set(sj, "coordinate", json_string(mech_ham_coordinate_name(s, sec->index)));
    set(sj, "value", api_real(c, sec->value));
    set(sj, "direction",
        json_string(sec->angle ? "in the direction of rotation (sign of p_phi), "
                                 "phi taken modulo 2 pi"
                               : "increasing (its momentum > 0)"));
    json_array_append_new(plane, json_string(mech_ham_coordinate_name(s, o)));
    json_array_append_new(plane, json_string(mech_ham_momentum_name(s, o)));
    set(sj, "plane", plane);
    return sj;
}

json_t *api_op_hamiltonian_poincare(struct api_call *c, const json_t *body)
{
    const json_t *js = json_object_get(body, "system"), *orbits = json_object_get(body, "orbits");
    struct mech_ham_system s;
    if (!api_ham_system_read(c, js, 2, &s)) return NULL;
    if (s.dof != 2) {
        api_call_invalid(c, "/system", "a Poincaré section needs 2 degrees of freedom; %s has %d",
                         api_ham_kind_name(&s), s.dof);
        return NULL;
    }
    struct mech_poincare_section sec;
    if (!read_section(c, json_object_get(body, "section"), &s, &sec)) return NULL;
    const double t_max = api_number(body, "t_max", 1.0);
    const size_t maxc = (size_t)api_number_of(body, "max_crossings");
    const size_t no = json_array_size(orbits);
    double *y0 = malloc(no * 4 * sizeof *y0);
    json_t *out = NULL;
    struct orbit_sink sink = {c, &s, y0, NULL};
    struct mech_error e;
    mech_error_clear(&e);
    if (!y0) {
        api_call_fail_core(c, mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory"), &e, "");
        goto done;
    }
    if (!read_starts(c, orbits, &s, &sec, y0)) goto done;
    const double tau = mech_ham_time_scale(&s, y0);
    struct api_ham_integ hi;
    if (!api_ham_integrator_read(c, json_object_get(body, "integrator"), "/integrator", &s, y0, tau,
                                 t_max / tau, "gauss6", 50.0, NULL, &hi))
        goto done;
    if (api_dry_run_requested(body)) {
        out = api_dry_run_answer(c, api_ham_selection(c, &hi));
        goto done;
    }
    sink.orbits = json_array();
    struct mech_poincare_problem pp = {&s, sec, NULL, t_max, maxc, hi.m, hi.ch.opt};
    struct mech_poincare_totals tot;
    enum mech_status st =
        mech_poincare_orbits(&pp, y0, no, &c->budget, orbit_json, &sink, &tot, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        goto done;
    }
    out = json_object();
    set(out, "system", api_ham_system_json(&s, js));
    set(out, "section", section_json(c, &s, &sec));
    set(out, "orbits", sink.orbits);
    sink.orbits = NULL;
    set(out, "diagnostics", api_ham_diagnostics(c, &hi, &tot.stats, tot.second_order, tau));
    set(out, "cost", json_object());
done:
    json_decref(sink.orbits);
    free(y0);
    return out;
}
