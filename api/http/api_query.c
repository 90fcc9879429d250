/* api_query.c — GET (or HEAD) of an operation with ?request=: the same
 * request as a POST body, answered deterministically, so it gets a strong
 * ETag of (build, path, canonical request), 304 for a matching
 * If-None-Match, and may be cached for a day unless it depended on load. */
#include "http/api_query.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "http/api_etag.h"
#include "run/api_run.h"
#include "json/json_read.h"
#include "http/respond.h"
#include "run/routes.h"

/* Strong ETag of (build, path, canonical request) into buf (>= 19 bytes).
 * Returns 0, or -1 if memory ran out. */
static int request_etag(const char *path, const json_t *body, char *buf, size_t n)
{
    char *canon = json_dumps(body, JSON_COMPACT | JSON_SORT_KEYS | JSON_REAL_PRECISION(17) |
                                       JSON_ENCODE_ANY);
    if (!canon) return -1;
    uint64_t h = api_etag_build_hash();
    h = api_etag_fnv1a(h, path);
    h = api_etag_fnv1a(h, canon);
    free(canon);
    snprintf(buf, n, "\"%016llx\"", (unsigned long long)h);
    return 0;
}

void api_run_query(size_t ri, struct api_full_request *req, const struct api_request_ext *ext,
                   struct api_response *resp)
{
    json_error_t jerr;
    /* json_loads of a C string: the same tree or error as json_loadb of its strlen. */
    json_t *body = api_json_read(ext->query_request, strlen(ext->query_request), &jerr);
    if (!body) {
        if (api_parse_out_of_memory(&jerr, resp)) {
            resp->cache_control = "no-store";
            return;
        }
        char d[300];
        snprintf(d, sizeof d, "the request query parameter: line %d, column %d: %s", jerr.line,
                 jerr.column, jerr.text);
        api_response_problem(resp, API_PROBLEM_MALFORMED_JSON, d);
        resp->cache_control = "no-store";
        return;
    }
    char etag[sizeof resp->etag];
    if (request_etag(api_routes[ri]->path, body, etag, sizeof etag)) etag[0] = '\0';
    if (etag[0] && api_etag_matches(ext->if_none_match, etag)) {
        json_decref(body);
        memset(resp, 0, sizeof *resp);
        resp->status = 304;
        snprintf(resp->etag, sizeof resp->etag, "%s", etag);
        resp->cache_control = "public, max-age=86400";
        return;
    }
    api_run_body_into(ri, req, body, resp);
    /* An answer that depended on load (a batch item stopped by the deadline,
     * a partial result) is not the answer of this request: it must neither be
     * cached nor carry the ETag the full answer has. */
    if (resp->status == 200 && etag[0] && !resp->depends_on_load) {
        snprintf(resp->etag, sizeof resp->etag, "%s", etag);
        resp->cache_control = "public, max-age=86400";
    } else {
        resp->cache_control = "no-store";
    }
}
