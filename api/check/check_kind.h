/* check_kind.h — what an answer IS, for POST /v1/check: kinds of quantities
 * (a number, a vector, an axis up to sign, a quaternion up to sign, an angle
 * modulo 2 pi, a subspace, eigenvectors with degenerate groups, an axis with
 * its angle), the units a student may answer in, and the comparison of an
 * answer of each kind with mechd's. Which field of which operation is of
 * which kind and unit is data: the operations' response schemas
 * (api/check/check_field.h).
 *
 * Pure functions on plain arrays of doubles: no JSON, no I/O, no allocation;
 * reentrant. api/check/check_tree.c turns JSON into these arrays and back and
 * api/check/check_grade.c grades with them (for api/ops/tools/check.c).
 */
#ifndef API_CHECK_KIND_H
#define API_CHECK_KIND_H

#include <stddef.h>

enum api_check_kind {
    API_KIND_NUMBER,       /* number or array compared element-wise (the default) */
    API_KIND_VECTOR,       /* 1-D array compared as a vector: |a - e| <= tol(|e|) */
    API_KIND_MATRIX,       /* 2-D array compared as a whole (Frobenius norm) */
    API_KIND_AXIS,         /* 1-D direction, up to sign and length (normalised first) */
    API_KIND_QUATERNION,   /* [w,x,y,z], q and -q are the same rotation */
    API_KIND_ANGLE,        /* number or array of angles, each modulo 2 pi */
    API_KIND_SUBSPACE,     /* rows spanning a subspace: same span, student rows orthogonal */
    API_KIND_EIGENVECTORS, /* rows = eigenvectors; each up to sign, rows whose eigenvalues
                              agree compared as one subspace */
    API_KIND_AXIS_ANGLE,   /* {"axis": [3], "angle": rad}: the same rotation ((n, t) ~
                              (-n, -t) ~ (n, t + 2 pi)) */
    API_KIND_COUNT
};

/* Kind by name ("number", "vector", "matrix", "axis", "quaternion", "angle",
 * "subspace", "eigenvectors", "axis_angle"); returns 0, or -1 if unknown. */
int api_check_kind_parse(const char *name, enum api_check_kind *out);

/* The name of a kind (static string). */
const char *api_check_kind_name(enum api_check_kind k);

/* All kind names, comma-separated, for messages (static string). */
extern const char api_check_kind_list[];

/* One unit a student may answer in: value_SI = value * factor. dim names the
 * dimension ("L", "M", "T", "E", "angle", "ML2", ...), equal strings meaning
 * convertible. */
struct api_unit {
    const char *name;
    double factor;
    const char *dim;
};

/* Unit by name (exact, case-sensitive: "km", "eV", "deg", "kg m^2", "km/s",
 * ...); NULL if unknown. */
const struct api_unit *api_unit_find(const char *name);

/* All unit names, comma-separated, for messages (static string). */
extern const char api_unit_list[];

/* Tolerance criteria. Absent criteria are < 0 (rel, abs) or 0 (sig). scale
 * (>= 0) is the size of the quantity's problem: values at or below the
 * tolerance applied to the scale count as zero. rec_rel, rec_abs: mechd's own
 * numerical error (always applied). */
struct api_check_tol {
    double rel, abs;
    int sig;
    double sig_unit; /* 0: figures counted in the field's unit; else the factor of the
                        student's unit to the field's, the figures counted in it */
    double scale;
    double rec_rel, rec_abs;
};

/* The bound on |a - e| for an expected magnitude mag >= 0: the largest of
 * rel*mag, abs, half a unit in the sig-th figure of mag (of mag / sig_unit,
 * times sig_unit, when sig_unit > 0: the figures of the value written in the
 * student's unit), rec_abs + rec_rel*mag. */
double api_check_bound(const struct api_check_tol *t, double mag);

/* Result of comparing one answer. */
struct api_check_outcome {
    int correct;
    double abs_err; /* the error measured (element-wise: the largest) */
    double rel_err; /* abs_err / |expected| over nonzero expected; valid if have_rel */
    int have_rel;
    double bound;     /* the bound applied (the largest) */
    size_t compared;  /* numbers compared */
    size_t nwrong;    /* wrong elements (NUMBER, ANGLE) or rows (EIGENVECTORS, SUBSPACE) */
    size_t wrong[20]; /* their indices into the flat array (rows for row kinds) */
};

/* Compare the student's a[0..n) with the expected e[0..n) as kind k; rows x
 * cols is the shape (cols = n, rows = 1 for a 1-D array or a number).
 * eigenvalues (NULL if none; rows of them) group EIGENVECTORS rows whose
 * eigenvalues agree within deg_tol. For AXIS_ANGLE, n = 4: [nx, ny, nz,
 * angle]. Returns 0, or -1 when the shape does not suit the kind (a
 * quaternion of 3 numbers, a zero axis given by the student sets *why). */
int api_check_compare(enum api_check_kind k, const double *e, const double *a, size_t rows,
                      size_t cols, const double *eigenvalues, double deg_tol,
                      const struct api_check_tol *t, struct api_check_outcome *out,
                      const char **why);

#endif
