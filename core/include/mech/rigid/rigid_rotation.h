/* mech/rigid/rigid_rotation.h — rotation of a rigid body about its centre of mass
 * (or a fixed point): Euler's equations in the principal (body) frame with the
 * attitude carried as a unit quaternion, and the exact torque-free solution in
 * Jacobi elliptic functions.
 *
 * Notes §2.7–2.9 (and Landau & Lifshitz, Mechanics, §36–37). In the body frame
 * with principal moments I1, I2, I3 and body angular velocity w,
 *     I1 w1' = (I2 - I3) w2 w3 + G1    (and cyclic)        [Euler's equations]
 * i.e. I w' + w x (I w) = G_body. The attitude is the passive quaternion q
 * (mech/rotation/attitude.h: space -> body components) with dq/dt = 1/2 q (x) (0, w);
 * a space-frame torque is turned into body axes with the current q. The space
 * angular momentum is L = R^T (I w); the kinetic energy T = 1/2 sum I_k w_k^2.
 *
 * The state is integrated dimensionless: time in units of 1/W and w in units
 * of W, W = the rate scale (|w0|, or sqrt(|G| / I_min) when larger, or 1/t_end
 * when both are 0), moments in units of the largest. So rtol/atol apply to
 * O(1) numbers (quaternion components and w / W) whatever the units, and a
 * fixed step dt (s) becomes dt W. The quaternion is integrated as four free
 * components (the flow keeps |q| = 1; numerically |q| drifts at the level of
 * the integration error): every use (torque in body axes, L, output) takes
 * q / |q|, and the drift max ||q| - 1| is reported, never corrected silently.
 *
 * Thread-safety: reentrant; nothing global.
 */
#ifndef MECH_RIGID_ROTATION_H
#define MECH_RIGID_ROTATION_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

/* ---- exact torque-free solution ------------------------------------------ */

enum mech_rigid_exact_kind {
    MECH_RIGID_EXACT_STEADY = 0,  /* w constant: a sphere, w = 0, or w along a principal axis */
    MECH_RIGID_EXACT_SYMMETRIC,   /* two moments equal: w_perp turns at a constant rate */
    MECH_RIGID_EXACT_ELLIPTIC,    /* asymmetric, L^2 != 2 E I2: cn, sn, dn */
    MECH_RIGID_EXACT_SEPARATRIX,  /* asymmetric, L^2 = 2 E I2 (k = 1): sech, tanh */
};

/* Moments closer than this (relative to the largest) are treated as equal. */
#define MECH_RIGID_SYMMETRIC_RTOL 1e-13
/* |L^2 - 2 E I2| below this times L^2 is the separatrix (k = 1). */
#define MECH_RIGID_SEPARATRIX_RTOL 1e-15

/* The closed-form w(t) of a torque-free body (Landau & Lifshitz §37). The body
 * axes are relabelled by a proper signed permutation P (det +1) so that
 * J1 < J2 < J3 (J = the sorted moments) and u = P w; then, with
 * D_j = L^2 - 2 E J_j = sum_i J_i (J_i - J_j) u_i^2 (no cancellation of the
 * j-th term), for D_2 > 0 ("rotation about the largest axis"):
 *   u1 = A1 cn(tau), u2 = s A2 sn(tau), u3 = s A3 dn(tau),  s = sign(u3),
 *   A1^2 = -D3 / (J1 (J3 - J1)), A2^2 = -D3 / (J2 (J3 - J2)), A3^2 = D1 / (J3 (J3 - J1)),
 *   tau = lambda t + tau0, lambda^2 = (J3 - J2) D1 / (J1 J2 J3),
 *   m = k^2 = (J2 - J1) (-D3) / ((J3 - J2) D1);
 * for D_2 < 0 suffixes 1 and 3 swap roles:
 *   u3 = A3 cn, u2 = s A2 sn, u1 = s A1 dn, s = sign(u1),
 *   A3^2 = D1 / (J3 (J3 - J1)), A2^2 = D1 / (J2 (J2 - J1)), A1^2 = -D3 / (J1 (J3 - J1)),
 *   lambda^2 = (J2 - J1) (-D3) / (J1 J2 J3), m = (J3 - J2) D1 / ((J2 - J1) (-D3)).
 * (The signs follow from substituting into Euler's equations with
 * sn' = cn dn, cn' = -sn dn, dn' = -m sn cn.) tau0 = F(phi0 | m) with the
 * amplitude phi0 = atan2(s u2 / A2, u_cn / A_cn), F continued beyond pi/2.
 * The period of w is 4 K(m) / lambda; the intermediate-axis component u2
 * changes sign every 2 K / lambda (a "flip" of the body when it rotates near
 * the intermediate axis). Separatrix (m = 1): cn = dn = sech, sn = tanh,
 * with the sign of the cn component kept explicitly; no period.
 * Symmetric (J_a = J_b != J_c, symmetry axis c): u_c constant and (u_a, u_b)
 * turns at Omega = (J_c - J_a) / J_a u_c (notes §2.9:
 * Omega = (I3 - I12) / I12 w3). */
