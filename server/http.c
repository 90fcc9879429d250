/* http.c — libmicrohttpd front end (see http.h).
 *
 * DESIGN. Per-request state (struct srv_req) is allocated on the first access
 * callback and freed in MHD_OPTION_NOTIFY_COMPLETED. A request body is
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
 * Server routes and inline GETs are answered on the I/O thread. Everything
 * else reserves a queue slot, suspends the connection and is submitted to the
 * pool; the worker runs api_handle() (which cannot fail) and resumes the
 * connection, and the next access callback sends the stored response. A full
 * queue answers 503 + Retry-After at once. (STYLE.md §9; libmicrohttpd's
 * src/examples/suspend_resume_epoll.c.)
 *
 * SECURITY. With --token-file, every /v1 request needs the bearer token
 * (checked on the first callback, before any body byte is read; compared in
 * constant time); /healthz, /metrics, /problems/... and the front end stay open.
 * CORS is off unless --cors-origin lists origins: only those get
 * Access-Control-Allow-Origin on /v1 answers and a 204 to a preflight. Every
 * answer built here carries nosniff, Referrer-Policy, X-Frame-Options and a
 * CSP of default-src 'none' (static files carry static.c's own set).
 * Answers libmicrohttpd writes itself (431 header too large, 400 on a broken
 * request line or an unparsable Content-Length) carry none of these: it
 * offers no hook for them.
 *
 * QUICK OPERATIONS. A POST that api_quick_route() accepts (a closed-form
 * operation on a body of at most API_QUICK_MAX_BODY bytes) is answered on the
 * I/O thread, with the same deadline, step budget and cancel flag as a pooled
 * request: the suspend -> worker -> resume hand-off (two context switches, a
 * futex wake-up and an eventfd write) costs more than such an operation. It is
 * logged and counted in /metrics like any other request. The choice is
 * measured, not assumed (DESIGN.md): runs of a quick route, inline or on a
 * worker, update a moving average of the route's *thread CPU time*
 * (CLOCK_THREAD_CPUTIME_ID) per byte of request (plus SRV_QUICK_BASE_BYTES for
 * the fixed costs), and a request runs inline only while its predicted time is
 * at most --inline-max-us, so a route that turns out slow (or a large body)
 * goes to the pool and never holds an I/O thread, and /healthz, for long. CPU
 * time, not wall time: a thread preempted for a millisecond during a 5 µs
 * boost (common when the clients run on the same cores) would otherwise look
 * 200 times slower, and one such run sent every later boost to
 * the niced workers, whose small queue then refused cheap requests with 503
 * (issue 15). Reading that clock is a system call (3.5-5 µs on the 2-core VM,
 * about a boost), so one run in SRV_QUICK_SAMPLE is measured, the first run of
 * a route always; one measurement moves the average by at most a factor of
 * 1 + (SRV_QUICK_CAP - 1) / 8. The decision recovers: the average decays with
 * every measured run, and a route predicted too slow still runs inline (and
 * is measured) once in SRV_QUICK_REPROBE requests, so a full pool that
 * refuses it cannot freeze a stale estimate. The first request of a route runs
 * inline.
 *
 * I/O THREADS. libmicrohttpd runs a pool of --io-threads epoll threads (its
 * MHD_OPTION_THREAD_POOL_SIZE; default 2, the machine's cores), each with its
 * own connections; suspend/resume works per connection in that mode.
 *
 * CANCELLATION. A suspended connection is not polled by libmicrohttpd, so a
 * watcher thread checks the sockets of pooled requests every 10 ms and raises
 * the request's own cancel flag when the client has hung up: a running request
 * stops at its next budget check; a request still waiting in the queue is
 * taken out of it at once (srv_pool_remove), so its slot frees, and is
 * answered 503 cancelled and resumed by the watcher itself. A close and a
 * half-close (shutdown(SHUT_WR), as `nc -N` and some scripts send after a
 * whole request) are the same FIN on the wire, so a hang-up counts only once
 * it has been seen for SRV_HANGUP_GRACE_MS: a cheap request from a
 * half-closing client is answered (it used to be answered 503 cancelled
 * whenever it was pooled rather than run inline), a long one is cancelled.
 *
 * SLOW CLIENTS. libmicrohttpd's connection timeout counts idle time only, so a
 * client sending a byte a second is never timed out by it. Every connection
 * is therefore registered (MHD_OPTION_NOTIFY_CONNECTION) with the time it
 * became ready for a request (when it connected, or when its previous answer
 * was sent) and a receive state. The I/O thread claims the connection when a
 * whole request has arrived (or is answered early); the watcher closes a
 * connection still receiving --request-timeout-ms after it became ready:
 * shutdown(2) of its socket, after which libmicrohttpd sees end-of-file and
 * closes it on its own thread. Both sides switch the state with a
 * compare-and-swap, so exactly one wins: either the request is answered or the
 * connection is closed (no 408 is sent: the I/O thread owns what is written on
 * the socket). The socket stays open while registered (libmicrohttpd notifies
 * CLOSED before it closes the descriptor), so the watcher never touches a
 * reused descriptor. Keep-alive idle time counts towards the limit.
 *
 * CONNECTION FLOODS. Connections are counted as they register. When a new one
 * takes the count (not counting those already shutting) over
 * --max-connections, the registered connection that has waited longest for a
 * whole request (CONN_RX with the oldest ready time: idle keep-alive, connected
 * and silent, or trickling) is shut down the same way, so a health probe or a
 * real client always gets a slot: 600 idle connections against 512 used to
 * make most /healthz probes fail. Connections with a request queued, running
 * or being answered are never chosen. libmicrohttpd's own limit sits above
 * --max-connections (conn_hard_limit) to absorb connections accepted before
 * the shut ones have closed. Every SRV_REAP_PERIOD_MS the watcher also polls
 * the sockets of waiting connections and shuts down those whose client has
 * gone (end-of-file with nothing left to read, or an error, seen on two sweeps
 * in a row): libmicrohttpd's edge-triggered epoll misses a FIN that arrived
 * before it accepted the connection, and 1,500 half-sent, closed requests
 * otherwise sat in CLOSE-WAIT, holding every slot, until the idle timeout.
 * Both are counted in /metrics (mechd_connections_evicted_total,
 * mechd_connections_reaped_total) next to mechd_connections_open.
 */
