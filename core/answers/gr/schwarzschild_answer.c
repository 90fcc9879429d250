/* schwarzschild_answer.c — the POST /v1/gr/schwarzschild answer in the
 * caller's units (mech/answers/gr/schwarzschild_answer.h): the named radii, the clocks
 * and circular orbit at r, the clock comparison, the radial infall and the
 * sampled effective potentials, from schwarzschild.c and radial_infall.c in
 * geometric units through gr_units.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/answers/gr/schwarzschild_answer.h"

/* The static clock and circular geodesic at r, converted to the caller's units. */
static enum mech_status at_r(const struct mech_schw_request *q, struct mech_schw_at_r *a,
                             struct mech_error *err)
{
    const struct mech_gr_units *u = &q->units;
    const double r = mech_gr_len_in(u, q->r);
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_schw_static_clock(r, &a->stat, &e) != MECH_OK ||
        mech_schw_circular_orbit(r, &a->circ, &e) != MECH_OK)
        return mech_error_set(err, MECH_EDOMAIN, "r",
                              "r = %.17g is not outside the horizon r_s = %.17g: no static "
                              "clock or orbit there",
                              q->r, mech_gr_len_out(u, 2.0));
    a->r = q->r;
    a->r_over_rs = r / 2.0;
    a->weak_field_potential = 1.0 / r;
    struct mech_schw_circular *co = &a->circ;
    if (co->stability != MECH_SCHW_ORBIT_NONE) {
        co->angular_momentum = mech_gr_ang_out(u, co->angular_momentum);
        co->omega = co->omega / mech_gr_time_out(u, 1.0);
        co->period_t = mech_gr_time_out(u, co->period_t);
        co->period_tau = mech_gr_time_out(u, co->period_tau);
    }
    return MECH_OK;
}

static enum mech_status infall(const struct mech_schw_request *q, struct mech_radial_infall *f,
                               struct mech_error *err)
{
    const struct mech_gr_units *u = &q->units;
    enum mech_status st = mech_radial_infall_from_rest(mech_gr_len_in(u, q->infall_from), f, err);
    if (st != MECH_OK) return st;
    f->to_horizon = mech_gr_time_out(u, f->to_horizon);
    f->to_singularity = mech_gr_time_out(u, f->to_singularity);
    f->horizon_to_singularity = mech_gr_time_out(u, f->horizon_to_singularity);
    return MECH_OK;
}

/* The sampled range, checked; the samples allocated and filled. */
static enum mech_status potential(const struct mech_schw_request *q, struct mech_schw_potential *v,
                                  struct mech_error *err)
{
    const struct mech_gr_units *u = &q->units;
    const double L = mech_gr_ang_in(u, q->potential_L);
    double ru, rs;
    const int ne = mech_schw_veff_extrema(L, &ru, &rs);
    /* sampled evenly in the caller's length unit, so given ends are kept exactly */
    const double rmin = q->has_r_min ? q->r_min : mech_gr_len_out(u, 2.0);
    const double rmax =
        q->has_r_max ? q->r_max : mech_gr_len_out(u, fmax(30.0, ne ? 3.0 * rs : 0.0));
    if (!(mech_gr_len_in(u, rmin) >= 2.0))
        return mech_error_set(err, MECH_EDOMAIN, "effective_potential/r_min",
                              "r_min must be at least r_s = %.17g (outside the horizon)",
                              mech_gr_len_out(u, 2.0));
    if (!(rmax > rmin) || !isfinite(rmax))
        return mech_error_set(err, MECH_EINVAL, "effective_potential/r_max",
                              "r_max must be above r_min");
    const size_t n = q->samples;
    if (n < 2 || n > MECH_SCHW_POTENTIAL_MAX_SAMPLES)
        return mech_error_set(err, MECH_EINVAL, "effective_potential/samples",
                              "samples must be 2 to %d, got %zu", MECH_SCHW_POTENTIAL_MAX_SAMPLES,
                              n);
    v->r = malloc(n * sizeof *v->r);
    v->massive = malloc(n * sizeof *v->massive);
    v->massive_minus_one = malloc(n * sizeof *v->massive_minus_one);
    v->photon = malloc(n * sizeof *v->photon);
    if (!v->r || !v->massive || !v->massive_minus_one || !v->photon)
        return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory");
    v->n = n;
    const double inv_len2 = 1.0 / (mech_gr_len_out(u, 1.0) * mech_gr_len_out(u, 1.0));
    for (size_t i = 0; i < n; i++) {
        v->r[i] = i + 1 == n ? rmax : rmin + (rmax - rmin) * (double)i / (double)(n - 1);
        const double r = mech_gr_len_in(u, v->r[i]), Lr = L / r;
        v->massive[i] = mech_schw_veff_massive(r, L);
        /* V - 1 = -2/r + L^2/r^2 - 2 L^2/r^3, without the cancellation of V - 1 */
        v->massive_minus_one[i] = -2.0 / r + Lr * Lr - 2.0 * Lr * Lr / r;
        v->photon[i] = mech_schw_veff_photon(r) * inv_len2;
    }
    v->L = mech_gr_ang_out(u, L);
    v->n_extrema = ne;
    v->unstable_r = ne ? mech_gr_len_out(u, ru) : NAN;
    v->unstable_V = ne ? mech_schw_veff_massive(ru, L) : NAN;
    v->stable_r = ne ? mech_gr_len_out(u, rs) : NAN;
    v->stable_V = ne ? mech_schw_veff_massive(rs, L) : NAN;
    v->photon_max_r = mech_gr_len_out(u, MECH_SCHW_PHOTON_SPHERE);
    v->photon_max_W = inv_len2 / 27.0; /* W(3) = (1/3)/9 */
    return MECH_OK;
}

