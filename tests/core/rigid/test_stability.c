/* test_stability.c — stability of spin about a principal axis (notes §2.10):
 * the closed-form coefficient k against hand values, the intermediate-axis
 * theorem over random bodies, degenerate and refused inputs, and a direct
 * numerical linearisation: Euler's equations integrated with mech_ode_solve
 * from a small perturbation, the measured oscillation frequency or growth
 * rate compared with sqrt(-k) or sqrt(k). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/ode/ode.h"
#include "mech/base/constants.h"
#include "mech/rigid/stability.h"
#include "testlib.h"

/* Torque-free Euler equations (notes §2.8): I1 w1' = (I2 - I3) w2 w3, cyclic. */
static enum mech_status euler_rhs(double t, const double *w, double *dw, void *params)
{
    (void)t;
    const double *I = params;
    dw[0] = (I[1] - I[2]) * w[1] * w[2] / I[0];
    dw[1] = (I[2] - I[0]) * w[2] * w[0] / I[1];
    dw[2] = (I[0] - I[1]) * w[0] * w[1] / I[2];
    return MECH_OK;
}

/* Integrate from spin about `axis` (1-based) plus delta along the next axis b;
 * samples eps (component b) at n points on [0, t_end]. */
static int integrate(const double I[3], int axis, double spin, double delta, double t_end, size_t n,
                     double *eps)
{
    int a = axis - 1, b = (a + 1) % 3;
    double y0[3] = {0, 0, 0};
    y0[a] = spin;
    y0[b] = delta;
    double *ys = malloc(n * 3 * sizeof *ys);
    if (!ys) return -1;
    struct mech_ode_system sys = {3, euler_rhs, NULL, 0, (void *)I, NULL, 0, NULL};
    struct mech_ode_problem p = {0};
    p.sys = &sys;
    p.method = mech_ode_method_find("rk8pd");
    p.opt.rtol = 1e-13;
    p.opt.atol = 1e-13 * fabs(delta);
    p.t0 = 0;
    p.t_end = t_end;
    p.y0 = y0;
    p.n_samples = n;
    p.sample_y = ys;
    struct mech_budget bud = mech_budget_make(10000000, 60);
    struct mech_ode_result res;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_ode_solve(&p, &bud, &res, &e);
    for (size_t i = 0; i < n; i++)
        eps[i] = ys[3 * i + b];
    free(ys);
    return st == MECH_OK ? 0 : -1;
}

/* Mean angular frequency from the zero crossings of x sampled every h. */
static double crossing_frequency(const double *x, size_t n, double h)
{
    double first = -1, last = -1;
    int count = 0;
    for (size_t i = 0; i + 1 < n; i++)
        if ((x[i] < 0) != (x[i + 1] < 0)) {
            double tc = h * ((double)i + x[i] / (x[i] - x[i + 1]));
            if (first < 0) first = tc;
            last = tc;
            count++;
        }
    if (count < 3) return NAN;
    return MECH_PI * (count - 1) / (last - first); /* half a period between crossings */
}

static struct mech_stability stab(double i1, double i2, double i3, int axis, double spin)
{
    double m[3] = {i1, i2, i3};
    struct mech_stability s;
    memset(&s, 0, sizeof s);
    CHECK(mech_stability_principal(m, axis, spin, &s, NULL) == MECH_OK);
    return s;
}

