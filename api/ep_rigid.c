/* ep_rigid.c — POST /v1/rigid/inertia: inertia tensor, principal axes, angular
 * momentum and kinetic energy of a rigid body made of simple parts, holes and
 * closed triangle meshes, with each part's own contribution for auditing.
 * JSON <-> core only; the physics is core/inertia.c and core/rotation.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "rotation_request.h"
#include "mech/inertia.h"
#include "mech/rotation.h"
#include "mech/vector_algebra.h"

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
#define S_ROW3                                                                          \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"                       \
    "{\"type\":\"number\",\"minimum\":-2,\"maximum\":2}}"

#define S_ORIENTATION API_ROTATION_SCHEMA

#define S_HOLE                                                                          \
    ",\"hole\":{\"type\":\"boolean\",\"default\":false,\"description\":\"true: the part is "  \
    "removed material (its mass, first moment and tensor are subtracted); its mass is "  \
    "what its volume would weigh at the body's density\"}"
#define S_PART(name, desc, props, req)                                                  \
    "{\"type\":\"object\",\"additionalProperties\":false,\"description\":\"" desc "\","   \
    "\"required\":[\"shape\",\"mass\"" req "],"                                           \
    "\"properties\":{\"shape\":{\"const\":\"" name "\"},\"mass\":" S_MASS S_HOLE props "}}"
#define S_SHAPE(name, desc, extra_props, extra_req)                                     \
    S_PART(name, desc, ",\"position\":" S_VEC3("m, centre of the part in scene axes")    \
           extra_props, ",\"position\"" extra_req)
#define S_SHAPE_AT(name, desc, where, extra_props, extra_req)                           \
    S_PART(name, desc, ",\"position\":" S_VEC3(where) extra_props, ",\"position\"" extra_req)

#define S_ORIENT_PROP ",\"orientation\":" S_ORIENTATION
#define S_SIZE                                                                          \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_LEN("m")            \
    ",\"description\":\"edges [a, b, c] along body x, y, z, m\"}"
#define S_SIZE2                                                                         \
    "{\"type\":\"array\",\"minItems\":2,\"maxItems\":2,\"items\":" S_LEN("m")            \
    ",\"description\":\"edges [a, b] along body x, y, m\"}"
#define S_SEMI                                                                          \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_LEN("m")            \
    ",\"description\":\"semi-axes [a, b, c] along body x, y, z, m\"}"
#define S_CORNERS                                                                       \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_VEC3("m")           \
    ",\"description\":\"the three corners in scene axes, m\"}"
#define S_MESH_VERTICES                                                                 \
    "{\"type\":\"array\",\"minItems\":4,\"maxItems\":100000,\"items\":" S_VEC3("m")      \
    ",\"description\":\"points in body axes (scene axes when position and orientation "  \
    "are left out), m\"}"
#define S_MESH_FACES                                                                    \
    "{\"type\":\"array\",\"minItems\":4,\"maxItems\":200000,\"items\":"                  \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"                       \
    "{\"type\":\"integer\",\"minimum\":0,\"maximum\":99999}},"                           \
    "\"description\":\"triangles [i, j, k] (0-based vertex indices), counter-clockwise "  \
    "seen from outside (all clockwise is accepted too and reported as inverted)\"}"

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
#define S_CONE     S_SHAPE_AT("cone", "solid right circular cone opening along body +z " \
                              "from its apex", "m, the APEX in scene axes",               \
                              ",\"radius\":" S_LEN("m, base radius") ",\"height\":"       \
                              S_LEN("m") S_ORIENT_PROP, ",\"radius\",\"height\"")
#define S_HEMI     S_SHAPE_AT("hemisphere", "solid half ball, dome along body +z",      \
                              "m, centre of the flat face in scene axes",                 \
                              ",\"radius\":" S_LEN("m") S_ORIENT_PROP, ",\"radius\"")
#define S_TUBE     S_SHAPE("tube", "thick-walled cylinder, axis along body z",          \
                           ",\"inner_radius\":{\"type\":\"number\",\"minimum\":0,"        \
                           "\"maximum\":1e15,\"description\":\"m, < outer_radius\"}"      \
                           ",\"outer_radius\":" S_LEN("m") ",\"height\":" S_LEN("m")      \
                           S_ORIENT_PROP, ",\"inner_radius\",\"outer_radius\",\"height\"")
#define S_DISC     S_SHAPE("disc", "thin disc in the body xy plane",                    \
                           ",\"radius\":" S_LEN("m") S_ORIENT_PROP, ",\"radius\"")
#define S_RING     S_SHAPE("ring", "thin hoop in the body xy plane",                    \
                           ",\"radius\":" S_LEN("m") S_ORIENT_PROP, ",\"radius\"")
#define S_PLATE    S_SHAPE("plate", "thin rectangle in the body xy plane",              \
                           ",\"size\":" S_SIZE2 S_ORIENT_PROP, ",\"size\"")
#define S_TRIANGLE S_PART("triangle", "thin triangular plate given by its corners in "  \
                          "scene axes (no position or orientation)",                      \
                          ",\"vertices\":" S_CORNERS, ",\"vertices\"")
#define S_ELLIPSOID S_SHAPE("ellipsoid", "solid ellipsoid, semi-axes along body x, y, z", \
                            ",\"semi_axes\":" S_SEMI S_ORIENT_PROP, ",\"semi_axes\"")
#define S_TORUS    S_SHAPE("torus", "solid ring torus, axis along body z",              \
                           ",\"major_radius\":" S_LEN("m, centre of the tube")            \
                           ",\"minor_radius\":" S_LEN("m, radius of the tube, < major")   \
                           S_ORIENT_PROP, ",\"major_radius\",\"minor_radius\"")
#define S_MESH     S_PART("mesh", "closed, consistently oriented triangle mesh of "     \
                          "uniform density",                                              \
                          ",\"position\":" S_VEC3("m, where the vertices' origin sits in " \
                          "scene axes (default [0,0,0])") S_ORIENT_PROP                    \
                          ",\"vertices\":" S_MESH_VERTICES ",\"faces\":" S_MESH_FACES,     \
                          ",\"vertices\",\"faces\"")
#define S_POINT    S_SHAPE("point", "point mass", "", "")
#define S_TENSOR_ROW                                                                    \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"                       \
    "{\"type\":\"number\",\"minimum\":-1e60,\"maximum\":1e60}}"
#define S_TENSOR   S_SHAPE("tensor", "a part known by its mass, its own tensor about its " \
                           "centre of mass and that centre (position)",                   \
                           ",\"tensor\":{\"type\":\"array\",\"minItems\":3,"            \
                           "\"maxItems\":3,\"items\":" S_TENSOR_ROW ",\"description\":"    \
                           "\"kg m^2, about the part's centre of mass, in its body axes "  \
                           "(scene axes without orientation); symmetric\"}" S_ORIENT_PROP, \
                           ",\"tensor\"")

/* The point branch comes last: when a part fails two branches with the same
 * number of errors (a sphere missing its radius fails "sphere" by the missing
 * radius and "point" only by its shape), the validator reports the first, and
 * the part's own shape is the more helpful one. */
