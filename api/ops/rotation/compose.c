/* compose.c — POST /v1/rotation/compose: the product of a list of rotations.
 * JSON <-> core only: the parsing and encoding of a rotation is
 * api/request/rotation_request.c, the mathematics core/rotation/rotation.c
 * (mech/rotation/rotation.h). */
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "request/rotation_request.h"

#define MAX_FACTORS 1000

json_t *api_op_rotation_compose(struct api_call *c, const json_t *body)
{
    const json_t *list = json_object_get(body, "rotations");
    size_t n = json_array_size(list);
    const char *s = api_string_of(body, "sense");
    enum mech_rotation_sense sense =
        strcmp(s, "active") == 0 ? MECH_ROTATION_ACTIVE : MECH_ROTATION_PASSIVE;
    double(*qs)[4] = calloc(n ? n : 1, sizeof *qs);
    if (!qs) return api_call_out_of_memory(c, NULL);
    int bad = 0;
    for (size_t i = 0; i < n && i < MAX_FACTORS; i++) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/rotations/%zu", i);
        struct api_rotation r;
        if (api_rotation_read(c, json_array_get(list, i), ptr, sense, &r) != 0) {
            bad = 1;
            continue; /* report every bad item, not only the first */
        }
        memcpy(qs[i], r.q, sizeof r.q);
    }
    if (bad) {
        free(qs);
        return NULL;
    }
    struct api_rotation prod;
    memset(&prod, 0, sizeof prod);
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st =
        mech_rotation_compose((const double(*)[4])qs, n, sense, prod.q, &c->budget, &e);
    free(qs);
    if (st == MECH_OK) st = mech_rotation_matrix_of_quaternion(prod.q, sense, &prod.matrix, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    prod.sense = sense;
    mech_rotation_residuals(prod.matrix, &prod.orth, &prod.det);
    json_t *out = json_pack("{s:i}", "count", (json_int_t)n);
    if (!out) return api_call_out_of_memory(c, NULL);
    if (api_rotation_encode(c, out, &prod) != 0) {
        json_decref(out);
        return NULL;
    }
    return out;
}
