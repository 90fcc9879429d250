/* http_body.c — the request body: buffered up to --max-body, its framing checked
 * before any byte of it is read, and a mid-body 413 written on the socket
 * (part of the HTTP front end, see http.c).
 *
 * BODY LIMIT. A request body is
 * buffered up to --max-body: a Content-Length over the limit is answered 413
 * on the first callback, before any byte of the body is read; a chunked body
 * that passes the limit is read on (and dropped) for at most
 * SRV_CHUNKED_GRACE more bytes, so that a client sending all of a slightly
 * too large body before reading gets its 413; past that it is answered 413
 * and its connection closed at once (refuse_mid_body: libmicrohttpd only
 * queues a response before the body or after all of it, and reading on to the
 * end let one client stream 11.5 GB in 5 s).
 *
 * FRAMING. libmicrohttpd frames a body by Transfer-Encoding if present, else
 * by the first Content-Length, and accepts what RFC 9112 section 6 says to
 * refuse. On the first callback (headers only) a request with both
 * Content-Length and Transfer-Encoding, with Content-Length headers that
 * disagree, with a Transfer-Encoding other than exactly "chunked" (which
 * libmicrohttpd would read to end-of-connection) or with Transfer-Encoding on
 * HTTP/1.0 is answered 400 /problems/bad-framing with Connection: close, before
 * any body byte reaches the API: behind a proxy that frames differently such a
 * request is a smuggling vector. An unparsable Content-Length is refused by
 * libmicrohttpd itself before any callback (its 400 page, whose header block
 * libmicrohttpd 0.9.75 writes twice; no hook comes earlier).
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
#include "mech/base/budget.h"

/* Header iterator of framing_problem: counts Content-Length and
 * Transfer-Encoding headers, notes whether the Content-Lengths differ. */
struct framing_scan {
    int n_cl, n_te, cl_differ;
    const char *cl, *te;
};

static enum MHD_Result framing_header(void *cls, enum MHD_ValueKind kind, const char *key,
                                      const char *value)
{
    struct framing_scan *f = cls;
    (void)kind;
    if (!key) return MHD_YES;
    if (strcasecmp(key, MHD_HTTP_HEADER_CONTENT_LENGTH) == 0) {
        if (f->n_cl++ == 0)
            f->cl = value;
        else if (!value || !f->cl || strcmp(value, f->cl) != 0)
            f->cl_differ = 1;
    } else if (strcasecmp(key, MHD_HTTP_HEADER_TRANSFER_ENCODING) == 0) {
        if (f->n_te++ == 0) f->te = value;
    }
    return MHD_YES;
}

/* Why the request's body framing is refused (see FRAMING above), as the
 * problem detail (static text: nothing from the request is echoed), or NULL
 * when it is unambiguous. version is the request's HTTP version. */
const char *framing_problem(struct MHD_Connection *conn, const char *version)
{
    struct framing_scan f = {0, 0, 0, NULL, NULL};
    MHD_get_connection_values(conn, MHD_HEADER_KIND, framing_header, &f);
    if (f.n_te > 0 && f.n_cl > 0)
        return "the request has both Content-Length and Transfer-Encoding; send exactly one "
               "of them (RFC 9112 section 6.3)";
    if (f.cl_differ)
        return "the request has Content-Length headers with different values; send one "
               "Content-Length (RFC 9112 section 6.3)";
    if (f.n_te > 1 || (f.n_te == 1 && (!f.te || strcasecmp(f.te, "chunked") != 0)))
        return "Transfer-Encoding must be exactly \"chunked\", the only transfer coding this "
               "server reads; or send the body with Content-Length";
    if (f.n_te > 0 && version && strcmp(version, MHD_HTTP_VERSION_1_0) == 0)
        return "Transfer-Encoding is not defined in HTTP/1.0; send the body with Content-Length "
               "(RFC 9112 section 6.1)";
    return NULL;
}

/* Set on an I/O thread just before on_request returns MHD_NO on purpose (the
 * answer is already on the socket): libmicrohttpd then logs "Application
 * reported internal error, closing connection.", which is not true, and
 * mhd_logger drops that one line. Cleared at every on_request entry. */
_Thread_local int tl_closing_on_purpose;

/* libmicrohttpd's error log (MHD_OPTION_EXTERNAL_LOGGER): its messages as it
 * would print them on stderr, minus the false alarm above. */
void mhd_logger(void *cls, const char *fmt, va_list ap)
{
    (void)cls;
    char line[512];
    int n = vsnprintf(line, sizeof line, fmt, ap);
    if (n < 0) return;
    if (tl_closing_on_purpose && strstr(line, "reported internal error")) {
        tl_closing_on_purpose = 0;
        return;
    }
    fputs(line, stderr);
}

/* send() all of buf on a non-blocking socket without SIGPIPE; stops at the
 * first error or full buffer (the connection is closed next anyway). */
static void send_some(int fd, const char *buf, size_t len)
{
    while (len > 0) {
        ssize_t n = send(fd, buf, len, MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n <= 0) {
            if (n < 0 && errno == EINTR) continue;
            return;
        }
        buf += n;
        len -= (size_t)n;
    }
}

