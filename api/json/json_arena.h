/* json_arena.h — per-thread bump allocation for the short-lived jansson trees
 * of one operation request (see api/json/json_arena.c). */
#ifndef API_JSON_ARENA_H
#define API_JSON_ARENA_H

#include <stddef.h>
#include <stdint.h>

/* Bytes of the arena each thread keeps (allocated at its first
 * api_json_arena_begin(), freed when the thread exits). */
#define API_JSON_ARENA_BYTES 65536u

/* Start an arena scope on the calling thread: until the matching
 * api_json_arena_end(), api_json_arena_alloc() hands out memory from the
 * thread's arena. Scopes nest; memory is reclaimed when the outermost ends.
 * Never fails: when the arena cannot be set up (out of memory) the scope
 * simply hands out nothing and callers use malloc as before. */
void api_json_arena_begin(void);

/* End the scope begun last on this thread. Ending the outermost scope
 * forgets everything handed out in it: every tree built from the arena must
 * have been released (or never be touched again) by then. */
void api_json_arena_end(void);

/* The calling thread's arena (api/json/json_arena.c). Exposed only so that the two
 * functions below, called for every jansson allocation and free, inline. */
struct api_json_arena {
    char *base;  /* API_JSON_ARENA_BYTES, or NULL before the first scope */
    size_t used; /* bytes handed out in the current outermost scope */
    int depth;   /* open scopes on this thread */
};
extern _Thread_local struct api_json_arena api_json_arena_tls;

/* Marks n bytes at p usable for AddressSanitizer (api/json/json_arena.c poisons the
 * arena outside live allocations); nothing in other builds. */
#if defined(__SANITIZE_ADDRESS__)
#define API_JSON_ARENA_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define API_JSON_ARENA_ASAN 1
#endif
#endif
#ifdef API_JSON_ARENA_ASAN
void api_json_arena_unpoison(void *p, size_t n);
#else
#define api_json_arena_unpoison(p, n) ((void)(p), (void)(n))
#endif

/* n bytes (16-byte aligned) from the calling thread's arena, or NULL when no
 * scope is open on this thread or the arena has no room left (the caller then
 * allocates elsewhere). Never calls malloc. */
static inline void *api_json_arena_alloc(size_t n)
{
    struct api_json_arena *a = &api_json_arena_tls;
    if (a->depth <= 0 || !a->base || n > API_JSON_ARENA_BYTES) return NULL;
    size_t need = n ? (n + 15u) & ~(size_t)15u : 16u; /* malloc(0) may be unique: so are we */
    if (need > API_JSON_ARENA_BYTES - a->used) return NULL;
    char *p = a->base + a->used;
    a->used += need;
    api_json_arena_unpoison(p, n ? n : 1);
    return p;
}

/* Whether p points into the calling thread's arena (memory that must not be
 * passed to free()). False for NULL. */
static inline int api_json_arena_owns(const void *p)
{
    /* As integers: comparing pointers into different objects is undefined. */
    const uintptr_t b = (uintptr_t)api_json_arena_tls.base, c = (uintptr_t)p;
    return c && b && c >= b && c - b < API_JSON_ARENA_BYTES;
}

#endif
