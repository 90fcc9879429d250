/* test_mesh.c — mech/rigid/mesh.h and the "mesh" part of mech/rigid/inertia.h.
 *
 * Meshes are generated here: a box (12 triangles) and solids of revolution
 * (a profile polygon in the (rho, z) half-plane turned through N segments):
 * cone, cylinder, tube, hemisphere, sphere (-> ellipsoid by scaling) and torus.
 *
 * Independent references:
 *  - A box mesh IS the box: mass properties to round-off.
 *  - A solid of revolution of a straight-sided profile (cone, cylinder, tube) or
 *    of a regular polygon (the torus's section) faceted with N segments is,
 *    slice by slice, a regular N-gon (or N-gon ring) of circumradius rho(z)
 *    instead of a disc (the side quads are planar trapezoids, so the triangles
 *    are exact). A regular N-gon of circumradius rho has area
 *    (N/2) rho^2 sin(D) and second moment int x^2 dA = (A rho^2/12)(2 + cos D),
 *    D = 2 pi/N, against pi rho^2 and A rho^2/4 for the disc. So, for a fixed
 *    mass, the faceted solid's tensor about its centroid has its "across the
 *    axis" part M<x^2> multiplied by exactly (2 + cos D)/3 and its <z^2> part
 *    unchanged: closed forms of the faceted solids, checked to round-off.
 *  - Against the smooth closed forms the error is O(1/N^2) (-(D^2)/6 relative):
 *    errors must fall by 4 each time N doubles; with one Richardson step
 *    (4 Q(2N) - Q(N))/3 the curved shapes reach 1e-6 within the face limit.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/rigid/inertia.h"
#include "mech/base/constants.h"
#include "mech/rigid/mesh.h"
#include "mech/rotation/rotation.h"
#include "testlib.h"

/* ---- mesh generators ----------------------------------------------------- */

struct gen {
    struct mech_vec3 *v;
    size_t nv, capv;
    size_t *f;
    size_t nf, capf;
};

static size_t addv(struct gen *g, double x, double y, double z)
{
    if (g->nv == g->capv) {
        g->capv = g->capv ? 2 * g->capv : 64;
        g->v = realloc(g->v, g->capv * sizeof *g->v);
    }
    g->v[g->nv] = mech_vec3_make(x, y, z);
    return g->nv++;
}

static void addf(struct gen *g, size_t a, size_t b, size_t c)
{
    if (g->nf == g->capf) {
        g->capf = g->capf ? 2 * g->capf : 64;
        g->f = realloc(g->f, 3 * g->capf * sizeof *g->f);
    }
    g->f[3 * g->nf] = a;
    g->f[3 * g->nf + 1] = b;
    g->f[3 * g->nf + 2] = c;
    g->nf++;
}

static void gen_free(struct gen *g)
{
    free(g->v);
    free(g->f);
    memset(g, 0, sizeof *g);
}

static struct mech_mesh as_mesh(const struct gen *g)
{
    struct mech_mesh m = {g->v, g->nv, g->f, g->nf};
    return m;
}

/* Box with edges a, b, c along x, y, z centred at c0; faces counter-clockwise
 * seen from outside. */
static void gen_box(struct gen *g, double a, double b, double c, struct mech_vec3 c0)
{
    for (int k = 0; k < 8; k++)
        addv(g, c0.x + (k & 1 ? a / 2 : -a / 2), c0.y + (k & 2 ? b / 2 : -b / 2),
             c0.z + (k & 4 ? c / 2 : -c / 2));
    /* quads (outward, CCW): -z 0 2 3 1; +z 4 5 7 6; -y 0 1 5 4; +y 2 6 7 3; -x 0 4 6 2; +x 1 3 7 5
     */
    static const size_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int k = 0; k < 6; k++) {
        addf(g, q[k][0], q[k][1], q[k][2]);
        addf(g, q[k][0], q[k][2], q[k][3]);
    }
}

/* Solid of revolution about z: profile points (rho[k], z[k]), k < np, running
 * counter-clockwise in the (rho, z) plane (interior on the left), turned through
 * n segments. closed = 0: the first and last points are on the axis (poles);
 * closed = 1: the profile is a loop away from the axis (tube, torus). */
