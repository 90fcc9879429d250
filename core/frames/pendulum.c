/* pendulum.c — the Foucault pendulum (mech/frames/pendulum.h): the full nonlinear
 * spherical pendulum in the rotating Earth frame, integrated by RATTLE with
 * the Coriolis term in Cayley (implicit-midpoint) form, optionally composed
 * to order 4, and the swing-plane precession measured at the turning points.
 *
 * The step. Per unit mass the Lagrangian in the Earth frame is
 *   L = |u'|^2 / 2 + u'.(W x r) + [|W x r|^2 / 2] - g z,   |u| = l
 * (u = r - s; the vector potential A = W x r has curl 2 W, the Coriolis term;
 * Goldstein §4.10 / notes §1.2). Its discrete Lagrangian with A at the chord
 * midpoint and V by the trapezoid rule gives, on the constraint (Hairer,
 * Lubich & Wanner, Geometric Numerical Integration, 2nd ed., §VII.1.4 RATTLE;
 * Marsden & West, Acta Numerica 2001, §3.5 constrained variational
 * integrators):
 *   w      = (I + h K)^-1 [v0 + h/2 (F(u0) + mu u0)],    K x = W x x
 *   u1     = u0 + h w,      |u1| = l           (mu: a quadratic, solved exactly)
 *   v1     = (I - h K) w + h/2 (F(u1) + nu u1), u1.v1 = 0 (nu: a projection)
 * The Coriolis part is the Cayley transform (I + hK)^-1 (I - hK): an exact
 * rotation about W by 2 atan(h|W|), as in Boris' scheme; with W = 0 this is
 * textbook RATTLE. The map is symplectic on T*(sphere), symmetric, and exact
 * on the constraint. (I + hK)^-1 x = (x - k x x + k (k.x)) / (1 + |k|^2),
 * k = h W (from K^2 = k k^T - |k|^2 I).
 *
 * Order 4: Yoshida's triple jump (Phys. Lett. A 150, 262 (1990)), steps
 * g1 h, g0 h, g1 h with g1 = 1/(2 - 2^(1/3)), g0 = 1 - 2 g1; valid because the
 * RATTLE step is symmetric.
 *
 * The measurement. The swing plane's azimuth psi (mod pi, unwrapped) is read
 * at every maximum of the horizontal distance rho and fitted with a straight
 * line in t. Expected slope: the notes' linear solution turns the plane at
 * -W sin(lat) (clockwise in the north). At finite amplitude the spherical
 * pendulum's own apsides advance at (3/8) omega0 a b / l^2 in the sense of
 * the motion (G. B. Airy, Mon. Not. R. Astron. Soc. 11, 121 (1851); Olsson,
 * Am. J. Phys. 49, 531 (1981), eq. 15), and a b omega0 = h, twice the areal
 * velocity seen from a frame turning at W sin(lat): h = x y' - y x' +
 * W sin(lat) rho^2, conserved when only the vertical component of W acts.
 * Released from rest h = W sin(lat) a^2: the measured rate is
 * -W sin(lat) (1 - 3 a^2 / (8 l^2)). With the centrifugal term
 * V_c = -|W x r|^2 / 2 ~ -W^2 (x^2 + y^2 sin^2 lat) / 2, whose anisotropic
 * part -W^2 cos^2(lat) x^2 / 2 exerts the mean torque
 * dh/dt = -(W^2 cos^2(lat) a^2 / 4) sin 2 psi: with psi = psi0 - W sin(lat) t,
 * h(t) = h0 + (W^2 cos^2(lat) a^2 / (8 W sin lat)) (cos 2 psi0 - cos 2 psi),
 * a change of (cot^2(lat) / 8) h0 (12.5 % at 45 degrees) that the Airy term
 * follows. So h(t) is integrated along the run, H = int h dt, and the slope
 * of H at the turning points (fitted like psi) gives the Airy rate of the
 * ellipse actually swung (airy_rate_mean).
 */
#include "mech/frames/pendulum.h"
#include "mech/base/constants.h"

#include <math.h>

const char *mech_pendulum_method_name(enum mech_pendulum_method m)
{
    switch (m) {
    case MECH_PENDULUM_RATTLE:
        return "rattle";
    case MECH_PENDULUM_RATTLE_YOSHIDA4:
        return "rattle_yoshida4";
    }
    return NULL;
}