#ifdef __linux__
#define _GNU_SOURCE /* POLLRDHUP */
#endif
#include "http.h"

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
#include "routes.h"
#include "static.h"
#include "mech/budget.h"

#ifndef POLLRDHUP
#define POLLRDHUP 0 /* not Linux: a gone client is seen by POLLHUP/POLLERR only */
#endif

#define SRV_CONNECTION_TIMEOUT_S 30u /* idle/slow connections are closed after this */
#define SRV_BODY_CHUNK 4096u         /* first allocation for a body of unknown length */
#define SRV_BODY_SMALL 512u          /* ... unless its first piece fits in this (a quick request):
                                        glibc serves < 1 KiB from its small bins, while every
                                        larger malloc first consolidates the fast bins */
#define SRV_WATCH_PERIOD_MS 10       /* how often suspended clients are checked for a hang-up */
#define SRV_REAP_PERIOD_MS 100       /* how often waiting connections are checked for a gone client */
#define SRV_HANGUP_GRACE_MS 500      /* end-of-file seen this long before a pooled request is cancelled */
#define SRV_QUICK_BASE_BYTES 512u    /* the fixed cost of a request, in body bytes */
#define SRV_TRIM_BYTES (4u << 20)    /* freeing an answer this large returns free heap to the OS */
#define SRV_DRAIN_MAX (1u << 20)     /* bytes read and dropped after a mid-body 413 */
#define SRV_CHUNKED_GRACE (1u << 20) /* a chunked body is read this far past --max-body */
#define SRV_REQUEST_ID_MAX 64        /* longest X-Request-Id kept from a client */
#define SRV_QUICK_SAMPLE 16u         /* a quick route's CPU time is read on one run in this many */
#define SRV_QUICK_CAP 8              /* a measurement counts as at most this many times the average */
#define SRV_QUICK_REPROBE 64u        /* a route predicted too slow runs inline once in this many */

/* Sent with every answer mechd builds (static files carry their own set from
 * static.c: same nosniff / Referrer-Policy / X-Frame-Options, a CSP that lets
 * the front end load its own scripts). JSON and text need no sources at all. */
#define SRV_API_CSP                                                                                \
    "default-src 'none'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'"
/* CORS (only for origins listed with --cors-origin). */
#define SRV_CORS_METHODS "GET, HEAD, POST, OPTIONS"
#define SRV_CORS_HEADERS "Authorization, Content-Type, If-None-Match"
#define SRV_CORS_EXPOSE "ETag, Retry-After, X-Request-Id"
#define SRV_CORS_MAX_AGE "600"

struct srv_req;

/* Per quick route (api_routes index). Relaxed atomics: a lost update only
 * delays the average or shifts a sample by one request. */
struct srv_quick_stat {
    atomic_llong cost;   /* moving average of thread CPU ns per KiB of (body +
                            SRV_QUICK_BASE_BYTES); 0 = not measured yet */
    atomic_uint runs;    /* runs so far: every SRV_QUICK_SAMPLE-th is measured */
    atomic_uint too_slow; /* requests predicted over --inline-max-us: every
                             SRV_QUICK_REPROBE-th runs inline anyway */
};

/* Receive state of a connection (struct srv_conn.rx), switched by CAS. */
enum conn_rx {
    CONN_RX = 0,    /* waiting for or receiving a request: the receive limit runs */
    CONN_BUSY,      /* claimed by the I/O thread: request queued, running or answering */
    CONN_SHUT,      /* the server shut the socket down (receive limit, room for a new
                       connection, client gone); libmicrohttpd closes it. Final. */
};

/* One per open connection (libmicrohttpd's socket context), in http->conns
 * under conn_mu from NOTIFY_CONNECTION STARTED to CLOSED. */
struct srv_conn {
    int fd;
    atomic_int rx;         /* enum conn_rx */
    atomic_llong ready_ms; /* mech_clock_seconds() in ms when it became ready for a request */
    int eof_sweeps;        /* consecutive reaper sweeps that found the client gone (conn_mu) */
    struct srv_conn *prev, *next;
};

struct srv_http {
    struct MHD_Daemon *daemon;
    const struct srv_config *cfg;
    struct srv_pool *pool;
    volatile int cancel; /* raised at shutdown; copied into every pooled request's flag */
    /* Requests handed to the pool (queued or running), watched for a client
     * hang-up by the watcher thread. Guarded by watch_mu. */
    pthread_mutex_t watch_mu;
    struct srv_req *watched;
    int watch_stop;
    int watch_started;
    pthread_t watcher;
    int listen_fd; /* from MHD_quiesce_daemon, closed after stop; -1 if none */
    atomic_ulong next_id; /* only for request ids when getrandom(2) fails */
    atomic_int stopping;  /* SIGTERM: not accepting; answers carry Connection: close */
    atomic_int inflight; /* requests between first callback and completion */
    /* Open connections, for the receive time limit, room for new ones and
     * reaping dead peers. Guarded by conn_mu. */
    pthread_mutex_t conn_mu;
    struct srv_conn *conns;
    int n_conns; /* registered connections */
    int n_shut;  /* ... of which CONN_SHUT (closing, no longer counted against the limit) */
    /* The reaper's poll set (watcher thread only), grown as needed. */
    struct pollfd *reap_pfd;
    struct srv_conn **reap_conn;
    size_t reap_cap;
    /* Per route (api_routes index): the measured cost of quick routes (see
     * QUICK OPERATIONS); NULL if it could not be allocated (nothing inline). */
    struct srv_quick_stat *quick;
};

enum req_state {
    REQ_RECEIVING = 0, /* headers and body arriving */
    REQ_QUEUED,        /* suspended, owned by the pool */
    REQ_DONE,          /* aresp filled by a worker (or cancel), connection resumed */
    REQ_ANSWERED,      /* response queued to MHD */
};

