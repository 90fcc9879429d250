/* log.h — one access-log line per request on stderr, and the request
 * counters behind GET /metrics. Thread-safe. */
#ifndef SERVER_LOG_H
#define SERVER_LOG_H

#include <stddef.h>

/* One finished request, as srv_log_request logs it. Strings are borrowed and
 * may be NULL (logged as "-"). */
struct srv_log_entry {
    const char *id;            /* request id: the client's X-Request-Id or a generated one */
    const char *client;        /* peer address (numeric IPv4/IPv6) */
    const char *forwarded_for; /* X-Forwarded-For as the client (a proxy) sent it */
    const char *method, *path;
    const char *route; /* metrics label (see srv_log_request) */
    int status;        /* HTTP status sent; 0: none was sent */
    long usec;         /* from the first header to completion */
    unsigned long long bytes; /* response body bytes sent */
    unsigned long long answer_bytes; /* the whole answer's body bytes */
    int cut_off;              /* 1: the connection ended before the whole answer was sent */
};

/* Record a finished request: writes
 *   "mechd: 2026-11-25T08:45:02.123Z req=ID METHOD PATH STATUS USECus bytes=N client=ADDR"
 *   (+ " xff=X-FORWARDED-FOR" when the request had one) and a newline
 * to stderr in one write(2) (the timestamp is RFC 3339 UTC with milliseconds;
 * control characters and spaces in method/path/id/xff become '?', each field is
 * bounded), and adds it to the metrics under e->route (a label from a bounded
 * set: the API path, "static", "other"; copied; NULL or a label with characters
 * other than [A-Za-z0-9/._-] counts as "other"). */
void srv_log_request(const struct srv_log_entry *e);

/* --log-format json: from now on every line (requests and notes) is one JSON
 * object: {"time", "level", "msg", and for a request "request_id", "method",
 * "path", "status", "duration_us", "bytes" (sent), "cut_off" (true when the
 * connection ended before the whole answer was sent), "answer_bytes" (the
 * whole answer), "client", "forwarded_for" (null when absent)}; strings escaped, control and non-ASCII bytes as '?'. Call before
 * the server's threads start (not synchronised). */
void srv_log_set_json(int json);

/* Write the current time as RFC 3339 UTC with milliseconds
 * ("2026-11-25T08:45:02.123Z", 24 characters + NUL) into out (>= 32 bytes). */
void srv_log_timestamp(char *out);

/* Count connections closed because they did not send a whole request within
 * --request-timeout-ms (mechd_request_timeouts_total). */
void srv_metrics_count_timeouts(unsigned long n);

/* Count connections closed to make room for a new one beyond --max-connections
 * (mechd_connections_evicted_total), and connections closed because their
 * client had gone while they waited for a request (mechd_connections_reaped_total). */
void srv_metrics_count_evictions(unsigned long n);
void srv_metrics_count_reaped(unsigned long n);

/* Count shut connections shut down again because libmicrohttpd had not closed
 * them SRV_SHUT_NUDGE_MS after the first shutdown (mechd_connections_nudged_total). */
void srv_metrics_count_shut_nudges(unsigned long n);

/* Write a free-form line "mechd: TIMESTAMP TEXT\n" to stderr (start-up, shutdown). */
void srv_log_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The gauges /metrics shows besides the counters kept here. */
struct srv_metrics_gauges {
    int queue_depth, queue_capacity, workers_busy, workers;
    double worker_busy_seconds;
    int connections_open; /* connections registered now */
    int connections_max;  /* --max-connections, as fitted to the descriptor limit */
    size_t answer_memory, answer_memory_max, answer_memory_peak; /* bytes (answer_mem.h) */
    unsigned long answer_memory_refused;
};

/* Prometheus text exposition (version 0.0.4) of the counters (requests by
 * route and status, latency histograms overall and by route), the gauges g,
 * the process metrics (process_cpu_seconds_total, process_resident_memory_bytes,
 * process_virtual_memory_bytes, process_open_fds, process_max_fds,
 * process_start_time_seconds; from /proc) and mechd_build_info. Returns a
 * malloc'd NUL-terminated string (caller frees) and its length in *len, or
 * NULL when out of memory. */
char *srv_metrics_text(const struct srv_metrics_gauges *g, unsigned long *len_out);

#endif
