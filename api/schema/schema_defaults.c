/* schema_defaults.c — api_schema_apply_defaults (api/schema/schema.h): every default a
 * schema states, filled into a valid body, so C never restates one. */
#include "schema/schema_internal.h"

#include <string.h>

/* The body a handler sees carries every default its schema states, so C never
 * restates one. Copy on write: a node returns NULL when nothing below it
 * changes, else a new value (a shallow copy of the object or array with the
 * changed members replaced), so the caller's instance is never modified and
 * the common case of a body that states everything copies nothing. */

/* A default as the request parser would have produced it (api/json/json_read.c
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
        if (api_schema_node_errors(s->oneof[i].node, inst) == 0) return s->oneof[i].node;
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
