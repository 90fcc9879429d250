/* api_samples.h — the answer budget (api/run/api_samples.c). */
#ifndef API_API_SAMPLES_H
#define API_API_SAMPLES_H

#include <stddef.h>

#include <jansson.h>

/* NULL when the samples that body (validated against route ri's schema,
 * borrowed) asks for in all — every numeric "samples" member, and the default
 * of each operation a /v1/batch or /v1/check item names without one — fit in
 * cap; else the 422 answer-too-large problem (new reference) naming, at
 * prefix + the pointer, where the count passed cap. Routes whose schema has
 * no samples and no nested operations are not walked. */
json_t *api_answer_budget_problem(size_t ri, const json_t *body, const char *prefix, long cap);

/* The samples body (validated against route ri's schema, borrowed) asks for
 * in all, counted as api_answer_budget_problem counts them; 0 for a route
 * whose schema has no samples and no nested operations. */
double api_answer_samples(size_t ri, const json_t *body);

#endif
