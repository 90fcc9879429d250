/* check_grade.c — grading one field of POST /v1/check and its feedback
 * sentence (contracts in check_grade.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_grade.h"
#include "check_tree.h"

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
    case API_KIND_AXIS_ANGLE: return "a rotation as {\"axis\": [x, y, z], \"angle\": a}";
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

/* The student-facing message: the verdict, what was expected in shape, kind
 * and unit, and the value itself only when reveal is set. */
json_t *api_check_feedback(const struct api_check_grade *g, const json_t *want, const char *unit,
                           const char *field_unit, int reveal)
{
    char shape[128], msg[900];
    if (json_is_object(want))
        snprintf(shape, sizeof shape, "an object {\"axis\": [3 numbers], \"angle\": a number}");
    else
        api_check_shape_words(want, shape, sizeof shape);
    const char *u = unit ? unit : field_unit;
    const char *what = kind_words(g->kind);
    if (json_is_array(want) && g->kind == API_KIND_NUMBER) what = "numbers, each judged on its own";
    if (json_is_array(want) && g->kind == API_KIND_ANGLE) what = "angles, each modulo a full turn";
    int n = snprintf(msg, sizeof msg, "%s Expected %s, given as %s%s%s%s%s",
                     g->wrong == 0 ? "Correct." : "Not within the tolerance.", what, shape,
                     u && strcmp(u, "1") ? ", in " : "", u && strcmp(u, "1") ? u : "",
                     u && !strcmp(u, "1") ? ", dimensionless" : "",
                     !u ? " (in SI units unless answer.unit says otherwise)" : "");
    if (g->note && n > 0 && (size_t)n < sizeof msg)
        n += snprintf(msg + n, sizeof msg - (size_t)n, "; %s", g->note);
    if (n > 0 && (size_t)n < sizeof msg) snprintf(msg + n, sizeof msg - (size_t)n, ".");
    if (!reveal) return json_string(msg);
    json_t *shown =
        json_is_object(want) ? json_deep_copy(want) : api_check_scaled_copy(want, 1 / g->factor, 0);
    if (json_is_object(want) && shown && g->factor != 1)
        json_object_set_new(
            shown, "angle",
            json_real(json_number_value(json_object_get(want, "angle")) / g->factor));
    char *text =
        shown ? json_dumps(shown, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(6)) : NULL;
    json_decref(shown);
    char full[1400];
    snprintf(full, sizeof full, "%s The expected value is %.400s%s%s.", msg, text ? text : "?",
             u && strcmp(u, "1") ? " " : "", u && strcmp(u, "1") ? u : "");
    /* json_dumps allocates through jansson's allocator, which inside an
     * operation request is the per-thread arena (api_alloc.c): free(3) on that
     * memory aborts the process. Give it back the way it came. */
    json_malloc_t jmalloc;
    json_free_t jfree;
    json_get_alloc_funcs(&jmalloc, &jfree);
    if (text) jfree(text);
    return json_string(full);
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
