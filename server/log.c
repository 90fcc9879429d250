/* log.c — access log on stderr and the counters behind /metrics (see log.h).
 * Counters sit behind one mutex: a request touches it once, when it ends. */
#include "log.h"

#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define STATUS_MIN 100
#define STATUS_MAX 599

static pthread_mutex_t stats_mu = PTHREAD_MUTEX_INITIALIZER;
static unsigned long requests_by_status[STATUS_MAX - STATUS_MIN + 1];
static unsigned long requests_no_response;
static double duration_sum; /* seconds */
static unsigned long duration_count;

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

void srv_log_request(unsigned long id, const char *method, const char *path, int status, long usec)
{
    char m[24], p[512], line[640];
    sanitize(m, sizeof m, method);
    sanitize(p, sizeof p, path);
    int n = snprintf(line, sizeof line, "mechd: req=%lu %s %s %d %ldus\n", id, m, p, status, usec);
    if (n > 0) write_all(line, (size_t)n < sizeof line ? (size_t)n : sizeof line - 1);

    pthread_mutex_lock(&stats_mu);
    if (status >= STATUS_MIN && status <= STATUS_MAX)
        requests_by_status[status - STATUS_MIN]++;
    else
        requests_no_response++;
    duration_sum += (double)usec * 1e-6;
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
                       unsigned long *len_out)
{
    struct text t = {malloc(4096), 0, 4096, 0};
    if (!t.s) return NULL;
    t.s[0] = '\0';

    pthread_mutex_lock(&stats_mu);
    text_add(&t, "# HELP mechd_requests_total Requests finished, by HTTP status "
                 "(status=\"none\": no response was sent).\n"
                 "# TYPE mechd_requests_total counter\n");
    for (int s = STATUS_MIN; s <= STATUS_MAX; s++)
        if (requests_by_status[s - STATUS_MIN])
            text_add(&t, "mechd_requests_total{status=\"%d\"} %lu\n", s,
                     requests_by_status[s - STATUS_MIN]);
    if (requests_no_response)
        text_add(&t, "mechd_requests_total{status=\"none\"} %lu\n", requests_no_response);
    text_add(&t,
             "# HELP mechd_request_duration_seconds Time from request headers to completion.\n"
             "# TYPE mechd_request_duration_seconds summary\n"
             "mechd_request_duration_seconds_sum %.9g\n"
             "mechd_request_duration_seconds_count %lu\n",
             duration_sum, duration_count);
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
             "mechd_workers %d\n",
             queue_depth, queue_capacity, workers_busy, workers);
    if (t.oom) {
        free(t.s);
        return NULL;
    }
    if (len_out) *len_out = t.len;
    return t.s;
}