struct mech_rigid_exact {
    enum mech_rigid_exact_kind kind;
    double p[3][3];       /* signed permutation: u = P w (det +1) */
    double J[3];          /* sorted moments (the caller's units) */
    double A[3];          /* amplitudes (rad/s) */
    double s_cn;          /* sign of the cn component (separatrix), else +1 */
    double s;             /* sign s above */
    int cn_axis, dn_axis; /* 0 and 2 (D2 > 0) or 2 and 0 (D2 < 0), sorted indices */
    double lambda;        /* rad/s (elliptic, separatrix), Omega (symmetric) */
    double m, kprime2;    /* k^2 and 1 - k^2 (computed without cancellation) */
    double K;             /* K(m) (elliptic) */
    double tau0;          /* phase at t = 0 */
    double period;        /* 4 K / lambda (elliptic), 2 pi / |Omega| (symmetric), 0 otherwise */
    double flip_interval; /* 2 K / lambda (elliptic), 0 otherwise */
    int sym_axis;         /* symmetric: the sorted index of the symmetry axis (0 or 2) */
    double u0[3];         /* sorted initial w */
    double L2, twoE;      /* L^2 and 2E at t = 0 */
};

/* Set up the exact solution for moments I[0..2] (> 0, finite) and the initial
 * body angular velocity w0 (finite). Statuses: MECH_OK; MECH_EINVAL (param
 * "moments" or "omega") for non-finite or non-positive input; MECH_ENUMERIC
 * if a GSL special function fails. */
enum mech_status mech_rigid_exact_init(const double I[3], struct mech_vec3 w0,
                                       struct mech_rigid_exact *ex, struct mech_error *err);

/* w(t) in the caller's body axes (rad/s). MECH_ENUMERIC if GSL's elliptic
 * functions fail or a value is not finite. The phase is reduced modulo 4K
 * (one period) before evaluation, so long times keep full accuracy. */
enum mech_status mech_rigid_exact_omega(const struct mech_rigid_exact *ex, double t,
                                        struct mech_vec3 *w, struct mech_error *err);

/* ---- integration ------------------------------------------------------------ */

enum mech_rigid_torque_frame {
    MECH_RIGID_TORQUE_NONE = 0,
    MECH_RIGID_TORQUE_BODY,  /* constant in body axes */
    MECH_RIGID_TORQUE_SPACE, /* constant in space axes */
};

struct mech_rigid_problem {
    double moments[3];        /* principal moments I1, I2, I3 (kg m^2), > 0, finite, and
                                 physical: each <= the sum of the other two (1e-12 slack) */
    struct mech_vec3 omega;   /* initial angular velocity, body axes (rad/s) */
    double q0[4];             /* initial passive attitude [w, x, y, z] (space -> body),
                                 non-zero; normalised here */
    enum mech_rigid_torque_frame torque_frame;
    struct mech_vec3 torque;  /* N m, in torque_frame axes */
    double t_end;             /* s, > 0 */
    size_t samples;           /* 2..100000, evenly spaced over [0, t_end] */
    const char *method;       /* a first-order method of mech_ode_method_find() */
    struct mech_ode_options opt; /* rtol/atol on the dimensionless state; dt in s */
};

struct mech_rigid_result {
    /* Caller-owned buffers of `samples` entries; any may be NULL. */
    double *t;
    struct mech_vec3 *omega;          /* body axes, rad/s */
    double *quaternion;               /* 4 per sample, q / |q| */
    struct mech_vec3 *angular_momentum; /* space axes, kg m^2/s */
    double *kinetic_energy;           /* J */
    /* Filled by the call. */
    size_t n_samples;
    struct mech_ode_stats stats;
    double rate_scale;                /* W (1/s) used to make time dimensionless */
    struct mech_vec3 L0;              /* space L at t = 0 */
    double T0;                        /* kinetic energy at t = 0 */
    /* Drifts over every accepted step and sample: */
    double max_L_norm_drift;          /* max ||L| - |L0|| / |L0| (|L0| = 0: absolute) */
    double max_T_drift;               /* max |T - T0| / T0 (T0 = 0: absolute) */
    double max_L_vector_drift;        /* max |L - L_ref| / |L0|, L_ref = L0 + G t (space torque
                                         or none); NaN for a body torque */
    double max_quaternion_norm_drift; /* max ||q| - 1| */
    int torque_free;
    /* Against the exact solution (torque-free runs): */
    int has_exact;
    struct mech_rigid_exact exact;
    double max_omega_error;           /* rad/s, max |w - w_exact| over the samples */
    double max_relative_omega_error;  /* max_omega_error / |w0| */
    double final_omega_error;
    /* Flips: sign changes of the intermediate-axis component of w over the samples */
    long flips;                       /* number of sign changes seen */
    double measured_period;           /* 2 x the mean interval between the first and last
                                         sign change (linear interpolation between samples);
                                         NaN with fewer than 2 */
};

/* The principal moments of a physical body: each finite and > 0 (kg m^2)
 * and none above the sum of the other two (the triangle inequality, to
 * 1e-12 relative). MECH_OK, or MECH_EDOMAIN at "moments" naming the moment
 * and the mistake. The one check for mech_rigid_rotate and the closed form. */
enum mech_status mech_rigid_moments_check(const double I[3], struct mech_error *err);

/* Integrate Euler's equations and the attitude from t = 0 to t_end.
 * Statuses: MECH_OK; MECH_EINVAL / MECH_EDOMAIN with param "moments",
 * "omega", "orientation", "torque/value", "samples", "t_end", "integrator/..."
 * (a second-order-only method is MECH_EINVAL at "integrator/method");
 * MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED (err->progress in seconds);
 * MECH_ENUMERIC; MECH_ENOMEM. On failure only the samples written
 * (res->n_samples) are meaningful. */
enum mech_status mech_rigid_rotate(const struct mech_rigid_problem *p,
                                   const struct mech_budget *budget,
                                   struct mech_rigid_result *res, struct mech_error *err);

/* Dimensionless rate scale W (1/s) used by mech_rigid_rotate for p (see above). */
double mech_rigid_rate_scale(const struct mech_rigid_problem *p);

#endif
