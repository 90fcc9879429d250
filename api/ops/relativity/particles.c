/* particles.c — GET /v1/relativity/particles: the particle table the
 * kinematics operations take names from (core/relativity/particles.c, PDG
 * 2024 masses in MeV/c²). */
#include "run/endpoint.h"
#include "mech/relativity/particles.h"

json_t *api_op_relativity_particles(struct api_call *c, const json_t *body)
{
    (void)body;
    json_t *list = json_array();
    for (size_t i = 0; list && i < mech_particle_count(); i++) {
        const struct mech_particle *p = mech_particle_at(i);
        json_array_append_new(list, json_pack("{s:s,s:o,s:s}", "name", p->name, "mass_mev",
                                              api_real(c, p->mass), "source", p->source));
    }
    return json_pack("{s:s,s:s,s:o}", "edition", MECH_PARTICLE_EDITION, "mass_unit", "MeV/c^2",
                     "particles", list);
}
