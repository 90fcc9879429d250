/* main.c — mechd entry point: options, process-wide set-up, and the signal
 * wait that drives a clean shutdown.
 *
 * SIGINT/SIGTERM are blocked in every thread and taken with sigwait() here,
 * so no work happens in a signal handler. Shutdown: stop accepting and raise
 * the cancel flag (running computations stop at their next budget check),
 * answer queued jobs 503 cancelled and join the workers (every suspended
 * connection is resumed by then), give the answers a moment to be sent, stop
 * the daemon, exit 0.
 */
#include <gsl/gsl_errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "api.h"
#include "config.h"
#include "http.h"
#include "log.h"
#include "workers.h"

#define SRV_DRAIN_SECONDS 3.0 /* how long answers to cancelled work may take to go out */

int main(int argc, char **argv)
{
    struct srv_config cfg;
    memset(&cfg, 0, sizeof cfg);
    switch (srv_config_load(&cfg, argc, argv, stdout, stderr)) {
    case SRV_CONFIG_RUN:
        break;
    case SRV_CONFIG_EXIT:
        return 0;
    case SRV_CONFIG_ERROR:
        return 2;
    }

    gsl_set_error_handler_off(); /* process-wide, once (STYLE.md §6) */
    if (api_init() != 0) {
        srv_log_note("API initialisation failed: %s", api_init_error());
        return 1;
    }

    /* Block the stop signals before any thread starts, so all inherit the mask. */
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    if (pthread_sigmask(SIG_BLOCK, &stop, NULL) != 0) {
        srv_log_note("cannot block signals");
        return 1;
    }
    signal(SIGPIPE, SIG_IGN);

    struct srv_pool *pool = srv_pool_create(cfg.workers, cfg.queue);
    if (!pool) {
        srv_log_note("cannot start %d worker threads", cfg.workers);
        return 1;
    }
    struct srv_http *http = srv_http_start(&cfg, pool);
    if (!http) {
        srv_pool_free(pool);
        return 1;
    }
    srv_log_note("workers=%d queue=%d max_body=%zu deadline_ms=%ld max_steps=%ld", cfg.workers,
                 cfg.queue, cfg.max_body, cfg.deadline_ms, cfg.max_steps);

    int sig = 0;
    while (sigwait(&stop, &sig) != 0) {
    }
    srv_log_note("%s received, shutting down", sig == SIGINT ? "SIGINT" : "SIGTERM");

    srv_http_quiesce(http); /* no new connections; cancel flag raised */
    srv_pool_stop(pool);    /* queued jobs -> 503 cancelled; running ones stop; joined */
    srv_http_drain(http, SRV_DRAIN_SECONDS);
    srv_http_stop(http);
    srv_pool_free(pool);
    srv_log_note("stopped");
    return 0;
}
