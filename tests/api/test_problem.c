/* test_problem.c — pins every mech_status to its name, its problem kind, HTTP
 * status and type URI, and every problem kind to its status/type/title
 * (codes are append-only; a renumbering or a changed URI fails here). */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "run/endpoint.h"
#include "testlib.h"

static const struct {
    enum mech_status st;
    int value;
    const char *name;
    int http;
    const char *type;
} status_rows[] = {
    {MECH_OK, 0, "ok", 0, NULL},
    {MECH_EINVAL, 1, "invalid-argument", 422, "/problems/validation-error"},
    {MECH_EDOMAIN, 2, "domain-error", 422, "/problems/domain-error"},
    {MECH_EBUDGET, 3, "step-budget-exceeded", 422, "/problems/compute-budget-exceeded"},
    {MECH_EDEADLINE, 4, "deadline-exceeded", 422, "/problems/compute-budget-exceeded"},
    {MECH_ECANCELLED, 5, "cancelled", 503, "/problems/cancelled"},
    {MECH_ENOMEM, 6, "out-of-memory", 500, "/problems/internal-error"},
    {MECH_ENUMERIC, 7, "numerical-failure", 422, "/problems/numerical-failure"},
    {MECH_EINTERNAL, 8, "internal-error", 500, "/problems/internal-error"},
};

static const struct {
    enum api_problem kind;
    int value, status;
    const char *type;
} problem_rows[] = {
    {API_PROBLEM_MALFORMED_JSON, 1, 400, "/problems/malformed-json"},
    {API_PROBLEM_NOT_FOUND, 2, 404, "/problems/not-found"},
    {API_PROBLEM_METHOD_NOT_ALLOWED, 3, 405, "/problems/method-not-allowed"},
    {API_PROBLEM_BODY_TOO_LARGE, 4, 413, "/problems/body-too-large"},
    {API_PROBLEM_UNSUPPORTED_MEDIA, 5, 415, "/problems/unsupported-media-type"},
    {API_PROBLEM_VALIDATION, 6, 422, "/problems/validation-error"},
    {API_PROBLEM_DOMAIN, 7, 422, "/problems/domain-error"},
    {API_PROBLEM_BUDGET, 8, 422, "/problems/compute-budget-exceeded"},
    {API_PROBLEM_NUMERIC, 9, 422, "/problems/numerical-failure"},
    {API_PROBLEM_QUEUE_FULL, 10, 503, "/problems/queue-full"},
    {API_PROBLEM_INTERNAL, 11, 500, "/problems/internal-error"},
    {API_PROBLEM_CANCELLED, 12, 503, "/problems/cancelled"},
    {API_PROBLEM_UNAUTHORIZED, 13, 401, "/problems/unauthorized"},
    {API_PROBLEM_CORS_FORBIDDEN, 14, 403, "/problems/cors-origin-not-allowed"},
    {API_PROBLEM_REQUEST_MISSING, 15, 400, "/problems/request-missing"},
    {API_PROBLEM_ANSWER_TOO_LARGE, 16, 422, "/problems/answer-too-large"},
    {API_PROBLEM_BAD_FRAMING, 17, 400, "/problems/bad-framing"},
    {API_PROBLEM_ANSWER_MEMORY, 18, 503, "/problems/answer-memory-full"},
    {API_PROBLEM_BAD_REQUEST, 19, 400, "/problems/bad-request"},
    {API_PROBLEM_URI_TOO_LONG, 20, 414, "/problems/uri-too-long"},
    {API_PROBLEM_HEADERS_TOO_LARGE, 21, 431, "/problems/headers-too-large"},
};

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK_EQ_INT(MECH_STATUS_COUNT, sizeof status_rows / sizeof status_rows[0]);
    CHECK_EQ_INT(API_PROBLEM_COUNT, 1 + sizeof problem_rows / sizeof problem_rows[0]);

    for (size_t i = 0; i < sizeof problem_rows / sizeof problem_rows[0]; i++) {
        CHECK_EQ_INT(problem_rows[i].kind, problem_rows[i].value);
        CHECK_EQ_INT(api_problem_status(problem_rows[i].kind), problem_rows[i].status);
        CHECK(!strcmp(api_problem_type(problem_rows[i].kind), problem_rows[i].type));
        CHECK(strlen(api_problem_title(problem_rows[i].kind)) > 0);
    }
    CHECK(!strcmp(mech_status_name((enum mech_status)99), "unknown"));

    for (size_t i = 0; i < sizeof status_rows / sizeof status_rows[0]; i++) {
        CHECK_EQ_INT(status_rows[i].st, status_rows[i].value);
        CHECK(!strcmp(mech_status_name(status_rows[i].st), status_rows[i].name));
        if (status_rows[i].st == MECH_OK) continue;
        /* The mapping an endpoint applies to a failed core call. */
        struct api_call c;
        memset(&c, 0, sizeof c);
        struct mech_error e;
        mech_error_clear(&e);
        mech_error_set(&e, status_rows[i].st, "mass", "because");
        e.progress.t_reached = 1;
        e.progress.t_target = 4;
        CHECK(api_call_fail_core(&c, status_rows[i].st, &e, "/bodies/0") == NULL);
        CHECK_EQ_INT(api_problem_status(c.problem), status_rows[i].http);
        CHECK(!strcmp(api_problem_type(c.problem), status_rows[i].type));
        if (status_rows[i].st == MECH_EINVAL || status_rows[i].st == MECH_EDOMAIN) {
            const char *p = json_string_value(json_object_get(json_array_get(c.errors, 0), "pointer"));
            CHECK(p && !strcmp(p, "/bodies/0/mass"));
        }
        if (status_rows[i].st == MECH_EBUDGET) {
            json_t *prog = json_object_get(c.extra, "progress");
            CHECK_CLOSE(json_number_value(json_object_get(prog, "fraction_done")), 0.25, 0, 0);
        }
        json_decref(c.errors);
        json_decref(c.extra);
    }

    /* First error wins in mech_error. */
    struct mech_error e;
    mech_error_clear(&e);
    mech_error_set(&e, MECH_EDOMAIN, "a", "first");
    mech_error_set(&e, MECH_EINVAL, "b", "second");
    CHECK_EQ_INT(e.code, MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "a") && !strcmp(e.text, "first"));
    CHECK(mech_error_set(NULL, MECH_EINVAL, NULL, "x") == MECH_EINVAL);

    /* A problem response carries the pinned fields. */
    struct api_response r;
    api_response_problem(&r, API_PROBLEM_QUEUE_FULL, "busy");
    CHECK_EQ_INT(r.status, 503);
    CHECK_EQ_INT(r.retry_after, 1);
    CHECK(!strcmp(r.content_type, "application/problem+json"));
    json_t *j = json_loads(r.body, 0, NULL);
    CHECK(!strcmp(json_string_value(json_object_get(j, "type")), "/problems/queue-full"));
    CHECK_EQ_INT(json_integer_value(json_object_get(j, "status")), 503);
    CHECK(!strcmp(json_string_value(json_object_get(j, "detail")), "busy"));
    json_decref(j);
    api_response_free(&r);
    api_response_free(&r); /* idempotent */
    TEST_MAIN_END();
}
