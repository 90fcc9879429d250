/* test_schema.c — the JSON Schema subset validator: each keyword accepts what
 * it should, rejects what it should, and names the right JSON pointer; the
 * compiled validator (api/schema_*.c) gives exactly the errors — count, pointer,
 * detail, order — of a reference interpreter kept below (the interpreter mechd
 * used before schemas were compiled: it walks the schema's jansson objects;
 * for a oneOf that matches no branch it applies the rules of api/schema/schema.h, written
 * again from the json_t), over every route schema with its catalog example
 * and hundreds of mutated copies each, and the comparison must meet each way
 * of reporting such a oneOf; hand-derived messages pin the texts themselves. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "api.h"
#include "catalog/catalog.h"
#include "http/respond.h"
#include "run/routes.h"
#include "schema/schema.h"
#include "testlib.h"

/* ==== reference interpreter (test only) =====================================
 * Straight from the schema's json_t on every call; same messages. */

#define REF_PTR_MAX 512

struct rctx {
    json_t *errors;
    size_t count;
};

static void ref_error(struct rctx *v, const char *pointer, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void ref_error(struct rctx *v, const char *pointer, const char *fmt, ...)
{
    v->count++;
    if (!v->errors || json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) return;
    char detail[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    json_array_append_new(v->errors, api_error_entry(pointer, detail));
}

static const char *ref_type_name(const json_t *j)
{
    if (json_is_object(j)) return "object";
    if (json_is_array(j)) return "array";
    if (json_is_string(j)) return "string";
    if (json_is_number(j)) return "number";
    if (json_is_boolean(j)) return "boolean";
    return "null";
}

static int ref_type_matches(const char *t, const json_t *j)
{
    if (!strcmp(t, "object")) return json_is_object(j);
    if (!strcmp(t, "array")) return json_is_array(j);
    if (!strcmp(t, "string")) return json_is_string(j);
    if (!strcmp(t, "number")) return json_is_number(j);
    if (!strcmp(t, "integer"))
        return json_is_number(j) && isfinite(json_number_value(j)) &&
               floor(json_number_value(j)) == json_number_value(j);
    if (!strcmp(t, "boolean")) return json_is_boolean(j);
    if (!strcmp(t, "null")) return json_is_null(j);
    return 0;
}

static int ref_same(const json_t *a, const json_t *b)
{
    if (json_is_number(a) && json_is_number(b))
        return json_number_value(a) == json_number_value(b);
    return json_equal((json_t *)a, (json_t *)b);
}

static void ref_text(const json_t *j, char *buf, size_t n)
{
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(15));
    snprintf(buf, n, "%s", s ? s : "?");
    free(s);
}

static void ref_index(char *buf, const char *base, size_t i)
{
    snprintf(buf, REF_PTR_MAX, "%s/%zu", base, i);
}

static void ref_key(char *buf, const char *base, const char *key)
{
    snprintf(buf, REF_PTR_MAX, "%s", base);
    api_pointer_append(buf, REF_PTR_MAX, key);
}

static void ref_validate(struct rctx *v, const json_t *s, const json_t *inst, const char *ptr);

/* ---- choosing the branch to report (the rules of api/schema/schema.h, written again
 * from the schema's json_t: type names as strings, key sets by walking
 * properties and nested oneOf on every call) ---- */

static const char *const ref_kinds[] = {"object", "array", "string", "number", "boolean", "null"};

/* The JSON kinds (names above, "integer" being a number) that schema s admits,
 * as a string "|object|number|"; every kind when s says nothing about it. */
static void ref_kinds_of(const json_t *s, char *buf, size_t n)
{
    const json_t *t = json_object_get(s, "type"), *c = json_object_get(s, "const"),
                 *e = json_object_get(s, "enum");
    snprintf(buf, n, "|");
    for (size_t i = 0; i < 6; i++) {
        int ok = 0;
        if (t) {
            size_t k;
            json_t *x;
            if (json_is_string(t)) {
                const char *name = json_string_value(t);
                ok = !strcmp(name, ref_kinds[i]) ||
                     (!strcmp(name, "integer") && !strcmp(ref_kinds[i], "number"));
            }
            json_array_foreach(t, k, x) {
                const char *name = json_string_value(x);
                if (!strcmp(name, ref_kinds[i]) ||
                    (!strcmp(name, "integer") && !strcmp(ref_kinds[i], "number")))
                    ok = 1;
            }
        } else if (c) {
            ok = !strcmp(ref_type_name(c), ref_kinds[i]);
        } else if (e) {
            size_t k;
            json_t *x;
            json_array_foreach(e, k, x) if (!strcmp(ref_type_name(x), ref_kinds[i])) ok = 1;
        } else {
            ok = 1;
        }
        if (ok) {
            size_t len = strlen(buf);
            snprintf(buf + len, n - len, "%s|", ref_kinds[i]);
        }
    }
}

static int ref_admits(const json_t *s, const json_t *inst)
{
    char kinds[80], want[20];
    ref_kinds_of(s, kinds, sizeof kinds);
    snprintf(want, sizeof want, "|%s|", ref_type_name(inst));
    return strstr(kinds, want) != NULL;
}

/* Whether branch b knows key: a property of it or of a branch of its oneOf. */
static int ref_knows(const json_t *b, const char *key)
{
    if (json_object_get(json_object_get(b, "properties"), key)) return 1;
    size_t i;
    json_t *x;
    json_array_foreach(json_object_get(b, "oneOf"), i, x) if (ref_knows(x, key)) return 1;
    return 0;
}

static const json_t *ref_const_at(const json_t *b, const char *key)
{
    return json_object_get(json_object_get(json_object_get(b, "properties"), key), "const");
}

/* What kind of value branch b is, in words. */
static void ref_kind_text(const json_t *b, char *buf, size_t n)
{
    const json_t *t = json_object_get(b, "type");
    if (json_is_string(t)) {
        const char *name = json_string_value(t);
        snprintf(buf, n, "%s %s", strchr("aeiou", name[0]) ? "an" : "a", name);
    } else if (t) {
        buf[0] = '\0';
        size_t i;
        json_t *x;
        json_array_foreach(t, i, x) {
            size_t len = strlen(buf);
            snprintf(buf + len, n - len, "%s%s", i ? " or " : "", json_string_value(x));
        }
    } else if (json_object_get(b, "const")) {
        ref_text(json_object_get(b, "const"), buf, n < 120 ? n : 120);
    } else if (json_object_get(b, "enum")) {
        char t2[300];
        ref_text(json_object_get(b, "enum"), t2, sizeof t2);
        snprintf(buf, n, "one of ");
        size_t len = strlen(buf); /* truncated to n - 1 bytes, as schema.c's */
        for (size_t k = 0; t2[k] && len + 1 < n; k++) buf[len++] = t2[k];
        buf[len] = '\0';
    } else {
        snprintf(buf, n, "any value");
    }
}

/* Append item to list (n bytes) after sep, as far as it fits. */
static void ref_list_add(char *list, size_t n, const char *sep, const char *item)
{
    size_t len = strlen(list);
    if (len + 1 < n) snprintf(list + len, n - len, "%s%s", len ? sep : "", item);
}

/* The distinct consts the candidates give key, in branch order, as text. */
static void ref_const_list(const json_t *branches, const int *cand, const char *key, char *out,
                           size_t n)
{
    size_t i;
    json_t *b;
    out[0] = '\0';
    json_array_foreach(branches, i, b) {
        const json_t *c = cand[i] ? ref_const_at(b, key) : NULL;
        if (!c) continue;
        int seen = 0;
        for (size_t j = 0; j < i; j++)
            if (cand[j] && ref_const_at(json_array_get(branches, j), key) &&
                ref_same(ref_const_at(json_array_get(branches, j), key), c))
                seen = 1;
        if (seen) continue;
        char t[120];
        ref_text(c, t, sizeof t);
        ref_list_add(out, n, ", ", t);
    }
}

static long ref_choose(struct rctx *v, const json_t *branches, const json_t *inst,
                       const char *ptr)
{
    int cand[64];
    size_t nb = json_array_size(branches), i, alive = 0;
    json_t *b;
    char list[400], child[REF_PTR_MAX];
    /* the JSON type */
    json_array_foreach(branches, i, b) alive += (cand[i] = ref_admits(b, inst));
    if (!alive) {
        list[0] = '\0';
        json_array_foreach(branches, i, b) {
            char t[200];
            ref_kind_text(b, t, sizeof t);
            int seen = 0;
            for (size_t j = 0; j < i; j++) {
                char u[200];
                ref_kind_text(json_array_get(branches, j), u, sizeof u);
                if (!strcmp(t, u)) seen = 1;
            }
            if (!seen) ref_list_add(list, sizeof list, " or ", t);
        }
        ref_error(v, ptr, "must be %s, got %s", list, ref_type_name(inst));
        return -1;
    }
    /* the discriminator values */
    if (json_is_object(inst)) {
        json_array_foreach(branches, i, b) {
            const char *key;
            json_t *ps;
            json_object_foreach(json_object_get(b, "properties"), key, ps) {
                if (!json_object_get(ps, "const")) continue;
                const json_t *x = json_object_get(inst, key);
                if (!x) continue;
                size_t left = 0;
                for (size_t j = 0; j < nb; j++)
                    left += cand[j] && (!ref_const_at(json_array_get(branches, j), key) ||
                                        ref_same(ref_const_at(json_array_get(branches, j), key), x));
                if (!left) {
                    ref_const_list(branches, cand, key, list, sizeof list);
                    char got[200];
                    ref_text(x, got, sizeof got);
                    ref_key(child, ptr, key);
                    ref_error(v, child, "unknown %s %s; expected one of %s", key, got, list);
                    return -1;
                }
                for (size_t j = 0; j < nb; j++)
                    if (cand[j] && ref_const_at(json_array_get(branches, j), key) &&
                        !ref_same(ref_const_at(json_array_get(branches, j), key), x))
                        cand[j] = 0;
                alive = left;
            }
        }
    }
    /* the JSON type of the items */
    if (json_is_array(inst) && alive > 1) {
        size_t score[64], top = 0, bottom = (size_t)-1;
        json_array_foreach(branches, i, b) {
            if (!cand[i]) continue;
            const json_t *items = json_object_get(b, "items");
            score[i] = 0;
            size_t k;
            json_t *x;
            json_array_foreach(inst, k, x) score[i] += !items || ref_admits(items, x);
            if (score[i] > top) top = score[i];
            if (score[i] < bottom) bottom = score[i];
        }
        if (top != bottom) {
            alive = 0;
            for (size_t j = 0; j < nb; j++)
                if (cand[j] && score[j] != top) cand[j] = 0;
                else alive += cand[j];
        }
    }
    /* the keys only some candidates know */
    if (json_is_object(inst) && alive > 1) {
        size_t score[64] = {0}, top = 0;
        const char *key;
        json_t *x;
        json_object_foreach((json_t *)inst, key, x) {
            size_t know = 0;
            for (size_t j = 0; j < nb; j++) know += cand[j] && ref_knows(json_array_get(branches, j), key);
            if (know == 0 || know == alive) continue;
            for (size_t j = 0; j < nb; j++)
                if (cand[j] && ref_knows(json_array_get(branches, j), key)) {
                    score[j]++;
                    if (score[j] > top) top = score[j];
                }
        }
        if (top) {
            alive = 0;
            for (size_t j = 0; j < nb; j++)
                if (cand[j] && score[j] != top) cand[j] = 0;
                else alive += cand[j];
        } else {
            /* Do the candidates' key sets differ at all? Collect them. */
            json_t *all = json_object();
            for (size_t j = 0; j < nb; j++) {
                if (!cand[j]) continue;
                json_t *todo = json_array();
                json_array_append(todo, json_array_get(branches, j));
                for (size_t t = 0; t < json_array_size(todo); t++) {
                    const json_t *node = json_array_get(todo, t);
                    json_object_foreach(json_object_get(node, "properties"), key, x)
                        json_object_set_new(all, key, json_true());
                    size_t k;
                    json_t *y;
                    json_array_foreach(json_object_get(node, "oneOf"), k, y)
                        json_array_append(todo, y);
                }
                json_decref(todo);
            }
            int differ = 0;
            json_object_foreach(all, key, x)
                for (size_t j = 0; j < nb; j++)
                    if (cand[j] && !ref_knows(json_array_get(branches, j), key)) differ = 1;
            json_decref(all);
            if (differ) {
                /* a discriminator of every candidate, missing */
                json_array_foreach(branches, i, b) {
                    if (!cand[i]) continue;
                    json_object_foreach(json_object_get(b, "properties"), key, x) {
                        if (!json_object_get(x, "const") || json_object_get(inst, key)) continue;
                        int every = 1;
                        for (size_t j = 0; j < nb; j++)
                            if (cand[j] && !ref_const_at(json_array_get(branches, j), key))
                                every = 0;
                        if (!every) continue;
                        ref_const_list(branches, cand, key, list, sizeof list);
                        ref_key(child, ptr, key);
                        ref_error(v, child, "is required: one of %s", list);
                        return -1;
                    }
                }
                list[0] = '\0';
                json_array_foreach(branches, i, b) {
                    if (!cand[i]) continue;
                    char form[200] = "";
                    const json_t *req = json_object_get(b, "required");
                    if (!json_array_size(req)) {
                        ref_kind_text(b, form, sizeof form);
                    } else {
                        size_t k;
                        json_t *r;
                        json_array_foreach(req, k, r) {
                            const char *name = json_string_value(r);
                            char c[120] = "";
                            if (ref_const_at(b, name)) ref_text(ref_const_at(b, name), c, sizeof c);
                            size_t len = strlen(form);
                            snprintf(form + len, sizeof form - len, "%s%s%s%s", k ? ", " : "{",
                                     name, c[0] ? " " : "", c);
                        }
                        size_t len = strlen(form);
                        if (len + 1 < sizeof form) snprintf(form + len, sizeof form - len, "}");
                    }
                    ref_list_add(list, sizeof list, ", ", form);
                }
                ref_error(v, ptr, "matches none of the allowed forms; give one of %s", list);
                return -1;
            }
        }
    }
    /* the fewest errors */
    long best = -1;
    size_t best_count = (size_t)-1;
    json_array_foreach(branches, i, b) {
        if (!cand[i]) continue;
        struct rctx t = {NULL, 0};
        ref_validate(&t, b, inst, ptr);
        if (t.count < best_count) {
            best_count = t.count;
            best = (long)i;
        }
    }
    return best;
}

static void ref_oneof(struct rctx *v, const json_t *branches, const json_t *inst, const char *ptr)
{
    size_t i, passes = 0;
    json_t *b;
    json_array_foreach(branches, i, b) {
        struct rctx t = {NULL, 0};
        ref_validate(&t, b, inst, ptr);
        if (t.count == 0) passes++;
    }
    if (passes == 1) return;
    if (passes > 1) {
        ref_error(v, ptr, "matches more than one of the allowed forms");
        return;
    }
    long best = ref_choose(v, branches, inst, ptr);
    if (best >= 0) ref_validate(v, json_array_get(branches, (size_t)best), inst, ptr);
}

static void ref_validate(struct rctx *v, const json_t *s, const json_t *inst, const char *ptr)
{
    if (v->errors && json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) { v->count++; return; }
    const json_t *k;
    char child[REF_PTR_MAX];
    if ((k = json_object_get(s, "type"))) {
        int ok = 0;
        char names[200] = "";
        if (json_is_string(k)) {
            ok = ref_type_matches(json_string_value(k), inst);
            snprintf(names, sizeof names, "%s %s",
                     strchr("aeiou", json_string_value(k)[0]) ? "an" : "a", json_string_value(k));
        } else {
            size_t i;
            json_t *e;
            json_array_foreach(k, i, e) {
                if (ref_type_matches(json_string_value(e), inst)) ok = 1;
                size_t len = strlen(names);
                snprintf(names + len, sizeof names - len, "%s%s", i ? " or " : "",
                         json_string_value(e));
            }
        }
        if (!ok) {
            ref_error(v, ptr, "must be %s, got %s", names, ref_type_name(inst));
            return;
        }
    }
    if ((k = json_object_get(s, "const")) && !ref_same(k, inst)) {
        char t[120];
        ref_text(k, t, sizeof t);
        ref_error(v, ptr, "must be %s", t);
        return;
    }
    if ((k = json_object_get(s, "enum"))) {
        size_t i;
        json_t *e;
        int found = 0;
        json_array_foreach(k, i, e) if (ref_same(e, inst)) found = 1;
        if (!found) {
            char t[300];
            ref_text(k, t, sizeof t);
            ref_error(v, ptr, "must be one of %s", t);
            return;
        }
    }
    if (json_is_object(inst)) {
        const json_t *props = json_object_get(s, "properties");
        size_t i;
        json_t *e;
        json_array_foreach(json_object_get(s, "required"), i, e) {
            if (!json_object_get(inst, json_string_value(e))) {
                ref_key(child, ptr, json_string_value(e));
                ref_error(v, child, "is required");
            }
        }
        const char *key;
        json_t *val;
        json_object_foreach((json_t *)inst, key, val) {
            ref_key(child, ptr, key);
            const json_t *ps = props ? json_object_get(props, key) : NULL;
            if (ps) {
                ref_validate(v, ps, val, child);
            } else if (json_is_false(json_object_get(s, "additionalProperties"))) {
                char allowed[300] = "";
                const char *pk;
                json_t *pv;
                json_object_foreach((json_t *)props, pk, pv) {
                    size_t len = strlen(allowed);
                    snprintf(allowed + len, sizeof allowed - len, "%s%s", len ? ", " : "", pk);
                }
                ref_error(v, child, "unknown key; allowed here: %s",
                          allowed[0] ? allowed : "none");
            }
        }
        size_t n = json_object_size(inst);
        if ((k = json_object_get(s, "minProperties")) && (double)n < json_number_value(k))
            ref_error(v, ptr, "must have at least %g members", json_number_value(k));
        if ((k = json_object_get(s, "maxProperties")) && (double)n > json_number_value(k))
            ref_error(v, ptr, "must have at most %g members", json_number_value(k));
    } else if (json_is_array(inst)) {
        size_t n = json_array_size(inst);
        if ((k = json_object_get(s, "minItems")) && (double)n < json_number_value(k)) {
            ref_error(v, ptr, "must have at least %g items, got %zu", json_number_value(k), n);
            return;
        }
        if ((k = json_object_get(s, "maxItems")) && (double)n > json_number_value(k)) {
            ref_error(v, ptr, "must have at most %g items, got %zu", json_number_value(k), n);
            return;
        }
        if ((k = json_object_get(s, "items"))) {
            for (size_t i = 0; i < n; i++) {
                if (v->errors && json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) break;
                ref_index(child, ptr, i);
                ref_validate(v, k, json_array_get(inst, i), child);
            }
        }
        if (json_is_true(json_object_get(s, "uniqueItems"))) {
            for (size_t i = 0; i < n; i++)
                for (size_t j = i + 1; j < n && j < 1000; j++)
                    if (ref_same(json_array_get(inst, i), json_array_get(inst, j))) {
                        ref_index(child, ptr, j);
                        ref_error(v, child, "repeats item %zu; items must be unique", i);
                        return;
                    }
        }
    } else if (json_is_number(inst)) {
        double x = json_number_value(inst);
        if ((k = json_object_get(s, "minimum")) && !(x >= json_number_value(k)))
            ref_error(v, ptr, "must be >= %.17g, got %.17g", json_number_value(k), x);
        if ((k = json_object_get(s, "maximum")) && !(x <= json_number_value(k)))
            ref_error(v, ptr, "must be <= %.17g, got %.17g", json_number_value(k), x);
        if ((k = json_object_get(s, "exclusiveMinimum")) && !(x > json_number_value(k)))
            ref_error(v, ptr, "must be > %.17g, got %.17g", json_number_value(k), x);
        if ((k = json_object_get(s, "exclusiveMaximum")) && !(x < json_number_value(k)))
            ref_error(v, ptr, "must be < %.17g, got %.17g", json_number_value(k), x);
    }
    if ((k = json_object_get(s, "oneOf"))) ref_oneof(v, k, inst, ptr);
}

/* ==== helpers ================================================================ */

static long compared, mismatches;
static long seen_unknown, seen_required_one_of, seen_forms, seen_types;

/* Validate inst with both validators, full and count-only; any difference
 * is a mismatch (the first few are printed). Returns the compiled count. */
static size_t compare(const json_t *schema, const struct api_schema *c, const json_t *inst,
                      const char *pointer, const char *what)
{
    json_t *ref = json_array(), *got = json_array();
    struct rctx r = {ref, 0};
    ref_validate(&r, schema, inst, pointer);
    size_t n = api_schema_validate(c, inst, pointer, got);
    struct rctx rc = {NULL, 0};
    ref_validate(&rc, schema, inst, pointer);
    size_t nc = api_schema_validate(c, inst, pointer, NULL);
    compared++;
    /* which of choose_branch's own messages the comparison met */
    size_t gi;
    json_t *ge;
    json_array_foreach(got, gi, ge) {
        const char *d = json_string_value(json_object_get(ge, "detail"));
        if (!d) continue;
        if (!strncmp(d, "unknown ", 8) && strstr(d, "; expected one of ")) seen_unknown++;
        else if (!strncmp(d, "is required: one of ", 20)) seen_required_one_of++;
        else if (!strncmp(d, "matches none of the allowed forms", 33)) seen_forms++;
        else if (!strncmp(d, "must be ", 8) && strstr(d, " or ") && strstr(d, ", got ")) seen_types++;
    }
    if (n != r.count || nc != rc.count || !json_equal(ref, got)) {
        if (mismatches++ < 10) {
            char *a = json_dumps(inst, JSON_COMPACT), *b = json_dumps(ref, JSON_COMPACT),
                 *g = json_dumps(got, JSON_COMPACT);
            fprintf(stderr, "mismatch (%s) on %s:\n  ref %zu/%zu %s\n  got %zu/%zu %s\n", what,
                    a, r.count, rc.count, b, n, nc, g);
            free(a);
            free(b);
            free(g);
        }
    }
    json_decref(ref);
    json_decref(got);
    return n;
}

/* Validate instance text against schema text with the compiled validator
 * (and compare it with the reference); return the error count and the first
 * error's pointer in ptr. */
static size_t run(const char *schema, const char *inst, char *ptr, size_t n)
{
    json_t *s = json_loads(schema, JSON_DECODE_INT_AS_REAL, NULL);
    json_t *i = json_loads(inst, JSON_DECODE_INT_AS_REAL | JSON_DECODE_ANY, NULL);
    char msg[200];
    struct api_schema *c = s ? api_schema_compile(s, msg, sizeof msg) : NULL;
    if (!s || !i || !c) { fprintf(stderr, "bad test JSON or schema\n"); return 999; }
    json_t *errs = json_array();
    size_t count = api_schema_validate(c, i, "", errs);
    const char *p = json_string_value(json_object_get(json_array_get(errs, 0), "pointer"));
    snprintf(ptr, n, "%s", p ? p : "(none)");
    compare(s, c, i, "", inst);
    api_schema_free(c);
    json_decref(s);
    json_decref(i);
    json_decref(errs);
    return count;
}

#define EXPECT(schema, inst, nerr, pointer)                                    \
    do {                                                                       \
        char p_[256];                                                          \
        size_t c_ = run(schema, inst, p_, sizeof p_);                          \
        CHECK_EQ_INT(c_, nerr);                                                \
        if ((nerr) > 0 && strcmp(p_, pointer)) {                               \
            tl_failed++;                                                       \
            fprintf(stderr, "%s:%d: pointer %s, want %s\n", __FILE__, __LINE__, p_, pointer); \
        }                                                                      \
    } while (0)

/* The full error list as text "pointer|detail;pointer|detail;..." (compiled
 * validator, with `prefix`), compared with a hand-written expectation. */
static void expect_list(int line, const char *schema, const char *inst, const char *prefix,
                        size_t nerr, const char *want)
{
    json_t *s = json_loads(schema, JSON_DECODE_INT_AS_REAL, NULL);
    json_t *i = json_loads(inst, JSON_DECODE_INT_AS_REAL | JSON_DECODE_ANY, NULL);
    char msg[200];
    struct api_schema *c = s ? api_schema_compile(s, msg, sizeof msg) : NULL;
    if (!s || !i || !c) {
        tl_failed++;
        fprintf(stderr, "%d: bad test JSON or schema\n", line);
        return;
    }
    json_t *errs = json_array();
    size_t count = api_schema_validate(c, i, prefix, errs);
    char text[2000] = "";
    size_t k;
    json_t *e;
    json_array_foreach(errs, k, e) {
        size_t len = strlen(text);
        snprintf(text + len, sizeof text - len, "%s%s|%s", k ? ";" : "",
                 json_string_value(json_object_get(e, "pointer")),
                 json_string_value(json_object_get(e, "detail")));
    }
    if (count != nerr || strcmp(text, want) || api_schema_validate(c, i, prefix, NULL) != nerr) {
        tl_failed++;
        fprintf(stderr, "%s:%d: %zu errors [%s], want %zu [%s]\n", __FILE__, line, count, text,
                nerr, want);
    } else {
        tl_passed++;
    }
    api_schema_free(c);
    json_decref(s);
    json_decref(i);
    json_decref(errs);
}

#define EXPECT_LIST(schema, inst, prefix, nerr, want)                          \
    expect_list(__LINE__, schema, inst, prefix, nerr, want)

/* ==== mutations of route examples ============================================ */

/* Node of root at pointer (only the pointers this file builds: no escapes in
 * keys that need them are followed — such keys are skipped when collecting). */
static json_t *node_at(json_t *root, const char *ptr)
{
    json_t *n = root;
    char tok[256];
    while (*ptr == '/') {
        ptr++;
        size_t len = strcspn(ptr, "/");
        if (len >= sizeof tok) return NULL;
        memcpy(tok, ptr, len);
        tok[len] = '\0';
        ptr += len;
        if (json_is_object(n)) n = json_object_get(n, tok);
        else if (json_is_array(n)) n = json_array_get(n, strtoul(tok, NULL, 10));
        else return NULL;
        if (!n) return NULL;
    }
    return n;
}

/* Pointers of the nodes of j worth mutating: all, except inside long arrays
 * (first two and last item only) and below depth 8. */
static void collect(const json_t *j, const char *ptr, int depth, char (*out)[256], size_t *n,
                    size_t cap)
{
    if (*n >= cap) return;
    snprintf(out[(*n)++], 256, "%s", ptr);
    if (depth >= 8 || strlen(ptr) > 200) return;
    char child[600];
    if (json_is_object(j)) {
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)j, k, v) {
            if (strpbrk(k, "/~") || strlen(k) > 50) continue;
            snprintf(child, sizeof child, "%s/%s", ptr, k);
            collect(v, child, depth + 1, out, n, cap);
        }
    } else if (json_is_array(j)) {
        size_t m = json_array_size(j);
        for (size_t i = 0; i < m; i++) {
            if (i >= 2 && i + 1 < m) continue;
            snprintf(child, sizeof child, "%s/%zu", ptr, i);
            collect(json_array_get(j, i), child, depth + 1, out, n, cap);
        }
    }
}

