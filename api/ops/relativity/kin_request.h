/* kin_request.h — request readers and answer encoders shared by the
 * particle-kinematics operations (see api/ops/relativity/kin_request.c). Each returns 1 on success and 0 after
 * recording the error on the call (a validation or domain error at the JSON
 * pointer given, or the core's error under it). */
#ifndef API_KIN_REQUEST_H
#define API_KIN_REQUEST_H

#include <jansson.h>

#include "run/endpoint.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"

/* The request's "energy_unit" (default filled by the schema) into *u. */
int api_kin_unit_of(struct api_call *c, const json_t *body, enum mech_energy_unit *u);

/* Mass (in unit u, units of energy/c^2) of a particle field: a name from the
 * particle table or a number >= 0. ptr names the field in errors. */
int api_kin_mass_of(struct api_call *c, const json_t *v, const char *ptr, enum mech_energy_unit u,
                    double *m);

/* The state of motion of a particle of mass m from the object at ptr: at most
 * one of energy, kinetic_energy, momentum, velocity; none given: at rest
 * (*given = 0). */
int api_kin_motion_of(struct api_call *c, const json_t *obj, const char *ptr, double m,
                      struct mech_kin_motion *k, int *given);

/* Angle from key (radians) or key_deg (degrees) of obj, at most one; ptr names
 * obj in errors. Returns 1 if present (value in *rad), 0 if absent, -1 after
 * recording an error. */
int api_kin_angle_of(struct api_call *c, const json_t *obj, const char *key, const char *ptr,
                     double *rad);

/* Encoders (new references; NULL only when memory runs out): a particle's
 * mass, energy, kinetic_energy, momentum and (massive) its precise speed; a
 * system's centre-of-momentum velocity (null when the total is light-like);
 * the *_deg companion of an angle in radians. */
json_t *api_kin_describe_motion(struct api_call *c, const struct mech_kin_motion *k);
json_t *api_kin_describe_cm(struct api_call *c, const struct mech_kin_system *s);
json_t *api_kin_deg_of(struct api_call *c, double rad);

/* A finished answer: res itself, or (res NULL: memory ran out) the 500 recorded
 * and NULL. */
json_t *api_kin_finish(struct api_call *c, json_t *res);

#endif
