/* bench_closed_form.c — what the closed form costs against the preset that
 * would integrate the same scene ("cost then grows with the
 * samples, not with the orbits").
 *
 * Scenes (201 samples): Kepler GM = a = 1, e = 0.5 and 0.9 from pericentre,
 * 10 and 1000 orbits; the oscillator k = m = 1, 1e4 periods. For each: thread
 * CPU of mech_trajectory_closed_form_ex (best of 5) and of
 * mech_trajectory_integrate at the "machine" choice of mech_trajectory_choose
 * (one run), the integration's error against the exact reference, and the
 * ratio integrate / closed form from the same run.
 * Measures, never asserts: exits 0 whatever the figures (1 if a run fails).
 * Not part of the tests. Usage: bench_closed_form
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "mech/frames/closed_form.h"
#include "mech/base/constants.h"

static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#define NS 201
static struct mech_vec3 R[NS], V[NS];
static double T[NS];

int main(void)
{
    const double PI = MECH_PI;
    struct mech_force kep = {.type = MECH_FORCE_CENTRAL_GRAVITY}, spr = {.type = MECH_FORCE_SPRING};
    kep.u.central_gravity.gm = 1.0;
    spr.u.spring.k = 1.0;
    printf("# bench_closed_form: closed form vs the machine preset, %d samples, thread CPU\n", NS);
    printf("%-28s %12s %8s %10s %14s %12s %10s\n", "scene", "closed_ms", "evals", "stated_err",
           "machine", "machine_ms", "ratio");
    for (int sc = 0; sc < 5; sc++) {
        struct mech_trajectory_problem p;
        memset(&p, 0, sizeof p);
        p.mass = 1.0;
        p.samples = NS;
        p.reduce_planar = 1;
        char name[64];
        if (sc < 4) {
            const double e = sc < 2 ? 0.5 : 0.9, q = 1 - e, orbits = sc % 2 ? 1000 : 10;
            p.forces = &kep;
            p.n_forces = 1;
            p.position = mech_vec3_make(q, 0, 0);
            p.velocity = mech_vec3_make(0, sqrt((1 + e) / q), 0);
            p.t_end = orbits * 2 * PI;
            snprintf(name, sizeof name, "Kepler e=%g, %g orbits", e, orbits);
        } else {
            p.forces = &spr;
            p.n_forces = 1;
            p.position = mech_vec3_make(1, 0, 0);
            p.velocity = mech_vec3_make(0, 1, 0);
            p.t_end = 1e4 * 2 * PI;
            snprintf(name, sizeof name, "oscillator, 1e4 periods");
        }
        struct mech_trajectory_result r;
        memset(&r, 0, sizeof r);
        r.t = T;
        r.position = R;
        r.velocity = V;
        struct mech_error err;
        mech_error_clear(&err);
        struct mech_closed_form_evidence ev;
        double best = INFINITY;
        for (int k = 0; k < 5; k++) {
            const double c0 = cpu();
            if (mech_trajectory_closed_form_ex(&p, &r, &ev, NULL, &err) != MECH_OK) {
                fprintf(stderr, "%s: %s\n", name, err.text);
                return 1;
            }
            best = fmin(best, cpu() - c0);
        }
        struct mech_trajectory_choice ch;
        mech_trajectory_choose(&p, mech_accuracy_preset_at(MECH_ACCURACY_MACHINE)->promise, &ch,
                               &err);
        p.method = ch.method;
        p.opt = ch.opt;
        struct mech_budget b = mech_budget_make(100000000, 600.0);
        struct mech_trajectory_result r2;
        memset(&r2, 0, sizeof r2);
        const double c0 = cpu();
        if (mech_trajectory_integrate(&p, &b, &r2, &err) != MECH_OK) {
            fprintf(stderr, "%s: %s\n", name, err.text);
            return 1;
        }
        const double ci = cpu() - c0;
        char mcol[40];
        snprintf(mcol, sizeof mcol, "%s %.1e", ch.method, r2.reference.max_relative_position_error);
        printf("%-28s %12.4f %8d %10.2g %14s %12.2f %10.0f\n", name, best * 1e3, ev.evaluations,
               ev.error_bound, mcol, ci * 1e3, ci / best);
    }
    return 0;
}
