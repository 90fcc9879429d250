/* mech/frames/scenes_first_order.h — the notes' closed forms that the chapter-1
 * ballistic scenes (mech/frames/scenes.h) quote beside their numerical answers:
 * the falling object's eastward deflection, the vertical shot's speed and
 * height and its westward drift, and the cannonball's launch, no-rotation
 * landing and the due-east formulas of notes §1.5 problems 4-5.
 *
 * Local Earth axes (x east, y north, z up), w = W (0, cos lat, sin lat),
 * to first order in W (derivations in core/frames/scenes_first_order.c).
 * Units SI, angles in degrees where the name says _deg, else radians.
 * Pure functions: no allocation, no globals, reentrant. Inputs outside the
 * stated ranges give NaN (never a crash); the caller checks finiteness. */
#ifndef MECH_SCENES_FIRST_ORDER_H
#define MECH_SCENES_FIRST_ORDER_H

#include "mech/base/vec.h"

/* Eastward deflection (m) of a body dropped from rest from height h:
 * x_east = (W cos(lat) / 3) sqrt(8 h^3 / g) (notes §1.4, "Deflection of a
 * Falling Object"; 1.86 cm at h = 100 m, lat 32 deg). h >= 0 m, g > 0
 * m/s^2, W >= 0 rad/s (all finite), latitude_deg in [-90, 90]; NaN
 * outside. Relative error a few ulp; overflows to +inf only for h^3 / g
 * beyond the double range (h > 1e100 m at g ~ 10). */
double mech_scene_drop_east(double height, double g, double omega, double latitude_deg);

/* The launch speed (m/s) that rises to height h: sqrt(2 g h). h >= 0 m,
 * g > 0 m/s^2, both finite; NaN outside. */
double mech_scene_vertical_shot_speed(double height, double g);

/* A vertical shot at speed v0 to first order in W. */
struct mech_scene_vertical_shot_first_order {
    double height;      /* m: v0^2 / (2 g), the top of the flight */
    double flight_time; /* s: 2 v0 / g */
    double west;        /* m: (4/3) W cos(lat) sqrt(8 h^3 / g) (notes §1.5 problem 3) */
    double drop_east;   /* m: the drop's eastward deflection from the same height
                           (mech_scene_drop_east): west = 4 drop_east */
};

/* Fill *out for a vertical shot at v0 (m/s, finite, >= 0; g, W, latitude as
 * mech_scene_drop_east). Out-of-range input gives NaN members. out must not
 * be NULL. */
void mech_scene_vertical_shot_first_order(double v0, double g, double omega,
                                          double latitude_deg,
                                          struct mech_scene_vertical_shot_first_order *out);

/* A cannonball fired at speed v0, elevation alpha above the horizon and
 * azimuth phi counterclockwise from east. */
struct mech_scene_cannonball_first_order {
    double elevation, azimuth;   /* rad: the request's degrees converted */
    struct mech_vec3 forward;    /* unit horizontal firing direction (cos phi, sin phi, 0) */
    struct mech_vec3 velocity;   /* m/s: v0 (cos a cos phi, cos a sin phi, sin a) */
    double t0;                   /* s: no-rotation flight time 2 v0 sin(a) / g */
    double range;                /* m: no-rotation range v0^2 sin(2a) / g */
    double south_due_east;       /* m: 4 v0^3 W sin(lat) sin^2(a) cos(a) / g^2 (notes §1.5
                                    problem 4, firing due east) */
    double range_increase_due_east; /* m: W cos(lat) sqrt(2 R^3 / g) (cot^1/2 a - tan^3/2 a / 3)
                                       (notes §1.5 problem 5, firing due east) */
};

/* Fill *out. v0 >= 0 m/s, elevation_deg in (0, 90], azimuth_deg finite,
 * g > 0 m/s^2, W >= 0 rad/s (all finite), latitude_deg in [-90, 90].
 * Out-of-range input gives NaN members. out must not be NULL.
 * Accuracy: round-off, except range_increase_due_east near elevation 60 deg,
 * where its two terms cancel (the absolute error stays at round-off of
 * either term). */
void mech_scene_cannonball_first_order(double v0, double elevation_deg, double azimuth_deg,
                                       double g, double omega, double latitude_deg,
                                       struct mech_scene_cannonball_first_order *out);

#endif
