/* steady_motion.c — the spherical pendulum's conical motion and a central
 * power law's circular orbit at a given angle or radius
 * (mech/hamiltonian/steady_motion.h). */
#include <math.h>

#include "mech/base/constants.h"
#include "mech/hamiltonian/steady_motion.h"

int mech_ham_conical_motion(const struct mech_ham_system *s, double theta,
                            struct mech_ham_conical *out)
{
    if (s->kind != MECH_HAM_SPHERICAL_PENDULUM || !(theta > 0.0 && theta < 0.5 * MECH_PI)) return 0;
    const double wphi = sqrt(s->g / (s->length * cos(theta)));
    const double sn = sin(theta);
    out->theta = theta;
    out->phi_dot = wphi;
    out->p_phi = s->mass * s->length * s->length * sn * sn * wphi;
    out->has_period = wphi > 0.0;
    out->period = out->has_period ? 2.0 * MECH_PI / wphi : NAN;
    return 1;
}

int mech_ham_central_circular(const struct mech_ham_system *s, double r,
                              struct mech_ham_central_circular *out)
{
    const double Kn = s->strength * s->power;
    if (s->kind != MECH_HAM_CENTRAL || !(Kn > 0.0)) return 0;
    const double pc = sqrt(s->mass * Kn * pow(r, s->power + 2.0));
    out->r = r;
    out->p_phi = pc;
    out->period = 2.0 * MECH_PI * s->mass * r * r / pc;
    out->stable = s->power > -2.0;
    return 1;
}