#define S_BODY                                                                          \
    "{\"oneOf\":[" S_ROD "," S_BOX "," S_SPHERE "," S_SHELL "," S_CYLINDER "," S_CONE    \
    "," S_HEMI "," S_TUBE "," S_DISC "," S_RING "," S_PLATE "," S_TRIANGLE ","           \
    S_ELLIPSOID "," S_TORUS "," S_MESH "," S_TENSOR "," S_POINT "]}"

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
    "Inertia tensor of a rigid body made of parts, each with a mass (kg) and, unless said "
    "otherwise, the position of its centre (m, scene axes). Shapes (body axes = the rows of "
    "the part's orientation; moments about the part's centre of mass): point; rod (length "
    "along body z: ML^2/12 across); box (size [a,b,c] along body x,y,z); sphere (solid, "
    "2MR^2/5); shell (thin spherical, 2MR^2/3); cylinder (solid, radius, height, axis body "
    "z: MR^2/2, M(3R^2+h^2)/12); cone (solid, radius, height; position is the APEX, the "
    "cone opens along body +z, centre of mass 3h/4 from the apex: 3MR^2/10 about the axis, "
    "3M(4R^2+h^2)/80 across); hemisphere (solid, radius; position is the centre of the flat "
    "face, dome along body +z, centre of mass 3R/8 up: 2MR^2/5 about the axis, 83MR^2/320 "
    "across); tube (inner_radius a < outer_radius b, height, axis body z: M(a^2+b^2)/2, "
    "M(3(a^2+b^2)+h^2)/12); disc (thin, radius, in the body xy plane: MR^2/2, MR^2/4); ring "
    "(thin hoop, radius, in the body xy plane: MR^2, MR^2/2); plate (thin rectangle, size "
    "[a,b] along body x,y: Mb^2/12, Ma^2/12, M(a^2+b^2)/12); triangle (thin plate, three "
    "vertices in SCENE axes, no position or orientation; collinear corners are refused at "
    "/bodies/i/vertices); ellipsoid (solid, semi_axes [a,b,c] along body x,y,z: "
    "M(b^2+c^2)/5, ...); torus (solid ring torus, major_radius R > minor_radius r, axis "
    "body z: M(R^2+3r^2/4) about the axis, M(R^2/2+5r^2/8) across); mesh (closed triangle "
    "mesh of uniform density: vertices [[x,y,z],...] in body axes, placed at scene point "
    "position + R^T v, position default [0,0,0] and no orientation meaning the vertices "
    "are scene coordinates; faces [[i,j,k],...] counter-clockwise seen from outside; every "
    "edge must join exactly two faces that run along it in opposite directions, else 422 "
    "at /bodies/i/faces saying which edge is open, shared by more faces or inconsistently "
    "oriented; a mesh oriented all inwards is accepted and reported as inverted; volume "
    "integrals by the divergence theorem over signed tetrahedra, in coordinates centred "
    "on the mesh; at most 100000 vertices and 200000 faces, three budget steps per face); "
    "tensor (a part known by its mass, its own tensor about its centre of mass, kg m^2, in "
    "its body axes, and position = that centre: the parallel-axis theorem on a tensor the "
    "user has; refused at /bodies/i/tensor when not symmetric within 1e-12 of its largest "
    "entry or when no mass distribution has it: a principal moment < 0 or larger than the "
    "sum of the other two). "
    "Any part may be \"hole\": true: it is removed material, entering every sum with "
    "negative mass; its mass is the mass its volume would have at the surrounding "
    "material's density (the caller's job), and the total mass must stay > 0. A part's "
    "orientation is the passive rotation R of the notes (scene components to body "
    "components; its rows are the body axes in scene axes), so the part contributes R^T "
    "I_body R; give it as exactly one of matrix, euler_zxz [phi, theta, psi] (z-x-z, R = "
    "R_psi R_theta R_phi), axis_angle {axis, angle} or quaternion [w,x,y,z] = [cos(a/2), "
    "sin(a/2) n]. Answers mass, center_of_mass, origin, tensor (kg m^2, about origin, "
    "default the centre of mass), tensor_center_of_mass, and principal: moments ascending, "
    "axes as unit rows (right-handed; rows 0 and 1 have their largest-magnitude component "
    "positive, row 2 = row 0 x row 1), degenerate = two moments agree within 1e-10 of the "
    "largest (then the axes are one orthonormal basis of the degenerate subspace: the scene "
    "axes if all three agree). With omega (rad/s, rotation about the origin held at rest): "
    "angular_momentum = I omega and kinetic_energy = omega.I.omega/2, angle_L_omega (rad, "
    "atan2(|omega x L|, omega.L); null when omega or L is zero) and torque_to_hold_axis = "
    "omega x L (N m: the torque that keeps the body turning steadily at omega about that "
    "axis, dL/dt of L carried round with the body). parts lists, per part "
    "in order, its shape, hole flag, mass (negative for a hole), center_of_mass (scene) "
    "and tensor about its own centre of mass in scene axes (negative for a hole), plus "
    "volume and inverted for a mesh: tensor_center_of_mass = sum over parts of tensor + "
    "mass (d^2 1 - d d^T), d = part centre of mass - center_of_mass. Precision: the "
    "tensor about the centre of mass is summed in centred coordinates and moved with the "
    "parallel-axis theorem, so bodies far from the scene origin keep full relative "
    "precision; principal moments are right to about 1e-15 of the largest.";

