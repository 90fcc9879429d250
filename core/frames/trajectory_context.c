/* trajectory_context.c — the context one trajectory run shares between its
 * equations of motion, its fast path and its observer (trajectory_context.h):
 * the frame's terms the scene models, the relativistic corrections, the
 * Kepler split, the angular-momentum centre and the planar reduction, and
 * what the scene's equations depend on (drag, velocity, time). */
#include "trajectory_context.h"

#include <string.h>

/* The integrator's side of mech_trajectory_angular_center: its frame terms. */
static int angular_momentum_center(const struct traj_ctx *c, struct mech_vec3 *center)
{
    const int rot = (c->coriolis || c->centrifugal || c->euler) &&
                    (mech_vec3_norm(c->w) > 0.0 || mech_vec3_norm(c->wdot) > 0.0);
    const int tr = c->translational && mech_vec3_norm(c->A) > 0.0;
    return mech_trajectory_angular_center(c->p, rot, tr, center);
}

/* The Kepler split of a scene (wisdom_holman, mech/ode/ode.h): the index of its
 * one central_gravity force when the frame is inertial and exactly one
 * central_gravity acts (the other forces are the perturbation), else -1 with
 * *why (may be NULL) saying what is missing. */
int mech_traj_kepler_split_index(const struct mech_trajectory_problem *p, const char **why)
{
    int idx = -1, n = 0;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) {
            idx = (int)i;
            n++;
        }
    const char *w = NULL;
    if (p->frame.type != MECH_FRAME_INERTIAL) w = "the frame is not inertial";
    else if (p->relativity) w = "a relativistic term is modelled (integrated whole, no split)";
    else if (n == 0) w = "the scene has no central_gravity force";
    else if (n > 1) w = "the scene has more than one";
    if (why) *why = w;
    return w ? -1 : idx;
}

void mech_traj_ctx_init(struct traj_ctx *c, const struct mech_trajectory_problem *p,
                        double fixed_dt, struct mech_error *err)
{
    memset(c, 0, sizeof *c);
    c->p = p;
    c->err = err;
    c->noninertial = p->frame.type != MECH_FRAME_INERTIAL;
    c->w = mech_frame_omega(&p->frame);
    if (p->frame.type == MECH_FRAME_ROTATING) {
        c->wdot = p->frame.omega_dot;
        c->A = p->frame.acceleration;
    }
    c->coriolis = c->noninertial && (p->fictitious & MECH_FICTITIOUS_CORIOLIS);
    c->centrifugal = c->noninertial && (p->fictitious & MECH_FICTITIOUS_CENTRIFUGAL);
    c->euler = c->noninertial && (p->fictitious & MECH_FICTITIOUS_EULER);
    c->translational = c->noninertial && (p->fictitious & MECH_FICTITIOUS_TRANSLATIONAL);
    c->fixed_dt = fixed_dt;
    c->kepler_index = mech_traj_kepler_split_index(p, NULL);
    c->special = !c->noninertial && (p->relativity & MECH_RELATIVITY_SPECIAL);
    c->pn1_index = -1;
    if (!c->noninertial) {
        size_t n = 0;
        for (size_t i = 0; i < p->n_forces; i++)
            if (p->forces[i].type == MECH_FORCE_CENTRAL_GRAVITY) {
                n++;
                c->pn1_index = (int)i;
            }
        if (n != 1) c->pn1_index = -1;
    }
    c->pn1 = c->pn1_index >= 0 && (p->relativity & MECH_RELATIVITY_SCHWARZSCHILD_1PN);
    c->track_l = angular_momentum_center(c, &c->lcenter);
    c->r_last = p->position;
    mech_traj_fast_setup(c);
}

int mech_traj_scene_has_drag(const struct mech_trajectory_problem *p)
{
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LINEAR_DRAG && p->forces[i].u.linear_drag.b > 0.0)
            return 1;
    return 0;
}

/* Whether the acceleration depends on the velocity: drag, Coriolis in a
 * rotating frame, or a magnetic field acting on a charge. */
int mech_traj_scene_velocity_dependent(const struct traj_ctx *c)
{
    const struct mech_trajectory_problem *p = c->p;
    if (mech_traj_scene_has_drag(p)) return 1;
    if (c->special || c->pn1) return 1; /* v/c terms */
    if (c->coriolis && (mech_vec3_norm(c->w) > 0.0 || mech_vec3_norm(c->wdot) > 0.0)) return 1;
    for (size_t i = 0; i < p->n_forces; i++)
        if (p->forces[i].type == MECH_FORCE_LORENTZ && p->charge != 0.0 &&
            mech_vec3_norm(p->forces[i].u.lorentz.B) > 0.0)
            return 1;
    return 0;
}

/* Whether the time-dependent rotation makes the equations depend on t. */
int mech_traj_scene_time_dependent(const struct traj_ctx *c)
{
    return (c->coriolis || c->centrifugal || c->euler) && mech_vec3_norm(c->wdot) > 0.0;
}

/* Set up planar integration in c when asked and possible for this method. */
void mech_traj_ctx_plane(struct traj_ctx *c, const struct mech_ode_method_info *mi)
{
    struct mech_vec3 n;
    c->dim2 = 0;
    /* a special run's state is (r, u): no planar form */
    if (!c->p->reduce_planar || c->special || !mech_trajectory_plane(c->p, &n)) return;
    /* Boris rotates 3-vectors: 2-D only when it needs no Lorentz split */
    if (!strcmp(mi->name, "boris") && mech_traj_scene_velocity_dependent(c)) return;
    c->dim2 = 1;
    mech_trajectory_plane_axes(n, &c->e1, &c->e2);
    mech_traj_fast_setup(c); /* the force vectors in plane coordinates */
}
