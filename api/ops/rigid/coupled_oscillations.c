/* coupled_oscillations.c — POST /v1/coupled-oscillations: normal modes of
 * M q'' + K q = 0 for given matrices or a standard set-up built from its parts
 * (a chain of masses and springs, the double pendulum, coupled pendulums), and
 * the motion from initial conditions as a sum of modes.
 * JSON <-> core only; the physics is core/hamiltonian/coupled_oscillations.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/hamiltonian/coupled_oscillations.h"

#define NMAX MECH_COUPLED_MAX_DOF
#define SET(o, k, v) json_object_set_new_nocheck((o), (k), (v))

/* Everything one request needs, on the heap (a few tens of kB). */
struct work {
    size_t n;
    double m[NMAX * NMAX], k[NMAX * NMAX];
    char names[NMAX][24];
    struct mech_coupled_modes modes;
    double q0[NMAX], v0[NMAX], a[NMAX], b[NMAX], energy[NMAX], q[NMAX], qd[NMAX];
};

static json_t *fail(struct api_call *c, enum mech_status st, const struct mech_error *e)
{
    return api_call_fail_core(c, st, e, "/system");
}

/* Read an n x n matrix member (rows checked square against the first row's
 * length, or against want when want > 0). Returns its size, 0 after
 * recording a validation error. */
static size_t read_matrix(struct api_call *c, const json_t *s, const char *key, size_t want,
                          double *out)
{
    const json_t *rows = json_object_get(s, key);
    size_t n = json_array_size(rows);
    char ptr[96];
    if (want && n != want) {
        snprintf(ptr, sizeof ptr, "/system/%s", key);
        api_call_invalid(c, ptr, "has %zu rows, the mass matrix %zu: both are n x n", n, want);
        return 0;
    }
    for (size_t i = 0; i < n; i++) {
        const json_t *row = json_array_get(rows, i);
        if (json_array_size(row) != n) {
            snprintf(ptr, sizeof ptr, "/system/%s/%zu", key, i);
            api_call_invalid(c, ptr, "has %zu entries; the matrix has %zu rows and must be square",
                             json_array_size(row), n);
            return 0;
        }
        for (size_t j = 0; j < n; j++) out[i * n + j] = json_number_value(json_array_get(row, j));
    }
    return n;
}

/* Build M and K and the coordinates' names from the system. 0 on failure
 * (recorded). */
static int build(struct api_call *c, const json_t *s, const char *name, struct work *w)
{
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = MECH_OK;
    if (!strcmp(name, "matrices")) {
        if (!(w->n = read_matrix(c, s, "mass_matrix", 0, w->m))) return 0;
        if (!read_matrix(c, s, "stiffness_matrix", w->n, w->k)) return 0;
        for (size_t i = 0; i < w->n; i++) snprintf(w->names[i], sizeof w->names[i], "q%zu", i);
        return 1;
    }
    if (!strcmp(name, "spring_chain")) {
        const json_t *mj = json_object_get(s, "masses"), *sj = json_object_get(s, "springs");
        double masses[NMAX], springs[NMAX + 1];
        size_t n = json_array_size(mj), ns = json_array_size(sj);
        for (size_t i = 0; i < n && i < NMAX; i++)
            masses[i] = json_number_value(json_array_get(mj, i));
        for (size_t i = 0; i < ns && i < NMAX + 1; i++)
            springs[i] = json_number_value(json_array_get(sj, i));
        const char *walls = api_string_of(s, "walls");
        int left = !strcmp(walls, "both") || !strcmp(walls, "left");
        int right = !strcmp(walls, "both") || !strcmp(walls, "right");
        st = mech_coupled_chain(n, masses, springs, ns, left, right, w->m, w->k, &e);
        if (st != MECH_OK) {
            fail(c, st, &e);
            return 0;
        }
        w->n = n;
        for (size_t i = 0; i < n; i++) snprintf(w->names[i], sizeof w->names[i], "x%zu", i);
        return 1;
    }
    if (!strcmp(name, "double_pendulum"))
        st = mech_coupled_double_pendulum(api_number_of(s, "m1"), api_number_of(s, "m2"),
                                          api_number_of(s, "l1"), api_number_of(s, "l2"),
                                          api_number_of(s, "g"), w->m, w->k, &e);
    else {
        double l = api_number_of(s, "length");
        st = mech_coupled_pendulums(api_number_of(s, "mass"), l, api_number_of(s, "k"),
                                    api_number(s, "attach", l), api_number_of(s, "g"), w->m,
                                    w->k, &e);
    }
    if (st != MECH_OK) {
        fail(c, st, &e);
        return 0;
    }
    w->n = 2;
    strcpy(w->names[0], "theta1");
    strcpy(w->names[1], "theta2");
    return 1;
}

static json_t *matrix(struct api_call *c, size_t n, const double *a)
{
    json_t *rows = json_array();
    for (size_t i = 0; rows && i < n; i++) json_array_append_new(rows, api_reals(c, a + i * n, n));
    return rows;
}

