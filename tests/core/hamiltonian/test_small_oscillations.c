/* test_small_oscillations.c — core/hamiltonian/small_oscillations.c against closed forms
 * and second methods: power-law potentials V = k r^n (apsidal angle
 * pi/sqrt(n + 2): Kepler pi, oscillator pi/2, the logarithm pi/sqrt 2),
 * Kepler's and the oscillator's frequencies and energies, Kepler plus eps/r^2
 * (apsidal angle pi sqrt(1 - 2 eps)), k_eff against a finite-difference second
 * derivative of the effective potential, unstable orbits (n < -2); the conical
 * pendulum against a finite-difference linearisation of its theta equation;
 * physical pendulums (rod about its end, disc about its rim in and out of its
 * plane) against the textbook formulas; and the errors. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/hamiltonian/small_oscillations.h"
#include "mech/base/constants.h"
#include "testlib.h"

static double veff(const struct mech_potential_term *t, size_t n, double m, double l, double r)
{
    double v = l * l / (2 * m * r * r);
    for (size_t i = 0; i < n; i++) v += t[i].n == 0 ? t[i].k * log(r) : t[i].k * pow(r, t[i].n);
    return v;
}

static void test_power_laws(void)
{
    const double ns[] = {-1, 2, 1, -1.5, 0, 0.5, -1.9};
    struct mech_error e;
    mech_error_clear(&e);
    for (int i = 0; i < 7; i++) {
        double n = ns[i], k = n == 0 ? 3.0 : 3.0 / n; /* k n > 0: attractive */
        struct mech_potential_term t = {k, n};
        struct mech_orbit_oscillation o;
        double m = 2.5, r0 = 1.7;
        CHECK(mech_orbit_oscillation(&t, 1, m, r0, &o, &e) == MECH_OK);
        CHECK(o.stable);
        CHECK_CLOSE(o.apsidal_angle, MECH_PI / sqrt(n + 2), 4e-16, 0);
        CHECK_CLOSE(o.omega_r / o.omega_phi, sqrt(n + 2), 4e-16, 0);
        /* second method: V_eff'(r0) = 0 and V_eff''(r0) = k_eff by differences */
        double h = 1e-4 * r0, l = o.angular_momentum;
        double f0 = veff(&t, 1, m, l, r0), fp = veff(&t, 1, m, l, r0 + h),
               fm = veff(&t, 1, m, l, r0 - h);
        CHECK_CLOSE((fp - fm) / (2 * h), 0, 0, 1e-6 * fabs(o.dv)); /* O(h^2) */
        CHECK_CLOSE((fp - 2 * f0 + fm) / (h * h), o.k_eff, 1e-6, 0);
        CHECK_CLOSE(o.energy, f0, 1e-15, 1e-15);
    }
}

