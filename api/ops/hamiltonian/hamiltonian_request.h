/* hamiltonian_request.h — what the Hamiltonian operations that integrate
 * a system share (api/ops/hamiltonian/flow.c, _liouville.c, _poincare.c): the
 * system and state readers, the system's description, the integrator block
 * (second-order methods accepted for separable H; a default method at
 * dt = time scale / divisor without a block), the selection and diagnostics
 * objects, and the energy and conserved-momentum drift objects. */
#ifndef API_EP_HAMILTONIAN_REQUEST_H
#define API_EP_HAMILTONIAN_REQUEST_H

#include "run/endpoint.h"
#include "request/integrator_block.h"
#include "mech/hamiltonian/hamiltonian.h"

/* An integrator chosen for one run. */
struct api_ham_integ {
    struct api_integrator_choice ch;
    const struct mech_integrator *m;
    int own; /* 1: our default (no block) or a second-order method we accepted */
    char reason[400];
};

/* The catalog name of s's kind ("oscillator", ...). Never NULL. */
const char *api_ham_kind_name(const struct mech_ham_system *s);

/* Read /system (schema-validated) into s and check it (mech_ham_system_check);
 * n_q: the oscillator's degrees of freedom (1 or 2), read from the request's
 * q. Returns 1, or 0 after recording the problem (/system/name, /system,
 * /system/k or /system/omega, /q, or the core's field). */
int api_ham_system_read(struct api_call *c, const json_t *js, size_t n_q,
                        struct mech_ham_system *s);

/* Read (q, p) from obj's "q" and "p" arrays (s->dof values each) into y
 * (2 dof values) and check the state (mech_ham_state_check); prefix: obj's
 * JSON pointer ("" for the body). Returns 1, or 0 after recording the problem
 * at <prefix>/q, <prefix>/p or the core's field under prefix. */
int api_ham_state_read(struct api_call *c, const json_t *obj, const char *prefix,
                       const struct mech_ham_system *s, double *y);

/* The answer's "system" object: name, H as text, degrees of freedom,
 * coordinate and momentum names, cyclic coordinates, separability. js: the
 * request's /system. Returns a new reference. */
json_t *api_ham_system_json(const struct mech_ham_system *s, const json_t *js);

/* Parse the integrator block at `pointer` (NULL block: def_method at
 * dt = tau / def_div, tau in s). Second-order methods are accepted for
 * separable systems (refused at <pointer>/method otherwise); the rest go to
 * the shared parser with span t_end / tau and the state's scale at y0
 * (mech_ham_state_scale) as atol's scale. pilot: the chooser's pilot hook
 * for the shared parser (borrowed; mech/ode/chooser_pilot.h), or NULL for none.
 * Returns 1, or 0 after recording the problem. */
int api_ham_integrator_read(struct api_call *c, const json_t *block, const char *pointer,
                            const struct mech_ham_system *s, const double *y0, double tau,
                            double span, const char *def_method, double def_div,
                            const struct mech_pilot_system *pilot, struct api_ham_integ *out);

/* The diagnostics' "selection" object of hi. Returns a new reference. */
json_t *api_ham_selection(struct api_call *c, const struct api_ham_integ *hi);

/* A run's "diagnostics" object: the integrator's statistics, symplectic,
 * the form integrated, the time scale tau (s), the selection. */
json_t *api_ham_diagnostics(struct api_call *c, const struct api_ham_integ *hi,
                            const struct mech_ode_stats *st, int second_order, double tau);

/* The drift object of one invariant: initial, final, max_abs_drift,
 * max_rel_drift (null when not finite). */
json_t *api_ham_drift_json(struct api_call *c, const struct mech_ham_drift *d);

/* The "conserved" array: each conserved momentum's drift with its name,
 * kind (cyclic or symmetry) and cyclic coordinate. */
json_t *api_ham_conserved_json(struct api_call *c, const struct mech_ham_system *s, size_t n,
                               const struct mech_ham_conserved *cl,
                               const struct mech_ham_drift *dr);

#endif
