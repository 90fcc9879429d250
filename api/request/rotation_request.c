/* rotation_request.c — parsing a rotation given in any form into a unit
 * quaternion, and encoding it in every form (see api/request/rotation_request.h; the
 * physics and conventions are core/rotation/rotation.c, mech/rotation/rotation.h). */
#include "request/rotation_request.h"

#include <stdio.h>
#include <string.h>

static const char *const forms[] = {"matrix",     "euler_zxz",  "euler",
                                    "axis_angle", "quaternion", "rotation_vector"};
#define NFORMS (sizeof forms / sizeof forms[0])

static struct mech_mat3 mat3_of(const json_t *rows)
{
    struct mech_mat3 m;
    for (int i = 0; i < 3; i++) {
        struct mech_vec3 r = api_vec3_of(json_array_get(rows, (size_t)i));
        m.a[i][0] = r.x;
        m.a[i][1] = r.y;
        m.a[i][2] = r.z;
    }
    return m;
}

static void reals_of(const json_t *a, double *x, size_t n)
{
    for (size_t i = 0; i < n; i++)
        x[i] = json_number_value(json_array_get(a, i));
}

void api_rotation_set_sense(struct api_rotation *r, enum mech_rotation_sense sense)
{
    if (r->sense != sense) r->matrix = mech_mat3_transpose(r->matrix);
    r->sense = sense;
}

int api_rotation_read(struct api_call *c, const json_t *obj, const char *pointer,
                      enum mech_rotation_sense default_sense, struct api_rotation *out)
{
    char where[192];
    const char *form = NULL;
    for (size_t k = 0; k < NFORMS; k++)
        if (json_object_get(obj, forms[k])) {
            if (form) {
                snprintf(where, sizeof where, "%s/%s", pointer, forms[k]);
                api_call_invalid(c, where,
                                 "give the rotation as exactly one of matrix, euler_zxz, euler, "
                                 "axis_angle, quaternion, rotation_vector: got both %s and %s",
                                 form, forms[k]);
                return -1;
            }
            form = forms[k];
        }
    if (!form) {
        api_call_invalid(c, pointer,
                         "no rotation given: give exactly one of matrix, euler_zxz, euler, "
                         "axis_angle, quaternion, rotation_vector");
        return -1;
    }
    memset(out, 0, sizeof *out);
    /* The item's own sense when the client gave one; else default_sense (a
     * /v1/rotation/compose item inherits the list's sense, which the
     * schema's per-item default cannot say). */
    char sense_ptr[300];
    snprintf(sense_ptr, sizeof sense_ptr, "%s/sense", pointer);
    const char *sense = api_call_given(c, sense_ptr) ? api_string(obj, "sense", NULL) : NULL;
    out->sense = sense
                     ? (strcmp(sense, "active") == 0 ? MECH_ROTATION_ACTIVE : MECH_ROTATION_PASSIVE)
                     : default_sense;
    const json_t *v = json_object_get(obj, form);
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st;
    snprintf(where, sizeof where, "%s", pointer); /* core params are relative to it */
    if (!strcmp(form, "matrix")) {
        struct mech_mat3 m = mat3_of(v), p;
        mech_rotation_residuals(m, &out->orth, &out->det);
        st = mech_rotation_from_matrix(m, &p, &e);
        if (st == MECH_OK) st = mech_quaternion_from_matrix(p, out->sense, out->q, &e);
        if (st == MECH_OK) {
            out->from_matrix = 1;
            out->matrix = p;
            return 0;
        }
    } else if (!strcmp(form, "euler_zxz")) {
        double a[3];
        reals_of(v, a, 3);
        st = mech_quaternion_from_euler(MECH_EULER_ZXZ, 1, a, out->q, &e);
        if (st != MECH_OK) { /* the core names "angles"; the field here is euler_zxz */
            mech_error_clear(&e);
            mech_error_set(&e, st, "euler_zxz", "angles must be finite");
        }
    } else if (!strcmp(form, "euler")) {
        snprintf(where, sizeof where, "%s/euler", pointer);
        enum mech_euler_sequence seq;
        double a[3];
        reals_of(json_object_get(v, "angles"), a, 3);
        st = mech_euler_sequence_find(api_string(v, "sequence", ""), &seq, &e);
        if (st == MECH_OK)
            st = mech_quaternion_from_euler(seq, json_is_true(json_object_get(v, "intrinsic")), a,
                                            out->q, &e);
    } else if (!strcmp(form, "axis_angle")) {
        snprintf(where, sizeof where, "%s/axis_angle", pointer);
        st = mech_quaternion_from_axis_angle(api_vec3_member(v, "axis", mech_vec3_make(0, 0, 0)),
                                             api_number(v, "angle", 0), out->q, &e);
    } else if (!strcmp(form, "quaternion")) {
        reals_of(v, out->q, 4);
        st = mech_quaternion_canonical(out->q, &e);
    } else {
        st = mech_quaternion_from_rotation_vector(api_vec3_of(v), out->q, &e);
    }
    if (st == MECH_OK)
        st = mech_rotation_matrix_of_quaternion(out->q, out->sense, &out->matrix, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, where);
        return -1;
    }
    mech_rotation_residuals(out->matrix, &out->orth, &out->det);
    return 0;
}

