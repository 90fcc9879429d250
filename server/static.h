/* static.h — the classroom front end's static files (clients/web), served at /.
 *
 * srv_static_init() reads every servable file under a root directory into
 * memory once, before the server starts; srv_static_lookup() then maps a URL
 * path to one of those in-memory files, or refuses. Lookups never touch the
 * file system, so no request can reach a file outside the root: the table only
 * holds regular files found under the root's real path (symlinks resolved with
 * realpath and checked to stay inside), no hidden files or directories, only
 * known extensions, and under size caps.
 *
 * Thread-safety: init and free are not thread-safe and must run while no
 * lookup can happen (before the daemon starts / after it stops); lookups are
 * read-only and may run concurrently from any thread.
 *
 * Wiring (server/http.c): for a GET or HEAD whose path is not an API route,
 *     struct srv_static_file f;
 *     if (srv_static_lookup(path, &f) == 0) {
 *         if (srv_static_not_modified(&f, if_none_match)) -> 304 with f.etag
 *         else 200 with body f.body/f.len (MHD_RESPMEM_PERSISTENT: the cache
 *              owns it until srv_static_free), Content-Type f.content_type,
 *              and every header of f.headers[0 .. f.n_headers).
 *     }
 */
#ifndef MECHD_SERVER_STATIC_H
#define MECHD_SERVER_STATIC_H

#include <stddef.h>

/* The compiled-in default root: the source tree's clients/web (set by CMake
 * as -DMECHD_STATIC_DIR="${CMAKE_SOURCE_DIR}/clients/web"). */
#ifndef MECHD_STATIC_DIR
#define MECHD_STATIC_DIR "clients/web"
#endif

#define SRV_STATIC_MAX_FILE (4u << 20)   /* bytes: a larger file is skipped */
#define SRV_STATIC_MAX_TOTAL (32u << 20) /* bytes: all files together */
#define SRV_STATIC_MAX_FILES 512u
#define SRV_STATIC_MAX_DEPTH 8

/* The Content-Security-Policy sent with every static file: everything from
 * this origin only, no inline scripts or styles, no plugins; framing as
 * srv_static_set_frame_ancestors() allows (by default none: 'none'). */
#define SRV_STATIC_CSP_BASE                                                                        \
    "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; "              \
    "connect-src 'self'; font-src 'self'; object-src 'none'; base-uri 'none'; "                    \
    "form-action 'self'; frame-ancestors "
#define SRV_STATIC_CSP SRV_STATIC_CSP_BASE "'none'"

struct srv_static_header {
    const char *name, *value; /* static strings or owned by the cache */
};

#define SRV_STATIC_HEADERS 6

/* One cached file. Every pointer is borrowed from the cache and stays valid
 * until srv_static_free(). */
struct srv_static_file {
    const char *path; /* URL path, e.g. "/index.html" */
    const char *body; /* the file's bytes (not NUL-terminated for the client) */
    size_t len;
    const char *content_type; /* e.g. "text/html; charset=utf-8" */
    const char *etag;         /* strong ETag, quoted: "\"3f2a…\"" (hash of the bytes) */
    struct srv_static_header headers[SRV_STATIC_HEADERS]; /* Cache-Control, CSP, nosniff, … */
    int n_headers;
};

/* Read the servable files under root (NULL: MECHD_STATIC_DIR) into memory,
 * replacing any previous cache. Returns the number of files cached (>= 0),
 * or -1 if root cannot be opened or resolved (the cache is then empty and
 * every lookup answers not found; the server still runs). Files over
 * SRV_STATIC_MAX_FILE, beyond SRV_STATIC_MAX_FILES or SRV_STATIC_MAX_TOTAL,
 * with unknown extensions, hidden, or whose real path leaves the root are
 * skipped. Not thread-safe (see above). */
int srv_static_init(const char *root);

/* Free the cache. Safe to call twice or without init. */
void srv_static_free(void);

/* Map a decoded URL path (no query string) to a cached file. "/" and any path
 * ending in "/" mean that directory's index.html. Refuses (returns -1, *out
 * untouched) a NULL or empty path, one not starting with "/", containing "..",
 * "." or empty segments ("//"), a backslash, '%' (a still-encoded or doubly
 * encoded character), a control character, a segment starting with '.'
 * (hidden files), or longer than 1024 bytes. Returns 0 and fills *out on a hit,
 * -1 otherwise (answer 404). Thread-safe after init. */
int srv_static_lookup(const char *url_path, struct srv_static_file *out);

/* 1 if the request's If-None-Match header (may be NULL) matches f's ETag
 * (a list, weak comparison, or "*"), so a 304 Not Modified can be sent. */
int srv_static_not_modified(const struct srv_static_file *f, const char *if_none_match);

/* Let the pages of these origins (comma-separated "scheme://host[:port]", as
 * --frame-ancestors validated them; NULL or "" for none) embed the front end
 * in a frame: the CSP then says "frame-ancestors ORIGIN …" and no
 * X-Frame-Options is sent (it cannot name an origin; browsers obey the CSP).
 * By default, and with "", "frame-ancestors 'none'" and X-Frame-Options DENY.
 * Returns 0, or -1 when the list does not fit (nothing changed). Not
 * thread-safe: call before the server starts. */
int srv_static_set_frame_ancestors(const char *origins);

/* Number of cached files (0 before init). */
int srv_static_count(void);

#endif
