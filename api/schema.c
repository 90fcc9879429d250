/* schema.c — the JSON Schema subset validator (see schema.h): the self-check
 * of a route schema, its compilation into a tree of struct snode, and the
 * validation of a request against that tree.
 *
 * Every message, pointer and the order of the errors are those of the
 * reference interpreter in tests/api/test_schema.c (it walks the schema's
 * jansson objects on every call, the way mechd validated before schemas were
 * compiled, and chooses the branch of a oneOf that matched none by the same
 * rules, written again), which compares the two over every route schema. */
#include "schema.h"
#include "respond.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PTR_MAX 512

/* Type bits: what `type` allows (T_INTEGER: a number with integral value). */
enum {
    T_OBJECT = 1u << 0,
    T_ARRAY = 1u << 1,
    T_STRING = 1u << 2,
    T_NUMBER = 1u << 3,
    T_INTEGER = 1u << 4,
    T_BOOLEAN = 1u << 5,
    T_NULL = 1u << 6,
};
#define T_ANY (T_OBJECT | T_ARRAY | T_STRING | T_NUMBER | T_BOOLEAN | T_NULL)

/* Which numeric keywords a node has. */
enum {
    H_MIN_ITEMS = 1u << 0,
    H_MAX_ITEMS = 1u << 1,
    H_MIN_PROPS = 1u << 2,
    H_MAX_PROPS = 1u << 3,
    H_MINIMUM = 1u << 4,
    H_MAXIMUM = 1u << 5,
    H_EX_MINIMUM = 1u << 6,
    H_EX_MAXIMUM = 1u << 7,
};

struct snode;

/* One entry of `properties`: key borrowed from the schema, len its bytes. */
struct sprop {
    const char *key;
    size_t len;
    struct snode *node;
};

/* A discriminator of a oneOf branch: property `key` must equal `value` (the
 * property schema's `const`, borrowed). */
struct sdisc {
    const char *key;
    const json_t *value;
};

/* A property name (borrowed from the schema) and its length. */
struct skey {
    const char *key;
    size_t len;
};

/* One oneOf branch and what tells it apart from its siblings when an instance
 * matches none of them (see choose_branch): its const properties, the JSON
 * types it admits and those of its items, and every key it knows (its own
 * properties and, recursively, those of its own oneOf branches). */
struct sbranch {
    struct snode *node;
    struct sdisc *disc;
    size_t ndisc;
    unsigned tmask;    /* coarse T_* (integer counted as number); T_ANY if untyped */
    unsigned imask;    /* the same for its items; T_ANY without items */
    struct skey *keys;
    size_t nkeys;
};

/* One compiled schema object. Texts are formatted at compile time exactly as
 * the messages print them; pointers to json_t are borrowed from the schema. */
struct snode {
    unsigned has_type;  /* `type` present */
    unsigned type_mask; /* T_* */
    unsigned bounds;    /* H_* */
    int addl_false;     /* additionalProperties: false */
    int unique;         /* uniqueItems: true */
    char *type_msg;     /* "must be an integer", "must be string or null" */
    const json_t *cnst;
    char *cnst_text;
    const json_t *enm;
    char *enum_text;
    struct sprop *props;
    size_t nprops;
    const char **required;
    size_t nrequired;
    char *allowed; /* "a, b" or "none" (with addl_false only) */
    struct snode *items;
    struct sbranch *oneof;
    size_t noneof;
    double min_items, max_items, min_props, max_props;
    double minimum, maximum, ex_minimum, ex_maximum;
    const json_t *dflt; /* `default` (borrowed), or NULL */
    int fills;          /* 1: a property default lies in this node's subtree */
};

struct api_schema {
    struct snode *root;
};

/* ---- pointers -------------------------------------------------------------- */

/* Append '/' + escaped token to buf, which holds len bytes (capacity n).
 * Returns the new length. */
static size_t pointer_append_at(char *buf, size_t n, size_t len, const char *token)
{
    if (len + 1 >= n) return len;
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
    return len;
}

void api_pointer_append(char *buf, size_t n, const char *token)
{
    pointer_append_at(buf, n, strlen(buf), token);
}

/* ptr (plen bytes) + "/" + escaped key into buf[PTR_MAX]; returns its length. */
static size_t pointer_key(char *buf, const char *ptr, size_t plen, const char *key)
{
    if (plen > PTR_MAX - 1) plen = PTR_MAX - 1;
    memcpy(buf, ptr, plen);
    buf[plen] = '\0';
    return pointer_append_at(buf, PTR_MAX, plen, key);
}

/* base (blen bytes) + "/" + i into buf[PTR_MAX] (truncated to PTR_MAX - 1
 * bytes); without printf, since a 100000-vector request asks for 500000 of
 * these. Returns its length. */
static size_t pointer_index(char *buf, const char *base, size_t blen, size_t i)
{
    char digits[24];
    size_t nd = 0, k = i;
    do {
        digits[nd++] = (char)('0' + k % 10);
        k /= 10;
    } while (k);
    if (blen + 2 + nd > PTR_MAX) { /* does not fit: truncate like snprintf */
        snprintf(buf, PTR_MAX, "%s/%zu", base, i);
        return strlen(buf);
    }
    memcpy(buf, base, blen);
    buf[blen++] = '/';
    while (nd) buf[blen++] = digits[--nd];
    buf[blen] = '\0';
    return blen;
}

