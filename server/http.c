/* http.c — libmicrohttpd front end (see http.h): per-request state, routing,
 * answering and the libmicrohttpd request callbacks. The rest of the front
 * end, one file per DESIGN heading (shared types in http_internal.h):
 * http_body.c (BODY LIMIT, FRAMING), http_security.c (SECURITY: it decides
 * from the headers, through its own face http_security.h, and this file
 * answers), http_head.c (REQUEST HEAD: 414, 431, Host, what OPTIONS names),
 * request_id.c (the X-Request-Id), quick.c (QUICK OPERATIONS, GATED
 * OPERATIONS), answer_budget.c (ANSWER MEMORY), answer_send.c
 * (the bytes of an answer sent), conn_watch.c (CANCELLATION, SLOW CLIENTS,
 * CONNECTION FLOODS), http_daemon.c (start and stop, descriptors) and
 * io_loop.c (I/O THREADS).
 *
 * DESIGN. Per-request state (struct srv_req) is allocated on the first access
 * callback and freed in MHD_OPTION_NOTIFY_COMPLETED.
 * Server routes and inline GETs are answered on the I/O thread. Everything
 * else reserves a queue slot, suspends the connection and is submitted to the
 * pool; the worker runs api_handle() (which cannot fail) and resumes the
 * connection, and the next access callback sends the stored response. A full
 * queue answers 503 + Retry-After at once. (The worker's step cannot fail; libmicrohttpd's
 * src/examples/suspend_resume_epoll.c.)
 */
#ifdef __linux__
#define _GNU_SOURCE /* POLLRDHUP */
#endif
#include "http_internal.h"
#include "http_security.h"

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

#include "answer_mem.h"
#include "api.h"
#include "log.h"
#include "static.h"
#include "mech/base/budget.h"

static const char index_html[] =
    "<!DOCTYPE html>\n"
    "<html lang=\"en\"><head><meta charset=\"utf-8\"><title>mechd</title></head>\n"
    "<body>\n"
    "<h1>mechd</h1>\n"
    "<p>mechd is a physics computation server for a university mechanics course: it answers\n"
    "JSON over HTTP with inertia tensors, Lorentz boosts and integrated trajectories, and says\n"
    "how accurate each answer is.</p>\n"
    "<ul>\n"
    "<li><a href=\"/v1\">/v1</a> &mdash; the catalog of operations, with schemas and "
    "examples</li>\n"
    "<li><a href=\"/v1/openapi.json\">/v1/openapi.json</a> &mdash; the OpenAPI document</li>\n"
    "<li><a href=\"/healthz\">/healthz</a> and <a href=\"/metrics\">/metrics</a></li>\n"
    "</ul>\n"
    "<p>Example: <code>curl -s localhost:8080/v1</code></p>\n"
    "</body></html>\n";

/* ---- per-request state ----------------------------------------------------- */

