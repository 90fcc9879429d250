/* test_tides_on.c — tides raised on a body other than the Earth (the `on`
 * body of mech/answers/frames/tides_answer.h) and the named-body sets, against closed forms:
 *   the Earth raising tides on the Moon (GM_E = 3.986004418e14 m^3/s^2 at
 *   d = 3.844e8 m, point on the Moon's surface r = 1.7374e6 m below the Earth):
 *     first order 2 GM_E r / d^3 = 2.4356e-5 m/s^2 radial, exactly
 *     GM_E r (2d - r) / (d^2 (d - r)^2); equilibrium tide range
 *     3 GM_E r^4 / (2 GM_moon d^3) (19.56 m);
 *   the older form (radius and gm_earth set to the Moon's) gives the same
 *   numbers to the last bit; the legacy set's Moon changes the tide height by
 *   GM_moon(DE440) / (G 7.342e22) - 1 = 5.3e-4 and the Sun's by the DE405 GM;
 *   refusals name the field. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/frames/tides_answer.h"
#include "testlib.h"

static const double GME = 3.986004418e14, D = 3.844e8, RM = 1.7374e6;
static const double GMM = 4.902800118e12;

static struct mech_tides_request earth_on_moon(void)
{
    struct mech_tides_request q;
    memset(&q, 0, sizeof q);
    q.body = MECH_TIDES_BODY_CUSTOM;
    q.custom.has_gm = q.custom.has_distance = 1;
    q.custom.gm = GME;
    q.custom.distance = D;
    q.radius = 6371008.8;
    q.gm_earth = MECH_EARTH_GM;
    q.has_on = 1;
    q.on.name = "moon";
    return q;
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_tides_answer a, b;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_tides_request q = earth_on_moon();
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_OK);
    CHECK(!strcmp(a.on.name, "moon"));
    CHECK_CLOSE(a.on_radius, RM, 0, 0);
    CHECK_CLOSE(a.on_gm, GMM, 0, 0);
    CHECK(strstr(a.on.source, "DE440") != NULL);
    CHECK_CLOSE(a.acceleration.first_order.radial, 2.0 * GME * RM / (D * D * D), 1e-15, 0);
    CHECK_CLOSE(a.acceleration.exact.radial, GME * RM * (2.0 * D - RM) / (D * D * (D - RM) * (D - RM)),
                1e-14, 0);
    CHECK_CLOSE(a.height.range, 3.0 * GME * pow(RM, 4) / (2.0 * GMM * D * D * D), 1e-14, 0);
    CHECK_CLOSE(a.height.range, 19.563, 1e-4, 0);
    CHECK_EQ_INT(a.has_spring_neap, 0); /* the Moon and the Sun are placed about the Earth */

    /* the older form: radius and gm_earth reinterpreted as the Moon's */
    struct mech_tides_request old = earth_on_moon();
    old.has_on = 0;
    old.radius = RM;
    old.gm_earth = GMM;
    CHECK_EQ_INT(mech_tides_answer(&old, &b, &e), MECH_OK);
    CHECK(a.acceleration.exact.radial == b.acceleration.exact.radial);
    CHECK(a.acceleration.exact.tangential == b.acceleration.exact.tangential);
    CHECK(a.height.range == b.height.range);

    /* a custom `on` by mass and radius: GM = G m */
    q = earth_on_moon();
    q.on.name = NULL;
    q.on.has_mass = q.on.has_radius = 1;
    q.on.mass = 7.342e22;
    q.on.radius = RM;
    CHECK_EQ_INT(mech_tides_answer(&q, &b, &e), MECH_OK);
    CHECK_CLOSE(b.on_gm, MECH_GRAVITATIONAL_CONSTANT * 7.342e22, 1e-16, 0);
    CHECK_CLOSE(b.height.range, a.height.range * GMM / (MECH_GRAVITATIONAL_CONSTANT * 7.342e22),
                1e-14, 0);
    /* the legacy set's Moon is that same body */
    q = earth_on_moon();
    q.set = MECH_BODY_SET_LEGACY;
    struct mech_tides_answer l;
    CHECK_EQ_INT(mech_tides_answer(&q, &l, &e), MECH_OK);
    CHECK(l.height.range == b.height.range);
    CHECK(strstr(l.on.source, "legacy") != NULL);

    /* on the Earth by name: the default Earth, spring and neap kept */
    q = earth_on_moon();
    q.body = MECH_TIDES_BODY_MOON;
    q.on.name = "earth";
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_OK);
    struct mech_tides_request dflt = q;
    dflt.has_on = 0;
    CHECK_EQ_INT(mech_tides_answer(&dflt, &b, &e), MECH_OK);
    CHECK(a.height.range == b.height.range && a.has_spring_neap && b.has_spring_neap);
    CHECK(a.spring_range == b.spring_range);

    /* the sets: the Moon's tide on the Earth, 3 GM r^4 / (2 GM_E d^3) with each GM;
     * the Sun's with 1.32712440018e20 in the legacy set */
    const double r = 6371008.8;
    CHECK_CLOSE(b.moon_height.range, 3.0 * GMM * pow(r, 4) / (2.0 * GME * D * D * D), 1e-14, 0);
    dflt.set = MECH_BODY_SET_LEGACY;
    CHECK_EQ_INT(mech_tides_answer(&dflt, &l, &e), MECH_OK);
    CHECK_CLOSE(l.moon_height.range,
                3.0 * MECH_GRAVITATIONAL_CONSTANT * 7.342e22 * pow(r, 4) / (2.0 * GME * D * D * D),
                1e-14, 0);
    CHECK_CLOSE(l.sun.gm, 1.32712440018e20, 0, 0);
    CHECK_CLOSE(b.sun.gm, 1.32712440041279419e20, 0, 0);
    CHECK_CLOSE(l.moon_height.range / b.moon_height.range - 1.0,
                MECH_GRAVITATIONAL_CONSTANT * 7.342e22 / GMM - 1.0, 1e-10, 0);
    CHECK(strstr(l.moon.source, "legacy") && strstr(b.moon.source, "DE440"));

    /* refusals */
    q = earth_on_moon();
    q.custom.gm = 0;
    q.body = MECH_TIDES_BODY_MOON;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_EINVAL); /* the Moon on itself */
    CHECK(!strcmp(e.param, "on"));
    q = earth_on_moon();
    q.on.name = "mars";
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_EINVAL);
    CHECK(!strcmp(e.param, "on"));
    q = earth_on_moon();
    q.on.name = NULL;
    q.on.has_gm = 1;
    q.on.gm = GMM;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_EINVAL); /* no radius */
    CHECK(!strcmp(e.param, "on/radius"));
    q.on.has_mass = 1;
    q.on.mass = 1.0;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_EINVAL); /* both gm and mass */
    CHECK(!strcmp(e.param, "on"));
    q = earth_on_moon();
    q.on.has_radius = 1;
    q.on.radius = 4e8; /* the point beyond the Earth */
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_tides_answer(&q, &a, &e), MECH_EDOMAIN);
    CHECK(!strcmp(e.param, "body/distance"));
    TEST_MAIN_END();
}
