/* api_etag.h — entity tags of the API's answers (api/http/api_etag.c). */
#ifndef API_API_ETAG_H
#define API_API_ETAG_H

#include <stdint.h>

/* FNV-1a 64 of s (NUL-terminated, borrowed) continued from h, followed by a
 * NUL separator, so ("ab", "c") and ("a", "bc") differ. */
uint64_t api_etag_fnv1a(uint64_t h, const char *s);

/* FNV-1a 64 of "mechd VERSION BUILD_ID" from the offset basis: where every
 * entity tag of this build starts. */
uint64_t api_etag_build_hash(void);

/* 1 when an If-None-Match header value (NULL: 0) lists etag (weak comparison:
 * a W/ prefix is ignored) or is "*"; 0 for an empty etag. */
int api_etag_matches(const char *header, const char *etag);

#endif
