/* flow.c — POST /v1/hamiltonian/flow: Hamilton's equations for
 * a catalog system (core/hamiltonian/hamiltonian.c) with the energy and the
 * conserved momenta's drift, and beside the run the steady motion at the
 * start (core/hamiltonian/steady_motion.c: the spherical pendulum's conical
 * motion, a central power law's circular orbit) and a central orbit's
 * pericentres and apsidal angle (core/hamiltonian/apsides.c). Physics
 * sources: Goldstein ch. 3 and 8, Taylor ch. 13.
 * Integrators: the shared block through api/ops/hamiltonian/hamiltonian_request.c; without
 * one the symplectic gauss6 at dt = (time scale) / 50. This file parses,
 * calls the core and encodes. */
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "ops/hamiltonian/hamiltonian_request.h"
#include "mech/hamiltonian/apsides.h"
#include "mech/hamiltonian/steady_motion.h"

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

static json_t *conical_json(struct api_call *c, const struct mech_ham_conical *m)
{
    json_t *co = json_object();
    set(co, "theta", api_real(c, m->theta));
    set(co, "phi_dot", api_real(c, m->phi_dot));
    set(co, "p_phi", api_real(c, m->p_phi));
    set(co, "period", m->has_period ? api_real(c, m->period) : json_null());
    set(co, "note",
        json_string("conical motion at this theta: start with p_theta = 0 and this "
                    "p_phi and theta stays constant, phi' = sqrt(g/(l cos theta))"));
    return co;
}

static json_t *circular_json(struct api_call *c, const struct mech_ham_central_circular *m)
{
    json_t *co = json_object();
    set(co, "r", api_real(c, m->r));
    set(co, "p_phi", api_real(c, m->p_phi));
    set(co, "period", api_real(c, m->period));
    set(co, "stable", json_boolean(m->stable));
    return co;
}

static json_t *apsides_json(struct api_call *c, const struct mech_apsides *a)
{
    json_t *o = json_object();
    if (a->radial) {
        set(o, "note", json_string("p_phi = 0: radial motion, no apsides"));
        return o;
    }
    json_t *pc = json_object();
    set(pc, "t", api_reals(c, a->t, a->n));
    set(pc, "r", api_reals(c, a->r, a->n));
    set(pc, "phi", api_reals(c, a->phi, a->n));
    set(o, "pericentres", pc);
    set(o, "apsidal_angle_measured",
        a->has_measured ? api_real(c, a->angle_measured) : json_null());
    set(o, "apsidal_angle_near_circular",
        a->has_near_circular ? api_real(c, a->angle_near_circular) : json_null());
    set(o, "note",
        json_string("pericentres are p_r = 0 crossings upwards, located by "
                    "root-finding with the flow's method; the measured apsidal "
                    "angle is the mean pericentre-to-pericentre angle / 2; "
                    "pi/sqrt(n+2) is its limit for near-circular orbits "
                    "(Goldstein §3.6)"));
    return o;
}

/* t, q and p of the samples */
static void samples_json(struct api_call *c, json_t *out, const struct mech_ham_flow_result *r,
                         size_t n)
{
    const size_t dim = 2 * n;
    set(out, "t", api_reals(c, r->t, r->n_samples));
    json_t *jq = json_array(), *jp = json_array();
    for (size_t i = 0; i < r->n_samples; i++) {
        json_array_append_new(jq, api_reals(c, r->y + i * dim, n));
        json_array_append_new(jp, api_reals(c, r->y + i * dim + n, n));
    }
    set(out, "q", jq);
    set(out, "p", jp);
}

json_t *api_op_hamiltonian_flow(struct api_call *c, const json_t *body)
{
    const json_t *js = json_object_get(body, "system");
    struct mech_ham_system s;
    double y0[MECH_HAM_MAX_DIM];
    if (!api_ham_system_read(c, js, json_array_size(json_object_get(body, "q")), &s)) return NULL;
    if (!api_ham_state_read(c, body, "", &s, y0)) return NULL;
    const double t_end = api_number(body, "t_end", 1.0);
    const size_t ns = (size_t)api_number_of(body, "samples"), dim = 2 * (size_t)s.dof;
    const double tau = mech_ham_time_scale(&s, y0);
    struct api_ham_integ hi;
    const struct mech_ham_flow_problem pp = {.sys = &s, .y0 = y0, .t_end = t_end, .n_samples = 2};
    const struct mech_pilot_system pilot = {mech_ham_pilot_run, (void *)&pp};
    if (!api_ham_integrator_read(c, json_object_get(body, "integrator"), "/integrator", &s, y0, tau,
                                 t_end / tau, "gauss6", 50.0, &pilot, &hi))
        return NULL;
    if (api_dry_run_requested(body)) return api_dry_run_answer(c, api_ham_selection(c, &hi));

    struct mech_ham_flow_result r;
    memset(&r, 0, sizeof r);
    r.t = malloc(ns * sizeof *r.t);
    r.y = malloc(ns * dim * sizeof *r.y);
    struct mech_apsides ap;
    memset(&ap, 0, sizeof ap);
    json_t *out = NULL;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_ham_flow_problem p = {&s, y0, t_end, ns, hi.m, hi.ch.opt};
    enum mech_status st =
        !r.t || !r.y ? mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for %zu samples", ns)
                     : mech_ham_flow(&p, &c->budget, &r, &e);
    if (st == MECH_OK && s.kind == MECH_HAM_CENTRAL)
        st = mech_apsides_find(&s, y0, t_end, hi.m, hi.ch.opt, &c->budget, r.stats.steps, &ap, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
    } else {
        out = json_object();
        set(out, "system", api_ham_system_json(&s, js));
        samples_json(c, out, &r, (size_t)s.dof);
        set(out, "energy", api_ham_drift_json(c, &r.energy));
        set(out, "conserved",
            api_ham_conserved_json(c, &s, r.n_conserved, r.conserved, r.conserved_drift));
        struct mech_ham_conical cm;
        if (mech_ham_conical_motion(&s, y0[0], &cm))
            set(out, "conical_motion", conical_json(c, &cm));
        struct mech_ham_central_circular cc;
        if (mech_ham_central_circular(&s, y0[0], &cc))
            set(out, "circular_orbit", circular_json(c, &cc));
        if (s.kind == MECH_HAM_CENTRAL) set(out, "apsides", apsides_json(c, &ap));
        set(out, "diagnostics", api_ham_diagnostics(c, &hi, &r.stats, r.second_order, tau));
        set(out, "cost", json_object());
    }
    mech_apsides_free(&ap);
    free(r.t);
    free(r.y);
    return out;
}
