/* rotation_request.h — one rotation given in any of mechd's forms: the JSON
 * Schema fragment (C string macros, so every route that takes a rotation
 * states the same text), its parsing into a unit quaternion, and the encoding
 * of a rotation in every representation. Used by POST /v1/rotation/convert,
 * /compose and /apply; other endpoints may embed API_ROTATION_SCHEMA too.
 *
 * The conventions (sense, sequences, composition, locks) are those of
 * core/include/mech/rotation.h; API_ROTATION_DOC states them for the catalog.
 * Not thread-shared state: everything lives in the caller's structs.
 */
#ifndef API_ROTATION_REQUEST_H
#define API_ROTATION_REQUEST_H

#include "endpoint.h"
#include "mech/rotation.h"

/* ---- schema fragments --------------------------------------------------------
 * Angles are radians, |angle| <= 1e6 (beyond that sin/cos of a double carry
 * no useful digits); quaternion and axis components any finite size up to
 * 1e15 (normalised without overflow); matrix entries in [-2, 2] (a rotation's
 * are in [-1, 1]; the residual check refuses the rest with its own message). */
#define API_ROT_ANGLE "{\"type\":\"number\",\"minimum\":-1e6,\"maximum\":1e6}"
#define API_ROT_COMP "{\"type\":\"number\",\"minimum\":-1e15,\"maximum\":1e15}"
#define API_ROT_ARRAY(n, item, desc)                                                         \
    "{\"type\":\"array\",\"minItems\":" #n ",\"maxItems\":" #n ",\"items\":" item              \
    ",\"description\":\"" desc "\"}"

