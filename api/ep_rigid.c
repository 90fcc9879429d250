/* ep_rigid.c — POST /v1/rigid/inertia: inertia tensor, principal axes, angular
 * momentum and kinetic energy of a rigid body made of simple parts.
 * JSON <-> core only; the physics is core/inertia.c and core/rotation.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "mech/inertia.h"
#include "mech/rotation.h"

/* ---- schema ------------------------------------------------------------------ */

/* clang-format off */
#define S_COORD "{\"type\":\"number\",\"minimum\":-1e15,\"maximum\":1e15}"
#define S_VEC3(desc)                                                                    \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_COORD               \
    ",\"description\":\"" desc "\"}"
#define S_LEN(desc)                                                                     \
    "{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e15,"                      \
    "\"description\":\"" desc "\"}"
#define S_MASS                                                                          \
    "{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"                      \
    "\"description\":\"kg, > 0\"}"
#define S_ANGLE "{\"type\":\"number\",\"minimum\":-1e6,\"maximum\":1e6}"
#define S_ROW3                                                                          \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"                       \
    "{\"type\":\"number\",\"minimum\":-2,\"maximum\":2}}"

#define S_MATRIX                                                                        \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_ROW3                \
    ",\"description\":\"3x3 rows, orthonormal with det +1 to 1e-9\"}"
#define S_EULER                                                                         \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_ANGLE               \
    ",\"description\":\"[phi, theta, psi] rad: phi about z, theta about the new x, "     \
    "psi about the new z; R = R_psi R_theta R_phi\"}"
#define S_AXIS_ANGLE                                                                    \
    "{\"type\":\"object\",\"additionalProperties\":false,"                               \
    "\"required\":[\"axis\",\"angle\"],"                                                 \
    "\"properties\":{\"axis\":" S_VEC3("non-zero axis") ",\"angle\":" S_ANGLE "},"       \
    "\"description\":\"axes turned by angle (rad, right-handed) about axis\"}"
#define S_QUATERNION                                                                    \
    "{\"type\":\"array\",\"minItems\":4,\"maxItems\":4,\"items\":" S_COORD               \
    ",\"description\":\"[w, x, y, z] = [cos(a/2), sin(a/2) n], normalised here\"}"
#define S_ORIENTATION                                                                   \
    "{\"type\":\"object\",\"minProperties\":1,\"maxProperties\":1,"                      \
    "\"additionalProperties\":false,"                                                   \
    "\"description\":\"Passive rotation R taking scene components to body components "  \
    "(rows of R = body axes in scene axes), given as exactly one form.\","               \
    "\"properties\":{\"matrix\":" S_MATRIX ",\"euler_zxz\":" S_EULER                    \
    ",\"axis_angle\":" S_AXIS_ANGLE ",\"quaternion\":" S_QUATERNION "}}"

#define S_SHAPE(name, desc, extra_props, extra_req)                                     \
    "{\"type\":\"object\",\"additionalProperties\":false,\"description\":\"" desc "\","   \
    "\"required\":[\"shape\",\"mass\",\"position\"" extra_req "],"                        \
    "\"properties\":{\"shape\":{\"const\":\"" name "\"},\"mass\":" S_MASS                 \
    ",\"position\":" S_VEC3("m, centre of the part in scene axes") extra_props "}}"

#define S_ORIENT_PROP ",\"orientation\":" S_ORIENTATION
#define S_SIZE                                                                          \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_LEN("m")            \
    ",\"description\":\"edges [a, b, c] along body x, y, z, m\"}"

#define S_ROD      S_SHAPE("rod", "thin rod along body z",                              \
                           ",\"length\":" S_LEN("m") S_ORIENT_PROP, ",\"length\"")
#define S_BOX      S_SHAPE("box", "solid box, edges along body x, y, z",                \
                           ",\"size\":" S_SIZE S_ORIENT_PROP, ",\"size\"")
#define S_SPHERE   S_SHAPE("sphere", "solid sphere",                                    \
                           ",\"radius\":" S_LEN("m") S_ORIENT_PROP, ",\"radius\"")
#define S_SHELL    S_SHAPE("shell", "thin spherical shell",                             \
                           ",\"radius\":" S_LEN("m") S_ORIENT_PROP, ",\"radius\"")
#define S_CYLINDER S_SHAPE("cylinder", "solid cylinder, axis along body z",             \
                           ",\"radius\":" S_LEN("m") ",\"height\":" S_LEN("m")          \
                           S_ORIENT_PROP, ",\"radius\",\"height\"")
#define S_POINT    S_SHAPE("point", "point mass", "", "")

