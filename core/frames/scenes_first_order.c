/* scenes_first_order.c — the notes' first-order closed forms for the
 * chapter-1 ballistic scenes (mech/frames/scenes_first_order.h).
 *
 * Derivation (notes §1.3-1.5): r'' = g - 2 w x r' to first order in W, with
 * w = W (0, cos lat, sin lat) and g = (0, 0, -g), gives r = r_0 + r_1,
 * r_0 = r0 + v0 t + g t^2 / 2, r_1 = -w x (v0 t^2 + g t^3 / 3).
 *   drop from rest at height h: w x g = (-W cos(lat) g, 0, 0), so
 *     x_1 = W cos(lat) g t^3 / 3 at t = sqrt(2 h / g):
 *     x_east = (W cos(lat) / 3) sqrt(8 h^3 / g);
 *   vertical shot v0 = (0, 0, v0), T = 2 v0 / g, h = v0^2 / (2 g):
 *     x_1(T) = -W cos(lat) (v0 T^2 - g T^3 / 3) = -(4/3) W cos(lat) sqrt(8 h^3 / g)
 *     (west, four times the drop's east);
 *   firing due east, v0 = v0 (cos a, 0, sin a), T = 2 v0 sin(a) / g:
 *     y_1(T) = -W sin(lat) v0 cos(a) T^2 (south 4 v0^3 W sin(lat) sin^2 a cos a / g^2);
 *     x_1(T) + v0 cos(a) dt_1, dt_1 = -z_1(T) / z_0'(T) = W cos(lat) cos(a) T^2 / sin(a):
 *     dR = 4 W cos(lat) v0^3 (sin a cos^2 a - sin^3 a / 3) / g^2
 *        = W cos(lat) sqrt(2 R^3 / g) (cot^1/2 a - tan^3/2 a / 3), R = v0^2 sin(2a) / g.
 * The expressions below are the ones the API has always answered, kept
 * operation for operation so its answers stay byte-identical.
 */
#include "mech/frames/scenes_first_order.h"
#include "mech/base/constants.h"

#include <math.h>

static int earth_ok(double g, double omega, double latitude_deg)
{
    return isfinite(g) && g > 0.0 && isfinite(omega) && omega >= 0.0 &&
           latitude_deg >= -90.0 && latitude_deg <= 90.0;
}

double mech_scene_drop_east(double height, double g, double omega, double latitude_deg)
{
    if (!(isfinite(height) && height >= 0.0) || !earth_ok(g, omega, latitude_deg)) return NAN;
    const double lat = latitude_deg * MECH_PI / 180.0;
    return omega * cos(lat) / 3.0 * sqrt(8.0 * height * height * height / g);
}

double mech_scene_vertical_shot_speed(double height, double g)
{
    if (!(isfinite(height) && height >= 0.0 && isfinite(g) && g > 0.0)) return NAN;
    return sqrt(2.0 * g * height);
}

void mech_scene_vertical_shot_first_order(double v0, double g, double omega,
                                          double latitude_deg,
                                          struct mech_scene_vertical_shot_first_order *out)
{
    if (!(isfinite(v0) && v0 >= 0.0) || !earth_ok(g, omega, latitude_deg)) {
        out->height = out->flight_time = out->west = out->drop_east = NAN;
        return;
    }
    out->height = v0 * v0 / (2.0 * g);
    out->flight_time = 2.0 * v0 / g;
    out->drop_east = mech_scene_drop_east(out->height, g, omega, latitude_deg);
    out->west = 4.0 * out->drop_east;
}

void mech_scene_cannonball_first_order(double v0, double elevation_deg, double azimuth_deg,
                                       double g, double omega, double latitude_deg,
                                       struct mech_scene_cannonball_first_order *out)
{
    if (!(isfinite(v0) && v0 >= 0.0) || !(elevation_deg > 0.0 && elevation_deg <= 90.0) ||
        !isfinite(azimuth_deg) || !earth_ok(g, omega, latitude_deg)) {
        out->elevation = out->azimuth = out->t0 = out->range = NAN;
        out->south_due_east = out->range_increase_due_east = NAN;
        out->forward = out->velocity = mech_vec3_make(NAN, NAN, NAN);
        return;
    }
    const double al = elevation_deg * MECH_PI / 180.0;
    const double ph = azimuth_deg * MECH_PI / 180.0;
    const double lat = latitude_deg * MECH_PI / 180.0, W = omega;
    out->elevation = al;
    out->azimuth = ph;
    out->forward = mech_vec3_make(cos(ph), sin(ph), 0);
    out->velocity = mech_vec3_make(v0 * cos(al) * cos(ph), v0 * cos(al) * sin(ph), v0 * sin(al));
    out->t0 = 2.0 * v0 * sin(al) / g;
    const double R = v0 * v0 * sin(2.0 * al) / g;
    out->range = R;
    const double sa = sin(al), ca = cos(al);
    out->south_due_east = 4.0 * v0 * v0 * v0 * W * sin(lat) * sa * sa * ca / (g * g);
    /* The notes' form W cos(lat) sqrt(2R^3/g) (sqrt(cot a) - sin a sqrt(tan a)/(3 cos a))
     * is 4 W cos(lat) v0^3 sin a (4 cos^2 a - 1) / (3 g^2): its two terms cancel at 60 deg,
     * where the increase is 0. Written as (2 cos a - 1)(2 cos a + 1) with
     * 2 cos a - 1 = 2 (cos a - cos 60) = -4 sin(a/2 + 30 deg) sin((a - 60 deg)/2), the
     * difference of angles taken in degrees (exact near 60), every digit survives. */
    const double half_d = 0.5 * (elevation_deg - 60.0) * (MECH_PI / 180.0);
    const double two_c_minus_1 = -4.0 * sin(0.5 * al + MECH_PI / 6.0) * sin(half_d);
    out->range_increase_due_east = 4.0 * W * cos(lat) * v0 * v0 * v0 * sa * two_c_minus_1 *
                                   (2.0 * ca + 1.0) / (3.0 * g * g);
}
