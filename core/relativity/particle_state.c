/* particle_state.c — one free particle's γ, β, E, p, T, η from any one of
 * them (see mech/relativity/particle_state.h). Velocity forms go through a
 * struct mech_boost (core/relativity/boost.c keeps γ − 1, 1 − β, βγ, η exact for the
 * form given); energy forms through struct mech_kin_motion
 * (core/relativity/kinematics.c: T = p²/(E + m), never E − m of a rounded E). */
#include "mech/relativity/particle_state.h"

#include <math.h>
#include <string.h>

#include "mech/relativity/boost.h"
#include "mech/relativity/kinematics.h"

static const char *const given_name[] = {
    [MECH_PARTICLE_GIVEN_BETA] = "beta",
    [MECH_PARTICLE_GIVEN_SPEED] = "speed",
    [MECH_PARTICLE_GIVEN_GAMMA] = "gamma",
    [MECH_PARTICLE_GIVEN_GAMMA_MINUS_ONE] = "gamma_minus_one",
    [MECH_PARTICLE_GIVEN_ONE_MINUS_BETA] = "one_minus_beta",
    [MECH_PARTICLE_GIVEN_RAPIDITY] = "rapidity",
    [MECH_PARTICLE_GIVEN_BETA_GAMMA] = "beta_gamma",
    [MECH_PARTICLE_GIVEN_ENERGY] = "energy",
    [MECH_PARTICLE_GIVEN_MOMENTUM] = "momentum",
    [MECH_PARTICLE_GIVEN_KINETIC] = "kinetic_energy",
};

/* Copy a callee's error, naming the caller's field instead of the callee's. */
static enum mech_status relay(struct mech_error *err, const struct mech_error *e,
                              enum mech_status st, const char *param)
{
    return mech_error_set(err, st, param, "%s", e->text);
}

/* The boost of a velocity form along +x. */
static enum mech_status boost_of(enum mech_particle_given g, double x, struct mech_boost *b,
                                 struct mech_error *err)
{
    const struct mech_vec3 ex = mech_vec3_make(1, 0, 0);
    const char *name = given_name[g];
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st;
    if (!isfinite(x)) return mech_error_set(err, MECH_EINVAL, name, "must be a finite number");
    switch (g) {
    case MECH_PARTICLE_GIVEN_BETA:
        if (x < 0) return mech_error_set(err, MECH_EDOMAIN, name, "a speed: beta >= 0, got %.17g", x);
        st = mech_boost_from_beta(mech_vec3_make(x, 0, 0), b, &e);
        break;
    case MECH_PARTICLE_GIVEN_SPEED:
        if (x < 0) return mech_error_set(err, MECH_EDOMAIN, name, "a speed is >= 0, got %.17g m/s", x);
        if (x >= MECH_C)
            return mech_error_set(err, MECH_EDOMAIN, name,
                                  "a massive particle moves slower than c = 299792458 m/s, got %.17g m/s",
                                  x);
        st = mech_boost_from_beta(mech_vec3_make(x / MECH_C, 0, 0), b, &e);
        break;
    case MECH_PARTICLE_GIVEN_GAMMA:
        st = mech_boost_from_gamma(x, ex, b, &e);
        break;
    case MECH_PARTICLE_GIVEN_GAMMA_MINUS_ONE:
        st = mech_boost_from_gamma_minus_one(x, ex, b, &e);
        break;
    case MECH_PARTICLE_GIVEN_ONE_MINUS_BETA:
        if (x > 1)
            return mech_error_set(err, MECH_EDOMAIN, name,
                                  "a speed: 1 - beta is in (0, 1], got %.17g (beta < 0)", x);
        st = mech_boost_from_one_minus_beta(x, ex, b, &e);
        break;
    case MECH_PARTICLE_GIVEN_RAPIDITY:
        if (x < 0)
            return mech_error_set(err, MECH_EDOMAIN, name, "a speed: rapidity >= 0, got %.17g", x);
        st = mech_boost_from_rapidity(x, ex, b, &e);
        break;
    case MECH_PARTICLE_GIVEN_BETA_GAMMA:
        if (x < 0)
            return mech_error_set(err, MECH_EDOMAIN, name, "beta gamma = p/m >= 0, got %.17g", x);
        /* γ − 1 = (βγ)²/(γ + 1), γ = hypot(1, βγ): no cancellation, no overflow. */
        st = mech_boost_from_gamma_minus_one(x * (x / (hypot(1.0, x) + 1.0)), ex, b, &e);
        break;
    default:
        return mech_error_set(err, MECH_EINTERNAL, NULL, "not a velocity form");
    }
    return st == MECH_OK ? MECH_OK : relay(err, &e, st, name);
}

static int is_velocity_form(enum mech_particle_given g)
{
    return g != MECH_PARTICLE_GIVEN_ENERGY && g != MECH_PARTICLE_GIVEN_MOMENTUM &&
           g != MECH_PARTICLE_GIVEN_KINETIC;
}

