/* earth_rotation.c — the Earth's rotation rate as a rate or a sidereal day
 * (see api/request/earth_rotation.h). */
#include "request/earth_rotation.h"
#include "mech/base/constants.h"

#include <stdio.h>


int api_earth_rotation(struct api_call *c, const json_t *obj, const char *prefix,
                       const char *rate_key, double def, double *omega)
{
    const json_t *day = json_object_get(obj, "sidereal_day");
    *omega = api_number(obj, rate_key, def);
    if (!day) return 1;
    /* The rate has a schema default, so the body always has one: ask whether
     * the client gave it. */
    char given[160];
    snprintf(given, sizeof given, "%s/%s", prefix ? prefix : "", rate_key);
    if (api_call_given(c, given)) {
        char ptr[160];
        snprintf(ptr, sizeof ptr, "%s/sidereal_day", prefix ? prefix : "");
        api_call_invalid(c, ptr, "give at most one of %s and sidereal_day (%s = 2 pi / "
                                 "sidereal_day)", rate_key, rate_key);
        return 0;
    }
    *omega = (2.0 * MECH_PI) / json_number_value(day);
    return 1;
}
