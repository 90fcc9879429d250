/* term_estimate.c — the rule behind "fictitious": "auto" (mech/frames/trajectory.h,
 * mech_term_effect_estimate): the effect on positions and velocities of
 * leaving out a term whose acceleration is bounded, against the accuracy
 * asked for. Reusable by any scene that knows such a bound. */
#include "mech/frames/trajectory.h"

#include <math.h>
#include <stdio.h> /* snprintf only, for the reason text */
#include <string.h>

/* ---- modelling only what the scene requires --------------------------------
 * Model only what the scene requires (docs/design.md): estimate each fictitious term's effect on
 * the returned positions and velocities before integrating, keep only those
 * that matter at the accuracy asked for, say why for every one. */

void mech_term_effect_estimate(const char *term, double accel_bound, double T, double L, double V,
                               double target, double safety, struct mech_term_estimate *out)
{
    memset(out, 0, sizeof *out);
    out->term = term;
    out->applicable = 1;
    if (!(safety >= 1.0)) safety = 1.0;
    out->accel_bound = accel_bound;
    /* a term of size <= a over T moves r by <= a T^2/2 and v by <= a T */
    out->position_effect = 0.5 * accel_bound * T * T;
    out->velocity_effect = accel_bound * T;
    double rp = L > 0.0 ? out->position_effect / L : 0.0;
    double rv = V > 0.0 ? out->velocity_effect / V : 0.0;
    out->relative_effect = fmax(rp, rv);
    const double threshold = target / safety;
    if (!(L > 0.0) && !(V > 0.0)) {
        out->included = accel_bound > 0.0;
        snprintf(out->reason, sizeof out->reason,
                 out->included ? "the scene has no position or velocity scale: a non-zero term "
                                 "(%.3g m/s^2) is kept"
                               : "zero along the trajectory (%.3g m/s^2)",
                 accel_bound);
        return;
    }
    out->included = out->relative_effect > threshold;
    /* name the dominant of the two effects in the reason */
    const int by_velocity = rv > rp;
    const double eff = by_velocity ? out->velocity_effect : out->position_effect;
    const double scale = by_velocity ? V : L;
    const char *unit_s = by_velocity ? "m/s" : "m";
    snprintf(out->reason, sizeof out->reason,
             "estimated effect %.3g %s %s target %.3g x %.6g %s / safety %g (|a| <= %.3g m/s^2 "
             "over T = %.6g s: |a| T^2/2 = %.3g m, |a| T = %.3g m/s)",
             eff, unit_s, out->included ? ">" : "<=", target, scale, unit_s, safety, accel_bound,
             T, out->position_effect, out->velocity_effect);
}
