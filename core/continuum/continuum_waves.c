/* continuum_waves.c — string and rod waves and the beam's bending modes
 * (see mech/continuum/continuum_waves.h). */
#include "mech/continuum/continuum_waves.h"
#include "mech/base/constants.h"

#include <math.h>

enum mech_status mech_string_wave_speed(double tension, double linear_density, double *c,
                                        struct mech_error *err)
{
    if (!isfinite(tension) || tension <= 0)
        return mech_error_set(err, MECH_EDOMAIN, "tension",
                              "a string's tension is a finite force > 0 N, got %.17g", tension);
    if (!isfinite(linear_density) || linear_density <= 0)
        return mech_error_set(err, MECH_EDOMAIN, "linear_density",
                              "a linear density is a finite mass per length > 0 kg/m, got %.17g",
                              linear_density);
    /* sqrt of each factor: no overflow or underflow of the quotient. */
    *c = sqrt(tension) / sqrt(linear_density);
    return MECH_OK;
}

static enum mech_status check_mode(int n, struct mech_error *err)
{
    if (n < 1 || n > MECH_CONTINUUM_MODE_MAX)
        return mech_error_set(err, MECH_EINVAL, "modes", "a mode number is 1 .. %d, got %d",
                              MECH_CONTINUUM_MODE_MAX, n);
    return MECH_OK;
}

enum mech_status mech_rod_axial_mode(enum mech_rod_ends ends, int n, double *kl,
                                     struct mech_error *err)
{
    enum mech_status st = check_mode(n, err);
    if (st != MECH_OK) return st;
    switch (ends) {
    case MECH_ROD_FREE_FREE:
    case MECH_ROD_CLAMPED_CLAMPED:
    case MECH_ROD_PINNED_PINNED: /* a pin holds the end axially: fixed-fixed */
        *kl = n * MECH_PI; /* u ∝ cos(nπs/L) (free) or sin(nπs/L) (fixed) */
        return MECH_OK;
    case MECH_ROD_CLAMPED_FREE:
        *kl = (n - 0.5) * MECH_PI; /* u ∝ sin((n − ½)π s/L): a node at the clamp, an antinode at the tip */
        return MECH_OK;
    default:
        return mech_error_set(err, MECH_EINVAL, "ends", "unknown end conditions");
    }
}

/* cos x − s sech x, with sech x = 2e^{−x}/(1 + e^{−2x}) (never overflows). */
static double characteristic(double x, double s)
{
    const double q = exp(-x);
    return cos(x) - s * (2 * q / (1 + q * q));
}

/* The root of characteristic(·, s) in [a, b] (a sign change), by bisection
 * until the interval cannot shrink: the last bit, whatever the slope. */
static double bisect(double a, double b, double s)
{
    double fa = characteristic(a, s);
    for (int i = 0; i < 200; i++) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        const double fm = characteristic(m, s);
        if (fm == 0) return m;
        if ((fm < 0) == (fa < 0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

enum mech_status mech_beam_bending_root(enum mech_rod_ends ends, int n, double *x, double *sigma,
                                        struct mech_error *err)
{
    enum mech_status st = check_mode(n, err);
    if (st != MECH_OK) return st;
    double r, sg = 0;
    switch (ends) {
    case MECH_ROD_FREE_FREE:
    case MECH_ROD_CLAMPED_CLAMPED: {
        /* cos x cosh x = 1: cos x = sech x, one root in [nπ, (n + 1)π]. */
        r = bisect(n * MECH_PI, (n + 1) * MECH_PI, 1.0);
        const double e = exp(-r), sn = sin(r), cs = cos(r);
        sg = (1 + e * e - 2 * e * cs) / (1 - e * e - 2 * e * sn); /* (cosh − cos)/(sinh − sin) */
        break;
    }
    case MECH_ROD_CLAMPED_FREE: {
        /* cos x cosh x = −1: cos x = −sech x, one root in [(n − 1)π, nπ]. */
        r = bisect((n - 1) * MECH_PI, n * MECH_PI, -1.0);
        const double e = exp(-r), sn = sin(r), cs = cos(r);
        sg = (1 - e * e - 2 * e * sn) / (1 + e * e + 2 * e * cs); /* (sinh − sin)/(cosh + cos) */
        break;
    }
    case MECH_ROD_PINNED_PINNED:
        r = n * MECH_PI;
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, "ends", "unknown end conditions");
    }
    *x = r;
    if (sigma) *sigma = sg;
    return MECH_OK;
}

struct mech_wave_mode mech_wave_mode_nondispersive(double c, double length, double kl)
{
    struct mech_wave_mode m;
    m.wavenumber = kl / length;
    m.angular_frequency = c * m.wavenumber;
    m.frequency = m.angular_frequency / (2 * MECH_PI);
    m.wavelength = 2 * MECH_PI / m.wavenumber;
    m.phase_speed = m.group_speed = c;
    return m;
}

struct mech_wave_mode mech_wave_mode_bending(double a, double length, double x)
{
    struct mech_wave_mode m;
    m.wavenumber = x / length;
    m.phase_speed = a * m.wavenumber;
    m.group_speed = 2 * m.phase_speed;
    m.angular_frequency = m.phase_speed * m.wavenumber;
    m.frequency = m.angular_frequency / (2 * MECH_PI);
    m.wavelength = 2 * MECH_PI / m.wavenumber;
    return m;
}
