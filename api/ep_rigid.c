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

json_t *api_op_rigid_inertia(struct api_call *c, const json_t *body)
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

