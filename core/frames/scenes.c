/* scenes.c — the notes' chapter-1 scenes (mech/frames/scenes.h): ballistic motion
 * in the local Earth frame against the first-order Coriolis formulas with
 * their second-order terms, and the rotating-table puck experiments (§1.1)
 * seen from both frames.
 */
#include "mech/frames/scenes.h"
#include "mech/frames/trajectory_plan.h"
#include "mech/base/constants.h"
#include "mech/frames/reference.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *mech_scene_model_name(enum mech_scene_model m)
{
    switch (m) {
    case MECH_SCENE_MODEL_AUTO: return "auto";
    case MECH_SCENE_MODEL_CORIOLIS: return "coriolis";
    case MECH_SCENE_MODEL_CORIOLIS_CENTRIFUGAL: return "coriolis_centrifugal";
    }
    return NULL;
}

void mech_scene_ballistic_fix(struct mech_scene_ballistic_result *out)
{
    out->problem.forces = out->forces;
}

/* Earth angular velocity in local axes (notes §1.3). */
static struct mech_vec3 earth_w(const struct mech_scene_ballistic *s)
{
    struct mech_frame f;
    memset(&f, 0, sizeof f);
    f.type = MECH_FRAME_EARTH;
    f.latitude_deg = s->latitude_deg;
    f.omega_magnitude = s->omega;
    return mech_frame_omega(&f);
}

/* Zeroth-order flight time: z0 + vz t - g t^2/2 = 0, the positive root,
 * written without cancellation: t = 2 z0 / (sqrt(vz^2 + 2 g z0) - vz) when
 * vz < 0, else (vz + sqrt(vz^2 + 2 g z0)) / g. */
static double flight_time(double z0, double vz, double g)
{
    const double disc = sqrt(vz * vz + 2.0 * g * z0);
    return vz >= 0.0 ? (vz + disc) / g : 2.0 * z0 / (disc - vz);
}

/* z of the series r_0 + r_1 (+ r_2 with Coriolis / centrifugal parts) at t. */
static struct mech_vec3 series_at(const struct mech_scene_ballistic *s, struct mech_vec3 w,
                                  int second, int centrifugal, double t)
{
    struct mech_vec3 r, v, so;
    const struct mech_vec3 g = mech_vec3_make(0, 0, -s->g);
    mech_coriolis_first_order(w, g, centrifugal, s->r0, s->v0, t, &r, &v, &so);
    return second ? mech_vec3_add(r, so) : r;
}

/* Landing of the series (z = 0 going down) near T0: bisection on
 * [T0/2, 3 T0/2] to round-off (the series is a polynomial; its root is within
 * a relative O(w^2 T0^2) << 1/2 of T0). */
