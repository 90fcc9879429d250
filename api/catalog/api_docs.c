/* api_docs.c — the two documents GET /v1 and GET /v1/openapi.json serve
 * (api/catalog/catalog.c writes them): each with its strong ETag, a gzip copy made on
 * first demand, and 304 for a matching If-None-Match. */
#include "catalog/api_docs.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <zlib.h>

#include "http/api_etag.h"
#include "catalog/catalog.h"

/* Both documents are fixed for the life of the process (generated from the
 * route table at init), 0.5 and 1.2 MB of JSON that gzip shrinks tenfold. Each
 * is kept with a gzip copy (zlib, level 6: 55 and 89 KB, 15 ms together; made
 * on the first request that accepts gzip, so `mechd eval` and a server that
 * is never asked pay nothing) and a strong ETag per
 * representation: FNV-1a 64 of (build, the identity text), with "-gz" for the
 * gzip one. Served as static memory (no copy per request), Cache-Control
 * "no-cache" (a cache may keep them but revalidates: they change with the
 * build), Vary: Accept-Encoding, and 304 with the 200's Content-Length for a
 * matching If-None-Match. */
struct doc_cache {
    const char *text; /* borrowed from api/catalog/catalog.c */
    size_t len;
    unsigned char *gz; /* gzip of text, or NULL (then only identity is served) */
    size_t gz_len;
    char etag[24], etag_gz[24];
    pthread_once_t gz_once; /* doc_gzip runs once, on first use */
    int gz_ready;           /* 1: gz was made already (a host's catalog): no gz_once */
    const char *vary;       /* the Vary header (static string) */
};
static struct doc_cache doc_catalog = {.gz_once = PTHREAD_ONCE_INIT},
                        doc_openapi = {.gz_once = PTHREAD_ONCE_INIT};

/* gzip (RFC 1952) of text into d->gz; left NULL when memory runs out. */
static int doc_gzip(struct doc_cache *d)
{
    z_stream zs;
    memset(&zs, 0, sizeof zs);
    if (deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) return -1;
    uLong cap = deflateBound(&zs, (uLong)d->len);
    d->gz = malloc(cap);
    if (!d->gz) {
        deflateEnd(&zs);
        return -1;
    }
    zs.next_in = (Bytef *)(uintptr_t)d->text;
    zs.avail_in = (uInt)d->len;
    zs.next_out = d->gz;
    zs.avail_out = (uInt)cap;
    int rc = deflate(&zs, Z_FINISH);
    d->gz_len = zs.total_out;
    deflateEnd(&zs);
    if (rc != Z_STREAM_END) {
        free(d->gz);
        d->gz = NULL;
        return -1;
    }
    return 0;
}

static int doc_init(struct doc_cache *d, const char *text)
{
    if (!text) return -1;
    d->text = text;
    d->len = strlen(text);
    uint64_t h = api_etag_build_hash();
    h = api_etag_fnv1a(h, text);
    snprintf(d->etag, sizeof d->etag, "\"%016llx\"", (unsigned long long)h);
    snprintf(d->etag_gz, sizeof d->etag_gz, "\"%016llx-gz\"", (unsigned long long)h);
    return 0;
}

static void gzip_catalog(void)
{
    doc_gzip(&doc_catalog);
}

static void gzip_openapi(void)
{
    doc_gzip(&doc_openapi);
}

/* Whether an Accept-Encoding header value admits gzip (RFC 9110 12.5.3): listed
 * as gzip or x-gzip with q > 0, or not listed while "*" is with q > 0. */
static int accepts_gzip(const char *h)
{
    int gzip = -1, star = -1;
    while (h && *h) {
        while (*h == ' ' || *h == '\t' || *h == ',') h++;
        if (!*h) break;
        const char *name = h;
        while (*h && *h != ',' && *h != ';' && *h != ' ' && *h != '\t') h++;
        size_t nl = (size_t)(h - name);
        int ok = 1; /* q defaults to 1 */
        while (*h && *h != ',') {
            while (*h == ';' || *h == ' ' || *h == '\t') h++;
            if ((h[0] == 'q' || h[0] == 'Q') && h[1] == '=') {
                ok = strtod(h + 2, NULL) > 0; /* a qvalue is 0..1 with at most 3 decimals */
            }
            while (*h && *h != ',' && *h != ';') h++;
        }
        if ((nl == 4 && !strncasecmp(name, "gzip", 4)) ||
            (nl == 6 && !strncasecmp(name, "x-gzip", 6)))
            gzip = ok;
        else if (nl == 1 && *name == '*')
            star = ok;
    }
    return gzip >= 0 ? gzip : star == 1;
}

/* GET/HEAD of /v1 or /v1/openapi.json (see doc_cache above). */
static void serve_doc(struct doc_cache *d, const struct api_request_ext *ext,
                      struct api_response *resp)
{
    int gz = ext && accepts_gzip(ext->accept_encoding);
    if (gz && !d->gz_ready)
        pthread_once(&d->gz_once, d == &doc_catalog ? gzip_catalog : gzip_openapi);
    gz = gz && d->gz;
    const char *etag = gz ? d->etag_gz : d->etag;
    size_t len = gz ? d->gz_len : d->len;
    memset(resp, 0, sizeof *resp);
    snprintf(resp->etag, sizeof resp->etag, "%s", etag);
    resp->cache_control = "no-cache";
    resp->vary = d->vary ? d->vary : "Accept-Encoding";
    if (ext && api_etag_matches(ext->if_none_match, etag)) {
        resp->status = 304;
        resp->full_length = len;
        return;
    }
    resp->status = 200;
    resp->content_type = "application/json";
    resp->body = gz ? (char *)d->gz : (char *)(uintptr_t)d->text;
    resp->body_len = len;
    resp->body_static = 1;
    resp->content_encoding = gz ? "gzip" : NULL;
}

