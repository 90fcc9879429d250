/* bench_chooser_regret.c — the chooser and the presets against mechd's own
 * methods in hindsight, GSL called directly and SciPy's solve_ivp, on one
 * scene of each class, in one run (never a test: it prints and plots,
 * asserts nothing).
 *
 * For each scene (central gravity, oscillators, a rotating frame, a charged
 * particle, a rigid body, the heavy top, geodesics incl. strong deflection,
 * Hamiltonian flows incl. a pendulum):
 *   hindsight: every mechd method the operation accepts, swept through the
 *     API (rk8pd, rkf45, rkck, radau15 over rtol 1e-1 .. 1e-14; gauss6,
 *     yoshida6, rk4 over h = P/8 .. P/4096), error measured here against the
 *     scene's reference, evaluations from the answer, thread CPU;
 *   the chooser at target_error 1e-2, 1e-3, 1e-6, 1e-9, 1e-12 ("closed_form":
 *     false: integrating); regret = its evaluations (pilot included) over
 *     the fewest of any hindsight run meeting the same target, and the same
 *     for CPU; whether the true error lands in [target/30, target];
 *   the presets draft .. machine: machine / draft CPU;
 *   the predictions: predicted / counted evaluations, predicted / measured
 *     CPU, achieved.error / the true error;
 *   GSL's rk8pd called directly (gsl_odeiv2_driver, a bare right-hand side
 *     counting its calls) and SciPy's DOP853, LSODA and Radau (rtol = atol)
 *     where a bare right-hand side exists: the fewest evaluations and the
 *     CPU meeting each target.
 * Error: the largest over the answer's samples of |got - ref| / scale, the
 * scene's scale (positions: orbit size, amplitude, gyration radius, |omega|;
 * velocities: the largest speed of the motion; the pendulum's amplitude and
 * largest momentum); light: |measured - exact
 * deflection| / (pi + exact); GSL and SciPy: the final state only.
 * References: Kepler's equation (long double), cos/sin, the rotating
 * oscillator turned by hand, the gyration circle, Jacobi's elliptic
 * functions (rigid body, pendulum), the exact deflection; the heavy top,
 * Mercury and Henon-Heiles against rkck at rtol 1e-14.
 *
 * Run: build/bench_chooser_regret [OUT_DIR] (default build/bench-out): the
 * tables on stdout, chooser_regret.dat and chooser_regret.png (gnuplot) in
 * OUT_DIR, and chooser_hindsight.tsv (every swept run: method, setting,
 * error, evaluations, CPU) and chooser_runs.tsv (the chooser's and presets'
 * runs with their predictions), which bench/fit_chooser_rows.py fits into
 * the chooser's rows. MECHD_BENCH_DIR points at bench/ (for the SciPy
 * script) when run outside its source tree; MECHD_REGRET_SCENES=0,3 measures
 * only those scenes, MECHD_REGRET_QUICK=1 skips GSL and SciPy (while tuning).
 * About 8 minutes on 2 shared cores (1 without GSL and SciPy).
 */
#define _GNU_SOURCE
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>
#include <sys/stat.h>
#include <time.h>

#include "../tests/api/scene_set.h"

#define NT 5
static const double TARGETS[NT] = {1e-2, 1e-3, 1e-6, 1e-9, 1e-12};
static const char *const PRESETS[4] = {"draft", "balanced", "precise", "machine"};
static const double PROMISE[4] = {1e-3, 1e-8, 1e-10, 1e-11};

enum rk { RK_KEPLER, RK_OSC2, RK_OSC1, RK_ROTOSC, RK_LORENTZ, RK_RIGID, RK_LIGHT, RK_PEND,
          RK_RUN };

struct rscene {
    struct scene_def sd; /* name, path, body (no integrator), arrays, floor_ */
    const char *cls;     /* the class named in the tables */
    enum rk ref;
    double period;       /* fixed steps h = period / n */
    double t_end;
    const char *bare;    /* GSL/SciPy right-hand side name (NULL: none) */
    double y0[6];
    int dim;
};

#define TRAJ(NAME, CLS, REF, BODY, P, T, BARE, DIM, ...)                                         \
    {{NAME, "/v1/trajectory", BODY, REF_RUN, 0, {"position", "velocity", NULL}, 1.0},          \
     CLS, REF, P, T, BARE, {__VA_ARGS__}, DIM}

