/* workers.c — fixed thread pool with a bounded queue of intrusive jobs in
 * two FIFO lists, short and long (see workers.h, FAIR QUEUES). One mutex
 * guards the lists; the workers wait on one condition, the express worker on
 * its own. Nothing is allocated per job, so submitting cannot fail.
 *
 * PRIORITY. Every worker runs as SCHED_BATCH (Linux): a worker that wakes up
 * never preempts a running I/O thread, so /healthz and quick answers get a
 * core at once. By default its nice value is the I/O threads' own: equal CPU
 * weight. With nice +10 (the earlier default) a worker weighs 110 against an
 * I/O thread's 1024, and under a flood of cheap requests answered on the I/O
 * threads (with the load generator on the same cores) a long job got ~1/15
 * of a core: 0.6 s of CPU took up to 10 s of wall time and 1 in 16 ended at
 * its deadline. --worker-nice N still lowers the workers by N. Failure to
 * change the policy or priority is harmless. */
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

/* One FIFO list of waiting jobs. */
struct job_list {
    struct srv_job *head, *tail;
};

struct srv_pool {
    pthread_mutex_t mu;
    pthread_cond_t cv;         /* the workers: a job of either kind, or stopping */
    pthread_cond_t cv_express; /* the express worker: a short job, or stopping */
    struct job_list list[2];   /* [0] long, [1] short jobs */
    unsigned long long seq;    /* next arrival number */
    int queued;   /* jobs in the lists */
    int reserved; /* slots reserved but not yet submitted */
    int capacity;
    int busy;            /* workers inside job->run */
    double busy_seconds; /* summed time of finished job->run calls */
    int stopping;
    int joined;
    int nthreads; /* started, the express worker (the last) included */
    int nworkers; /* --workers: threads before the express one */
    int nice; /* added to each worker's nice value (0: unchanged) */
    pthread_t *threads;
};

/* One worker's start argument. */
struct worker_arg {
    struct srv_pool *p;
    int express;
};

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* SCHED_BATCH, and lower the calling thread's priority by `nice` (see
 * PRIORITY above). On Linux setpriority(PRIO_PROCESS, 0, ...) changes the
 * calling thread only. */
static void worker_lower_priority(int nice)
{
#if defined(__linux__) && defined(SCHED_BATCH)
    struct sched_param sp = {0};
    (void)pthread_setschedparam(pthread_self(), SCHED_BATCH, &sp);
#endif
    if (nice <= 0) return;
#ifdef __linux__
    errno = 0;
    int base = getpriority(PRIO_PROCESS, 0);
    if (base == -1 && errno != 0) base = 0;
    (void)setpriority(PRIO_PROCESS, 0, base + nice > 19 ? 19 : base + nice);
#endif
}

/* Take the next job for a worker (the oldest of both lists) or the express
 * worker (the oldest short one); NULL if none. p->mu held. */
static struct srv_job *take(struct srv_pool *p, int express)
{
    struct srv_job *s = p->list[1].head, *l = express ? NULL : p->list[0].head;
    int k = s && (!l || s->seq < l->seq) ? 1 : l ? 0 : -1;
    if (k < 0) return NULL;
    struct srv_job *job = p->list[k].head;
    p->list[k].head = job->next;
    if (!p->list[k].head) p->list[k].tail = NULL;
    p->queued--;
    return job;
}

static void *worker_main(void *arg)
{
    struct worker_arg *wa = arg;
    struct srv_pool *p = wa->p;
    int express = wa->express;
    free(wa);
#ifdef __linux__
    pthread_setname_np(pthread_self(), express ? "mechd-express" : "mechd-worker");
#endif
    worker_lower_priority(p->nice);
    pthread_mutex_lock(&p->mu);
    for (;;) {
        struct srv_job *job;
        while (!(job = take(p, express)) && !p->stopping)
            pthread_cond_wait(express ? &p->cv_express : &p->cv, &p->mu);
        if (!job) break; /* stopping and nothing left */
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
    p->threads = calloc((size_t)workers + 1, sizeof *p->threads);
    if (!p->threads) {
        free(p);
        return NULL;
    }
    pthread_mutex_init(&p->mu, NULL);
    pthread_cond_init(&p->cv, NULL);
    pthread_cond_init(&p->cv_express, NULL);
    p->capacity = capacity;
    p->nice = nice < 0 ? 0 : nice;
    p->nworkers = workers;
    for (int i = 0; i <= workers; i++) {
        struct worker_arg *wa = malloc(sizeof *wa);
        if (wa) *wa = (struct worker_arg){p, i == workers};
        if (!wa || pthread_create(&p->threads[i], NULL, worker_main, wa) != 0) {
            free(wa);
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
    struct job_list *l = &p->list[job->short_job ? 1 : 0];
    job->seq = p->seq++;
    if (l->tail)
        l->tail->next = job;
    else
        l->head = job;
    l->tail = job;
    p->queued++;
    pthread_cond_signal(&p->cv);
    if (job->short_job) pthread_cond_signal(&p->cv_express);
    pthread_mutex_unlock(&p->mu);
}

int srv_pool_remove(struct srv_pool *p, struct srv_job *job)
{
    int removed = 0;
    pthread_mutex_lock(&p->mu);
    for (int k = 0; k < 2 && !removed; k++) {
        struct job_list *l = &p->list[k];
        struct srv_job *prev = NULL;
        for (struct srv_job *j = l->head; j; prev = j, j = j->next) {
            if (j != job) continue;
            if (prev)
                prev->next = j->next;
            else
                l->head = j->next;
            if (l->tail == j) l->tail = prev;
            p->queued--;
            j->next = NULL;
            removed = 1;
            break;
        }
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
    struct srv_job *lists[2] = {p->list[0].head, p->list[1].head};
    p->list[0].head = p->list[0].tail = p->list[1].head = p->list[1].tail = NULL;
    p->queued = 0;
    pthread_cond_broadcast(&p->cv);
    pthread_cond_broadcast(&p->cv_express);
    int join = !p->joined;
    p->joined = 1;
    pthread_mutex_unlock(&p->mu);

    for (int k = 0; k < 2; k++) {
        struct srv_job *list = lists[k];
        while (list) {
            struct srv_job *next = list->next;
            list->next = NULL;
            list->cancel(list);
            list = next;
        }
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
    pthread_cond_destroy(&p->cv_express);
    pthread_mutex_destroy(&p->mu);
    free(p->threads);
    free(p);
}
