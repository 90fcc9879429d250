/* hamiltonian.c — the catalog of Hamiltonian systems of mech/hamiltonian/hamiltonian.h:
 * H(q, p), its first and second derivatives (Hamilton's equations and their
 * variational equations), cyclic coordinates and conserved momenta, the
 * ensemble ODE (many trajectories with tangent vectors, in first- or
 * second-order form) and the flow with energy / momentum drift.
 *
 * Sources: Goldstein, Poole & Safko, Classical Mechanics, 3rd ed. (2002),
 * §8.1 (Hamilton's equations, eq. 8.18), §8.2 (cyclic coordinates and
 * conservation theorems), §9.9 (Liouville's theorem); Taylor, Classical
 * Mechanics (2005), ch. 13 (§13.2–13.4: Hamilton's equations, ignorable
 * coordinates). The variational equations d(dy)/dt = J Hess(H) dy are the
 * linearisation of y' = J grad H (Hairer, Lubich & Wanner, Geometric
 * Numerical Integration, 2nd ed., §VI.2).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ode/integrators/integrator.h"
#include "mech/hamiltonian/hamiltonian.h"

/* ---- the catalog ------------------------------------------------------------ */

enum mech_status mech_ham_system_check(struct mech_ham_system *s, struct mech_error *err)
{
    if (!s) return mech_error_set(err, MECH_EINVAL, NULL, "no system given");
#define POS(field, name)                                                                     \
    if (!(isfinite(s->field) && s->field > 0.0))                                             \
        return mech_error_set(err, MECH_EDOMAIN, "system/" name, name " must be > 0, got %.17g", \
                              s->field);
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
        if (s->dof != 1 && s->dof != 2)
            return mech_error_set(err, MECH_EINVAL, "q",
                                  "the oscillator has 1 or 2 degrees of freedom, got %d", s->dof);
        POS(mass, "mass");
        for (int i = 0; i < s->dof; i++)
            if (!(isfinite(s->k[i]) && s->k[i] > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, i ? "system/k/1" : "system/k/0",
                                      "spring constants must be > 0, got %.17g", s->k[i]);
        return MECH_OK;
    case MECH_HAM_PENDULUM:
    case MECH_HAM_SPHERICAL_PENDULUM:
        s->dof = s->kind == MECH_HAM_PENDULUM ? 1 : 2;
        POS(mass, "mass");
        POS(length, "length");
        if (!(isfinite(s->g) && s->g >= 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "system/g", "g must be >= 0, got %.17g", s->g);
        return MECH_OK;
    case MECH_HAM_CYLINDER:
        s->dof = 2;
        POS(mass, "mass");
        POS(radius, "radius");
        if (!(isfinite(s->strength) && s->strength >= 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "system/k", "k must be >= 0, got %.17g",
                                  s->strength);
        return MECH_OK;
    case MECH_HAM_CENTRAL:
    case MECH_HAM_POTENTIAL_3D:
        s->dof = s->kind == MECH_HAM_CENTRAL ? 2 : 3;
        POS(mass, "mass");
        if (s->kind == MECH_HAM_POTENTIAL_3D && s->potential == MECH_HAM_POT_HARMONIC) {
            for (int i = 0; i < 3; i++)
                if (!(isfinite(s->k[i]) && s->k[i] > 0.0))
                    return mech_error_set(err, MECH_EDOMAIN,
                                          i == 0 ? "system/k/0" : i == 1 ? "system/k/1" : "system/k/2",
                                          "spring constants must be > 0, got %.17g", s->k[i]);
            return MECH_OK;
        }
        if (s->kind == MECH_HAM_POTENTIAL_3D && s->potential != MECH_HAM_POT_POWER)
            return mech_error_set(err, MECH_EINVAL, "system/potential", "unknown potential");
        if (!(isfinite(s->strength) && s->strength != 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "system/k", "k must be non-zero, got %.17g",
                                  s->strength);
        if (!(isfinite(s->power) && s->power != 0.0 && fabs(s->power) <= 20.0))
            return mech_error_set(err, MECH_EDOMAIN, "system/n",
                                  "the exponent n must be non-zero with |n| <= 20, got %.17g",
                                  s->power);
        return MECH_OK;
    case MECH_HAM_HENON_HEILES:
        s->dof = 2;
        s->mass = 1.0;
        return MECH_OK;
    default:
        return mech_error_set(err, MECH_EINVAL, "system/name", "unknown system");
    }
#undef POS
}

size_t mech_ham_dim(const struct mech_ham_system *s)
{
    return 2u * (size_t)s->dof;
}

const char *mech_ham_coordinate_name(const struct mech_ham_system *s, size_t i)
{
    static const char *const xyz[] = {"x", "y", "z"};
    switch (s->kind) {
    case MECH_HAM_PENDULUM: return "theta";
    case MECH_HAM_SPHERICAL_PENDULUM: return i == 0 ? "theta" : "phi";
    case MECH_HAM_CYLINDER: return i == 0 ? "z" : "phi";
    case MECH_HAM_CENTRAL: return i == 0 ? "r" : "phi";
    default: return i < 3 ? xyz[i] : "?";
    }
}

const char *mech_ham_momentum_name(const struct mech_ham_system *s, size_t i)
{
    static const char *const pxyz[] = {"p_x", "p_y", "p_z"};
    switch (s->kind) {
    case MECH_HAM_PENDULUM: return "p_theta";
    case MECH_HAM_SPHERICAL_PENDULUM: return i == 0 ? "p_theta" : "p_phi";
    case MECH_HAM_CYLINDER: return i == 0 ? "p_z" : "p_phi";
    case MECH_HAM_CENTRAL: return i == 0 ? "p_r" : "p_phi";
    default: return i < 3 ? pxyz[i] : "?";
    }
}

static double norm3(const double *x)
{
    return hypot(hypot(x[0], x[1]), x[2]);
}

enum mech_status mech_ham_state_check(const struct mech_ham_system *s, const double *y,
                                      struct mech_error *err)
{
    const size_t n = (size_t)s->dof;
    for (size_t i = 0; i < 2 * n; i++)
        if (!isfinite(y[i]))
            return mech_error_set(err, MECH_EDOMAIN, i < n ? "q" : "p", "non-finite initial state");
    switch (s->kind) {
    case MECH_HAM_SPHERICAL_PENDULUM:
        if (sin(y[0]) == 0.0 && y[3] != 0.0)
            return mech_error_set(err, MECH_EDOMAIN, "p/1",
                                  "p_phi = m l^2 sin^2(theta) phi' must be 0 at the pole "
                                  "theta = %.17g (sin theta = 0); got %.17g",
                                  y[0], y[3]);
        return MECH_OK;
    case MECH_HAM_CENTRAL:
        if (!(y[0] > 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "q/0",
                                  "r must be > 0 (plane polar coordinates), got %.17g", y[0]);
        return MECH_OK;
    case MECH_HAM_POTENTIAL_3D:
        if (s->potential == MECH_HAM_POT_POWER && !(norm3(y) > 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "q",
                                  "r = |q| must be > 0: V = K r^n is singular or not smooth at "
                                  "the origin");
        return MECH_OK;
    default: return MECH_OK;
    }
}

/* Singularity messages for the flow (MECH_ENUMERIC). */
static enum mech_status hit_centre(struct mech_error *err, double r)
{
    return mech_error_set(err, MECH_ENUMERIC, NULL,
                          "the orbit reached the centre (r = %.3g): the potential is singular "
                          "there; use a smaller dt, an adaptive method, or a larger angular "
                          "momentum",
                          r);
}

static enum mech_status hit_pole(struct mech_error *err, double th)
{
    return mech_error_set(err, MECH_ENUMERIC, NULL,
                          "the spherical pendulum reached the pole (theta = %.3g, sin theta = 0) "
                          "with p_phi != 0: the step was too large for the centrifugal barrier",
                          th);
}

/* dH/dq and dH/dp at y. */
static enum mech_status derivs(const struct mech_ham_system *s, const double *y, double *Hq,
                               double *Hp, struct mech_error *err)
{
    const size_t n = (size_t)s->dof;
    const double *q = y, *p = y + n;
    const double m = s->mass;
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
        for (size_t i = 0; i < n; i++) {
            Hq[i] = s->k[i] * q[i];
            Hp[i] = p[i] / m;
        }
        return MECH_OK;
    case MECH_HAM_PENDULUM: {
        const double M = m * s->length * s->length;
        Hq[0] = m * s->g * s->length * sin(q[0]);
        Hp[0] = p[0] / M;
        return MECH_OK;
    }
    case MECH_HAM_SPHERICAL_PENDULUM: {
        const double M = m * s->length * s->length, sn = sin(q[0]), cs = cos(q[0]);
        double cent = 0.0, rate = 0.0;
        if (p[1] != 0.0) {
            if (sn == 0.0) return hit_pole(err, q[0]);
            rate = p[1] / (M * sn * sn);        /* phi' */
            cent = -p[1] * rate * cs / sn;      /* -p_phi^2 cos / (M sin^3) */
        }
        Hq[0] = cent + m * s->g * s->length * sn;
        Hq[1] = 0.0;
        Hp[0] = p[0] / M;
        Hp[1] = rate;
        return MECH_OK;
    }
    case MECH_HAM_CYLINDER:
        Hq[0] = s->strength * q[0];
        Hq[1] = 0.0;
        Hp[0] = p[0] / m;
        Hp[1] = p[1] / (m * s->radius * s->radius);
        return MECH_OK;
    case MECH_HAM_CENTRAL: {
        const double r = q[0];
        if (!(r > 0.0)) return hit_centre(err, r);
        const double rate = p[1] / (m * r * r);
        Hq[0] = -p[1] * rate / r + s->strength * s->power * pow(r, s->power - 1.0);
        Hq[1] = 0.0;
        Hp[0] = p[0] / m;
        Hp[1] = rate;
        return MECH_OK;
    }
    case MECH_HAM_HENON_HEILES:
        /* H = (px^2 + py^2)/2 + (x^2 + y^2)/2 + x^2 y - y^3/3 */
        Hq[0] = q[0] + 2.0 * q[0] * q[1];
        Hq[1] = q[1] + q[0] * q[0] - q[1] * q[1];
        Hp[0] = p[0];
        Hp[1] = p[1];
        return MECH_OK;
    case MECH_HAM_POTENTIAL_3D:
        if (s->potential == MECH_HAM_POT_HARMONIC) {
            for (size_t i = 0; i < 3; i++) Hq[i] = s->k[i] * q[i];
        } else {
            const double r = norm3(q);
            if (!(r > 0.0)) return hit_centre(err, r);
            const double f = s->strength * s->power * pow(r, s->power - 2.0);
            for (size_t i = 0; i < 3; i++) Hq[i] = f * q[i];
        }
        for (size_t i = 0; i < 3; i++) Hp[i] = p[i] / m;
        return MECH_OK;
    default: return mech_error_set(err, MECH_EINTERNAL, NULL, "unknown system kind");
    }
}

/* Second derivatives: Hqq[i][j] = d2H/dq_i dq_j, Hqp[i][j] = d2H/dq_i dp_j,
 * Hpp[i][j] = d2H/dp_i dp_j (all zeroed first). */
static enum mech_status hessian(const struct mech_ham_system *s, const double *y,
                                double Hqq[3][3], double Hqp[3][3], double Hpp[3][3],
                                struct mech_error *err)
{
    const size_t n = (size_t)s->dof;
    const double *q = y, *p = y + n;
    const double m = s->mass;
    memset(Hqq, 0, 9 * sizeof(double));
    memset(Hqp, 0, 9 * sizeof(double));
    memset(Hpp, 0, 9 * sizeof(double));
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
        for (size_t i = 0; i < n; i++) {
            Hqq[i][i] = s->k[i];
            Hpp[i][i] = 1.0 / m;
        }
        return MECH_OK;
    case MECH_HAM_PENDULUM: {
        const double M = m * s->length * s->length;
        Hqq[0][0] = m * s->g * s->length * cos(q[0]);
        Hpp[0][0] = 1.0 / M;
        return MECH_OK;
    }
    case MECH_HAM_SPHERICAL_PENDULUM: {
        /* d/dtheta (cos/sin^3) = -1/sin^2 - 3 cos^2/sin^4 */
        const double M = m * s->length * s->length, sn = sin(q[0]), cs = cos(q[0]);
        if (sn == 0.0) return hit_pole(err, q[0]);
        const double s2 = sn * sn;
        Hqq[0][0] = p[1] * p[1] / M * (1.0 / s2 + 3.0 * cs * cs / (s2 * s2)) +
                    m * s->g * s->length * cs;
        Hqp[0][1] = -2.0 * p[1] * cs / (M * s2 * sn);
        Hpp[0][0] = 1.0 / M;
        Hpp[1][1] = 1.0 / (M * s2);
        return MECH_OK;
    }
    case MECH_HAM_CYLINDER:
        Hqq[0][0] = s->strength;
        Hpp[0][0] = 1.0 / m;
        Hpp[1][1] = 1.0 / (m * s->radius * s->radius);
        return MECH_OK;
    case MECH_HAM_CENTRAL: {
        const double r = q[0];
        if (!(r > 0.0)) return hit_centre(err, r);
        const double r2 = r * r;
        Hqq[0][0] = 3.0 * p[1] * p[1] / (m * r2 * r2) +
                    s->strength * s->power * (s->power - 1.0) * pow(r, s->power - 2.0);
        Hqp[0][1] = -2.0 * p[1] / (m * r2 * r);
        Hpp[0][0] = 1.0 / m;
        Hpp[1][1] = 1.0 / (m * r2);
        return MECH_OK;
    }
    case MECH_HAM_HENON_HEILES:
        Hqq[0][0] = 1.0 + 2.0 * q[1];
        Hqq[0][1] = Hqq[1][0] = 2.0 * q[0];
        Hqq[1][1] = 1.0 - 2.0 * q[1];
        Hpp[0][0] = Hpp[1][1] = 1.0;
        return MECH_OK;
    case MECH_HAM_POTENTIAL_3D:
        if (s->potential == MECH_HAM_POT_HARMONIC) {
            for (size_t i = 0; i < 3; i++) Hqq[i][i] = s->k[i];
        } else {
            /* Hess(K r^n) = K n r^(n-2) (I + (n-2) x x^T / r^2) */
            const double r = norm3(q);
            if (!(r > 0.0)) return hit_centre(err, r);
            const double f = s->strength * s->power * pow(r, s->power - 2.0);
            const double g = f * (s->power - 2.0) / (r * r);
            for (size_t i = 0; i < 3; i++)
                for (size_t j = 0; j < 3; j++) Hqq[i][j] = g * q[i] * q[j] + (i == j ? f : 0.0);
        }
        for (size_t i = 0; i < 3; i++) Hpp[i][i] = 1.0 / m;
        return MECH_OK;
    default: return mech_error_set(err, MECH_EINTERNAL, NULL, "unknown system kind");
    }
}

/* dv = J Hess(H) v: d(dq)_i = sum_j Hqp[j][i] dq_j + Hpp[i][j] dp_j,
 * d(dp)_i = -sum_j Hqq[i][j] dq_j + Hqp[i][j] dp_j. */
static void tangent_apply(size_t n, double Hqq[3][3], double Hqp[3][3], double Hpp[3][3],
                          const double *v, double *dv)
{
    for (size_t i = 0; i < n; i++) {
        double a = 0.0, b = 0.0;
        for (size_t j = 0; j < n; j++) {
            a += Hqp[j][i] * v[j] + Hpp[i][j] * v[n + j];
            b -= Hqq[i][j] * v[j] + Hqp[i][j] * v[n + j];
        }
        dv[i] = a;
        dv[n + i] = b;
    }
}

double mech_ham_potential_energy(const struct mech_ham_system *s, const double *q)
{
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR: {
        double V = 0.0;
        for (int i = 0; i < s->dof; i++) V += 0.5 * s->k[i] * q[i] * q[i];
        return V;
    }
    case MECH_HAM_PENDULUM:
    case MECH_HAM_SPHERICAL_PENDULUM: {
        /* 1 - cos theta = 2 sin^2(theta/2), without cancellation near 0 */
        const double h = sin(0.5 * q[0]);
        return s->mass * s->g * s->length * 2.0 * h * h;
    }
    case MECH_HAM_CYLINDER:
        return 0.5 * s->strength * (s->radius * s->radius + q[0] * q[0]);
    case MECH_HAM_CENTRAL:
        return q[0] > 0.0 ? s->strength * pow(q[0], s->power) : NAN;
    case MECH_HAM_HENON_HEILES:
        return 0.5 * (q[0] * q[0] + q[1] * q[1]) + q[0] * q[0] * q[1] - q[1] * q[1] * q[1] / 3.0;
    case MECH_HAM_POTENTIAL_3D:
        if (s->potential == MECH_HAM_POT_HARMONIC)
            return 0.5 * (s->k[0] * q[0] * q[0] + s->k[1] * q[1] * q[1] + s->k[2] * q[2] * q[2]);
        else {
            const double r = norm3(q);
            return r > 0.0 ? s->strength * pow(r, s->power) : NAN;
        }
    default: return NAN;
    }
}

enum mech_status mech_ham_energy(const struct mech_ham_system *s, const double *y, double *E,
                                 struct mech_error *err)
{
    const size_t n = (size_t)s->dof;
    const double *q = y, *p = y + n;
    const double m = s->mass;
    double T = 0.0;
    switch (s->kind) {
    case MECH_HAM_PENDULUM: T = p[0] * p[0] / (2.0 * m * s->length * s->length); break;
    case MECH_HAM_SPHERICAL_PENDULUM: {
        const double M = m * s->length * s->length, sn = sin(q[0]);
        T = p[0] * p[0] / (2.0 * M);
        if (p[1] != 0.0) {
            if (sn == 0.0) return hit_pole(err, q[0]);
            T += p[1] * p[1] / (2.0 * M * sn * sn);
        }
        break;
    }
    case MECH_HAM_CYLINDER:
        T = p[0] * p[0] / (2.0 * m) + p[1] * p[1] / (2.0 * m * s->radius * s->radius);
        break;
    case MECH_HAM_CENTRAL:
        if (!(q[0] > 0.0)) return hit_centre(err, q[0]);
        T = p[0] * p[0] / (2.0 * m) + p[1] * p[1] / (2.0 * m * q[0] * q[0]);
        break;
    default:
        for (size_t i = 0; i < n; i++) T += p[i] * p[i] / (2.0 * m);
        break;
    }
    const double V = mech_ham_potential_energy(s, q);
    *E = T + V;
    if (!isfinite(*E))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "the energy is not finite (T = %.3g, V = %.3g)",
                              T, V);
    return MECH_OK;
}

enum mech_status mech_ham_rhs(const struct mech_ham_system *s, const double *y, double *dydt,
                              const double *v, double *dv, struct mech_error *err)
{
    const size_t n = (size_t)s->dof;
    double Hq[3], Hp[3];
    enum mech_status st = derivs(s, y, Hq, Hp, err);
    if (st != MECH_OK) return st;
    for (size_t i = 0; i < n; i++) {
        dydt[i] = Hp[i];
        dydt[n + i] = -Hq[i];
    }
    if (v && dv) {
        double Hqq[3][3], Hqp[3][3], Hpp[3][3];
        if ((st = hessian(s, y, Hqq, Hqp, Hpp, err)) != MECH_OK) return st;
        tangent_apply(n, Hqq, Hqp, Hpp, v, dv);
    }
    return MECH_OK;
}

int mech_ham_separable(const struct mech_ham_system *s, double *M)
{
    double mm[3] = {s->mass, s->mass, s->mass};
    int ok = 1;
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
    case MECH_HAM_HENON_HEILES:
    case MECH_HAM_POTENTIAL_3D: break;
    case MECH_HAM_PENDULUM: mm[0] = s->mass * s->length * s->length; break;
    case MECH_HAM_CYLINDER: mm[1] = s->mass * s->radius * s->radius; break;
    default: ok = 0;
    }
    if (ok && M)
        for (int i = 0; i < 3; i++) M[i] = mm[i];
    return ok;
}

