/* schwarzschild.c — POST /v1/gr/schwarzschild: radii, clocks and red
 * shift, circular orbits, the GPS-style clock comparison, the radial infall
 * and the effective potentials (the notes' "A Little General Relativity",
 * built as Hartle, "Gravity" ch. 9 and 11; Carroll ch. 5; Schutz ch. 11).
 * The answer is one core call, mech_schw_answer (core/answers/gr/schwarzschild_answer.c);
 * this file parses the request (its units with api/ops/gr/gr_units.c), calls it
 * and encodes the answer. */
#include <math.h>

#include "run/endpoint.h"
#include "ops/gr/gr_units.h"
#include "mech/answers/gr/schwarzschild_answer.h"

#define MICROSECONDS_PER_DAY 86400e6

static const char *stability_name(enum mech_schw_stability s)
{
    switch (s) {
    case MECH_SCHW_ORBIT_STABLE:
        return "stable";
    case MECH_SCHW_ORBIT_UNSTABLE:
        return "unstable";
    case MECH_SCHW_ORBIT_MARGINAL:
        return "marginal";
    default:
        return "none";
    }
}

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

/* The request's fields, in its units (schema-validated). */
static void read_request(const json_t *body, struct mech_schw_request *q)
{
    const json_t *rj = json_object_get(body, "r"), *refj = json_object_get(body, "reference_r");
    const json_t *ij = json_object_get(body, "infall_from");
    const json_t *ej = json_object_get(body, "effective_potential");
    q->has_r = rj != NULL;
    q->r = json_number_value(rj);
    q->has_reference_r = refj != NULL;
    q->reference_r = json_number_value(refj);
    q->has_infall_from = ij != NULL;
    q->infall_from = json_number_value(ij);
    q->has_potential = ej != NULL;
    if (ej) {
        const json_t *a = json_object_get(ej, "r_min"), *b = json_object_get(ej, "r_max");
        q->potential_L = api_number(ej, "angular_momentum", 0);
        q->has_r_min = a != NULL;
        q->r_min = json_number_value(a);
        q->has_r_max = b != NULL;
        q->r_max = json_number_value(b);
        q->samples = (size_t)api_number_of(ej, "samples");
    }
}

static json_t *at_r_json(struct api_call *c, const struct mech_schw_at_r *a)
{
    const struct mech_schw_circular *co = &a->circ;
    json_t *o = json_object(), *st = json_object(), *cj = json_object();
    set(o, "r", api_real(c, a->r)); /* echoed exactly */
    set(o, "r_over_rs", api_real(c, a->r_over_rs));
    set(o, "weak_field_potential", api_real(c, a->weak_field_potential));
    set(st, "clock_rate", api_real(c, a->stat.rate));
    set(st, "clock_rate_deficit", api_real(c, a->stat.rate_deficit));
    set(st, "redshift", api_real(c, a->stat.redshift));
    set(o, "static", st);
    set(cj, "exists", json_boolean(co->stability != MECH_SCHW_ORBIT_NONE));
    set(cj, "stability", json_string(stability_name(co->stability)));
    if (co->stability != MECH_SCHW_ORBIT_NONE) {
        set(cj, "clock_rate", api_real(c, co->rate));
        set(cj, "clock_rate_deficit", api_real(c, co->rate_deficit));
        set(cj, "energy", api_real(c, co->energy));
        set(cj, "binding_efficiency", api_real(c, co->binding_efficiency));
        set(cj, "angular_momentum", api_real(c, co->angular_momentum));
        set(cj, "local_speed_over_c", api_real(c, co->local_speed));
        set(cj, "angular_velocity", api_real(c, co->omega));
        set(cj, "period_coordinate", api_real(c, co->period_t));
        set(cj, "period_proper", api_real(c, co->period_tau));
    } else {
        set(cj, "why",
            json_string("no circular geodesic at or inside the photon sphere r = "
                        "3GM/c^2"));
    }
    set(o, "circular_orbit", cj);
    return o;
}

static json_t *three(struct api_call *c, double g, double v, double n)
{
    json_t *o = json_object();
    set(o, "gravitational", api_real(c, g));
    set(o, "velocity", api_real(c, v));
    set(o, "net", api_real(c, n));
    return o;
}

