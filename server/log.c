/* log.c — access log on stderr and the counters behind /metrics (see log.h).
 * ACCESS LOG: one line per request (RFC 3339 UTC timestamp, request id,
 * method, path, status, duration, bytes, client address), formatted by hand (no stdio, no locale,
 * no FILE lock) and written with a single unbuffered write(2), so lines never
 * interleave and none is lost on any shutdown; perf under wrk puts the whole
 * log line at ~1.4 % of mechd's CPU per small request (it was ~2.4 % with
 * snprintf), so buffering lines across requests (which could delay or lose
 * them) is not worth it. See srv_log_request.
 * Counters sit behind one mutex: a request touches it once, when it ends.
 * Request counts are kept per (route, status) in a fixed table: the server
 * passes a bounded set of route labels (see http.c route_label), and a label
 * that does not fit is counted as route "other", so memory and the metrics
 * page stay bounded whatever clients send.
 * With --log-format json (srv_log_set_json) every line, requests and notes,
 * is one JSON object instead, built the same way. */
#include "log.h"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#ifndef MECHD_VERSION
#define MECHD_VERSION "0.0.0"
#endif
#ifndef MECHD_BUILD_ID
#define MECHD_BUILD_ID "unknown"
#endif

#define STATUS_MIN 100
#define STATUS_MAX 599

#define ROUTE_SLOTS 512 /* (route, status) pairs; the last one is the overflow "other" */
#define ROUTE_LABEL_MAX 64

/* Prometheus' default latency buckets, extended down to 0.5 ms (an inline
 * GET takes tens of µs). Upper bounds in seconds; +Inf is implicit. */
static const double bucket_le[] = {0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05,
                                   0.1,    0.25,  0.5,    1,     2.5,  5,     10};
#define N_BUCKETS (sizeof bucket_le / sizeof bucket_le[0])

#define HIST_SLOTS 256 /* routes with a latency histogram; the last one is the overflow "other" */

/* One route's latency histogram (mechd_route_request_duration_seconds). */
struct route_hist {
    char route[ROUTE_LABEL_MAX];
    unsigned long buckets[N_BUCKETS + 1]; /* last: over the largest bound */
    double sum;
    unsigned long count;
};

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
static unsigned long request_timeouts; /* connections closed by --request-timeout-ms */
static unsigned long conns_evicted;    /* closed to make room (--max-connections) */
static unsigned long conns_reaped;     /* closed because the client had gone */
static unsigned long conns_nudged;     /* shut down again: still open a second after */
static struct route_hist route_hists[HIST_SLOTS];
static int n_route_hists;

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

/* The histogram of route (a label as count_route takes it); stats_mu held. */
static struct route_hist *route_hist(const char *route)
{
    if (!route || !label_ok(route)) route = "other";
    for (int i = 0; i < n_route_hists; i++)
        if (strcmp(route_hists[i].route, route) == 0) return &route_hists[i];
    if (n_route_hists < HIST_SLOTS - 1) {
        struct route_hist *h = &route_hists[n_route_hists++];
        strcpy(h->route, route);
        return h;
    }
    struct route_hist *h = &route_hists[HIST_SLOTS - 1]; /* full: one shared overflow */
    strcpy(h->route, "other");
    return h;
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

/* Append s to the line at *o (stopping at `end`), replacing control
 * characters and spaces so that one request stays one parseable line. */
static char *put_clean(char *o, char *end, const char *s, size_t max)
{
    if (!s) s = "-";
    for (size_t i = 0; *s && i < max && o < end; s++, i++) {
        unsigned char ch = (unsigned char)*s;
        *o++ = (ch < 0x21 || ch == 0x7f) ? '?' : (char)ch;
    }
    return o;
}

static char *put_str(char *o, char *end, const char *s)
{
    while (*s && o < end)
        *o++ = *s++;
    return o;
}

static char *put_ulong(char *o, char *end, unsigned long u)
{
    char d[24];
    int n = 0;
    do {
        d[n++] = (char)('0' + u % 10);
        u /= 10;
    } while (u);
    while (n > 0 && o < end)
        *o++ = d[--n];
    return o;
}

static char *put_long(char *o, char *end, long v)
{
    if (v < 0 && o < end) *o++ = '-';
    return put_ulong(o, end, v < 0 ? 0UL - (unsigned long)v : (unsigned long)v);
}

/* Append s as a JSON string (quotes included, at most max bytes of s), with
 * '"' and '\\' escaped and control characters and non-ASCII bytes replaced by
 * '?' (so the line is valid JSON and ASCII whatever a client sent). */
static char *put_json_str(char *o, char *end, const char *s, size_t max)
{
    if (!s) return put_str(o, end, "null");
    if (o < end) *o++ = '"';
    for (size_t i = 0; *s && i < max && o + 2 < end; s++, i++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') {
            *o++ = '\\';
            *o++ = (char)ch;
        } else {
            *o++ = (ch < 0x20 || ch >= 0x7f) ? '?' : (char)ch;
        }
    }
    if (o < end) *o++ = '"';
    return o;
}

