/* velocity_addition.c — relativistic velocity addition (notes §3.10) from
 * rapidities and light-cone components, aberration of light, and the
 * composition of boosts with its Wigner (Thomas) rotation.
 *
 * Derivation of the precise forms used (object: rapidity a along n_o; frame:
 * rapidity b along n_f; c = cos θ = n_o·n_f, s = sin θ). The object's
 * 4-velocity is (cosh a, sinh a n_o); the boost to the frame gives
 *   γ' = cosh a cosh b − sinh a sinh b c
 *      = cosh(a − b) + sinh a sinh b (1 − c),
 * so γ' − 1 = 2 sinh²((a − b)/2) + sinh a sinh b (1 − c) (all terms ≥ 0);
 *   u∥' = cosh b sinh a c − sinh b cosh a
 *       = sinh(a − b) − (1 − c) sinh a cosh b       (used for c ≥ 0)
 *       = −sinh(a + b) + (1 + c) sinh a cosh b      (used for c < 0),
 *   u⊥' = sinh a s.
 * 1 − c and 1 + c come from the cross product (s² / (1 ± c)), never from
 * 1 − (rounded c), so small angles keep their precision.
 */
#include "mech/relativity/velocity_addition.h"
#include "mech/base/compensated.h"

#include <math.h>
#include <stdio.h>

/* The angle between unit vectors f and o: cos, sin, 1 − cos, 1 + cos (each
 * to a few ulp) and the unit vector m ⊥ f in the plane, toward o (has_m = 0
 * when they are parallel or antiparallel). */
struct angle_parts {
    double c, s, omc, opc;
    struct mech_vec3 m;
    int has_m;
};

static struct angle_parts angle_between(struct mech_vec3 f, struct mech_vec3 o)
{
    struct angle_parts a;
    struct mech_vec3 w = mech_cross_compensated(f, o);
    double s = mech_vec3_norm(w);
    double c = mech_dot_compensated(f, o);
    /* Normalise (c, s) onto the unit circle: the inputs are unit to rounding. */
    double h = hypot(c, s);
    if (h > 0) {
        c /= h;
        s /= h;
    }
    a.c = c;
    a.s = s;
    if (c >= 0) {
        a.opc = 1.0 + c;
        a.omc = s * s / a.opc; /* 1 − cos θ = sin²θ / (1 + cos θ) */
    } else {
        a.omc = 1.0 - c;
        a.opc = s * s / a.omc;
    }
    a.has_m = s > 0;
    if (a.has_m) {
        /* (f × o) × f = o − (o·f) f, of length s. */
        struct mech_vec3 m = mech_cross_compensated(w, f);
        double len = mech_vec3_norm(m);
        a.m = mech_vec3_scale(m, 1.0 / len);
    } else {
        a.m = mech_vec3_make(0, 0, 0);
    }
    return a;
}

/* 2 sinh²(x/2) = cosh x − 1 without cancellation. */
static double cosh_m1(double x)
{
    double sh = sinh(0.5 * x);
    return 2.0 * sh * sh;
}

enum mech_status mech_velocity_add(const struct mech_boost *object, const struct mech_boost *frame,
                                   struct mech_boost *out, struct mech_error *err)
{
    if (!object || !frame || !out)
        return mech_error_set(err, MECH_EINVAL, NULL, "object, frame and output are required");
    const double a = object->rapidity, b = frame->rapidity;
    const double sa = object->beta_gamma, sb = frame->beta_gamma;
    const double cb = frame->gamma;
    struct angle_parts ap = angle_between(frame->direction, object->direction);