static json_t *clock_json(struct api_call *c, const struct mech_schw_request *q,
                          const struct mech_schw_clock_compare *cc)
{
    const double day = MICROSECONDS_PER_DAY;
    json_t *k = json_object();
    set(k, "reference", json_string("static clock at reference_r"));
    set(k, "clock", json_string("clock on the circular orbit at r"));
    set(k, "reference_r", api_real(c, q->reference_r));
    set(k, "r", api_real(c, q->r));
    set(k, "fractional", three(c, cc->gravitational, cc->velocity, cc->net));
    set(k, "microseconds_per_day",
        three(c, cc->gravitational * day, cc->velocity * day, cc->net * day));
    json_t *fo = json_object();
    set(fo, "gravitational", api_real(c, cc->first_order_gravitational));
    set(fo, "velocity", api_real(c, cc->first_order_velocity));
    set(fo, "net", api_real(c, cc->first_order_net));
    set(fo, "microseconds_per_day_net", api_real(c, cc->first_order_net * day));
    set(k, "first_order", fo);
    json_t *uf = json_object();
    set(uf, "gravitational", api_real(c, cc->uniform_field_gravitational));
    set(uf, "label",
        json_string("approximation: the notes' uniform-field red shift g h/c^2, g = "
                    "GM/R^2 at reference_r, h = r - R (relative error ~h/R beside "
                    "fractional.gravitational)"));
    set(k, "uniform_field", uf);
    set(k, "left_out",
        json_string("the reference's own motion (the Earth's rotation: "
                    "v^2/(2c^2) ~ 1.2e-12 at the equator, 0.1 us/day), "
                    "other masses, orbit eccentricity"));
    return k;
}

static json_t *infall_json(struct api_call *c, const struct mech_schw_request *q,
                           const struct mech_radial_infall *f)
{
    json_t *ri = json_object();
    set(ri, "from", api_real(c, q->infall_from));
    set(ri, "proper_time_to_horizon", api_real(c, f->to_horizon));
    set(ri, "proper_time_to_singularity", api_real(c, f->to_singularity));
    set(ri, "proper_time_horizon_to_singularity", api_real(c, f->horizon_to_singularity));
    set(ri, "coordinate_time_to_horizon", json_null());
    set(ri, "starts_on_horizon", json_boolean(f->on_horizon));
    set(ri, "note",
        json_string("a fall from rest; the coordinate (far-away) time to the horizon "
                    "is infinite, hence null; the proper time to r = 0 equals the "
                    "Newtonian free-fall time"));
    return ri;
}

static json_t *real_if(struct api_call *c, int has, double x)
{
    return has ? api_real(c, x) : json_null();
}

static json_t *potential_json(struct api_call *c, const struct mech_gr_units *u,
                              const struct mech_schw_potential *p)
{
    const size_t n = p->n;
    const int ne = p->n_extrema;
    json_t *v = json_object();
    set(v, "angular_momentum", api_real(c, p->L));
    set(v, "massive_normalisation",
        json_string("(dr/dtau)^2/c^2 + V = (E/mc^2)^2, V = (1 - r_s/r)(1 + "
                    "L^2/(c^2 r^2)), dimensionless"));
    set(v, "photon_normalisation",
        json_string(u->geometric ? "(1/L^2)(dr/dlambda)^2 = 1/b^2 - W, W = (1 - "
                                   "r_s/r)/r^2, (GM/c^2)^-2"
                                 : "(1/L^2)(dr/dlambda)^2 = 1/b^2 - W, W = (1 - "
                                   "r_s/r)/r^2, 1/m^2"));
    set(v, "r", api_reals(c, p->r, n));
    set(v, "massive", api_reals(c, p->massive, n));
    set(v, "massive_minus_one", api_reals(c, p->massive_minus_one, n));
    set(v, "photon", api_reals(c, p->photon, n));
    json_t *x = json_object();
    set(x, "count", json_integer(ne));
    set(x, "unstable_r", real_if(c, ne, p->unstable_r));
    set(x, "unstable_V", real_if(c, ne, p->unstable_V));
    set(x, "stable_r", real_if(c, ne, p->stable_r));
    set(x, "stable_V", real_if(c, ne, p->stable_V));
    set(v, "massive_extrema", x);
    json_t *pm = json_object();
    set(pm, "r", api_real(c, p->photon_max_r));
    set(pm, "W", api_real(c, p->photon_max_W));
    set(v, "photon_maximum", pm);
    return v;
}

json_t *api_op_gr_schwarzschild(struct api_call *c, const json_t *body)
{
    struct mech_schw_request q = {0};
    if (!api_gr_units_read(c, body, &q.units)) return NULL;
    read_request(body, &q);
    struct mech_schw_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_schw_answer(&q, &a, &e);
    if (st != MECH_OK) {
        mech_schw_answer_free(&a);
        return api_call_fail_core(c, st, &e, "");
    }
    json_t *out = json_object();
    set(out, "units", api_gr_units_json(c, &q.units));
    set(out, "schwarzschild_radius", api_real(c, a.schwarzschild_radius));
    set(out, "photon_sphere", api_real(c, a.photon_sphere));
    set(out, "isco", api_real(c, a.isco));
    set(out, "critical_impact_parameter", api_real(c, a.critical_impact_parameter));
    set(out, "isco_binding_efficiency", api_real(c, a.isco_binding_efficiency));
    if (a.has_at_r) set(out, "at_r", at_r_json(c, &a.at_r));
    if (a.has_clock) set(out, "clock_comparison", clock_json(c, &q, &a.clock));
    if (a.has_infall) set(out, "radial_infall", infall_json(c, &q, &a.infall));
    if (a.has_potential) set(out, "effective_potential", potential_json(c, &q.units, &a.potential));
    mech_schw_answer_free(&a);
    return out;
}
