/* geodesic_setup.c — from a geodesic request's initial-condition form, in SI
 * or geometric units, to the problem mech_geodesic_integrate runs, with the
 * motion's class and its exact references (mech/answers/gr/geodesic_setup.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/gr/geodesic_setup.h"

const char *mech_geodesic_class_name(enum mech_geodesic_class k)
{
    switch (k) {
    case MECH_GEODESIC_BOUND:
        return "bound";
    case MECH_GEODESIC_UNBOUND:
        return "unbound";
    case MECH_GEODESIC_CIRCULAR:
        return "circular";
    default:
        return "plunge";
    }
}

/* An initial-state error names the request's field: r0 stays, the others go
 * under initial/, turning points given by a and e are a's. */
static enum mech_status init_fail(enum mech_status st, struct mech_error *e, int axes,
                                  struct mech_error *err)
{
    char path[96];
    if (!strcmp(e->param, "r0"))
        snprintf(path, sizeof path, "r0");
    else if (axes && (!strcmp(e->param, "periapsis") || !strcmp(e->param, "apoapsis")))
        snprintf(path, sizeof path, "initial/semi_major_axis");
    else
        snprintf(path, sizeof path, "initial/%.80s", e->param);
    return mech_error_set(err, st, path, "%s", e->text);
}

static enum mech_status init_state(const struct mech_geodesic_request *q,
                                   struct mech_geodesic_init *in, struct mech_error *err)
{
    const struct mech_gr_units *u = &q->units;
    struct mech_error e;
    mech_error_clear(&e);
    /* A ray from far away (impact_parameter, no r0) starts at 100 b, at least 1000 GM/c^2:
     * the deflection's tail beyond r0 is added by quadrature, so the start only moves the
     * measured value by the integration error (1.7e-14 to 2.9e-14 rad for the Sun's limb
     * from 10 b to 1400 b). */
    const double r0 = q->has_r0 ? mech_gr_len_in(u, q->r0)
                      : q->form == MECH_GEODESIC_FORM_IMPACT
                          ? fmax(100.0 * mech_gr_len_in(u, q->impact_parameter), 1000.0)
                          : NAN;
    const int dir = q->outward ? 1 : -1;
    enum mech_status st;
    switch (q->form) {
    case MECH_GEODESIC_FORM_ENERGY:
        st = mech_geodesic_init_energy(r0, q->phi0, q->energy,
                                       mech_gr_ang_in(u, q->angular_momentum), dir, in, &e);
        break;
    case MECH_GEODESIC_FORM_LOCAL:
        st = mech_geodesic_init_local(q->kind, r0, q->phi0, mech_gr_speed_in(u, q->v_radial),
                                      mech_gr_speed_in(u, q->v_tangential), in, &e);
        break;
    case MECH_GEODESIC_FORM_IMPACT:
        st = mech_geodesic_init_impact(r0, q->phi0, mech_gr_len_in(u, q->impact_parameter), dir,
                                       in, &e);
        break;
    default: {
        double rp, ra;
        if (q->form == MECH_GEODESIC_FORM_TURNING) {
            rp = mech_gr_len_in(u, q->periapsis);
            ra = mech_gr_len_in(u, q->apoapsis);
        } else {
            const double a = mech_gr_len_in(u, q->semi_major_axis);
            rp = a * (1.0 - q->eccentricity);
            ra = a * (1.0 + q->eccentricity);
        }
        st = mech_geodesic_init_orbit(rp, ra, q->phi0, in, &e);
    }
    }
    if (st != MECH_OK) return init_fail(st, &e, q->form == MECH_GEODESIC_FORM_AXES, err);
    return MECH_OK;
}

enum mech_status mech_geodesic_setup(const struct mech_geodesic_request *q,
                                     struct mech_geodesic_setup *out, struct mech_error *err)
{
    const struct mech_gr_units *u = &q->units;
    const int photon = q->kind == MECH_GEODESIC_NULL;
    struct mech_geodesic_setup s;
    memset(&s, 0, sizeof s);
    struct mech_geodesic_init in;
    enum mech_status st = init_state(q, &in, err);
    if (st != MECH_OK) return st;

    /* classification and exact references */
    s.cls = MECH_GEODESIC_PLUNGE;
    s.bd = (struct mech_geodesic_bound){NAN, NAN, NAN};
    s.adv_exact = s.adv_quad = s.period_tau = s.period_t = NAN;
    if (!photon) {
        if ((st = mech_geodesic_classify(&in, &s.cls, &s.bd, err)) != MECH_OK) return st;
        s.bound = s.cls == MECH_GEODESIC_BOUND;
        if (s.bound) {
            if ((st = mech_geodesic_precession_exact(&s.bd, &s.adv_exact, err)) != MECH_OK ||
                (st = mech_geodesic_precession_quadrature(&s.bd, in.E, in.L, &s.adv_quad,
                                                          &s.period_tau, &s.period_t, err)) !=
                    MECH_OK)
                return st;
        }
    }
    if (q->has_orbits && !s.bound)
        return mech_error_set(err, MECH_EINVAL, "orbits",
                              "orbits counts radial periods of a bound orbit; this motion is %s: "
                              "give tau_end",
                              mech_geodesic_class_name(s.cls));

    struct mech_geodesic_problem *p = &s.problem;
    p->init = in;
    const double T = mech_geodesic_time_unit(&in);
    s.time_unit = T;
    const double rs_esc = q->has_r_escape ? mech_gr_len_in(u, q->r_escape)
                                          : 2.0 * (s.bound ? 1.0 / s.bd.u1 : in.r0);
    p->r_escape = rs_esc;
    if (!(rs_esc > in.r0))
        return mech_error_set(err, MECH_EINVAL, "r_escape",
                              "r_escape must be beyond the start radius %.17g",
                              mech_gr_len_out(u, in.r0));
    if (photon) {
        /* default: the straight-line path to r_escape, 2 % longer (the Shapiro delay is
         * ~4GM/c^2 ln(r/b)), plus 100 loops of the photon sphere for near-critical light */
        const double b = fabs(in.L), r02 = fmax(0.0, (in.r0 - b) * (in.r0 + b));
        const double re2 = fmax(0.0, (rs_esc - b) * (rs_esc + b));
        const double path = in.rdot0 <= 0 ? sqrt(r02) + sqrt(re2) : sqrt(re2) - sqrt(r02);
        p->param_end =
            q->has_lambda_end ? mech_gr_time_in(u, q->lambda_end) : 1.02 * path + 600.0 * MECH_PI;
    } else
        p->param_end = q->has_tau_end ? mech_gr_time_in(u, q->tau_end) : q->orbits * s.period_tau;
    p->constraint_bound = q->constraint_bound;
    if (q->has_orbits) p->periapsis_lookahead = 0.25 * s.period_tau; /* whole periods end on a periapsis */
    p->samples = q->samples;
    if (!isfinite(p->param_end) || !(p->param_end / T > 0))
        return mech_error_set(err, MECH_EINVAL, photon ? "lambda_end" : "tau_end",
                              "the run's length is not representable");
    *out = s;
    return MECH_OK;
}