static char *dup_str(const char *s)
{
    if (!s) return NULL;
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

/* ---- request ids and client addresses ------------------------------------------- */


/* The connection's peer address, numeric ("127.0.0.1", "::1"), or "-". */
static void client_address(struct MHD_Connection *conn, char *out, size_t n)
{
    const union MHD_ConnectionInfo *ci =
        MHD_get_connection_info(conn, MHD_CONNECTION_INFO_CLIENT_ADDRESS);
    const struct sockaddr *sa = ci ? ci->client_addr : NULL;
    const char *ok = NULL;
    if (sa && sa->sa_family == AF_INET)
        ok = inet_ntop(AF_INET, &((const struct sockaddr_in *)(const void *)sa)->sin_addr, out,
                       (socklen_t)n);
    else if (sa && sa->sa_family == AF_INET6)
        ok = inet_ntop(AF_INET6, &((const struct sockaddr_in6 *)(const void *)sa)->sin6_addr, out,
                       (socklen_t)n);
    if (!ok) snprintf(out, n, "-");
}

static void req_free(struct srv_req *r)
{
    if (!r) return;
    srv_mem_release(r->http ? r->http->mem : NULL, r->charged); /* an answer never sent */
    api_response_free(&r->aresp);
    free(r->method);
    free(r->path);
    free(r->content_type);
    free(r->query_request);
    free(r->if_none_match);
    free(r->accept_encoding);
    free(r->host);
    free(r->origin);
    free(r->forwarded_for);
    free(r->body);
    free(r);
}

/* Worker side: cannot fail; the outcome is stored in the request. After
 * MHD_resume_connection the I/O thread may free r: touch nothing after it. */
static void req_run(struct srv_job *job)
{
    struct srv_req *r = (struct srv_req *)job;
    pthread_mutex_lock(&r->http->watch_mu);
    int gone = r->client_gone;
    pthread_mutex_unlock(&r->http->watch_mu);
    if (gone) /* hung up while waiting: nobody to answer, do not run it */
        api_response_problem(&r->aresp, API_PROBLEM_CANCELLED,
                             "the client closed the connection; the request was not run");
    else
        run_api(r);
    watch_remove(r->http, r);
    r->state = REQ_DONE;
    srv_io_resume(r->io, r->conn);
}

static void req_cancel(struct srv_job *job)
{
    struct srv_req *r = (struct srv_req *)job;
    api_response_problem(&r->aresp, API_PROBLEM_CANCELLED,
                         "the server is shutting down; the request was not run");
    watch_remove(r->http, r);
    r->state = REQ_DONE;
    srv_io_resume(r->io, r->conn);
}

/* ---- answering --------------------------------------------------------------- */

/* Headers every answer built here carries: the security set, and CORS for an
 * allowed origin. vary (static, or NULL) joins Origin in one Vary header. */
static void add_common_headers(struct srv_req *r, struct MHD_Response *mr, const char *vary)
{
    MHD_add_response_header(mr, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(mr, "Referrer-Policy", "no-referrer");
    MHD_add_response_header(mr, "X-Frame-Options", "DENY");
    MHD_add_response_header(mr, "Content-Security-Policy", SRV_API_CSP);
    char both[96];
    if (vary && r->vary_origin) {
        snprintf(both, sizeof both, "%s, Origin", vary);
        MHD_add_response_header(mr, MHD_HTTP_HEADER_VARY, both);
    } else if (vary || r->vary_origin) {
        MHD_add_response_header(mr, MHD_HTTP_HEADER_VARY, vary ? vary : "Origin");
    }
    if (r->cors_ok && r->origin) {
        MHD_add_response_header(mr, "Access-Control-Allow-Origin", r->origin);
        MHD_add_response_header(mr, "Access-Control-Expose-Headers", SRV_CORS_EXPOSE);
    }
}

/* Never called: a 304 has no body (RFC 9110 15.4.5). */
static ssize_t no_body(void *cls, uint64_t pos, char *buf, size_t max)
{
    (void)cls;
    (void)pos;
    (void)buf;
    (void)max;
    return MHD_CONTENT_READER_END_OF_STREAM;
}

/* The response object of a 304. libmicrohttpd 0.9.75 sends a 304 with the
 * Content-Length of its response object, which RFC 9110 8.6 allows only when
 * it equals the 200's length: so a 304 whose 200 length is known (full_len > 0)
 * gets an object of that length whose reader is never called (no body is sent
 * for a 304), and one whose 200 length is unknown (GET ?request=: the
 * operation is not run) an object of unknown length in HTTP/1.0-compatible
 * mode, which sends no Content-Length and no chunked framing, and closes the
 * connection after the headers. */
static struct MHD_Response *not_modified_response(size_t full_len)
{
    if (full_len > 0) return MHD_create_response_from_callback(full_len, 64, no_body, NULL, NULL);
    struct MHD_Response *mr = MHD_create_response_from_callback(MHD_SIZE_UNKNOWN, 64, no_body,
                                                                NULL, NULL);
    if (mr) MHD_set_response_options(mr, MHD_RF_HTTP_1_0_COMPATIBLE_STRICT, MHD_RO_END);
    return mr;
}

/* Send resp (its body is handed to MHD, which frees it, unless it is static)
 * with Content-Type, Retry-After and X-Request-Id; a problem gets its
 * instance (the request path) if the API layer has not given it one, and its
 * request_id (the X-Request-Id sent back in the header). resp is
 * left empty. */
static enum MHD_Result answer(struct srv_req *r, struct api_response *resp)
{
    struct MHD_Response *mr;
    int status = resp->status >= 100 && resp->status <= 599 ? resp->status : 500;
    api_response_set_instance(resp, r->path ? r->path : "");
    api_response_set_request_id(resp, r->id); /* every problem names its request */
    if (status == MHD_HTTP_NOT_MODIFIED) {
        mr = not_modified_response(resp->full_length);
    } else if (resp->body && resp->body_static) {
        mr = MHD_create_response_from_buffer(resp->body_len, resp->body, MHD_RESPMEM_PERSISTENT);
    } else if (resp->body) {
        mr = answer_response(r, resp); /* answer_send.c: takes the body */
    } else {
        mr = MHD_create_response_from_buffer(0, (void *)"", MHD_RESPMEM_PERSISTENT);
    }
    r->state = REQ_ANSWERED;
    if (!mr) {
        api_response_free(resp);
        return MHD_NO; /* out of memory: MHD closes the connection */
    }
    r->bytes = status == MHD_HTTP_NOT_MODIFIED || (r->method && strcmp(r->method, "HEAD") == 0)
                   ? 0
                   : (unsigned long long)resp->body_len;
    char buf[32];
    if (resp->content_type)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_CONTENT_TYPE, resp->content_type);
    if (resp->retry_after > 0) {
        snprintf(buf, sizeof buf, "%d", resp->retry_after);
        MHD_add_response_header(mr, MHD_HTTP_HEADER_RETRY_AFTER, buf);
    }
    MHD_add_response_header(mr, "X-Request-Id", r->id);
    add_common_headers(r, mr, resp->vary);
    if (r->www_authenticate)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_WWW_AUTHENTICATE, r->www_authenticate);
    if (r->close_conn || atomic_load(&r->http->stopping))
        MHD_add_response_header(mr, MHD_HTTP_HEADER_CONNECTION, "close");
    if (resp->etag[0] && !resp->depends_on_load)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_ETAG, resp->etag);
    if (resp->depends_on_load)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    else if (resp->cache_control)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_CACHE_CONTROL, resp->cache_control);
    if (resp->content_encoding)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_CONTENT_ENCODING, resp->content_encoding);
    if (status == MHD_HTTP_METHOD_NOT_ALLOWED && resp->allow)
        MHD_add_response_header(mr, MHD_HTTP_HEADER_ALLOW, resp->allow);
    else if (status == MHD_HTTP_METHOD_NOT_ALLOWED && r->path &&
             (strcmp(r->path, "/healthz") == 0 || strcmp(r->path, "/metrics") == 0 ||
              strcmp(r->path, "/") == 0))
        MHD_add_response_header(mr, MHD_HTTP_HEADER_ALLOW, "GET, HEAD");
    enum MHD_Result ret = MHD_queue_response(r->conn, (unsigned)status, mr);
    MHD_destroy_response(mr);
    api_response_free(resp);
    if (ret == MHD_YES) r->status = status;
    return ret;
}

