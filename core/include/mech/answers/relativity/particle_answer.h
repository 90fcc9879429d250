/* mech/answers/relativity/particle_answer.h — one POST /v1/relativity/particle answer, from
 * the request as read to everything the answer states: the energy unit, the
 * particle's mass (a name from the table of mech/relativity/particles.h, or a number),
 * its state of motion from the one quantity given (mech/relativity/particle_state.h)
 * and, for an unstable particle, its lifetime in the lab. The API's handler
 * parses, calls mech_particle_answer() once and encodes.
 *
 * Units: natural (c = 1): mass, energies and momentum in the request's
 * energy unit; lifetimes in s, lengths in m. Pure; thread-safe; no
 * allocation. */
#ifndef MECH_PARTICLE_ANSWER_H
#define MECH_PARTICLE_ANSWER_H

#include "mech/relativity/particle_state.h"
#include "mech/relativity/particles.h"
#include "mech/base/status.h"

struct mech_particle_request {
    const char *energy_unit;        /* "eV", "keV", "MeV", "GeV" or "TeV" (borrowed) */
    const char *particle;           /* a name of mech/relativity/particles.h's table (borrowed), or
                                       NULL: the mass below */
    double mass;                    /* energy_unit/c², >= 0 (particle == NULL) */
    enum mech_particle_given given; /* the one quantity of motion given */
    double value;                   /* its number, in energy_unit where it is an energy */
    int has_proper_lifetime;        /* 1: the lifetime block is wanted */
    double proper_lifetime;         /* τ, s, > 0 */
};

struct mech_particle_answer {
    enum mech_energy_unit unit;
    struct mech_particle_state state;
    int has_lifetime;                       /* has_proper_lifetime of the request */
    struct mech_particle_lifetime lifetime; /* τ, cτ, γτ, βγcτ */
    double lab_c_tau;                       /* c γτ, m */
};

/* Compute *out for request q. Statuses, err->param naming the request's field:
 *   MECH_EINVAL (no param) for a NULL pointer;
 *   MECH_EINVAL "energy_unit" for an unknown unit;
 *   MECH_EINVAL "particle" for a name not in the table ("unknown particle
 *     name \"...\"");
 *   mech_particle_state_from's statuses, its param "mass" reported as
 *     "particle" (a negative mass; a massless particle given a velocity
 *     form), the others at the quantity's name ("beta", "energy", ...);
 *   MECH_EDOMAIN "proper_lifetime" (τ <= 0 or not finite) or "particle" (a
 *     massless particle has no proper time).
 * out is written only on success. err may be NULL. */
enum mech_status mech_particle_answer(const struct mech_particle_request *q,
                                      struct mech_particle_answer *out, struct mech_error *err);

#endif
