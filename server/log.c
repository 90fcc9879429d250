/* log.c — access log on stderr and the counters behind /metrics (see log.h).
 * Counters sit behind one mutex: a request touches it once, when it ends.
 * Request counts are kept per (route, status) in a fixed table: the server
 * passes a bounded set of route labels (see http.c route_label), and a label
 * that does not fit is counted as route "other", so memory and the metrics
 * page stay bounded whatever clients send. */
#include "log.h"

#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define STATUS_MIN 100
#define STATUS_MAX 599

#define ROUTE_SLOTS 512 /* (route, status) pairs; the last one is the overflow "other" */
#define ROUTE_LABEL_MAX 64

/* Prometheus' default latency buckets, extended down to 0.5 ms (an inline
 * GET takes tens of µs). Upper bounds in seconds; +Inf is implicit. */
static const double bucket_le[] = {0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05,
                                   0.1,    0.25,  0.5,    1,     2.5,  5,     10};
#define N_BUCKETS (sizeof bucket_le / sizeof bucket_le[0])

struct route_count {
    char route[ROUTE_LABEL_MAX];
    int status; /* 0: no response was sent */
    unsigned long n;
};

static pthread_mutex_t stats_mu = PTHREAD_MUTEX_INITIALIZER;
static struct route_count route_counts[ROUTE_SLOTS];
static int n_route_counts;
static unsigned long duration_buckets[N_BUCKETS + 1]; /* last: over the largest bound */
static double duration_sum;                           /* seconds */
static unsigned long duration_count;

/* A label value is safe in the exposition format without escaping when it has
 * only these characters (no quote, backslash or newline). */
static int label_ok(const char *s)
{
    size_t n = 0;
    for (; s[n]; n++) {
        char c = s[n];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '/' || c == '.' || c == '_' || c == '-'))
            return 0;
    }
    return n > 0 && n < ROUTE_LABEL_MAX;
}

/* Count one request; stats_mu held. */
static void count_route(const char *route, int status)
{
    if (!route || !label_ok(route)) route = "other";
    for (int i = 0; i < n_route_counts; i++)
        if (route_counts[i].status == status && strcmp(route_counts[i].route, route) == 0) {
            route_counts[i].n++;
            return;
        }
    struct route_count *c;
    if (n_route_counts < ROUTE_SLOTS - 1) {
        c = &route_counts[n_route_counts++];
    } else { /* full: one shared overflow slot */
        c = &route_counts[ROUTE_SLOTS - 1];
        if (c->n == 0) {
            strcpy(c->route, "other");
            c->status = -1;
        }
    }
    if (c->n == 0 && c->status != -1) {
        strcpy(c->route, route);
        c->status = status;
    }
    c->n++;
}

static void write_all(const char *s, size_t n)
{
    while (n > 0) {
        ssize_t w = write(STDERR_FILENO, s, n);
        if (w <= 0) return; /* nothing sensible to do about a broken stderr */
        s += w;
        n -= (size_t)w;
    }
}

/* Copy at most cap-1 chars of s into out, replacing control characters and
 * spaces so that one request stays one parseable line. */
static void sanitize(char *out, size_t cap, const char *s)
{
    size_t i = 0;
    if (!s) s = "-";
    for (; *s && i + 1 < cap; s++) {
        unsigned char ch = (unsigned char)*s;
        out[i++] = (ch < 0x21 || ch == 0x7f) ? '?' : (char)ch;
    }
    out[i] = '\0';
}

void srv_log_request(unsigned long id, const char *method, const char *path, const char *route,
                     int status, long usec)
{
    char m[24], p[512], line[640];
    sanitize(m, sizeof m, method);
    sanitize(p, sizeof p, path);
    int n = snprintf(line, sizeof line, "mechd: req=%lu %s %s %d %ldus\n", id, m, p, status, usec);
    if (n > 0) write_all(line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1);

    double seconds = (double)usec * 1e-6;
    size_t b = 0;
    while (b < N_BUCKETS && seconds > bucket_le[b])
        b++;
    pthread_mutex_lock(&stats_mu);
    count_route(route, status >= STATUS_MIN && status <= STATUS_MAX ? status : 0);
    duration_buckets[b]++;
    duration_sum += seconds;
    duration_count++;
    pthread_mutex_unlock(&stats_mu);
}

