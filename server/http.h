/* http.h — mechd's HTTP front: libmicrohttpd (epoll; cfg->io_threads
 * daemons, each run by an I/O thread of our own, io_loop.c) that reads requests, refuses
 * ambiguous body framing, enforces the body limit, the total receive time
 * (cfg->request_timeout_ms) and the connection limit (cfg->max_connections:
 * the longest-waiting idle connection makes room; connections whose client
 * has gone are reaped), answers the server-owned routes (/healthz, /metrics,
 * /), cheap GETs, quick POSTs (api_quick_route) and gated POSTs predicted
 * cheap (api_gated_route) inline, and hands
 * everything else to the worker pool with suspend/resume; a queued job whose
 * client hangs up leaves the queue at once.
 *
 * Shutdown order (main.c): srv_http_stop_accepting, srv_http_drain (the grace
 * period: running and queued requests may finish), srv_http_quiesce (cancel
 * the rest), srv_pool_stop, srv_http_drain, srv_http_stop, srv_pool_free.
 * Not thread-safe: call from main only.
 */
#ifndef SERVER_HTTP_H
#define SERVER_HTTP_H

#include "config.h"
#include "workers.h"

struct srv_http;

/* Start listening on cfg->bind:cfg->port and print exactly one line
 * "mechd listening on http://ADDR:PORT" to stdout (then fflush). cfg and pool
 * are borrowed and must outlive the server. Returns NULL (after logging why on
 * stderr) if the daemon cannot start. */
struct srv_http *srv_http_start(const struct srv_config *cfg, struct srv_pool *pool);

/* Stop accepting connections (the listening socket is closed to new ones);
 * requests in flight go on, and every answer from now on carries
 * "Connection: close" so keep-alive clients move to another replica. */
void srv_http_stop_accepting(struct srv_http *h);

/* Stop accepting connections (srv_http_stop_accepting) and raise the cancel flag of every request
 * handed to the pool (and of any handed later), so running computations stop
 * at their next budget check. */
void srv_http_quiesce(struct srv_http *h);

/* Wait until no request is in flight (every answer sent) or `seconds` pass;
 * returns how many requests are still in flight (0 for a NULL h). */
int srv_http_drain(struct srv_http *h, double seconds);

/* Stop the hang-up watcher thread and the daemon (closing remaining
 * connections) and free h. All suspended connections must have been resumed
 * (srv_pool_stop does that). h may be NULL. */
void srv_http_stop(struct srv_http *h);

#endif
