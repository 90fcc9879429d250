/* test_auto_model.c — "fictitious": "auto" (mech_trajectory_model_select):
 * on scenes where each fictitious term in turn is and is not negligible at
 * the requested accuracy, the estimate includes exactly the terms that
 * matter, and the answer with the chosen terms agrees with the all-terms
 * answer to the requested accuracy (relative to the scene's position scale).
 * Also: the left-out term's real effect stays below its estimate (the bound
 * is honest); a frame without rotation carries no rotation term; planar
 * scenes are integrated in two dimensions and agree with three; the Euler
 * term against the exact free particle in a frame with w(t) = w0 + w' t; the
 * translational term against r0 + v0 t + (g - A) t^2/2; Lorentz (cyclotron
 * circle, E x B drift, energy with -q E.r) and the third-body tide (first
 * order in r/d at 1 m from the Moon's distance, where the naive difference
 * loses every digit).
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "mech/frames/reference.h"
#include "mech/base/constants.h"
#include "mech/frames/trajectory.h"
#include "testlib.h"

static const double G0 = 9.80665;
static const double W_E = MECH_EARTH_OMEGA_SIDEREAL;

enum { NS = 201 };
static double ts[NS];
static struct mech_vec3 pos[NS], vel[NS], pos2[NS], vel2[NS];
static struct mech_force forces[4];

static struct mech_budget budget(void)
{
    return mech_budget_make(20000000, 600.0);
}

/* Run p with method/opt chosen for `target` and fictitious = mask. */
static enum mech_status run_at(struct mech_trajectory_problem p, unsigned mask, double target,
                               struct mech_vec3 *ps, struct mech_vec3 *vs,
                               struct mech_trajectory_result *r)
{
    struct mech_trajectory_choice ch;
    struct mech_error e;
    mech_error_clear(&e);
    p.fictitious = mask;
    CHECK_EQ_INT(mech_trajectory_choose(&p, target, &ch, &e), MECH_OK);
    p.method = ch.method;
    p.opt = ch.opt;
    struct mech_budget b = budget();
    memset(r, 0, sizeof *r);
    r->t = ts;
    r->position = ps;
    r->velocity = vs;
    enum mech_status st = mech_trajectory_integrate(&p, &b, r, &e);
    if (st != MECH_OK) fprintf(stderr, "run failed: %s\n", e.text);
    return st;
}

static double max_diff(const struct mech_vec3 *a, const struct mech_vec3 *b, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, mech_vec3_norm(mech_vec3_sub(a[i], b[i])));
    return m;
}

/* The core property: at `target`, auto picks `want_mask` among the
 * applicable terms, and auto's answer agrees with all terms to the target
 * (positions relative to L = max |r|, velocities to V = max |v|); a term left
 * out moves the answer by no more than its estimate. */
