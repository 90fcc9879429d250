/* http_head.c — the request head, checked before any body byte is read: the
 * target's length (414), the head's size (431), Host (400); and the methods a
 * path answers to, for OPTIONS (part of the HTTP front end, see http.c).
 *
 * REQUEST HEAD. libmicrohttpd answers a head that does not fit in its
 * per-connection memory itself, with an HTML page and no hook to change it.
 * That memory is SRV_MHD_POOL (40 KiB), above this server's own limits on the
 * target (SRV_TARGET_MAX) and the whole head (SRV_HEADERS_MAX), so that up to
 * about its size (a head of some 40 KB) the answer is this server's
 * problem+json. It is not larger: libmicrohttpd zeroes the whole of it after
 * each request of a kept-alive connection. The target's
 * length is taken from libmicrohttpd's URI log callback (on_uri), which sees
 * the target as sent, query included. RFC 9112 section 3.2: an HTTP/1.1
 * request without a Host header, or with more than one, gets 400.
 */
#include "http_internal.h"

#include <microhttpd.h>
#include <string.h>
#include <strings.h>

#include "api.h"
#include "static.h"

/* libmicrohttpd's URI log callback: the request target as sent, before the
 * headers; its length is kept on the connection for head_problem. Returns
 * NULL, so the request's context starts empty. */
void *on_uri(void *cls, const char *uri, struct MHD_Connection *conn)
{
    (void)cls;
    const union MHD_ConnectionInfo *sci =
        MHD_get_connection_info(conn, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    struct srv_conn *sc = sci ? sci->socket_context : NULL;
    if (sc) sc->target_len = uri ? strlen(uri) : 0;
    return NULL;
}

static enum MHD_Result count_host(void *cls, enum MHD_ValueKind kind, const char *key,
                                  const char *value)
{
    (void)kind;
    (void)value;
    if (key && strcasecmp(key, MHD_HTTP_HEADER_HOST) == 0) ++*(int *)cls;
    return MHD_YES;
}

/* A request head this server refuses before reading any body: a target
 * longer than SRV_TARGET_MAX (414), a head larger than SRV_HEADERS_MAX (431),
 * an HTTP/1.1 request without exactly one Host header (400, RFC 9112 section
 * 3.2; HTTP/1.0 may omit it). Sets r->head_problem and r->head_detail and
 * returns 1, else 0. Heads larger than libmicrohttpd's per-connection memory
 * (SRV_MHD_POOL) are refused by libmicrohttpd itself, with its own HTML 414
 * or 431. */
int head_problem(struct srv_req *r, struct MHD_Connection *conn, const char *version)
{
    if (r->sc && r->sc->target_len > SRV_TARGET_MAX) {
        r->head_problem = API_PROBLEM_URI_TOO_LONG;
        r->head_detail = "the request target (path and query) is longer than 32768 bytes; send a "
                         "large request as a POST body";
        return 1;
    }
    const union MHD_ConnectionInfo *hs =
        MHD_get_connection_info(conn, MHD_CONNECTION_INFO_REQUEST_HEADER_SIZE);
    if (hs && hs->header_size > SRV_HEADERS_MAX) {
        r->head_problem = API_PROBLEM_HEADERS_TOO_LARGE;
        r->head_detail = "the request line and headers are larger than 32768 bytes";
        return 1;
    }
    int hosts = 0;
    if (version && strcmp(version, MHD_HTTP_VERSION_1_1) == 0) {
        MHD_get_connection_values(conn, MHD_HEADER_KIND, count_host, &hosts);
        if (hosts != 1) {
            r->head_problem = API_PROBLEM_BAD_REQUEST;
            r->head_detail = hosts == 0 ? "an HTTP/1.1 request must carry a Host header"
                                        : "the request carries more than one Host header";
            return 1;
        }
    }
    return 0;
}

/* The methods path answers to (static), or NULL when nothing is there. */
const char *allowed_methods(const char *p)
{
    if (strcmp(p, "*") == 0) return "GET, HEAD, POST, OPTIONS";
    for (size_t i = 0; i < api_operation_count(); i++)
        if (strcmp(api_operation_path(i), p) == 0)
            return strcmp(api_operation_method(i), "POST") == 0 ? "POST, GET, HEAD, OPTIONS"
                                                                 : "GET, HEAD, OPTIONS";
    struct srv_static_file f;
    if (strcmp(p, "/v1") == 0 || strcmp(p, "/v1/") == 0 || strcmp(p, "/v1/openapi.json") == 0 ||
        strcmp(p, "/healthz") == 0 || strcmp(p, "/metrics") == 0 || strcmp(p, "/") == 0 ||
        (strncmp(p, "/problems/", 10) == 0 && p[10] != '\0') ||
        (strncmp(p, "/v1/", 4) != 0 && strncmp(p, "/problems/", 10) != 0 &&
         srv_static_lookup(p, &f) == 0))
        return "GET, HEAD, OPTIONS";
    return NULL;
}
