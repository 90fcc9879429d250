/* bench_calibrate_chooser.c — measures the constants of the chooser's model
 * (core/ode/chooser.c: it predicts each candidate's cost and error).
 *
 * For each scene class and candidate method it runs mech_trajectory_integrate
 * (the path the answers take) at three settings and two run lengths, and fits
 *   adaptive:   error = A tol^a span^b (>= F span^g, round-off),      evaluations = B span tol^-c
 *   fixed step: error = A (h/T)^a span^b,    evaluations = B span (h/T)^-1
 * (span = t_end / T in dynamical times T = sqrt(|r0| / |a0|), as the chooser
 * measures it), and the CPU seconds per right-hand-side evaluation. Errors are
 * max(relative position error, relative velocity error) over 101 samples,
 * against the exact reference (Kepler, oscillator) or a round-off run
 * (rk8pd at rtol 1e-14: the falling object with Coriolis).
 *
 * Output: one C initialiser line per (class, method), pasted into
 * core/ode/chooser_table.h with this program's name and the date. Run:
 *   ./build/bench_calibrate_chooser
 * It takes a few seconds; timings are CPU seconds of this machine.
 * With --presets it prints instead each preset's choice, CPU and achieved
 * error on the presets' particle scenes (no calibration); --floors the
 * round-off floors; --pendulum the Foucault pendulum's law
 * (core/frames/chooser_pendulum.c); --general the general class's rows on the
 * isotropic oscillator seen from a rotating frame. The scenes are
 * tests/chooser_scenes.h's.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/budget.h"
#include "mech/base/constants.h"
#include "mech/frames/trajectory.h"

#include "../tests/chooser_scenes.h"

#define NS 101

struct scene {
    const char *cls;
    struct mech_trajectory_problem p;
    struct mech_force f[2];
    double T;             /* dynamical time */
    double spans[2];      /* run lengths in T */
    int exact;            /* exact reference available */
    double S;             /* atol = rtol x S, the chooser's scale of the scene */
};

/* The calibration scenes are tests/chooser_scenes.h's (the tests that check
 * the model use the same definitions); here with the two run lengths. */
static void from_cs(struct scene *s, const struct chooser_scene *c, double orbits0,
                    double orbits1)
{
    memset(s, 0, sizeof *s);
    s->cls = c->cls;
    s->p = c->p;
    s->f[0] = c->f[0];
    s->T = c->T;
    s->S = c->S;
    s->exact = c->exact;
    s->spans[0] = orbits0 * c->period / c->T;
    s->spans[1] = orbits1 * c->period / c->T;
}

static void scene_kepler(struct scene *s)
{
    struct chooser_scene c;
    cs_kepler(&c, "kepler e=0.5", 0.5, 10); /* 10 and 1000 orbits */
    from_cs(s, &c, 10, 1000);
}

static void scene_osc(struct scene *s)
{
    struct chooser_scene c;
    cs_oscillator(&c, "oscillator", 10); /* 10 and 1e4 periods */
    from_cs(s, &c, 10, 10000);
}

static void scene_rotosc(struct scene *s)
{
    struct chooser_scene c;
    cs_rotating_oscillator(&c, "rotating oscillator", 10); /* 10 and 100 periods */
    from_cs(s, &c, 10, 100);
}

static void scene_fall(struct scene *s)
{
    struct chooser_scene c;
    cs_fall(&c, "falling object");
    /* the fall lasts sqrt(2) T whatever the height: one span, b = 0 */
    from_cs(s, &c, 1, 1);
}

struct meas {
    double err, evals, cpu;
    int ok;
};