static void check_auto(const char *name, struct mech_trajectory_problem p, double target,
                       unsigned want_mask)
{
    struct mech_trajectory_model m;
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_budget b = budget();
    CHECK_EQ_INT(mech_trajectory_model_select(&p, target, &b, &m, &e), MECH_OK);
    if (m.fictitious != want_mask)
        fprintf(stderr, "%s at %g: chose 0x%x, want 0x%x\n", name, target, m.fictitious, want_mask);
    CHECK_EQ_INT(m.fictitious, want_mask);
    unsigned all = 0;
    for (int k = 0; k < MECH_TRAJECTORY_N_FICTITIOUS; k++) {
        CHECK(m.terms[k].term != NULL && m.terms[k].reason[0] != '\0');
        if (m.terms[k].applicable) all |= 1u << k;
    }
    struct mech_trajectory_result ra, rall;
    CHECK_EQ_INT(run_at(p, m.fictitious, target, pos, vel, &ra), MECH_OK);
    CHECK_EQ_INT(run_at(p, all, target, pos2, vel2, &rall), MECH_OK);
    CHECK_EQ_INT(ra.n_samples, rall.n_samples);
    const double dr = max_diff(pos, pos2, ra.n_samples), dv = max_diff(vel, vel2, ra.n_samples);
    const double L = rall.max_radius, V = rall.max_speed;
    printf("%-34s target %.0e: terms 0x%x of 0x%x, |auto - all| = %.3g m (%.2g rel), %.3g m/s "
           "(%.2g rel)\n",
           name, target, m.fictitious, all, dr, dr / L, dv, dv / V);
    CHECK(dr <= target * L);
    CHECK(dv <= target * V);
    /* the estimate bounds the real effect of what was left out (plus the two
     * runs' integration errors, each within target) */
    double est_r = 0.0, est_v = 0.0;
    for (int k = 0; k < MECH_TRAJECTORY_N_FICTITIOUS; k++)
        if (m.terms[k].applicable && !m.terms[k].included) {
            est_r += m.terms[k].position_effect;
            est_v += m.terms[k].velocity_effect;
            CHECK(strstr(m.terms[k].reason, "estimated effect") != NULL);
        }
    CHECK(dr <= est_r + 2.0 * target * L);
    CHECK(dv <= est_v + 2.0 * target * V);
}

static struct mech_trajectory_problem drop(double h, double lat_deg)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    p.position = mech_vec3_make(0, 0, h);
    p.frame.type = MECH_FRAME_EARTH;
    p.frame.latitude_deg = lat_deg;
    p.frame.omega_magnitude = W_E;
    forces[0].type = MECH_FORCE_UNIFORM_GRAVITY;
    forces[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -G0);
    p.forces = forces;
    p.n_forces = 1;
    p.t_end = sqrt(2.0 * h / G0) * 0.999; /* just before landing */
    p.samples = 101;
    p.reduce_planar = 1;
    return p;
}

/* The example: the centrifugal term of a 100 m drop (|a| ~ W^2 h =
 * 5.3e-7 m/s^2, effect ~5e-6 m = 5e-8 of 100 m) is negligible at 1e-6 and
 * not at 1e-12; the Coriolis term (effect ~2 cm) never is at these. */
static void test_centrifugal_drop(void)
{
    struct mech_trajectory_problem p = drop(100.0, 32.0);
    check_auto("100 m drop (centrifugal)", p, 1e-6, MECH_FICTITIOUS_CORIOLIS);
    check_auto("100 m drop (centrifugal)", p, 1e-12,
               MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL);
    /* the reason of the left-out term names the numbers */
    struct mech_trajectory_model m;
    struct mech_budget b = budget();
    CHECK_EQ_INT(mech_trajectory_model_select(&p, 1e-6, &b, &m, NULL), MECH_OK);
    CHECK(!m.terms[1].included && m.terms[1].position_effect > 1e-6 &&
          m.terms[1].position_effect < 1e-5);
    /* |a_cf| <= W^2 h (the displacement's distance to the axis is <= h) */
    CHECK(m.terms[1].accel_bound <= W_E * W_E * 100.0 * 1.0001);
    CHECK_CLOSE(m.position_scale, 100.0, 1e-9, 0);
    printf("  left out: %s\n", m.terms[1].reason);
    CHECK(!m.terms[2].applicable && !m.terms[3].applicable); /* earth: no Euler, no A */
}

/* Coriolis: a 5 cm drop (t = 0.1 s; 2 W v t^2/2 ~ 7e-7 m = 1.5e-5 of 5 cm)
 * is negligible at 1e-3 and not at 1e-8; the centrifugal never is here. */
