/* vector_algebra.c — dot, cross, angle, components, projections and triple
 * products of user vectors (notes ch. 0), computed on copies scaled by powers
 * of two so that nothing overflows or underflows on the way. */
#include "mech/rotation/vector_algebra.h"

#include <float.h>
#include <math.h>

/* v scaled by 2^-e so that its largest component lies in [0.5, 1); e = 0 for
 * the zero vector. Exact (bits below 2^-1074 of a tiny companion component
 * are the only loss, far below round-off of the result). */
static struct mech_vec3 scaled(struct mech_vec3 v, int *e)
{
    double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    *e = 0;
    if (m == 0) return v;
    frexp(m, e);
    return mech_vec3_make(ldexp(v.x, -*e), ldexp(v.y, -*e), ldexp(v.z, -*e));
}

static struct mech_vec3 vldexp(struct mech_vec3 v, int e)
{
    return mech_vec3_make(ldexp(v.x, e), ldexp(v.y, e), ldexp(v.z, e));
}

/* 2^e times a number below 8 in magnitude (a scaled triple product is at most
 * 3^(3/2)) stays finite. */
static int fits(int e) { return e <= DBL_MAX_EXP - 4; }

int mech_vector_unit(struct mech_vec3 a, struct mech_vec3 *u)
{
    if (!u || !mech_vec3_isfinite(a)) return 0;
    int e;
    struct mech_vec3 as = scaled(a, &e);
    double n = mech_vec3_norm(as);
    if (n == 0) return 0;
    *u = mech_vec3_scale(as, 1 / n);
    return 1;
}

enum mech_status mech_vector_pair(struct mech_vec3 a, struct mech_vec3 b,
                                  struct mech_vector_pair *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output given");
    if (!mech_vec3_isfinite(a)) return mech_error_set(err, MECH_EINVAL, "a", "must be finite");
    if (!mech_vec3_isfinite(b)) return mech_error_set(err, MECH_EINVAL, "b", "must be finite");
    int ea, eb;
    struct mech_vec3 as = scaled(a, &ea), bs = scaled(b, &eb);
    if (!fits(ea + eb))
        return mech_error_set(err, MECH_EDOMAIN, "b",
                              "|a| |b| ~ 2^%d is beyond the double range (1.8e308): the "
                              "products would overflow; scale the units",
                              ea + eb);
    struct mech_vector_pair r;
    r.norm_a = mech_vec3_norm(a);
    r.norm_b = mech_vec3_norm(b);
    double ds = mech_vec3_dot(as, bs);
    struct mech_vec3 cs = mech_vec3_cross(as, bs);
    r.dot = ldexp(ds, ea + eb);
    r.cross = vldexp(cs, ea + eb);
    struct mech_vec3 c = r.cross;
    struct mech_mat3 t = {{{0, c.z, -c.y}, {-c.z, 0, c.x}, {c.y, -c.x, 0}}};
    r.cross_tensor = t;
    r.has_angle = r.norm_a > 0 && r.norm_b > 0;
    r.angle = r.b_along_a = r.a_along_b = 0;
    r.b_on_a = r.b_across_a = mech_vec3_make(0, 0, 0);
    if (r.has_angle) {
        double na = mech_vec3_norm(as), nb = mech_vec3_norm(bs);
        r.angle = atan2(mech_vec3_norm(cs), ds);
        struct mech_vec3 ua = mech_vec3_scale(as, 1 / na);
        double bu = mech_vec3_dot(ua, bs); /* b . a-hat, scaled by 2^-eb */
        r.b_along_a = ldexp(bu, eb);
        r.a_along_b = ldexp(ds / nb, ea);
        r.b_on_a = vldexp(mech_vec3_scale(ua, bu), eb);
        r.b_across_a = vldexp(mech_vec3_sub(bs, mech_vec3_scale(ua, bu)), eb);
    }
    r.difference = mech_vec3_sub(a, b);
    r.sum = mech_vec3_add(a, b);
    int ed;
    struct mech_vec3 ds2 = scaled(r.difference, &ed);
    r.distance = ldexp(mech_vec3_norm(ds2), ed);
    if (!mech_vec3_isfinite(r.difference) || !mech_vec3_isfinite(r.sum) || !isfinite(r.distance))
        return mech_error_set(err, MECH_EDOMAIN, "b",
                              "a + b or a - b is beyond the double range (1.8e308); scale the "
                              "units");
    *out = r;
    return MECH_OK;
}

enum mech_status mech_vector_triple(struct mech_vec3 a, struct mech_vec3 b, struct mech_vec3 c,
                                    double *scalar, struct mech_vec3 *vector,
                                    struct mech_error *err)
{
    if (!mech_vec3_isfinite(a)) return mech_error_set(err, MECH_EINVAL, "a", "must be finite");
    if (!mech_vec3_isfinite(b)) return mech_error_set(err, MECH_EINVAL, "b", "must be finite");
    if (!mech_vec3_isfinite(c)) return mech_error_set(err, MECH_EINVAL, "c", "must be finite");
    int ea, eb, ec;
    struct mech_vec3 as = scaled(a, &ea), bs = scaled(b, &eb), cs = scaled(c, &ec);
    int e = ea + eb + ec;
    if (!fits(e))
        return mech_error_set(err, MECH_EDOMAIN, "c",
                              "|a| |b| |c| ~ 2^%d is beyond the double range (1.8e308): the "
                              "triple products would overflow; scale the units",
                              e);
    struct mech_vec3 bxc = mech_vec3_cross(bs, cs);
    if (scalar) *scalar = ldexp(mech_vec3_dot(as, bxc), e);
    if (vector) *vector = vldexp(mech_vec3_cross(as, bxc), e);
    return MECH_OK;
}
