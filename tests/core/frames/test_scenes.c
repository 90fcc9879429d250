/* test_scenes.c — the chapter-1 scenes (core/frames/scenes.c) against the notes'
 * formulas and their second-order terms, derived by hand:
 *   falling object (h = 100 m, lat 32 deg): first order x_east =
 *     (W cos lat / 3) sqrt(8 h^3 / g) (notes: 1.9 cm); second order, south:
 *     Coriolis (1/6) g W^2 sin cos t^4 + centrifugal (5/24) g W^2 sin cos t^4;
 *   vertical shot (h = 100 m): first order west (4/3) W cos lat sqrt(8h^3/g)
 *     (four times the drop's); second order north W^2 sin cos v0 T^3 (1/3 - 1/12);
 *   cannonball due east: the notes' problems 4 and 5 (south deflection
 *     4 v0^3 W sin lat sin^2 a cos a / g^2; range increase
 *     W cos lat sqrt(2 R^3 / g) (cot^1/2 a - tan^3/2 a / 3)); firing north
 *     deflects right (east) in the north, left in the south;
 *   the numerical answers (auto terms) differ from the first-order formulas
 *     by the second-order terms, up to third-order terms and the integration
 *     tolerance (the quality bar);
 *   the rotating table: the notes' effective forces -m w^2 r (e_y + 4/pi e_x)
 *     and -m w^2 r e_y, the return to the start after half a turn, the
 *     circle of the puck at rest, rotating path = transformed straight line.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/frames/scenes.h"
#include "mech/base/constants.h"
#include "testlib.h"

static const double G0 = 9.80665;
static const double W_E = MECH_EARTH_OMEGA_SIDEREAL;

static struct mech_budget budget(void)
{
    return mech_budget_make(20000000, 600.0);
}

static struct mech_scene_ballistic earth(double lat)
{
    struct mech_scene_ballistic s;
    memset(&s, 0, sizeof s);
    s.latitude_deg = lat;
    s.g = G0;
    s.omega = W_E;
    return s;
}

static struct mech_scene_ballistic_result R;

static void report(const char *name, const struct mech_scene_ballistic_result *r)
{
    printf("%s: numerical (%.12g, %.12g) t %.12g; first order (%.12g, %.12g); difference "
           "(%.3g, %.3g); second order (%.3g, %.3g); unexplained (%.3g, %.3g); tol %.3g; "
           "terms 0x%x, %s\n",
           name, r->numerical.r.x, r->numerical.r.y, r->numerical.t, r->first_order.r.x,
           r->first_order.r.y, r->difference.r.x, r->difference.r.y, r->second_order.r.x,
           r->second_order.r.y, r->unexplained.r.x, r->unexplained.r.y, r->integration_tolerance,
           r->problem.fictitious, r->choice.method);
}

static void test_falling(void)
{
    const double h = 100.0, lat = 32.0 * MECH_PI / 180.0, s = sin(lat), c = cos(lat);
    struct mech_scene_ballistic sc = earth(32.0);
    sc.r0 = mech_vec3_make(0, 0, h);
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = budget();
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-10, &b, &R, &e), MECH_OK);
    report("falling object 100 m, 32 deg, 1e-10", &R);
    const double t0 = sqrt(2.0 * h / G0);
    const double east = W_E * c / 3.0 * sqrt(8.0 * h * h * h / G0);
    CHECK_CLOSE(R.first_order.r.x, east, 1e-14, 0);
    CHECK_CLOSE(R.first_order.r.y, 0.0, 0, 1e-20);
    CHECK_CLOSE(R.first_order.t, t0, 1e-15, 0);
    CHECK_CLOSE(R.first_order.r.x, 0.019, 0, 0.0005); /* the notes' 1.9 cm */
    /* at 1e-10 both terms are modelled; second order south (3/8) g W^2 s c t^4 */
    CHECK(R.problem.fictitious == (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL));
    const double k = G0 * W_E * W_E * s * c * pow(t0, 4);
    CHECK_CLOSE(-R.second_coriolis.r.y, k / 6.0, 1e-6, 0);
    CHECK_CLOSE(-R.second_centrifugal.r.y, 5.0 * k / 24.0, 1e-6, 0);
    CHECK_CLOSE(-R.second_order.r.y, 3.0 * k / 8.0, 1e-6, 0);
    /* the quality bar: numerical - first order = the second-order terms,
     * up to third order (~W^3 g t^5 ~ 1e-9 m) and the integration error */
    CHECK_CLOSE(-R.numerical.r.y, 3.0 * k / 8.0, 1e-3, 1e-9);
    CHECK(fabs(R.unexplained.r.y) < 1e-9 + R.integration_tolerance);
    CHECK(fabs(R.difference.r.x) < 1e-8);
    CHECK(fabs(R.unexplained.r.x) < 1e-8);
    /* at the default 1e-8 the centrifugal term (5e-8 relative) is still in */
    b = budget();
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-8, &b, &R, &e), MECH_OK);
    CHECK(R.problem.fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    /* at 1e-6 it is left out: the series then has no centrifugal part and
     * the numerical south deflection is the Coriolis part alone */
    b = budget();
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-6, &b, &R, &e), MECH_OK);
    report("falling object 100 m, 32 deg, 1e-6", &R);
    CHECK(R.problem.fictitious == MECH_FICTITIOUS_CORIOLIS);
    CHECK_CLOSE(R.second_centrifugal.r.y, 0.0, 0, 1e-20);
    CHECK_CLOSE(-R.numerical.r.y, k / 6.0, 1e-2, 1e-9);
    CHECK(fabs(R.unexplained.r.y) < R.integration_tolerance);
    /* the equator: no south deflection at any order (sin lat = 0); planar */
    sc = earth(0.0);
    sc.r0 = mech_vec3_make(0, 0, h);
    b = budget();
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-10, &b, &R, &e), MECH_OK);
    CHECK_CLOSE(R.numerical.r.y, 0.0, 0, 1e-15);
    CHECK_EQ_INT(R.run.dimensions, 2);
    CHECK_CLOSE(R.first_order.r.x, W_E / 3.0 * sqrt(8.0 * h * h * h / G0), 1e-14, 0);
    /* domain errors */
    sc.latitude_deg = 91.0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-8, &b, &R, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "latitude_deg") == 0);
    sc = earth(10.0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-8, &b, &R, &e),
                 MECH_EDOMAIN); /* on the ground at rest */
}

