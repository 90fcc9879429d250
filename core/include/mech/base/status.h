/* mech/base/status.h — status codes and the caller-owned error record shared by
 * every fallible libmech function.
 *
 * Contract (docs/design.md, "Numerics and errors"): fallible functions return enum mech_status and
 * take an optional `struct mech_error *` last. The first error recorded wins;
 * later ones are ignored. Nothing is allocated on an error path. Codes are
 * append-only: never renumber or remove one (pinned by tests/api/test_problem.c).
 */
#ifndef MECH_STATUS_H
#define MECH_STATUS_H

#include <stddef.h>

enum mech_status {
    MECH_OK = 0,
    MECH_EINVAL = 1,     /* an argument is malformed (wrong size, zero vector, NULL) */
    MECH_EDOMAIN = 2,    /* physically impossible input: beta >= 1, m <= 0, r <= 2GM/c^2 */
    MECH_EBUDGET = 3,    /* step or sample budget exhausted before the end */
    MECH_EDEADLINE = 4,  /* wall-clock deadline passed before the end */
    MECH_ECANCELLED = 5, /* cancel flag raised (server shutting down) */
    MECH_ENOMEM = 6,     /* allocation failed */
    MECH_ENUMERIC = 7,   /* the numerics failed: non-finite value, step size underflow */
    MECH_EINTERNAL = 8,  /* a bug: an invariant of libmech itself was broken */
    MECH_STATUS_COUNT    /* keep last */
};

/* Where a failed computation got to, for budget/deadline errors. */
struct mech_progress {
    long steps;       /* steps taken when it stopped */
    double t_reached; /* independent variable reached (s), NaN if not applicable */
    double t_target;  /* where it was going (s), NaN if not applicable */
};

struct mech_error {
    enum mech_status code;  /* MECH_OK while no error is recorded */
    char param[96];         /* offending input, as a JSON-pointer-like path without
                               the leading '/', e.g. "velocity/beta"; "" if none */
    char text[200];         /* short human-readable explanation */
    struct mech_progress progress;
};

/* Short stable name of a status ("ok", "invalid-argument", ...). Never NULL. */
const char *mech_status_name(enum mech_status s);

/* Clear an error record (code MECH_OK, empty strings, NaN progress). err may be NULL. */
void mech_error_clear(struct mech_error *err);

/* Record an error unless one is already recorded (first error wins).
 * err may be NULL (then nothing is recorded). param may be NULL. Returns code,
 * so callers can write `return mech_error_set(err, MECH_EDOMAIN, "mass", "...")`. */
enum mech_status mech_error_set(struct mech_error *err, enum mech_status code,
                                const char *param, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