/* 1: log lines are JSON objects (--log-format json); set once before threads start. */
static int log_json;

void srv_log_set_json(int json)
{
    log_json = json != 0;
}

/* The access log. One line per request, built by hand (no stdio: no
 * locale, no FILE lock, no format parsing) and written with one write(2) on
 * stderr, unbuffered: a line is in the kernel when the request is counted, so
 * no line is lost on any shutdown, clean or not, and lines of concurrent
 * requests never interleave (one write of < PIPE_BUF bytes). Measured with
 * perf under wrk: the whole log line costs ~2 % of mechd's CPU per small
 * request (the write itself ~1 %), so buffering across requests would save
 * little and could delay or lose lines. */
/* Two digits, zero-padded (0..99), or more for a larger value. */
static char *put_2(char *o, char *end, unsigned long u)
{
    if (u < 10 && o < end) *o++ = '0';
    return put_ulong(o, end, u);
}

void srv_log_timestamp(char *out)
{
    struct timespec ts;
    struct tm tm;
    clock_gettime(CLOCK_REALTIME, &ts);
    time_t t = ts.tv_sec;
    if (!gmtime_r(&t, &tm)) memset(&tm, 0, sizeof tm);
    char *o = out, *end = out + 31;
    unsigned long ms = (unsigned long)(ts.tv_nsec / 1000000);
    o = put_ulong(o, end, (unsigned long)(tm.tm_year + 1900));
    o = put_str(o, end, "-");
    o = put_2(o, end, (unsigned long)(tm.tm_mon + 1));
    o = put_str(o, end, "-");
    o = put_2(o, end, (unsigned long)tm.tm_mday);
    o = put_str(o, end, "T");
    o = put_2(o, end, (unsigned long)tm.tm_hour);
    o = put_str(o, end, ":");
    o = put_2(o, end, (unsigned long)tm.tm_min);
    o = put_str(o, end, ":");
    o = put_2(o, end, (unsigned long)tm.tm_sec);
    o = put_str(o, end, ".");
    if (ms < 100) o = put_str(o, end, "0");
    o = put_2(o, end, ms);
    o = put_str(o, end, "Z");
    *o = '\0';
}