/* ---- validation ---------------------------------------------------------------- */

struct vctx {
    json_t *errors; /* may be NULL: count only */
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

static int type_ok(unsigned mask, const json_t *j)
{
    switch (json_typeof(j)) {
    case JSON_OBJECT: return (mask & T_OBJECT) != 0;
    case JSON_ARRAY: return (mask & T_ARRAY) != 0;
    case JSON_STRING: return (mask & T_STRING) != 0;
    case JSON_INTEGER:
    case JSON_REAL: {
        if (mask & T_NUMBER) return 1;
        if (!(mask & T_INTEGER)) return 0;
        double x = json_number_value(j);
        return isfinite(x) && floor(x) == x;
    }
    case JSON_TRUE:
    case JSON_FALSE: return (mask & T_BOOLEAN) != 0;
    case JSON_NULL: return (mask & T_NULL) != 0;
    }
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

/* The compiled child for property `key` (len bytes), or NULL. Properties are
 * few per object: a linear scan that mostly stops at the length. */
static const struct snode *prop_find(const struct snode *s, const char *key, size_t len)
{
    for (size_t i = 0; i < s->nprops; i++) {
        const struct sprop *p = &s->props[i];
        if (p->len == len && p->key[0] == key[0] && !memcmp(p->key, key, len)) return p->node;
    }
    return NULL;
}

static void validate(struct vctx *v, const struct snode *s, const json_t *inst, const char *ptr,
                     size_t plen);

static void validate_object(struct vctx *v, const struct snode *s, const json_t *inst,
                            const char *ptr, size_t plen)
{
    char child[PTR_MAX];
    for (size_t i = 0; i < s->nrequired; i++) {
        const char *k = s->required[i];
        if (!json_object_get(inst, k)) {
            if (!v->errors) { v->count++; continue; } /* counting only */
            pointer_key(child, ptr, plen, k);
            add_error(v, child, "is required");
        }
    }
    const char *key;
    json_t *val;
    json_object_foreach((json_t *)inst, key, val) {
        /* strlen, not the stored length: a key with an embedded NUL is looked
         * up by its C-string prefix, as json_object_get() would. */
        const struct snode *ps = prop_find(s, key, strlen(key));
        if (!ps && !s->addl_false) continue;
        if (!v->errors) { /* counting only: no pointers */
            if (ps) validate(v, ps, val, ptr, plen);
            else v->count++;
            continue;
        }
        size_t clen = pointer_key(child, ptr, plen, key);
        if (ps) validate(v, ps, val, child, clen);
        else add_error(v, child, "unknown key; allowed here: %s", s->allowed);
    }
    if (s->bounds & (H_MIN_PROPS | H_MAX_PROPS)) {
        size_t n = json_object_size(inst);
        if ((s->bounds & H_MIN_PROPS) && (double)n < s->min_props)
            add_error(v, ptr, "must have at least %g members", s->min_props);
        if ((s->bounds & H_MAX_PROPS) && (double)n > s->max_props)
            add_error(v, ptr, "must have at most %g members", s->max_props);
    }
}

static void validate_array(struct vctx *v, const struct snode *s, const json_t *inst,
                           const char *ptr, size_t plen)
{
    size_t n = json_array_size(inst);
    if ((s->bounds & H_MIN_ITEMS) && (double)n < s->min_items) {
        add_error(v, ptr, "must have at least %g items, got %zu", s->min_items, n);
        return;
    }
    if ((s->bounds & H_MAX_ITEMS) && (double)n > s->max_items) {
        add_error(v, ptr, "must have at most %g items, got %zu", s->max_items, n);
        return;
    }
    char child[PTR_MAX];
    if (s->items) {
        for (size_t i = 0; i < n; i++) {
            if (!v->errors) {
                validate(v, s->items, json_array_get(inst, i), ptr, plen);
                continue;
            }
            /* Stop descending once the error list is full: a 100000-item
             * array of wrong items must not cost 100000 messages. */
            if (json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) break;
            size_t clen = pointer_index(child, ptr, plen, i);
            validate(v, s->items, json_array_get(inst, i), child, clen);
        }
    }
    if (s->unique) {
        for (size_t i = 0; i < n; i++)
            for (size_t j = i + 1; j < n && j < 1000; j++)
                if (json_same(json_array_get(inst, i), json_array_get(inst, j))) {
                    if (v->errors) pointer_index(child, ptr, plen, j);
                    add_error(v, v->errors ? child : ptr, "repeats item %zu; items must be unique",
                              i);
                    return;
                }
    }
}

static void validate_number(struct vctx *v, const struct snode *s, const json_t *inst,
                            const char *ptr)
{
    if (!s->bounds) return;
    double x = json_number_value(inst);
    if ((s->bounds & H_MINIMUM) && !(x >= s->minimum))
        add_error(v, ptr, "must be >= %.17g, got %.17g", s->minimum, x);
    if ((s->bounds & H_MAXIMUM) && !(x <= s->maximum))
        add_error(v, ptr, "must be <= %.17g, got %.17g", s->maximum, x);
    if ((s->bounds & H_EX_MINIMUM) && !(x > s->ex_minimum))
        add_error(v, ptr, "must be > %.17g, got %.17g", s->ex_minimum, x);
    if ((s->bounds & H_EX_MAXIMUM) && !(x < s->ex_maximum))
        add_error(v, ptr, "must be < %.17g, got %.17g", s->ex_maximum, x);
}

/* A branch is ruled out by a discriminator when one of its properties is a
 * `const` and the instance holds that key with another value (e.g. a body
 * with "shape": "box" is not a sphere, whatever else is wrong with it). */
static int discriminator_mismatch(const struct sbranch *b, const json_t *inst)
{
    if (!b->ndisc || !json_is_object(inst)) return 0;
    for (size_t i = 0; i < b->ndisc; i++) {
        const json_t *x = json_object_get(inst, b->disc[i].key);
        if (x && !json_same(b->disc[i].value, x)) return 1;
    }
    return 0;
}

/* Short text form of a value for a message, into buf (n bytes, truncated);
 * returns buf. */
static char *value_text_tmp(const json_t *j, char *buf, size_t n)
{
    /* json_dumps allocates with jansson's allocator (during a request, the
     * per-thread arena of json_arena.c): free it with jansson's free. */
    json_malloc_t m;
    json_free_t f;
    json_get_alloc_funcs(&m, &f);
    char *t = json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(15));
    snprintf(buf, n, "%s", t ? t : "?");
    if (t) f(t);
    return buf;
}

/* The coarse type bit of an instance (an integer counts as a number). */
static unsigned coarse_type(const json_t *j)
{
    switch (json_typeof(j)) {
    case JSON_OBJECT: return T_OBJECT;
    case JSON_ARRAY: return T_ARRAY;
    case JSON_STRING: return T_STRING;
    case JSON_INTEGER:
    case JSON_REAL: return T_NUMBER;
    case JSON_TRUE:
    case JSON_FALSE: return T_BOOLEAN;
    case JSON_NULL: return T_NULL;
    }
    return 0;
}

static int branch_has_key(const struct sbranch *b, const char *key, size_t len)
{
    for (size_t i = 0; i < b->nkeys; i++)
        if (b->keys[i].len == len && !memcmp(b->keys[i].key, key, len)) return 1;
    return 0;
}

/* The const that branch b requires of property key, or NULL. */
static const json_t *branch_const(const struct sbranch *b, const char *key)
{
    for (size_t i = 0; i < b->ndisc; i++)
        if (!strcmp(b->disc[i].key, key)) return b->disc[i].value;
    return NULL;
}

/* What a branch's JSON type is, for "must be X or Y": its type message
 * without "must be ", its const, or its enum. */
static void branch_type_text(const struct sbranch *b, char *buf, size_t n)
{
    const struct snode *s = b->node;
    if (s->has_type) snprintf(buf, n, "%s", s->type_msg + strlen("must be "));
    else if (s->cnst) snprintf(buf, n, "%s", s->cnst_text);
    else if (s->enm) snprintf(buf, n, "one of %s", s->enum_text);
    else snprintf(buf, n, "any value");
}

/* A branch's required keys as "{a, b}" (a key whose value is a const shown
 * with it: {type "spring", k}); a branch that requires none by its type. */
static void branch_form_text(const struct sbranch *b, char *buf, size_t n)
{
    const struct snode *s = b->node;
    if (!s->nrequired) {
        branch_type_text(b, buf, n);
        return;
    }
    size_t len = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < s->nrequired && len + 1 < n; i++) {
        const json_t *c = branch_const(b, s->required[i]);
        const struct snode *ps = prop_find(s, s->required[i], strlen(s->required[i]));
        snprintf(buf + len, n - len, "%s%s%s%s", i ? ", " : "{", s->required[i], c ? " " : "",
                 c && ps ? ps->cnst_text : "");
        len = strlen(buf);
    }
    if (len + 1 < n) snprintf(buf + len, n - len, "}");
}

