/* kinematics_compton.c — POST /v1/relativity/kinematics/compton: Compton
 * scattering of a photon off a particle (notes §3, problems 18, 19).
 * Energies, masses (unit/c²) and momenta (unit/c) are in `energy_unit`
 * (eV … TeV, default MeV; c = 1); particles are a name from the PDG 2024 table
 * (core/relativity/particles.c) or a mass. The numerics live in
 * core/relativity/kinematics.c; the readers and encoders the kinematics
 * operations share are api/ops/relativity/kin_request.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"
#include "ops/relativity/kin_request.h"

json_t *api_op_relativity_kinematics_compton(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    if (!api_kin_unit_of(c, body, &u)) return NULL;
    const json_t *je = json_object_get(body, "energy"), *jw = json_object_get(body, "wavelength");
    if (je && jw) api_call_invalid(c, "/wavelength", "give energy or wavelength, not both");
    if (!je && !jw) api_call_invalid(c, "", "give the photon's energy or wavelength");
    double theta = 0;
    int ha = api_kin_angle_of(c, body, "angle", "/angle", &theta);
    if (ha == 0) api_call_invalid(c, "", "give the scattering angle as angle or angle_deg");
    double m = 0;
    const json_t *jt = json_object_get(body, "target");
    int okm = 1;
    if (jt)
        okm = api_kin_mass_of(c, jt, "/target", u, &m);
    else
        m = mech_energy_convert(mech_particle_find("electron")->mass, MECH_MEV, u);
    if (!okm || c->problem != API_PROBLEM_NONE) return NULL;
    double hc = mech_energy_hc(u);
    double lambda = jw ? json_number_value(jw) : 0;
    double e = jw ? hc / lambda : json_number_value(je);
    if (!(m > 0)) {
        api_call_domain(c, "/target",
                        "the target must have a mass: a massless particle cannot be at rest");
        return NULL;
    }
    struct mech_kin_compton r;
    struct mech_error err;
    mech_error_clear(&err);
    enum mech_status st = mech_kin_compton(e, m, theta, &r, &err);
    if (st != MECH_OK) {
        if (!strcmp(err.param, "energy") && jw) snprintf(err.param, sizeof err.param, "wavelength");
        return api_call_fail_core(c, st, &err, "");
    }
    double lc = hc / m, dl = lc * r.one_minus_cos;
    if (!jw) lambda = hc / e;
    double lambda_out = jw ? lambda + dl : hc / r.energy_out;

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "target_mass", api_real(c, m));
    json_object_set_new_nocheck(res, "angle", api_real(c, theta));
    json_object_set_new_nocheck(res, "angle_deg", api_kin_deg_of(c, theta));
    json_t *in = json_object(), *sc = json_object(), *rc = json_object();
    json_object_set_new_nocheck(in, "energy", api_real(c, e));
    json_object_set_new_nocheck(in, "wavelength", api_real(c, lambda));
    json_object_set_new_nocheck(res, "incident", in);
    json_object_set_new_nocheck(sc, "energy", api_real(c, r.energy_out));
    json_object_set_new_nocheck(sc, "wavelength", api_real(c, lambda_out));
    json_object_set_new_nocheck(res, "scattered", sc);
    json_object_set_new_nocheck(res, "wavelength_shift", api_real(c, dl));
    json_object_set_new_nocheck(res, "compton_wavelength", api_real(c, lc));
    json_object_set_new_nocheck(rc, "kinetic_energy", api_real(c, r.recoil_kinetic));
    json_object_set_new_nocheck(rc, "energy", api_real(c, m + r.recoil_kinetic));
    json_object_set_new_nocheck(rc, "momentum", api_real(c, r.recoil_momentum));
    json_object_set_new_nocheck(rc, "angle", api_real(c, r.recoil_angle));
    json_object_set_new_nocheck(rc, "angle_deg", api_kin_deg_of(c, r.recoil_angle));
    json_object_set_new_nocheck(res, "recoil", rc);
    return api_kin_finish(c, res);
}