void srv_log_request(const struct srv_log_entry *e)
{
    char line[2048]; /* the longest JSON line (every field at its bound, escaped) fits,
                        and stays one write below PIPE_BUF */
    char ts[32];
    srv_log_timestamp(ts);
    /* end is a plain char *: GCC 12 -O0 warns when a pointer into the not yet
     * written buffer is passed as const char * (-Wmaybe-uninitialized). */
    char *o = line, *end = line + sizeof line - 1; /* room for the newline */
    if (log_json) {
        o = put_str(o, end, "{\"time\":\"");
        o = put_str(o, end, ts);
        o = put_str(o, end, "\",\"level\":\"info\",\"msg\":\"request\",\"request_id\":");
        o = put_json_str(o, end, e->id, 64);
        o = put_str(o, end, ",\"method\":");
        o = put_json_str(o, end, e->method, 23);
        o = put_str(o, end, ",\"path\":");
        o = put_json_str(o, end, e->path, 511);
        o = put_str(o, end, ",\"status\":");
        o = put_long(o, end, e->status);
        o = put_str(o, end, ",\"duration_us\":");
        o = put_long(o, end, e->usec);
        o = put_str(o, end, ",\"bytes\":");
        o = put_ulong(o, end, (unsigned long)e->bytes);
        o = put_str(o, end, e->cut_off ? ",\"cut_off\":true" : ",\"cut_off\":false");
        o = put_str(o, end, ",\"answer_bytes\":");
        o = put_ulong(o, end, (unsigned long)e->answer_bytes);
        o = put_str(o, end, ",\"client\":");
        o = put_json_str(o, end, e->client, 64);
        o = put_str(o, end, ",\"forwarded_for\":");
        o = put_json_str(o, end, e->forwarded_for, 160);
        o = put_str(o, end, "}");
        goto write_line;
    }
    o = put_str(o, end, "mechd: ");
    o = put_str(o, end, ts);
    o = put_str(o, end, " req=");
    o = put_clean(o, end, e->id, 64);
    o = put_str(o, end, " ");
    o = put_clean(o, end, e->method, 23);
    o = put_str(o, end, " ");
    o = put_clean(o, end, e->path, 511);
    o = put_str(o, end, " ");
    o = put_long(o, end, e->status);
    o = put_str(o, end, " ");
    o = put_long(o, end, e->usec);
    o = put_str(o, end, "us bytes=");
    o = put_ulong(o, end, (unsigned long)e->bytes);
    if (e->cut_off) {
        o = put_str(o, end, " cut_off=true answer_bytes=");
        o = put_ulong(o, end, (unsigned long)e->answer_bytes);
    }
    o = put_str(o, end, " client=");
    o = put_clean(o, end, e->client, 64);
    if (e->forwarded_for) {
        o = put_str(o, end, " xff=");
        o = put_clean(o, end, e->forwarded_for, 160);
    }
write_line:
    *o++ = '\n';
    write_all(line, (size_t)(o - line));

    long usec = e->usec;
    int status = e->status;
    const char *route = e->route;
    double seconds = (double)usec * 1e-6;
    size_t b = 0;
    while (b < N_BUCKETS && seconds > bucket_le[b])
        b++;
    pthread_mutex_lock(&stats_mu);
    count_route(route, status >= STATUS_MIN && status <= STATUS_MAX ? status : 0);
    duration_buckets[b]++;
    duration_sum += seconds;
    duration_count++;
    struct route_hist *rh = route_hist(route);
    rh->buckets[b]++;
    rh->sum += seconds;
    rh->count++;
    pthread_mutex_unlock(&stats_mu);
}

void srv_metrics_count_timeouts(unsigned long n)
{
    pthread_mutex_lock(&stats_mu);
    request_timeouts += n;
    pthread_mutex_unlock(&stats_mu);
}

void srv_metrics_count_evictions(unsigned long n)
{
    pthread_mutex_lock(&stats_mu);
    conns_evicted += n;
    pthread_mutex_unlock(&stats_mu);
}

void srv_metrics_count_reaped(unsigned long n)
{
    pthread_mutex_lock(&stats_mu);
    conns_reaped += n;
    pthread_mutex_unlock(&stats_mu);
}

void srv_metrics_count_shut_nudges(unsigned long n)
{
    pthread_mutex_lock(&stats_mu);
    conns_nudged += n;
    pthread_mutex_unlock(&stats_mu);
}