static void gen_revolve(struct gen *g, const double *rho, const double *z, size_t np, int closed,
                        size_t n)
{
    size_t first = closed ? 0 : 1, last = closed ? np - 1 : np - 2; /* ring profile indices */
    size_t p0 = 0, p1 = 0;
    if (!closed) {
        p0 = addv(g, 0, 0, z[0]);
        p1 = addv(g, 0, 0, z[np - 1]);
    }
    size_t base = g->nv;
    for (size_t k = first; k <= last; k++)
        for (size_t i = 0; i < n; i++) {
            double u = 2 * MECH_PI * (double)i / (double)n;
            addv(g, rho[k] * cos(u), rho[k] * sin(u), z[k]);
        }
#define RING(k, i) (base + ((k)-first) * n + ((i) % n))
    for (size_t i = 0; i < n; i++) {
        if (!closed) addf(g, p0, RING(first, i + 1), RING(first, i));
        size_t kend = closed ? last + 1 : last;
        for (size_t k = first; k < kend; k++) {
            size_t k2 = (closed && k == last) ? first : k + 1;
            size_t a = RING(k, i), b = RING(k, i + 1), c = RING(k2, i + 1), d = RING(k2, i);
            addf(g, a, b, c);
            addf(g, a, c, d);
        }
        if (!closed) addf(g, RING(last, i), RING(last, i + 1), p1);
    }
#undef RING
}

static void gen_cone(struct gen *g, double r, double h, size_t n) /* apex at 0, opens +z */
{
    double rho[3] = {0, r, 0}, z[3] = {0, h, h};
    gen_revolve(g, rho, z, 3, 0, n);
}

static void gen_tube(struct gen *g, double a, double b, double h, size_t n) /* a = 0: cylinder */
{
    if (a == 0) {
        double rho[4] = {0, b, b, 0}, z[4] = {-h / 2, -h / 2, h / 2, h / 2};
        gen_revolve(g, rho, z, 4, 0, n);
    } else {
        double rho[4] = {a, b, b, a}, z[4] = {-h / 2, -h / 2, h / 2, h / 2};
        gen_revolve(g, rho, z, 4, 1, n);
    }
}

/* arc of radius r from angle t0 to t1 in k segments, appended to rho/z from index at */
static size_t arc(double *rho, double *z, size_t at, double r, double t0, double t1, size_t k)
{
    for (size_t j = 0; j <= k; j++) {
        double t = t0 + (t1 - t0) * (double)j / (double)k;
        rho[at + j] = r * cos(t);
        z[at + j] = r * sin(t);
    }
    return at + k + 1;
}

static void gen_hemisphere(struct gen *g, double r, size_t n, size_t k) /* flat face at z = 0 */
{
    double *rho = malloc((k + 2) * sizeof *rho), *z = malloc((k + 2) * sizeof *z);
    rho[0] = 0;
    z[0] = 0;
    arc(rho, z, 1, r, 0, MECH_PI / 2, k);
    rho[k + 1] = 0; /* the pole exactly on the axis */
    gen_revolve(g, rho, z, k + 2, 0, n);
    free(rho);
    free(z);
}

static void gen_sphere(struct gen *g, double r, size_t n, size_t k)
{
    double *rho = malloc((k + 1) * sizeof *rho), *z = malloc((k + 1) * sizeof *z);
    arc(rho, z, 0, r, -MECH_PI / 2, MECH_PI / 2, k);
    rho[0] = rho[k] = 0;
    gen_revolve(g, rho, z, k + 1, 0, n);
    free(rho);
    free(z);
}

static void gen_torus(struct gen *g, double big, double r, size_t n, size_t m)
{
    double *rho = malloc(m * sizeof *rho), *z = malloc(m * sizeof *z);
    for (size_t j = 0; j < m; j++) {
        double v = 2 * MECH_PI * (double)j / (double)m;
        rho[j] = big + r * cos(v);
        z[j] = r * sin(v);
    }
    gen_revolve(g, rho, z, m, 1, n);
    free(rho);
    free(z);
}

/* ---- helpers --------------------------------------------------------------- */

static struct mech_budget budget(void)
{
    return mech_budget_make(100000000, 60.0);
}

static struct mech_mat3 diag(double a, double b, double c)
{
    struct mech_mat3 m = {{{a, 0, 0}, {0, b, 0}, {0, 0, c}}};
    return m;
}

static double mat_max(struct mech_mat3 a)
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(a.a[i][j]));
    return d;
}

/* max |a - b| / max |b| */
static double rel_diff(struct mech_mat3 a, struct mech_mat3 b)
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(a.a[i][j] - b.a[i][j]));
    return d / mat_max(b);
}

