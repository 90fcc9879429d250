/* test_relativistic_trajectory.c — special-relativistic dynamics in
 * mech_trajectory_integrate (state (r, u = gamma v)) against the exact
 * uniform-field motions (mech/relativity/charged_motion.h) and closed forms written
 * here:
 *   a proton in B = 1 T at beta = 1e-6, beta = 0.8 and gamma = 1e6: gyration
 *   radius gamma m v/(q B), period 2 pi gamma m/(q B), every sample on the
 *   helix; the Newtonian model at beta = 0.8 is 11 % of the radius off after
 *   10 ns, which is why the model must add the term;
 *   hyperbolic motion in E from rest to gamma = 1e6: x = (c^2/a)(gamma - 1),
 *   u = a t;
 *   the E x B drift and a constant force (uniform gravity m g) with B;
 *   drag, a spring and central gravity (forces without a closed form here):
 *   the relativistic energy (gamma - 1) m c^2 + U conserved where it must be,
 *   and at beta = 1e-9 the answer equal to the Newtonian one to 1e-17;
 *   the closed form ("relativistic_uniform_fields") equal to the integration;
 *   the contract: a speed at or above c, a rotating frame, both corrections
 *   together and a proper velocity without special relativity are refused. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/relativity/charged_motion.h"
#include "mech/frames/closed_form.h"
#include "mech/base/constants.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

#define QP 1.602176634e-19   /* C, exact SI */
#define MP 1.67262192369e-27 /* kg, CODATA 2018 */

static const double c = MECH_C;
enum { NS = 201 };
static double ts[NS];
static struct mech_vec3 pos[NS], vel[NS], pvel[NS];

static struct mech_vec3 V(double x, double y, double z) { return mech_vec3_make(x, y, z); }

static struct mech_force lorentz(struct mech_vec3 E, struct mech_vec3 B)
{
    struct mech_force f;
    memset(&f, 0, sizeof f);
    f.type = MECH_FORCE_LORENTZ;
    f.u.lorentz.E = E;
    f.u.lorentz.B = B;
    return f;
}

static struct mech_trajectory_problem proton(const struct mech_force *f, size_t nf, double t_end)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = MP;
    p.charge = QP;
    p.frame.type = MECH_FRAME_INERTIAL;
    p.forces = f;
    p.n_forces = nf;
    p.t_end = t_end;
    p.samples = NS;
    p.method = "rk8pd";
    p.opt.rtol = 1e-13;
    p.opt.atol = 0.0;
    p.relativity = MECH_RELATIVITY_SPECIAL;
    return p;
}

static enum mech_status run(const struct mech_trajectory_problem *p,
                            struct mech_trajectory_result *r, struct mech_error *e)
{
    struct mech_budget b = mech_budget_make(10000000, 600.0);
    memset(r, 0, sizeof *r);
    r->t = ts;
    r->position = pos;
    r->velocity = vel;
    r->proper_velocity = pvel;
    mech_error_clear(e);
    enum mech_status st = mech_trajectory_integrate(p, &b, r, e);
    if (st != MECH_OK) fprintf(stderr, "  error: %s (%s)\n", e->text, e->param);
    return st;
}

/* The helix of a proton in B = 1 T along z, started at the origin with
 * proper velocity u along x: centre (0, -R), R = u/Omega = gamma m v/(q B),
 * angle Omega t / gamma. Every sample within tol R of it, and u kept. */
