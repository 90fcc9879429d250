/* endpoint.h — what a handler file sees of the API layer.
 *
 * An operation's handler is the function its data file
 * api/ops/<domain>/<operation>.json names ("handler": api_op_<path>),
 * defined beside it in api/ops/<domain>/<operation>.c (tests/lint/check_handlers.py);
 * that handler is all the file exports for the operation. The data file
 * holds the rest (path, summary, description, request and response schemas,
 * example, flags), and the build turns it into the route table
 * (scripts/ops_gen.py -> ops.def -> api/run/routes.c). The request-body JSON Schema
 * (a documented subset, see api/schema/schema.h) is enforced before the handler runs, so a handler may assume the types, required keys,
 * ranges and array sizes its schema states; it checks only what a schema
 * cannot say (e.g. |beta| < 1) and reports it with api_call_invalid() /
 * api_call_domain() naming the JSON pointer.
 */
#ifndef API_ENDPOINT_H
#define API_ENDPOINT_H

#include <jansson.h>

#include "api.h"
#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* The envelope: request keys every operation takes, whatever its own schema
 * (docs/design.md, "Envelope"). The route table adds them to the root of every POST route's
 * schema (api_route_schema_add_envelope, api/run/routes.c), so a route's own schema
 * must not declare them at its root; a schema that embeds another
 * operation's request (/v1/compare's "request") uses these texts. */
#define API_ENVELOPE_COST_SCHEMA                                                                \
    "{\"type\":\"boolean\",\"default\":true,\"description\":\"envelope key, taken by "           \
    "every operation: false leaves out the measured time (the cost block of the operations "    \
    "that integrate), so equal requests give byte-identical answers; in a batch, false also "   \
    "applies to every item\"}"

struct api_full_request; /* api/run/api_run.h */

struct api_call {
    struct api_full_request *req; /* the request being run and the pipeline's settings
                                     (api/run/api_run.h); an operation that runs others passes it on */
    struct mech_budget budget;   /* from the request: max_steps, deadline, cancel */
    json_t *errors;              /* [{pointer, detail}] collected so far (owned) */
    enum api_problem problem;    /* set when the call failed */
    char detail[256];            /* problem detail */
    json_t *extra;               /* extra members for the problem (e.g. progress), owned */
    int nonfinite;               /* set when a non-finite number was encoded */
    int no_cost;                 /* the request asked for no measured cost ("cost": false,
                                    or GET ?request=); inner operations inherit it */
    const json_t *given;         /* the body as the client sent it, before the schema's defaults
                                    were filled in (borrowed; the handler's body has them): for
                                    the few handlers that must know whether a key was given
                                    (alternatives such as gm | g0) or echo a block as given; read
                                    it with api_call_given() */
    const json_t *body;          /* the handler's body (defaults filled in; borrowed) */
    int depends_on_load;         /* set by a handler whose answer depended on load or time (an
                                    item or run stopped by the deadline or a budget, a partial
                                    result): the answer is then never cached and gets no ETag
                                    (Cache-Control: no-store), whatever its status */
    int gated;                   /* the request's own operation, run under a cost gate: it
                                    calls api_call_cost_gate once its cost is predicted */
};

/* For an operation that predicts its cost (api_gated_route): ask the
 * request's gate (api_request_ext) whether to go on, once, with the
 * predicted CPU seconds (-1 for unknown). Returns 0 to go on (always, when
 * c is not gated, as for a batch's items), 1 when the gate stopped the
 * request: the handler then returns NULL at once, computing nothing more;
 * the request is answered as deferred. */
int api_call_cost_gate(struct api_call *c, double predicted_cpu_s);

/* Handler: returns a new reference to the result object, or NULL after
 * recording why (validation/domain errors or a failure). Must not leak on
 * either path. */
typedef json_t *(*api_op_fn)(struct api_call *call, const json_t *body);