static enum MHD_Result answer_problem(struct srv_req *r, enum api_problem kind, const char *detail)
{
    api_response_free(&r->aresp);
    api_response_problem(&r->aresp, kind, detail);
    return answer(r, &r->aresp);
}

/* A server-owned body (copied: answer() hands bodies to MHD with free()). */
static enum MHD_Result answer_text(struct srv_req *r, int status, const char *content_type,
                                   char *owned_body, size_t len)
{
    if (!owned_body) return answer_problem(r, API_PROBLEM_INTERNAL, NULL);
    api_response_free(&r->aresp);
    r->aresp.status = status;
    r->aresp.content_type = content_type;
    r->aresp.body = owned_body;
    r->aresp.body_len = len;
    r->aresp.retry_after = 0;
    return answer(r, &r->aresp);
}

/* A problem the server decides before the API layer sees the request (401,
 * 403): the problem table's body with this detail (static text), never cached. */
static enum MHD_Result answer_server_problem(struct srv_req *r, enum api_problem kind,
                                             const char *detail)
{
    api_response_free(&r->aresp);
    api_response_problem(&r->aresp, kind, detail);
    r->aresp.cache_control = "no-store";
    return answer(r, &r->aresp);
}

/* A CORS preflight (OPTIONS with Origin and Access-Control-Request-Method) of
 * /v1 from a listed origin: 204 with the allowed methods and headers
 * (SECURITY, http_security.c, decides). A preflight from any other origin is
 * answered as a plain OPTIONS (answer_options): Allow and no CORS headers, so
 * the browser refuses the cross-origin request itself. */