static const struct rscene SC[] = {
    TRAJ("Kepler e=0.5, 10 orbits", "central gravity", RK_KEPLER,
         "{\"particle\":{\"mass\":1,\"position\":[0.5,0,0],\"velocity\":[0,1.7320508075688772,0]},"
         "\"forces\":[{\"type\":\"central_gravity\",\"gm\":1}],\"t_end\":62.831853071795862,"
         "\"samples\":101}",
         6.283185307179586, 62.831853071795862, "kepler", 6, 0.5, 0, 0, 0, 1.7320508075688772, 0),
    TRAJ("Kepler e=0.9, 10 orbits", "central gravity", RK_KEPLER,
         "{\"particle\":{\"mass\":1,\"position\":[0.09999999999999998,0,0],\"velocity\":[0,"
         "4.358898943540674,0]},\"forces\":[{\"type\":\"central_gravity\",\"gm\":1}],"
         "\"t_end\":62.831853071795862,\"samples\":101}",
         6.283185307179586, 62.831853071795862, "kepler", 6, 0.09999999999999998, 0, 0, 0,
         4.358898943540674, 0),
    TRAJ("oscillator 2-D, 100 periods", "oscillator", RK_OSC2,
         "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0.5,0]},"
         "\"forces\":[{\"type\":\"spring\",\"k\":1}],\"t_end\":628.31853071795865,\"samples\":101}",
         6.283185307179586, 628.31853071795865, "oscillator", 6, 1, 0, 0, 0, 0.5, 0),
    TRAJ("oscillator 1-D, 100 periods", "oscillator", RK_OSC1,
         "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0,0]},"
         "\"forces\":[{\"type\":\"spring\",\"k\":1}],\"t_end\":628.31853071795865,\"samples\":101}",
         6.283185307179586, 628.31853071795865, "oscillator", 6, 1, 0, 0, 0, 0, 0),
    TRAJ("oscillator, rotating frame, 20 periods", "rotating frame", RK_ROTOSC,
         "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0.5,0]},"
         "\"frame\":{\"type\":\"rotating\",\"omega\":[0,0,0.3]},"
         "\"fictitious\":[\"coriolis\",\"centrifugal\"],\"forces\":[{\"type\":\"spring\",\"k\":1}],"
         "\"t_end\":125.66370614359172,\"samples\":101}",
         6.283185307179586, 125.66370614359172, "rotosc", 6, 1, 0, 0, 0, 0.5, 0),
    TRAJ("charge in B, 20 gyrations", "charged particle", RK_LORENTZ,
         "{\"particle\":{\"mass\":1,\"charge\":1,\"position\":[1,0,0],\"velocity\":[0,-1,0]},"
         "\"forces\":[{\"type\":\"lorentz\",\"E\":[0,0,0],\"B\":[0,0,1]}],"
         "\"t_end\":125.66370614359172,\"samples\":101}",
         6.283185307179586, 125.66370614359172, "lorentz", 6, 1, 0, 0, 0, -1, 0),
    {{"rigid body 1:2:3, 100 s", "/v1/rigid/rotate",
      "{\"moments\":[1,2,3],\"omega\":[0.05,1,0.05],\"t_end\":100,\"samples\":11}", REF_RIGID, 0,
      {"omega", NULL, NULL}, 1.0},
     "rigid body", RK_RIGID, 6.0, 100, "rigid", {0.05, 1, 0.05}, 3},
    {{"heavy top 5 s", "/v1/rigid/top",
      "{\"I1\":0.02,\"I3\":0.01,\"mass\":1.0,\"distance\":0.1,\"theta\":1.0471975511965976,"
      "\"phi_dot\":0.99,\"psi_dot\":99.5,\"t_end\":5,\"samples\":11}",
      REF_RUN, 0, {"theta", "phi", "psi"}, 1.0},
     "heavy top", RK_RUN, 0.063, 5, NULL, {0}, 0},
    {{"Mercury geodesic 10 orbits", "/v1/gr/geodesic",
      "{\"M\":\"sun\",\"kind\":\"timelike\",\"initial\":{\"semi_major_axis\":57909050000.0,"
      "\"eccentricity\":0.20563593},\"orbits\":10,\"samples\":11}",
      REF_RUN, 0, {"samples/r", "samples/phi", NULL}, 1.0},
     "timelike geodesic", RK_RUN, 0.1, 10, NULL, {0}, 0},
    {{"light, b = 5.2 M (strong)", "/v1/gr/geodesic",
      "{\"units\":\"geometric\",\"kind\":\"null\",\"initial\":{\"impact_parameter\":5.2,"
      "\"radial_direction\":\"inward\"},\"samples\":11}",
      REF_RUN, 0, {NULL, NULL, NULL}, 1.0},
     "null geodesic", RK_LIGHT, 0.1, 1, NULL, {0}, 0},
    {{"pendulum flow, 2.5 rad, 100 s", "/v1/hamiltonian/flow",
      "{\"system\":{\"name\":\"pendulum\",\"mass\":1,\"length\":1},\"q\":[2.5],\"p\":[0],"
      "\"t_end\":100,\"samples\":11}",
      REF_RUN, 0, {"q", "p", NULL}, 1.0},
     "Hamiltonian flow", RK_PEND, 2.0, 100, "pendulum", {2.5, 0}, 2},
    {{"Henon-Heiles 1000", "/v1/hamiltonian/flow",
      "{\"system\":{\"name\":\"henon_heiles\"},\"q\":[0,0],\"p\":[0.1,0],\"t_end\":1000,"
      "\"samples\":11}",
      REF_RUN, 0, {"q", "p", NULL}, 0.1},
     "Hamiltonian flow", RK_RUN, 6.3, 1000, "henon_heiles", {0, 0, 0.1, 0}, 4},
};
enum { NSC = sizeof SC / sizeof *SC };

/* ---- references ------------------------------------------------------------ */

static double th0_pend = 2.5;

static void pend_exact(double t, double *th, double *p)
{
    const double w0 = sqrt(9.80665), k = sin(0.5 * th0_pend);
    const double K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE);
    double sn, cn, dn;
    gsl_sf_elljac_e(w0 * t + K, k * k, &sn, &cn, &dn);
    *th = 2.0 * asin(k * sn);
    *p = 2.0 * k * w0 * cn;
}

/* the exact state (r, v or the flow's (q, p)) of a trajectory-like scene at t */
static void exact_state(const struct rscene *s, double t, double *y)
{
    memset(y, 0, 6 * sizeof *y);
    const long double tt = t;
    switch (s->ref) {
    case RK_KEPLER: kepler_state(s->y0[0], s->y0[4], t, y, y + 3); break;
    case RK_OSC2:
    case RK_OSC1: {
        const long double ph = fmodl(tt, TWO_PI_L);
        y[0] = (double)cosl(ph);
        y[3] = (double)-sinl(ph);
        if (s->ref == RK_OSC2) {
            y[1] = (double)(0.5L * sinl(ph));
            y[4] = (double)(0.5L * cosl(ph));
        }
        break;
    }
    case RK_ROTOSC: {
        const long double ph = fmodl(tt, TWO_PI_L), th = fmodl(0.3L * tt, TWO_PI_L);
        const double xi = (double)cosl(ph), yi = (double)(0.8L * sinl(ph));
        const double vxi = (double)-sinl(ph), vyi = (double)(0.8L * cosl(ph));
        const double c = (double)cosl(th), sn = (double)sinl(th);
        y[0] = c * xi + sn * yi;
        y[1] = -sn * xi + c * yi;
        y[3] = c * vxi + sn * vyi + 0.3 * y[1];
        y[4] = -sn * vxi + c * vyi - 0.3 * y[0];
        break;
    }
    case RK_LORENTZ: {
        const long double ph = fmodl(tt, TWO_PI_L);
        y[0] = (double)cosl(ph);
        y[1] = (double)-sinl(ph);
        y[3] = (double)-sinl(ph);
        y[4] = (double)-cosl(ph);
        break;
    }
    case RK_PEND: pend_exact(t, y, y + 1); break;
    default: break;
    }
}

