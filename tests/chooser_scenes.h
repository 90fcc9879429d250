/* chooser_scenes.h — the chooser's calibration scenes, defined once for the
 * program that measures the model's constants (bench/bench_calibrate_chooser.c)
 * and the tests that check its predictions (tests/core/ode/test_chooser.c,
 * tests/core/frames/test_chooser_pendulum.c): Kepler orbits from pericentre, the
 * isotropic oscillator, the falling object with Coriolis (notes §1.3), and
 * the Foucault pendulum (notes §1.3). Header-only (static functions, unused
 * ones allowed); needs libmech. */
#ifndef MECHD_TESTS_CHOOSER_SCENES_H
#define MECHD_TESTS_CHOOSER_SCENES_H

#include <math.h>
#include <string.h>

#include "mech/base/budget.h"
#include "mech/base/constants.h"
#include "mech/frames/pendulum.h"
#include "mech/frames/trajectory.h"

#define CS_UNUSED __attribute__((unused))

struct chooser_scene {
    const char *name;
    const char *cls;                  /* the chooser's class of the scene */
    struct mech_trajectory_problem p; /* p.forces = f after cs_fix() */
    struct mech_force f[2];
    double T;      /* the chooser's dynamical time (pericentre time, 1/omega, sqrt(h/g)) */
    double period; /* one orbit or period (s); the fall's duration */
    double S;      /* the scale: atol = rtol x S in calibration runs */
    int exact;     /* 1: the trajectory code has an exact reference */
};

/* Point p.forces at the scene's own array (after copying the struct). */
static CS_UNUSED void cs_fix(struct chooser_scene *s)
{
    s->p.forces = s->f;
    s->p.n_forces = 1;
}

/* Kepler, GM = a = 1 (period 2 pi), from pericentre (1 - e, 0, 0) with
 * v = sqrt((1 + e) / (1 - e)), for `orbits` orbits; calibration: e = 0.5. */
static CS_UNUSED void cs_kepler(struct chooser_scene *s, const char *name, double e, double orbits)
{
    memset(s, 0, sizeof *s);
    s->name = name;
    s->cls = "central_gravity";
    s->f[0].type = MECH_FORCE_CENTRAL_GRAVITY;
    s->f[0].u.central_gravity.gm = 1.0;
    s->p.mass = 1.0;
    s->p.position = mech_vec3_make(1.0 - e, 0, 0);
    s->p.velocity = mech_vec3_make(0, sqrt((1.0 + e) / (1.0 - e)), 0);
    s->period = 2.0 * MECH_PI;
    s->p.t_end = orbits * s->period;
    s->T = sqrt(pow(1.0 - e, 3.0));
    /* 0.61: the scale the calibration of 2026-11-25 ran with at e = 0.5 */
    s->S = e == 0.5 ? 0.61 : fmin(1.0 - e, sqrt((1.0 + e) / (1.0 - e)));
    s->exact = 1;
    cs_fix(s);
}

/* The isotropic oscillator q'' = -q from (1, 0, 0) with v = (0, 0.5, 0)
 * (an ellipse), for `periods` periods of 2 pi. */
static CS_UNUSED void cs_oscillator(struct chooser_scene *s, const char *name, double periods)
{
    memset(s, 0, sizeof *s);
    s->name = name;
    s->cls = "oscillator";
    s->f[0].type = MECH_FORCE_SPRING;
    s->f[0].u.spring.k = 1.0;
    s->p.mass = 1.0;
    s->p.position = mech_vec3_make(1, 0, 0);
    s->p.velocity = mech_vec3_make(0, 0.5, 0);
    s->period = 2.0 * MECH_PI;
    s->p.t_end = periods * s->period;
    s->T = 1.0;
    s->S = 0.5;
    s->exact = 1;
    cs_fix(s);
}

/* That oscillator seen from a frame turning at 0.3 rad/s about z
 * (Coriolis and centrifugal): the `general` class's calibration scene; its
 * exact reference is the inertial ellipse turned back (mech/frames/reference.h). */
static CS_UNUSED void cs_rotating_oscillator(struct chooser_scene *s, const char *name,
                                             double periods)
{
    cs_oscillator(s, name, periods);
    s->cls = "general";
    s->p.frame.type = MECH_FRAME_ROTATING;
    s->p.frame.omega = mech_vec3_make(0, 0, 0.3);
    s->p.fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
}

/* The notes' falling object: 100 m at 32 deg N, g = 9.80665, Coriolis and
 * the centrifugal term of the displacement, until t = sqrt(2 h / g). No
 * exact reference in the trajectory code (compare with a round-off run). */
static CS_UNUSED void cs_fall(struct chooser_scene *s, const char *name)
{
    memset(s, 0, sizeof *s);
    s->name = name;
    s->cls = "uniform_field";
    s->f[0].type = MECH_FORCE_UNIFORM_GRAVITY;
    s->f[0].u.uniform_gravity.g = mech_vec3_make(0, 0, -9.80665);
    s->p.mass = 1.0;
    s->p.position = mech_vec3_make(0, 0, 100);
    s->p.frame.type = MECH_FRAME_EARTH;
    s->p.frame.latitude_deg = 32.0;
    s->p.frame.omega_magnitude = MECH_EARTH_OMEGA_SIDEREAL;
    s->p.fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    s->period = sqrt(2.0 * 100 / 9.80665);
    s->p.t_end = s->period;
    s->T = sqrt(100 / 9.80665); /* the fall lasts sqrt(2) T whatever the height */
    s->S = 31.3;
    s->exact = 0;
    cs_fix(s);
}

/* The Foucault pendulum of the pendulum chooser's calibration: l = 67 m,
 * g = 9.80665, W sidereal, 28 kg, released from rest at amp_deg towards the
 * east, centrifugal term modelled, `swings` planar periods at n steps per
 * swing with method m. */
static CS_UNUSED void cs_foucault(struct mech_foucault_problem *p, double lat, double amp_deg,
                                  double swings, enum mech_pendulum_method m, double n)
{
    memset(p, 0, sizeof *p);
    p->length = 67;
    p->g = 9.80665;
    p->latitude_deg = lat;
    p->omega_magnitude = MECH_EARTH_OMEGA_SIDEREAL;
    p->mass = 28;
    p->amplitude_deg = amp_deg;
    p->centrifugal = 1;
    p->method = m;
    p->t_end = swings * mech_pendulum_period(67, 9.80665, amp_deg * MECH_PI / 180);
    p->steps = (long)ceil(swings * n - 1e-9);
}

/* Run cs_foucault(...) with a generous budget; 1 on success. */
static CS_UNUSED int cs_foucault_run(double lat, double amp_deg, double swings,
                                     enum mech_pendulum_method m, double n,
                                     struct mech_foucault_result *r)
{
    struct mech_foucault_problem p;
    cs_foucault(&p, lat, amp_deg, swings, m, n);
    struct mech_budget b = {1000000000L, mech_clock_seconds() + 600, NULL};
    struct mech_error e;
    mech_error_clear(&e);
    return mech_foucault_integrate(&p, &b, r, &e) == MECH_OK;
}

/* The pendulum's error measure: max(|period - ref| / ref, |rate - ref| / W). */
static CS_UNUSED double cs_foucault_err(const struct mech_foucault_result *r,
                                        const struct mech_foucault_result *ref)
{
    return fmax(fabs(r->period - ref->period) / ref->period,
                fabs(r->precession.slope - ref->precession.slope) / MECH_EARTH_OMEGA_SIDEREAL);
}

#endif
