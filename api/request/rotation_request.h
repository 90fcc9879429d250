/* rotation_request.h — one rotation given in any of mechd's forms: its
 * parsing into a unit quaternion, and the encoding of a rotation in every
 * representation. Used by POST /v1/rotation/convert, /compose and /apply; the
 * rotation's request schema is in their data files (api/ops/rotation/).
 *
 * The conventions (sense, sequences, composition, locks) are those of
 * core/include/mech/rotation/rotation.h; the data files' descriptions state them.
 * Not thread-shared state: everything lives in the caller's structs.
 */
#ifndef API_ROTATION_REQUEST_H
#define API_ROTATION_REQUEST_H

#include "run/endpoint.h"
#include "mech/rotation/rotation.h"

struct api_rotation {
    double q[4];                    /* canonical unit quaternion of the turn */
    enum mech_rotation_sense sense; /* the sense of `matrix` */
    int from_matrix;                /* 1: the input was a matrix */
    struct mech_mat3 matrix;        /* R in `sense`: the polished input matrix, or from q */
    double orth, det;               /* residuals: of the input matrix, else of `matrix` */
};

/* Read the rotation object `obj` (schema-validated against the rotation schema of api/ops/rotation/convert.json)
 * found at JSON pointer `pointer` ("" for the body). default_sense is used when
 * it has no "sense". Returns 0, or -1 after recording errors in c (two forms,
 * no form, a bad matrix, a zero axis or quaternion ...), naming the field. */
int api_rotation_read(struct api_call *c, const json_t *obj, const char *pointer,
                      enum mech_rotation_sense default_sense, struct api_rotation *out);

/* The same turn in another sense (q unchanged, matrix transposed). */
void api_rotation_set_sense(struct api_rotation *r, enum mech_rotation_sense sense);

/* Add to `out` every representation of r: sense, matrix, quaternion,
 * axis_angle, rotation_vector, euler_zxz, gimbal_lock, gimbal, euler (all 12
 * sequences, intrinsic and extrinsic), residuals, notes. Returns 0, or -1
 * after recording a failure in c. */
int api_rotation_encode(struct api_call *c, json_t *out, const struct api_rotation *r);

/* Text for route descriptions: what api_rotation_encode answers. */

#endif