size_t mech_ham_conserved_list(const struct mech_ham_system *s,
                               struct mech_ham_conserved out[MECH_HAM_MAX_CONSERVED])
{
    switch (s->kind) {
    case MECH_HAM_SPHERICAL_PENDULUM:
    case MECH_HAM_CYLINDER:
    case MECH_HAM_CENTRAL:
        out[0] = (struct mech_ham_conserved){"p_phi", 1, 1};
        return 1;
    case MECH_HAM_OSCILLATOR:
        if (s->dof == 2 && s->k[0] == s->k[1]) {
            out[0] = (struct mech_ham_conserved){"L_z", 0, 0};
            return 1;
        }
        return 0;
    case MECH_HAM_POTENTIAL_3D:
        if (s->potential == MECH_HAM_POT_POWER ||
            (s->k[0] == s->k[1] && s->k[1] == s->k[2])) {
            out[0] = (struct mech_ham_conserved){"L_x", 0, 0};
            out[1] = (struct mech_ham_conserved){"L_y", 0, 0};
            out[2] = (struct mech_ham_conserved){"L_z", 0, 0};
            return 3;
        }
        if (s->k[0] == s->k[1]) {
            out[0] = (struct mech_ham_conserved){"L_z", 0, 0};
            return 1;
        }
        return 0;
    default: return 0;
    }
}

