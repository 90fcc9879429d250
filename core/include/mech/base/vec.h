/* mech/base/vec.h — small value types: 3-vectors and 3x3 matrices.
 *
 * Pass by value, cannot fail, header-only. Matrices are row-major:
 * m.a[i][j] is row i, column j.
 */
#ifndef MECH_VEC_H
#define MECH_VEC_H

#include <math.h>

struct mech_vec3 { double x, y, z; };
struct mech_mat3 { double a[3][3]; };

static inline struct mech_vec3 mech_vec3_make(double x, double y, double z)
{ struct mech_vec3 v = {x, y, z}; return v; }
static inline struct mech_vec3 mech_vec3_add(struct mech_vec3 a, struct mech_vec3 b)
{ return mech_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline struct mech_vec3 mech_vec3_sub(struct mech_vec3 a, struct mech_vec3 b)
{ return mech_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline struct mech_vec3 mech_vec3_scale(struct mech_vec3 a, double s)
{ return mech_vec3_make(a.x * s, a.y * s, a.z * s); }
static inline double mech_vec3_dot(struct mech_vec3 a, struct mech_vec3 b)
{ return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline struct mech_vec3 mech_vec3_cross(struct mech_vec3 a, struct mech_vec3 b)
{ return mech_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
/* Euclidean norm without overflow or underflow for any finite components
 * (correct to ~1 ulp; +inf if a component is infinite, NaN if one is NaN and
 * none infinite, as hypot).
 *
 * Fast path: sqrt(x^2 + y^2 + z^2) when the sum of squares lies in
 * [2^-968, DBL_MAX]: no square overflowed (the sum is finite), and a square
 * that underflowed (to a subnormal or 0, absolute error <= 2^-1075) is
 * below 2^-107 of the sum, so the result is as good as hypot's (3 roundings
 * in the sum, 1 in sqrt: < 2 ulp). Otherwise (tiny or huge vectors, 0,
 * inf, NaN) the scaled hypot(hypot(x, y), z), exact at the extremes. The
 * fast path is ~10x cheaper than two hypot calls: this norm is in the
 * innermost loop of every trajectory. */
static inline double mech_vec3_norm(struct mech_vec3 a)
{
    const double s = a.x * a.x + a.y * a.y + a.z * a.z;
    if (s >= 0x1p-968 && s <= 0x1.fffffffffffffp+1023) return sqrt(s);
    return hypot(hypot(a.x, a.y), a.z);
}
static inline int mech_vec3_isfinite(struct mech_vec3 a)
{ return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* Unit vector along a: a scaled by 1/|a|. a must be non-zero and finite (a
 * zero or non-finite a gives a non-finite result); for a vector that may be
 * zero, tiny or huge use mech_vec3_unit_checked. */
static inline struct mech_vec3 mech_vec3_unit(struct mech_vec3 a)
{ return mech_vec3_scale(a, 1.0 / mech_vec3_norm(a)); }

/* Unit vector along any v: divided first by max|v_i| so that no square
 * overflows or underflows, then by the norm of that. Divisions, not products
 * with a reciprocal, so each component is correctly rounded: the Doppler
 * factor along the line of flight at gamma = 1e15
 * (tests/core/relativity/test_doppler.c) is right only in this form.
 * Returns 1 and sets *u, or 0 (leaving *u untouched) when v is zero or not
 * finite. */
static inline int mech_vec3_unit_checked(struct mech_vec3 v, struct mech_vec3 *u)
{
    if (!mech_vec3_isfinite(v)) return 0;
    const double m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    if (m == 0) return 0;
    const struct mech_vec3 s = mech_vec3_make(v.x / m, v.y / m, v.z / m);
    const double len = mech_vec3_norm(s);
    *u = mech_vec3_make(s.x / len, s.y / len, s.z / len);
    return 1;
}
static inline double mech_vec3_get(struct mech_vec3 a, int i)
{ return i == 0 ? a.x : (i == 1 ? a.y : a.z); }

static inline struct mech_mat3 mech_mat3_identity(void)
{ struct mech_mat3 m = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; return m; }
static inline struct mech_vec3 mech_mat3_mul_vec(struct mech_mat3 m, struct mech_vec3 v)
{
    return mech_vec3_make(m.a[0][0] * v.x + m.a[0][1] * v.y + m.a[0][2] * v.z,
                          m.a[1][0] * v.x + m.a[1][1] * v.y + m.a[1][2] * v.z,
                          m.a[2][0] * v.x + m.a[2][1] * v.y + m.a[2][2] * v.z);
}
static inline struct mech_mat3 mech_mat3_mul(struct mech_mat3 a, struct mech_mat3 b)
{
    struct mech_mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.a[i][j] = a.a[i][0] * b.a[0][j] + a.a[i][1] * b.a[1][j] + a.a[i][2] * b.a[2][j];
    return r;
}
static inline struct mech_mat3 mech_mat3_transpose(struct mech_mat3 m)
{
    struct mech_mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r.a[i][j] = m.a[j][i];
    return r;
}
static inline int mech_mat3_isfinite(struct mech_mat3 m)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!isfinite(m.a[i][j])) return 0;
    return 1;
}

#endif
