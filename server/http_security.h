/* http_security.h — SECURITY of the HTTP front end (http_security.c): what the
 * bearer token and CORS decide about a request. The front end (http.c) asks
 * and acts on the answer; nothing here answers a request or knows the
 * front end's per-request state, so the dependency runs one way,
 * http.c -> http_security.c. */
#ifndef SRV_HTTP_SECURITY_H
#define SRV_HTTP_SECURITY_H

#include <microhttpd.h>

#include "config.h"

/* What SECURITY decides about one request from its first callback (its
 * headers). Every text is static. */
struct srv_access {
    int cors_ok;     /* Origin is in --cors-origin: answers carry Access-Control-Allow-Origin */
    int vary_origin; /* a /v1 answer while CORS is on: answers carry Vary: Origin */
    int preflight;   /* a CORS preflight of /v1 (it carries no credentials): once the
                        request is complete, answer it with srv_preflight_headers if
                        cors_ok, else as a plain OPTIONS (Allow, no CORS header) */
    const char *refusal;          /* the 401's detail (the token is missing or wrong), or
                                     NULL: the request may go on */
    const char *www_authenticate; /* the 401's WWW-Authenticate value, with refusal */
};

/* Decide for a request to path (method, Origin header origin or NULL; the
 * Authorization and Access-Control-Request-Method headers are read from conn
 * only when they matter). Only /v1 and the paths under it are checked: for
 * any other path *out is all zero. cfg and conn are borrowed. Cannot fail. */
void srv_access_check(const struct srv_config *cfg, struct MHD_Connection *conn,
                      const char *method, const char *path, const char *origin,
                      struct srv_access *out);

/* Add an allowed preflight's Access-Control-Allow-Methods, -Allow-Headers
 * and -Max-Age to mr (borrowed). */
void srv_preflight_headers(struct MHD_Response *mr);

#endif
