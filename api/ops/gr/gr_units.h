/* gr_units.h — the units block the general-relativity operations share
 * (api/ops/gr/schwarzschild.c, api/ops/gr/geodesic.c): M and units read from
 * the request into mech/gr/gr_units.h's set-up, and the answer's "units" object. */
#ifndef API_EP_GR_UNITS_H
#define API_EP_GR_UNITS_H

#include "run/endpoint.h"
#include "mech/gr/gr_units.h"

/* Read /M and /units (schema-validated) and set up the units with
 * mech_gr_units_init. Returns 1, or 0 after recording the problem at /M
 * (SI without a mass; a mass whose GM/c^2 is not a usable length). */
int api_gr_units_read(struct api_call *c, const json_t *body, struct mech_gr_units *u);

/* The answer's "units" object: the system, the unit of each kind of
 * quantity, c, and with a mass GM, GM/c^2, GM/c^3 and the mass in kg.
 * Returns a new reference. */
json_t *api_gr_units_json(struct api_call *c, const struct mech_gr_units *u);

#endif
