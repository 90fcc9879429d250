/* check_evidence.h — the tolerance mechd recommends for one field of an
 * operation's answer, for POST /v1/check: ten times the largest
 * relative-error figure the answer's own "diagnostics" give on the way down
 * to the field (Richardson estimates, drifts of conserved quantities, target
 * errors), or 1e-12 (a closed form) when they give none. The rules are in
 * docs/grading.md, "recommended_tolerance".
 */
#ifndef API_CHECK_EVIDENCE_H
#define API_CHECK_EVIDENCE_H

#include <jansson.h>

struct api_check_recommended {
    double rel;      /* recommended relative tolerance, >= 1e-12 */
    double abs;      /* rel times the field's scale (0 for an object) */
    double scale;    /* largest |number| of the field, and of its siblings
                        when the field is one number in an array; 0 for an object */
    int from_diag;   /* 1: rel comes from the diagnostics; 0: closed-form default */
    double evidence; /* the largest relative-error figure found (0 if none) */
    char where[512]; /* its JSON pointer in the answer ("" if none) */
};

/* The recommended tolerance for the value want (borrowed, found at JSON
 * pointer `pointer` in answer, its container parent, NULL for the root) into
 * *out. Scans the "diagnostics" object of answer's root and of every object
 * on the pointer's path (12 levels deep at most); members named like
 * relative errors count ("target_error", "quaternion_norm_drift", or
 * "relative"/"_rel_" with "error", "drift", "difference", "precision" or
 * "bound"), skipping objects that say "conserved": false or "kind":
 * "first_order" (physics or a model, not numerical error). Non-finite figures
 * are ignored. Never fails; no allocation; reentrant. */
void api_check_recommend(json_t *answer, const char *pointer, const json_t *want,
                         const json_t *parent, struct api_check_recommended *out);

#endif
