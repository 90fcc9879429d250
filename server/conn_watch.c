/* conn_watch.c — the watcher thread and the connection registry: hang-ups of
 * pooled requests, slow clients, connection floods and dead peers (part of
 * the HTTP front end, see http.c).
 *
 * CANCELLATION. A suspended connection is not polled by libmicrohttpd, so a
 * watcher thread checks the sockets of pooled requests every 10 ms and raises
 * the request's own cancel flag when the client has hung up: a running request
 * stops at its next budget check; a request still waiting in the queue is
 * taken out of it at once (srv_pool_remove), so its slot frees, and is
 * answered 503 cancelled and resumed by the watcher itself. A close and a
 * half-close (shutdown(SHUT_WR), as `nc -N` and some scripts send after a
 * whole request) are the same FIN on the wire, so a hang-up counts only once
 * it has been seen for --hangup-grace-ms (500 ms): a cheap request from a
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
 * A connection the server shut down (for any of these reasons) that is still
 * open SRV_SHUT_NUDGE_MS later is shut down again, once a second: each
 * shutdown(2) wakes libmicrohttpd's epoll, so one lost wake-up cannot hold
 * the slot until the idle timeout (a CI run under TSan once left 256 such
 * sockets open). All three are counted in /metrics
 * (mechd_connections_evicted_total, mechd_connections_reaped_total,
 * mechd_connections_nudged_total) next to mechd_connections_open.
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

/* ---- watching pooled requests for a client hang-up ------------------------------ */

/* Add r to the watched list (before it is submitted to the pool). */
void watch_add(struct srv_http *h, struct srv_req *r)
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
void watch_remove(struct srv_http *h, struct srv_req *r)
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
    c->shut_ms = now_ms();
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
    /* The list runs newest first and ready_ms has millisecond steps, so
     * connections accepted in one burst tie: on a tie the later in the list
     * (accepted earlier) is chosen. Taking the first of a tie evicted the
     * newest, which, with two I/O threads finishing their accepts out of
     * order, could be a probe that had just connected. */
    for (struct srv_conn *c = h->conns; c; c = c->next) {
        if (c == fresh || atomic_load(&c->rx) != CONN_RX) continue;
        long long t = atomic_load(&c->ready_ms);
        if (!victim || t <= oldest) {
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
    long long now = now_ms();
    for (struct srv_conn *c = h->conns; c && k < h->reap_cap; c = c->next) {
        if (c->fd < 0) continue;
        if (atomic_load(&c->rx) == CONN_SHUT) {
            /* Shut down but still open: libmicrohttpd has not seen the
             * shutdown yet. Shut it down again, which wakes its epoll once
             * more (inet_shutdown always signals a state change), so a
             * wake-up lost in a busy event loop cannot keep the socket, and
             * its connection slot, until the idle timeout. */
            if (now - c->shut_ms >= SRV_SHUT_NUDGE_MS) {
                c->shut_ms = now;
                shutdown(c->fd, SHUT_RDWR);
                srv_metrics_count_shut_nudges(1);
            }
            continue;
        }
        if (atomic_load(&c->rx) != CONN_RX) continue;
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
void *watcher_main(void *arg)
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
                } else if (now_ms() - r->eof_since_ms >= h->cfg->hangup_grace_ms) {
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
                srv_io_resume(r->io, r->conn); /* r may be freed from here on */
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
int conn_claim(struct srv_req *r)
{
    if (!r->sc) return 1;
    int expected = CONN_RX;
    if (atomic_compare_exchange_strong(&r->sc->rx, &expected, CONN_BUSY)) return 1;
    return expected != CONN_SHUT;
}

int conn_shut(const struct srv_conn *c)
{
    return c && atomic_load(&c->rx) == CONN_SHUT;
}

/* NOTIFY_CONNECTION: register a new connection, unregister a closing one (on
 * its I/O thread; the descriptor is closed only after CLOSED returns). */
void on_connection(void *cls, struct MHD_Connection *conn, void **socket_context,
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
        if (h->n_conns - h->n_shut > h->max_connections) evict_longest_waiting(h, c);
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
