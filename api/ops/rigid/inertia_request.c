/* inertia_request.c — a POST /v1/rigid/inertia request body read into core's
 * parts (simple shapes, holes, triangle meshes, tensors; orientations in any
 * form of api/request/rotation_request.h) and computed by core/rigid/inertia.c. Shared
 * by /v1/rigid/inertia and /v1/rigid/rotate, so no operation calls another
 * through JSON. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ops/rigid/inertia_request.h"
#include "request/rotation_request.h"
#include "mech/rotation/rotation.h"

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

/* Read body i's orientation (any form of api/request/rotation_request.h; passive by
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
    const char *shape = api_string_of(b, "shape");
    int s = -1;
    for (int k = 0; k < MECH_SHAPE_COUNT; k++)
        if (!strcmp(shape, shape_names[k])) s = k;
    snprintf(prefix, np, "/bodies/%zu", i);
    if (s < 0) return mech_error_set(e, MECH_EINVAL, "shape", "unknown shape \"%s\"", shape);
    p->shape = (enum mech_inertia_shape)s;
    p->mass = api_number_of(b, "mass");
    p->hole = json_is_true(json_object_get(b, "hole"));
    p->position = api_vec3_member(b, "position", mech_vec3_make(0, 0, 0));
    p->orientation = mech_mat3_identity();
    switch (p->shape) {
    case MECH_SHAPE_ROD:
        p->dim[0] = api_number_of(b, "length");
        break;
    case MECH_SHAPE_BOX:
        dims3(b, "size", p->dim);
        break;
    case MECH_SHAPE_SPHERE:
    case MECH_SHAPE_SHELL:
    case MECH_SHAPE_HEMISPHERE:
    case MECH_SHAPE_DISC:
    case MECH_SHAPE_RING:
        p->dim[0] = api_number_of(b, "radius");
        break;
    case MECH_SHAPE_CYLINDER:
    case MECH_SHAPE_CONE:
        p->dim[0] = api_number_of(b, "radius");
        p->dim[1] = api_number_of(b, "height");
        break;
    case MECH_SHAPE_TUBE:
        p->dim[0] = api_number_of(b, "inner_radius");
        p->dim[1] = api_number_of(b, "outer_radius");
        p->dim[2] = api_number_of(b, "height");
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
        p->dim[0] = api_number_of(b, "major_radius");
        p->dim[1] = api_number_of(b, "minor_radius");
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

const char *api_inertia_shape_name(enum mech_inertia_shape s)
{
    return (int)s >= 0 && s < MECH_SHAPE_COUNT && shape_names[s] ? shape_names[s] : "";
}

void api_inertia_body_free(struct api_inertia_body *b)
{
    if (!b) return;
    free_parts(b->parts, b->n);
    free(b->props);
    b->parts = NULL;
    b->props = NULL;
    b->n = 0;
}

int api_inertia_body_compute(struct api_call *c, const json_t *body,
                             struct api_inertia_body *out)
{
    memset(out, 0, sizeof *out);
    const json_t *bodies = json_object_get(body, "bodies");
    size_t n = json_array_size(bodies);
    struct mech_error e;
    mech_error_clear(&e);
    out->parts = calloc(n ? n : 1, sizeof *out->parts);
    out->props = calloc(n ? n : 1, sizeof *out->props);
    if (!out->parts || !out->props) {
        api_inertia_body_free(out);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for %zu parts", n);
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        return 0;
    }
    out->n = n;
    for (size_t i = 0; i < n; i++) {
        char prefix[96];
        enum mech_status st =
            read_part(c, json_array_get(bodies, i), i, &out->parts[i], prefix, sizeof prefix, &e);
        if (st != MECH_OK) {
            /* an orientation error is already recorded in c, naming its field */
            if (c->problem == API_PROBLEM_NONE) api_call_fail_core(c, st, &e, prefix);
            return 0;
        }
    }
    const json_t *oj = json_object_get(body, "origin");
    struct mech_vec3 origin;
    int have_origin = oj && json_is_array(oj);
    if (have_origin) origin = api_vec3_of(oj);
    enum mech_status st = mech_inertia_compute_parts(out->parts, n, have_origin ? &origin : NULL,
                                                     &c->budget, &out->result, out->props, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        return 0;
    }
    const json_t *wj = json_object_get(body, "omega");
    if (!wj) return 1;
    out->has_omega = 1;
    out->omega = api_vec3_of(wj);
    st = mech_inertia_spin(out->result.tensor, out->omega, &out->angular_momentum,
                           &out->kinetic_energy, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        return 0;
    }
    /* angle between L and omega (atan2, core/rotation/vector_algebra.c) and omega x L;
     * when the pair cannot be formed the answer says null, not an error */
    struct mech_error e2;
    mech_error_clear(&e2);
    out->has_pair = mech_vector_pair(out->omega, out->angular_momentum, &out->pair, &e2) == MECH_OK;
    return 1;
}

static int mat3_finite(const struct mech_mat3 *m)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!isfinite(m->a[i][j])) return 0;
    return 1;
}

static int vec3_finite(struct mech_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

int api_inertia_body_finite(const struct api_inertia_body *b)
{
    const struct mech_inertia *r = &b->result;
    if (!isfinite(r->mass) || !vec3_finite(r->center_of_mass) || !vec3_finite(r->origin) ||
        !mat3_finite(&r->tensor) || !mat3_finite(&r->tensor_cm) ||
        !mat3_finite(&r->principal.axes))
        return 0;
    for (int k = 0; k < 3; k++)
        if (!isfinite(r->principal.moments[k])) return 0;
    for (size_t i = 0; i < b->n; i++) {
        const struct mech_inertia_part_props *p = &b->props[i];
        if (!isfinite(p->mass) || !vec3_finite(p->center_of_mass) || !mat3_finite(&p->tensor))
            return 0;
        if (b->parts[i].shape == MECH_SHAPE_MESH && !isfinite(p->volume)) return 0;
    }
    if (b->has_omega) {
        if (!vec3_finite(b->angular_momentum) || !isfinite(b->kinetic_energy)) return 0;
        if (b->has_pair && b->pair.has_angle && !isfinite(b->pair.angle)) return 0;
        if (b->has_pair && !vec3_finite(b->pair.cross)) return 0;
    }
    return 1;
}
