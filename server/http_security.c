/* http_security.c — the bearer token and CORS of /v1 (part of the HTTP front end, see
 * http.c; its face is http_security.h).
 *
 * SECURITY. With --token-file, every /v1 request needs the bearer token
 * (checked on the first callback, before any body byte is read; compared in
 * constant time); /healthz, /metrics, /problems/... and the front end stay open.
 * The 401 is the problem table's (api/http/problem.c).
 * CORS is off unless --cors-origin lists origins: only those get
 * Access-Control-Allow-Origin on /v1 answers and a 204 with the allowed
 * methods and headers to a preflight; a preflight from any other origin is
 * answered as a plain OPTIONS (204 with Allow, no CORS header). Every
 * answer built here carries nosniff, Referrer-Policy, X-Frame-Options and a
 * CSP of default-src 'none' (static files carry static.c's own set).
 * Answers libmicrohttpd writes itself (431 header too large, 400 on a broken
 * request line or an unparsable Content-Length) carry none of these: it
 * offers no hook for them.
 *
 * This file decides (struct srv_access) and http.c answers: the checks here
 * call nothing of the front end, so the two files do not depend on each other
 * in a loop.
 */
#include "http_security.h"

#include <microhttpd.h>
#include <string.h>
#include <strings.h>

/* The allowed preflight's answer headers (CORS, only for origins listed with
 * --cors-origin). */
#define SRV_CORS_METHODS "GET, HEAD, POST, OPTIONS"
#define SRV_CORS_HEADERS "Authorization, Content-Type, If-None-Match"
#define SRV_CORS_MAX_AGE "600"

/* /v1 and everything under it: the token and CORS apply here. */
static int is_v1_path(const char *p)
{
    return strcmp(p, "/v1") == 0 || strncmp(p, "/v1/", 4) == 0;
}

/* Is origin (the Origin header) one of the comma-separated allowed origins?
 * Scheme and host compare case-insensitively (RFC 6454 §6.1 serialises them in
 * lower case anyway). */
static int origin_allowed(const char *list, const char *origin)
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
static int token_ok(const struct srv_config *cfg, const char *authorization)
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

void srv_access_check(const struct srv_config *cfg, struct MHD_Connection *conn,
                      const char *method, const char *path, const char *origin,
                      struct srv_access *out)
{
    memset(out, 0, sizeof *out);
    if (!is_v1_path(path)) return;
    int cors_on = cfg->cors_origins[0] != '\0';
    out->vary_origin = cors_on;
    out->cors_ok = cors_on && origin && origin_allowed(cfg->cors_origins, origin);
    /* A CORS preflight (OPTIONS with Origin and Access-Control-Request-Method)
     * carries no credentials, so it is decided before the token check. */
    if (strcmp(method, MHD_HTTP_METHOD_OPTIONS) == 0 && origin &&
        MHD_lookup_connection_value(conn, MHD_HEADER_KIND, "Access-Control-Request-Method")) {
        out->preflight = 1;
        return;
    }
    if (cfg->token_len == 0) return;
    const char *auth =
        MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_AUTHORIZATION);
    if (token_ok(cfg, auth)) return;
    int given = auth != NULL;
    out->www_authenticate =
        given ? "Bearer realm=\"mechd\", error=\"invalid_token\"" : "Bearer realm=\"mechd\"";
    out->refusal = given ? "the bearer token is not valid for this server"
                         : "this server requires 'Authorization: Bearer TOKEN' for /v1";
}

void srv_preflight_headers(struct MHD_Response *mr)
{
    MHD_add_response_header(mr, "Access-Control-Allow-Methods", SRV_CORS_METHODS);
    MHD_add_response_header(mr, "Access-Control-Allow-Headers", SRV_CORS_HEADERS);
    MHD_add_response_header(mr, "Access-Control-Max-Age", SRV_CORS_MAX_AGE);
}
