/* api_etag.c — entity tags of the API's answers: FNV-1a 64 hashes that start
 * from the build (so one build's answer is never served for another's) and
 * If-None-Match matching (RFC 9110 13.1.2). */
#include "http/api_etag.h"

#include <string.h>

#ifndef MECHD_BUILD_ID
#define MECHD_BUILD_ID ""
#endif

/* FNV-1a 64 over the parts, each followed by a NUL separator. */
uint64_t api_etag_fnv1a(uint64_t h, const char *s)
{
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        h ^= *p;
        h *= 0x100000001b3ULL;
    }
    h *= 0x100000001b3ULL; /* the separator: h ^= 0 */
    return h;
}

uint64_t api_etag_build_hash(void)
{
    return api_etag_fnv1a(0xcbf29ce484222325ULL, "mechd " MECHD_VERSION " " MECHD_BUILD_ID);
}

/* Whether an If-None-Match header value lists `etag` (weak comparison, RFC 9110
 * 13.1.2: a W/ prefix is ignored) or is "*". */
int api_etag_matches(const char *header, const char *etag)
{
    if (!header || !etag || !etag[0]) return 0;
    size_t elen = strlen(etag);
    const char *p = header;
    while (*p) {
        while (*p == ' ' || *p == '\t' || *p == ',') p++;
        if (!*p) break;
        const char *start = p;
        while (*p && *p != ',') p++;
        const char *end = p;
        while (end > start && (end[-1] == ' ' || end[-1] == '\t')) end--;
        if (end - start == 1 && *start == '*') return 1;
        if (end - start >= 2 && start[0] == 'W' && start[1] == '/') start += 2;
        if ((size_t)(end - start) == elen && !strncmp(start, etag, elen)) return 1;
    }
    return 0;
}