/* Append to buf (capacity n, NUL-terminated) with a separator. */
static void text_add(char *buf, size_t n, const char *sep, const char *t)
{
    size_t len = strlen(buf);
    if (len + 1 < n) snprintf(buf + len, n - len, "%s%s", len ? sep : "", t);
}

/* The instance matches no branch: choose the one whose errors to report, or
 * report what is wrong with the choice itself. cand[] (nb entries) starts as
 * every branch. In order, each step narrowing the candidates only when it
 * tells them apart:
 *  1. the JSON type: the branches that admit the instance's type; none ->
 *     "must be <each branch's type> or ..., got <type>";
 *  2. for an object, each discriminator key (a property some candidates
 *     require to be a const) present in the instance: the candidates whose
 *     const it equals (or that have none there); none -> at /key
 *     "unknown key <value>; expected one of <consts>";
 *  3. for an array, the JSON type of its items: the candidates whose items
 *     admit the most of them;
 *  4. for an object, its keys that some candidates know and others do not:
 *     the candidates that know the most of them; when it has none: a
 *     discriminator key every candidate has is missing -> at /key "is
 *     required: one of <consts>", else "matches none of the allowed forms;
 *     give one of {required keys}, ...";
 *  5. the candidate with the fewest errors (the first on a tie).
 * Returns the branch index to validate, or -1 after reporting the error. */