static void test_coriolis_short_drop(void)
{
    struct mech_trajectory_problem p = drop(0.05, 45.0);
    check_auto("5 cm drop (coriolis)", p, 1e-3, 0u);
    check_auto("5 cm drop (coriolis)", p, 1e-8, MECH_FICTITIOUS_CORIOLIS);
    /* with nothing rotating left, the scene is velocity-free and planar */
    struct mech_trajectory_result r;
    CHECK_EQ_INT(run_at(p, 0u, 1e-3, pos, vel, &r), MECH_OK);
    CHECK_EQ_INT(r.dimensions, 2);
    /* a long projectile flight: Coriolis matters even at 1e-3 */
    struct mech_trajectory_problem q = drop(0.0, 45.0);
    q.velocity = mech_vec3_make(300, 0, 300);
    q.t_end = 60.0;
    check_auto("300 m/s projectile (coriolis)", q, 1e-3, MECH_FICTITIOUS_CORIOLIS);
}

/* A rotating frame whose rate changes: w(t) = (0, 0, w0 + w' t). A free
 * particle (no force) is a straight line inertially; in the frame its
 * components are that line rotated passively by theta(t) = w0 t + w' t^2/2.
 * All terms vs exact to 1e-9; auto at 1e-3 drops the small Euler term,
 * at 1e-8 keeps it. */
static void test_euler(void)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 2.0;
    p.frame.type = MECH_FRAME_ROTATING;
    const double w0 = 1e-2, wd = 5e-7;
    p.frame.omega = mech_vec3_make(0, 0, w0);
    p.frame.omega_dot = mech_vec3_make(0, 0, wd);
    p.position = mech_vec3_make(10, 0, 0);
    p.velocity = mech_vec3_make(0, 0.5, 0.1);
    p.t_end = 20.0;
    p.samples = 101;
    /* Euler |a| = w' |r| ~ 5e-7 x 15: effect ~ 1.5e-3 m of ~15 m (1e-4) and
     * 1.5e-4 m/s of ~0.6 m/s (2.5e-4): below 1e-2 / 10, above 1e-8 / 10 */
    check_auto("free particle, w' (euler)", p, 1e-2,
               MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL);
    check_auto("free particle, w' (euler)", p, 1e-8,
               MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL | MECH_FICTITIOUS_EULER);
    struct mech_trajectory_result r;
    CHECK_EQ_INT(run_at(p, MECH_FICTITIOUS_ALL, 1e-12, pos, vel, &r), MECH_OK);
    /* inertial: r_I = r0 + (v0 + w0 x r0) t */
    const struct mech_vec3 W0 = p.frame.omega;
    const struct mech_vec3 vi = mech_vec3_add(p.velocity, mech_vec3_cross(W0, p.position));
    double err = 0.0;
    for (size_t i = 0; i < r.n_samples; i++) {
        const double t = ts[i], th = w0 * t + 0.5 * wd * t * t;
        struct mech_vec3 ri = mech_vec3_add(p.position, mech_vec3_scale(vi, t));
        struct mech_vec3 rr =
            mech_vec3_make(ri.x * cos(th) + ri.y * sin(th), -ri.x * sin(th) + ri.y * cos(th), ri.z);
        err = fmax(err, mech_vec3_norm(mech_vec3_sub(pos[i], rr)));
    }
    printf("free particle with w(t): max |r - exact| = %.3g m (|r| ~ 12 m)\n", err);
    CHECK(err < 1e-9);
    /* time-dependent rotation: nothing is conserved, and the answer says so */
    CHECK_EQ_INT(r.invariants[0].conserved, 0);
    CHECK(strstr(r.invariants[0].note, "not conserved") != NULL);
    CHECK_EQ_INT(r.n_invariants, 1);
    /* w and w' along z, r0, v0 not in a plane normal to z: 3-D */
    CHECK_EQ_INT(r.dimensions, 3);
}

/* An accelerating, non-rotating frame: only the translational term is
 * applicable; exact r = r0 + v0 t + (g - A) t^2/2. */
