/* scene_set.h — the accuracy presets' scene set as API requests, with the references
 * each scene is measured against (Kepler's equation, cos/sin, the Jacobi
 * closed form, or an independent run of a different method at rtol 1e-14),
 * shared by tests/api/test_preset_scenes.c and bench/bench_workprecision.c
 * so the test and the figures measure the same thing. Header-only (static
 * functions, unused ones allowed); needs api.h, jansson, mech/base/budget.h,
 * mech/rigid/rigid_rotation.h.
 */
#ifndef MECHD_TESTS_SCENE_SET_H
#define MECHD_TESTS_SCENE_SET_H

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "mech/rigid/rigid_rotation.h"

#include "../kepler_ld.h"

#define SS_UNUSED __attribute__((unused))

static int ss_quiet; /* 1: post() does not print refused requests */

#define SS_PI 3.14159265358979323846
#define TWO_PI_L 6.283185307179586476925286766559L

static SS_UNUSED json_t *post(const char *path, const json_t *body, int *status)
{
    char *text = json_dumps(body, JSON_COMPACT | JSON_REAL_PRECISION(17));
    struct api_request req = {"POST", path, "application/json", text, strlen(text), 200000000,
                              mech_clock_seconds() + 300, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    free(text);
    *status = resp.status;
    json_t *j = json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL);
    if (resp.status != 200 && !ss_quiet) fprintf(stderr, "%s -> %d: %.400s\n", path, resp.status, resp.body);
    api_response_free(&resp);
    return j;
}

/* max |a - b| / max(|b|, floor) over every number of two same-shaped trees */
static SS_UNUSED double tree_err(const json_t *a, const json_t *b, double floor_)
{
    if (json_is_number(a) && json_is_number(b)) {
        const double x = json_number_value(a), y = json_number_value(b);
        if (!isfinite(x)) return INFINITY;
        return fabs(x - y) / fmax(fabs(y), floor_);
    }
    if (json_is_array(a) && json_is_array(b) && json_array_size(a) == json_array_size(b)) {
        double e = 0;
        for (size_t i = 0; i < json_array_size(a); i++)
            e = fmax(e, tree_err(json_array_get(a, i), json_array_get(b, i), floor_));
        return e;
    }
    return INFINITY; /* shapes differ: a miss, never a pass */
}

/* a JSON pointer-ish path "samples/r" into an object */
static SS_UNUSED const json_t *at(const json_t *o, const char *path)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *s = strtok(buf, "/"); s && o; s = strtok(NULL, "/")) o = json_object_get(o, s);
    return o;
}

/* ---- exact references ------------------------------------------------------ */

/* The Kepler orbit (gm = 1) through the scene's own initial state: pericentre
 * r0 = (q, 0, 0), v0 = (0, u, 0), the doubles the request sends. Its elements
 * are formed from those doubles in long double (a = 1 / (2/q - u^2),
 * e = 1 - q/a), not taken as the nominal a = 1 and e: the rounding of q and u
 * changes the mean motion by ~1e-15 relative at e = 0.9, which over 1000
 * orbits moves the reference by ~5e-10, far above round-off. */
static SS_UNUSED void kepler_state(double q, double u, double t, double *r, double *v)
{
    kepler_ld_pericentre(q, u, t, r, v); /* tests/kepler_ld.h */
    r[2] = 0;
    v[2] = 0;
}

static SS_UNUSED json_t *vec3(const double *x) { return json_pack("[fff]", x[0], x[1], x[2]); }

/* exact answer-shaped object for the trajectory scenes (position, velocity);
 * body: the scene's request (its initial state fixes the Kepler orbit) */
