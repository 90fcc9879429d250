/* check_kind.c — kinds, units and the comparisons of POST /v1/check (see
 * api/check/check_kind.h and docs/grading.md, "Kinds and units"; which field is of
 * which kind comes from the response schemas: api/check/check_field.c).
 * Pure: plain arrays in, an outcome out; no JSON, no I/O, no allocation.
 */
#include "check/check_kind.h"
#include "mech/base/constants.h"

#include <math.h>
#include <string.h>

#define KIND_MAX_DIM 16 /* rows and columns of SUBSPACE / EIGENVECTORS */

static const char *const kind_names[API_KIND_COUNT] = {"number",   "vector",       "matrix",
                                                       "axis",     "quaternion",   "angle",
                                                       "subspace", "eigenvectors", "axis_angle"};

const char api_check_kind_list[] =
    "number, vector, matrix, axis, quaternion, angle, subspace, eigenvectors, axis_angle";

int api_check_kind_parse(const char *name, enum api_check_kind *out)
{
    for (int k = 0; k < API_KIND_COUNT; k++)
        if (name && !strcmp(name, kind_names[k])) {
            *out = (enum api_check_kind)k;
            return 0;
        }
    return -1;
}

const char *api_check_kind_name(enum api_check_kind k)
{
    return (unsigned)k < API_KIND_COUNT ? kind_names[k] : "number";
}

/* ---- units ------------------------------------------------------------------ */

#define EV 1.602176634e-19  /* J, exact (SI 2019) */

static const struct api_unit units[] = {
    {"1", 1, "1"},
    {"m", 1, "L"},
    {"km", 1e3, "L"},
    {"cm", 1e-2, "L"},
    {"mm", 1e-3, "L"},
    {"um", 1e-6, "L"},
    {"nm", 1e-9, "L"},
    {"au", 1.495978707e11, "L"},
    {"ly", 9.4607304725808e15, "L"},
    {"pc", 3.0856775814913673e16, "L"},
    {"s", 1, "T"},
    {"ms", 1e-3, "T"},
    {"us", 1e-6, "T"},
    {"ns", 1e-9, "T"},
    {"min", 60, "T"},
    {"h", 3600, "T"},
    {"day", 86400, "T"},
    {"yr", 31557600, "T"},
    {"kg", 1, "M"},
    {"g", 1e-3, "M"},
    {"t", 1e3, "M"},
    {"J", 1, "E"},
    {"kJ", 1e3, "E"},
    {"MJ", 1e6, "E"},
    {"erg", 1e-7, "E"},
    {"eV", EV, "E"},
    {"keV", 1e3 * EV, "E"},
    {"MeV", 1e6 * EV, "E"},
    {"GeV", 1e9 * EV, "E"},
    {"TeV", 1e12 * EV, "E"},
    {"rad", 1, "angle"},
    {"deg", MECH_PI / 180, "angle"},
    {"rev", 2 * MECH_PI, "angle"},
    {"arcmin", MECH_PI / 10800, "angle"},
    {"arcsec", MECH_PI / 648000, "angle"},
    {"mrad", 1e-3, "angle"},
    {"m/s", 1, "L/T"},
    {"km/s", 1e3, "L/T"},
    {"km/h", 1 / 3.6, "L/T"},
    {"cm/s", 1e-2, "L/T"},
    {"m/s^2", 1, "L/T2"},
    {"rad/s", 1, "angle/T"},
    {"deg/s", MECH_PI / 180, "angle/T"},
    {"rpm", 2 * MECH_PI / 60, "angle/T"},
    {"rev/s", 2 * MECH_PI, "angle/T"},
    {"Hz", 1, "1/T"},
    {"kHz", 1e3, "1/T"},
    {"kg m^2", 1, "ML2"},
    {"g cm^2", 1e-7, "ML2"},
    {"kg m^2/s", 1, "ML2/T"},
    {"J s", 1, "ML2/T"},
    {"kg m/s", 1, "ML/T"},
    {"eV/c", EV / MECH_C, "ML/T"},
    {"keV/c", 1e3 * EV / MECH_C, "ML/T"},
    {"MeV/c", 1e6 * EV / MECH_C, "ML/T"},
    {"GeV/c", 1e9 * EV / MECH_C, "ML/T"},
    {"TeV/c", 1e12 * EV / MECH_C, "ML/T"},
    {"eV/c^2", EV / (MECH_C * MECH_C), "M"}, /* masses in natural units: E = m c^2 */
    {"keV/c^2", 1e3 * EV / (MECH_C * MECH_C), "M"},
    {"MeV/c^2", 1e6 * EV / (MECH_C * MECH_C), "M"},
    {"GeV/c^2", 1e9 * EV / (MECH_C * MECH_C), "M"},
    {"TeV/c^2", 1e12 * EV / (MECH_C * MECH_C), "M"},
    {"eV^2", EV * EV, "E2"}, /* Mandelstam s, t, u in natural units (c = 1) */
    {"keV^2", (1e3 * EV) * (1e3 * EV), "E2"},
    {"MeV^2", (1e6 * EV) * (1e6 * EV), "E2"},
    {"GeV^2", (1e9 * EV) * (1e9 * EV), "E2"},
    {"TeV^2", (1e12 * EV) * (1e12 * EV), "E2"},
    {"N", 1, "F"},
    {"kN", 1e3, "F"},
    {"N m", 1, "torque"},
    {"W", 1, "P"},
    {"kW", 1e3, "P"},
    {"kg/s", 1, "M/T"},
};

