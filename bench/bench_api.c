/* bench_api.c — cost of each operation's catalog example through
 * api_handle(), in-process, against a baseline measured in the same run:
 * parsing and re-serialising the same request body with jansson (the floor
 * any JSON endpoint pays). Prints µs per request and the ratio; figures vary
 * 15-40 % between runs on shared machines, the ratio much less.
 * Run: make bench (or build/bench_api [seconds-per-case]). Never part of the tests. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jansson.h>

#include "api.h"
#include "mech/base/budget.h"
#include "run/routes.h"

static double per_call(double seconds, void (*fn)(const struct api_route *), const struct api_route *r)
{
    long n = 0;
    double t0 = mech_clock_seconds(), t;
    do {
        for (int i = 0; i < 16; i++) fn(r);
        n += 16;
        t = mech_clock_seconds() - t0;
    } while (t < seconds);
    return t / (double)n;
}

static void baseline(const struct api_route *r)
{
    json_t *j = json_loads(r->example, JSON_DECODE_INT_AS_REAL, NULL);
    char *s = json_dumps(j, JSON_COMPACT | JSON_REAL_PRECISION(17));
    free(s);
    json_decref(j);
}

static void handle(const struct api_route *r)
{
    struct api_request req = {"POST", r->path, "application/json", r->example, strlen(r->example),
                              10000000, mech_clock_seconds() + 60, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    if (resp.status != 200) fprintf(stderr, "%s: status %d\n", r->path, resp.status);
    api_response_free(&resp);
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    /* argv[1]: seconds per case, or `make bench`'s output directory (ignored). */
    char *end = NULL;
    double seconds = argc > 1 ? strtod(argv[1], &end) : 0.5;
    if (argc > 1 && (end == argv[1] || *end || !(seconds > 0))) seconds = 0.5;
    if (api_init()) return 1;
    printf("%-24s %14s %14s %10s\n", "operation (example)", "api_handle µs", "baseline µs", "ratio");
    for (size_t i = 0; i < api_route_count; i++) {
        if (!api_routes[i]->example) continue; /* GET resources */
        double b = per_call(seconds, baseline, api_routes[i]);
        double h = per_call(seconds, handle, api_routes[i]);
        printf("%-24s %14.2f %14.2f %10.1f\n", api_routes[i]->path, h * 1e6, b * 1e6, h / b);
    }
    return 0;
}
