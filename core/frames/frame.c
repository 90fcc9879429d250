/* frame.c — the angular velocity of a reference frame in its own axes
 * (mech/frames/frame.h; notes §1.2, §1.3). */
#include "mech/frames/frame.h"
#include "mech/base/constants.h"

#include <math.h>

struct mech_vec3 mech_frame_omega(const struct mech_frame *frame)
{
    switch (frame->type) {
    case MECH_FRAME_ROTATING:
        return frame->omega;
    case MECH_FRAME_EARTH: {
        /* notes §1.3: w points from the south to the north pole; in local
         * axes (east, north, up) at latitude lat: w = W (0, cos lat, sin lat). */
        double lat = frame->latitude_deg * (MECH_PI / 180.0);
        return mech_vec3_make(0.0, frame->omega_magnitude * cos(lat),
                              frame->omega_magnitude * sin(lat));
    }
    case MECH_FRAME_INERTIAL:
    default:
        return mech_vec3_make(0.0, 0.0, 0.0);
    }
}
