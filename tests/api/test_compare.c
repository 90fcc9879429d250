/* test_compare.c — POST /v1/compare against separately run POST
 * /v1/trajectory requests with the same settings: every row's errors, drifts,
 * steps and evaluations are the same numbers (bit for bit) as the
 * corresponding single request's diagnostics.reference (exact-reference
 * scene), or as the differences recomputed here from the single requests'
 * samples and a radau15 rtol 1e-10 request (scene without a reference).
 * Also: the shared step budget (the runs that finished are answered, the rest
 * marked not run, and such a partial answer is never cached; when none
 * finished the request fails naming the run, with the steps of the whole
 * request), a run whose method does not apply is a failed row, validation of
 * runs/sweep, and GET /v1/integrators (api_integrators_catalog) against the
 * registry and the schema's method lists. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api.h"
#include "ops/integrators/integrators.h"
#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "mech/base/vec.h"
#include "run/routes.h"
#include "testlib.h"
#include "request/trajectory_request.h"

static json_t *post(const char *path, json_t *body, long max_steps, int *status)
{
    char *text = json_dumps(body, JSON_COMPACT | JSON_REAL_PRECISION(17));
    struct api_request req = {"POST", path, "application/json", text, strlen(text), max_steps,
                              mech_clock_seconds() + 120, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    free(text);
    *status = resp.status;
    json_t *j = json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL);
    if (resp.status != 200) fprintf(stderr, "%s -> %d: %.600s\n", path, resp.status, resp.body);
    api_response_free(&resp);
    return j;
}

static double num(const json_t *o, const char *k) { return json_number_value(json_object_get(o, k)); }

static json_t *trajectory_with(const json_t *request, const json_t *integrator)
{
    json_t *b = json_deep_copy(request);
    json_object_set_new(b, "integrator", json_deep_copy(integrator));
    json_object_set_new(b, "cost", json_false());
    int st;
    json_t *r = post("/v1/trajectory", b, 10000000, &st);
    json_decref(b);
    CHECK_EQ_INT(st, 200);
    return r;
}

static const char kepler_request[] =
    "{\"particle\": {\"mass\": 2, \"position\": [1, 0, 0], \"velocity\": [0, 1.2247448713915890, "
    "0.1]}, \"forces\": [{\"type\": \"central_gravity\", \"gm\": 1}], \"t_end\": 30, "
    "\"samples\": 31}";

static void test_exact_scene(void)
{
    json_t *request = json_loads(kepler_request, JSON_DECODE_INT_AS_REAL, NULL);
    json_t *runs = json_loads(
        "[{\"method\": \"rk8pd\", \"rtol\": 1e-9, \"atol\": 1e-12}, {\"method\": \"verlet\", "
        "\"dt\": 0.01}, {\"accuracy\": \"balanced\"}, {\"target_error\": 1e-5}, {\"method\": "
        "\"gauss4\", \"dt\": 0.05}, {\"method\": \"rkf45\"}]",
        JSON_DECODE_INT_AS_REAL, NULL);
    json_t *body = json_pack("{s:s,s:O,s:O,s:b}", "operation", "/v1/trajectory", "request",
                             request, "runs", runs, "cost", 0);
    int st;
    json_t *cmp = post("/v1/compare", body, 10000000, &st);
    CHECK_EQ_INT(st, 200);
    json_t *ref = json_object_get(cmp, "reference");
    CHECK(!strcmp(json_string_value(json_object_get(ref, "kind")), "exact"));
    CHECK(!strcmp(json_string_value(json_object_get(ref, "name")), "kepler"));
    json_t *rows = json_object_get(cmp, "runs");
    CHECK_EQ_INT(json_array_size(rows), json_array_size(runs));
    double total = 0;
    for (size_t i = 0; i < json_array_size(rows); i++) {
        json_t *row = json_array_get(rows, i);
        json_t *tr = trajectory_with(request, json_array_get(runs, i));
        json_t *d = json_object_get(tr, "diagnostics");
        json_t *tref = json_object_get(d, "reference");
        CHECK(!strcmp(json_string_value(json_object_get(row, "status")), "ok"));
        CHECK(!strcmp(json_string_value(json_object_get(row, "method")),
                      json_string_value(json_object_get(d, "method"))));
        const char *keys[] = {"max_position_error", "final_position_error", "max_velocity_error",
                              "max_relative_position_error", "max_relative_velocity_error"};
        for (int k = 0; k < 5; k++) CHECK(num(row, keys[k]) == num(tref, keys[k]));
        const char *ints[] = {"steps", "rejected_steps", "rhs_evaluations"};
        for (int k = 0; k < 3; k++) CHECK(num(row, ints[k]) == num(d, ints[k]));
        if (json_object_get(d, "rtol")) {
            CHECK(num(row, "rtol") == num(d, "rtol"));
            CHECK(num(row, "atol") == num(d, "atol"));
        } else {
            CHECK(num(row, "dt") == num(d, "dt"));
        }
        json_t *ri = json_object_get(row, "invariants"), *ti = json_object_get(d, "invariants");
        CHECK_EQ_INT(json_array_size(ri), 2); /* energy and angular momentum */
        CHECK_EQ_INT(json_array_size(ri), json_array_size(ti));
        for (size_t k = 0; k < json_array_size(ri); k++)
            CHECK(num(json_array_get(ri, k), "max_relative_drift") ==
                  num(json_array_get(ti, k), "max_relative_drift"));
        CHECK(json_object_get(row, "cost") == NULL); /* measured time only under cost */
        printf("compare kepler run %zu %s: rel error %.3e, %g steps\n", i,
               json_string_value(json_object_get(row, "method")),
               num(row, "max_relative_position_error"), num(row, "steps"));
        total += num(row, "steps");
        json_decref(tr);
    }
    CHECK(num(cmp, "total_steps") == total);
    CHECK(json_object_get(cmp, "cost") == NULL); /* "cost": false */
    /* the chosen run keeps its promise */
    CHECK(num(json_array_get(rows, 2), "max_relative_position_error") < 1e-8);
    CHECK(num(json_array_get(rows, 3), "max_relative_position_error") < 1e-5);
    json_decref(cmp);

    /* The shared budget: enough for the first run only. The verlet run needs
     * 3000 steps (30 s / 0.01 s); with 3010 the rk8pd run leaves too few, and
     * verlet is refused before its first step. The finished run is answered,
     * the rest are marked not run, and the answer says it is partial. */
    json_t *full = post("/v1/compare", body, 10000000, &st);
    const double rk8pd_steps = num(json_array_get(json_object_get(full, "runs"), 0), "steps");
    CHECK(rk8pd_steps > 30 && rk8pd_steps <= 3010); /* it fits, verlet then cannot */
    CHECK(json_is_false(json_object_get(full, "partial")));
    cmp = post("/v1/compare", body, 3010, &st);
    CHECK_EQ_INT(st, 200);
    CHECK(json_is_true(json_object_get(cmp, "partial")));
    rows = json_object_get(cmp, "runs");
    CHECK_EQ_INT(json_array_size(rows), json_array_size(runs));
    CHECK(json_equal(json_array_get(rows, 0), json_array_get(json_object_get(full, "runs"), 0)));
    for (size_t i = 1; i < json_array_size(rows); i++) {
        json_t *row = json_array_get(rows, i);
        CHECK(!strcmp(json_string_value(json_object_get(row, "status")) ?: "", "not_run"));
        CHECK(json_equal(json_object_get(row, "requested"), json_array_get(runs, i)));
        const char *why = json_string_value(json_object_get(row, "reason"));
        CHECK(why && strstr(why, "step budget of 3010 steps"));
        CHECK(why && strstr(why, i == 1 ? "stopped" : "not started"));
        if (i > 1) CHECK(why && strstr(why, "during run 1 (/runs/1)"));
        CHECK(json_object_get(row, "max_position_error") == NULL);
    }
    /* verlet was refused up front: it took no step, and reached no time */
    json_t *prog1 = json_object_get(json_array_get(rows, 1), "progress");
    CHECK(num(prog1, "steps") == 0);
    CHECK(json_object_get(prog1, "t_reached") == NULL);
    CHECK(num(cmp, "total_steps") == rk8pd_steps);
    json_decref(cmp);
    json_decref(full);

    /* A partial answer depends on the budget: GET ?request= gives it no ETag
     * and no-store; the full answer is cacheable. */
    char *q = json_dumps(body, JSON_COMPACT | JSON_REAL_PRECISION(17));
    for (int partial = 1; partial >= 0; partial--) {
        struct api_request req = {"GET", "/v1/compare", NULL, NULL, 0, partial ? 3010 : 10000000,
                                  mech_clock_seconds() + 120, NULL};
        struct api_request_ext ext = {.query_request = q};
        struct api_response resp;
        api_handle_ext(&req, &ext, &resp);
        CHECK_EQ_INT(resp.status, 200);
        CHECK(partial == (strstr(resp.body ? resp.body : "", "\"partial\":true") != NULL));
        CHECK(partial ? resp.etag[0] == '\0' : resp.etag[0] == '"');
        CHECK(!strcmp(resp.cache_control ? resp.cache_control : "",
                      partial ? "no-store" : "public, max-age=86400"));
        api_response_free(&resp);
    }
    free(q);

    /* Nothing finished: 30 steps cannot take the first run (rk8pd, which
     * needs rk8pd_steps > 30) to its end: 422 naming it. */
    cmp = post("/v1/compare", body, 30, &st);
    CHECK_EQ_INT(st, 422);
    CHECK(!strcmp(json_string_value(json_object_get(cmp, "type")) ?: "",
                  "/problems/compute-budget-exceeded"));
    CHECK(!strcmp(json_string_value(json_object_get(cmp, "run")) ?: "", "/runs/0"));
    CHECK(strstr(json_string_value(json_object_get(cmp, "detail")) ?: "", "run 0") != NULL);
    json_t *prog = json_object_get(cmp, "progress");
    CHECK(num(prog, "steps") == num(prog, "run_steps")); /* exact reference: no other steps */
    CHECK(num(prog, "steps") >= 30);
    json_decref(cmp);
    json_decref(body);
    json_decref(runs);
    json_decref(request);
}

