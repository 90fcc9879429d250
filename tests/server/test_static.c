/* test_static.c — server/static.c: the static file cache refuses every path
 * that could leave the root (.., encoded traversal, backslashes, hidden files,
 * symlinks escaping the root), maps "/" to index.html, serves the right bytes,
 * content types and security headers, and answers If-None-Match.
 * Builds its own throw-away tree under /tmp (mkdtemp) and removes it. */
#define _XOPEN_SOURCE 700 /* mkdtemp, symlink */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../server/static.h"
#include "../testlib.h"

static char base[64];

static void put(const char *rel, const char *text)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s", base, rel);
    FILE *f = fopen(p, "wb");
    if (!f) {
        perror(p);
        exit(2);
    }
    fputs(text, f);
    fclose(f);
}

static void dir(const char *rel)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s", base, rel);
    mkdir(p, 0755);
}

static void link_to(const char *target, const char *rel)
{
    char p[256];
    snprintf(p, sizeof p, "%s/%s", base, rel);
    if (symlink(target, p) != 0) perror(p);
}

static const char *header(const struct srv_static_file *f, const char *name)
{
    for (int i = 0; i < f->n_headers; i++)
        if (strcmp(f->headers[i].name, name) == 0) return f->headers[i].value;
    return NULL;
}

static int found(const char *path)
{
    struct srv_static_file f;
    return srv_static_lookup(path, &f) == 0;
}