struct srv_req {
    struct srv_job job; /* first member: the pool hands it back to run/cancel */
    struct MHD_Connection *conn;
    char id[SRV_REQUEST_ID_MAX + 1]; /* X-Request-Id: the client's (validated) or generated */
    char client[48];                 /* peer address, numeric */
    char *forwarded_for;             /* owned copy of X-Forwarded-For, or NULL */
    unsigned long long bytes;        /* response body bytes sent */
    double t0;
    char *method, *path, *content_type;  /* owned copies */
    char *query_request, *if_none_match; /* owned copies: ?request= (decoded), If-None-Match */
    char *accept_encoding;               /* owned copy of Accept-Encoding, or NULL */
    char *body;
    size_t body_len, body_cap, body_seen;
    int too_large;
    int oom;
    const char *bad_framing; /* why the body's framing is refused (static text), or NULL */
    int close_conn;          /* answer with Connection: close */
    int cors_ok;       /* Origin is in --cors-origin: send Access-Control-Allow-Origin */
    int vary_origin;   /* a /v1 answer while CORS is on: send Vary: Origin */
    int preflight;     /* a CORS preflight: answered in dispatch (keeps the connection) */
    const char *route; /* metrics label when the server knows it ("static", ...), or NULL */
    char *origin;      /* owned copy of the Origin header, or NULL */
    const char *www_authenticate; /* static value for a 401, or NULL */
    enum req_state state;
    int status; /* HTTP status sent, 0 if none */
    struct api_request areq;
    struct api_request_ext aext;
    struct api_response aresp;
    /* Cooperative cancellation (pooled requests only). areq.cancel points at
     * `cancel`; the watcher raises it when the client hangs up (client_gone),
     * srv_http_quiesce when the server stops. Written with __atomic stores. */
    volatile int cancel;
    int client_gone;
    long long eof_since_ms; /* when the watcher first saw end-of-file in a row, 0 if not */
    int fd; /* the connection's socket, -1 if unknown */
    struct srv_http *http;
    struct srv_conn *sc; /* the connection's registration, or NULL */
    long route_index;    /* index in api_routes of a POST to an operation, else -1 */
    int quick_route;     /* route is quick and the body small enough (api_quick_route) */
    int quick_probe;     /* runs inline although predicted too slow: measure it */
    struct srv_req *watch_prev, *watch_next; /* in http->watched, under watch_mu */
    int watching;
};

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

/* May a client-given X-Request-Id be kept? 1..SRV_REQUEST_ID_MAX characters of
 * [A-Za-z0-9._:+/=-]: enough for UUIDs, hex, base64 and the ids proxies make,
 * nothing that needs escaping in a header, a log line or a JSON string. */
static int request_id_ok(const char *s)
{
    size_t n = 0;
    if (!s) return 0;
    for (; s[n]; n++) {
        char c = s[n];
        if (n >= SRV_REQUEST_ID_MAX ||
            !((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '.' || c == '_' || c == ':' || c == '+' || c == '/' || c == '=' || c == '-'))
            return 0;
    }
    return n > 0;
}

/* A request id into out (SRV_REQUEST_ID_MAX + 1 bytes): `given` (the incoming
 * X-Request-Id) when request_id_ok, else 32 lower-case hex digits of 128 random
 * bits from getrandom(2), so ids from any number of replicas do not collide
 * (probability ~2^-65 for 2^32 requests) without coordination. Should the
 * kernel refuse getrandom, the bits come from the clock, the process id and a
 * counter through splitmix64 (unique within the process, very likely across). */
static void request_id(struct srv_http *h, const char *given, char *out)
{
    if (request_id_ok(given)) {
        strcpy(out, given);
        return;
    }
    unsigned char b[16];
    ssize_t got = getrandom(b, sizeof b, GRND_NONBLOCK);
    if (got != (ssize_t)sizeof b) {
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        unsigned long long x =
            (unsigned long long)ts.tv_sec * 1000000000ULL + (unsigned long long)ts.tv_nsec;
        unsigned long long y =
            ((unsigned long long)getpid() << 32) ^ atomic_fetch_add(&h->next_id, 1);
        for (int half = 0; half < 2; half++) {
            unsigned long long z = (half ? y : x) + 0x9e3779b97f4a7c15ULL;
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            z ^= z >> 31;
            for (int i = 0; i < 8; i++)
                b[half * 8 + i] = (unsigned char)(z >> (8 * i));
        }
    }
    static const char hex[] = "0123456789abcdef";
    for (int i = 0; i < 16; i++) {
        out[2 * i] = hex[b[i] >> 4];
        out[2 * i + 1] = hex[b[i] & 15];
    }
    out[32] = '\0';
}

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
    api_response_free(&r->aresp);
    free(r->method);
    free(r->path);
    free(r->content_type);
    free(r->query_request);
    free(r->if_none_match);
    free(r->accept_encoding);
    free(r->origin);
    free(r->forwarded_for);
    free(r->body);
    free(r);
}

/* ---- watching pooled requests for a client hang-up ------------------------------ */

/* Add r to the watched list (before it is submitted to the pool). */
static void watch_add(struct srv_http *h, struct srv_req *r)
{
    pthread_mutex_lock(&h->watch_mu);
    if (__atomic_load_n(&h->cancel, __ATOMIC_SEQ_CST))
        __atomic_store_n(&r->cancel, 1, __ATOMIC_SEQ_CST);
    r->watch_prev = NULL;
    r->watch_next = h->watched;
    if (h->watched) h->watched->watch_prev = r;
    h->watched = r;
    r->watching = 1;
    pthread_mutex_unlock(&h->watch_mu);
}

/* Unlink r from the watched list; watch_mu held. */
static void watch_unlink(struct srv_http *h, struct srv_req *r)
{
    if (r->watching) {
        if (r->watch_prev)
            r->watch_prev->watch_next = r->watch_next;
        else
            h->watched = r->watch_next;
        if (r->watch_next) r->watch_next->watch_prev = r->watch_prev;
        r->watch_prev = r->watch_next = NULL;
        r->watching = 0;
    }
}

/* Remove r (before its connection is resumed: after that r may be freed). */
static void watch_remove(struct srv_http *h, struct srv_req *r)
{
    pthread_mutex_lock(&h->watch_mu);
    watch_unlink(h, r);
    pthread_mutex_unlock(&h->watch_mu);
}

/* Has the peer closed its side? A suspended connection is not polled by
 * libmicrohttpd, so look at the socket: readable with recv() peeking 0 bytes
 * (EOF) or an error means the client is gone; readable with data (a pipelined
 * request) is not a hang-up. A client that half-closes (shutdown(SHUT_WR))
 * after sending its request is treated as gone too: HTTP/1.1 clients do not
 * do that in practice (RFC 9112 §9.6), and nginx's client-abort check does
 * the same. */