static void test_translational(void)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    p.frame.type = MECH_FRAME_ROTATING; /* omega = 0: an accelerating frame */
    p.frame.acceleration = mech_vec3_make(1e-4, 0, 2e-4);
    forces[0].type = MECH_FORCE_UNIFORM_GRAVITY;
    forces[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -G0);
    p.forces = forces;
    p.n_forces = 1;
    p.position = mech_vec3_make(0, 0, 0);
    p.velocity = mech_vec3_make(20, 0, 30);
    p.t_end = 6.0;
    p.samples = 61;
    p.reduce_planar = 1;
    /* |A| T^2/2 = 2.2e-4 x 18 = 4e-3 m of ~120 m: 3.4e-5 relative */
    check_auto("accelerating frame (translational)", p, 1e-3, 0u);
    check_auto("accelerating frame (translational)", p, 1e-8, MECH_FICTITIOUS_TRANSLATIONAL);
    struct mech_trajectory_model m;
    struct mech_budget b = budget();
    CHECK_EQ_INT(mech_trajectory_model_select(&p, 1e-8, &b, &m, NULL), MECH_OK);
    for (int k = 0; k < 3; k++) {
        CHECK(!m.terms[k].applicable); /* the frame does not rotate: not carried */
        CHECK(strstr(m.terms[k].reason, "not carried") != NULL);
    }
    struct mech_trajectory_result r;
    CHECK_EQ_INT(run_at(p, MECH_FICTITIOUS_ALL, 1e-12, pos, vel, &r), MECH_OK);
    struct mech_vec3 ga = mech_vec3_sub(forces[0].u.uniform_gravity.g, p.frame.acceleration);
    double err = 0.0;
    for (size_t i = 0; i < r.n_samples; i++) {
        struct mech_vec3 ex = mech_vec3_add(mech_vec3_scale(p.velocity, ts[i]),
                                            mech_vec3_scale(ga, 0.5 * ts[i] * ts[i]));
        err = fmax(err, mech_vec3_norm(mech_vec3_sub(pos[i], ex)));
    }
    CHECK(err < 1e-12 * 200);
    /* the uniform-gravity reference absorbs -A, and the Jacobi integral with
     * + m A.r is conserved */
    CHECK_EQ_INT(r.reference.kind, MECH_REFERENCE_EXACT);
    CHECK(r.reference.max_position_error < 1e-10);
    CHECK(r.invariants[0].conserved && r.invariants[0].max_relative_drift < 1e-12);
    /* g, A, r0, v0 all in the x-z plane: two dimensions */
    CHECK_EQ_INT(r.dimensions, 2);
    CHECK_CLOSE(fabs(r.plane_normal.y), 1.0, 1e-15, 0);
}