static enum MHD_Result answer_preflight(struct srv_req *r)
{
    struct MHD_Response *mr =
        MHD_create_response_from_buffer(0, (void *)"", MHD_RESPMEM_PERSISTENT);
    r->state = REQ_ANSWERED;
    if (!mr) return MHD_NO;
    MHD_add_response_header(mr, "X-Request-Id", r->id);
    add_common_headers(r, mr, NULL);
    srv_preflight_headers(mr);
    enum MHD_Result ret = MHD_queue_response(r->conn, MHD_HTTP_NO_CONTENT, mr);
    MHD_destroy_response(mr);
    if (ret == MHD_YES) r->status = MHD_HTTP_NO_CONTENT;
    return ret;
}

static int is_get(const char *m)
{
    return strcmp(m, MHD_HTTP_METHOD_GET) == 0 || strcmp(m, MHD_HTTP_METHOD_HEAD) == 0;
}

/* Paths the API layer answers (operations, catalog, problem types). */
static int is_api_path(const char *p)
{
    return strcmp(p, "/v1") == 0 || strncmp(p, "/v1/", 4) == 0 || strncmp(p, "/problems/", 10) == 0;
}

/* Send a cached static file (200) or 304 when If-None-Match matches. The
 * body belongs to the static cache, which outlives the daemon. */
static enum MHD_Result answer_static(struct srv_req *r, const struct srv_static_file *f)
{
    int not_modified = srv_static_not_modified(f, r->if_none_match);
    r->route = "static";
    /* A 304 carries the 200's Content-Length, never 0 (see not_modified_response). */
    struct MHD_Response *mr =
        not_modified ? not_modified_response(f->len)
                     : MHD_create_response_from_buffer(f->len, (void *)f->body,
                                                       MHD_RESPMEM_PERSISTENT);
    r->state = REQ_ANSWERED;
    if (!mr) return MHD_NO;
    r->bytes = not_modified || (r->method && strcmp(r->method, "HEAD") == 0)
                   ? 0
                   : (unsigned long long)f->len;
    MHD_add_response_header(mr, "X-Request-Id", r->id);
    if (!not_modified) MHD_add_response_header(mr, MHD_HTTP_HEADER_CONTENT_TYPE, f->content_type);
    /* f->headers carry ETag, Cache-Control, the CSP and nosniff. */
    for (int i = 0; i < f->n_headers && i < SRV_STATIC_HEADERS; i++)
        if (f->headers[i].name && f->headers[i].value)
            MHD_add_response_header(mr, f->headers[i].name, f->headers[i].value);
    int status = not_modified ? MHD_HTTP_NOT_MODIFIED : MHD_HTTP_OK;
    enum MHD_Result ret = MHD_queue_response(r->conn, (unsigned)status, mr);
    MHD_destroy_response(mr);
    if (ret == MHD_YES) r->status = status;
    return ret;
}

/* /healthz, /metrics, static files, /: returns 1 and answers if path is a
 * server route. */
