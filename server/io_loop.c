/* io_loop.c — the I/O threads: one libmicrohttpd daemon each, run by our own
 * event loop (part of the HTTP front end, see http.c and http_daemon.c).
 *
 * WHY NOT libmicrohttpd's OWN THREADS. In its internal-thread epoll mode
 * libmicrohttpd drains its epoll set in a loop that calls epoll_wait again
 * while the previous call returned exactly MAX_EVENTS (128) events, with the
 * same blocking timeout (daemon.c MHD_epoll; in Debian 12's 0.9.75 and still
 * in libmicrohttpd's master in 2026). The 128 events already collected are
 * processed only after that second call returns: when exactly 128
 * connections of one I/O thread become readable at once and their clients
 * then wait for answers, nothing more arrives and the thread sleeps until
 * the idle timeout (30 s) or an unrelated event. wrk with 256 connections on
 * two I/O threads hit it: a round with no answer at all for 5 s (seen in CI
 * and locally, 1 round in ~50); 128 keep-alive clients sending together on
 * one thread hit it every time (tests/integration/test_io_burst.py).
 *
 * THE LOOP. Each daemon runs in external-polling epoll mode: its thread
 * poll()s the daemon's epoll descriptor (MHD_DAEMON_INFO_EPOLL_FD) and a
 * wake-up eventfd, with MHD_get_timeout's timeout, then calls MHD_run, which
 * drains the set with a zero timeout and so never blocks holding collected
 * events. A resumed connection wakes the loop through our eventfd
 * (srv_io_resume: libmicrohttpd's own channel can be drained before the
 * daemon sees the resume). The first daemon binds the
 * listening socket; the others get a dup(2) of it, so every thread accepts
 * from the one socket (as libmicrohttpd's own pool does) and every daemon
 * owns, and may close, its own descriptor. Quiescing (SIGTERM) happens on
 * each I/O thread itself, so no epoll_ctl races the event loop.
 */
#ifdef __linux__
#define _GNU_SOURCE
#endif
#include "http_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <microhttpd.h>
#include <poll.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "mech/base/budget.h"

#define IO_QUIESCE_WAIT_S 2.0 /* how long srv_io_quiesce waits for the threads */

static __thread struct srv_io *tl_io; /* the I/O thread's own, NULL elsewhere */

static void io_wake(struct srv_io *io)
{
    uint64_t one = 1;
    if (io && io->wake_fd >= 0) {
        ssize_t n = write(io->wake_fd, &one, sizeof one);
        (void)n; /* EAGAIN: the counter is already non-zero, the thread will wake */
    }
}

static void io_drain_wake(struct srv_io *io)
{
    uint64_t v;
    ssize_t n = read(io->wake_fd, &v, sizeof v);
    (void)n;
}

/* The daemon's open connections, after freeing the closed ones (this
 * thread only: libmicrohttpd cleans up on the caller's thread in this mode). */
static unsigned int io_connections(struct srv_io *io)
{
    const union MHD_DaemonInfo *ci =
        MHD_get_daemon_info(io->daemon, MHD_DAEMON_INFO_CURRENT_CONNECTIONS);
    return ci ? ci->num_connections : 0;
}

/* One I/O thread: wait for the daemon's events (or a wake-up), run it, and
 * quiesce or stop when asked. */
static void *io_main(void *arg)
{
    struct srv_io *io = arg;
    tl_io = io;
    pthread_setname_np(pthread_self(), "mechd-io");
    const union MHD_DaemonInfo *ei = MHD_get_daemon_info(io->daemon, MHD_DAEMON_INFO_EPOLL_FD);
    struct pollfd p[2] = {{ei ? ei->epoll_fd : -1, POLLIN, 0}, {io->wake_fd, POLLIN, 0}};
    while (!atomic_load(&io->stop)) {
        if (atomic_load(&io->quiesce) && !atomic_load(&io->quiesced)) {
            MHD_socket fd = MHD_quiesce_daemon(io->daemon);
            io->listen_fd = fd == MHD_INVALID_SOCKET ? -1 : (int)fd;
            atomic_store(&io->quiesced, 1);
        }
        MHD_UNSIGNED_LONG_LONG to = 0;
        int timeout = -1; /* no connection with a timeout: wait for an event */
        if (MHD_get_timeout(io->daemon, &to) == MHD_YES)
            timeout = to > (MHD_UNSIGNED_LONG_LONG)INT_MAX ? INT_MAX : (int)to;
        int n = poll(p, 2, timeout);
        if (n < 0 && errno != EINTR) {
            /* Cannot happen with valid descriptors; do not spin if it does. */
            struct timespec ts = {0, 10 * 1000 * 1000};
            nanosleep(&ts, NULL);
        }
        if (n > 0 && (p[1].revents & POLLIN)) io_drain_wake(io);
        /* At its limit (MHD_OPTION_CONNECTION_LIMIT, or descriptors run
         * out) the daemon takes the listening socket out of its epoll set,
         * and puts it back only at the start of a run below the limit: a run
         * that closed connections is followed by another at once, or
         * connections waiting in the backlog would wait for an unrelated
         * event (a flood of clients that closed their half-sent requests
         * left /healthz unanswered). Each repeat closed at least one. */
        unsigned int before, after = io_connections(io);
        do {
            before = after;
            MHD_run(io->daemon);
            after = io_connections(io);
        } while (after < before);
    }
    return NULL;
}