static void helix(double u, double tol)
{
    const struct mech_force f = lorentz(V(0, 0, 0), V(0, 0, 1.0));
    const double Om = QP / MP, gamma = sqrt(1.0 + (u / c) * (u / c));
    const double R = u / Om, T = 2.0 * MECH_PI * gamma / Om;
    struct mech_trajectory_problem p = proton(&f, 1, 1.5 * T);
    p.has_proper_velocity = 1;
    p.proper_velocity = V(u, 0, 0);
    p.velocity = V(u / gamma, 0, 0);
    struct mech_trajectory_result r;
    struct mech_error e;
    CHECK(run(&p, &r, &e) == MECH_OK);
    CHECK(r.relativistic);
    CHECK_EQ_INT(r.n_samples, NS);
    CHECK(r.reference.kind == 1 && !strcmp(r.reference.name, "relativistic_uniform_fields"));
    double worst = 0.0, worst_u = 0.0;
    for (size_t i = 0; i < r.n_samples; i++) {
        const double ph = Om * ts[i] / gamma;
        const struct mech_vec3 want = V(R * sin(ph), R * (cos(ph) - 1.0), 0);
        worst = fmax(worst, mech_vec3_norm(mech_vec3_sub(pos[i], want)) / R);
        worst_u = fmax(worst_u, fabs(mech_vec3_norm(pvel[i]) - u) / u);
    }
    CHECK_CLOSE(worst, 0, 0, tol);
    CHECK_CLOSE(worst_u, 0, 0, tol);
    /* the reference report (the exact motion of mech/relativity/charged_motion.h) agrees */
    CHECK_CLOSE(r.reference.max_relative_position_error, 0, 0, tol);
    /* energy (gamma - 1) m c^2 conserved */
    CHECK(r.invariant.conserved);
    CHECK_CLOSE(r.invariant.initial, MP * c * c * (u / c) * (u / c) / (gamma + 1.0), 1e-14, 0);
    CHECK_CLOSE(r.invariant.max_relative_drift, 0, 0, tol);
    /* the same scene from the closed form */
    struct mech_trajectory_result cf;
    memset(&cf, 0, sizeof cf);
    static struct mech_vec3 cpos[NS];
    cf.position = cpos;
    CHECK(mech_trajectory_has_closed_form(&p));
    CHECK(mech_trajectory_closed_form(&p, &cf, &e) == MECH_OK);
    CHECK(!strcmp(cf.method, "closed_form"));
    CHECK(cf.relativistic);
    double d = 0.0;
    for (size_t i = 0; i < NS; i++)
        d = fmax(d, mech_vec3_norm(mech_vec3_sub(cpos[i], pos[i])) / R);
    CHECK_CLOSE(d, 0, 0, tol);
}

