/* api.c — api_handle(): the dispatch of one HTTP-shaped request. Everything
 * an HTTP request to /v1 can meet passes through here, with or without a
 * socket: the documents (api/catalog/api_docs.c), the problem types, the GET resources,
 * GET ?request= (api/http/api_query.c) and the operations (api/run/api_run.c: media type,
 * parse, validation, the answer budget, the handler, cost), with the
 * checked allocator's verdict (api/json/api_alloc.c) over all of it. The route
 * table's set-up is api/run/api_init.c. */
#include "api.h"

#include <stdio.h>
#include <string.h>

#include <jansson.h>

#include "json/api_alloc.h"
#include "catalog/api_docs.h"
#include "run/api_init.h"
#include "http/api_query.h"
#include "run/api_run.h"
#include "http/respond.h"
#include "run/routes.h"

static int is_get(const char *m)
{
    return !strcmp(m, "GET") || !strcmp(m, "HEAD");
}

/* A GET route: call the handler without a body; it cannot fail on input. */
static void run_resource(size_t ri, struct api_full_request *req, struct api_response *resp)
{
    struct api_call call;
    memset(&call, 0, sizeof call);
    call.req = req;
    json_t *result = api_routes[ri]->fn(&call, NULL);
    if (!result || call.problem != API_PROBLEM_NONE || call.nonfinite) {
        api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
        snprintf(resp->note, sizeof resp->note, "%.40s: resource handler failed",
                 api_routes[ri]->path);
    } else {
        api_respond_json(resp, 200, "application/json", result);
    }
    json_decref(result);
    json_decref(call.errors);
    json_decref(call.extra);
}

/* GET /problems/<slug>: what a problem type means (its type URI resolves here). */
static void serve_problem_doc(const char *slug, struct api_response *resp)
{
    enum api_problem k = api_problem_by_slug(slug);
    if (k == API_PROBLEM_NONE) {
        api_response_problem(resp, API_PROBLEM_NOT_FOUND, "no such problem type");
        return;
    }
    json_t *doc = json_pack("{s:s,s:s,s:i,s:s}", "type", api_problem_type(k), "title",
                            api_problem_title(k), "status", api_problem_status(k),
                            "description", api_problem_description(k));
    api_respond_json(resp, 200, "application/json", doc);
    json_decref(doc);
}

/* 405 for a path that takes `want` ("GET" or "POST"), with its Allow header
 * (RFC 9110 §15.5.6). An operation also answers GET/HEAD with ?request=. */
static void method_not_allowed(struct api_response *resp, const char *want)
{
    int post = !strcmp(want, "POST");
    api_response_problem(resp, API_PROBLEM_METHOD_NOT_ALLOWED,
                         post ? "this path takes POST (or GET with ?request= and the JSON body, "
                                "URL-encoded)"
                              : "this path takes GET (or HEAD)");
    resp->allow = post ? "POST, GET, HEAD" : "GET, HEAD";
}

void api_handle(const struct api_request *req, struct api_response *resp)
{
    api_handle_ext(req, NULL, resp);
}

static void handle(const struct api_request *req0, const struct api_request_ext *ext,
                   struct api_response *resp);

void api_handle_ext(const struct api_request *req0, const struct api_request_ext *ext,
                    struct api_response *resp)
{
    api_json_alloc_watch();
    handle(req0, ext, resp);
    if (api_json_alloc_failed()) { /* something was dropped: never send it (api/json/api_alloc.c) */
        api_respond_out_of_memory(resp);
        snprintf(resp->note, sizeof resp->note, "out of memory while building the answer");
    }
    /* RFC 9457 instance: the request path (the same bytes with or without a
     * server, so `mechd eval` matches; X-Request-Id names the occurrence). */
    api_response_set_instance(resp, req0 && req0->path ? req0->path : "");
}

static void handle(const struct api_request *req0, const struct api_request_ext *ext,
                   struct api_response *resp)
{
    memset(resp, 0, sizeof *resp);
    struct api_full_request full;
    memset(&full, 0, sizeof full);
    full.req = *req0;
    const struct api_request *req = &full.req;
    const char *query = ext ? ext->query_request : NULL;
    full.no_cost = (ext && ext->no_cost) || (query && is_get(req->method ? req->method : ""));
    full.max_samples = ext && ext->max_samples > 0 ? ext->max_samples : API_DEFAULT_MAX_SAMPLES;
    full.admit = ext ? ext->admit : NULL;
    full.admit_ctx = ext ? ext->admit_ctx : NULL;
    full.admit_pending = full.admit != NULL;
    full.gate = ext ? ext->gate : NULL;
    full.gate_ctx = ext ? ext->gate_ctx : NULL;
    full.gate_armed = full.gate != NULL;
    if (api_init() != 0) {
        api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
        snprintf(resp->note, sizeof resp->note, "api_init failed: %.150s", api_init_error());
        return;
    }
    const char *m = req->method ? req->method : "";
    const char *path = req->path ? req->path : "";

    if (!strcmp(path, "/v1") || !strcmp(path, "/v1/")) {
        if (!is_get(m)) { method_not_allowed(resp, "GET"); return; }
        api_docs_serve_catalog(ext, resp);
        return;
    }
    if (!strcmp(path, "/v1/openapi.json")) {
        if (!is_get(m)) { method_not_allowed(resp, "GET"); return; }
        api_docs_serve_openapi(ext, resp);
        return;
    }
    if (!strncmp(path, "/problems/", 10)) {
        if (!is_get(m)) { method_not_allowed(resp, "GET"); return; }
        serve_problem_doc(path + 10, resp);
        return;
    }
    long ri = api_route_index(path);
    if (ri < 0) {
        char d[200];
        snprintf(d, sizeof d, "no operation at %.120s; GET /v1 lists them all", path);
        api_response_problem(resp, API_PROBLEM_NOT_FOUND, d);
        return;
    }
    const char *want = api_routes[ri]->method;
    if (!strcmp(want, "POST") && is_get(m) && query) {
        api_run_query((size_t)ri, &full, ext, resp);
        return;
    }
    if (!strcmp(want, "POST") && is_get(m)) {
        api_response_problem(resp, API_PROBLEM_REQUEST_MISSING,
                             "this operation needs a request: POST it as the JSON body, or GET "
                             "this path with ?request=<the request JSON, URL-encoded>");
        resp->cache_control = "no-store";
        return;
    }
    if (!strcmp(want, "GET") ? !is_get(m) : strcmp(m, want) != 0) {
        method_not_allowed(resp, want);
        return;
    }
    if (!strcmp(want, "GET")) {
        run_resource((size_t)ri, &full, resp);
    } else {
        api_run_post((size_t)ri, &full, resp);
        resp->cache_control = "no-store";
    }
}
