/* fuzz_http.c — libFuzzer harness for the HTTP request path, without sockets.
 *
 * server/http.c's request handling lives in libmicrohttpd callbacks (static
 * functions over an MHD_Connection), so it cannot be called on its own. This
 * harness fuzzes everything behind it that takes client bytes:
 *   - api_handle_ext() with a fuzzed method, path, ?request= query (decoded
 *     here the way a URL decoder would: %XX and '+'), Content-Type,
 *     If-None-Match and body;
 *   - srv_static_lookup() with the fuzzed path (the raw bytes and the decoded
 *     ones) and srv_static_not_modified() with the fuzzed If-None-Match, over
 *     the real front end (clients/web, MECHD_STATIC_DIR).
 * libmicrohttpd's own parsing (request line, header syntax) and http.c's
 * callbacks are covered by fuzz_server.c (the real server over TCP).
 *
 * Input layout: lines "METHOD\nPATH[?QUERY]\nCONTENT-TYPE\nIF-NONE-MATCH\nBODY..."
 * (an empty content-type or If-None-Match line means the header is absent).
 * Checks: as fuzz_api.c (fuzz_common.h), plus a static hit must be a file
 * whose path equals the one looked up (or its index.html) with a body, type
 * and ETag, and lookups refuse every path with "..", "%", "\\" or "//". */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "api.h"
#include "fuzz_common.h"
#include "mech/base/budget.h"
#include "static.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    if (api_init() != 0) {
        fprintf(stderr, "api_init: %s\n", api_init_error());
        abort();
    }
    if (srv_static_init(NULL) <= 0) fprintf(stderr, "fuzz_http: no static files under %s\n",
                                            MECHD_STATIC_DIR);
    return 0;
}

/* Next line of [*p, end) as a new NUL-terminated string; advances *p. */
static char *take_line(const char **p, const char *end)
{
    const char *nl = memchr(*p, '\n', (size_t)(end - *p));
    size_t n = nl ? (size_t)(nl - *p) : (size_t)(end - *p);
    char *s = malloc(n + 1);
    if (!s) abort();
    memcpy(s, *p, n);
    s[n] = '\0';
    *p = nl ? nl + 1 : end;
    return s;
}

static int hexval(int c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* In-place URL decoding (%XX, and '+' as space when plus is set). */
static void url_decode(char *s, int plus)
{
    char *o = s;
    for (char *i = s; *i; i++) {
        if (*i == '%' && hexval(i[1]) >= 0 && hexval(i[2]) >= 0) {
            *o++ = (char)(hexval(i[1]) * 16 + hexval(i[2]));
            i += 2;
        } else if (plus && *i == '+') {
            *o++ = ' ';
        } else {
            *o++ = *i;
        }
    }
    *o = '\0';
}

static void check_static(const char *path, const char *inm)
{
    struct srv_static_file f;
    memset(&f, 0, sizeof f);
    if (srv_static_lookup(path, &f) != 0) return;
    if (strstr(path, "..") || strchr(path, '%') || strchr(path, '\\') || strstr(path, "//") ||
        path[0] != '/') {
        fprintf(stderr, "fuzz_http: static lookup accepted '%s'\n", path);
        abort();
    }
    if (!f.path || !f.body || !f.content_type || !f.etag || f.n_headers < 0 ||
        f.n_headers > SRV_STATIC_HEADERS) {
        fprintf(stderr, "fuzz_http: incomplete static file for '%s'\n", path);
        abort();
    }
    size_t n = strlen(path);
    if (strcmp(f.path, path) && !(path[n - 1] == '/' && !strncmp(f.path, path, n) &&
                                  !strcmp(f.path + n, "index.html"))) {
        fprintf(stderr, "fuzz_http: '%s' served '%s'\n", path, f.path);
        abort();
    }
    (void)srv_static_not_modified(&f, inm);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *p = (const char *)data, *end = p + size;
    char *method = take_line(&p, end);
    char *target = take_line(&p, end);
    char *ctype = take_line(&p, end);
    char *inm = take_line(&p, end);
    size_t blen = (size_t)(end - p);
    char *body = malloc(blen + 1);
    if (!body) abort();
    memcpy(body, p, blen);
    body[blen] = '\0';

    /* Split the target at '?', decode the path, find request= in the query. */
    char *query = strchr(target, '?');
    if (query) *query++ = '\0';
    char *request = NULL;
    for (char *q = query; q && *q;) {
        char *amp = strchr(q, '&');
        if (amp) *amp = '\0';
        if (!strncmp(q, "request=", 8)) {
            request = q + 8;
            url_decode(request, 1);
        }
        q = amp ? amp + 1 : NULL;
    }
    check_static(target, inm[0] ? inm : NULL); /* the raw, still-encoded path */
    url_decode(target, 0);
    check_static(target, inm[0] ? inm : NULL);

    struct api_request req = {
        .method = method,
        .path = target,
        .content_type = ctype[0] ? ctype : NULL,
        .body = body,
        .body_len = blen,
        .max_steps = 20000,
        .deadline = mech_clock_seconds() + 2.0,
        .cancel = NULL,
    };
    struct api_request_ext ext = {
        .query_request = request,
        .if_none_match = inm[0] ? inm : NULL,
        .no_cost = 0,
    };
    struct api_response resp;
    api_handle_ext(&req, &ext, &resp);
    fuzz_check_response(&resp, 1);
    api_response_free(&resp);
    free(method);
    free(target);
    free(ctype);
    free(inm);
    free(body);
    return 0;
}
