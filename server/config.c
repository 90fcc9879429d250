/* config.c — parse mechd's options (command line > MECHD_* environment >
 * default) with strict validation; see config.h. */
#include "config.h"

#include "answer_mem.h" /* srv_mem_default_cap */
#include "static.h"     /* MECHD_STATIC_DIR, the default root */

#include <arpa/inet.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef MECHD_VERSION
#define MECHD_VERSION "0.0.0"
#endif
#ifndef MECHD_BUILD_ID
#define MECHD_BUILD_ID "unknown" /* the git commit it was configured from (CMake) */
#endif

/* The default front end of an installed mechd: PREFIX/share/mechd/web when this
 * executable is PREFIX/bin/mechd and that directory holds an index.html (what
 * `make install` lays out, wherever PREFIX or DESTDIR put it); otherwise the
 * build's MECHD_STATIC_DIR (the source tree's clients/web). Returns buf or the
 * static default; never fails. */
static const char *installed_static_dir(char *buf, size_t n)
{
    char exe[900];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0 || (size_t)len >= sizeof exe - 1) return MECHD_STATIC_DIR;
    exe[len] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash) return MECHD_STATIC_DIR;
    *slash = '\0'; /* PREFIX/bin */
    char index[1024];
    if (snprintf(buf, n, "%s/../share/mechd/web", exe) >= (int)n ||
        snprintf(index, sizeof index, "%s/index.html", buf) >= (int)sizeof index ||
        access(index, R_OK) != 0)
        return MECHD_STATIC_DIR;
    return buf;
}

enum opt_id {
    OPT_BIND,
    OPT_PORT,
    OPT_WORKERS,
    OPT_QUEUE,
    OPT_MAX_BODY,
    OPT_DEADLINE_MS,
    OPT_MAX_STEPS,
    OPT_STATIC_DIR,
    OPT_TOKEN_FILE,
    OPT_CORS_ORIGIN,
    OPT_IO_THREADS,
    OPT_REQUEST_TIMEOUT_MS,
    OPT_INLINE_MAX_US,
    OPT_WORKER_NICE,
    OPT_MAX_SAMPLES,
    OPT_MAX_ANSWER_MEMORY,
    OPT_MAX_CONNECTIONS,
    OPT_SHUTDOWN_GRACE_MS,
    OPT_HANGUP_GRACE_MS,
    OPT_LOG_FORMAT,
    OPT_FRAME_ANCESTORS,
    OPT_COUNT
};

/* One row per option: its flag, environment variable, default (as text, so
 * --help shows exactly what is parsed), valid range and help text. */
