/* config.h — mechd's settings: command line, MECHD_* environment, defaults.
 *
 * Precedence: command line, then environment, then the built-in default.
 * Every option is validated; an invalid value is reported on stderr and the
 * program exits with status 2 (see srv_config_load()).
 */
#ifndef SERVER_CONFIG_H
#define SERVER_CONFIG_H

#include <stddef.h>
#include <stdio.h>

struct srv_config {
    char bind[64];           /* numeric IPv4 or IPv6 address to listen on */
    int port;                /* 0..65535; 0 picks a free port */
    int workers;             /* compute threads, 1..1024 */
    int queue;               /* jobs waiting for a worker, 1..1000000 */
    size_t max_body;         /* request body limit in bytes, 1..1 GiB */
    long deadline_ms;        /* wall-clock budget per request, 1..86400000 ms */
    long max_steps;          /* step budget per integration, 1..1e12 */
    char static_dir[1024];   /* root of the front end's static files (clients/web) */
    char token_file[1024];   /* --token-file: "" for no authentication */
    char token[257];         /* the bearer token read from token_file ("" if none) */
    size_t token_len;        /* strlen(token), 0 when /v1 is open */
    char cors_origins[2048]; /* allowed origins, comma-separated, normalised; "" = CORS off */
    char frame_ancestors[2048]; /* origins that may embed the front end in a frame,
                                   comma-separated; "" = none may (the default) */
    int io_threads;          /* I/O threads (one libmicrohttpd daemon each), 1..64 */
    long request_timeout_ms; /* time to receive one whole request, 100..3600000 ms */
    long inline_max_us;      /* quick operations run inline while predicted <= this, 0..1e6 µs */
    int worker_nice;         /* nice increment of the compute workers, 0..19 */
    long max_samples;        /* answer budget: samples per request (batch items summed), 1..1e9 */
    size_t max_answer_memory; /* bytes of answers held at once (computed, not yet sent);
                                 0 before srv_config_load, which fills in the default */
    int max_connections;     /* connections held open at once before the longest-waiting
                                idle one is closed to make room, 8..100000 */
    long shutdown_grace_ms;  /* on SIGTERM/SIGINT, time running and queued requests get to
                                finish before they are cancelled, 0..600000 ms */
    long hangup_grace_ms;    /* how long a pooled request's client end-of-file must persist
                                before it counts as a hang-up and cancels it, 0..600000 ms */
    int log_json;            /* --log-format json: log lines are JSON objects */
};

#define SRV_TOKEN_MAX 256 /* longest accepted bearer token, in bytes */

enum srv_config_result {
    SRV_CONFIG_RUN = 0,   /* cfg is filled: start the server */
    SRV_CONFIG_EXIT = 1,  /* --help or --version was printed to out: exit 0 */
    SRV_CONFIG_ERROR = 2, /* a message was printed to err: exit 2 */
};

/* Fill cfg from argv (argv[0] is the program name) and the MECHD_* variables.
 * --help and --version print to `out`; errors print one line each to `err`.
 * Not thread-safe (reads the environment); call once from main. */
enum srv_config_result srv_config_load(struct srv_config *cfg, int argc, char **argv, FILE *out,
                                       FILE *err);

#endif