static void test_numerical_reference(void)
{
    /* central gravity + a uniform field: no exact reference */
    json_t *request = json_loads(
        "{\"particle\": {\"mass\": 1, \"position\": [1, 0, 0], \"velocity\": [0, 1, 0]}, "
        "\"forces\": [{\"type\": \"central_gravity\", \"gm\": 1}, {\"type\": "
        "\"uniform_gravity\", \"g\": [0.01, 0, 0]}], \"t_end\": 10, \"samples\": 21, \"stop\": "
        "{\"coordinate\": \"y\", \"crosses\": -0.5, \"direction\": \"decreasing\"}}",
        JSON_DECODE_INT_AS_REAL, NULL);
    json_t *sweep = json_loads("{\"methods\": [\"rk8pd\", \"yoshida4\", \"boris\"], "
                               "\"tolerances\": [1e-8], \"dts\": [0.01, 0.005]}",
                               JSON_DECODE_INT_AS_REAL, NULL);
    json_t *body = json_pack("{s:s,s:O,s:O}", "operation", "/v1/trajectory", "request", request,
                             "sweep", sweep);
    int st;
    json_t *cmp = post("/v1/compare", body, 10000000, &st);
    CHECK_EQ_INT(st, 200);
    json_t *ref = json_object_get(cmp, "reference");
    CHECK(!strcmp(json_string_value(json_object_get(ref, "kind")), "numerical"));
    CHECK(!strcmp(json_string_value(json_object_get(ref, "name")), "radau15"));
    json_t *rows = json_object_get(cmp, "runs");
    CHECK_EQ_INT(json_array_size(rows), 5);
    json_t *rblock = json_pack("{s:s,s:f,s:f}", "method", "radau15", "rtol", 1e-10, "atol", 0.0);
    json_t *rt = trajectory_with(request, rblock);
    json_t *rpos = json_object_get(rt, "position");
    CHECK(num(ref, "steps") == num(json_object_get(rt, "diagnostics"), "steps"));
    for (size_t i = 0; i < json_array_size(rows); i++) {
        json_t *row = json_array_get(rows, i);
        json_t *tr = trajectory_with(request, json_object_get(row, "requested"));
        json_t *pos = json_object_get(tr, "position");
        size_t n = json_array_size(pos) < json_array_size(rpos) ? json_array_size(pos)
                                                                : json_array_size(rpos);
        double mx = 0;
        for (size_t k = 0; k <= n; k++) {
            const json_t *a, *b;
            if (k < n) {
                a = json_array_get(pos, k);
                b = json_array_get(rpos, k);
            } else {
                a = json_object_get(json_object_get(tr, "stopped"), "position");
                b = json_object_get(json_object_get(rt, "stopped"), "position");
                if (!a || !b) break;
            }
            struct mech_vec3 d = mech_vec3_make(
                json_number_value(json_array_get(a, 0)) - json_number_value(json_array_get(b, 0)),
                json_number_value(json_array_get(a, 1)) - json_number_value(json_array_get(b, 1)),
                json_number_value(json_array_get(a, 2)) - json_number_value(json_array_get(b, 2)));
            mx = fmax(mx, mech_vec3_norm(d));
        }
        CHECK(num(row, "max_position_error") == mx);
        CHECK(num(row, "steps") == num(json_object_get(tr, "diagnostics"), "steps"));
        printf("compare numerical run %zu %s: max |dr| %.3e (recomputed %.3e)\n", i,
               json_string_value(json_object_get(row, "method")), num(row, "max_position_error"),
               mx);
        json_decref(tr);
    }
    json_t *cost = json_object_get(cmp, "cost");
    CHECK_EQ_INT(json_array_size(json_object_get(cost, "runs")), json_array_size(rows));
    CHECK(num(cost, "reference_cpu_seconds") >= 0 && num(cost, "cpu_seconds") > 0);

    /* Budget for the reference and 5 more steps: the reference finishes, the
     * first run (rk8pd, adaptive) stops after a few steps and nothing
     * finished: 422, and progress.steps counts the reference's steps too
     * (it used to say only the stopped run's). */
    const double ref_steps = num(ref, "steps");
    CHECK(ref_steps > 5);
    json_t *cmp2 = post("/v1/compare", body, (long)ref_steps + 5, &st);
    CHECK_EQ_INT(st, 422);
    CHECK(!strcmp(json_string_value(json_object_get(cmp2, "run")) ?: "", "/sweep"));
    json_t *prog = json_object_get(cmp2, "progress");
    CHECK(num(prog, "run_steps") > 0 && num(prog, "run_steps") <= 6);
    CHECK(num(prog, "steps") == ref_steps + num(prog, "run_steps"));
    json_decref(cmp2);

    json_decref(rt);
    json_decref(rblock);
    json_decref(cmp);
    json_decref(body);

    /* boris does not apply with drag: a failed row, the request still answers */
    json_array_append_new(json_object_get(request, "forces"),
                          json_pack("{s:s,s:f}", "type", "linear_drag", "b", 0.01));
    body = json_pack("{s:s,s:O,s:[{s:s,s:f},{s:s,s:f}]}", "operation", "/v1/trajectory",
                     "request", request, "runs", "method", "boris", "dt", 0.01, "method", "rk4",
                     "dt", 0.01);
    cmp = post("/v1/compare", body, 10000000, &st);
    CHECK_EQ_INT(st, 200);
    rows = json_object_get(cmp, "runs");
    CHECK(!strcmp(json_string_value(json_object_get(json_array_get(rows, 0), "status")), "failed"));
    CHECK(!strcmp(json_string_value(json_object_get(json_array_get(rows, 1), "status")), "ok"));
    json_decref(cmp);
    json_decref(body);
    json_decref(sweep);
    json_decref(request);
}