const char api_unit_list[] =
    "1, m, km, cm, mm, um, nm, au, ly, pc, s, ms, us, ns, min, h, day, yr, kg, g, t, J, kJ, MJ, "
    "erg, eV, keV, MeV, GeV, TeV, rad, deg, rev, arcmin, arcsec, mrad, m/s, km/s, km/h, cm/s, "
    "m/s^2, rad/s, deg/s, rpm, rev/s, Hz, kHz, kg m^2, g cm^2, kg m^2/s, J s, kg m/s, eV/c, keV/c, "
    "MeV/c, GeV/c, TeV/c, eV/c^2, keV/c^2, MeV/c^2, GeV/c^2, TeV/c^2, eV^2, keV^2, MeV^2, GeV^2, "
    "TeV^2, N, kN, N m, W, kW, kg/s";

const struct api_unit *api_unit_find(const char *name)
{
    if (!name) return NULL;
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (!strcmp(units[i].name, name)) return &units[i];
    return NULL;
}

/* ---- tolerance ------------------------------------------------------------------- */

/* Half a unit in the n-th significant figure of m > 0. */
static double sig_bound(double m, int n)
{
    if (!(m > 0) || n <= 0 || !isfinite(m)) return 0;
    return 0.5 * pow(10.0, floor(log10(m)) - n + 1);
}

double api_check_bound(const struct api_check_tol *t, double mag)
{
    double b = t->rec_abs + t->rec_rel * mag;
    if (t->rel >= 0 && t->rel * mag > b) b = t->rel * mag;
    if (t->abs >= 0 && t->abs > b) b = t->abs;
    if (t->sig > 0) {
        double su = t->sig_unit > 0 ? t->sig_unit : 1;
        double sb = sig_bound(mag / su, t->sig) * su;
        if (sb > b) b = sb;
    }
    return b;
}

/* The bound at the problem's scale: magnitudes at or below it count as zero. */
static double zero_level(const struct api_check_tol *t)
{
    return t->scale > 0 ? api_check_bound(t, t->scale) : 0;
}

/* ---- helpers ------------------------------------------------------------------------ */

