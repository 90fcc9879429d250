/* check_field.c — the kind and unit of a field of an operation's answer, from
 * the x-mechd-check annotations of its response schema (see api/check/check_field.h and
 * docs/grading.md, "Kinds and units"). Walks the parsed schema along the JSON
 * pointer; no allocation, nothing kept between calls.
 */
#include "check/check_field.h"

#include <string.h>

#include "run/routes.h"

#define FIELD_TOKEN_MAX 256 /* longest property name looked up (ours are short) */

/* The "x-mechd-check" object of a schema node, or NULL. */
static const json_t *annotation(const json_t *node)
{
    const json_t *a = json_object_get(node, "x-mechd-check");
    return json_is_object(a) ? a : NULL;
}

/* The annotation's unit when it is one mechd knows or a template, else NULL. */
static const char *annotated_unit(const json_t *node)
{
    const char *u = json_string_value(json_object_get(annotation(node), "unit"));
    return u && (api_unit_find(u) || strchr(u, '{')) ? u : NULL;
}

/* Token [tok, tok + len) unescaped (RFC 6901) into buf (FIELD_TOKEN_MAX);
 * 0, or -1 when it does not fit or holds a bad escape. */
static int unescape(const char *tok, size_t len, char *buf)
{
    size_t o = 0;
    for (size_t i = 0; i < len; i++) {
        char ch = tok[i];
        if (ch == '~') {
            if (i + 1 >= len || (tok[i + 1] != '0' && tok[i + 1] != '1')) return -1;
            ch = tok[++i] == '0' ? '~' : '/';
        }
        if (o + 1 >= FIELD_TOKEN_MAX) return -1;
        buf[o++] = ch;
    }
    buf[o] = '\0';
    return 0;
}

static int is_index(const char *tok, size_t len)
{
    if (len == 0) return 0;
    for (size_t i = 0; i < len; i++)
        if (tok[i] < '0' || tok[i] > '9') return 0;
    return 1;
}

/* One step from node along the token: an array's items for an index, an
 * object's property by name. NULL when node has no such step. */
static const json_t *step_one(const json_t *node, const char *tok, size_t len, int *via_items)
{
    const json_t *items = json_object_get(node, "items");
    if (json_is_object(items) && is_index(tok, len)) {
        *via_items = 1;
        return items;
    }
    const json_t *props = json_object_get(node, "properties");
    char name[FIELD_TOKEN_MAX];
    if (json_is_object(props) && !unescape(tok, len, name)) {
        const json_t *p = json_object_get(props, name);
        if (json_is_object(p)) {
            *via_items = 0;
            return p;
        }
    }
    return NULL;
}

/* The step from node itself, else from the first of its alternatives that has it. */
static const json_t *step(const json_t *node, const char *tok, size_t len, int *via_items)
{
    const json_t *next = step_one(node, tok, len, via_items);
    if (next) return next;
    const json_t *alts = json_object_get(node, "oneOf");
    size_t i;
    const json_t *alt;
    json_array_foreach(alts, i, alt)
        if ((next = step_one(alt, tok, len, via_items))) return next;
    return NULL;
}

int api_check_field_in_schema(const json_t *schema, const char *pointer,
                              enum api_check_kind *kind, const char **unit)
{
    *kind = API_KIND_NUMBER;
    *unit = NULL;
    if (!json_is_object(schema) || !pointer || (pointer[0] && pointer[0] != '/')) return 0;
    const json_t *node = schema;
    const char *carried = NULL; /* the unit of the enclosing arrays, through items only */
    const char *p = pointer;
    while (*p == '/') {
        const char *tok = p + 1;
        size_t len = strcspn(tok, "/");
        int via_items = 0;
        const char *here = annotated_unit(node);
        const json_t *next = step(node, tok, len, &via_items);
        if (!next) return 0; /* not described: a plain number of unknown unit */
        carried = via_items ? (here ? here : carried) : NULL;
        node = next;
        p = tok + len;
    }
    int applied = 0;
    const char *kname = json_string_value(json_object_get(annotation(node), "kind"));
    if (kname && !api_check_kind_parse(kname, kind)) applied = 1;
    const char *u = annotated_unit(node);
    if (!u) u = carried;
    if (u) {
        *unit = u;
        applied = 1;
    }
    return applied;
}

int api_check_field(const char *path, const char *pointer, enum api_check_kind *kind,
                    const char **unit)
{
    for (size_t i = 0; path && i < api_route_count; i++)
        if (!strcmp(api_routes[i]->path, path))
            return api_check_field_in_schema(api_route_response_schema(i), pointer, kind, unit);
    *kind = API_KIND_NUMBER;
    *unit = NULL;
    return 0;
}

/* The string at JSON pointer [p, p + len) of doc (objects by name, arrays by
 * index), or NULL. */
static const char *string_at(const json_t *doc, const char *p, size_t len)
{
    const char *end = p + len;
    while (doc && p < end && *p == '/') {
        const char *tok = p + 1;
        size_t n = 0;
        while (tok + n < end && tok[n] != '/')
            n++;
        char name[FIELD_TOKEN_MAX];
        if (json_is_array(doc) && is_index(tok, n) && n < 10) {
            size_t i = 0;
            for (size_t k = 0; k < n; k++)
                i = 10 * i + (size_t)(tok[k] - '0');
            doc = json_array_get(doc, i);
        } else if (json_is_object(doc) && !unescape(tok, n, name)) {
            doc = json_object_get(doc, name);
        } else {
            return NULL;
        }
        p = tok + n;
    }
    return p == end ? json_string_value(doc) : NULL;
}

const char *api_check_unit_expand(const char *spec, const json_t *answer)
{
    if (!spec) return NULL;
    char buf[FIELD_TOKEN_MAX];
    size_t o = 0;
    for (const char *s = spec; *s;) {
        const char *piece = s;
        size_t n = 1;
        if (*s == '{') {
            const char *close = strchr(s, '}');
            if (!close) return NULL;
            piece = string_at(answer, s + 1, (size_t)(close - s - 1));
            if (!piece) return NULL;
            n = strlen(piece);
            s = close + 1;
        } else {
            s++;
        }
        if (o + n >= sizeof buf) return NULL;
        memcpy(buf + o, piece, n);
        o += n;
    }
    buf[o] = '\0';
    const struct api_unit *u = api_unit_find(buf);
    return u ? u->name : NULL;
}
