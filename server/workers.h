/* workers.h — a fixed pool of compute threads behind a bounded job queue.
 *
 * The I/O thread reserves a slot (srv_pool_reserve), suspends its connection,
 * then submits (srv_pool_submit), which cannot fail. A worker pops the job and
 * calls job->run; on shutdown, queued jobs get job->cancel instead. Neither
 * callback can fail: results and errors live in the enclosing request
 * (the worker's step cannot fail). After run/cancel returns the pool never touches the job
 * again, so the callback may hand the job's memory back to its owner.
 *
 * FAIR QUEUES. A job is short (a closed-form operation: its cost is linear
 * in its body, milliseconds at most; or an integration predicted to take a
 * few milliseconds at most) or long (an integration, a search: up to the
 * deadline). The workers take jobs of both kinds in arrival order, so a
 * flood of short jobs delays a long one only by the short jobs that arrived
 * before it; one more thread, the express worker, takes short jobs only, so a
 * short job never waits for a long one to finish while every worker computes
 * one.
 *
 * Workers (the express one too) run as SCHED_BATCH on Linux (a worker that
 * wakes up does not preempt a running I/O thread) plus `nice` (0 by default:
 * the same CPU share as the I/O threads, so a long job keeps its fair share of
 * the CPU under a flood of cheap requests answered on the I/O threads; a
 * larger nice favours the I/O threads and starves long jobs under such a
 * flood).
 * All functions are thread-safe except srv_pool_create/srv_pool_free.
 */
#ifndef SERVER_WORKERS_H
#define SERVER_WORKERS_H

struct srv_job {
    struct srv_job *next;                /* queue link, owned by the pool */
    void (*run)(struct srv_job *job);    /* on a worker thread */
    void (*cancel)(struct srv_job *job); /* instead of run, when the pool stops */
    int short_job;                       /* 1: short (see FAIR QUEUES), set before submitting */
    unsigned long long seq;              /* arrival order, owned by the pool */
};

struct srv_pool;

enum srv_pool_result {
    SRV_POOL_OK = 0,
    SRV_POOL_FULL,    /* queue capacity reached: answer 503 + Retry-After */
    SRV_POOL_STOPPED, /* shutting down: answer 503 cancelled */
};

#define SRV_POOL_DEFAULT_NICE 0 /* the I/O threads' weight: a fair share for long jobs */

/* Start `workers` threads (>= 1) and the express worker, with a queue of
 * `capacity` (>= 1) waiting jobs of both kinds. Each worker runs as
 * SCHED_BATCH (Linux) and adds `nice` (0..19; 0: unchanged) to its nice
 * value. srv_pool_create uses SRV_POOL_DEFAULT_NICE. Returns NULL if a thread
 * or allocation fails (nothing is left running). */
struct srv_pool *srv_pool_create_nice(int workers, int capacity, int nice);
struct srv_pool *srv_pool_create(int workers, int capacity);

/* Reserve one queue slot. On SRV_POOL_OK the caller must call srv_pool_submit
 * exactly once. */
enum srv_pool_result srv_pool_reserve(struct srv_pool *p);

/* Queue a job into a reserved slot. Cannot fail: if the pool has stopped in
 * between, job->cancel runs at once on the calling thread. */
void srv_pool_submit(struct srv_pool *p, struct srv_job *job);

/* Take a job that is still waiting out of the queue, freeing its slot at
 * once (a client that hung up while its job waited). Returns 1 if it was
 * removed: the pool forgets it and calls neither run nor cancel, so the caller
 * owns it again and must finish it itself. Returns 0 if the job is not
 * waiting (a worker has taken it, srv_pool_stop has cancelled it, or it was
 * never submitted): then run or cancel is called as usual. O(queue length). */
int srv_pool_remove(struct srv_pool *p, struct srv_job *job);

/* Current number of waiting jobs, of workers (the express one included)
 * running a job, and the total seconds workers have spent in finished
 * job->run calls. Any pointer may be NULL. */
void srv_pool_stats(struct srv_pool *p, int *queued, int *busy, double *busy_seconds);

/* Stop accepting jobs, call cancel on every queued job (on the calling
 * thread), wait for running jobs to finish and join the threads. Idempotent. */
void srv_pool_stop(struct srv_pool *p);

/* Stop (if not done) and free the pool. p may be NULL. */
void srv_pool_free(struct srv_pool *p);

#endif
