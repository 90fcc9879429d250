/* eval.h — `mechd eval`: answer one request offline (no socket), for graders
 * without network. See srv_eval_main(). */
#ifndef SERVER_EVAL_H
#define SERVER_EVAL_H

#include <stdio.h>

/* Run `mechd eval [--operation PATH] [--cost] [--max-steps=N] [--deadline-ms=N] [FILE]`.
 * argv[0] is "eval". Reads FILE (or stdin when FILE is absent or "-"): either
 * {"operation": "/v1/...", "request": {...}} or, with --operation, the bare
 * request. Calls api_handle_ext() in-process exactly as the server does for
 * GET ?request= (the measured cost is dropped unless --cost, so the output is
 * byte-identical to the server's GET answer and to its POST answer without
 * cost) and writes the body to out. Returns the exit status: 0 for a 2xx
 * answer, 1 for a 4xx problem (the problem+json is on out), 3 for a 5xx
 * problem, 2 for a usage or I/O error (a message on err). */
int srv_eval_main(int argc, char **argv, FILE *in, FILE *out, FILE *err);

/* Usage text of the eval subcommand (for --help). */
void srv_eval_usage(FILE *out);

#endif
