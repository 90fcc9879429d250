/* test_em_fields.c — E and B under a boost (core/relativity/em_fields.c): the notes'
 * component formulas for a boost along x, the field of a charge at rest seen
 * moving (B' = −β×E'), invariants before and after (to 1e-14 of the field
 * scale squared up to γ = 1e15), there-and-back identity, a plane wave
 * staying null with its amplitude scaled by the Doppler factor of
 * core/relativity/doppler.c, SI against Heaviside–Lorentz, and the extremes. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/relativity/doppler.h"
#include "mech/relativity/em_fields.h"
#include "testlib.h"

static struct mech_em_boosted boost_fields(const struct mech_boost *b, struct mech_vec3 e,
                                           struct mech_vec3 bf, enum mech_em_units u)
{
    struct mech_em_boosted r;
    struct mech_error err;
    mech_error_clear(&err);
    enum mech_status st = mech_em_fields_boost(b, e, bf, u, &r, &err);
    CHECK(st == MECH_OK);
    if (st != MECH_OK) fprintf(stderr, "  error: %s\n", err.text);
    return r;
}

static void check_vec(struct mech_vec3 got, struct mech_vec3 want, double atol)
{
    CHECK_CLOSE(got.x, want.x, 0, atol);
    CHECK_CLOSE(got.y, want.y, 0, atol);
    CHECK_CLOSE(got.z, want.z, 0, atol);
}

/* Invariants after must equal before to tol × scale². */
static void check_invariants(const struct mech_em_boosted *r, double tol, double scale_extra)
{
    CHECK_CLOSE(r->after.e2_minus_b2, r->before.e2_minus_b2, 0, tol * r->scale2);
    CHECK_CLOSE(r->after.e_dot_b * scale_extra, r->before.e_dot_b * scale_extra, 0,
                tol * r->scale2);
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_boost b;

    /* Notes "Lorentz Transformation of the Fields", boost along x with
     * β = 0.6 (γ = 1.25 for the double 0.6 to 1e-16): E'x = Ex,
     * E'y = γ(Ey − βBz), E'z = γ(Ez + βBy), B'x = Bx, B'y = γ(By + βEz),
     * B'z = γ(Bz − βEy). E = (1,2,3), B = (4,5,6):
     * E' = (1, −2, 7.5), B' = (4, 8.5, 6); E² − B² = 14 − 77 = −63 and
     * E·B = 32 before and after. */
    CHECK(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &b, NULL) == MECH_OK);
    struct mech_em_boosted r = boost_fields(&b, mech_vec3_make(1, 2, 3), mech_vec3_make(4, 5, 6),
                                            MECH_EM_HEAVISIDE_LORENTZ);
    check_vec(r.e, mech_vec3_make(1, -2, 7.5), 1e-14);
    check_vec(r.b, mech_vec3_make(4, 8.5, 6), 1e-14);
    CHECK_CLOSE(r.before.e2_minus_b2, -63, 0, 0);
    CHECK_CLOSE(r.before.e_dot_b, 32, 0, 0);
    CHECK_CLOSE(r.after.e2_minus_b2, -63, 1e-15, 0);
    CHECK_CLOSE(r.after.e_dot_b, 32, 1e-15, 0);
    CHECK_CLOSE(r.scale2, 91, 0, 0);

    /* A charge at rest (pure E) seen from a frame moving with β (any
     * direction): B' = −β×E' (it moves with −βc), E'∥ = E∥, and
     * E² − B² = |E|² > 0 stays, E·B = 0 stays. */
    {
        const struct mech_vec3 e = mech_vec3_make(1, 2, -3);
        const struct mech_vec3 betas[] = {mech_vec3_make(0.3, -0.2, 0.5),
                                          mech_vec3_make(0, 0, -0.999), mech_vec3_make(1e-9, 0, 0)};
        for (int i = 0; i < 3; i++) {
            CHECK(mech_boost_from_beta(betas[i], &b, NULL) == MECH_OK);
            r = boost_fields(&b, e, mech_vec3_make(0, 0, 0), MECH_EM_HEAVISIDE_LORENTZ);
            struct mech_vec3 want_b = mech_vec3_scale(mech_vec3_cross(betas[i], r.e), -1);
            check_vec(r.b, want_b, 4e-16 * b.gamma * 4);
            CHECK_CLOSE(mech_vec3_dot(r.e, b.direction), mech_vec3_dot(e, b.direction), 1e-15,
                        1e-15);
            CHECK_CLOSE(r.after.e2_minus_b2, 14, 1e-15, 0);
            CHECK_CLOSE(r.after.e_dot_b, 0, 0, 1e-15 * r.scale2);
        }
    }

    /* Invariants and there-and-back at every speed: random-looking fields,
     * oblique boosts from η = 1e-12 to γ = 1e15 (η ≈ 35.2). */
    {
        const double etas[] = {1e-12, 1e-3, 0.7, 5, 20, 35.2};
        const struct mech_vec3 e = mech_vec3_make(0.37, -1.21, 2.03);
        const struct mech_vec3 bf = mech_vec3_make(-0.77, 0.52, 1.4);
        double worst = 0, worst_rt = 0;
        for (size_t i = 0; i < sizeof etas / sizeof etas[0]; i++) {
            CHECK(mech_boost_from_rapidity(etas[i], mech_vec3_make(1, -2, 0.5), &b, NULL) ==
                  MECH_OK);
            r = boost_fields(&b, e, bf, MECH_EM_HEAVISIDE_LORENTZ);
            check_invariants(&r, 1e-15, 1);
            worst = fmax(worst, fabs(r.after.e2_minus_b2 - r.before.e2_minus_b2) / r.scale2);
            worst = fmax(worst, fabs(r.after.e_dot_b - r.before.e_dot_b) / r.scale2);
            if (etas[i] > 5) continue;
            /* There and back: the boosted fields are rounded at their own size,
             * ~e^{η} larger, and that round-off is amplified e^{η} on the way
             * back (as for 4-vectors, tests/core/relativity/test_boost.c). */
            struct mech_boost inv = mech_boost_inverse(&b);
            struct mech_em_boosted back = boost_fields(&inv, r.e, r.b, MECH_EM_HEAVISIDE_LORENTZ);
            const double tol = 1e-15 * exp(2 * etas[i]) * 2.5 * 8;
            check_vec(back.e, e, tol);
            check_vec(back.b, bf, tol);
            worst_rt = fmax(worst_rt,
                            fmax(fabs(back.e.x - e.x), fabs(back.b.z - bf.z)) / exp(2 * etas[i]));
        }
        printf("invariant agreement (relative to |E|^2+|B|^2): worst %.3g; round trip worst "
               "%.3g e^(2 eta)\n",
               worst, worst_rt);
    }

    /* Plane wave along +x (E = A ŷ, B = A ẑ, E ⟂ B, |E| = |B|): after any
     * boost it stays null (both invariants exactly 0 in the light-cone form)
     * and its amplitude scales by the Doppler factor of an observer with that
     * velocity: D = γ(1 − β·x̂) (core/relativity/doppler.c, independent formula). */
    {
        const double amp = 3.5;
        const struct mech_vec3 e = mech_vec3_make(0, amp, 0), bf = mech_vec3_make(0, 0, amp);
        const struct mech_vec3 dirs[] = {mech_vec3_make(1, 0, 0), mech_vec3_make(-1, 0, 0),
                                         mech_vec3_make(0.3, 0.4, -1), mech_vec3_make(0, 1, 0)};
        const double etas[] = {1e-12, 0.4, 17, 35};
        for (int k = 0; k < 4; k++) {
            for (int i = 0; i < 4; i++) {
                CHECK(mech_boost_from_rapidity(etas[i], dirs[k], &b, NULL) == MECH_OK);
                r = boost_fields(&b, e, bf, MECH_EM_HEAVISIDE_LORENTZ);
                struct mech_doppler d;
                CHECK(mech_doppler_compute(NULL, &b, mech_vec3_make(1, 0, 0),
                                           MECH_DOPPLER_SOURCE_FRAME, &d, NULL) == MECH_OK);
                double ne = mech_vec3_norm(r.e), nb = mech_vec3_norm(r.b);
                CHECK_CLOSE(ne, amp * d.factor, 4e-15, 0);
                CHECK_CLOSE(nb, amp * d.factor, 4e-15, 0);
                CHECK_CLOSE(mech_vec3_dot(r.e, r.b), 0, 0, 4e-15 * ne * nb);
                CHECK_CLOSE(r.after.e2_minus_b2, 0, 0, 1e-15 * r.scale2);
                CHECK_CLOSE(r.after.e_dot_b, 0, 0, 1e-15 * r.scale2);
                if (k < 2) {
                    /* Along the line of flight: exactly e^{∓η}, components exact. */
                    CHECK_CLOSE(r.e.y, amp * (k == 0 ? exp(-etas[i]) : exp(etas[i])), 4e-16, 0);
                    CHECK(r.after.e2_minus_b2 == 0 && r.after.e_dot_b == 0);
                    /* A wave keeps full relative precision there and back. */
                    struct mech_boost inv = mech_boost_inverse(&b);
                    struct mech_em_boosted back =
                        boost_fields(&inv, r.e, r.b, MECH_EM_HEAVISIDE_LORENTZ);
                    CHECK_CLOSE(back.e.y, amp, 1e-15, 0);
                    CHECK_CLOSE(back.b.z, amp, 1e-15, 0);
                }
            }
        }
    }

    /* SI against Heaviside–Lorentz: (E, cB) transforms as the HL (E, B). */
    {
        const double c = MECH_C;
        const struct mech_vec3 e = mech_vec3_make(1e3, -2e3, 500);
        const struct mech_vec3 bsi = mech_vec3_make(1e-5, 0, 3e-5);
        CHECK(mech_boost_from_beta(mech_vec3_make(0.2, 0.5, -0.1), &b, NULL) == MECH_OK);
        struct mech_em_boosted si = boost_fields(&b, e, bsi, MECH_EM_SI);
        struct mech_em_boosted hl =
            boost_fields(&b, e, mech_vec3_scale(bsi, c), MECH_EM_HEAVISIDE_LORENTZ);
        check_vec(si.e, hl.e, 1e-15 * mech_vec3_norm(hl.e));
        check_vec(mech_vec3_scale(si.b, c), hl.b, 1e-15 * mech_vec3_norm(hl.b));
        CHECK_CLOSE(si.before.e2_minus_b2, hl.before.e2_minus_b2, 1e-15, 0);
        CHECK_CLOSE(si.after.e_dot_b * c, hl.after.e_dot_b, 1e-15, 0);
        check_invariants(&si, 1e-15, c);
        /* SI by hand, boost along x with v = 0.6c: E'y = γ(Ey − v Bz). */
        CHECK(mech_boost_from_beta(mech_vec3_make(0.6, 0, 0), &b, NULL) == MECH_OK);
        si = boost_fields(&b, e, bsi, MECH_EM_SI);
        CHECK_CLOSE(si.e.y, 1.25 * (-2e3 - 0.6 * c * 3e-5), 1e-15, 0);
        CHECK_CLOSE(si.b.z, 1.25 * (3e-5 - 0.6 * (-2e3) / c), 1e-15, 0);
    }

    /* Extremes. β = 1e-12 with E only along y and B along z: E'y = γ(Ey − βBz)
     * keeps the tiny β term; γ = 1e15: a nearly null field keeps its invariants. */
    {
        CHECK(mech_boost_from_beta(mech_vec3_make(1e-12, 0, 0), &b, NULL) == MECH_OK);
        r = boost_fields(&b, mech_vec3_make(0, 0, 0), mech_vec3_make(0, 0, 1),
                         MECH_EM_HEAVISIDE_LORENTZ);
        CHECK_CLOSE(r.e.y, -b.beta_gamma, 1e-16, 0);
        CHECK_CLOSE(r.b.z, b.gamma, 1e-16, 0);
        CHECK(mech_boost_from_gamma(1e15, mech_vec3_make(0, 0, 1), &b, NULL) == MECH_OK);
        r = boost_fields(&b, mech_vec3_make(1, 0, 0), mech_vec3_make(0, 1 + 1e-10, 0),
                         MECH_EM_HEAVISIDE_LORENTZ);
        check_invariants(&r, 1e-16, 1);
        /* E'x = γ(Ex − βBy) = γ(1 − β) − βγδ with δ the excess of By over 1
         * (exactly (1 + 1e-10) − 1 in doubles): −1e5 plus 5e-16. */
        const double delta = (1 + 1e-10) - 1;
        CHECK_CLOSE(r.e.x, -b.beta_gamma * delta, 1e-14, 0);
        /* Huge but finite fields. */
        r = boost_fields(&b, mech_vec3_make(1e100, 0, 0), mech_vec3_make(0, 0, 1e100),
                         MECH_EM_HEAVISIDE_LORENTZ);
        CHECK_CLOSE(r.e.x, 1e115, 1e-15, 0);
        check_invariants(&r, 1e-16, 1);
    }

    /* Invalid input. */
    {
        struct mech_em_boosted o;
        struct mech_error err;
        mech_error_clear(&err);
        CHECK(mech_em_fields_boost(&b, mech_vec3_make(NAN, 0, 0), mech_vec3_make(0, 0, 0),
                                   MECH_EM_SI, &o, &err) == MECH_EINVAL);
        CHECK(strcmp(err.param, "E") == 0);
        CHECK(mech_em_fields_boost(NULL, mech_vec3_make(0, 0, 0), mech_vec3_make(0, 0, 0),
                                   MECH_EM_SI, &o, NULL) == MECH_EINVAL);
    }
    TEST_MAIN_END();
}