static SS_UNUSED json_t *exact_trajectory(const json_t *ans, int kepler, const char *body)
{
    json_t *req = json_loads(body, 0, NULL);
    const double q = json_number_value(json_array_get(at(req, "particle/position"), 0));
    const double u = json_number_value(json_array_get(at(req, "particle/velocity"), 1));
    json_decref(req);
    json_t *P = json_array(), *V = json_array(), *ts = json_object_get(ans, "t");
    for (size_t i = 0; i < json_array_size(ts); i++) {
        double t = json_number_value(json_array_get(ts, i)), r[3], v[3];
        if (kepler) {
            kepler_state(q, u, t, r, v);
        } else { /* x = cos t, y = 0.5 sin t */
            long double ph = fmodl((long double)t, TWO_PI_L);
            r[0] = (double)cosl(ph), r[1] = (double)(0.5L * sinl(ph)), r[2] = 0;
            v[0] = (double)-sinl(ph), v[1] = (double)(0.5L * cosl(ph)), v[2] = 0;
        }
        json_array_append_new(P, vec3(r));
        json_array_append_new(V, vec3(v));
    }
    return json_pack("{soso}", "position", P, "velocity", V);
}

static SS_UNUSED json_t *exact_rigid(const json_t *ans)
{
    const double I[3] = {1, 2, 3};
    struct mech_rigid_exact ex;
    struct mech_error err;
    mech_error_clear(&err);
    if (mech_rigid_exact_init(I, mech_vec3_make(0.05, 1, 0.05), &ex, &err) != MECH_OK) return NULL;
    json_t *W = json_array(), *ts = json_object_get(ans, "t");
    for (size_t i = 0; i < json_array_size(ts); i++) {
        struct mech_vec3 w;
        if (mech_rigid_exact_omega(&ex, json_number_value(json_array_get(ts, i)), &w, &err) !=
            MECH_OK) {
            json_decref(W);
            return NULL;
        }
        double x[3] = {w.x, w.y, w.z};
        json_array_append_new(W, vec3(x));
    }
    return json_pack("{so}", "omega", W);
}

/* ---- the scene set --------------------------------------------------------- */

enum ref_kind { REF_KEPLER, REF_OSC, REF_RIGID, REF_RUN };

struct scene_def {
    const char *name, *path, *body; /* body without "integrator" */
    enum ref_kind ref;
    double e;              /* Kepler */
    const char *arrays[3]; /* compared */
    double floor_;
};

/* The trajectory scenes are Newtonian by statement ("relativity": [], their
 * references are Newton's): in SI, gm = 1 at a = 1 m is a 1.5e10 kg mass whose
 * Schwarzschild precession, ~1e-15 rad per orbit, the automatic model adds at
 * machine over 1000 orbits of e = 0.9 (estimated effect 3e-12 > 1e-11/10), and
 * the falling object's special-relativistic 1e-13 exceeds the reference run's
 * rtol 1e-14 in a rotating frame, where it cannot be modelled. */
