/* api_alloc.h — what the API pipeline asks of jansson's checked allocator
 * (api/json/api_alloc.c; installed by api_install_json_allocator, api.h). */
#ifndef API_API_ALLOC_H
#define API_API_ALLOC_H

/* 1 when jansson allocates through the checked allocator (main's set-up ran). */
int api_json_allocator_installed(void);

/* Clear this thread's allocation-failure flag (at the start of a request). */
void api_json_alloc_watch(void);

/* 1 when an allocation failed on this thread since api_json_alloc_watch: the
 * answer built may lack a member and must not be sent. */
int api_json_alloc_failed(void);

/* 1 when an operation request should run in the per-thread arena
 * (api/json/json_arena.c): the allocator below the checked one is the C library's. A
 * test's own allocator turns the arena off. */
int api_json_arena_wanted(void);

#endif