static int peer_closed(int fd)
{
    struct pollfd pfd = {fd, POLLIN, 0};
    if (poll(&pfd, 1, 0) <= 0) return 0;
    if (pfd.revents & (POLLERR | POLLHUP | POLLNVAL)) return 1;
    if (!(pfd.revents & POLLIN)) return 0;
    char c;
    ssize_t n = recv(fd, &c, 1, MSG_PEEK | MSG_DONTWAIT);
    if (n == 0) return 1;
    return n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR;
}

static long long now_ms(void)
{
    return (long long)(mech_clock_seconds() * 1000.0);
}

/* Shut down connection c if it is still waiting for or receiving a request
 * (CONN_RX -> CONN_SHUT; conn_mu held), counting it with count(1) in /metrics
 * before the client can see the close: libmicrohttpd then sees end-of-file
 * and closes it on its own thread. Registered, so the descriptor is still
 * libmicrohttpd's open socket. Returns 1 if this call shut it down, 0 if the
 * I/O thread had claimed it (or it was already shut). */
static int conn_shut_down(struct srv_http *h, struct srv_conn *c, void (*count)(unsigned long))
{
    int expected = CONN_RX;
    if (!atomic_compare_exchange_strong(&c->rx, &expected, CONN_SHUT)) return 0;
    h->n_shut++;
    count(1);
    if (c->fd >= 0) shutdown(c->fd, SHUT_RDWR);
    return 1;
}

/* Close every connection that has been receiving one request for longer than
 * --request-timeout-ms (see SLOW CLIENTS above) and count it in /metrics.
 * Returns how many. Lock order: conn_mu, then log.c's counters. */
static int close_slow_connections(struct srv_http *h)
{
    long long now = now_ms(), limit = h->cfg->request_timeout_ms;
    int n = 0;
    if (limit <= 0) return 0; /* no limit configured */
    pthread_mutex_lock(&h->conn_mu);
    for (struct srv_conn *c = h->conns; c; c = c->next) {
        if (atomic_load(&c->rx) != CONN_RX || now - atomic_load(&c->ready_ms) <= limit) continue;
        n += conn_shut_down(h, c, srv_metrics_count_timeouts);
    }
    pthread_mutex_unlock(&h->conn_mu);
    return n;
}

/* Make room for a new connection beyond --max-connections (conn_mu held):
 * shut down the connection that has waited longest for a whole request
 * (CONN_RX with the oldest ready_ms: an idle keep-alive connection, a client
 * that connected and sent nothing, or a slow sender), other than `fresh`.
 * Connections whose request is queued, running or being answered are never
 * chosen. Returns 1 if one was shut down. */
static int evict_longest_waiting(struct srv_http *h, const struct srv_conn *fresh)
{
    struct srv_conn *victim = NULL;
    long long oldest = 0;
    for (struct srv_conn *c = h->conns; c; c = c->next) {
        if (c == fresh || atomic_load(&c->rx) != CONN_RX) continue;
        long long t = atomic_load(&c->ready_ms);
        if (!victim || t < oldest) {
            victim = c;
            oldest = t;
        }
    }
    return victim ? conn_shut_down(h, victim, srv_metrics_count_evictions) : 0;
}

/* Did the client go away, given poll()'s revents for its socket? An error or
 * a hang-up, or end-of-file (POLLRDHUP) with nothing left to read: a request
 * whose bytes are still in the socket is left for libmicrohttpd to read. */
static int peer_gone(int fd, short revents)
{
    if (revents & (POLLERR | POLLHUP | POLLNVAL)) return 1;
    if (!(revents & POLLRDHUP)) return 0;
    char c;
    ssize_t n = recv(fd, &c, 1, MSG_PEEK | MSG_DONTWAIT);
    if (n == 0) return 1;
    return n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR;
}

/* Close connections waiting for a request whose client has gone (closed its
 * socket, or half-closed it after a partial request). libmicrohttpd's epoll
 * loop misses such a FIN when it arrived before the connection was accepted
 * (edge-triggered: the one readiness event is spent reading the partial
 * request), and the socket would sit in CLOSE-WAIT, holding a connection slot,
 * until the idle timeout. One poll() over every CONN_RX socket; a connection
 * is shut down when two sweeps in a row (SRV_REAP_PERIOD_MS apart) find its
 * client gone, so a request that arrived with its FIN and is being read
 * (bytes already consumed, not yet claimed) is not cut. Returns how many.
 * Watcher thread only. Lock order: conn_mu, then log.c's counters. */
static int reap_dead_peers(struct srv_http *h)
{
    int n = 0;
    pthread_mutex_lock(&h->conn_mu);
    size_t want = (size_t)(h->n_conns > 0 ? h->n_conns : 0);
    if (want > h->reap_cap) {
        size_t cap = want + want / 2 + 16;
        struct pollfd *p = realloc(h->reap_pfd, cap * sizeof *p);
        if (p) h->reap_pfd = p;
        struct srv_conn **c = p ? realloc(h->reap_conn, cap * sizeof *c) : NULL;
        if (c) h->reap_conn = c;
        if (p && c) h->reap_cap = cap;
    }
    size_t k = 0;
    for (struct srv_conn *c = h->conns; c && k < h->reap_cap; c = c->next) {
        if (c->fd < 0 || atomic_load(&c->rx) != CONN_RX) continue;
        h->reap_pfd[k] = (struct pollfd){c->fd, POLLRDHUP, 0};
        h->reap_conn[k++] = c;
    }
    if (k > 0 && poll(h->reap_pfd, (nfds_t)k, 0) > 0) {
        for (size_t i = 0; i < k; i++) {
            struct srv_conn *c = h->reap_conn[i];
            if (!h->reap_pfd[i].revents || !peer_gone(c->fd, h->reap_pfd[i].revents)) {
                c->eof_sweeps = 0;
                continue;
            }
            if (++c->eof_sweeps >= 2) n += conn_shut_down(h, c, srv_metrics_count_reaped);
        }
    } else {
        for (size_t i = 0; i < k; i++)
            h->reap_conn[i]->eof_sweeps = 0;
    }
    pthread_mutex_unlock(&h->conn_mu);
    return n;
}