double mech_ham_conserved_value(const struct mech_ham_system *s,
                                const struct mech_ham_conserved *c, const double *y)
{
    const size_t n = (size_t)s->dof;
    if (c->cyclic) return y[n + c->index];
    const double *q = y, *p = y + n;
    /* L = q x p in Cartesian coordinates (2D: the z component) */
    if (n == 2) return q[0] * p[1] - q[1] * p[0];
    switch (c->name[2]) {
    case 'x': return q[1] * p[2] - q[2] * p[1];
    case 'y': return q[2] * p[0] - q[0] * p[2];
    default: return q[0] * p[1] - q[1] * p[0];
    }
}

double mech_ham_time_scale(const struct mech_ham_system *s, const double *y)
{
    const size_t n = (size_t)s->dof;
    const double *q = y, *p = y + n;
    const double m = s->mass;
    double w = 0.0;
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
        for (size_t i = 0; i < n; i++) w = fmax(w, sqrt(s->k[i] / m));
        break;
    case MECH_HAM_PENDULUM:
    case MECH_HAM_SPHERICAL_PENDULUM: {
        const double M = m * s->length * s->length;
        w = sqrt(s->g / s->length) + fabs(p[0]) / M;
        if (s->kind == MECH_HAM_SPHERICAL_PENDULUM && p[1] != 0.0) {
            const double sn = sin(q[0]);
            if (sn != 0.0) w += fabs(p[1] / (M * sn * sn));
        }
        break;
    }
    case MECH_HAM_CYLINDER:
        w = sqrt(s->strength / m) + fabs(p[1]) / (m * s->radius * s->radius);
        break;
    case MECH_HAM_CENTRAL: {
        const double r = q[0];
        if (r > 0.0)
            w = sqrt(fabs(s->strength * s->power) * pow(r, s->power - 2.0) / m) +
                fabs(p[0]) / (m * r) + fabs(p[1]) / (m * r * r);
        break;
    }
    case MECH_HAM_HENON_HEILES: w = 1.0 + hypot(p[0], p[1]); break;
    case MECH_HAM_POTENTIAL_3D:
        if (s->potential == MECH_HAM_POT_HARMONIC) {
            for (size_t i = 0; i < 3; i++) w = fmax(w, sqrt(s->k[i] / m));
        } else {
            const double r = norm3(q);
            if (r > 0.0)
                w = sqrt(fabs(s->strength * s->power) * pow(r, s->power - 2.0) / m) +
                    norm3(p) / (m * r);
        }
        break;
    default: break;
    }
    return (isfinite(w) && w > 0.0) ? 1.0 / w : 1.0;
}

