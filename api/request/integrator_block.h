/* integrator_block.h — the shared `integrator` block for FIRST-ORDER systems
 * (Euler's equations, tops, ...): its schema is the trajectory's
 * (the "integrator" of api/ops/frames/trajectory.json, so the block is
 * documented identically), parsed here into a method and settings.
 *
 * - {"method": m, "rtol", "atol"} or {"method": m, "dt"}: used as given, except
 *   that methods flagged second_order in GET /v1/integrators (verlet,
 *   yoshida4/6, symplectic_euler, boris, radau15) need q'' = a(t, q, v) and
 *   are refused with a 422 at <pointer>/method saying why.
 * - {"accuracy": preset} or {"target_error": x} (default accuracy "balanced"):
 *   the target (a preset's promise), given to the predictive chooser
 *   (mech/ode/chooser.h, class first_order, span = the run in dynamical times):
 *   the cheapest candidate (rk8pd, rkf45; msbdf when stiff) predicted to meet
 *   it, every candidate listed with its predictions in the selection;
 *   atol = rtol x the caller's state scale (1 for dimensionless states).
 * Not thread-shared: each call owns its struct api_integrator_choice. */
#ifndef API_INTEGRATOR_BLOCK_H
#define API_INTEGRATOR_BLOCK_H

#include "run/endpoint.h"
#include "mech/ode/chooser.h"
#include "mech/ode/chooser_pilot.h"
#include "mech/ode/method_choice.h"
#include "mech/ode/ode.h"

struct api_integrator_choice {
    const char *method;          /* static or borrowed from the block */
    struct mech_ode_options opt; /* rtol, atol; dt in the caller's time unit (s) */
    const json_t *requested;     /* the block (borrowed) or NULL */
    int chosen;                  /* 1: from a preset / target error / the default */
    const char *accuracy;        /* preset name or NULL */
    struct mech_method_choice mc; /* when chosen: core's choice (mech/ode/method_choice.h):
                                    target, reason, the chooser's candidates, closed_form
                                    (method/opt above stay the best integrator's), the
                                    pilot, whose steps were taken off c->budget.max_steps */
};

/* What the caller integrates, for messages and for atol. */
struct api_integrator_system {
    const char *equations; /* e.g. "Euler's equations with a quaternion attitude" */
    const char *state;     /* e.g. "the dimensionless state (quaternion and omega / rate scale)" */
    double state_scale;    /* atol = rtol x state_scale for chosen settings (> 0) */
    size_t samples;        /* samples written (each costs a sub-step); 0 if unknown */
    double rhs_cost_s;     /* CPU s of one right-hand side if known, else 0 */
    const char *rows;      /* the chooser's rows for this operation (mech_scene_profile.rows;
                              static), NULL: the first_order class's */
    int second_order;      /* 1: the system also has the form q'' = a(q) (separable
                              Hamiltonians), so radau15 is a candidate */
};

/* The settings of a block that names a method: rtol and atol (for an
 * adaptive method the schema fills their defaults) and dt (required for a
 * fixed-step method); each 0 when the block does not carry it, i.e. when the
 * method does not use it. block may be NULL (all 0). */
struct mech_ode_options api_integrator_settings(const json_t *block);

/* Parse `block` (schema-validated against that integrator schema, or NULL
 * for the default) into *out for the system `sys`. `pointer` names the block
 * ("/integrator"), `span` the run's length in dynamical times (>= 0). Returns
 * 0 after recording an error in c (second-order-only method), else 1. */
int api_integrator_block_parse(struct api_call *c, const json_t *block, const char *pointer,
                               double span, const struct api_integrator_system *sys,
                               struct api_integrator_choice *out);

/* The same for a system that has a closed form (closed_form_name, static,
 * e.g. "torque-free rigid body"; NULL: none): the chooser lists it as the
 * candidate "closed_form" and chooses it, when the block does not say
 * "closed_form": false, if it is predicted cheaper (its cost grows with the
 * samples only); out->closed_form says so. */