static int server_route(struct srv_http *h, struct srv_req *r, enum MHD_Result *ret)
{
    const char *p = r->path;
    int health = strcmp(p, "/healthz") == 0, metrics = strcmp(p, "/metrics") == 0,
        index = strcmp(p, "/") == 0;
    if (!health && !metrics && is_get(r->method) && !is_api_path(p)) {
        /* The front end (clients/web) when present; else the built-in page at /. */
        struct srv_static_file f;
        if (srv_static_lookup(p, &f) == 0) {
            *ret = answer_static(r, &f);
            return 1;
        }
    }
    if (!health && !metrics && !index) return 0;
    if (!is_get(r->method)) {
        char detail[96];
        snprintf(detail, sizeof detail, "%s accepts GET and HEAD only", p);
        *ret = answer_problem(r, API_PROBLEM_METHOD_NOT_ALLOWED, detail);
    } else if (health) {
        static const char ok[] = "{\"status\":\"ok\"}";
        *ret = answer_text(r, 200, "application/json", dup_str(ok), sizeof ok - 1);
    } else if (metrics) {
        struct srv_metrics_gauges g = {.workers = h->cfg->workers,
                                       .queue_capacity = h->cfg->queue,
                                       .connections_max = h->max_connections};
        unsigned long len = 0;
        srv_pool_stats(h->pool, &g.queue_depth, &g.workers_busy, &g.worker_busy_seconds);
        pthread_mutex_lock(&h->conn_mu);
        g.connections_open = h->n_conns;
        pthread_mutex_unlock(&h->conn_mu);
        srv_mem_stats(h->mem, &g.answer_memory, &g.answer_memory_max, &g.answer_memory_peak,
                      &g.answer_memory_refused);
        char *text = srv_metrics_text(&g, &len);
        *ret = answer_text(r, 200, "text/plain; version=0.0.4; charset=utf-8", text, len);
    } else {
        *ret = answer_text(r, 200, "text/html; charset=utf-8", dup_str(index_html),
                           sizeof index_html - 1);
    }
    return 1;
}

/* OPTIONS that is not an allowed CORS preflight (RFC 9110 9.3.7): 204 with
 * Allow for a path that exists (and Access-Control-Allow-Origin for a listed
 * origin), 404 otherwise. A preflight from an origin not listed gets this
 * answer too: no Access-Control-* header. */
static enum MHD_Result answer_options(struct srv_req *r)
{
    const char *allow = allowed_methods(r->path);
    if (!allow) return answer_problem(r, API_PROBLEM_NOT_FOUND, "no resource has this path");
    struct MHD_Response *mr =
        MHD_create_response_from_buffer(0, (void *)"", MHD_RESPMEM_PERSISTENT);
    r->state = REQ_ANSWERED;
    if (!mr) return MHD_NO;
    MHD_add_response_header(mr, MHD_HTTP_HEADER_ALLOW, allow);
    MHD_add_response_header(mr, "X-Request-Id", r->id);
    add_common_headers(r, mr, NULL);
    if (r->close_conn || atomic_load(&r->http->stopping))
        MHD_add_response_header(mr, MHD_HTTP_HEADER_CONNECTION, "close");
    enum MHD_Result ret = MHD_queue_response(r->conn, MHD_HTTP_NO_CONTENT, mr);
    MHD_destroy_response(mr);
    if (ret == MHD_YES) r->status = MHD_HTTP_NO_CONTENT;
    return ret;
}

/* The whole request has arrived (or is answered early): route it. */
static enum MHD_Result dispatch(struct srv_http *h, struct srv_req *r)
{
    char detail[160];
    if (!conn_claim(r)) {
        r->state = REQ_ANSWERED;
        return MHD_NO; /* the receive limit passed: the watcher closed the connection */
    }
    if (r->oom) return answer_problem(r, API_PROBLEM_INTERNAL, NULL);
    if (r->head_problem) return answer_problem(r, r->head_problem, r->head_detail);
    if (r->bad_framing) return answer_problem(r, API_PROBLEM_BAD_FRAMING, r->bad_framing);
    if (r->too_large) {
        snprintf(detail, sizeof detail, "the request body exceeds the limit of %zu bytes",
                 h->cfg->max_body);
        return answer_problem(r, API_PROBLEM_BODY_TOO_LARGE, detail);
    }
    if (r->preflight && r->cors_ok) return answer_preflight(r);
    if (strcmp(r->method, MHD_HTTP_METHOD_OPTIONS) == 0) return answer_options(r);
    enum MHD_Result ret;
    if (server_route(h, r, &ret)) return ret;