/* the scale each component is measured against */
static double comp_scale(const struct rscene *s, int i)
{
    if (s->ref == RK_PEND) return i == 0 ? th0_pend : 2.0 * sin(0.5 * th0_pend) * sqrt(9.80665);
    if (s->ref == RK_ROTOSC && i >= 3) return 1.3; /* the largest speed seen in the frame */
    if (s->ref == RK_KEPLER && i >= 3) return s->y0[4]; /* the speed at pericentre */
    if (!strcmp(s->cls, "Hamiltonian flow")) return 0.1;
    return 1.0;
}

static json_t *REF[NSC]; /* RK_RUN / RK_RIGID: the reference answer (or arrays) */

/* The error of an answer against the scene's reference. */
static double answer_error(int si, const json_t *a)
{
    const struct rscene *s = &SC[si];
    if (s->ref == RK_LIGHT) {
        const double m = json_number_value(at(a, "deflection/measured"));
        const double ex = json_number_value(at(a, "deflection/exact"));
        return isfinite(m) && ex > 0 ? fabs(m - ex) / (SS_PI + ex) : INFINITY;
    }
    if (s->ref == RK_RUN || s->ref == RK_RIGID) {
        if (!REF[si]) return INFINITY;
        double e = 0;
        for (int k = 0; k < 3 && s->sd.arrays[k]; k++)
            e = fmax(e, tree_err(at(a, s->sd.arrays[k]), at(REF[si], s->sd.arrays[k]),
                                 s->sd.floor_ > 0 ? s->sd.floor_ : 1.0));
        return e;
    }
    const json_t *t = json_object_get(a, "t");
    const int flow = s->ref == RK_PEND;
    const json_t *P = json_object_get(a, flow ? "q" : "position"),
                 *V = json_object_get(a, flow ? "p" : "velocity");
    if (!json_array_size(t)) return INFINITY;
    double e = 0;
    for (size_t j = 0; j < json_array_size(t); j++) {
        double y[6];
        exact_state(s, json_number_value(json_array_get(t, j)), y);
        const int n = flow ? 1 : 3;
        for (int d = 0; d < n; d++) {
            const double gp = json_number_value(json_array_get(json_array_get(P, j), (size_t)d));
            const double gv = json_number_value(json_array_get(json_array_get(V, j), (size_t)d));
            e = fmax(e, fabs(gp - y[d]) / comp_scale(s, d));
            e = fmax(e, fabs(gv - y[flow ? 1 : 3 + d]) / comp_scale(s, flow ? 1 : 3 + d));
            if (!isfinite(gp) || !isfinite(gv)) return INFINITY;
        }
    }
    return e;
}

/* ---- one run through the API ------------------------------------------------ */

struct run {
    int ok;
    double err, evals, cpu;
    double pred_err, pred_evals, pred_cpu, achieved, span;
    char method[16];
    double setting;
};

static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static struct run api_run(int si, json_t *integ)
{
    struct run r;
    memset(&r, 0, sizeof r);
    r.err = INFINITY;
    r.achieved = -1;
    json_t *b = with_integrator(SC[si].sd.body, integ);
    if (!b) return r;
    int st = 0;
    json_t *a = NULL;
    double best = INFINITY;
    for (int rep = 0; rep < 5; rep++) {
        if (a) json_decref(a);
        const double c0 = thread_cpu();
        ss_quiet = 1;
        a = post(SC[si].sd.path, b, &st);
        ss_quiet = 0;
        best = fmin(best, thread_cpu() - c0);
        if (st != 200 || best > 2e-3) break; /* short runs: the best of up to 5 */
    }
    json_decref(b);
    if (st == 200 && a) {
        r.ok = 1;
        r.cpu = best;
        r.err = answer_error(si, a);
        const json_t *d = json_object_get(a, "diagnostics");
        r.evals = json_number_value(json_object_get(d, "rhs_evaluations"));
        const json_t *pil = at(a, "diagnostics/selection/pilot/evaluations");
        if (json_is_number(pil)) r.evals += json_number_value(pil);
        snprintf(r.method, sizeof r.method, "%s", json_string_value(json_object_get(d, "method")) ?
                 json_string_value(json_object_get(d, "method")) : "?");
        const json_t *rt = json_object_get(d, "rtol"), *dt = json_object_get(d, "dt");
        r.setting = json_is_number(rt) ? json_number_value(rt) : json_number_value(dt);
        const json_t *cands = at(a, "diagnostics/selection/candidates");
        for (size_t i = 0; i < json_array_size(cands); i++) {
            const json_t *c = json_array_get(cands, i);
            if (strcmp(json_string_value(json_object_get(c, "verdict")), "chosen")) continue;
            r.pred_err = json_number_value(json_object_get(c, "predicted_error"));
            r.pred_evals = json_number_value(json_object_get(c, "predicted_evaluations"));
            r.pred_cpu = json_number_value(json_object_get(c, "predicted_cpu_s"));
        }
        r.span = json_number_value(at(a, "diagnostics/selection/span"));
        const json_t *ach = at(a, "diagnostics/selection/achieved/error");
        if (json_is_number(ach)) r.achieved = json_number_value(ach);
    }
    json_decref(a);
    return r;
}