/* ---- ensembles ---------------------------------------------------------------- */

size_t mech_ham_ensemble_dim(const struct mech_ham_ensemble *e)
{
    return 2u * (size_t)e->sys->dof * e->n_traj * (1u + e->n_tan);
}

/* Offset of trajectory j's tangent k (k = 0: the state, k >= 1: tangent k-1) in the q-half. */
static size_t ens_off(const struct mech_ham_ensemble *e, size_t j, size_t k)
{
    const size_t n = (size_t)e->sys->dof;
    return (j * (1u + e->n_tan) + k) * n;
}

void mech_ham_ensemble_put(const struct mech_ham_ensemble *e, double *Y, size_t j,
                           const double *y, const double *const *tangents)
{
    const size_t n = (size_t)e->sys->dof, half = mech_ham_ensemble_dim(e) / 2;
    for (size_t k = 0; k <= e->n_tan; k++) {
        const double *src = k == 0 ? y : tangents[k - 1];
        const size_t o = ens_off(e, j, k);
        for (size_t i = 0; i < n; i++) {
            Y[o + i] = src[i];
            Y[half + o + i] = e->second_order ? src[n + i] / e->M[i] : src[n + i];
        }
    }
}

void mech_ham_ensemble_get(const struct mech_ham_ensemble *e, const double *Y, size_t j,
                           double *y, size_t k, double *tan)
{
    const size_t n = (size_t)e->sys->dof, half = mech_ham_ensemble_dim(e) / 2;
    for (size_t pass = 0; pass < 2; pass++) {
        double *dst = pass == 0 ? y : tan;
        if (!dst) continue;
        const size_t o = ens_off(e, j, pass == 0 ? 0 : k + 1);
        for (size_t i = 0; i < n; i++) {
            dst[i] = Y[o + i];
            dst[n + i] = e->second_order ? Y[half + o + i] * e->M[i] : Y[half + o + i];
        }
    }
}

