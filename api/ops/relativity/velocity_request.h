/* velocity_request.h — the relativistic `velocity` input shared by every
 * relativity endpoint: exactly one of {"beta": [..]}, {"rapidity": η,
 * "direction": [..]}, {"gamma": γ, "direction": [..]} or {"one_minus_beta": ε,
 * "direction": [..]}, each carrying its own precision into a core
 * struct mech_boost (core/include/mech/relativity/boost.h), and its description in
 * answers (gamma, gamma_minus_one, beta, rapidity, one_minus_beta). */
#ifndef API_VELOCITY_REQUEST_H
#define API_VELOCITY_REQUEST_H

#include "run/endpoint.h"
#include "mech/relativity/boost.h"


/* JSON Schema of a velocity (use as the value of a property). */

/* Build the boost of a schema-validated velocity object `vel`. On success
 * returns 1 and fills *out; on a domain or validation error (|β| ≥ 1, γ < 1,
 * ε outside (0, 2), zero direction) records it at `pointer` + "/" + field
 * ("/velocity/beta") and returns 0. */
int api_velocity_parse(struct api_call *c, const json_t *vel, const char *pointer,
                       struct mech_boost *out);

/* Add gamma, gamma_minus_one, beta (vector), rapidity, one_minus_beta of b
 * to the object `into` (in that order). */
void api_velocity_describe(struct api_call *c, const struct mech_boost *b, json_t *into);

#endif