/* ---- the hindsight sweep ------------------------------------------------------ */

#define MAXH 400
struct hrun {
    char method[16];
    double x; /* rtol or h/P */
    struct run r;
};
static struct hrun H[NSC][MAXH];
static size_t NH[NSC];
static double ATOL_SCALE[NSC];

static void sweep(int si)
{
    static const char *const ad[] = {"rk8pd", "rkf45", "rkck", "radau15"};
    static const char *const fx[] = {"gauss6", "yoshida6", "rk4"};
    for (size_t m = 0; m < 4; m++) {
        for (int k = 2; k <= 28; k++) {
            const double x = pow(10.0, -0.5 * k);
            if (!strcmp(ad[m], "radau15") && x < 1e-10) break;
            struct run r = api_run(si, json_pack("{sssfsf}", "method", ad[m], "rtol", x, "atol",
                                                 x * ATOL_SCALE[si]));
            if (!r.ok) continue; /* refused (out of range, stopped): the next setting */
            if (NH[si] < MAXH) {
                struct hrun *h = &H[si][NH[si]++];
                snprintf(h->method, sizeof h->method, "%s", ad[m]);
                h->x = x;
                h->r = r;
            }
            if (r.cpu > 0.25) break;
        }
    }
    for (size_t m = 0; m < 3; m++) {
        for (int n = 8; n <= 4096; n *= 2) {
            const double dt = SC[si].period / n;
            if (SC[si].t_end / dt > 3e6) break;
            struct run r = api_run(si, json_pack("{sssf}", "method", fx[m], "dt", dt));
            if (!r.ok) continue;
            if (NH[si] < MAXH) {
                struct hrun *h = &H[si][NH[si]++];
                snprintf(h->method, sizeof h->method, "%s", fx[m]);
                h->x = 1.0 / n;
                h->r = r;
            }
            if (r.cpu > 0.25) break;
        }
    }
}

/* the cheapest hindsight run meeting target by evaluations (by_cpu 0) or CPU */
static const struct hrun *best_meeting(int si, double target, int by_cpu)
{
    const struct hrun *b = NULL;
    for (size_t i = 0; i < NH[si]; i++) {
        const struct hrun *h = &H[si][i];
        if (!(h->r.err <= target)) continue;
        if (!b || (by_cpu ? h->r.cpu < b->r.cpu : h->r.evals < b->r.evals)) b = h;
    }
    return b;
}

/* ---- GSL rk8pd called directly on a bare right-hand side ---------------------- */

static long g_evals;

static int bare_rhs(double t, const double *y, double *f, void *vp)
{
    (void)t;
    const char *name = vp;
    g_evals++;
    if (!strcmp(name, "kepler")) {
        const double r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2], k = -1.0 / (r2 * sqrt(r2));
        f[0] = y[3], f[1] = y[4], f[2] = y[5];
        f[3] = k * y[0], f[4] = k * y[1], f[5] = k * y[2];
    } else if (!strcmp(name, "oscillator")) {
        f[0] = y[3], f[1] = y[4], f[2] = y[5], f[3] = -y[0], f[4] = -y[1], f[5] = -y[2];
    } else if (!strcmp(name, "rotosc")) {
        const double w = 0.3;
        f[0] = y[3], f[1] = y[4], f[2] = y[5];
        f[3] = -y[0] + 2 * w * y[4] + w * w * y[0];
        f[4] = -y[1] - 2 * w * y[3] + w * w * y[1];
        f[5] = -y[2];
    } else if (!strcmp(name, "lorentz")) {
        f[0] = y[3], f[1] = y[4], f[2] = y[5], f[3] = y[4], f[4] = -y[3], f[5] = 0;
    } else if (!strcmp(name, "rigid")) {
        f[0] = (2.0 - 3.0) / 1.0 * y[1] * y[2];
        f[1] = (3.0 - 1.0) / 2.0 * y[2] * y[0];
        f[2] = (1.0 - 2.0) / 3.0 * y[0] * y[1];
    } else if (!strcmp(name, "pendulum")) {
        f[0] = y[1], f[1] = -9.80665 * sin(y[0]);
    } else { /* henon_heiles */
        f[0] = y[2], f[1] = y[3];
        f[2] = -y[0] - 2 * y[0] * y[1];
        f[3] = -y[1] - y[0] * y[0] + y[1] * y[1];
    }
    return GSL_SUCCESS;
}

/* the reference final state of a bare scene, in the bare state's layout */
static int bare_ref(int si, double *y)
{
    const struct rscene *s = &SC[si];
    if (s->ref != RK_RUN && s->ref != RK_RIGID) {
        exact_state(s, s->t_end, y);
        return 1;
    }
    /* the last sample of the reference answer */
    const char *key = s->ref == RK_RIGID ? "omega" : NULL;
    if (key) {
        const json_t *w = json_object_get(REF[si], "omega");
        const json_t *l = json_array_get(w, json_array_size(w) - 1);
        for (int i = 0; i < 3; i++) y[i] = json_number_value(json_array_get(l, (size_t)i));
        return 1;
    }
    const json_t *q = json_object_get(REF[si], "q"), *p = json_object_get(REF[si], "p");
    if (!json_array_size(q)) return 0;
    const json_t *ql = json_array_get(q, json_array_size(q) - 1),
                 *pl = json_array_get(p, json_array_size(p) - 1);
    y[0] = json_number_value(json_array_get(ql, 0));
    y[1] = json_number_value(json_array_get(ql, 1));
    y[2] = json_number_value(json_array_get(pl, 0));
    y[3] = json_number_value(json_array_get(pl, 1));
    return 1;
}