/* A & S 17.6: K(k) = pi / (2 AGM(1, k')), k' = cos(alpha/2) for k = sin(alpha/2). */
double mech_pendulum_period(double length, double g, double alpha)
{
    double a = 1.0, b = cos(0.5 * alpha);
    for (int i = 0; i < 40 && fabs(a - b) > 1e-16 * a; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return 2.0 * MECH_PI * sqrt(length / g) / (0.5 * (a + b));
}

double mech_pendulum_period_correction(double alpha)
{
    const double sq = sin(0.25 * alpha);
    double a = 1.0, b = cos(0.5 * alpha), d = 2.0 * sq * sq; /* d = a - b, exactly formed */
    double s = 0.0;                                          /* 1 - AGM = sum of d_n / 2 */
    for (int i = 0; i < 40 && d > 1e-17 * s; i++) {
        s += 0.5 * d;
        const double ra = sqrt(a), rb = sqrt(b), an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
        d = 0.5 * (d / (ra + rb)) * (d / (ra + rb)); /* (sqrt a - sqrt b)^2 / 2 */
    }
    return s / (0.5 * (a + b)); /* 1/AGM - 1 = (1 - AGM)/AGM */
}

/* ---- the system ------------------------------------------------------------ */

struct pend {
    struct mech_vec3 W; /* Earth rotation in local axes (rad/s) */
    double l, l2, g;
    int centrifugal;
    long nforce;
};

/* Acceleration per unit mass except the Coriolis and tension terms, at
 * u = r - s (s = (0, 0, l)): g + [-W x (W x r)]. */
static struct mech_vec3 pend_force(struct pend *P, struct mech_vec3 u)
{
    struct mech_vec3 a = mech_vec3_make(0.0, 0.0, -P->g);
    P->nforce++;
    if (P->centrifugal) {
        struct mech_vec3 r = mech_vec3_make(u.x, u.y, u.z + P->l);
        a = mech_vec3_sub(a, mech_vec3_cross(P->W, mech_vec3_cross(P->W, r)));
    }
    return a;
}

/* Height above the rest point on the sphere: z = l + u_z = rho^2 / (l - u_z)
 * (no cancellation at small amplitude, where l + u_z would lose every digit). */
static double pend_height(double l, struct mech_vec3 u)
{
    return (u.x * u.x + u.y * u.y) / (l - u.z);
}

/* Jacobi integral per unit mass: |v|^2/2 + g z - [|W x r|^2/2]. */
static double pend_energy(const struct pend *P, struct mech_vec3 u, struct mech_vec3 v)
{
    double z = pend_height(P->l, u);
    double e = 0.5 * mech_vec3_dot(v, v) + P->g * z;
    if (P->centrifugal) {
        struct mech_vec3 r = mech_vec3_make(u.x, u.y, z);
        struct mech_vec3 wr = mech_vec3_cross(P->W, r);
        e -= 0.5 * mech_vec3_dot(wr, wr);
    }
    return e;
}

/* (I + K)^-1 x with K x = k x x. */
static struct mech_vec3 cayley_inv(struct mech_vec3 k, double k2, struct mech_vec3 x)
{
    struct mech_vec3 y = mech_vec3_sub(x, mech_vec3_cross(k, x));
    y = mech_vec3_add(y, mech_vec3_scale(k, mech_vec3_dot(k, x)));
    return mech_vec3_scale(y, 1.0 / (1.0 + k2));
}

/* One RATTLE step of length h (may be negative) from (u, v) with the force f
 * at u; on return f is the force at the new u. Returns 0 if the constraint
 * equation has no real root (step far too long) or a value is non-finite. */
static int pend_step(struct pend *P, double h, struct mech_vec3 *u, struct mech_vec3 *v,
                     struct mech_vec3 *f)
{
    struct mech_vec3 k = mech_vec3_scale(P->W, h);
    double k2 = mech_vec3_dot(k, k);
    struct mech_vec3 u0 = *u;
    struct mech_vec3 a = mech_vec3_add(*v, mech_vec3_scale(*f, 0.5 * h));
    struct mech_vec3 w0 = cayley_inv(k, k2, a);
    struct mech_vec3 mu_dir = cayley_inv(k, k2, u0);
    struct mech_vec3 D = mech_vec3_scale(w0, h);
    struct mech_vec3 d = mech_vec3_scale(mu_dir, h);
    /* |u0 + D + m d|^2 = l^2:  A m^2 + 2 B m + c0 = 0; c0 carries the
     * current constraint residual so round-off never accumulates. */
    double c0 = (mech_vec3_dot(u0, u0) - P->l2) + 2.0 * mech_vec3_dot(u0, D) + mech_vec3_dot(D, D);
    double B = mech_vec3_dot(u0, d) + mech_vec3_dot(D, d);
    double A = mech_vec3_dot(d, d);
    double disc = B * B - A * c0;
    if (!(disc >= 0.0) || !isfinite(disc)) return 0;
    double den = B + copysign(sqrt(disc), B);
    if (den == 0.0) return 0;
    double m = -c0 / den; /* the root of smaller magnitude (the physical tension) */
    struct mech_vec3 w = mech_vec3_add(w0, mech_vec3_scale(mu_dir, m));
    struct mech_vec3 u1 = mech_vec3_add(u0, mech_vec3_scale(w, h));
    struct mech_vec3 f1 = pend_force(P, u1);
    struct mech_vec3 v1 = mech_vec3_sub(w, mech_vec3_cross(k, w));
    v1 = mech_vec3_add(v1, mech_vec3_scale(f1, 0.5 * h));
    double uu = mech_vec3_dot(u1, u1);
    v1 = mech_vec3_sub(v1, mech_vec3_scale(u1, mech_vec3_dot(v1, u1) / uu));
    if (!mech_vec3_isfinite(u1) || !mech_vec3_isfinite(v1)) return 0;
    *u = u1;
    *v = v1;
    *f = f1;
    return 1;
}

/* ---- turning points ---------------------------------------------------------- */

/* Cubic Hermite interpolant of the horizontal motion over one step. */
struct hermite {
    double x0, y0, x1, y1, mx0, my0, mx1, my1; /* m, and h * velocity (m) */
    double h;
};

static void hermite_eval(const struct hermite *H, double s, double *x, double *y, double *dx,
                         double *dy)
{
    double s2 = s * s, s3 = s2 * s;
    double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s,
           d11 = 3 * s2 - 2 * s;
    *x = h00 * H->x0 + h10 * H->mx0 + h01 * H->x1 + h11 * H->mx1;
    *y = h00 * H->y0 + h10 * H->my0 + h01 * H->y1 + h11 * H->my1;
    *dx = (d00 * H->x0 + d10 * H->mx0 + d01 * H->x1 + d11 * H->mx1) / H->h;
    *dy = (d00 * H->y0 + d10 * H->my0 + d01 * H->y1 + d11 * H->my1) / H->h;
}

/* Root of x x' + y y' on [0, 1] (f0 = value at 0, f1 at 1, opposite signs or
 * f0 == 0) by the Illinois false-position method; returns s and the point. */
static double hermite_turn(const struct hermite *H, double f0, double f1, double *x, double *y)
{
    double a = 0.0, b = 1.0, fa = f0, fb = f1, s = 0.0;
    int side = 0;
    if (f0 == 0.0) {
        *x = H->x0;
        *y = H->y0;
        return 0.0;
    }
    for (int i = 0; i < 100; i++) {
        double dx, dy;
        s = (a * fb - b * fa) / (fb - fa);
        if (!(s > a && s < b)) s = 0.5 * (a + b);
        hermite_eval(H, s, x, y, &dx, &dy);
        double fs = *x * dx + *y * dy;
        if (fs == 0.0 || b - a < 1e-15) break;
        if ((fs > 0) == (fa > 0)) {
            a = s;
            fa = fs;
            if (side == -1) fb *= 0.5;
            side = -1;
        } else {
            b = s;
            fb = fs;
            if (side == 1) fa *= 0.5;
            side = 1;
        }
    }
    return s;
}

/* Online least-squares line (Welford-style co-moments: no cancellation). */
struct fit {
    long n;
    double mt, my, ctt, cty, cyy;
};

static void fit_add(struct fit *F, double t, double y)
{
    F->n++;
    double dt = t - F->mt, dy = y - F->my;
    F->mt += dt / (double)F->n;
    F->my += dy / (double)F->n;
    F->ctt += dt * (t - F->mt);
    F->cty += dt * (y - F->my);
    F->cyy += dy * (y - F->my);
}

static struct mech_pendulum_fit fit_result(const struct fit *F)
{
    struct mech_pendulum_fit r = {F->n, 0.0, 0.0, 0.0};
    if (F->n < 2 || !(F->ctt > 0.0)) return r;
    r.slope = F->cty / F->ctt;
    double ssr = F->cyy - r.slope * F->cty;
    if (ssr < 0.0) ssr = 0.0;
    r.rms_residual = sqrt(ssr / (double)F->n);
    if (F->n > 2) r.stderr_slope = sqrt(ssr / (double)(F->n - 2) / F->ctt);
    return r;
}

/* ---- the run ------------------------------------------------------------------ */

static enum mech_status pend_validate(const struct mech_foucault_problem *p, struct mech_error *err)
{
    if (!(p->length > 0.0 && p->length <= 1e7))
        return mech_error_set(err, MECH_EDOMAIN, "length",
                              "length must be in (0, 1e7] m, got %.17g", p->length);
    if (!(p->g > 0.0 && p->g <= 1e4))
        return mech_error_set(err, MECH_EDOMAIN, "g", "g must be in (0, 1e4] m/s^2, got %.17g",
                              p->g);
    if (!(p->latitude_deg >= -90.0 && p->latitude_deg <= 90.0))
        return mech_error_set(err, MECH_EDOMAIN, "latitude_deg",
                              "latitude must be in [-90, 90] degrees, got %.17g", p->latitude_deg);
    if (!(p->omega_magnitude >= 0.0 && p->omega_magnitude <= 1.0))
        return mech_error_set(err, MECH_EDOMAIN, "omega_magnitude",
                              "omega_magnitude must be in [0, 1] rad/s, got %.17g",
                              p->omega_magnitude);
    if (!(p->mass > 0.0 && p->mass <= 1e30))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "mass must be in (0, 1e30] kg, got %.17g",
                              p->mass);
    if (!(p->amplitude_deg > 0.0 && p->amplitude_deg < 90.0))
        return mech_error_set(err, MECH_EDOMAIN, "release/amplitude_deg",
                              "amplitude must be in (0, 90) degrees, got %.17g", p->amplitude_deg);
    if (!isfinite(p->azimuth_deg) || fabs(p->azimuth_deg) > 1e6)
        return mech_error_set(err, MECH_EINVAL, "release/azimuth_deg",
                              "azimuth must be finite, |azimuth| <= 1e6 degrees");
    if (!(fabs(p->transverse_velocity) <= 1e6))
        return mech_error_set(err, MECH_EINVAL, "release/transverse_velocity",
                              "transverse velocity must be finite, |v| <= 1e6 m/s");
    if (!(p->t_end > 0.0 && isfinite(p->t_end)))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0 s");
    if (p->steps < 1) return mech_error_set(err, MECH_EINVAL, "steps", "steps must be >= 1");
    if (!mech_pendulum_method_name(p->method))
        return mech_error_set(err, MECH_EINVAL, "method", "unknown pendulum method");
    double omega0 = sqrt(p->g / p->length);
    double h = p->t_end / (double)p->steps;
    double rate = fmax(omega0, p->omega_magnitude);
    if (!(h * rate <= 2.0 * MECH_PI / 6.0))
        return mech_error_set(err, MECH_EDOMAIN, "steps",
                              "step %.6g s is longer than 1/6 of the pendulum's period or of the "
                              "rotation (%.6g s): give more steps",
                              h, 2.0 * MECH_PI / rate);
    double a = p->length * sin(p->amplitude_deg * MECH_PI / 180.0);
    if (fabs(p->transverse_velocity) > 0.5 * a * omega0)
        return mech_error_set(err, MECH_EDOMAIN, "release/transverse_velocity",
                              "|transverse velocity| %.6g m/s exceeds half of a omega0 = %.6g m/s: "
                              "the path is too round (b/a > 1/2) to have a swing plane",
                              fabs(p->transverse_velocity), 0.5 * a * omega0);
    return MECH_OK;
}

