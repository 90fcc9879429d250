/* http_internal.h — what the files of the HTTP front end (http.c and the
 * files named in its header comment) share: limits, the per-connection and
 * per-request state, and the functions one file calls in another. Not for
 * use outside server/http*.c, conn_watch.c and quick.c (http_security.c
 * needs none of it: see http_security.h). */
#ifndef SRV_HTTP_INTERNAL_H
#define SRV_HTTP_INTERNAL_H

#include <microhttpd.h>
#include <poll.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>

#include "api.h"
#include "http.h"
#include "static.h"

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
#define SRV_SHUT_NUDGE_MS 1000       /* a shut connection still open this long is shut down again */
#define SRV_QUICK_BASE_BYTES 512u    /* the fixed cost of a request, in body bytes */
#define SRV_TRACK_MIN (64u << 10)   /* answers this large are sent through a reader that
                                        counts the bytes sent (a cut-off answer is logged so) */
#define SRV_TRACK_BLOCK (32u << 10) /* ... in blocks of this many bytes */
#define SRV_MEM_WAIT_MS 1000       /* a worker waits this long for answer memory before a 503 */
#define SRV_TRIM_BYTES (4u << 20)    /* freeing an answer this large returns free heap to the OS */
#define SRV_DRAIN_MAX (1u << 20)     /* bytes read and dropped after a mid-body 413 */
#define SRV_CHUNKED_GRACE (1u << 20) /* a chunked body is read this far past --max-body */
#define SRV_TARGET_MAX (32u << 10)  /* longest request target (path and query): 414 beyond */
#define SRV_HEADERS_MAX (32u << 10) /* largest request head (request line and headers): 431 */
#define SRV_MHD_POOL (40u << 10)    /* libmicrohttpd's per-connection memory: room for both
                                       limits, so that this server, not libmicrohttpd, answers
                                       414 and 431 (as problem+json) up to about this size.
                                       libmicrohttpd zeroes all of it after every request on a
                                       kept-alive connection: 96 KiB cost ~1.2 µs a request
                                       (0.37 µs for its default 32 KiB), so no more than the
                                       limits need */
#define SRV_REQUEST_ID_MAX 64        /* longest X-Request-Id kept from a client */
#define SRV_QUICK_SAMPLE 16u         /* a quick route's CPU time is read on one run in this many */
#define SRV_QUICK_CAP 8              /* a measurement counts as at most this many times the average */
#define SRV_QUICK_REPROBE 64u        /* a route predicted too slow runs inline once in this many */
#define SRV_QUICK_FULL_FACTOR 16.0   /* with the queue full, a quick route predicted at most this
                                        many times --inline-max-us runs inline instead of a 503 */
#define SRV_GATE_BODY_MAX (16u << 10) /* a gated request is started on the I/O thread (parsed,
                                        validated, its cost predicted) only up to this body */
#define SRV_GATE_RATIO_ONE 1024      /* fixed point of a gated route's measured/predicted CPU */
#define SRV_GATE_RATIO_MIN 256       /* ... kept within 1/4 .. 4 of the chooser's prediction */
#define SRV_GATE_RATIO_MAX 4096
#define SRV_GATE_SAMPLE_NS 1000.0    /* encoding one sample of an answer, beside the prediction */
#define SRV_SHORT_JOB_US 2000.0      /* a gated request predicted within this is a short job */

/* Sent with every answer mechd builds (static files carry their own set from
 * static.c: same nosniff / Referrer-Policy / X-Frame-Options, a CSP that lets
 * the front end load its own scripts). JSON and text need no sources at all. */
#define SRV_API_CSP                                                                                \
    "default-src 'none'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'"
/* CORS (only for origins listed with --cors-origin): what an answer lets the
 * page read. The preflight's headers are SECURITY's (http_security.c). */
#define SRV_CORS_EXPOSE "ETag, Retry-After, X-Request-Id"

struct srv_req;

/* Per quick route (route index, api_operation_path()). Relaxed atomics: a lost update only
 * delays the average or shifts a sample by one request. */
struct srv_quick_stat {
    atomic_llong cost;   /* moving average of thread CPU ns per KiB of (body +
                            SRV_QUICK_BASE_BYTES); 0 = not measured yet */
    atomic_uint runs;    /* runs so far: every SRV_QUICK_SAMPLE-th is measured */
    atomic_uint too_slow; /* requests predicted over --inline-max-us: every
                             SRV_QUICK_REPROBE-th runs inline anyway */
    atomic_llong ratio;   /* a gated route's moving average of thread CPU per predicted
                             CPU (SRV_GATE_RATIO_ONE = as predicted); 0 = not measured */
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
    long long shut_ms;     /* when the server last shut it down (CONN_SHUT), 0 before (conn_mu) */
    size_t target_len;     /* length of the current request's target as sent (I/O thread) */
    char client[48];       /* the peer's numeric address, formatted on the connection's
                              first request ("" before; I/O thread) */
    struct srv_conn *prev, *next;
};

