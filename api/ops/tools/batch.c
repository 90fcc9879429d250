/* batch.c — POST /v1/batch: several operations in one request, answered
 * in order, each with its own status (see also api/ops/tools/check.c).
 *
 * The items run in-process through api_run_operation(), the same pipeline
 * api_handle() uses, sharing this request's budget: one deadline, one cancel
 * flag. Nesting (/v1/check or /v1/batch inside) is refused, so the work of
 * one request stays bounded by API_BATCH_MAX operations.
 */
#include <stdio.h>
#include <string.h>

#include "run/endpoint.h"
#include "check/grading_nest.h"
#include "http/respond.h"

json_t *api_op_batch(struct api_call *c, const json_t *body)
{
    const json_t *ops = json_object_get(body, "operations");
    json_t *results = json_array();
    if (!results) return NULL;
    size_t i;
    json_t *item;
    json_array_foreach(ops, i, item) {
        const char *op = api_string_of(item, "operation"); /* required */
        char prefix[64];
        snprintf(prefix, sizeof prefix, "/operations/%zu/request", i);
        char opptr[64];
        snprintf(opptr, sizeof opptr, "/operations/%zu/operation", i);
        json_t *res = NULL;
        int st;
        if (api_is_nested_op(op)) {
            res = api_problem_object(API_PROBLEM_VALIDATION, "cannot be nested in a batch");
            json_object_set_new_nocheck(res, "errors",
                                        json_pack("[{s:s,s:s}]", "pointer", opptr, "detail",
                                                  "/v1/check and /v1/batch cannot be "
                                                  "nested in a batch"));
            st = api_problem_status(API_PROBLEM_VALIDATION);
        } else if (c->budget.deadline > 0 && mech_clock_seconds() > c->budget.deadline) {
            c->depends_on_load = 1; /* a partial answer: never cached (api.h) */
            res = api_problem_object(API_PROBLEM_BUDGET,
                                     "the batch's deadline passed before this operation started");
            json_object_set_new_nocheck(
                res, "progress",
                json_pack("{s:i,s:i}", "completed", (int)i, "total", (int)json_array_size(ops)));
            st = api_problem_status(API_PROBLEM_BUDGET);
        } else {
            st = api_run_operation(c, op, json_object_get(item, "request"), prefix, &res);
            if (st < 0) {
                char d[200];
                snprintf(d, sizeof d, "no POST operation at %.120s; GET /v1 lists them", op);
                res = api_problem_object(API_PROBLEM_VALIDATION, d);
                json_object_set_new_nocheck(
                    res, "errors", json_pack("[{s:s,s:s}]", "pointer", opptr, "detail", d));
                st = api_problem_status(API_PROBLEM_VALIDATION);
            }
        }
        if (!res) {
            json_decref(results);
            return NULL;
        }
        if (st != 200) { /* RFC 9457 instance: this item of this batch */
            char inst[96];
            snprintf(inst, sizeof inst, "/v1/batch#/operations/%zu", i);
            json_object_set_new_nocheck(res, "instance", json_string(inst));
        }
        json_array_append_new(results, json_pack("{s:i,s:o}", "status", st,
                                                 st == 200 ? "body" : "problem", res));
    }
    return json_pack("{s:o}", "results", results);
}

