/* fuzz_common.h — shared checks for the libFuzzer harnesses (tests/fuzz/):
 * a response from api_handle_ext() must be well-formed whatever the input.
 * Any violation prints the reason and aborts, so libFuzzer keeps the input. */
#ifndef MECHD_FUZZ_COMMON_H
#define MECHD_FUZZ_COMMON_H

#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"

static void fuzz_fail(const char *why, const struct api_response *r)
{
    fprintf(stderr, "fuzz: %s (status %d, note '%s', body '%.400s')\n", why, r->status, r->note,
            r->body ? r->body : "(null)");
    abort();
}

/* Statuses api_handle_ext may answer without memory failure, cancellation or
 * a queue: a 500 is a bug (an endpoint returned no result / internal error). */
static int fuzz_status_allowed(int s)
{
    return s == 200 || s == 304 || s == 400 || s == 404 || s == 405 || s == 415 || s == 422;
}


static void fuzz_check_response(const struct api_response *r, int head_or_304_ok)
{
    if (!fuzz_status_allowed(r->status)) fuzz_fail("status outside the allowed set", r);
    if (r->status == 304) {
        if (r->body) fuzz_fail("304 with a body", r);
        if (!r->etag[0]) fuzz_fail("304 without an ETag", r);
        return;
    }
    (void)head_or_304_ok;
    if (!r->body) fuzz_fail("no body", r);
    if (strlen(r->body) != r->body_len) fuzz_fail("body_len does not match the body", r);
    if (!r->content_type) fuzz_fail("no content type", r);
    if (strncmp(r->content_type, "application/json", 16) &&
        strncmp(r->content_type, "application/problem+json", 24) &&
        strncmp(r->content_type, "text/", 5))
        fuzz_fail("unexpected content type", r);
    if (!strncmp(r->content_type, "text/", 5)) return;
    json_error_t e;
    json_t *j = json_loads(r->body, JSON_DECODE_ANY, &e);
    if (!j) fuzz_fail("body is not JSON", r);
    if (r->status != 200) {
        if (strcmp(r->content_type, "application/problem+json"))
            fuzz_fail("an error without problem+json", r);
        const char *type = json_string_value(json_object_get(j, "type"));
        json_t *st = json_object_get(j, "status");
        if (!json_is_object(j) || !type || strncmp(type, "/problems/", 10) ||
            !json_is_number(st) || (int)json_number_value(st) != r->status ||
            !json_is_string(json_object_get(j, "title")) ||
            !json_is_string(json_object_get(j, "detail")))
            fuzz_fail("malformed problem object", r);
        json_t *errs = json_object_get(j, "errors");
        if (errs) {
            size_t i;
            json_t *x;
            if (!json_is_array(errs)) fuzz_fail("errors is not an array", r);
            json_array_foreach(errs, i, x) {
                const char *p = json_string_value(json_object_get(x, "pointer"));
                if (!p || (p[0] && p[0] != '/')) fuzz_fail("error without a JSON pointer", r);
                if (!json_is_string(json_object_get(x, "detail"))) fuzz_fail("error without detail", r);
            }
        }
    }
    json_decref(j);
}

#endif