/* Planar detection: what is and is not planar, and 2-D = 3-D answers. */
static void test_planar(void)
{
    struct mech_trajectory_problem p = drop(100.0, 0.0); /* equator: w = (0, W, 0) */
    p.fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    struct mech_vec3 n;
    CHECK(mech_trajectory_plane(&p, &n));
    CHECK_CLOSE(fabs(n.y), 1.0, 1e-15, 0);
    p.frame.latitude_deg = 32.0; /* w tilted out of every plane holding z */
    CHECK(!mech_trajectory_plane(&p, &n));
    p.fictitious = 0; /* no rotation term modelled: the vertical line is planar */
    CHECK(mech_trajectory_plane(&p, &n));
    /* a Kepler orbit in an oblique plane: 2-D and 3-D agree to round-off level */
    struct mech_trajectory_problem k;
    memset(&k, 0, sizeof k);
    k.mass = 1.0;
    forces[0].type = MECH_FORCE_CENTRAL_GRAVITY;
    forces[0].u.central_gravity.gm = 1.0;
    forces[0].u.central_gravity.center = mech_vec3_make(0, 0, 0);
    k.forces = forces;
    k.n_forces = 1;
    k.position = mech_vec3_make(1, 0, 0);
    k.velocity = mech_vec3_make(0, 0.8, 0.6);
    k.t_end = 10.0;
    k.samples = 101;
    k.method = "rk8pd";
    k.opt.rtol = 1e-12;
    k.opt.atol = 1e-14;
    struct mech_budget b = budget();
    struct mech_trajectory_result r2, r3;
    memset(&r2, 0, sizeof r2);
    memset(&r3, 0, sizeof r3);
    r2.position = pos;
    r3.position = pos2;
    k.reduce_planar = 1;
    CHECK_EQ_INT(mech_trajectory_integrate(&k, &b, &r2, NULL), MECH_OK);
    k.reduce_planar = 0;
    CHECK_EQ_INT(mech_trajectory_integrate(&k, &b, &r3, NULL), MECH_OK);
    CHECK_EQ_INT(r2.dimensions, 2);
    CHECK_EQ_INT(r3.dimensions, 3);
    const double d = max_diff(pos, pos2, r2.n_samples);
    printf("oblique Kepler orbit: |2-D - 3-D| = %.3g (both rk8pd 1e-12), 2-D error vs Kepler "
           "%.3g, 3-D %.3g\n",
           d, r2.reference.max_position_error, r3.reference.max_position_error);
    CHECK(d < 1e-10);
    CHECK(r2.reference.max_position_error < 1e-10);
    /* out of plane by round-off only: the 2-D samples have n.r = 0 to ~1e-16 */
    for (size_t i = 0; i < r2.n_samples; i++)
        CHECK(fabs(mech_vec3_dot(pos[i], r2.plane_normal)) < 1e-15);
    /* a velocity slightly out of the plane of r0 and the force: 3-D */
    k.reduce_planar = 1;
    forces[1].type = MECH_FORCE_UNIFORM_GRAVITY;
    forces[1].u.uniform_gravity.g = mech_vec3_make(0, 1e-3, 0);
    k.n_forces = 2;
    CHECK(!mech_trajectory_plane(&k, &n));
    /* Lorentz: E in the plane and B normal keep it planar; B in the plane does not */
    struct mech_trajectory_problem l;
    memset(&l, 0, sizeof l);
    l.mass = 1.0;
    l.charge = 1.0;
    forces[0].type = MECH_FORCE_LORENTZ;
    forces[0].u.lorentz.E = mech_vec3_make(1, 0, 0);
    forces[0].u.lorentz.B = mech_vec3_make(0, 0, 2);
    l.forces = forces;
    l.n_forces = 1;
    l.velocity = mech_vec3_make(0, 1, 0);
    CHECK(mech_trajectory_plane(&l, &n));
    CHECK_CLOSE(fabs(n.z), 1.0, 0, 0);
    forces[0].u.lorentz.B = mech_vec3_make(0, 2, 0);
    CHECK(!mech_trajectory_plane(&l, &n));
    l.charge = 0.0; /* no charge: the fields do nothing */
    CHECK(mech_trajectory_plane(&l, &n));
}

/* Lorentz: q v x B gyration (radius m v / (q B), angular frequency q B / m)
 * with an E x B drift E/B, exact:
 *   x = (v_perp'/wc) sin(wc t) + vd t, ... — here E = (0, E, 0), B = (0, 0, B),
 *   drift vd = E x B / B^2 = (E/B, 0, 0); in the drifting frame a circle. */
