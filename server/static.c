/* static.c — the classroom front end's static files, cached at startup
 * (see static.h).
 *
 * DESIGN. The directory is small (a few hundred KiB), so every servable file
 * is read once by srv_static_init() into one table and lookups are an exact
 * match of the normalised URL path against that table: a request can never
 * name a file the walk did not accept, whatever its encoding. The walk itself
 * only accepts regular files whose realpath() lies inside the root's
 * realpath(), with a known extension, not hidden, under the size caps.
 * Headers: HTML, JS, CSS and JSON are "no-cache" (always revalidated with the
 * ETag, so a teacher's edit shows on the next reload); images and fonts may be
 * kept a day; a file whose name carries a content hash (name.0123abcd.js) is
 * immutable for a year.
 */
#define _XOPEN_SOURCE 700 /* realpath (XSI) */
#include "static.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SRV_STATIC_MAX_URL 1024u

struct entry {
    char *path; /* URL path, owned */
    char *body; /* owned */
    size_t len;
    const char *content_type;
    const char *cache_control;
    char etag[24];
};

static struct entry *cache;
static int n_cache;
static size_t total_bytes;
static char root_real[PATH_MAX];
static size_t root_len;
/* the CSP of every file, and whether X-Frame-Options: DENY goes with it */
static char csp[sizeof SRV_STATIC_CSP_BASE + 2100] = SRV_STATIC_CSP;
static int frame_deny = 1;

static const struct {
    const char *ext, *type, *cache;
} types[] = {
    {".html", "text/html; charset=utf-8", "no-cache"},
    {".js", "text/javascript; charset=utf-8", "no-cache"},
    {".mjs", "text/javascript; charset=utf-8", "no-cache"},
    {".css", "text/css; charset=utf-8", "no-cache"},
    {".json", "application/json", "no-cache"},
    {".svg", "image/svg+xml", "public, max-age=86400"},
    {".png", "image/png", "public, max-age=86400"},
    {".ico", "image/x-icon", "public, max-age=86400"},
    {".woff2", "font/woff2", "public, max-age=86400"},
    {".txt", "text/plain; charset=utf-8", "no-cache"},
};

static const char *immutable_cache = "public, max-age=31536000, immutable";

/* The type table row for name's extension, or -1. */
static int type_of(const char *name)
{
    const char *dot = strrchr(name, '.');
    if (!dot) return -1;
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcmp(dot, types[i].ext) == 0) return (int)i;
    return -1;
}

/* 1 if name looks like "stem.<8 or more hex digits>.ext" (a content-hashed asset). */
static int is_hashed(const char *name)
{
    const char *last = strrchr(name, '.');
    if (!last || last == name) return 0;
    const char *p = last;
    size_t n = 0;
    while (p > name && p[-1] != '.') {
        char ch = p[-1];
        if (!((ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'f'))) return 0;
        n++;
        p--;
    }
    return p > name + 1 && n >= 8;
}