int api_integrator_block_parse_cf(struct api_call *c, const json_t *block, const char *pointer,
                                  double span, const struct api_integrator_system *sys,
                                  const char *closed_form_name,
                                  struct api_integrator_choice *out);

/* Optional cost-model hooks of a system (zero / NULL: the class's table
 * alone). */
struct api_integrator_hooks {
    double cost_span;      /* the run in the cost law's units when the span overstates or
                              understates the work (the heavy top: mech_top_cost_span) */
    double closed_form_evaluations;  /* the closed form's predicted evaluations (0: one
                                        per sample) and CPU s of one (0: the default) */
    double closed_form_cpu_per_eval;
    const struct mech_pilot_system *pilot; /* a short pilot run of the system when the
                              prediction is uncertain and expensive (mech/ode/chooser_pilot.h;
                              borrowed for the call); NULL: none. Never run for dry runs
                              ("dry_run": true in c->body). */
    double error_gain;     /* mech_scene_profile.error_gain (0: 1): light near the photon
                              sphere (mech_geodesic_error_gain) */
};

/* api_integrator_block_parse_cf with the hooks (NULL: none). */
int api_integrator_block_parse_hooks(struct api_call *c, const json_t *block, const char *pointer,
                                     double span, const struct api_integrator_system *sys,
                                     const char *closed_form_name,
                                     const struct api_integrator_hooks *hooks,
                                     struct api_integrator_choice *out);

/* {"requested", "method", "rtol", "atol" | "dt", ["target_error"], "reason",
 * and when chosen scene_class, span, model, candidates}. New reference. */
json_t *api_integrator_block_selection(struct api_call *c, const struct api_integrator_choice *ch);

/* The selection of a run that was integrated: with selection.achieved when
 * the method was chosen by accuracy, its error the measured `error` (< 0:
 * none measured) with its `evidence`, else the calibrated law's prediction at
 * the setting run (the chooser's rows, measured on the operation's own
 * scene), the evidence saying it is a prediction; at_least_law: `error` is
 * a lower bound (an invariant's error, which can cancel) and the larger of it
 * and the law is reported. New reference. */
json_t *api_integrator_block_selection_run(struct api_call *c,
                                           const struct api_integrator_choice *ch, double error,
                                           const char *evidence, int at_least_law);

/* The same with selection.achieved (when chosen and cpu_s >= 0): the
 * achieved relative error (< 0: unknown) and its evidence (NULL: none). */
json_t *api_integrator_block_selection_achieved(struct api_call *c,
                                                const struct api_integrator_choice *ch,
                                                double error, const char *evidence,
                                                double cpu_s);

/* Add "method", "rtol"/"atol" or "dt", "order", "steps", "rejected_steps",
 * "rhs_evaluations" to the object d. */
void api_integrator_block_stats(struct api_call *c, json_t *d,
                                const struct api_integrator_choice *ch,
                                const struct mech_ode_stats *stats);

/* "dry_run": true in the request body. */
int api_dry_run_requested(const json_t *body);

/* The answer of a dry run: {"dry_run": true, "diagnostics": {"steps": 0,
 * "rhs_evaluations": 0, "selection": selection}} (selection stolen). New
 * reference, or NULL after recording an allocation failure. */
json_t *api_dry_run_answer(struct api_call *c, json_t *selection);

/* The chooser's predictions into the object `into`: scene_class, span, model,
 * roundoff_floor, candidates [{method, settings, predicted_error,
 * predicted_evaluations, predicted_cpu_s, verdict, why}]. Returns into. */
json_t *api_selection_predictions(struct api_call *c, const struct mech_selection *sel,
                                  json_t *into);

/* selection.achieved: the achieved error (< 0: unknown, then null) with its
 * evidence beside the chosen candidate's prediction, met_target,
 * within_prediction (achieved <= 30 x predicted), predicted_cpu_s (the
 * measured CPU is the answer's cost.cpu_seconds; cpu_s is unused) and a note
 * that says a miss.
 * New reference. */
json_t *api_selection_achieved(struct api_call *c, const struct mech_candidate *pred,
                               double target, double error, const char *evidence,
                               double cpu_s);

#endif