static const char example[] =
    "{\"bodies\":["
    "{\"shape\":\"box\",\"mass\":2,\"size\":[0.4,0.3,0.2],\"position\":[0,0,0],"
    "\"orientation\":{\"euler_zxz\":[0.5,0.3,0]}},"
    "{\"shape\":\"point\",\"mass\":0.5,\"position\":[0.3,0,0.1]},"
    "{\"shape\":\"cone\",\"mass\":0.3,\"radius\":0.05,\"height\":0.1,\"position\":[0,0,0.3]},"
    "{\"shape\":\"cylinder\",\"mass\":0.020944,\"radius\":0.02,\"height\":0.2,"
    "\"position\":[0,0,0],\"orientation\":{\"euler_zxz\":[0.5,0.3,0]},\"hole\":true}],"
    "\"origin\":\"center_of_mass\",\"omega\":[0,0,10]}";

/* ---- handler ----------------------------------------------------------------- */

static const char *const shape_names[MECH_SHAPE_COUNT] = {
    [MECH_SHAPE_POINT] = "point",       [MECH_SHAPE_ROD] = "rod",
    [MECH_SHAPE_BOX] = "box",           [MECH_SHAPE_SPHERE] = "sphere",
    [MECH_SHAPE_SHELL] = "shell",       [MECH_SHAPE_CYLINDER] = "cylinder",
    [MECH_SHAPE_CONE] = "cone",         [MECH_SHAPE_HEMISPHERE] = "hemisphere",
    [MECH_SHAPE_TUBE] = "tube",         [MECH_SHAPE_DISC] = "disc",
    [MECH_SHAPE_RING] = "ring",         [MECH_SHAPE_PLATE] = "plate",
    [MECH_SHAPE_TRIANGLE] = "triangle", [MECH_SHAPE_ELLIPSOID] = "ellipsoid",
    [MECH_SHAPE_TORUS] = "torus",       [MECH_SHAPE_MESH] = "mesh",
    [MECH_SHAPE_TENSOR] = "tensor",
};

