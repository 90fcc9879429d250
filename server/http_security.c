/* http_security.c — the bearer token and CORS of /v1 (part of the HTTP front end, see
 * http.c).
 *
 * SECURITY. With --token-file, every /v1 request needs the bearer token
 * (checked on the first callback, before any body byte is read; compared in
 * constant time); /healthz, /metrics, /problems/... and the front end stay open.
 * The 401 and the preflight's 403 are the problem table's (api/problem.c).
 * CORS is off unless --cors-origin lists origins: only those get
 * Access-Control-Allow-Origin on /v1 answers and a 204 to a preflight. Every
 * answer built here carries nosniff, Referrer-Policy, X-Frame-Options and a
 * CSP of default-src 'none' (static files carry static.c's own set).
 * Answers libmicrohttpd writes itself (431 header too large, 400 on a broken
 * request line or an unparsable Content-Length) carry none of these: it
 * offers no hook for them.
 */
#ifdef __linux__
#define _GNU_SOURCE /* POLLRDHUP */
#endif
#include "http_internal.h"

#include <arpa/inet.h>
#include <errno.h>
#include <malloc.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/resource.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "api.h"
#include "log.h"
#include "static.h"
#include "mech/budget.h"

/* /v1 and everything under it: the token and CORS apply here. */
int is_v1_path(const char *p)
{
    return strcmp(p, "/v1") == 0 || strncmp(p, "/v1/", 4) == 0;
}

/* Is origin (the Origin header) one of the comma-separated allowed origins?
 * Scheme and host compare case-insensitively (RFC 6454 §6.1 serialises them in
 * lower case anyway). */
int origin_allowed(const char *list, const char *origin)
{
    size_t n = strlen(origin);
    if (n == 0) return 0;
    for (const char *p = list; *p;) {
        size_t k = strcspn(p, ",");
        if (k == n && strncasecmp(p, origin, n) == 0) return 1;
        p += k;
        if (*p == ',') p++;
    }
    return 0;
}

/* Does the Authorization header carry the configured bearer token? The token
 * comparison reads a fixed SRV_TOKEN_MAX bytes whatever the input, so its time
 * says nothing about how many leading characters matched (RFC 6750 §2.1). */
int token_ok(const struct srv_config *cfg, const char *authorization)
{
    if (!authorization) return 0;
    while (*authorization == ' ')
        authorization++;
    if (strncasecmp(authorization, "Bearer ", 7) != 0) return 0;
    const char *given = authorization + 7;
    while (*given == ' ')
        given++;
    size_t glen = strlen(given);
    while (glen > 0 && given[glen - 1] == ' ')
        glen--;
    volatile unsigned char diff = (unsigned char)(glen != cfg->token_len);
    for (size_t i = 0; i < SRV_TOKEN_MAX; i++) {
        unsigned char a = i < glen ? (unsigned char)given[i] : 0;
        unsigned char b = i < cfg->token_len ? (unsigned char)cfg->token[i] : 0;
        diff |= (unsigned char)(a ^ b);
    }
    return diff == 0;
}

/* CORS preflight (OPTIONS with Origin and Access-Control-Request-Method) for
 * /v1: 204 with the allowed methods and headers for a listed origin, else 403.
 * Preflights carry no credentials, so they are answered before the token check. */
enum MHD_Result answer_preflight(struct srv_req *r)
{
    if (!r->cors_ok)
        return answer_server_problem(r, API_PROBLEM_CORS_FORBIDDEN,
                                     "this origin is not in the server's --cors-origin list");
    struct MHD_Response *mr =
        MHD_create_response_from_buffer(0, (void *)"", MHD_RESPMEM_PERSISTENT);
    r->state = REQ_ANSWERED;
    if (!mr) return MHD_NO;
    MHD_add_response_header(mr, "X-Request-Id", r->id);
    add_common_headers(r, mr, NULL);
    MHD_add_response_header(mr, "Access-Control-Allow-Methods", SRV_CORS_METHODS);
    MHD_add_response_header(mr, "Access-Control-Allow-Headers", SRV_CORS_HEADERS);
    MHD_add_response_header(mr, "Access-Control-Max-Age", SRV_CORS_MAX_AGE);
    enum MHD_Result ret = MHD_queue_response(r->conn, MHD_HTTP_NO_CONTENT, mr);
    MHD_destroy_response(mr);
    if (ret == MHD_YES) r->status = MHD_HTTP_NO_CONTENT;
    return ret;
}