static double norm(const double *x, size_t n)
{
    double s = 0, m = 0;
    for (size_t i = 0; i < n; i++)
        if (fabs(x[i]) > m) m = fabs(x[i]);
    if (m == 0 || !isfinite(m)) return m;
    for (size_t i = 0; i < n; i++)
        s += (x[i] / m) * (x[i] / m);
    return m * sqrt(s);
}

/* |a - s e| for s = +1 and -1, the smaller. */
static double dist_up_to_sign(const double *e, const double *a, size_t n)
{
    double p = 0, m = 0;
    for (size_t i = 0; i < n; i++) {
        p += (a[i] - e[i]) * (a[i] - e[i]);
        m += (a[i] + e[i]) * (a[i] + e[i]);
    }
    return sqrt(p < m ? p : m);
}

static void wrong_at(struct api_check_outcome *o, size_t i)
{
    if (o->nwrong < sizeof o->wrong / sizeof o->wrong[0]) o->wrong[o->nwrong] = i;
    o->nwrong++;
}

static void note_error(struct api_check_outcome *o, double err, double mag, double bound)
{
    if (err > o->abs_err || isnan(err)) o->abs_err = err;
    if (mag > 0) {
        double r = err / mag;
        if (!o->have_rel || r > o->rel_err) o->rel_err = r;
        o->have_rel = 1;
    }
    if (bound > o->bound) o->bound = bound;
}

/* One judged quantity: correct when err <= bound(mag), or when both the
 * expected magnitude and the student's are zero at the problem's scale. */
static int judge(const struct api_check_tol *t, struct api_check_outcome *o, double err, double mag,
                 double amag)
{
    double b = api_check_bound(t, mag);
    double z = zero_level(t);
    if (mag <= z && amag <= z && z > b) b = z;
    note_error(o, err, mag, b);
    return err <= b;
}

/* ---- kinds ------------------------------------------------------------------------------ */

static void elementwise(int angle, const double *e, const double *a, size_t n,
                        const struct api_check_tol *t, struct api_check_outcome *o)
{
    for (size_t i = 0; i < n; i++) {
        double err, mag, amag;
        if (angle) {
            err = fabs(remainder(a[i] - e[i], 2 * MECH_PI));
            mag = fabs(remainder(e[i], 2 * MECH_PI));
            amag = fabs(remainder(a[i], 2 * MECH_PI));
        } else {
            err = fabs(a[i] - e[i]);
            mag = fabs(e[i]);
            amag = fabs(a[i]);
        }
        if (!judge(t, o, err, mag, amag)) wrong_at(o, i);
    }
}

static void as_whole(const double *e, const double *a, size_t n, const struct api_check_tol *t,
                     struct api_check_outcome *o)
{
    double d[KIND_MAX_DIM * KIND_MAX_DIM];
    double err = 0;
    if (n <= sizeof d / sizeof d[0]) {
        for (size_t i = 0; i < n; i++)
            d[i] = a[i] - e[i];
        err = norm(d, n);
    } else { /* long vectors: plain sum (no overflow concern at answer scale) */
        double s = 0;
        for (size_t i = 0; i < n; i++)
            s += (a[i] - e[i]) * (a[i] - e[i]);
        err = sqrt(s);
    }
    if (!judge(t, o, err, norm(e, n), norm(a, n))) wrong_at(o, 0);
}

/* Unit direction of x[0..n) into u; 0 if x is zero (or not finite). */
static int unit_of(const double *x, size_t n, double *u)
{
    double m = norm(x, n);
    if (!(m > 0) || !isfinite(m)) return 0;
    for (size_t i = 0; i < n; i++)
        u[i] = x[i] / m;
    return 1;
}

/* A direction (row) up to sign: error = |a^ -+ e^| (chord between the lines'
 * unit vectors), bound at magnitude 1. */
