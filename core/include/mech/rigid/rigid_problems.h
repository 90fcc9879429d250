/* mech/rigid/rigid_problems.h — the rigid-body chapter's closed-form problems beyond
 * the inertia tensor (notes §2.9 and §2.11 homework 3, 4, 10):
 *
 * Free symmetric top (notes §2.9). I1 = I2 = I_perp, I3 about the symmetry
 * axis e3, body components omega = (w1, w2, w3), w_perp = |(w1, w2)|. With no
 * torque L = I omega is fixed in space; L, omega and e3 lie in one plane
 * (HW 10). In Euler angles with the space z along L:
 *   theta (e3 to L):      tan theta = I_perp w_perp / (I3 w3)
 *   alpha (e3 to omega):  tan alpha = w_perp / w3       (the body cone's half-angle)
 *   space cone (omega about L): half-angle |theta - alpha|
 *   phi_dot = L / I_perp  (e3 and omega go round L: the space precession)
 *   psi_dot = (I_perp - I3) w3 / I_perp  (omega round e3 in the body; the notes'
 *             Omega = (I3 - I1) w3 / I1 with the opposite sign convention)
 * and omega = phi_dot L_hat + psi_dot e3 exactly (tests check this identity).
 * Prolate (I3 < I_perp): the body cone rolls on the outside of the space cone;
 * oblate (I3 > I_perp): the space cone lies inside the body cone.
 *
 * Struck ball (HW 3). A ball (or cylinder, hoop...) of radius R, mass m and
 * I_cm = m k² struck by a horizontal impulse J at height h above its centre
 * starts with v0 = J/m and w0 = J h / (m k²); it rolls without slipping from
 * the start (v0 = w0 R) iff h = k² / R (2R/5 for a solid sphere: the cushion
 * of a billiard table at 7R/5 above the cloth). Otherwise friction acts until
 * it rolls, angular momentum about the contact line being conserved:
 *   v_final = v0 R (R + h) / (R² + k²).
 *
 * Toppling box (HW 4). A uniform box (width a in the plane of the fall,
 * height b) balanced on an edge with its centre of mass above the edge
 * (d = sqrt(a² + b²)/2 high) falls onto its base (centre of mass at b/2).
 *   edge held (no slip): m g (d - b/2) = I_edge w² / 2, I_edge = m (a² + b²)/3;
 *     cube: w² = (3 g / (2 l)) (sqrt 2 - 1)  (the notes' answer);
 *   frictionless floor: no horizontal force, the centre of mass falls
 *     straight down; when the base lands the edge is a/2 from it horizontally,
 *     so v_cm = w a/2 and m g (d - b/2) = (I_cm + m a²/4) w² / 2,
 *     I_cm = m (a² + b²)/12;  cube: w² = (12 g / (5 l)) (sqrt 2 - 1).
 * The impulse the floor gives to stop it is m v_cm at landing: for the held
 * edge v_cm = w (b/2 horizontal, a/2 vertical), for the frictionless floor
 * w a/2 vertical.
 *
 * Pure functions, no allocation, thread-safe. Units SI.
 */
#ifndef MECH_RIGID_PROBLEMS_H
#define MECH_RIGID_PROBLEMS_H

#include "mech/base/status.h"

struct mech_free_symmetric_top {
    double angular_momentum;  /* |L|, kg m^2/s */
    double theta;             /* angle between e3 and L, rad, [0, pi] */
    double alpha;             /* angle between e3 and omega (body cone half-angle), rad */
    double space_cone;        /* angle between omega and L (space cone half-angle), rad */
    double precession_space;  /* phi_dot = |L| / I_perp, rad/s */
    double precession_body;   /* psi_dot = (I_perp - I3) w3 / I_perp, rad/s */
    double ellipticity;       /* dynamical ellipticity (C - A)/A = (I3 - I_perp)/I_perp:
                                 > 0 oblate, < 0 prolate (the difference exact when
                                 I3 >= I_perp/2, Sterbenz) */
    double omega_magnitude;   /* |omega| */
    int prolate;              /* 1 if I3 < I_perp, 0 if oblate or spherical */
};

