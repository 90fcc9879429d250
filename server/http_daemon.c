/* http_daemon.c — starting and stopping the libmicrohttpd daemons and the watcher
 * (srv_http_start ... srv_http_stop of http.h; part of the HTTP front end,
 * see http.c).
 *
 * I/O THREADS. --io-threads (default 2, the machine's cores) threads of our
 * own, each running one libmicrohttpd daemon in epoll mode with its own
 * connections (io_loop.c says why not libmicrohttpd's internal thread pool);
 * suspend/resume works per connection in that mode.
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

#include "answer_mem.h"
#include "api.h"
#include "log.h"
#include "static.h"
#include "mech/base/budget.h"

/* ---- lifecycle ------------------------------------------------------------------ */

/* Descriptors the server holds besides its client connections: stdin,
 * stdout, stderr; per I/O thread the listening socket (or its dup), the
 * epoll set, our wake-up eventfd and libmicrohttpd's inter-thread channel;
 * and a margin for the short-lived ones (/metrics reads /proc, the watcher,
 * a static file reload, the C library). */
#define SRV_FD_RESERVED 24u
#define SRV_FD_PER_IO 4u

/* libmicrohttpd's own connection limit for n held connections: n plus
 * headroom for connections accepted before the ones shut down to make room
 * have closed (libmicrohttpd accepts up to 10 at a time per I/O thread; the
 * limit is split evenly between the threads, srv_io_start). A connection
 * over this limit is closed by libmicrohttpd at once, unanswered. */
static unsigned int conn_hard_limit(unsigned int n, unsigned int threads)
{
    return n + n / 8u + 16u * threads;
}

/* Fit the connection limits to the descriptor limit (RLIMIT_NOFILE), once at
 * start. The soft limit is raised towards what --max-connections needs, up to
 * the hard limit. If that is still too few, --max-connections is lowered so
 * that libmicrohttpd's limit (conn_hard_limit) stays below the descriptors
 * left after SRV_FD_RESERVED and SRV_FD_PER_IO per I/O thread: then accept()
 * never fails with EMFILE (in which state libmicrohttpd 0.9.75 could
 * busy-wait a core on the still-readable listening socket), and
 * --max-connections is reached first, so the longest-waiting idle
 * connection is closed to make room and /healthz is still answered. Sets
 * h->max_connections; returns libmicrohttpd's limit, or 0 when the
 * descriptor limit leaves no room for a single connection. */
static unsigned int fit_descriptors(struct srv_http *h, unsigned int threads)
{
    unsigned int n = (unsigned int)h->cfg->max_connections;
    unsigned int hard = conn_hard_limit(n, threads);
    rlim_t reserved = (rlim_t)SRV_FD_RESERVED + (rlim_t)SRV_FD_PER_IO * threads;
    rlim_t need = (rlim_t)hard + reserved;
    struct rlimit rl;
    h->max_connections = (int)n;
    if (getrlimit(RLIMIT_NOFILE, &rl) != 0) return hard;
    if (rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < need) {
        rlim_t old = rl.rlim_cur;
        rl.rlim_cur = rl.rlim_max == RLIM_INFINITY || rl.rlim_max >= need ? need : rl.rlim_max;
        if (setrlimit(RLIMIT_NOFILE, &rl) != 0) rl.rlim_cur = old;
    }
    if (rl.rlim_cur == RLIM_INFINITY || rl.rlim_cur >= need) return hard;
    if (rl.rlim_cur < reserved + 2u * threads) {
        srv_log_note("the descriptor limit (ulimit -n) is %lu: too low to serve connections "
                     "(the server itself needs about %lu)",
                     (unsigned long)rl.rlim_cur, (unsigned long)reserved);
        return 0;
    }
    unsigned int avail = (unsigned int)(rl.rlim_cur - reserved);
    /* Keep about 1/9 of them (and two per I/O thread) as the headroom of
     * conn_hard_limit: connections accepted while shut ones close. */
    unsigned int spare = avail / 9u + 2u * threads;
    if (spare > avail - threads) spare = avail - threads;
    unsigned int fit = avail - spare;
    if (fit > n) fit = n;
    h->max_connections = (int)fit;
    if (fit < n)
        srv_log_note("--max-connections %u lowered to %u: the descriptor limit (ulimit -n) is "
                     "%lu, %lu would be needed",
                     n, fit, (unsigned long)rl.rlim_cur, (unsigned long)need);
    return avail;
}

/* What start_daemon needs beyond h: the address to bind and the flags. */
struct daemon_ctx {
    const struct sockaddr *sa;
    unsigned int flags;
};