static void test_vertical_shot(void)
{
    const double h = 100.0, lat = 32.0 * MECH_PI / 180.0, s = sin(lat), c = cos(lat);
    const double v0 = sqrt(2.0 * G0 * h), T = 2.0 * v0 / G0;
    struct mech_scene_ballistic sc = earth(32.0);
    sc.v0 = mech_vec3_make(0, 0, v0);
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = budget();
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-10, &b, &R, &e), MECH_OK);
    report("vertical shot h 100 m, 32 deg", &R);
    const double west = 4.0 / 3.0 * W_E * c * sqrt(8.0 * h * h * h / G0);
    CHECK_CLOSE(-R.first_order.r.x, west, 1e-13, 0);
    /* four times the drop's deflection (the notes' problem 3) */
    CHECK_CLOSE(-R.first_order.r.x / (W_E * c / 3.0 * sqrt(8.0 * h * h * h / G0)), 4.0, 1e-13, 0);
    CHECK_CLOSE(R.first_order.t, T, 1e-15, 0);
    /* second order: north W^2 s c v0 T^3 (1/3 Coriolis - 1/12 centrifugal) */
    const double k = W_E * W_E * s * c * v0 * T * T * T;
    CHECK_CLOSE(R.second_coriolis.r.y, k / 3.0, 1e-6, 0);
    CHECK_CLOSE(R.second_centrifugal.r.y, -k / 12.0, 1e-6, 0);
    CHECK_CLOSE(R.numerical.r.y, k / 4.0, 1e-3, 1e-9);
    /* unexplained: third order, W^3 cos^3 g T^5 ~ 5e-8 m times a small coefficient
     * (measured 1e-8 m east, 1e-12 m north): below 1e-3 of the second order */
    CHECK(hypot(R.unexplained.r.x, R.unexplained.r.y) <
          1e-3 * hypot(R.second_order.r.x, R.second_order.r.y) + R.integration_tolerance);
    CHECK(hypot(R.difference.r.x, R.difference.r.y) <=
          2.0 * hypot(R.second_order.r.x, R.second_order.r.y) + R.integration_tolerance);
}

