/* mechd_eval.c — the `mechd-eval` program: `mechd eval` without the HTTP
 * server, so it links only the API and core layers (jansson, GSL, zlib, libm,
 * libc) and never libmicrohttpd or its TLS stack. Built twice by CMake:
 * `mechd-eval` (shared libraries) and `mechd-eval-static` (fully static, for
 * grader containers that have none of them; `make static-eval`). Same options,
 * input, output and exit statuses as `mechd eval` (see ../eval.h). */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <string.h>

#include "api.h"
#include "eval.h"

#ifndef MECHD_VERSION
#define MECHD_VERSION "0.0.0"
#endif
#ifndef MECHD_BUILD_ID
#define MECHD_BUILD_ID "unknown"
#endif

/* argv as for `mechd eval` without the word "eval": mechd-eval [OPTIONS] [FILE].
 * --version prints the version and the git commit it was built from.
 * Exit statuses: see srv_eval_main. */
int main(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
        printf("mechd-eval %s (commit %s)\n", MECHD_VERSION, MECHD_BUILD_ID);
        return 0;
    }
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    if (api_init() != 0) {
        fprintf(stderr, "mechd-eval: API initialisation failed: %s\n", api_init_error());
        return 3;
    }
    return srv_eval_main(argc, argv, stdin, stdout, stderr);
}