static int all_finite(const double *x, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* Every number the answer carries is finite (NaN fields of an absent
 * circular orbit or of missing extrema are not carried). */
static int answer_finite(const struct mech_schw_answer *a)
{
    const double radii[5] = {a->schwarzschild_radius, a->photon_sphere, a->isco,
                             a->critical_impact_parameter, a->isco_binding_efficiency};
    if (!all_finite(radii, 5)) return 0;
    if (a->has_at_r) {
        const struct mech_schw_at_r *r = &a->at_r;
        const struct mech_schw_circular *co = &r->circ;
        const double x[6] = {r->r,         r->r_over_rs,         r->weak_field_potential,
                             r->stat.rate, r->stat.rate_deficit, r->stat.redshift};
        const double y[9] = {co->rate,
                             co->rate_deficit,
                             co->energy,
                             co->binding_efficiency,
                             co->angular_momentum,
                             co->local_speed,
                             co->omega,
                             co->period_t,
                             co->period_tau};
        if (!all_finite(x, 6) || (co->stability != MECH_SCHW_ORBIT_NONE && !all_finite(y, 9)))
            return 0;
    }
    if (a->has_clock) {
        const struct mech_schw_clock_compare *c = &a->clock;
        const double x[7] = {c->gravitational,
                             c->velocity,
                             c->net,
                             c->first_order_gravitational,
                             c->first_order_velocity,
                             c->first_order_net,
                             c->uniform_field_gravitational};
        if (!all_finite(x, 7)) return 0;
    }
    if (a->has_infall) {
        const double x[3] = {a->infall.to_horizon, a->infall.to_singularity,
                             a->infall.horizon_to_singularity};
        if (!all_finite(x, 3)) return 0;
    }
    if (a->has_potential) {
        const struct mech_schw_potential *v = &a->potential;
        const double x[3] = {v->L, v->photon_max_r, v->photon_max_W};
        const double y[4] = {v->unstable_r, v->unstable_V, v->stable_r, v->stable_V};
        if (!all_finite(x, 3) || (v->n_extrema && !all_finite(y, 4)) || !all_finite(v->r, v->n) ||
            !all_finite(v->massive, v->n) || !all_finite(v->massive_minus_one, v->n) ||
            !all_finite(v->photon, v->n))
            return 0;
    }
    return 1;
}

enum mech_status mech_schw_answer(const struct mech_schw_request *req, struct mech_schw_answer *out,
                                  struct mech_error *err)
{
    memset(out, 0, sizeof *out);
    const struct mech_gr_units *u = &req->units;
    out->schwarzschild_radius = mech_gr_len_out(u, MECH_SCHW_HORIZON);
    out->photon_sphere = mech_gr_len_out(u, MECH_SCHW_PHOTON_SPHERE);
    out->isco = mech_gr_len_out(u, MECH_SCHW_ISCO);
    out->critical_impact_parameter = mech_gr_len_out(u, MECH_SCHW_CRITICAL_IMPACT);
    out->isco_binding_efficiency = MECH_SCHW_ISCO_BINDING_EFFICIENCY;
    enum mech_status st = MECH_OK;
    if (req->has_reference_r && !req->has_r)
        return mech_error_set(err, MECH_EINVAL, "r",
                              "reference_r compares with a circular orbit at r: give r");
    if (req->has_r) {
        if ((st = at_r(req, &out->at_r, err)) != MECH_OK) return st;
        out->has_at_r = 1;
    }
    if (req->has_reference_r) {
        /* the radii as given, with GM/c^2 in their unit: r - R is formed before scaling */
        st = mech_schw_clock_compare(req->reference_r, req->r, mech_gr_len_out(u, 1.0), &out->clock,
                                     err);
        if (st != MECH_OK) return st;
        out->has_clock = 1;
    }
    if (req->has_infall_from) {
        if ((st = infall(req, &out->infall, err)) != MECH_OK) return st;
        out->has_infall = 1;
    }
    if (req->has_potential) {
        st = potential(req, &out->potential, err);
        if (st != MECH_OK) {
            mech_schw_answer_free(out);
            return st;
        }
        out->has_potential = 1;
    }
    if (!answer_finite(out)) {
        mech_schw_answer_free(out);
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "the result is not finite for this input (overflow or a "
                              "singularity)");
    }
    return MECH_OK;
}

void mech_schw_answer_free(struct mech_schw_answer *a)
{
    struct mech_schw_potential *v = &a->potential;
    free(v->r);
    free(v->massive);
    free(v->massive_minus_one);
    free(v->photon);
    v->r = v->massive = v->massive_minus_one = v->photon = NULL;
    v->n = 0;
    a->has_potential = 0;
}
