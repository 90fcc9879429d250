/* answer_send.c — handing an answer's body to libmicrohttpd (part of the
 * HTTP front end, see http.c): answers of SRV_TRACK_MIN bytes or more through
 * a reader that counts the bytes sent (so a cut-off answer is logged with
 * what was sent, not its length) and gives the answer's memory back to the
 * answer-memory budget when libmicrohttpd frees it; smaller ones as a buffer,
 * sent with the headers in one write. */
#include "http_internal.h"

#include <malloc.h>
#include <microhttpd.h>
#include <stdlib.h>
#include <string.h>

#include "answer_mem.h"

/* MHD's free of an answer body: a large answer (a long trajectory, a batch)
 * leaves megabytes of freed heap in the worker's and I/O thread's malloc
 * arenas, which glibc keeps; give them back to the OS at once. */
static void free_answer(void *body)
{
    size_t n = malloc_usable_size(body);
    free(body);
    if (n >= SRV_TRIM_BYTES) malloc_trim(0);
}

/* An answer of at least SRV_TRACK_MIN bytes, handed to libmicrohttpd through
 * a reader (answer_read) that copies it out in SRV_TRACK_BLOCK blocks and
 * notes, on every read, how much of it was sent: libmicrohttpd asks for the
 * block at the position it has sent up to. So a connection closed halfway is
 * logged with the bytes sent (to within one block), not the answer's length. */
struct srv_answer {
    char *body;
    size_t len;
    struct srv_req *r;   /* r->sent is updated; r outlives every read of its answer */
    struct srv_mem *mem; /* `charged` bytes are given back to it when the answer is freed */
    size_t charged;
};

static ssize_t answer_read(void *cls, uint64_t pos, char *buf, size_t max)
{
    struct srv_answer *a = cls;
    if (pos >= a->len) return MHD_CONTENT_READER_END_OF_STREAM;
    a->r->sent = pos;
    size_t n = a->len - (size_t)pos < max ? a->len - (size_t)pos : max;
    memcpy(buf, a->body + pos, n);
    return (ssize_t)n;
}

static void answer_release(void *cls)
{
    struct srv_answer *a = cls;
    free_answer(a->body);
    srv_mem_release(a->mem, a->charged);
    free(a);
}

/* The response object of a tracked answer (takes resp->body and r's charge on success). */
static struct MHD_Response *tracked_response(struct srv_req *r, struct api_response *resp)
{
    struct srv_answer *a = malloc(sizeof *a);
    if (!a) return NULL;
    *a = (struct srv_answer){resp->body, resp->body_len, r, r->http->mem, r->charged};
    struct MHD_Response *mr = MHD_create_response_from_callback(resp->body_len, SRV_TRACK_BLOCK,
                                                                answer_read, a, answer_release);
    if (!mr) {
        free(a);
        return NULL;
    }
    resp->body = NULL; /* MHD owns it now, through a */
    r->charged = 0;
    r->tracked = 1;
    return mr;
}

struct MHD_Response *answer_response(struct srv_req *r, struct api_response *resp)
{
    if (resp->body_len >= SRV_TRACK_MIN && !(r->method && strcmp(r->method, "HEAD") == 0))
        return tracked_response(r, resp);
    struct MHD_Response *mr =
        MHD_create_response_from_buffer_with_free_callback(resp->body_len, resp->body, free_answer);
    if (mr) resp->body = NULL; /* MHD owns it now */
    return mr;
}