static const struct opt_spec {
    const char *flag;
    const char *env;
    const char *def;
    long long min, max; /* for numeric options */
    const char *help;
} opts[OPT_COUNT] = {
    [OPT_BIND] = {"--bind", "MECHD_BIND", "127.0.0.1", 0, 0,
                  "numeric IPv4 or IPv6 address to listen on"},
    [OPT_PORT] = {"--port", "MECHD_PORT", "8080", 0, 65535,
                  "TCP port; 0 picks a free port (the listening line on stdout shows it)"},
    [OPT_WORKERS] = {"--workers", "MECHD_WORKERS", "2", 1, 1024, "compute worker threads"},
    [OPT_QUEUE] = {"--queue", "MECHD_QUEUE", "64", 1, 1000000,
                   "jobs that may wait for a worker; beyond it requests get 503"},
    [OPT_MAX_BODY] = {"--max-body", "MECHD_MAX_BODY", "1048576", 1, 1073741824LL,
                      "largest request body in bytes; larger bodies get 413"},
    [OPT_DEADLINE_MS] = {"--deadline-ms", "MECHD_DEADLINE_MS", "10000", 1, 86400000LL,
                         "wall-clock budget of one request in ms, from when it is queued"},
    [OPT_MAX_STEPS] = {"--max-steps", "MECHD_MAX_STEPS", "10000000", 1, 1000000000000LL,
                       "step budget of one integration"},
    [OPT_STATIC_DIR] = {"--static-dir", "MECHD_STATIC_DIR", MECHD_STATIC_DIR, 0, 0,
                        "directory of the front end served at / (read once at start; when it "
                        "is missing a built-in start page is served); an installed mechd "
                        "defaults to PREFIX/share/mechd/web"},
    [OPT_TOKEN_FILE] = {"--token-file", "MECHD_TOKEN_FILE", "", 0, 0,
                        "file holding one bearer token (printable ASCII, <= 256 bytes); when "
                        "set, every /v1 request needs 'Authorization: Bearer TOKEN'"},
    [OPT_CORS_ORIGIN] = {"--cors-origin", "MECHD_CORS_ORIGIN", "", 0, 0,
                         "origin allowed to call /v1 from a browser, e.g. https://lab.example.org; "
                         "repeatable or comma-separated; none: CORS off"},
    [OPT_IO_THREADS] = {"--io-threads", "MECHD_IO_THREADS", "2", 1, 64,
                        "HTTP I/O threads (libmicrohttpd's thread pool); they read requests, "
                        "answer quick operations and /healthz, and send answers"},
    [OPT_REQUEST_TIMEOUT_MS] = {"--request-timeout-ms", "MECHD_REQUEST_TIMEOUT_MS", "30000", 100,
                                3600000LL,
                                "longest time a client may take to send one whole request "
                                "(headers and body, counted from the connection or its previous "
                                "answer); slower connections are closed"},
    [OPT_INLINE_MAX_US] = {"--inline-max-us", "MECHD_INLINE_MAX_US", "100", 0, 1000000,
                           "a quick operation (closed form) or a trajectory is answered on an "
                           "I/O thread while its predicted CPU cost is at most this many µs; "
                           "0: every operation goes to the workers"},
    [OPT_WORKER_NICE] = {"--worker-nice", "MECHD_WORKER_NICE", "0", 0, 19,
                         "how much lower the compute workers' scheduling priority is than the "
                         "I/O threads' (nice increment; workers always run SCHED_BATCH, so a "
                         "waking worker never preempts an I/O thread); 0: the same CPU share, "
                         "so long jobs keep their fair share under a flood of cheap requests"},
    [OPT_MAX_SAMPLES] = {"--max-samples", "MECHD_MAX_SAMPLES", "200000", 1, 1000000000LL,
                         "answer budget: the samples one request may ask for, summed over its "
                         "\"samples\" members and a batch's items; more get 422 "
                         "answer-too-large before anything is computed"},
    [OPT_MAX_ANSWER_MEMORY] = {"--max-answer-memory", "MECHD_MAX_ANSWER_MEMORY", "auto",
                               1048576LL, 1099511627776LL,
                               "bytes of answers the server holds at once for clients still "
                               "reading them (and being computed); a request whose predicted "
                               "answer does not fit waits up to 1 s, then gets 503 "
                               "answer-memory-full with Retry-After. auto: 512 MiB or a "
                               "quarter of the memory (RAM or cgroup limit), whichever is less"},
    [OPT_MAX_CONNECTIONS] = {"--max-connections", "MECHD_MAX_CONNECTIONS", "512", 8, 100000,
                             "connections held open at once; a new one beyond it closes the "
                             "connection that has waited longest without sending a whole "
                             "request, so /healthz stays reachable under a connection flood"},
    [OPT_SHUTDOWN_GRACE_MS] = {"--shutdown-grace-ms", "MECHD_SHUTDOWN_GRACE_MS", "10000", 0,
                               600000,
                               "on SIGTERM/SIGINT: stop accepting, then let running and queued "
                               "requests finish for up to this many ms before cancelling them "
                               "(keep it under the container's grace period, often 30 s)"},
    [OPT_HANGUP_GRACE_MS] = {"--hangup-grace-ms", "MECHD_HANGUP_GRACE_MS", "500", 0, 600000,
                             "a request running on a worker is cancelled once its client's "
                             "end-of-file has been seen this long (a half-close after a whole "
                             "request, as nc -N sends, is the same FIN as a hang-up)"},
    [OPT_LOG_FORMAT] = {"--log-format", "MECHD_LOG_FORMAT", "text", 0, 0,
                        "log lines on stderr: text (\"mechd: TIME req=ID ...\") or json (one "
                        "JSON object per line, for log collectors)"},
    [OPT_FRAME_ANCESTORS] = {"--frame-ancestors", "MECHD_FRAME_ANCESTORS", "none", 0, 0,
                             "origins whose pages may embed the front end in an iframe (a course "
                             "site), e.g. https://course.example.edu; comma-separated; none: no "
                             "framing (CSP frame-ancestors 'none', X-Frame-Options DENY)"},
};

