/* workers.c — fixed thread pool with a bounded FIFO of intrusive jobs (see
 * workers.h). One mutex guards the queue; workers wait on one condition.
 * Nothing is allocated per job, so submitting cannot fail. */
#include "workers.h"

#include <pthread.h>
#include <stdlib.h>
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
    pthread_t *threads;
};

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void *worker_main(void *arg)
{
    struct srv_pool *p = arg;
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
