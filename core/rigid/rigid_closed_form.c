/* rigid_closed_form.c — the torque-free rigid body answered from its exact
 * solution, attitude included (mech/rigid/rigid_closed_form.h): omega(t) from
 * mech_rigid_exact_omega (Jacobi elliptic functions, or the symmetric and
 * steady forms), and the orientation from the fixed angular momentum
 * (Landau & Lifshitz §37): in the frame with L along z, the Euler angles
 * (ZXZ, passive) of the body satisfy
 *   cos theta = J_c w_c / |L|,  tan psi = J_a w_a / (J_b w_b),
 *   phi' = |L| (J_a w_a^2 + J_b w_b^2) / (J_a^2 w_a^2 + J_b^2 w_b^2),
 * where (a, b, c) is a cyclic relabelling of the principal axes with c the
 * axis along which L's perpendicular part never vanishes: the dn axis of the
 * elliptic solution (largest moment when L^2 > 2 E I2, smallest otherwise),
 * the symmetry axis of a symmetric body. phi is integrated by adaptive
 * Gauss–Legendre quadrature over one period of phi' (once) and the remainder,
 * to round-off (its values at 16 points of the period tabulated once, so a
 * sample costs at most one piece's quadrature); a symmetric body has phi' = |L| / J_a exactly (regular
 * precession), a steady rotation the elementary rotation about omega.
 */
#include "mech/rigid/rigid_closed_form.h"
#include "mech/base/constants.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "mech/rotation/attitude.h"

#define RCF_GL_N 16
#define RCF_PIECES_PER_PERIOD 16

struct rcf_ctx {
    struct mech_rigid_exact ex;
    double Q[3][3];      /* abc components = Q (caller body components); rows: a, b, c */
    double J[3];         /* moments along a, b, c */
    double Lmag;         /* |L| */
    double T;            /* period of phi' (s); 0: phi' constant */
    double phidot_const; /* symmetric: |L| / J_a */
    double x[RCF_GL_N], w[RCF_GL_N];
    double table[RCF_PIECES_PER_PERIOD + 1]; /* integral of phi' over [0, j T / 16] */
    int evaluations;
    struct mech_error *err;
};

