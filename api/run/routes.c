/* routes.c — the route table: every operation mechd serves, expanded from
 * the generated ops.def (one line per api/ops/<domain>/<operation>.json, see
 * scripts/ops_gen.py). The catalog (GET /v1), the OpenAPI document and the
 * README's endpoint table all come from these entries. To add an operation,
 * write its data file, not C here. The envelope keys
 * (api_envelope_properties) are added here to every POST route's schema. */
#include "run/routes.h"

#include <stdio.h>

/* Each operation's data file (api/ops/<domain>/<operation>.json) becomes one
 * API_OP(handler, method, path, summary, description, request_schema,
 * example, reports_cost, quick, response_schema) line of ops.def, which
 * scripts/ops_gen.py generates in the build tree; the handler is the one
 * symbol the operation's C file exports (its prototype is in
 * ops_handlers.h, also generated). */
#define API_OP(fn_, method_, path_, summary_, description_, schema_, example_, cost_, quick_,   \
               response_)                                                                       \
    static const struct api_route route_##fn_ = {                                              \
        .method = method_,                                                                     \
        .path = path_,                                                                         \
        .summary = summary_,                                                                   \
        .description = description_,                                                           \
        .schema = schema_,                                                                     \
        .example = example_,                                                                   \
        .fn = fn_,                                                                             \
        .reports_cost = cost_,                                                                 \
        .quick = quick_,                                                                       \
        .response_schema = response_,                                                          \
    };
#include "ops.def"
#undef API_OP

/* In api/ops/catalog_order.json's order: the catalog's and OpenAPI's. */
const struct api_route *const api_routes[] = {
#define API_OP(fn_, ...) &route_##fn_,
#include "ops.def"
#undef API_OP
};
const size_t api_route_count = sizeof api_routes / sizeof api_routes[0];

const char api_envelope_properties[] = "{\"cost\":" API_ENVELOPE_COST_SCHEMA "}";

int api_route_schema_add_envelope(json_t *schema, char *msg, size_t n)
{
    json_t *props = json_object_get(schema, "properties");
    if (!json_is_object(props)) {
        snprintf(msg, n, "the root schema has no properties to add the envelope keys to");
        return -1;
    }
    json_t *env = json_loads(api_envelope_properties, 0, NULL);
    if (!env) {
        snprintf(msg, n, "out of memory (or a broken envelope text)");
        return -1;
    }
    const char *key;
    json_t *val;
    json_object_foreach(env, key, val) {
        if (json_object_get(props, key)) {
            snprintf(msg, n, "declares the envelope key '%s' at its root; the route table adds it",
                     key);
            json_decref(env);
            return -1;
        }
        if (json_object_set(props, key, val)) {
            snprintf(msg, n, "out of memory");
            json_decref(env);
            return -1;
        }
    }
    json_decref(env);
    return 0;
}
