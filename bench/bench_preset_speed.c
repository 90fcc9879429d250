/* bench_preset_speed.c — what one preset request costs through the API, and
 * machine / draft per scene, quickly (a few seconds; bench_chooser_regret
 * prints the same ratio beside the whole hindsight sweep, in minutes).
 *
 * The scenes are the integrating scenes of bench_chooser_regret (the same
 * request bodies, "closed_form": false). For each, draft and machine are
 * posted through api_handle() in-process, interleaved, and the least thread
 * CPU of the rounds is kept; evaluations are the answer's (pilot included).
 * Printed: per scene draft and machine evaluations and CPU, machine / draft
 * CPU, and the geometric mean; and the fixed cost per request, measured as a
 * trajectory of 2 samples over a tiny span (Kepler, t_end = 1e-3 of a period:
 * a handful of steps), which is what every request pays before and after its
 * integration.
 *
 * Measures, never asserts. Usage: bench_preset_speed [OUT_DIR] (ignored).
 * Environment: MECHD_BENCH_ROUNDS (default 7); MECHD_BENCH_ONLY = "<scene
 * index>-<preset>" (e.g. "0-draft", "fixed-draft") posts that request once,
 * twice, for callgrind (valgrind --tool=callgrind --toggle-collect=handle_measured
 * build/bench_preset_speed counts the second).
 */
#define _GNU_SOURCE
#include <gsl/gsl_errno.h>
#include <time.h>

#include "../tests/api/scene_set.h"

struct pscene {
    const char *name, *path, *body;
};

#define TRJ(NAME, BODY) {NAME, "/v1/trajectory", BODY}
static const struct pscene PS[] = {
    TRJ("Kepler e=0.5, 10 orbits",
        "{\"particle\":{\"mass\":1,\"position\":[0.5,0,0],\"velocity\":[0,1.7320508075688772,0]},"
        "\"forces\":[{\"type\":\"central_gravity\",\"gm\":1}],\"t_end\":62.831853071795862,"
        "\"samples\":101}"),
    TRJ("Kepler e=0.9, 10 orbits",
        "{\"particle\":{\"mass\":1,\"position\":[0.09999999999999998,0,0],\"velocity\":[0,"
        "4.358898943540674,0]},\"forces\":[{\"type\":\"central_gravity\",\"gm\":1}],"
        "\"t_end\":62.831853071795862,\"samples\":101}"),
    TRJ("oscillator 2-D, 100 periods",
        "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0.5,0]},"
        "\"forces\":[{\"type\":\"spring\",\"k\":1}],\"t_end\":628.31853071795865,\"samples\":101}"),
    TRJ("oscillator 1-D, 100 periods",
        "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0,0]},"
        "\"forces\":[{\"type\":\"spring\",\"k\":1}],\"t_end\":628.31853071795865,\"samples\":101}"),
    TRJ("oscillator, rotating frame, 20 periods",
        "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0.5,0]},"
        "\"frame\":{\"type\":\"rotating\",\"omega\":[0,0,0.3]},"
        "\"fictitious\":[\"coriolis\",\"centrifugal\"],\"forces\":[{\"type\":\"spring\",\"k\":1}],"
        "\"t_end\":125.66370614359172,\"samples\":101}"),
    TRJ("charge in B, 20 gyrations",
        "{\"particle\":{\"mass\":1,\"charge\":1,\"position\":[1,0,0],\"velocity\":[0,-1,0]},"
        "\"forces\":[{\"type\":\"lorentz\",\"E\":[0,0,0],\"B\":[0,0,1]}],"
        "\"t_end\":125.66370614359172,\"samples\":101}"),
    {"rigid body 1:2:3, 100 s", "/v1/rigid/rotate",
     "{\"moments\":[1,2,3],\"omega\":[0.05,1,0.05],\"t_end\":100,\"samples\":11}"},
    {"heavy top 5 s", "/v1/rigid/top",
     "{\"I1\":0.02,\"I3\":0.01,\"mass\":1.0,\"distance\":0.1,\"theta\":1.0471975511965976,"
     "\"phi_dot\":0.99,\"psi_dot\":99.5,\"t_end\":5,\"samples\":11}"},
    {"Mercury geodesic 10 orbits", "/v1/gr/geodesic",
     "{\"M\":\"sun\",\"kind\":\"timelike\",\"initial\":{\"semi_major_axis\":57909050000.0,"
     "\"eccentricity\":0.20563593},\"orbits\":10,\"samples\":11}"},
    {"light, b = 5.2 M (strong)", "/v1/gr/geodesic",
     "{\"units\":\"geometric\",\"kind\":\"null\",\"initial\":{\"impact_parameter\":5.2,"
     "\"radial_direction\":\"inward\"},\"samples\":11}"},
    {"pendulum flow, 2.5 rad, 100 s", "/v1/hamiltonian/flow",
     "{\"system\":{\"name\":\"pendulum\",\"mass\":1,\"length\":1},\"q\":[2.5],\"p\":[0],"
     "\"t_end\":100,\"samples\":11}"},
    {"Henon-Heiles 1000", "/v1/hamiltonian/flow",
     "{\"system\":{\"name\":\"henon_heiles\"},\"q\":[0,0],\"p\":[0.1,0],\"t_end\":1000,"
     "\"samples\":11}"},
};
enum { NPS = sizeof PS / sizeof *PS };

