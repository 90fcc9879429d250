/* call.c — what endpoints use to report errors, encode results and read
 * schema-validated input (see api/run/endpoint.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "run/api_run.h"
#include "run/endpoint.h"
#include "http/respond.h"

static void add_error(struct api_call *c, enum api_problem kind, const char *pointer,
                      const char *fmt, va_list ap)
{
    char detail[400];
    vsnprintf(detail, sizeof detail, fmt, ap);
    /* Validation outranks domain: a request with both is reported as invalid. */
    if (c->problem == API_PROBLEM_NONE || (c->problem == API_PROBLEM_DOMAIN &&
                                           kind == API_PROBLEM_VALIDATION))
        c->problem = kind;
    if (!c->errors) c->errors = json_array();
    if (c->errors && json_array_size(c->errors) < 20)
        json_array_append_new(c->errors, api_error_entry(pointer, detail));
}

/* The value at a JSON pointer in root, or NULL. */
static const json_t *pointer_get(const json_t *v, const char *pointer)
{
    const char *p = pointer ? pointer : "";
    while (v && *p == '/') {
        p++;
        char tok[128];
        size_t n = 0;
        for (; *p && *p != '/'; p++) {
            char ch = *p;
            if (ch == '~' && (p[1] == '0' || p[1] == '1')) ch = *++p == '0' ? '~' : '/';
            if (n + 1 >= sizeof tok) return NULL; /* no key of a route schema is this long */
            tok[n++] = ch;
        }
        tok[n] = '\0';
        if (json_is_object(v)) {
            v = json_object_get(v, tok);
        } else if (json_is_array(v)) {
            char *end;
            unsigned long i = strtoul(tok, &end, 10);
            v = n && *end == '\0' ? json_array_get(v, i) : NULL;
        } else {
            v = NULL;
        }
    }
    return *p ? NULL : v;
}

const json_t *api_call_given(const struct api_call *c, const char *pointer)
{
    return c ? pointer_get(c->given, pointer) : NULL;
}

const json_t *api_call_as_given(const struct api_call *c, const json_t *value,
                                const char *pointer)
{
    if (!c || !value || !c->body || pointer_get(c->body, pointer) != value) return value;
    const json_t *g = pointer_get(c->given, pointer);
    return g ? g : value;
}

int api_call_cost_gate(struct api_call *c, double predicted_cpu_s)
{
    if (!c || !c->gated) return 0;
    c->gated = 0;
    struct api_full_request *req = c->req;
    if (!req || !req->gate || !req->gate(req->gate_ctx, predicted_cpu_s)) return 0;
    req->deferred = 1;
    return 1;
}

void api_call_invalid(struct api_call *c, const char *pointer, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    add_error(c, API_PROBLEM_VALIDATION, pointer, fmt, ap);
    va_end(ap);
}

void api_call_domain(struct api_call *c, const char *pointer, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    add_error(c, API_PROBLEM_DOMAIN, pointer, fmt, ap);
    va_end(ap);
}

static void set_problem(struct api_call *c, enum api_problem kind, const char *text)
{
    if (c->problem == API_PROBLEM_NONE) c->problem = kind;
    snprintf(c->detail, sizeof c->detail, "%s", text);
}