    r->areq.method = r->method;
    r->areq.path = r->path;
    r->areq.content_type = r->content_type;
    r->areq.body = r->body;
    r->areq.body_len = r->body_len;
    r->areq.max_steps = h->cfg->max_steps;
    r->areq.cancel = &r->cancel;
    r->areq.deadline = mech_clock_seconds() + (double)h->cfg->deadline_ms / 1000.0;
    r->aext.query_request = r->query_request;
    r->aext.if_none_match = r->if_none_match;
    r->aext.accept_encoding = r->accept_encoding;
    r->aext.host = r->host;
    r->aext.max_samples = h->cfg->max_samples;
    r->aext.admit = answer_admit; /* the answer-memory budget (answer_budget.c) */
    r->aext.admit_ctx = r;

    /* GET ?request= runs an operation: it goes to the pool like a POST. */
    if (strcmp(r->method, MHD_HTTP_METHOD_GET) == 0 && !r->query_request &&
        api_is_inline(r->method, r->path)) {
        api_handle_ext(&r->areq, &r->aext, &r->aresp);
        return answer(r, &r->aresp);
    }
    /* A quick POST: cheaper to answer here than to hand off (see QUICK OPERATIONS). */
    long qi = r->query_request ? -1 : api_quick_route(r->method, r->path, r->body_len);
    if (qi >= 0) {
        r->route_index = qi;
        r->quick_route = 1;
        if (quick_inline(h, r)) {
            run_api(r);
            return answer(r, &r->aresp);
        }
    }
    /* An operation that predicts its cost: started here under the cost gate,
     * finished here when predicted cheap (see GATED OPERATIONS, quick.c). */
    long gi = qi >= 0 || r->query_request ? -1 : api_gated_route(r->method, r->path);
    if (gi >= 0) {
        r->route_index = gi;
        r->gated = 1;
        if (gate_try_inline(h, r)) return answer(r, &r->aresp);
    }
    switch (srv_pool_reserve(h->pool)) {
    case SRV_POOL_FULL:
        /* A quick operation predicted too slow to answer here is still
         * answered here rather than refused while the queue is full, as
         * long as it is predicted to cost at most SRV_QUICK_FULL_FACTOR
         * times --inline-max-us: a few sampled outliers can lift a boost's
         * estimate over the limit, and a microsecond request must not get a
         * 503 for it (a CI run saw 65 of 340,000). Measured, so
         * the estimate learns from it. */
        if (r->quick_route && quick_fits_when_full(h, r)) {
            r->quick_probe = 1;
            run_api(r);
            return answer(r, &r->aresp);
        }
        snprintf(detail, sizeof detail,
                 "all %d compute workers are busy and %d requests are waiting; retry later",
                 h->cfg->workers, h->cfg->queue);
        api_response_free(&r->aresp);
        api_response_problem(&r->aresp, API_PROBLEM_QUEUE_FULL, detail);
        r->aresp.retry_after = 1;
        return answer(r, &r->aresp);
    case SRV_POOL_STOPPED:
        return answer_problem(r, API_PROBLEM_CANCELLED, "the server is shutting down");
    case SRV_POOL_OK:
        break;
    }
    r->state = REQ_QUEUED;
    /* A closed form, or an operation predicted short: the express worker may take it. */
    r->job.short_job = r->quick_route || r->job.short_job;
    watch_add(h, r);
    MHD_suspend_connection(r->conn);
    /* Cannot fail; may run req_cancel (and resume) at once if the pool stopped. */
    srv_pool_submit(h->pool, &r->job);
    return MHD_YES;
}

/* ---- libmicrohttpd callbacks ------------------------------------------------ */