static void sample_err(const struct mech_vec3 *r, const struct mech_vec3 *v,
                       const struct mech_vec3 *rr, const struct mech_vec3 *vr, size_t n, double *e)
{
    double dr = 0, dv = 0, sr = 0, sv = 0;
    for (size_t i = 0; i < n; i++) {
        dr = fmax(dr, mech_vec3_norm(mech_vec3_sub(r[i], rr[i])));
        dv = fmax(dv, mech_vec3_norm(mech_vec3_sub(v[i], vr[i])));
        sr = fmax(sr, mech_vec3_norm(rr[i]));
        sv = fmax(sv, mech_vec3_norm(vr[i]));
    }
    *e = fmax(dr / sr, dv / sv);
}

static struct mech_vec3 ref_r[NS], ref_v[NS];

static struct meas run(struct scene *s, double span, const char *method, double x, int adaptive,
                       size_t ns)
{
    struct meas m = {0, 0, 0, 0};
    struct mech_trajectory_problem p = s->p;
    p.forces = s->f;
    p.n_forces = 1;
    p.t_end = span * s->T;
    p.samples = ns;
    p.reduce_planar = 1;
    p.method = method;
    if (adaptive) {
        p.opt.rtol = x;
        p.opt.atol = x * s->S;
    } else {
        p.opt.dt = x * s->T;
    }
    static struct mech_vec3 r[NS], v[NS];
    static double t[NS];
    struct mech_trajectory_result res;
    memset(&res, 0, sizeof res);
    res.t = t;
    res.position = r;
    res.velocity = v;
    struct mech_budget b = {200000000L, mech_clock_seconds() + 60.0, NULL};
    struct mech_error e;
    mech_error_clear(&e);
    double c0 = mech_cpu_seconds();
    enum mech_status st = mech_trajectory_integrate(&p, &b, &res, &e);
    m.cpu = mech_cpu_seconds() - c0;
    if (st != MECH_OK) {
        fprintf(stderr, "%s %s %g: %s\n", s->cls, method, x, e.text);
        return m;
    }
    m.evals = (double)res.stats.rhs_evaluations;
    if (s->exact) {
        m.err = fmax(res.reference.max_relative_position_error,
                     res.reference.max_relative_velocity_error);
    } else {
        sample_err(r, v, ref_r, ref_v, res.n_samples, &m.err);
    }
    m.err = fmax(m.err, 1e-17);
    m.ok = 1;
    return m;
}

static void make_reference(struct scene *s)
{
    struct mech_trajectory_problem p = s->p;
    p.forces = s->f;
    p.n_forces = 1;
    p.t_end = s->spans[0] * s->T;
    p.samples = NS;
    p.reduce_planar = 1;
    p.method = "rk8pd";
    p.opt.rtol = 1e-14;
    p.opt.atol = 1e-14;
    static double t[NS];
    struct mech_trajectory_result res;
    memset(&res, 0, sizeof res);
    res.t = t;
    res.position = ref_r;
    res.velocity = ref_v;
    struct mech_budget b = {200000000L, mech_clock_seconds() + 60.0, NULL};
    struct mech_error e;
    if (mech_trajectory_integrate(&p, &b, &res, &e) != MECH_OK) {
        fprintf(stderr, "reference: %s\n", e.text);
        exit(1);
    }
}

/* least squares of y = c0 + c1 x (n points) */
static void fit(const double *x, const double *y, int n, double *c0, double *c1)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    double d = n * sxx - sx * sx;
    *c1 = d != 0 ? (n * sxy - sx * sy) / d : 0;
    *c0 = (sy - *c1 * sx) / n;
}

struct method {
    const char *name;
    int adaptive;
    double x[4]; /* tolerances or h/T, loosest first */
};

/* The round-off floor F span^g of the class: radau15 at eps 1e-9 (its
 * floor) over both spans (one span: g = 1.5). */
static double floor_of(struct scene *s, double *g)
{
    struct meas m0 = run(s, s->spans[0], "radau15", 1e-9, 1, NS);
    *g = 1.5;
    if (s->spans[1] > s->spans[0]) {
        struct meas m1 = run(s, s->spans[1], "radau15", 1e-9, 1, NS);
        *g = log(m1.err / m0.err) / log(s->spans[1] / s->spans[0]);
    }
    return m0.err / pow(s->spans[0], *g);
}