static struct mech_mat3 richardson(struct mech_mat3 coarse, struct mech_mat3 fine)
{
    struct mech_mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.a[i][j] = (4 * fine.a[i][j] - coarse.a[i][j]) / 3;
    return r;
}

static struct mech_inertia_part part(enum mech_inertia_shape s, double m, struct mech_vec3 pos,
                                     double d0, double d1, double d2)
{
    struct mech_inertia_part p;
    memset(&p, 0, sizeof p);
    p.shape = s;
    p.mass = m;
    p.position = pos;
    p.orientation = mech_mat3_identity();
    p.dim[0] = d0;
    p.dim[1] = d1;
    p.dim[2] = d2;
    return p;
}

static struct mech_inertia_part mesh_part(const struct gen *g, double m, struct mech_vec3 pos,
                                          struct mech_mat3 r)
{
    struct mech_inertia_part p = part(MECH_SHAPE_MESH, m, pos, 0, 0, 0);
    p.orientation = r;
    p.mesh = as_mesh(g);
    return p;
}

/* Single part through mech_inertia_compute; returns 1 on success. */
static int solve(const struct mech_inertia_part *p, struct mech_inertia *out)
{
    struct mech_budget b = budget();
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_inertia_compute(p, 1, NULL, &b, out, &e);
    if (st != MECH_OK) fprintf(stderr, "compute failed: %s: %s\n", e.param, e.text);
    CHECK(st == MECH_OK);
    return st == MECH_OK;
}

/* Tensor about the centroid of a mesh of mass m (identity placement), or NaNs. */
static struct mech_mat3 mesh_tensor(const struct gen *g, double m, struct mech_vec3 *com)
{
    struct mech_inertia res;
    struct mech_inertia_part p = mesh_part(g, m, mech_vec3_make(0, 0, 0), mech_mat3_identity());
    if (!solve(&p, &res)) return diag(NAN, NAN, NAN);
    if (com) *com = res.center_of_mass;
    return res.tensor_cm;
}

static enum mech_status props(const struct gen *g, struct mech_mesh_properties *out,
                              struct mech_error *e)
{
    struct mech_budget b = budget();
    struct mech_mesh m = as_mesh(g);
    mech_error_clear(e);
    return mech_mesh_properties(&m, &b, NULL, out, e);
}

/* A convergence study of a smooth shape against its closed form `want`:
 * meshes at resolutions n, 2n, 4n, 8n (built by make(g, n)), errors must fall by
 * 4 +- 10 % per doubling (O(1/N^2)), and one Richardson step from the two
 * finest must be within `rich_tol`. Prints the figures. */
static void converge(const char *name, void (*make)(struct gen *, size_t), size_t n0, double m,
                     struct mech_mat3 want, struct mech_vec3 com_want, double com_scale,
                     double rich_tol)
{
    struct mech_mat3 t[4];
    double err[4];
    size_t faces = 0;
    for (int l = 0; l < 4; l++) {
        struct gen g = {0};
        make(&g, n0 << l);
        faces = g.nf;
        struct mech_vec3 com;
        t[l] = mesh_tensor(&g, m, &com);
        err[l] = rel_diff(t[l], want);
        /* the centroid of these symmetric meshes is exact up to the profile's own error */
        if (l == 3) CHECK(mech_vec3_norm(mech_vec3_sub(com, com_want)) <= 1e-3 * com_scale);
        gen_free(&g);
    }
    double rich = rel_diff(richardson(t[2], t[3]), want);
    printf("%-10s rel. error N=%zu..%zu: %.3g %.3g %.3g %.3g (ratios %.3f %.3f %.3f); "
           "Richardson %.3g; %zu faces\n",
           name, n0, n0 << 3, err[0], err[1], err[2], err[3], err[0] / err[1], err[1] / err[2],
           err[2] / err[3], rich, faces);
    for (int l = 0; l < 3; l++) {
        double ratio = err[l] / err[l + 1];
        CHECK(ratio > 3.6 && ratio < 4.4);
    }
    CHECK(rich <= rich_tol);
}

