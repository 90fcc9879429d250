/* test_scene_models.c — the ballistic scenes' choice of model
 * (mech_scene_ballistic.model in core/frames/scenes.c): Coriolis only, as most
 * textbooks solve the scenes, or Coriolis and centrifugal, checked two ways.
 *
 * Closed forms (first order in W, w = W (0, cos lat, sin lat), x east,
 * y north, z up):
 *   drop from h:           x_east = (1/3) W g t^3 cos lat, t = sqrt(2 h / g);
 *   vertical shot at v0:   x_west = (4/3) W cos lat v0^3 / g^2;
 *   cannonball due east:   south 4 v0^3 W sin lat sin^2 a cos a / g^2,
 *                          range + 4 W cos lat v0^3 sin a (4 cos^2 a - 1) / (3 g^2).
 * Second methods, written here independently of core:
 *   Coriolis only, exactly: v' = g - W2 n x v (W2 = 2 W, n = w / W) keeps the
 *   part of v along n growing as g_par t and turns the rest about the steady
 *   drift u* = -(n x g) / W2 by the angle -W2 t, so
 *     r(t) = r0 + (v0.n) n t + g_par t^2/2 + u0 S1 - (n x u0) S2
 *            - (n x g) D / W2 + g_perp S2 / W2,
 *   S1 = sin(W2 t)/W2, S2 = (1 - cos W2 t)/W2, D = (W2 t - sin W2 t)/W2 (a
 *   series for small W2 t: no digits lost), u0 = v0 - (v0.n) n;
 *   both terms: classical RK4 of r'' = g - 2 w x r' - w x (w x r) with 20 000
 *   steps over the flight and the landing step bisected.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/frames/scenes.h"
#include "testlib.h"

static const double G0 = 9.80665;
static const double W_E = MECH_EARTH_OMEGA_SIDEREAL;

static struct mech_scene_ballistic_result R;

static struct mech_scene_ballistic scene(double lat, enum mech_scene_model m)
{
    struct mech_scene_ballistic s;
    memset(&s, 0, sizeof s);
    s.latitude_deg = lat;
    s.g = G0;
    s.omega = W_E;
    s.model = m;
    return s;
}

static struct mech_vec3 omega_vec(double lat_deg)
{
    const double l = lat_deg * MECH_PI / 180.0;
    return mech_vec3_make(0, W_E * cos(l), W_E * sin(l));
}

/* x - sin x without cancellation. */
static double x_minus_sin(double x)
{
    if (fabs(x) > 0.1) return x - sin(x);
    const double x2 = x * x;
    double term = x * x2 / 6.0, sum = 0.0;
    for (int k = 1; k < 12; k++) {
        sum += term;
        term *= -x2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
    }
    return sum;
}

/* The exact Coriolis-only position at t (see the header). */
static struct mech_vec3 coriolis_exact(const struct mech_scene_ballistic *s, double t)
{
    const struct mech_vec3 w = omega_vec(s->latitude_deg);
    const double W2 = 2.0 * mech_vec3_norm(w);
    const struct mech_vec3 n = mech_vec3_scale(w, 2.0 / W2);
    const struct mech_vec3 g = mech_vec3_make(0, 0, -s->g);
    const double x = W2 * t, sx = sin(0.5 * x);
    const double S1 = sin(x) / W2, S2 = 2.0 * sx * sx / W2, D = x_minus_sin(x) / W2;
    const struct mech_vec3 gpar = mech_vec3_scale(n, mech_vec3_dot(g, n));
    const struct mech_vec3 gperp = mech_vec3_sub(g, gpar);
    const struct mech_vec3 vpar = mech_vec3_scale(n, mech_vec3_dot(s->v0, n));
    const struct mech_vec3 u0 = mech_vec3_sub(s->v0, vpar);
    struct mech_vec3 r = mech_vec3_add(s->r0, mech_vec3_scale(vpar, t));
    r = mech_vec3_add(r, mech_vec3_scale(gpar, 0.5 * t * t));
    r = mech_vec3_add(r, mech_vec3_scale(u0, S1));
    r = mech_vec3_sub(r, mech_vec3_scale(mech_vec3_cross(n, u0), S2));
    r = mech_vec3_sub(r, mech_vec3_scale(mech_vec3_cross(n, g), D / W2));
    r = mech_vec3_add(r, mech_vec3_scale(gperp, S2 / W2));
    return r;
}

