/* schema_internal.h — what the files of the JSON Schema validator share (the
 * face for everyone else is api/schema/schema.h): the compiled tree (struct snode and
 * its parts), the validation context, the small helpers the walker calls on
 * every value (inline, so splitting the validator into files costs the hot
 * path no call), and the functions one of its files calls in another.
 *
 * The files and their one-way arrows (A -> B: A calls B):
 *   api/schema/schema_compile.c  compilation and freeing of the tree        -> api/schema/schema_check.c
 *   api/schema/schema_check.c    the supported subset and the self-check     -> api/schema/schema_error.c
 *   api/schema/schema_validate.c the walker: every keyword, oneOf by count   -> api/schema/schema_branch.c, api/schema/schema_error.c
 *   api/schema/schema_branch.c   which oneOf branch an instance was meant to be, and what
 *                     is wrong with the choice itself             -> api/schema/schema_error.c
 *   api/schema/schema_error.c    the error list: one entry per violation, and JSON pointers
 *                     (api_pointer_append; the walker's inline pieces are below)
 *   api/schema/schema_defaults.c the defaults filled into a valid body       -> api/schema/schema_validate.c
 * Not for use outside api/schema*.c. */
#ifndef API_SCHEMA_INTERNAL_H
#define API_SCHEMA_INTERNAL_H

#include <jansson.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "schema/schema.h"

/* Longest JSON pointer the validator builds (longer ones are cut). */
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

/* What one validation collects (api/schema/schema_error.c). */
struct vctx {
    json_t *errors; /* may be NULL: count only */
    size_t count;
};

/* ---- pointers (inline: a 100000-vector request asks for 500000) ------------- */

/* Append '/' + escaped token to buf, which holds len bytes (capacity n).
 * Returns the new length. */
static inline size_t pointer_append_at(char *buf, size_t n, size_t len, const char *token)
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

/* ptr (plen bytes) + "/" + escaped key into buf[PTR_MAX]; returns its length. */
static inline size_t pointer_key(char *buf, const char *ptr, size_t plen, const char *key)
{
    if (plen > PTR_MAX - 1) plen = PTR_MAX - 1;
    memcpy(buf, ptr, plen);
    buf[plen] = '\0';
    return pointer_append_at(buf, PTR_MAX, plen, key);
}

/* base (blen bytes) + "/" + i into buf[PTR_MAX] (truncated to PTR_MAX - 1
 * bytes); without printf, since a 100000-vector request asks for 500000 of
 * these. Returns its length. */
static inline size_t pointer_index(char *buf, const char *base, size_t blen, size_t i)
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

/* ---- small helpers of the walker and the branch choice ------------------------- */

/* JSON equality where 1 and 1.0 are equal (instances are parsed with
 * JSON_DECODE_INT_AS_REAL, schemas may hold integers). */
static inline int json_same(const json_t *a, const json_t *b)
{
    if (json_is_number(a) && json_is_number(b))
        return json_number_value(a) == json_number_value(b);
    return json_equal((json_t *)a, (json_t *)b);
}

/* The compiled child for property `key` (len bytes), or NULL. Properties are
 * few per object: a linear scan that mostly stops at the length. */
static inline const struct snode *prop_find(const struct snode *s, const char *key, size_t len)
{
    for (size_t i = 0; i < s->nprops; i++) {
        const struct sprop *p = &s->props[i];
        if (p->len == len && p->key[0] == key[0] && !memcmp(p->key, key, len)) return p->node;
    }
    return NULL;
}

/* The coarse type bit of an instance (an integer counts as a number). */
static inline unsigned coarse_type(const json_t *j)
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

static inline int branch_has_key(const struct sbranch *b, const char *key, size_t len)
{
    for (size_t i = 0; i < b->nkeys; i++)
        if (b->keys[i].len == len && !memcmp(b->keys[i].key, key, len)) return 1;
    return 0;
}

/* A branch is ruled out by a discriminator when one of its properties is a
 * `const` and the instance holds that key with another value (e.g. a body
 * with "shape": "box" is not a sphere, whatever else is wrong with it). */
static inline int discriminator_mismatch(const struct sbranch *b, const json_t *inst)
{
    if (!b->ndisc || !json_is_object(inst)) return 0;
    for (size_t i = 0; i < b->ndisc; i++) {
        const json_t *x = json_object_get(inst, b->disc[i].key);
        if (x && !json_same(b->disc[i].value, x)) return 1;
    }
    return 0;
}

/* ---- across the files ------------------------------------------------------ */

/* api/schema/schema_error.c: count a violation at pointer and, when v lists errors and
 * the list is not full (API_SCHEMA_MAX_ERRORS), append {"pointer", "detail"}
 * with the formatted detail (cut at 400 bytes). */
void api_schema_add_error(struct vctx *v, const char *pointer, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* api/schema/schema_error.c: the JSON type of j as messages name it ("number" for
 * integers and reals). Static text. */
const char *api_schema_type_name(const json_t *j);

/* api/schema/schema_branch.c: inst (at ptr, plen bytes) matches no branch of s's oneOf:
 * narrow the candidates by the form it was meant to have (the rules are
 * listed there) into cand[] (s->noneof entries, 1 = still a candidate).
 * Returns how many candidates are left (>= 1), or -1 after reporting what is
 * wrong with the choice itself into v. */
long api_schema_branch_candidates(struct vctx *v, const struct snode *s, const json_t *inst,
                                  const char *ptr, size_t plen, unsigned char *cand);

/* api/schema/schema_validate.c: the number of violations of inst against node s,
 * counted only (no message, no pointer). */
size_t api_schema_node_errors(const struct snode *s, const json_t *inst);

/* api/schema/schema_check.c: the T_* bit of a JSON Schema type name, 0 if the subset has
 * no such type. */
unsigned api_schema_type_bit(const char *name);

#endif