static void print_help(FILE *out, const char *prog)
{
    fprintf(out,
            "Usage: %s [OPTION]...\n"
            "mechd: a physics computation server (JSON over HTTP).\n\n"
            "Options (each also settable from the environment variable shown;\n"
            "the command line wins over the environment):\n",
            prog);
    for (int i = 0; i < OPT_COUNT; i++) {
        char left[40];
        snprintf(left, sizeof left, "%s=VALUE", opts[i].flag);
        fprintf(out, "  %-22s %s\n  %-22s default %s, env %s\n", left, opts[i].help, "",
                *opts[i].def ? opts[i].def : "none", opts[i].env);
    }
    fprintf(out, "  %-22s show this help and exit\n", "--help");
    fprintf(out, "  %-22s show the version and exit\n", "--version");
    fprintf(out, "\nSIGINT/SIGTERM stop the server cleanly: no new connections, running and queued\n"
                 "requests get --shutdown-grace-ms to finish, then are cancelled (503); exit 0.\n");
    fprintf(out,
            "\nOffline mode (no network):\n"
            "  %s eval [--operation=PATH] [--cost] [FILE]   (see %s eval --help)\n"
            "  answers one request from FILE or stdin with exactly the body the server\n"
            "  would send; exit status 0 answer, 1 problem (4xx), 3 server failure, 2 usage.\n",
            prog, prog);
}

/* Strict decimal integer in [min, max]: no sign games, no trailing text. */
static int parse_int(const char *s, long long min, long long max, long long *out)
{
    if (!s || !*s || (*s != '-' && (*s < '0' || *s > '9'))) return -1;
    errno = 0;
    char *end = NULL;
    long long v = strtoll(s, &end, 10);
    if (errno || !end || *end != '\0' || v < min || v > max) return -1;
    *out = v;
    return 0;
}

/* Read the bearer token: the file's first line without surrounding
 * whitespace; printable ASCII only (RFC 6750 b64token is a subset). */
static int load_token(struct srv_config *cfg, const char *path, const char *source, FILE *err)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(err, "mechd: cannot read %s '%s': %s\n", source, path, strerror(errno));
        return -1;
    }
    char buf[SRV_TOKEN_MAX + 4];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    char *s = buf;
    while (*s == ' ' || *s == '\t')
        s++;
    size_t len = strcspn(s, "\r\n");
    int cut = s[len] == '\0' && n == sizeof buf - 1; /* first line longer than the buffer */
    while (len > 0 && (s[len - 1] == ' ' || s[len - 1] == '\t'))
        len--;
    s[len] = '\0';
    int ok = !cut && len > 0 && len <= SRV_TOKEN_MAX;
    for (size_t i = 0; ok && i < len; i++)
        ok = s[i] > 0x20 && s[i] < 0x7f;
    if (!ok) {
        fprintf(err,
                "mechd: invalid %s '%s': expected one token of 1 to %d printable ASCII "
                "characters without spaces on the first line\n",
                source, path, SRV_TOKEN_MAX);
        return -1;
    }
    memcpy(cfg->token, s, len + 1);
    cfg->token_len = len;
    return 0;
}

/* Append comma-separated origins ("scheme://host[:port]", no path, or "null"
 * is refused) to dst (cap bytes: cfg->cors_origins or cfg->frame_ancestors). */
