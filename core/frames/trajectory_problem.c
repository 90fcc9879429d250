/* trajectory_problem.c — a trajectory scene as stated (mech/frames/trajectory_problem.h):
 * its validation with the API path of every field, the centre about which it
 * conserves angular momentum, and the plane a planar scene stays in. */
#include "mech/frames/trajectory_problem.h"
#include "mech/base/constants.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for error parameter paths */
#include <string.h>

static enum mech_status check_vec(struct mech_vec3 v, const char *param, struct mech_error *err)
{
    if (!mech_vec3_isfinite(v))
        return mech_error_set(err, MECH_EINVAL, param, "components must be finite");
    return MECH_OK;
}

struct mech_vec3 mech_schwarzschild_1pn_accel(double gm, struct mech_vec3 d, struct mech_vec3 v)
{
    const double dn = mech_vec3_norm(d);
    const struct mech_vec3 n = mech_vec3_scale(d, 1.0 / dn);
    const double k = (gm / (MECH_C * dn)) / (MECH_C * dn);
    const double v2 = mech_vec3_dot(v, v), nv = mech_vec3_dot(n, v);
    return mech_vec3_add(mech_vec3_scale(n, k * (4.0 * gm / dn - v2)),
                         mech_vec3_scale(v, 4.0 * k * nv));
}

struct mech_vec3 mech_trajectory_proper_velocity0(const struct mech_trajectory_problem *p)
{
    if (p->has_proper_velocity) return p->proper_velocity;
    const double beta = mech_vec3_norm(p->velocity) / MECH_C;
    return mech_vec3_scale(p->velocity, 1.0 / sqrt((1.0 - beta) * (1.0 + beta)));
}

/* The relativistic corrections asked for must be modellable: an inertial
 * frame (a rotating frame's fictitious terms are Newtonian), a speed below c
 * for special relativity, one central mass for the 1PN term, not both. */
static enum mech_status relativity_check(const struct mech_trajectory_problem *p,
                                         struct mech_error *err)
{
    const unsigned r = p->relativity;
    if (r & ~(MECH_RELATIVITY_SPECIAL | MECH_RELATIVITY_SCHWARZSCHILD_1PN))
        return mech_error_set(err, MECH_EINVAL, "relativity", "unknown relativistic term");
    if (p->has_proper_velocity) {
        if (!mech_vec3_isfinite(p->proper_velocity))
            return mech_error_set(err, MECH_EINVAL, "particle/proper_velocity",
                                  "components must be finite");
        if (!(r & MECH_RELATIVITY_SPECIAL))
            return mech_error_set(err, MECH_EINVAL, "particle/proper_velocity",
                                  "a proper velocity is the state of special-relativistic "
                                  "dynamics: the model must include \"relativistic\"");
    }
    if (!r) return MECH_OK;
    if (p->frame.type != MECH_FRAME_INERTIAL)
        return mech_error_set(err, MECH_EINVAL, "relativity",
                              "relativistic terms are modelled in an inertial frame only (the "
                              "fictitious forces of a rotating frame are Newtonian)");
    if ((r & MECH_RELATIVITY_SPECIAL) && (r & MECH_RELATIVITY_SCHWARZSCHILD_1PN))
        return mech_error_set(err, MECH_EINVAL, "relativity",
                              "\"relativistic\" and \"schwarzschild_1pn\" are not modelled "
                              "together: the 1PN orbit about a mass already holds its "
                              "special-relativistic kinematics");
    if ((r & MECH_RELATIVITY_SPECIAL) && !p->has_proper_velocity &&
        !(mech_vec3_norm(p->velocity) < MECH_C))
        return mech_error_set(err, MECH_EDOMAIN, "particle/velocity",
                              "|velocity| = %.17g m/s is not below c = 299792458 m/s, which "
                              "special relativity requires (give particle.proper_velocity "
                              "u = gamma v for speeds near c)",
                              mech_vec3_norm(p->velocity));
    if (r & MECH_RELATIVITY_SCHWARZSCHILD_1PN) {
        size_t n = 0;
        for (size_t i = 0; i < p->n_forces; i++)
            n += p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY;
        if (n != 1)
            return mech_error_set(err, MECH_EINVAL, "relativity",
                                  "\"schwarzschild_1pn\" corrects the field of exactly one "
                                  "central mass; the scene has %zu central_gravity forces",
                                  n);
    }
    return MECH_OK;
}