static void test_validation(void)
{
    const char *bad[] = {
        /* both runs and sweep */
        "{\"operation\": \"/v1/trajectory\", \"request\": %s, \"runs\": [{\"method\": \"rk4\", "
        "\"dt\": 0.1}], \"sweep\": {\"methods\": [\"rk4\"], \"dts\": [0.1]}}",
        /* neither */
        "{\"operation\": \"/v1/trajectory\", \"request\": %s}",
        /* a fixed-step method in a sweep without dts */
        "{\"operation\": \"/v1/trajectory\", \"request\": %s, \"sweep\": {\"methods\": "
        "[\"rk4\"], \"tolerances\": [1e-6]}}",
        /* 14 methods x 16 dts > 64 runs */
        "{\"operation\": \"/v1/trajectory\", \"request\": %s, \"sweep\": {\"methods\": "
        "[\"rk4\", \"verlet\", \"euler\", \"gauss4\", \"gauss6\"], \"dts\": [1, 2, 3, 4, 5, 6, 7, "
        "8, 9, 10, 11, 12, 13, 14, 15, 16]}}",
        /* an unknown operation */
        "{\"operation\": \"/v1/rigid/inertia\", \"request\": %s, \"runs\": [{\"method\": \"rk4\", "
        "\"dt\": 0.1}]}",
        /* a bad scene */
        "{\"operation\": \"/v1/trajectory\", \"request\": {\"particle\": {\"mass\": 1, "
        "\"position\": [0, 0, 0], \"velocity\": [0, 1, 0]}, \"forces\": [{\"type\": "
        "\"central_gravity\", \"gm\": 1}], \"t_end\": 1}%s, \"runs\": [{\"method\": \"rk4\", "
        "\"dt\": 0.1}]}",
    };
    const char *want_ptr[] = {"/sweep", "", "/sweep/dts", "/sweep", "/operation",
                              "/request/particle/position"};
    for (int i = 0; i < 6; i++) {
        char text[2048];
        snprintf(text, sizeof text, bad[i], i == 5 ? "" : kepler_request);
        json_t *b = json_loads(text, JSON_DECODE_INT_AS_REAL, NULL);
        CHECK(b != NULL);
        int st;
        json_t *r = post("/v1/compare", b, 10000000, &st);
        CHECK_EQ_INT(st, 422);
        const char *p = json_string_value(
            json_object_get(json_array_get(json_object_get(r, "errors"), 0), "pointer"));
        if (!p || strcmp(p, want_ptr[i])) printf("case %d: pointer %s, want %s\n", i, p ? p : "(none)", want_ptr[i]);
        CHECK(p && !strcmp(p, want_ptr[i]));
        json_decref(r);
        json_decref(b);
    }
}