/* The watcher thread, every SRV_WATCH_PERIOD_MS: raise the cancel flag of each
 * pooled request whose client hung up (a running one stops at its next budget
 * check: mech_budget_check reads the flag every 256 steps); take such a
 * request out of the queue if it is still waiting there, answer it 503 and
 * resume its connection (the slot frees at once); close connections that
 * are too slow to send their request; every SRV_REAP_PERIOD_MS, close
 * waiting connections whose client has gone. Lock order: watch_mu, then the
 * pool's. */
static void *watcher_main(void *arg)
{
    struct srv_http *h = arg;
    for (unsigned round = 1;; round++) {
        pthread_mutex_lock(&h->watch_mu);
        if (h->watch_stop) {
            pthread_mutex_unlock(&h->watch_mu);
            break;
        }
        struct srv_req *next;
        for (struct srv_req *r = h->watched; r; r = next) {
            next = r->watch_next;
            if (r->fd >= 0 && !r->client_gone) {
                if (!peer_closed(r->fd)) {
                    r->eof_since_ms = 0;
                } else if (!r->eof_since_ms) {
                    r->eof_since_ms = now_ms();
                } else if (now_ms() - r->eof_since_ms >= SRV_HANGUP_GRACE_MS) {
                    r->client_gone = 1;
                    __atomic_store_n(&r->cancel, 1, __ATOMIC_SEQ_CST);
                }
            }
            /* Not found when a worker has it (it sees client_gone), when it is
             * not submitted yet (tried again next round) or when the pool
             * stopped (req_cancel answers it). Found: the pool forgets it and
             * it is ours to finish, as req_run would. */
            if (r->client_gone && srv_pool_remove(h->pool, &r->job)) {
                api_response_problem(&r->aresp, API_PROBLEM_CANCELLED,
                                     "the client closed the connection; the request was not run");
                watch_unlink(h, r);
                r->state = REQ_DONE;
                MHD_resume_connection(r->conn); /* r may be freed from here on */
            }
        }
        pthread_mutex_unlock(&h->watch_mu);
        int closed = close_slow_connections(h);
        if (closed > 0) {
            srv_log_note("closed %d connection%s that sent no whole request within %ld ms", closed,
                         closed == 1 ? "" : "s", h->cfg->request_timeout_ms);
        }
        if (round % (SRV_REAP_PERIOD_MS / SRV_WATCH_PERIOD_MS) == 0) {
            int reaped = reap_dead_peers(h);
            if (reaped > 0)
                srv_log_note("closed %d waiting connection%s whose client had gone", reaped,
                             reaped == 1 ? "" : "s");
        }
        struct timespec ts = {0, SRV_WATCH_PERIOD_MS * 1000L * 1000L};
        nanosleep(&ts, NULL);
    }
    return NULL;
}

/* The I/O thread claims the connection for the request it is about to answer
 * or queue. Returns 0 if the watcher has already timed it out: the caller
 * returns MHD_NO and libmicrohttpd closes the connection. */
static int conn_claim(struct srv_req *r)
{
    if (!r->sc) return 1;
    int expected = CONN_RX;
    if (atomic_compare_exchange_strong(&r->sc->rx, &expected, CONN_BUSY)) return 1;
    return expected != CONN_SHUT;
}

static int conn_shut(const struct srv_conn *c)
{
    return c && atomic_load(&c->rx) == CONN_SHUT;
}

/* NOTIFY_CONNECTION: register a new connection, unregister a closing one (on
 * its I/O thread; the descriptor is closed only after CLOSED returns). */
static void on_connection(void *cls, struct MHD_Connection *conn, void **socket_context,
                          enum MHD_ConnectionNotificationCode code)
{
    struct srv_http *h = cls;
    if (code == MHD_CONNECTION_NOTIFY_STARTED) {
        struct srv_conn *c = calloc(1, sizeof *c);
        *socket_context = c;
        if (!c) return; /* served without the receive limit (the idle timeout still applies) */
        const union MHD_ConnectionInfo *ci =
            MHD_get_connection_info(conn, MHD_CONNECTION_INFO_CONNECTION_FD);
        c->fd = ci ? (int)ci->connect_fd : -1;
        atomic_init(&c->rx, CONN_RX);
        atomic_init(&c->ready_ms, now_ms());
        pthread_mutex_lock(&h->conn_mu);
        c->prev = NULL;
        c->next = h->conns;
        if (h->conns) h->conns->prev = c;
        h->conns = c;
        h->n_conns++;
        /* Over --max-connections (not counting those already closing): make
         * room, so a health probe or a real client gets in during a flood. */
        if (h->n_conns - h->n_shut > h->cfg->max_connections) evict_longest_waiting(h, c);
        pthread_mutex_unlock(&h->conn_mu);
    } else if (code == MHD_CONNECTION_NOTIFY_CLOSED) {
        struct srv_conn *c = *socket_context;
        *socket_context = NULL;
        if (!c) return;
        pthread_mutex_lock(&h->conn_mu);
        if (c->prev)
            c->prev->next = c->next;
        else
            h->conns = c->next;
        if (c->next) c->next->prev = c->prev;
        h->n_conns--;
        if (atomic_load(&c->rx) == CONN_SHUT) h->n_shut--;
        pthread_mutex_unlock(&h->conn_mu);
        free(c);
    }
}

/* ---- quick operations: measured cost -------------------------------------------- */

static unsigned long long quick_units(size_t body_len)
{
    return (unsigned long long)body_len + SRV_QUICK_BASE_BYTES;
}

