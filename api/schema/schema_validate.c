/* schema_validate.c — the walker: api_schema_validate (api/schema/schema.h) checks an
 * instance against the compiled tree, keyword by keyword (type, const, enum,
 * properties, required, additionalProperties, items and their bounds,
 * uniqueItems, the numeric bounds, oneOf), listing each violation with its
 * pointer (api/schema/schema_error.c). A oneOf that no branch matches asks
 * api/schema/schema_branch.c which branch was meant, and settles a tie by the fewest
 * errors here.
 *
 * Every message, pointer and the order of the errors are those of the
 * reference interpreter in tests/api/test_schema.c (it walks the schema's
 * jansson objects on every call, the way mechd validated before schemas were
 * compiled, and chooses the branch of a oneOf that matched none by the same
 * rules, written again), which compares the two over every route schema.
 *
 * This is the hot path of every request: the walker's own steps stay static
 * in this file and the helpers it calls per value are inline
 * (api/schema/schema_internal.h); only a violation calls out of the file. */
#include "schema/schema_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

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
            api_schema_add_error(v, child, "is required");
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
        else api_schema_add_error(v, child, "unknown key; allowed here: %s", s->allowed);
    }
    if (s->bounds & (H_MIN_PROPS | H_MAX_PROPS)) {
        size_t n = json_object_size(inst);
        if ((s->bounds & H_MIN_PROPS) && (double)n < s->min_props)
            api_schema_add_error(v, ptr, "must have at least %g members", s->min_props);
        if ((s->bounds & H_MAX_PROPS) && (double)n > s->max_props)
            api_schema_add_error(v, ptr, "must have at most %g members", s->max_props);
    }
}

static void validate_array(struct vctx *v, const struct snode *s, const json_t *inst,
                           const char *ptr, size_t plen)
{
    size_t n = json_array_size(inst);
    if ((s->bounds & H_MIN_ITEMS) && (double)n < s->min_items) {
        api_schema_add_error(v, ptr, "must have at least %g items, got %zu", s->min_items, n);
        return;
    }
    if ((s->bounds & H_MAX_ITEMS) && (double)n > s->max_items) {
        api_schema_add_error(v, ptr, "must have at most %g items, got %zu", s->max_items, n);
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
                    api_schema_add_error(v, v->errors ? child : ptr, "repeats item %zu; items must be unique",
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
        api_schema_add_error(v, ptr, "must be >= %.17g, got %.17g", s->minimum, x);
    if ((s->bounds & H_MAXIMUM) && !(x <= s->maximum))
        api_schema_add_error(v, ptr, "must be <= %.17g, got %.17g", s->maximum, x);
    if ((s->bounds & H_EX_MINIMUM) && !(x > s->ex_minimum))
        api_schema_add_error(v, ptr, "must be > %.17g, got %.17g", s->ex_minimum, x);
    if ((s->bounds & H_EX_MAXIMUM) && !(x < s->ex_maximum))
        api_schema_add_error(v, ptr, "must be < %.17g, got %.17g", s->ex_maximum, x);
}

/* Rule 5 of the branch choice (api/schema/schema_branch.c): of the candidates cand[]
 * (nc of them), the one with the fewest errors, the first on a tie; the only
 * one without validating it. */
static long fewest_errors(const struct snode *s, const json_t *inst, const char *ptr, size_t plen,
                          const unsigned char *cand, size_t nc)
{
    const size_t nb = s->noneof;
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
        api_schema_add_error(v, ptr, "matches more than one of the allowed forms");
        return;
    }
    /* None matched: report why the form the instance was meant to be failed. */
    unsigned char cand[API_SCHEMA_MAX_BRANCHES];
    long nc = api_schema_branch_candidates(v, s, inst, ptr, plen, cand);
    if (nc < 1) return;
    long b = fewest_errors(s, inst, ptr, plen, cand, (size_t)nc);
    if (b >= 0) validate(v, s->oneof[b].node, inst, ptr, plen);
}

/* Recursion follows the compiled tree, so its depth is at most the schema's
 * (<= API_SCHEMA_MAX_DEPTH), whatever the instance. */
static void validate(struct vctx *v, const struct snode *s, const json_t *inst, const char *ptr,
                     size_t plen)
{
    if (v->errors && json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) { v->count++; return; }
    if (s->has_type && !type_ok(s->type_mask, inst)) {
        api_schema_add_error(v, ptr, "%s, got %s", s->type_msg, api_schema_type_name(inst));
        return;
    }
    if (s->cnst && !json_same(s->cnst, inst)) {
        api_schema_add_error(v, ptr, "must be %s", s->cnst_text);
        return;
    }
    if (s->enm) {
        size_t i;
        json_t *e;
        int found = 0;
        json_array_foreach(s->enm, i, e) if (json_same(e, inst)) { found = 1; break; }
        if (!found) {
            api_schema_add_error(v, ptr, "must be one of %s", s->enum_text);
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

size_t api_schema_node_errors(const struct snode *s, const json_t *inst)
{
    struct vctx t = {NULL, 0};
    validate(&t, s, inst, "", 0);
    return t.count;
}
