/* fuzz_server.c — libFuzzer harness for the real HTTP request path: bytes on a
 * TCP connection to the real server.
 *
 * Once (LLVMFuzzerInitialize): the whole server in-process, as main.c sets it
 * up — srv_config_load() with fixed arguments (127.0.0.1, an ephemeral port,
 * 2 workers, short deadlines, CORS on), api_init(), srv_static_init() over
 * clients/web, a worker pool (srv_pool_create) and srv_http_start(). The port
 * is read from the "mechd listening on http://ADDR:PORT" line it prints.
 *
 * Per input: a fresh TCP connection to 127.0.0.1:PORT, the input written as
 * is (request line, headers, body — possibly several pipelined requests, or
 * garbage), then everything the server sends is read until it closes the
 * connection. So libmicrohttpd's own parsing (request line, headers, chunked
 * bodies, Expect, pipelining) and every callback of server/http.c (routing,
 * limits, CORS, static files, suspend/resume through the worker pool, the
 * access log) run on the input. libmicrohttpd is not instrumented (a system
 * library): coverage feedback comes from server/, api/ and core/.
 *
 * Ending a connection: the client half-closes (shutdown SHUT_WR) once the
 * server is idle on it — it has read every byte (FIONREAD of its end, found
 * in this process by getpeername), no request is suspended in the worker
 * pool (MHD_suspend/resume_connection are wrapped with ld --wrap and
 * counted), and nothing arrived for FUZZ_SERVER_QUIET_MS. Half-closing
 * earlier would be wrong twice over: http.c treats a half-close during a
 * pooled request as a hang-up (503 cancelled, the work never shown), and
 * libmicrohttpd 0.9.75 (edge-triggered epoll) does not notice a FIN that
 * arrives together with the request's last bytes, so a keep-alive
 * connection would stay open until --request-timeout-ms.
 *
 * Checks: the server either closes the connection without a byte or answers
 * something that starts with a well-formed status line "HTTP/1.x NNN " whose
 * header block ends with CRLF CRLF; it never answers 500 (an internal error
 * is a bug); it closes the connection within FUZZ_SERVER_WAIT_S seconds
 * (no hang). ASan/UBSan/LSan watch the server threads too.
 *
 * Run with -close_fd_mask=2 (tests/fuzz/run.sh does): the server's access log
 * (one stderr line per request) is discarded; libFuzzer's output, sanitizer
 * reports and this harness's own messages keep the original stderr.
 */
#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdatomic.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <microhttpd.h>

#include "api.h"
#include "config.h"
#include "http.h"
#include "static.h"
#include "workers.h"

#define FUZZ_SERVER_WAIT_S 10    /* longest wait for the server to finish a connection */
#define FUZZ_SERVER_QUIET_MS 3   /* idle this long (and nothing pooled): half-close */
#define FUZZ_SERVER_UNREAD_S 0.5 /* the server may leave input unread: half-close anyway */

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Connections suspended by server/http.c (a request in the worker pool):
 * linked with -Wl,--wrap=MHD_suspend_connection,--wrap=MHD_resume_connection. */
static atomic_int g_suspended;
void __real_MHD_suspend_connection(struct MHD_Connection *c);
void __real_MHD_resume_connection(struct MHD_Connection *c);
void __wrap_MHD_suspend_connection(struct MHD_Connection *c);
void __wrap_MHD_resume_connection(struct MHD_Connection *c);
void __wrap_MHD_suspend_connection(struct MHD_Connection *c)
{
    atomic_fetch_add(&g_suspended, 1);
    __real_MHD_suspend_connection(c);
}
void __wrap_MHD_resume_connection(struct MHD_Connection *c)
{
    __real_MHD_resume_connection(c);
    atomic_fetch_sub(&g_suspended, 1);
}

/* Reachable from globals for LeakSanitizer: the server lives for the process. */
static struct srv_config g_cfg;
static struct srv_pool *g_pool;
static struct srv_http *g_http;
static int g_port;
static int g_err = 2; /* the original stderr (dup'ed before libFuzzer closes fd 2) */

