/* main.c — mechd entry point: options, process-wide set-up, and the signal
 * wait that drives a clean shutdown.
 *
 * SIGINT/SIGTERM are blocked in every thread and taken with sigwait() here,
 * so no work happens in a signal handler. Shutdown: stop accepting, let
 * running and queued requests finish for up to --shutdown-grace-ms (a
 * container's orchestrator sends SIGTERM, then SIGKILL after its own grace
 * period, often 30 s), then raise the cancel flag (running computations stop
 * at their next budget check), answer the still-queued jobs 503 cancelled and
 * join the workers (every suspended connection is resumed by then), give the
 * answers a moment to be sent, stop the daemon, exit 0.
 */
#include <gsl/gsl_errno.h>
#include <malloc.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "api.h"
#include "config.h"
#include "eval.h"
#include "healthcheck.h"
#include "http.h"
#include "log.h"
#include "mhd_panic.h"
#include "static.h"
#include "workers.h"

#define SRV_DRAIN_SECONDS 3.0 /* how long answers to cancelled work may take to go out */
#define SRV_MMAP_THRESHOLD (1 << 20) /* blocks this large come from mmap, freed straight back */
#define SRV_TRIM_THRESHOLD (4 << 20) /* free heap above this at an arena's top is returned */

int main(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "eval") == 0) {
        /* Offline mode: one request through the API layer, no socket. */
        gsl_set_error_handler_off();
        api_install_json_allocator(); /* jansson's allocator: process-wide, once */
        if (api_init() != 0) {
            srv_log_note("API initialisation failed: %s", api_init_error());
            return 3;
        }
        return srv_eval_main(argc - 1, argv + 1, stdin, stdout, stderr);
    }

    if (argc >= 2 && strcmp(argv[1], "healthcheck") == 0) /* the image's HEALTHCHECK */
        return srv_healthcheck_main(argc - 1, argv + 1, stderr);

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
    srv_log_set_json(cfg.log_json); /* before any thread logs */

    gsl_set_error_handler_off(); /* process-wide, once: GSL's default handler aborts */
    api_install_json_allocator(); /* jansson's allocator: process-wide, once */
    srv_mhd_panic_install();      /* libmicrohttpd's panics: survive its quiesce race */
    /* Return memory after large answers. glibc's default thresholds are
     * dynamic: freeing one 16 MB answer raises the mmap threshold to 16 MB and
     * the trim threshold to 32 MB, after which every worker's malloc arena
     * keeps its freed answer-sized top for good (malloc_trim does not shrink
     * a thread arena's top). Fixed thresholds keep large blocks on mmap and let
     * arenas shrink; http.c also calls malloc_trim(0) after a large answer. */
    mallopt(M_MMAP_THRESHOLD, SRV_MMAP_THRESHOLD);
    mallopt(M_TRIM_THRESHOLD, SRV_TRIM_THRESHOLD);
    if (api_init() != 0) {
        srv_log_note("API initialisation failed: %s", api_init_error());
        return 1;
    }

    /* The front end's files, read once; without them / is a built-in page. */
    int n_static = srv_static_init(cfg.static_dir);
    if (n_static < 0)
        srv_log_note("no static files at %s: serving the built-in start page", cfg.static_dir);
    if (srv_static_set_frame_ancestors(cfg.frame_ancestors) != 0) {
        srv_log_note("--frame-ancestors: the list is too long");
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

    struct srv_pool *pool = srv_pool_create_nice(cfg.workers, cfg.queue, cfg.worker_nice);
    if (!pool) {
        srv_log_note("cannot start %d worker threads", cfg.workers);
        srv_static_free();
        return 1;
    }
    struct srv_http *http = srv_http_start(&cfg, pool);
    if (!http) {
        srv_pool_free(pool);
        srv_static_free();
        return 1;
    }
    srv_log_note("workers=%d queue=%d io_threads=%d max_body=%zu deadline_ms=%ld max_steps=%ld "
                 "request_timeout_ms=%ld inline_max_us=%ld worker_nice=%d max_answer_memory=%zu "
                 "static_files=%d",
                 cfg.workers, cfg.queue, cfg.io_threads, cfg.max_body, cfg.deadline_ms,
                 cfg.max_steps, cfg.request_timeout_ms, cfg.inline_max_us, cfg.worker_nice,
                 cfg.max_answer_memory, n_static < 0 ? 0 : n_static);

    int sig = 0;
    while (sigwait(&stop, &sig) != 0) {
    }
    srv_log_note("%s received, shutting down", sig == SIGINT ? "SIGINT" : "SIGTERM");

    srv_http_stop_accepting(http); /* no new connections; work in flight goes on */
    int left = srv_http_drain(http, (double)cfg.shutdown_grace_ms / 1000.0);
    if (left > 0)
        srv_log_note("shutdown grace period (%ld ms) over: cancelling %d request%s", cfg.shutdown_grace_ms,
                     left, left == 1 ? "" : "s");
    srv_http_quiesce(http); /* cancel flag raised */
    srv_pool_stop(pool);    /* queued jobs -> 503 cancelled; running ones stop; joined */
    srv_http_drain(http, SRV_DRAIN_SECONDS);
    srv_http_stop(http);
    srv_pool_free(pool);
    srv_static_free();
    srv_log_note("stopped");
    return 0;
}