/* One Euler reading as {angles, gimbal_lock, lock_distance, combination, value}. */
static json_t *euler_entry(struct api_call *c, const struct mech_euler_angles *ea)
{
    return json_pack("{s:o,s:b,s:o,s:s,s:o}", "angles", api_reals(c, ea->angles, 3), "gimbal_lock",
                     ea->gimbal_lock, "lock_distance", api_real(c, ea->lock_distance),
                     "combination",
                     ea->combination_sign > 0 ? "angles[0]+angles[2]" : "angles[0]-angles[2]",
                     "value", api_real(c, ea->combination));
}

int api_rotation_encode(struct api_call *c, json_t *out, const struct api_rotation *r)
{
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_vec3 axis;
    double angle;
    struct mech_euler_angles zxz;
    enum mech_status st = mech_quaternion_to_axis_angle(r->q, &axis, &angle, &e);
    if (st == MECH_OK) st = mech_quaternion_to_euler(r->q, MECH_EULER_ZXZ, 1, &zxz, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        return -1;
    }
    json_t *notes = json_array();
    json_t *euler = json_pack("{s:o,s:o}", "intrinsic", json_object(), "extrinsic", json_object());
    if (!notes || !euler) {
        json_decref(notes);
        json_decref(euler);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        return -1;
    }
    for (int intr = 1; intr >= 0; intr--) {
        json_t *dst = json_object_get(euler, intr ? "intrinsic" : "extrinsic");
        for (int k = 0; k < MECH_EULER_SEQUENCE_COUNT; k++) {
            struct mech_euler_angles ea;
            st = mech_quaternion_to_euler(r->q, (enum mech_euler_sequence)k, intr, &ea, &e);
            if (st != MECH_OK) {
                json_decref(notes);
                json_decref(euler);
                api_call_fail_core(c, st, &e, "");
                return -1;
            }
            json_object_set_new(dst, mech_euler_sequence_name((enum mech_euler_sequence)k),
                                euler_entry(c, &ea));
        }
    }
    json_object_set_new_nocheck(
        out, "sense", json_string(r->sense == MECH_ROTATION_ACTIVE ? "active" : "passive"));
    json_object_set_new_nocheck(out, "matrix", api_mat3(c, r->matrix));
    json_object_set_new_nocheck(out, "quaternion", api_reals(c, r->q, 4));
    json_object_set_new(
        out, "axis_angle",
        json_pack("{s:o,s:o}", "axis", api_vec3(c, axis), "angle", api_real(c, angle)));
    json_object_set_new_nocheck(out, "rotation_vector", api_vec3(c, mech_vec3_scale(axis, angle)));
    json_object_set_new_nocheck(out, "euler_zxz", api_reals(c, zxz.angles, 3));
    json_object_set_new_nocheck(out, "gimbal_lock", json_boolean(zxz.gimbal_lock));
    json_object_set_new_nocheck(out, "gimbal",
                                json_pack("{s:o,s:s,s:o}", "lock_distance",
                                          api_real(c, zxz.lock_distance), "combination",
                                          zxz.combination_sign > 0 ? "phi+psi" : "phi-psi", "value",
                                          api_real(c, zxz.combination)));
    json_object_set_new_nocheck(out, "euler", euler);
    json_object_set_new(
        out, "residuals",
        json_pack("{s:o,s:o}", "orthonormality", api_real(c, r->orth), "det", api_real(c, r->det)));
    if (angle == 0)
        json_array_append_new(notes, json_string("angle 0 (the identity): the axis is arbitrary; "
                                                 "[0, 0, 1] is given"));
    if (r->q[0] == 0)
        json_array_append_new(notes, json_string("angle pi: axis and -axis give the same "
                                                 "rotation; the sign follows the quaternion's "
                                                 "rule (w = 0: first non-zero of x, y, z > 0)"));
    if (zxz.gimbal_lock) {
        char txt[200];
        snprintf(txt, sizeof txt,
                 "euler_zxz at gimbal lock (theta = %s): only %s is determined; the branch "
                 "psi = 0 is given",
                 zxz.combination_sign > 0 ? "0" : "pi",
                 zxz.combination_sign > 0 ? "phi + psi" : "phi - psi");
        json_array_append_new(notes, json_string(txt));
    }
    json_object_set_new_nocheck(out, "notes", notes);
    return 0;
}