/* CPU time this thread has used, in ns; -1 if the clock cannot be read. */
static long long thread_cpu_ns(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return -1;
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Fold one measured run (cpu_ns of thread CPU time for a body of body_len
 * bytes) into the route's moving average: weight 1/8, the measurement capped
 * at SRV_QUICK_CAP times the average, so one outlier (a page fault, a cold
 * cache) cannot send a route to the pool on its own. */
static void quick_record(struct srv_quick_stat *q, long long cpu_ns, size_t body_len)
{
    long long per_kib = (long long)((double)cpu_ns * 1024.0 / (double)quick_units(body_len)) + 1;
    long long old = atomic_load_explicit(&q->cost, memory_order_relaxed);
    if (old > 0 && per_kib > SRV_QUICK_CAP * old) per_kib = SRV_QUICK_CAP * old;
    atomic_store_explicit(&q->cost, old ? old + (per_kib - old) / 8 : per_kib,
                          memory_order_relaxed);
}

/* Run the API on r; for a quick route, measure the run's thread CPU time on
 * one run in SRV_QUICK_SAMPLE (and on every probe) for the route's average. */
static void run_api(struct srv_req *r)
{
    struct srv_quick_stat *q =
        r->quick_route && r->http->quick ? &r->http->quick[r->route_index] : NULL;
    int measure =
        q && (r->quick_probe ||
              atomic_fetch_add_explicit(&q->runs, 1, memory_order_relaxed) % SRV_QUICK_SAMPLE == 0);
    long long c0 = measure ? thread_cpu_ns() : -1;
    api_handle_ext(&r->areq, &r->aext, &r->aresp);
    if (c0 < 0) return;
    long long c1 = thread_cpu_ns();
    if (c1 >= c0) quick_record(q, c1 - c0, r->body_len);
}

/* Whether the quick request r runs inline: predicted to finish within
 * --inline-max-us, or (once in SRV_QUICK_REPROBE requests predicted over it)
 * a probe that re-measures the route, so the estimate can come back down. */
static int quick_inline(struct srv_http *h, struct srv_req *r)
{
    if (!r->quick_route || !h->quick || h->cfg->inline_max_us <= 0) return 0;
    struct srv_quick_stat *q = &h->quick[r->route_index];
    long long per_kib = atomic_load_explicit(&q->cost, memory_order_relaxed);
    double predicted_ns = (double)per_kib * (double)quick_units(r->body_len) / 1024.0;
    if (predicted_ns <= (double)h->cfg->inline_max_us * 1000.0) return 1;
    unsigned n = atomic_fetch_add_explicit(&q->too_slow, 1, memory_order_relaxed);
    if (n % SRV_QUICK_REPROBE != SRV_QUICK_REPROBE - 1) return 0;
    r->quick_probe = 1;
    return 1;
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
    MHD_resume_connection(r->conn);
}

static void req_cancel(struct srv_job *job)
{
    struct srv_req *r = (struct srv_req *)job;
    api_response_problem(&r->aresp, API_PROBLEM_CANCELLED,
                         "the server is shutting down; the request was not run");
    watch_remove(r->http, r);
    r->state = REQ_DONE;
    MHD_resume_connection(r->conn);
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

/* MHD's free of an answer body: a large answer (a long trajectory, a batch)
 * leaves megabytes of freed heap in the worker's and I/O thread's malloc
 * arenas, which glibc keeps; give them back to the OS at once. */
static void free_answer(void *body)
{
    size_t n = malloc_usable_size(body);
    free(body);
    if (n >= SRV_TRIM_BYTES) malloc_trim(0);
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
        mr = MHD_create_response_from_buffer_with_free_callback(resp->body_len, resp->body,
                                                                 free_answer);
        if (mr) resp->body = NULL; /* MHD owns it now */
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

/* A problem+json the API layer has no kind for (401, 403): type, title and
 * detail are static text (nothing from the request, so nothing to escape). */
static enum MHD_Result answer_server_problem(struct srv_req *r, int status, const char *slug,
                                             const char *title, const char *detail)
{
    char *body = malloc(512);
    if (!body) return answer_problem(r, API_PROBLEM_INTERNAL, NULL);
    int n = snprintf(body, 512,
                     "{\"type\":\"/problems/%s\",\"title\":\"%s\",\"status\":%d,"
                     "\"detail\":\"%s\"}",
                     slug, title, status, detail);
    if (n < 0 || n >= 512) {
        free(body);
        return answer_problem(r, API_PROBLEM_INTERNAL, NULL);
    }
    api_response_free(&r->aresp);
    r->aresp.status = status;
    r->aresp.content_type = "application/problem+json";
    r->aresp.body = body;
    r->aresp.body_len = (size_t)n;
    r->aresp.retry_after = 0;
    r->aresp.cache_control = "no-store";
    return answer(r, &r->aresp);
}

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

/* CORS preflight (OPTIONS with Origin and Access-Control-Request-Method) for
 * /v1: 204 with the allowed methods and headers for a listed origin, else 403.
 * Preflights carry no credentials, so they are answered before the token check. */
static enum MHD_Result answer_preflight(struct srv_req *r)
{
    if (!r->cors_ok)
        return answer_server_problem(r, 403, "cors-origin-not-allowed", "Origin not allowed",
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
        int queued = 0, busy = 0;
        double busy_s = 0;
        unsigned long len = 0;
        srv_pool_stats(h->pool, &queued, &busy, &busy_s);
        pthread_mutex_lock(&h->conn_mu);
        int open_conns = h->n_conns;
        pthread_mutex_unlock(&h->conn_mu);
        char *text = srv_metrics_text(queued, busy, h->cfg->workers, h->cfg->queue, busy_s,
                                      open_conns, h->cfg->max_connections, &len);
        *ret = answer_text(r, 200, "text/plain; version=0.0.4; charset=utf-8", text, len);
    } else {
        *ret = answer_text(r, 200, "text/html; charset=utf-8", dup_str(index_html),
                           sizeof index_html - 1);
    }
    return 1;
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
    if (r->bad_framing) return answer_problem(r, API_PROBLEM_BAD_FRAMING, r->bad_framing);
    if (r->too_large) {
        snprintf(detail, sizeof detail, "the request body exceeds the limit of %zu bytes",
                 h->cfg->max_body);
        return answer_problem(r, API_PROBLEM_BODY_TOO_LARGE, detail);
    }
    if (r->preflight) return answer_preflight(r);
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
    r->aext.max_samples = h->cfg->max_samples;

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
    switch (srv_pool_reserve(h->pool)) {
    case SRV_POOL_FULL:
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
    watch_add(h, r);
    MHD_suspend_connection(r->conn);
    /* Cannot fail; may run req_cancel (and resume) at once if the pool stopped. */
    srv_pool_submit(h->pool, &r->job);
    return MHD_YES;
}

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
static const char *framing_problem(struct MHD_Connection *conn, const char *version)
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
static _Thread_local int tl_closing_on_purpose;

/* libmicrohttpd's error log (MHD_OPTION_EXTERNAL_LOGGER): its messages as it
 * would print them on stderr, minus the false alarm above. */
static void mhd_logger(void *cls, const char *fmt, va_list ap)
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
static enum MHD_Result refuse_mid_body(struct srv_http *h, struct srv_req *r)
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
static void take_body(struct srv_http *h, struct srv_req *r, const char *data, size_t n)
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

/* ---- libmicrohttpd callbacks ------------------------------------------------ */

static enum MHD_Result on_request(void *cls, struct MHD_Connection *conn, const char *url,
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
        r->http = h;
        r->sc = sc;
        r->route_index = -1;
        r->fd = -1;
        const union MHD_ConnectionInfo *ci =
            MHD_get_connection_info(conn, MHD_CONNECTION_INFO_CONNECTION_FD);
        if (ci) r->fd = (int)ci->connect_fd;
        request_id(h, MHD_lookup_connection_value(conn, MHD_HEADER_KIND, "X-Request-Id"), r->id);
        client_address(conn, r->client, sizeof r->client);
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
        const char *origin =
            MHD_lookup_connection_value(conn, MHD_HEADER_KIND, MHD_HTTP_HEADER_ORIGIN);
        r->origin = dup_str(origin);
        *con_cls = r;
        atomic_fetch_add(&h->inflight, 1);
        if (!r->method || !r->path || (ct && !r->content_type) || (qr && !r->query_request) ||
            (inm && !r->if_none_match) || (ae && !r->accept_encoding) || (origin && !r->origin)) {
            r->oom = 1;
            return dispatch(h, r); /* answers 500 */
        }
        r->bad_framing = framing_problem(conn, version);
        if (r->bad_framing) {
            r->close_conn = 1;
            return dispatch(h, r); /* answers 400, before any body byte is read */
        }
        if (is_v1_path(r->path)) {
            int cors_on = h->cfg->cors_origins[0] != '\0';
            r->vary_origin = cors_on;
            r->cors_ok = cors_on && r->origin && origin_allowed(h->cfg->cors_origins, r->origin);
            if (strcmp(r->method, MHD_HTTP_METHOD_OPTIONS) == 0 && r->origin &&
                MHD_lookup_connection_value(conn, MHD_HEADER_KIND,
                                            "Access-Control-Request-Method")) {
                r->preflight = 1;
                return MHD_YES;
            }
            if (h->cfg->token_len > 0 &&
                !token_ok(h->cfg, MHD_lookup_connection_value(conn, MHD_HEADER_KIND,
                                                              MHD_HTTP_HEADER_AUTHORIZATION))) {
                int given = MHD_lookup_connection_value(conn, MHD_HEADER_KIND,
                                                        MHD_HTTP_HEADER_AUTHORIZATION) != NULL;
                r->www_authenticate = given ? "Bearer realm=\"mechd\", error=\"invalid_token\""
                                            : "Bearer realm=\"mechd\"";
                if (!conn_claim(r)) {
                    r->state = REQ_ANSWERED;
                    return MHD_NO;
                }
                return answer_server_problem(
                    r, 401, "unauthorized", "Unauthorized",
                    given ? "the bearer token is not valid for this server"
                          : "this server requires 'Authorization: Bearer TOKEN' for /v1");
            }
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
    if (r->route_index >= 0) return api_routes[r->route_index]->path;
    const char *p = r->path;
    if (!p) return "other";
    if (strcmp(p, "/healthz") == 0 || strcmp(p, "/metrics") == 0 || strcmp(p, "/") == 0) return p;
    for (size_t i = 0; i < api_route_count; i++)
        if (strcmp(api_routes[i]->path, p) == 0) return api_routes[i]->path;
    if (is_api_path(p) && ((r->status >= 200 && r->status < 300) || r->status == 304)) return p;
    return "other";
}

static void on_completed(void *cls, struct MHD_Connection *conn, void **con_cls,
                         enum MHD_RequestTerminationCode toe)
{
    struct srv_http *h = cls;
    struct srv_req *r = *con_cls;
    (void)conn;
    (void)toe;
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
                               .bytes = r->bytes};
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
static size_t unescape_no_nul(void *cls, struct MHD_Connection *c, char *s)
{
    (void)cls;
    (void)c;
    size_t n = MHD_http_unescape(s);
    for (size_t i = 0; i < n; i++)
        if (s[i] == '\0') s[i] = '\x01';
    return n;
}

/* ---- lifecycle ------------------------------------------------------------------ */

/* libmicrohttpd's own connection limit: --max-connections plus headroom for
 * connections accepted before the ones shut down to make room have closed
 * (libmicrohttpd accepts up to 10 at a time per I/O thread, and splits its
 * limit evenly between the threads). A connection over this limit is closed
 * by libmicrohttpd at once, unanswered. */
static unsigned int conn_hard_limit(const struct srv_config *cfg)
{
    unsigned int n = (unsigned int)cfg->max_connections;
    unsigned int threads = cfg->io_threads > 1 ? (unsigned int)cfg->io_threads : 1u;
    return n + n / 8u + 16u * threads;
}

/* Raise the soft descriptor limit to what hard_limit connections need (plus
 * the listening socket, epoll, eventfds, log and static files), up to the
 * hard limit; say so if that is not enough (accept() then fails beyond it). */
static void ensure_descriptors(const struct srv_config *cfg, unsigned int hard_limit)
{
    struct rlimit rl;
    rlim_t need = (rlim_t)hard_limit + 64u;
    if (getrlimit(RLIMIT_NOFILE, &rl) != 0 || rl.rlim_cur >= need) return;
    rlim_t old = rl.rlim_cur;
    rl.rlim_cur = rl.rlim_max == RLIM_INFINITY || rl.rlim_max >= need ? need : rl.rlim_max;
    if (setrlimit(RLIMIT_NOFILE, &rl) != 0) rl.rlim_cur = old;
    if (rl.rlim_cur < need)
        srv_log_note("--max-connections %d needs about %lu file descriptors but the limit is "
                     "%lu: connections beyond it are refused",
                     cfg->max_connections, (unsigned long)need, (unsigned long)rl.rlim_cur);
}

struct srv_http *srv_http_start(const struct srv_config *cfg, struct srv_pool *pool)
{
    struct srv_http *h = calloc(1, sizeof *h);
    if (!h) return NULL;
    h->cfg = cfg;
    h->pool = pool;
    h->listen_fd = -1;
    pthread_mutex_init(&h->watch_mu, NULL);
    pthread_mutex_init(&h->conn_mu, NULL);
    h->quick = calloc(api_route_count ? api_route_count : 1, sizeof *h->quick);
    for (size_t i = 0; h->quick && i < api_route_count; i++) {
        atomic_init(&h->quick[i].cost, 0);
        atomic_init(&h->quick[i].runs, 0);
        atomic_init(&h->quick[i].too_slow, 0);
    }
    atomic_init(&h->next_id, 0);
    atomic_init(&h->stopping, 0);
    atomic_init(&h->inflight, 0);

    struct sockaddr_in sin;
    struct sockaddr_in6 sin6;
    struct sockaddr *sa;
    unsigned int flags = MHD_USE_EPOLL | MHD_USE_INTERNAL_POLLING_THREAD |
                         MHD_ALLOW_SUSPEND_RESUME | MHD_USE_ERROR_LOG;
    memset(&sin, 0, sizeof sin);
    memset(&sin6, 0, sizeof sin6);
    if (inet_pton(AF_INET, cfg->bind, &sin.sin_addr) == 1) {
        sin.sin_family = AF_INET;
        sin.sin_port = htons((uint16_t)cfg->port);
        sa = (struct sockaddr *)&sin;
    } else if (inet_pton(AF_INET6, cfg->bind, &sin6.sin6_addr) == 1) {
        sin6.sin6_family = AF_INET6;
        sin6.sin6_port = htons((uint16_t)cfg->port);
        sa = (struct sockaddr *)&sin6;
        flags |= MHD_USE_IPv6;
    } else {
        srv_log_note("cannot parse bind address '%s'", cfg->bind);
        pthread_mutex_destroy(&h->watch_mu);
        pthread_mutex_destroy(&h->conn_mu);
        free(h->quick);
        free(h);
        return NULL;
    }

    /* One I/O thread means no pool: then the pool option, last in the list,
     * is replaced by the end marker (libmicrohttpd warns about a size of 0 or 1). */
    unsigned int io_threads = cfg->io_threads > 1 ? (unsigned int)cfg->io_threads : 0u;
    enum MHD_OPTION pool_opt = io_threads > 1 ? MHD_OPTION_THREAD_POOL_SIZE : MHD_OPTION_END;
    unsigned int hard_limit = conn_hard_limit(cfg);
    ensure_descriptors(cfg, hard_limit);
    h->daemon = MHD_start_daemon(
        flags, (uint16_t)cfg->port, NULL, NULL, on_request, h, MHD_OPTION_EXTERNAL_LOGGER,
        mhd_logger, NULL, MHD_OPTION_SOCK_ADDR, sa,
        MHD_OPTION_CONNECTION_TIMEOUT, SRV_CONNECTION_TIMEOUT_S, MHD_OPTION_CONNECTION_LIMIT,
        hard_limit, MHD_OPTION_NOTIFY_COMPLETED, on_completed, h,
        MHD_OPTION_NOTIFY_CONNECTION, on_connection, h, MHD_OPTION_UNESCAPE_CALLBACK,
        unescape_no_nul, NULL, pool_opt, io_threads, MHD_OPTION_END);
    if (!h->daemon) {
        srv_log_note("cannot listen on %s port %d: %s", cfg->bind, cfg->port,
                     errno ? strerror(errno) : "libmicrohttpd failed to start");
        pthread_mutex_destroy(&h->watch_mu);
        pthread_mutex_destroy(&h->conn_mu);
        free(h->quick);
        free(h);
        return NULL;
    }
    if (pthread_create(&h->watcher, NULL, watcher_main, h) == 0)
        h->watch_started = 1;
    else /* still serves; a hang-up is then only noticed at the deadline */
        srv_log_note("cannot start the hang-up watcher thread");
    int port = cfg->port;
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(h->daemon, MHD_DAEMON_INFO_BIND_PORT);
    if (info && info->port) port = info->port;
    int v6 = sa->sa_family == AF_INET6;
    printf("mechd listening on http://%s%s%s:%d\n", v6 ? "[" : "", cfg->bind, v6 ? "]" : "", port);
    fflush(stdout);
    return h;
}

void srv_http_stop_accepting(struct srv_http *h)
{
    if (!h) return;
    if (atomic_exchange(&h->stopping, 1)) return;
    if (h->listen_fd < 0) {
        MHD_socket fd = MHD_quiesce_daemon(h->daemon);
        h->listen_fd = fd == MHD_INVALID_SOCKET ? -1 : (int)fd;
    }
    /* In epoll mode MHD_quiesce_daemon has taken the socket out of every I/O
     * thread's epoll set before returning; shutting it down now makes the
     * kernel refuse new connections (and reset those waiting in the backlog)
     * during the grace period, instead of holding them unanswered. It is
     * closed in srv_http_stop, as MHD asks. */
    if (h->listen_fd >= 0) shutdown(h->listen_fd, SHUT_RDWR);
}

void srv_http_quiesce(struct srv_http *h)
{
    if (!h) return;
    srv_http_stop_accepting(h);
    pthread_mutex_lock(&h->watch_mu);
    __atomic_store_n(&h->cancel, 1, __ATOMIC_SEQ_CST);
    for (struct srv_req *r = h->watched; r; r = r->watch_next)
        __atomic_store_n(&r->cancel, 1, __ATOMIC_SEQ_CST);
    pthread_mutex_unlock(&h->watch_mu);
}

int srv_http_drain(struct srv_http *h, double seconds)
{
    if (!h) return 0;
    double end = mech_clock_seconds() + seconds;
    while (atomic_load(&h->inflight) > 0 && mech_clock_seconds() < end) {
        struct timespec ts = {0, 10 * 1000 * 1000};
        nanosleep(&ts, NULL);
    }
    return atomic_load(&h->inflight);
}

void srv_http_stop(struct srv_http *h)
{
    if (!h) return;
    if (h->watch_started) {
        pthread_mutex_lock(&h->watch_mu);
        h->watch_stop = 1;
        pthread_mutex_unlock(&h->watch_mu);
        pthread_join(h->watcher, NULL);
    }
    MHD_stop_daemon(h->daemon);
    if (h->listen_fd >= 0) close(h->listen_fd);
    pthread_mutex_destroy(&h->watch_mu);
    pthread_mutex_destroy(&h->conn_mu);
    free(h->quick);
    free(h->reap_pfd);
    free(h->reap_conn);
    free(h);
}
