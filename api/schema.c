/* schema.c — the JSON Schema subset validator (see schema.h). */
#include "schema.h"
#include "respond.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PTR_MAX 512

struct vctx {
    json_t *errors;  /* may be NULL: count only */
    size_t count;
};

static void add_error(struct vctx *v, const char *pointer, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void add_error(struct vctx *v, const char *pointer, const char *fmt, ...)
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

void api_pointer_append(char *buf, size_t n, const char *token)
{
    size_t len = strlen(buf);
    if (len + 1 >= n) return;
    buf[len++] = '/';
    for (const char *p = token; *p && len + 1 < n; p++) {
        if (*p == '~' || *p == '/') {
            if (len + 2 >= n) break;
            buf[len++] = '~';
            buf[len++] = *p == '~' ? '0' : '1';
        } else {
            buf[len++] = *p;
        }
    }
    buf[len] = '\0';
}

/* base + "/" + i into buf (truncated to n - 1 bytes); without printf, since a
 * 100000-vector request asks for 500000 of these. */
static void pointer_index(char *buf, size_t n, const char *base, size_t i)
{
    char digits[24];
    size_t nd = 0;
    do {
        digits[nd++] = (char)('0' + i % 10);
        i /= 10;
    } while (i);
    size_t len = strlen(base);
    if (len + 2 + nd > n) { /* does not fit: the slow path truncates like snprintf */
        snprintf(buf, n, "%s/%zu", base, i);
        return;
    }
    memcpy(buf, base, len);
    buf[len++] = '/';
    while (nd) buf[len++] = digits[--nd];
    buf[len] = '\0';
}

static const char *type_name(const json_t *j)
{
    switch (json_typeof(j)) {
    case JSON_OBJECT: return "object";
    case JSON_ARRAY: return "array";
    case JSON_STRING: return "string";
    case JSON_INTEGER:
    case JSON_REAL: return "number";
    case JSON_TRUE:
    case JSON_FALSE: return "boolean";
    case JSON_NULL: return "null";
    }
    return "unknown";
}

static int type_matches(const char *t, const json_t *j)
{
    if (!strcmp(t, "object")) return json_is_object(j);
    if (!strcmp(t, "array")) return json_is_array(j);
    if (!strcmp(t, "string")) return json_is_string(j);
    if (!strcmp(t, "number")) return json_is_number(j);
    if (!strcmp(t, "integer")) {
        if (!json_is_number(j)) return 0;
        double x = json_number_value(j);
        return isfinite(x) && floor(x) == x;
    }
    if (!strcmp(t, "boolean")) return json_is_boolean(j);
    if (!strcmp(t, "null")) return json_is_null(j);
    return 0;
}

/* JSON equality where 1 and 1.0 are equal (instances are parsed with
 * JSON_DECODE_INT_AS_REAL, schemas may hold integers). */
static int json_same(const json_t *a, const json_t *b)
{
    if (json_is_number(a) && json_is_number(b))
        return json_number_value(a) == json_number_value(b);
    return json_equal((json_t *)a, (json_t *)b);
}

/* Short text form of a small JSON value for messages. */
static void value_text(const json_t *j, char *buf, size_t n)
{
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(15));
    snprintf(buf, n, "%s", s ? s : "?");
    free(s);
}

/* The keywords of one schema node, read in one pass over its members (a node
 * has a handful; looking each of the 17 keywords up by hash cost more than
 * the validation itself). NULL where absent. */
struct kw {
    const json_t *type, *cnst, *enm, *oneof, *props, *required, *addl, *min_props, *max_props;
    const json_t *items, *min_items, *max_items, *unique;
    const json_t *minimum, *maximum, *ex_minimum, *ex_maximum;
};