static void test_kepler_and_oscillator(void)
{
    struct mech_error e;
    struct mech_orbit_oscillation o;
    const double gm = MECH_EARTH_GM, m = 1000, r0 = 7e6;
    struct mech_potential_term kep = {-gm * m, -1};
    CHECK(mech_orbit_oscillation(&kep, 1, m, r0, &o, &e) == MECH_OK);
    CHECK_CLOSE(o.omega_phi, sqrt(gm / (r0 * r0 * r0)), 1e-15, 0);
    CHECK_CLOSE(o.omega_r, o.omega_phi, 1e-15, 0);
    CHECK_CLOSE(o.apsidal_angle, MECH_PI, 1e-15, 0);
    CHECK_CLOSE(o.energy, -gm * m / (2 * r0), 1e-15, 0);
    CHECK_CLOSE(o.angular_momentum, m * sqrt(gm * r0), 1e-15, 0);
    const double w = 3;
    struct mech_potential_term osc = {m * w * w / 2, 2};
    CHECK(mech_orbit_oscillation(&osc, 1, m, 2, &o, &e) == MECH_OK);
    CHECK_CLOSE(o.omega_phi, w, 1e-15, 0);
    CHECK_CLOSE(o.omega_r, 2 * w, 1e-15, 0);
    CHECK_CLOSE(o.apsidal_angle, MECH_PI / 2, 1e-15, 0);
    CHECK_CLOSE(o.energy, m * w * w * 4, 1e-15, 0);
    /* Kepler + eps/r^2 at r0 = 1 (m = 1, GM = 1): pi sqrt(1 - 2 eps) */
    for (double eps = -0.2; eps < 0.3; eps += 0.05) {
        struct mech_potential_term two[2] = {{-1, -1}, {eps, -2}};
        CHECK(mech_orbit_oscillation(two, 2, 1, 1, &o, &e) == MECH_OK);
        CHECK_CLOSE(o.apsidal_angle, MECH_PI * sqrt(1 - 2 * eps), 1e-15, 0);
    }
    /* unstable: V = k r^-3, k < 0: k_eff = V'' + 3V'/r = V' (n + 2)/r < 0 */
    struct mech_potential_term un = {-1, -3};
    CHECK(mech_orbit_oscillation(&un, 1, 1, 1, &o, &e) == MECH_OK);
    CHECK(!o.stable);
    CHECK_CLOSE(o.growth_rate, o.omega_phi, 1e-15, 0); /* sqrt(-(n + 2)) = 1 */
    CHECK(o.apsidal_angle == 0 && o.omega_r == 0);
}

static void test_orbit_errors(void)
{
    struct mech_error e;
    struct mech_orbit_oscillation o;
    struct mech_potential_term rep = {1, -1}; /* +1/r: repulsive */
    mech_error_clear(&e);
    CHECK(mech_orbit_oscillation(&rep, 1, 1, 1, &o, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "r0"));
    struct mech_potential_term two[2] = {{-1, -1}, {NAN, 2}};
    mech_error_clear(&e);
    CHECK(mech_orbit_oscillation(two, 2, 1, 1, &o, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "terms/1/k"));
    mech_error_clear(&e);
    CHECK(mech_orbit_oscillation(two, 1, 1, 0, &o, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "r0"));
}

/* theta'' = f(theta) = h^2 cos t / sin^3 t - (g/l) sin t, h = phi' sin^2 a */
static void test_conical(void)
{
    struct mech_error e;
    struct mech_conical_pendulum c;
    const double l = 1.3, g = 9.81;
    for (double a = 0.05; a < 1.5; a += 0.2) {
        CHECK(mech_conical_pendulum(l, g, a, &c, &e) == MECH_OK);
        double h = c.phi_dot * sin(a) * sin(a);
#define F(t) (h * h * cos(t) / pow(sin(t), 3) - (g / l) * sin(t))
        CHECK_CLOSE(F(a), 0, 0, 1e-12 * g / l);
        double d = 1e-4; /* Richardson on two central differences: O(d^4) */
        double fprime = (4 * (F(a + d / 2) - F(a - d / 2)) / d - (F(a + d) - F(a - d)) / (2 * d)) / 3;
#undef F
        CHECK_CLOSE(c.omega_theta * c.omega_theta, -fprime, 1e-8, 0);
        CHECK_CLOSE(c.apsidal_angle, MECH_PI * c.phi_dot / c.omega_theta, 1e-15, 0);
        CHECK_CLOSE(c.speed, l * sin(a) * sqrt(g / (l * cos(a))), 1e-15, 0);
    }
    mech_error_clear(&e);
    CHECK(mech_conical_pendulum(l, g, MECH_PI / 2, &c, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "angle"));
}

