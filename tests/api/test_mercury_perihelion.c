/* test_mercury_perihelion.c — Mercury's perihelion advance obtained through
 * POST /v1/trajectory (the Schwarzschild 1PN term chosen by "relativity":
 * "auto") against POST /v1/gr/geodesic's exact Schwarzschild advance
 * (42.9808 arcsec per Julian century for a = 5.7909050e10 m, e = 0.20563593,
 * GM = 1.32712440018e20 m^3/s^2), to 1e-3.
 *
 * Measurement: Mercury starts at perihelion of its Newtonian osculating orbit
 * and runs N = 415 radial periods (the geodesic's coordinate-time radial
 * period, ~ one century); the direction of the osculating Laplace-Runge-Lenz
 * vector v x (r x v) - GM r/|r| at the start and at the end (the same phase
 * of the orbit, so the 1PN term's periodic part cancels) gives the advance
 * over N orbits. Controls: the answer says it included schwarzschild_1pn with
 * its estimate; the 1PN energy it reports is conserved; the same scene with
 * "relativity": [] (Newtonian) advances by less than 1e-4 arcsec per century. */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "mech/base/constants.h"
#include "mech/base/vec.h"
#include "testlib.h"

static const double GM = 1.32712440018e20, A = 5.7909050e10, E = 0.20563593;

static json_t *post(const char *path, const char *text, int *status)
{
    struct api_request req = {"POST", path, "application/json", text, strlen(text), 50000000,
                              mech_clock_seconds() + 300, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    *status = resp.status;
    json_t *j = json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL);
    if (resp.status != 200) fprintf(stderr, "%s -> %d: %.600s\n", path, resp.status, resp.body);
    api_response_free(&resp);
    return j;
}

static const json_t *at(const json_t *j, const char *path)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", path);
    const json_t *cur = j;
    for (char *tok = strtok(buf, "/"); tok && cur; tok = strtok(NULL, "/"))
        cur = json_is_array(cur) ? json_array_get(cur, (size_t)atoi(tok)) : json_object_get(cur, tok);
    return cur;
}

static double num(const json_t *j, const char *path) { return json_number_value(at(j, path)); }

static struct mech_vec3 vec(const json_t *a)
{
    return mech_vec3_make(json_number_value(json_array_get(a, 0)),
                          json_number_value(json_array_get(a, 1)),
                          json_number_value(json_array_get(a, 2)));
}

/* Angle of the osculating Laplace-Runge-Lenz vector of sample i. */
static double lrl_angle(const json_t *ans, size_t i)
{
    const struct mech_vec3 r = vec(json_array_get(json_object_get(ans, "position"), i));
    const struct mech_vec3 v = vec(json_array_get(json_object_get(ans, "velocity"), i));
    const struct mech_vec3 h = mech_vec3_cross(r, v);
    const struct mech_vec3 lrl =
        mech_vec3_sub(mech_vec3_cross(v, h), mech_vec3_scale(r, GM / mech_vec3_norm(r)));
    return atan2(lrl.y, lrl.x);
}

/* Mercury from perihelion over n radial periods P (s); relativity "" = auto. */
static json_t *mercury(double P, int n, const char *relativity, int *status)
{
    const double rp = A * (1.0 - E), vp = sqrt(GM * (1.0 + E) / (A * (1.0 - E)));
    char body[1024];
    snprintf(body, sizeof body,
             "{\"particle\": {\"mass\": 3.3011e23, \"position\": [%.17g, 0, 0], \"velocity\": [0, "
             "%.17g, 0]}, \"forces\": [{\"type\": \"central_gravity\", \"gm\": %.17g}], "
             "\"t_end\": %.17g, \"samples\": 2, \"integrator\": {\"target_error\": 1e-11}%s%s, "
             "\"cost\": false}",
             rp, vp, GM, n * P, *relativity ? ", \"relativity\": " : "", relativity);
    return post("/v1/trajectory", body, status);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK(api_init() == 0);
    int st;
    /* the reference: the exact Schwarzschild advance and radial period */
    char gbody[400];
    snprintf(gbody, sizeof gbody,
             "{\"M\": {\"gm\": %.17g}, \"kind\": \"timelike\", \"initial\": {\"semi_major_axis\": "
             "%.17g, \"eccentricity\": %.17g}, \"orbits\": 20, \"samples\": 2, \"integrator\": "
             "{\"accuracy\": \"precise\"}}",
             GM, A, E);
    json_t *geo = post("/v1/gr/geodesic", gbody, &st);
    CHECK_EQ_INT(st, 200);
    const double exact = num(geo, "precession/arcsec_per_century/exact");
    const double P = num(geo, "orbit/radial_period_coordinate");
    CHECK_CLOSE(exact, 42.98, 1e-3, 0);
    json_decref(geo);

    const int N = 415; /* 415 radial periods ~ 0.99995 Julian century */
    const double century = 36525.0 * 86400.0;
    const double arcsec = 180.0 / MECH_PI * 3600.0;
    json_t *ans = mercury(P, N, "", &st);
    CHECK_EQ_INT(st, 200);
    if (st == 200) {
        const double shift = remainder(lrl_angle(ans, 1) - lrl_angle(ans, 0), 2.0 * MECH_PI);
        const double per_century = shift / N * (century / P) * arcsec;
        printf("Mercury through /v1/trajectory: %.9g arcsec/century (geodesic exact %.9g, "
               "ratio - 1 = %.3g)\n",
               per_century, exact, per_century / exact - 1.0);
        CHECK_CLOSE(per_century, exact, 1e-3, 0);
        CHECK(json_is_true(at(ans, "model/relativity/terms/1/included")));
        CHECK(!json_is_true(at(ans, "model/relativity/terms/0/included")));
        CHECK(!strcmp(json_string_value(at(ans, "model/relativity/terms/1/term")),
                      "schwarzschild_1pn"));
        CHECK(num(ans, "model/relativity/terms/1/estimated_effect/relative") > 1e-12);
        /* the 1PN energy is what the dynamics conserve */
        CHECK(json_is_true(at(ans, "diagnostics/invariants/0/conserved")));
        CHECK_CLOSE(num(ans, "diagnostics/invariants/0/max_relative_drift"), 0, 0, 1e-9);
        printf("  1PN energy drift %.3g, angular momentum drift %.3g, %g steps\n",
               num(ans, "diagnostics/invariants/0/max_relative_drift"),
               num(ans, "diagnostics/invariants/1/max_relative_drift"),
               num(ans, "diagnostics/steps"));
    }
    json_decref(ans);
    /* control: the Newtonian model does not advance */
    ans = mercury(P, N, "[]", &st);
    CHECK_EQ_INT(st, 200);
    if (st == 200) {
        const double shift = remainder(lrl_angle(ans, 1) - lrl_angle(ans, 0), 2.0 * MECH_PI);
        const double per_century = shift / N * (century / P) * arcsec;
        printf("Newtonian control: %.3g arcsec/century\n", per_century);
        CHECK_CLOSE(per_century, 0, 0, 1e-4);
        CHECK(!json_is_true(at(ans, "model/relativity/terms/1/included")));
    }
    json_decref(ans);
    TEST_MAIN_END();
}
