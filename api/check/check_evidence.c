/* check_evidence.c — the recommended tolerance of POST /v1/check from an
 * answer's own error figures (contract in api/check/check_evidence.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check/check_evidence.h"
#include "check/check_tree.h"
#include "schema/schema.h"

#define CHECK_CLOSED_FORM_RELATIVE 1e-12 /* numerical error assumed without evidence */
#define CHECK_EVIDENCE_FACTOR 10.0       /* safety factor on the operation's own error figures */

/* Whether a diagnostics member is a relative-error figure of the computation
 * (not a physical quantity that happens to be relative, like relative_velocity). */
static int is_relative_evidence(const char *key)
{
    if (!strcmp(key, "target_error") || !strcmp(key, "quaternion_norm_drift")) return 1;
    if (!strstr(key, "relative") && !strstr(key, "_rel_")) return 0;
    return strstr(key, "error") || strstr(key, "drift") || strstr(key, "difference") ||
           strstr(key, "precision") || strstr(key, "bound");
}

/* Walk a diagnostics subtree, keeping the largest relative-error figure and
 * where it was. Objects that say "conserved": false are skipped: the drift of
 * a quantity that is not conserved is physics, not error; so are comparisons
 * with a first-order (approximate) reference, whose difference is the model's. */
static void scan_evidence(const json_t *j, char *ptr, size_t cap, double *worst, char *where,
                          size_t where_n, int depth)
{
    if (depth > 12) return;
    size_t len = strlen(ptr);
    if (json_is_object(j)) {
        if (json_is_false(json_object_get(j, "conserved"))) return;
        const char *kind = json_string_value(json_object_get(j, "kind"));
        if (kind && !strcmp(kind, "first_order")) return; /* a model, not the error */
        const char *key;
        json_t *v;
        json_object_foreach((json_t *)j, key, v) {
            api_pointer_append(ptr, cap, key);
            if (json_is_number(v)) {
                double x = fabs(json_number_value(v));
                if (is_relative_evidence(key) && isfinite(x) && x > *worst) {
                    *worst = x;
                    snprintf(where, where_n, "%s", ptr);
                }
            } else {
                scan_evidence(v, ptr, cap, worst, where, where_n, depth + 1);
            }
            ptr[len] = '\0';
        }
    } else if (json_is_array(j)) {
        size_t i;
        json_t *v;
        json_array_foreach(j, i, v) {
            snprintf(ptr + len, cap - len, "/%zu", i);
            scan_evidence(v, ptr, cap, worst, where, where_n, depth + 1);
            ptr[len] = '\0';
        }
    }
}

/* Evidence from the "diagnostics" members of the answer's root and of every
 * object on the way down to the pointer (the nearest context of the value). */
static double find_evidence(json_t *answer, const char *pointer, char *where, size_t where_n)
{
    double worst = 0;
    where[0] = '\0';
    char prefix[512];
    char scan[512];
    size_t plen = strlen(pointer);
    /* every prefix of the pointer that ends at a token boundary, root first */
    for (size_t cut = 0; cut <= plen && cut < sizeof prefix; cut++) {
        if (cut != 0 && cut != plen && pointer[cut] != '/') continue;
        memcpy(prefix, pointer, cut);
        prefix[cut] = '\0';
        int bad;
        json_t *node = api_check_pointer_get(answer, prefix, NULL, &bad);
        json_t *d = json_is_object(node) ? json_object_get(node, "diagnostics") : NULL;
        if (!json_is_object(d)) continue;
        snprintf(scan, sizeof scan, "%s", prefix);
        api_pointer_append(scan, sizeof scan, "diagnostics");
        scan_evidence(d, scan, sizeof scan, &worst, where, where_n, 0);
    }
    return worst;
}

void api_check_recommend(json_t *answer, const char *pointer, const json_t *want,
                         const json_t *parent, struct api_check_recommended *out)
{
    out->evidence = find_evidence(answer, pointer, out->where, sizeof out->where);
    out->rel = CHECK_EVIDENCE_FACTOR * out->evidence;
    out->from_diag = out->rel > CHECK_CLOSED_FORM_RELATIVE;
    if (!out->from_diag) out->rel = CHECK_CLOSED_FORM_RELATIVE;
    out->scale = json_is_object(want) ? 0 : api_check_max_abs(want, 0);
    if (json_is_number(want) && json_is_array(parent)) {
        double s = api_check_max_abs(parent, 0);
        if (s > out->scale) out->scale = s;
    }
    out->abs = out->rel * out->scale;
}
