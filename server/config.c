/* config.c — parse mechd's options (command line > MECHD_* environment >
 * default) with strict validation; see config.h. */
#include "config.h"

#include "static.h" /* MECHD_STATIC_DIR, the default root */

#include <arpa/inet.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#ifndef MECHD_VERSION
#define MECHD_VERSION "0.0.0"
#endif

enum opt_id {
    OPT_BIND,
    OPT_PORT,
    OPT_WORKERS,
    OPT_QUEUE,
    OPT_MAX_BODY,
    OPT_DEADLINE_MS,
    OPT_MAX_STEPS,
    OPT_STATIC_DIR,
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
                        "is missing a built-in start page is served)"},
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
                opts[i].def, opts[i].env);
    }
    fprintf(out, "  %-22s show this help and exit\n", "--help");
    fprintf(out, "  %-22s show the version and exit\n", "--version");
    fprintf(out, "\nSIGINT/SIGTERM stop the server cleanly (exit status 0).\n");
    fprintf(out, "\nOffline mode (no network):\n"
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
    long long v;
    if (parse_int(value, o->min, o->max, &v) != 0) {
        fprintf(err, "mechd: invalid %s '%s': expected an integer in [%lld, %lld]\n", source, value,
                o->min, o->max);
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

    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            print_help(out, prog);
            return SRV_CONFIG_EXIT;
        }
        if (strcmp(a, "--version") == 0) {
            fprintf(out, "mechd %s\n", MECHD_VERSION);
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
        cli[found] = value;
    }

    for (int k = 0; k < OPT_COUNT; k++) {
        char source[64];
        const char *value = cli[k];
        if (value) {
            snprintf(source, sizeof source, "option %s", opts[k].flag);
        } else if ((value = getenv(opts[k].env)) != NULL) {
            snprintf(source, sizeof source, "environment variable %s", opts[k].env);
        } else {
            value = opts[k].def;
            snprintf(source, sizeof source, "default of %s", opts[k].flag);
        }
        if (set_option(cfg, (enum opt_id)k, value, source, err) != 0) return SRV_CONFIG_ERROR;
    }
    return SRV_CONFIG_RUN;
}
