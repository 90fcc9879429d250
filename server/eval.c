/* eval.c — `mechd eval` (see eval.h): one request through api_handle_ext()
 * with no network, printing exactly the body the server would send. */
#include "eval.h"

#include <errno.h>
#include <jansson.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"

#define EVAL_MAX_INPUT (64L * 1024 * 1024) /* bytes read from FILE or stdin */

void srv_eval_usage(FILE *out)
{
    fprintf(out,
            "Usage: mechd eval [--operation=PATH] [--cost] [--max-steps=N] [--deadline-ms=N] "
            "[FILE]\n"
            "Answer one request offline (no network) and print exactly the body the server\n"
            "would send for GET PATH?request=... (the same bytes as POST without cost).\n"
            "FILE (default: stdin) holds {\"operation\": \"/v1/...\", \"request\": {...}},\n"
            "or, with --operation, the bare request body.\n"
            "  --operation=PATH  the operation, e.g. /v1/rigid/inertia (or --operation PATH)\n"
            "  --cost            keep the measured cost (cpu_seconds) in the answer\n"
            "  --max-steps=N     step budget per integration (default 10000000)\n"
            "  --deadline-ms=N   wall-clock budget in ms (default 10000)\n"
            "Exit status: 0 answer printed; 1 the request was refused (4xx problem+json\n"
            "printed on stdout, also when the input is not JSON: 400 malformed-json naming\n"
            "the input); 3 server-side failure (5xx problem+json); 2 usage error.\n");
}

static char *read_all(FILE *f, size_t *len)
{
    size_t cap = 4096, n = 0;
    char *b = malloc(cap + 1);
    if (!b) return NULL;
    for (;;) {
        if (n == cap) {
            if (cap >= (size_t)EVAL_MAX_INPUT) { free(b); errno = EFBIG; return NULL; }
            char *nb = realloc(b, cap * 2 + 1);
            if (!nb) { free(b); return NULL; }
            b = nb;
            cap *= 2;
        }
        size_t got = fread(b + n, 1, cap - n, f);
        n += got;
        if (got == 0) break;
    }
    if (ferror(f)) { free(b); return NULL; }
    b[n] = '\0';
    *len = n;
    return b;
}

/* The input is not JSON: print a 400 malformed-json problem naming the input
 * (FILE or stdin) and where jansson stopped, as the server names its body;
 * instance is the operation when it is known. Returns exit status 1 (a
 * refused request, like any other problem: not a usage error). */
static int malformed_input(const char *file, const char *operation, const json_error_t *jerr,
                           FILE *out)
{
    char detail[512]; /* room for the longest: 200 bytes of file name + jansson's 160 */
    int named = file && strcmp(file, "-");
    snprintf(detail, sizeof detail, "the input (%s%.200s) is not valid JSON: line %d, column %d: %s",
             named ? "file " : "standard input", named ? file : "", jerr->line, jerr->column,
             jerr->text);
    struct api_response resp;
    memset(&resp, 0, sizeof resp);
    api_response_problem(&resp, API_PROBLEM_MALFORMED_JSON, detail);
    if (operation) api_response_set_instance(&resp, operation);
    if (resp.body) fwrite(resp.body, 1, resp.body_len, out);
    fflush(out);
    api_response_free(&resp);
    return 1;
}

static int parse_long(const char *s, long min, long max, long *out)
{
    if (!s || !*s) return -1;
    errno = 0;
    char *end = NULL;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < min || v > max) return -1;
    *out = v;
    return 0;
}

/* Value of --name=VALUE or --name VALUE at argv[*i]; NULL if argv[*i] is not it. */
static const char *opt_value(int argc, char **argv, int *i, const char *name, int *missing)
{
    size_t n = strlen(name);
    if (strncmp(argv[*i], name, n)) return NULL;
    if (argv[*i][n] == '=') return argv[*i] + n + 1;
    if (argv[*i][n] != '\0') return NULL;
    if (*i + 1 >= argc) { *missing = 1; return NULL; }
    return argv[++*i];
}

