/* check_grade.c — grading one field of POST /v1/check and its feedback
 * sentence (contracts in api/check/check_grade.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check/check_grade.h"
#include "check/check_tree.h"

/* Fold one comparison into the grade: counts, largest errors and bound. */
static void grade_add(struct api_check_grade *g, const struct api_check_outcome *o)
{
    g->count += o->compared;
    if (o->abs_err > g->max_abs_err || isnan(o->abs_err)) g->max_abs_err = o->abs_err;
    if (o->have_rel && (!g->have_rel || o->rel_err > g->max_rel_err)) g->max_rel_err = o->rel_err;
    g->have_rel |= o->have_rel;
    if (o->bound > g->max_bound) g->max_bound = o->bound;
}

/* Count a wrong element or row; list its pointer (the first 20). */
static void grade_wrong(struct api_check_grade *g, const char *ptr)
{
    g->wrong++;
    if (g->wrong_ptrs && json_array_size(g->wrong_ptrs) < 20)
        json_array_append_new(g->wrong_ptrs, json_string(ptr));
}

/* Element-wise kinds (number, angle): every number of the tree on its own. */
static void grade_tree(struct api_check_grade *g, const json_t *want, const json_t *got, char *ptr,
                       size_t n)
{
    if (json_is_number(want)) {
        double e = json_number_value(want), a = json_number_value(got) * g->factor;
        struct api_check_outcome o;
        api_check_compare(g->kind, &e, &a, 1, 1, NULL, 0, &g->tol, &o, NULL);
        grade_add(g, &o);
        if (!o.correct) grade_wrong(g, ptr);
        return;
    }
    size_t len = strlen(ptr);
    for (size_t i = 0; i < json_array_size(want); i++) {
        snprintf(ptr + len, n - len, "/%zu", i);
        grade_tree(g, json_array_get(want, i), json_array_get(got, i), ptr, n);
        ptr[len] = '\0';
    }
}

/* What a kind means, for the feedback. */
static const char *kind_words(enum api_check_kind k)
{
    switch (k) {
    case API_KIND_VECTOR: return "a vector (judged as a whole)";
    case API_KIND_MATRIX: return "a matrix (judged as a whole)";
    case API_KIND_AXIS: return "a direction (either sign and any length are accepted)";
    case API_KIND_QUATERNION: return "a rotation quaternion [w, x, y, z] (q and -q are accepted)";
    case API_KIND_ANGLE: return "an angle (modulo a full turn)";
    case API_KIND_SUBSPACE: return "vectors spanning a subspace (any orthogonal basis of it)";
    case API_KIND_EIGENVECTORS:
        return "eigenvectors as rows (each of either sign; rows of equal eigenvalues may be any "
               "orthonormal basis of their subspace)";
    case API_KIND_AXIS_ANGLE: return "a rotation: an axis with its angle";
    default: return "a number";
    }
}

/* The eigenvalues belonging to rows of eigenvectors at want: a sibling array
 * "moments" or "eigenvalues" of the same length in the object holding it. */
static int sibling_eigenvalues(const json_t *parent, size_t rows, double *lam, double *deg_tol)
{
    static const char *const names[] = {"moments", "eigenvalues"};
    if (!json_is_object(parent) || rows > 16) return 0;
    for (size_t k = 0; k < 2; k++) {
        const json_t *a = json_object_get(parent, names[k]);
        if (!json_is_array(a) || json_array_size(a) != rows) continue;
        double m = 0;
        int ok = 1;
        for (size_t i = 0; i < rows; i++) {
            const json_t *v = json_array_get(a, i);
            if (!json_is_number(v)) ok = 0;
            lam[i] = json_number_value(v);
            if (fabs(lam[i]) > m) m = fabs(lam[i]);
        }
        if (!ok) continue;
        *deg_tol = 1e-10 * m; /* the rule of /v1/rigid/inertia's "degenerate" */
        return 1;
    }
    return 0;
}

/* Compare a non-element-wise kind; 0, or -1 after recording a 422. */
static int grade_whole(struct api_call *c, struct api_check_grade *g, const json_t *want,
                       const json_t *value, const json_t *parent, const char *pointer,
                       const char *kind_ptr)
{
    double *e = NULL, *a = NULL;
    double ev[4], av[4];
    size_t rows = 1, cols = 4;
    const char *why = NULL;
    if (g->kind == API_KIND_AXIS_ANGLE) {
        if (api_check_axis_angle_of(want, ev)) {
            api_call_invalid(c, kind_ptr,
                             "axis_angle: %.200s is not an {\"axis\", \"angle\"} "
                             "object in the answer",
                             pointer);
            return -1;
        }
        if (api_check_axis_angle_of(value, av)) {
            api_call_invalid(c, "/answer/value",
                             "give the rotation as {\"axis\": [x, y, z], "
                             "\"angle\": a number}");
            return -1;
        }
        av[3] *= g->factor;
        e = ev;
        a = av;
    } else {
        size_t r2, c2;
        int fe = api_check_flatten(want, &e, &rows, &cols);
        int fa = fe ? 0 : api_check_flatten(value, &a, &r2, &c2);
        if (fe || fa) {
            free(e);
            free(a);
            if (fe == -2 || fa == -2) {
                struct mech_error me;
                mech_error_clear(&me);
                mech_error_set(&me, MECH_ENOMEM, NULL, "out of memory");
                api_call_fail_core(c, MECH_ENOMEM, &me, "");
                return -1;
            }
            api_call_invalid(c, kind_ptr,
                             "kind %s compares a number, an array of numbers or "
                             "rows of numbers; %.200s is not one",
                             api_check_kind_name(g->kind), pointer);
            return -1;
        }
        for (size_t i = 0; i < rows * cols; i++)
            a[i] *= g->factor;
    }
    double lam[16], deg_tol = 0;
    int have_lam =
        g->kind == API_KIND_EIGENVECTORS && sibling_eigenvalues(parent, rows, lam, &deg_tol);
    struct api_check_outcome o;
    int st = api_check_compare(g->kind, e, a, rows, cols, have_lam ? lam : NULL, deg_tol, &g->tol,
                               &o, &why);
    if (e != ev) free(e);
    if (a != av) free(a);
    if (st) {
        api_call_invalid(c, kind_ptr, "kind %s does not fit %.200s: %s",
                         api_check_kind_name(g->kind), pointer, why ? why : "wrong shape");
        return -1;
    }
    g->note = why;
    grade_add(g, &o);
    int rowwise = g->kind == API_KIND_SUBSPACE || g->kind == API_KIND_EIGENVECTORS;
    for (size_t i = 0; i < o.nwrong; i++) {
        char ptr[600];
        if (rowwise && i < sizeof o.wrong / sizeof o.wrong[0])
            snprintf(ptr, sizeof ptr, "%.500s/%zu", pointer, o.wrong[i]);
        else
            snprintf(ptr, sizeof ptr, "%.500s", pointer);
        grade_wrong(g, ptr);
        if (!rowwise) break;
    }
    return 0;
}

