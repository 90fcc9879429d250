/* floor_server.c — the floor of this HTTP stack for bench_http: a minimal
 * libmicrohttpd server (epoll, a thread pool of 2 like the figures in
 * notes/machine.md) answering every request, any method and body, with the
 * same small fixed JSON. Nothing is parsed or computed, so its requests per
 * second and CPU per request are what mechd could at best reach.
 * Usage: floor_server [PORT]   (0 or none: a free port). Prints
 * "floor listening on http://127.0.0.1:PORT" and runs until SIGTERM/SIGINT.
 * Binds 127.0.0.1 only. Never part of the tests. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <arpa/inet.h>
#include <microhttpd.h>
#include <netinet/in.h>

static const char BODY[] = "{\"status\":\"ok\",\"value\":[0.875,-0.125,0.0,0.0]}";
static struct MHD_Response *fixed;
static volatile sig_atomic_t stop;

static void on_signal(int sig)
{
    (void)sig;
    stop = 1;
}

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url, const char *method,
                                  const char *version, const char *upload, size_t *upload_size, void **state)
{
    static int first;
    if (*state == NULL) { /* headers only: come back with the body */
        *state = &first;
        return MHD_YES;
    }
    if (*upload_size) { /* discard the body */
        *upload_size = 0;
        return MHD_YES;
    }
    return MHD_queue_response(c, MHD_HTTP_OK, fixed);
}

int main(int argc, char **argv)
{
    unsigned port = argc > 1 ? (unsigned)strtoul(argv[1], NULL, 10) : 0;
    struct sockaddr_in sa;
    memset(&sa, 0, sizeof sa);
    sa.sin_family = AF_INET;
    sa.sin_port = htons((uint16_t)port);
    sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    fixed = MHD_create_response_from_buffer(sizeof BODY - 1, (void *)BODY, MHD_RESPMEM_PERSISTENT);
    if (!fixed || MHD_add_response_header(fixed, "Content-Type", "application/json") != MHD_YES) return 1;
    struct MHD_Daemon *d = MHD_start_daemon(MHD_USE_EPOLL_INTERNAL_THREAD | MHD_USE_ERROR_LOG, (uint16_t)port, NULL,
                                            NULL, on_request, NULL, MHD_OPTION_SOCK_ADDR, &sa,
                                            MHD_OPTION_THREAD_POOL_SIZE, 2u, MHD_OPTION_CONNECTION_TIMEOUT, 30u,
                                            MHD_OPTION_END);
    if (!d) {
        fprintf(stderr, "floor_server: cannot start on port %u\n", port);
        return 1;
    }
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(d, MHD_DAEMON_INFO_BIND_PORT);
    printf("floor listening on http://127.0.0.1:%u\n", info ? (unsigned)info->port : port);
    fflush(stdout);
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    while (!stop) pause();
    MHD_stop_daemon(d);
    MHD_destroy_response(fixed);
    return 0;
}