void srv_log_note(const char *fmt, ...)
{
    char line[512];
    int n = snprintf(line, sizeof line, "mechd: ");
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(line + n, sizeof line - (size_t)n - 1, fmt, ap);
    va_end(ap);
    if (k < 0) return;
    size_t len = strlen(line);
    line[len++] = '\n';
    write_all(line, len);
}

/* Growable text buffer for the metrics page (bounded: ~500 status lines). */
struct text {
    char *s;
    size_t len, cap;
    int oom;
};

static void text_add(struct text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void text_add(struct text *t, const char *fmt, ...)
{
    if (t->oom) return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(t->s + t->len, t->cap - t->len, fmt, ap);
        va_end(ap);
        if (n < 0) {
            t->oom = 1;
            return;
        }
        if ((size_t)n < t->cap - t->len) {
            t->len += (size_t)n;
            return;
        }
        size_t cap = 2 * t->cap + (size_t)n + 1;
        char *s = realloc(t->s, cap);
        if (!s) {
            t->oom = 1;
            return;
        }
        t->s = s;
        t->cap = cap;
    }
}

char *srv_metrics_text(int queue_depth, int workers_busy, int workers, int queue_capacity,
                       double worker_busy_seconds, unsigned long *len_out)
{
    struct text t = {malloc(4096), 0, 4096, 0};
    if (!t.s) return NULL;
    t.s[0] = '\0';

    pthread_mutex_lock(&stats_mu);
    text_add(&t, "# HELP mechd_requests_total Requests finished, by route (the API path, "
                 "\"static\" for front-end files, \"other\" for anything unknown) and HTTP "
                 "status (\"none\": no response was sent).\n"
                 "# TYPE mechd_requests_total counter\n");
    for (int i = 0; i < ROUTE_SLOTS; i++) {
        const struct route_count *c = &route_counts[i];
        if (c->n == 0) continue;
        if (c->status > 0)
            text_add(&t, "mechd_requests_total{route=\"%s\",status=\"%d\"} %lu\n", c->route,
                     c->status, c->n);
        else
            text_add(&t, "mechd_requests_total{route=\"%s\",status=\"%s\"} %lu\n", c->route,
                     c->status == 0 ? "none" : "other", c->n);
    }
    text_add(&t, "# HELP mechd_request_duration_seconds Time from request headers to completion.\n"
                 "# TYPE mechd_request_duration_seconds histogram\n");
    unsigned long cum = 0;
    for (size_t b = 0; b < N_BUCKETS; b++) {
        cum += duration_buckets[b];
        text_add(&t, "mechd_request_duration_seconds_bucket{le=\"%g\"} %lu\n", bucket_le[b], cum);
    }
    cum += duration_buckets[N_BUCKETS];
    text_add(&t,
             "mechd_request_duration_seconds_bucket{le=\"+Inf\"} %lu\n"
             "mechd_request_duration_seconds_sum %.9g\n"
             "mechd_request_duration_seconds_count %lu\n",
             cum, duration_sum, duration_count);
    pthread_mutex_unlock(&stats_mu);

    text_add(&t,
             "# HELP mechd_queue_depth Jobs waiting for a compute worker.\n"
             "# TYPE mechd_queue_depth gauge\n"
             "mechd_queue_depth %d\n"
             "# HELP mechd_queue_capacity Largest number of waiting jobs (--queue).\n"
             "# TYPE mechd_queue_capacity gauge\n"
             "mechd_queue_capacity %d\n"
             "# HELP mechd_workers_busy Compute workers running a job.\n"
             "# TYPE mechd_workers_busy gauge\n"
             "mechd_workers_busy %d\n"
             "# HELP mechd_workers Compute workers (--workers).\n"
             "# TYPE mechd_workers gauge\n"
             "mechd_workers %d\n"
             "# HELP mechd_worker_busy_seconds_total Time compute workers spent running jobs "
             "(summed over workers; counted when a job ends).\n"
             "# TYPE mechd_worker_busy_seconds_total counter\n"
             "mechd_worker_busy_seconds_total %.9g\n",
             queue_depth, queue_capacity, workers_busy, workers, worker_busy_seconds);
    if (t.oom) {
        free(t.s);
        return NULL;
    }
    if (len_out) *len_out = t.len;
    return t.s;
}
