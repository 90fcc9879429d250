/* fuzz_api.c — libFuzzer harness for the API entry point (hostile
 * input): arbitrary bytes as the request body of every operation, through
 * api_handle_ext() with no socket.
 *
 * Input layout: byte 0 = flags, byte 1 = route selector, rest = body.
 *   selector < api_route_count: that route's path; otherwise the path is the
 *   body's first line (up to '\n', which is then dropped from the body).
 *   flags bits 0-1: method (0 the route's own, 1 GET, 2 HEAD, 3 DELETE);
 *   bit 2: GET ?request=<body> (ext.query_request, NUL-terminated copy);
 *   bit 3: Content-Type "text/plain" instead of "application/json; charset=utf-8";
 *   bit 4: If-None-Match "*"; bit 5: no_cost.
 * Checks (fuzz_common.h): status in the allowed set (no 500), a JSON body that
 * is a well-formed problem+json for every error, a 304 only with an ETag.
 * FUZZ_LIST_ROUTES=1 ./fuzz_api prints "index<TAB>method<TAB>path" per route
 * and exits (tests/fuzz/build_corpus.py uses it to seed the corpus). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "api.h"
#include "fuzz_common.h"
#include "mech/base/budget.h"
#include "run/routes.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    if (getenv("FUZZ_LIST_ROUTES")) {
        for (size_t i = 0; i < api_route_count; i++)
            printf("%zu\t%s\t%s\n", i, api_routes[i]->method, api_routes[i]->path);
        exit(0);
    }
    if (api_init() != 0) {
        fprintf(stderr, "api_init: %s\n", api_init_error());
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    unsigned flags = data[0];
    size_t sel = data[1];
    const char *body = (const char *)data + 2;
    size_t blen = size - 2;
    char path[512];
    if (sel < api_route_count) {
        snprintf(path, sizeof path, "%s", api_routes[sel]->path);
    } else {
        const char *nl = memchr(body, '\n', blen);
        size_t n = nl ? (size_t)(nl - body) : blen;
        if (n >= sizeof path) n = sizeof path - 1;
        memcpy(path, body, n);
        path[n] = '\0';
        if (nl) {
            blen -= (size_t)(nl - body) + 1;
            body = nl + 1;
        } else {
            blen = 0;
        }
    }
    static const char *const methods[] = {NULL, "GET", "HEAD", "DELETE"};
    const char *method = methods[flags & 3];
    if (!method) method = sel < api_route_count ? api_routes[sel]->method : "POST";

    char *copy = malloc(blen + 1); /* NUL-terminated copy: the query string needs one */
    if (!copy) return 0;
    memcpy(copy, body, blen);
    copy[blen] = '\0';

    struct api_request req = {
        .method = method,
        .path = path,
        .content_type = (flags & 8) ? "text/plain" : "application/json; charset=utf-8",
        .body = copy,
        .body_len = blen,
        .max_steps = 20000,
        .deadline = mech_clock_seconds() + 2.0,
        .cancel = NULL,
    };
    struct api_request_ext ext = {
        .query_request = (flags & 4) ? copy : NULL,
        .if_none_match = (flags & 16) ? "*" : NULL,
        .no_cost = (flags & 32) ? 1 : 0,
    };
    struct api_response resp;
    api_handle_ext(&req, &ext, &resp);
    fuzz_check_response(&resp, 1);
    api_response_free(&resp);
    free(copy);
    return 0;
}