static void read_keywords(const json_t *s, struct kw *k)
{
    memset(k, 0, sizeof *k);
    const char *key;
    json_t *val;
    json_object_foreach((json_t *)s, key, val) {
        switch (key[0]) {
        case 't': if (!strcmp(key, "type")) k->type = val; break;
        case 'c': if (!strcmp(key, "const")) k->cnst = val; break;
        case 'e':
            if (!strcmp(key, "enum")) k->enm = val;
            else if (!strcmp(key, "exclusiveMinimum")) k->ex_minimum = val;
            else if (!strcmp(key, "exclusiveMaximum")) k->ex_maximum = val;
            break;
        case 'o': if (!strcmp(key, "oneOf")) k->oneof = val; break;
        case 'p': if (!strcmp(key, "properties")) k->props = val; break;
        case 'r': if (!strcmp(key, "required")) k->required = val; break;
        case 'a': if (!strcmp(key, "additionalProperties")) k->addl = val; break;
        case 'i': if (!strcmp(key, "items")) k->items = val; break;
        case 'u': if (!strcmp(key, "uniqueItems")) k->unique = val; break;
        case 'm':
            if (!strcmp(key, "minimum")) k->minimum = val;
            else if (!strcmp(key, "maximum")) k->maximum = val;
            else if (!strcmp(key, "minItems")) k->min_items = val;
            else if (!strcmp(key, "maxItems")) k->max_items = val;
            else if (!strcmp(key, "minProperties")) k->min_props = val;
            else if (!strcmp(key, "maxProperties")) k->max_props = val;
            break;
        default: break;
        }
    }
}

static void validate(struct vctx *v, const json_t *s, const json_t *inst, const char *ptr);

static void validate_type(struct vctx *v, const json_t *t, const json_t *inst, const char *ptr,
                          int *ok)
{
    if (json_is_string(t)) {
        *ok = type_matches(json_string_value(t), inst);
        if (!*ok)
            add_error(v, ptr, "must be %s %s, got %s",
                      strchr("aeiou", json_string_value(t)[0]) ? "an" : "a",
                      json_string_value(t), type_name(inst));
        return;
    }
    size_t i;
    json_t *e;
    json_array_foreach(t, i, e) {
        if (type_matches(json_string_value(e), inst)) { *ok = 1; return; }
    }
    *ok = 0;
    if (!v->errors) { v->count++; return; } /* counting only: no message */
    char names[200] = "";
    json_array_foreach(t, i, e) {
        size_t len = strlen(names);
        snprintf(names + len, sizeof names - len, "%s%s", i ? " or " : "", json_string_value(e));
    }
    add_error(v, ptr, "must be %s, got %s", names, type_name(inst));
}

static void validate_object(struct vctx *v, const struct kw *kw, const json_t *inst,
                            const char *ptr)
{
    const json_t *props = kw->props;
    const json_t *req = kw->required;
    const json_t *addl = kw->addl;
    char child[PTR_MAX];
    size_t i;
    json_t *e;

    json_array_foreach(req, i, e) {
        const char *k = json_string_value(e);
        if (!json_object_get(inst, k)) {
            if (!v->errors) { v->count++; continue; } /* counting only */
            snprintf(child, sizeof child, "%s", ptr);
            api_pointer_append(child, sizeof child, k);
            add_error(v, child, "is required");
        }
    }
    const char *key;
    json_t *val;
    json_object_foreach((json_t *)inst, key, val) {
        /* Pointers only matter where errors are recorded (not when counting). */
        const char *cp = ptr;
        if (v->errors) {
            snprintf(child, sizeof child, "%s", ptr);
            api_pointer_append(child, sizeof child, key);
            cp = child;
        }
        const json_t *ps = props ? json_object_get(props, key) : NULL;
        if (ps) {
            validate(v, ps, val, cp);
        } else if (json_is_false(addl)) {
            if (!v->errors) { v->count++; continue; } /* counting only */
            char allowed[300] = "";
            const char *pk;
            json_t *pv;
            json_object_foreach((json_t *)props, pk, pv) {
                size_t len = strlen(allowed);
                snprintf(allowed + len, sizeof allowed - len, "%s%s", len ? ", " : "", pk);
            }
            add_error(v, cp, "unknown key; allowed here: %s", allowed[0] ? allowed : "none");
        }
    }
    const json_t *mn = kw->min_props;
    const json_t *mx = kw->max_props;
    size_t n = json_object_size(inst);
    if (mn && (double)n < json_number_value(mn))
        add_error(v, ptr, "must have at least %g members", json_number_value(mn));
    if (mx && (double)n > json_number_value(mx))
        add_error(v, ptr, "must have at most %g members", json_number_value(mx));
}

