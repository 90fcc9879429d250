/* inertia_request.h — a POST /v1/rigid/inertia request body read into core's
 * parts and computed by core/rigid/inertia.c. Shared by /v1/rigid/inertia and
 * /v1/rigid/rotate (whose "inertia" member is such a request), so neither
 * operation calls the other through JSON: a handler calls core, never
 * another route. */
#ifndef API_INERTIA_REQUEST_H
#define API_INERTIA_REQUEST_H

#include <jansson.h>

#include "run/endpoint.h"
#include "mech/rigid/inertia.h"
#include "mech/rotation/vector_algebra.h"

struct api_inertia_body {
    size_t n;                                /* parts */
    struct mech_inertia_part *parts;         /* n, owned (meshes too) */
    struct mech_inertia_part_props *props;   /* n, owned: each part's own contribution */
    struct mech_inertia result;              /* the whole body */
    int has_omega;                           /* the request gave "omega" (rad/s, scene axes) */
    struct mech_vec3 omega, angular_momentum; /* with has_omega: omega and L = I omega */
    double kinetic_energy;                   /* J, with has_omega */
    int has_pair;                            /* with has_omega: mech_vector_pair(omega, L) succeeded */
    struct mech_vector_pair pair;            /* omega and L: angle, omega x L */
};

/* The request's name of a shape ("box"); "" for a value out of range. */
const char *api_inertia_shape_name(enum mech_inertia_shape s);

/* Read `body` (an inertia request, schema-validated with defaults filled in:
 * bodies[], optional origin [m] and omega [rad/s]) into *out and compute the
 * body's tensor, principal axes and, with omega, L and the kinetic energy.
 * Returns 1 on success; 0 after recording why in c (errors at pointers
 * relative to `body`: "/bodies/2/mass", or a budget / numerical / internal
 * problem). *out is written either way and must be released with
 * api_inertia_body_free. */
int api_inertia_body_compute(struct api_call *c, const json_t *body,
                             struct api_inertia_body *out);

/* 1 when every number the /v1/rigid/inertia answer would carry for b is
 * finite (the answer's own non-finite check), else 0. */
int api_inertia_body_finite(const struct api_inertia_body *b);

/* Free what api_inertia_body_compute allocated; b may be zeroed. */
void api_inertia_body_free(struct api_inertia_body *b);

#endif
