/* quick.c — whether a quick operation is answered on the I/O thread or by a
 * worker, from its measured CPU cost (part of the HTTP front end, see http.c).
 *
 * QUICK OPERATIONS. A POST that api_quick_route() accepts (a closed-form
 * operation, whatever the size of its body up to --max-body) is answered on the
 * I/O thread, with the same deadline, step budget and cancel flag as a pooled
 * request: the suspend -> worker -> resume hand-off (two context switches, a
 * futex wake-up and an eventfd write) costs more than such an operation. It is
 * logged and counted in /metrics like any other request. The choice is
 * measured, not assumed: runs of a quick route, inline or on a
 * worker, update a moving average of the route's *thread CPU time*
 * (CLOCK_THREAD_CPUTIME_ID) per byte of request (plus SRV_QUICK_BASE_BYTES for
 * the fixed costs), and a request runs inline only while its predicted time is
 * at most --inline-max-us, so a route that turns out slow (or a body large
 * enough to be slow: the decision is the predicted cost, never the size)
 * goes to the pool, as a short job (workers.h, FAIR QUEUES), and never holds
 * an I/O thread, and /healthz, for long. CPU
 * time, not wall time: a thread preempted for a millisecond during a 5 µs
 * boost (common when the clients run on the same cores) would otherwise look
 * 200 times slower, and one such run sent every later boost to
 * the niced workers, whose small queue then refused cheap requests with 503
 * (a cheap request must never be refused for load). Reading that clock is a system call (3.5-5 µs on the 2-core VM,
 * about a boost), so one run in SRV_QUICK_SAMPLE is measured, the first run of
 * a route always; one measurement moves the average by at most a factor of
 * 1 + (SRV_QUICK_CAP - 1) / 8. The decision recovers: the average decays with
 * every measured run, and a route predicted too slow still runs inline (and
 * is measured) once in SRV_QUICK_REPROBE requests, so a full pool that
 * refuses it cannot freeze a stale estimate. The first request of a route runs
 * inline.
 *
 * GATED OPERATIONS. An operation whose cost is not linear in its body (an
 * integration) but predicted by its chooser before it integrates
 * (api_gated_route: /v1/trajectory) is started on the I/O thread under a cost
 * gate (api_request_ext.gate), whatever its body's size up to
 * SRV_GATE_BODY_MAX: parsed, validated, its answer memory admitted and its
 * method chosen there. The gate then decides from the prediction: the
 * chooser's predicted CPU plus SRV_GATE_SAMPLE_NS per sample asked for, times
 * the route's measured ratio of thread CPU to that prediction (a moving
 * average like the quick routes' cost, from 1 until measured, kept within
 * 1/4 .. 4). Predicted within --inline-max-us, it is computed and answered on
 * the I/O thread; else it stops before computing anything and goes to the
 * pool (a short job when predicted within SRV_SHORT_JOB_US: the express
 * worker may take it), which runs it again from its body. A run with no
 * prediction (a method and step given by the client, the first pass of
 * "fictitious": "auto") or whose answer memory must wait goes to the pool as
 * a long job. The first parse is the price of deciding from the cost: a few
 * microseconds per kilobyte, against a hand-off that a cheap integration no
 * longer pays.
 */
#ifdef __linux__
#define _GNU_SOURCE /* POLLRDHUP */
#endif
#include "http_internal.h"

#include <arpa/inet.h>
#include <errno.h>
#include <malloc.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/resource.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "api.h"
#include "log.h"
#include "static.h"
#include "mech/base/budget.h"

/* ---- quick operations: measured cost -------------------------------------------- */

static unsigned long long quick_units(size_t body_len)
{
    return (unsigned long long)body_len + SRV_QUICK_BASE_BYTES;
}

