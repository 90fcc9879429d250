/* schema_compile.c — api_schema_compile and api_schema_free (api/schema/schema.h): a
 * checked schema (api/schema/schema_check.c) turned into the tree of struct snode the
 * walker reads (api/schema/schema_internal.h), with every message that depends only on
 * the schema formatted in advance and, for each oneOf branch, what tells it
 * apart from its siblings. */
#include "schema/schema_internal.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Compile the `type` keyword t into s (mask and message). 0, or -1 on OOM. */
static int compile_type(struct snode *s, const json_t *t)
{
    char text[220];
    s->has_type = 1;
    if (json_is_string(t)) {
        const char *name = json_string_value(t);
        s->type_mask = api_schema_type_bit(name);
        snprintf(text, sizeof text, "must be %s %s", strchr("aeiou", name[0]) ? "an" : "a",
                 name);
    } else {
        char names[200] = "";
        size_t i;
        json_t *e;
        json_array_foreach(t, i, e) {
            s->type_mask |= api_schema_type_bit(json_string_value(e));
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
    if (api_schema_check(schema, msg, n)) return NULL;
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