static json_t *modes_json(struct api_call *c, const struct mech_coupled_modes *r)
{
    static const char *kinds[] = {"oscillating", "zero", "unstable"};
    json_t *arr = json_array();
    for (size_t p = 0; arr && p < r->n; p++) {
        json_t *m = json_object();
        if (!m) break;
        int osc = r->kind[p] == MECH_MODE_OSCILLATING, uns = r->kind[p] == MECH_MODE_UNSTABLE;
        SET(m, "omega_squared", api_real(c, r->omega2[p]));
        SET(m, "omega", uns ? json_null() : api_real(c, r->omega[p]));
        SET(m, "frequency", uns ? json_null() : api_real(c, r->omega[p] / (2 * MECH_PI)));
        SET(m, "period", osc ? api_real(c, 2 * MECH_PI / r->omega[p]) : json_null());
        SET(m, "growth_rate", uns ? api_real(c, r->growth[p]) : json_null());
        SET(m, "kind", json_string(kinds[r->kind[p]]));
        SET(m, "degenerate", json_boolean(r->degenerate_mode[p]));
        SET(m, "vector", api_reals(c, r->vectors[p], r->n));
        json_array_append_new(arr, m);
    }
    return arr;
}

/* The motion block; NULL after recording a failure. */
static json_t *motion(struct api_call *c, const json_t *init, struct work *w)
{
    size_t n = w->n;
    const json_t *qj = json_object_get(init, "q"), *vj = json_object_get(init, "qdot");
    if (json_array_size(qj) != n) {
        api_call_invalid(c, "/initial/q", "has %zu entries; the system has %zu coordinates",
                         json_array_size(qj), n);
        return NULL;
    }
    if (vj && json_array_size(vj) != n) {
        api_call_invalid(c, "/initial/qdot", "has %zu entries; the system has %zu coordinates",
                         json_array_size(vj), n);
        return NULL;
    }
    for (size_t i = 0; i < n; i++) {
        w->q0[i] = json_number_value(json_array_get(qj, i));
        w->v0[i] = vj ? json_number_value(json_array_get(vj, i)) : 0.0;
    }
    mech_coupled_project(&w->modes, w->m, w->q0, w->v0, w->a, w->b, w->energy);
    double total = 0;
    for (size_t p = 0; p < n; p++) total += w->energy[p];
    json_t *out = json_object(), *samples = json_array();
    if (!out || !samples) {
        json_decref(out);
        json_decref(samples);
        return NULL;
    }
    SET(out, "modal_position", api_reals(c, w->a, n));
    SET(out, "modal_velocity", api_reals(c, w->b, n));
    SET(out, "mode_energies", api_reals(c, w->energy, n));
    SET(out, "energy", api_real(c, total));
    SET(out, "samples", samples);
    const json_t *tj = json_object_get(init, "times");
    for (size_t i = 0; i < json_array_size(tj); i++) {
        double t = json_number_value(json_array_get(tj, i));
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st = mech_coupled_at(&w->modes, w->a, w->b, t, w->q, w->qd, &e);
        if (st != MECH_OK) {
            json_decref(out);
            snprintf(e.param, sizeof e.param, "initial/times/%zu", i);
            api_call_fail_core(c, st, &e, "");
            return NULL;
        }
        json_t *smp = json_object();
        if (!smp) break;
        SET(smp, "t", api_real(c, t));
        SET(smp, "q", api_reals(c, w->q, n));
        SET(smp, "qdot", api_reals(c, w->qd, n));
        json_array_append_new(samples, smp);
    }
    return out;
}

json_t *api_op_coupled_oscillations(struct api_call *c, const json_t *body)
{
    const json_t *s = json_object_get(body, "system");
    const char *name = api_string_of(s, "name");
    struct work *w = malloc(sizeof *w);
    if (!w) {
        struct mech_error e;
        mech_error_clear(&e);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    json_t *out = NULL;
    if (!build(c, s, name, w)) goto done;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_coupled_modes(w->n, w->m, w->k, &w->modes, &e);
    if (st != MECH_OK) {
        fail(c, st, &e);
        goto done;
    }
    const json_t *init = json_object_get(body, "initial");
    json_t *mot = NULL;
    if (init && !(mot = motion(c, init, w))) goto done;
    out = json_object();
    json_t *coords = json_array();
    if (!out || !coords) {
        json_decref(out);
        json_decref(coords);
        json_decref(mot);
        out = NULL;
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        goto done;
    }
    for (size_t i = 0; i < w->n; i++) json_array_append_new(coords, json_string(w->names[i]));
    SET(out, "system", json_string(name));
    SET(out, "coordinates", coords);
    SET(out, "mass_matrix", matrix(c, w->n, w->m));
    SET(out, "stiffness_matrix", matrix(c, w->n, w->k));
    SET(out, "modes", modes_json(c, &w->modes));
    SET(out, "degenerate", json_boolean(w->modes.degenerate));
    SET(out, "zero_modes", json_integer(w->modes.zero_modes));
    SET(out, "stable", json_boolean(w->modes.stable));
    if (mot) SET(out, "motion", mot);
done:
    free(w);
    return out;
}
