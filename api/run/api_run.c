/* api_run.c — an operation's request run: its media type and JSON body
 * (api_run_post), then the pipeline every operation shares, also for the
 * items of /v1/batch and /v1/check (api_run_operation): schema validation,
 * the answer budget (api/run/api_samples.c), the defaults filled in, the handler, the
 * non-finite check, cost accounting, and the problem+json of each failure. */
#include "run/api_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "json/api_alloc.h"
#include "run/api_init.h"
#include "run/api_samples.h"
#include "run/boost_direct.h"
#include "json/json_arena.h"
#include "json/json_read.h"
#include "http/respond.h"
#include "run/routes.h"
#include "schema/schema.h"

static int request_no_cost(const struct api_full_request *req)
{
    return req ? req->no_cost : 0;
}

static long request_max_samples(const struct api_full_request *req)
{
    return req ? req->max_samples : API_DEFAULT_MAX_SAMPLES;
}

/* Copy of `errors` with every pointer prefixed (new reference). */
static json_t *prefixed_errors(const json_t *errors, const char *prefix)
{
    json_t *out = json_array();
    size_t i;
    json_t *e;
    json_array_foreach(errors, i, e) {
        json_t *c = json_deep_copy(e);
        const char *p = json_string_value(json_object_get(e, "pointer"));
        if (c && p && prefix && *prefix) {
            size_t n = strlen(prefix) + strlen(p) + 1;
            char *q = malloc(n);
            if (q) {
                snprintf(q, n, "%s%s", prefix, p);
                json_object_set_new_nocheck(c, "pointer", json_string(q));
                free(q);
            }
        }
        json_array_append_new(out, c);
    }
    return out;
}

static json_t *problem_json(enum api_problem kind, const char *detail, const json_t *errors,
                            const json_t *extra)
{
    json_t *p = api_problem_object(kind, detail);
    if (p && errors) json_object_set(p, "errors", (json_t *)errors);
    if (p && extra) json_object_update(p, (json_t *)extra);
    return p;
}

/* Whether a problem kind says the answer depended on load or time. */
static int problem_depends_on_load(enum api_problem k)
{
    return k == API_PROBLEM_BUDGET || k == API_PROBLEM_CANCELLED || k == API_PROBLEM_QUEUE_FULL ||
           k == API_PROBLEM_ANSWER_MEMORY;
}

/* The pipeline after parsing: schema validation, the answer budget, the
 * handler, the non-finite check, cost accounting. Returns the HTTP status and
 * sets *out to the answer or the problem object (new reference; NULL only
 * when memory ran out). Error pointers are prefixed with prefix ("" at top
 * level). note gets the reason of a 500 for the log. no_cost: an enclosing
 * request (a batch) asked for no measured cost. *dep is set to 1 when the
 * outcome depended on load or time (the handler said so, or a budget,
 * deadline or cancellation stopped it), else left alone. */
