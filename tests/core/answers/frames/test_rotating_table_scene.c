/* test_rotating_table_scene.c — the rotating table (notes §1.1) as one
 * /v1/scenes/rotating-table computation (mech/answers/frames/rotating_table_scene.h),
 * against the closed form: a free puck moves on the straight line
 * r(t) = r0 + v0 t in the inertial frame, so in the table's axes (turning at
 * w about z, the frames coinciding at t = 0) it is that line rotated back,
 * x' = x cos wt + y sin wt, y' = -x sin wt + y cos wt. The integrated
 * rotating-frame path (centrifugal and Coriolis terms) must follow it to the
 * requested accuracy; the first puck returns to its start after half a turn,
 * the second draws a circle of radius r1. The effective forces at t = 0 are
 * the notes': -m w² r1 (e_y + (4/pi) e_x) and -m w² r1 e_y. Then the
 * experiment's refusals, a dry run, and the largest inputs. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/base/constants.h"
#include "mech/answers/frames/rotating_table_scene.h"
#include "testlib.h"

static struct mech_rotating_table_request request(enum mech_table_experiment x, double w)
{
    struct mech_rotating_table_request q;
    memset(&q, 0, sizeof q);
    q.scene.experiment = x;
    q.scene.omega = w;
    q.scene.radius = 1;
    q.scene.mass = 1;
    q.scene.samples = 21;
    q.target = 1e-8;
    return q;
}

/* The closed-form path in the table's axes at t. */
static struct mech_vec3 closed_form(struct mech_vec3 r0, struct mech_vec3 v0, double w, double t)
{
    const double x = r0.x + v0.x * t, y = r0.y + v0.y * t, z = r0.z + v0.z * t;
    const double c = cos(w * t), s = sin(w * t);
    return mech_vec3_make(x * c + y * s, -x * s + y * c, z);
}

/* Run q; every sample against the closed form within tol (m). */
static struct mech_rotating_table_scene *
run_against_closed_form(const struct mech_rotating_table_request *q, struct mech_vec3 r0,
                        struct mech_vec3 v0, double t_end, double tol)
{
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    struct mech_rotating_table_scene *s = NULL;
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rotating_table_scene(q, &b, &s, &e), MECH_OK);
    if (!s) {
        fprintf(stderr, "  %s\n", e.text);
        return NULL;
    }
    const struct mech_scene_table_result *r = &s->result;
    CHECK_EQ_INT(r->n_samples, q->scene.samples);
    CHECK_CLOSE(r->t_end, t_end, 1e-15, 0);
    double worst = 0;
    for (size_t i = 0; i < r->n_samples; i++) {
        const double t = t_end * (double)i / (double)(q->scene.samples - 1);
        CHECK_CLOSE(r->t[i], t, 1e-15, 0);
        const struct mech_vec3 want = closed_form(r0, v0, q->scene.omega, t);
        worst = fmax(worst, mech_vec3_norm(mech_vec3_sub(r->rotating[i], want)));
        CHECK(mech_vec3_norm(mech_vec3_sub(r->rotating_exact[i], want)) <=
              1e-14 * (1 + mech_vec3_norm(want)));
        CHECK(mech_vec3_norm(
                  mech_vec3_sub(r->inertial[i], mech_vec3_add(r0, mech_vec3_scale(v0, t)))) <=
              1e-15 * (1 + mech_vec3_norm(want)));
    }
    CHECK(worst <= tol);
    if (!(worst <= tol)) fprintf(stderr, "  worst %.3g > %.3g\n", worst, tol);
    return s;
}

static void check_through_center(void)
{
    const double w = 1.0, r1 = 1.0, m = 1.0;
    struct mech_rotating_table_request q = request(MECH_TABLE_THROUGH_CENTER, w);
    const struct mech_vec3 r0 = {0, r1, 0}, v0 = {0, -2 * r1 * w / MECH_PI, 0};
    struct mech_rotating_table_scene *s = run_against_closed_form(&q, r0, v0, MECH_PI / w, 1e-6);
    if (!s) return;
    CHECK(strcmp(s->experiment, "through_center") == 0);
    /* after half a turn the puck is back where it started, seen from the table */
    CHECK(mech_vec3_norm(mech_vec3_sub(s->result.end_rotating, r0)) <= 1e-6);
    /* F' = -m w x (w x r) - 2 m w x v' with v' = v0 - w x r0 = (w r1, v0.y, 0) */
    const double f = m * w * w * r1;
    CHECK_CLOSE(s->result.centrifugal.y, f, 1e-15, 0);
    CHECK_CLOSE(s->result.coriolis.x, -4 / MECH_PI * f, 1e-15, 0);
    CHECK_CLOSE(s->result.coriolis.y, -2 * f, 1e-15, 0);
    CHECK_CLOSE(s->result.total.x, -4 / MECH_PI * f, 1e-15, 0);
    CHECK_CLOSE(s->result.total.y, -f, 1e-15, 0);
    CHECK_CLOSE(s->result.v0_rotating.x, w * r1, 1e-15, 0);
    mech_rotating_table_scene_free(s);
}

static void check_at_rest(void)
{
    const double w = -2.0, r1 = 3.0, m = 2.5;
    struct mech_rotating_table_request q = request(MECH_TABLE_AT_REST, w);
    q.scene.radius = r1;
    q.scene.mass = m;
    q.scene.samples = 7;
    const struct mech_vec3 r0 = {0, r1, 0}, v0 = {0, 0, 0};
    struct mech_rotating_table_scene *s =
        run_against_closed_form(&q, r0, v0, 2 * MECH_PI / fabs(w), 3e-6);
    if (!s) return;
    /* a circle of radius r1 seen from the table */
    for (size_t i = 0; i < s->result.n_samples; i++)
        CHECK_CLOSE(mech_vec3_norm(s->result.rotating[i]), r1, 1e-6, 0);
    CHECK_CLOSE(s->result.total.x, 0, 0, 1e-14);
    CHECK_CLOSE(s->result.total.y, -m * w * w * r1, 1e-15, 0);
    CHECK_CLOSE(s->result.coriolis.y, -2 * m * w * w * r1, 1e-15, 0);
    mech_rotating_table_scene_free(s);
}