/* The deadline, deterministically: already passed when the request starts,
 * so the first run meets it at its first check and no run finished: still
 * the 422, naming the run, with no step taken. (A partial answer under the
 * deadline takes the same path as under the step budget, tested above; a
 * deadline that passes between two runs is a matter of timing.) */
static void test_deadline_nothing_finished(void)
{
    char *text = NULL;
    json_t *body = json_pack("{s:s,s:o,s:[{s:s,s:f}],s:b}", "operation", "/v1/trajectory",
                             "request", json_loads(kepler_request, JSON_DECODE_INT_AS_REAL, NULL),
                             "runs", "method", "rk4", "dt", 0.01, "cost", 0);
    text = json_dumps(body, JSON_COMPACT);
    struct api_request req = {"POST", "/v1/compare", "application/json", text, strlen(text),
                              10000000, mech_clock_seconds() - 1, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    CHECK_EQ_INT(resp.status, 422);
    json_t *r = json_loads(resp.body ? resp.body : "", JSON_DECODE_INT_AS_REAL, NULL);
    api_response_free(&resp);
    free(text);
    CHECK(!strcmp(json_string_value(json_object_get(r, "run")) ?: "", "/runs/0"));
    json_t *prog = json_object_get(r, "progress");
    CHECK(!strcmp(json_string_value(json_object_get(prog, "limit")) ?: "", "deadline"));
    CHECK(json_is_number(json_object_get(prog, "steps")) && num(prog, "steps") == 0);
    json_decref(r);
    json_decref(body);
}

/* GET /v1/integrators: every registered method, the presets, and the method
 * lists of the request schema equal the registry's adaptive / fixed split. */
static void test_integrators_catalog(void)
{
    json_t *cat = api_integrators_catalog();
    json_t *ms = json_object_get(cat, "methods");
    CHECK_EQ_INT(json_array_size(ms), mech_ode_method_count());
    CHECK_EQ_INT(json_array_size(ms), 16); /* with wisdom_holman(_corrected) */
    /* The method lists of /v1/trajectory's integrator block (its data file,
     * api/ops/frames/trajectory.json): oneOf[0] adaptive, oneOf[1] fixed-step. */
    const json_t *schema = NULL;
    for (size_t i = 0; i < api_route_count; i++)
        if (!strcmp(api_routes[i]->path, "/v1/trajectory")) schema = api_route_schema(i);
    const json_t *branches = json_object_get(
        json_object_get(json_object_get(schema, "properties"), "integrator"), "oneOf");
    json_t *adaptive = json_incref(json_object_get(
        json_object_get(json_object_get(json_array_get(branches, 0), "properties"), "method"),
        "enum"));
    json_t *fixed = json_incref(json_object_get(
        json_object_get(json_object_get(json_array_get(branches, 1), "properties"), "method"),
        "enum"));
    CHECK(json_array_size(adaptive) > 0 && json_array_size(fixed) > 0);
    CHECK_EQ_INT(json_array_size(adaptive) + json_array_size(fixed), mech_ode_method_count());
    for (size_t i = 0; i < json_array_size(ms); i++) {
        json_t *m = json_array_get(ms, i);
        const char *name = json_string_value(json_object_get(m, "name"));
        struct mech_ode_method_info mi = mech_ode_method_describe(mech_ode_method_find(name));
        CHECK_EQ_INT((int)json_integer_value(json_object_get(m, "order")), mi.order);
        CHECK(json_is_true(json_object_get(m, "adaptive")) == !!mi.adaptive);
        CHECK(strlen(json_string_value(json_object_get(m, "doc"))) > 20);
        CHECK(strlen(json_string_value(json_object_get(m, "reference"))) > 5);
        json_t *list = mi.adaptive ? adaptive : fixed;
        int found = 0;
        for (size_t k = 0; k < json_array_size(list); k++)
            found |= !strcmp(json_string_value(json_array_get(list, k)), name);
        if (!found) printf("method %s missing from the schema's list\n", name);
        CHECK(found);
    }
    CHECK_EQ_INT(json_array_size(json_object_get(cat, "accuracy_presets")), 4);
    /* once the API serves it, GET /v1/integrators returns the same document */
    struct api_request req = {"GET", "/v1/integrators", NULL, NULL, 0, 1000,
                              mech_clock_seconds() + 10, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    CHECK_EQ_INT(resp.status, 200);
    json_t *got = resp.body ? json_loads(resp.body, 0, NULL) : NULL;
    CHECK(got && json_equal(got, cat));
    json_decref(got);
    api_response_free(&resp);
    json_decref(adaptive);
    json_decref(fixed);
    json_decref(cat);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK(api_init() == 0);
    test_exact_scene();
    test_numerical_reference();
    test_validation();
    test_deadline_nothing_finished();
    test_integrators_catalog();
    TEST_MAIN_END();
}
