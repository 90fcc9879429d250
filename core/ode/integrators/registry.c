/* integrators/registry.c — the const table of every ODE method libmech
 * offers, in catalog order (a const table: no run-time registration). The API
 * catalog and the README's method table come from these descriptors. Add a
 * method by writing its file and one line in MECH_INTEGRATOR_LIST
 * (integrator.h). */
#include <string.h>

#include "ode/integrators/integrator.h"

#define MECH_INTEGRATOR_ENTRY(name) &mech_integrator_##name,
const struct mech_integrator *const mech_integrator_table[] = {
    MECH_INTEGRATOR_LIST(MECH_INTEGRATOR_ENTRY)
};
#undef MECH_INTEGRATOR_ENTRY
const size_t mech_integrator_count = sizeof mech_integrator_table / sizeof mech_integrator_table[0];

const struct mech_integrator *mech_ode_method_find(const char *name)
{
    if (!name) return NULL;
    for (size_t i = 0; i < mech_integrator_count; i++)
        if (strcmp(mech_integrator_table[i]->name, name) == 0) return mech_integrator_table[i];
    return NULL;
}

size_t mech_ode_method_count(void) { return mech_integrator_count; }

const struct mech_integrator *mech_ode_method_at(size_t i)
{
    return i < mech_integrator_count ? mech_integrator_table[i] : NULL;
}

struct mech_ode_method_info mech_ode_method_describe(const struct mech_integrator *m)
{
    struct mech_ode_method_info info = {
        .name = m->name,
        .order = m->order,
        .adaptive = (m->flags & MECH_INTEGRATOR_ADAPTIVE) != 0,
        .symplectic = (m->flags & MECH_INTEGRATOR_SYMPLECTIC) != 0,
        .implicit = (m->flags & MECH_INTEGRATOR_EXPLICIT) == 0,
        .symmetric = (m->flags & MECH_INTEGRATOR_SYMMETRIC) != 0,
        .second_order = (m->flags & MECH_INTEGRATOR_SECOND_ORDER) != 0,
        .kepler_split = (m->flags & MECH_INTEGRATOR_KEPLER_SPLIT) != 0,
        .doc = m->doc,
        .reference = m->reference ? m->reference : "",
    };
    return info;
}