static double bare_err(int si, const double *y, const double *yr)
{
    const struct rscene *s = &SC[si];
    double e = 0;
    for (int i = 0; i < s->dim; i++) {
        double sc = comp_scale(s, i);
        if (s->ref == RK_PEND) sc = comp_scale(s, i);
        e = fmax(e, fabs(y[i] - yr[i]) / sc);
    }
    return isfinite(e) ? e : INFINITY;
}

struct brun {
    double x, err, evals, cpu;
};
static struct brun GS[NSC][32];
static size_t NGS[NSC];

static void gsl_sweep(int si)
{
    const struct rscene *s = &SC[si];
    double yr[6];
    if (!s->bare || !bare_ref(si, yr)) return;
    for (int k = 2; k <= 28; k++) {
        const double x = pow(10.0, -0.5 * k);
        gsl_odeiv2_system sys = {bare_rhs, NULL, (size_t)s->dim, (void *)s->bare};
        double best = INFINITY, err = INFINITY;
        long ev = 0;
        for (int rep = 0; rep < 3; rep++) {
            gsl_odeiv2_driver *d =
                gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, x, x);
            double y[6], t = 0;
            memcpy(y, s->y0, sizeof y);
            g_evals = 0;
            const double c0 = thread_cpu();
            const int st = gsl_odeiv2_driver_apply(d, &t, s->t_end, y);
            best = fmin(best, thread_cpu() - c0);
            gsl_odeiv2_driver_free(d);
            ev = g_evals;
            err = st == GSL_SUCCESS ? bare_err(si, y, yr) : INFINITY;
            if (best > 2e-3) break;
        }
        GS[si][NGS[si]++] = (struct brun){x, err, (double)ev, best};
        if (best > 0.25) break;
    }
}

/* ---- SciPy ---------------------------------------------------------------------- */

static const char *const SCIPY_M[3] = {"DOP853", "LSODA", "Radau"};
static struct brun SP[NSC][3][16];
static size_t NSP[NSC][3];

static void scipy_sweep(int si, const char *bench_dir)
{
    const struct rscene *s = &SC[si];
    double yr[6];
    if (!s->bare || !bare_ref(si, yr)) return;
    for (int m = 0; m < 3; m++) {
        char cmd[1200];
        int n = snprintf(cmd, sizeof cmd,
                         "timeout 20 /usr/bin/python3 '%s/workprecision_scipy.py' --scene %s --method %s "
                         "%.17g 1.0",
                         bench_dir, s->bare, SCIPY_M[m], s->t_end);
        for (int i = 0; i < s->dim; i++) n += snprintf(cmd + n, sizeof cmd - (size_t)n, " %.17g", s->y0[i]);
        n += snprintf(cmd + n, sizeof cmd - (size_t)n,
                      " -- 1e-2 1e-3 1e-4 1e-5 1e-6 1e-7 1e-8 1e-9 1e-10 1e-11 1e-12 1e-13 2>/dev/null");
        FILE *f = popen(cmd, "r");
        if (!f) return;
        char line[2048];
        while (fgets(line, sizeof line, f) && NSP[si][m] < 16) {
            double x, cpu, y[6] = {0};
            long nfev;
            char *p = strstr(line, "rtol=");
            if (!p || sscanf(p, "rtol=%lf nfev=%ld cpu=%lf", &x, &nfev, &cpu) != 3) continue;
            char *fin = strstr(line, "final=");
            if (!fin) continue;
            fin += 6;
            for (int i = 0; i < s->dim; i++) y[i] = strtod(fin, &fin);
            SP[si][m][NSP[si][m]++] = (struct brun){x, bare_err(si, y, yr), (double)nfev, cpu};
        }
        pclose(f);
    }
}

static const struct brun *bbest(const struct brun *b, size_t n, double target)
{
    const struct brun *r = NULL;
    for (size_t i = 0; i < n; i++)
        if (b[i].err <= target && (!r || b[i].evals < r->evals)) r = &b[i];
    return r;
}

/* ---- main ------------------------------------------------------------------------ */