static void calibrate(struct scene *s, const struct method *md, double F, double g)
{
    struct meas m[4], ml;
    double lx[4], le[4], lc[4], lxc[4];
    int n = 0, nc = 0;
    double cpu = 0, ev = 0, per_sample = 0;
    const double fl0 = F * pow(s->spans[0], g);
    for (int i = 0; i < 4; i++) {
        m[i] = run(s, s->spans[0], md->name, md->x[i], md->adaptive, NS);
        struct meas c2 = run(s, s->spans[0], md->name, md->x[i], md->adaptive, 2);
        if (!m[i].ok || !c2.ok) return;
        per_sample = fmax(per_sample, (m[i].evals - c2.evals) / (NS - 2));
        lxc[nc] = log(md->x[i]);
        lc[nc++] = log(fmax(c2.evals, 1.0) / s->spans[0]);
        cpu += c2.cpu;
        ev += c2.evals;
        if (m[i].err > 10 * fl0) {
            lx[n] = log(md->x[i]);
            le[n++] = log(m[i].err);
        }
    }
    double la = log(fl0), a = 0, lb, c;
    if (n >= 2) fit(lx, le, n, &la, &a);
    else if (n == 1) la = le[0], a = 0;
    fit(lxc, lc, nc, &lb, &c);
    double b = 0;
    if (s->spans[1] > s->spans[0] && n >= 1) {
        /* the setting above the floor whose error is nearest 1e-8 (the
         * longer run's error must not saturate at O(1)), over the longer span */
        int k = 0;
        for (int i = 1; i < n; i++)
            if (fabs(le[i] - log(1e-8)) < fabs(le[k] - log(1e-8))) k = i;
        double x = exp(lx[k]);
        ml = run(s, s->spans[1], md->name, x, md->adaptive, NS);
        if (!ml.ok) return;
        double e0 = exp(le[k]);
        b = log(ml.err / e0) / log(s->spans[1] / s->spans[0]);
    }
    double A = exp(la) / pow(s->spans[0], b);
    /* the method's own floor: its tightest setting over the longer span,
     * when that is above what the power law predicts (round-off of a
     * method without compensated summation) */
    double Fm = F;
    if (s->spans[1] > s->spans[0]) {
        struct meas mt = run(s, s->spans[1], md->name, md->x[3], md->adaptive, NS);
        double law = A * pow(md->x[3], a) * pow(s->spans[1], b);
        if (mt.ok && mt.err > 3.0 * law) Fm = fmax(F, mt.err / pow(s->spans[1], g));
    }
    printf("    {\"%s\", \"%s\", %.3g, %.3f, %.3f, %.3g, %.3f, %.3g, %.3g, %.3g, %.3f, %.3g},\n"
           "    /* errors %.2g %.2g %.2g %.2g at x = %g %g %g %g (span %.4g); fitted on %d */\n",
           s->cls, md->name, A, a, b, exp(lb), -c, per_sample, ev > 0 ? cpu / ev : 0, F, g, Fm,
           m[0].err, m[1].err, m[2].err, m[3].err, md->x[0], md->x[1], md->x[2], md->x[3],
           s->spans[0], n);
}

/* --presets: each preset on the presets' particle scenes through
 * mech_trajectory_choose + mech_trajectory_integrate: method, CPU (best of
 * 3), achieved error, and the machine/draft and machine/balanced ratios. */