int srv_eval_main(int argc, char **argv, FILE *in, FILE *out, FILE *err)
{
    const char *operation = NULL, *file = NULL;
    int cost = 0;
    long max_steps = 10000000, deadline_ms = 10000;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int missing = 0;
        if (!strcmp(argv[i], "--help")) {
            srv_eval_usage(out);
            return 0;
        } else if (!strcmp(argv[i], "--cost")) {
            cost = 1;
        } else if ((v = opt_value(argc, argv, &i, "--operation", &missing))) {
            operation = v;
        } else if ((v = opt_value(argc, argv, &i, "--max-steps", &missing))) {
            if (parse_long(v, 1, 1000000000000L, &max_steps)) {
                fprintf(err, "mechd eval: invalid --max-steps '%s'\n", v);
                return 2;
            }
        } else if ((v = opt_value(argc, argv, &i, "--deadline-ms", &missing))) {
            if (parse_long(v, 1, 86400000L, &deadline_ms)) {
                fprintf(err, "mechd eval: invalid --deadline-ms '%s'\n", v);
                return 2;
            }
        } else if (missing) {
            fprintf(err, "mechd eval: %s needs a value\n", argv[i]);
            return 2;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(err, "mechd eval: unknown option '%s' (see mechd eval --help)\n", argv[i]);
            return 2;
        } else if (!file) {
            file = argv[i];
        } else {
            fprintf(err, "mechd eval: more than one FILE given\n");
            return 2;
        }
    }

    FILE *f = in;
    if (file && strcmp(file, "-")) {
        f = fopen(file, "rb");
        if (!f) {
            fprintf(err, "mechd eval: cannot open %s: %s\n", file, strerror(errno));
            return 2;
        }
    }
    size_t len = 0;
    char *text = read_all(f, &len);
    if (f != in) fclose(f);
    if (!text) {
        fprintf(err, "mechd eval: cannot read the request: %s\n", strerror(errno));
        return 2;
    }

    /* The server's GET path takes the request as JSON text: pass it through
     * unchanged (bare form) or re-serialised from the envelope. */
    char *request_text = NULL;
    char *path = NULL;
    json_error_t jerr;
    if (operation) {
        /* Checked here so that the problem names the input, not the server's
         * "request query parameter" the text is handed to below. */
        json_t *probe =
            json_loadb(text, len, JSON_DECODE_ANY | JSON_DECODE_INT_AS_REAL | JSON_REJECT_DUPLICATES,
                       &jerr);
        if (!probe) {
            free(text);
            return malformed_input(file, operation, &jerr, out);
        }
        json_decref(probe);
        request_text = text;
        path = strdup(operation);
    } else {
        json_t *env = json_loadb(text, len, JSON_DECODE_INT_AS_REAL | JSON_REJECT_DUPLICATES,
                                 &jerr);
        if (!env) {
            free(text);
            return malformed_input(file, NULL, &jerr, out);
        }
        const char *op = env ? json_string_value(json_object_get(env, "operation")) : NULL;
        json_t *rq = env ? json_object_get(env, "request") : NULL;
        if (!env || !op || !rq || json_object_size(env) != 2) {
            fprintf(err, "mechd eval: without --operation the input must be {\"operation\": "
                         "\"/v1/...\", \"request\": {...}}\n");
            json_decref(env);
            free(text);
            return 2;
        }
        path = strdup(op);
        request_text = json_dumps(rq, JSON_COMPACT | JSON_REAL_PRECISION(17) | JSON_ENCODE_ANY);
        json_decref(env);
        free(text);
        text = NULL;
    }
    if (!path || !request_text) {
        fprintf(err, "mechd eval: out of memory\n");
        free(path);
        if (request_text != text) free(request_text);
        free(text);
        return 2;
    }

    static const volatile int never = 0;
    struct api_request req;
    memset(&req, 0, sizeof req);
    req.method = "GET";
    req.path = path;
    req.max_steps = max_steps;
    req.deadline = mech_clock_seconds() + (double)deadline_ms / 1000.0;
    req.cancel = &never;
    struct api_request_ext ext;
    memset(&ext, 0, sizeof ext);
    ext.query_request = request_text;
    ext.no_cost = !cost;
    /* --cost: run as the server runs a POST (the cost is measured). */
    if (cost) {
        req.method = "POST";
        req.content_type = "application/json";
        req.body = request_text;
        req.body_len = strlen(request_text);
        ext.query_request = NULL;
    }
    struct api_response resp;
    api_handle_ext(&req, &ext, &resp);
    if (resp.body) fwrite(resp.body, 1, resp.body_len, out);
    fflush(out);
    int status = resp.status;
    api_response_free(&resp);
    if (request_text != text) free(request_text);
    free(text);
    free(path);
    if (status >= 200 && status < 300) return 0;
    if (status >= 400 && status < 500) return 1;
    return 3;
}