enum mech_status mech_trajectory_check(const struct mech_trajectory_problem *p,
                                       struct mech_error *err)
{
    enum mech_status st;
    char param[64];
    if (!(isfinite(p->mass) && p->mass > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "particle/mass",
                              "mass must be finite and > 0, got %.17g", p->mass);
    if (!isfinite(p->charge))
        return mech_error_set(err, MECH_EINVAL, "particle/charge", "charge must be finite");
    if ((st = check_vec(p->position, "particle/position", err)) != MECH_OK) return st;
    if ((st = check_vec(p->velocity, "particle/velocity", err)) != MECH_OK) return st;
    switch (p->frame.type) {
    case MECH_FRAME_INERTIAL:
        break;
    case MECH_FRAME_ROTATING:
        if ((st = check_vec(p->frame.omega, "frame/omega", err)) != MECH_OK) return st;
        if ((st = check_vec(p->frame.omega_dot, "frame/omega_dot", err)) != MECH_OK) return st;
        if ((st = check_vec(p->frame.acceleration, "frame/acceleration", err)) != MECH_OK)
            return st;
        break;
    case MECH_FRAME_EARTH:
        if (!(p->frame.latitude_deg >= -90.0 && p->frame.latitude_deg <= 90.0))
            return mech_error_set(err, MECH_EDOMAIN, "frame/latitude_deg",
                                  "latitude must be in [-90, 90] degrees, got %.17g",
                                  p->frame.latitude_deg);
        if (!(isfinite(p->frame.omega_magnitude) && p->frame.omega_magnitude >= 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "frame/omega_magnitude",
                                  "omega_magnitude must be finite and >= 0, got %.17g",
                                  p->frame.omega_magnitude);
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, "frame/type", "unknown frame type");
    }
    if (p->n_forces > MECH_TRAJECTORY_MAX_FORCES || (p->n_forces && !p->forces))
        return mech_error_set(err, MECH_EINVAL, "forces", "at most %d forces",
                              MECH_TRAJECTORY_MAX_FORCES);
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            snprintf(param, sizeof param, "forces/%zu/g", i);
            if ((st = check_vec(f->u.uniform_gravity.g, param, err)) != MECH_OK) return st;
            break;
        case MECH_FORCE_CENTRAL_GRAVITY: {
            snprintf(param, sizeof param, "forces/%zu/gm", i);
            if (!(isfinite(f->u.central_gravity.gm) && f->u.central_gravity.gm > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "gm must be finite and > 0");
            snprintf(param, sizeof param, "forces/%zu/center", i);
            if ((st = check_vec(f->u.central_gravity.center, param, err)) != MECH_OK) return st;
            struct mech_vec3 d = mech_vec3_sub(p->position, f->u.central_gravity.center);
            if (!(mech_vec3_norm(d) > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, "particle/position",
                                      "the particle starts at the centre of force %zu", i);
            break;
        }
        case MECH_FORCE_SPRING:
            snprintf(param, sizeof param, "forces/%zu/k", i);
            if (!(isfinite(f->u.spring.k) && f->u.spring.k >= 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "k must be finite and >= 0");
            snprintf(param, sizeof param, "forces/%zu/rest_length", i);
            if (!(isfinite(f->u.spring.rest_length) && f->u.spring.rest_length >= 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param,
                                      "rest_length must be finite and >= 0");
            snprintf(param, sizeof param, "forces/%zu/anchor", i);
            if ((st = check_vec(f->u.spring.anchor, param, err)) != MECH_OK) return st;
            break;
        case MECH_FORCE_LINEAR_DRAG:
            snprintf(param, sizeof param, "forces/%zu/b", i);
            if (!(isfinite(f->u.linear_drag.b) && f->u.linear_drag.b >= 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "b must be finite and >= 0");
            break;
        case MECH_FORCE_LORENTZ:
            snprintf(param, sizeof param, "forces/%zu/E", i);
            if ((st = check_vec(f->u.lorentz.E, param, err)) != MECH_OK) return st;
            snprintf(param, sizeof param, "forces/%zu/B", i);
            if ((st = check_vec(f->u.lorentz.B, param, err)) != MECH_OK) return st;
            break;
        case MECH_FORCE_THIRD_BODY_TIDE: {
            snprintf(param, sizeof param, "forces/%zu/gm", i);
            if (!(isfinite(f->u.third_body_tide.gm) && f->u.third_body_tide.gm > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param, "gm must be finite and > 0");
            snprintf(param, sizeof param, "forces/%zu/position", i);
            if ((st = check_vec(f->u.third_body_tide.position, param, err)) != MECH_OK) return st;
            if (!(mech_vec3_norm(f->u.third_body_tide.position) > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, param,
                                      "the tide-raising body cannot be at the frame's origin");
            if (!(mech_vec3_norm(mech_vec3_sub(p->position, f->u.third_body_tide.position)) > 0.0))
                return mech_error_set(err, MECH_EDOMAIN, "particle/position",
                                      "the particle starts at the tide-raising body of force %zu",
                                      i);
            break;
        }
        default:
            snprintf(param, sizeof param, "forces/%zu/type", i);
            return mech_error_set(err, MECH_EINVAL, param, "unknown force type");
        }
    }
    if ((st = relativity_check(p, err)) != MECH_OK) return st;
    if (!(isfinite(p->t_end) && p->t_end > 0.0))
        return mech_error_set(err, MECH_EINVAL, "t_end", "t_end must be finite and > 0");
    if (p->samples < MECH_TRAJECTORY_MIN_SAMPLES || p->samples > MECH_TRAJECTORY_MAX_SAMPLES)
        return mech_error_set(err, MECH_EINVAL, "samples", "samples must be in [%d, %d]",
                              MECH_TRAJECTORY_MIN_SAMPLES, MECH_TRAJECTORY_MAX_SAMPLES);
    if (p->has_stop) {
        if (p->stop_axis < 0 || p->stop_axis > 2)
            return mech_error_set(err, MECH_EINVAL, "stop/coordinate", "axis must be x, y or z");
        if (!isfinite(p->stop_value))
            return mech_error_set(err, MECH_EINVAL, "stop/crosses", "value must be finite");
        if (p->stop_direction != MECH_STOP_EITHER && p->stop_direction != MECH_STOP_INCREASING &&
            p->stop_direction != MECH_STOP_DECREASING)
            return mech_error_set(err, MECH_EINVAL, "stop/direction", "unknown direction");
    }
    return MECH_OK;
}

int mech_trajectory_angular_center(const struct mech_trajectory_problem *p, int rotation_active,
                                   int translation_active, struct mech_vec3 *center)
{
    if (!p || !center || rotation_active || translation_active) return 0;
    int have = 0;
    struct mech_vec3 ctr = mech_vec3_make(0, 0, 0);
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        struct mech_vec3 fc;
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            if (mech_vec3_norm(f->u.uniform_gravity.g) > 0.0) return 0;
            continue;
        case MECH_FORCE_LINEAR_DRAG:
            if (f->u.linear_drag.b > 0.0) return 0;
            continue;
        case MECH_FORCE_SPRING:
            if (f->u.spring.k == 0.0) continue;
            fc = f->u.spring.anchor;
            break;
        case MECH_FORCE_CENTRAL_GRAVITY:
            fc = f->u.central_gravity.center;
            break;
        case MECH_FORCE_LORENTZ:
            if (p->charge == 0.0 ||
                (mech_vec3_norm(f->u.lorentz.E) == 0.0 && mech_vec3_norm(f->u.lorentz.B) == 0.0))
                continue;
            return 0;
        default:
            return 0;
        }
        if (have && (fc.x != ctr.x || fc.y != ctr.y || fc.z != ctr.z)) return 0;
        ctr = fc;
        have = 1;
    }
    *center = ctr;
    return have;
}

/* ---- planar scenes --------------------------------------------------------- */

/* |n.u| <= 1e-15 |u| with n a unit vector: u lies in the plane of normal n. */
static int in_plane(struct mech_vec3 n, struct mech_vec3 u)
{
    return fabs(mech_vec3_dot(n, u)) <= 1e-15 * mech_vec3_norm(u);
}

/* |n x u| <= 1e-15 |u|: u is along n. */
static int along(struct mech_vec3 n, struct mech_vec3 u)
{
    return mech_vec3_norm(mech_vec3_cross(n, u)) <= 1e-15 * mech_vec3_norm(u);
}

/* The coordinate axis least aligned with u (u != 0), crossed with u, normalised. */
static struct mech_vec3 perpendicular_to(struct mech_vec3 u)
{
    double ax = fabs(u.x), ay = fabs(u.y), az = fabs(u.z);
    struct mech_vec3 e = ax <= ay && ax <= az ? mech_vec3_make(1, 0, 0)
                         : ay <= az           ? mech_vec3_make(0, 1, 0)
                                              : mech_vec3_make(0, 0, 1);
    return mech_vec3_unit(mech_vec3_cross(e, u));
}

int mech_trajectory_plane(const struct mech_trajectory_problem *p, struct mech_vec3 *normal)
{
    struct mech_vec3 inp[2 * MECH_TRAJECTORY_MAX_FORCES + 4], nrm[MECH_TRAJECTORY_MAX_FORCES + 2];
    size_t ni = 0, nn = 0;
    if (!p || (p->n_forces && !p->forces) || p->n_forces > MECH_TRAJECTORY_MAX_FORCES) return 0;
    inp[ni++] = p->position;
    inp[ni++] = p->velocity;
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY: inp[ni++] = f->u.uniform_gravity.g; break;
        case MECH_FORCE_CENTRAL_GRAVITY: inp[ni++] = f->u.central_gravity.center; break;
        case MECH_FORCE_SPRING:
            if (f->u.spring.k != 0.0) inp[ni++] = f->u.spring.anchor;
            break;
        case MECH_FORCE_LINEAR_DRAG: break; /* -b v stays in the plane */
        case MECH_FORCE_LORENTZ:
            if (p->charge != 0.0) {
                inp[ni++] = f->u.lorentz.E;
                nrm[nn++] = f->u.lorentz.B; /* v x B in the plane iff B is normal */
            }
            break;
        case MECH_FORCE_THIRD_BODY_TIDE: inp[ni++] = f->u.third_body_tide.position; break;
        default: return 0;
        }
    }
    if (p->frame.type != MECH_FRAME_INERTIAL) {
        const unsigned fm = p->fictitious;
        /* Coriolis -2 w x v and centrifugal -w x (w x r) stay in the plane when w
         * is normal to it (then -w x (w x r) = |w|^2 r); Euler -(dw/dt) x r when
         * dw/dt is normal; translational -A when A lies in it */
        if (fm & (MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL)) {
            nrm[nn++] = mech_frame_omega(&p->frame);
            if (p->frame.type == MECH_FRAME_ROTATING) nrm[nn++] = p->frame.omega_dot;
        }
        if ((fm & MECH_FICTITIOUS_EULER) && p->frame.type == MECH_FRAME_ROTATING)
            nrm[nn++] = p->frame.omega_dot;
        if ((fm & MECH_FICTITIOUS_TRANSLATIONAL) && p->frame.type == MECH_FRAME_ROTATING)
            inp[ni++] = p->frame.acceleration;
    }
    for (size_t i = 0; i < ni + nn; i++)
        if (!mech_vec3_isfinite(i < ni ? inp[i] : nrm[i - ni])) return 0;
    /* the normal: a given one, or the cross product of two independent in-plane vectors */
    struct mech_vec3 n = mech_vec3_make(0, 0, 0);
    int have = 0;
    for (size_t i = 0; i < nn && !have; i++)
        if (mech_vec3_norm(nrm[i]) > 0.0) {
            n = mech_vec3_unit(nrm[i]);
            have = 1;
        }
    for (size_t i = 0; i < ni && !have; i++) {
        if (!(mech_vec3_norm(inp[i]) > 0.0)) continue;
        for (size_t j = i + 1; j < ni && !have; j++) {
            struct mech_vec3 x = mech_vec3_cross(inp[i], inp[j]);
            if (mech_vec3_norm(x) > 1e-15 * mech_vec3_norm(inp[i]) * mech_vec3_norm(inp[j])) {
                n = mech_vec3_unit(x);
                have = 1;
            }
        }
    }
    if (!have) {
        /* every in-plane vector is on one line (or zero): any plane holding it */
        for (size_t i = 0; i < ni && !have; i++)
            if (mech_vec3_norm(inp[i]) > 0.0) {
                n = perpendicular_to(inp[i]);
                have = 1;
            }
        if (!have) n = mech_vec3_make(0, 0, 1);
    }
    for (size_t i = 0; i < ni; i++)
        if (!in_plane(n, inp[i])) return 0;
    for (size_t i = 0; i < nn; i++)
        if (!along(n, nrm[i])) return 0;
    if (normal) *normal = n;
    return 1;
}

void mech_trajectory_plane_axes(struct mech_vec3 n, struct mech_vec3 *e1, struct mech_vec3 *e2)
{
    *e1 = perpendicular_to(n);
    *e2 = mech_vec3_cross(n, *e1);
}