/* One row of the route table (api/run/routes.c builds them from ops.def). */
struct api_route {
    const char *method;      /* "POST" */
    const char *path;        /* "/v1/rigid/inertia" */
    const char *summary;     /* one line */
    const char *description; /* a paragraph: conventions, units, precision */
    const char *schema;      /* JSON Schema of the request body, as JSON text */
    const char *example;     /* an example request body (JSON text) that succeeds */
    api_op_fn fn;
    int reports_cost;        /* 1: the framework adds cost.cpu_seconds (and honours "cost": false) */
    int quick;               /* 1: closed form, no integration or search loop; its cost grows at
                                most linearly with the body, so a small request may be answered
                                on the server's I/O thread (api_quick_route) */
    const char *response_schema; /* JSON Schema of the 200 answer, as JSON text */
};

/* Every handler's prototype (generated from the api/ops data files by
 * scripts/ops_gen.py), so the compiler checks each definition against it. */
#include "ops_handlers.h"

/* The value at JSON pointer `pointer` ("/integrator", "/runs/2"; "" the
 * root) of the body as the client sent it (c->given), or NULL when it was
 * not given (or c->given is NULL). Borrowed. Use it only to tell a given key
 * from a filled-in default, or to echo a block as given; read values from
 * the handler's body. */
const json_t *api_call_given(const struct api_call *c, const char *pointer);

/* A block to echo in an answer (an integrator block as "requested"): when
 * `value` is the handler's body's value at `pointer`, the same value as the
 * client gave it (without filled-in defaults); otherwise (a block the
 * handler built) `value` itself. Borrowed. */
const json_t *api_call_as_given(const struct api_call *c, const json_t *value,
                                const char *pointer);

/* Record a validation error at a JSON pointer ("/bodies/0/mass"); 422. */
void api_call_invalid(struct api_call *c, const char *pointer, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Record a physics-domain error at a JSON pointer (beta >= 1, r <= 2GM/c^2); 422. */
void api_call_domain(struct api_call *c, const char *pointer, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Map a failed core call to a problem and return NULL. EINVAL/EDOMAIN with a
 * param become errors at pointer_prefix + "/" + param (pointer_prefix may be
 * ""); EBUDGET/EDEADLINE become compute-budget-exceeded with the progress;
 * ECANCELLED -> 503; ENUMERIC -> numerical failure (with errors[] at the param when the
 * core names one); others -> 500. */
json_t *api_call_fail_core(struct api_call *c, enum mech_status st,
                           const struct mech_error *e, const char *pointer_prefix);

/* Out of memory while building an answer: drops `partial` (the answer built so
 * far, may be NULL) and records the 500 as api_call_fail_core does for
 * MECH_ENOMEM. Returns NULL. */
json_t *api_call_out_of_memory(struct api_call *c, json_t *partial);

/* Encoders: new references. A non-finite value encodes as null and sets
 * c->nonfinite, which turns the whole answer into a numerical-failure problem. */
json_t *api_real(struct api_call *c, double x);
json_t *api_vec3(struct api_call *c, struct mech_vec3 v);
json_t *api_mat3(struct api_call *c, struct mech_mat3 m);       /* [[row0],[row1],[row2]] */
json_t *api_reals(struct api_call *c, const double *x, size_t n);

/* Readers for schema-validated input (numbers are JSON reals after parsing;
 * integers are accepted where numbers are). */
double api_number(const json_t *obj, const char *key, double def);   /* def if absent */
struct mech_vec3 api_vec3_of(const json_t *array3);                  /* a [x,y,z] array */
struct mech_vec3 api_vec3_member(const json_t *obj, const char *key, struct mech_vec3 def);
const char *api_string(const json_t *obj, const char *key, const char *def);

/* Readers for a key the handler's body always has: one its schema requires,
 * or one with a "default" (filled in before the handler runs, see
 * api_schema_apply_defaults), so no handler restates a default. Absent (a
 * handler that does not match its schema: a bug) reads as NaN, which every
 * core function refuses, or as "" — never as a silent number. */
double api_number_of(const json_t *obj, const char *key);
const char *api_string_of(const json_t *obj, const char *key);

#endif
