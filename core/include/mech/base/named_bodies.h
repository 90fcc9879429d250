/* mech/base/named_bodies.h — the bodies a request may name ("sun", "moon",
 * "earth"), in versioned sets so that a client's answers do not change when
 * the constants are revised: "DE440" (the default: JPL DE440 GMs, Park et al.
 * 2021) and "legacy" (the values mechd used before DE440: the Sun's GM of
 * DE405, the Moon from the fact sheet's rounded mass). Each value carries its
 * source, which every answer that uses a named body states. SI units. */
#ifndef MECH_NAMED_BODIES_H
#define MECH_NAMED_BODIES_H

enum mech_body_set {
    MECH_BODY_SET_DE440 = 0, /* the default */
    MECH_BODY_SET_LEGACY,
};

struct mech_named_body {
    const char *name;   /* "sun", "moon", "earth" */
    double gm;          /* m^3/s^2 */
    double mass;        /* kg, gm / G (legacy Moon: the mass it was given as) */
    double radius;      /* m, mean radius */
    double distance;    /* m, mean distance from the Earth (0 for the Earth) */
    const char *source; /* the values and where they come from, one sentence */
};

/* The set's request name ("DE440", "legacy"); NULL outside the enum. */
const char *mech_body_set_name(enum mech_body_set set);

/* The set named `name`; 0 and *set untouched for an unknown name (the
 * caller's 422 names its field and the allowed values "DE440", "legacy"). */
int mech_body_set_parse(const char *name, enum mech_body_set *set);

/* The body `name` of `set`, or NULL for an unknown name or set. The pointer
 * is to static, read-only data. */
const struct mech_named_body *mech_named_body(enum mech_body_set set, const char *name);

#endif