json_t *api_call_fail_core(struct api_call *c, enum mech_status st,
                           const struct mech_error *e, const char *pointer_prefix)
{
    const char *text = e && e->text[0] ? e->text : mech_status_name(st);
    char pointer[256];
    snprintf(pointer, sizeof pointer, "%s%s%s", pointer_prefix ? pointer_prefix : "",
             e && e->param[0] ? "/" : "", e && e->param[0] ? e->param : "");
    switch (st) {
    case MECH_EINVAL:
        api_call_invalid(c, pointer, "%s", text);
        break;
    case MECH_EDOMAIN:
        api_call_domain(c, pointer, "%s", text);
        break;
    case MECH_EBUDGET:
    case MECH_EDEADLINE: {
        set_problem(c, API_PROBLEM_BUDGET, text);
        json_t *prog = json_object();
        if (prog && e) {
            json_object_set_new_nocheck(prog, "limit",
                                        json_string(st == MECH_EBUDGET ? "max_steps" : "deadline"));
            json_object_set_new_nocheck(prog, "steps", json_integer(e->progress.steps));
            if (isfinite(e->progress.t_reached))
                json_object_set_new_nocheck(prog, "t_reached", json_real(e->progress.t_reached));
            if (isfinite(e->progress.t_target))
                json_object_set_new_nocheck(prog, "t_target", json_real(e->progress.t_target));
            if (isfinite(e->progress.t_reached) && isfinite(e->progress.t_target) &&
                e->progress.t_target != 0)
                json_object_set_new_nocheck(
                    prog, "fraction_done", json_real(e->progress.t_reached / e->progress.t_target));
        }
        if (!c->extra) c->extra = json_object();
        if (c->extra && prog)
            json_object_set_new_nocheck(c->extra, "progress", prog);
        else json_decref(prog);
        break;
    }
    case MECH_ECANCELLED:
        set_problem(c, API_PROBLEM_CANCELLED, text);
        break;
    case MECH_ENUMERIC:
        set_problem(c, API_PROBLEM_NUMERIC, text);
        /* Name the input that led there when the core knows it. */
        if (e && e->param[0]) {
            if (!c->errors) c->errors = json_array();
            if (c->errors && json_array_size(c->errors) < 20)
                json_array_append_new(c->errors, api_error_entry(pointer, text));
        }
        break;
    default:
        set_problem(c, API_PROBLEM_INTERNAL, "internal error");
        break;
    }
    return NULL;
}

json_t *api_real(struct api_call *c, double x)
{
    if (!isfinite(x)) {
        c->nonfinite = 1;
        return json_null();
    }
    /* Normalise -0 to 0 so answers do not differ by the sign of zero. */
    return json_real(x == 0 ? 0.0 : x);
}

json_t *api_reals(struct api_call *c, const double *x, size_t n)
{
    json_t *a = json_array();
    for (size_t i = 0; a && i < n; i++) json_array_append_new(a, api_real(c, x[i]));
    return a;
}

json_t *api_vec3(struct api_call *c, struct mech_vec3 v)
{
    double x[3] = {v.x, v.y, v.z};
    return api_reals(c, x, 3);
}

json_t *api_mat3(struct api_call *c, struct mech_mat3 m)
{
    json_t *a = json_array();
    for (int i = 0; a && i < 3; i++) json_array_append_new(a, api_reals(c, m.a[i], 3));
    return a;
}

double api_number(const json_t *obj, const char *key, double def)
{
    const json_t *v = json_object_get(obj, key);
    return json_is_number(v) ? json_number_value(v) : def;
}

double api_number_of(const json_t *obj, const char *key)
{
    const json_t *v = json_object_get(obj, key);
    return json_is_number(v) ? json_number_value(v) : NAN;
}

const char *api_string_of(const json_t *obj, const char *key)
{
    const json_t *v = json_object_get(obj, key);
    return json_is_string(v) ? json_string_value(v) : "";
}

struct mech_vec3 api_vec3_of(const json_t *a)
{
    return mech_vec3_make(json_number_value(json_array_get(a, 0)),
                          json_number_value(json_array_get(a, 1)),
                          json_number_value(json_array_get(a, 2)));
}

struct mech_vec3 api_vec3_member(const json_t *obj, const char *key, struct mech_vec3 def)
{
    const json_t *a = json_object_get(obj, key);
    return json_is_array(a) ? api_vec3_of(a) : def;
}

const char *api_string(const json_t *obj, const char *key, const char *def)
{
    const json_t *v = json_object_get(obj, key);
    return json_is_string(v) ? json_string_value(v) : def;
}

json_t *api_call_out_of_memory(struct api_call *c, json_t *partial)
{
    struct mech_error e;
    json_decref(partial);
    mech_error_clear(&e);
    mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
    return api_call_fail_core(c, MECH_ENOMEM, &e, "");
}