/* Read body i's orientation (any form of api/rotation_request.h; passive by
 * default) into the passive matrix *r. Errors are recorded in c, naming the
 * field; the return value is then MECH_EINVAL. */
static enum mech_status read_orientation(struct api_call *c, const json_t *o, size_t i,
                                         struct mech_mat3 *r)
{
    char ptr[96];
    snprintf(ptr, sizeof ptr, "/bodies/%zu/orientation", i);
    struct api_rotation rot;
    if (api_rotation_read(c, o, ptr, MECH_ROTATION_PASSIVE, &rot) != 0) return MECH_EINVAL;
    api_rotation_set_sense(&rot, MECH_ROTATION_PASSIVE);
    *r = rot.matrix;
    return MECH_OK;
}

static void dims3(const json_t *b, const char *key, double *d)
{
    struct mech_vec3 v = api_vec3_member(b, key, mech_vec3_make(0, 0, 0));
    d[0] = v.x;
    d[1] = v.y;
    d[2] = v.z;
}

/* Read a mesh part's vertices and faces (schema-validated sizes and ranges)
 * into new arrays owned by p->mesh (freed by free_parts). */
static enum mech_status read_mesh(const json_t *b, struct mech_inertia_part *p,
                                  struct mech_error *e)
{
    const json_t *vj = json_object_get(b, "vertices"), *fj = json_object_get(b, "faces");
    size_t nv = json_array_size(vj), nf = json_array_size(fj);
    struct mech_vec3 *v = malloc((nv ? nv : 1) * sizeof *v);
    size_t *f = malloc((nf ? 3 * nf : 1) * sizeof *f);
    p->mesh.vertices = v;
    p->mesh.faces = f;
    if (!v || !f) return mech_error_set(e, MECH_ENOMEM, NULL, "out of memory for a mesh");
    for (size_t k = 0; k < nv; k++)
        v[k] = api_vec3_of(json_array_get(vj, k));
    for (size_t k = 0; k < nf; k++) {
        const json_t *t = json_array_get(fj, k);
        for (size_t q = 0; q < 3; q++)
            f[3 * k + q] = (size_t)json_number_value(json_array_get(t, q));
    }
    p->mesh.n_vertices = nv;
    p->mesh.n_faces = nf;
    return MECH_OK;
}

