/* mech/answers/gr/geodesic_run.h — one POST /v1/gr/geodesic run after its set-up
 * (mech/answers/gr/geodesic_setup.h): the integration (mech_geodesic_integrate) into
 * sample arrays it allocates, the motion's name, and the references the
 * measured periapsis advance and light deflection are shown beside: the
 * weak-field advance 6 pi GM/(c^2 a (1 - e^2)), the deflection by quadrature
 * and by Byrd & Friedman's elliptic form with its precision, 4GM/(c^2 b) and
 * the second order 4/b + 15 pi/(4 b^2) (Hartle §9.3, §11.1; Carroll §5.6).
 * Geometric units (M = 1) throughout; the caller converts. Thread-safe. */
#ifndef MECH_GEODESIC_RUN_H
#define MECH_GEODESIC_RUN_H

#include "mech/base/budget.h"
#include "mech/answers/gr/geodesic_setup.h"
#include "mech/base/status.h"

struct mech_geodesic_answer {
    /* the run: result.param/t/r/phi are arrays of problem.samples doubles owned
     * by the answer (free with mech_geodesic_answer_free), filled up to
     * result.n_samples, geometric units */
    struct mech_geodesic_result result;
    int integrated;      /* 1 once the integration succeeded (a later failure is a reference's) */
    const char *motion;  /* timelike: mech_geodesic_class_name; light: "scatter" (b > 3 sqrt 3,
                            outside the photon sphere, inward), "escape" or "capture" */
    int scatter;         /* light that turns outside the photon sphere: deflection computed */
    double advance_first_order; /* bound: 6 pi/(a(1 - e^2)) = 3 pi (u1 + u2), rad (NaN) */
    double deflection_exact;    /* scatter: quadrature without cancellation, rad (NaN) */
    double deflection_elliptic; /* scatter: elliptic form, ends in "- pi" (NaN) */
    double elliptic_precision;  /* scatter: its relative precision ~4e-16 pi / delta (NaN) */
    double closest_approach;    /* scatter: r_min, GM/c^2 (NaN) */
    double deflection_first_order;  /* scatter: 4/b (NaN) */
    double deflection_second_order; /* scatter: 4/b + 15 pi/(4 b^2) (NaN) */
};

/* Run `p` (a mech_geodesic_setup's problem with method and opt set by the
 * caller) and measure it against the references of `s`. budget is mandatory.
 * Statuses: EINVAL "samples" (more than SIZE_MAX / sizeof(double): the
 * arrays' size would overflow; fewer than 2 is mech_geodesic_integrate's);
 * those of mech_geodesic_integrate (EINVAL, EBUDGET, EDEADLINE,
 * ECANCELLED, ENUMERIC "constraint_bound" with result.n_samples and
 * result.stats kept, ENOMEM), with integrated = 0; after a successful
 * integration, those of mech_geodesic_deflection_exact / _quadrature
 * (EDOMAIN/ENUMERIC "impact_parameter", ENUMERIC, ENOMEM) with integrated = 1.
 * out is always initialised; the caller frees it with mech_geodesic_answer_free
 * on every path. err may be NULL. */
enum mech_status mech_geodesic_run(const struct mech_geodesic_setup *s,
                                   const struct mech_geodesic_problem *p,
                                   const struct mech_budget *budget,
                                   struct mech_geodesic_answer *out, struct mech_error *err);

/* Free the answer's arrays (NULL-safe, idempotent). */
void mech_geodesic_answer_free(struct mech_geodesic_answer *a);

/* The chooser's pilot hook (mech/ode/chooser_pilot.h) for geodesics in strong
 * field, where the table's first-order cost law (fitted on Mercury's weak
 * field) is least certain. mech_geodesic_pilot_applies: 1 for a bound orbit
 * whose periapsis is within MECH_GEODESIC_PILOT_STRONG_R (GM/c^2) or a motion
 * that is not bound, else 0. mech_geodesic_pilot_run is struct
 * mech_pilot_system's run with ctx = a const struct mech_geodesic_problem *
 * (the run's; its samples, method, opt and look-ahead ignored): the geodesic
 * over the first `fraction` of param_end, two samples, no periapsis
 * look-ahead; y_end = (r, phi, t) at the end (geometric units), *dim = 3.
 * Statuses as mech_geodesic_integrate; MECH_EDOMAIN when the pilot is
 * captured or escapes (its rate is then no guide). */
#define MECH_GEODESIC_PILOT_STRONG_R 100.0

/* The chooser's profile of light that scatters (mech/ode/chooser.h): its error
 * gain over the first-order calibration and its run in the cost law's
 * units. Light that passes close to the photon sphere winds around it and
 * every error grows about e-fold per radian of the winding: measured with
 * rk8pd at rtol 1e-6 .. 1e-12 against the exact deflection, the relative
 * error of the deflection is 0.1 .. 5x the first-order law at b = 5.3 .. 100
 * (deflection 3.6 .. 0.04 rad), 8 .. 16x at b = 5.22 (5.0 rad), 34 .. 69x
 * at b = 5.2 (6.8 rad): gain = 2 max(1, e^(delta - 3.3)), delta the exact
 * deflection (mech_geodesic_deflection_quadrature). The evaluations of a
 * scattering ray from r0 = 100 b (at least 1000) hardly depend on b (rk8pd at
 * 1e-8: 940 .. 1160 for b = 5.2 .. 100), 7 .. 9x the first-order law at
 * the ray's span: cost_span = 8 span. b in GM/c^2; for light that does
 * not scatter (captured, b <= 3 sqrt 3) gain 1 and cost_span = span. */
double mech_geodesic_error_gain(double b);
#define MECH_GEODESIC_SCATTER_COST_FACTOR 8.0
int mech_geodesic_pilot_applies(const struct mech_geodesic_setup *s);
enum mech_status mech_geodesic_pilot_run(void *ctx, const char *method,
                                         const struct mech_ode_options *opt, double fraction,
                                         const struct mech_budget *budget,
                                         struct mech_ode_stats *stats, double *y_end,
                                         size_t *dim, struct mech_error *err);

#endif