#define API_ROTATION_PROPERTIES                                                              \
    "\"matrix\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"                   \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"                              \
    "{\"type\":\"number\",\"minimum\":-2,\"maximum\":2}},"                                      \
    "\"description\":\"3x3 rows: the rotation matrix R in the given sense (passive: rows = "    \
    "new axes in old coordinates); orthonormal with det +1 to 1e-9 (max |R^T R - 1|), "         \
    "then polished to round-off\"},"                                                            \
    "\"euler_zxz\":" API_ROT_ARRAY(3, API_ROT_ANGLE,                                           \
        "[phi, theta, psi] rad, the notes' z-x-z angles: phi about z, theta about the new x "   \
        "(line of nodes), psi about the new z; passive R = R_psi R_theta R_phi; the same as "   \
        "euler {sequence ZXZ, intrinsic true}") ","                                             \
    "\"euler\":{\"type\":\"object\",\"additionalProperties\":false,"                            \
    "\"required\":[\"sequence\",\"intrinsic\",\"angles\"],\"properties\":{"                     \
    "\"sequence\":{\"enum\":[\"XYZ\",\"XZY\",\"YXZ\",\"YZX\",\"ZXY\",\"ZYX\",\"XYX\",\"XZX\","  \
    "\"YXY\",\"YZY\",\"ZXZ\",\"ZYZ\"],\"description\":\"axes of the three turns in the order "  \
    "they are applied\"},"                                                                      \
    "\"intrinsic\":{\"type\":\"boolean\",\"description\":\"true: each turn about the axis as "  \
    "moved by the turns before it (body axes); false: about the fixed original axes. "          \
    "Required: the two readings differ\"},"                                                     \
    "\"angles\":" API_ROT_ARRAY(3, API_ROT_ANGLE, "rad, one per letter of the sequence")       \
    "},\"description\":\"any of the 12 Euler/Tait-Bryan sequences, intrinsic or extrinsic\"}," \
    "\"axis_angle\":{\"type\":\"object\",\"additionalProperties\":false,"                       \
    "\"required\":[\"axis\",\"angle\"],\"properties\":{"                                        \
    "\"axis\":" API_ROT_ARRAY(3, API_ROT_COMP, "non-zero, any length (normalised here)") ","    \
    "\"angle\":" API_ROT_ANGLE "},"                                                             \
    "\"description\":\"a right-handed turn by angle (rad) about axis\"},"                       \
    "\"quaternion\":" API_ROT_ARRAY(4, API_ROT_COMP,                                           \
        "[w, x, y, z] = [cos(a/2), sin(a/2) n] for the turn by a about n; any non-zero "        \
        "length (normalised here); q and -q are the same turn") ","                             \
    "\"rotation_vector\":" API_ROT_ARRAY(3, API_ROT_ANGLE,                                     \
        "angle (rad) times the unit axis; [0, 0, 0] is the identity") ","                       \
    "\"sense\":{\"enum\":[\"passive\",\"active\"],\"default\":\"passive\",\"description\":"     \
    "\"passive (the notes): R takes a vector's components in the old axes to the new axes; "    \
    "active: R turns the vector in fixed axes. R_active = R_passive^T for the same turn; the "  \
    "angle/axis/quaternion parameters of a turn do not depend on the sense\"}"

/* One rotation: exactly one form (checked by the handler, which names the
 * extra form) plus an optional sense. */
#define API_ROTATION_SCHEMA                                                                  \
    "{\"type\":\"object\",\"additionalProperties\":false,\"minProperties\":1,"                  \
    "\"description\":\"a rotation given as exactly one of matrix, euler_zxz, euler, "          \
    "axis_angle, quaternion, rotation_vector, with an optional sense\","                       \
    "\"properties\":{" API_ROTATION_PROPERTIES "}}"

/* The conventions, for route descriptions. */
#define API_ROTATION_DOC                                                                      \
    "A rotation is given as exactly one of: matrix (3x3 rows, R in the request's sense); "    \
    "euler_zxz [phi, theta, psi] (the notes: phi about z, theta about the new x, psi about "   \
    "the new z; passive R = R_psi R_theta R_phi); euler {sequence, intrinsic, angles} for "   \
    "the 12 sequences XYZ XZY YXZ YZX ZXY ZYX (Tait-Bryan) and XYX XZX YXY YZY ZXZ ZYZ "       \
    "(proper Euler), letters = axes of the turns in the order applied, intrinsic = about "    \
    "the moved (body) axes, extrinsic = about the fixed axes (extrinsic XYZ (a,b,c) = "       \
    "intrinsic ZYX (c,b,a); ZXZ intrinsic = euler_zxz); axis_angle {axis, angle}; "           \
    "quaternion [w,x,y,z] = [cos(a/2), sin(a/2) n]; rotation_vector = angle x unit axis. "   \
    "All angles are radians and right-handed. Each form names a TURN; sense says what the "   \
    "matrix R means: passive (default, the notes' convention): the axes are turned and "      \
    "R takes a vector's components in the old axes to the new axes (rows of R = new axes "    \
    "in old coordinates); active: the vector is turned in fixed axes, v' = R v. "             \
    "R_active = R_passive^T; the parameters of the other forms are the same in both "         \
    "senses. In the active sense the intrinsic sequence (i,j,k) is R = R_i(a0) R_j(a1) "       \
    "R_k(a2) and the quaternion's matrix is the usual "                                        \
    "[[1-2(y2+z2), 2(xy-wz), 2(xz+wy)], ...]; in the passive sense both are transposed. "

struct api_rotation {
    double q[4];                    /* canonical unit quaternion of the turn */
    enum mech_rotation_sense sense; /* the sense of `matrix` */
    int from_matrix;                /* 1: the input was a matrix */
    struct mech_mat3 matrix;        /* R in `sense`: the polished input matrix, or from q */
    double orth, det;               /* residuals: of the input matrix, else of `matrix` */
};

/* Read the rotation object `obj` (schema-validated against API_ROTATION_SCHEMA)
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
#define API_ROTATION_ANSWER_DOC                                                               \
    "Answer, for the rotation in the request's sense: matrix (R; for a matrix input the "     \
    "input polished to the nearest rotation); quaternion [w,x,y,z] unit, canonical sign "     \
    "w > 0 (at w = 0 exactly: the first non-zero of x, y, z is positive); axis_angle "        \
    "{axis (unit), angle in [0, pi]} (at angle 0 the axis is arbitrary and [0,0,1] is "       \
    "given; at angle pi, axis and -axis are the same turn and the sign follows the "          \
    "quaternion's rule); rotation_vector = angle x axis; euler_zxz [phi, theta, psi] with "   \
    "phi, psi in (-pi, pi], theta in [0, pi]; gimbal_lock (of euler_zxz) and gimbal "        \
    "{lock_distance: distance of theta from the nearer lock 0 or pi, combination: the "       \
    "angle combination that lock leaves determined (phi+psi at theta = 0, phi-psi at "        \
    "theta = pi), value: its value in (-pi, pi], continuous through the lock}; euler "       \
    "{intrinsic: {XYZ: {...}, ...}, extrinsic: {...}}: all 24 readings, each {angles, "       \
    "gimbal_lock, lock_distance, combination (\"angles[0]+angles[2]\" or "                \
    "\"angles[0]-angles[2]\"), value}, angles[0] and angles[2] in (-pi, pi], angles[1] "  \
    "in [0, pi] (proper Euler) or [-pi/2, pi/2] (Tait-Bryan). At a lock (angles[1] within "    \
    "1e-14 rad of 0 or pi, resp. +-pi/2) gimbal_lock is true and the branch angles[2] = 0, "  \
    "angles[0] = the combination is returned (psi = 0 for z-x-z); away from it the three "     \
    "angles are returned, and as the lock is approached the combination stays exact while "  \
    "the separate angles become ill-conditioned (error ~ 1e-16 / lock_distance from a "        \
    "matrix; full precision from Euler angles given directly, which pass through the "        \
    "quaternion without cancellation). Extraction: Shepperd's method for the quaternion, "     \
    "atan2 of sums and differences of quaternion components for the angles (Bernardes and "   \
    "Viollet 2022), never asin/acos of a rounded value. residuals {orthonormality: "          \
    "max |(R^T R - 1)_ij|, det: det R - 1}: of the input matrix as given, otherwise of the "   \
    "matrix answered (round-off evidence). notes: plain-language remarks on any lock or "      \
    "arbitrary axis."

#endif
