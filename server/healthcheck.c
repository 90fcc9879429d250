/* healthcheck.c — `mechd healthcheck` (see healthcheck.h): one GET /healthz
 * over a plain socket, so the container image needs no curl or wget. Reads at
 * most the status line; every step is bounded by one deadline (poll). */
#include "healthcheck.h"

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#define HC_DEFAULT_PORT 8080
#define HC_DEFAULT_TIMEOUT_MS 3000
#define HC_MAX_TIMEOUT_MS 60000

/* Parse a decimal integer in [lo, hi]; 0 on success. */
static int parse_int(const char *s, long lo, long hi, long *out)
{
    char *end;
    if (!s || !*s) return -1;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < lo || v > hi) return -1;
    *out = v;
    return 0;
}

static long ms_left(const struct timespec *deadline)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (deadline->tv_sec - now.tv_sec) * 1000 + (deadline->tv_nsec - now.tv_nsec) / 1000000;
}

/* Wait for fd to be ready for events before the deadline; 0 when ready. */
static int wait_fd(int fd, short events, const struct timespec *deadline)
{
    for (;;) {
        long left = ms_left(deadline);
        if (left <= 0) return -1;
        struct pollfd p = {fd, events, 0};
        int n = poll(&p, 1, (int)left);
        if (n > 0) return 0;
        if (n < 0 && errno != EINTR) return -1;
    }
}

int srv_healthcheck_main(int argc, char **argv, FILE *err)
{
    const char *host = "127.0.0.1";
    long port = HC_DEFAULT_PORT, timeout = HC_DEFAULT_TIMEOUT_MS;
    const char *env_port = getenv("MECHD_PORT");
    if (env_port && parse_int(env_port, 1, 65535, &port)) {
        fprintf(err, "mechd healthcheck: MECHD_PORT=%.20s is not a port (1..65535)\n", env_port);
        return 2;
    }
    for (int i = 1; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(argv[i], "--port") && !parse_int(v, 1, 65535, &port))
            i++;
        else if (!strcmp(argv[i], "--timeout-ms") && !parse_int(v, 1, HC_MAX_TIMEOUT_MS, &timeout))
            i++;
        else if (!strcmp(argv[i], "--host") && v) {
            host = v;
            i++;
        } else {
            fprintf(err, "usage: mechd healthcheck [--port N] [--host ADDR] [--timeout-ms N]\n"
                         "  GET /healthz from mechd at ADDR:N (default 127.0.0.1, MECHD_PORT or "
                         "8080); exit 0 when it answers 200\n");
            return 2;
        }
    }
    struct sockaddr_storage sa;
    socklen_t salen;
    memset(&sa, 0, sizeof sa);
    struct sockaddr_in *s4 = (struct sockaddr_in *)&sa;
    struct sockaddr_in6 *s6 = (struct sockaddr_in6 *)&sa;
    if (inet_pton(AF_INET, host, &s4->sin_addr) == 1) {
        s4->sin_family = AF_INET;
        s4->sin_port = htons((unsigned short)port);
        salen = sizeof *s4;
    } else if (inet_pton(AF_INET6, host, &s6->sin6_addr) == 1) {
        s6->sin6_family = AF_INET6;
        s6->sin6_port = htons((unsigned short)port);
        salen = sizeof *s6;
    } else {
        fprintf(err, "mechd healthcheck: --host %.64s is not a numeric IPv4 or IPv6 address\n",
                host);
        return 2;
    }
    struct timespec deadline;
    clock_gettime(CLOCK_MONOTONIC, &deadline);
    deadline.tv_sec += timeout / 1000;
    deadline.tv_nsec += (timeout % 1000) * 1000000;
    if (deadline.tv_nsec >= 1000000000) {
        deadline.tv_sec++;
        deadline.tv_nsec -= 1000000000;
    }
    int fd = socket(sa.ss_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        fprintf(err, "mechd healthcheck: socket: %s\n", strerror(errno));
        return 1;
    }
    const char *why = NULL;
    int soerr = 0;
    socklen_t sl = sizeof soerr;
    if (connect(fd, (struct sockaddr *)&sa, salen) != 0 && errno != EINPROGRESS) {
        why = strerror(errno);
    } else if (wait_fd(fd, POLLOUT, &deadline)) {
        why = "no connection within the timeout";
    } else if (getsockopt(fd, SOL_SOCKET, SO_ERROR, &soerr, &sl) != 0 || soerr) {
        why = strerror(soerr ? soerr : errno);
    }
    static const char req[] = "GET /healthz HTTP/1.0\r\nHost: localhost\r\n\r\n";
    size_t sent = 0;
    while (!why && sent < sizeof req - 1) {
        ssize_t n = send(fd, req + sent, sizeof req - 1 - sent, MSG_NOSIGNAL);
        if (n > 0)
            sent += (size_t)n;
        else if (n < 0 && errno != EAGAIN && errno != EINTR)
            why = strerror(errno);
        else if (wait_fd(fd, POLLOUT, &deadline))
            why = "could not send within the timeout";
    }
    char line[64];
    size_t got = 0;
    while (!why && got < sizeof line - 1 && !memchr(line, '\n', got)) {
        if (wait_fd(fd, POLLIN, &deadline)) {
            why = "no answer within the timeout";
            break;
        }
        ssize_t n = recv(fd, line + got, sizeof line - 1 - got, 0);
        if (n > 0)
            got += (size_t)n;
        else if (n == 0)
            break;
        else if (errno != EAGAIN && errno != EINTR)
            why = strerror(errno);
    }
    close(fd);
    line[got] = '\0';
    if (!why && (strncmp(line, "HTTP/1.", 7) || got < 12 || strncmp(line + 8, " 200", 4)))
        why = got ? "the answer was not 200" : "the connection closed without an answer";
    if (why) {
        char *nl = strpbrk(line, "\r\n");
        if (nl) *nl = '\0';
        fprintf(err, "mechd healthcheck: %s:%ld: %s%s%.40s%s\n", host, port, why, got ? " (\"" : "",
                got ? line : "", got ? "\")" : "");
        return 1;
    }
    return 0;
}