/* One I/O thread: a libmicrohttpd daemon in external-polling epoll mode and
 * the thread that runs it (io_loop.c). */
struct srv_io {
    struct srv_http *http;
    struct MHD_Daemon *daemon;
    pthread_t thread;
    int started;
    int wake_fd;         /* eventfd: quiesce and stop requests wake the loop */
    int listen_fd;       /* returned by MHD_quiesce_daemon; closed after stop; -1 before */
    atomic_int quiesce;  /* asked to stop accepting (srv_io_quiesce) */
    atomic_int quiesced; /* ... and done, on the I/O thread itself */
    atomic_int stop;     /* asked to leave the loop (srv_io_stop) */
};

struct srv_http {
    struct srv_io *io; /* --io-threads of them (io_loop.c) */
    int n_io;
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
    /* Per route (route index, api.h): the measured cost of quick routes (see
     * QUICK OPERATIONS); NULL if it could not be allocated (nothing inline). */
    struct srv_quick_stat *quick;
    /* The answer-memory budget (answer_mem.h; NULL if it could not be
     * allocated: no budget), and per route the measured answer size
     * (answer_budget.c), NULL if it could not be allocated. */
    struct srv_mem *mem;
    atomic_llong *answer_ratio;
    /* Connections held open before the longest-waiting idle one is closed:
     * --max-connections, lowered at start to what the descriptor limit
     * (RLIMIT_NOFILE) leaves room for (http_daemon.c). */
    int max_connections;
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
    struct srv_io *io; /* the I/O thread that owns conn (wakes it on resume) */
    char id[SRV_REQUEST_ID_MAX + 1]; /* X-Request-Id: the client's (validated) or generated */
    char client[48];                 /* peer address, numeric */
    char *forwarded_for;             /* owned copy of X-Forwarded-For, or NULL */
    unsigned long long bytes;        /* response body bytes queued (the whole answer) */
    unsigned long long sent;         /* of a tracked answer (struct srv_answer): body bytes
                                        sent before the last read of its reader */
    int tracked;                     /* the answer's reader updates `sent` */
    size_t charged;                  /* bytes reserved in the answer-memory budget for this
                                        request's answer (handed to the answer when sent) */
    double mem_units;                /* the size units its answer was predicted from, 0 if none */
    double t0;
    char *method, *path, *content_type;  /* owned copies */
    char *query_request, *if_none_match; /* owned copies: ?request= (decoded), If-None-Match */
    char *accept_encoding;               /* owned copy of Accept-Encoding, or NULL */
    char *host;                          /* owned copy of Host, or NULL (GET /v1's curl lines) */
    char *body;
    size_t body_len, body_cap, body_seen;
    int too_large;
    int oom;
    const char *bad_framing; /* why the body's framing is refused (static text), or NULL */
    enum api_problem head_problem; /* the request head is refused (414, 431, 400), or NONE */
    const char *head_detail;       /* ... and why (static text) */
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
    long route_index;    /* route index (api.h) of a POST to an operation, else -1 */
    int quick_route;     /* route is quick and the body small enough (api_quick_route) */
    int quick_probe;     /* runs inline although predicted too slow: measure it */
    int gated;           /* a POST to a gated route (api_gated_route, see GATED OPERATIONS) */
    int gate_attempt;    /* being started on the I/O thread under the cost gate */
    int mem_deferred;    /* ... and its answer memory did not fit: stop at the gate */
    double predicted_cpu_s; /* what the gate was told (-1 unknown, 0 not asked) */
    double samples;      /* samples the request asks for (answer_admit) */
    double gate_est_ns;  /* the estimate the gate decided on (0: none) */
    struct srv_req *watch_prev, *watch_next; /* in http->watched, under watch_mu */
    int watching;
};

/* The I/O thread is closing the connection on purpose (http_body.c, on_request). */
extern _Thread_local int tl_closing_on_purpose;

/* http.c */
enum MHD_Result on_request(void *cls, struct MHD_Connection *conn, const char *url,
                           const char *method, const char *version, const char *upload_data,
                           size_t *upload_data_size, void **con_cls);
void on_completed(void *cls, struct MHD_Connection *conn, void **con_cls,
                  enum MHD_RequestTerminationCode toe);
size_t unescape_no_nul(void *cls, struct MHD_Connection *c, char *s);
void *on_uri(void *cls, const char *uri, struct MHD_Connection *conn);

/* answer_send.c */
/* The response object for resp's malloc'd body (not static, not a 304): on
 * success it owns the body (resp->body becomes NULL) and, for a body of at
 * least SRV_TRACK_MIN bytes sent to a non-HEAD request, r's answer-memory
 * charge, and keeps r->sent up to date while it is sent (r->tracked). NULL
 * when out of memory (resp and r unchanged). */
struct MHD_Response *answer_response(struct srv_req *r, struct api_response *resp);

/* http_head.c */
/* Sets r->head_problem and r->head_detail and returns 1 when the request head
 * is refused (target over SRV_TARGET_MAX: 414; head over SRV_HEADERS_MAX: 431;
 * HTTP/1.1 without exactly one Host: 400), else 0. */
