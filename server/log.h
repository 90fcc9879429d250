/* log.h — one access-log line per request on stderr, and the request
 * counters behind GET /metrics. Thread-safe. */
#ifndef SERVER_LOG_H
#define SERVER_LOG_H

/* Record a finished request: writes
 *   "mechd: req=ID METHOD PATH STATUS USECus\n"
 * to stderr in one write(2) (control characters in method/path become '?'),
 * and adds it to the metrics under `route` (a label from a bounded set: the
 * API path, "static", "other"; copied; NULL or a label with characters other
 * than [A-Za-z0-9/._-] counts as "other"). status 0 means no response was
 * sent (the client went away or the server stopped). method/path may be NULL. */
void srv_log_request(unsigned long id, const char *method, const char *path, const char *route,
                     int status, long usec);

/* Count connections closed because they did not send a whole request within
 * --request-timeout-ms (mechd_request_timeouts_total). */
void srv_metrics_count_timeouts(unsigned long n);

/* Count connections closed to make room for a new one beyond --max-connections
 * (mechd_connections_evicted_total), and connections closed because their
 * client had gone while they waited for a request (mechd_connections_reaped_total). */
void srv_metrics_count_evictions(unsigned long n);
void srv_metrics_count_reaped(unsigned long n);

/* Write a free-form line "mechd: TEXT\n" to stderr (start-up, shutdown). */
void srv_log_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Prometheus text exposition (version 0.0.4) of the counters plus the given
 * gauges (connections_open: connections registered now; connections_max:
 * --max-connections). Returns a malloc'd NUL-terminated string (caller frees)
 * and its length in *len, or NULL when out of memory. */
char *srv_metrics_text(int queue_depth, int workers_busy, int workers, int queue_capacity,
                       double worker_busy_seconds, int connections_open, int connections_max,
                       unsigned long *len_out);

#endif