/* CPU time this thread has used, in ns; -1 if the clock cannot be read. */
static long long thread_cpu_ns(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return -1;
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Fold one measured run (cpu_ns of thread CPU time for a body of body_len
 * bytes) into the route's moving average: weight 1/8, the measurement capped
 * at SRV_QUICK_CAP times the average, so one outlier (a page fault, a cold
 * cache) cannot send a route to the pool on its own. */
static void quick_record(struct srv_quick_stat *q, long long cpu_ns, size_t body_len)
{
    long long per_kib = (long long)((double)cpu_ns * 1024.0 / (double)quick_units(body_len)) + 1;
    long long old = atomic_load_explicit(&q->cost, memory_order_relaxed);
    if (old > 0 && per_kib > SRV_QUICK_CAP * old) per_kib = SRV_QUICK_CAP * old;
    atomic_store_explicit(&q->cost, old ? old + (per_kib - old) / 8 : per_kib,
                          memory_order_relaxed);
}

/* The gated request r's predicted thread CPU in ns before the route's ratio:
 * the chooser's prediction + SRV_GATE_SAMPLE_NS per sample. */
static double gate_base_ns(const struct srv_req *r)
{
    return r->predicted_cpu_s * 1e9 + r->samples * SRV_GATE_SAMPLE_NS;
}

static double gate_estimate_ns(const struct srv_http *h, const struct srv_req *r)
{
    long long ratio = h->quick ? atomic_load_explicit(&h->quick[r->route_index].ratio,
                                                      memory_order_relaxed)
                               : 0;
    if (ratio <= 0) ratio = SRV_GATE_RATIO_ONE;
    return gate_base_ns(r) * (double)ratio / SRV_GATE_RATIO_ONE;
}

/* Fold one measured full run of a gated request (cpu_ns of thread CPU) into
 * its route's ratio: weight 1/8, within SRV_GATE_RATIO_MIN .. _MAX. */
static void gate_record_run(struct srv_quick_stat *q, long long cpu_ns, const struct srv_req *r)
{
    double base = gate_base_ns(r);
    if (!(base > 0)) return;
    double m = (double)cpu_ns * SRV_GATE_RATIO_ONE / base;
    long long measured = m < SRV_GATE_RATIO_MIN   ? SRV_GATE_RATIO_MIN
                         : m > SRV_GATE_RATIO_MAX ? SRV_GATE_RATIO_MAX
                                                  : (long long)m;
    long long old = atomic_load_explicit(&q->ratio, memory_order_relaxed);
    atomic_store_explicit(&q->ratio, old ? old + (measured - old) / 8 : measured,
                          memory_order_relaxed);
}

/* The gate of a request started on the I/O thread: go on (0) when predicted
 * within --inline-max-us, else stop (1): it goes to the pool. */
static int gate_inline(void *ctx, double predicted_cpu_s)
{
    struct srv_req *r = ctx;
    r->predicted_cpu_s = predicted_cpu_s >= 0 ? predicted_cpu_s : -1.0;
    if (r->predicted_cpu_s < 0) return 1;
    r->gate_est_ns = gate_estimate_ns(r->http, r);
    if (r->mem_deferred) return 1;
    return r->gate_est_ns > (double)r->http->cfg->inline_max_us * 1000.0;
}

/* The gate of a run on a worker: records the prediction, never stops. */
static int gate_record(void *ctx, double predicted_cpu_s)
{
    struct srv_req *r = ctx;
    r->predicted_cpu_s = predicted_cpu_s >= 0 ? predicted_cpu_s : -1.0;
    return 0;
}

int gate_try_inline(struct srv_http *h, struct srv_req *r)
{
    r->aext.gate_ctx = r;
    r->aext.gate = gate_record;
    if (!h->quick || h->cfg->inline_max_us <= 0 || r->body_len > SRV_GATE_BODY_MAX) return 0;
    r->aext.gate = gate_inline;
    r->gate_attempt = 1;
    run_api(r);
    r->gate_attempt = 0;
    if (!r->aresp.deferred) return 1;
    api_response_free(&r->aresp);
    r->aext.gate = gate_record;
    r->mem_deferred = 0;
    r->job.short_job = r->predicted_cpu_s > 0 && r->gate_est_ns > 0 &&
                       r->gate_est_ns <= SRV_SHORT_JOB_US * 1000.0;
    r->predicted_cpu_s = 0;
    return 0;
}

/* Run the API on r; for a quick or gated route, measure the run's thread CPU
 * time on one run in SRV_QUICK_SAMPLE (and on every probe) for the route's
 * average (a gated run stopped at its gate is not measured). */
void run_api(struct srv_req *r)
{
    struct srv_quick_stat *q = (r->quick_route || r->gated) && r->http->quick && r->route_index >= 0
                                   ? &r->http->quick[r->route_index]
                                   : NULL;
    /* A gated route's runs are all measured until its ratio is known (its
     * first runs may all be pooled, after attempts stopped at the gate). */
    int measure =
        q && (r->quick_probe ||
              (r->gated && !r->gate_attempt &&
               atomic_load_explicit(&q->ratio, memory_order_relaxed) == 0) ||
              atomic_fetch_add_explicit(&q->runs, 1, memory_order_relaxed) % SRV_QUICK_SAMPLE == 0);
    long long c0 = measure ? thread_cpu_ns() : -1;
    api_handle_ext(&r->areq, &r->aext, &r->aresp);
    answer_settle(r); /* charge the answer's real size (answer_budget.c) */
    if (c0 < 0) return;
    long long c1 = thread_cpu_ns();
    if (c1 < c0) return;
    if (r->quick_route)
        quick_record(q, c1 - c0, r->body_len);
    else if (!r->aresp.deferred && r->aresp.status == 200 && r->predicted_cpu_s > 0)
        gate_record_run(q, c1 - c0, r);
}

/* Whether the quick request r runs inline: predicted to finish within
 * --inline-max-us, or (once in SRV_QUICK_REPROBE requests predicted over it)
 * a probe that re-measures the route, so the estimate can come back down. */
int quick_inline(struct srv_http *h, struct srv_req *r)
{
    if (!r->quick_route || !h->quick || h->cfg->inline_max_us <= 0) return 0;
    struct srv_quick_stat *q = &h->quick[r->route_index];
    long long per_kib = atomic_load_explicit(&q->cost, memory_order_relaxed);
    double predicted_ns = (double)per_kib * (double)quick_units(r->body_len) / 1024.0;
    if (predicted_ns <= (double)h->cfg->inline_max_us * 1000.0) return 1;
    unsigned n = atomic_fetch_add_explicit(&q->too_slow, 1, memory_order_relaxed);
    if (n % SRV_QUICK_REPROBE != SRV_QUICK_REPROBE - 1) return 0;
    r->quick_probe = 1;
    return 1;
}

int quick_fits_when_full(const struct srv_http *h, const struct srv_req *r)
{
    if (!r->quick_route || !h->quick || h->cfg->inline_max_us <= 0) return 0;
    const struct srv_quick_stat *q = &h->quick[r->route_index];
    long long per_kib = atomic_load_explicit(&q->cost, memory_order_relaxed);
    double predicted_ns = (double)per_kib * (double)quick_units(r->body_len) / 1024.0;
    return predicted_ns <= (double)h->cfg->inline_max_us * 1000.0 * SRV_QUICK_FULL_FACTOR;
}