/* 64-bit FNV-1a of the bytes, for the ETag. */
static unsigned long long fnv1a(const char *s, size_t n)
{
    unsigned long long h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)s[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* 1 if real (a realpath) is the root or inside it. */
static int inside_root(const char *real)
{
    return strncmp(real, root_real, root_len) == 0 &&
           (real[root_len] == '\0' || real[root_len] == '/' || root_len == 1);
}

/* Read a regular file of known size into a new buffer; NULL on failure. */
static char *read_all(const char *fs_path, size_t size)
{
    FILE *f = fopen(fs_path, "rb");
    if (!f) return NULL;
    char *buf = malloc(size ? size : 1);
    if (buf && fread(buf, 1, size, f) != size) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    return buf;
}

static void add_file(const char *fs_path, const char *url, const char *name, size_t size)
{
    int t = type_of(name);
    if (t < 0 || size > SRV_STATIC_MAX_FILE || n_cache >= (int)SRV_STATIC_MAX_FILES ||
        total_bytes + size > SRV_STATIC_MAX_TOTAL || strlen(url) > SRV_STATIC_MAX_URL)
        return;
    struct entry *grown = realloc(cache, (size_t)(n_cache + 1) * sizeof *cache);
    if (!grown) return;
    cache = grown;
    char *body = read_all(fs_path, size);
    char *path = strdup(url);
    if (!body || !path) {
        free(body);
        free(path);
        return;
    }
    struct entry *e = &cache[n_cache++];
    e->path = path;
    e->body = body;
    e->len = size;
    e->content_type = types[t].type;
    e->cache_control = is_hashed(name) ? immutable_cache : types[t].cache;
    snprintf(e->etag, sizeof e->etag, "\"%016llx\"", fnv1a(body, size));
    total_bytes += size;
}

/* Walk fs_dir (mapped to URL prefix url_dir, "" for the root). */
static void walk(const char *fs_dir, const char *url_dir, int depth)
{
    if (depth > SRV_STATIC_MAX_DEPTH) return;
    DIR *d = opendir(fs_dir);
    if (!d) return;
    struct dirent *de;
    while ((de = readdir(d)) != NULL) {
        const char *name = de->d_name;
        if (name[0] == '.' || strchr(name, '\\') || strchr(name, '%')) continue; /* hidden, odd */
        char fs_path[PATH_MAX], url[PATH_MAX], real[PATH_MAX];
        if (snprintf(fs_path, sizeof fs_path, "%s/%s", fs_dir, name) >= (int)sizeof fs_path ||
            snprintf(url, sizeof url, "%s/%s", url_dir, name) >= (int)sizeof url)
            continue;
        if (!realpath(fs_path, real) || !inside_root(real)) continue; /* escaping symlink */
        struct stat st;
        if (stat(real, &st) != 0) continue;
        if (S_ISDIR(st.st_mode))
            walk(real, url, depth + 1);
        else if (S_ISREG(st.st_mode))
            add_file(real, url, name, (size_t)st.st_size);
    }
    closedir(d);
}

void srv_static_free(void)
{
    for (int i = 0; i < n_cache; i++) {
        free(cache[i].path);
        free(cache[i].body);
    }
    free(cache);
    cache = NULL;
    n_cache = 0;
    total_bytes = 0;
    root_real[0] = '\0';
    root_len = 0;
}

int srv_static_init(const char *root)
{
    srv_static_free();
    if (!root) root = MECHD_STATIC_DIR;
    if (!realpath(root, root_real)) {
        root_real[0] = '\0';
        return -1;
    }
    struct stat st;
    if (stat(root_real, &st) != 0 || !S_ISDIR(st.st_mode)) {
        root_real[0] = '\0';
        return -1;
    }
    root_len = strlen(root_real);
    walk(root_real, "", 0);
    return n_cache;
}

int srv_static_set_frame_ancestors(const char *origins)
{
    if (!origins || !*origins) {
        snprintf(csp, sizeof csp, "%s", SRV_STATIC_CSP);
        frame_deny = 1;
        return 0;
    }
    if (sizeof SRV_STATIC_CSP_BASE + strlen(origins) >= sizeof csp) return -1;
    /* the CSP source list is space-separated */
    int n = snprintf(csp, sizeof csp, "%s", SRV_STATIC_CSP_BASE);
    for (const char *p = origins; *p && (size_t)n < sizeof csp - 1; p++)
        csp[n++] = *p == ',' ? ' ' : *p;
    csp[n] = '\0';
    frame_deny = 0;
    return 0;
}

int srv_static_count(void)
{
    return n_cache;
}

/* 1 if the URL path is acceptable (see static.h for the rules). */
static int path_ok(const char *p)
{
    size_t n = strlen(p);
    if (n == 0 || n > SRV_STATIC_MAX_URL || p[0] != '/') return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char ch = (unsigned char)p[i];
        if (ch < 0x20 || ch == 0x7f || ch == '\\' || ch == '%') return 0;
        /* at the start of each segment: no empty, hidden, "." or ".." segment */
        if (ch == '/' && i + 1 < n && (p[i + 1] == '/' || p[i + 1] == '.')) return 0;
    }
    return strstr(p, "..") == NULL;
}

int srv_static_lookup(const char *url_path, struct srv_static_file *out)
{
    if (!url_path || !out || !path_ok(url_path)) return -1;
    char want[SRV_STATIC_MAX_URL + 16];
    size_t n = strlen(url_path);
    snprintf(want, sizeof want, "%s%s", url_path, url_path[n - 1] == '/' ? "index.html" : "");
    for (int i = 0; i < n_cache; i++) {
        const struct entry *e = &cache[i];
        if (strcmp(e->path, want) != 0) continue;
        memset(out, 0, sizeof *out);
        out->path = e->path;
        out->body = e->body;
        out->len = e->len;
        out->content_type = e->content_type;
        out->etag = e->etag;
        out->headers[0] = (struct srv_static_header){"Cache-Control", e->cache_control};
        out->headers[1] = (struct srv_static_header){"Content-Security-Policy", csp};
        out->headers[2] = (struct srv_static_header){"X-Content-Type-Options", "nosniff"};
        out->headers[3] = (struct srv_static_header){"Referrer-Policy", "no-referrer"};
        out->headers[4] = (struct srv_static_header){"ETag", e->etag};
        out->n_headers = 5;
        if (frame_deny) out->headers[out->n_headers++] = (struct srv_static_header){"X-Frame-Options", "DENY"};
        return 0;
    }
    return -1;
}

int srv_static_not_modified(const struct srv_static_file *f, const char *inm)
{
    if (!f || !inm || !f->etag) return 0;
    size_t elen = strlen(f->etag);
    const char *p = inm;
    while (*p) {
        while (*p == ' ' || *p == '\t' || *p == ',')
            p++;
        if (*p == '*') return 1;
        if (p[0] == 'W' && p[1] == '/') p += 2; /* weak comparison (RFC 9110 §13.1.2) */
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        while (len > 0 && (p[len - 1] == ' ' || p[len - 1] == '\t'))
            len--;
        if (len == elen && strncmp(p, f->etag, elen) == 0) return 1;
        if (!end) break;
        p = end + 1;
    }
    return 0;
}