static void test_cannonball(void)
{
    const double v0 = 500.0, al = 30.0 * MECH_PI / 180.0, lat = 45.0 * MECH_PI / 180.0;
    struct mech_scene_ballistic sc = earth(45.0);
    sc.v0 = mech_vec3_make(v0 * cos(al), 0, v0 * sin(al));
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = budget();
    CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-10, &b, &R, &e), MECH_OK);
    report("cannonball 500 m/s, 30 deg, due east, 45 deg", &R);
    const double sa = sin(al), ca = cos(al), R0 = v0 * v0 * sin(2.0 * al) / G0;
    const double d = 4.0 * v0 * v0 * v0 * W_E * sin(lat) * sa * sa * ca / (G0 * G0);
    const double dR =
        W_E * cos(lat) * sqrt(2.0 * R0 * R0 * R0 / G0) * (sqrt(ca / sa) - pow(sa / ca, 1.5) / 3.0);
    CHECK_CLOSE(-R.first_order.r.y, d, 1e-12, 0);      /* problem 4: south */
    CHECK_CLOSE(R.first_order.r.x - R0, dR, 1e-10, 0); /* problem 5: range increase */
    CHECK_CLOSE(R.zeroth.r.x, R0, 1e-15, 0);
    /* numerical - first order = second order, up to third order in W T0 = 4e-3 */
    const double so = hypot(R.second_order.r.x, R.second_order.r.y);
    const double un = hypot(R.unexplained.r.x, R.unexplained.r.y);
    printf("  |second order| = %.4g m, |unexplained| = %.3g m (%.2g of it)\n", so, un, un / so);
    CHECK(un < 0.02 * so + R.integration_tolerance);
    CHECK(so < 1e-2 * hypot(R.first_order.r.x - R0, R.first_order.r.y)); /* it is second order */
    /* firing north: deflected right (east) in the northern hemisphere, left in the south */
    for (int k = 0; k < 2; k++) {
        sc = earth(k ? -45.0 : 45.0);
        sc.v0 = mech_vec3_make(0, v0 * ca, v0 * sa);
        b = budget();
        CHECK_EQ_INT(mech_scene_ballistic_run(&sc, 1e-8, &b, &R, &e), MECH_OK);
        CHECK(k ? R.numerical.r.x < 0.0 : R.numerical.r.x > 0.0);
        CHECK(k ? R.first_order.r.x < 0.0 : R.first_order.r.x > 0.0);
    }
}

static void test_table(void)
{
    enum { N = 41 };
    static double t[N];
    static struct mech_vec3 a[N], rot[N], ex[N];
    struct mech_scene_table s;
    memset(&s, 0, sizeof s);
    s.experiment = MECH_TABLE_THROUGH_CENTER;
    s.omega = 2.0;
    s.radius = 3.0;
    s.mass = 0.5;
    s.samples = N;
    struct mech_scene_table_result r;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.inertial = a;
    r.rotating = rot;
    r.rotating_exact = ex;
    struct mech_budget b = budget();
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_scene_table_run(&s, 1e-10, &b, &r, &e), MECH_OK);
    /* the notes: F' = -m w^2 r (e_y + (4/pi) e_x) at t = 0 */
    const double f = s.mass * s.omega * s.omega * s.radius;
    CHECK_CLOSE(r.total.x, -4.0 / MECH_PI * f, 1e-15, 0);
    CHECK_CLOSE(r.total.y, -f, 1e-15, 0);
    CHECK_CLOSE(r.centrifugal.y, f, 1e-15, 0);
    CHECK_CLOSE(r.coriolis.y, -2.0 * f, 1e-15, 0);
    CHECK_CLOSE(r.v0_rotating.x, s.omega * s.radius, 1e-15, 0); /* -w x r = w r e_x */
    CHECK_CLOSE(r.t_end, MECH_PI / s.omega, 1e-15, 0);
    /* inertial: through the centre at half time, at -r1 e_y at the end */
    CHECK_CLOSE(a[N / 2].y, 0.0, 0, 1e-15);
    CHECK_CLOSE(a[N - 1].y, -s.radius, 1e-15, 0);
    /* rotating: back at the start after half a turn */
    CHECK_CLOSE(r.end_rotating.x, 0.0, 0, 1e-9);
    CHECK_CLOSE(r.end_rotating.y, s.radius, 1e-9, 0);
    printf("table through centre: max |rotating - exact| = %.3g m (%.2g rel), end (%.3g, %.12g)\n",
           r.max_position_error, r.max_relative_position_error, r.end_rotating.x, r.end_rotating.y);
    CHECK(r.max_relative_position_error < 1e-9);
    CHECK(r.model.fictitious == (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL));
    CHECK_EQ_INT(r.run.dimensions, 2);
    /* at rest inertially: a circle of radius r1 in the rotating frame, held by
     * F' = -m w^2 r e_y (Coriolis twice the centrifugal, opposite) */
    s.experiment = MECH_TABLE_AT_REST;
    s.omega = -0.5;
    memset(&r, 0, sizeof r);
    r.rotating = rot;
    CHECK_EQ_INT(mech_scene_table_run(&s, 1e-10, &b, &r, &e), MECH_OK);
    const double f2 = s.mass * s.omega * s.omega * s.radius;
    CHECK_CLOSE(r.total.y, -f2, 1e-15, 0);
    CHECK_CLOSE(r.total.x, 0.0, 0, 1e-15);
    CHECK_CLOSE(r.coriolis.y, -2.0 * f2, 1e-15, 0);
    for (size_t i = 0; i < r.n_samples; i++)
        CHECK_CLOSE(mech_vec3_norm(rot[i]), s.radius, 1e-9, 0);
    /* errors */
    s.omega = 0.0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_scene_table_run(&s, 1e-8, &b, &r, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "omega") == 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_falling();
    test_vertical_shot();
    test_cannonball();
    test_table();
    TEST_MAIN_END();
}