/* Gauss–Legendre nodes and weights on [-1, 1] (Newton on P_n). */
static void gl_nodes(double *x, double *w)
{
    const int n = RCF_GL_N;
    for (int i = 0; i < n; i++) {
        double z = cos(MECH_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; it++) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= n; k++) {
                double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            const double dz = p1 / dp;
            z -= dz;
            if (fabs(dz) < 1e-17) break;
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

/* omega at t in abc components. */
static enum mech_status rcf_omega_abc(struct rcf_ctx *c, double t, double u[3])
{
    struct mech_vec3 wb;
    c->evaluations++;
    enum mech_status st = mech_rigid_exact_omega(&c->ex, t, &wb, c->err);
    if (st != MECH_OK) return st;
    for (int r = 0; r < 3; r++) u[r] = c->Q[r][0] * wb.x + c->Q[r][1] * wb.y + c->Q[r][2] * wb.z;
    return MECH_OK;
}

static enum mech_status rcf_phidot(struct rcf_ctx *c, double t, double *f)
{
    double u[3];
    enum mech_status st = rcf_omega_abc(c, t, u);
    if (st != MECH_OK) return st;
    const double ja = c->J[0] * u[0], jb = c->J[1] * u[1];
    *f = c->Lmag * (ja * u[0] + jb * u[1]) / (ja * ja + jb * jb);
    return MECH_OK;
}

static enum mech_status gl_piece(struct rcf_ctx *c, double a, double b, double *out)
{
    const double h = 0.5 * (b - a), m = 0.5 * (a + b);
    double s = 0.0;
    for (int i = 0; i < RCF_GL_N; i++) {
        double f;
        enum mech_status st = rcf_phidot(c, m + h * c->x[i], &f);
        if (st != MECH_OK) return st;
        s += c->w[i] * f;
    }
    *out = h * s;
    return MECH_OK;
}

/* Adaptive: accept a piece when its two halves agree with it to 1e-15
 * relative (phi' > 0, so relative is meaningful); at most 30 halvings. */
static enum mech_status gl_adapt(struct rcf_ctx *c, double a, double b, double whole, int depth,
                                 double *out)
{
    const double m = 0.5 * (a + b);
    double l, r;
    enum mech_status st;
    if ((st = gl_piece(c, a, m, &l)) != MECH_OK || (st = gl_piece(c, m, b, &r)) != MECH_OK)
        return st;
    if (depth >= 30 || fabs(l + r - whole) <= 1e-15 * fabs(l + r)) {
        *out = l + r;
        return MECH_OK;
    }
    double x, y;
    if ((st = gl_adapt(c, a, m, l, depth + 1, &x)) != MECH_OK ||
        (st = gl_adapt(c, m, b, r, depth + 1, &y)) != MECH_OK)
        return st;
    *out = x + y;
    return MECH_OK;
}

/* integral of phi' over [a, b] (0 <= a <= b <= T): pieces of at most T/16. */
static enum mech_status phi_integral(struct rcf_ctx *c, double a, double b, double *out)
{
    *out = 0.0;
    if (!(b > a)) return MECH_OK;
    const double hmax = c->T / RCF_PIECES_PER_PERIOD;
    const int n = (int)ceil((b - a) / hmax);
    for (int k = 0; k < n; k++) {
        const double x0 = a + (b - a) * k / n, x1 = k + 1 == n ? b : a + (b - a) * (k + 1) / n;
        double whole, v;
        enum mech_status st;
        if ((st = gl_piece(c, x0, x1, &whole)) != MECH_OK ||
            (st = gl_adapt(c, x0, x1, whole, 0, &v)) != MECH_OK)
            return st;
        *out += v;
    }
    return MECH_OK;
}

/* Passive elementary rotations. */
static struct mech_mat3 rot_z(double c, double s)
{
    struct mech_mat3 m = {{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}};
    return m;
}
static struct mech_mat3 rot_x(double c, double s)
{
    struct mech_mat3 m = {{{1, 0, 0}, {0, c, s}, {0, -s, c}}};
    return m;
}

/* M(t) = Rz(psi) Rx(theta) Rz(phi): L-frame -> abc components, from omega_abc and phi. */
static struct mech_mat3 rcf_euler(const struct rcf_ctx *c, const double u[3], double phi)
{
    const double la = c->J[0] * u[0] / c->Lmag, lb = c->J[1] * u[1] / c->Lmag;
    const double lc = c->J[2] * u[2] / c->Lmag;
    const double st = hypot(la, lb);
    const double ct = lc;
    /* st > 0 whenever L is not along c (steady rotations take another path) */
    const double sp = st > 0.0 ? la / st : 0.0, cp = st > 0.0 ? lb / st : 1.0;
    return mech_mat3_mul(mech_mat3_mul(rot_z(cp, sp), rot_x(ct, st)), rot_z(cos(phi), sin(phi)));
}

/* The same validation as mech_rigid_rotate (but no method). */
static enum mech_status rcf_check(const struct mech_rigid_problem *p, double *qn,
                                  struct mech_error *err)
{
    enum mech_status mst = mech_rigid_moments_check(p->moments, err);
    if (mst != MECH_OK) return mst;
    if (!mech_vec3_isfinite(p->omega))
        return mech_error_set(err, MECH_EINVAL, "omega", "omega must be finite");
    double s = 0;
    for (int i = 0; i < 4; i++) s += p->q0[i] * p->q0[i];
    *qn = sqrt(s);
    if (!(isfinite(*qn) && *qn > 0))
        return mech_error_set(err, MECH_EINVAL, "orientation",
                              "the orientation must be a non-zero finite quaternion");
    if (!(isfinite(p->t_end) && p->t_end > 0))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0");
    if (p->samples < 2 || p->samples > 100000)
        return mech_error_set(err, MECH_EINVAL, "samples", "samples must be in 2..100000");
    if (p->torque_frame != MECH_RIGID_TORQUE_NONE &&
        !(p->torque.x == 0 && p->torque.y == 0 && p->torque.z == 0))
        return mech_error_set(err, MECH_EINVAL, "torque/value",
                              "a torqued body has no closed form here: integrate it");
    return MECH_OK;
}

int mech_rigid_has_closed_form(const struct mech_rigid_problem *p)
{
    struct mech_rigid_exact ex;
    struct mech_error e;
    mech_error_clear(&e);
    if (!p) return 0;
    if (p->torque_frame != MECH_RIGID_TORQUE_NONE &&
        !(p->torque.x == 0 && p->torque.y == 0 && p->torque.z == 0))
        return 0;
    if (mech_rigid_exact_init(p->moments, p->omega, &ex, &e) != MECH_OK) return 0;
    return ex.kind != MECH_RIGID_EXACT_SEPARATRIX;
}

/* The evaluations of one quadrature piece: gl_piece's 16 nodes and
 * gl_adapt's two halves (32), accepted at the first level away from the
 * separatrix (1:2:3 with m = 0.04 .. 0.71, 1:1.5:2, a symmetric top, 1 ..
 * 1e4 s, 2 .. 1001 samples: the counts equal the prediction exactly); near
 * it (m = 0.995, 0.999998) a few pieces take a halving, 64 more each, which
 * the prediction leaves out (measured within 1.11x). */
#define RCF_EVALS_PER_PIECE 48.0

/* Pieces phi_integral(a, b) splits [a, b] into (0 when b <= a). */
static double rcf_pieces(double a, double b, double hmax)
{
    return b > a ? ceil((b - a) / hmax) : 0.0;
}

double mech_rigid_closed_form_predict_evaluations(const struct mech_rigid_problem *p)
{
    if (!p || !mech_rigid_has_closed_form(p)) return -1.0;
    if (!(isfinite(p->t_end) && p->t_end > 0) || p->samples < 2 || p->samples > 100000)
        return -1.0;
    struct mech_rigid_exact ex;
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_rigid_exact_init(p->moments, p->omega, &ex, &e) != MECH_OK) return -1.0;
    const double n = (double)p->samples;
    const double *I = p->moments;
    const struct mech_vec3 w0 = p->omega;
    const struct mech_vec3 Lb0 = mech_vec3_make(I[0] * w0.x, I[1] * w0.y, I[2] * w0.z);
    const double Lmag = mech_vec3_norm(Lb0), wn = mech_vec3_norm(w0);
    /* the same tests as mech_rigid_closed_form */
    if (ex.kind == MECH_RIGID_EXACT_STEADY ||
        mech_vec3_norm(mech_vec3_cross(Lb0, w0)) <= 1e-15 * Lmag * wn)
        return n;
    if (ex.kind == MECH_RIGID_EXACT_SYMMETRIC) return n + 1.0;
    const double T = ex.flip_interval;
    if (!(T > 0.0 && isfinite(T))) return -1.0;
    const double hmax = T / RCF_PIECES_PER_PERIOD;
    double pieces = 0.0;
    for (int j = 0; j < RCF_PIECES_PER_PERIOD; j++) {
        const double a = T * j / RCF_PIECES_PER_PERIOD;
        const double b = j + 1 == RCF_PIECES_PER_PERIOD ? T : T * (j + 1) / RCF_PIECES_PER_PERIOD;
        pieces += rcf_pieces(a, b, hmax);
    }
    /* the sample loop's plan, as mech_rigid_closed_form follows it */
    long n_prev = -1;
    double r_prev = 0.0;
    for (size_t i = 0; i < p->samples; i++) {
        const double t = p->t_end * ((double)i / (double)(p->samples - 1));
        const double kk = floor(t / T);
        /* (periods beyond 2^62 only in absurd requests: counted as new ones) */
        const long kl = kk < 4.6e18 ? (long)kk : -2;
        double r = fma(-kk, T, t);
        if (r < 0.0) r = 0.0;
        if (r > T) r = T;
        if (kl == n_prev && r >= r_prev) {
            pieces += rcf_pieces(r_prev, r, hmax);
        } else {
            int j = (int)floor(r / T * RCF_PIECES_PER_PERIOD);
            if (j < 0) j = 0;
            if (j > RCF_PIECES_PER_PERIOD) j = RCF_PIECES_PER_PERIOD;
            const double rj = j == RCF_PIECES_PER_PERIOD ? T : T * j / RCF_PIECES_PER_PERIOD;
            pieces += rcf_pieces(rj, r, hmax);
        }
        n_prev = kl;
        r_prev = r;
    }
    /* omega at t = 0 (the attitude's set-up), one per sample, the pieces */
    return 1.0 + n + RCF_EVALS_PER_PIECE * pieces;
}

/* Which sorted axis serves as c, and the cyclic order (a, b, c). */
static void rcf_axes(const struct mech_rigid_exact *ex, int idx[3])
{
    const int c = ex->kind == MECH_RIGID_EXACT_SYMMETRIC ? ex->sym_axis : ex->dn_axis;
    idx[2] = c;
    idx[0] = (c + 1) % 3;
    idx[1] = (c + 2) % 3;
}

enum mech_status mech_rigid_closed_form(const struct mech_rigid_problem *p,
                                        struct mech_rigid_result *res,
                                        struct mech_rigid_closed_form_evidence *evidence,
                                        const struct mech_budget *budget,
                                        struct mech_error *err)
{
    if (!p || !res) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    double qn = 0.0;
    enum mech_status st = rcf_check(p, &qn, err);
    if (st != MECH_OK) return st;
    struct rcf_ctx c;
    memset(&c, 0, sizeof c);
    c.err = err;
    if ((st = mech_rigid_exact_init(p->moments, p->omega, &c.ex, err)) != MECH_OK) return st;
    if (c.ex.kind == MECH_RIGID_EXACT_SEPARATRIX)
        return mech_error_set(err, MECH_EDOMAIN, "omega",
                              "on the separatrix (L^2 = 2 E I2) the motion takes infinite time to "
                              "approach the intermediate axis and the attitude has no closed "
                              "form here: integrate it");
    gl_nodes(c.x, c.w);
    double q0[4];
    for (int i = 0; i < 4; i++) q0[i] = p->q0[i] / qn;
    const struct mech_mat3 R0 = mech_attitude_matrix(q0);
    const double *I = p->moments;
    const struct mech_vec3 w0 = p->omega;
    const struct mech_vec3 Lb0 = mech_vec3_make(I[0] * w0.x, I[1] * w0.y, I[2] * w0.z);
    c.Lmag = mech_vec3_norm(Lb0);
    /* steady: omega parallel to L (a sphere, omega = 0 or a principal axis) */
    const double wn = mech_vec3_norm(w0);
    const int steady = c.ex.kind == MECH_RIGID_EXACT_STEADY ||
                       mech_vec3_norm(mech_vec3_cross(Lb0, w0)) <= 1e-15 * c.Lmag * wn;
    int idx[3];
    rcf_axes(&c.ex, idx);
    for (int r = 0; r < 3; r++) {
        c.J[r] = c.ex.J[idx[r]];
        for (int k = 0; k < 3; k++) c.Q[r][k] = c.ex.p[idx[r]][k];
    }
    struct mech_mat3 Qm, RL = mech_mat3_identity();
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) Qm.a[r][k] = c.Q[r][k];
    double Phi = 0.0; /* phi over one period T */
    if (!steady) {
        double u0[3];
        if ((st = rcf_omega_abc(&c, 0.0, u0)) != MECH_OK) return st;
        /* R_L = M(0)^T Q R0 (phi(0) = 0) */
        RL = mech_mat3_mul(mech_mat3_transpose(rcf_euler(&c, u0, 0.0)), mech_mat3_mul(Qm, R0));
        if (c.ex.kind == MECH_RIGID_EXACT_SYMMETRIC) {
            c.phidot_const = c.Lmag / c.J[0];
        } else {
            c.T = c.ex.flip_interval; /* phi' depends on squares: period 2K / lambda */
            /* the integral at the 16 piece boundaries of one period, once */
            c.table[0] = 0.0;
            for (int j = 0; j < RCF_PIECES_PER_PERIOD; j++) {
                double d;
                const double a = c.T * j / RCF_PIECES_PER_PERIOD;
                const double b = j + 1 == RCF_PIECES_PER_PERIOD ? c.T
                                                                : c.T * (j + 1) / RCF_PIECES_PER_PERIOD;
                if ((st = phi_integral(&c, a, b, &d)) != MECH_OK) return st;
                c.table[j + 1] = c.table[j] + d;
            }
            Phi = c.table[RCF_PIECES_PER_PERIOD];
        }
    }

    res->rate_scale = mech_rigid_rate_scale(p);
    memset(&res->stats, 0, sizeof res->stats);
    res->torque_free = 1;
    res->L0 = mech_attitude_to_space(q0, Lb0);
    res->T0 = 0.5 * (I[0] * w0.x * w0.x + I[1] * w0.y * w0.y + I[2] * w0.z * w0.z);
    res->max_L_norm_drift = res->max_T_drift = res->max_L_vector_drift = 0.0;
    res->max_quaternion_norm_drift = 0.0;
    res->n_samples = 0;
    res->has_exact = 1;
    res->exact = c.ex;
    res->max_omega_error = res->max_relative_omega_error = res->final_omega_error = 0.0;
    res->flips = 0;
    res->measured_period = NAN;

    const size_t n = p->samples;
    double prev_q[4] = {q0[0], q0[1], q0[2], q0[3]};
    long n_prev = -1;
    double r_prev = 0.0, I_prev = 0.0;
    double first = NAN, last = NAN, prev_u2 = 0, prev_t = 0;
    const double L0n = mech_vec3_norm(res->L0);
    struct mech_budget clock_only;
    if (budget) {
        clock_only = *budget;
        clock_only.max_steps = LONG_MAX; /* deadline and cancel only */
    }
    for (size_t i = 0; i < n; i++) {
        const double t = p->t_end * ((double)i / (double)(n - 1));
        if (budget && (st = mech_budget_check(&clock_only, (long)i, 0, err)) != MECH_OK) {
            if (err) {
                err->progress.t_reached = i > 0 ? p->t_end * ((double)(i - 1) / (double)(n - 1)) : 0.0;
                err->progress.t_target = p->t_end;
            }
            return st;
        }
        struct mech_vec3 wb;
        if ((st = mech_rigid_exact_omega(&c.ex, t, &wb, err)) != MECH_OK) return st;
        c.evaluations++;
        struct mech_mat3 R;
        if (steady) {
            /* rotation about the constant omega by |omega| t (passive) */
            if (wn > 0.0) {
                const struct mech_vec3 e = mech_vec3_scale(w0, 1.0 / wn);
                const double a = wn * t, ca = cos(a), sa = sin(a);
                const double ev[3] = {e.x, e.y, e.z};
                struct mech_mat3 K = {{{0, -e.z, e.y}, {e.z, 0, -e.x}, {-e.y, e.x, 0}}}, Rot;
                for (int r = 0; r < 3; r++)
                    for (int k = 0; k < 3; k++)
                        Rot.a[r][k] = (r == k ? ca : 0.0) + (1.0 - ca) * ev[r] * ev[k] - sa * K.a[r][k];
                R = mech_mat3_mul(Rot, R0);
            } else {
                R = R0;
            }
        } else {
            double phi;
            if (c.T == 0.0) {
                phi = c.phidot_const * t;
            } else {
                /* t = k T + r; phi = k Phi + integral over [0, r] (continued from the
                 * previous sample within the same period) */
                const double kk = floor(t / c.T);
                double r = fma(-kk, c.T, t);
                if (r < 0.0) r = 0.0;
                if (r > c.T) r = c.T;
                double Ir;
                if ((long)kk == n_prev && r >= r_prev) {
                    double d;
                    if ((st = phi_integral(&c, r_prev, r, &d)) != MECH_OK) return st;
                    Ir = I_prev + d;
                } else {
                    /* from the nearest table boundary below r: one piece at most */
                    int j = (int)floor(r / c.T * RCF_PIECES_PER_PERIOD);
                    if (j < 0) j = 0;
                    if (j > RCF_PIECES_PER_PERIOD) j = RCF_PIECES_PER_PERIOD;
                    const double rj = j == RCF_PIECES_PER_PERIOD ? c.T
                                                                 : c.T * j / RCF_PIECES_PER_PERIOD;
                    double d = 0.0;
                    if (r > rj && (st = phi_integral(&c, rj, r, &d)) != MECH_OK) return st;
                    Ir = c.table[j] + d;
                }
                n_prev = (long)kk;
                r_prev = r;
                I_prev = Ir;
                phi = kk * Phi + Ir;
            }
            double u[3];
            for (int r = 0; r < 3; r++) u[r] = c.Q[r][0] * wb.x + c.Q[r][1] * wb.y + c.Q[r][2] * wb.z;
            R = mech_mat3_mul(mech_mat3_mul(mech_mat3_transpose(Qm), rcf_euler(&c, u, phi)), RL);
        }
        double q[4];
        mech_attitude_from_matrix(R, q);
        /* continuous sign from the given q0 */
        const double dot = q[0] * prev_q[0] + q[1] * prev_q[1] + q[2] * prev_q[2] + q[3] * prev_q[3];
        if (dot < 0.0)
            for (int k = 0; k < 4; k++) q[k] = -q[k];
        memcpy(prev_q, q, sizeof q);
        const double qq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        res->max_quaternion_norm_drift = fmax(res->max_quaternion_norm_drift, fabs(qq - 1.0));
        const struct mech_vec3 Lb = mech_vec3_make(I[0] * wb.x, I[1] * wb.y, I[2] * wb.z);
        const struct mech_vec3 L = mech_attitude_to_space(q, Lb);
        const double T = 0.5 * (I[0] * wb.x * wb.x + I[1] * wb.y * wb.y + I[2] * wb.z * wb.z);
        if (res->t) res->t[i] = t;
        if (res->omega) res->omega[i] = wb;
        if (res->quaternion) memcpy(res->quaternion + 4 * i, q, sizeof q);
        if (res->angular_momentum) res->angular_momentum[i] = L;
        if (res->kinetic_energy) res->kinetic_energy[i] = T;
        res->n_samples = i + 1;
        res->max_T_drift = fmax(res->max_T_drift, res->T0 > 0 ? fabs(T - res->T0) / res->T0
                                                              : fabs(T - res->T0));
        res->max_L_norm_drift = fmax(res->max_L_norm_drift,
                                     L0n > 0 ? fabs(mech_vec3_norm(L) - L0n) / L0n
                                             : mech_vec3_norm(L));
        res->max_L_vector_drift =
            fmax(res->max_L_vector_drift, L0n > 0 ? mech_vec3_norm(mech_vec3_sub(L, res->L0)) / L0n
                                                  : mech_vec3_norm(L));
        /* flips: sign changes of the intermediate-axis component (sorted row 1) */
        const double(*P)[3] = c.ex.p;
        const double u2 = P[1][0] * wb.x + P[1][1] * wb.y + P[1][2] * wb.z;
        if (i > 0 && ((prev_u2 < 0 && u2 >= 0) || (prev_u2 > 0 && u2 <= 0)) && u2 != prev_u2) {
            const double tc = prev_t + (t - prev_t) * prev_u2 / (prev_u2 - u2);
            if (res->flips == 0) first = tc;
            last = tc;
            res->flips++;
        }
        prev_u2 = u2;
        prev_t = t;
    }
    if (res->flips >= 2) res->measured_period = 2 * (last - first) / (double)(res->flips - 1);
    if (evidence) {
        evidence->solution = steady                                    ? "steady"
                             : c.ex.kind == MECH_RIGID_EXACT_SYMMETRIC ? "symmetric"
                                                                       : "elliptic";
        evidence->max_invariant_drift =
            fmax(res->max_T_drift, fmax(res->max_L_norm_drift, res->max_L_vector_drift));
        evidence->error_bound = fmax(evidence->max_invariant_drift, 4.0 * DBL_EPSILON);
        evidence->evaluations = c.evaluations;
    }
    return MECH_OK;
}
