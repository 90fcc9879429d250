/* boost_direct.h — POST /v1/relativity/boost answered straight from the
 * request's bytes, without JSON trees, for the plain request shape (see
 * api/run/boost_direct.c). */
#ifndef API_BOOST_DIRECT_H
#define API_BOOST_DIRECT_H

#include <stddef.h>

#include "api.h"
#include "mech/base/budget.h"

/* Answer the boost request body text (len bytes, need not be NUL-terminated)
 * directly when it has the plain shape: a JSON object whose members are
 * "vectors" (one 4-vector of numbers, or 1..100000 of them), "velocity" as
 * {"beta": [3 numbers]}, and optionally "matrix" and the envelope's "cost"
 * as true/false; keys without escapes, no duplicates, every number inside
 * the schema's bounds (|x| <= 1e150) and read as api_json_read() reads it.
 *
 * Returns 1 with resp filled (status 200, application/json, a malloc()ed body
 * the caller frees with api_response_free) when the boost succeeded: the
 * body is then byte for byte the one the general pipeline (parse, schema,
 * api_op_relativity_boost, api_json_write_compact) writes for the same
 * request. Returns 0 with resp untouched for every other case — another
 * shape, anything the schema or the core would refuse (|beta| >= 1, a
 * non-finite result), a budget, deadline or cancellation stop, memory
 * running out — so that the general pipeline answers it, errors included.
 * budget: the request's (steps, deadline, cancel), one step per vector.
 * Thread-safe. */
int api_boost_direct(const char *text, size_t len, const struct mech_budget *budget,
                     struct api_response *resp);

#endif