int api_run_parsed(size_t ri, struct api_full_request *req, const json_t *body, const char *prefix,
                   int no_cost, json_t **out, char *note, size_t note_n, int *dep)
{
    const struct api_route *r = api_routes[ri];
    const struct api_schema *compiled = api_route_schema_compiled(ri);
    *out = NULL;
    /* Count first: a valid body (the usual case) then costs no error
     * pointers. Zero counted means zero listed (the modes differ only past
     * API_SCHEMA_MAX_ERRORS); for an invalid body the listing run's count is
     * the one reported, as before. */
    size_t nerr = api_schema_validate(compiled, body, prefix, NULL);
    if (nerr) {
        json_t *errors = json_array();
        nerr = api_schema_validate(compiled, body, prefix, errors);
        char d[120];
        snprintf(d, sizeof d, "%zu error%s in the request", nerr, nerr == 1 ? "" : "s");
        *out = problem_json(API_PROBLEM_VALIDATION, d, errors, NULL);
        json_decref(errors);
        return api_problem_status(API_PROBLEM_VALIDATION);
    }
    long cap = request_max_samples(req);
    json_t *too_large = api_answer_budget_problem(ri, body, prefix, cap);
    if (too_large) {
        *out = too_large;
        return api_problem_status(API_PROBLEM_ANSWER_TOO_LARGE);
    }
    /* Admission (the server's answer-memory budget): once, for the request's
     * own operation, before anything is computed. */
    if (req && req->admit_pending) {
        req->admit_pending = 0;
        if (req->admit(req->admit_ctx, (long)ri, api_answer_samples(ri, body))) {
            *out = problem_json(API_PROBLEM_ANSWER_MEMORY,
                                "the server holds as much answer memory as it may "
                                "(--max-answer-memory) for answers still being sent; retry later",
                                NULL, NULL);
            *dep = 1;
            return api_problem_status(API_PROBLEM_ANSWER_MEMORY);
        }
    }

    /* The handler sees the body with its schema's defaults filled in (a
     * copy; the caller's body is left as it is), so no handler restates a
     * default. The envelope keys are the framework's and stay as given. */
    static const char *const envelope_keys[] = {"cost", NULL};
    json_t *full = api_schema_apply_defaults(compiled, body, envelope_keys);
    if (!full) {
        if (note) snprintf(note, note_n, "%.40s: out of memory filling defaults", r->path);
        *out = problem_json(API_PROBLEM_INTERNAL, "internal error", NULL, NULL);
        return api_problem_status(API_PROBLEM_INTERNAL);
    }

    struct api_call call;
    memset(&call, 0, sizeof call);
    call.req = req;
    call.given = body;
    call.body = full;
    call.budget.max_steps = req->req.max_steps > 0 ? req->req.max_steps : 1;
    call.budget.deadline = isfinite(req->req.deadline) ? req->req.deadline : 0;
    call.budget.cancel = req->req.cancel;
    call.gated = req->gate_armed; /* only the request's own operation is gated */
    req->gate_armed = 0;
    int want_cost =
        !no_cost && !request_no_cost(req) && !json_is_false(json_object_get(body, "cost"));
    call.no_cost = !want_cost;

    /* The thread CPU clock is a system call, not a vDSO read: only for routes
     * that report it. */
    double cpu0 = r->reports_cost ? mech_cpu_seconds() : 0.0;
    json_t *result = r->fn(&call, full);
    double cpu = r->reports_cost ? mech_cpu_seconds() - cpu0 : 0.0;
    json_decref(full);
    if (req->deferred) { /* the gate stopped it: nothing to answer */
        json_decref(result);
        json_decref(call.errors);
        json_decref(call.extra);
        return 0;
    }

    if (result && call.problem == API_PROBLEM_NONE && call.nonfinite) {
        call.problem = API_PROBLEM_NUMERIC;
        snprintf(call.detail, sizeof call.detail,
                 "the result is not finite for this input (overflow or a singularity)");
    }
    if (call.depends_on_load || problem_depends_on_load(call.problem)) *dep = 1;
    if (!result || call.problem != API_PROBLEM_NONE) {
        enum api_problem k = call.problem != API_PROBLEM_NONE ? call.problem : API_PROBLEM_INTERNAL;
        char d[300];
        if (call.errors && json_array_size(call.errors)) {
            size_t n = json_array_size(call.errors);
            snprintf(d, sizeof d, "%s", n == 1 ? json_string_value(json_object_get(
                                                     json_array_get(call.errors, 0), "detail"))
                                               : "several fields are invalid");
        } else {
            snprintf(d, sizeof d, "%s", call.detail[0] ? call.detail : "internal error");
        }
        if (k == API_PROBLEM_INTERNAL) {
            *out = problem_json(k, "internal error", NULL, NULL);
            if (note)
                snprintf(note, note_n, "%.40s: %.150s", r->path,
                         call.detail[0] ? call.detail : "handler returned no result");
        } else {
            json_t *pe = call.errors ? prefixed_errors(call.errors, prefix) : NULL;
            *out = problem_json(k, d, pe, call.extra);
            json_decref(pe);
        }
        json_decref(result);
        json_decref(call.errors);
        json_decref(call.extra);
        return api_problem_status(k);
    }
    json_decref(call.errors);
    json_decref(call.extra);

    if (r->reports_cost) {
        if (want_cost) {
            json_t *cost = json_object_get(result, "cost");
            if (!json_is_object(cost)) {
                cost = json_object();
                json_object_set_new_nocheck(result, "cost", cost);
            }
            if (cost) json_object_set_new_nocheck(cost, "cpu_seconds", json_real(cpu));
        } else {
            json_object_del(result, "cost");
        }
    }
    *out = result;
    return 200;
}