void srv_log_note(const char *fmt, ...)
{
    char line[512];
    char ts[32];
    srv_log_timestamp(ts);
    va_list ap;
    if (log_json) { /* {"time": ..., "level": "info", "msg": the note} */
        char msg[400];
        va_start(ap, fmt);
        int k = vsnprintf(msg, sizeof msg, fmt, ap);
        va_end(ap);
        if (k < 0) return;
        char jl[1024]; /* msg escaped at most doubles */
        char *o = jl, *end = jl + sizeof jl - 1;
        o = put_str(o, end, "{\"time\":\"");
        o = put_str(o, end, ts);
        o = put_str(o, end, "\",\"level\":\"info\",\"msg\":");
        o = put_json_str(o, end, msg, sizeof msg);
        o = put_str(o, end, "}");
        *o++ = '\n';
        write_all(jl, (size_t)(o - jl));
        return;
    }
    int n = snprintf(line, sizeof line, "mechd: %s ", ts);
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

/* Prometheus' standard process metrics, from /proc (Linux; nothing elsewhere
 * or when /proc cannot be read): CPU seconds, resident and virtual memory,
 * open and allowed descriptors, start time. */
static void process_metrics(struct text *t)
{
    long tick = sysconf(_SC_CLK_TCK), page = sysconf(_SC_PAGESIZE);
    char buf[1024];
    int fd = open("/proc/self/stat", O_RDONLY | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, buf, sizeof buf - 1) : -1;
    if (fd >= 0) close(fd);
    const char *p = n > 0 ? (buf[n] = '\0', strrchr(buf, ')')) : NULL;
    unsigned long long utime = 0, stime = 0, start = 0, vsize = 0;
    long long rss = 0;
    /* After "pid (comm)": field 3 state ... 14 utime, 15 stime, 22 starttime, 23 vsize, 24 rss. */
    int ok = p && tick > 0 &&
             sscanf(p + 1,
                    " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu %*d %*d %*d %*d %*d "
                    "%*d %llu %llu %lld",
                    &utime, &stime, &start, &vsize, &rss) == 5;
    if (ok) {
        double btime = 0;
        fd = open("/proc/stat", O_RDONLY | O_CLOEXEC);
        char sb[8192];
        ssize_t k = fd >= 0 ? read(fd, sb, sizeof sb - 1) : -1;
        if (fd >= 0) close(fd);
        if (k > 0) {
            sb[k] = '\0';
            const char *bt = strstr(sb, "\nbtime ");
            if (bt) btime = strtod(bt + 7, NULL);
        }
        text_add(t,
                 "# HELP process_cpu_seconds_total Total user and system CPU time spent in "
                 "seconds.\n"
                 "# TYPE process_cpu_seconds_total counter\n"
                 "process_cpu_seconds_total %.9g\n"
                 "# HELP process_resident_memory_bytes Resident memory size in bytes.\n"
                 "# TYPE process_resident_memory_bytes gauge\n"
                 "process_resident_memory_bytes %lld\n"
                 "# HELP process_virtual_memory_bytes Virtual memory size in bytes.\n"
                 "# TYPE process_virtual_memory_bytes gauge\n"
                 "process_virtual_memory_bytes %llu\n",
                 (double)(utime + stime) / (double)tick, rss * (long long)page, vsize);
        if (btime > 0)
            text_add(t,
                     "# HELP process_start_time_seconds Start time of the process since unix "
                     "epoch in seconds.\n"
                     "# TYPE process_start_time_seconds gauge\n"
                     "process_start_time_seconds %.2f\n",
                     btime + (double)start / (double)tick);
    }
    DIR *d = opendir("/proc/self/fd");
    if (d) {
        long open_fds = -1; /* the directory's own descriptor is not counted */
        while (readdir(d))
            open_fds++;
        closedir(d);
        open_fds -= 2; /* "." and ".." */
        struct rlimit rl;
        text_add(t,
                 "# HELP process_open_fds Number of open file descriptors.\n"
                 "# TYPE process_open_fds gauge\n"
                 "process_open_fds %ld\n",
                 open_fds < 0 ? 0 : open_fds);
        if (getrlimit(RLIMIT_NOFILE, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
            text_add(t,
                     "# HELP process_max_fds Maximum number of open file descriptors.\n"
                     "# TYPE process_max_fds gauge\n"
                     "process_max_fds %llu\n",
                     (unsigned long long)rl.rlim_cur);
    }
}

char *srv_metrics_text(const struct srv_metrics_gauges *g, unsigned long *len_out)
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
    text_add(&t, "# HELP mechd_route_request_duration_seconds Time from request headers to "
                 "completion, by route (labelled as mechd_requests_total).\n"
                 "# TYPE mechd_route_request_duration_seconds histogram\n");
    for (int i = 0; i < HIST_SLOTS; i++) {
        const struct route_hist *rh = &route_hists[i];
        if (rh->count == 0) continue;
        unsigned long c = 0;
        for (size_t b = 0; b < N_BUCKETS; b++) {
            c += rh->buckets[b];
            text_add(&t, "mechd_route_request_duration_seconds_bucket{route=\"%s\",le=\"%g\"} %lu\n",
                     rh->route, bucket_le[b], c);
        }
        c += rh->buckets[N_BUCKETS];
        text_add(&t,
                 "mechd_route_request_duration_seconds_bucket{route=\"%s\",le=\"+Inf\"} %lu\n"
                 "mechd_route_request_duration_seconds_sum{route=\"%s\"} %.9g\n"
                 "mechd_route_request_duration_seconds_count{route=\"%s\"} %lu\n",
                 rh->route, c, rh->route, rh->sum, rh->route, rh->count);
    }
    text_add(&t,
             "# HELP mechd_request_timeouts_total Connections closed because they did not send a "
             "whole request within --request-timeout-ms.\n"
             "# TYPE mechd_request_timeouts_total counter\n"
             "mechd_request_timeouts_total %lu\n",
             request_timeouts);
    text_add(&t,
             "# HELP mechd_connections_evicted_total Connections closed to make room for a new "
             "one beyond --max-connections (the one that had waited longest for a request).\n"
             "# TYPE mechd_connections_evicted_total counter\n"
             "mechd_connections_evicted_total %lu\n"
             "# HELP mechd_connections_reaped_total Connections closed because the client had "
             "gone while they waited for a request.\n"
             "# TYPE mechd_connections_reaped_total counter\n"
             "mechd_connections_reaped_total %lu\n"
             "# HELP mechd_connections_nudged_total Shut connections shut down again because "
             "they were still open a second after the first shutdown.\n"
             "# TYPE mechd_connections_nudged_total counter\n"
             "mechd_connections_nudged_total %lu\n",
             conns_evicted, conns_reaped, conns_nudged);
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
             "mechd_worker_busy_seconds_total %.9g\n"
             "# HELP mechd_connections_open Client connections open now.\n"
             "# TYPE mechd_connections_open gauge\n"
             "mechd_connections_open %d\n"
             "# HELP mechd_connections_max Connections held open before the longest-waiting "
             "idle one is closed (--max-connections).\n"
             "# TYPE mechd_connections_max gauge\n"
             "mechd_connections_max %d\n",
             g->queue_depth, g->queue_capacity, g->workers_busy, g->workers,
             g->worker_busy_seconds, g->connections_open, g->connections_max);
    text_add(&t,
             "# HELP mechd_answer_memory_bytes Bytes of answers held now, computed or being "
             "computed, for clients still reading them.\n"
             "# TYPE mechd_answer_memory_bytes gauge\n"
             "mechd_answer_memory_bytes %zu\n"
             "# HELP mechd_answer_memory_max_bytes The answer-memory budget "
             "(--max-answer-memory).\n"
             "# TYPE mechd_answer_memory_max_bytes gauge\n"
             "mechd_answer_memory_max_bytes %zu\n"
             "# HELP mechd_answer_memory_peak_bytes The most answer memory held at once since "
             "start.\n"
             "# TYPE mechd_answer_memory_peak_bytes gauge\n"
             "mechd_answer_memory_peak_bytes %zu\n"
             "# HELP mechd_answer_memory_refused_total Requests answered 503 because their "
             "predicted answer did not fit in the answer-memory budget.\n"
             "# TYPE mechd_answer_memory_refused_total counter\n"
             "mechd_answer_memory_refused_total %lu\n",
             g->answer_memory, g->answer_memory_max, g->answer_memory_peak,
             g->answer_memory_refused);
    process_metrics(&t);
    text_add(&t,
             "# HELP mechd_build_info The running build: version and the git commit it was "
             "built from.\n"
             "# TYPE mechd_build_info gauge\n"
             "mechd_build_info{version=\"%s\",commit=\"%s\"} 1\n",
             MECHD_VERSION, MECHD_BUILD_ID);
    if (t.oom) {
        free(t.s);
        return NULL;
    }
    if (len_out) *len_out = t.len;
    return t.s;
}