static void presets_table(void)
{
    static struct scene sc[6];
    const double es[4] = {0.5, 0.9, 0.5, 0.9}, orb[4] = {10, 10, 1000, 1000};
    for (int k = 0; k < 4; k++) {
        scene_kepler(&sc[k]);
        const double e = es[k];
        sc[k].p.position = mech_vec3_make(1.0 - e, 0, 0);
        sc[k].p.velocity = mech_vec3_make(0, sqrt((1.0 + e) / (1.0 - e)), 0);
        sc[k].T = sqrt(pow(1.0 - e, 3.0));
        sc[k].spans[0] = orb[k] * 2 * MECH_PI / sc[k].T;
    }
    scene_osc(&sc[4]);
    sc[4].spans[0] = 1e4 * 2 * MECH_PI;
    scene_fall(&sc[5]);
    sc[5].p.fictitious = MECH_FICTITIOUS_CORIOLIS;
    make_reference(&sc[5]);
    const char *names[6] = {"kepler e=0.5 10", "kepler e=0.9 10", "kepler e=0.5 1000",
                            "kepler e=0.9 1000", "oscillator 1e4", "falling Coriolis"};
    printf("%-18s %-8s %-8s %10s %10s %10s\n", "scene", "preset", "method", "cpu_s", "error",
           "predicted");
    for (int k = 0; k < 6; k++) {
        double cpu[MECH_ACCURACY_COUNT];
        for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
            const struct mech_accuracy_preset *pr = mech_accuracy_preset_at((enum mech_accuracy)a);
            struct mech_trajectory_problem p = sc[k].p;
            p.forces = sc[k].f;
            p.n_forces = 1;
            p.t_end = sc[k].spans[0] * sc[k].T;
            p.samples = NS;
            p.reduce_planar = 1;
            static struct mech_trajectory_choice ch;
            if (mech_trajectory_choose(&p, pr->promise, &ch, NULL) != MECH_OK) continue;
            struct meas best = {0, 0, 1e300, 0};
            for (int rep = 0; rep < 3; rep++) {
                struct meas m = run(&sc[k], sc[k].spans[0], ch.method,
                                    ch.sel.c[ch.sel.chosen].adaptive ? ch.opt.rtol
                                                                     : ch.opt.dt / sc[k].T,
                                    ch.sel.c[ch.sel.chosen].adaptive, NS);
                if (m.ok && m.cpu < best.cpu) best = m;
            }
            cpu[a] = best.cpu;
            printf("%-18s %-8s %-8s %10.3g %10.2g %10.2g%s\n", names[k], pr->name, ch.method,
                   best.cpu, best.err, ch.sel.c[ch.sel.chosen].predicted_error,
                   ch.sel.beyond ? " beyond" : "");
        }
        printf("%-18s machine/draft %.2f, machine/balanced %.2f\n", names[k],
               cpu[MECH_ACCURACY_MACHINE] / fmax(cpu[MECH_ACCURACY_DRAFT], 1e-9),
               cpu[MECH_ACCURACY_MACHINE] / fmax(cpu[MECH_ACCURACY_BALANCED], 1e-9));
    }
}

/* --floors: the round-off floor of the Kepler class against eccentricity
 * (the chooser's floor model, core/ode/chooser.c ecc_floor_factor): radau15 at
 * eps 1e-9 and 2e-9 (its floor; two settings give two round-off histories)
 * and rk8pd at rtol 1e-13, over 10, 100 and 1000 orbits from pericentre, each
 * error divided by the e = 0.5 class floor Fm span^g of chooser_table.h. */