/* srv_io_daemon_fn: one daemon with mechd's callbacks and limits. */
static struct MHD_Daemon *start_daemon(struct srv_http *h, int listen_fd, unsigned int conn_limit,
                                       void *ctx)
{
    const struct daemon_ctx *d = ctx;
    if (listen_fd < 0)
        return MHD_start_daemon(
            d->flags, (uint16_t)h->cfg->port, NULL, NULL, on_request, h, MHD_OPTION_EXTERNAL_LOGGER,
            mhd_logger, NULL, MHD_OPTION_SOCK_ADDR, d->sa, MHD_OPTION_CONNECTION_TIMEOUT,
            SRV_CONNECTION_TIMEOUT_S, MHD_OPTION_CONNECTION_LIMIT, conn_limit,
            MHD_OPTION_NOTIFY_COMPLETED, on_completed, h, MHD_OPTION_NOTIFY_CONNECTION,
            on_connection, h, MHD_OPTION_UNESCAPE_CALLBACK, unescape_no_nul, NULL,
            MHD_OPTION_URI_LOG_CALLBACK, on_uri, NULL, MHD_OPTION_CONNECTION_MEMORY_LIMIT,
            (size_t)SRV_MHD_POOL, MHD_OPTION_END);
    return MHD_start_daemon(
        d->flags, 0, NULL, NULL, on_request, h, MHD_OPTION_EXTERNAL_LOGGER, mhd_logger, NULL,
        MHD_OPTION_LISTEN_SOCKET, (MHD_socket)listen_fd, MHD_OPTION_CONNECTION_TIMEOUT,
        SRV_CONNECTION_TIMEOUT_S, MHD_OPTION_CONNECTION_LIMIT, conn_limit,
        MHD_OPTION_NOTIFY_COMPLETED, on_completed, h, MHD_OPTION_NOTIFY_CONNECTION, on_connection,
        h, MHD_OPTION_UNESCAPE_CALLBACK, unescape_no_nul, NULL, MHD_OPTION_URI_LOG_CALLBACK,
        on_uri, NULL, MHD_OPTION_CONNECTION_MEMORY_LIMIT, (size_t)SRV_MHD_POOL, MHD_OPTION_END);
}

struct srv_http *srv_http_start(const struct srv_config *cfg, struct srv_pool *pool)
{
    struct srv_http *h = calloc(1, sizeof *h);
    if (!h) return NULL;
    h->cfg = cfg;
    h->pool = pool;
    pthread_mutex_init(&h->watch_mu, NULL);
    pthread_mutex_init(&h->conn_mu, NULL);
    const size_t n_routes = api_operation_count();
    h->quick = calloc(n_routes ? n_routes : 1, sizeof *h->quick);
    for (size_t i = 0; h->quick && i < n_routes; i++) {
        atomic_init(&h->quick[i].cost, 0);
        atomic_init(&h->quick[i].runs, 0);
        atomic_init(&h->quick[i].too_slow, 0);
        atomic_init(&h->quick[i].ratio, 0);
    }
    atomic_init(&h->next_id, 0);
    atomic_init(&h->stopping, 0);
    atomic_init(&h->inflight, 0);

    struct sockaddr_in sin;
    struct sockaddr_in6 sin6;
    struct sockaddr *sa;
    unsigned int flags = MHD_USE_EPOLL | MHD_ALLOW_SUSPEND_RESUME | MHD_USE_ERROR_LOG;
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

    unsigned int io_threads = cfg->io_threads > 1 ? (unsigned int)cfg->io_threads : 1u;
    unsigned int hard_limit = fit_descriptors(h, io_threads);
    struct daemon_ctx dctx = {sa, flags};
    h->mem = srv_mem_create(cfg->max_answer_memory ? cfg->max_answer_memory
                                                   : srv_mem_default_cap());
    h->answer_ratio = answer_ratios_new(n_routes);
    errno = 0;
    if (hard_limit == 0 || srv_io_start(h, io_threads, hard_limit, start_daemon, &dctx) != 0) {
        if (hard_limit)
            srv_log_note("cannot listen on %s port %d: %s", cfg->bind, cfg->port,
                         errno ? strerror(errno) : "libmicrohttpd failed to start");
        srv_io_stop(h);
        pthread_mutex_destroy(&h->watch_mu);
        pthread_mutex_destroy(&h->conn_mu);
        srv_mem_free(h->mem);
        free(h->answer_ratio);
        free(h->quick);
        free(h);
        return NULL;
    }
    if (pthread_create(&h->watcher, NULL, watcher_main, h) == 0)
        h->watch_started = 1;
    else /* still serves; a hang-up is then only noticed at the deadline */
        srv_log_note("cannot start the hang-up watcher thread");
    int port = srv_io_port(h) ? srv_io_port(h) : cfg->port;
    int v6 = sa->sa_family == AF_INET6;
    printf("mechd listening on http://%s%s%s:%d\n", v6 ? "[" : "", cfg->bind, v6 ? "]" : "", port);
    fflush(stdout);
    return h;
}

void srv_http_stop_accepting(struct srv_http *h)
{
    if (!h) return;
    if (atomic_exchange(&h->stopping, 1)) return;
    srv_io_quiesce(h);
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
    srv_io_stop(h); /* frees every answer still held: their memory goes back to h->mem */
    pthread_mutex_destroy(&h->watch_mu);
    pthread_mutex_destroy(&h->conn_mu);
    srv_mem_free(h->mem);
    free(h->answer_ratio);
    free(h->quick);
    free(h->reap_pfd);
    free(h->reap_conn);
    free(h);
}