/* First-order form: (q, p) blocks; each trajectory's Hessian is computed once
 * for all its tangents. */
static enum mech_status ens_rhs_first(const struct mech_ham_ensemble *e, const double *Y,
                                      double *dY)
{
    const struct mech_ham_system *s = e->sys;
    const size_t n = (size_t)s->dof, half = mech_ham_ensemble_dim(e) / 2;
    for (size_t j = 0; j < e->n_traj; j++) {
        double y[MECH_HAM_MAX_DIM], Hq[3], Hp[3];
        const size_t o = ens_off(e, j, 0);
        for (size_t i = 0; i < n; i++) {
            y[i] = Y[o + i];
            y[n + i] = Y[half + o + i];
        }
        enum mech_status st = derivs(s, y, Hq, Hp, e->err);
        if (st != MECH_OK) return st;
        for (size_t i = 0; i < n; i++) {
            dY[o + i] = Hp[i];
            dY[half + o + i] = -Hq[i];
        }
        if (e->n_tan == 0) continue;
        double Hqq[3][3], Hqp[3][3], Hpp[3][3];
        if ((st = hessian(s, y, Hqq, Hqp, Hpp, e->err)) != MECH_OK) return st;
        for (size_t k = 1; k <= e->n_tan; k++) {
            const size_t ok = ens_off(e, j, k);
            double v[MECH_HAM_MAX_DIM], dv[MECH_HAM_MAX_DIM];
            for (size_t i = 0; i < n; i++) {
                v[i] = Y[ok + i];
                v[n + i] = Y[half + ok + i];
            }
            tangent_apply(n, Hqq, Hqp, Hpp, v, dv);
            for (size_t i = 0; i < n; i++) {
                dY[ok + i] = dv[i];
                dY[half + ok + i] = dv[n + i];
            }
        }
    }
    return MECH_OK;
}