/* Landing (z = 0 going down) of the exact Coriolis-only motion near T0. */
static struct mech_scene_landing coriolis_exact_landing(const struct mech_scene_ballistic *s,
                                                        double T0)
{
    double lo = 0.5 * T0, hi = 1.5 * T0;
    for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; i++) {
        const double mid = 0.5 * (lo + hi);
        if (coriolis_exact(s, mid).z > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    struct mech_scene_landing l = {0.5 * (lo + hi), coriolis_exact(s, 0.5 * (lo + hi))};
    l.r.z = 0.0;
    return l;
}

/* r'' = g - 2 w x r' - cf w x (w x r) as a 6-vector. */
static void rhs(const struct mech_scene_ballistic *s, int cf, const double *y, double *dy)
{
    const struct mech_vec3 w = omega_vec(s->latitude_deg);
    const struct mech_vec3 r = mech_vec3_make(y[0], y[1], y[2]);
    const struct mech_vec3 v = mech_vec3_make(y[3], y[4], y[5]);
    struct mech_vec3 a = mech_vec3_make(0, 0, -s->g);
    a = mech_vec3_sub(a, mech_vec3_scale(mech_vec3_cross(w, v), 2.0));
    if (cf) a = mech_vec3_sub(a, mech_vec3_cross(w, mech_vec3_cross(w, r)));
    dy[0] = v.x, dy[1] = v.y, dy[2] = v.z, dy[3] = a.x, dy[4] = a.y, dy[5] = a.z;
}

static void rk4_step(const struct mech_scene_ballistic *s, int cf, const double *y, double h,
                     double *out)
{
    double k1[6], k2[6], k3[6], k4[6], t[6];
    rhs(s, cf, y, k1);
    for (int i = 0; i < 6; i++) t[i] = y[i] + 0.5 * h * k1[i];
    rhs(s, cf, t, k2);
    for (int i = 0; i < 6; i++) t[i] = y[i] + 0.5 * h * k2[i];
    rhs(s, cf, t, k3);
    for (int i = 0; i < 6; i++) t[i] = y[i] + h * k3[i];
    rhs(s, cf, t, k4);
    for (int i = 0; i < 6; i++) out[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

/* RK4 landing: fixed steps of T0/20000 until z < 0, then the last step's
 * length bisected (one RK4 step from the state before it). */
static struct mech_scene_landing rk4_landing(const struct mech_scene_ballistic *s, int cf,
                                             double T0)
{
    const double h = T0 / 20000.0;
    double y[6] = {s->r0.x, s->r0.y, s->r0.z, s->v0.x, s->v0.y, s->v0.z}, yn[6];
    double t = 0.0;
    for (int i = 0; i < 40000; i++) {
        rk4_step(s, cf, y, h, yn);
        if (yn[2] < 0.0) break;
        memcpy(y, yn, sizeof y);
        t += h;
    }
    double lo = 0.0, hi = h;
    for (int i = 0; i < 100; i++) {
        const double mid = 0.5 * (lo + hi);
        rk4_step(s, cf, y, mid, yn);
        if (yn[2] > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    rk4_step(s, cf, y, 0.5 * (lo + hi), yn);
    struct mech_scene_landing l = {t + 0.5 * (lo + hi), mech_vec3_make(yn[0], yn[1], 0.0)};
    return l;
}

static int run(struct mech_scene_ballistic *s, double target)
{
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = mech_budget_make(20000000, 600.0);
    return mech_scene_ballistic_run(s, target, &b, &R, &e);
}

static double hdist(struct mech_vec3 a, struct mech_vec3 b)
{
    return hypot(a.x - b.x, a.y - b.y);
}

static void test_drop_coriolis(void)
{
    const double h = 100.0, lat = 32.0 * MECH_PI / 180.0, t = sqrt(2.0 * h / G0);
    struct mech_scene_ballistic s = scene(32.0, MECH_SCENE_MODEL_CORIOLIS);
    s.r0 = mech_vec3_make(0, 0, h);
    CHECK_EQ_INT(run(&s, 1e-10), MECH_OK);
    /* at 1e-10 "auto" keeps the centrifugal term too; the model asked for does not */
    CHECK(R.problem.fictitious == MECH_FICTITIOUS_CORIOLIS);
    CHECK_CLOSE(R.second_centrifugal.r.y, 0.0, 0, 0);
    const double east = W_E * G0 * t * t * t * cos(lat) / 3.0;
    CHECK_CLOSE(R.first_order.r.x, east, 1e-14, 0);
    /* the exact Coriolis-only landing: east to first order, south (1/6) g W^2 sin cos t^4 */
    const struct mech_scene_landing ex = coriolis_exact_landing(&s, t);
    CHECK_CLOSE(ex.r.x, east, 1e-6, 0);
    const double south = G0 * W_E * W_E * sin(lat) * cos(lat) * pow(t, 4) / 6.0;
    CHECK_CLOSE(-ex.r.y, south, 1e-3, 0);
    /* the run against the exact solution and against RK4 */
    printf("drop, coriolis: run (%.12g, %.6g), exact (%.12g, %.6g), tol %.3g\n", R.numerical.r.x,
           R.numerical.r.y, ex.r.x, ex.r.y, R.integration_tolerance);
    CHECK(hdist(R.numerical.r, ex.r) <= R.integration_tolerance);
    CHECK_CLOSE(R.numerical.t, ex.t, 1e-9, 0);
    const struct mech_scene_landing rk = rk4_landing(&s, 0, t);
    CHECK(hdist(rk.r, ex.r) <= 1e-12);
}

static void test_vertical_shot_coriolis(void)
{
    const double v0 = 100.0, lat = 45.0 * MECH_PI / 180.0, T = 2.0 * v0 / G0;
    struct mech_scene_ballistic s = scene(45.0, MECH_SCENE_MODEL_CORIOLIS);
    s.v0 = mech_vec3_make(0, 0, v0);
    CHECK_EQ_INT(run(&s, 1e-10), MECH_OK);
    CHECK(R.problem.fictitious == MECH_FICTITIOUS_CORIOLIS);
    const double west = 4.0 / 3.0 * W_E * cos(lat) * v0 * v0 * v0 / (G0 * G0);
    CHECK_CLOSE(-R.first_order.r.x, west, 1e-13, 0);
    const struct mech_scene_landing ex = coriolis_exact_landing(&s, T);
    CHECK_CLOSE(-ex.r.x, west, 1e-5, 0);
    /* Coriolis twice: north W^2 sin cos v0 T^3 / 3 (the series' Coriolis part) */
    CHECK_CLOSE(ex.r.y, W_E * W_E * sin(lat) * cos(lat) * v0 * T * T * T / 3.0, 1e-3, 0);
    CHECK_CLOSE(R.second_coriolis.r.y, ex.r.y, 1e-3, 0);
    printf("vertical shot, coriolis: run (%.12g, %.6g), exact (%.12g, %.6g), tol %.3g\n",
           R.numerical.r.x, R.numerical.r.y, ex.r.x, ex.r.y, R.integration_tolerance);
    CHECK(hdist(R.numerical.r, ex.r) <= R.integration_tolerance);
    CHECK(hdist(rk4_landing(&s, 0, T).r, ex.r) <= 1e-9);
}

static void test_cannonball(void)
{
    const double v0 = 500.0, a = 30.0 * MECH_PI / 180.0, lat = 45.0 * MECH_PI / 180.0;
    const double T0 = 2.0 * v0 * sin(a) / G0, R0 = v0 * v0 * sin(2.0 * a) / G0;
    const double sa = sin(a), ca = cos(a);
    const double south = 4.0 * v0 * v0 * v0 * W_E * sin(lat) * sa * sa * ca / (G0 * G0);
    const double dR =
        4.0 * W_E * cos(lat) * v0 * v0 * v0 * sa * (4.0 * ca * ca - 1.0) / (3.0 * G0 * G0);
    /* Coriolis only */
    struct mech_scene_ballistic s = scene(45.0, MECH_SCENE_MODEL_CORIOLIS);
    s.v0 = mech_vec3_make(v0 * ca, 0, v0 * sa);
    CHECK_EQ_INT(run(&s, 1e-10), MECH_OK);
    CHECK(R.problem.fictitious == MECH_FICTITIOUS_CORIOLIS);
    CHECK_CLOSE(-R.first_order.r.y, south, 1e-12, 0);
    CHECK_CLOSE(R.first_order.r.x - R0, dR, 1e-10, 0);
    const struct mech_scene_landing ex = coriolis_exact_landing(&s, T0);
    /* the exact deflections differ from the first-order ones by second order (W T0 ~ 4e-3) */
    CHECK_CLOSE(-ex.r.y, south, 1e-2, 0);
    CHECK_CLOSE(ex.r.x - R0, dR, 1e-2, 0);
    printf("cannonball, coriolis: run (%.12g, %.12g), exact (%.12g, %.12g), tol %.3g\n",
           R.numerical.r.x, R.numerical.r.y, ex.r.x, ex.r.y, R.integration_tolerance);
    CHECK(hdist(R.numerical.r, ex.r) <= R.integration_tolerance);
    CHECK(hdist(rk4_landing(&s, 0, T0).r, ex.r) <= 1e-7); /* 5e-12 of the range */
    /* numerical - first order is the Coriolis part of the second order (third order left) */
    CHECK(hdist(R.difference.r, R.second_coriolis.r) < 0.02 * hypot(R.second_coriolis.r.x,
                                                                   R.second_coriolis.r.y) +
                                                           R.integration_tolerance);
    const struct mech_vec3 cor = R.numerical.r;

    /* Coriolis and centrifugal, at draft accuracy where "auto" drops the centrifugal term */
    s.model = MECH_SCENE_MODEL_CORIOLIS_CENTRIFUGAL;
    CHECK_EQ_INT(run(&s, 1e-10), MECH_OK);
    CHECK(R.problem.fictitious == (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL));
    const struct mech_scene_landing rk = rk4_landing(&s, 1, T0);
    printf("cannonball, both: run (%.12g, %.12g), rk4 (%.12g, %.12g), tol %.3g\n",
           R.numerical.r.x, R.numerical.r.y, rk.r.x, rk.r.y, R.integration_tolerance);
    CHECK(hdist(R.numerical.r, rk.r) <= R.integration_tolerance);
    /* the centrifugal term moves the landing by the series' centrifugal part */
    const double cfm = hypot(R.second_centrifugal.r.x, R.second_centrifugal.r.y);
    CHECK(cfm > 0.0);
    CHECK(fabs(hdist(R.numerical.r, cor) - cfm) < 0.02 * cfm + 2.0 * R.integration_tolerance);
    struct mech_scene_ballistic d = s;
    CHECK_EQ_INT(run(&d, 1e-3), MECH_OK);
    CHECK(R.problem.fictitious == (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL));
    d.model = MECH_SCENE_MODEL_AUTO;
    CHECK_EQ_INT(run(&d, 1e-3), MECH_OK);
    CHECK(R.problem.fictitious == MECH_FICTITIOUS_CORIOLIS); /* the default is unchanged */
}

static void test_drop_both_rk4(void)
{
    const double h = 1000.0, t = sqrt(2.0 * h / G0);
    struct mech_scene_ballistic s = scene(-60.0, MECH_SCENE_MODEL_CORIOLIS_CENTRIFUGAL);
    s.r0 = mech_vec3_make(0, 0, h);
    CHECK_EQ_INT(run(&s, 1e-10), MECH_OK);
    const struct mech_scene_landing rk = rk4_landing(&s, 1, t);
    CHECK(hdist(R.numerical.r, rk.r) <= R.integration_tolerance);
    CHECK_CLOSE(R.numerical.t, rk.t, 1e-9, 0);
    /* southern hemisphere: still east, and the second-order drift is towards the equator */
    CHECK(R.numerical.r.x > 0.0 && R.numerical.r.y > 0.0);
}

static void test_errors(void)
{
    struct mech_scene_ballistic s = scene(10.0, (enum mech_scene_model)7);
    s.r0 = mech_vec3_make(0, 0, 10);
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = mech_budget_make(20000000, 600.0);
    CHECK_EQ_INT(mech_scene_ballistic_run(&s, 1e-8, &b, &R, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "model"));
    CHECK(mech_scene_model_name((enum mech_scene_model)7) == NULL);
    CHECK(!strcmp(mech_scene_model_name(MECH_SCENE_MODEL_CORIOLIS), "coriolis"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_drop_coriolis();
    test_vertical_shot_coriolis();
    test_cannonball();
    test_drop_both_rk4();
    test_errors();
    TEST_MAIN_END();
}
