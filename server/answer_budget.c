/* answer_budget.c — predicting an answer's size and charging it to the
 * answer-memory budget (part of the HTTP front end, see http.c;
 * answer_mem.c keeps the count).
 *
 * ANSWER MEMORY. An answer stays in memory until its last byte is sent, so a
 * slow reader holds it for as long as it likes; --max-answer-memory bounds
 * the bytes all answers hold at once. Each request to an operation is
 * admitted before anything is computed (the API layer calls answer_admit
 * after validation and the samples budget): its answer is predicted from the
 * request, in units of SRV_ANSWER_SAMPLE_UNITS per sample asked for (summed
 * as the samples budget sums them) plus one per body byte plus
 * SRV_ANSWER_BASE_UNITS, times the route's measured bytes per unit. The
 * estimate starts at SRV_ANSWER_RATIO_INIT, rises at once to any answer that
 * was larger and decays by 1/16 of the gap per smaller one, so it errs high.
 * A prediction that does not fit what is left waits up to SRV_MEM_WAIT_MS for
 * answers to be sent (on a worker; never past the request's deadline, and
 * not at all on an I/O thread), else the request is answered 503
 * answer-memory-full with Retry-After. Once computed, the prediction is
 * replaced by the answer's real size when it is at least SRV_TRACK_MIN bytes
 * (smaller answers are sent in one write and are not counted), and given
 * back when libmicrohttpd frees the answer: after its last byte, or when the
 * connection closes. /healthz, /metrics, the catalog and static files are not
 * counted: they are static memory or small. */
#include "http_internal.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "answer_mem.h"
#include "mech/base/budget.h"

#define SRV_ANSWER_SAMPLE_UNITS 128.0 /* units per sample asked for */
#define SRV_ANSWER_BASE_UNITS 1024.0  /* units of every answer */
#define SRV_ANSWER_RATIO_ONE 1024     /* fixed point of the bytes-per-unit ratio */
#define SRV_ANSWER_RATIO_INIT (2 * SRV_ANSWER_RATIO_ONE) /* before a route's first answer */

atomic_llong *answer_ratios_new(size_t n_routes)
{
    atomic_llong *a = calloc(n_routes ? n_routes : 1, sizeof *a);
    for (size_t i = 0; a && i < n_routes; i++)
        atomic_init(&a[i], SRV_ANSWER_RATIO_INIT);
    return a;
}

int answer_admit(void *ctx, long route, double samples)
{
    struct srv_req *r = ctx;
    struct srv_http *h = r->http;
    if (!h->mem) return 0;
    long long ratio = SRV_ANSWER_RATIO_INIT;
    if (h->answer_ratio && route >= 0 && (size_t)route < api_operation_count())
        ratio = atomic_load_explicit(&h->answer_ratio[route], memory_order_relaxed);
    double units = samples * SRV_ANSWER_SAMPLE_UNITS + (double)r->body_len + SRV_ANSWER_BASE_UNITS;
    double predicted = units * (double)ratio / SRV_ANSWER_RATIO_ONE;
    if (!(predicted >= 0) || predicted > 1e18) predicted = 1e18;
    long wait_ms = r->gate_attempt ? -1 : 0; /* a gated attempt's refusal is no refusal */
    if (!srv_io_current()) { /* a worker may wait; an I/O thread must not */
        double left_ms = (r->areq.deadline - mech_clock_seconds()) * 1000.0;
        wait_ms = left_ms < SRV_MEM_WAIT_MS ? (long)left_ms : SRV_MEM_WAIT_MS;
    }
    r->samples = samples;
    size_t got = srv_mem_reserve(h->mem, (size_t)predicted, wait_ms, &r->cancel);
    if (got == 0 && predicted >= 1.0) {
        /* Started on the I/O thread under the cost gate: not refused here,
         * but sent to a worker, which may wait for memory. */
        if (r->gate_attempt) {
            r->mem_deferred = 1;
            return 0;
        }
        return 1;
    }
    r->charged = got;
    r->mem_units = units;
    if (r->route_index < 0) r->route_index = route; /* learn under this route; metrics label */
    return 0;
}

void answer_settle(struct srv_req *r)
{
    struct srv_http *h = r->http;
    const struct api_response *a = &r->aresp;
    size_t held = a->body && !a->body_static && a->body_len >= SRV_TRACK_MIN ? a->body_len : 0;
    if (!h->mem) return;
    if (held != r->charged) srv_mem_adjust(h->mem, r->charged, held);
    r->charged = held;
    long ri = r->route_index;
    if (r->mem_units > 0 && a->status == 200 && h->answer_ratio && ri >= 0 &&
        (size_t)ri < api_operation_count()) {
        atomic_llong *q = &h->answer_ratio[ri];
        double m = (double)a->body_len * SRV_ANSWER_RATIO_ONE / r->mem_units;
        long long measured = m > 1e15 ? (long long)1e15 : (long long)ceil(m);
        long long old = atomic_load_explicit(q, memory_order_relaxed);
        long long next = measured >= old ? measured : old - (old - measured) / 16;
        if (next < 1) next = 1;
        atomic_store_explicit(q, next, memory_order_relaxed);
    }
    r->mem_units = 0;
}
