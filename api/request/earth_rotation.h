/* earth_rotation.h — the Earth's rotation rate of a request, given either as
 * a rate under the operation's own key (omega_magnitude, omega_earth) or as
 * a sidereal_day in seconds (rate = 2 pi / sidereal_day), at most one of the
 * two: the rule /v1/earth/gravity introduced (its omega | sidereal_day), so
 * every operation with an Earth accepts the notes' "one sidereal day"
 * wording. Shared by the trajectory's Earth frame, the scenes and
 * /v1/small-oscillations' Foucault pendulum. */
#ifndef API_EARTH_ROTATION_H
#define API_EARTH_ROTATION_H

#include <jansson.h>

#include "run/endpoint.h"

/* The rotation rate (rad/s) of obj: 2 pi / obj.sidereal_day when given, else
 * obj[rate_key] or def. Both given: a validation error at
 * prefix + "/sidereal_day" and 0 returned; 1 otherwise. obj may be NULL
 * (then def). Borrowed references only; nothing allocated. */
int api_earth_rotation(struct api_call *c, const json_t *obj, const char *prefix,
                       const char *rate_key, double def, double *omega);

#endif