enum mech_status mech_foucault_integrate(const struct mech_foucault_problem *p,
                                         const struct mech_budget *budget,
                                         struct mech_foucault_result *res, struct mech_error *err)
{
    if (!p || !res)
        return mech_error_set(err, MECH_EINVAL, NULL, "mech_foucault_integrate: NULL argument");
    enum mech_status st = pend_validate(p, err);
    if (st != MECH_OK) return st;
    st = mech_budget_check(budget, 0, 1, err);
    if (st != MECH_OK) return st;
    double h = p->t_end / (double)p->steps;
    if (p->steps > budget->max_steps) {
        if (err && err->code == MECH_OK) {
            mech_error_set(err, MECH_EBUDGET, "steps", "%ld steps needed, the step budget is %ld",
                           p->steps, budget->max_steps);
            err->progress.steps = 0;
            err->progress.t_reached = (double)budget->max_steps * h;
            err->progress.t_target = p->t_end;
        }
        return MECH_EBUDGET;
    }

    const double deg = MECH_PI / 180.0;
    double lat = p->latitude_deg * deg, alpha = p->amplitude_deg * deg, az = p->azimuth_deg * deg;
    struct pend P;
    P.W = mech_vec3_make(0.0, p->omega_magnitude * cos(lat), p->omega_magnitude * sin(lat));
    if (p->latitude_deg == 90.0 || p->latitude_deg == -90.0) P.W.y = 0.0;
    P.l = p->length;
    P.l2 = p->length * p->length;
    P.g = p->g;
    P.centrifugal = p->centrifugal != 0;
    P.nforce = 0;