static void test_physical(void)
{
    struct mech_error e;
    struct mech_physical_pendulum p;
    const double m = 2, g = 9.81, L = 1.2, R = 0.3;
    /* rod along z, pivot at its top end, hinge along x: I = m L^2/3, arm L/2 */
    struct mech_mat3 rod = {{{m * L * L / 12, 0, 0}, {0, m * L * L / 12, 0}, {0, 0, 0}}};
    mech_error_clear(&e);
    CHECK(mech_physical_pendulum(m, rod, mech_vec3_make(0, 0, -L / 2), mech_vec3_make(1, 0, 0), g,
                                 &p, &e) == MECH_OK);
    CHECK_CLOSE(p.moment_axis, m * L * L / 3, 1e-15, 0);
    CHECK_CLOSE(p.omega, sqrt(3 * g / (2 * L)), 1e-15, 0);
    CHECK_CLOSE(p.equivalent_length, 2 * L / 3, 1e-15, 0);
    /* disc in the xz plane (axis y), pivot on its rim above the centre */
    struct mech_mat3 disc = {{{m * R * R / 4, 0, 0}, {0, m * R * R / 2, 0}, {0, 0, m * R * R / 4}}};
    struct mech_vec3 d = mech_vec3_make(0, 0, -R);
    CHECK(mech_physical_pendulum(m, disc, d, mech_vec3_make(0, 3, 0), g, &p, &e) == MECH_OK);
    CHECK_CLOSE(p.omega, sqrt(2 * g / (3 * R)), 1e-15, 0); /* in plane: I = 3/2 m R^2 */
    CHECK(mech_physical_pendulum(m, disc, d, mech_vec3_make(-2, 0, 0), g, &p, &e) == MECH_OK);
    CHECK_CLOSE(p.omega, sqrt(4 * g / (5 * R)), 1e-15, 0); /* out of plane: 5/4 m R^2 */
    CHECK_CLOSE(p.period, 2 * MECH_PI * sqrt(5 * R / (4 * g)), 1e-15, 0);
    mech_error_clear(&e);
    CHECK(mech_physical_pendulum(m, disc, d, mech_vec3_make(0, 0, 1), g, &p, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "offset"));
    mech_error_clear(&e);
    CHECK(mech_physical_pendulum(m, disc, d, mech_vec3_make(0, 0, 0), g, &p, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "axis"));
}

/* Foucault: the modes solve -a^2 - 2 omega_z a + omega0^2 = 0 (a = ccw, -cw);
 * and a second method: integrate the linear equations (RK4, small step) from a
 * planar release and read the plane's turn after a number of swings. */