int main(void)
{
    snprintf(base, sizeof base, "/tmp/mechd-static-XXXXXX");
    if (!mkdtemp(base)) {
        perror("mkdtemp");
        return 2;
    }
    /* root = base/web; base/secret.txt lies outside it */
    dir("web");
    dir("web/labs");
    dir("web/.git");
    put("secret.txt", "TOP SECRET");
    put("web/index.html", "<!doctype html><title>mechd</title>");
    put("web/app.js", "export const x = 1;\n");
    put("web/style.css", "body{}");
    put("web/labs/inertia.js", "// lab\n");
    put("web/labs/index.html", "<p>labs</p>");
    put("web/icon.svg", "<svg/>");
    put("web/data.json", "{}");
    put("web/app.0123abcd.js", "//hashed\n");
    put("web/.hidden.js", "hidden");
    put("web/.git/config", "[core]");
    put("web/notes.exe", "MZ");               /* unknown extension: skipped */
    link_to("../secret.txt", "web/leak.txt"); /* escapes the root: skipped */
    link_to("/etc", "web/etc");               /* escapes the root: skipped */
    link_to("app.js", "web/alias.js");        /* stays inside: served */

    char root[128];
    snprintf(root, sizeof root, "%s/web", base);
    int n = srv_static_init(root);
    /* index.html app.js style.css labs/inertia.js labs/index.html icon.svg data.json
     * app.0123abcd.js alias.js */
    CHECK_EQ_INT(n, 9);
    CHECK_EQ_INT(srv_static_count(), 9);

    struct srv_static_file f;
    CHECK(srv_static_lookup("/", &f) == 0);
    CHECK(strcmp(f.path, "/index.html") == 0);
    CHECK_EQ_INT(f.len, strlen("<!doctype html><title>mechd</title>"));
    CHECK(memcmp(f.body, "<!doctype html>", 15) == 0);
    CHECK(strcmp(f.content_type, "text/html; charset=utf-8") == 0);
    CHECK(header(&f, "Cache-Control") && strcmp(header(&f, "Cache-Control"), "no-cache") == 0);
    CHECK(header(&f, "Content-Security-Policy") &&
          strstr(header(&f, "Content-Security-Policy"), "default-src 'self'") &&
          strstr(header(&f, "Content-Security-Policy"), "script-src 'self';") &&
          !strstr(header(&f, "Content-Security-Policy"), "unsafe-inline"));
    CHECK(header(&f, "X-Content-Type-Options") &&
          strcmp(header(&f, "X-Content-Type-Options"), "nosniff") == 0);
    CHECK(header(&f, "ETag") && f.etag[0] == '"' && strlen(f.etag) == 18);
    /* framing: none by default; the origins of --frame-ancestors may, and then
     * no X-Frame-Options (it cannot name an origin); "" is none again */
    CHECK(strstr(header(&f, "Content-Security-Policy"), "frame-ancestors 'none'") &&
          header(&f, "X-Frame-Options") && strcmp(header(&f, "X-Frame-Options"), "DENY") == 0);
    CHECK(srv_static_set_frame_ancestors("https://course.example.edu,http://localhost:3000") == 0);
    CHECK(srv_static_lookup("/", &f) == 0 && !header(&f, "X-Frame-Options"));
    CHECK(strstr(header(&f, "Content-Security-Policy"),
                 "; frame-ancestors https://course.example.edu http://localhost:3000") &&
          strstr(header(&f, "Content-Security-Policy"), "script-src 'self';"));
    CHECK(srv_static_set_frame_ancestors("") == 0);
    CHECK(srv_static_lookup("/", &f) == 0 && header(&f, "X-Frame-Options") &&
          strstr(header(&f, "Content-Security-Policy"), "frame-ancestors 'none'"));

    CHECK(srv_static_lookup("/labs/", &f) == 0 && strcmp(f.path, "/labs/index.html") == 0);
    CHECK(srv_static_lookup("/app.js", &f) == 0 &&
          strcmp(f.content_type, "text/javascript; charset=utf-8") == 0);
    CHECK(srv_static_lookup("/style.css", &f) == 0 &&
          strcmp(f.content_type, "text/css; charset=utf-8") == 0);
    CHECK(srv_static_lookup("/icon.svg", &f) == 0 && strcmp(f.content_type, "image/svg+xml") == 0 &&
          strstr(header(&f, "Cache-Control"), "max-age=86400"));
    CHECK(srv_static_lookup("/data.json", &f) == 0 &&
          strcmp(f.content_type, "application/json") == 0);
    CHECK(srv_static_lookup("/app.0123abcd.js", &f) == 0 &&
          strstr(header(&f, "Cache-Control"), "immutable"));
    CHECK(srv_static_lookup("/labs/inertia.js", &f) == 0 && f.len == 7);
    CHECK(srv_static_lookup("/alias.js", &f) == 0 && f.len == strlen("export const x = 1;\n"));

    /* refused: traversal in every spelling, hidden files, escaping symlinks */
    const char *bad[] = {
        "",
        "index.html",
        "/..",
        "/../secret.txt",
        "/labs/../index.html",
        "/labs/..",
        "/%2e%2e/secret.txt",
        "/%2E%2E%2Fsecret.txt",
        "/%252e%252e/secret.txt",
        "/app%2ejs",
        "/..\\secret.txt",
        "/labs\\inertia.js",
        "/.hidden.js",
        "/.git/config",
        "/labs/./inertia.js",
        "//app.js",
        "/./app.js",
        "/leak.txt",
        "/etc/passwd",
        "/etc/",
        "/notes.exe",
        "/nothing.js",
        "/app.js\x01",
        "/labs",
        "/index.html/",
        "/app.js/..",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int hit = found(bad[i]);
        if (hit) fprintf(stderr, "served a forbidden path: %s\n", bad[i]);
        CHECK(!hit);
    }
    CHECK(srv_static_lookup(NULL, &f) == -1);
    char longp[2100];
    memset(longp, 'a', sizeof longp - 1);
    longp[0] = '/';
    longp[sizeof longp - 1] = '\0';
    CHECK(!found(longp));

    /* If-None-Match */
    CHECK(srv_static_lookup("/app.js", &f) == 0);
    char inm[64];
    snprintf(inm, sizeof inm, "\"x\", W/%s", f.etag);
    CHECK(srv_static_not_modified(&f, f.etag));
    CHECK(srv_static_not_modified(&f, inm));
    CHECK(srv_static_not_modified(&f, "*"));
    CHECK(!srv_static_not_modified(&f, "\"0000000000000000\""));
    CHECK(!srv_static_not_modified(&f, NULL));
    struct srv_static_file g;
    CHECK(srv_static_lookup("/style.css", &g) == 0 && strcmp(g.etag, f.etag) != 0);

    /* a missing root: -1, empty cache, every lookup refused */
    CHECK_EQ_INT(srv_static_init("/nonexistent/mechd-static"), -1);
    CHECK_EQ_INT(srv_static_count(), 0);
    CHECK(!found("/"));
    srv_static_free();
    srv_static_free(); /* twice is fine */

    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", base);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", base);
    TEST_MAIN_END();
}
