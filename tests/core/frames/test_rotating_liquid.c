/* test_rotating_liquid.c — the free surface of a liquid turning with its
 * container (notes §1.5 HW 2): the volume under the answered surface
 * integrated numerically (Simpson) equals pi R² h0 in both regimes, the
 * surface is normal to the effective gravity (finite-difference slope =
 * w² r / g), the two regimes meet at w = 2 sqrt(g h0)/R, the rim reaches H
 * exactly at the spill rate in both regimes, w = 0 is flat, refused inputs. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/frames/rotating_liquid.h"
#include "mech/base/constants.h"
#include "testlib.h"

/* Volume under the surface by composite Simpson on r h(r) (n even). The
 * integrand has a kink at the dry radius, so split there. */
static double volume(const struct mech_rotating_liquid *p, const struct mech_rotating_liquid_surface *s)
{
    double total = 0, edges[3] = {0, s->dry_radius, p->radius};
    for (int k = 0; k < 2; k++) {
        double a = edges[k], b = edges[k + 1];
        if (!(b > a)) continue;
        const int n = 20000;
        double h = (b - a) / n, sum = 0;
        for (int i = 0; i <= n; i++) {
            double r = a + i * h, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
            sum += w * 2 * MECH_PI * r * mech_rotating_liquid_height(p, s, r);
        }
        total += sum * h / 3;
    }
    return total;
}

static void check_volume_and_slope(void)
{
    const double ws[] = {0, 3, 10, 14.0, 25, 80};
    for (size_t i = 0; i < sizeof ws / sizeof ws[0]; i++) {
        struct mech_rotating_liquid p = {ws[i], 9.80665, 0.1, 0.05, 0};
        struct mech_rotating_liquid_surface s;
        CHECK_EQ_INT(mech_rotating_liquid_surface(&p, &s, NULL), MECH_OK);
        double v = volume(&p, &s), v0 = MECH_PI * p.radius * p.radius * p.depth;
        printf("w = %g: exposed %d, rim %.6f m, centre %.6f m, dry r0 %.6f m, volume/rest %.15f\n",
               p.omega, s.bottom_exposed, s.rim_height, s.centre_height, s.dry_radius, v / v0);
        CHECK_CLOSE(v, v0, 1e-12, 0);
        /* equipotential: dz/dr = w² r / g wherever there is liquid (central difference) */
        for (double r = 0.02; r < 0.1; r += 0.02) {
            if (r < s.dry_radius + 1e-3) continue;
            double d = 1e-5;
            double slope = (mech_rotating_liquid_height(&p, &s, r + d) -
                            mech_rotating_liquid_height(&p, &s, r - d)) / (2 * d);
            CHECK_CLOSE(slope, p.omega * p.omega * r / p.g, 1e-7, 1e-12);
        }
        CHECK_CLOSE(mech_rotating_liquid_height(&p, &s, p.radius), s.rim_height, 1e-14, 1e-16);
        CHECK_CLOSE(s.rim_height - s.z_centre, s.rise, 1e-13, 1e-16);
    }
}

static void check_regimes_meet_and_spill(void)
{
    const double g = 9.81, R = 0.2, h0 = 0.1;
    struct mech_rotating_liquid p = {2 * sqrt(g * h0) / R, g, R, h0, 0};
    struct mech_rotating_liquid_surface s;
    CHECK_EQ_INT(mech_rotating_liquid_surface(&p, &s, NULL), MECH_OK);
    CHECK_CLOSE(s.rim_height, 2 * h0, 1e-15, 0); /* the vertex just touches the bottom */
    CHECK_CLOSE(s.z_centre, 0, 0, 1e-16);
    p.omega *= 1 + 1e-12; /* just past: the exposed branch, continuous */
    CHECK_EQ_INT(mech_rotating_liquid_surface(&p, &s, NULL), MECH_OK);
    CHECK(s.bottom_exposed);
    CHECK_CLOSE(s.rim_height, 2 * h0, 1e-11, 0);
    /* spill rate: the rim is at H exactly there, in each regime */
    const double Hs[] = {0.15, 0.2, 0.35};
    for (size_t i = 0; i < 3; i++) {
        struct mech_rotating_liquid q = {0, g, R, h0, Hs[i]};
        CHECK_EQ_INT(mech_rotating_liquid_surface(&q, &s, NULL), MECH_OK);
        CHECK(!s.spills);
        q.omega = s.omega_spill;
        CHECK_EQ_INT(mech_rotating_liquid_surface(&q, &s, NULL), MECH_OK);
        CHECK_CLOSE(s.rim_height, Hs[i], 1e-14, 0);
        q.omega *= 1.001;
        CHECK_EQ_INT(mech_rotating_liquid_surface(&q, &s, NULL), MECH_OK);
        CHECK(s.spills);
    }
    /* at rest: flat, infinite focal length */
    struct mech_rotating_liquid f = {0, g, R, h0, 0};
    CHECK_EQ_INT(mech_rotating_liquid_surface(&f, &s, NULL), MECH_OK);
    CHECK(s.rim_height == h0 && s.centre_height == h0 && isinf(s.focal_length));
}

static void check_refusals(void)
{
    struct mech_rotating_liquid_surface s;
    struct mech_error e;
    struct mech_rotating_liquid bad[] = {{-1, 9.8, 1, 1, 0},  {1, 0, 1, 1, 0},   {1, 9.8, 0, 1, 0},
                                         {1, 9.8, 1, -1, 0}, {1, 9.8, 1, 1, 0.5}, {NAN, 9.8, 1, 1, 0}};
    const char *param[] = {"omega", "g", "radius", "depth", "container_height", "omega"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        mech_error_clear(&e);
        CHECK_EQ_INT(mech_rotating_liquid_surface(&bad[i], &s, &e), MECH_EINVAL);
        CHECK(strcmp(e.param, param[i]) == 0);
    }
    CHECK_EQ_INT(mech_rotating_liquid_surface(NULL, &s, NULL), MECH_EINVAL);
}

int main(void)
{
    gsl_set_error_handler_off();
    check_volume_and_slope();
    check_regimes_meet_and_spill();
    check_refusals();
    TEST_MAIN_END();
}