static int add_origins(char *dst, size_t cap, const char *value, const char *source, FILE *err)
{
    const char *p = value;
    while (*p) {
        while (*p == ',' || *p == ' ')
            p++;
        size_t n = strcspn(p, ", ");
        if (n == 0) break;
        int ok =
            (strncmp(p, "http://", 7) == 0 && n > 7) || (strncmp(p, "https://", 8) == 0 && n > 8);
        size_t start = strncmp(p, "https://", 8) == 0 ? 8 : 7;
        for (size_t i = start; ok && i < n; i++)
            ok = p[i] > 0x20 && p[i] < 0x7f && p[i] != '/' && p[i] != '*';
        size_t used = strlen(dst);
        if (!ok || used + n + 2 > cap) {
            fprintf(err,
                    "mechd: invalid %s '%.*s': expected an origin such as "
                    "https://lab.example.org or http://localhost:3000 (no path, no '*')\n",
                    source, (int)n, p);
            return -1;
        }
        if (used) dst[used++] = ',';
        memcpy(dst + used, p, n);
        dst[used + n] = '\0';
        p += n;
    }
    return 0;
}

static int set_option(struct srv_config *cfg, enum opt_id id, const char *value, const char *source,
                      FILE *err)
{
    const struct opt_spec *o = &opts[id];
    if (id == OPT_BIND) {
        unsigned char addr[sizeof(struct in6_addr)];
        if (strlen(value) >= sizeof cfg->bind ||
            (inet_pton(AF_INET, value, addr) != 1 && inet_pton(AF_INET6, value, addr) != 1)) {
            fprintf(err, "mechd: invalid %s '%s': expected a numeric IPv4 or IPv6 address\n",
                    source, value);
            return -1;
        }
        strcpy(cfg->bind, value);
        return 0;
    }
    if (id == OPT_STATIC_DIR) {
        if (!*value || strlen(value) >= sizeof cfg->static_dir) {
            fprintf(err, "mechd: invalid %s '%s': expected a directory path (< %zu bytes)\n",
                    source, value, sizeof cfg->static_dir);
            return -1;
        }
        strcpy(cfg->static_dir, value);
        return 0;
    }
    if (id == OPT_TOKEN_FILE) {
        cfg->token[0] = '\0';
        cfg->token_len = 0;
        if (!*value) return 0; /* no authentication */
        if (strlen(value) >= sizeof cfg->token_file) {
            fprintf(err, "mechd: invalid %s: path too long\n", source);
            return -1;
        }
        strcpy(cfg->token_file, value);
        return load_token(cfg, value, source, err);
    }
    if (id == OPT_CORS_ORIGIN)
        return add_origins(cfg->cors_origins, sizeof cfg->cors_origins, value, source, err);
    if (id == OPT_FRAME_ANCESTORS) {
        cfg->frame_ancestors[0] = '\0';
        if (strcmp(value, "none") == 0) return 0;
        return add_origins(cfg->frame_ancestors, sizeof cfg->frame_ancestors, value, source, err);
    }
    if (id == OPT_LOG_FORMAT) {
        if (strcmp(value, "text") && strcmp(value, "json")) {
            fprintf(err, "mechd: invalid %s '%.40s': expected text or json\n", source, value);
            return -1;
        }
        cfg->log_json = !strcmp(value, "json");
        return 0;
    }
    if (id == OPT_MAX_ANSWER_MEMORY && strcmp(value, "auto") == 0) {
        cfg->max_answer_memory = srv_mem_default_cap();
        return 0;
    }
    long long v;
    if (parse_int(value, o->min, o->max, &v) != 0) {
        fprintf(err, "mechd: invalid %s '%s': expected %san integer in [%lld, %lld]\n", source,
                value, id == OPT_MAX_ANSWER_MEMORY ? "auto or " : "", o->min, o->max);
        return -1;
    }
    switch (id) {
    case OPT_PORT:
        cfg->port = (int)v;
        break;
    case OPT_WORKERS:
        cfg->workers = (int)v;
        break;
    case OPT_QUEUE:
        cfg->queue = (int)v;
        break;
    case OPT_MAX_BODY:
        cfg->max_body = (size_t)v;
        break;
    case OPT_DEADLINE_MS:
        cfg->deadline_ms = (long)v;
        break;
    case OPT_MAX_STEPS:
        cfg->max_steps = (long)v;
        break;
    case OPT_IO_THREADS:
        cfg->io_threads = (int)v;
        break;
    case OPT_REQUEST_TIMEOUT_MS:
        cfg->request_timeout_ms = (long)v;
        break;
    case OPT_INLINE_MAX_US:
        cfg->inline_max_us = (long)v;
        break;
    case OPT_WORKER_NICE:
        cfg->worker_nice = (int)v;
        break;
    case OPT_MAX_SAMPLES:
        cfg->max_samples = (long)v;
        break;
    case OPT_MAX_ANSWER_MEMORY:
        cfg->max_answer_memory = (size_t)v;
        break;
    case OPT_MAX_CONNECTIONS:
        cfg->max_connections = (int)v;
        break;
    case OPT_SHUTDOWN_GRACE_MS:
        cfg->shutdown_grace_ms = (long)v;
        break;
    case OPT_HANGUP_GRACE_MS:
        cfg->hangup_grace_ms = (long)v;
        break;
    default:
        break;
    }
    return 0;
}

