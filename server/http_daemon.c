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

#include "api.h"
#include "log.h"
#include "static.h"
#include "mech/budget.h"

/* ---- lifecycle ------------------------------------------------------------------ */

/* libmicrohttpd's own connection limit: --max-connections plus headroom for
 * connections accepted before the ones shut down to make room have closed
 * (libmicrohttpd accepts up to 10 at a time per I/O thread; the limit is
 * split evenly between the threads, srv_io_start). A connection over this limit is closed
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
            on_connection, h, MHD_OPTION_UNESCAPE_CALLBACK, unescape_no_nul, NULL, MHD_OPTION_END);
    return MHD_start_daemon(
        d->flags, 0, NULL, NULL, on_request, h, MHD_OPTION_EXTERNAL_LOGGER, mhd_logger, NULL,
        MHD_OPTION_LISTEN_SOCKET, (MHD_socket)listen_fd, MHD_OPTION_CONNECTION_TIMEOUT,
        SRV_CONNECTION_TIMEOUT_S, MHD_OPTION_CONNECTION_LIMIT, conn_limit,
        MHD_OPTION_NOTIFY_COMPLETED, on_completed, h, MHD_OPTION_NOTIFY_CONNECTION, on_connection,
        h, MHD_OPTION_UNESCAPE_CALLBACK, unescape_no_nul, NULL, MHD_OPTION_END);
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
    unsigned int hard_limit = conn_hard_limit(cfg);
    ensure_descriptors(cfg, hard_limit);
    struct daemon_ctx dctx = {sa, flags};
    if (srv_io_start(h, io_threads, hard_limit, start_daemon, &dctx) != 0) {
        srv_log_note("cannot listen on %s port %d: %s", cfg->bind, cfg->port,
                     errno ? strerror(errno) : "libmicrohttpd failed to start");
        srv_io_stop(h);
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
    srv_io_stop(h);
    pthread_mutex_destroy(&h->watch_mu);
    pthread_mutex_destroy(&h->conn_mu);
    free(h->quick);
    free(h->reap_pfd);
    free(h->reap_conn);
    free(h);
}