static void floors_table(void)
{
    const double es[] = {0.0, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95}, orb[] = {10, 100, 1000};
    const double F = 7.24e-16, g = 1.098; /* the central_gravity row's */
    printf("%-5s %-6s %10s %10s %10s %10s  %s\n", "e", "orbits", "span", "radau 1e-9",
           "radau 2e-9", "rk8pd 1e-13", "worst / (F span^g)");
    for (size_t i = 0; i < sizeof es / sizeof *es; i++)
        for (size_t k = 0; k < sizeof orb / sizeof *orb; k++) {
            struct scene s;
            scene_kepler(&s);
            const double e = es[i];
            s.p.position = mech_vec3_make(1.0 - e, 0, 0);
            s.p.velocity = mech_vec3_make(0, sqrt((1.0 + e) / (1.0 - e)), 0);
            s.T = sqrt(pow(1.0 - e, 3.0));
            s.S = fmin(1.0 - e, sqrt((1.0 + e) / (1.0 - e)));
            const double span = orb[k] * 2 * MECH_PI / s.T;
            struct meas m1 = run(&s, span, "radau15", 1e-9, 1, NS);
            struct meas m2 = run(&s, span, "radau15", 2e-9, 1, NS);
            struct meas m3 = run(&s, span, "rk8pd", 1e-13, 1, NS);
            const double worst = fmax(m1.err, m2.err);
            printf("%-5.2f %-6.0f %10.4g %10.2g %10.2g %10.2g  %.2f\n", e, orb[k], span, m1.err,
                   m2.err, m3.err, worst / (F * pow(span, g)));
            fflush(stdout);
        }
    /* the oscillator: an ellipse (1, 0.5) and a circle, 10 .. 1e4 periods */
    const double Fo = 4.03e-17, go = 1.097; /* the oscillator row's */
    const double vy[] = {0.5, 1.0}, per[] = {10, 100, 1000, 10000};
    for (size_t i = 0; i < 2; i++)
        for (size_t k = 0; k < 4; k++) {
            struct scene s;
            scene_osc(&s);
            s.p.velocity = mech_vec3_make(0, vy[i], 0);
            const double span = per[k] * 2 * MECH_PI;
            struct meas m1 = run(&s, span, "radau15", 1e-9, 1, NS);
            struct meas m2 = run(&s, span, "radau15", 2e-9, 1, NS);
            const double worst = fmax(m1.err, m2.err);
            printf("osc v=%-4.1f %-6.0f %10.4g %10.2g %10.2g %10s  %.2f (span^1.5: %.3g)\n", vy[i],
                   per[k], span, m1.err, m2.err, "-", worst / (Fo * pow(span, go)),
                   worst / pow(span, 1.5));
            fflush(stdout);
        }
}

/* --pendulum: the Foucault pendulum's law (core/frames/chooser_pendulum.c): for
 * rattle (p = 2) and rattle_yoshida4 (p = 4) at several steps per swing n,
 * latitudes 32 .. 80 deg, amplitudes 3 .. 30 deg, 100 and 1000 swings, the
 * error max(|period - ref| / ref, |rate - ref| / W) against
 * rattle_yoshida4 at 12800 steps per swing, divided by (2 pi / n)^p
 * (1 + 3 alpha^2): the constant C (its largest value is the table's), and
 * the CPU seconds per force evaluation. Points within 30x of the round-off
 * floor are left out. */
