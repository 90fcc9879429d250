/* rigid_problems.c — closed-form rigid-body problems of notes chapter 2: the
 * free symmetric top's cones and precession rates, the struck ball, the
 * toppling box; derivations in mech/rigid/rigid_problems.h. */
#include "mech/rigid/rigid_problems.h"

#include <math.h>

static int positive(double x) { return isfinite(x) && x > 0; }

enum mech_status mech_free_symmetric_top(double i_perp, double i3, const double omega[3],
                                         struct mech_free_symmetric_top *out,
                                         struct mech_error *err)
{
    if (!omega || !out) return mech_error_set(err, MECH_EINVAL, NULL, "no omega or no output");
    if (!positive(i_perp)) return mech_error_set(err, MECH_EINVAL, "i_perp", "I_perp must be > 0");
    if (!positive(i3)) return mech_error_set(err, MECH_EINVAL, "i3", "I3 must be > 0");
    if (i3 > 2 * i_perp * (1 + 1e-12))
        return mech_error_set(err, MECH_EDOMAIN, "i3",
                              "I3 = %.17g > 2 I_perp = %.17g: no body has it (I3 <= I1 + I2)", i3,
                              2 * i_perp);
    for (int k = 0; k < 3; k++)
        if (!isfinite(omega[k])) return mech_error_set(err, MECH_EINVAL, "omega", "omega must be finite");
    double wp = hypot(omega[0], omega[1]), w3 = omega[2];
    if (!(wp > 0 || w3 != 0))
        return mech_error_set(err, MECH_EINVAL, "omega", "omega must not be zero");
    out->omega_magnitude = hypot(wp, w3);
    out->angular_momentum = hypot(i_perp * wp, i3 * w3);
    out->theta = atan2(i_perp * wp, i3 * w3);
    out->alpha = atan2(wp, w3);
    out->space_cone = fabs(out->theta - out->alpha);
    out->precession_space = out->angular_momentum / i_perp;
    out->precession_body = (i_perp - i3) * w3 / i_perp;
    out->ellipticity = (i3 - i_perp) / i_perp;
    out->prolate = i3 < i_perp;
    if (!isfinite(out->angular_momentum) || !isfinite(out->precession_space))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite result (extreme inputs)");
    return MECH_OK;
}

enum mech_status mech_struck_ball(double m, double r, double k2, double j, double h,
                                  struct mech_struck_ball *out, struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output");
    if (!positive(m)) return mech_error_set(err, MECH_EINVAL, "mass", "mass must be > 0");
    if (!positive(r)) return mech_error_set(err, MECH_EINVAL, "radius", "radius must be > 0");
    if (!positive(k2)) return mech_error_set(err, MECH_EINVAL, "k2", "I_cm/m must be > 0");
    if (!positive(j)) return mech_error_set(err, MECH_EINVAL, "impulse", "impulse must be > 0");
    if (!isfinite(h) || fabs(h) > r)
        return mech_error_set(err, MECH_EINVAL, "height",
                              "the strike must hit the ball: |height| <= radius %.17g m, got %.17g",
                              r, h);
    out->rolling_height = k2 / r;
    out->rolling_height_floor = r + k2 / r;
    out->v0 = j / m;
    out->w0 = j * h / (m * k2);
    /* v0 - w0 R = J/m (1 - h R / k²) = J/m (k² - h R)/k² */
    out->slip_velocity = j / m * (k2 - h * r) / k2;
    /* angular momentum about the contact line: J (R + h) = (m R² + m k²) v/R */
    out->v_final = j / m * r * (r + h) / (r * r + k2);
    double ke0 = 0.5 * m * out->v0 * out->v0 + 0.5 * m * k2 * out->w0 * out->w0;
    /* 1 - ke1/ke0, without cancellation: ke0 - ke1 = m (k² - hR)² J² / (2 m² k² (R² + k²))
     * (the slip's energy: expand ke0 and ke1 over the common denominator) */
    double d = (k2 - h * r);
    out->energy_lost_fraction = ke0 > 0 ? (j * j * d * d / (2 * m * k2 * (r * r + k2))) / ke0 : 0;
    return MECH_OK;
}

enum mech_status mech_topple_box(double m, double a, double b, double g, struct mech_topple *out,
                                 struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output");
    if (!positive(m)) return mech_error_set(err, MECH_EINVAL, "mass", "mass must be > 0");
    if (!positive(a)) return mech_error_set(err, MECH_EINVAL, "width", "width must be > 0");
    if (!positive(b)) return mech_error_set(err, MECH_EINVAL, "height", "height must be > 0");
    if (!positive(g)) return mech_error_set(err, MECH_EINVAL, "g", "g must be > 0");
    double d = 0.5 * hypot(a, b);
    /* d - b/2 = (d² - b²/4)/(d + b/2) = (a²/4)/(d + b/2): no cancellation for a << b */
    double drop = 0.25 * a * a / (d + 0.5 * b);
    out->drop = drop;
    double i_edge = m * (a * a + b * b) / 3, i_cm = m * (a * a + b * b) / 12;
    out->omega_held = sqrt(2 * m * g * drop / i_edge);
    out->omega_free = sqrt(2 * m * g * drop / (i_cm + m * a * a / 4));
    out->impulse_held[0] = m * out->omega_held * b / 2;
    out->impulse_held[1] = m * out->omega_held * a / 2;
    out->impulse_free = m * out->omega_free * a / 2;
    if (!isfinite(out->omega_held) || !isfinite(out->omega_free) || !isfinite(out->impulse_held[0]))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite result (extreme inputs)");
    return MECH_OK;
}

enum mech_status mech_rolling_incline(double m, double i_axis, double radius, double angle,
                                      double g, double length,
                                      struct mech_rolling_incline *out,
                                      struct mech_error *err)
{
    if (!out) return mech_error_set(err, MECH_EINVAL, NULL, "no output");
    if (!positive(m)) return mech_error_set(err, MECH_EINVAL, "mass", "must be finite and > 0");
    if (!(isfinite(i_axis) && i_axis >= 0))
        return mech_error_set(err, MECH_EINVAL, "moment", "must be finite and >= 0");
    if (!positive(radius))
        return mech_error_set(err, MECH_EINVAL, "radius",
                              "the rolling radius must be finite and > 0, got %.17g", radius);
    if (!(angle > 0 && angle < 1.5707963267948966))
        return mech_error_set(err, MECH_EINVAL, "angle",
                              "the incline's angle must be in (0, pi/2) rad, got %.17g", angle);
    if (!positive(g)) return mech_error_set(err, MECH_EINVAL, "g", "must be finite and > 0");
    if (!(isfinite(length) && length >= 0))
        return mech_error_set(err, MECH_EINVAL, "length", "must be finite and >= 0");
    /* k = I/(m R^2) computed as (I/m)/R/R so neither m R^2 nor I overflows on the way */
    const double k = i_axis / m / radius / radius, s = sin(angle);
    out->moment_axis = i_axis;
    out->k = k;
    out->acceleration = g * s / (1 + k);
    out->friction_force = m * g * s * (k / (1 + k));
    out->min_friction_coefficient = tan(angle) * (k / (1 + k));
    out->time = length > 0 ? sqrt(2 * length / out->acceleration) : 0;
    out->speed = sqrt(2 * out->acceleration * length);
    out->angular_speed = out->speed / radius;
    out->sliding_fraction = 1 / (1 + k);
    if (!isfinite(out->k) || !isfinite(out->time) || !isfinite(out->speed) ||
        !isfinite(out->angular_speed) || !isfinite(out->friction_force))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "non-finite result (extreme inputs)");
    return MECH_OK;
}
