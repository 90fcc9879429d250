/* test_mhd_panic.c — server/mhd_panic.c: libmicrohttpd's quiesce race (its
 * "Failed to remove listen FD from epoll set." with errno ENOENT) is survived
 * and logged; the same message with another errno, any other panic, and a
 * panic with no reason abort the process (checked in forked children). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../../server/mhd_panic.h"
#include "../testlib.h"

/* The reason string of libmicrohttpd 0.9.75 (daemon.c, MHD_quiesce_daemon). */
static const char quiesce_reason[] = "Failed to remove listen FD from epoll set.\n";

/* Run srv_mhd_panic in a child with errno = err; 1 if the child returned from
 * it (exit 0), 0 if it was killed by SIGABRT, -1 otherwise. */
static int child_survives(const char *reason, int err)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        freopen("/dev/null", "w", stderr); /* the abort's log line is expected */
        errno = err;
        srv_mhd_panic(NULL, "daemon.c", 5531, reason);
        _exit(0);
    }
    int st = 0;
    if (waitpid(pid, &st, 0) != pid) return -1;
    if (WIFEXITED(st) && WEXITSTATUS(st) == 0) return 1;
    if (WIFSIGNALED(st) && WTERMSIG(st) == SIGABRT) return 0;
    return -1;
}

int main(void)
{
    CHECK(srv_mhd_panic_is_benign(quiesce_reason, ENOENT) == 1);
    CHECK(srv_mhd_panic_is_benign(quiesce_reason, EBADF) == 0);
    CHECK(srv_mhd_panic_is_benign(quiesce_reason, 0) == 0);
    CHECK(srv_mhd_panic_is_benign("Failed to add listen FD to epoll set.\n", ENOENT) == 0);
    CHECK(srv_mhd_panic_is_benign(NULL, ENOENT) == 0);

    CHECK_EQ_INT(child_survives(quiesce_reason, ENOENT), 1);
    CHECK_EQ_INT(child_survives(quiesce_reason, EBADF), 0);
    CHECK_EQ_INT(child_survives("Failed to signal quiesce via inter-thread communication channel.\n",
                                ENOENT),
                 0);
    CHECK_EQ_INT(child_survives(NULL, ENOENT), 0);
    TEST_MAIN_END();
}
