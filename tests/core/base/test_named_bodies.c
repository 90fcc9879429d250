/* test_named_bodies.c — the versioned named-body sets (core/base/named_bodies.c):
 * each set answers its own values, as published:
 *   DE440: GM_sun = 1.32712440041279419e20, GM_moon = 4.902800118e12 m^3/s^2
 *     (Park et al. 2021, Table 8: 132712440041.279419 and 4902.800118 km^3/s^2);
 *   legacy: GM_sun = 1.32712440018e20 (DE405), the Moon's mass 7.342e22 kg with
 *     GM = G m = 6.67430e-11 x 7.342e22 = 4.90027106e12 m^3/s^2;
 *   both: GM_E = 3.986004418e14 (IERS 2010), radii 6371008.8, 1.7374e6, 6.957e8 m;
 * the Sun's Schwarzschild radius 2 GM/c^2 differs between the sets in its
 * 10th digit (2953.2500770 m against 2953.2500765 m); every source names its set. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/named_bodies.h"
#include "testlib.h"

int main(void)
{
    gsl_set_error_handler_off();
    const struct mech_named_body *s = mech_named_body(MECH_BODY_SET_DE440, "sun");
    const struct mech_named_body *m = mech_named_body(MECH_BODY_SET_DE440, "moon");
    const struct mech_named_body *e = mech_named_body(MECH_BODY_SET_DE440, "earth");
    const struct mech_named_body *ls = mech_named_body(MECH_BODY_SET_LEGACY, "sun");
    const struct mech_named_body *lm = mech_named_body(MECH_BODY_SET_LEGACY, "moon");
    const struct mech_named_body *le = mech_named_body(MECH_BODY_SET_LEGACY, "earth");
    CHECK(s && m && e && ls && lm && le);
    if (!(s && m && e && ls && lm && le)) TEST_MAIN_END();
    CHECK_CLOSE(s->gm, 1.32712440041279419e20, 0, 0);
    CHECK_CLOSE(m->gm, 4.902800118e12, 0, 0);
    CHECK_CLOSE(e->gm, 3.986004418e14, 0, 0);
    CHECK_CLOSE(ls->gm, 1.32712440018e20, 0, 0);
    CHECK_CLOSE(lm->mass, 7.342e22, 0, 0);
    CHECK_CLOSE(lm->gm, 6.67430e-11 * 7.342e22, 1e-16, 0);
    CHECK_CLOSE(lm->gm, 4.90027106e12, 1e-9, 0);
    CHECK_CLOSE(le->gm, e->gm, 0, 0);
    CHECK_CLOSE(m->radius, 1.7374e6, 0, 0);
    CHECK_CLOSE(s->radius, 6.957e8, 0, 0);
    CHECK_CLOSE(e->radius, 6371008.8, 0, 0);
    CHECK_CLOSE(s->distance, 1.495978707e11, 0, 0);
    CHECK_CLOSE(m->distance, 3.844e8, 0, 0);
    CHECK_CLOSE(m->mass, 4.902800118e12 / 6.67430e-11, 1e-15, 0);
    /* r_s = 2 GM/c^2: 2953.2500770 m (DE440) and 2953.2500765 m (DE405) */
    const double c2 = 299792458.0 * 299792458.0;
    CHECK_CLOSE(2.0 * s->gm / c2, 2953.25007701, 1e-11, 0);
    CHECK_CLOSE(2.0 * ls->gm / c2, 2953.25007650, 1e-11, 0);
    CHECK(fabs(2.0 * s->gm / c2 - 2.0 * ls->gm / c2) > 1e-7); /* the 10th digit */
    CHECK(strstr(s->source, "DE440") && strstr(m->source, "DE440"));
    CHECK(strstr(ls->source, "legacy") && strstr(ls->source, "DE405"));
    CHECK(strstr(lm->source, "legacy") && strstr(lm->source, "7.342e22"));
    /* names */
    enum mech_body_set set = MECH_BODY_SET_DE440;
    CHECK(mech_body_set_parse("legacy", &set) && set == MECH_BODY_SET_LEGACY);
    CHECK(mech_body_set_parse("DE440", &set) && set == MECH_BODY_SET_DE440);
    CHECK(!mech_body_set_parse("DE430", &set) && set == MECH_BODY_SET_DE440);
    CHECK(!mech_body_set_parse(NULL, &set));
    CHECK(!strcmp(mech_body_set_name(MECH_BODY_SET_LEGACY), "legacy"));
    CHECK(mech_body_set_name((enum mech_body_set)9) == NULL);
    CHECK(mech_named_body(MECH_BODY_SET_DE440, "mars") == NULL);
    CHECK(mech_named_body((enum mech_body_set)9, "sun") == NULL);
    CHECK(mech_named_body(MECH_BODY_SET_DE440, NULL) == NULL);
    TEST_MAIN_END();
}