static int series_landing(const struct mech_scene_ballistic *s, struct mech_vec3 w, int cf,
                          double T0, struct mech_scene_landing *out)
{
    double lo = 0.5 * T0, hi = 1.5 * T0;
    double zlo = series_at(s, w, 1, cf, lo).z, zhi = series_at(s, w, 1, cf, hi).z;
    if (!(zlo > 0.0 && zhi < 0.0)) return 0;
    for (int i = 0; i < 200 && hi - lo > 2e-16 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        double zm = series_at(s, w, 1, cf, mid).z;
        if (zm > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    out->t = 0.5 * (lo + hi);
    out->r = series_at(s, w, 1, cf, out->t);
    out->r.z = 0.0;
    return 1;
}

static struct mech_scene_landing landing_sub(struct mech_scene_landing a,
                                             struct mech_scene_landing b)
{
    struct mech_scene_landing d = {a.t - b.t, mech_vec3_sub(a.r, b.r)};
    return d;
}

static enum mech_status check_ballistic(const struct mech_scene_ballistic *s,
                                        struct mech_error *err)
{
    if (!(s->latitude_deg >= -90.0 && s->latitude_deg <= 90.0))
        return mech_error_set(err, MECH_EDOMAIN, "latitude_deg",
                              "latitude must be in [-90, 90] degrees, got %.17g", s->latitude_deg);
    if (!(s->g > 0.0 && s->g <= 1e3))
        return mech_error_set(err, MECH_EDOMAIN, "g", "g must be in (0, 1000] m/s^2, got %.17g",
                              s->g);
    if (!(s->omega >= 0.0 && s->omega <= 1e-2))
        return mech_error_set(err, MECH_EDOMAIN, "omega",
                              "omega must be in [0, 1e-2] rad/s, got %.17g", s->omega);
    if (!mech_vec3_isfinite(s->r0) || !(s->r0.z >= 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "r0", "the start must be finite, at z >= 0");
    if (!mech_vec3_isfinite(s->v0))
        return mech_error_set(err, MECH_EDOMAIN, "v0", "the velocity must be finite");
    if (!(s->r0.z > 0.0 || s->v0.z > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "v0",
                              "a projectile starting on the ground must be fired upwards");
    if (!mech_scene_model_name(s->model))
        return mech_error_set(err, MECH_EDOMAIN, "model",
                              "model must be auto, coriolis or coriolis_centrifugal");
    return MECH_OK;
}

/* A scene's run planned by core's trajectory pipeline (mech/frames/trajectory_plan.h):
 * with auto_model, "auto" picks the fictitious terms (all of them for a dry
 * run), else p->fictitious is kept; the chooser picks the method for target;
 * the first pass's steps come off *budget. */
static enum mech_status scene_plan(struct mech_trajectory_problem *p, int auto_model,
                                   double target, int dry_run, struct mech_budget *budget,
                                   struct mech_trajectory_model *model,
                                   struct mech_trajectory_choice *choice, struct mech_error *err)
{
    const struct mech_trajectory_plan_request q = {auto_model, dry_run, target, 1, target};
    struct mech_trajectory_plan plan;
    enum mech_status st = mech_trajectory_plan(p, &q, budget, &plan, err);
    *model = plan.model;
    *choice = plan.choice;
    return st;
}

enum mech_status mech_scene_ballistic_formulas(const struct mech_scene_ballistic *s,
                                               int centrifugal,
                                               struct mech_scene_ballistic_result *out,
                                               struct mech_error *err)
{
    enum mech_status st = check_ballistic(s, err);
    if (st != MECH_OK) return st;
    const struct mech_vec3 w = earth_w(s);
    const double T0 = flight_time(s->r0.z, s->v0.z, s->g);
    /* zeroth order: no rotation */
    out->zeroth.t = T0;
    out->zeroth.r = series_at(s, mech_vec3_make(0, 0, 0), 0, 0, T0);
    out->zeroth.r.z = 0.0;
    /* first order, linearised in w (notes §1.3-1.4 and problems 3-5):
     * r_1(T0) horizontal + v_h(T0) dt1, dt1 = -z_1(T0) / z_0'(T0) */
    struct mech_vec3 r1 = mech_vec3_sub(series_at(s, w, 0, 0, T0), out->zeroth.r);
    const double vz_land = s->v0.z - s->g * T0; /* < 0 */
    const double dt1 = -r1.z / vz_land;
    out->first_order.t = T0 + dt1;
    out->first_order.r = mech_vec3_add(
        out->zeroth.r, mech_vec3_make(r1.x + s->v0.x * dt1, r1.y + s->v0.y * dt1, 0.0));
    out->first_order.r.z = 0.0;
    struct mech_scene_landing cor, all;
    if (!series_landing(s, w, 0, T0, &cor) || !series_landing(s, w, centrifugal, T0, &all))
        return mech_error_set(err, MECH_EDOMAIN, "omega",
                              "the rotation is too fast for the perturbation series (w T0 must "
                              "be small)");
    out->series = all;
    out->second_order = landing_sub(all, out->first_order);
    out->second_coriolis = landing_sub(cor, out->first_order);
    out->second_centrifugal = landing_sub(all, cor);
    return MECH_OK;
}

enum mech_status mech_scene_ballistic_run(const struct mech_scene_ballistic *s, double target,
                                          const struct mech_budget *budget,
                                          struct mech_scene_ballistic_result *out,
                                          struct mech_error *err)
{
    if (!s || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(out, 0, sizeof *out);
    enum mech_status st = check_ballistic(s, err);
    if (st != MECH_OK) return st;
    const double T0 = flight_time(s->r0.z, s->v0.z, s->g);

    struct mech_trajectory_problem *p = &out->problem;
    out->forces[0].type = MECH_FORCE_UNIFORM_GRAVITY;
    out->forces[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -s->g);
    p->mass = 1.0;
    p->position = s->r0;
    p->velocity = s->v0;
    p->frame.type = MECH_FRAME_EARTH;
    p->frame.latitude_deg = s->latitude_deg;
    p->frame.omega_magnitude = s->omega;
    p->forces = out->forces;
    p->n_forces = 1;
    p->t_end = 2.0 * T0 + 1.0;
    p->samples = 2;
    p->has_stop = 1;
    p->stop_axis = 2;
    p->stop_value = 0.0;
    p->stop_direction = MECH_STOP_DECREASING;
    p->reduce_planar = 1;

    /* the terms: "auto" (which fictitious terms matter at this accuracy) or
     * the model asked for; then the method; a dry run stops at the selection */
    const int auto_model = s->model == MECH_SCENE_MODEL_AUTO;
    if (s->model == MECH_SCENE_MODEL_CORIOLIS) p->fictitious = MECH_FICTITIOUS_CORIOLIS;
    if (s->model == MECH_SCENE_MODEL_CORIOLIS_CENTRIFUGAL)
        p->fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    struct mech_budget b2 = *budget;
    if ((st = scene_plan(p, auto_model, target, s->dry_run, &b2, &out->model, &out->choice,
                         err)) != MECH_OK ||
        s->dry_run)
        return st;
    if ((st = mech_trajectory_integrate(p, &b2, &out->run, err)) != MECH_OK) return st;
    if (!out->run.stopped)
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the projectile did not land before t = %.9g s", p->t_end);
    out->numerical.t = out->run.t_stop;
    out->numerical.r = out->run.stop_position;
    out->numerical.r.z = 0.0; /* on the event surface to round-off */

    const int cf = (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL) != 0;
    if ((st = mech_scene_ballistic_formulas(s, cf, out, err)) != MECH_OK) return st;
    out->difference = landing_sub(out->numerical, out->first_order);
    out->unexplained = landing_sub(out->difference, out->second_order);
    out->integration_tolerance = target * out->run.max_radius;
    return MECH_OK;
}

/* ---- the rotating table --------------------------------------------------- */

/* Components in the table's axes at time t of an inertial vector (passive
 * rotation by w t about z: rotations are passive, docs/design.md): x' = x cos + y sin,
 * y' = -x sin + y cos. */
static struct mech_vec3 to_table(struct mech_vec3 a, double wt)
{
    const double c = cos(wt), s = sin(wt);
    return mech_vec3_make(a.x * c + a.y * s, -a.x * s + a.y * c, a.z);
}

enum mech_status mech_scene_table_run(const struct mech_scene_table *s, double target,
                                      const struct mech_budget *budget,
                                      struct mech_scene_table_result *out, struct mech_error *err)
{
    if (!s || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    if (!(isfinite(s->omega) && s->omega != 0.0 && fabs(s->omega) <= 1e6))
        return mech_error_set(err, MECH_EDOMAIN, "omega",
                              "omega must be non-zero with |omega| <= 1e6 rad/s, got %.17g",
                              s->omega);
    if (!(isfinite(s->mass) && s->mass > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "mass must be > 0");
    if (s->samples < MECH_TRAJECTORY_MIN_SAMPLES || s->samples > MECH_TRAJECTORY_MAX_SAMPLES)
        return mech_error_set(err, MECH_EDOMAIN, "samples", "samples must be in [%d, %d]",
                              MECH_TRAJECTORY_MIN_SAMPLES, MECH_TRAJECTORY_MAX_SAMPLES);
    const double w = s->omega;
    struct mech_vec3 r0, v0;
    double t_end;
    switch (s->experiment) {
    case MECH_TABLE_THROUGH_CENTER:
    case MECH_TABLE_AT_REST:
        if (!(isfinite(s->radius) && s->radius > 0.0 && s->radius <= 1e15))
            return mech_error_set(err, MECH_EDOMAIN, "radius", "radius must be in (0, 1e15] m");
        r0 = mech_vec3_make(0, s->radius, 0);
        if (s->experiment == MECH_TABLE_THROUGH_CENTER) {
            /* notes §1.1: r1 -> 0 -> r1 (across) during half a turn, pi / |w|:
             * speed 2 r1 / (pi / |w|) = 2 r1 |w| / pi, inward */
            v0 = mech_vec3_make(0, -2.0 * s->radius * fabs(w) / MECH_PI, 0);
            t_end = MECH_PI / fabs(w);
        } else {
            v0 = mech_vec3_make(0, 0, 0);
            t_end = 2.0 * MECH_PI / fabs(w);
        }
        break;
    case MECH_TABLE_CUSTOM:
        if (!mech_vec3_isfinite(s->r0) || !mech_vec3_isfinite(s->v0))
            return mech_error_set(err, MECH_EDOMAIN, "position", "must be finite");
        if (!(isfinite(s->t_end) && s->t_end > 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "t_end", "t_end must be > 0");
        r0 = s->r0;
        v0 = s->v0;
        t_end = s->t_end;
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, "experiment", "unknown experiment");
    }
    const struct mech_vec3 W = mech_vec3_make(0, 0, w);
    out->t_end = t_end;
    out->r0_inertial = r0;
    out->v0_inertial = v0;
    /* frames coincide at t = 0: r' = r, v' = v - w x r (notes §1.1) */
    out->r0_rotating = r0;
    out->v0_rotating = mech_vec3_sub(v0, mech_vec3_cross(W, r0));
    /* notes §1.2: F' = F - m w x (w x r) - 2 m w x v' */
    out->centrifugal = mech_vec3_scale(mech_vec3_cross(W, mech_vec3_cross(W, r0)), -s->mass);
    out->coriolis = mech_vec3_scale(mech_vec3_cross(W, out->v0_rotating), -2.0 * s->mass);
    out->total = mech_vec3_add(out->centrifugal, out->coriolis);

    struct mech_trajectory_problem *p = &out->problem;
    memset(p, 0, sizeof *p);
    p->mass = s->mass;
    p->position = r0;
    p->velocity = out->v0_rotating;
    p->frame.type = MECH_FRAME_ROTATING;
    p->frame.omega = W;
    p->t_end = t_end;
    p->samples = s->samples;
    p->reduce_planar = 1;
    struct mech_budget b2 = *budget;
    enum mech_status st =
        scene_plan(p, 1, target, s->dry_run, &b2, &out->model, &out->choice, err);
    if (st != MECH_OK || s->dry_run) return st;
    struct mech_trajectory_result *r = &out->run;
    memset(r, 0, sizeof *r);
    r->t = out->t;
    r->position = out->rotating;
    if ((st = mech_trajectory_integrate(p, &b2, r, err)) != MECH_OK) return st;
    out->n_samples = r->n_samples;
    double emax = 0.0, rmax = 0.0;
    for (size_t i = 0; i < r->n_samples; i++) {
        const double t = t_end * (double)i / (double)(s->samples - 1);
        if (out->t) out->t[i] = t;
        struct mech_vec3 ri = mech_vec3_add(r0, mech_vec3_scale(v0, t));
        struct mech_vec3 rr = to_table(ri, w * t);
        if (out->inertial) out->inertial[i] = ri;
        if (out->rotating_exact) out->rotating_exact[i] = rr;
        rmax = fmax(rmax, mech_vec3_norm(rr));
        if (out->rotating) {
            emax = fmax(emax, mech_vec3_norm(mech_vec3_sub(out->rotating[i], rr)));
            if (i + 1 == r->n_samples) out->end_rotating = out->rotating[i];
        }
    }
    out->max_position_error = emax;
    out->max_relative_position_error = rmax > 0.0 ? emax / rmax : 0.0;
    return MECH_OK;
}