/* a request paying the fixed cost and almost no integration */
static const struct pscene FIXED = TRJ(
    "fixed cost: Kepler, 1e-3 period, 2 samples",
    "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,1,0]},"
    "\"forces\":[{\"type\":\"central_gravity\",\"gm\":1}],\"t_end\":0.0062831853071795862,"
    "\"samples\":2}");

static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct one {
    int ok;
    double cpu, evals;
    char method[16];
};

/* api_handle, as the function callgrind measures (--toggle-collect=handle_measured) */
static __attribute__((noinline)) void handle_measured(const struct api_request *req,
                                                      struct api_response *resp)
{
    api_handle(req, resp);
}

static struct one post_once(const struct pscene *s, const char *preset, int measured)
{
    struct one o = {0, INFINITY, 0, "?"};
    json_t *b = json_loads(s->body, JSON_DECODE_INT_AS_REAL, NULL);
    json_object_set_new(b, "integrator", json_pack("{sssb}", "accuracy", preset, "closed_form", 0));
    char *text = json_dumps(b, JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(b);
    struct api_request req = {"POST", s->path, "application/json", text, strlen(text), 200000000,
                              mech_clock_seconds() + 300, NULL};
    struct api_response resp;
    const double c0 = thread_cpu();
    if (measured) handle_measured(&req, &resp);
    else api_handle(&req, &resp);
    o.cpu = thread_cpu() - c0;
    free(text);
    if (resp.status == 200) {
        json_t *a = json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL);
        const json_t *d = json_object_get(a, "diagnostics");
        o.evals = json_number_value(json_object_get(d, "rhs_evaluations"));
        const json_t *pil = at(a, "diagnostics/selection/pilot/evaluations");
        if (json_is_number(pil)) o.evals += json_number_value(pil);
        const char *m = json_string_value(json_object_get(d, "method"));
        snprintf(o.method, sizeof o.method, "%s", m ? m : "?");
        o.ok = 1;
        json_decref(a);
    } else {
        fprintf(stderr, "%s %s -> %d: %.300s\n", s->name, preset, resp.status, resp.body);
    }
    api_response_free(&resp);
    return o;
}

int main(int argc, char **argv)
{
    (void)argc, (void)argv;
    gsl_set_error_handler_off();
    api_install_json_allocator();
    if (api_init()) return 1;
    const char *er = getenv("MECHD_BENCH_ROUNDS"), *only = getenv("MECHD_BENCH_ONLY");
    int rounds = er ? atoi(er) : 7;
    if (rounds < 1) rounds = 1;
    if (only) {
        const char *dash = strchr(only, '-');
        if (!dash) return 2;
        const struct pscene *s = !strncmp(only, "fixed", 5) ? &FIXED : &PS[atoi(only) % NPS];
        post_once(s, dash + 1, 0); /* the thread's one-time set-up */
        struct one o = post_once(s, dash + 1, 1);
        printf("%s %s: %s, %.0f evaluations, %.3f ms\n", s->name, dash + 1, o.method, o.evals,
               o.cpu * 1e3);
        return o.ok ? 0 : 1;
    }
    double fixed = INFINITY;
    for (int r = 0; r < 3 * rounds; r++) fixed = fmin(fixed, post_once(&FIXED, "draft", 0).cpu);
    printf("# presets through api_handle (in-process), least thread CPU of %d rounds\n", rounds);
    printf("# fixed cost per request (%s): %.1f µs\n", FIXED.name, fixed * 1e6);
    printf("| scene | draft | machine | machine / draft |\n|---|---|---|---|\n");
    double gsum = 0.0;
    int gn = 0;
    for (int i = 0; i < NPS; i++) {
        struct one best[2];
        static const char *const pr[2] = {"draft", "machine"};
        for (int k = 0; k < 2; k++) best[k] = (struct one){0, INFINITY, 0, "?"};
        for (int r = 0; r < rounds; r++)
            for (int k = 0; k < 2; k++) {
                struct one o = post_once(&PS[i], pr[k], 0);
                if (o.ok && o.cpu < best[k].cpu) best[k] = o;
            }
        const double ratio = best[1].cpu / best[0].cpu;
        printf("| %s | %s %.0f, %.3f ms | %s %.0f, %.3f ms | %.2f× |\n", PS[i].name, best[0].method,
               best[0].evals, best[0].cpu * 1e3, best[1].method, best[1].evals, best[1].cpu * 1e3,
               ratio);
        if (best[0].ok && best[1].ok) {
            gsum += log(ratio);
            gn++;
        }
    }
    printf("# geometric mean machine / draft: %.2f× over %d scenes\n", exp(gsum / gn), gn);
    return 0;
}
