/* api_alloc.c — jansson's allocator for the whole process: checked (a failed
 * allocation anywhere in a request turns its answer into the 500) and, inside
 * an operation request, served from the per-thread arena (api/json/json_arena.c).
 * Installed by main() through api_install_json_allocator (api.h). */
#include "json/api_alloc.h"

#include <stdlib.h>

#include <jansson.h>

#include "api.h"
#include "json/json_arena.h"

/* Endpoints build answers with json_object_set_new(), json_array_append_new(),
 * json_pack() and the encoders; checking each of those hundreds of calls would
 * bury the physics, and one unchecked failure silently drops a member (a 200
 * with a field missing, or a 422 listing fewer errors than it counts). So
 * jansson allocates through json_malloc_checked() (installed by main() through
 * api_install_json_allocator(), api.h), which records a failure in
 * a per-thread flag; api_handle_ext() (api/http/api.c) clears the flag before a request and,
 * when it is raised afterwards, answers the fixed 500 out-of-memory problem
 * instead of whatever was built. The previous allocator (the C library's, or
 * one a test installed before api_init) does the allocating — except inside
 * an operation request (api_run_post, api/run/api_run.c), where the per-thread arena of
 * api/json/json_arena.c serves what fits while the previous allocator is the C
 * library's. A test's own allocator turns the arena off, so an
 * allocation-failure sweep still reaches every jansson allocation. */
static _Thread_local int json_alloc_failed;
static json_malloc_t prev_json_malloc;
static json_free_t prev_json_free;
static int json_arena_enabled;

static void *json_malloc_checked(size_t n)
{
    void *p = api_json_arena_alloc(n); /* NULL outside a scope or when full */
    if (!p) p = prev_json_malloc ? prev_json_malloc(n) : malloc(n);
    if (!p) json_alloc_failed = 1;
    return p;
}

static void json_free_checked(void *p)
{
    if (api_json_arena_owns(p)) return; /* reclaimed when its scope ends */
    if (prev_json_free)
        prev_json_free(p);
    else
        free(p);
}

void api_install_json_allocator(void)
{
    json_malloc_t m;
    json_free_t f;
    json_get_alloc_funcs(&m, &f);
    if (m == json_malloc_checked) return;
    prev_json_malloc = m;
    prev_json_free = f;
    json_arena_enabled = m == malloc && f == free;
    json_set_alloc_funcs(json_malloc_checked, json_free_checked);
}

int api_json_allocator_installed(void)
{
    json_malloc_t m;
    json_free_t f;
    json_get_alloc_funcs(&m, &f);
    return m == json_malloc_checked;
}

void api_json_alloc_watch(void)
{
    json_alloc_failed = 0;
}

int api_json_alloc_failed(void)
{
    return json_alloc_failed;
}

int api_json_arena_wanted(void)
{
    return json_arena_enabled;
}