/* Second-order form (separable H): a = -M^-1 dV/dq, tangent a = -M^-1 Hqq dq.
 * Q and V are the two halves; A gets the accelerations of the whole q-half. */
static enum mech_status ens_accel(const struct mech_ham_ensemble *e, const double *Q, double *A)
{
    const struct mech_ham_system *s = e->sys;
    const size_t n = (size_t)s->dof;
    for (size_t j = 0; j < e->n_traj; j++) {
        double y[MECH_HAM_MAX_DIM] = {0}, Hq[3], Hp[3];
        const size_t o = ens_off(e, j, 0);
        for (size_t i = 0; i < n; i++) y[i] = Q[o + i]; /* p = 0: dV/dq does not depend on it */
        enum mech_status st = derivs(s, y, Hq, Hp, e->err);
        if (st != MECH_OK) return st;
        for (size_t i = 0; i < n; i++) A[o + i] = -Hq[i] / e->M[i];
        if (e->n_tan == 0) continue;
        double Hqq[3][3], Hqp[3][3], Hpp[3][3];
        if ((st = hessian(s, y, Hqq, Hqp, Hpp, e->err)) != MECH_OK) return st;
        for (size_t k = 1; k <= e->n_tan; k++) {
            const size_t ok = ens_off(e, j, k);
            for (size_t i = 0; i < n; i++) {
                double a = 0.0;
                for (size_t l = 0; l < n; l++) a -= Hqq[i][l] * Q[ok + l];
                A[ok + i] = a / e->M[i];
            }
        }
    }
    return MECH_OK;
}