static int axis_row(const double *e, const double *a, size_t n, const struct api_check_tol *t,
                    struct api_check_outcome *o, const char **note)
{
    double ue[KIND_MAX_DIM], ua[KIND_MAX_DIM];
    if (!unit_of(a, n, ua)) {
        if (note) *note = "a zero vector has no direction";
        note_error(o, 1, 1, api_check_bound(t, 1)); /* |0 - e^|: finite, always wrong */
        return 0;
    }
    if (!unit_of(e, n, ue)) return judge(t, o, norm(a, n), 0, norm(a, n));
    return judge(t, o, dist_up_to_sign(ue, ua, n), 1, 1);
}

/* Rows a (k rows of n) against the span of rows e: each student row (made
 * unit) lies in the span, and the student rows are mutually orthogonal.
 * Returns the number of wrong rows, recorded with index offset base. */
static size_t subspace_rows(const double *e, const double *a, size_t k, size_t n,
                            const struct api_check_tol *t, struct api_check_outcome *o, size_t base,
                            const char **note)
{
    double basis[KIND_MAX_DIM][KIND_MAX_DIM];
    double ua[KIND_MAX_DIM][KIND_MAX_DIM];
    size_t rank = 0;
    for (size_t r = 0; r < k; r++) { /* modified Gram-Schmidt on the expected rows */
        double v[KIND_MAX_DIM];
        for (size_t j = 0; j < n; j++)
            v[j] = e[r * n + j];
        for (size_t q = 0; q < rank; q++) {
            double d = 0;
            for (size_t j = 0; j < n; j++)
                d += v[j] * basis[q][j];
            for (size_t j = 0; j < n; j++)
                v[j] -= d * basis[q][j];
        }
        if (norm(v, n) > 1e-8 && unit_of(v, n, basis[rank])) rank++;
    }
    size_t bad = 0;
    double b1 = api_check_bound(t, 1);
    for (size_t r = 0; r < k; r++) {
        int ok = unit_of(a + r * n, n, ua[r]);
        double err = 1; /* a zero row: |0 - its direction| */
        if (ok) {       /* distance from the span */
            double v[KIND_MAX_DIM];
            for (size_t j = 0; j < n; j++)
                v[j] = ua[r][j];
            for (size_t q = 0; q < rank; q++) {
                double d = 0;
                for (size_t j = 0; j < n; j++)
                    d += ua[r][j] * basis[q][j];
                for (size_t j = 0; j < n; j++)
                    v[j] -= d * basis[q][j];
            }
            err = norm(v, n);
            for (size_t s = 0; s < r; s++) { /* orthogonal to the earlier rows */
                double d = 0;
                for (size_t j = 0; j < n; j++)
                    d += ua[r][j] * ua[s][j];
                if (fabs(d) > err) err = fabs(d);
            }
        } else if (note) {
            *note = "a zero vector has no direction";
        }
        note_error(o, err, 1, b1);
        if (!ok || !(err <= b1)) {
            wrong_at(o, base + r);
            bad++;
        }
    }
    return bad;
}

static int quaternion(const double *e, const double *a, const struct api_check_tol *t,
                      struct api_check_outcome *o)
{
    double mag = norm(e, 4);
    return judge(t, o, dist_up_to_sign(e, a, 4), mag, norm(a, 4));
}

/* Unit quaternion of the rotation by angle about axis (n = [x,y,z]); 0 when
 * the axis is zero and the angle is not a multiple of 2 pi. */
static int quat_of_axis_angle(const double *x, double q[4])
{
    double u[3];
    double h = 0.5 * x[3];
    if (!unit_of(x, 3, u)) {
        if (fabs(remainder(x[3], 2 * MECH_PI)) != 0) return 0;
        q[0] = 1;
        q[1] = q[2] = q[3] = 0;
        return 1;
    }
    q[0] = cos(h);
    for (int i = 0; i < 3; i++)
        q[i + 1] = sin(h) * u[i];
    return 1;
}

/* Axis with angle: the rotations compared; error = the angle of the rotation
 * taking one to the other (rad): |q1 - q2| = 2 sin(phi / 4) for unit q. */
