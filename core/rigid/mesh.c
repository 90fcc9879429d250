/* mesh.c — mass properties of a closed triangle mesh by the divergence theorem
 * (signed tetrahedra; Tonon 2005, Eberly 2002). See mech/rigid/mesh.h. */
#include "mech/rigid/mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* One directed edge of one face, stored by its undirected key (lo < hi). */
struct edge {
    size_t lo, hi; /* vertex indices, lo < hi */
    size_t face;   /* face index */
    int fwd;       /* 1 if the face traverses lo -> hi, 0 if hi -> lo */
};

/* Total order (lo, hi, fwd, face): equal keys group together, and the order
 * inside a group does not depend on qsort's instability (deterministic errors). */
static int edge_cmp(const void *pa, const void *pb)
{
    const struct edge *a = pa, *b = pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    if (a->fwd != b->fwd) return a->fwd < b->fwd ? -1 : 1;
    if (a->face != b->face) return a->face < b->face ? -1 : 1;
    return 0;
}

static enum mech_status step(const struct mech_budget *budget, long *steps, struct mech_error *err)
{
    return mech_budget_check(budget, ++*steps, 0, err);
}

/* Edge-manifold, closed, consistently oriented: every undirected edge used by
 * exactly two faces, once in each direction. e[0..ne) sorted. */
static enum mech_status check_edges(const struct edge *e, size_t ne, struct mech_error *err)
{
    size_t i = 0;
    while (i < ne) {
        size_t j = i, nfwd = 0;
        while (j < ne && e[j].lo == e[i].lo && e[j].hi == e[i].hi) {
            nfwd += (size_t)e[j].fwd;
            j++;
        }
        size_t count = j - i;
        if (count == 1)
            return mech_error_set(err, MECH_EINVAL, "faces",
                                  "the mesh is not closed: edge (%zu, %zu) of face %zu belongs to "
                                  "no other face",
                                  e[i].lo, e[i].hi, e[i].face);
        if (count > 2)
            return mech_error_set(err, MECH_EINVAL, "faces",
                                  "the mesh is not manifold: edge (%zu, %zu) is shared by %zu "
                                  "faces (%zu, %zu, %zu, ...); each edge must join exactly two",
                                  e[i].lo, e[i].hi, count, e[i].face, e[i + 1].face, e[i + 2].face);
        if (nfwd != 1)
            return mech_error_set(err, MECH_EINVAL, "faces",
                                  "inconsistent orientation: faces %zu and %zu both traverse edge "
                                  "(%zu -> %zu) the same way (is one of them flipped?)",
                                  e[i].face, e[i + 1].face, e[i].fwd ? e[i].lo : e[i].hi,
                                  e[i].fwd ? e[i].hi : e[i].lo);
        i = j;
    }
    return MECH_OK;
}

static void add_outer(double s[3][3], double w, const double *u)
{
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++)
            s[i][j] += w * u[i] * u[j];
}

enum mech_status mech_mesh_properties(const struct mech_mesh *mesh,
                                      const struct mech_budget *budget, long *steps,
                                      struct mech_mesh_properties *out, struct mech_error *err)
{
    long own = 0;
    if (!steps) steps = &own;
    if (!mesh || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no mesh or output given");
    enum mech_status st = mech_budget_check(budget, *steps, 1, err);
    if (st != MECH_OK) return st;
    const size_t nv = mesh->n_vertices, nf = mesh->n_faces;
    if (!mesh->vertices || nv < 4 || nv > MECH_MESH_MAX_VERTICES)
        return mech_error_set(err, MECH_EINVAL, "vertices",
                              "a closed mesh needs 4 to %d vertices, got %zu",
                              MECH_MESH_MAX_VERTICES, nv);
    if (!mesh->faces || nf < 4 || nf > MECH_MESH_MAX_FACES)
        return mech_error_set(err, MECH_EINVAL, "faces",
                              "a closed mesh needs 4 to %d faces, got %zu", MECH_MESH_MAX_FACES,
                              nf);
    const struct mech_vec3 *v = mesh->vertices;
    const size_t *f = mesh->faces;

    /* Pass 0: indices, finiteness, bounding box, directed edges. */
    struct edge *e = malloc(3 * nf * sizeof *e);
    if (!e) return mech_error_set(err, MECH_ENOMEM, NULL, "edge list of %zu faces", nf);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t k = 0; k < nf; k++) {
        if ((st = step(budget, steps, err)) != MECH_OK) goto out;
        char param[40];
        const size_t *t = f + 3 * k;
        for (int q = 0; q < 3; q++) {
            if (t[q] >= nv) {
                snprintf(param, sizeof param, "faces/%zu", k);
                st = mech_error_set(err, MECH_EINVAL, param,
                                    "vertex index %zu out of range (the mesh has %zu vertices)",
                                    t[q], nv);
                goto out;
            }
            struct mech_vec3 p = v[t[q]];
            if (!mech_vec3_isfinite(p)) {
                st = mech_error_set(err, MECH_EINVAL, "vertices", "vertex %zu is not finite", t[q]);
                goto out;
            }
            double c[3] = {p.x, p.y, p.z};
            for (int a = 0; a < 3; a++) {
                lo[a] = fmin(lo[a], c[a]);
                hi[a] = fmax(hi[a], c[a]);
            }
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            snprintf(param, sizeof param, "faces/%zu", k);
            st = mech_error_set(err, MECH_EINVAL, param, "face %zu repeats a vertex", k);
            goto out;
        }
        for (int q = 0; q < 3; q++) {
            size_t a = t[q], b = t[(q + 1) % 3];
            struct edge *d = &e[3 * k + (size_t)q];
            d->lo = a < b ? a : b;
            d->hi = a < b ? b : a;
            d->face = k;
            d->fwd = a < b;
        }
    }
    qsort(e, 3 * nf, sizeof *e, edge_cmp);
    st = check_edges(e, 3 * nf, err);
out:
    free(e);
    if (st != MECH_OK) return st;