void api_check_number_words(double x, char *buf, size_t n)
{
    char t[40];
    snprintf(t, sizeof t, "%.6g", x == 0 ? 0.0 : x); /* no "-0" */
    char *e = strchr(t, 'e');
    if (!e) {
        snprintf(buf, n, "%s", t);
        return;
    }
    /* 1e+06 -> 1e6, 2.5e-05 -> 2.5e-5 */
    int ex = atoi(e + 1);
    *e = '\0';
    snprintf(buf, n, "%se%d", t, ex);
}

/* A value in words into buf: numbers shortest (6 figures), arrays as
 * [a, b, c], an axis with its angle as "axis [x, y, z], angle a"; each
 * number divided by f (into the student's unit). */
static void value_words(const json_t *v, double f, char *buf, size_t n, int depth)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (json_is_number(v)) {
        api_check_number_words(json_number_value(v) / f, buf, n);
        return;
    }
    if (json_is_object(v)) {
        char ax[200], an[40];
        value_words(json_object_get(v, "axis"), 1, ax, sizeof ax, depth + 1);
        api_check_number_words(json_number_value(json_object_get(v, "angle")) / f, an, sizeof an);
        snprintf(buf, n, "axis %s, angle %s", ax, an);
        return;
    }
    if (!json_is_array(v) || depth > 8) return;
    size_t o = 0;
    for (size_t i = 0; i < json_array_size(v) && o + 8 < n; i++) {
        if (i == 20) {
            o += (size_t)snprintf(buf + o, n - o, ", ...");
            break;
        }
        o += (size_t)snprintf(buf + o, n - o, "%s", i ? ", " : "[");
        if (o >= n) break;
        value_words(json_array_get(v, i), f, buf + o, n - o, depth + 1);
        o += strlen(buf + o);
    }
    if (o + 2 < n) snprintf(buf + o, n - o, "]");
}

/* The student-facing message: the verdict, the slip or problem (`why`), what
 * was expected in shape, kind and unit, and the value itself only when
 * reveal is set. */
json_t *api_check_feedback(const struct api_check_grade *g, int correct, const json_t *want,
                           const char *unit, const char *field_unit, int reveal, const char *why)
{
    char shape[128], msg[1400];
    if (json_is_object(want))
        snprintf(shape, sizeof shape, "an axis of 3 numbers with an angle");
    else
        api_check_shape_words(want, shape, sizeof shape);
    const char *u = unit ? unit : field_unit;
    const char *what = kind_words(g->kind);
    if (json_is_array(want) && g->kind == API_KIND_NUMBER) what = "numbers, each judged on its own";
    if (json_is_array(want) && g->kind == API_KIND_ANGLE) what = "angles, each modulo a full turn";
    int n = snprintf(msg, sizeof msg, "%s%s%s Expected %s, given as %s%s%s%s",
                     correct ? "Correct." : "Not correct.", why && why[0] ? " " : "",
                     why ? why : "", what, shape, u && strcmp(u, "1") ? ", in " : "",
                     u && strcmp(u, "1") ? u : "", u && !strcmp(u, "1") ? ", dimensionless" : "");
    if (g->note && n > 0 && (size_t)n < sizeof msg)
        n += snprintf(msg + n, sizeof msg - (size_t)n, "; %s", g->note);
    if (n > 0 && (size_t)n < sizeof msg) n += snprintf(msg + n, sizeof msg - (size_t)n, ".");
    if (reveal && n > 0 && (size_t)n < sizeof msg) {
        char text[600];
        value_words(want, g->factor > 0 ? g->factor : 1, text, sizeof text, 0);
        snprintf(msg + n, sizeof msg - (size_t)n, " The expected value is %s%s%s.", text,
                 u && strcmp(u, "1") ? " " : "", u && strcmp(u, "1") ? u : "");
    }
    return json_string(msg);
}

int api_check_grade_field(struct api_call *c, struct api_check_grade *g, const json_t *want,
                          const json_t *value, const json_t *parent, const char *pointer,
                          const char *kind_ptr)
{
    if (g->kind == API_KIND_NUMBER || g->kind == API_KIND_ANGLE) {
        char ptr[1024];
        snprintf(ptr, sizeof ptr, "%s", pointer);
        grade_tree(g, want, value, ptr, sizeof ptr);
        return 0;
    }
    return grade_whole(c, g, want, value, parent, pointer, kind_ptr);
}