    *res = (struct mech_foucault_result){0};
    double wz = P.W.z;
    res->omega_vertical = wz;
    res->omega0 = sqrt(p->g / p->length);
    res->small_amplitude_period = 2.0 * MECH_PI * sqrt(p->length / p->g);
    res->finite_amplitude_period = mech_pendulum_period(p->length, p->g, alpha);

    /* release: notes §1.3 "pick the initial conditions ... to give cosine" */
    double rho0 = p->length * sin(alpha);
    struct mech_vec3 u = mech_vec3_make(rho0 * cos(az), rho0 * sin(az), -p->length * cos(alpha));
    struct mech_vec3 v =
        mech_vec3_make(-p->transverse_velocity * sin(az), p->transverse_velocity * cos(az), 0.0);
    res->h_vertical = u.x * v.y - u.y * v.x + wz * (u.x * u.x + u.y * u.y);
    res->airy_rate = 0.375 * res->h_vertical / P.l2;

    double e0 = pend_energy(&P, u, v);
    double escale = fabs(e0) > 0.0 ? fabs(e0) : 1.0;
    struct mech_vec3 f = pend_force(&P, u);

    double sub[3];
    int nsub;
    if (p->method == MECH_PENDULUM_RATTLE_YOSHIDA4) {
        double g1 = 1.0 / (2.0 - cbrt(2.0));
        sub[0] = g1 * h;
        sub[1] = (1.0 - 2.0 * g1) * h;
        sub[2] = g1 * h;
        nsub = 3;
    } else {
        sub[0] = h;
        nsub = 1;
    }

