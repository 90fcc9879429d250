/* integrator_block.h — the shared `integrator` block for FIRST-ORDER systems
 * (Euler's equations, tops, ...): its schema is the trajectory's
 * (API_TRAJ_INTEGRATOR_SCHEMA of trajectory_request.h, so the block is
 * documented identically), parsed here into a method and settings.
 *
 * - {"method": m, "rtol", "atol"} or {"method": m, "dt"}: used as given, except
 *   that methods flagged second_order in GET /v1/integrators (verlet,
 *   yoshida4/6, symplectic_euler, boris, radau15) need q'' = a(t, q, v) and
 *   are refused with a 422 at <pointer>/method saying why.
 * - {"accuracy": preset} or {"target_error": x} (default accuracy "balanced"):
 *   the loosest preset whose promise meets the target
 *   (mech_accuracy_preset_at()), its `method_other` (rkf45 for draft, rk8pd
 *   otherwise: adaptive, first-order capable) at rtol_other scaled by
 *   min(target / promise, 10), and — as mech_trajectory_choose() does for long
 *   runs — tightened by (20 pi) / span when the run spans more than 20 pi
 *   dynamical times (span = t_end x rate scale), floored at 1e-15;
 *   atol = rtol x the caller's state scale (1 for dimensionless states).
 * Not thread-shared: each call owns its struct api_integrator_choice. */
#ifndef API_INTEGRATOR_BLOCK_H
#define API_INTEGRATOR_BLOCK_H

#include "endpoint.h"
#include "mech/ode.h"

struct api_integrator_choice {
    const char *method;          /* static or borrowed from the block */
    struct mech_ode_options opt; /* rtol, atol; dt in the caller's time unit (s) */
    const json_t *requested;     /* the block (borrowed) or NULL */
    int chosen;                  /* 1: from a preset / target error / the default */
    const char *accuracy;        /* preset name or NULL */
    double target;               /* the relative error aimed at (chosen) */
    char reason[400];
};

/* What the caller integrates, for messages and for atol. */
struct api_integrator_system {
    const char *equations; /* e.g. "Euler's equations with a quaternion attitude" */
    const char *state;     /* e.g. "the dimensionless state (quaternion and omega / rate scale)" */
    double state_scale;    /* atol = rtol x state_scale for chosen settings (> 0) */
};

/* Parse `block` (schema-validated against API_TRAJ_INTEGRATOR_SCHEMA, or NULL
 * for the default) into *out for the system `sys`. `pointer` names the block
 * ("/integrator"), `span` the run's length in dynamical times (>= 0). Returns
 * 0 after recording an error in c (second-order-only method), else 1. */
int api_integrator_block_parse(struct api_call *c, const json_t *block, const char *pointer,
                               double span, const struct api_integrator_system *sys,
                               struct api_integrator_choice *out);

/* {"requested", "method", "rtol", "atol" | "dt", ["target_error"], "reason"}. New reference. */
json_t *api_integrator_block_selection(struct api_call *c, const struct api_integrator_choice *ch);

/* Add "method", "rtol"/"atol" or "dt", "order", "steps", "rejected_steps",
 * "rhs_evaluations" to the object d. */
void api_integrator_block_stats(struct api_call *c, json_t *d,
                                const struct api_integrator_choice *ch,
                                const struct mech_ode_stats *stats);

#endif