static const struct scene_def SCENES[] = {
#define KEP(E, N, Q, VY, T)                                                                      \
    {"kepler e=" #E " " #N " orbits", "/v1/trajectory",                                         \
     "{\"particle\":{\"mass\":1,\"position\":[" Q ",0,0],\"velocity\":[0," VY ",0]},"         \
     "\"forces\":[{\"type\":\"central_gravity\",\"gm\":1}],\"relativity\":[],"                \
     "\"t_end\":" T ",\"samples\":3}",                                                          \
     REF_KEPLER, E, {"position", "velocity", NULL}, 1.0}
    KEP(0.5, 10, "0.5", "1.7320508075688772", "62.831853071795862"),
    KEP(0.5, 1000, "0.5", "1.7320508075688772", "6283.1853071795862"),
    KEP(0.9, 10, "0.09999999999999998", "4.358898943540674", "62.831853071795862"),
    KEP(0.9, 1000, "0.09999999999999998", "4.358898943540674", "6283.1853071795862"),
#undef KEP
    {"oscillator 1e4 periods", "/v1/trajectory",
     "{\"particle\":{\"mass\":1,\"position\":[1,0,0],\"velocity\":[0,0.5,0]},"
     "\"forces\":[{\"type\":\"spring\",\"k\":1}],\"relativity\":[],"
     "\"t_end\":62831.853071795864,\"samples\":3}",
     REF_OSC, 0, {"position", "velocity", NULL}, 1.0},
    {"falling 100 m, 32 deg N, Coriolis", "/v1/trajectory",
     "{\"particle\":{\"mass\":1,\"position\":[0,0,100],\"velocity\":[0,0,0]},"
     "\"frame\":{\"type\":\"earth\",\"latitude_deg\":32},"
     "\"forces\":[{\"type\":\"uniform_gravity\",\"g\":[0,0,-9.80665]}],"
     "\"relativity\":[],"
     "\"fictitious\":[\"coriolis\"],\"t_end\":4.5160075575178755,\"samples\":3}",
     REF_RUN, 0, {"position", "velocity", NULL}, 44.29},
    {"rigid body 1:2:3, 100 s", "/v1/rigid/rotate",
     "{\"moments\":[1,2,3],\"omega\":[0.05,1,0.05],\"t_end\":100,\"samples\":11}", REF_RIGID, 0,
     {"omega", NULL, NULL}, 1.0},
    {"heavy top 5 s", "/v1/rigid/top",
     "{\"I1\":0.02,\"I3\":0.01,\"mass\":1.0,\"distance\":0.1,\"theta\":1.0471975511965976,"
     "\"phi_dot\":0.99,\"psi_dot\":99.5,\"t_end\":5,\"samples\":11}",
     REF_RUN, 0, {"theta", "phi", "psi"}, 1.0},
    {"Mercury geodesic 10 orbits", "/v1/gr/geodesic",
     "{\"M\":\"sun\",\"kind\":\"timelike\",\"initial\":{\"semi_major_axis\":57909050000.0,"
     "\"eccentricity\":0.20563593},\"orbits\":10,\"samples\":11}",
     REF_RUN, 0, {"samples/r", "samples/phi", NULL}, 1.0},
    {"Henon-Heiles 1000", "/v1/hamiltonian/flow",
     "{\"system\":{\"name\":\"henon_heiles\"},\"q\":[0,0],\"p\":[0.1,0],\"t_end\":1000,"
     "\"samples\":11}",
     REF_RUN, 0, {"q", "p", NULL}, 0.1},
};
enum { N_SCENES = sizeof SCENES / sizeof *SCENES };

static SS_UNUSED json_t *with_integrator(const char *body, json_t *integ)
{
    json_t *b = json_loads(body, JSON_DECODE_INT_AS_REAL, NULL);
    if (!b) {
        fprintf(stderr, "bad scene body: %s\n", body);
        json_decref(integ);
        return NULL;
    }
    json_object_set_new(b, "integrator", integ);
    json_object_set_new(b, "cost", json_false());
    return b;
}

/* an independent run: a method other than `not`, at rtol 1e-14 */
static SS_UNUSED json_t *reference_run(const struct scene_def *sc, const char *not, const char **used)
{
    static const char *const cand[] = {"radau15", "rk8pd", "rkck"};
    for (size_t k = 0; k < 3; k++) {
        if (strcmp(cand[k], not) == 0) continue;
        json_t *b = with_integrator(sc->body, json_pack("{sssfsf}", "method", cand[k], "rtol",
                                                        1e-14, "atol", 1e-14));
        int st;
        ss_quiet = 1; /* a method the operation refuses is not an error here */
        json_t *a = post(sc->path, b, &st);
        ss_quiet = 0;
        json_decref(b);
        if (st == 200) {
            *used = cand[k];
            return a;
        }
        json_decref(a);
    }
    return NULL;
}


/* The promise the answer holds itself to: the preset's, or the figure the
 * selection re-states when round-off makes it unreachable (its reason says
 * "beyond what the preset can keep ... about X relative"). */
static SS_UNUSED double ss_restated(const json_t *ans, double promise)
{
    const char *reason = json_string_value(json_object_get(
        json_object_get(json_object_get(ans, "diagnostics"), "selection"), "reason"));
    const char *beyond = reason ? strstr(reason, "beyond what the preset can keep") : NULL;
    const char *about = beyond ? strstr(beyond, "about ") : NULL;
    return about ? fmax(promise, strtod(about + 6, NULL)) : promise;
}

#endif