/* The point branch comes last: when a part fails two branches with the same
 * number of errors (a sphere missing its radius fails "sphere" by the missing
 * radius and "point" only by its shape), the validator reports the first, and
 * the part's own shape is the more helpful one. */
#define S_BODY                                                                          \
    "{\"oneOf\":[" S_ROD "," S_BOX "," S_SPHERE "," S_SHELL "," S_CYLINDER "," S_POINT "]}"

static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"bodies\"],"
    "\"properties\":{"
    "\"bodies\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":10000,\"items\":" S_BODY
    ",\"description\":\"the parts of one rigid body\"},"
    "\"origin\":{\"oneOf\":[" S_VEC3("m, point the tensor is taken about") ","
    "{\"const\":\"center_of_mass\"}],\"default\":\"center_of_mass\"},"
    "\"omega\":" S_VEC3("rad/s, angular velocity in scene axes (rotation about origin)")
    "}}";
/* clang-format on */

static const char description[] =
    "Inertia tensor of a rigid body made of parts: point masses, thin rods (length along "
    "body z), solid boxes (size [a,b,c] along body x,y,z), solid spheres, thin spherical "
    "shells and solid cylinders (radius, height, axis along body z), each with a mass (kg) "
    "and the position of its centre (m, scene axes). A part's optional orientation is the "
    "passive rotation R of the notes (scene components to body components; its rows are "
    "the body axes in scene axes), so the part contributes R^T I_body R; give it as exactly "
    "one of matrix, euler_zxz [phi, theta, psi] (z-x-z, R = R_psi R_theta R_phi), "
    "axis_angle {axis, angle} or quaternion [w,x,y,z] = [cos(a/2), sin(a/2) n]. "
    "Answers mass, center_of_mass, origin, tensor (kg m^2, about origin, default the "
    "centre of mass), tensor_center_of_mass, and principal: moments ascending, axes as unit "
    "rows (right-handed; rows 0 and 1 have their largest-magnitude component positive, row "
    "2 = row 0 x row 1), degenerate = two moments agree within 1e-10 of the largest (then "
    "the axes are one orthonormal basis of the degenerate subspace: the scene axes if all "
    "three agree). With omega (rad/s, rotation about the origin held at rest): "
    "angular_momentum = I omega and kinetic_energy = omega.I.omega/2. Precision: the "
    "tensor about the centre of mass is summed in centred coordinates and moved with the "
    "parallel-axis theorem, so bodies far from the scene origin keep full relative "
    "precision; principal moments are right to about 1e-15 of the largest.";

static const char example[] =
    "{\"bodies\":["
    "{\"shape\":\"box\",\"mass\":2,\"size\":[0.4,0.3,0.2],\"position\":[0,0,0],"
    "\"orientation\":{\"euler_zxz\":[0.5,0.3,0]}},"
    "{\"shape\":\"point\",\"mass\":0.5,\"position\":[0.3,0,0.1]}],"
    "\"origin\":\"center_of_mass\",\"omega\":[0,0,10]}";

/* ---- handler ----------------------------------------------------------------- */

static const char *const shape_names[MECH_SHAPE_COUNT] = {
    [MECH_SHAPE_POINT] = "point", [MECH_SHAPE_ROD] = "rod",
    [MECH_SHAPE_BOX] = "box",     [MECH_SHAPE_SPHERE] = "sphere",
    [MECH_SHAPE_SHELL] = "shell", [MECH_SHAPE_CYLINDER] = "cylinder",
};

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

/* Read body i's orientation (schema-validated: exactly one form) into *r.
 * Returns MECH_OK, or the core status with e filled and *prefix set to the JSON
 * pointer the core's param is relative to. */
static enum mech_status read_orientation(const json_t *o, size_t i, struct mech_mat3 *r,
                                         char *prefix, size_t np, struct mech_error *e)
{
    const json_t *v;
    snprintf(prefix, np, "/bodies/%zu/orientation", i);
    if ((v = json_object_get(o, "matrix"))) return mech_rotation_from_matrix(mat3_of(v), r, e);
    if ((v = json_object_get(o, "euler_zxz")))
        return mech_rotation_from_euler_zxz(json_number_value(json_array_get(v, 0)),
                                            json_number_value(json_array_get(v, 1)),
                                            json_number_value(json_array_get(v, 2)), r, e);
    if ((v = json_object_get(o, "axis_angle"))) {
        snprintf(prefix, np, "/bodies/%zu/orientation/axis_angle", i);
        return mech_rotation_from_axis_angle(api_vec3_member(v, "axis", mech_vec3_make(0, 0, 0)),
                                             api_number(v, "angle", 0), r, e);
    }
    if ((v = json_object_get(o, "quaternion"))) {
        double q[4];
        for (size_t k = 0; k < 4; k++)
            q[k] = json_number_value(json_array_get(v, k));
        return mech_rotation_from_quaternion(q, r, e);
    }
    return mech_error_set(e, MECH_EINVAL, NULL, "no orientation form given");
}