static long choose_branch(struct vctx *v, const struct snode *s, const json_t *inst,
                          const char *ptr, size_t plen, unsigned char *cand)
{
    const size_t nb = s->noneof;
    size_t nc = nb;
    char text[400], part[200];
    /* 1. the JSON type */
    const unsigned ty = coarse_type(inst);
    size_t keep = 0;
    for (size_t i = 0; i < nb; i++) keep += (s->oneof[i].tmask & ty) != 0;
    if (keep == 0) {
        if (v->errors) {
            text[0] = '\0';
            for (size_t i = 0; i < nb; i++) {
                branch_type_text(&s->oneof[i], part, sizeof part);
                int dup = 0; /* sixteen object forms are "an object" once */
                for (size_t j = 0; j < i && !dup; j++) {
                    char prev[200];
                    branch_type_text(&s->oneof[j], prev, sizeof prev);
                    dup = !strcmp(prev, part);
                }
                if (!dup) text_add(text, sizeof text, " or ", part);
            }
        }
        add_error(v, ptr, "must be %s, got %s", v->errors ? text : "", type_name(inst));
        return -1;
    }
    for (size_t i = 0; i < nb; i++) cand[i] = (s->oneof[i].tmask & ty) != 0;
    nc = keep;
    /* 2. discriminator values, in branch and property order */
    if (ty == T_OBJECT) {
        for (size_t i = 0; i < nb; i++) {
            for (size_t d = 0; d < s->oneof[i].ndisc; d++) {
                const char *key = s->oneof[i].disc[d].key;
                const json_t *x = json_object_get(inst, key);
                if (!x) continue;
                size_t m = 0;
                for (size_t j = 0; j < nb; j++) {
                    if (!cand[j]) continue;
                    const json_t *c = branch_const(&s->oneof[j], key);
                    m += !c || json_same(c, x);
                }
                if (m == 0) {
                    char child[PTR_MAX];
                    if (v->errors) {
                        text[0] = '\0';
                        for (size_t j = 0; j < nb; j++) {
                            const json_t *c = cand[j] ? branch_const(&s->oneof[j], key) : NULL;
                            int dup = 0;
                            for (size_t k = 0; c && k < j; k++)
                                if (cand[k] && branch_const(&s->oneof[k], key) &&
                                    json_same(branch_const(&s->oneof[k], key), c))
                                    dup = 1;
                            if (!c || dup) continue;
                            const struct snode *ps =
                                prop_find(s->oneof[j].node, key, strlen(key));
                            text_add(text, sizeof text, ", ", ps ? ps->cnst_text : "?");
                        }
                        char *got = value_text_tmp(x, part, sizeof part);
                        pointer_key(child, ptr, plen, key);
                        add_error(v, child, "unknown %s %s; expected one of %s", key, got, text);
                    } else {
                        add_error(v, ptr, "unknown");
                    }
                    return -1;
                }
                for (size_t j = 0; j < nb; j++) {
                    if (!cand[j]) continue;
                    const json_t *c = branch_const(&s->oneof[j], key);
                    if (c && !json_same(c, x)) cand[j] = 0;
                }
                nc = m;
            }
        }
    }
    /* 3. the JSON type of an array's items */
    if (ty == T_ARRAY && nc > 1) {
        size_t best = 0, lo = (size_t)-1, score[API_SCHEMA_MAX_BRANCHES];
        for (size_t i = 0; i < nb; i++) {
            if (!cand[i]) continue;
            size_t k = 0, n = json_array_size(inst);
            for (size_t j = 0; j < n; j++)
                k += (s->oneof[i].imask & coarse_type(json_array_get(inst, j))) != 0;
            score[i] = k;
            if (k > best) best = k;
            if (k < lo) lo = k;
        }
        if (best > lo) {
            nc = 0;
            for (size_t i = 0; i < nb; i++)
                if (cand[i]) nc += (cand[i] = score[i] == best);
        }
    }
    /* 4. the keys that tell the candidates apart */
    if (ty == T_OBJECT && nc > 1) {
        size_t score[API_SCHEMA_MAX_BRANCHES] = {0}, best = 0;
        int differ = 0;
        for (size_t i = 0; i < nb && !differ; i++)
            for (size_t k = 0; cand[i] && k < s->oneof[i].nkeys && !differ; k++)
                for (size_t j = 0; j < nb; j++)
                    if (cand[j] && !branch_has_key(&s->oneof[j], s->oneof[i].keys[k].key,
                                                   s->oneof[i].keys[k].len)) {
                        differ = 1;
                        break;
                    }
        const char *key;
        json_t *val;
        json_object_foreach((json_t *)inst, key, val) {
            size_t klen = strlen(key); /* as validate_object looks keys up */
            size_t have = 0;
            for (size_t i = 0; i < nb; i++)
                have += cand[i] && branch_has_key(&s->oneof[i], key, klen);
            if (have == 0 || have == nc) continue; /* tells nothing apart */
            for (size_t i = 0; i < nb; i++)
                if (cand[i] && branch_has_key(&s->oneof[i], key, klen) && ++score[i] > best)
                    best = score[i];
        }
        if (best > 0) {
            nc = 0;
            for (size_t i = 0; i < nb; i++)
                if (cand[i]) nc += (cand[i] = score[i] == best);
        } else if (differ) {
            /* a discriminator every candidate has, missing: name it */
            const char *dkey = NULL;
            for (size_t i = 0; i < nb && !dkey; i++)
                for (size_t d = 0; cand[i] && d < s->oneof[i].ndisc && !dkey; d++) {
                    const char *k = s->oneof[i].disc[d].key;
                    int all = 1;
                    for (size_t j = 0; j < nb && all; j++)
                        all = !cand[j] || branch_const(&s->oneof[j], k) != NULL;
                    if (all && !json_object_get(inst, k)) dkey = k;
                }
            if (dkey) {
                char child[PTR_MAX];
                if (v->errors) {
                    text[0] = '\0';
                    for (size_t j = 0; j < nb; j++) {
                        if (!cand[j]) continue;
                        const struct snode *ps = prop_find(s->oneof[j].node, dkey, strlen(dkey));
                        int dup = 0;
                        for (size_t k = 0; k < j && !dup; k++)
                            dup = cand[k] && json_same(branch_const(&s->oneof[k], dkey),
                                                       branch_const(&s->oneof[j], dkey));
                        if (!dup) text_add(text, sizeof text, ", ", ps ? ps->cnst_text : "?");
                    }
                    pointer_key(child, ptr, plen, dkey);
                }
                add_error(v, v->errors ? child : ptr, "is required: one of %s",
                          v->errors ? text : "");
                return -1;
            }
            if (v->errors) {
                text[0] = '\0';
                for (size_t i = 0; i < nb; i++) {
                    if (!cand[i]) continue;
                    branch_form_text(&s->oneof[i], part, sizeof part);
                    text_add(text, sizeof text, ", ", part);
                }
            }
            add_error(v, ptr, "matches none of the allowed forms; give one of %s",
                      v->errors ? text : "");
            return -1;
        }
    }
    /* 5. the fewest errors */
    long best = -1;
    size_t best_count = (size_t)-1;
    for (size_t i = 0; i < nb; i++) {
        if (!cand[i]) continue;
        if (nc == 1) return (long)i;
        struct vctx t = {NULL, 0};
        validate(&t, s->oneof[i].node, inst, ptr, plen);
        if (t.count < best_count) {
            best_count = t.count;
            best = (long)i;
        }
    }
    return best;
}