static enum mech_status ens_ode_rhs(double t, const double *Y, double *dY, void *params)
{
    (void)t;
    const struct mech_ham_ensemble *e = params;
    if (!e->second_order) return ens_rhs_first(e, Y, dY);
    const size_t half = mech_ham_ensemble_dim(e) / 2;
    memcpy(dY, Y + half, half * sizeof *dY);
    return ens_accel(e, Y, dY + half);
}

static enum mech_status ens_ode_accel(double t, const double *q, const double *v, double *a,
                                      void *params)
{
    (void)t;
    (void)v;
    return ens_accel(params, q, a);
}

/* Components of q that are one point's Cartesian coordinates, for step-size
 * control per particle (mech_ode_system.particle_dim): x (, y (, z)) of the
 * oscillator, Hénon–Heiles and potential_3d; 1 for generalised coordinates
 * (the pendulum's angle, the cylinder's z and phi), never put under one norm.
 * Each trajectory and each tangent of the ensemble is a block of dof. */
static size_t ham_particle_dim(const struct mech_ham_system *s)
{
    switch (s->kind) {
    case MECH_HAM_OSCILLATOR:
    case MECH_HAM_HENON_HEILES:
    case MECH_HAM_POTENTIAL_3D: return (size_t)s->dof;
    default: return 1;
    }
}

enum mech_status mech_ham_ensemble_init(struct mech_ham_ensemble *e,
                                        const struct mech_ham_system *s, size_t n_traj,
                                        size_t n_tan, const struct mech_integrator *m,
                                        struct mech_ode_system *sys_out, struct mech_error *err)
{
    if (!e || !s || !m || !sys_out || n_traj == 0)
        return mech_error_set(err, MECH_EINVAL, NULL, "incomplete ensemble");
    memset(e, 0, sizeof *e);
    memset(sys_out, 0, sizeof *sys_out);
    e->sys = s;
    e->n_traj = n_traj;
    e->n_tan = n_tan;
    e->err = err;
    if (m->flags & MECH_INTEGRATOR_SECOND_ORDER) {
        if (!mech_ham_separable(s, e->M))
            return mech_error_set(err, MECH_EINVAL, "integrator/method",
                                  "%s needs the second-order form q'' = a(q), which exists only "
                                  "for separable H = sum p_i^2/(2 M_i) + V(q) (oscillator, "
                                  "pendulum, cylinder, henon_heiles, potential_3d); this system's "
                                  "kinetic energy depends on q: use gauss4 or gauss6 "
                                  "(symplectic for any H) or an adaptive method",
                                  m->name);
        e->second_order = 1;
        sys_out->accel = ens_ode_accel;
        sys_out->flags = MECH_ODE_VELOCITY_FREE;
        sys_out->particle_dim = ham_particle_dim(s);
    }
    sys_out->dim = mech_ham_ensemble_dim(e);
    sys_out->rhs = ens_ode_rhs;
    sys_out->params = e;
    return MECH_OK;
}

