/* mhd_panic.c — libmicrohttpd's panic handler.
 *
 * libmicrohttpd calls its panic function, abort() by default, where it finds
 * a state it did not expect. One of them is a race of its own, present in
 * Debian 12's 0.9.75 and still in 0.9.77: MHD_quiesce_daemon (our SIGTERM
 * path, srv_http_stop_accepting) marks each I/O thread quiesced and then
 * removes the listening socket from that thread's epoll set; an I/O thread
 * woken in between (by any connection event) sees the mark and removes the
 * socket itself, so the quiesce's epoll_ctl(EPOLL_CTL_DEL) fails with ENOENT
 * and libmicrohttpd panics: "Failed to remove listen FD from epoll set."
 * (a helper's test run under load saw mechd abort on SIGTERM this way). The
 * socket is out of the set either way, and after the panic call returns the
 * library records exactly that and goes on, so this one panic, with errno
 * ENOENT, is logged and survived. Every other panic is logged and aborts.
 * Since the I/O threads became mechd's own (io_loop.c), each quiesces its
 * daemon on its own thread and the race cannot arise; the guard stays for a
 * libmicrohttpd that panics there anyway. */
#include "mhd_panic.h"

#include <errno.h>
#include <microhttpd.h>
#include <stdlib.h>
#include <string.h>

#include "log.h"

#define LISTEN_FD_EPOLL_RACE "Failed to remove listen FD from epoll set"

int srv_mhd_panic_is_benign(const char *reason, int err)
{
    return reason && err == ENOENT && strstr(reason, LISTEN_FD_EPOLL_RACE) != NULL;
}

void srv_mhd_panic(void *cls, const char *file, unsigned int line, const char *reason)
{
    int err = errno; /* epoll_ctl's, untouched: libmicrohttpd panics right after the call */
    (void)cls;
    if (srv_mhd_panic_is_benign(reason, err)) {
        srv_log_note("libmicrohttpd (%s:%u): %s ignored: the socket had already left that "
                     "set (a race inside MHD_quiesce_daemon)",
                     file ? file : "?", line, LISTEN_FD_EPOLL_RACE);
        return;
    }
    srv_log_note("libmicrohttpd panic (%s:%u): %s (errno %d)", file ? file : "?", line,
                 reason ? reason : "no reason given", err);
    abort();
}

void srv_mhd_panic_install(void)
{
    MHD_set_panic_func(srv_mhd_panic, NULL);
}