/* Parse bodies[i] into *p. Returns MECH_OK or a core status with e and prefix set. */
static enum mech_status read_part(struct api_call *c, const json_t *b, size_t i,
                                  struct mech_inertia_part *p,
                                  char *prefix, size_t np, struct mech_error *e)
{
    const char *shape = api_string(b, "shape", "");
    int s = -1;
    for (int k = 0; k < MECH_SHAPE_COUNT; k++)
        if (!strcmp(shape, shape_names[k])) s = k;
    snprintf(prefix, np, "/bodies/%zu", i);
    if (s < 0) return mech_error_set(e, MECH_EINVAL, "shape", "unknown shape \"%s\"", shape);
    p->shape = (enum mech_inertia_shape)s;
    p->mass = api_number(b, "mass", 0);
    p->hole = json_is_true(json_object_get(b, "hole"));
    p->position = api_vec3_member(b, "position", mech_vec3_make(0, 0, 0));
    p->orientation = mech_mat3_identity();
    switch (p->shape) {
    case MECH_SHAPE_ROD:
        p->dim[0] = api_number(b, "length", 0);
        break;
    case MECH_SHAPE_BOX:
        dims3(b, "size", p->dim);
        break;
    case MECH_SHAPE_SPHERE:
    case MECH_SHAPE_SHELL:
    case MECH_SHAPE_HEMISPHERE:
    case MECH_SHAPE_DISC:
    case MECH_SHAPE_RING:
        p->dim[0] = api_number(b, "radius", 0);
        break;
    case MECH_SHAPE_CYLINDER:
    case MECH_SHAPE_CONE:
        p->dim[0] = api_number(b, "radius", 0);
        p->dim[1] = api_number(b, "height", 0);
        break;
    case MECH_SHAPE_TUBE:
        p->dim[0] = api_number(b, "inner_radius", 0);
        p->dim[1] = api_number(b, "outer_radius", 0);
        p->dim[2] = api_number(b, "height", 0);
        break;
    case MECH_SHAPE_PLATE: {
        const json_t *sz = json_object_get(b, "size");
        p->dim[0] = json_number_value(json_array_get(sz, 0));
        p->dim[1] = json_number_value(json_array_get(sz, 1));
        break;
    }
    case MECH_SHAPE_ELLIPSOID:
        dims3(b, "semi_axes", p->dim);
        break;
    case MECH_SHAPE_TORUS:
        p->dim[0] = api_number(b, "major_radius", 0);
        p->dim[1] = api_number(b, "minor_radius", 0);
        break;
    case MECH_SHAPE_TRIANGLE: {
        const json_t *vj = json_object_get(b, "vertices");
        for (size_t k = 0; k < 3; k++)
            p->vertices[k] = api_vec3_of(json_array_get(vj, k));
        break;
    }
    case MECH_SHAPE_TENSOR: {
        const json_t *tj = json_object_get(b, "tensor");
        for (size_t r = 0; r < 3; r++)
            for (size_t q = 0; q < 3; q++)
                p->tensor.a[r][q] = json_number_value(json_array_get(json_array_get(tj, r), q));
        break;
    }
    case MECH_SHAPE_MESH: {
        enum mech_status st = read_mesh(b, p, e);
        if (st != MECH_OK) return st;
        break;
    }
    default:
        break;
    }
    const json_t *o = json_object_get(b, "orientation");
    if (o) return read_orientation(c, o, i, &p->orientation);
    return MECH_OK;
}

static void free_parts(struct mech_inertia_part *parts, size_t n)
{
    for (size_t i = 0; i < n && parts; i++) {
        free((void *)parts[i].mesh.vertices);
        free((void *)parts[i].mesh.faces);
    }
    free(parts);
}

static json_t *parts_json(struct api_call *c, const struct mech_inertia_part *parts,
                          const struct mech_inertia_part_props *pp, size_t n)
{
    json_t *arr = json_array();
    for (size_t i = 0; arr && i < n; i++) {
        json_t *o = json_object();
        if (!o || json_array_append_new(arr, o)) {
            json_decref(arr);
            return NULL;
        }
        json_object_set_new_nocheck(o, "shape", json_string(shape_names[parts[i].shape]));
        json_object_set_new_nocheck(o, "hole", json_boolean(parts[i].hole));
        json_object_set_new_nocheck(o, "mass", api_real(c, pp[i].mass));
        json_object_set_new_nocheck(o, "center_of_mass", api_vec3(c, pp[i].center_of_mass));
        json_object_set_new_nocheck(o, "tensor", api_mat3(c, pp[i].tensor));
        if (parts[i].shape == MECH_SHAPE_MESH) {
            json_object_set_new_nocheck(o, "volume", api_real(c, pp[i].volume));
            json_object_set_new_nocheck(o, "inverted", json_boolean(pp[i].inverted));
        }
    }
    return arr;
}