static void pendulum_table(void)
{
    static const double lats[] = {32, 45, 80}, amps[] = {3, 10, 30}, swings[] = {100, 1000};
    static const double ns[2][4] = {{160, 320, 640, 1280}, {20, 40, 80, 160}};
    const enum mech_pendulum_method ms[2] = {MECH_PENDULUM_RATTLE, MECH_PENDULUM_RATTLE_YOSHIDA4};
    double cmax[2] = {0, 0}, cmin[2] = {INFINITY, INFINITY}, cpu[2] = {0, 0}, ev[2] = {0, 0};
    printf("%-5s %-5s %-6s %-16s %7s %10s %10s\n", "lat", "amp", "swings", "method", "n",
           "error", "C");
    for (size_t i = 0; i < 3; i++)
        for (size_t j = 0; j < 3; j++)
            for (size_t k = 0; k < 2; k++) {
                if (j > 0 && i != 1) continue; /* amplitudes at 45 deg only */
                static struct mech_foucault_result ref, r;
                if (!cs_foucault_run(lats[i], amps[j], swings[k], MECH_PENDULUM_RATTLE_YOSHIDA4,
                                     12800, &ref))
                    continue;
                const double alpha = amps[j] * MECH_PI / 180;
                const double fl = fmax(1e-14, 1e-13 / (MECH_EARTH_OMEGA_SIDEREAL * ref.swings *
                                                       ref.period));
                for (int m = 0; m < 2; m++)
                    for (int q = 0; q < 4; q++) {
                        const double c0 = mech_cpu_seconds();
                        if (!cs_foucault_run(lats[i], amps[j], swings[k], ms[m], ns[m][q], &r))
                            continue;
                        cpu[m] += mech_cpu_seconds() - c0;
                        ev[m] += (double)r.force_evaluations;
                        const double e = cs_foucault_err(&r, &ref);
                        const double C = e / (pow(2 * MECH_PI / ns[m][q], m ? 4 : 2) *
                                              (1 + 3 * alpha * alpha));
                        printf("%-5.0f %-5.0f %-6.0f %-16s %7.0f %10.2e %10.3g%s\n", lats[i],
                               amps[j], swings[k], mech_pendulum_method_name(ms[m]), ns[m][q], e,
                               C, e > 30 * fl ? "" : " (near the floor: left out)");
                        if (e > 30 * fl) {
                            cmax[m] = fmax(cmax[m], C);
                            cmin[m] = fmin(cmin[m], C);
                        }
                    }
                fflush(stdout);
            }
    for (int m = 0; m < 2; m++)
        printf("%s: C in [%.3g, %.3g], CPU per force evaluation %.3g s\n",
               mech_pendulum_method_name(ms[m]), cmin[m], cmax[m], ev[m] > 0 ? cpu[m] / ev[m] : 0);
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "--pendulum")) {
        pendulum_table();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "--presets")) {
        presets_table();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "--floors")) {
        floors_table();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "--general")) {
        /* the general class's own rows: the oscillator seen from a rotating
         * frame (no yoshida6: Coriolis depends on the velocity) */
        static struct scene g;
        scene_rotosc(&g);
        static const struct method gm[] = {
            {"radau15", 1, {1e-2, 1e-3, 1e-4, 1e-6}}, {"rk8pd", 1, {1e-5, 1e-7, 1e-9, 1e-12}},
            {"rkf45", 1, {1e-4, 1e-6, 1e-8, 1e-10}},  {"msbdf", 1, {1e-4, 1e-6, 1e-8, 1e-10}},
            {"gauss6", 0, {0.2, 0.1, 0.05, 0.025}},
        };
        double gg, F = floor_of(&g, &gg);
        for (size_t j = 0; j < sizeof gm / sizeof gm[0]; j++) calibrate(&g, &gm[j], F, gg);
        return 0;
    }
    static struct scene sc[3];
    scene_kepler(&sc[0]);
    scene_osc(&sc[1]);
    scene_fall(&sc[2]);
    make_reference(&sc[2]);
    static const struct method ms[] = {
        {"radau15", 1, {1e-2, 1e-3, 1e-4, 1e-6}},
        {"rk8pd", 1, {1e-5, 1e-7, 1e-9, 1e-12}},
        {"rkf45", 1, {1e-4, 1e-6, 1e-8, 1e-10}},
        {"msbdf", 1, {1e-4, 1e-6, 1e-8, 1e-10}},
        {"gauss6", 0, {0.2, 0.1, 0.05, 0.025}},
        {"yoshida6", 0, {0.2, 0.1, 0.05, 0.025}},
    };
    printf("/* bench_calibrate_chooser: {class, method, A, a, b, B, c, evals_per_sample,\n"
           " * cpu_per_eval_s, F, g, Fm} with error = max(A x^a span^b, Fm span^g),\n"
           " * evaluations = B span x^-c + evals_per_sample samples (x = tol or h/T) */\n");
    for (int k = 0; k < 3; k++) {
        double g, F = floor_of(&sc[k], &g);
        for (size_t j = 0; j < sizeof ms / sizeof ms[0]; j++) {
            if (!strcmp(sc[k].cls, "uniform_field") && !strcmp(ms[j].name, "yoshida6")) continue;
            calibrate(&sc[k], &ms[j], F, g);
        }
    }
    return 0;
}