static void check_custom(void)
{
    struct mech_rotating_table_request q = request(MECH_TABLE_CUSTOM, 1.5);
    const struct mech_vec3 r0 = {1, 2, 0}, v0 = {0.5, -1, 0.2};
    q.scene.r0 = r0;
    q.scene.v0 = v0;
    q.scene.t_end = 3;
    q.scene.samples = 9;
    q.has_position = q.has_velocity = q.has_t_end = 1;
    struct mech_rotating_table_scene *s = run_against_closed_form(&q, r0, v0, 3, 1e-6);
    if (!s) return;
    CHECK(strcmp(s->experiment, "custom") == 0);
    CHECK(s->result.max_position_error <= 1e-6);
    mech_rotating_table_scene_free(s);
}

static void expect(const struct mech_rotating_table_request *q, enum mech_status st,
                   const char *param, const char *text)
{
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    struct mech_rotating_table_scene *s = (struct mech_rotating_table_scene *)&b; /* not NULL */
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_rotating_table_scene(q, &b, &s, &e), st);
    CHECK(s == NULL);
    CHECK(strcmp(e.param, param) == 0);
    CHECK(strstr(e.text, text) != NULL);
    if (strcmp(e.param, param) || !strstr(e.text, text))
        fprintf(stderr, "  got '%s': %s\n", e.param, e.text);
}

static void check_refusals(void)
{
    struct mech_rotating_table_request q = request(MECH_TABLE_CUSTOM, 1);
    q.has_position = q.has_t_end = 1;
    q.scene.t_end = 1;
    expect(&q, MECH_EINVAL, "", "needs velocity");
    q.has_position = 0;
    expect(&q, MECH_EINVAL, "", "needs position");
    q = request(MECH_TABLE_AT_REST, 1);
    q.has_t_end = 1;
    expect(&q, MECH_EINVAL, "t_end", "only for experiment \"custom\"");
    q = request(MECH_TABLE_THROUGH_CENTER, 1);
    q.has_velocity = 1;
    expect(&q, MECH_EINVAL, "velocity", "only for experiment");
    q = request(MECH_TABLE_THROUGH_CENTER, 0);
    expect(&q, MECH_EDOMAIN, "omega", "must rotate");
    q = request(MECH_TABLE_THROUGH_CENTER, 1);
    q.scene.samples = 1;
    expect(&q, MECH_EDOMAIN, "samples", "samples");
    q.scene.samples = (size_t)-1; /* no allocation of that size: the run refuses it */
    expect(&q, MECH_EDOMAIN, "samples", "samples");
    q = request(MECH_TABLE_THROUGH_CENTER, 1);
    q.scene.mass = 0;
    expect(&q, MECH_EDOMAIN, "mass", "mass");
    q = request(MECH_TABLE_AT_REST, 1);
    q.scene.radius = -1;
    expect(&q, MECH_EDOMAIN, "radius", "radius");
    q = request(MECH_TABLE_THROUGH_CENTER, NAN);
    expect(&q, MECH_EDOMAIN, "omega", "omega");
    /* a step budget too small for the run */
    q = request(MECH_TABLE_THROUGH_CENTER, 1);
    struct mech_budget tiny = mech_budget_make(3, 600.0);
    struct mech_rotating_table_scene *s = NULL;
    enum mech_status st = mech_rotating_table_scene(&q, &tiny, &s, NULL);
    CHECK(st == MECH_EBUDGET && s == NULL);
    CHECK_EQ_INT(mech_rotating_table_scene(NULL, &tiny, &s, NULL), MECH_EINVAL);
    CHECK_EQ_INT(mech_rotating_table_scene(&q, &tiny, NULL, NULL), MECH_EINVAL);
    mech_rotating_table_scene_free(NULL);
}

/* A dry run chooses and integrates nothing; the largest table still answers finitely. */
static void check_dry_run_and_extremes(void)
{
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    struct mech_rotating_table_request q = request(MECH_TABLE_THROUGH_CENTER, 0.5);
    q.scene.dry_run = 1;
    struct mech_rotating_table_scene *s = NULL;
    CHECK_EQ_INT(mech_rotating_table_scene(&q, &b, &s, NULL), MECH_OK);
    if (s) {
        CHECK_EQ_INT(s->result.n_samples, 0);
        CHECK(s->result.run.stats.steps == 0);
        mech_rotating_table_scene_free(s);
    }
    q = request(MECH_TABLE_THROUGH_CENTER, 1e6);
    q.scene.radius = 1e15;
    q.scene.samples = 3;
    const struct mech_vec3 r0 = {0, 1e15, 0}, v0 = {0, -2e21 / MECH_PI, 0};
    s = run_against_closed_form(&q, r0, v0, MECH_PI / 1e6, 1e15 * 1e-6);
    if (s) {
        CHECK_CLOSE(s->result.total.y, -1e27, 1e-15, 0);
        mech_rotating_table_scene_free(s);
    }
}

int main(void)
{
    gsl_set_error_handler_off();
    check_through_center();
    check_at_rest();
    check_custom();
    check_refusals();
    check_dry_run_and_extremes();
    TEST_MAIN_END();
}
