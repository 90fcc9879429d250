/* healthcheck.h — `mechd healthcheck`: the container HEALTHCHECK without curl. */
#ifndef SERVER_HEALTHCHECK_H
#define SERVER_HEALTHCHECK_H

#include <stdio.h>

/* `mechd healthcheck [--port N] [--host ADDR] [--timeout-ms N]`: GET /healthz
 * from a mechd on ADDR (numeric IPv4 or IPv6, default 127.0.0.1) and port N
 * (default MECHD_PORT from the environment, else 8080) over plain HTTP/1.0,
 * waiting at most --timeout-ms (default 3000, 1..60000) in all. argv[0] is
 * "healthcheck". Returns the exit status: 0 when the answer is 200, 1 when it
 * is not or no answer came (one line on err says why), 2 for a usage error. */
int srv_healthcheck_main(int argc, char **argv, FILE *err);

#endif