    /* Pass 1: volume and centroid relative to the bounding-box centre b. Each
     * face (p, q, r) with the reference point spans a tetrahedron of signed
     * volume det/6, det = p.(q x r), and first moment det (p + q + r)/24. */
    const struct mech_vec3 b = mech_vec3_make(0.5 * lo[0] + 0.5 * hi[0], 0.5 * lo[1] + 0.5 * hi[1],
                                              0.5 * lo[2] + 0.5 * hi[2]);
    double v6 = 0, absv6 = 0;
    struct mech_vec3 m24 = {0, 0, 0};
    for (size_t k = 0; k < nf; k++) {
        if ((st = step(budget, steps, err)) != MECH_OK) return st;
        const size_t *t = f + 3 * k;
        struct mech_vec3 p = mech_vec3_sub(v[t[0]], b), q = mech_vec3_sub(v[t[1]], b),
                         r = mech_vec3_sub(v[t[2]], b);
        double det = mech_vec3_dot(p, mech_vec3_cross(q, r));
        v6 += det;
        absv6 += fabs(det);
        m24 = mech_vec3_add(m24, mech_vec3_scale(mech_vec3_add(p, mech_vec3_add(q, r)), det));
    }
    if (!isfinite(v6) || !isfinite(absv6) || !mech_vec3_isfinite(m24))
        return mech_error_set(err, MECH_ENUMERIC, "vertices", "the volume integrals overflow");
    if (!(absv6 > 0) || fabs(v6) <= 1e-12 * absv6)
        return mech_error_set(err, MECH_EINVAL, "faces",
                              "the mesh encloses no volume (signed volume %.3g m^3 against "
                              "%.3g m^3 of tetrahedra)",
                              v6 / 6, absv6 / 6);
    struct mech_vec3 cr = mech_vec3_scale(m24, 1.0 / (4.0 * v6)); /* centroid - b */

    /* Pass 2: second moments about c = b + cr, each vertex as (v - b) - cr.
     * Tetrahedron (0, p, q, r): integral of x x^T = det/120 (p p^T + q q^T +
     * r r^T + s s^T), s = p + q + r (Tonon 2005, eq. for a vertex at the origin).
     * The residual first moment about c (round-off of cr) is removed at the end. */
    double s2[3][3] = {{0}};
    struct mech_vec3 m24c = {0, 0, 0};
    double v6c = 0;
    for (size_t k = 0; k < nf; k++) {
        if ((st = step(budget, steps, err)) != MECH_OK) return st;
        const size_t *t = f + 3 * k;
        struct mech_vec3 p = mech_vec3_sub(mech_vec3_sub(v[t[0]], b), cr);
        struct mech_vec3 q = mech_vec3_sub(mech_vec3_sub(v[t[1]], b), cr);
        struct mech_vec3 r = mech_vec3_sub(mech_vec3_sub(v[t[2]], b), cr);
        struct mech_vec3 s = mech_vec3_add(p, mech_vec3_add(q, r));
        double det = mech_vec3_dot(p, mech_vec3_cross(q, r));
        double pa[3] = {p.x, p.y, p.z}, qa[3] = {q.x, q.y, q.z}, ra[3] = {r.x, r.y, r.z},
               sa[3] = {s.x, s.y, s.z};
        add_outer(s2, det, pa);
        add_outer(s2, det, qa);
        add_outer(s2, det, ra);
        add_outer(s2, det, sa);
        v6c += det;
        m24c = mech_vec3_add(m24c, mech_vec3_scale(s, det));
    }
    /* covariance about c: S/120 - m1 m1^T / V with m1 = m24c/24, V = v6c/6 */
    double m1[3] = {m24c.x / 24.0, m24c.y / 24.0, m24c.z / 24.0};
    double vol = v6c / 6.0;
    double sign = vol < 0 ? -1.0 : 1.0;
    struct mech_mesh_properties res;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++)
            res.covariance.a[i][j] = res.covariance.a[j][i] =
                sign * (s2[i][j] / 120.0 - m1[i] * m1[j] / vol);
    res.volume = fabs(vol);
    res.centroid = mech_vec3_add(
        b, mech_vec3_add(cr, mech_vec3_scale(mech_vec3_make(m1[0], m1[1], m1[2]), 1.0 / vol)));
    res.inverted = vol < 0;
    if (!isfinite(res.volume) || !mech_vec3_isfinite(res.centroid) ||
        !mech_mat3_isfinite(res.covariance))
        return mech_error_set(err, MECH_ENUMERIC, "vertices", "the volume integrals overflow");
    *out = res;
    return MECH_OK;
}
