/* respond.c — serialising JSON bodies into api_response, with a fixed
 * fallback when memory runs out. */
#include "respond.h"

#include <stdlib.h>
#include <string.h>

static const char oom_body[] =
    "{\"type\":\"/problems/internal-error\",\"title\":\"Internal error\",\"status\":500,"
    "\"detail\":\"out of memory\"}\n";

void api_respond_out_of_memory(struct api_response *resp)
{
    free(resp->body);
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
    char *s = body ? json_dumps(body, JSON_COMPACT | JSON_REAL_PRECISION(17)) : NULL;
    if (!s) { api_respond_out_of_memory(resp); return; }
    size_t n = strlen(s);
    char *b = realloc(s, n + 2); /* add a trailing newline for terminals */
    if (!b) { free(s); api_respond_out_of_memory(resp); return; }
    b[n] = '\n';
    b[n + 1] = '\0';
    resp->status = status;
    resp->content_type = content_type;
    resp->body = b;
    resp->body_len = n + 1;
}

void api_response_free(struct api_response *resp)
{
    if (!resp) return;
    free(resp->body);
    resp->body = NULL;
    resp->body_len = 0;
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
    json_object_set_new(e, "pointer", api_json_text(pointer));
    json_object_set_new(e, "detail", api_json_text(detail));
    return e;
}