    /* cosh(a − b) − 1 and sinh(a − b): from the rapidity difference while it is
     * small (exact by Sterbenz when a ≈ b), else from E = e^{|a − b|} as a product
     * of the boosts' e^{±η} (each correctly rounded), since a large rounded
     * rapidity carries an absolute error ε·η that e^{±η'} would amplify:
     * cosh d − 1 = (E − 1)²/(2E), sinh |d| = (E − 1/E)/2. */
    const double d = a - b;
    double cm1, shd;
    if (fabs(d) < 0.5) {
        cm1 = cosh_m1(d);
        shd = sinh(d);
    } else {
        double E = d > 0 ? object->exp_rapidity * frame->exp_neg_rapidity
                         : frame->exp_rapidity * object->exp_neg_rapidity;
        cm1 = (E - 1.0) * ((E - 1.0) / (2.0 * E));
        shd = copysign(0.5 * (E - 1.0 / E), d);
    }
    /* notes §3.10 rewritten (header comment): γ' − 1 as a sum of terms ≥ 0. */
    double gm1 = cm1 + sa * sb * ap.omc;
    double par;
    if (ap.c >= 0) {
        par = shd - ap.omc * sa * cb;
    } else {
        double shs = a + b < 0.5 ? sinh(a + b)
                                 : 0.5 * (object->exp_rapidity * frame->exp_rapidity -
                                          object->exp_neg_rapidity * frame->exp_neg_rapidity);
        par = ap.opc * sa * cb - shs;
    }
    double perp = sa * ap.s;
    if (!isfinite(gm1) || !isfinite(par) || !isfinite(perp))
        return mech_error_set(err, MECH_ENUMERIC, "velocity",
                              "the relative velocity overflows (rapidities %.17g and %.17g)", a, b);
    struct mech_vec3 dir = mech_vec3_scale(frame->direction, par);
    if (ap.has_m) dir = mech_vec3_add(dir, mech_vec3_scale(ap.m, perp));
    if (gm1 > 0 && !(mech_vec3_norm(dir) > 0)) gm1 = 0; /* below round-off: at rest */

    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_boost_from_gamma_minus_one(gm1, dir, out, &e);
    if (st != MECH_OK) return mech_error_set(err, MECH_ENUMERIC, "velocity", "%s", e.text);
    return MECH_OK;
}

enum mech_status mech_velocity_add_light(struct mech_vec3 direction, const struct mech_boost *frame,
                                         struct mech_vec3 *direction_out, double *frequency_ratio,
                                         struct mech_error *err)
{
    if (!frame || !direction_out || !frequency_ratio)
        return mech_error_set(err, MECH_EINVAL, NULL, "frame and outputs are required");
    double m = fmax(fabs(direction.x), fmax(fabs(direction.y), fabs(direction.z)));
    if (!mech_vec3_isfinite(direction) || m == 0)
        return mech_error_set(err, MECH_EINVAL, "direction",
                              "the direction of the light must be a nonzero finite vector");
    struct mech_vec3 k = mech_vec3_scale(direction, 1.0 / m);
    k = mech_vec3_unit(k);
    struct angle_parts ap = angle_between(frame->direction, k);
    /* Photon (1, k): light-cone components along n_f are u = 1 − c, v = 1 + c;
     * the boost scales u' = e^{η} u, v' = e^{−η} v (core/relativity/boost.c). Then
     * ν'/ν = (u' + v')/2, cos θ' = (v' − u')/(u' + v'), sin θ' = 2 s/(u' + v'). */
    double up = frame->exp_rapidity * ap.omc, vp = frame->exp_neg_rapidity * ap.opc;
    double sum = up + vp;
    double cp = (vp - up) / sum, sp = 2.0 * ap.s / sum;
    struct mech_vec3 kp = mech_vec3_scale(frame->direction, cp);
    if (ap.has_m) kp = mech_vec3_add(kp, mech_vec3_scale(ap.m, sp));
    double ratio = 0.5 * sum;
    if (!isfinite(ratio) || !mech_vec3_isfinite(kp))
        return mech_error_set(err, MECH_ENUMERIC, "velocity", "the boosted light is not finite");
    *direction_out = mech_vec3_unit(kp);
    *frequency_ratio = ratio;
    return MECH_OK;
}

/* tan(ε/2) = num/den for the Wigner rotation of first then second (see the
 * header); with t_i = tanh(η_i/2) = βγ/(γ + 1) and
 * 1 − t1 t2 = (1 − t1) + t1 (1 − t2), 1 − t = 2 e^{−η}/(1 + e^{−η}), so the
 * denominator 1 − t1 t2 + t1 t2 (1 + cos θ) has no cancellation. */
static void wigner_half(const struct mech_boost *first, const struct mech_boost *second,
                        double *num, double *den, struct mech_vec3 *axis)
{
    struct angle_parts ap = angle_between(first->direction, second->direction);
    double t1 = first->beta_gamma / (first->gamma + 1.0);
    double t2 = second->beta_gamma / (second->gamma + 1.0);
    double u1 = 2.0 * first->exp_neg_rapidity / (1.0 + first->exp_neg_rapidity);
    double u2 = 2.0 * second->exp_neg_rapidity / (1.0 + second->exp_neg_rapidity);
    double t = t1 * t2;
    *num = ap.s * t;
    *den = (u1 + t1 * u2) + t * ap.opc;
    struct mech_vec3 w = mech_cross_compensated(second->direction, first->direction);
    double len = mech_vec3_norm(w);
    if (*num > 0 && len > 0) {
        *axis = mech_vec3_scale(w, 1.0 / len);
    } else {
        *num = 0;
        *den = 1;
        *axis = mech_vec3_make(0, 0, 0);
    }
}

