/* struck_ball.c — POST /v1/rigid/struck-ball (notes §2.11 HW 3: a ball struck
 * by a cue, rolling without slipping).
 * JSON <-> core only: physics and derivations in core/rigid/rigid_problems.c
 * and mech/rigid/rigid_problems.h. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/rigid/rigid_problems.h"

static void set_real(struct api_call *c, json_t *o, const char *k, double x)
{
    json_object_set_new(o, k, api_real(c, x));
}


json_t *api_op_rigid_struck_ball(struct api_call *c, const json_t *body)
{
    double r = api_number_of(body, "radius"), m = api_number_of(body, "mass");
    const char *shape = api_string_of(body, "shape");
    double f = !strcmp(shape, "spherical_shell") ? 2.0 / 3 : !strcmp(shape, "solid_cylinder") ? 0.5
               : !strcmp(shape, "hoop")          ? 1.0
                                                 : 0.4;
    double k2 = json_object_get(body, "moment_of_inertia")
                    ? api_number(body, "moment_of_inertia", 0) / m
                    : f * r * r;
    double h = api_number(body, "height", k2 / r);
    struct mech_struck_ball s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_struck_ball(m, r, k2, api_number_of(body, "impulse"), h, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object();
    if (!out) return NULL;
    set_real(c, out, "k2_over_R2", k2 / (r * r));
    set_real(c, out, "rolling_height", s.rolling_height);
    set_real(c, out, "rolling_height_floor", s.rolling_height_floor);
    set_real(c, out, "height", h);
    set_real(c, out, "v0", s.v0);
    set_real(c, out, "w0", s.w0);
    set_real(c, out, "slip_velocity", s.slip_velocity);
    json_object_set_new(out, "rolls_at_once", json_boolean(fabs(s.slip_velocity) <= 1e-14 * s.v0));
    set_real(c, out, "v_final", s.v_final);
    set_real(c, out, "w_final", s.v_final / r);
    set_real(c, out, "energy_lost_fraction", s.energy_lost_fraction);
    return out;
}