int api_docs_init(void)
{
    return doc_init(&doc_catalog, api_catalog_text()) || doc_init(&doc_openapi, api_openapi_text())
               ? -1
               : 0;
}

/* The catalog's curl lines and examples say where the server is: written as
 * DOCS_HOST_DEFAULT, they name the host the client asked (Host header) instead,
 * so a line copied from GET /v1 on mechd.example.edu:9000 works as it is. Only
 * host names, IPv4 and bracketed IPv6 addresses with an optional port are
 * taken (at most 255 bytes); anything else keeps the default. */
#define DOCS_HOST_DEFAULT "127.0.0.1:8080"
#define DOCS_URL_DEFAULT "http://" DOCS_HOST_DEFAULT

static int host_usable(const char *h)
{
    size_t n = h ? strlen(h) : 0;
    if (n == 0 || n > 255 || !strcmp(h, DOCS_HOST_DEFAULT)) return 0;
    for (size_t i = 0; i < n; i++) {
        char c = h[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '.' || c == '-' || c == ':' || c == '[' || c == ']'))
            return 0;
    }
    return 1;
}

/* The catalog with every DOCS_URL_DEFAULT written as http://host (malloc'd,
 * NUL-terminated, *len set), or NULL when out of memory. */
static char *catalog_for_host(const char *host, size_t *len)
{
    const char *text = doc_catalog.text;
    size_t from = strlen(DOCS_URL_DEFAULT), to = strlen(host) + 7, count = 0;
    for (const char *p = strstr(text, DOCS_URL_DEFAULT); p; p = strstr(p + from, DOCS_URL_DEFAULT))
        count++;
    size_t n = doc_catalog.len - count * from + count * to;
    char *out = malloc(n + 1), *o = out;
    if (!out) return NULL;
    const char *p = text;
    for (const char *q = strstr(p, DOCS_URL_DEFAULT); q; q = strstr(p, DOCS_URL_DEFAULT)) {
        memcpy(o, p, (size_t)(q - p));
        o += q - p;
        o += sprintf(o, "http://%s", host);
        p = q + from;
    }
    strcpy(o, p);
    *len = n;
    return out;
}

/* The catalogs of the hosts asked for so far (at most DOCS_HOSTS_MAX, made once
 * each with their gzip and ETags, kept for the process's life like the default
 * text, so a response may point into them). Guarded by host_docs_lock. */
#define DOCS_HOSTS_MAX 8
static struct host_doc {
    char host[256];
    struct doc_cache d;
} host_docs[DOCS_HOSTS_MAX];
static size_t n_host_docs;
static pthread_mutex_t host_docs_lock = PTHREAD_MUTEX_INITIALIZER;

/* The cached catalog for host, made on its first request; NULL when the
 * table is full or memory ran out. */
static struct doc_cache *catalog_of_host(const char *host)
{
    struct doc_cache *found = NULL;
    pthread_mutex_lock(&host_docs_lock);
    for (size_t i = 0; i < n_host_docs && !found; i++)
        if (!strcmp(host_docs[i].host, host)) found = &host_docs[i].d;
    if (!found && n_host_docs < DOCS_HOSTS_MAX) {
        size_t len = 0;
        char *text = catalog_for_host(host, &len);
        struct host_doc *e = &host_docs[n_host_docs];
        if (text && !doc_init(&e->d, text)) {
            snprintf(e->host, sizeof e->host, "%s", host);
            doc_gzip(&e->d); /* gz stays NULL without memory: identity only */
            e->d.gz_ready = 1;
            e->d.vary = "Accept-Encoding, Host";
            n_host_docs++;
            found = &e->d;
        } else {
            free(text);
        }
    }
    pthread_mutex_unlock(&host_docs_lock);
    return found;
}

void api_docs_serve_catalog(const struct api_request_ext *ext, struct api_response *resp)
{
    struct doc_cache *d = ext && host_usable(ext->host) ? catalog_of_host(ext->host) : NULL;
    if (d) {
        serve_doc(d, ext, resp);
        return;
    }
    if (!ext || !host_usable(ext->host)) {
        serve_doc(&doc_catalog, ext, resp);
        return;
    }
    /* more hosts than the table holds: a copy for this request, identity only */
    size_t len = 0;
    char *body = catalog_for_host(ext->host, &len);
    memset(resp, 0, sizeof *resp);
    if (!body) { /* no memory for the copy: the default text is still right but for its host */
        serve_doc(&doc_catalog, ext, resp);
        return;
    }
    uint64_t h = api_etag_fnv1a(api_etag_build_hash(), body);
    snprintf(resp->etag, sizeof resp->etag, "\"%016llx\"", (unsigned long long)h);
    resp->cache_control = "no-cache";
    resp->vary = "Accept-Encoding, Host";
    if (api_etag_matches(ext->if_none_match, resp->etag)) {
        free(body);
        resp->status = 304;
        resp->full_length = len;
        return;
    }
    resp->status = 200;
    resp->content_type = "application/json";
    resp->body = body;
    resp->body_len = len;
}

void api_docs_serve_openapi(const struct api_request_ext *ext, struct api_response *resp)
{
    serve_doc(&doc_openapi, ext, resp);
}