int main(void)
{
    gsl_set_error_handler_off();
    struct mech_trajectory_result r;
    struct mech_error e;

    helix(1e-6 * c / sqrt(1.0 - 1e-12), 1e-10);
    helix(4.0 / 3.0 * c, 1e-10);         /* beta = 0.8 */
    helix(sqrt(1e12 - 1.0) * c, 1e-10); /* gamma = 1e6 */

    /* The scene: 0.8 c in 1 T for 10 ns with Newton's F = q v x B is
     * 11 % of the gyration radius off: radius m v/(qB) instead of gamma m v/(qB),
     * phase Omega t instead of Omega t/gamma */
    {
        const struct mech_force f = lorentz(V(0, 0, 0), V(0, 0, 1.0));
        struct mech_trajectory_problem p = proton(&f, 1, 10e-9);
        p.velocity = V(0.8 * c, 0, 0);
        struct mech_trajectory_problem pn = p;
        pn.relativity = 0;
        CHECK(run(&p, &r, &e) == MECH_OK);
        const struct mech_vec3 rel = pos[NS - 1];
        CHECK(run(&pn, &r, &e) == MECH_OK);
        const double R = 4.0 / 3.0 * c * MP / QP;
        const double off = mech_vec3_norm(mech_vec3_sub(pos[NS - 1], rel)) / R;
        /* closed form of both: Newton's circle of radius 0.6 R at rate Omega */
        const double Om = QP / MP, t = 10e-9;
        const struct mech_vec3 newton = V(0.6 * R * sin(Om * t), 0.6 * R * (cos(Om * t) - 1), 0);
        const struct mech_vec3 einstein =
            V(R * sin(0.6 * Om * t), R * (cos(0.6 * Om * t) - 1), 0);
        CHECK_CLOSE(off, mech_vec3_norm(mech_vec3_sub(newton, einstein)) / R, 1e-9, 0);
        CHECK(off > 0.10 && off < 0.12);
        /* the Newtonian run measured the term it left out: q v B/m (1 - 1/gamma)
         * (v perpendicular to the force: the (A.v) v part is 0) */
        CHECK(!r.relativity_terms[0].included);
        CHECK_CLOSE(r.relativity_terms[0].max_acceleration, Om * 0.8 * c * (1.0 - 0.6), 1e-9, 0);
    }

    /* hyperbolic motion in E = 1 MV/m from rest to gamma = 1e6:
     * u = a t, x = (c^2/a)(gamma - 1), gamma - 1 = (a t/c)^2 / (gamma + 1) */
    {
        const double E = 1e6, a = QP * E / MP, t_end = 1e6 * c / a;
        const struct mech_force f = lorentz(V(E, 0, 0), V(0, 0, 0));
        struct mech_trajectory_problem p = proton(&f, 1, t_end);
        CHECK(run(&p, &r, &e) == MECH_OK);
        double worst = 0.0;
        for (size_t i = 1; i < r.n_samples; i++) {
            const double at = a * ts[i], g = sqrt(1.0 + (at / c) * (at / c));
            const double x = c * c / a * ((at / c) * (at / c) / (g + 1.0));
            worst = fmax(worst, fabs(pos[i].x - x) / x);
            worst = fmax(worst, fabs(pvel[i].x - at) / at);
        }
        CHECK_CLOSE(worst, 0, 0, 1e-10);
        CHECK_CLOSE(r.reference.max_relative_position_error, 0, 0, 1e-10);
        /* beta = 1e-6 in the same field: t = 1e-6 c / a */
        p.t_end = 1e-6 * c / a;
        CHECK(run(&p, &r, &e) == MECH_OK);
        const double at = a * p.t_end, g = sqrt(1.0 + (at / c) * (at / c));
        CHECK_CLOSE(pos[NS - 1].x, c * c / a * ((at / c) * (at / c) / (g + 1.0)), 1e-12, 0);
    }

    /* E x B drift at 0.8 c (E = 0.8 c B), and uniform gravity with B (the
     * closed form's constant force): integration against mech/relativity/charged_motion.h */
    {
        const struct mech_force f = lorentz(V(0, 0.8 * c, 0), V(0, 0, 1.0));
        struct mech_trajectory_problem p = proton(&f, 1, 3e-7);
        p.velocity = V(0, 0, 1e7);
        CHECK(run(&p, &r, &e) == MECH_OK);
        CHECK(!strcmp(r.reference.name, "relativistic_uniform_fields"));
        CHECK_CLOSE(r.reference.max_relative_position_error, 0, 0, 1e-10);
        /* the mean drift: x(t) / t -> 0.8 c over many gyrations */
        CHECK_CLOSE(pos[NS - 1].x / ts[NS - 1], 0.8 * c, 0.02, 0);

        struct mech_force fg[2] = {lorentz(V(0, 0, 0), V(0, 0, 1e-7)), {0}};
        fg[1].type = MECH_FORCE_UNIFORM_GRAVITY;
        fg[1].u.uniform_gravity.g = V(0, 0, -9.80665e12);
        struct mech_trajectory_problem q = proton(fg, 2, 1e-4);
        q.velocity = V(1e8, 0, 0);
        CHECK(run(&q, &r, &e) == MECH_OK);
        CHECK(!strcmp(r.reference.name, "relativistic_uniform_fields"));
        CHECK_CLOSE(r.reference.max_relative_position_error, 0, 0, 1e-10);
    }

    /* forces with no closed form here: a spring at beta ~ 0.9 conserves
     * (gamma - 1) m c^2 + k x^2/2; drag makes it fall; at beta = 1e-9 the
     * relativistic run equals the Newtonian one to ~beta^2 */
    {
        struct mech_force fs;
        memset(&fs, 0, sizeof fs);
        fs.type = MECH_FORCE_SPRING;
        fs.u.spring.k = 1.0;
        struct mech_trajectory_problem p = proton(&fs, 1, 1.0);
        p.mass = 1.0;
        p.charge = 0.0;
        p.position = V(1.0, 0, 0);
        p.velocity = V(0, 0.9 * c, 0);
        p.opt.rtol = 1e-12;
        CHECK(run(&p, &r, &e) == MECH_OK);
        CHECK(r.invariant.conserved);
        CHECK_CLOSE(r.invariant.max_relative_drift, 0, 0, 1e-9);
        CHECK_CLOSE(r.invariant.initial, c * c * (1.0 / sqrt(0.19) - 1.0) + 0.5, 1e-12, 0);
        CHECK(r.reference.kind == 0); /* no Newtonian reference for a relativistic run */

        p.velocity = V(0, 1e-9 * c, 0);
        p.position = V(0.3, 0, 0);
        CHECK(run(&p, &r, &e) == MECH_OK);
        const struct mech_vec3 rel = pos[NS - 1];
        struct mech_trajectory_problem pn = p;
        pn.relativity = 0;
        CHECK(run(&pn, &r, &e) == MECH_OK);
        CHECK_CLOSE(mech_vec3_norm(mech_vec3_sub(rel, pos[NS - 1])), 0, 0, 1e-11 * 0.3);
        /* and the Newtonian run sized the term it left out at ~ beta^2 |a| */
        CHECK(r.relativity_terms[0].max_acceleration < 1e-17 * 0.3 * 1.5 * 1.0001);
        CHECK(r.relativity_terms[0].max_acceleration > 0.0);

        struct mech_force fd;
        memset(&fd, 0, sizeof fd);
        fd.type = MECH_FORCE_LINEAR_DRAG;
        fd.u.linear_drag.b = 1e-9;
        struct mech_trajectory_problem q = proton(&fd, 1, 1e-6);
        q.velocity = V(0.99 * c, 0, 0);
        CHECK(run(&q, &r, &e) == MECH_OK);
        CHECK(!r.invariant.conserved);
        CHECK(r.invariant.final < r.invariant.initial);
        /* dp/dt = -b v, p = m u: u falls as d u/dt = -(b/m) u/gamma; with
         * gamma >> 1 the speed stays below c */
        for (size_t i = 0; i < NS; i++) CHECK(mech_vec3_norm(vel[i]) < c);
    }

    /* the contract */
    {
        const struct mech_force f = lorentz(V(0, 0, 0), V(0, 0, 1.0));
        struct mech_trajectory_problem p = proton(&f, 1, 1e-9);
        p.velocity = V(c, 0, 0);
        CHECK(run(&p, &r, &e) == MECH_EDOMAIN);
        CHECK(!strcmp(e.param, "particle/velocity"));
        p.velocity = V(0.5 * c, 0, 0);
        p.frame.type = MECH_FRAME_ROTATING;
        p.frame.omega = V(0, 0, 1);
        CHECK(run(&p, &r, &e) == MECH_EINVAL);
        CHECK(!strcmp(e.param, "relativity"));
        p.frame.type = MECH_FRAME_INERTIAL;
        p.relativity = 0;
        p.has_proper_velocity = 1;
        p.proper_velocity = V(c, 0, 0);
        CHECK(run(&p, &r, &e) == MECH_EINVAL);
        CHECK(!strcmp(e.param, "particle/proper_velocity"));
        p.has_proper_velocity = 0;
        p.relativity = MECH_RELATIVITY_SPECIAL | MECH_RELATIVITY_SCHWARZSCHILD_1PN;
        CHECK(run(&p, &r, &e) == MECH_EINVAL);
        CHECK(!strcmp(e.param, "relativity"));
        /* second-order-only methods cannot integrate (r, u) */
        p.relativity = MECH_RELATIVITY_SPECIAL;
        p.method = "verlet";
        p.opt.dt = 1e-12;
        CHECK(run(&p, &r, &e) != MECH_OK);
    }
    TEST_MAIN_END();
}