static json_t *inertia(struct api_call *c, const json_t *body)
{
    const json_t *bodies = json_object_get(body, "bodies");
    size_t n = json_array_size(bodies);
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_inertia_part *parts = calloc(n ? n : 1, sizeof *parts);
    struct mech_inertia_part_props *pp = calloc(n ? n : 1, sizeof *pp);
    if (!parts || !pp) {
        free(parts);
        free(pp);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for %zu parts", n);
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    for (size_t i = 0; i < n; i++) {
        char prefix[96];
        enum mech_status st =
            read_part(c, json_array_get(bodies, i), i, &parts[i], prefix, sizeof prefix, &e);
        if (st != MECH_OK) {
            free_parts(parts, n);
            free(pp);
            /* an orientation error is already recorded in c, naming its field */
            return c->problem != API_PROBLEM_NONE ? NULL : api_call_fail_core(c, st, &e, prefix);
        }
    }
    const json_t *oj = json_object_get(body, "origin");
    struct mech_vec3 origin;
    int have_origin = oj && json_is_array(oj);
    if (have_origin) origin = api_vec3_of(oj);

    struct mech_inertia res;
    enum mech_status st = mech_inertia_compute_parts(parts, n, have_origin ? &origin : NULL,
                                                     &c->budget, &res, pp, &e);
    if (st != MECH_OK) {
        free_parts(parts, n);
        free(pp);
        return api_call_fail_core(c, st, &e, "");
    }

    const json_t *wj = json_object_get(body, "omega");
    struct mech_vec3 l = {0, 0, 0};
    double ke = 0;
    if (wj) st = mech_inertia_spin(res.tensor, api_vec3_of(wj), &l, &ke, &e);
    json_t *out = st == MECH_OK ? json_object() : NULL;
    json_t *pr = st == MECH_OK ? json_object() : NULL;
    json_t *pj = st == MECH_OK ? parts_json(c, parts, pp, n) : NULL;
    free_parts(parts, n);
    free(pp);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    if (!out || !pr || !pj) {
        json_decref(out);
        json_decref(pr);
        json_decref(pj);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    json_object_set_new_nocheck(out, "mass", api_real(c, res.mass));
    json_object_set_new_nocheck(out, "center_of_mass", api_vec3(c, res.center_of_mass));
    json_object_set_new_nocheck(out, "origin", api_vec3(c, res.origin));
    json_object_set_new_nocheck(out, "tensor", api_mat3(c, res.tensor));
    json_object_set_new_nocheck(out, "tensor_center_of_mass", api_mat3(c, res.tensor_cm));
    json_object_set_new_nocheck(pr, "moments", api_reals(c, res.principal.moments, 3));
    json_object_set_new_nocheck(pr, "axes", api_mat3(c, res.principal.axes));
    json_object_set_new_nocheck(pr, "degenerate", json_boolean(res.principal.degenerate));
    json_object_set_new_nocheck(out, "principal", pr);
    if (wj) {
        json_object_set_new_nocheck(out, "angular_momentum", api_vec3(c, l));
        json_object_set_new_nocheck(out, "kinetic_energy", api_real(c, ke));
        /* angle between L and omega (atan2, core/vector_algebra.c) and omega x L */
        struct mech_vector_pair vp;
        struct mech_error e2;
        mech_error_clear(&e2);
        int ok = mech_vector_pair(api_vec3_of(wj), l, &vp, &e2) == MECH_OK;
        json_object_set_new_nocheck(out, "angle_L_omega",
                                    ok && vp.has_angle ? api_real(c, vp.angle) : json_null());
        json_object_set_new_nocheck(out, "torque_to_hold_axis",
                                    ok ? api_vec3(c, vp.cross) : json_null());
    }
    json_object_set_new_nocheck(out, "parts", pj);
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
    1, /* quick */
};
