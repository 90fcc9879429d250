/* workers.c — fixed thread pool with a bounded FIFO of intrusive jobs (see
 * workers.h). One mutex guards the queue; workers wait on one condition.
 * Nothing is allocated per job, so submitting cannot fail.
 *
 * PRIORITY. Workers run below the HTTP I/O threads: each worker lowers its own
 * scheduling priority when it starts (nice +N, default SRV_POOL_DEFAULT_NICE,
 * and SCHED_BATCH on Linux, where both are per-thread attributes), so on a
 * machine whose cores are all busy computing, the I/O threads still get a
 * core as soon as they have work: /healthz, 503s and quick operations stay
 * fast under overload (measured with tests/load/overload.py: /healthz p99
 * 1.6-4.0 ms with nice 10 against 4.6-5.5 ms at equal priority). The price:
 * anything else on the machine at normal priority (a load generator, another
 * service) now wins CPU from the workers too. N = 0 leaves the workers at
 * the I/O threads' priority. Failure to lower the priority is harmless. */
#ifdef __linux__
#define _GNU_SOURCE /* SCHED_BATCH */
#endif
#include "workers.h"

#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <time.h>

struct srv_pool {
    pthread_mutex_t mu;
    pthread_cond_t cv;
    struct srv_job *head, *tail;
    int queued;   /* jobs in the list */
    int reserved; /* slots reserved but not yet submitted */
    int capacity;
    int busy;            /* workers inside job->run */
    double busy_seconds; /* summed time of finished job->run calls */
    int stopping;
    int joined;
    int nthreads;
    int nice; /* added to each worker's nice value (0: unchanged) */
    pthread_t *threads;
};

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Lower the calling thread's priority by `nice` (see PRIORITY above). On
 * Linux setpriority(PRIO_PROCESS, 0, ...) changes the calling thread only. */
static void worker_lower_priority(int nice)
{
    if (nice <= 0) return;
#if defined(__linux__) && defined(SCHED_BATCH)
    struct sched_param sp = {0};
    (void)pthread_setschedparam(pthread_self(), SCHED_BATCH, &sp);
#endif
#ifdef __linux__
    errno = 0;
    int base = getpriority(PRIO_PROCESS, 0);
    if (base == -1 && errno != 0) base = 0;
    (void)setpriority(PRIO_PROCESS, 0, base + nice > 19 ? 19 : base + nice);
#endif
}

static void *worker_main(void *arg)
{
    struct srv_pool *p = arg;
    worker_lower_priority(p->nice);
    pthread_mutex_lock(&p->mu);
    for (;;) {
        while (!p->head && !p->stopping)
            pthread_cond_wait(&p->cv, &p->mu);
        struct srv_job *job = p->head;
        if (!job) break; /* stopping and nothing left */
        p->head = job->next;
        if (!p->head) p->tail = NULL;
        p->queued--;
        p->busy++;
        pthread_mutex_unlock(&p->mu);
        job->next = NULL;
        double t0 = now_seconds();
        job->run(job); /* the job may be freed by its owner from here on */
        double dt = now_seconds() - t0;
        pthread_mutex_lock(&p->mu);
        p->busy--;
        p->busy_seconds += dt;
    }
    pthread_mutex_unlock(&p->mu);
    return NULL;
}

struct srv_pool *srv_pool_create(int workers, int capacity)
{
    return srv_pool_create_nice(workers, capacity, SRV_POOL_DEFAULT_NICE);
}

struct srv_pool *srv_pool_create_nice(int workers, int capacity, int nice)
{
    if (workers < 1 || capacity < 1) return NULL;
    struct srv_pool *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->threads = calloc((size_t)workers, sizeof *p->threads);
    if (!p->threads) {
        free(p);
        return NULL;
    }
    pthread_mutex_init(&p->mu, NULL);
    pthread_cond_init(&p->cv, NULL);
    p->capacity = capacity;
    p->nice = nice < 0 ? 0 : nice;
    for (int i = 0; i < workers; i++) {
        if (pthread_create(&p->threads[i], NULL, worker_main, p) != 0) {
            srv_pool_free(p); /* joins the nthreads started so far */
            return NULL;
        }
        p->nthreads++;
    }
    return p;
}

enum srv_pool_result srv_pool_reserve(struct srv_pool *p)
{
    enum srv_pool_result r = SRV_POOL_OK;
    pthread_mutex_lock(&p->mu);
    if (p->stopping)
        r = SRV_POOL_STOPPED;
    else if (p->queued + p->reserved >= p->capacity)
        r = SRV_POOL_FULL;
    else
        p->reserved++;
    pthread_mutex_unlock(&p->mu);
    return r;
}

void srv_pool_submit(struct srv_pool *p, struct srv_job *job)
{
    job->next = NULL;
    pthread_mutex_lock(&p->mu);
    p->reserved--;
    if (p->stopping) {
        pthread_mutex_unlock(&p->mu);
        job->cancel(job);
        return;
    }
    if (p->tail)
        p->tail->next = job;
    else
        p->head = job;
    p->tail = job;
    p->queued++;
    pthread_cond_signal(&p->cv);
    pthread_mutex_unlock(&p->mu);
}

int srv_pool_remove(struct srv_pool *p, struct srv_job *job)
{
    int removed = 0;
    pthread_mutex_lock(&p->mu);
    struct srv_job *prev = NULL;
    for (struct srv_job *j = p->head; j; prev = j, j = j->next) {
        if (j != job) continue;
        if (prev)
            prev->next = j->next;
        else
            p->head = j->next;
        if (p->tail == j) p->tail = prev;
        p->queued--;
        j->next = NULL;
        removed = 1;
        break;
    }
    pthread_mutex_unlock(&p->mu);
    return removed;
}

void srv_pool_stats(struct srv_pool *p, int *queued, int *busy, double *busy_seconds)
{
    pthread_mutex_lock(&p->mu);
    if (queued) *queued = p->queued;
    if (busy) *busy = p->busy;
    if (busy_seconds) *busy_seconds = p->busy_seconds;
    pthread_mutex_unlock(&p->mu);
}

void srv_pool_stop(struct srv_pool *p)
{
    pthread_mutex_lock(&p->mu);
    p->stopping = 1;
    struct srv_job *list = p->head;
    p->head = p->tail = NULL;
    p->queued = 0;
    pthread_cond_broadcast(&p->cv);
    int join = !p->joined;
    p->joined = 1;
    pthread_mutex_unlock(&p->mu);

    while (list) {
        struct srv_job *next = list->next;
        list->next = NULL;
        list->cancel(list);
        list = next;
    }
    if (join)
        for (int i = 0; i < p->nthreads; i++)
            pthread_join(p->threads[i], NULL);
}

void srv_pool_free(struct srv_pool *p)
{
    if (!p) return;
    srv_pool_stop(p);
    pthread_cond_destroy(&p->cv);
    pthread_mutex_destroy(&p->mu);
    free(p->threads);
    free(p);
}
