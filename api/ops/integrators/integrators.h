/* integrators.h — GET /v1/integrators, a GET route of the route table
 * (api_route_integrators: no body, no schema). */
#ifndef API_EP_INTEGRATORS_H
#define API_EP_INTEGRATORS_H

#include <jansson.h>

/* The catalog of ODE methods and accuracy presets:
 *   {"methods": [{name, order, adaptive, symplectic, implicit, symmetric,
 *                 second_order, settings, doc, reference}],
 *    "accuracy_presets": [{name, promise, velocity_free: {method, rtol},
 *                          velocity_dependent: {method, rtol}, doc}],
 *    "target_error": how a target maps to a method, "default": ...}
 * from the const registry (mech/ode/ode.h) and the presets (mech/frames/trajectory.h).
 * New reference (NULL only when out of memory). Thread-safe, deterministic. */
json_t *api_integrators_catalog(void);

#endif