struct srv_io *srv_io_current(void)
{
    return tl_io;
}

/* libmicrohttpd's resume signals its inter-thread channel, but an I/O loop
 * that drained that channel after the daemon's last look at its resumed
 * connections (MHD_run checks them before it waits) would find nothing to
 * wake it: MHD_get_timeout does not count a pending resume. Our own wake-up
 * after the resume makes the loop run the daemon once more. */
void srv_io_resume(struct srv_io *io, struct MHD_Connection *conn)
{
    MHD_resume_connection(conn);
    io_wake(io);
}

int srv_io_start(struct srv_http *h, unsigned int n, unsigned int conn_limit,
                 srv_io_daemon_fn start, void *ctx)
{
    h->io = calloc(n, sizeof *h->io);
    if (!h->io) return -1;
    h->n_io = (int)n;
    for (unsigned int i = 0; i < n; i++) {
        h->io[i].wake_fd = -1;
        h->io[i].listen_fd = -1;
    }
    /* libmicrohttpd's own pool split its limit evenly between the threads; so do we. */
    unsigned int per = conn_limit / n + (conn_limit % n ? 1u : 0u);
    for (unsigned int i = 0; i < n; i++) {
        struct srv_io *io = &h->io[i];
        io->http = h;
        io->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
        if (io->wake_fd < 0) return -1;
        if (i == 0) {
            io->daemon = start(h, -1, per, ctx);
        } else {
            const union MHD_DaemonInfo *li =
                MHD_get_daemon_info(h->io[0].daemon, MHD_DAEMON_INFO_LISTEN_FD);
            int fd = li ? fcntl(li->listen_fd, F_DUPFD_CLOEXEC, 0) : -1;
            if (fd < 0) return -1;
            io->daemon = start(h, fd, per, ctx);
            if (!io->daemon) close(fd);
        }
        if (!io->daemon) return -1;
    }
    for (unsigned int i = 0; i < n; i++) {
        if (pthread_create(&h->io[i].thread, NULL, io_main, &h->io[i]) != 0) return -1;
        h->io[i].started = 1;
    }
    return 0;
}

int srv_io_port(const struct srv_http *h)
{
    if (!h->io || !h->io[0].daemon) return 0;
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(h->io[0].daemon, MHD_DAEMON_INFO_BIND_PORT);
    return info ? info->port : 0;
}

void srv_io_quiesce(struct srv_http *h)
{
    if (!h->io) return;
    for (int i = 0; i < h->n_io; i++) {
        if (!h->io[i].started) continue;
        atomic_store(&h->io[i].quiesce, 1);
        io_wake(&h->io[i]);
    }
    double end = mech_clock_seconds() + IO_QUIESCE_WAIT_S;
    for (int i = 0; i < h->n_io; i++) {
        while (h->io[i].started && !atomic_load(&h->io[i].quiesced) && mech_clock_seconds() < end) {
            struct timespec ts = {0, 1000 * 1000};
            nanosleep(&ts, NULL);
        }
    }
    /* Every thread's socket is out of its epoll set: shutting the shared
     * socket down makes the kernel refuse new connections (and reset those
     * waiting in the backlog) during the grace period instead of holding them
     * unanswered. The descriptors are closed in srv_io_stop. */
    for (int i = 0; i < h->n_io; i++)
        if (atomic_load(&h->io[i].quiesced) && h->io[i].listen_fd >= 0) {
            shutdown(h->io[i].listen_fd, SHUT_RDWR);
            break; /* one socket behind every descriptor */
        }
}

void srv_io_stop(struct srv_http *h)
{
    if (!h->io) return;
    for (int i = 0; i < h->n_io; i++) {
        atomic_store(&h->io[i].stop, 1);
        io_wake(&h->io[i]);
    }
    for (int i = 0; i < h->n_io; i++)
        if (h->io[i].started) pthread_join(h->io[i].thread, NULL);
    for (int i = 0; i < h->n_io; i++) {
        struct srv_io *io = &h->io[i];
        if (io->daemon) MHD_stop_daemon(io->daemon); /* closes its listening descriptor unless quiesced */
        if (atomic_load(&io->quiesced) && io->listen_fd >= 0) close(io->listen_fd);
        if (io->wake_fd >= 0) close(io->wake_fd);
    }
    free(h->io);
    h->io = NULL;
    h->n_io = 0;
}