int main(void)
{
    gsl_set_error_handler_off();

    /* 1. Hand values, I = (1, 2, 3), w = 1 (notes §2.10):
     * axis 1: (I3 - I1)(I1 - I2)/(I2 I3) = 2(-1)/6 = -1/3, stable, sqrt(1/3);
     * axis 2: (I1 - I2)(I2 - I3)/(I3 I1) = (-1)(-1)/3 = 1/3, unstable;
     * axis 3: (I2 - I3)(I3 - I1)/(I1 I2) = (-1)(2)/2 = -1, stable, 1. */
    {
        struct mech_stability s = stab(1, 2, 3, 1, 1);
        CHECK_CLOSE(s.k, -1.0 / 3, 1e-16, 0);
        CHECK(s.kind == MECH_STABILITY_STABLE && s.role == MECH_AXIS_SMALLEST);
        CHECK_CLOSE(s.frequency, sqrt(1.0 / 3), 1e-16, 0);
        CHECK(s.growth_rate == 0);
        CHECK_EQ_INT(s.perturbation_axes[0], 2);
        CHECK_EQ_INT(s.perturbation_axes[1], 3);
        CHECK_CLOSE(s.coupling[0], 1.0, 1e-16, 0);      /* (I3 - I1) w / I2 */
        CHECK_CLOSE(s.coupling[1], -1.0 / 3, 1e-16, 0); /* (I1 - I2) w / I3 */
        CHECK_EQ_INT(s.intermediate_axis, 2);
        s = stab(1, 2, 3, 2, 1);
        CHECK_CLOSE(s.k, 1.0 / 3, 1e-16, 0);
        CHECK(s.kind == MECH_STABILITY_UNSTABLE && s.role == MECH_AXIS_INTERMEDIATE);
        CHECK_CLOSE(s.growth_rate, sqrt(1.0 / 3), 1e-16, 0);
        CHECK(s.frequency == 0);
        CHECK_EQ_INT(s.perturbation_axes[0], 3);
        CHECK_EQ_INT(s.perturbation_axes[1], 1);
        s = stab(1, 2, 3, 3, -1); /* the sign of the spin does not matter */
        CHECK_CLOSE(s.k, -1.0, 1e-16, 0);
        CHECK(s.kind == MECH_STABILITY_STABLE && s.role == MECH_AXIS_LARGEST);
        /* unsorted: the intermediate moment is axis 3 */
        s = stab(3, 1, 2, 3, 10);
        CHECK(s.kind == MECH_STABILITY_UNSTABLE);
        CHECK_EQ_INT(s.intermediate_axis, 3);
        CHECK_CLOSE(s.k, 100.0 * (3 - 2) * (2 - 1) / (1 * 3), 1e-15, 0);
        /* a book 0.2 x 0.15 x 0.03 m, 1 kg: I = m(b^2 + c^2)/12 ... about the
         * 0.15 edge (intermediate), spin 10 rad/s */
        double m = 1, a = 0.2, b = 0.15, c = 0.03;
        double i1 = m * (b * b + c * c) / 12, i2 = m * (a * a + c * c) / 12,
               i3 = m * (a * a + b * b) / 12;
        s = stab(i1, i2, i3, 2, 10);
        double k = (i1 - i2) * (i2 - i3) / (i3 * i1) * 100;
        CHECK_CLOSE(s.k, k, 1e-14, 0);
        CHECK(s.kind == MECH_STABILITY_UNSTABLE);
    }

    /* 2. Intermediate-axis theorem over random bodies (moments from random
     * point clouds so they are physical): exactly the strictly intermediate
     * axis is unstable; k scales as w^2. */
    {
        unsigned long seed = 99;
        int bad = 0;
        for (int n = 0; n < 5000; n++) {
            double pts[3];
            double xx = 0, yy = 0, zz = 0;
            for (int p = 0; p < 4; p++) {
                for (int d = 0; d < 3; d++) {
                    seed = seed * 6364136223846793005UL + 1442695040888963407UL;
                    pts[d] = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
                }
                xx += pts[0] * pts[0];
                yy += pts[1] * pts[1];
                zz += pts[2] * pts[2];
            }
            double mo[3] = {yy + zz, xx + zz, xx + yy}; /* diagonal, enough for the theorem */
            for (int ax = 1; ax <= 3; ax++) {
                struct mech_stability s;
                if (mech_stability_principal(mo, ax, 2.5, &s, NULL) != MECH_OK) {
                    bad++;
                    continue;
                }
                double ia = mo[ax - 1], ib = mo[ax % 3], ic = mo[(ax + 1) % 3];
                int inter = (ib < ia && ia < ic) || (ic < ia && ia < ib);
                if ((s.kind == MECH_STABILITY_UNSTABLE) != inter) bad++;
                if (inter != (s.intermediate_axis == ax)) bad++;
                struct mech_stability s2;
                mech_stability_principal(mo, ax, 5.0, &s2, NULL);
                if (fabs(s2.k - 4 * s.k) > 1e-15 * fabs(4 * s.k)) bad++;
            }
        }
        CHECK_EQ_INT(bad, 0);
    }

    /* 3. Degenerate moments and no spin: marginal, k = 0 exactly. */
    {
        struct mech_stability s = stab(1, 1, 2, 1, 3); /* a transverse axis of a symmetric body */
        CHECK(s.k == 0 && s.kind == MECH_STABILITY_MARGINAL && s.role == MECH_AXIS_DEGENERATE);
        CHECK(s.frequency == 0 && s.growth_rate == 0);
        CHECK_EQ_INT(s.intermediate_axis, 0);
        CHECK_CLOSE(s.coupling[0], 3.0, 1e-16, 0); /* eps drifts at (I3 - I1) w eta / I2 */
        s = stab(1, 1, 2, 3, 3); /* its symmetry axis: stable, k = -(I3 - I1)^2 w^2 / I1^2 */
        CHECK_CLOSE(s.k, -9.0, 1e-16, 0);
        CHECK(s.kind == MECH_STABILITY_STABLE);
        s = stab(2, 2, 2, 2, 5); /* sphere */
        CHECK(s.k == 0 && s.kind == MECH_STABILITY_MARGINAL);
        s = stab(1, 2, 3, 2, 0); /* no spin */
        CHECK(s.k == 0 && s.kind == MECH_STABILITY_MARGINAL);
        /* nearly degenerate: exact differences keep full precision */
        volatile double i2 = 1 + 1e-12;
        s = stab(1, i2, 2, 2, 1);
        double k = (1 - i2) * (i2 - 2) / 2; /* (I1 - I2)(I2 - I3)/(I3 I1), differences exact */
        CHECK_CLOSE(s.k, k, 1e-15, 0);
        CHECK(s.kind == MECH_STABILITY_UNSTABLE);
        /* extreme scales */
        s = stab(1e-30, 2e-30, 3e-30, 1, 1e6);
        CHECK_CLOSE(s.k, -1e12 / 3, 1e-15, 0);
        s = stab(1e30, 2e30, 3e30, 2, 1e-6);
        CHECK_CLOSE(s.k, 1e-12 / 3, 1e-15, 0);
        /* flat lamina on the triangle inequality: I3 = I1 + I2 is allowed, with slack */
        s = stab(0.1, 0.2, 0.3, 3, 1);
        CHECK(s.kind == MECH_STABILITY_STABLE);
    }

    /* 4. Refusals name the field. */
    {
        struct mech_error e;
        struct mech_stability s;
        double m0[3] = {1, 0, 1};
        mech_error_clear(&e);
        CHECK(mech_stability_principal(m0, 1, 1, &s, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "moments/1") == 0);
        double tri[3] = {1, 1, 3};
        mech_error_clear(&e);
        CHECK(mech_stability_principal(tri, 1, 1, &s, &e) == MECH_EDOMAIN);
        CHECK(strcmp(e.param, "moments/2") == 0);
        double ok[3] = {1, 2, 3};
        mech_error_clear(&e);
        CHECK(mech_stability_principal(ok, 4, 1, &s, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "axis") == 0);
        mech_error_clear(&e);
        CHECK(mech_stability_principal(ok, 1, NAN, &s, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "spin") == 0);
        double nan[3] = {1, NAN, 1};
        mech_error_clear(&e);
        CHECK(mech_stability_principal(nan, 1, 1, &s, &e) == MECH_EINVAL);
        CHECK(strcmp(e.param, "moments/1") == 0);
    }

    /* 5. Direct numerical linearisation: Euler's equations integrated (rk8pd,
     * rtol 1e-13) from spin + a perturbation of 1e-10 spin. Stable axes: the
     * frequency of eps from its zero crossings over ~20 periods; the unstable
     * axis: eps = delta cosh(sqrt(k) t) (eta(0) = 0), so the growth rate is
     * acosh(eps(T)/delta)/T with eps(T) ~ 1e-4 spin, still linear. */
    {
        const double bodies[3][3] = {{1, 2, 3}, {2.5e-6, 1.1e-6, 3.0e-6}, {400, 700, 350}};
        const double spins[3] = {1, 120, -0.05};
        double worst_f = 0, worst_g = 0;
        for (int bi = 0; bi < 3; bi++)
            for (int ax = 1; ax <= 3; ax++) {
                double spin = spins[bi], delta = 1e-10 * fabs(spin);
                struct mech_stability s;
                CHECK(mech_stability_principal(bodies[bi], ax, spin, &s, NULL) == MECH_OK);
                if (s.kind == MECH_STABILITY_STABLE) {
                    size_t n = 40001;
                    double t_end = 20 * 2 * MECH_PI / s.frequency;
                    double *eps = malloc(n * sizeof *eps);
                    CHECK(eps && integrate(bodies[bi], ax, spin, delta, t_end, n, eps) == 0);
                    double f = crossing_frequency(eps, n, t_end / (double)(n - 1));
                    worst_f = fmax(worst_f, fabs(f - s.frequency) / s.frequency);
                    CHECK_CLOSE(f, s.frequency, 1e-8, 0);
                    free(eps);
                } else {
                    CHECK(s.kind == MECH_STABILITY_UNSTABLE);
                    double t_end = acosh(1e6) / s.growth_rate;
                    double eps[2] = {0.0, 0.0};
                    CHECK(integrate(bodies[bi], ax, spin, delta, t_end, 2, eps) == 0);
                    double g = acosh(eps[1] / delta) / t_end;
                    worst_g = fmax(worst_g, fabs(g - s.growth_rate) / s.growth_rate);
                    CHECK_CLOSE(g, s.growth_rate, 1e-7, 0);
                }
            }
        printf("numerical linearisation: frequency rel. error %.3g, growth-rate rel. error %.3g\n",
               worst_f, worst_g);
    }
    TEST_MAIN_END();
}