/* A chunked body has just passed --max-body + SRV_CHUNKED_GRACE while arriving. libmicrohttpd
 * queues a response only before the body or after all of it
 * (MHD_queue_response), and reading on to the end is what a client streaming
 * gigabytes wants. So the 413 problem+json (with the headers answer() sends
 * and Connection: close) is written on the socket here, on the I/O thread
 * that owns the connection, which has written nothing for this request (no
 * response was queued; libmicrohttpd answers one request at a time); the
 * write side is shut, what the client has already sent is drained (bounded),
 * so that the close is less likely to reset the answer away, and MHD_NO makes
 * libmicrohttpd close the connection. The request is logged as 413. */
enum MHD_Result refuse_mid_body(struct srv_http *h, struct srv_req *r)
{
    r->state = REQ_ANSWERED;
    if (!conn_claim(r) || r->fd < 0) return MHD_NO;
    char detail[160];
    snprintf(detail, sizeof detail, "the request body exceeds the limit of %zu bytes",
             h->cfg->max_body);
    struct api_response resp;
    memset(&resp, 0, sizeof resp);
    api_response_problem(&resp, API_PROBLEM_BODY_TOO_LARGE, detail);
    api_response_set_request_id(&resp, r->id);
    if (!resp.body) return MHD_NO; /* out of memory: just close */
    char date[64] = "";
    time_t now = time(NULL);
    struct tm tm;
    if (gmtime_r(&now, &tm)) strftime(date, sizeof date, "%a, %d %b %Y %H:%M:%S GMT", &tm);
    char head[2048];
    size_t k = 0;
#define HEAD_ADD(...)                                                                              \
    do {                                                                                           \
        int n_ = snprintf(head + k, sizeof head - k, __VA_ARGS__);                                 \
        k = n_ < 0 || (size_t)n_ >= sizeof head - k ? sizeof head : k + (size_t)n_;                \
    } while (0)
    HEAD_ADD("HTTP/1.1 413 %s\r\nDate: %s\r\nConnection: close\r\n",
             MHD_get_reason_phrase_for(MHD_HTTP_CONTENT_TOO_LARGE), date);
    HEAD_ADD("Content-Type: %s\r\nContent-Length: %zu\r\nX-Request-Id: %s\r\n",
             resp.content_type ? resp.content_type : "application/problem+json", resp.body_len,
             r->id);
    HEAD_ADD("X-Content-Type-Options: nosniff\r\nReferrer-Policy: no-referrer\r\n"
             "X-Frame-Options: DENY\r\nContent-Security-Policy: %s\r\n",
             SRV_API_CSP);
    if (resp.cache_control) HEAD_ADD("Cache-Control: %s\r\n", resp.cache_control);
    if (r->vary_origin) HEAD_ADD("Vary: Origin\r\n");
    if (r->cors_ok && r->origin) /* a listed origin: printable, no CR/LF (origin_allowed) */
        HEAD_ADD("Access-Control-Allow-Origin: %s\r\nAccess-Control-Expose-Headers: %s\r\n",
                 r->origin, SRV_CORS_EXPOSE);
    HEAD_ADD("\r\n");
#undef HEAD_ADD
    if (k < sizeof head) {
        r->bytes = resp.body_len;
        send_some(r->fd, head, k);
        send_some(r->fd, resp.body, resp.body_len);
        r->status = 413;
    }
    api_response_free(&resp);
    shutdown(r->fd, SHUT_WR);
    char sink[16384];
    for (size_t drained = 0; drained < SRV_DRAIN_MAX;) {
        ssize_t n = recv(r->fd, sink, sizeof sink, MSG_DONTWAIT);
        if (n <= 0) break;
        drained += (size_t)n;
    }
    tl_closing_on_purpose = 1;
    return MHD_NO;
}

/* Take a chunk of body: buffer it while under the limit, else count and drop it. */
void take_body(struct srv_http *h, struct srv_req *r, const char *data, size_t n)
{
    size_t limit = h->cfg->max_body;
    r->body_seen = r->body_seen + n < r->body_seen ? (size_t)-1 : r->body_seen + n;
    if (r->too_large || r->oom) return;
    if (r->body_seen > limit) {
        r->too_large = 1;
        free(r->body);
        r->body = NULL;
        r->body_len = r->body_cap = 0;
        return;
    }
    if (r->body_len + n > r->body_cap) {
        size_t cap = r->body_cap ? r->body_cap : n <= SRV_BODY_SMALL ? SRV_BODY_SMALL : SRV_BODY_CHUNK;
        while (cap < r->body_len + n)
            cap *= 2;
        if (cap > limit) cap = limit;
        char *b = realloc(r->body, cap);
        if (!b) {
            r->oom = 1;
            free(r->body);
            r->body = NULL;
            r->body_len = r->body_cap = 0;
            return;
        }
        r->body = b;
        r->body_cap = cap;
    }
    memcpy(r->body + r->body_len, data, n);
    r->body_len += n;
}