int head_problem(struct srv_req *r, struct MHD_Connection *conn, const char *version);

/* request_id.c */
/* The request id into out (SRV_REQUEST_ID_MAX + 1 bytes): `given` (the
 * incoming X-Request-Id, may be NULL) when it is 1..SRV_REQUEST_ID_MAX
 * characters of [A-Za-z0-9._:+/=-], else 32 lower-case hex digits of 128 bits
 * from this thread's generator (seeded by getrandom(2) on its first use).
 * Cannot fail. */
void request_id(struct srv_http *h, const char *given, char *out);
/* The methods path answers to ("GET, HEAD, OPTIONS", ...; static), or NULL
 * when nothing is there. */
const char *allowed_methods(const char *path);

/* http_body.c */
const char *framing_problem(struct MHD_Connection *conn, const char *version);
void mhd_logger(void *cls, const char *fmt, va_list ap);
enum MHD_Result refuse_mid_body(struct srv_http *h, struct srv_req *r);
void take_body(struct srv_http *h, struct srv_req *r, const char *data, size_t n);

/* http_security.c has a face of its own (http_security.h): it needs none of this. */

/* quick.c */
void run_api(struct srv_req *r);
int quick_inline(struct srv_http *h, struct srv_req *r);
/* A POST to a gated route: start it on the I/O thread under the cost gate
 * when --inline-max-us allows and its body is at most SRV_GATE_BODY_MAX.
 * Returns 1 when r->aresp holds its answer (computed here, or a problem),
 * 0 when it must go to the pool (the gate stopped it, or it was not started
 * here): r->aext then carries the recording gate for the worker's run and
 * r->job.short_job says whether the prediction makes it a short job. */
int gate_try_inline(struct srv_http *h, struct srv_req *r);
/* 1 if a quick route's request is predicted to cost at most SRV_QUICK_FULL_FACTOR
 * times --inline-max-us (0 when --inline-max-us is 0): run inline rather than
 * refused when the queue is full. */
int quick_fits_when_full(const struct srv_http *h, const struct srv_req *r);

/* answer_budget.c */
/* api_request_ext.admit for r (ctx): predict the answer's size from the
 * route's measured bytes per unit (samples and body bytes) and reserve it in
 * h->mem: a worker waits up to SRV_MEM_WAIT_MS (never past the deadline), an
 * I/O thread not at all. Returns 0 when reserved, 1 to refuse (503). */
int answer_admit(void *ctx, long route, double samples);
/* After the API ran on r: charge the answer's real size instead of the
 * prediction (what the I/O thread will hold until it is sent: bodies of at
 * least SRV_TRACK_MIN bytes), and learn the route's bytes per unit. */
void answer_settle(struct srv_req *r);
/* Per-route answer-size estimates for h (h->answer_ratio); NULL if out of memory. */
atomic_llong *answer_ratios_new(size_t n_routes);

/* io_loop.c */
/* Starts one libmicrohttpd daemon without an internal polling thread: it
 * binds the configured address when listen_fd < 0, else serves listen_fd
 * (a descriptor it then owns); at most conn_limit connections. NULL on
 * failure. (http_daemon.c provides it, with the request callbacks.) */
typedef struct MHD_Daemon *(*srv_io_daemon_fn)(struct srv_http *h, int listen_fd,
                                               unsigned int conn_limit, void *ctx);
/* Start n I/O threads, each running one daemon made by start(h, fd, limit,
 * ctx) with at most ceil(conn_limit / n) connections; the first binds, the
 * others share a dup of its listening socket. Returns 0, or -1 with
 * whatever started left for srv_io_stop. */
int srv_io_start(struct srv_http *h, unsigned int n, unsigned int conn_limit,
                 srv_io_daemon_fn start, void *ctx);
/* The srv_io of the calling I/O thread; NULL on any other thread. */
struct srv_io *srv_io_current(void);
/* MHD_resume_connection(conn), then wake io's loop (io may be NULL: no
 * wake-up). Any thread. conn may be freed once this returns. */
void srv_io_resume(struct srv_io *io, struct MHD_Connection *conn);
/* The bound TCP port (0 if unknown). */
int srv_io_port(const struct srv_http *h);
/* Every I/O thread stops accepting (on its own thread; waits up to 2 s for
 * them), then the listening socket is shut down. Idempotent. */
void srv_io_quiesce(struct srv_http *h);
/* Stop and join the I/O threads, stop the daemons (closing their
 * connections), close the descriptors, free h->io. */
void srv_io_stop(struct srv_http *h);

/* conn_watch.c */
void watch_add(struct srv_http *h, struct srv_req *r);
void watch_remove(struct srv_http *h, struct srv_req *r);
void *watcher_main(void *arg);
int conn_claim(struct srv_req *r);
int conn_shut(const struct srv_conn *c);
void on_connection(void *cls, struct MHD_Connection *conn, void **socket_context,
                   enum MHD_ConnectionNotificationCode code);

#endif