static void test_lorentz(void)
{
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 2.0;
    p.charge = 3.0;
    const double B = 4.0, E = 5.0;
    forces[0].type = MECH_FORCE_LORENTZ;
    forces[0].u.lorentz.E = mech_vec3_make(0, E, 0);
    forces[0].u.lorentz.B = mech_vec3_make(0, 0, B);
    p.forces = forces;
    p.n_forces = 1;
    p.velocity = mech_vec3_make(1, 0, 0.25);
    p.t_end = 10.0;
    p.samples = 101;
    p.method = "rk8pd";
    p.opt.rtol = 1e-13;
    p.opt.atol = 1e-15;
    struct mech_budget b = budget();
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r);
    r.t = ts;
    r.position = pos;
    r.velocity = vel;
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, NULL), MECH_OK);
    const double wc = p.charge * B / p.mass, vd = E / B;
    /* u = v - vd x: u' = (q/m) u x B: rotates clockwise for q B > 0:
     * u = (u0 cos wc t, -u0 sin wc t), u0 = 1 - vd */
    const double u0 = 1.0 - vd;
    double err = 0.0;
    for (size_t i = 0; i < r.n_samples; i++) {
        const double t = ts[i];
        struct mech_vec3 ex =
            mech_vec3_make(vd * t + u0 * sin(wc * t) / wc, u0 * (cos(wc * t) - 1.0) / wc, 0.25 * t);
        err = fmax(err, mech_vec3_norm(mech_vec3_sub(pos[i], ex)));
    }
    printf("Lorentz E x B drift, rk8pd: max |r - exact| = %.3g m, energy drift %.3g\n", err,
           r.invariants[0].max_relative_drift);
    CHECK(err < 1e-10);
    /* energy with -q E.r is conserved (v x B does no work) */
    CHECK(r.invariants[0].conserved);
    CHECK(r.invariants[0].max_relative_drift < 1e-11);
    /* Boris: exact gyration phase for E = 0 up to its known phase error;
     * energy conserved to round-off with pure B */
    forces[0].u.lorentz.E = mech_vec3_make(0, 0, 0);
    p.method = "boris";
    p.opt.dt = 1e-3;
    memset(&r, 0, sizeof r);
    r.position = pos;
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, NULL), MECH_OK);
    printf("Lorentz pure B, boris dt 1e-3: energy drift %.3g\n",
           r.invariants[0].max_relative_drift);
    CHECK(r.invariants[0].max_relative_drift < 1e-13);
    /* gyration: a circle of radius m v_perp / (q B) = 1/6 about (0, -1/6): Boris
     * keeps it to O((wc dt)^2) = 4e-5 */
    const double rg = 1.0 / wc;
    double rerr = 0.0;
    for (size_t i = 0; i < r.n_samples; i++)
        rerr = fmax(rerr, fabs(hypot(pos[i].x, pos[i].y + rg) - rg));
    printf("Lorentz pure B, boris: gyration radius error %.3g (relative %.3g)\n", rerr, rerr / rg);
    CHECK(rerr < 4e-5 * rg);
}

/* Third-body tide: 1 m from the origin with the Moon at 3.844e8 m: the
 * tidal acceleration agrees with the first-order (GM/d^3)(3 (d.r) d/d^2 - r)
 * to O(r/d) = 3e-9 relative (the direct difference of the two attractions
 * would keep no correct digit); at r/d = 0.1 it agrees with the direct
 * formula to 1e-14. Through the trajectory's first sample: model term size. */
