/* answer_mem.c — the answer-memory budget (see answer_mem.h): a byte count
 * under one mutex, and a condition variable on which a worker waits briefly
 * for answers to be sent before its request is refused. */
#include "answer_mem.h"

#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#define MEM_DEFAULT_MAX ((size_t)512 << 20) /* 512 MiB */
#define MEM_DEFAULT_MIN ((size_t)16 << 20)  /* never below 16 MiB by default */
#define MEM_WAIT_SLICE_MS 20                /* a waiter re-reads its cancel flag this often */

struct srv_mem {
    pthread_mutex_t mu;
    pthread_cond_t cv; /* CLOCK_MONOTONIC; signalled when bytes are released */
    size_t cap, used, peak;
    unsigned long refused;
};

struct srv_mem *srv_mem_create(size_t cap)
{
    if (cap == 0) return NULL;
    struct srv_mem *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    pthread_condattr_t ca;
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    pthread_mutex_init(&m->mu, NULL);
    pthread_cond_init(&m->cv, &ca);
    pthread_condattr_destroy(&ca);
    m->cap = cap;
    return m;
}

void srv_mem_free(struct srv_mem *m)
{
    if (!m) return;
    pthread_cond_destroy(&m->cv);
    pthread_mutex_destroy(&m->mu);
    free(m);
}

/* now + ms on CLOCK_MONOTONIC */
static struct timespec deadline_after(long ms)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    ts.tv_sec += ms / 1000;
    ts.tv_nsec += (ms % 1000) * 1000000L;
    if (ts.tv_nsec >= 1000000000L) {
        ts.tv_sec++;
        ts.tv_nsec -= 1000000000L;
    }
    return ts;
}

static int before(const struct timespec *a, const struct timespec *b)
{
    return a->tv_sec < b->tv_sec || (a->tv_sec == b->tv_sec && a->tv_nsec < b->tv_nsec);
}

size_t srv_mem_reserve(struct srv_mem *m, size_t n, long wait_ms, const volatile int *cancel)
{
    if (!m || n == 0) return 0;
    if (n > m->cap) n = m->cap;
    pthread_mutex_lock(&m->mu);
    if (m->used + n > m->cap && wait_ms > 0) {
        struct timespec end = deadline_after(wait_ms);
        while (m->used + n > m->cap && !(cancel && __atomic_load_n(cancel, __ATOMIC_RELAXED))) {
            struct timespec now, slice = deadline_after(MEM_WAIT_SLICE_MS);
            clock_gettime(CLOCK_MONOTONIC, &now);
            if (!before(&now, &end)) break;
            if (before(&end, &slice)) slice = end;
            int rc = pthread_cond_timedwait(&m->cv, &m->mu, &slice);
            if (rc != 0 && rc != ETIMEDOUT) break;
        }
    }
    size_t got = 0;
    if (m->used + n <= m->cap) {
        m->used += n;
        if (m->used > m->peak) m->peak = m->used;
        got = n;
    } else if (wait_ms >= 0) {
        m->refused++;
    }
    pthread_mutex_unlock(&m->mu);
    return got;
}

void srv_mem_adjust(struct srv_mem *m, size_t from, size_t to)
{
    if (!m || from == to) return;
    pthread_mutex_lock(&m->mu);
    m->used = m->used >= from ? m->used - from : 0;
    m->used += to;
    if (m->used > m->peak) m->peak = m->used;
    if (to < from) pthread_cond_broadcast(&m->cv);
    pthread_mutex_unlock(&m->mu);
}

void srv_mem_release(struct srv_mem *m, size_t n)
{
    if (!m || n == 0) return;
    pthread_mutex_lock(&m->mu);
    m->used = m->used >= n ? m->used - n : 0;
    pthread_cond_broadcast(&m->cv);
    pthread_mutex_unlock(&m->mu);
}

void srv_mem_stats(struct srv_mem *m, size_t *used, size_t *cap, size_t *peak,
                   unsigned long *refused)
{
    size_t u = 0, c = 0, p = 0;
    unsigned long r = 0;
    if (m) {
        pthread_mutex_lock(&m->mu);
        u = m->used;
        c = m->cap;
        p = m->peak;
        r = m->refused;
        pthread_mutex_unlock(&m->mu);
    }
    if (used) *used = u;
    if (cap) *cap = c;
    if (peak) *peak = p;
    if (refused) *refused = r;
}

/* The cgroup (v2) memory limit of this process in bytes, 0 when none is set
 * or it cannot be read. */
static unsigned long long cgroup_memory_max(void)
{
    FILE *f = fopen("/sys/fs/cgroup/memory.max", "re");
    if (!f) return 0;
    unsigned long long v = 0;
    if (fscanf(f, "%llu", &v) != 1) v = 0; /* "max": no limit */
    fclose(f);
    return v;
}

size_t srv_mem_default_cap(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    unsigned long long ram = pages > 0 && page > 0 ? (unsigned long long)pages * (unsigned long long)page : 0;
    unsigned long long cg = cgroup_memory_max();
    if (cg > 0 && (ram == 0 || cg < ram)) ram = cg;
    unsigned long long cap = ram ? ram / 4 : MEM_DEFAULT_MAX;
    if (cap > MEM_DEFAULT_MAX) cap = MEM_DEFAULT_MAX;
    if (cap < MEM_DEFAULT_MIN) cap = MEM_DEFAULT_MIN;
    return (size_t)cap;
}