static void die(const char *fmt, const char *a, const uint8_t *data, size_t size)
{
    dprintf(g_err, "fuzz_server: ");
    dprintf(g_err, fmt, a);
    if (data) {
        dprintf(g_err, "\n  input (%zu bytes): '", size);
        for (size_t i = 0; i < size && i < 400; i++) {
            unsigned char c = data[i];
            if (c >= 32 && c < 127 && c != '\\') dprintf(g_err, "%c", c);
            else dprintf(g_err, "\\x%02x", c);
        }
        dprintf(g_err, "%s'", size > 400 ? "..." : "");
    }
    dprintf(g_err, "\n");
    abort();
}

/* srv_http_start prints its address on stdout: read it through a pipe. */
static int start_server(void)
{
    int fds[2];
    if (pipe(fds) != 0) return -1;
    fflush(stdout);
    int saved = dup(STDOUT_FILENO);
    if (saved < 0 || dup2(fds[1], STDOUT_FILENO) < 0) return -1;
    g_http = srv_http_start(&g_cfg, g_pool);
    fflush(stdout);
    dup2(saved, STDOUT_FILENO);
    close(saved);
    close(fds[1]);
    if (!g_http) {
        close(fds[0]);
        return -1;
    }
    char line[256];
    size_t n = 0;
    while (n < sizeof line - 1) {
        ssize_t r = read(fds[0], line + n, sizeof line - 1 - n);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        n += (size_t)r;
        if (memchr(line, '\n', n)) break;
    }
    close(fds[0]);
    line[n] = '\0';
    const char *colon = strrchr(line, ':');
    g_port = colon ? atoi(colon + 1) : 0;
    return g_port > 0 ? 0 : -1;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    g_err = dup(STDERR_FILENO);
    if (g_err < 0) g_err = STDERR_FILENO;
    signal(SIGPIPE, SIG_IGN);
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    char *args[] = {"fuzz_server", "--bind", "127.0.0.1", "--port", "0", "--workers", "2",
                    "--queue", "64", "--io-threads", "1", "--deadline-ms", "2000",
                    "--max-steps", "1000000", "--max-body", "4096", "--request-timeout-ms",
                    "5000", "--cors-origin", "http://fuzz.example", NULL};
    int n = (int)(sizeof args / sizeof args[0]) - 1;
    if (srv_config_load(&g_cfg, n, args, stdout, stderr) != SRV_CONFIG_RUN)
        die("srv_config_load refused the arguments%s", "", NULL, 0);
    if (api_init() != 0) die("api_init: %s", api_init_error(), NULL, 0);
    if (srv_static_init(g_cfg.static_dir) <= 0)
        dprintf(g_err, "fuzz_server: no static files under %s\n", g_cfg.static_dir);
    g_pool = srv_pool_create(g_cfg.workers, g_cfg.queue);
    if (!g_pool) die("srv_pool_create failed%s", "", NULL, 0);
    if (start_server() != 0) die("srv_http_start failed%s", "", NULL, 0);
    return 0;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* Wait for fd to become ready for `events` until `deadline`: 1 ready, 0 timeout. */
static int wait_fd(int fd, short events, double deadline)
{
    for (;;) {
        double left = deadline - now_s();
        if (left <= 0) return 0;
        struct pollfd p = {.fd = fd, .events = events};
        int r = poll(&p, 1, (int)(left * 1000) + 1);
        if (r > 0) return 1;
        if (r < 0 && errno != EINTR) return 1; /* let the read/write report it */
    }
}

/* "HTTP/1.x NNN " at the start: returns NNN, or -1. */
static int status_of(const char *r, size_t n)
{
    if (n < 13 || memcmp(r, "HTTP/1.", 7) || (r[7] != '0' && r[7] != '1') || r[8] != ' ')
        return -1;
    for (int i = 9; i < 12; i++)
        if (r[i] < '0' || r[i] > '9') return -1;
    if (r[12] != ' ') return -1;
    return (r[9] - '0') * 100 + (r[10] - '0') * 10 + (r[11] - '0');
}

/* The server's descriptor of the connection whose client end is `s` (this
 * process holds both), or -1 if it is not accepted yet. */
static int server_end(int s)
{
    struct sockaddr_in me, peer;
    socklen_t len = sizeof me;
    if (getsockname(s, (struct sockaddr *)&me, &len) != 0) return -1;
    for (int fd = 3; fd < 1024; fd++) {
        if (fd == s) continue;
        len = sizeof peer;
        if (getpeername(fd, (struct sockaddr *)&peer, &len) == 0 && len == sizeof peer &&
            peer.sin_family == AF_INET && peer.sin_port == me.sin_port &&
            peer.sin_addr.s_addr == me.sin_addr.s_addr)
            return fd;
    }
    return -1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int s = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (s < 0) die("socket: %s", strerror(errno), NULL, 0);
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)g_port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(s, (struct sockaddr *)&a, sizeof a) != 0) {
        /* libFuzzer's timer signal can interrupt a blocking connect; the
         * connection then completes in the background (POSIX connect(2)):
         * wait for it and read its outcome. A CI run once stopped here. */
        int e = errno, err = 0;
        socklen_t len = sizeof err;
        if (e == EINTR) {
            struct pollfd p = {s, POLLOUT, 0};
            while (poll(&p, 1, 10000) < 0 && errno == EINTR) {
            }
            if (getsockopt(s, SOL_SOCKET, SO_ERROR, &err, &len) != 0) err = errno;
        } else {
            err = e;
        }
        if (err) die("connect to the server: %s", strerror(err), data, size);
    }
    double deadline = now_s() + FUZZ_SERVER_WAIT_S;

    /* Write the input; the server may answer and close before reading it all
     * (a refused header or body): then stop writing and read the answer. */
    size_t off = 0;
    while (off < size) {
        if (!wait_fd(s, POLLOUT, deadline)) die("server stopped reading for %s s", "10", data, size);
        ssize_t w = send(s, data + off, size - off, MSG_NOSIGNAL | MSG_DONTWAIT);
        if (w < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (w <= 0) break; /* EPIPE / ECONNRESET: the server closed */
        off += (size_t)w;
    }

    char head[8192];
    size_t n = 0, total = 0;
    int half = 0, srv_fd = -1;
    double written = now_s(), last = written;
    for (;;) {
        double t = now_s();
        if (t > deadline) die("connection still open after %s s", "10", data, size);
        struct pollfd p = {.fd = s, .events = POLLIN};
        int r = poll(&p, 1, half ? (int)((deadline - t) * 1000) + 1 : 1);
        if (r < 0 && errno != EINTR) die("poll: %s", strerror(errno), data, size);
        if (r > 0) {
            char buf[16384];
            ssize_t k = recv(s, buf, sizeof buf, MSG_DONTWAIT);
            if (k < 0 && (errno == EINTR || errno == EAGAIN)) continue;
            if (k <= 0) break; /* closed (or reset) */
            if (n < sizeof head) {
                size_t c = (size_t)k < sizeof head - n ? (size_t)k : sizeof head - n;
                memcpy(head + n, buf, c);
                n += c;
            }
            total += (size_t)k;
            last = now_s();
            continue;
        }
        if (half) continue;
        t = now_s();
        if (t - last < FUZZ_SERVER_QUIET_MS * 1e-3) continue;
        if (atomic_load(&g_suspended) > 0) { /* a worker has it: the answer will come */
            last = t;
            continue;
        }
        if (srv_fd < 0) srv_fd = server_end(s);
        int unread = 0;
        if (srv_fd >= 0 && ioctl(srv_fd, FIONREAD, &unread) == 0 && unread > 0 &&
            t - written < FUZZ_SERVER_UNREAD_S)
            continue; /* not read yet (or never: then after FUZZ_SERVER_UNREAD_S) */
        shutdown(s, SHUT_WR);
        half = 1;
    }
    close(s);

    if (total == 0) return 0; /* closed without an answer: allowed */
    int st = status_of(head, n);
    if (st < 100) die("answer does not start with a status line%s", "", data, size);
    if (st == 500) die("the server answered 500%s", "", data, size);
    /* The header block of the first response ends within the first 8 KiB. */
    int ended = 0;
    for (size_t i = 0; i + 3 < n; i++)
        if (head[i] == '\r' && head[i + 1] == '\n' && head[i + 2] == '\r' && head[i + 3] == '\n') {
            ended = 1;
            break;
        }
    if (!ended) die("the response's header block does not end with CRLF CRLF%s", "", data, size);
    return 0;
}
