/* schema_branch.c — alternatives: when an instance matches no branch of a
 * oneOf, which branch it was meant to be (by its JSON type, a discriminator's
 * value, its items' types, the keys only some branches know), and the error
 * when that choice itself is wrong ("must be X or Y", "unknown type ...",
 * "is required: one of ...", "matches none of the allowed forms"). The last
 * rule, the fewest errors, needs the walker and is in api/schema/schema_validate.c. */
#include "schema/schema_internal.h"

#include <stdio.h>
#include <string.h>

/* Short text form of a value for a message, into buf (n bytes, truncated);
 * returns buf. */
static char *value_text_tmp(const json_t *j, char *buf, size_t n)
{
    /* json_dumps allocates with jansson's allocator (during a request, the
     * per-thread arena of api/json/json_arena.c): free it with jansson's free. */
    json_malloc_t m;
    json_free_t f;
    json_get_alloc_funcs(&m, &f);
    char *t = json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(15));
    snprintf(buf, n, "%s", t ? t : "?");
    if (t) f(t);
    return buf;
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
 *  5. the candidate with the fewest errors (the first on a tie): that one
 *     validates, so it is the walker's (api/schema/schema_validate.c, fewest_errors).
 * Returns how many candidates are left in cand[], or -1 after reporting the
 * error. */
long api_schema_branch_candidates(struct vctx *v, const struct snode *s, const json_t *inst,
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
        api_schema_add_error(v, ptr, "must be %s, got %s", v->errors ? text : "", api_schema_type_name(inst));
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
                        api_schema_add_error(v, child, "unknown %s %s; expected one of %s", key, got, text);
                    } else {
                        api_schema_add_error(v, ptr, "unknown");
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
                api_schema_add_error(v, v->errors ? child : ptr, "is required: one of %s",
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
            api_schema_add_error(v, ptr, "matches none of the allowed forms; give one of %s",
                      v->errors ? text : "");
            return -1;
        }
    }
    return (long)nc;
}