static struct run CH[NSC][NT], PR[NSC][4];
static int SKIP[NSC];

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    api_install_json_allocator();
    if (api_init() != 0) return 1;
    const char *out_dir = argc > 1 ? argv[1] : "build/bench-out";
    mkdir(out_dir, 0755);
    char bench_dir[1024];
    const char *env = getenv("MECHD_BENCH_DIR");
    snprintf(bench_dir, sizeof bench_dir, "%s", env && *env ? env : __FILE__);
    if (!(env && *env)) {
        char *slash = strrchr(bench_dir, '/');
        if (slash) *slash = '\0';
        else snprintf(bench_dir, sizeof bench_dir, "bench");
    }
    const int have_scipy = system("/usr/bin/python3 -c 'import scipy' >/dev/null 2>&1") == 0;
    const double wall0 = mech_clock_seconds();
    time_t now = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    printf("# bench_chooser_regret: the chooser against mechd's own methods in hindsight, %s\n",
           date);

    /* MECHD_REGRET_SCENES=0,3,7 measures only those scenes (while tuning;
     * the tables then list only them); MECHD_REGRET_QUICK=1 skips GSL and SciPy */
    const char *only = getenv("MECHD_REGRET_SCENES");
    const int quick = getenv("MECHD_REGRET_QUICK") != NULL;
    for (int si = 0; si < NSC; si++) {
        SKIP[si] = 0;
        if (only && *only) {
            char key[16];
            snprintf(key, sizeof key, ",%d,", si);
            char list[256];
            snprintf(list, sizeof list, ",%s,", only);
            SKIP[si] = strstr(list, key) == NULL;
        }
        if (SKIP[si]) continue;
        /* the reference and the atol scale the chooser uses on this scene */
        if (SC[si].ref == RK_RUN) {
            const char *used = "";
            REF[si] = reference_run(&SC[si].sd, "rk8pd", &used);
        } else if (SC[si].ref == RK_RIGID) {
            json_t *b = with_integrator(SC[si].sd.body, json_pack("{sssfsf}", "method", "rk8pd",
                                                                   "rtol", 1e-6, "atol", 1e-6));
            int st;
            json_t *a = post(SC[si].sd.path, b, &st);
            json_decref(b);
            REF[si] = exact_rigid(a);
            json_decref(a);
        }
        json_t *b = with_integrator(SC[si].sd.body, json_pack("{sfsb}", "target_error", 1e-6,
                                                              "closed_form", 0));
        int st;
        json_t *a = post(SC[si].sd.path, b, &st);
        json_decref(b);
        const double rt = json_number_value(at(a, "diagnostics/rtol")),
                     at_ = json_number_value(at(a, "diagnostics/atol"));
        ATOL_SCALE[si] = rt > 0 && at_ > 0 ? at_ / rt : 1.0;
        json_decref(a);
        sweep(si);
        for (int k = 0; k < NT; k++)
            CH[si][k] = api_run(si, json_pack("{sfsb}", "target_error", TARGETS[k],
                                              "closed_form", 0));
        for (int k = 0; k < 4; k++)
            PR[si][k] = api_run(si, json_pack("{sssb}", "accuracy", PRESETS[k], "closed_form", 0));
        if (!quick) gsl_sweep(si);
        if (have_scipy && !quick) scipy_sweep(si, bench_dir);
        fprintf(stderr, "%s: %zu hindsight runs\n", SC[si].sd.name, NH[si]);
    }

    /* ---- the regret table ---- */
    printf("\n## Regret: the chooser's evaluations / the fewest of any mechd run meeting the "
           "target in hindsight (CPU ratio in brackets)\n");
    printf("# cell: ratio [CPU ratio] chosen method; MISS(error) when the chooser's true error "
           "is above the target; '-' when no hindsight run reaches it; "
           "'over' when the true error is below target/30 (targets >= 1e-6)\n");
    printf("| scene | class |");
    for (int k = 0; k < NT; k++) printf(" %.0e |", TARGETS[k]);
    printf("\n|---|---|");
    for (int k = 0; k < NT; k++) printf("---|");
    printf("\n");
    double lsum = 0;
    int ln = 0, within = 0, cells = 0, win_ok = 0, win_n = 0;
    for (int si = 0; si < NSC; si++) {
        if (SKIP[si]) continue;
        printf("| %s | %s |", SC[si].sd.name, SC[si].cls);
        for (int k = 0; k < NT; k++) {
            const struct run *c = &CH[si][k];
            const struct hrun *be = best_meeting(si, TARGETS[k], 0);
            const struct hrun *bc = best_meeting(si, TARGETS[k], 1);
            if (!c->ok) {
                printf(" refused |");
                continue;
            }
            if (!be) {
                double bmin = INFINITY;
                for (size_t i = 0; i < NH[si]; i++) bmin = fmin(bmin, H[si][i].r.err);
                printf(" - (no run reaches it: best %.1e; chooser %.1e) |", bmin, c->err);
                continue;
            }
            const double re = c->evals / be->r.evals, rc = bc ? c->cpu / bc->r.cpu : NAN;
            const int miss = !(c->err <= TARGETS[k]);
            const int over = TARGETS[k] >= 1e-6 && c->err < TARGETS[k] / 30;
            if (TARGETS[k] >= 1e-6) {
                win_n++;
                win_ok += !miss && !over;
            }
            cells++;
            within += re <= 1.25 && !miss;
            lsum += log(re);
            ln++;
            printf(" %s%.2f%s [%.2f] %s%s%s", re > 1.25 ? "**" : "", re, re > 1.25 ? "**" : "",
                   rc, c->method, miss ? " MISS" : "", over ? " over" : "");
            if (miss) printf(" (%.1e)", c->err);
            printf(" |");
        }
        printf("\n");
    }
    printf("# cells within 1.25x (and meeting the target): %d of %d; geometric mean of the "
           "evaluation ratio %.2f; true error in [target/30, target] at targets >= 1e-6: %d of "
           "%d\n",
           within, cells, ln ? exp(lsum / ln) : NAN, win_ok, win_n);

    printf("\n## The best in hindsight per scene and target (method setting: error, evaluations, "
           "CPU) beside the chooser's run\n");
    for (int si = 0; si < NSC; si++) {
        if (SKIP[si]) continue;
        printf("%s\n", SC[si].sd.name);
        for (int k = 0; k < NT; k++) {
            const struct hrun *be = best_meeting(si, TARGETS[k], 0);
            const struct run *c = &CH[si][k];
            printf("  %.0e: chooser %-8s %.3g: err %.2e, %.0f evals, %.3g ms (pred %.2e, %.0f evals, "
                   "%.3g ms; achieved %.2e)",
                   TARGETS[k], c->method, c->setting, c->err, c->evals, 1e3 * c->cpu, c->pred_err,
                   c->pred_evals, 1e3 * c->pred_cpu, c->achieved);
            if (be)
                printf(" | best %-8s %.3g: err %.2e, %.0f evals, %.3g ms\n", be->method, be->x,
                       be->r.err, be->r.evals, 1e3 * be->r.cpu);
            else
                printf(" | best: none reaches it\n");
        }
    }

    /* ---- presets ---- */
    printf("\n## Presets: true error (promise), evaluations, CPU; machine / draft CPU\n");
    printf("# limit: machine's CPU over the cheapest CPU of any mechd run in hindsight meeting "
           "1e-3 (what machine / draft could be if draft cost no more than that run)\n");
    printf("| scene | draft | balanced | precise | machine | machine / draft | limit |\n"
           "|---|---|---|---|---|---|---|\n");
    double gsum = 0, lsum2 = 0;
    int gn = 0, ln2 = 0;
    for (int si = 0; si < NSC; si++) {
        if (SKIP[si]) continue;
        printf("| %s |", SC[si].sd.name);
        for (int k = 0; k < 4; k++) {
            const struct run *p = &PR[si][k];
            printf(" %s %.1e%s, %.0f, %.3g ms |", p->method, p->err,
                   p->err <= PROMISE[k] ? "" : " (>promise)", p->evals, 1e3 * p->cpu);
        }
        const double r = PR[si][3].cpu / PR[si][0].cpu;
        gsum += log(r);
        gn++;
        const struct hrun *b3 = best_meeting(si, 1e-3, 1);
        const double lim = b3 ? PR[si][3].cpu / b3->r.cpu : NAN;
        if (isfinite(lim)) {
            lsum2 += log(lim);
            ln2++;
        }
        printf(" %.2f× | %.2f× |\n", r, lim);
    }
    printf("# geometric mean of machine / draft: %.2f×; of the limit: %.2f×\n", exp(gsum / gn),
           ln2 ? exp(lsum2 / ln2) : NAN);

    /* ---- prediction ratios ---- */
    printf("\n## Predictions over the chooser's runs (all targets and presets): predicted / "
           "counted evaluations, predicted / measured CPU, achieved.error / true error\n");
    printf("| scene | evals pred/counted | CPU pred/measured | achieved / true |\n|---|---|---|---|\n");
    for (int si = 0; si < NSC; si++) {
        if (SKIP[si]) continue;
        double e0 = INFINITY, e1 = 0, c0 = INFINITY, c1 = 0, a0 = INFINITY, a1 = 0;
        int na = 0;
        for (int k = 0; k < NT + 4; k++) {
            const struct run *r = k < NT ? &CH[si][k] : &PR[si][k - NT];
            if (!r->ok) continue;
            if (r->evals > 0) {
                e0 = fmin(e0, r->pred_evals / r->evals);
                e1 = fmax(e1, r->pred_evals / r->evals);
            }
            if (r->cpu > 0) {
                c0 = fmin(c0, r->pred_cpu / r->cpu);
                c1 = fmax(c1, r->pred_cpu / r->cpu);
            }
            if (r->achieved >= 0 && r->err > 1e-14) {
                a0 = fmin(a0, r->achieved / r->err);
                a1 = fmax(a1, r->achieved / r->err);
                na++;
            }
        }
        printf("| %s | %.2f–%.2f | %.2f–%.2f | ", SC[si].sd.name, e0, e1, c0, c1);
        if (na) printf("%.2f–%.2f |\n", a0, a1);
        else printf("none (no evidence in the answer) |\n");
    }

    /* ---- GSL and SciPy ---- */
    printf("\n## Beside: GSL rk8pd called directly, SciPy solve_ivp (final state): fewest "
           "evaluations meeting each target (CPU ms); the chooser's for comparison\n");
    printf("| scene | target | chooser | mechd best | GSL rk8pd | DOP853 | LSODA | Radau |\n"
           "|---|---|---|---|---|---|---|---|\n");
    for (int si = 0; si < NSC; si++) {
        if (!SC[si].bare || SKIP[si] || quick) continue;
        for (int k = 0; k < NT; k++) {
            const struct hrun *be = best_meeting(si, TARGETS[k], 0);
            printf("| %s | %.0e | %.0f (%.3g) | ", SC[si].sd.name, TARGETS[k], CH[si][k].evals,
                   1e3 * CH[si][k].cpu);
            if (be) printf("%.0f (%.3g) |", be->r.evals, 1e3 * be->r.cpu);
            else printf("- |");
            const struct brun *g = bbest(GS[si], NGS[si], TARGETS[k]);
            if (g) printf(" %.0f (%.3g) |", g->evals, 1e3 * g->cpu);
            else printf(" - |");
            for (int m = 0; m < 3; m++) {
                const struct brun *sp = bbest(SP[si][m], NSP[si][m], TARGETS[k]);
                if (!have_scipy) printf(" not measured |");
                else if (sp) printf(" %.0f (%.3g) |", sp->evals, 1e3 * sp->cpu);
                else printf(" - |");
            }
            printf("\n");
        }
    }

    /* ---- data and plot ---- */
    char path[1024];
    /* every hindsight run, for fitting the chooser's rows */
    snprintf(path, sizeof path, "%s/chooser_hindsight.tsv", out_dir);
    FILE *hf = fopen(path, "w");
    if (hf) {
        fprintf(hf, "scene\tmethod\tx\terror\tevaluations\tcpu_s\n");
        for (int si = 0; si < NSC; si++)
            for (size_t i = 0; i < NH[si]; i++)
                fprintf(hf, "%d\t%s\t%.3g\t%.3e\t%.0f\t%.3e\n", si, H[si][i].method, H[si][i].x,
                        H[si][i].r.err, H[si][i].r.evals, H[si][i].r.cpu);
        fclose(hf);
    }
    /* every chooser and preset run, for checking the rows' predictions */
    snprintf(path, sizeof path, "%s/chooser_runs.tsv", out_dir);
    hf = fopen(path, "w");
    if (hf) {
        fprintf(hf, "scene\ttarget\tmethod\tx\tspan\terror\tpredicted_error\tachieved\t"
                    "evaluations\tpredicted_evaluations\tcpu_s\tpredicted_cpu_s\n");
        for (int si = 0; si < NSC; si++)
            for (int k = 0; k < NT + 4; k++) {
                const struct run *r = k < NT ? &CH[si][k] : &PR[si][k - NT];
                if (SKIP[si] || !r->ok) continue;
                fprintf(hf, "%d\t%.0e\t%s\t%.4g\t%.6g\t%.3e\t%.3e\t%.3e\t%.0f\t%.0f\t%.3e\t%.3e\n",
                        si, k < NT ? TARGETS[k] : PROMISE[k - NT], r->method, r->setting, r->span,
                        r->err, r->pred_err, r->achieved, r->evals, r->pred_evals, r->cpu,
                        r->pred_cpu);
            }
        fclose(hf);
    }
    snprintf(path, sizeof path, "%s/chooser_regret.dat", out_dir);
    FILE *f = fopen(path, "w");
    if (f) {
        /* one gnuplot index per scene: hindsight methods (blocks), then chooser, presets,
         * GSL, SciPy */
        for (int si = 0; si < NSC; si++) {
            fprintf(f, "# scene %d %s\n", si, SC[si].sd.name);
            const char *last = "";
            for (size_t i = 0; i < NH[si]; i++) {
                if (strcmp(last, H[si][i].method)) {
                    if (i) fprintf(f, "\n");
                    last = H[si][i].method;
                    fprintf(f, "NaN NaN %s\n", last); /* a block is never empty */
                }
                if (isfinite(H[si][i].r.err))
                    fprintf(f, "%g %g %s\n", H[si][i].r.evals, fmax(H[si][i].r.err, 1e-17),
                            H[si][i].method);
            }
            fprintf(f, "\n");
            for (int k = 0; k < NT; k++)
                fprintf(f, "%g %g chooser\n", CH[si][k].evals, fmax(CH[si][k].err, 1e-17));
            fprintf(f, "\n");
            for (int k = 0; k < 4; k++)
                fprintf(f, "%g %g preset\n", PR[si][k].evals, fmax(PR[si][k].err, 1e-17));
            fprintf(f, "\nNaN NaN gsl\n");
            for (size_t i = 0; i < NGS[si]; i++)
                if (isfinite(GS[si][i].err))
                    fprintf(f, "%g %g gsl\n", GS[si][i].evals, fmax(GS[si][i].err, 1e-17));
            fprintf(f, "\n");
            for (int m = 0; m < 3; m++) {
                fprintf(f, "NaN NaN %s\n", SCIPY_M[m]);
                for (size_t i = 0; i < NSP[si][m]; i++)
                    if (isfinite(SP[si][m][i].err))
                        fprintf(f, "%g %g %s\n", SP[si][m][i].evals, fmax(SP[si][m][i].err, 1e-17),
                                SCIPY_M[m]);
                fprintf(f, "\n");
            }
            fprintf(f, "\n\n");
        }
        fclose(f);
        char gp[1024];
        snprintf(gp, sizeof gp, "%s/chooser_regret.gp", out_dir);
        FILE *g = fopen(gp, "w");
        if (g) {
            fprintf(g, "set terminal pngcairo size 1800,1400 font ',9'\nset output '%s/chooser_regret.png'\n",
                    out_dir);
            fprintf(g, "set multiplot layout 3,4 title 'work-precision: error vs right-hand-side "
                       "evaluations (log-log); mechd methods in hindsight (lines), the chooser at "
                       "1e-2..1e-12 (black circles), presets (red squares), GSL rk8pd direct, "
                       "SciPy DOP853/LSODA/Radau (final state)'\n");
            fprintf(g, "set logscale xy\nset format y '%%.0e'\nset key bottom left font ',7'\n"
                       "set xlabel 'evaluations'\nset ylabel 'error'\n");
            for (int si = 0; si < NSC; si++) {
                fprintf(g, "set title '%s'\n", SC[si].sd.name);
                /* blocks: 0..nm-1 methods, then chooser, presets, gsl, 3 scipy */
                int nm = 0;
                const char *last = "";
                char names[8][16];
                for (size_t i = 0; i < NH[si]; i++)
                    if (strcmp(last, H[si][i].method) && nm < 8) {
                        last = H[si][i].method;
                        snprintf(names[nm++], 16, "%s", last);
                    }
                fprintf(g, "plot ");
                for (int m = 0; m < nm; m++)
                    fprintf(g, "'%s' index %d every :::%d::%d using 1:2 with linespoints pt 7 ps 0.4 title '%s', ",
                            path, si, m, m, names[m]);
                fprintf(g, "'%s' index %d every :::%d::%d using 1:2 with points pt 6 ps 1.6 lc rgb 'black' title 'chooser', ",
                        path, si, nm, nm);
                fprintf(g, "'%s' index %d every :::%d::%d using 1:2 with points pt 5 ps 1.2 lc rgb 'red' title 'presets', ",
                        path, si, nm + 1, nm + 1);
                fprintf(g, "'%s' index %d every :::%d::%d using 1:2 with lines dt 2 lw 2 title 'GSL rk8pd', ",
                        path, si, nm + 2, nm + 2);
                for (int m = 0; m < 3; m++)
                    fprintf(g, "'%s' index %d every :::%d::%d using 1:2 with lines dt 3 title 'SciPy %s'%s",
                            path, si, nm + 3 + m, nm + 3 + m, SCIPY_M[m], m < 2 ? ", " : "\n");
            }
            fprintf(g, "unset multiplot\n");
            fclose(g);
            char cmd[1200];
            snprintf(cmd, sizeof cmd, "gnuplot '%s' 2>/dev/null", gp);
            const int rc = system(cmd);
            printf("\n# data %s, plot %s/chooser_regret.png (%s)\n", path, out_dir,
                   rc == 0 ? "written" : "gnuplot failed or missing");
        }
    }
    printf("# wall %.0f s\n", mech_clock_seconds() - wall0);
    for (int si = 0; si < NSC; si++) json_decref(REF[si]);
    return 0;
}