static void validate_array(struct vctx *v, const struct kw *kw, const json_t *inst,
                           const char *ptr)
{
    size_t n = json_array_size(inst);
    const json_t *mn = kw->min_items;
    const json_t *mx = kw->max_items;
    if (mn && (double)n < json_number_value(mn)) {
        add_error(v, ptr, "must have at least %g items, got %zu", json_number_value(mn), n);
        return;
    }
    if (mx && (double)n > json_number_value(mx)) {
        add_error(v, ptr, "must have at most %g items, got %zu", json_number_value(mx), n);
        return;
    }
    const json_t *items = kw->items;
    if (items) {
        char child[PTR_MAX];
        for (size_t i = 0; i < n; i++) {
            /* Stop descending once the error list is full: a 100000-item
             * array of wrong items must not cost 100000 messages. */
            if (v->errors && json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) break;
            if (v->errors) pointer_index(child, sizeof child, ptr, i);
            validate(v, items, json_array_get(inst, i), v->errors ? child : ptr);
        }
    }
    if (json_is_true(kw->unique)) {
        for (size_t i = 0; i < n; i++)
            for (size_t j = i + 1; j < n && j < 1000; j++)
                if (json_same(json_array_get(inst, i), json_array_get(inst, j))) {
                    char child[PTR_MAX];
                    pointer_index(child, sizeof child, ptr, j);
                    add_error(v, child, "repeats item %zu; items must be unique", i);
                    return;
                }
    }
}

static void validate_number(struct vctx *v, const struct kw *kw, const json_t *inst,
                            const char *ptr)
{
    double x = json_number_value(inst);
    const json_t *k;
    if ((k = kw->minimum) && !(x >= json_number_value(k)))
        add_error(v, ptr, "must be >= %.17g, got %.17g", json_number_value(k), x);
    if ((k = kw->maximum) && !(x <= json_number_value(k)))
        add_error(v, ptr, "must be <= %.17g, got %.17g", json_number_value(k), x);
    if ((k = kw->ex_minimum) && !(x > json_number_value(k)))
        add_error(v, ptr, "must be > %.17g, got %.17g", json_number_value(k), x);
    if ((k = kw->ex_maximum) && !(x < json_number_value(k)))
        add_error(v, ptr, "must be < %.17g, got %.17g", json_number_value(k), x);
}

/* A branch is ruled out by a discriminator when one of its properties is a
 * `const` and the instance holds that key with another value (e.g. a body
 * with "shape": "box" is not a sphere, whatever else is wrong with it). */
static int discriminator_mismatch(const json_t *branch, const json_t *inst)
{
    const json_t *props = json_object_get(branch, "properties");
    if (!json_is_object(inst) || !props) return 0;
    const char *k;
    json_t *ps;
    json_object_foreach((json_t *)props, k, ps) {
        const json_t *c = json_object_get(ps, "const");
        const json_t *v = json_object_get(inst, k);
        if (c && v && !json_same(c, v)) return 1;
    }
    return 0;
}

static void validate_oneof(struct vctx *v, const json_t *branches, const json_t *inst,
                           const char *ptr)
{
    size_t i, best = 0, best_count = (size_t)-1, passes = 0;
    int best_mismatch = 1, any_allowed = 0;
    json_t *b;
    /* A branch whose discriminator (a const property) the instance contradicts
     * cannot pass, and is only a candidate for the error report when every
     * branch is contradicted: then it need not be validated at all. */
    json_array_foreach(branches, i, b) if (!discriminator_mismatch(b, inst)) any_allowed = 1;
    json_array_foreach(branches, i, b) {
        if (any_allowed && discriminator_mismatch(b, inst)) continue;
        struct vctx t = {NULL, 0};
        validate(&t, b, inst, ptr);
        if (t.count == 0) passes++;
        int mismatch = discriminator_mismatch(b, inst);
        /* Prefer branches the discriminator allows, then fewest errors. */
        if (mismatch < best_mismatch || (mismatch == best_mismatch && t.count < best_count)) {
            best_mismatch = mismatch;
            best_count = t.count;
            best = i;
        }
    }
    if (passes == 1) return;
    if (passes > 1) {
        add_error(v, ptr, "matches more than one of the allowed forms");
        return;
    }
    /* None matched: report why the closest form failed. */
    validate(v, json_array_get(branches, best), inst, ptr);
}

