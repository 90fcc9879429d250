/* status.c — names of mech_status codes and the first-error-wins recorder. */
#include "mech/base/status.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const char *const status_names[MECH_STATUS_COUNT] = {
    [MECH_OK] = "ok",
    [MECH_EINVAL] = "invalid-argument",
    [MECH_EDOMAIN] = "domain-error",
    [MECH_EBUDGET] = "step-budget-exceeded",
    [MECH_EDEADLINE] = "deadline-exceeded",
    [MECH_ECANCELLED] = "cancelled",
    [MECH_ENOMEM] = "out-of-memory",
    [MECH_ENUMERIC] = "numerical-failure",
    [MECH_EINTERNAL] = "internal-error",
};

const char *mech_status_name(enum mech_status s)
{
    if ((int)s < 0 || s >= MECH_STATUS_COUNT || !status_names[s]) return "unknown";
    return status_names[s];
}

void mech_error_clear(struct mech_error *err)
{
    if (!err) return;
    memset(err, 0, sizeof *err);
    err->code = MECH_OK;
    err->progress.steps = 0;
    err->progress.t_reached = NAN;
    err->progress.t_target = NAN;
}

enum mech_status mech_error_set(struct mech_error *err, enum mech_status code,
                                const char *param, const char *fmt, ...)
{
    if (!err || err->code != MECH_OK) return code;
    err->code = code;
    snprintf(err->param, sizeof err->param, "%s", param ? param : "");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->text, sizeof err->text, fmt, ap);
    va_end(ap);
    return code;
}
