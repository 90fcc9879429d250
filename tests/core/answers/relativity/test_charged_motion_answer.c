/* test_charged_motion_answer.c — what a course asks of a charge in uniform
 * fields (core/answers/relativity/charged_motion_answer.c), against closed forms
 * written here:
 *   the E x B drift at 0.8 c: frame velocity E x B/B^2, gamma 5/3, B' = B/gamma,
 *   E' = 0; from rest the helix there has radius gamma_w^2 w m/(q B) and proper
 *   period 2 pi gamma_w m/(q B);
 *   hyperbolic motion of an electron from rest at lab time t and at proper
 *   time tau: z = (c^2/a)(sqrt(1 + (a t/c)^2) - 1), tau = (c/a) asinh(a t/c),
 *   t = (c/a) sinh(a tau/c), z = (c^2/a)(cosh(a tau/c) - 1);
 *   parallel E and B: the transverse helix turns at q B/m per proper second
 *   with radius u_perp m/(q B), the drift along the fields hyperbolic;
 *   |E| > c|B| crossed: B vanishes in the frame at c^2 B/E;
 *   a constant force alone (q = 0) is hyperbolic motion, no frame fields;
 *   null fields and bad times refused. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/answers/relativity/charged_motion_answer.h"
#include "mech/base/constants.h"
#include "testlib.h"

#define QP 1.602176634e-19
#define MP 1.67262192369e-27
#define ME 9.1093837015e-31

static const double c = MECH_C;

static struct mech_vec3 V(double x, double y, double z) { return mech_vec3_make(x, y, z); }

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_charged_answer a;
    struct mech_charged_motion_state st[4], sp[4];
    struct mech_error e;

    /* E x B drift, proton, E = 0.8 c (1 T) along y, B = 1 T along z */
    {
        struct mech_charged_question q = {.mass = MP, .charge = QP, .E = V(0, 0.8 * c, 0),
                                          .B = V(0, 0, 1)};
        CHECK(mech_charged_answer(&q, &a, st, sp, &e) == MECH_OK);
        CHECK_EQ_INT(a.motion.kind, MECH_CHARGED_CROSSED_MAGNETIC);
        CHECK_CLOSE(a.frame_velocity.x, 0.8 * c, 1e-15, 0);
        CHECK_CLOSE(a.frame_gamma, 5.0 / 3.0, 1e-15, 0);
        CHECK(!strcmp(a.vanishes, "E"));
        CHECK_CLOSE(a.frame_B.z, 0.6, 1e-14, 0);
        CHECK_CLOSE(mech_vec3_norm(a.frame_E), 0, 0, 0);
        CHECK_CLOSE(a.e2_minus_c2b2, -0.36 * c * c, 1e-14, 0);
        const double Om = QP / MP, gw = 5.0 / 3.0, w = 0.8 * c;
        CHECK(a.has_helix && a.has_pitch && !a.has_hyperbolic);
        CHECK_CLOSE(a.radius, gw * gw * w / Om, 1e-14, 0);
        CHECK_CLOSE(a.proper_period, 2 * MECH_PI * gw / Om, 1e-14, 0);
        CHECK_CLOSE(a.period, 2 * MECH_PI * gw * gw / Om, 1e-14, 0);
        CHECK_CLOSE(a.pitch, 0, 0, 1e-20);
    }
    /* hyperbolic motion of an electron in E = 1 MV/m along z (force along -z) */
    {
        const double E = 1e6, acc = QP * E / ME;
        const double ts[2] = {1e-9, 1e-6}, taus[1] = {1e-9};
        struct mech_charged_question q = {.mass = ME, .charge = -QP, .E = V(0, 0, E),
                                          .t = ts, .n_t = 2, .tau = taus, .n_tau = 1};
        CHECK(mech_charged_answer(&q, &a, st, sp, &e) == MECH_OK);
        CHECK_EQ_INT(a.motion.kind, MECH_CHARGED_ELECTRIC);
        CHECK(!strcmp(a.vanishes, "B") && !a.has_helix && a.has_hyperbolic);
        CHECK_CLOSE(a.accel_proper, acc, 1e-15, 0);
        CHECK_CLOSE(a.frame_E.z, E, 1e-15, 0); /* the field itself (the lab is the frame) */
        CHECK_CLOSE(a.motion.n.z, -1.0, 0, 0);  /* the axis along the force on -e */
        for (int i = 0; i < 2; i++) {
            const double x = acc * ts[i] / c, g = sqrt(1 + x * x);
            CHECK_CLOSE(st[i].r.z, -c * c / acc * (x * x / (g + 1)), 1e-13, 0);
            CHECK_CLOSE(st[i].tau, c / acc * asinh(x), 1e-13, 0);
            CHECK_CLOSE(st[i].gamma, g, 1e-14, 0);
        }
        const double k = acc * taus[0] / c;
        CHECK_CLOSE(sp[0].t, c / acc * sinh(k), 1e-13, 0);
        CHECK_CLOSE(sp[0].r.z, -c * c / acc * 2 * sinh(k / 2) * sinh(k / 2), 1e-13, 0);
        CHECK_CLOSE(sp[0].u.z, -c * sinh(k), 1e-13, 0);
    }
    /* parallel E and B along z, proton with u = (1e8, 0, 0) */
    {
        const double E = 3e5, B = 0.5, u = 1e8, taus[1] = {2e-8};
        struct mech_charged_question q = {.mass = MP, .charge = QP, .E = V(0, 0, E),
                                          .B = V(0, 0, B), .proper_velocity = V(u, 0, 0),
                                          .tau = taus, .n_tau = 1};
        CHECK(mech_charged_answer(&q, &a, st, sp, &e) == MECH_OK);
        CHECK_EQ_INT(a.motion.kind, MECH_CHARGED_PARALLEL);
        CHECK(!strcmp(a.vanishes, "neither") && a.has_helix && !a.has_pitch && a.has_hyperbolic);
        const double Om = QP * B / MP, acc = QP * E / MP, k = acc / c;
        CHECK_CLOSE(a.omega_proper, Om, 1e-15, 0);
        CHECK_CLOSE(a.radius, u / Om, 1e-15, 0);
        CHECK_CLOSE(a.proper_period, 2 * MECH_PI / Om, 1e-15, 0);
        const double tau = taus[0], U0 = c * sqrt(1 + (u / c) * (u / c));
        CHECK_CLOSE(sp[0].t, U0 * sinh(k * tau) / (k * c), 1e-13, 0);
        CHECK_CLOSE(sp[0].r.z, U0 * (cosh(k * tau) - 1) / k, 1e-11, 0);
        CHECK_CLOSE(sp[0].r.x, u / Om * sin(Om * tau), 1e-12, 0);
        CHECK_CLOSE(sp[0].r.y, u / Om * (cos(Om * tau) - 1), 1e-12, 0);
    }
    /* crossed, |E| = 2 c |B|: B vanishes in the frame at c^2 B/E = c/2 */
    {
        struct mech_charged_question q = {.mass = MP, .charge = QP, .E = V(0, 2 * c * 1e-3, 0),
                                          .B = V(0, 0, 1e-3)};
        CHECK(mech_charged_answer(&q, &a, st, sp, &e) == MECH_OK);
        CHECK_EQ_INT(a.motion.kind, MECH_CHARGED_CROSSED_ELECTRIC);
        CHECK(!strcmp(a.vanishes, "B"));
        CHECK_CLOSE(a.frame_beta, 0.5, 1e-15, 0);
        CHECK_CLOSE(mech_vec3_norm(a.frame_E), sqrt(3.0) * c * 1e-3, 1e-14, 0);
    }
    /* a constant force alone: hyperbolic, no fields to report */
    {
        struct mech_charged_question q = {.mass = 2.0, .charge = 0.0, .force = V(0, 0, -19.6)};
        CHECK(mech_charged_answer(&q, &a, st, sp, &e) == MECH_OK);
        CHECK(!a.has_frame_fields && a.has_hyperbolic);
        CHECK_CLOSE(a.accel_proper, 9.8, 1e-15, 0);
    }
    /* refusals */
    {
        struct mech_charged_question q = {.mass = MP, .charge = QP, .E = V(0, c, 0),
                                          .B = V(0, 0, 1)};
        mech_error_clear(&e);
        CHECK(mech_charged_answer(&q, &a, st, sp, &e) == MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "E"));
        const double bad[1] = {-1.0};
        struct mech_charged_question r = {.mass = MP, .charge = QP, .B = V(0, 0, 1), .t = bad,
                                          .n_t = 1};
        mech_error_clear(&e);
        CHECK(mech_charged_answer(&r, &a, st, sp, &e) == MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "times/0"));
        r.n_t = 0;
        r.mass = 0.0;
        CHECK(mech_charged_answer(&r, &a, st, sp, &e) == MECH_EDOMAIN);
    }
    TEST_MAIN_END();
}
