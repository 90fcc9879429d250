/* velocity_request.h — the relativistic `velocity` input shared by every
 * relativity endpoint: exactly one of {"beta": [..]}, {"rapidity": η,
 * "direction": [..]}, {"gamma": γ, "direction": [..]} or {"one_minus_beta": ε,
 * "direction": [..]}, each carrying its own precision into a core
 * struct mech_boost (core/include/mech/boost.h), and its description in
 * answers (gamma, gamma_minus_one, beta, rapidity, one_minus_beta). */
#ifndef API_VELOCITY_REQUEST_H
#define API_VELOCITY_REQUEST_H

#include "endpoint.h"
#include "mech/boost.h"

#define API_VELOCITY_DIR3                                                                          \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\"},"           \
    "\"description\":\"direction of the velocity; any nonzero length\"}"

/* JSON Schema of a velocity (use as the value of a property). */
#define API_VELOCITY_SCHEMA                                                                        \
    "{\"type\":\"object\",\"description\":\"a velocity as exactly one of four forms; give the "  \
    "one that carries the precision you have (near c: rapidity, gamma or one_minus_beta)\","     \
    "\"oneOf\":["                                                                                  \
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"beta\"],"                 \
    "\"properties\":{\"beta\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,"                  \
    "\"items\":{\"type\":\"number\"},\"description\":\"beta = v/c, |beta| < 1\"}}},"               \
    "{\"type\":\"object\",\"additionalProperties\":false,"                                         \
    "\"required\":[\"rapidity\",\"direction\"],\"properties\":{"                                   \
    "\"rapidity\":{\"type\":\"number\",\"minimum\":-350,\"maximum\":350,"                          \
    "\"description\":\"eta = atanh(beta); negative means along -direction\"},"                     \
    "\"direction\":" API_VELOCITY_DIR3 "}},"                                                       \
    "{\"type\":\"object\",\"additionalProperties\":false,"                                         \
    "\"required\":[\"gamma\",\"direction\"],\"properties\":{"                                      \
    "\"gamma\":{\"type\":\"number\",\"maximum\":1e151,"                                            \
    "\"description\":\"Lorentz factor, >= 1\"},"                                                   \
    "\"direction\":" API_VELOCITY_DIR3 "}},"                                                       \
    "{\"type\":\"object\",\"additionalProperties\":false,"                                         \
    "\"required\":[\"one_minus_beta\",\"direction\"],\"properties\":{"                             \
    "\"one_minus_beta\":{\"type\":\"number\",\"description\":\"1 - beta in (0, 2), "               \
    "the precise way to give beta near 1 (e.g. 1e-15); above 1 means beta < 0\"},"                 \
    "\"direction\":" API_VELOCITY_DIR3 "}}"                                                        \
    "]}"

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