static void validate_oneof(struct vctx *v, const struct snode *s, const json_t *inst,
                           const char *ptr, size_t plen)
{
    size_t passes = 0, nb = s->noneof;
    /* A branch whose discriminator (a const property) the instance
     * contradicts cannot pass: it need not be validated. */
    for (size_t i = 0; i < nb && passes < 2; i++) {
        if (discriminator_mismatch(&s->oneof[i], inst)) continue;
        struct vctx t = {NULL, 0};
        validate(&t, s->oneof[i].node, inst, ptr, plen);
        if (t.count == 0) passes++;
    }
    if (passes == 1) return;
    if (passes > 1) {
        add_error(v, ptr, "matches more than one of the allowed forms");
        return;
    }
    /* None matched: report why the form the instance was meant to be failed. */
    unsigned char cand[API_SCHEMA_MAX_BRANCHES];
    long b = choose_branch(v, s, inst, ptr, plen, cand);
    if (b >= 0) validate(v, s->oneof[b].node, inst, ptr, plen);
}

/* Recursion follows the compiled tree, so its depth is at most the schema's
 * (<= API_SCHEMA_MAX_DEPTH), whatever the instance. */
static void validate(struct vctx *v, const struct snode *s, const json_t *inst, const char *ptr,
                     size_t plen)
{
    if (v->errors && json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) { v->count++; return; }
    if (s->has_type && !type_ok(s->type_mask, inst)) {
        add_error(v, ptr, "%s, got %s", s->type_msg, type_name(inst));
        return;
    }
    if (s->cnst && !json_same(s->cnst, inst)) {
        add_error(v, ptr, "must be %s", s->cnst_text);
        return;
    }
    if (s->enm) {
        size_t i;
        json_t *e;
        int found = 0;
        json_array_foreach(s->enm, i, e) if (json_same(e, inst)) { found = 1; break; }
        if (!found) {
            add_error(v, ptr, "must be one of %s", s->enum_text);
            return;
        }
    }
    switch (json_typeof(inst)) {
    case JSON_OBJECT: validate_object(v, s, inst, ptr, plen); break;
    case JSON_ARRAY: validate_array(v, s, inst, ptr, plen); break;
    case JSON_INTEGER:
    case JSON_REAL: validate_number(v, s, inst, ptr); break;
    default: break;
    }
    if (s->noneof) validate_oneof(v, s, inst, ptr, plen);
}

size_t api_schema_validate(const struct api_schema *schema, const json_t *instance,
                           const char *pointer, json_t *errors)
{
    if (!schema) return 0; /* as the empty schema {} (what a NULL json_t schema did) */
    struct vctx v = {errors, 0};
    const char *p = pointer ? pointer : "";
    validate(&v, schema->root, instance, p, strlen(p));
    return v.count;
}

/* ---- defaults ------------------------------------------------------------------ *
 *
 * The body a handler sees carries every default its schema states, so C never
 * restates one. Copy on write: a node returns NULL when nothing below it
 * changes, else a new value (a shallow copy of the object or array with the
 * changed members replaced), so the caller's instance is never modified and
 * the common case of a body that states everything copies nothing. */

