/* api_run.h — running an operation's request (api/run/api_run.c), shared by the
 * dispatch (api/http/api.c) and GET ?request= (api/http/api_query.c). */
#ifndef API_API_RUN_H
#define API_API_RUN_H

#include <stddef.h>

#include <jansson.h>

#include "api.h"

/* Every request api_handle_ext() runs is wrapped so that code holding only the
 * struct api_request (a handler's call->req, e.g. /v1/batch) can still see the
 * extras. Only api/http/api.c (api_handle_ext) creates them; the pipeline and the
 * handlers' struct api_call carry this struct, so no code casts an
 * api_request to it. */
struct api_full_request {
    struct api_request req; /* first member */
    int no_cost;
    long max_samples; /* > 0 */
    int (*admit)(void *ctx, long route, double samples); /* api_request_ext's, or NULL */
    void *admit_ctx;
    int admit_pending; /* 1 until the first (the request's own) run reaches admission */
    int (*gate)(void *ctx, double predicted_cpu_s); /* api_request_ext's, or NULL */
    void *gate_ctx;
    int gate_armed;    /* 1 until the first (the request's own) run starts: its call is gated */
    int deferred;      /* the gate stopped the request (api_call_cost_gate) */
};

/* The pipeline after parsing, for route ri (a POST operation): schema
 * validation, the answer budget, the handler on the body with its defaults
 * filled in, the non-finite check, cost accounting. Returns the HTTP status and sets *out to the answer or
 * the problem object (new reference; NULL only when memory ran out). Error
 * pointers are prefixed with prefix ("" at top level). note (note_n bytes,
 * may be NULL) gets the reason of a 500 for the log. no_cost: an enclosing
 * request (a batch) asked for no measured cost. *dep is set to 1 when the
 * outcome depended on load or time, else left alone. */
int api_run_parsed(size_t ri, struct api_full_request *req, const json_t *body, const char *prefix,
                   int no_cost, json_t **out, char *note, size_t note_n, int *dep);

/* Serialise an outcome of api_run_parsed into resp (consumes out; NULL gives
 * the 500); note (may be NULL or "") goes to resp->note. */
void api_respond_outcome(struct api_response *resp, int status, json_t *out, const char *note);

/* Run the parsed top-level body of operation ri (api_run_parsed with no
 * prefix), release body, and serialise the outcome into resp, with
 * resp->depends_on_load set when the answer depended on load or time. */
void api_run_body_into(size_t ri, struct api_full_request *req, json_t *body,
                       struct api_response *resp);

/* A parse that failed for lack of memory is the server's failure, not a
 * malformed body: returns 1 with resp filled with the 500, else 0. */
int api_parse_out_of_memory(const json_error_t *jerr, struct api_response *resp);

/* A POST to operation ri: the media type checked, the body parsed and run
 * through api_run_parsed, the answer into resp; every tree of the request
 * lives in the per-thread arena when api_json_arena_wanted(). */
void api_run_post(size_t ri, struct api_full_request *req, struct api_response *resp);

#endif