    struct fit psi_fit = {0}, h_fit = {0};
    double hcur = res->h_vertical, Hint = 0.0, max_v = mech_vec3_norm(v);
    double max_r = mech_vec3_norm(mech_vec3_make(u.x, u.y, pend_height(p->length, u)));
    double psi_prev = 0.0, t_first = 0.0, t_last = 0.0, apo_sum = 0.0, peri_sum = 0.0;
    long napo = 0, nperi = 0;
    double fprev = u.x * v.x + u.y * v.y;
    double max_de = 0.0, max_dc = 0.0, max_tan = 0.0;
    /* the swing's speed scale: |u.v| is compared with l times it (near the
     * rosette's cusps |v| itself is ~0 and would make any ratio meaningless) */
    double vref = sqrt(2.0 * p->g * p->length * (1.0 - cos(alpha))) + fabs(p->transverse_velocity);

    for (long n = 1; n <= p->steps; n++) {
        st = mech_budget_check(budget, n, 0, err);
        if (st != MECH_OK) {
            if (err) {
                err->progress.t_reached = (double)(n - 1) * h;
                err->progress.t_target = p->t_end;
            }
            return st;
        }
        struct mech_vec3 u0 = u, v0 = v;
        for (int j = 0; j < nsub; j++) {
            if (!pend_step(&P, sub[j], &u, &v, &f))
                return mech_error_set(err, MECH_ENUMERIC, "steps",
                                      "the constrained step failed at t = %.6g s (step too long "
                                      "or a non-finite value)",
                                      (double)(n - 1) * h);
        }
        double t0 = (double)(n - 1) * h, t1 = (double)n * h;

        /* conservation */
        double de = fabs(pend_energy(&P, u, v) - e0) / escale;
        double dc = fabs(mech_vec3_norm(u) - p->length) / p->length;
        double vn = mech_vec3_norm(v);
        double tan_err = fabs(mech_vec3_dot(u, v)) / (p->length * vref);
        if (de > max_de) max_de = de;
        if (dc > max_dc) max_dc = dc;
        if (tan_err > max_tan) max_tan = tan_err;
        if (vn > max_v) max_v = vn;
        double rn = mech_vec3_norm(mech_vec3_make(u.x, u.y, pend_height(p->length, u)));
        if (rn > max_r) max_r = rn;
        double hprev = hcur, Hprev = Hint;
        hcur = u.x * v.y - u.y * v.x + wz * (u.x * u.x + u.y * u.y);
        Hint += 0.5 * h * (hprev + hcur);

        /* turning points: x x' + y y' falls through 0 (apocentre) or rises (pericentre) */
        double fcur = u.x * v.x + u.y * v.y;
        int apo = fprev >= 0.0 && fcur < 0.0, peri = fprev <= 0.0 && fcur > 0.0;
        if (apo || peri) {
            struct hermite H = {u0.x, u0.y, u.x, u.y, h * v0.x, h * v0.y, h * v.x, h * v.y, h};
            double x, y;
            double s = hermite_turn(&H, fprev, fcur, &x, &y);
            double tt = t0 + s * (t1 - t0);
            double rho = hypot(x, y);
            if (apo) {
                double psi = atan2(y, x);
                if (napo > 0) psi += MECH_PI * nearbyint((psi_prev - psi) / MECH_PI);
                psi_prev = psi;
                fit_add(&psi_fit, tt, psi);
                fit_add(&h_fit, tt, Hprev + s * h * (hprev + 0.5 * s * (hcur - hprev)));
                if (napo == 0) t_first = tt;
                t_last = tt;
                apo_sum += rho;
                napo++;
            } else {
                peri_sum += rho;
                nperi++;
            }
        }
        fprev = fcur;
    }