static void test_tide(void)
{
    const double gm = MECH_MOON_GM, d = MECH_MOON_DISTANCE;
    struct mech_trajectory_problem p;
    memset(&p, 0, sizeof p);
    p.mass = 1.0;
    forces[0].type = MECH_FORCE_THIRD_BODY_TIDE;
    forces[0].u.third_body_tide.gm = gm;
    forces[0].u.third_body_tide.position = mech_vec3_make(d, 0, 0);
    p.forces = forces;
    p.n_forces = 1;
    p.t_end = 1e-9; /* just the initial acceleration, through the term size */
    p.samples = 2;
    p.method = "rk8pd";
    p.opt.rtol = 1e-10;
    p.opt.atol = 0;
    struct mech_budget b = budget();
    struct mech_trajectory_result r;
    const struct mech_vec3 rs[3] = {{1, 0, 0}, {0, 1, 0}, {0.6, 0.8, 0}};
    for (int k = 0; k < 3; k++) {
        p.position = rs[k];
        memset(&r, 0, sizeof r);
        CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, NULL), MECH_OK);
        /* first order: (gm/d^3) (3 x e_x - r): |a| = (gm/d^3) |(2x, -y, 0)| */
        const double k3 = gm / (d * d * d);
        const double want = k3 * hypot(2.0 * rs[k].x, rs[k].y);
        CHECK_CLOSE(r.terms[0].max_acceleration, want, 1e-8, 0);
    }
    /* far from the origin: the direct formula is accurate there */
    p.position = mech_vec3_make(0.1 * d, 0.05 * d, 0);
    memset(&r, 0, sizeof r);
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, NULL), MECH_OK);
    struct mech_vec3 D = mech_vec3_sub(forces[0].u.third_body_tide.position, p.position);
    double s = mech_vec3_norm(D);
    struct mech_vec3 direct =
        mech_vec3_sub(mech_vec3_scale(D, gm / (s * s * s)), mech_vec3_make(gm / (d * d), 0, 0));
    CHECK_CLOSE(r.terms[0].max_acceleration, mech_vec3_norm(direct), 1e-12, 0);
    /* a tide-raising body at the origin, or the particle on it: domain errors */
    struct mech_error e;
    mech_error_clear(&e);
    p.position = forces[0].u.third_body_tide.position;
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, &e), MECH_EDOMAIN);
    forces[0].u.third_body_tide.position = mech_vec3_make(0, 0, 0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_integrate(&p, &b, &r, &e), MECH_EDOMAIN);
    CHECK(strcmp(e.param, "forces/0/position") == 0);
}

/* mech_term_effect_estimate: the rule and its reason text. */
static void test_estimate_rule(void)
{
    struct mech_term_estimate t;
    mech_term_effect_estimate("centrifugal", 6e-10, 10.0, 100.0, 0.0, 1e-8, 10.0, &t);
    CHECK_CLOSE(t.position_effect, 3e-8, 1e-15, 0);
    CHECK_CLOSE(t.relative_effect, 3e-10, 1e-15, 0);
    CHECK(!t.included); /* 3e-10 <= 1e-9 */
    CHECK(strstr(t.reason, "estimated effect 3e-08 m <= target 1e-08 x 100 m / safety 10") != NULL);
    printf("rule: %s\n", t.reason);
    mech_term_effect_estimate("coriolis", 6e-8, 10.0, 100.0, 0.0, 1e-8, 10.0, &t);
    CHECK(t.included);
    mech_term_effect_estimate("x", 0.0, 1.0, 0.0, 0.0, 1e-8, 10.0, &t);
    CHECK(!t.included);
    mech_term_effect_estimate("x", 1.0, 1.0, 0.0, 0.0, 1e-8, 10.0, &t);
    CHECK(t.included);
    /* bad target: a typed error */
    struct mech_trajectory_problem p = drop(10.0, 10.0);
    struct mech_trajectory_model m;
    struct mech_budget b = budget();
    struct mech_error e;
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_model_select(&p, 0.0, &b, &m, &e), MECH_EINVAL);
    /* inertial: nothing applicable, no first pass */
    p.frame.type = MECH_FRAME_INERTIAL;
    CHECK_EQ_INT(mech_trajectory_model_select(&p, 1e-8, &b, &m, NULL), MECH_OK);
    CHECK(!m.first_pass_done && m.fictitious == 0);
    /* a budget too small for the first pass: a typed budget error */
    p = drop(100.0, 32.0);
    struct mech_budget tiny = mech_budget_make(2, 60.0);
    mech_error_clear(&e);
    CHECK_EQ_INT(mech_trajectory_model_select(&p, 1e-8, &tiny, &m, &e), MECH_EBUDGET);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_estimate_rule();
    test_centrifugal_drop();
    test_coriolis_short_drop();
    test_euler();
    test_translational();
    test_planar();
    test_lorentz();
    test_tide();
    TEST_MAIN_END();
}