/* Replace the node at ptr in a copy of root by `with` (stolen); new root. */
static json_t *replaced(const json_t *root, const char *ptr, json_t *with)
{
    json_t *copy = json_deep_copy(root);
    const char *slash = strrchr(ptr, '/');
    if (!slash) {
        json_decref(copy);
        return with;
    }
    char parent[256];
    snprintf(parent, sizeof parent, "%.*s", (int)(slash - ptr), ptr);
    json_t *p = node_at(copy, parent);
    if (json_is_object(p)) json_object_set_new(p, slash + 1, with);
    else if (json_is_array(p)) json_array_set_new(p, strtoul(slash + 1, NULL, 10), with);
    else json_decref(with);
    return copy;
}

/* Every const value in a schema (the discriminators among them). */
static void schema_consts(const json_t *s, json_t *out)
{
    if (json_is_object(s)) {
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)s, k, v) {
            if (!strcmp(k, "const") && json_array_size(out) < 64) json_array_append(out, v);
            else schema_consts(v, out);
        }
    } else if (json_is_array(s)) {
        size_t i;
        json_t *v;
        json_array_foreach(s, i, v) schema_consts(v, out);
    }
}

static int schema_depth(const json_t *s)
{
    int d = 0;
    const json_t *k;
    if ((k = json_object_get(s, "items"))) {
        int c = 1 + schema_depth(k);
        if (c > d) d = c;
    }
    const char *key;
    json_t *v;
    json_object_foreach(json_object_get(s, "properties"), key, v) {
        int c = 1 + schema_depth(v);
        if (c > d) d = c;
    }
    size_t i;
    json_array_foreach(json_object_get(s, "oneOf"), i, v) {
        int c = 1 + schema_depth(v);
        if (c > d) d = c;
    }
    return d;
}

