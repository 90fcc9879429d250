/* respond.c — serialising JSON bodies into api_response, with a fixed
 * fallback when memory runs out. */
#include "http/respond.h"

#include <stdlib.h>
#include <string.h>

#include "json/json_write.h"

static const char oom_body[] =
    "{\"type\":\"/problems/internal-error\",\"title\":\"Internal error\",\"status\":500,"
    "\"detail\":\"out of memory\"}\n";

void api_respond_out_of_memory(struct api_response *resp)
{
    if (!resp->body_static) free(resp->body);
    memset(resp, 0, sizeof *resp);
    resp->status = 500;
    resp->content_type = "application/problem+json";
    resp->retry_after = 0;
    resp->body = strdup(oom_body); /* may be NULL: the server then sends an empty body */
    resp->body_len = resp->body ? strlen(resp->body) : 0;
}

void api_respond_text(struct api_response *resp, int status, const char *content_type,
                      const char *text)
{
    memset(resp, 0, sizeof *resp);
    resp->body = strdup(text);
    if (!resp->body) { api_respond_out_of_memory(resp); return; }
    resp->status = status;
    resp->content_type = content_type;
    resp->body_len = strlen(resp->body);
}

void api_respond_json(struct api_response *resp, int status, const char *content_type,
                      const json_t *body)
{
    memset(resp, 0, sizeof *resp);
    /* Only objects and arrays, as json_dumps without JSON_ENCODE_ANY; a
     * trailing newline for terminals. */
    size_t n = 0;
    char *b = body && (json_is_object(body) || json_is_array(body))
                  ? api_json_write_compact(body, "\n", &n)
                  : NULL;
    if (!b) { api_respond_out_of_memory(resp); return; }
    resp->status = status;
    resp->content_type = content_type;
    resp->body = b;
    resp->body_len = n;
}

void api_response_free(struct api_response *resp)
{
    if (!resp) return;
    if (!resp->body_static) free(resp->body);
    resp->body = NULL;
    resp->body_len = 0;
    resp->body_static = 0;
}

/* Longest part of an instance kept (a request path is client-controlled). */
#define INSTANCE_MAX 256

/* Insert "key": text (a JSON string, at most INSTANCE_MAX bytes of text kept)
 * as the last member of a problem+json body; nothing for other bodies. The
 * body is one compact JSON object and maybe a newline. 1 when added, 0 when
 * resp is no problem body, -1 when out of memory (the response is then the
 * out-of-memory problem). */
static int add_problem_member(struct api_response *resp, const char *key, const char *text_in)
{
    if (!resp || !resp->body || resp->body_static || !resp->content_type ||
        strcmp(resp->content_type, "application/problem+json") != 0)
        return 0;
    size_t end = resp->body_len;
    while (end > 0 && resp->body[end - 1] != '}')
        end--;
    if (end < 2) return 0;
    char cut[INSTANCE_MAX + 1];
    snprintf(cut, sizeof cut, "%s", text_in);
    json_t *js = api_json_text(cut);
    char *text = js ? json_dumps(js, JSON_ENCODE_ANY | JSON_COMPACT) : NULL;
    json_decref(js);
    char head[64];
    int hl = snprintf(head, sizeof head, ",\"%s\":", key);
    char *b = text && hl > 0 && (size_t)hl < sizeof head
                  ? malloc(resp->body_len + (size_t)hl + strlen(text) + 1)
                  : NULL;
    if (!b) {
        free(text);
        api_respond_out_of_memory(resp);
        return -1;
    }
    size_t tl = strlen(text);
    size_t at = end - 1; /* the closing brace */
    int empty = resp->body[at - 1] == '{';
    memcpy(b, resp->body, at);
    size_t n = at;
    memcpy(b + n, head + empty, (size_t)hl - (size_t)empty);
    n += (size_t)hl - (size_t)empty;
    memcpy(b + n, text, tl);
    n += tl;
    memcpy(b + n, resp->body + at, resp->body_len - at);
    n += resp->body_len - at;
    b[n] = '\0';
    free(text);
    free(resp->body);
    resp->body = b;
    resp->body_len = n;
    return 1;
}

void api_response_set_instance(struct api_response *resp, const char *instance)
{
    if (!resp || resp->instance_set || !instance) return;
    if (add_problem_member(resp, "instance", instance) != 0) resp->instance_set = 1;
}

void api_response_set_request_id(struct api_response *resp, const char *id)
{
    if (!resp || !id || !id[0]) return;
    add_problem_member(resp, "request_id", id);
}

json_t *api_json_text(const char *text)
{
    if (!text) text = "";
    json_t *j = json_string(text);
    if (j) return j;
    /* Not valid UTF-8 (or out of memory): keep ASCII, replace the rest. */
    size_t n = strlen(text);
    char *copy = malloc(n + 1);
    if (!copy) return NULL;
    for (size_t i = 0; i <= n; i++)
        copy[i] = (unsigned char)text[i] < 0x80 ? text[i] : '?';
    j = json_string(copy);
    free(copy);
    return j;
}

json_t *api_error_entry(const char *pointer, const char *detail)
{
    json_t *e = json_object();
    if (!e) return NULL;
    json_object_set_new_nocheck(e, "pointer", api_json_text(pointer));
    json_object_set_new_nocheck(e, "detail", api_json_text(detail));
    return e;
}
