/* answer_mem.h — the answer-memory budget (--max-answer-memory): how many
 * bytes of answers, computed or being computed, the server holds at once for
 * clients that have not read them yet. A slow reader keeps its whole answer
 * in memory until the last byte is sent; without a global bound, 30 clients
 * reading 58 MB answers at 64 KB/s held 1.79 GB. Thread-safe. */
#ifndef SERVER_ANSWER_MEM_H
#define SERVER_ANSWER_MEM_H

#include <stddef.h>

struct srv_mem;

/* A budget of cap bytes (> 0). NULL when out of memory. */
struct srv_mem *srv_mem_create(size_t cap);

/* Free the budget (m may be NULL). Nothing may use it afterwards. */
void srv_mem_free(struct srv_mem *m);

/* Reserve n bytes for one answer; n larger than the whole budget counts as
 * the whole budget (such an answer runs alone). Returns the bytes reserved
 * (to be given back with srv_mem_release or srv_mem_adjust), or 0 when they
 * did not fit: when wait_ms > 0 the caller first waits up to wait_ms for
 * answers to be released, giving up early once *cancel (may be NULL) is
 * nonzero. A refusal is counted (srv_mem_stats), except with wait_ms < 0 (a
 * try that will be made again elsewhere). n == 0 reserves nothing and
 * returns 0 without counting. */
size_t srv_mem_reserve(struct srv_mem *m, size_t n, long wait_ms, const volatile int *cancel);

/* Turn a reservation of `from` bytes into one of `to` bytes at once, without
 * waiting (an answer whose real size is now known: it is already computed,
 * so it is kept even when that passes the budget). */
void srv_mem_adjust(struct srv_mem *m, size_t from, size_t to);

/* Give back n reserved bytes (the answer was sent or dropped) and wake waiters. */
void srv_mem_release(struct srv_mem *m, size_t n);

/* The bytes reserved now, the budget, the most ever reserved at once and the
 * requests refused so far. Any pointer may be NULL; m may be NULL (all 0). */
void srv_mem_stats(struct srv_mem *m, size_t *used, size_t *cap, size_t *peak,
                   unsigned long *refused);

/* The default budget: 512 MiB or a quarter of the memory the process may use
 * (physical memory, or the cgroup's memory.max when that is lower), whichever
 * is less; at least 16 MiB. */
size_t srv_mem_default_cap(void);

#endif