enum mech_status mech_wigner_rotation(const struct mech_boost *first,
                                      const struct mech_boost *second, double *angle,
                                      struct mech_vec3 *axis, struct mech_error *err)
{
    if (!first || !second || !angle || !axis)
        return mech_error_set(err, MECH_EINVAL, NULL, "boosts and outputs are required");
    double num, den;
    wigner_half(first, second, &num, &den, axis);
    *angle = 2.0 * atan2(num, den);
    return MECH_OK;
}

/* ---- quaternions (w, x, y, z) for the accumulated turn of the axes -------- */

static void quat_mul(const double a[4], const double b[4], double r[4])
{
    double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    double n = sqrt(w * w + x * x + y * y + z * z);
    r[0] = w / n;
    r[1] = x / n;
    r[2] = y / n;
    r[3] = z / n;
}

/* Active rotation of v by the unit quaternion q: v + 2w (q×v) + 2 q×(q×v). */
static struct mech_vec3 quat_rotate(const double q[4], struct mech_vec3 v)
{
    struct mech_vec3 u = mech_vec3_make(q[1], q[2], q[3]);
    struct mech_vec3 t = mech_vec3_scale(mech_vec3_cross(u, v), 2.0);
    return mech_vec3_add(mech_vec3_add(v, mech_vec3_scale(t, q[0])), mech_vec3_cross(u, t));
}

/* The active rotation matrix of q (columns are the turned axes). */
static struct mech_mat3 quat_matrix(const double q[4])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    struct mech_mat3 m = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
    return m;
}

enum mech_status mech_boost_compose(const struct mech_boost *v, size_t n,
                                    const struct mech_budget *budget,
                                    struct mech_boost_composition *out, struct mech_error *err)
{
    if (!v || !out || n == 0)
        return mech_error_set(err, MECH_EINVAL, "boosts", "at least one boost is required");
    struct mech_boost acc = v[0];
    double q[4] = {1, 0, 0, 0};
    for (size_t k = 1; k < n; k++) {
        enum mech_status st = mech_budget_check(budget, (long)k, k == 1, err);
        if (st != MECH_OK) return st;
        /* Λ_k = R_acc B(acc); B(v) R_acc = R_acc B(R_acc^T v), and R_acc^T is
         * the active turn q: express v in the pure-boost frame's axes. */
        struct mech_boost vr = v[k];
        vr.direction = quat_rotate(q, v[k].direction);
        vr.direction = mech_vec3_unit(vr.direction);
        vr.beta_vec = mech_vec3_scale(vr.direction, vr.beta);
        /* B(vr) B(acc) = R2 B(acc ⊕ vr): the velocity of the new frame in the
         * original is vr seen from a frame moving with −acc. */
        double num, den;
        struct mech_vec3 axis;
        wigner_half(&acc, &vr, &num, &den, &axis);
        struct mech_boost inv = mech_boost_inverse(&acc), next;
        struct mech_error e;
        mech_error_clear(&e);
        if (mech_velocity_add(&vr, &inv, &next, &e) != MECH_OK) {
            char param[32];
            snprintf(param, sizeof param, "boosts/%zu", k);
            return mech_error_set(err, MECH_ENUMERIC, param,
                                  "the composition up to boost %zu is beyond rapidity %g: %s", k,
                                  MECH_BOOST_RAPIDITY_MAX, e.text);
        }
        double h = hypot(num, den);
        double q2[4] = {den / h, num / h * axis.x, num / h * axis.y, num / h * axis.z};
        double qn[4];
        quat_mul(q2, q, qn); /* A_total = A_2 A_acc (R_total = R_acc R_2) */
        for (int i = 0; i < 4; i++)
            q[i] = qn[i];
        acc = next;
    }
    if (q[0] < 0)
        for (int i = 0; i < 4; i++)
            q[i] = 0.0 - q[i];
    double sv = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    out->total = acc;
    for (int i = 0; i < 4; i++)
        out->quaternion[i] = q[i];
    out->angle = 2.0 * atan2(sv, q[0]);
    out->axis = sv > 0 ? mech_vec3_make(q[1] / sv, q[2] / sv, q[3] / sv) : mech_vec3_make(0, 0, 0);
    out->rotation = mech_mat3_transpose(quat_matrix(q));
    return MECH_OK;
}
