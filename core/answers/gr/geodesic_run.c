/* geodesic_run.c — integrate a set-up geodesic and put the measured periapsis
 * advance and light deflection beside their references
 * (mech/answers/gr/geodesic_run.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/gr/geodesic_run.h"
#include "mech/gr/schwarzschild.h"

void mech_geodesic_answer_free(struct mech_geodesic_answer *a)
{
    if (!a) return;
    free(a->result.param);
    free(a->result.t);
    free(a->result.r);
    free(a->result.phi);
    a->result.param = a->result.t = a->result.r = a->result.phi = NULL;
}

/* Light: b > 3 sqrt 3 outside the photon sphere turns (scatter, or escapes if
 * it starts outward); inside it, it turns back into the hole; b < 3 sqrt 3
 * falls in unless it starts outward. */
static const char *light_motion(const struct mech_geodesic_init *in, int *scatter)
{
    const int wide = fabs(in->L) > MECH_SCHW_CRITICAL_IMPACT;
    *scatter = wide && in->r0 > 3.0;
    return *scatter                      ? (in->rdot0 <= 0 ? "scatter" : "escape")
           : (wide || in->rdot0 <= 0) ? "capture"
                                         : "escape";
}

enum mech_status mech_geodesic_run(const struct mech_geodesic_setup *s,
                                   const struct mech_geodesic_problem *p,
                                   const struct mech_budget *budget,
                                   struct mech_geodesic_answer *out, struct mech_error *err)
{
    memset(out, 0, sizeof *out);
    out->advance_first_order = out->deflection_exact = out->deflection_elliptic = NAN;
    out->elliptic_precision = out->closest_approach = NAN;
    out->deflection_first_order = out->deflection_second_order = NAN;
    const int photon = p->init.kind == MECH_GEODESIC_NULL;
    if (photon)
        out->motion = light_motion(&p->init, &out->scatter);
    else
        out->motion = mech_geodesic_class_name(s->cls);

    const size_t n = p->samples;
    if (n > SIZE_MAX / sizeof(double))
        return mech_error_set(err, MECH_EINVAL, "samples", "%zu samples cannot be stored", n);
    struct mech_geodesic_result *r = &out->result;
    r->param = malloc(n * sizeof *r->param);
    r->t = malloc(n * sizeof *r->t);
    r->r = malloc(n * sizeof *r->r);
    r->phi = malloc(n * sizeof *r->phi);
    if (!r->param || !r->t || !r->r || !r->phi)
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
    enum mech_status st = mech_geodesic_integrate(p, budget, r, err);
    if (st != MECH_OK) return st;
    out->integrated = 1;

    if (s->bound) out->advance_first_order = 3.0 * MECH_PI * (s->bd.u1 + s->bd.u2);
    if (out->scatter) {
        const double b = fabs(p->init.L);
        double dx, dq, rmin;
        if ((st = mech_geodesic_deflection_exact(b, &dx, &rmin, err)) != MECH_OK ||
            (st = mech_geodesic_deflection_quadrature(b, &dq, err)) != MECH_OK)
            return st;
        out->deflection_exact = dq;
        out->deflection_elliptic = dx;
        /* the elliptic form ends in "- pi": ~4e-16 pi / delta relative */
        out->elliptic_precision = 4e-16 * MECH_PI / dq;
        out->closest_approach = rmin;
        out->deflection_first_order = 4.0 / b;
        out->deflection_second_order = 4.0 / b + 15.0 * MECH_PI / (4.0 * b * b);
    }
    return MECH_OK;
}

double mech_geodesic_error_gain(double b)
{
    if (!(b > 3.0 * sqrt(3.0)) || !isfinite(b)) return 1.0;
    double delta = 0.0;
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_geodesic_deflection_quadrature(b, &delta, &e) != MECH_OK || !isfinite(delta))
        return 1.0;
    /* capped: past ~30 rad of winding no double-precision run keeps anything */
    return 2.0 * exp(fmin(fmax(delta - 3.3, 0.0), 30.0));
}

int mech_geodesic_pilot_applies(const struct mech_geodesic_setup *s)
{
    if (!s) return 0;
    if (!s->bound) return 1;
    /* u2 = 1 / r_periapsis (GM/c^2) */
    return s->bd.u2 * MECH_GEODESIC_PILOT_STRONG_R > 1.0;
}

enum mech_status mech_geodesic_pilot_run(void *ctx, const char *method,
                                         const struct mech_ode_options *opt, double fraction,
                                         const struct mech_budget *budget,
                                         struct mech_ode_stats *stats, double *y_end,
                                         size_t *dim, struct mech_error *err)
{
    const struct mech_geodesic_problem *p0 = ctx;
    if (!p0 || !method || !opt || !stats || !y_end || !dim || !(fraction > 0.0 && fraction <= 1.0))
        return mech_error_set(err, MECH_EINVAL, NULL, "invalid pilot arguments");
    *dim = 0;
    memset(stats, 0, sizeof *stats);
    struct mech_geodesic_problem p = *p0;
    p.param_end = p0->param_end * fraction;
    p.periapsis_lookahead = 0.0;
    p.samples = 2;
    p.method = method;
    p.opt = *opt;
    double pa[2], t[2], r[2], phi[2];
    struct mech_geodesic_result res;
    memset(&res, 0, sizeof res);
    res.param = pa;
    res.t = t;
    res.r = r;
    res.phi = phi;
    enum mech_status st = mech_geodesic_integrate(&p, budget, &res, err);
    *stats = res.stats;
    if (st != MECH_OK) return st;
    if (res.captured || res.escaped)
        return mech_error_set(err, MECH_EDOMAIN, NULL,
                              "the pilot was captured or escaped: its rate is no guide");
    y_end[0] = res.end_r;
    y_end[1] = res.end_phi;
    y_end[2] = res.end_t;
    *dim = 3;
    return MECH_OK;
}