static double g_cone_r = 0.5, g_cone_h = 1.7;
static void make_cone(struct gen *g, size_t n)
{
    gen_cone(g, g_cone_r, g_cone_h, n);
}
static double g_hemi_r = 0.8;
static void make_hemi(struct gen *g, size_t n)
{
    gen_hemisphere(g, g_hemi_r, n, n / 4);
}
static double g_tor_big = 1.0, g_tor_r = 0.35;
static void make_torus(struct gen *g, size_t n)
{
    gen_torus(g, g_tor_big, g_tor_r, n, n / 2);
}
static double g_ell[3] = {0.6, 1.1, 1.9};
static void make_ellipsoid(struct gen *g, size_t n)
{
    gen_sphere(g, 1.0, n, n / 2);
    for (size_t k = 0; k < g->nv; k++) {
        g->v[k].x *= g_ell[0];
        g->v[k].y *= g_ell[1];
        g->v[k].z *= g_ell[2];
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_inertia res;
    struct mech_mesh_properties mp;
    struct mech_error e;
    const struct mech_vec3 zero = {0, 0, 0};

    /* 1. A box mesh is the box: volume, centroid, covariance V diag(a^2, b^2, c^2)/12,
     * and through mech_inertia the same tensor as the "box" shape, to round-off. */
    {
        double a = 0.4, b = 1.1, c = 2.3, M = 3.7;
        struct mech_vec3 c0 = mech_vec3_make(0.3, -0.2, 0.7);
        struct gen g = {0};
        gen_box(&g, a, b, c, c0);
        CHECK(props(&g, &mp, &e) == MECH_OK);
        double v = a * b * c;
        CHECK_CLOSE(mp.volume, v, 1e-15, 0);
        CHECK(mech_vec3_norm(mech_vec3_sub(mp.centroid, c0)) <= 1e-15);
        CHECK(rel_diff(mp.covariance, diag(v * a * a / 12, v * b * b / 12, v * c * c / 12)) <=
              1e-15);
        CHECK(mp.inverted == 0);
        struct mech_vec3 com;
        struct mech_mat3 t = mesh_tensor(&g, M, &com);
        struct mech_mat3 want =
            diag(M * (b * b + c * c) / 12, M * (a * a + c * c) / 12, M * (a * a + b * b) / 12);
        printf("box mesh: tensor rel. error %.3g\n", rel_diff(t, want));
        CHECK(rel_diff(t, want) <= 1e-15);
        CHECK(mech_vec3_norm(mech_vec3_sub(com, c0)) <= 1e-15);

        /* inside out: every face reversed -> same answer, flagged */
        for (size_t k = 0; k < g.nf; k++) {
            size_t tmp = g.f[3 * k + 1];
            g.f[3 * k + 1] = g.f[3 * k + 2];
            g.f[3 * k + 2] = tmp;
        }
        CHECK(props(&g, &mp, &e) == MECH_OK);
        CHECK(mp.inverted == 1);
        CHECK_CLOSE(mp.volume, v, 1e-15, 0);
        CHECK(rel_diff(mp.covariance, diag(v * a * a / 12, v * b * b / 12, v * c * c / 12)) <=
              1e-15);
        gen_free(&g);

        /* vertices in body axes, placed with position and orientation: the same as a
         * "box" part with that position and orientation */
        struct mech_mat3 r;
        mech_rotation_from_euler_zxz(0.4, 1.2, -2.1, &r, NULL);
        gen_box(&g, a, b, c, zero);
        struct mech_vec3 pos = mech_vec3_make(5, -3, 2);
        struct mech_inertia_part pm = mesh_part(&g, M, pos, r);
        struct mech_inertia_part pb = part(MECH_SHAPE_BOX, M, pos, a, b, c);
        pb.orientation = r;
        struct mech_inertia rb;
        if (solve(&pm, &res) && solve(&pb, &rb)) {
            printf("rotated box mesh vs box: tensor rel. error %.3g\n",
                   rel_diff(res.tensor_cm, rb.tensor_cm));
            CHECK(rel_diff(res.tensor_cm, rb.tensor_cm) <= 1e-14);
            CHECK(mech_vec3_norm(mech_vec3_sub(res.center_of_mass, pos)) <= 1e-14);
        }
        gen_free(&g);
    }

    /* 2. Far from the origin: a box mesh centred at (1e6, -1e6, 2e6) m. The
     * vertex coordinates are rounded (ulp 1.2e-10 m), so the reference is the box
     * whose edges are the exact differences of those rounded coordinates. */
    {
        double a = 0.3, b = 0.7, c = 0.11, M = 2.0;
        struct mech_vec3 c0 = mech_vec3_make(1e6, -1e6, 2e6);
        struct gen g = {0};
        gen_box(&g, a, b, c, c0);
        double ea = g.v[1].x - g.v[0].x, eb = g.v[2].y - g.v[0].y, ec = g.v[4].z - g.v[0].z;
        struct mech_vec3 mid =
            mech_vec3_make(g.v[0].x + ea / 2, g.v[0].y + eb / 2, g.v[0].z + ec / 2);
        struct mech_vec3 com;
        struct mech_mat3 t = mesh_tensor(&g, M, &com);
        struct mech_mat3 want = diag(M * (eb * eb + ec * ec) / 12, M * (ea * ea + ec * ec) / 12,
                                     M * (ea * ea + eb * eb) / 12);
        printf("box mesh at 1e6 m: tensor rel. error %.3g, centroid error %.3g m\n",
               rel_diff(t, want), mech_vec3_norm(mech_vec3_sub(com, mid)));
        CHECK(rel_diff(t, want) <= 1e-14);
        CHECK(mech_vec3_norm(mech_vec3_sub(com, mid)) <= 1e-9); /* ulp of 2e6 is 4.7e-10 */
        gen_free(&g);

        /* a cone 1e6 m out, compared with the faceted closed form (section 3) */
        size_t n = 64;
        double r = 0.5, h = 1.7, D = 2 * MECH_PI / (double)n, f = (2 + cos(D)) / 3;
        gen_cone(&g, r, h, n);
        for (size_t k = 0; k < g.nv; k++)
            g.v[k] = mech_vec3_add(g.v[k], c0);
        t = mesh_tensor(&g, M, &com);
        want = diag(3 * M * r * r / 20 * f + 3 * M * h * h / 80,
                    3 * M * r * r / 20 * f + 3 * M * h * h / 80, 3 * M * r * r / 10 * f);
        printf("cone mesh at 1e6 m vs faceted closed form: tensor rel. error %.3g\n",
               rel_diff(t, want));
        CHECK(rel_diff(t, want) <= 1e-9); /* vertices themselves rounded to ~1e-10 m */
        CHECK(fabs(com.z - (c0.z + 0.75 * h)) <= 1e-9);
        /* the very same solid moved back to the origin (w - c0 is exact, Sterbenz):
         * the far mesh loses nothing to its distance */
        for (size_t k = 0; k < g.nv; k++)
            g.v[k] = mech_vec3_sub(g.v[k], c0);
        struct mech_vec3 com0;
        struct mech_mat3 t0 = mesh_tensor(&g, M, &com0);
        printf("cone mesh at 1e6 m vs the same mesh at the origin: tensor rel. error %.3g\n",
               rel_diff(t, t0));
        CHECK(rel_diff(t, t0) <= 1e-14);
        CHECK(mech_vec3_norm(mech_vec3_sub(mech_vec3_sub(com, c0), com0)) <= 1e-9);
        gen_free(&g);
    }

    /* 3. Straight-sided solids of revolution against the faceted closed forms
     * (exact for the mesh, see the header) — cone, cylinder, tube — and the
     * cone against the smooth closed form: O(1/N^2), under 1e-6 at N = 4096. */
    {
        double r = 0.5, h = 1.7, M = 1.3, a = 0.3, b = 0.45, ht = 0.9;
        double worst = 0;
        for (size_t n = 8; n <= 1024; n *= 2) {
            double D = 2 * MECH_PI / (double)n, f = (2 + cos(D)) / 3;
            struct gen g = {0};
            struct mech_vec3 com;
            gen_cone(&g, r, h, n);
            struct mech_mat3 t = mesh_tensor(&g, M, &com);
            /* cone about its centroid: across = 3MR^2/20 (x^2 part) + 3Mh^2/80 (z part) */
            struct mech_mat3 want =
                diag(3 * M * r * r / 20 * f + 3 * M * h * h / 80,
                     3 * M * r * r / 20 * f + 3 * M * h * h / 80, 3 * M * r * r / 10 * f);
            worst = fmax(worst, rel_diff(t, want));
            CHECK(fabs(com.z - 0.75 * h) <= 1e-15 * h && fabs(com.x) <= 1e-15 * h);
            gen_free(&g);
            gen_tube(&g, 0, r, h, n); /* cylinder */
            t = mesh_tensor(&g, M, NULL);
            want = diag(M * r * r / 4 * f + M * h * h / 12, M * r * r / 4 * f + M * h * h / 12,
                        M * r * r / 2 * f);
            worst = fmax(worst, rel_diff(t, want));
            gen_free(&g);
            gen_tube(&g, a, b, ht, n);
            t = mesh_tensor(&g, M, NULL);
            want =
                diag(M * (a * a + b * b) / 4 * f + M * ht * ht / 12,
                     M * (a * a + b * b) / 4 * f + M * ht * ht / 12, M * (a * a + b * b) / 2 * f);
            worst = fmax(worst, rel_diff(t, want));
            gen_free(&g);
        }
        printf("cone, cylinder, tube meshes (N = 8..1024) vs faceted closed forms: worst rel. "
               "error %.3g\n",
               worst);
        CHECK(worst <= 1e-13);
        g_cone_r = r;
        g_cone_h = h;
        converge("cone", make_cone, 512, M,
                 diag(3 * M * (4 * r * r + h * h) / 80, 3 * M * (4 * r * r + h * h) / 80,
                      0.3 * M * r * r),
                 mech_vec3_make(0, 0, 0.75 * h), h, 1e-10);
        struct gen g = {0};
        gen_cone(&g, r, h, 4096);
        struct mech_mat3 t = mesh_tensor(&g, M, NULL);
        double e4096 = rel_diff(t, diag(3 * M * (4 * r * r + h * h) / 80,
                                        3 * M * (4 * r * r + h * h) / 80, 0.3 * M * r * r));
        printf("cone mesh N = 4096 (%zu faces) vs the smooth cone: rel. error %.3g\n", g.nf, e4096);
        CHECK(e4096 <= 1e-6);
        gen_free(&g);
    }

    /* 4. Torus: faceted closed form (N around, M even around the tube; section =
     * regular M-gon of circumradius r: area A = (M/2) r^2 sin(2pi/M),
     * int x^2 dA = int z^2 dA = J = (A r^2/12)(2 + cos(2pi/M))):
     * I_zz = M (2 + cos D)/3 (R^2 + 3J/A), I_xx = I_zz/2 + M J/A. Smooth limit:
     * J/A -> r^2/4: I_zz = M(R^2 + 3r^2/4), I_xx = M(R^2/2 + 5r^2/8). */
    {
        double big = g_tor_big, r = g_tor_r, M = 2.2, worst = 0;
        for (size_t n = 8; n <= 256; n *= 2) {
            size_t m = n / 2;
            struct gen g = {0};
            gen_torus(&g, big, r, n, m);
            double D = 2 * MECH_PI / (double)n, Dm = 2 * MECH_PI / (double)m;
            double ja = r * r / 12 * (2 + cos(Dm));
            double izz = M * (2 + cos(D)) / 3 * (big * big + 3 * ja);
            struct mech_mat3 want = diag(izz / 2 + M * ja, izz / 2 + M * ja, izz);
            struct mech_vec3 com;
            struct mech_mat3 t = mesh_tensor(&g, M, &com);
            worst = fmax(worst, rel_diff(t, want));
            CHECK(mech_vec3_norm(com) <= 1e-15);
            gen_free(&g);
        }
        printf("torus meshes (N = 8..256, M = N/2) vs faceted closed form: worst rel. error "
               "%.3g\n",
               worst);
        CHECK(worst <= 1e-12);
        converge("torus", make_torus, 32, M,
                 diag(M * (big * big / 2 + 5 * r * r / 8), M * (big * big / 2 + 5 * r * r / 8),
                      M * (big * big + 0.75 * r * r)),
                 zero, big, 1e-6);
    }

    /* 5. Curved profiles: hemisphere (centroid 3R/8 above the flat face) and
     * ellipsoid (a sphere mesh scaled along x, y, z) against the smooth forms. */
    {
        double R = g_hemi_r, M = 0.9;
        converge("hemisphere", make_hemi, 32, M,
                 diag(83 * M * R * R / 320, 83 * M * R * R / 320, 0.4 * M * R * R),
                 mech_vec3_make(0, 0, 0.375 * R), R, 1e-6);
        double *s = g_ell;
        converge("ellipsoid", make_ellipsoid, 32, M,
                 diag(M * (s[1] * s[1] + s[2] * s[2]) / 5, M * (s[0] * s[0] + s[2] * s[2]) / 5,
                      M * (s[0] * s[0] + s[1] * s[1]) / 5),
                 zero, 1, 1e-6);
    }

    /* 6. The mesh path and the shapes agree with the same placement (reference
     * point and body axes): a tilted cone (position = apex), hemisphere (position =
     * centre of the flat face) and torus, through mech_inertia_compute. */
    {
        struct mech_mat3 r;
        mech_rotation_from_axis_angle(mech_vec3_make(1, -2, 0.5), 0.8, &r, NULL);
        struct mech_vec3 pos = mech_vec3_make(3, 1, -2);
        double M = 1.1;
        struct gen g = {0};
        struct mech_inertia rs;
        /* cone, N = 4096: the faceting factor on the x^2 part is 1 - 3.9e-7 */
        gen_cone(&g, 0.5, 1.7, 4096);
        struct mech_inertia_part pm = mesh_part(&g, M, pos, r);
        struct mech_inertia_part ps = part(MECH_SHAPE_CONE, M, pos, 0.5, 1.7, 0);
        ps.orientation = r;
        if (solve(&pm, &res) && solve(&ps, &rs)) {
            CHECK(rel_diff(res.tensor_cm, rs.tensor_cm) <= 1e-6);
            CHECK(mech_vec3_norm(mech_vec3_sub(res.center_of_mass, rs.center_of_mass)) <= 1e-14);
            /* the centre of mass is 3h/4 from the apex along body z = row 2 of R */
            struct mech_vec3 z = mech_vec3_make(r.a[2][0], r.a[2][1], r.a[2][2]);
            CHECK(mech_vec3_norm(mech_vec3_sub(rs.center_of_mass,
                                               mech_vec3_add(pos, mech_vec3_scale(z, 1.275)))) <=
                  1e-15 * 4);
        }
        gen_free(&g);
        /* hemisphere: Richardson pair placed the same way */
        struct mech_mat3 tt[2];
        for (int l = 0; l < 2; l++) {
            gen_hemisphere(&g, 0.8, 256u << l, 64u << l);
            pm = mesh_part(&g, M, pos, r);
            if (solve(&pm, &res)) tt[l] = res.tensor_cm;
            gen_free(&g);
        }
        ps = part(MECH_SHAPE_HEMISPHERE, M, pos, 0.8, 0, 0);
        ps.orientation = r;
        if (solve(&ps, &rs)) {
            double eh = rel_diff(richardson(tt[0], tt[1]), rs.tensor_cm);
            printf("tilted hemisphere mesh (Richardson 256/512) vs shape: %.3g\n", eh);
            CHECK(eh <= 1e-6);
            CHECK(mech_vec3_norm(mech_vec3_sub(res.center_of_mass, rs.center_of_mass)) <= 1e-4);
        }
        /* torus with the faceted factor divided out is exact: compare the mesh with
         * the shape directly at N = 256, M = 128 within the faceting error 1.1e-4 */
        gen_torus(&g, 1.0, 0.35, 256, 128);
        pm = mesh_part(&g, M, pos, r);
        ps = part(MECH_SHAPE_TORUS, M, pos, 1.0, 0.35, 0);
        ps.orientation = r;
        if (solve(&pm, &res) && solve(&ps, &rs)) {
            CHECK(rel_diff(res.tensor_cm, rs.tensor_cm) <= 2e-4);
            CHECK(mech_vec3_norm(mech_vec3_sub(res.center_of_mass, pos)) <= 1e-14);
        }
        gen_free(&g);
    }

    /* 7. Typed errors: open, flipped face, non-manifold edge, bad indices,
     * repeated vertex, no volume, too small, non-finite, budget. */
    {
        struct gen g = {0};
        gen_box(&g, 1, 1, 1, zero);
        g.nf--; /* drop a face: open */
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces") == 0 && strstr(e.text, "not closed"));
        g.nf++;
        size_t tmp = g.f[4]; /* flip face 1 */
        g.f[4] = g.f[5];
        g.f[5] = tmp;
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces") == 0 && strstr(e.text, "inconsistent orientation"));
        printf("flipped face: %s\n", e.text);
        g.f[5] = g.f[4];
        g.f[4] = tmp;
        CHECK(props(&g, &mp, &e) == MECH_OK);
        g.f[7] = 8; /* out of range */
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces/2") == 0);
        g.f[7] = g.f[6]; /* repeats a vertex */
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces/2") == 0);
        gen_free(&g);

        /* two cubes sharing one edge: that edge joins four faces */
        gen_box(&g, 1, 1, 1, zero);
        struct gen g2 = {0};
        gen_box(&g2, 1, 1, 1, mech_vec3_make(1, 1, 0));
        /* merge, identifying g2's corners on the shared edge x = y = 0.5 */
        size_t map[8];
        for (size_t k = 0; k < 8; k++) {
            map[k] = (size_t)-1;
            for (size_t j = 0; j < 8; j++)
                if (mech_vec3_norm(mech_vec3_sub(g2.v[k], g.v[j])) == 0) map[k] = j;
        }
        for (size_t k = 0; k < 8; k++)
            if (map[k] == (size_t)-1) map[k] = addv(&g, g2.v[k].x, g2.v[k].y, g2.v[k].z);
        for (size_t k = 0; k < g2.nf; k++)
            addf(&g, map[g2.f[3 * k]], map[g2.f[3 * k + 1]], map[g2.f[3 * k + 2]]);
        CHECK(g.nv == 14);
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces") == 0 && strstr(e.text, "not manifold"));
        printf("non-manifold: %s\n", e.text);
        gen_free(&g);
        gen_free(&g2);

        /* a closed, consistent surface with no volume: a tetrahedron flattened
         * into the plane z = 0 */
        addv(&g, 0, 0, 0);
        addv(&g, 1, 0, 0);
        addv(&g, 0, 1, 0);
        addv(&g, 0.25, 0.25, 0);
        addf(&g, 0, 2, 1);
        addf(&g, 0, 1, 3);
        addf(&g, 1, 2, 3);
        addf(&g, 0, 3, 2);
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces") == 0 && strstr(e.text, "no volume"));
        g.nf = 3;
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces") == 0);
        gen_free(&g);

        gen_box(&g, 1, 1, 1, zero);
        g.v[3].y = NAN;
        CHECK(props(&g, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "vertices") == 0);
        g.v[3].y = 0.5;
        struct mech_mesh m = as_mesh(&g);
        struct mech_budget small = mech_budget_make(20, 60.0);
        long steps = 0;
        mech_error_clear(&e);
        CHECK(mech_mesh_properties(&m, &small, &steps, &mp, &e) == MECH_EBUDGET);
        struct mech_budget enough = mech_budget_make(36, 60.0);
        steps = 0;
        CHECK(mech_mesh_properties(&m, &enough, &steps, &mp, &e) == MECH_OK);
        CHECK_EQ_INT(steps, 36); /* three steps per face */
        volatile int cancel = 1;
        struct mech_budget cb = budget();
        cb.cancel = &cancel;
        CHECK(mech_mesh_properties(&m, &cb, NULL, &mp, NULL) == MECH_ECANCELLED);
        CHECK(mech_mesh_properties(&m, NULL, NULL, &mp, NULL) == MECH_EINVAL);

        /* through mech_inertia: the param names the part */
        g.f[7] = 9;
        struct mech_inertia_part pp[2] = {part(MECH_SHAPE_SPHERE, 1, zero, 1, 0, 0),
                                          mesh_part(&g, 1, zero, mech_mat3_identity())};
        struct mech_budget b = budget();
        mech_error_clear(&e);
        CHECK(mech_inertia_compute(pp, 2, NULL, &b, &res, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "bodies/1/faces/2") == 0);
        /* mesh parts are refused by the budget-less mech_inertia_part_tensor */
        struct mech_mat3 t;
        CHECK(mech_inertia_part_tensor(&pp[1], &t, NULL) == MECH_EINVAL);
        gen_free(&g);
    }

    /* 8. Size limits: the largest mesh allowed runs (a torus of 199 998 faces
     * against its faceted closed form); one face more is refused. */
    {
        struct gen g = {0};
        size_t n = 333, m = 300; /* 2 n m = 199800 faces */
        gen_torus(&g, 1.0, 0.35, n, m);
        CHECK(g.nf <= MECH_MESH_MAX_FACES);
        double D = 2 * MECH_PI / (double)n, Dm = 2 * MECH_PI / (double)m, M = 1;
        double ja = 0.35 * 0.35 / 12 * (2 + cos(Dm));
        double izz = M * (2 + cos(D)) / 3 * (1 + 3 * ja);
        struct mech_mat3 t = mesh_tensor(&g, M, NULL);
        printf("torus of %zu faces vs faceted closed form: %.3g\n", g.nf,
               rel_diff(t, diag(izz / 2 + M * ja, izz / 2 + M * ja, izz)));
        CHECK(rel_diff(t, diag(izz / 2 + M * ja, izz / 2 + M * ja, izz)) <= 1e-13);
        struct mech_mesh mm = as_mesh(&g);
        mm.n_faces = MECH_MESH_MAX_FACES + 1;
        struct mech_budget b = budget();
        mech_error_clear(&e);
        CHECK(mech_mesh_properties(&mm, &b, NULL, &mp, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "faces") == 0);
        gen_free(&g);
    }
    TEST_MAIN_END();
}