enum MHD_Result on_request(void *cls, struct MHD_Connection *conn, const char *url,
                           const char *method, const char *version, const char *upload_data,
                           size_t *upload_data_size, void **con_cls)
{
    struct srv_http *h = cls;
    struct srv_req *r = *con_cls;
    tl_closing_on_purpose = 0;

    if (!r) { /* first call: headers only */
        const union MHD_ConnectionInfo *sci =
            MHD_get_connection_info(conn, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
        struct srv_conn *sc = sci ? sci->socket_context : NULL;
        if (conn_shut(sc)) return MHD_NO;
        r = calloc(1, sizeof *r);
        if (!r) return MHD_NO;
        r->conn = conn;
        r->io = srv_io_current();
        r->http = h;
        r->sc = sc;
        r->route_index = -1;
        r->fd = -1;
        const union MHD_ConnectionInfo *ci =
            MHD_get_connection_info(conn, MHD_CONNECTION_INFO_CONNECTION_FD);
        if (ci) r->fd = (int)ci->connect_fd;
        request_id(h, MHD_lookup_connection_value(conn, MHD_HEADER_KIND, "X-Request-Id"), r->id);
        if (sc && sc->client[0]) { /* formatted once per connection, not per request */
            memcpy(r->client, sc->client, sizeof r->client);
        } else {
            client_address(conn, r->client, sizeof r->client);
            if (sc) memcpy(sc->client, r->client, sizeof sc->client);
        }
        r->forwarded_for =
            dup_str(MHD_lookup_connection_value(conn, MHD_HEADER_KIND, "X-Forwarded-For"));
        r->t0 = mech_clock_seconds();
        r->job.run = req_run;
        r->job.cancel = req_cancel;
        r->method = dup_str(method ? method : "");
        r->path = dup_str(url ? url : "");
        const char *ct =
            MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_CONTENT_TYPE);
        r->content_type = dup_str(ct);
        const char *qr = MHD_lookup_connection_value(conn, MHD_GET_ARGUMENT_KIND, "request");
        r->query_request = dup_str(qr);
        const char *inm =
            MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_IF_NONE_MATCH);
        r->if_none_match = dup_str(inm);
        const char *ae =
            MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_ACCEPT_ENCODING);
        r->accept_encoding = dup_str(ae);
        const char *host = MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_HOST);
        r->host = dup_str(host);
        const char *origin =
            MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_ORIGIN);
        r->origin = dup_str(origin);
        *con_cls = r;
        atomic_fetch_add(&h->inflight, 1);
        if (!r->method || !r->path || (ct && !r->content_type) || (qr && !r->query_request) ||
            (inm && !r->if_none_match) || (ae && !r->accept_encoding) || (origin && !r->origin) ||
            (host && !r->host)) {
            r->oom = 1;
            return dispatch(h, r); /* answers 500 */
        }
        if (head_problem(r, conn, version)) {
            r->close_conn = 1;
            return dispatch(h, r); /* answers 414, 431 or 400, before any body byte is read */
        }
        r->bad_framing = framing_problem(conn, version);
        if (r->bad_framing) {
            r->close_conn = 1;
            return dispatch(h, r); /* answers 400, before any body byte is read */
        }
        struct srv_access acc; /* SECURITY (http_security.c) decides, this file answers */
        srv_access_check(h->cfg, conn, r->method, r->path, r->origin, &acc);
        r->vary_origin = acc.vary_origin;
        r->cors_ok = acc.cors_ok;
        if (acc.preflight) {
            r->preflight = 1;
            return MHD_YES;
        }
        if (acc.refusal) {
            r->www_authenticate = acc.www_authenticate;
            if (!conn_claim(r)) {
                r->state = REQ_ANSWERED;
                return MHD_NO;
            }
            return answer_server_problem(r, API_PROBLEM_UNAUTHORIZED, acc.refusal);
        }
        const char *cl =
            MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_CONTENT_LENGTH);
        if (cl) {
            errno = 0;
            char *end = NULL;
            unsigned long long n = strtoull(cl, &end, 10);
            if (errno == ERANGE || n > (unsigned long long)h->cfg->max_body) {
                r->too_large = 1; /* answered now: the body is never read */
                return dispatch(h, r);
            }
        }
        return MHD_YES;
    }

    if (*upload_data_size) {
        if (conn_shut(r->sc)) return MHD_NO; /* closed by the receive limit */
        if (r->state == REQ_RECEIVING) take_body(h, r, upload_data, *upload_data_size);
        *upload_data_size = 0;
        /* Only a chunked body gets here past the limit (a Content-Length over
         * it was answered on the first call). Within SRV_CHUNKED_GRACE of it,
         * it is still read (and dropped) to its end, then answered 413 the
         * usual way: a client that sends its whole body before reading gets
         * that answer instead of a broken pipe. Beyond it, stop now. */
        if (r->too_large && r->state == REQ_RECEIVING &&
            r->body_seen > h->cfg->max_body + (size_t)SRV_CHUNKED_GRACE)
            return refuse_mid_body(h, r);
        return MHD_YES;
    }

    switch (r->state) {
    case REQ_RECEIVING:
        return dispatch(h, r);
    case REQ_DONE:
        return answer(r, &r->aresp);
    case REQ_QUEUED:   /* not expected while suspended */
    case REQ_ANSWERED: /* response already queued */
        break;
    }
    return MHD_YES;
}