/* A default as the request parser would have produced it (api/json_read.c
 * reads every number as a real: a default "samples": 200 becomes 200.0, just
 * as an explicit "samples": 200 in a request does). New reference or NULL. */
static json_t *default_value(const json_t *d)
{
    if (json_is_integer(d)) return json_real((double)json_integer_value(d));
    return json_deep_copy(d);
}

static json_t *fill(const struct snode *s, const json_t *inst, const char *const *skip, int *oom);

/* A shallow copy of an object or array (members shared), or NULL when memory
 * ran out — never a partial copy (jansson's json_copy may drop members then). */
static json_t *shallow_copy(const json_t *inst)
{
    json_t *out;
    if (json_is_object(inst)) {
        const char *key;
        json_t *val;
        if (!(out = json_object())) return NULL;
        json_object_foreach((json_t *)inst, key, val) {
            if (json_object_set_nocheck(out, key, val)) {
                json_decref(out);
                return NULL;
            }
        }
        return out;
    }
    size_t i;
    json_t *val;
    if (!(out = json_array())) return NULL;
    json_array_foreach(inst, i, val) {
        if (json_array_append(out, val)) {
            json_decref(out);
            return NULL;
        }
    }
    return out;
}

/* The oneOf branch inst matches (it was validated, so exactly one), or NULL.
 * When the discriminators (a const "shape", "type") leave one candidate, that
 * is the branch, with no second validation (an inertia request's bodies). */
static const struct snode *matching_branch(const struct snode *s, const json_t *inst)
{
    size_t left = 0, last = 0;
    for (size_t i = 0; i < s->noneof; i++)
        if (!discriminator_mismatch(&s->oneof[i], inst)) {
            left++;
            last = i;
        }
    if (left == 1) return s->oneof[last].node;
    for (size_t i = 0; i < s->noneof; i++) {
        if (discriminator_mismatch(&s->oneof[i], inst)) continue;
        struct vctx t = {NULL, 0};
        validate(&t, s->oneof[i].node, inst, "", 0);
        if (t.count == 0) return s->oneof[i].node;
    }
    return NULL;
}

static int skipped(const char *const *skip, const char *key)
{
    for (; skip && *skip; skip++)
        if (!strcmp(*skip, key)) return 1;
    return 0;
}

static json_t *fill(const struct snode *s, const json_t *inst, const char *const *skip, int *oom)
{
    if (!s->fills || *oom) return NULL;
    json_t *out = NULL;
    if (json_is_object(inst)) {
        for (size_t i = 0; i < s->nprops && !*oom; i++) {
            const struct sprop *p = &s->props[i];
            const json_t *child = json_object_getn(inst, p->key, p->len);
            json_t *rep;
            if (!child) {
                if (!p->node->dflt || skipped(skip, p->key)) continue;
                rep = default_value(p->node->dflt);
            } else {
                rep = fill(p->node, child, NULL, oom);
                if (!rep) continue;
            }
            if (!out) out = shallow_copy(inst);
            if (!rep || !out) {
                json_decref(rep);
                *oom = 1;
            } else if (json_object_setn_new_nocheck(out, p->key, p->len, rep)) {
                *oom = 1; /* rep was stolen */
            }
        }
    } else if (json_is_array(inst) && s->items && s->items->fills) {
        for (size_t i = 0; i < json_array_size(inst) && !*oom; i++) {
            json_t *rep = fill(s->items, json_array_get(inst, i), NULL, oom);
            if (!rep) continue;
            if (!out) out = shallow_copy(inst);
            if (!out) {
                json_decref(rep);
                *oom = 1;
            } else if (json_array_set_new(out, i, rep)) {
                *oom = 1;
            }
        }
    }
    if (s->noneof && !*oom) {
        const json_t *cur = out ? out : inst;
        const struct snode *b = matching_branch(s, cur);
        json_t *rep = b ? fill(b, cur, skip, oom) : NULL;
        if (rep) {
            json_decref(out);
            out = rep;
        }
    }
    if (*oom) {
        json_decref(out);
        return NULL;
    }
    return out;
}

json_t *api_schema_apply_defaults(const struct api_schema *schema, const json_t *instance,
                                  const char *const *skip_root)
{
    if (!instance) return NULL;
    int oom = 0;
    json_t *out = schema ? fill(schema->root, instance, skip_root, &oom) : NULL;
    if (oom) return NULL;
    return out ? out : json_incref((json_t *)instance);
}

/* ---- schema self-check ---------------------------------------------------- */

