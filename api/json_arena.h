/* json_arena.h — per-thread bump allocation for the short-lived jansson trees
 * of one operation request (see json_arena.c). */
#ifndef API_JSON_ARENA_H
#define API_JSON_ARENA_H

#include <stddef.h>

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

/* n bytes (16-byte aligned) from the calling thread's arena, or NULL when no
 * scope is open on this thread or the arena has no room left (the caller then
 * allocates elsewhere). Never calls malloc. */
void *api_json_arena_alloc(size_t n);

/* Whether p points into the calling thread's arena (memory that must not be
 * passed to free()). False for NULL. */
int api_json_arena_owns(const void *p);

#endif
