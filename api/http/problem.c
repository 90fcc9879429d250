/* problem.c — the one table that pins each problem kind to its HTTP status,
 * type URI and title (RFC 9457 problem+json), and the builder of problem
 * responses. Append-only: tests/api/test_problem.c pins every row. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jansson.h>

#include "api.h"
#include "http/respond.h"

struct problem_row {
    int status;
    const char *type;
    const char *title;
    const char *description;
};

static const struct problem_row problems[API_PROBLEM_COUNT] = {
    [API_PROBLEM_NONE] = {200, "about:blank", "OK", "No problem."},
    [API_PROBLEM_MALFORMED_JSON] = {400, "/problems/malformed-json", "Malformed JSON",
        "The request body is not valid JSON; the detail names the line and column."},
    [API_PROBLEM_NOT_FOUND] = {404, "/problems/not-found", "Not found",
        "No operation or resource has this path. GET /v1 lists every operation."},
    [API_PROBLEM_METHOD_NOT_ALLOWED] = {405, "/problems/method-not-allowed", "Method not allowed",
        "The path exists but not with this HTTP method; the detail says which method it takes."},
    [API_PROBLEM_BODY_TOO_LARGE] = {413, "/problems/body-too-large", "Request body too large",
        "The body is larger than the server's --max-body limit."},
    [API_PROBLEM_UNSUPPORTED_MEDIA] = {415, "/problems/unsupported-media-type",
        "Unsupported media type", "Request bodies must be sent as Content-Type: application/json."},
    [API_PROBLEM_VALIDATION] = {422, "/problems/validation-error", "Invalid request",
        "The request does not match the operation's schema; errors[] names each offending "
        "field by JSON pointer."},
    [API_PROBLEM_DOMAIN] = {422, "/problems/domain-error", "Outside the physical domain",
        "The request is well-formed but physically impossible (for example |beta| >= 1 or a "
        "non-positive mass); errors[] names the field."},
    [API_PROBLEM_BUDGET] = {422, "/problems/compute-budget-exceeded", "Compute budget exceeded",
        "The computation needed more steps, samples or time than the server allows; progress "
        "tells how far it got."},
    [API_PROBLEM_NUMERIC] = {422, "/problems/numerical-failure", "Numerical failure",
        "The numerics could not produce a finite, trustworthy answer for this input (for "
        "example a trajectory that runs into a singularity)."},
    [API_PROBLEM_QUEUE_FULL] = {503, "/problems/queue-full", "Server busy",
        "Every worker is busy and the queue is full; retry after Retry-After seconds."},
    [API_PROBLEM_INTERNAL] = {500, "/problems/internal-error", "Internal error",
        "A bug in mechd. The server log line with the same request id has the details."},
    [API_PROBLEM_CANCELLED] = {503, "/problems/cancelled", "Cancelled",
        "The server is shutting down and cancelled the computation; retry elsewhere or later."},
    [API_PROBLEM_UNAUTHORIZED] = {401, "/problems/unauthorized", "Unauthorized",
        "This server requires a bearer token (--token-file): send Authorization: Bearer TOKEN."},
    [API_PROBLEM_CORS_FORBIDDEN] = {403, "/problems/cors-origin-not-allowed",
        "Origin not allowed", "A cross-origin request from an origin the server does not list "
        "in --cors-origin."},
    [API_PROBLEM_REQUEST_MISSING] = {400, "/problems/request-missing", "Request missing",
        "This path is an operation: it computes from a request. POST the request as the JSON "
        "body, or GET the path with ?request=<the request JSON, URL-encoded>."},
    [API_PROBLEM_ANSWER_TOO_LARGE] = {422, "/problems/answer-too-large", "Answer too large",
        "The request asks for more samples in all (summed over its \"samples\" members and, "
        "in a batch, over its items) than the server's --max-samples allows; errors[] names the "
        "field where the sum passes the limit. Ask for fewer samples or split the request."},
    [API_PROBLEM_BAD_FRAMING] = {400, "/problems/bad-framing", "Bad request framing",
        "The length of the request cannot be read safely: it has both Content-Length and "
        "Transfer-Encoding, Content-Length headers that disagree, or a Transfer-Encoding other "
        "than chunked (RFC 9112 section 6). Send the body with one Content-Length, or with "
        "Transfer-Encoding: chunked alone. The server closes the connection."},
    [API_PROBLEM_ANSWER_MEMORY] = {503, "/problems/answer-memory-full", "Server busy",
        "The answers still being sent to clients hold all the memory the server gives them "
        "(--max-answer-memory), and this request's answer is predicted not to fit in what is "
        "left; nothing was computed. Retry after Retry-After seconds."},
    [API_PROBLEM_BAD_REQUEST] = {400, "/problems/bad-request", "Bad request",
        "The request head is not valid HTTP: an HTTP/1.1 request must carry exactly one Host "
        "header (RFC 9112 section 3.2). The server closes the connection."},
    [API_PROBLEM_URI_TOO_LONG] = {414, "/problems/uri-too-long", "URI too long",
        "The request target (path and query) is longer than the server reads; send a large "
        "request as a POST body instead of GET ?request=."},
    [API_PROBLEM_HEADERS_TOO_LARGE] = {431, "/problems/headers-too-large",
        "Request header fields too large",
        "The request line and headers together are larger than the server reads (RFC 6585 "
        "section 5); send fewer or shorter headers."},
};

int api_problem_status(enum api_problem kind)
{
    if ((int)kind < 0 || kind >= API_PROBLEM_COUNT) kind = API_PROBLEM_INTERNAL;
    return problems[kind].status;
}

const char *api_problem_type(enum api_problem kind)
{
    if ((int)kind < 0 || kind >= API_PROBLEM_COUNT) kind = API_PROBLEM_INTERNAL;
    return problems[kind].type;
}

const char *api_problem_title(enum api_problem kind)
{
    if ((int)kind < 0 || kind >= API_PROBLEM_COUNT) kind = API_PROBLEM_INTERNAL;
    return problems[kind].title;
}

const char *api_problem_description(enum api_problem kind)
{
    if ((int)kind < 0 || kind >= API_PROBLEM_COUNT) kind = API_PROBLEM_INTERNAL;
    return problems[kind].description;
}

enum api_problem api_problem_by_slug(const char *slug)
{
    for (int k = 1; k < API_PROBLEM_COUNT; k++)
        if (!strcmp(problems[k].type + strlen("/problems/"), slug)) return (enum api_problem)k;
    return API_PROBLEM_NONE;
}

json_t *api_problem_object(enum api_problem kind, const char *detail)
{
    if ((int)kind <= 0 || kind >= API_PROBLEM_COUNT) kind = API_PROBLEM_INTERNAL;
    json_t *p = json_object();
    if (!p) return NULL;
    json_object_set_new_nocheck(p, "type", json_string(problems[kind].type));
    json_object_set_new_nocheck(p, "title", json_string(problems[kind].title));
    json_object_set_new_nocheck(p, "status", json_integer(problems[kind].status));
    json_object_set_new_nocheck(
        p, "detail", api_json_text(detail && *detail ? detail : problems[kind].description));
    return p;
}

void api_response_problem(struct api_response *resp, enum api_problem kind, const char *detail)
{
    json_t *p = api_problem_object(kind, detail);
    api_respond_json(resp, api_problem_status(kind), "application/problem+json", p);
    json_decref(p);
    if (kind == API_PROBLEM_QUEUE_FULL || kind == API_PROBLEM_CANCELLED ||
        kind == API_PROBLEM_ANSWER_MEMORY)
        resp->retry_after = 1;
}