enum srv_config_result srv_config_load(struct srv_config *cfg, int argc, char **argv, FILE *out,
                                       FILE *err)
{
    const char *prog = argc > 0 && argv[0] ? argv[0] : "mechd";
    const char *cli[OPT_COUNT] = {0};
    int cors_cli = 0; /* --cors-origin seen on the command line (repeatable) */

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            print_help(out, prog);
            return SRV_CONFIG_EXIT;
        }
        if (strcmp(a, "--version") == 0) {
            fprintf(out, "mechd %s (commit %s)\n", MECHD_VERSION, MECHD_BUILD_ID);
            return SRV_CONFIG_EXIT;
        }
        int found = -1;
        const char *value = NULL;
        for (int k = 0; k < OPT_COUNT; k++) {
            size_t n = strlen(opts[k].flag);
            if (strncmp(a, opts[k].flag, n) != 0) continue;
            if (a[n] == '\0') {
                if (i + 1 >= argc) {
                    fprintf(err, "mechd: option %s needs a value (see --help)\n", opts[k].flag);
                    return SRV_CONFIG_ERROR;
                }
                value = argv[++i];
            } else if (a[n] == '=') {
                value = a + n + 1;
            } else {
                continue;
            }
            found = k;
            break;
        }
        if (found < 0) {
            fprintf(err, "mechd: unknown argument '%s' (see --help)\n", a);
            return SRV_CONFIG_ERROR;
        }
        if (found == OPT_CORS_ORIGIN) {
            char source[64];
            snprintf(source, sizeof source, "option %s", opts[found].flag);
            if (!cors_cli) cfg->cors_origins[0] = '\0';
            cors_cli = 1;
            if (add_origins(cfg->cors_origins, sizeof cfg->cors_origins, value, source, err) != 0)
                return SRV_CONFIG_ERROR;
            continue;
        }
        cli[found] = value;
    }

    char installed[1024];
    for (int k = 0; k < OPT_COUNT; k++) {
        char source[64];
        const char *value = cli[k];
        if (k == OPT_CORS_ORIGIN && cors_cli) continue; /* taken above */
        if (value) {
            snprintf(source, sizeof source, "option %s", opts[k].flag);
        } else if ((value = getenv(opts[k].env)) != NULL) {
            snprintf(source, sizeof source, "environment variable %s", opts[k].env);
        } else {
            value = opts[k].def;
            snprintf(source, sizeof source, "default of %s", opts[k].flag);
            if (k == OPT_STATIC_DIR) value = installed_static_dir(installed, sizeof installed);
        }
        if (set_option(cfg, (enum opt_id)k, value, source, err) != 0) return SRV_CONFIG_ERROR;
    }
    return SRV_CONFIG_RUN;
}