static void set_velocity(struct mech_particle_state *s, const struct mech_boost *b)
{
    s->has_rest_frame = 1;
    s->beta = b->beta;
    s->one_minus_beta = b->one_minus_beta;
    s->speed = b->beta * MECH_C;
    s->gamma = b->gamma;
    s->gamma_minus_one = b->gamma_minus_one;
    s->beta_gamma = b->beta_gamma;
    s->rapidity = b->rapidity;
    /* ½mβ² against T = m(γ − 1): ratio (γ + 1)/(2γ²), so the relative error is
     * −(γ − 1)(2γ + 1)/(2γ²) = −((γ − 1)/γ)(1 + 1/(2γ)), exact in γ − 1. */
    s->kinetic_newtonian = 0.5 * s->mass * b->beta * b->beta;
    s->kinetic_newtonian_rel_error = -(b->gamma_minus_one / b->gamma) * (1.0 + 0.5 / b->gamma);
    /* p²/2m / T = (γ + 1)/2 (p² = m²(γ − 1)(γ + 1)), so the error is (γ − 1)/2. */
    s->kinetic_p2_over_2m = 0.5 * (s->mass * b->beta_gamma) * b->beta_gamma;
    s->kinetic_p2_over_2m_rel_error = 0.5 * b->gamma_minus_one;
}

enum mech_status mech_particle_state_from(double m, enum mech_particle_given given, double value,
                                          struct mech_particle_state *out,
                                          struct mech_error *err)
{
    if ((unsigned)given > MECH_PARTICLE_GIVEN_KINETIC || !out)
        return mech_error_set(err, MECH_EINVAL, NULL, "unknown given quantity or NULL output");
    if (!isfinite(m) || m < 0)
        return mech_error_set(err, MECH_EDOMAIN, "mass",
                              "a mass is a finite number >= 0 (m c^2, the rest energy), got %.17g", m);
    struct mech_particle_state s;
    memset(&s, 0, sizeof s);
    s.mass = m;
    struct mech_boost b;
    if (is_velocity_form(given)) {
        if (m == 0)
            return mech_error_set(err, MECH_EDOMAIN, "mass",
                                  "a massless particle always moves at c: give its energy, "
                                  "momentum or kinetic energy, not %s", given_name[given]);
        enum mech_status st = boost_of(given, value, &b, err);
        if (st != MECH_OK) return st;
        s.energy = m * b.gamma;
        s.momentum = m * b.beta_gamma;
        s.kinetic = m * b.gamma_minus_one;
        if (!isfinite(s.energy))
            return mech_error_set(err, MECH_EDOMAIN, given_name[given],
                                  "the energy gamma m = %.17g * %.17g overflows", b.gamma, m);
        set_velocity(&s, &b);
        *out = s;
        return MECH_OK;
    }
    if (!isfinite(value))
        return mech_error_set(err, MECH_EINVAL, given_name[given], "must be a finite number");
    struct mech_kin_motion k;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st;
    if (given == MECH_PARTICLE_GIVEN_ENERGY)
        st = mech_kin_motion_from_energy(m, value, &k, &e);
    else if (given == MECH_PARTICLE_GIVEN_MOMENTUM)
        st = mech_kin_motion_from_momentum(m, value, &k, &e);
    else
        st = mech_kin_motion_from_kinetic(m, value, &k, &e);
    if (st != MECH_OK) return relay(err, &e, st, e.param[0] ? e.param : given_name[given]);
    s.energy = k.energy;
    s.momentum = k.momentum;
    s.kinetic = k.kinetic;
    if (m == 0) {
        /* E = p = T exactly (the kinematics' sqrt(T) sqrt(T + 2m) is 1 ulp off). */
        s.energy = s.momentum = s.kinetic = value;
        s.beta = 1;
        s.speed = MECH_C;
        *out = s;
        return MECH_OK;
    }
    st = mech_kin_motion_boost(&k, mech_vec3_make(1, 0, 0), &b, &e);
    if (st != MECH_OK) return relay(err, &e, st, given_name[given]);
    set_velocity(&s, &b);
    *out = s;
    return MECH_OK;
}

enum mech_status mech_particle_lifetime_of(const struct mech_particle_state *s, double tau,
                                           struct mech_particle_lifetime *out,
                                           struct mech_error *err)
{
    if (!isfinite(tau) || tau <= 0)
        return mech_error_set(err, MECH_EDOMAIN, "proper_lifetime",
                              "a lifetime is a finite number of seconds > 0, got %.17g", tau);
    if (!s->has_rest_frame)
        return mech_error_set(err, MECH_EDOMAIN, "mass",
                              "a massless particle has no rest frame, so no proper lifetime");
    const double lab = s->gamma * tau, len = s->beta_gamma * (MECH_C * tau);
    if (!isfinite(lab) || !isfinite(len))
        return mech_error_set(err, MECH_EDOMAIN, "proper_lifetime",
                              "gamma tau = %.17g * %.17g s overflows", s->gamma, tau);
    out->proper = tau;
    out->c_tau = MECH_C * tau;
    out->lab = lab;
    out->decay_length = len;
    return MECH_OK;
}
