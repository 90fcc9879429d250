/* mech/relativity/em_fields.h — electric and magnetic fields under a Lorentz boost, with
 * the two field invariants, kept precise up to γ = 1e15 and beyond.
 *
 * Convention (notes "Lorentz Transformation of the Fields", with the passive
 * boost of §3.3 and mech/relativity/boost.h): the fields at the same event, seen from the
 * frame moving with velocity βc n. Heaviside–Lorentz units with c = 1 (the
 * notes' units):
 *   E'∥ = E∥,  B'∥ = B∥,  E'⊥ = γ(E + β×B)⊥,  B'⊥ = γ(B − β×E)⊥;
 * SI (E in V/m, B in T): the same with B replaced by cB, i.e.
 *   E'⊥ = γ(E + v×B)⊥,  B'⊥ = γ(B − v×E/c²)⊥.
 * (Check: a charge at rest has only E; in the new frame it moves with −βc,
 * and B' = −β×E' is the field of a moving charge, u×E/c² with u = −βc.)
 *
 * Precision: the components perpendicular to n combine into
 * P = E⊥ + n×B and M = E⊥ − n×B, which scale exactly as P' = e^{η}P,
 * M' = e^{−η}M (the field analogue of light-cone components); each output is
 * taken from that form or from the γ − 1 form, whichever has the smaller
 * error bound. The invariants after the boost come from those light-cone
 * products, E'² − B'² = E∥² − B∥² + P'·M' and E'·B' = E∥B∥ + ½ n·(M'×P'),
 * with error-free products and compensated sums, so before and after agree to
 * a few 1e-16 of (|E|² + |B|²) at any γ (measured: ≤ 5.3e-16 up to γ = 1e15).
 *
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_EM_FIELDS_H
#define MECH_EM_FIELDS_H

#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Speed of light in m/s (exact, SI definition of the metre). */
#define MECH_EM_C MECH_C /* the speed of light of mech/base/constants.h, under the name api/ uses */

enum mech_em_units {
    MECH_EM_HEAVISIDE_LORENTZ = 0, /* c = 1: E and B in one unit */
    MECH_EM_SI = 1                 /* E in V/m, B in T */
};

struct mech_em_invariants {
    double e2_minus_b2; /* E² − B² (HL) or E² − c²B² (SI, V²/m²) */
    double e_dot_b;     /* E·B (HL) or E·B (SI, V·T/m) */
};

struct mech_em_boosted {
    struct mech_vec3 e, b;            /* the fields in the moving frame */
    struct mech_em_invariants before; /* from the given fields */
    struct mech_em_invariants after;  /* from the boosted light-cone combinations */
    double scale2;                    /* |E|² + |B|² (SI: |E|² + c²|B|²), the field scale² */
};

/* The two invariants of fields E, B (compensated: accurate to about one
 * rounding of the result plus 1e-32 of the field scale squared). Cannot fail;
 * results overflow only for |E| or c|B| beyond about 1e150. */
struct mech_em_invariants mech_em_invariants_of(struct mech_vec3 e, struct mech_vec3 b,
                                                enum mech_em_units units);

/* Boost fields E, B (units as `units` says) into the frame moving with the
 * velocity of `boost`. Statuses: MECH_OK; MECH_EINVAL (NULL arguments, param
 * "E"/"B" for non-finite fields); MECH_ENUMERIC if a result is not finite
 * (fields beyond about 1e150 at large γ). out is written only on success. */
enum mech_status mech_em_fields_boost(const struct mech_boost *boost, struct mech_vec3 e,
                                      struct mech_vec3 b, enum mech_em_units units,
                                      struct mech_em_boosted *out, struct mech_error *err);

#endif
