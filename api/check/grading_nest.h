/* grading_nest.h — which operations may not run inside /v1/check or
 * /v1/batch (shared by api/ops/tools/check.c and api/ops/tools/batch.c). */
#ifndef MECHD_GRADING_NEST_H
#define MECHD_GRADING_NEST_H

#include <string.h>

/* 1 if `path` is /v1/check or /v1/batch: those are refused as inner
 * operations, so one request's work stays bounded. path must be non-NULL. */
static inline int api_is_nested_op(const char *path)
{
    return !strcmp(path, "/v1/check") || !strcmp(path, "/v1/batch");
}

#endif
