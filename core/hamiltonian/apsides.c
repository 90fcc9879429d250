/* apsides.c — pericentres of a central orbit as upward p_r = 0 crossings
 * (mech_poincare_run on the section of coordinate index 2, the momentum p_r)
 * and the measured apsidal angle beside pi/sqrt(n + 2) (mech/hamiltonian/apsides.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/hamiltonian/apsides.h"
#include "mech/base/constants.h"
#include "mech/hamiltonian/poincare.h"

enum mech_status mech_apsides_find(const struct mech_ham_system *s, const double *y0, double t_end,
                                   const struct mech_integrator *method,
                                   struct mech_ode_options opt, const struct mech_budget *budget,
                                   long steps_used, struct mech_apsides *out,
                                   struct mech_error *err)
{
    enum { MAXP = MECH_APSIDES_MAX };
    memset(out, 0, sizeof *out);
    out->angle_measured = out->angle_near_circular = NAN;
    if (s->kind != MECH_HAM_CENTRAL)
        return mech_error_set(err, MECH_EINVAL, "system", "apsides are for a central potential");
    if (y0[3] == 0.0) {
        out->radial = 1;
        return MECH_OK;
    }
    double *buf = malloc(7 * MAXP * sizeof *buf);
    if (!buf) return mech_error_set(err, MECH_ENOMEM, NULL, "out of memory for the apsides");
    /* the section: component 2 of the state (p_r) = 0, upwards */
    struct mech_poincare_problem pp = {s, {2, 0.0, 0}, y0, t_end, MAXP, method, opt};
    struct mech_poincare_result pr;
    memset(&pr, 0, sizeof pr);
    pr.t = buf;
    pr.u = buf + MAXP;
    pr.v = buf + 2 * MAXP;
    pr.y = buf + 3 * MAXP;
    struct mech_budget b = *budget; /* what the flow left */
    b.max_steps -= steps_used;
    enum mech_status st = b.max_steps > 0
                              ? mech_poincare_run(&pp, &b, &pr, err)
                              : mech_error_set(err, MECH_EBUDGET, NULL,
                                               "the step budget is exhausted before the apsides "
                                               "are located");
    if (st != MECH_OK) {
        free(buf);
        return st;
    }
    const size_t n = pr.n_crossings;
    /* the three arrays live in buf's first 3 n slots: t, then r and phi copied down */
    for (size_t k = 0; k < n; k++) {
        buf[MAXP + k] = pr.y[4 * k];
        buf[2 * MAXP + k] = pr.y[4 * k + 1];
    }
    out->n = n;
    out->t = buf;
    out->r = buf + MAXP;
    out->phi = buf + 2 * MAXP;
    out->has_measured = n >= 2;
    if (n >= 2) out->angle_measured = (out->phi[n - 1] - out->phi[0]) / (2.0 * (double)(n - 1));
    out->has_near_circular = s->power > -2.0;
    if (out->has_near_circular) out->angle_near_circular = MECH_PI / sqrt(s->power + 2.0);
    return MECH_OK;
}

void mech_apsides_free(struct mech_apsides *a)
{
    free(a->t); /* one block: t, r and phi */
    a->t = a->r = a->phi = NULL;
    a->n = 0;
}
