/* mech/frames/frame.h — the reference frames a particle's motion is described in
 * (notes §1.2 "Rotating frames", §1.3 "Motion near the Earth"): inertial,
 * rotating (with a constant angular acceleration and an accelerating origin)
 * or the local Earth frame (x east, y north, z up), and the frame's angular
 * velocity. The equations of motion in them are mech/frames/trajectory.h's.
 *
 * Units: SI (rad/s, rad/s^2, m/s^2, degrees for the latitude). Pure, reentrant.
 */
#ifndef MECH_FRAME_H
#define MECH_FRAME_H

#include "mech/base/constants.h"
#include "mech/base/vec.h"

enum mech_frame_type { MECH_FRAME_INERTIAL = 0, MECH_FRAME_ROTATING, MECH_FRAME_EARTH };

struct mech_frame {
    enum mech_frame_type type;
    struct mech_vec3 omega;  /* ROTATING: angular velocity at t = 0 (rad/s), finite */
    struct mech_vec3 omega_dot;    /* ROTATING: constant angular acceleration (rad/s^2):
                                      w(t) = omega + omega_dot t; 0 for the other types */
    struct mech_vec3 acceleration; /* ROTATING: constant acceleration of the origin (m/s^2),
                                      frame axes; 0 for the other types */
    double latitude_deg;     /* EARTH: latitude in [-90, 90] degrees */
    double omega_magnitude;  /* EARTH: rotation rate >= 0 (rad/s); use MECH_EARTH_OMEGA_SIDEREAL */
};

/* Angular velocity of the frame in its own axes (rad/s) at t = 0: 0 for
 * inertial, omega for rotating, W (0, cos lat, sin lat) for earth. No validation. */
struct mech_vec3 mech_frame_omega(const struct mech_frame *frame);

#endif
