/* circular_orbit.c — POST /v1/hamiltonian/circular-orbit: the
 * circular orbits of a given angular momentum in a central potential (a sum
 * of power laws, as /v1/small-oscillations takes it, or a Kepler gm), with
 * their radius, energy, angular and radial frequencies, periods, apsidal
 * angle and stability (notes ch. 5, "Motion in a Central Potential").
 * JSON <-> core only; the physics is core/hamiltonian/circular_orbit.c. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/hamiltonian/circular_orbit.h"


#define SET(o, k, v) json_object_set_new_nocheck((o), (k), (v))

static json_t *orbit_json(struct api_call *c, const struct mech_orbit_oscillation *o, double r,
                          double res)
{
    json_t *j = json_object();
    if (!j) return NULL;
    SET(j, "radius", api_real(c, r));
    SET(j, "energy", api_real(c, o->energy));
    SET(j, "angular_momentum", api_real(c, o->angular_momentum));
    SET(j, "speed", api_real(c, r * o->omega_phi));
    SET(j, "omega_phi", api_real(c, o->omega_phi));
    SET(j, "period_phi", api_real(c, 2 * MECH_PI / o->omega_phi));
    SET(j, "V", api_real(c, o->v));
    SET(j, "dV", api_real(c, o->dv));
    SET(j, "d2V", api_real(c, o->d2v));
    SET(j, "k_eff", api_real(c, o->k_eff));
    const int ok = o->stable;
    SET(j, "stable", json_boolean(ok));
    SET(j, "stability", json_string(ok ? "stable" : o->k_eff < 0 ? "unstable" : "marginal"));
    SET(j, "omega_r", ok ? api_real(c, o->omega_r) : json_null());
    SET(j, "period_r", ok ? api_real(c, 2 * MECH_PI / o->omega_r) : json_null());
    SET(j, "frequency_ratio", ok ? api_real(c, o->omega_r / o->omega_phi) : json_null());
    SET(j, "apsidal_angle", ok ? api_real(c, o->apsidal_angle) : json_null());
    SET(j, "apsidal_angle_deg", ok ? api_real(c, o->apsidal_angle * (180 / MECH_PI)) : json_null());
    SET(j, "pericentre_angle", ok ? api_real(c, 2 * o->apsidal_angle) : json_null());
    SET(j, "growth_rate", o->k_eff < 0 ? api_real(c, o->growth_rate) : json_null());
    SET(j, "residual", api_real(c, res));
    return j;
}

json_t *api_op_hamiltonian_circular_orbit(struct api_call *c, const json_t *body)
{
    const json_t *tj = json_object_get(body, "terms"), *gj = json_object_get(body, "gm");
    if (!tj && !gj) {
        api_call_invalid(c, "", "give the potential: terms, gm or both");
        return NULL;
    }
    const double mass = api_number_of(body, "mass"), l = api_number(body, "angular_momentum", 1);
    struct mech_potential_term t[16];
    size_t n = 0;
    for (size_t i = 0; i < json_array_size(tj) && n < 15; i++) {
        t[n].k = api_number(json_array_get(tj, i), "k", 0);
        t[n].n = api_number(json_array_get(tj, i), "n", 0);
        n++;
    }
    if (gj) {
        t[n].k = -json_number_value(gj) * mass;
        t[n].n = -1;
        if (!isfinite(t[n].k)) {
            api_call_domain(c, "/gm", "gm m overflows a double");
            return NULL;
        }
        n++;
    }
    struct mech_circular_orbits o;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_circular_orbits_for_l(t, n, mass, l, &o, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *arr = json_array();
    if (!out || !arr) {
        json_decref(out), json_decref(arr);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    SET(out, "count", json_integer((json_int_t)o.count));
    SET(out, "method", json_string(o.closed_form ? "closed_form" : "bracketed"));
    for (size_t i = 0; i < o.count; i++)
        json_array_append_new(arr, orbit_json(c, &o.orbit[i], o.radius[i], o.residual[i]));
    SET(out, "orbits", arr);
    if (o.count == 0)
        SET(out, "note",
            json_string(o.out_of_range
                            ? "m r^3 V'(r) = L^2 has a root only at a radius beyond what "
                              "doubles carry: no circular orbit is answered"
                            : "no circular orbit has this angular momentum: m r^3 V'(r) = L^2 "
                              "has no root with V' > 0 (the force is nowhere attractive "
                              "enough, or repulsive)"));
    if (n == 1) {
        json_t *b = json_object();
        const int closed = t[0].n == -1 || t[0].n == 2;
        SET(b, "n", api_real(c, t[0].n));
        SET(b, "all_bound_orbits_closed", json_boolean(closed));
        SET(b, "text",
            json_string(closed ? "Bertrand's theorem: for n = -1 (Kepler) and n = 2 (the "
                                 "isotropic oscillator) every bound orbit is closed"
                               : "Bertrand's theorem: only n = -1 and n = 2 close every bound "
                                 "orbit; here a near-circular orbit closes only when "
                                 "sqrt(n + 2) is rational, after as many radial periods as "
                                 "its denominator"));
        SET(out, "bertrand", b);
    }
    return out;
}
