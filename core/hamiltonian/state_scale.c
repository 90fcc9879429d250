/* state_scale.c — the smallest scale of a Hamiltonian state's components
 * (mech/hamiltonian/state_scale.h), with each degree of freedom's inertia read from
 * the tangent flow of dH/dp (mech_ham_rhs). */
#include <math.h>

#include "mech/hamiltonian/state_scale.h"

double mech_ham_state_scale(const struct mech_ham_system *s, const double *y0, double tau)
{
    const size_t n = (size_t)s->dof;
    double sc = INFINITY;
    for (size_t i = 0; i < n; i++) {
        /* d(q_i')/d(p_i) along the unit vector e_{p_i}: 1/M_i */
        double f[MECH_HAM_MAX_DIM], dv[MECH_HAM_MAX_DIM], ev[MECH_HAM_MAX_DIM] = {0};
        ev[n + i] = 1.0;
        double M = s->mass;
        if (mech_ham_rhs(s, y0, f, ev, dv, NULL) == MECH_OK && dv[i] > 0.0 && isfinite(dv[i]))
            M = 1.0 / dv[i];
        const double q = fabs(y0[i]), p = fabs(y0[n + i]);
        const double cand[4] = {q, p, tau * p / M, M * q / tau};
        for (int k = 0; k < 4; k++)
            if (cand[k] > 0.0 && isfinite(cand[k]) && cand[k] < sc) sc = cand[k];
    }
    return isfinite(sc) ? sc : 1.0;
}