static int axis_angle(const double *e, const double *a, const struct api_check_tol *t,
                      struct api_check_outcome *o, const char **note)
{
    double qe[4], qa[4];
    if (!quat_of_axis_angle(e, qe)) { /* mechd never answers this: be safe */
        qe[0] = 1;
        qe[1] = qe[2] = qe[3] = 0;
    }
    if (!quat_of_axis_angle(a, qa)) {
        if (note) *note = "a zero axis with a nonzero angle is no rotation";
        note_error(o, MECH_PI, 0, api_check_bound(t, fabs(remainder(e[3], 2 * MECH_PI)))); /* no rotation */
        return 0;
    }
    double chord = dist_up_to_sign(qe, qa, 4);
    double phi = 4 * asin(chord / 2 < 1 ? chord / 2 : 1);
    double mag = fabs(remainder(e[3], 2 * MECH_PI));
    return judge(t, o, phi, mag, fabs(remainder(a[3], 2 * MECH_PI)));
}

int api_check_compare(enum api_check_kind k, const double *e, const double *a, size_t rows,
                      size_t cols, const double *eigenvalues, double deg_tol,
                      const struct api_check_tol *t, struct api_check_outcome *out,
                      const char **why)
{
    size_t n = rows * cols;
    memset(out, 0, sizeof *out);
    out->compared = n;
    if (why) *why = NULL;
    const char *note = NULL;
    switch (k) {
    case API_KIND_NUMBER:
    case API_KIND_ANGLE:
        elementwise(k == API_KIND_ANGLE, e, a, n, t, out);
        break;
    case API_KIND_VECTOR:
    case API_KIND_AXIS:
        if (rows != 1) {
            if (why) *why = "a vector is one array of numbers";
            return -1;
        }
        if (k == API_KIND_VECTOR) {
            as_whole(e, a, n, t, out);
        } else {
            if (n > KIND_MAX_DIM) {
                if (why) *why = "an axis has at most 16 components";
                return -1;
            }
            if (!axis_row(e, a, n, t, out, &note)) wrong_at(out, 0);
        }
        break;
    case API_KIND_MATRIX:
        as_whole(e, a, n, t, out);
        break;
    case API_KIND_QUATERNION:
        if (n != 4 || rows != 1) {
            if (why) *why = "a quaternion is [w, x, y, z]";
            return -1;
        }
        if (!quaternion(e, a, t, out)) wrong_at(out, 0);
        break;
    case API_KIND_AXIS_ANGLE:
        if (n != 4) {
            if (why) *why = "an axis with its angle is {\"axis\": [x, y, z], \"angle\": rad}";
            return -1;
        }
        if (!axis_angle(e, a, t, out, &note)) wrong_at(out, 0);
        break;
    case API_KIND_SUBSPACE:
    case API_KIND_EIGENVECTORS:
        if (rows > KIND_MAX_DIM || cols > KIND_MAX_DIM || rows > cols) {
            if (why)
                *why = "rows of vectors (at most as many rows as components, at most 16 "
                       "of each)";
            return -1;
        }
        if (k == API_KIND_SUBSPACE) {
            subspace_rows(e, a, rows, cols, t, out, 0, &note);
            break;
        }
        /* eigenvectors: rows whose eigenvalues agree form one subspace */
        for (size_t r = 0; r < rows;) {
            size_t end = r + 1;
            while (eigenvalues && end < rows && fabs(eigenvalues[end] - eigenvalues[r]) <= deg_tol)
                end++;
            if (end - r == 1) {
                if (!axis_row(e + r * cols, a + r * cols, cols, t, out, &note)) wrong_at(out, r);
            } else {
                subspace_rows(e + r * cols, a + r * cols, end - r, cols, t, out, r, &note);
            }
            r = end;
        }
        break;
    default:
        if (why) *why = "unknown kind";
        return -1;
    }
    out->correct = out->nwrong == 0;
    if (note && why) *why = note;
    return 0;
}