int api_run_operation(struct api_call *outer, const char *path, const json_t *request,
                      const char *pointer_prefix, json_t **out)
{
    *out = NULL;
    long ri = path ? api_route_index(path) : -1;
    if (ri < 0 || strcmp(api_routes[ri]->method, "POST") != 0 || !outer || !outer->req) return -1;
    char note[200];
    note[0] = '\0';
    int dep = 0;
    int status = api_run_parsed((size_t)ri, outer->req, request, pointer_prefix ? pointer_prefix : "",
                            outer->no_cost, out, note, sizeof note, &dep);
    if (dep) outer->depends_on_load = 1;
    if (!*out) {
        *out = problem_json(API_PROBLEM_INTERNAL, "internal error", NULL, NULL);
        status = 500;
    }
    return status;
}

/* Serialise an outcome of run_parsed into resp (consumes `out`). */
void api_respond_outcome(struct api_response *resp, int status, json_t *out, const char *note)
{
    if (!out) {
        api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
    } else {
        api_respond_json(resp, status, status == 200 ? "application/json"
                                                      : "application/problem+json", out);
        json_decref(out);
        if (status == 503) resp->retry_after = 1;
    }
    if (note && note[0]) snprintf(resp->note, sizeof resp->note, "%s", note);
}

/* A parse that failed for lack of memory is the server's failure, not a
 * malformed body: answer 500 (return 1, resp filled) instead of 400. */
int api_parse_out_of_memory(const json_error_t *jerr, struct api_response *resp)
{
    if (json_error_code(jerr) != json_error_out_of_memory) return 0;
    api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
    snprintf(resp->note, sizeof resp->note, "out of memory while parsing the request");
    return 1;
}

/* Media type equals application/json, ignoring case, parameters and spaces. */
static int is_json_media_type(const char *ct)
{
    if (!ct) return 0;
    while (*ct == ' ' || *ct == '\t') ct++;
    static const char want[] = "application/json";
    if (strncasecmp(ct, want, sizeof want - 1)) return 0;
    const char *rest = ct + sizeof want - 1;
    while (*rest == ' ' || *rest == '\t') rest++;
    return *rest == '\0' || *rest == ';';
}

/* Parse, validate, run and answer an operation's JSON body. */
static void run_body(size_t ri, struct api_full_request *req, struct api_response *resp)
{
    json_error_t jerr;
    const struct api_request *r = &req->req;
    json_t *body = api_json_read(r->body ? r->body : "", r->body ? r->body_len : 0, &jerr);
    if (!body) {
        if (api_parse_out_of_memory(&jerr, resp)) return;
        char d[300];
        snprintf(d, sizeof d, "line %d, column %d: %s", jerr.line, jerr.column, jerr.text);
        api_response_problem(resp, API_PROBLEM_MALFORMED_JSON, d);
        return;
    }
    api_run_body_into(ri, req, body, resp);
}

void api_run_body_into(size_t ri, struct api_full_request *req, json_t *body,
                       struct api_response *resp)
{
    json_t *out = NULL;
    char note[200];
    note[0] = '\0';
    int dep = 0;
    int status = api_run_parsed(ri, req, body, "", 0, &out, note, sizeof note, &dep);
    json_decref(body);
    if (req->deferred) {
        json_decref(out);
        resp->deferred = 1;
        return;
    }
    api_respond_outcome(resp, status, out, note);
    resp->depends_on_load = dep;
}

void api_run_post(size_t ri, struct api_full_request *req, struct api_response *resp)
{
    const char *ct = req->req.content_type;
    if (!is_json_media_type(ct)) {
        char d[200];
        snprintf(d, sizeof d, "send the body as Content-Type: application/json (got %s%.80s%s)",
                 ct ? "'" : "", ct ? ct : "none", ct ? "'" : "");
        api_response_problem(resp, API_PROBLEM_UNSUPPORTED_MEDIA, d);
        return;
    }
    /* The plain boost request is answered from its bytes (api/run/boost_direct.c:
     * the same answer without a JSON tree per number); every other request,
     * and every boost it declines, goes through the trees below. */
    const struct api_request *r = &req->req;
    if (r->body && !strcmp(api_routes[ri]->path, "/v1/relativity/boost")) {
        struct mech_budget budget = {r->max_steps > 0 ? r->max_steps : 1,
                                     isfinite(r->deadline) ? r->deadline : 0, r->cancel};
        if (api_boost_direct(r->body, r->body_len, &budget, resp)) return;
    }
    /* Every tree of this request (body, answer) is built and released in
     * this scope; the answer leaves as malloc()ed text (api/json/json_arena.c). */
    int arena = api_json_arena_wanted();
    if (arena) api_json_arena_begin();
    run_body(ri, req, resp);
    if (arena) api_json_arena_end();
}