/* Replace every number of j (in place) by `with`(copied). */
static void replace_numbers(json_t *j, const json_t *with)
{
    if (json_is_object(j)) {
        const char *k;
        json_t *v;
        json_object_foreach(j, k, v) {
            if (json_is_number(v)) json_object_set_new(j, k, json_deep_copy(with));
            else replace_numbers(v, with);
        }
    } else if (json_is_array(j)) {
        for (size_t i = 0; i < json_array_size(j); i++) {
            json_t *v = json_array_get(j, i);
            if (json_is_number(v)) json_array_set_new(j, i, json_deep_copy(with));
            else replace_numbers(v, with);
        }
    }
}

/* Mutate route example ex in every way below and compare both validators. */
static void sweep_route(const char *path, const json_t *schema, const struct api_schema *c,
                        const json_t *ex)
{
    static char ptrs[400][256];
    size_t np = 0;
    collect(ex, "", 0, ptrs, &np, 400);
    static const char *const values[] = {
        "\"x\"", "null", "true", "false", "0", "-1", "0.5", "1.5", "3", "7", "1e300", "-1e300",
        "2e150", "-2e150", "1e-300", "400", "1e16", "[]", "{}", "[1,2,3]", "[1,2,3,4]",
        "[[1,0,0,0]]", "[0.6,0,0]", "\"nope\"", "\"\"", "{\"beta\":[0.6,0,0]}",
        "[1,1]", "[\"a\",\"a\"]",
    };
    json_t *consts = json_array();
    schema_consts(schema, consts);
    char what[400];
    for (size_t p = 0; p < np; p++) {
        const char *ptr = ptrs[p];
        json_t *node = node_at((json_t *)ex, ptr);
        for (size_t k = 0; k < sizeof values / sizeof values[0]; k++) {
            json_t *inst = replaced(ex, ptr, json_loads(values[k], JSON_DECODE_ANY |
                                                                       JSON_DECODE_INT_AS_REAL,
                                                        NULL));
            snprintf(what, sizeof what, "%s: %s := %s", path, ptr, values[k]);
            compare(schema, c, inst, "", what);
            compare(schema, c, inst, "/requests/3/body", what);
            json_decref(inst);
        }
        /* Wrong discriminators: every const of the schema in every place. */
        size_t ci;
        json_t *cv;
        json_array_foreach(consts, ci, cv) {
            json_t *inst = replaced(ex, ptr, json_deep_copy(cv));
            snprintf(what, sizeof what, "%s: %s := const %zu", path, ptr, ci);
            compare(schema, c, inst, "", what);
            json_decref(inst);
        }
        if (json_is_object(node)) {
            const char *key;
            json_t *v;
            json_object_foreach(node, key, v) { /* remove each key */
                json_t *inst = json_deep_copy(ex);
                json_object_del(node_at(inst, ptr), key);
                snprintf(what, sizeof what, "%s: %s without %s", path, ptr, key);
                compare(schema, c, inst, "", what);
                json_decref(inst);
            }
            static const char *const extra[] = {"zz_unknown", "a/b~c", ""};
            for (size_t k = 0; k < 3; k++) { /* unknown keys */
                json_t *inst = json_deep_copy(ex);
                json_object_set_new(node_at(inst, ptr), extra[k], json_real(1));
                snprintf(what, sizeof what, "%s: %s plus '%s'", path, ptr, extra[k]);
                compare(schema, c, inst, "", what);
                json_decref(inst);
            }
        } else if (json_is_array(node) && json_array_size(node) > 0) {
            for (int k = 0; k < 4; k++) {
                json_t *inst = json_deep_copy(ex);
                json_t *a = node_at(inst, ptr);
                if (k == 0) json_array_remove(a, json_array_size(a) - 1);
                else if (k == 1) json_array_append_new(a, json_deep_copy(json_array_get(a, 0)));
                else if (k == 2) json_array_insert_new(a, 0, json_string("x"));
                else json_array_clear(a);
                snprintf(what, sizeof what, "%s: %s array edit %d", path, ptr, k);
                compare(schema, c, inst, "", what);
                json_decref(inst);
            }
        }
    }
    /* Many errors at once (more than the list holds), and every number out
     * of any bound or non-integral. */
    static const char *const everywhere[] = {"\"x\"", "1e300", "-1e300", "0.5", "-0.5", "null"};
    for (size_t k = 0; k < sizeof everywhere / sizeof everywhere[0]; k++) {
        json_t *w = json_loads(everywhere[k], JSON_DECODE_ANY | JSON_DECODE_INT_AS_REAL, NULL);
        json_t *inst = json_deep_copy(ex);
        replace_numbers(inst, w);
        snprintf(what, sizeof what, "%s: every number := %s", path, everywhere[k]);
        compare(schema, c, inst, "", what);
        json_decref(inst);
        json_decref(w);
    }
    /* An instance far deeper than any schema: recursion follows the schema. */
    json_t *deep = json_real(1);
    for (int d = 0; d < 1000; d++) {
        json_t *a = json_array();
        json_array_append_new(a, deep);
        deep = a;
    }
    for (size_t p = 0; p < np; p++) {
        json_t *inst = replaced(ex, ptrs[p], json_deep_copy(deep));
        snprintf(what, sizeof what, "%s: %s := 1000-deep array", path, ptrs[p]);
        compare(schema, c, inst, "", what);
        json_decref(inst);
    }
    json_decref(deep);
    json_decref(consts);
}