/* Free symmetric top with moments i_perp, i3 (kg m^2, > 0, finite) and body
 * angular velocity (w1, w2, w3) (rad/s, finite, not all zero). Statuses:
 * MECH_OK; MECH_EINVAL (params "i_perp", "i3", "omega"); MECH_EDOMAIN (param
 * "i3": I3 > 2 I_perp, which no body has: the perpendicular-axis theorem). */
enum mech_status mech_free_symmetric_top(double i_perp, double i3, const double omega[3],
                                         struct mech_free_symmetric_top *out,
                                         struct mech_error *err);

struct mech_struck_ball {
    double rolling_height;   /* k² / R above the centre, m */
    double rolling_height_floor; /* R + k²/R above the floor, m */
    double v0, w0;           /* J/m (m/s) and J h/(m k²) (rad/s): just after the strike */
    double slip_velocity;    /* v0 - w0 R at the start (forward slip positive), m/s */
    double v_final;          /* rolling speed reached, m/s */
    double energy_lost_fraction; /* 1 - KE_final / KE_initial */
};

/* A ball of mass m (kg), radius r (m), radius of gyration squared k2 = I_cm/m
 * (m^2, > 0; k2 <= r² for a body whose mass lies within r, but any k2 > 0 is
 * accepted), struck by a horizontal impulse j (N s, > 0) at height h above
 * the centre (m, |h| <= r). The answer's v0, w0 and speeds are for this j. Statuses: MECH_OK; MECH_EINVAL (params "mass",
 * "radius", "k2", "impulse", "height"). */
enum mech_status mech_struck_ball(double m, double r, double k2, double j, double h,
                                  struct mech_struck_ball *out, struct mech_error *err);

struct mech_topple {
    double drop;          /* fall of the centre of mass, d - b/2, m */
    double omega_held;    /* angular velocity at landing, edge held, rad/s */
    double omega_free;    /* frictionless floor, rad/s */
    double impulse_held[2]; /* floor impulse to stop it (horizontal, vertical), N s */
    double impulse_free;  /* frictionless: vertical, N s */
};

/* A uniform box of mass m, width a (in the plane of the fall) and height b
 * (m, > 0) falling from balance on an edge onto its base, in gravity g.
 * Statuses: MECH_OK; MECH_EINVAL (params "mass", "width", "height", "g"). */
enum mech_status mech_topple_box(double m, double a, double b, double g, struct mech_topple *out,
                                 struct mech_error *err);

struct mech_rolling_incline {
    double moment_axis;     /* I about the rolling axis through the centre of mass, kg m^2 */
    double k;               /* I / (m R^2), dimensionless */
    double acceleration;    /* g sin(a) / (1 + k), m/s^2, along the slope */
    double friction_force;  /* m g sin(a) k / (1 + k), N: static friction needed */
    double min_friction_coefficient; /* tan(a) k / (1 + k): rolls without slipping above it */
    double time;            /* sqrt(2 L / acceleration), s (0 for L = 0) */
    double speed;           /* sqrt(2 acceleration L) = sqrt(2 g h / (1 + k)), m/s */
    double angular_speed;   /* speed / R, rad/s */
    double sliding_fraction; /* 1/(1 + k): the share of the drop's energy m g h that is
                                translational at the bottom (k/(1 + k) rotational) */
};

/* A body of mass m (kg, > 0) rolling without slipping down an incline of
 * angle a (rad, 0 < a < pi/2) in gravity g (m/s^2, > 0), on a rolling radius R
 * (m, > 0: the distance from the axis through the centre of mass to the
 * contact line), with moment i_axis (kg m^2, >= 0) about that axis, over a
 * distance L along the slope (m, >= 0). Energy or torque about the contact:
 * m g sin(a) = m a_cm (1 + I/(m R^2)), so a_cm = g sin(a) / (1 + k); the
 * friction m a_cm k holds the roll, needing mu >= tan(a) k/(1 + k).
 * Statuses: MECH_OK; MECH_EINVAL param "mass", "moment", "radius", "angle",
 * "g", "length" (outside the ranges above, not finite). */
enum mech_status mech_rolling_incline(double m, double i_axis, double radius, double angle,
                                      double g, double length,
                                      struct mech_rolling_incline *out,
                                      struct mech_error *err);

#endif
