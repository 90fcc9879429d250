/* chooser_orbit.c — the dominant central-body orbit of a trajectory scene as
 * the chooser needs it (see mech/frames/chooser_orbit.h): period, eccentricity,
 * Wisdom-Holman's relative perturbation, and the run's length in the cost
 * law's units. */
#include "mech/frames/chooser_orbit.h"
#include "mech/base/constants.h"

#include <math.h>

/* span per orbit of the calibration scene, Kepler e = 0.5 counted in
 * pericentre times sqrt(q^3 / GM): 2 pi / 0.5^1.5 */
#define CAL_SPAN_PER_ORBIT 17.771531752633464

/* The acceleration of every force but the central body `skip`, at position
 * r with velocity v (m/s^2). */
static struct mech_vec3 other_accel(const struct mech_trajectory_problem *p, size_t skip,
                                    struct mech_vec3 r, struct mech_vec3 v)
{
    struct mech_vec3 a = mech_vec3_make(0, 0, 0);
    for (size_t i = 0; i < p->n_forces; i++) {
        const struct mech_force *f = &p->forces[i];
        if (i == skip) continue;
        switch (f->type) {
        case MECH_FORCE_UNIFORM_GRAVITY: a = mech_vec3_add(a, f->u.uniform_gravity.g); break;
        case MECH_FORCE_CENTRAL_GRAVITY: break; /* a second body: not reached (see caller) */
        case MECH_FORCE_SPRING: {
            const struct mech_vec3 d = mech_vec3_sub(r, f->u.spring.anchor);
            const double dn = mech_vec3_norm(d);
            if (dn > 0.0)
                a = mech_vec3_add(a, mech_vec3_scale(d, -f->u.spring.k *
                                                            (dn - f->u.spring.rest_length) /
                                                            (dn * p->mass)));
            break;
        }
        case MECH_FORCE_LINEAR_DRAG:
            a = mech_vec3_add(a, mech_vec3_scale(v, -f->u.linear_drag.b / p->mass));
            break;
        case MECH_FORCE_LORENTZ: {
            const struct mech_vec3 F =
                mech_vec3_add(f->u.lorentz.E, mech_vec3_cross(v, f->u.lorentz.B));
            a = mech_vec3_add(a, mech_vec3_scale(F, p->charge / p->mass));
            break;
        }
        case MECH_FORCE_THIRD_BODY_TIDE: {
            const struct mech_vec3 d = f->u.third_body_tide.position;
            const struct mech_vec3 dr = mech_vec3_sub(d, r);
            const double n1 = mech_vec3_norm(dr), n0 = mech_vec3_norm(d);
            if (n1 > 0.0 && n0 > 0.0)
                a = mech_vec3_add(
                    a, mech_vec3_scale(mech_vec3_sub(mech_vec3_scale(dr, 1.0 / (n1 * n1 * n1)),
                                                     mech_vec3_scale(d, 1.0 / (n0 * n0 * n0))),
                                       f->u.third_body_tide.gm));
            break;
        }
        }
    }
    return a;
}

void mech_chooser_profile_orbit(struct mech_scene_profile *s,
                                const struct mech_trajectory_problem *p)
{
    if (!s || !p || s->cls != MECH_SCENE_CENTRAL_GRAVITY || !(p->mass > 0.0)) return;
    /* the central body with the shortest pericentre time, as the span counts it */
    size_t best = p->n_forces, n_central = 0;
    double best_T = INFINITY, best_a = 0, best_e = 0, best_gm = 0;
    struct mech_vec3 best_r = mech_vec3_make(0, 0, 0);
    for (size_t i = 0; i < p->n_forces; i++) {
        if (p->forces[i].type != MECH_FORCE_CENTRAL_GRAVITY) continue;
        n_central++;
        const double gm = p->forces[i].u.central_gravity.gm;
        const struct mech_vec3 r = mech_vec3_sub(p->position, p->forces[i].u.central_gravity.center);
        const double rn = mech_vec3_norm(r);
        if (!(gm > 0.0) || !(rn > 0.0)) continue;
        const double h = mech_vec3_norm(mech_vec3_cross(r, p->velocity));
        const double v2 = mech_vec3_dot(p->velocity, p->velocity);
        /* 1/a = 2/r - v^2/GM; bound when positive */
        const double inv_a = 2.0 / rn - v2 / gm;
        const double e2 = 1.0 - h * h * inv_a / gm;
        const double e = sqrt(fmax(e2, 0.0));
        const double q = h * h / (gm * (1.0 + e));
        const double T = sqrt(q * q * q / gm);
        if (!(T < best_T)) continue;
        best_T = T;
        best = i;
        best_a = inv_a > 0.0 ? 1.0 / inv_a : -1.0;
        best_e = e;
        best_gm = gm;
        best_r = r;
    }
    if (best == p->n_forces || !(best_a > 0.0) || !(best_e < 1.0) || !isfinite(best_a)) return;
    const double P = 2.0 * MECH_PI * sqrt(best_a * best_a * best_a / best_gm);
    if (!(P > 0.0 && isfinite(P))) return;
    const double orbits = p->t_end / P;
    const double ratio = (1.0 + best_e) / (3.0 * (1.0 - best_e));
    const double cs = orbits * CAL_SPAN_PER_ORBIT * cbrt(ratio);
    if (!(cs > 0.0 && isfinite(cs))) return;
    s->orbit_period = P;
    s->eccentricity = best_e;
    s->cost_span = cs;
    s->perturbation = -1.0;
    if (n_central != 1 || p->frame.type != MECH_FRAME_INERTIAL) return;
    const struct mech_vec3 ra = mech_vec3_scale(best_r, best_a / mech_vec3_norm(best_r));
    const struct mech_vec3 at = mech_vec3_add(ra, p->forces[best].u.central_gravity.center);
    const double eps =
        mech_vec3_norm(other_accel(p, best, at, p->velocity)) * best_a * best_a / best_gm;
    if (isfinite(eps)) s->perturbation = eps;
}