static void test_foucault(void)
{
    struct mech_foucault_modes f;
    struct mech_error e;
    mech_error_clear(&e);
    const double l = 67, g = 9.80665, w = MECH_EARTH_OMEGA, lat = 32 * MECH_PI / 180;
    CHECK(mech_foucault_modes(l, g, w, lat, &f, &e) == MECH_OK);
    CHECK_CLOSE(f.omega_z, w * sin(lat), 1e-15, 0);
    double a1 = f.ccw, a2 = -f.cw;
    CHECK_CLOSE(-a1 * a1 - 2 * f.omega_z * a1 + g / l, 0, 0, 1e-15);
    CHECK_CLOSE(-a2 * a2 - 2 * f.omega_z * a2 + g / l, 0, 0, 1e-15);
    CHECK_CLOSE(f.precession, (a1 + a2) / 2, 1e-12, 0);
    /* exaggerated rotation so the turn is visible in a short run: omega_z = 0.05 omega0 */
    double om = 0.05 * sqrt(g / l) / sin(lat);
    CHECK(mech_foucault_modes(l, g, om, lat, &f, &e) == MECH_OK);
    double s[4] = {1, 0, 0, 0}, h = 1e-3, oz = f.omega_z, w0 = g / l, t = 0;
    int n = (int)(2 * MECH_PI / f.swing * 10 / h); /* ten swing periods */
    for (int k = 0; k < n; k++, t += h) {
        double k1[4], k2[4], k3[4], k4[4], y[4];
#define RHS(o, q) (o[0] = q[2], o[1] = q[3], o[2] = -w0 * q[0] + 2 * oz * q[3], \
                   o[3] = -w0 * q[1] - 2 * oz * q[2])
        RHS(k1, s);
        for (int i = 0; i < 4; i++) y[i] = s[i] + h / 2 * k1[i];
        RHS(k2, y);
        for (int i = 0; i < 4; i++) y[i] = s[i] + h / 2 * k2[i];
        RHS(k3, y);
        for (int i = 0; i < 4; i++) y[i] = s[i] + h * k3[i];
        RHS(k4, y);
#undef RHS
        for (int i = 0; i < 4; i++) s[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    /* closed form of this release: q = e^{-i oz t} (cos W t + i (oz/W) sin W t) */
    double W = f.swing, ph = -oz * t;
    double re = cos(W * t), im = oz / W * sin(W * t);
    CHECK_CLOSE(s[0], cos(ph) * re - sin(ph) * im, 0, 1e-9);
    CHECK_CLOSE(s[1], sin(ph) * re + cos(ph) * im, 0, 1e-9);
    mech_error_clear(&e);
    CHECK(mech_foucault_modes(l, g, w, 2, &f, &e) == MECH_EINVAL);
    CHECK(!strcmp(e.param, "latitude_deg"));
}

static double det3(struct mech_mat3 m)
{
    return m.a[0][0] * (m.a[1][1] * m.a[2][2] - m.a[1][2] * m.a[2][1]) -
           m.a[0][1] * (m.a[1][0] * m.a[2][2] - m.a[1][2] * m.a[2][0]) +
           m.a[0][2] * (m.a[1][0] * m.a[2][1] - m.a[1][1] * m.a[2][0]);
}

/* Ball joint: the disc hung from its rim has the two hinge frequencies as its
 * modes; for a body with products of inertia coupling the yaw, each omega^2
 * solves det(K - omega^2 I_pivot) = 0 with K = m g |d| (1 - e e^T) (the full
 * 3-D linearisation, an independent route from the reduced 2x2 one). */
static void test_ball(void)
{
    struct mech_error e;
    struct mech_ball_pendulum b;
    const double m = 2, g = 9.81, R = 0.3;
    struct mech_mat3 disc = {{{m * R * R / 4, 0, 0}, {0, m * R * R / 2, 0}, {0, 0, m * R * R / 4}}};
    mech_error_clear(&e);
    CHECK(mech_ball_pendulum(m, disc, mech_vec3_make(0, 0, -R), g, &b, &e) == MECH_OK);
    CHECK_CLOSE(b.omega[0], sqrt(4 * g / (5 * R)), 1e-15, 0);
    CHECK_CLOSE(b.omega[1], sqrt(2 * g / (3 * R)), 1e-15, 0);
    CHECK_CLOSE(b.axis[0].x, 1, 0, 1e-15);
    CHECK_CLOSE(b.axis[1].y, 1, 0, 1e-15);
    struct mech_mat3 body = {{{0.3, 0.05, -0.08}, {0.05, 0.4, 0.06}, {-0.08, 0.06, 0.5}}};
    struct mech_vec3 d = mech_vec3_make(0.1, -0.2, -0.7);
    CHECK(mech_ball_pendulum(m, body, d, g, &b, &e) == MECH_OK);
    double dn = mech_vec3_norm(d), ev[3] = {-d.x / dn, -d.y / dn, -d.z / dn};
    for (int k = 0; k < 2; k++) {
        struct mech_mat3 a;
        double w2 = b.omega[k] * b.omega[k], scale = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                a.a[i][j] = m * g * dn * ((i == j) - ev[i] * ev[j]) - w2 * b.tensor_pivot.a[i][j];
                scale = fmax(scale, fabs(a.a[i][j]));
            }
        CHECK(fabs(det3(a)) <= 1e-13 * scale * scale * scale);
        CHECK_CLOSE(mech_vec3_dot(b.axis[k], d), 0, 0, 1e-15);
    }
    CHECK(b.omega[0] > b.omega[1]);
    mech_error_clear(&e);
    CHECK(mech_ball_pendulum(m, body, mech_vec3_make(0, 0, 0), g, &b, &e) == MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "offset"));
}

int main(void)
{
    gsl_set_error_handler_off();
    test_power_laws();
    test_kepler_and_oscillator();
    test_orbit_errors();
    test_conical();
    test_physical();
    test_foucault();
    test_ball();
    TEST_MAIN_END();
}