/* ---- the flow ------------------------------------------------------------------ */

struct flow_obs {
    const struct mech_ham_ensemble *e;
    struct mech_ham_flow_result *res;
    struct mech_error *err;
};

static void drift_update(struct mech_ham_drift *d, double x)
{
    const double a = fabs(x - d->initial);
    if (a > d->max_abs) d->max_abs = a;
    d->final = x;
}

static enum mech_status flow_observe(double t, const double *Y, void *params)
{
    (void)t;
    struct flow_obs *o = params;
    double y[MECH_HAM_MAX_DIM], E;
    mech_ham_ensemble_get(o->e, Y, 0, y, 0, NULL);
    enum mech_status st = mech_ham_energy(o->e->sys, y, &E, o->err);
    if (st != MECH_OK) return st;
    drift_update(&o->res->energy, E);
    for (size_t c = 0; c < o->res->n_conserved; c++)
        drift_update(&o->res->conserved_drift[c],
                     mech_ham_conserved_value(o->e->sys, &o->res->conserved[c], y));
    return MECH_OK;
}

static void drift_finish(struct mech_ham_drift *d)
{
    d->max_rel = d->initial != 0.0 ? d->max_abs / fabs(d->initial) : NAN;
}

enum mech_status mech_ham_flow(const struct mech_ham_flow_problem *p,
                               const struct mech_budget *budget,
                               struct mech_ham_flow_result *res, struct mech_error *err)
{
    if (!p || !p->sys || !p->y0 || !p->method || !res || !res->t || !res->y)
        return mech_error_set(err, MECH_EINVAL, NULL, "incomplete flow problem");
    if (p->n_samples < 2)
        return mech_error_set(err, MECH_EINVAL, "samples", "at least 2 samples are needed");
    struct mech_ham_system sys = *p->sys;
    enum mech_status st = mech_ham_system_check(&sys, err);
    if (st != MECH_OK) return st;
    if ((st = mech_ham_state_check(&sys, p->y0, err)) != MECH_OK) return st;
    res->n_samples = 0;
    res->stats = (struct mech_ode_stats){0, 0, 0};
    double E0;
    if ((st = mech_ham_energy(&sys, p->y0, &E0, err)) != MECH_OK) return st;
    res->energy = (struct mech_ham_drift){E0, E0, 0.0, NAN};
    res->n_conserved = mech_ham_conserved_list(&sys, res->conserved);
    for (size_t c = 0; c < res->n_conserved; c++) {
        const double v = mech_ham_conserved_value(&sys, &res->conserved[c], p->y0);
        res->conserved_drift[c] = (struct mech_ham_drift){v, v, 0.0, NAN};
    }

    struct mech_ham_ensemble e;
    struct mech_ode_system ode;
    if ((st = mech_ham_ensemble_init(&e, &sys, 1, 0, p->method, &ode, err)) != MECH_OK) return st;
    res->second_order = e.second_order;
    const size_t dim = ode.dim;
    double Y0[MECH_HAM_MAX_DIM];
    mech_ham_ensemble_put(&e, Y0, 0, p->y0, NULL);
    struct flow_obs obs = {&e, res, err};
    struct mech_ode_problem op = {
        .sys = &ode, .method = p->method, .opt = p->opt, .t0 = 0.0, .t_end = p->t_end,
        .y0 = Y0, .n_samples = p->n_samples, .sample_t = res->t, .sample_y = res->y,
        .observe = flow_observe, .observe_params = &obs,
    };
    struct mech_ode_result r;
    memset(&r, 0, sizeof r);
    st = mech_ode_solve(&op, budget, &r, err);
    res->n_samples = r.n_samples;
    res->stats = r.stats;
    if (e.second_order) /* samples hold (q, v): back to (q, p) */
        for (size_t i = 0; i < r.n_samples; i++)
            for (size_t k = 0; k < dim / 2; k++) res->y[i * dim + dim / 2 + k] *= e.M[k];
    drift_finish(&res->energy);
    for (size_t c = 0; c < res->n_conserved; c++) drift_finish(&res->conserved_drift[c]);
    return st;
}
