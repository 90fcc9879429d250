/* kin_request.h — request readers shared by the particle-kinematics
 * operations (see kin_request.c). Each returns 1 on success and 0 after
 * recording the error on the call (a validation or domain error at the JSON
 * pointer given, or the core's error under it). */
#ifndef API_KIN_REQUEST_H
#define API_KIN_REQUEST_H

#include <jansson.h>

#include "endpoint.h"
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

#endif