/* Parse bodies[i] into *p. Returns MECH_OK or a core status with e and prefix set. */
static enum mech_status read_part(const json_t *b, size_t i, struct mech_inertia_part *p,
                                  char *prefix, size_t np, struct mech_error *e)
{
    const char *shape = api_string(b, "shape", "");
    int s = -1;
    for (int k = 0; k < MECH_SHAPE_COUNT; k++)
        if (!strcmp(shape, shape_names[k])) s = k;
    snprintf(prefix, np, "/bodies/%zu", i);
    if (s < 0) return mech_error_set(e, MECH_EINVAL, "shape", "unknown shape \"%s\"", shape);
    memset(p, 0, sizeof *p);
    p->shape = (enum mech_inertia_shape)s;
    p->mass = api_number(b, "mass", 0);
    p->position = api_vec3_member(b, "position", mech_vec3_make(0, 0, 0));
    p->orientation = mech_mat3_identity();
    switch (p->shape) {
    case MECH_SHAPE_ROD:
        p->dim[0] = api_number(b, "length", 0);
        break;
    case MECH_SHAPE_BOX: {
        struct mech_vec3 sz = api_vec3_member(b, "size", mech_vec3_make(0, 0, 0));
        p->dim[0] = sz.x;
        p->dim[1] = sz.y;
        p->dim[2] = sz.z;
        break;
    }
    case MECH_SHAPE_SPHERE:
    case MECH_SHAPE_SHELL:
        p->dim[0] = api_number(b, "radius", 0);
        break;
    case MECH_SHAPE_CYLINDER:
        p->dim[0] = api_number(b, "radius", 0);
        p->dim[1] = api_number(b, "height", 0);
        break;
    default:
        break;
    }
    const json_t *o = json_object_get(b, "orientation");
    if (o) return read_orientation(o, i, &p->orientation, prefix, np, e);
    return MECH_OK;
}

static json_t *inertia(struct api_call *c, const json_t *body)
{
    const json_t *bodies = json_object_get(body, "bodies");
    size_t n = json_array_size(bodies);
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_inertia_part *parts = calloc(n ? n : 1, sizeof *parts);
    if (!parts) {
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for %zu parts", n);
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    for (size_t i = 0; i < n; i++) {
        char prefix[96];
        enum mech_status st =
            read_part(json_array_get(bodies, i), i, &parts[i], prefix, sizeof prefix, &e);
        if (st != MECH_OK) {
            free(parts);
            return api_call_fail_core(c, st, &e, prefix);
        }
    }
    const json_t *oj = json_object_get(body, "origin");
    struct mech_vec3 origin;
    int have_origin = oj && json_is_array(oj);
    if (have_origin) origin = api_vec3_of(oj);

    struct mech_inertia res;
    enum mech_status st =
        mech_inertia_compute(parts, n, have_origin ? &origin : NULL, &c->budget, &res, &e);
    free(parts);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    const json_t *wj = json_object_get(body, "omega");
    struct mech_vec3 l = {0, 0, 0};
    double ke = 0;
    if (wj) {
        st = mech_inertia_spin(res.tensor, api_vec3_of(wj), &l, &ke, &e);
        if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    }

    json_t *out = json_object();
    json_t *pr = json_object();
    if (!out || !pr) {
        json_decref(out);
        json_decref(pr);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    json_object_set_new(out, "mass", api_real(c, res.mass));
    json_object_set_new(out, "center_of_mass", api_vec3(c, res.center_of_mass));
    json_object_set_new(out, "origin", api_vec3(c, res.origin));
    json_object_set_new(out, "tensor", api_mat3(c, res.tensor));
    json_object_set_new(out, "tensor_center_of_mass", api_mat3(c, res.tensor_cm));
    json_object_set_new(pr, "moments", api_reals(c, res.principal.moments, 3));
    json_object_set_new(pr, "axes", api_mat3(c, res.principal.axes));
    json_object_set_new(pr, "degenerate", json_boolean(res.principal.degenerate));
    json_object_set_new(out, "principal", pr);
    if (wj) {
        json_object_set_new(out, "angular_momentum", api_vec3(c, l));
        json_object_set_new(out, "kinetic_energy", api_real(c, ke));
    }
    return out;
}

const struct api_route api_route_rigid_inertia = {
    "POST",
    "/v1/rigid/inertia",
    "Inertia tensor, principal axes, angular momentum and kinetic energy of a rigid body",
    description,
    schema,
    example,
    inertia,
    0,
};
