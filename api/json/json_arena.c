/* json_arena.c — per-thread bump allocation for the jansson trees of one
 * operation request.
 *
 * A small request builds and frees some fifty jansson nodes (the parsed body,
 * the answer tree, object hash pairs): measured with callgrind, malloc and
 * free of those were ~16 % of mechd's user-space instructions per boost
 * request. Inside a scope (api/run/api_run.c's api_run_post: parse, validate, compute,
 * write, release) the jansson allocator takes memory from this arena with a
 * pointer bump, frees of arena memory cost nothing, and the end of the scope
 * reclaims it all at once. When the arena is full, allocation falls back to
 * malloc, so a large request works exactly as before.
 *
 * Safety rests on one rule: no jansson value built inside a scope outlives it.
 * run_operation's trees never leave the function (the answer leaves as text
 * malloc()ed by api/json/json_write.c), and nothing cached at start-up is built inside
 * a scope (api_init runs before, and GET resources are not scoped). Under
 * AddressSanitizer the arena is poisoned outside live allocations, so a value
 * used after its scope ended is reported by the sanitizer test run. */
#include "json/json_arena.h"

#include <pthread.h>
#include <stdlib.h>

#ifdef API_JSON_ARENA_ASAN /* see api/json/json_arena.h */
#include <sanitizer/asan_interface.h>
#define ARENA_POISON(p, n) ASAN_POISON_MEMORY_REGION((p), (n))
#define ARENA_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION((p), (n))
#else
#define ARENA_POISON(p, n) ((void)(p), (void)(n))
#define ARENA_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

_Thread_local struct api_json_arena api_json_arena_tls;

/* The thread's chunk is freed when the thread exits (I/O threads and workers
 * end at shutdown; LeakSanitizer would otherwise report it). */
static pthread_key_t arena_key;
static pthread_once_t arena_key_once = PTHREAD_ONCE_INIT;
static int arena_key_ok;

static void arena_thread_exit(void *base)
{
    ARENA_UNPOISON(base, API_JSON_ARENA_BYTES);
    free(base);
}

static void arena_key_create(void)
{
    arena_key_ok = pthread_key_create(&arena_key, arena_thread_exit) == 0;
}

void api_json_arena_begin(void)
{
    struct api_json_arena *a = &api_json_arena_tls;
    if (a->depth++ > 0) return;
    a->used = 0;
    if (a->base) return;
    pthread_once(&arena_key_once, arena_key_create);
    if (!arena_key_ok) return; /* could not free it at thread exit: no arena */
    char *b = malloc(API_JSON_ARENA_BYTES);
    if (!b) return; /* out of memory: this scope uses malloc; retried next scope */
    if (pthread_setspecific(arena_key, b) != 0) {
        free(b);
        return;
    }
    ARENA_POISON(b, API_JSON_ARENA_BYTES);
    a->base = b;
}

void api_json_arena_end(void)
{
    struct api_json_arena *a = &api_json_arena_tls;
    if (a->depth <= 0) return; /* unbalanced end: ignore */
    if (--a->depth > 0) return;
    if (a->base) ARENA_POISON(a->base, a->used);
    a->used = 0;
}

#ifdef API_JSON_ARENA_ASAN
void api_json_arena_unpoison(void *p, size_t n)
{
    ARENA_UNPOISON(p, n);
}
#endif