/* ns per call of both validators on one instance (figures only, no check). */
static void time_one(const char *path, const json_t *schema, const struct api_schema *c,
                     const json_t *inst)
{
    const int reps = 20000;
    volatile size_t sink = 0;
    struct timespec t0, t1, t2;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (int i = 0; i < reps; i++) {
        struct rctx r = {NULL, 0};
        ref_validate(&r, schema, inst, "");
        sink += r.count;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    for (int i = 0; i < reps; i++) sink += api_schema_validate(c, inst, "", NULL);
    clock_gettime(CLOCK_MONOTONIC, &t2);
    double a = ((double)(t1.tv_sec - t0.tv_sec) * 1e9 + (double)(t1.tv_nsec - t0.tv_nsec)) / reps;
    double b = ((double)(t2.tv_sec - t1.tv_sec) * 1e9 + (double)(t2.tv_nsec - t1.tv_nsec)) / reps;
    printf("validate %s example: reference interpreter %.0f ns, compiled %.0f ns per call\n", path,
           a, b);
    (void)sink;
}

#define OBJ "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"m\"]," \
            "\"properties\":{\"m\":{\"type\":\"number\",\"exclusiveMinimum\":0}," \
            "\"n\":{\"type\":\"integer\",\"minimum\":2,\"maximum\":5}," \
            "\"v\":{\"type\":\"array\",\"items\":{\"type\":\"number\"},\"minItems\":3,\"maxItems\":3}," \
            "\"k\":{\"enum\":[\"a\",\"b\"]}," \
            "\"a/b~c\":{\"type\":\"boolean\"}}}"

/* api_schema_apply_defaults: defaults are filled where the key is absent,
 * integers as reals (what the request parser gives), reals stay reals, only
 * in the oneOf branch the instance matches and only inside objects that are
 * there; the caller's instance is never modified, and is returned itself
 * (no copy) when nothing is missing. */
static void test_apply_defaults(void)
{
    const char *schema =
        "{\"type\":\"object\",\"properties\":{"
        "\"samples\":{\"type\":\"integer\",\"default\":200},"
        "\"rtol\":{\"type\":\"number\",\"default\":1e-9},"
        "\"unit\":{\"enum\":[\"MeV\",\"GeV\"],\"default\":\"MeV\"},"
        "\"cost\":{\"type\":\"boolean\",\"default\":true},"
        "\"opt\":{\"type\":\"object\",\"properties\":{\"g\":{\"type\":\"number\",\"default\":9.80665}}},"
        "\"list\":{\"type\":\"array\",\"items\":{\"type\":\"object\",\"properties\":{"
        "\"hole\":{\"type\":\"boolean\",\"default\":false}}}},"
        "\"block\":{\"oneOf\":["
        "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"method\"],"
        "\"properties\":{\"method\":{\"const\":\"rk8pd\"},\"atol\":{\"type\":\"number\",\"default\":1e-12}}},"
        "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"accuracy\"],"
        "\"properties\":{\"accuracy\":{\"type\":\"string\"},\"closed_form\":{\"type\":\"boolean\",\"default\":true}}}]}"
        "}}";
    char msg[200];
    json_t *s = json_loads(schema, 0, NULL);
    struct api_schema *c = s ? api_schema_compile(s, msg, sizeof msg) : NULL;
    CHECK(c != NULL);
    static const char *const skip[] = {"cost", NULL};

    json_t *in = json_loads("{\"list\":[{},{\"hole\":true}],\"block\":{\"accuracy\":\"draft\"},"
                            "\"unit\":\"GeV\"}",
                            JSON_DECODE_INT_AS_REAL, NULL);
    CHECK_EQ_INT((int)api_schema_validate(c, in, "", NULL), 0);
    char *before = json_dumps(in, JSON_SORT_KEYS);
    json_t *out = api_schema_apply_defaults(c, in, skip);
    CHECK(out != NULL && out != in);
    const json_t *smp = json_object_get(out, "samples");
    CHECK(json_is_real(smp) && json_real_value(smp) == 200.0); /* as "samples": 200 parses */
    const json_t *rt = json_object_get(out, "rtol");
    CHECK(json_is_real(rt) && json_real_value(rt) == 1e-9);
    CHECK(!strcmp(json_string_value(json_object_get(out, "unit")), "GeV")); /* given wins */
    CHECK(json_object_get(out, "cost") == NULL);                             /* skipped root key */
    CHECK(json_object_get(out, "opt") == NULL); /* an absent object is not created */
    CHECK(json_is_false(json_object_get(json_array_get(json_object_get(out, "list"), 0), "hole")));
    CHECK(json_is_true(json_object_get(json_array_get(json_object_get(out, "list"), 1), "hole")));
    const json_t *blk = json_object_get(out, "block");
    CHECK(json_is_true(json_object_get(blk, "closed_form"))); /* the matching branch's default */
    CHECK(json_object_get(blk, "atol") == NULL);             /* not the other branch's */
    CHECK_EQ_INT((int)api_schema_validate(c, out, "", NULL), 0);
    char *after = json_dumps(in, JSON_SORT_KEYS);
    CHECK(before && after && !strcmp(before, after)); /* the caller's instance is untouched */
    free(before);
    free(after);
    json_decref(out);
    json_decref(in);

    /* Everything given: the instance itself comes back, nothing copied. */
    in = json_loads("{\"samples\":7,\"rtol\":1e-3,\"unit\":\"MeV\",\"block\":{\"method\":\"rk8pd\","
                    "\"atol\":1e-9}}",
                    JSON_DECODE_INT_AS_REAL, NULL);
    out = api_schema_apply_defaults(c, in, skip);
    CHECK(out == in);
    json_decref(out);
    json_decref(in);
    /* The envelope key is filled when not skipped. */
    in = json_loads("{}", 0, NULL);
    out = api_schema_apply_defaults(c, in, NULL);
    CHECK(json_is_true(json_object_get(out, "cost")));
    json_decref(out);
    json_decref(in);
    api_schema_free(c);
    json_decref(s);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    test_apply_defaults();
    EXPECT(OBJ, "{\"m\":1}", 0, "");
    EXPECT(OBJ, "{}", 1, "/m");
    EXPECT(OBJ, "[]", 1, "");
    EXPECT(OBJ, "{\"m\":0}", 1, "/m");
    EXPECT(OBJ, "{\"m\":-1e-300}", 1, "/m");
    EXPECT(OBJ, "{\"m\":\"1\"}", 1, "/m");
    EXPECT(OBJ, "{\"m\":1,\"zz\":1}", 1, "/zz");
    EXPECT(OBJ, "{\"m\":1,\"n\":2.5}", 1, "/n");
    EXPECT(OBJ, "{\"m\":1,\"n\":3}", 0, "");
    EXPECT(OBJ, "{\"m\":1,\"n\":6}", 1, "/n");
    EXPECT(OBJ, "{\"m\":1,\"v\":[1,2]}", 1, "/v");
    EXPECT(OBJ, "{\"m\":1,\"v\":[1,2,\"x\"]}", 1, "/v/2");
    EXPECT(OBJ, "{\"m\":1,\"k\":\"c\"}", 1, "/k");
    EXPECT(OBJ, "{\"m\":1,\"k\":\"b\"}", 0, "");
    EXPECT(OBJ, "{\"m\":1,\"a/b~c\":1}", 1, "/a~1b~0c");
    /* Unknown key with characters that need escaping. */
    EXPECT(OBJ, "{\"m\":1,\"x/y\":1}", 1, "/x~1y");

    /* oneOf: exactly one branch; the closest branch's errors are reported. */
    const char *one =
        "{\"oneOf\":[{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"beta\"],"
        "\"properties\":{\"beta\":{\"type\":\"number\"}}},"
        "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"gamma\",\"dir\"],"
        "\"properties\":{\"gamma\":{\"type\":\"number\",\"minimum\":1},\"dir\":{\"type\":\"number\"}}}]}";
    EXPECT(one, "{\"beta\":0.5}", 0, "");
    EXPECT(one, "{\"gamma\":2,\"dir\":1}", 0, "");
    EXPECT(one, "{\"gamma\":0.5,\"dir\":1}", 1, "/gamma");
    EXPECT(one, "{\"beta\":\"x\"}", 1, "/beta");
    /* A const discriminator picks the branch whose errors are reported, even
     * when another branch has fewer errors. */
    const char *shapes =
        "{\"oneOf\":[{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"shape\",\"r\",\"m\",\"p\"],"
        "\"properties\":{\"shape\":{\"const\":\"sphere\"},\"r\":{\"type\":\"number\"},\"m\":{},\"p\":{}}},"
        "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"shape\"],"
        "\"properties\":{\"shape\":{\"const\":\"point\"},\"m\":{},\"p\":{}}}]}";
    EXPECT(shapes, "{\"shape\":\"sphere\",\"m\":1,\"p\":1}", 1, "/r");
    EXPECT(shapes, "{\"shape\":\"point\",\"r\":1}", 1, "/r");
    const char *both = "{\"oneOf\":[{\"type\":\"number\"},{\"minimum\":0}]}";
    EXPECT(both, "3", 1, "");

    /* type arrays, const, uniqueItems, min/maxProperties */
    EXPECT("{\"type\":[\"string\",\"null\"]}", "null", 0, "");
    EXPECT("{\"type\":[\"string\",\"null\"]}", "1", 1, "");
    EXPECT("{\"const\":\"x\"}", "\"y\"", 1, "");
    EXPECT("{\"const\":2}", "2.0", 0, "");
    EXPECT("{\"type\":\"array\",\"uniqueItems\":true}", "[\"a\",\"b\",\"a\"]", 1, "/2");
    EXPECT("{\"type\":\"object\",\"maxProperties\":1}", "{\"a\":1,\"b\":2}", 1, "");

    /* The texts themselves, derived by hand from the schema and the message
     * formats (%.17g of 1e150 is 9.9999999999999998e+149, of 2e150 2e+150,
     * of 1e300 1.0000000000000001e+300; python3 '%.17g' % x). */
    EXPECT_LIST(OBJ, "{\"zz\":1,\"m\":0,\"n\":2.5,\"v\":[1,2],\"k\":\"c\",\"a/b~c\":null}", "",
                6,
                "/zz|unknown key; allowed here: m, n, v, k, a/b~c;"
                "/m|must be > 0, got 0;"
                "/n|must be an integer, got number;"
                "/v|must have at least 3 items, got 2;"
                "/k|must be one of [\"a\",\"b\"];"
                "/a~1b~0c|must be a boolean, got null");
    EXPECT_LIST(OBJ, "{\"n\":1e300,\"v\":[1,true,\"x\"]}", "/requests/0/body", 4,
                "/requests/0/body/m|is required;"
                "/requests/0/body/n|must be <= 5, got 1.0000000000000001e+300;"
                "/requests/0/body/v/1|must be a number, got boolean;"
                "/requests/0/body/v/2|must be a number, got string");
    EXPECT_LIST(OBJ, "{\"m\":1,\"n\":1}", "", 1, "/n|must be >= 2, got 1");
    EXPECT_LIST(OBJ, "{\"m\":1,\"n\":-3}", "", 1, "/n|must be >= 2, got -3");
    EXPECT_LIST("{\"type\":[\"string\",\"null\"]}", "1", "", 1,
                "|must be string or null, got number");
    EXPECT_LIST("{\"type\":[\"integer\",\"null\"]}", "2.0", "", 0, "");
    EXPECT_LIST("{\"type\":\"integer\"}", "1e300", "", 0, "");
    EXPECT_LIST("{\"type\":\"integer\"}", "[]", "", 1, "|must be an integer, got array");
    EXPECT_LIST("{\"const\":\"x\"}", "\"y\"", "", 1, "|must be \"x\"");
    EXPECT_LIST("{\"const\":{\"a\":[1,2.5]}}", "{\"a\":[1,2.5]}", "", 0, "");
    EXPECT_LIST("{\"const\":{\"a\":[1,2.5]}}", "{\"a\":[1,2]}", "", 1,
                "|must be {\"a\":[1.0,2.5]}"); /* the schema's 1 was read as a real */
    EXPECT_LIST("{\"type\":\"array\",\"uniqueItems\":true}", "[\"a\",\"b\",\"a\"]", "/u", 1,
                "/u/2|repeats item 0; items must be unique");
    EXPECT_LIST("{\"type\":\"object\",\"maxProperties\":1,\"minProperties\":3}",
                "{\"a\":1,\"b\":2}", "", 2,
                "|must have at least 3 members;|must have at most 1 members");
    EXPECT_LIST("{\"type\":\"array\",\"maxItems\":1,\"items\":{\"type\":\"string\"}}", "[1,2]",
                "", 1, "|must have at most 1 items, got 2");
    EXPECT_LIST(both, "3", "", 1, "|matches more than one of the allowed forms");
    EXPECT_LIST("{\"type\":\"object\",\"additionalProperties\":false}", "{\"q\":1}", "", 1,
                "/q|unknown key; allowed here: none");
    EXPECT_LIST("{\"exclusiveMaximum\":1,\"exclusiveMinimum\":-1}", "1", "", 1,
                "|must be < 1, got 1");
    EXPECT_LIST("{\"exclusiveMaximum\":1,\"exclusiveMinimum\":-1}", "-1", "", 1,
                "|must be > -1, got -1");
    EXPECT_LIST("{\"exclusiveMaximum\":1,\"exclusiveMinimum\":-1}", "\"s\"", "", 0, "");
    /* Discriminator: "shape":"point" rules the sphere branch out although it
     * would report only one error (r missing is 1 for sphere; point has 1). */
    EXPECT_LIST(shapes, "{\"shape\":\"point\",\"r\":1}", "", 1,
                "/r|unknown key; allowed here: shape, m, p");
    /* No branch matches: the branch the instance was meant to be is chosen by
     * what tells the branches apart, or the choice itself is what is wrong
     * (hand-derived from the rules in api/schema/schema.h). An unknown discriminator
     * value is named with the values allowed (it used to be the fewest-errors
     * branch's 'must be "point"'). */
    EXPECT_LIST(shapes, "{\"shape\":\"cube\"}", "", 1,
                "/shape|unknown shape \"cube\"; expected one of \"sphere\", \"point\"");
    EXPECT_LIST(shapes, "{\"shape\":7,\"m\":1}", "/b", 1,
                "/b/shape|unknown shape 7.0; expected one of \"sphere\", \"point\"");
    /* the discriminator missing while nothing else tells: name it */
    EXPECT_LIST(shapes, "{\"m\":1}", "", 1, "/shape|is required: one of \"sphere\", \"point\"");
    /* a key only one branch knows (r: the sphere) chooses it */
    EXPECT_LIST(shapes, "{\"r\":1}", "", 3, "/shape|is required;/m|is required;/p|is required");
    /* the JSON type: one text per kind of value, said once */
    EXPECT_LIST(shapes, "5", "", 1, "|must be an object, got number");
    EXPECT_LIST("{\"oneOf\":[{\"type\":\"string\"},{\"type\":\"object\",\"required\":[\"mass\"],"
                "\"additionalProperties\":false,\"properties\":{\"mass\":{\"type\":\"number\"}}}]}",
                "{\"gm\":1}", "/body", 2,
                "/body/mass|is required;/body/gm|unknown key; allowed here: mass");
    EXPECT_LIST("{\"oneOf\":[{\"type\":\"array\"},{\"const\":\"auto\"}]}", "5", "", 1,
                "|must be an array or \"auto\", got number");
    EXPECT_LIST("{\"oneOf\":[{\"type\":\"number\"},{\"enum\":[\"sun\",\"earth\"]}]}", "null", "", 1,
                "|must be a number or one of [\"sun\",\"earth\"], got null");
    /* velocity forms: no key of any form -> what each form needs */
    EXPECT_LIST(one, "{\"speed\":1}", "/v", 1,
                "/v|matches none of the allowed forms; give one of {beta}, {gamma, dir}");
    EXPECT_LIST(one, "{}", "", 1, "|matches none of the allowed forms; give one of {beta}, {gamma, dir}");
    EXPECT_LIST(one, "{\"gamma\":2}", "", 1, "/dir|is required");
    /* one 4-vector or a list of them: the items' JSON type chooses (a list
     * of two used to get "must have at least 4 items, got 2") */
    const char *vec4 =
        "{\"oneOf\":[{\"type\":\"array\",\"minItems\":1,\"items\":{\"type\":\"array\",\"minItems\":4,"
        "\"maxItems\":4,\"items\":{\"type\":\"number\"}}},{\"type\":\"array\",\"minItems\":4,"
        "\"maxItems\":4,\"items\":{\"type\":\"number\"}}]}";
    EXPECT_LIST(vec4, "[[null,null,0,0],[1,0,0,0]]", "/vectors", 2,
                "/vectors/0/0|must be a number, got null;/vectors/0/1|must be a number, got null");
    EXPECT_LIST(vec4, "[null,null,0,0]", "", 2,
                "/0|must be a number, got null;/1|must be a number, got null");
    EXPECT_LIST(vec4, "[]", "", 1, "|must have at least 1 items, got 0");

    /* A huge array of wrong items reports a bounded number of errors. */
    {
        json_t *s = json_loads("{\"type\":\"array\",\"items\":{\"type\":\"string\"}}", 0, NULL);
        char msg[200];
        struct api_schema *c = api_schema_compile(s, msg, sizeof msg);
        json_t *a = json_array();
        for (int i = 0; i < 100000; i++) json_array_append_new(a, json_real(i));
        json_t *errs = json_array();
        size_t n = api_schema_validate(c, a, "", errs);
        CHECK(n >= API_SCHEMA_MAX_ERRORS);
        CHECK_EQ_INT(json_array_size(errs), API_SCHEMA_MAX_ERRORS);
        CHECK_EQ_INT(api_schema_validate(c, a, "", NULL), 100000);
        api_schema_free(c);
        json_decref(s);
        json_decref(a);
        json_decref(errs);
    }

    /* The self-check refuses unsupported keywords, malformed values and
     * schemas nested deeper than API_SCHEMA_MAX_DEPTH; compile does too. */
    {
        char msg[200];
        json_t *s = json_loads("{\"type\":\"object\",\"patternProperties\":{}}", 0, NULL);
        CHECK(api_schema_check(s, msg, sizeof msg) == -1);
        CHECK(strstr(msg, "patternProperties") != NULL);
        CHECK(api_schema_compile(s, msg, sizeof msg) == NULL);
        CHECK(strstr(msg, "patternProperties") != NULL);
        json_decref(s);
        s = json_loads("{\"type\":\"objekt\"}", 0, NULL);
        CHECK(api_schema_check(s, msg, sizeof msg) == -1);
        CHECK(api_schema_compile(s, msg, sizeof msg) == NULL);
        json_decref(s);
        s = json_loads("{\"properties\":{\"a\":{\"additionalProperties\":true}}}", 0, NULL);
        CHECK(api_schema_compile(s, msg, sizeof msg) == NULL);
        CHECK(!strcmp(msg, "#/properties/a: malformed value of 'additionalProperties'"));
        json_decref(s);
        s = json_loads(OBJ, 0, NULL);
        CHECK(api_schema_check(s, msg, sizeof msg) == 0);
        json_decref(s);
        char longmsg[600]; /* "#/items/items/...: ..." */
        for (int depth = API_SCHEMA_MAX_DEPTH; depth <= API_SCHEMA_MAX_DEPTH + 1; depth++) {
            json_t *d = json_object();
            for (int k = 0; k < depth; k++) d = json_pack("{s:o}", "items", d);
            struct api_schema *c = api_schema_compile(d, longmsg, sizeof longmsg);
            CHECK((c != NULL) == (depth <= API_SCHEMA_MAX_DEPTH));
            if (!c) CHECK(strstr(longmsg, "deeper than 32 levels") != NULL);
            api_schema_free(c);
            json_decref(d);
        }
        api_schema_free(NULL);
    }

    /* Every route schema: its example, and mutated copies, give the same
     * errors from the compiled tree as from the reference interpreter. */
    CHECK(api_init() == 0);
    int routes = 0, deepest = 0;
    seen_unknown = seen_required_one_of = seen_forms = seen_types = 0;
    for (size_t i = 0; i < api_route_count; i++) {
        const json_t *schema = api_route_schema(i);
        const struct api_schema *c = api_route_schema_compiled(i);
        CHECK((schema == NULL) == (c == NULL));
        if (!schema || !c || !api_routes[i]->example) continue;
        routes++;
        int d = schema_depth(schema);
        if (d > deepest) deepest = d;
        json_t *ex = json_loads(api_routes[i]->example, JSON_DECODE_INT_AS_REAL, NULL);
        CHECK(ex != NULL);
        if (!ex) continue;
        CHECK_EQ_INT(compare(schema, c, ex, "", api_routes[i]->path), 0);
        sweep_route(api_routes[i]->path, schema, c, ex);
        json_decref(ex);
    }
    CHECK(routes > 10);
    CHECK(deepest <= API_SCHEMA_MAX_DEPTH);
    CHECK(mismatches == 0);
    tl_passed += (int)(compared - mismatches);
    printf("%d route schemas (deepest %d levels), %ld instances compared, %ld mismatches\n",
           routes, deepest, compared, mismatches);
    /* The comparison reached every way of reporting a oneOf that matched no
     * branch (so the reference's rules are checked, not only its old paths). */
    printf("oneOf reports compared: %ld unknown value, %ld missing discriminator, %ld forms, "
           "%ld types\n", seen_unknown, seen_required_one_of, seen_forms, seen_types);
    CHECK(seen_unknown > 0 && seen_required_one_of > 0 && seen_forms > 0 && seen_types > 0);

    /* Figures only (never a check): validation cost before/after compiling. */
    for (size_t i = 0; i < api_route_count; i++) {
        const char *p = api_routes[i]->path;
        if (strcmp(p, "/v1/relativity/boost") && strcmp(p, "/v1/rigid/inertia")) continue;
        json_t *ex = json_loads(api_routes[i]->example, JSON_DECODE_INT_AS_REAL, NULL);
        if (ex) time_one(p, api_route_schema(i), api_route_schema_compiled(i), ex);
        json_decref(ex);
    }
    TEST_MAIN_END();
}
