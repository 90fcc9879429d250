/* test_particles_resource.c — GET /v1/relativity/particles lists the names
 * kinematics requests accept, with masses equal to the published values
 * (typed in here from PDG 2024 / CODATA 2018, not read from the table), and
 * every listed name works in a kinematics request. */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <stdio.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "testlib.h"

static json_t *call(const char *method, const char *path, const char *body, int *status)
{
    struct api_request req = {method, path, "application/json", body, body ? strlen(body) : 0,
                              1000000, mech_clock_seconds() + 60, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    *status = resp.status;
    json_t *j = resp.body ? json_loads(resp.body, 0, NULL) : NULL;
    api_response_free(&resp);
    return j;
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    int st;
    json_t *doc = call("GET", "/v1/relativity/particles", NULL, &st);
    CHECK_EQ_INT(st, 200);
    json_t *list = json_object_get(doc, "particles");
    CHECK(json_array_size(list) >= 20);
    static const struct { const char *name; double mev, rel; } known[] = {
        {"electron", 0.51099895000, 1e-10}, /* CODATA 2018 / PDG 2024 */
        {"proton", 938.27208816, 1e-10},
        {"muon", 105.6583755, 1e-9},
        {"pi0", 134.9768, 1e-6},
        {"photon", 0.0, 0.0},
    };
    for (size_t k = 0; k < sizeof known / sizeof known[0]; k++) {
        int found = 0;
        size_t i;
        json_t *p;
        json_array_foreach(list, i, p) {
            if (strcmp(json_string_value(json_object_get(p, "name")), known[k].name)) continue;
            found = 1;
            CHECK_CLOSE(json_number_value(json_object_get(p, "mass_mev")), known[k].mev,
                        known[k].rel, 0);
        }
        if (!found) fprintf(stderr, "%s not listed\n", known[k].name);
        CHECK(found);
    }
    /* Every listed name is accepted where a particle is expected (here one
     * particle with momentum 1 along z in an invariant-mass request). */
    size_t i;
    json_t *p;
    json_array_foreach(list, i, p) {
        char body[256];
        snprintf(body, sizeof body,
                 "{\"momenta\": [{\"particle\": \"%s\", \"momentum\": [0, 0, 1]}]}",
                 json_string_value(json_object_get(p, "name")));
        json_t *r = call("POST", "/v1/relativity/kinematics/invariant-mass", body, &st);
        if (st != 200) fprintf(stderr, "%s -> %d\n", body, st);
        CHECK_EQ_INT(st, 200);
        json_decref(r);
    }
    json_decref(doc);
    json_t *r = call("POST", "/v1/relativity/particles", "{}", &st);
    CHECK_EQ_INT(st, 405);
    json_decref(r);
    TEST_MAIN_END();
}