    res->turning_points = napo;
    res->pericentres = nperi;
    res->precession = fit_result(&psi_fit);
    if (napo >= 2) {
        res->period = 2.0 * (t_last - t_first) / (double)(napo - 1);
        res->swings = p->t_end / res->period;
    }
    res->airy_rate_mean = 0.375 * fit_result(&h_fit).slope / P.l2;
    res->max_speed = max_v;
    res->max_displacement = max_r;
    res->mean_apocentre = napo > 0 ? apo_sum / (double)napo : 0.0;
    res->mean_pericentre = nperi > 0 ? peri_sum / (double)nperi : 0.0;
    res->energy_initial = p->mass * e0;
    res->max_relative_energy_drift = max_de;
    res->max_constraint_error = max_dc;
    res->max_tangency_error = max_tan;
    res->final_position = mech_vec3_make(u.x, u.y, pend_height(p->length, u));
    res->final_velocity = v;
    res->steps = p->steps;
    res->force_evaluations = P.nforce;
    if (napo < 3)
        return mech_error_set(err, MECH_EDOMAIN, "t_end",
                              "only %ld turning points in %.6g s: run at least two swings to "
                              "measure a precession",
                              napo, p->t_end);
    if (!isfinite(res->precession.slope) || !isfinite(res->period) ||
        !isfinite(res->airy_rate_mean) || !isfinite(res->max_relative_energy_drift))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite result");
    return MECH_OK;
}
