/* topple.c — POST /v1/rigid/topple (notes §2.11 HW 4: a box falling off its
 * edge).
 * JSON <-> core only: physics and derivations in core/rigid/rigid_problems.c
 * and mech/rigid/rigid_problems.h. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/rigid/rigid_problems.h"

static void set_real(struct api_call *c, json_t *o, const char *k, double x)
{
    json_object_set_new(o, k, api_real(c, x));
}


json_t *api_op_rigid_topple(struct api_call *c, const json_t *body)
{
    double a = api_number(body, "width", 0);
    struct mech_topple t;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_topple_box(api_number_of(body, "mass"), a, api_number(body, "height", a),
                                          api_number_of(body, "g"), &t, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *held = json_object(), *free_ = json_object(),
           *ih = json_object(), *ifr = json_object();
    if (!out || !held || !free_ || !ih || !ifr) {
        json_decref(out);
        json_decref(held);
        json_decref(free_);
        json_decref(ih);
        json_decref(ifr);
        return NULL;
    }
    set_real(c, out, "drop", t.drop);
    set_real(c, held, "omega", t.omega_held);
    set_real(c, ih, "horizontal", t.impulse_held[0]);
    set_real(c, ih, "vertical", t.impulse_held[1]);
    set_real(c, ih, "magnitude", hypot(t.impulse_held[0], t.impulse_held[1]));
    json_object_set_new(held, "impulse", ih);
    set_real(c, free_, "omega", t.omega_free);
    set_real(c, ifr, "vertical", t.impulse_free);
    json_object_set_new(free_, "impulse", ifr);
    json_object_set_new(out, "edge_held", held);
    json_object_set_new(out, "frictionless", free_);
    json_object_set_new(out, "formula",
                        json_string("held: m g (d - b/2) = I_edge w^2/2, I_edge = m(a^2+b^2)/3; "
                                    "frictionless: m g (d - b/2) = (I_cm + m a^2/4) w^2/2"));
    return out;
}