static const char *const known_keywords[] = {
    "type", "properties", "required", "additionalProperties", "items", "minItems",
    "maxItems", "uniqueItems", "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum",
    "enum", "const", "oneOf", "minProperties", "maxProperties", "title", "description",
    "default", "examples", "x-mechd-check", /* annotation for POST /v1/check (docs/grading.md) */
    NULL,
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

static int check(const json_t *s, const char *where, int depth, char *msg, size_t n)
{
    if (!json_is_object(s)) { snprintf(msg, n, "%s: schema must be an object", where); return -1; }
    if (depth > API_SCHEMA_MAX_DEPTH) {
        snprintf(msg, n, "%s: schema nests deeper than %d levels", where, API_SCHEMA_MAX_DEPTH);
        return -1;
    }
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
                if (check(pv, sub, depth + 1, msg, n)) return -1;
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
            if (check(val, sub, depth + 1, msg, n)) return -1;
        } else if (!strcmp(key, "oneOf")) {
            size_t i;
            json_t *e;
            if (!json_is_array(val) || json_array_size(val) == 0 ||
                json_array_size(val) > API_SCHEMA_MAX_BRANCHES)
                goto bad;
            json_array_foreach(val, i, e) {
                snprintf(sub, sizeof sub, "%s/oneOf/%zu", where, i);
                if (check(e, sub, depth + 1, msg, n)) return -1;
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
    return check(schema, "#", 0, msg, n);
}

/* ---- compilation ------------------------------------------------------------ */

static void node_free(struct snode *s)
{
    if (!s) return;
    for (size_t i = 0; i < s->nprops; i++) node_free(s->props[i].node);
    for (size_t i = 0; i < s->noneof; i++) {
        node_free(s->oneof[i].node);
        free(s->oneof[i].disc);
        free(s->oneof[i].keys);
    }
    node_free(s->items);
    free(s->props);
    free(s->required);
    free(s->oneof);
    free(s->type_msg);
    free(s->cnst_text);
    free(s->enum_text);
    free(s->allowed);
    free(s);
}

/* Short text form of a small JSON value for messages, truncated to n - 1
 * bytes; NULL if memory ran out. */
static char *value_text(const json_t *j, size_t n)
{
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(15));
    if (!s) return NULL;
    if (strlen(s) > n - 1) s[n - 1] = '\0';
    char *t = strdup(s);
    free(s);
    return t;
}

static unsigned type_bit(const char *t)
{
    static const unsigned bits[] = {T_OBJECT, T_ARRAY, T_STRING, T_NUMBER,
                                    T_INTEGER, T_BOOLEAN, T_NULL};
    for (size_t i = 0; type_names[i]; i++)
        if (!strcmp(type_names[i], t)) return bits[i];
    return 0;
}

/* Compile the `type` keyword t into s (mask and message). 0, or -1 on OOM. */
static int compile_type(struct snode *s, const json_t *t)
{
    char text[220];
    s->has_type = 1;
    if (json_is_string(t)) {
        const char *name = json_string_value(t);
        s->type_mask = type_bit(name);
        snprintf(text, sizeof text, "must be %s %s", strchr("aeiou", name[0]) ? "an" : "a",
                 name);
    } else {
        char names[200] = "";
        size_t i;
        json_t *e;
        json_array_foreach(t, i, e) {
            s->type_mask |= type_bit(json_string_value(e));
            size_t len = strlen(names);
            snprintf(names + len, sizeof names - len, "%s%s", i ? " or " : "",
                     json_string_value(e));
        }
        snprintf(text, sizeof text, "must be %s", names);
    }
    return (s->type_msg = strdup(text)) ? 0 : -1;
}

static struct snode *compile_node(const json_t *schema);

static int compile_props(struct snode *s, const json_t *props)
{
    size_t np = json_object_size(props);
    if (np && !(s->props = calloc(np, sizeof *s->props))) return -1;
    const char *pk;
    size_t plen;
    json_t *pv;
    json_object_keylen_foreach((json_t *)props, pk, plen, pv) {
        struct sprop *p = &s->props[s->nprops];
        p->key = pk;
        p->len = plen;
        if (!(p->node = compile_node(pv))) return -1;
        s->nprops++;
    }
    return 0;
}

/* The discriminators of branch b: its properties that hold a `const`. */
static int compile_discriminators(struct sbranch *b)
{
    const struct snode *s = b->node;
    size_t nd = 0;
    for (size_t i = 0; i < s->nprops; i++) nd += s->props[i].node->cnst != NULL;
    if (!nd) return 0;
    if (!(b->disc = calloc(nd, sizeof *b->disc))) return -1;
    for (size_t i = 0; i < s->nprops; i++)
        if (s->props[i].node->cnst) {
            b->disc[b->ndisc].key = s->props[i].key;
            b->disc[b->ndisc].value = s->props[i].node->cnst;
            b->ndisc++;
        }
    return 0;
}

/* The coarse JSON types a compiled schema admits (see struct sbranch). */
static unsigned node_types(const struct snode *s)
{
    if (s->has_type) {
        unsigned m = s->type_mask & ~T_INTEGER;
        return s->type_mask & T_INTEGER ? m | T_NUMBER : m;
    }
    if (s->cnst) return coarse_type(s->cnst);
    if (s->enm) {
        unsigned m = 0;
        size_t i;
        json_t *e;
        json_array_foreach(s->enm, i, e) m |= coarse_type(e);
        return m;
    }
    return T_ANY;
}

/* Add key (len bytes) to b's key set unless it is there. 0, or -1 on OOM. */
static int branch_key_add(struct sbranch *b, const char *key, size_t len, size_t *cap)
{
    if (branch_has_key(b, key, len)) return 0;
    if (b->nkeys == *cap) {
        size_t nc = *cap ? 2 * *cap : 8;
        struct skey *k = realloc(b->keys, nc * sizeof *k);
        if (!k) return -1;
        b->keys = k;
        *cap = nc;
    }
    b->keys[b->nkeys].key = key;
    b->keys[b->nkeys].len = len;
    b->nkeys++;
    return 0;
}

/* What tells branch b apart (struct sbranch): types, item types, key set. */
static int compile_branch_info(struct sbranch *b)
{
    const struct snode *s = b->node;
    b->tmask = node_types(s);
    b->imask = s->items ? node_types(s->items) : T_ANY;
    size_t cap = 0;
    for (size_t i = 0; i < s->nprops; i++)
        if (branch_key_add(b, s->props[i].key, s->props[i].len, &cap)) return -1;
    for (size_t i = 0; i < s->noneof; i++)
        for (size_t k = 0; k < s->oneof[i].nkeys; k++)
            if (branch_key_add(b, s->oneof[i].keys[k].key, s->oneof[i].keys[k].len, &cap))
                return -1;
    return 0;
}

/* Compile one (already checked) schema object; NULL when memory ran out. */
static struct snode *compile_node(const json_t *schema)
{
    struct snode *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    const json_t *props = NULL;
    const char *key;
    json_t *val;
    json_object_foreach((json_t *)schema, key, val) {
        if (!strcmp(key, "type")) {
            if (compile_type(s, val)) goto oom;
        } else if (!strcmp(key, "const")) {
            s->cnst = val;
            if (!(s->cnst_text = value_text(val, 120))) goto oom;
        } else if (!strcmp(key, "enum")) {
            s->enm = val;
            if (!(s->enum_text = value_text(val, 300))) goto oom;
        } else if (!strcmp(key, "properties")) {
            props = val;
            if (compile_props(s, val)) goto oom;
        } else if (!strcmp(key, "required")) {
            size_t nr = json_array_size(val), i;
            json_t *e;
            if (nr && !(s->required = calloc(nr, sizeof *s->required))) goto oom;
            json_array_foreach(val, i, e) s->required[s->nrequired++] = json_string_value(e);
        } else if (!strcmp(key, "additionalProperties")) {
            s->addl_false = 1; /* the check admits only false */
        } else if (!strcmp(key, "items")) {
            if (!(s->items = compile_node(val))) goto oom;
        } else if (!strcmp(key, "default")) {
            s->dflt = val;
        } else if (!strcmp(key, "uniqueItems")) {
            s->unique = json_is_true(val);
        } else if (!strcmp(key, "oneOf")) {
            size_t nb = json_array_size(val), i;
            json_t *e;
            if (!(s->oneof = calloc(nb, sizeof *s->oneof))) goto oom;
            json_array_foreach(val, i, e) {
                struct sbranch *b = &s->oneof[s->noneof];
                if (!(b->node = compile_node(e))) goto oom;
                s->noneof++;
                if (compile_discriminators(b) || compile_branch_info(b)) goto oom;
            }
        } else {
            static const struct {
                const char *name;
                unsigned bit;
                size_t off;
            } num[] = {
                {"minItems", H_MIN_ITEMS, offsetof(struct snode, min_items)},
                {"maxItems", H_MAX_ITEMS, offsetof(struct snode, max_items)},
                {"minProperties", H_MIN_PROPS, offsetof(struct snode, min_props)},
                {"maxProperties", H_MAX_PROPS, offsetof(struct snode, max_props)},
                {"minimum", H_MINIMUM, offsetof(struct snode, minimum)},
                {"maximum", H_MAXIMUM, offsetof(struct snode, maximum)},
                {"exclusiveMinimum", H_EX_MINIMUM, offsetof(struct snode, ex_minimum)},
                {"exclusiveMaximum", H_EX_MAXIMUM, offsetof(struct snode, ex_maximum)},
            };
            for (size_t i = 0; i < sizeof num / sizeof num[0]; i++)
                if (!strcmp(key, num[i].name)) {
                    s->bounds |= num[i].bit;
                    *(double *)(void *)((char *)s + num[i].off) = json_number_value(val);
                }
        }
    }
    if (s->addl_false) {
        /* The keys an unknown one is told about, in schema order. */
        char allowed[300] = "";
        const char *pk;
        json_t *pv;
        json_object_foreach((json_t *)props, pk, pv) {
            size_t len = strlen(allowed);
            snprintf(allowed + len, sizeof allowed - len, "%s%s", len ? ", " : "", pk);
        }
        if (!(s->allowed = strdup(allowed[0] ? allowed : "none"))) goto oom;
    }
    /* Whether api_schema_apply_defaults has anything to do below this node. */
    for (size_t i = 0; i < s->nprops; i++)
        s->fills |= s->props[i].node->dflt != NULL || s->props[i].node->fills;
    if (s->items) s->fills |= s->items->fills;
    for (size_t i = 0; i < s->noneof; i++) s->fills |= s->oneof[i].node->fills;
    return s;
oom:
    node_free(s);
    return NULL;
}

struct api_schema *api_schema_compile(const json_t *schema, char *msg, size_t n)
{
    if (check(schema, "#", 0, msg, n)) return NULL;
    struct api_schema *c = malloc(sizeof *c);
    if (c && !(c->root = compile_node(schema))) {
        free(c);
        c = NULL;
    }
    if (!c) snprintf(msg, n, "out of memory");
    return c;
}

void api_schema_free(struct api_schema *s)
{
    if (!s) return;
    node_free(s->root);
    free(s);
}