static void validate(struct vctx *v, const json_t *s, const json_t *inst, const char *ptr)
{
    if (v->errors && json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) { v->count++; return; }
    struct kw kw;
    read_keywords(s, &kw);
    const json_t *k;
    if ((k = kw.type)) {
        int ok;
        validate_type(v, k, inst, ptr, &ok);
        if (!ok) return;
    }
    if ((k = kw.cnst) && !json_same(k, inst)) {
        char t[120] = "";
        if (v->errors) value_text(k, t, sizeof t); /* no message when counting only */
        add_error(v, ptr, "must be %s", t);
        return;
    }
    if ((k = kw.enm)) {
        size_t i;
        json_t *e;
        int found = 0;
        json_array_foreach(k, i, e) if (json_same(e, inst)) found = 1;
        if (!found) {
            char t[300] = "";
            if (v->errors) value_text(k, t, sizeof t);
            add_error(v, ptr, "must be one of %s", t);
            return;
        }
    }
    if (json_is_object(inst)) validate_object(v, &kw, inst, ptr);
    else if (json_is_array(inst)) validate_array(v, &kw, inst, ptr);
    else if (json_is_number(inst)) validate_number(v, &kw, inst, ptr);
    if ((k = kw.oneof)) validate_oneof(v, k, inst, ptr);
}

size_t api_schema_validate(const json_t *schema, const json_t *instance,
                           const char *pointer, json_t *errors)
{
    struct vctx v = {errors, 0};
    validate(&v, schema, instance, pointer ? pointer : "");
    return v.count;
}

/* ---- schema self-check ---------------------------------------------------- */

static const char *const known_keywords[] = {
    "type", "properties", "required", "additionalProperties", "items", "minItems",
    "maxItems", "uniqueItems", "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum",
    "enum", "const", "oneOf", "minProperties", "maxProperties", "title", "description",
    "default", "examples", NULL,
};
static const char *const type_names[] = {
    "object", "array", "string", "number", "integer", "boolean", "null", NULL,
};

static int in_list(const char *const *list, const char *s)
{
    for (; *list; list++)
        if (!strcmp(*list, s)) return 1;
    return 0;
}

static int check(const json_t *s, const char *where, char *msg, size_t n)
{
    if (!json_is_object(s)) { snprintf(msg, n, "%s: schema must be an object", where); return -1; }
    const char *key;
    json_t *val;
    char sub[PTR_MAX];
    json_object_foreach((json_t *)s, key, val) {
        if (!in_list(known_keywords, key)) {
            snprintf(msg, n, "%s: unsupported keyword '%s'", where, key);
            return -1;
        }
        if (!strcmp(key, "type")) {
            if (json_is_string(val)) {
                if (!in_list(type_names, json_string_value(val))) goto bad;
            } else if (json_is_array(val)) {
                size_t i;
                json_t *e;
                json_array_foreach(val, i, e)
                    if (!json_is_string(e) || !in_list(type_names, json_string_value(e))) goto bad;
            } else goto bad;
        } else if (!strcmp(key, "properties")) {
            if (!json_is_object(val)) goto bad;
            const char *pk;
            json_t *pv;
            json_object_foreach(val, pk, pv) {
                snprintf(sub, sizeof sub, "%s/properties", where);
                api_pointer_append(sub, sizeof sub, pk);
                if (check(pv, sub, msg, n)) return -1;
            }
        } else if (!strcmp(key, "required")) {
            size_t i;
            json_t *e;
            if (!json_is_array(val)) goto bad;
            json_array_foreach(val, i, e) if (!json_is_string(e)) goto bad;
        } else if (!strcmp(key, "additionalProperties")) {
            if (!json_is_false(val)) goto bad;
        } else if (!strcmp(key, "items")) {
            snprintf(sub, sizeof sub, "%s/items", where);
            if (check(val, sub, msg, n)) return -1;
        } else if (!strcmp(key, "oneOf")) {
            size_t i;
            json_t *e;
            if (!json_is_array(val) || json_array_size(val) == 0) goto bad;
            json_array_foreach(val, i, e) {
                snprintf(sub, sizeof sub, "%s/oneOf/%zu", where, i);
                if (check(e, sub, msg, n)) return -1;
            }
        } else if (!strcmp(key, "enum")) {
            if (!json_is_array(val)) goto bad;
        } else if (!strcmp(key, "uniqueItems")) {
            if (!json_is_boolean(val)) goto bad;
        } else if (in_list((const char *const[]){"minItems", "maxItems", "minimum", "maximum",
                                                  "exclusiveMinimum", "exclusiveMaximum",
                                                  "minProperties", "maxProperties", NULL},
                           key)) {
            if (!json_is_number(val)) goto bad;
        }
        continue;
    bad:
        snprintf(msg, n, "%s: malformed value of '%s'", where, key);
        return -1;
    }
    return 0;
}

int api_schema_check(const json_t *schema, char *msg, size_t n)
{
    return check(schema, "#", msg, n);
}
