/* test_process_setup.c — process-wide set-up is main()'s: the API
 * layer does not install jansson's allocator behind the caller's back, so
 * api_init() without api_install_json_allocator() first refuses, says why,
 * and every request then gets a 500 problem (never an answer built without
 * allocation-failure detection). This binary deliberately skips the call. */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "testlib.h"

int main(void)
{
    gsl_set_error_handler_off();
    json_malloc_t m0;
    json_free_t f0;
    json_get_alloc_funcs(&m0, &f0);
    CHECK(api_init() != 0);
    const char *why = api_init_error();
    CHECK(why && strstr(why, "api_install_json_allocator") != NULL);
    /* api_init() left jansson's allocator as it was. */
    json_malloc_t m1;
    json_free_t f1;
    json_get_alloc_funcs(&m1, &f1);
    CHECK(m1 == m0 && f1 == f0);
    const char body[] = "{\"beta\":[0.5,0,0],\"event\":[1,0,0,0]}";
    struct api_request req = {"POST", "/v1/relativity/boost", "application/json", body,
                              strlen(body), 1000, mech_clock_seconds() + 60, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    CHECK_EQ_INT(resp.status, 500);
    CHECK(resp.body && strstr(resp.body, "/problems/internal-error") != NULL);
    api_response_free(&resp);
    TEST_MAIN_END();
}
