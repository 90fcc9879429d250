/* respond.c — serialising JSON bodies into api_response, with a fixed
 * fallback when memory runs out. */
#include "respond.h"

#include <stdlib.h>
#include <string.h>

static const char oom_body[] =
    "{\"type\":\"/problems/internal-error\",\"title\":\"Internal error\",\"status\":500,"
    "\"detail\":\"out of memory\"}\n";

static void respond_oom(struct api_response *resp)
{
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
    if (!resp->body) { respond_oom(resp); return; }
    resp->status = status;
    resp->content_type = content_type;
    resp->body_len = strlen(resp->body);
}

void api_respond_json(struct api_response *resp, int status, const char *content_type,
                      const json_t *body)
{
    memset(resp, 0, sizeof *resp);
    char *s = body ? json_dumps(body, JSON_COMPACT | JSON_REAL_PRECISION(17)) : NULL;
    if (!s) { respond_oom(resp); return; }
    size_t n = strlen(s);
    char *b = realloc(s, n + 2); /* add a trailing newline for terminals */
    if (!b) { free(s); respond_oom(resp); return; }
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