/* The /metrics route label: a bounded set, whatever paths clients send. An
 * operation's path from the route table; a server route; "static"; a /v1 or
 * /problems resource that answered 2xx/304 (a fixed set of documents);
 * anything else "other". */
static const char *route_label(const struct srv_req *r)
{
    if (r->route) return r->route;
    if (r->route_index >= 0) return api_operation_path((size_t)r->route_index);
    const char *p = r->path;
    if (!p) return "other";
    if (strcmp(p, "/healthz") == 0 || strcmp(p, "/metrics") == 0 || strcmp(p, "/") == 0) return p;
    for (size_t i = 0; i < api_operation_count(); i++)
        if (strcmp(api_operation_path(i), p) == 0) return api_operation_path(i);
    if (is_api_path(p) && ((r->status >= 200 && r->status < 300) || r->status == 304)) return p;
    return "other";
}

void on_completed(void *cls, struct MHD_Connection *conn, void **con_cls,
                  enum MHD_RequestTerminationCode toe)
{
    struct srv_http *h = cls;
    struct srv_req *r = *con_cls;
    (void)conn;
    if (!r) return;
    *con_cls = NULL;
    double now = mech_clock_seconds();
    double us = (now - r->t0) * 1e6;
    struct srv_log_entry le = {.id = r->id,
                               .client = r->client,
                               .forwarded_for = r->forwarded_for,
                               .method = r->method,
                               .path = r->path,
                               .route = route_label(r),
                               .status = r->status,
                               .usec = (long)(us + 0.5),
                               .bytes = r->bytes,
                               .answer_bytes = r->bytes};
    /* Closed before the whole answer was sent: log what was sent (a tracked
     * answer knows it to within a block; a small one went in one write that
     * did not complete, so 0 is what is known to have arrived). */
    if (toe != MHD_REQUEST_TERMINATED_COMPLETED_OK && r->status && r->bytes > 0) {
        le.cut_off = 1;
        le.bytes = r->tracked && r->sent < r->bytes ? r->sent : 0;
    }
    srv_log_request(&le);
    /* The connection is ready for its next request: the receive limit restarts.
     * Only this I/O thread moves a connection out of CONN_BUSY. */
    if (r->sc && atomic_load(&r->sc->rx) == CONN_BUSY) {
        atomic_store(&r->sc->ready_ms, (long long)(now * 1000.0));
        atomic_store(&r->sc->rx, CONN_RX);
    }
    req_free(r);
    atomic_fetch_sub(&h->inflight, 1);
}

/* URL unescaping: libmicrohttpd's %HH decoding, except that a decoded NUL
 * ("%00") becomes 0x01. A C string would otherwise end at the NUL, so that
 * "/app.js%00.html" looked like "/app.js"; a control character is refused by
 * the static lookup and matches no API route. */
size_t unescape_no_nul(void *cls, struct MHD_Connection *c, char *s)
{
    (void)cls;
    (void)c;
    size_t n = MHD_http_unescape(s);
    for (size_t i = 0; i < n; i++)
        if (s[i] == '\0') s[i] = '\x01';
    return n;
}
