/* test_check_field.c — POST /v1/check reads what a field is (its kind and
 * unit) from the operations' response schemas (x-mechd-check annotations,
 * api/check/check_field.c):
 *   1. every entry of the C table the annotations replaced resolves to the
 *      same kind and unit as before (the frozen list below is that table,
 *      copied from api/check/check_kind.c before it was deleted; "*" = any index);
 *   2. every annotation of every route names a kind and a unit mechd knows
 *      (templates: for every value of the answer string they read), at
 *      least as many as the first table had, and a few added later;
 *   3. the walk on a small schema: properties (escaped names), items (index
 *      tokens only), oneOf, units inherited through items but not properties,
 *      an unknown kind or unit ignored, pointers the schema does not describe;
 *   4. unit templates and the new units' factors (CODATA / SI 2019 values);
 *   5. GET /v1 and the OpenAPI document carry the annotations as written.
 */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <stdio.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "check/check_field.h"
#include "check/check_kind.h"
#include "run/routes.h"
#include "testlib.h"

struct frozen {
    const char *op, *pointer, *kind, *unit;
};

/* api/check/check_kind.c's defaults[] as it was at commit 507235b (34 entries). */
static const struct frozen old_table[] = {
    {"/v1/rigid/inertia", "/mass", "number", "kg"},
    {"/v1/rigid/inertia", "/center_of_mass", "vector", "m"},
    {"/v1/rigid/inertia", "/origin", "vector", "m"},
    {"/v1/rigid/inertia", "/tensor", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/tensor/*", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/tensor/*/*", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/tensor_center_of_mass", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/tensor_center_of_mass/*", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/tensor_center_of_mass/*/*", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/principal/moments", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/principal/moments/*", "number", "kg m^2"},
    {"/v1/rigid/inertia", "/principal/axes", "eigenvectors", "1"},
    {"/v1/rigid/inertia", "/principal/axes/*", "axis", "1"},
    {"/v1/rigid/inertia", "/angular_momentum", "vector", "kg m^2/s"},
    {"/v1/rigid/inertia", "/kinetic_energy", "number", "J"},
    {"/v1/rigid/inertia", "/angle_L_omega", "angle", "rad"},
    {"/v1/rigid/inertia", "/torque_to_hold_axis", "vector", "N m"},
    {"/v1/rotation/convert", "/quaternion", "quaternion", "1"},
    {"/v1/rotation/convert", "/matrix", "number", "1"},
    {"/v1/rotation/convert", "/axis_angle", "axis_angle", "rad"},
    {"/v1/rotation/convert", "/axis_angle/angle", "angle", "rad"},
    {"/v1/rotation/convert", "/rotation_vector", "vector", "rad"},
    {"/v1/rotation/convert", "/euler_zxz", "angle", "rad"},
    {"/v1/rotation/convert", "/euler_zxz/*", "angle", "rad"},
    {"/v1/rotation/compose", "/quaternion", "quaternion", "1"},
    {"/v1/rotation/compose", "/matrix", "number", "1"},
    {"/v1/rotation/compose", "/axis_angle", "axis_angle", "rad"},
    {"/v1/rotation/compose", "/axis_angle/angle", "angle", "rad"},
    {"/v1/rotation/compose", "/rotation_vector", "vector", "rad"},
    {"/v1/rotation/compose", "/euler_zxz", "angle", "rad"},
    {"/v1/rotation/compose", "/euler_zxz/*", "angle", "rad"},
    {"/v1/rotation/apply", "/matrix", "number", "1"},
    {"/v1/rotation/apply", "/vectors/*", "vector", NULL},
    {"/v1/rotation/apply", "/tensors/*", "number", NULL},
};

static int same_str(const char *a, const char *b)
{
    return a == b || (a && b && !strcmp(a, b));
}

/* The pointer with each "*" replaced by idx. */
static void instantiate(const char *pattern, const char *idx, char *out, size_t n)
{
    size_t o = 0;
    for (const char *p = pattern; *p && o + 4 < n; p++) {
        if (*p == '*') {
            for (const char *q = idx; *q && o + 1 < n; q++)
                out[o++] = *q;
        } else {
            out[o++] = *p;
        }
    }
    out[o] = '\0';
}

static void frozen_entries(void)
{
    size_t n = sizeof old_table / sizeof old_table[0];
    CHECK_EQ_INT(n, 34);
    static const char *const idx[] = {"0", "2", "10"};
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < 3; k++) {
            char ptr[200];
            instantiate(old_table[i].pointer, idx[k], ptr, sizeof ptr);
            enum api_check_kind kind;
            const char *unit;
            int r = api_check_field(old_table[i].op, ptr, &kind, &unit);
            int ok = r == 1 && !strcmp(api_check_kind_name(kind), old_table[i].kind) &&
                     same_str(unit, old_table[i].unit);
            if (!ok)
                fprintf(stderr, "%s %s: %s %s, was %s %s\n", old_table[i].op, ptr,
                        api_check_kind_name(kind), unit ? unit : "(none)", old_table[i].kind,
                        old_table[i].unit ? old_table[i].unit : "(none)");
            CHECK(ok);
        }
    /* fields the table did not list stay plain numbers of no unit */
    enum api_check_kind kind;
    const char *unit;
    CHECK(api_check_field("/v1/rigid/inertia", "/parts/0/mass", &kind, &unit) == 0);
    CHECK(kind == API_KIND_NUMBER && unit == NULL);
    CHECK(api_check_field("/v1/rigid/inertia", "/principal/degenerate", &kind, &unit) == 0);
    CHECK(api_check_field("/v1/rotation/convert", "/axis_angle/axis", &kind, &unit) == 0);
    CHECK(kind == API_KIND_NUMBER && unit == NULL); /* not rad: no inheritance through objects */
    CHECK(api_check_field("/v1/no/such", "/mass", &kind, &unit) == 0);
    CHECK(api_check_field(NULL, "/mass", &kind, &unit) == 0);
}

/* The answer strings unit templates read, with every value the handlers
 * write there (the enums of their response schemas). */
#define TEMPLATE_VALUES 5
struct template_source {
    const char *pointer; /* "{/pointer}" in the template, without the braces */
    const char *values[TEMPLATE_VALUES];
};
static const struct template_source template_sources[] = {
    {"/energy_unit", {"eV", "keV", "MeV", "GeV", "TeV"}}, /* relativity/kinematics, particle */
    {"/units/time", {"s", "yr"}},                        /* relativity/worldline */
    {"/units/length", {"m", "ly"}},
};

/* The source of template u (its first "{...}"), or NULL. */
static const struct template_source *template_of(const char *u)
{
    const char *open = strchr(u, '{'), *close = open ? strchr(open, '}') : NULL;
    if (!close) return NULL;
    size_t n = (size_t)(close - open - 1);
    for (size_t i = 0; i < sizeof template_sources / sizeof template_sources[0]; i++)
        if (strlen(template_sources[i].pointer) == n &&
            !strncmp(template_sources[i].pointer, open + 1, n))
            return &template_sources[i];
    return NULL;
}

/* An answer holding value at pointer ("/a" or "/a/b"); the caller decrefs. */
static json_t *template_answer(const char *pointer, const char *value)
{
    const char *slash = strchr(pointer + 1, '/');
    if (!slash) return json_pack("{s:s}", pointer + 1, value);
    char outer[64];
    snprintf(outer, sizeof outer, "%.*s", (int)(slash - pointer - 1), pointer + 1);
    return json_pack("{s:{s:s}}", outer, slash + 1, value);
}

/* Every annotation under s: counted, its kind and unit known. */
static void every_annotation(const json_t *s, const char *where, size_t *count)
{
    if (json_is_array(s)) {
        size_t i;
        const json_t *v;
        json_array_foreach(s, i, v) every_annotation(v, where, count);
        return;
    }
    if (!json_is_object(s)) return;
    const json_t *a = json_object_get(s, "x-mechd-check");
    if (a) {
        (*count)++;
        enum api_check_kind k;
        const char *kn = json_string_value(json_object_get(a, "kind"));
        CHECK(kn && api_check_kind_parse(kn, &k) == 0);
        const char *u = json_string_value(json_object_get(a, "unit"));
        if (u && strchr(u, '{')) {
            const struct template_source *t = template_of(u);
            if (!t) fprintf(stderr, "%s: %s: no template source known to this test\n", where, u);
            CHECK(t != NULL);
            for (int i = 0; t && i < TEMPLATE_VALUES && t->values[i]; i++) {
                json_t *ans = template_answer(t->pointer, t->values[i]);
                const char *x = api_check_unit_expand(u, ans);
                if (!x)
                    fprintf(stderr, "%s: %s does not expand with %s\n", where, u, t->values[i]);
                CHECK(x != NULL && !strncmp(x, t->values[i], strlen(t->values[i])));
                json_decref(ans);
            }
        } else if (u) {
            if (!api_unit_find(u)) fprintf(stderr, "%s: unknown unit %s\n", where, u);
            CHECK(api_unit_find(u) != NULL);
        }
    }
    const char *key;
    const json_t *v;
    json_object_foreach((json_t *)s, key, v) {
        if (!strcmp(key, "x-mechd-check")) continue;
        every_annotation(v, where, count);
    }
}

static void all_routes(void)
{
    size_t count = 0;
    for (size_t i = 0; i < api_route_count; i++)
        every_annotation(api_route_response_schema(i), api_routes[i]->path, &count);
    printf("%zu x-mechd-check annotations\n", count);
    /* the old table (34) + the ones added with it (259); more came
     * since (relativity, continuum, frames, rigid, ...), and more may */
    CHECK(count >= 34 + 259);

    /* a few of the added ones, read against their handlers */
    enum api_check_kind kind;
    const char *unit;
    CHECK(api_check_field("/v1/relativity/kinematics/decay", "/at_theta_star/daughters/1/momentum",
                          &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "{/energy_unit}/c"));
    CHECK(api_check_field("/v1/relativity/kinematics/decay", "/lab_energy_ranges/0/1", &kind,
                          &unit) == 1);
    CHECK(same_str(unit, "{/energy_unit}")); /* inherited through two levels of items */
    CHECK(api_check_field("/v1/trajectory", "/position/3", &kind, &unit) == 1);
    CHECK(kind == API_KIND_VECTOR && same_str(unit, "m"));
    CHECK(api_check_field("/v1/trajectory", "/position/3/1", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "m"));
    CHECK(api_check_field("/v1/earth/gravity", "/sphere/deviation/mrad", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "mrad"));
    CHECK(api_check_field("/v1/rotation/compose", "/euler/extrinsic/ZYX/angles/2", &kind,
                          &unit) == 1);
    CHECK(kind == API_KIND_ANGLE && same_str(unit, "rad"));

    /* some added later, read against their encoders (the handlers in api/ops/<domain>/) */
    CHECK(api_check_field("/v1/relativity/particle", "/lifetime/decay_length", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "m")); /* beta gamma c tau */
    CHECK(api_check_field("/v1/relativity/particle", "/mass", &kind, &unit) == 1);
    CHECK(same_str(unit, "{/energy_unit}/c^2"));
    CHECK(api_check_field("/v1/relativity/force", "/force/2", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "N")); /* through the vector's items */
    CHECK(api_check_field("/v1/relativity/force", "/acceleration", &kind, &unit) == 1);
    CHECK(kind == API_KIND_VECTOR && same_str(unit, "m/s^2"));
    CHECK(api_check_field("/v1/relativity/doppler", "/angle_observer_frame_deg", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "deg")); /* a physical angle, not an orientation */
    CHECK(api_check_field("/v1/relativity/kinematics/collision", "/center_of_momentum/beta",
                          &kind, &unit) == 1);
    CHECK(kind == API_KIND_VECTOR && same_str(unit, "1")); /* v/c: dimensionless */
    CHECK(api_check_field("/v1/relativity/kinematics/elastic", "/t", &kind, &unit) == 1);
    CHECK(same_str(unit, "{/energy_unit}^2")); /* Mandelstam t */
    CHECK(api_check_field("/v1/small-oscillations", "/modes/1/period", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "s"));
    CHECK(api_check_field("/v1/hamiltonian/phase-area", "/action", &kind, &unit) == 1);
    CHECK(same_str(unit, "J s"));
    CHECK(api_check_field("/v1/scenes/cannonball", "/numerical/right", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "m"));
    CHECK(api_check_field("/v1/scenes/rotating-table", "/rotating_exact/4", &kind, &unit) == 1);
    CHECK(kind == API_KIND_VECTOR && same_str(unit, "m"));
    CHECK(api_check_field("/v1/relativity/worldline", "/total/distance", &kind, &unit) == 1);
    CHECK(same_str(unit, "{/units/length}")); /* m or ly, as the request chose */
    CHECK(api_check_field("/v1/continuum/string", "/modes/2/frequency", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "Hz"));
    CHECK(api_check_field("/v1/continuum/string", "/modes/2/n", &kind, &unit) == 0);
    CHECK(api_check_field("/v1/frames/rotating-liquid", "/surface/1/height", &kind, &unit) == 1);
    CHECK(same_str(unit, "m"));
    CHECK(api_check_field("/v1/rigid/struck-ball", "/w0", &kind, &unit) == 1);
    CHECK(kind == API_KIND_NUMBER && same_str(unit, "rad/s"));
}

static void walk(void)
{
    json_t *s = json_loads(
        "{\"type\":\"object\",\"properties\":{"
        "\"a/b\":{\"type\":\"number\",\"x-mechd-check\":{\"kind\":\"angle\",\"unit\":\"rad\"}},"
        "\"m~\":{\"type\":\"number\",\"x-mechd-check\":{\"kind\":\"number\",\"unit\":\"kg\"}},"
        "\"rows\":{\"type\":\"array\",\"x-mechd-check\":{\"kind\":\"matrix\",\"unit\":\"km\"},"
        "  \"items\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}}},"
        "\"obj\":{\"type\":\"object\",\"x-mechd-check\":{\"kind\":\"axis_angle\",\"unit\":\"rad\"},"
        "  \"properties\":{\"axis\":{\"type\":\"array\",\"items\":{\"type\":\"number\"}}}},"
        "\"typo\":{\"type\":\"number\",\"x-mechd-check\":{\"kind\":\"vectr\",\"unit\":\"furlong\"}},"
        "\"alt\":{\"oneOf\":[{\"type\":\"null\"},{\"type\":\"object\",\"properties\":{"
        "  \"q\":{\"type\":\"array\",\"x-mechd-check\":{\"kind\":\"quaternion\",\"unit\":\"1\"}}}}]}"
        "},\"x-mechd-check\":{\"kind\":\"vector\"}}",
        0, NULL);
    CHECK(s != NULL);
    enum api_check_kind k;
    const char *u;
    CHECK(api_check_field_in_schema(s, "/a~1b", &k, &u) == 1 && k == API_KIND_ANGLE &&
          same_str(u, "rad"));
    CHECK(api_check_field_in_schema(s, "/m~0", &k, &u) == 1 && same_str(u, "kg"));
    CHECK(api_check_field_in_schema(s, "/a/b", &k, &u) == 0 && k == API_KIND_NUMBER && !u);
    CHECK(api_check_field_in_schema(s, "/m~2", &k, &u) == 0); /* a bad escape */
    CHECK(api_check_field_in_schema(s, "/rows", &k, &u) == 1 && k == API_KIND_MATRIX &&
          same_str(u, "km"));
    CHECK(api_check_field_in_schema(s, "/rows/1/2", &k, &u) == 1 && k == API_KIND_NUMBER &&
          same_str(u, "km"));
    CHECK(api_check_field_in_schema(s, "/rows/x", &k, &u) == 0); /* items take indices only */
    CHECK(api_check_field_in_schema(s, "/rows/", &k, &u) == 0);
    CHECK(api_check_field_in_schema(s, "/obj", &k, &u) == 1 && k == API_KIND_AXIS_ANGLE);
    CHECK(api_check_field_in_schema(s, "/obj/axis", &k, &u) == 0 && !u); /* not rad */
    CHECK(api_check_field_in_schema(s, "/obj/axis/0", &k, &u) == 0 && !u);
    CHECK(api_check_field_in_schema(s, "/typo", &k, &u) == 0 && k == API_KIND_NUMBER && !u);
    CHECK(api_check_field_in_schema(s, "/alt/q", &k, &u) == 1 && k == API_KIND_QUATERNION &&
          same_str(u, "1"));
    CHECK(api_check_field_in_schema(s, "", &k, &u) == 1 && k == API_KIND_VECTOR && !u);
    CHECK(api_check_field_in_schema(s, "rows", &k, &u) == 0); /* not a pointer */
    CHECK(api_check_field_in_schema(s, "/nothing/here", &k, &u) == 0);
    CHECK(api_check_field_in_schema(NULL, "/rows", &k, &u) == 0 && k == API_KIND_NUMBER);
    CHECK(api_check_field_in_schema(s, NULL, &k, &u) == 0);
    char longp[2000];
    memset(longp, 'a', sizeof longp);
    longp[0] = '/';
    longp[sizeof longp - 1] = '\0';
    CHECK(api_check_field_in_schema(s, longp, &k, &u) == 0); /* longer than any name */
    json_decref(s);
}

#define EV 1.602176634e-19 /* J, exact (SI 2019) */
#define C 299792458.0      /* m/s, exact */

static void templates_and_units(void)
{
    json_t *ans = json_pack("{s:s,s:{s:s},s:i}", "energy_unit", "GeV", "deep", "u", "keV", "n", 3);
    CHECK(same_str(api_check_unit_expand("{/energy_unit}/c", ans), "GeV/c"));
    CHECK(same_str(api_check_unit_expand("{/energy_unit}/c^2", ans), "GeV/c^2"));
    CHECK(same_str(api_check_unit_expand("{/energy_unit}", ans), "GeV"));
    CHECK(same_str(api_check_unit_expand("{/energy_unit}^2", ans), "GeV^2"));
    CHECK(same_str(api_check_unit_expand("{/deep/u}", ans), "keV"));
    CHECK(same_str(api_check_unit_expand("kg m^2", ans), "kg m^2"));
    CHECK(api_check_unit_expand("{/n}", ans) == NULL);          /* not a string */
    CHECK(api_check_unit_expand("{/missing}/c", ans) == NULL);  /* nothing there */
    CHECK(api_check_unit_expand("{/energy_unit", ans) == NULL); /* unclosed */
    CHECK(api_check_unit_expand("{/energy_unit}/s", ans) == NULL); /* GeV/s: no such unit */
    CHECK(api_check_unit_expand("furlong", ans) == NULL);
    CHECK(api_check_unit_expand(NULL, ans) == NULL);
    CHECK(api_check_unit_expand("{/energy_unit}/c", NULL) == NULL);
    json_decref(ans);
    ans = json_pack("{s:{s:s,s:s}}", "units", "time", "yr", "length", "ly");
    CHECK(same_str(api_check_unit_expand("{/units/time}", ans), "yr"));
    CHECK(same_str(api_check_unit_expand("{/units/length}", ans), "ly"));
    json_decref(ans);
    /* worldline's year is Julian (365.25 d) and its light-year c times it, so c = 1 ly/yr */
    CHECK_CLOSE(api_unit_find("yr")->factor, 31557600.0, 0, 0);
    CHECK_CLOSE(api_unit_find("ly")->factor, C * 31557600.0, 1e-15, 0);

    /* the units added for the annotations: SI 2019 (e, c exact); CODATA 2018
     * gives 1 MeV/c^2 = 1.78266192e-30 kg and 1 eV/c = 5.34428599e-28 kg m/s */
    CHECK_CLOSE(api_unit_find("TeV")->factor, 1.602176634e-7, 1e-15, 0);
    CHECK_CLOSE(api_unit_find("MeV/c^2")->factor, 1.78266192e-30, 1e-8, 0);
    CHECK_CLOSE(api_unit_find("eV/c")->factor, 5.34428599e-28, 1e-8, 0);
    CHECK_CLOSE(api_unit_find("TeV/c^2")->factor, 1e12 * EV / (C * C), 1e-15, 0);
    CHECK_CLOSE(api_unit_find("keV/c")->factor, 1e3 * EV / C, 1e-15, 0);
    CHECK_CLOSE(api_unit_find("mrad")->factor * 1000, 1, 1e-15, 0);
    CHECK(!strcmp(api_unit_find("GeV/c^2")->dim, api_unit_find("kg")->dim));
    CHECK(!strcmp(api_unit_find("TeV/c")->dim, api_unit_find("kg m/s")->dim));
    CHECK(!strcmp(api_unit_find("mrad")->dim, api_unit_find("deg")->dim));
    /* squared energies (Mandelstam s, t, u): 1 GeV^2 = (1.602176634e-10 J)^2, and
     * 1 GeV^2 is 1e6 MeV^2, no energy and no mass */
    CHECK_CLOSE(api_unit_find("GeV^2")->factor, 2.566969966535569956e-20, 1e-15, 0); /* exact */
    CHECK_CLOSE(api_unit_find("GeV^2")->factor / api_unit_find("MeV^2")->factor, 1e6, 1e-15, 0);
    CHECK_CLOSE(api_unit_find("TeV^2")->factor, 1e24 * EV * EV, 1e-15, 0);
    CHECK(!strcmp(api_unit_find("eV^2")->dim, api_unit_find("keV^2")->dim));
    CHECK(strcmp(api_unit_find("eV^2")->dim, api_unit_find("eV")->dim) != 0);
    CHECK(strcmp(api_unit_find("eV^2")->dim, api_unit_find("eV/c^2")->dim) != 0);
    /* the message list names every unit of the table */
    static const char *const added[] = {"TeV", "mrad", "eV/c", "keV/c", "TeV/c", "eV/c^2",
                                        "keV/c^2", "MeV/c^2", "GeV/c^2", "TeV/c^2",
                                        "eV^2",    "keV^2", "MeV^2", "GeV^2", "TeV^2"};
    for (size_t i = 0; i < sizeof added / sizeof added[0]; i++) {
        char needle[32];
        snprintf(needle, sizeof needle, " %s,", added[i]);
        CHECK(strstr(api_unit_list, needle) != NULL);
    }
}

static json_t *get(const char *path)
{
    struct api_request req = {"GET", path, NULL, NULL, 0, 1000, mech_clock_seconds() + 300, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    json_t *j = resp.status == 200 && resp.body ? json_loads(resp.body, 0, NULL) : NULL;
    api_response_free(&resp);
    return j;
}

/* The annotation on /v1/rigid/inertia's principal axes in a response schema. */
static const char *axes_kind(const json_t *rs)
{
    const json_t *a = json_object_get(
        json_object_get(json_object_get(json_object_get(json_object_get(json_object_get(rs,
            "properties"), "principal"), "properties"), "axes"), "x-mechd-check"), "kind");
    return json_string_value(a);
}

static void documents(void)
{
    json_t *cat = get("/v1"), *oa = get("/v1/openapi.json");
    CHECK(cat != NULL && oa != NULL);
    const json_t *rs = NULL;
    size_t i;
    const json_t *op;
    json_array_foreach(json_object_get(cat, "operations"), i, op)
        if (!strcmp(json_string_value(json_object_get(op, "path")), "/v1/rigid/inertia"))
            rs = json_object_get(op, "response_schema");
    CHECK(same_str(axes_kind(rs), "eigenvectors"));
    const json_t *post = json_object_get(
        json_object_get(json_object_get(oa, "paths"), "/v1/rigid/inertia"), "post");
    const json_t *ors = json_object_get(json_object_get(json_object_get(json_object_get(
        json_object_get(post, "responses"), "200"), "content"), "application/json"), "schema");
    CHECK(same_str(axes_kind(ors), "eigenvectors"));
    json_decref(cat);
    json_decref(oa);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator();
    CHECK(api_init() == 0);
    frozen_entries();
    all_routes();
    walk();
    templates_and_units();
    documents();
    TEST_MAIN_END();
}
