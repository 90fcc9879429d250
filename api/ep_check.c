/* ep_check.c — POST /v1/check: grade a student's answer against any
 * operation's answer (POST /v1/batch is ep_batch.c).
 *
 * Both run the inner operations in-process through api_run_operation(), the
 * same pipeline api_handle() uses (schema validation, handler, non-finite
 * check), sharing this request's budget: one deadline, one cancel flag.
 * Nesting (/v1/check or /v1/batch inside either) is refused, so the work of
 * one request stays bounded by API_BATCH_MAX operations. The rules for
 * tolerances are documented in docs/grading.md and in the route descriptions.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_field.h"
#include "check_kind.h"
#include "grading_nest.h"
#include "mech/constants.h"
#include "endpoint.h"
#include "respond.h"
#include "schema.h"

#define CHECK_DEFAULT_RELATIVE 1e-2       /* tolerance when none is given */
#define CHECK_CLOSED_FORM_RELATIVE 1e-12  /* numerical error assumed without evidence */
#define CHECK_EVIDENCE_FACTOR 10.0        /* safety factor on the operation's own error figures */
#define CHECK_MAX_ELEMENTS 100000         /* numbers compared in one answer */

/* ---- shared ----------------------------------------------------------------- */

/* Turn an inner problem object into this call's failure (pointers were already
 * prefixed by api_run_operation). */
static json_t *fail_with_problem(struct api_call *c, const json_t *problem)
{
    const char *type = json_string_value(json_object_get(problem, "type"));
    enum api_problem k = API_PROBLEM_INTERNAL;
    if (type && !strncmp(type, "/problems/", 10)) k = api_problem_by_slug(type + 10);
    if (k == API_PROBLEM_NONE) k = API_PROBLEM_INTERNAL;
    c->problem = k;
    const char *d = json_string_value(json_object_get(problem, "detail"));
    snprintf(c->detail, sizeof c->detail, "%s", d ? d : "the operation failed");
    const json_t *errors = json_object_get(problem, "errors");
    if (json_is_array(errors)) {
        json_decref(c->errors);
        c->errors = json_deep_copy(errors);
    }
    const char *key;
    json_t *v;
    json_object_foreach((json_t *)problem, key, v) {
        if (!strcmp(key, "type") || !strcmp(key, "title") || !strcmp(key, "status") ||
            !strcmp(key, "detail") || !strcmp(key, "errors"))
            continue;
        if (!c->extra) c->extra = json_object();
        if (c->extra) json_object_set(c->extra, key, v);
    }
    return NULL;
}

/* ---- RFC 6901 JSON pointer ------------------------------------------------------ */

/* Resolve pointer in doc; NULL if it does not exist or is malformed. When
 * parent is not NULL it receives the container holding the target (NULL for
 * the root). *bad is set when the pointer is syntactically invalid. */
static json_t *pointer_get(json_t *doc, const char *ptr, json_t **parent, int *bad)
{
    *bad = 0;
    if (parent) *parent = NULL;
    if (!ptr[0]) return doc;
    if (ptr[0] != '/') { *bad = 1; return NULL; }
    json_t *cur = doc;
    const char *p = ptr;
    char tok[256];
    while (*p == '/') {
        p++;
        size_t n = 0;
        while (*p && *p != '/') {
            char ch = *p++;
            if (ch == '~') {
                if (*p == '0') ch = '~';
                else if (*p == '1') ch = '/';
                else { *bad = 1; return NULL; }
                p++;
            }
            if (n + 1 >= sizeof tok) { *bad = 1; return NULL; }
            tok[n++] = ch;
        }
        tok[n] = '\0';
        if (parent) *parent = cur;
        if (json_is_object(cur)) {
            cur = json_object_get(cur, tok);
        } else if (json_is_array(cur)) {
            /* array index: "0" or digits without a leading zero */
            if (!n || (n > 1 && tok[0] == '0') || n > 9) return NULL;
            size_t idx = 0;
            for (size_t i = 0; i < n; i++) {
                if (tok[i] < '0' || tok[i] > '9') return NULL;
                idx = idx * 10 + (size_t)(tok[i] - '0');
            }
            cur = json_array_get(cur, idx);
        } else {
            return NULL;
        }
        if (!cur) return NULL;
    }
    return cur;
}

/* ---- recommended tolerance --------------------------------------------------------- */

/* Whether a diagnostics member is a relative-error figure of the computation
 * (not a physical quantity that happens to be relative, like relative_velocity). */
static int is_relative_evidence(const char *key)
{
    if (!strcmp(key, "target_error") || !strcmp(key, "quaternion_norm_drift")) return 1;
    if (!strstr(key, "relative") && !strstr(key, "_rel_")) return 0;
    return strstr(key, "error") || strstr(key, "drift") || strstr(key, "difference") ||
           strstr(key, "precision") || strstr(key, "bound");
}

/* Walk a diagnostics subtree, keeping the largest relative-error figure and
 * where it was. Objects that say "conserved": false are skipped: the drift of
 * a quantity that is not conserved is physics, not error; so are comparisons
 * with a first-order (approximate) reference, whose difference is the model's. */
static void scan_evidence(const json_t *j, char *ptr, size_t cap, double *worst, char *where,
                          size_t where_n, int depth)
{
    if (depth > 12) return;
    size_t len = strlen(ptr);
    if (json_is_object(j)) {
        if (json_is_false(json_object_get(j, "conserved"))) return;
        const char *kind = json_string_value(json_object_get(j, "kind"));
        if (kind && !strcmp(kind, "first_order")) return; /* a model, not the error */
        const char *key;
        json_t *v;
        json_object_foreach((json_t *)j, key, v) {
            api_pointer_append(ptr, cap, key);
            if (json_is_number(v)) {
                double x = fabs(json_number_value(v));
                if (is_relative_evidence(key) && isfinite(x) && x > *worst) {
                    *worst = x;
                    snprintf(where, where_n, "%s", ptr);
                }
            } else {
                scan_evidence(v, ptr, cap, worst, where, where_n, depth + 1);
            }
            ptr[len] = '\0';
        }
    } else if (json_is_array(j)) {
        size_t i;
        json_t *v;
        json_array_foreach(j, i, v) {
            snprintf(ptr + len, cap - len, "/%zu", i);
            scan_evidence(v, ptr, cap, worst, where, where_n, depth + 1);
            ptr[len] = '\0';
        }
    }
}

/* Evidence from the "diagnostics" members of the answer's root and of every
 * object on the way down to the pointer (the nearest context of the value). */
static double find_evidence(json_t *answer, const char *pointer, char *where, size_t where_n)
{
    double worst = 0;
    where[0] = '\0';
    char prefix[512];
    char scan[512];
    size_t plen = strlen(pointer);
    /* every prefix of the pointer that ends at a token boundary, root first */
    for (size_t cut = 0; cut <= plen && cut < sizeof prefix; cut++) {
        if (cut != 0 && cut != plen && pointer[cut] != '/') continue;
        memcpy(prefix, pointer, cut);
        prefix[cut] = '\0';
        int bad;
        json_t *node = pointer_get(answer, prefix, NULL, &bad);
        json_t *d = json_is_object(node) ? json_object_get(node, "diagnostics") : NULL;
        if (!json_is_object(d)) continue;
        snprintf(scan, sizeof scan, "%s", prefix);
        api_pointer_append(scan, sizeof scan, "diagnostics");
        scan_evidence(d, scan, sizeof scan, &worst, where, where_n, 0);
    }
    return worst;
}

/* ---- comparison ------------------------------------------------------------------ */

struct grade {
    struct api_check_tol tol;
    enum api_check_kind kind;
    double factor;        /* student's unit -> the field's unit */
    double max_abs_err, max_rel_err, max_bound;
    int have_rel;
    size_t count, wrong;
    const char *note;     /* from the comparison (a zero axis ...); NULL if none */
    json_t *wrong_ptrs;   /* pointers into the operation's answer */
};

static void grade_add(struct grade *g, const struct api_check_outcome *o)
{
    g->count += o->compared;
    if (o->abs_err > g->max_abs_err || isnan(o->abs_err)) g->max_abs_err = o->abs_err;
    if (o->have_rel && (!g->have_rel || o->rel_err > g->max_rel_err)) g->max_rel_err = o->rel_err;
    g->have_rel |= o->have_rel;
    if (o->bound > g->max_bound) g->max_bound = o->bound;
}

static void grade_wrong(struct grade *g, const char *ptr)
{
    g->wrong++;
    if (g->wrong_ptrs && json_array_size(g->wrong_ptrs) < 20)
        json_array_append_new(g->wrong_ptrs, json_string(ptr));
}

/* Element-wise kinds (number, angle): every number of the tree on its own. */
static void grade_tree(struct grade *g, const json_t *want, const json_t *got, char *ptr, size_t n)
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

/* Largest |number| in a JSON value (numbers and nested arrays). */
static double max_abs(const json_t *j, int depth)
{
    if (json_is_number(j)) return fabs(json_number_value(j));
    double m = 0;
    if (json_is_array(j) && depth < 8) {
        size_t i;
        json_t *v;
        json_array_foreach(j, i, v) {
            double x = max_abs(v, depth + 1);
            if (x > m) m = x;
        }
    }
    return m;
}

/* Numbers in a numeric tree. */
static size_t count_numbers(const json_t *j, int depth)
{
    if (json_is_number(j)) return 1;
    size_t n = 0;
    if (json_is_array(j) && depth < 8)
        for (size_t i = 0; i < json_array_size(j); i++)
            n += count_numbers(json_array_get(j, i), depth + 1);
    return n;
}

/* Shape of a numeric tree in words: "a number", "an array of 3 numbers",
 * "a 3 x 3 array", or "nested arrays of 12 numbers". */
static void shape_words(const json_t *j, char *buf, size_t n)
{
    if (json_is_number(j)) {
        snprintf(buf, n, "a number");
        return;
    }
    size_t rows = json_array_size(j);
    const json_t *first = json_array_get(j, 0);
    if (json_is_number(first)) {
        snprintf(buf, n, "an array of %zu number%s", rows, rows == 1 ? "" : "s");
        return;
    }
    size_t cols = json_array_size(first);
    int rect = json_is_array(first);
    for (size_t i = 0; i < rows && rect; i++) {
        const json_t *r = json_array_get(j, i);
        rect = json_is_array(r) && json_array_size(r) == cols &&
               json_is_number(json_array_get(r, 0));
    }
    if (rect)
        snprintf(buf, n, "a %zu x %zu array (%zu arrays of %zu numbers)", rows, cols, rows, cols);
    else
        snprintf(buf, n, "nested arrays of %zu numbers in all", count_numbers(j, 0));
}

/* Shape check: want (the expected value) and got (the answer's value) are both
 * numbers or arrays of the same length down to numbers. Returns 0, or -1 with
 * the pointer (relative to /answer/value) of the first mismatch in where. */
static int same_shape(const json_t *want, const json_t *got, char *where, size_t n, size_t *count,
                      int depth)
{
    if (json_is_number(want)) {
        if (!json_is_number(got)) return -1;
        (*count)++;
        return 0;
    }
    if (!json_is_array(want) || !json_is_array(got) || depth > 8 ||
        json_array_size(want) != json_array_size(got))
        return -1;
    size_t len = strlen(where);
    for (size_t i = 0; i < json_array_size(want); i++) {
        snprintf(where + len, n - len, "/%zu", i);
        if (same_shape(json_array_get(want, i), json_array_get(got, i), where, n, count,
                       depth + 1))
            return -1;
        where[len] = '\0';
    }
    return *count > CHECK_MAX_ELEMENTS ? -1 : 0;
}

/* Flatten a number, an array of numbers or a rectangular array of arrays of
 * numbers into x (malloc'ed, *rows x *cols); -1 for any other shape, -2 when
 * out of memory (*x stays NULL then). */
static int flatten2(const json_t *j, double **x, size_t *rows, size_t *cols)
{
    *x = NULL;
    if (json_is_number(j)) {
        *rows = *cols = 1;
    } else if (json_is_number(json_array_get(j, 0))) {
        *rows = 1;
        *cols = json_array_size(j);
    } else {
        *rows = json_array_size(j);
        *cols = json_array_size(json_array_get(j, 0));
    }
    if (!*rows || !*cols || *rows * *cols > CHECK_MAX_ELEMENTS) return -1;
    *x = malloc(*rows * *cols * sizeof **x);
    if (!*x) return -2;
    if (json_is_number(j)) {
        (*x)[0] = json_number_value(j);
        return 0;
    }
    for (size_t r = 0; r < *rows; r++) {
        const json_t *row =
            *rows == 1 && json_is_number(json_array_get(j, 0)) ? j : json_array_get(j, r);
        if (json_array_size(row) != *cols) goto bad;
        for (size_t c = 0; c < *cols; c++) {
            const json_t *v = json_array_get(row, c);
            if (!json_is_number(v)) goto bad;
            (*x)[r * *cols + c] = json_number_value(v);
        }
    }
    return 0;
bad:
    free(*x);
    *x = NULL;
    return -1;
}

/* {"axis": [x, y, z], "angle": t} as [x, y, z, t]; -1 if not that shape. */
static int axis_angle_of(const json_t *j, double x[4])
{
    const json_t *axis = json_object_get(j, "axis");
    const json_t *angle = json_object_get(j, "angle");
    if (!json_is_object(j) || json_object_size(j) != 2 || !json_is_array(axis) ||
        json_array_size(axis) != 3 || !json_is_number(angle))
        return -1;
    for (size_t i = 0; i < 3; i++) {
        if (!json_is_number(json_array_get(axis, i))) return -1;
        x[i] = json_number_value(json_array_get(axis, i));
    }
    x[3] = json_number_value(angle);
    return 0;
}

/* Whether a value is a number or a (nested) array with only numbers. */
static int numeric_tree(const json_t *j, int depth)
{
    if (json_is_number(j)) return 1;
    if (!json_is_array(j) || depth > 8 || json_array_size(j) == 0) return 0;
    size_t i;
    json_t *v;
    json_array_foreach(j, i, v) if (!numeric_tree(v, depth + 1)) return 0;
    return 1;
}

/* ---- POST /v1/check ------------------------------------------------------------------ */

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

/* A copy of a numeric tree with every number multiplied by f. */
static json_t *scaled_copy(const json_t *j, double f, int depth)
{
    if (json_is_number(j)) return json_real(json_number_value(j) * f);
    json_t *out = json_array();
    if (!out || depth > 8) return out;
    for (size_t i = 0; i < json_array_size(j); i++)
        json_array_append_new(out, scaled_copy(json_array_get(j, i), f, depth + 1));
    return out;
}

/* The student-facing message: the verdict, what was expected in shape, kind
 * and unit, and the value itself only when reveal is set. */
static json_t *feedback(const struct grade *g, const json_t *want, const char *unit,
                        const char *field_unit, int reveal)
{
    char shape[128], msg[900];
    if (json_is_object(want))
        snprintf(shape, sizeof shape, "an object {\"axis\": [3 numbers], \"angle\": a number}");
    else
        shape_words(want, shape, sizeof shape);
    const char *u = unit ? unit : field_unit;
    const char *what = kind_words(g->kind);
    if (json_is_array(want) && g->kind == API_KIND_NUMBER)
        what = "numbers, each judged on its own";
    if (json_is_array(want) && g->kind == API_KIND_ANGLE)
        what = "angles, each modulo a full turn";
    int n = snprintf(msg, sizeof msg, "%s Expected %s, given as %s%s%s%s%s",
                     g->wrong == 0 ? "Correct." : "Not within the tolerance.", what,
                     shape, u && strcmp(u, "1") ? ", in " : "", u && strcmp(u, "1") ? u : "",
                     u && !strcmp(u, "1") ? ", dimensionless" : "",
                     !u ? " (in SI units unless answer.unit says otherwise)" : "");
    if (g->note && n > 0 && (size_t)n < sizeof msg)
        n += snprintf(msg + n, sizeof msg - (size_t)n, "; %s", g->note);
    if (n > 0 && (size_t)n < sizeof msg) snprintf(msg + n, sizeof msg - (size_t)n, ".");
    if (!reveal) return json_string(msg);
    json_t *shown = json_is_object(want) ? json_deep_copy(want)
                                         : scaled_copy(want, 1 / g->factor, 0);
    if (json_is_object(want) && shown && g->factor != 1)
        json_object_set_new(shown, "angle",
                            json_real(json_number_value(json_object_get(want, "angle")) /
                                      g->factor));
    char *text =
        shown ? json_dumps(shown, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(6)) : NULL;
    json_decref(shown);
    char full[1400];
    snprintf(full, sizeof full, "%s The expected value is %.400s%s%s.", msg, text ? text : "?",
             u && strcmp(u, "1") ? " " : "", u && strcmp(u, "1") ? u : "");
    free(text);
    return json_string(full);
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
static int grade_whole(struct api_call *c, struct grade *g, const json_t *want,
                       const json_t *value, const json_t *parent, const char *pointer,
                       const char *kind_ptr)
{
    double *e = NULL, *a = NULL;
    double ev[4], av[4];
    size_t rows = 1, cols = 4;
    const char *why = NULL;
    if (g->kind == API_KIND_AXIS_ANGLE) {
        if (axis_angle_of(want, ev)) {
            api_call_invalid(c, kind_ptr, "axis_angle: %.200s is not an {\"axis\", \"angle\"} "
                             "object in the answer", pointer);
            return -1;
        }
        if (axis_angle_of(value, av)) {
            api_call_invalid(c, "/answer/value", "give the rotation as {\"axis\": [x, y, z], "
                             "\"angle\": a number}");
            return -1;
        }
        av[3] *= g->factor;
        e = ev;
        a = av;
    } else {
        size_t r2, c2;
        int fe = flatten2(want, &e, &rows, &cols);
        int fa = fe ? 0 : flatten2(value, &a, &r2, &c2);
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
            api_call_invalid(c, kind_ptr, "kind %s compares a number, an array of numbers or "
                             "rows of numbers; %.200s is not one", api_check_kind_name(g->kind),
                             pointer);
            return -1;
        }
        for (size_t i = 0; i < rows * cols; i++) a[i] *= g->factor;
    }
    double lam[16], deg_tol = 0;
    int have_lam = g->kind == API_KIND_EIGENVECTORS &&
                   sibling_eigenvalues(parent, rows, lam, &deg_tol);
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

json_t *api_op_check(struct api_call *c, const json_t *body)
{
    const char *op = api_string(body, "operation", "");
    const json_t *request = json_object_get(body, "request");
    const json_t *answer = json_object_get(body, "answer");
    const char *pointer = api_string(answer, "pointer", "");
    const json_t *value = json_object_get(answer, "value");
    const json_t *tol = json_object_get(body, "tolerance");
    const char *kind_name = api_string(answer, "kind", NULL);
    const char *unit_name = api_string(answer, "unit", NULL);
    int reveal = json_is_true(json_object_get(body, "reveal"));

    if (api_is_nested_op(op)) {
        api_call_invalid(c, "/operation", "%s cannot be checked: /v1/check runs one operation",
                         op);
        return NULL;
    }
    int bad = 0;
    if (pointer[0] && pointer[0] != '/') bad = 1;
    for (const char *p = pointer; *p && !bad; p++)
        if (*p == '~' && p[1] != '0' && p[1] != '1') bad = 1;
    if (bad) {
        api_call_invalid(c, "/answer/pointer",
                         "not a JSON pointer (RFC 6901): it starts with '/' and escapes '~' as ~0 "
                         "and '/' as ~1");
        return NULL;
    }
    const struct api_unit *su = NULL;
    if (unit_name && !(su = api_unit_find(unit_name))) {
        api_call_invalid(c, "/answer/unit", "unknown unit \"%.20s\"; mechd converts from: %s",
                         unit_name, api_unit_list);
        return NULL;
    }
    /* What the field is, from the operation's response schema (its x-mechd-check
     * annotations); the request's answer.kind overrides the kind. */
    enum api_check_kind kind;
    const char *field_unit;
    api_check_field(op, pointer, &kind, &field_unit);
    if (kind_name) api_check_kind_parse(kind_name, &kind); /* the schema's enum: always known */
    const char *kind_ptr = kind_name ? "/answer/kind" : "/answer/pointer";
    if (json_is_object(value) && kind != API_KIND_AXIS_ANGLE) {
        api_call_invalid(c, "/answer/value",
                         "an object is an answer only for kind axis_angle ({\"axis\": [x, y, z], "
                         "\"angle\": a}); give a number or an array");
        return NULL;
    }
    if (json_is_array(value) && !numeric_tree(value, 0)) {
        api_call_invalid(c, "/answer/value", "must be a number or (nested) arrays of numbers");
        return NULL;
    }

    json_t *res = NULL;
    int st = api_run_operation(c, op, request, "/request", &res);
    if (st < 0) {
        api_call_invalid(c, "/operation", "no POST operation at %.120s; GET /v1 lists them", op);
        return NULL;
    }
    if (st != 200) {
        fail_with_problem(c, res);
        json_decref(res);
        return NULL;
    }
    json_object_del(res, "cost"); /* measured, not computed: never an answer */

    json_t *parent = NULL;
    json_t *want = pointer_get(res, pointer, &parent, &bad);
    if (!want) {
        api_call_invalid(c, "/answer/pointer", "%.200s does not exist in the answer of %.100s",
                         pointer, op);
        json_decref(res);
        return NULL;
    }
    if (kind != API_KIND_AXIS_ANGLE && !numeric_tree(want, 0)) {
        api_call_invalid(c, "/answer/pointer",
                         "%.200s names a %s in the answer of %.100s, not a number or an array of "
                         "numbers",
                         pointer,
                         json_is_object(want)   ? "JSON object"
                         : json_is_string(want) ? "string"
                         : json_is_boolean(want) ? "boolean"
                         : json_is_null(want)   ? "null"
                                                : "array that is not all numbers",
                         op);
        json_decref(res);
        return NULL;
    }
    field_unit = api_check_unit_expand(field_unit, res); /* "{/energy_unit}/c" -> "GeV/c" */
    const struct api_unit *fu = field_unit ? api_unit_find(field_unit) : NULL;
    if (su && fu && strcmp(su->dim, fu->dim)) {
        api_call_invalid(c, "/answer/unit",
                         "%.20s does not measure what %.200s is: give a unit convertible to %s%s",
                         unit_name, pointer, field_unit,
                         !strcmp(field_unit, "1") ? " (a pure number: leave unit out)" : "");
        json_decref(res);
        return NULL;
    }
    if (kind != API_KIND_AXIS_ANGLE) {
        char where[512] = "";
        size_t count = 0;
        if (same_shape(want, value, where, sizeof where, &count, 0)) {
            char shape[128], gave[128] = "something else";
            shape_words(want, shape, sizeof shape);
            if (json_is_number(value) || numeric_tree(value, 0))
                shape_words(value, gave, sizeof gave);
            api_call_invalid(c, "/answer/value",
                             "%.200s is %s: give %s, not %s%s%.200s%s", pointer, shape, shape,
                             gave, json_is_number(want) ? "" : " (first mismatch at /answer/value",
                             json_is_number(want) ? "" : where,
                             json_is_number(want) ? "" : ")");
            json_decref(res);
            return NULL;
        }
    }

    /* recommended tolerance from the operation's own error evidence */
    char ev_where[512];
    double evidence = find_evidence(res, pointer, ev_where, sizeof ev_where);
    double rec_rel = CHECK_EVIDENCE_FACTOR * evidence;
    int from_diag = rec_rel > CHECK_CLOSED_FORM_RELATIVE;
    if (!from_diag) rec_rel = CHECK_CLOSED_FORM_RELATIVE;
    double scale = json_is_object(want) ? 0 : max_abs(want, 0);
    if (json_is_number(want) && json_is_array(parent)) {
        double s = max_abs(parent, 0);
        if (s > scale) scale = s;
    }
    double rec_abs = rec_rel * scale;

    struct grade g;
    memset(&g, 0, sizeof g);
    int given = json_is_object(tol) && json_object_size(tol) > 0;
    int only_scale = given && json_object_size(tol) == 1 && json_object_get(tol, "scale");
    g.tol.rel = given && !only_scale ? api_number(tol, "relative", -1) : CHECK_DEFAULT_RELATIVE;
    g.tol.abs = given ? api_number(tol, "absolute", -1) : -1;
    g.tol.sig = given ? (int)api_number(tol, "significant_figures", 0) : 0;
    g.tol.scale = given ? api_number(tol, "scale", scale) : scale;
    if ((kind == API_KIND_ANGLE || kind == API_KIND_AXIS_ANGLE) && g.tol.scale < MECH_PI)
        g.tol.scale = MECH_PI;
    g.tol.rec_rel = rec_rel;
    g.tol.rec_abs = rec_abs;
    g.kind = kind;
    g.factor = su ? su->factor / (fu ? fu->factor : 1) : 1;
    g.wrong_ptrs = json_array();
    if (kind == API_KIND_NUMBER || kind == API_KIND_ANGLE) {
        char ptr[1024];
        snprintf(ptr, sizeof ptr, "%s", pointer);
        grade_tree(&g, want, value, ptr, sizeof ptr);
    } else if (grade_whole(c, &g, want, value, parent, pointer, kind_ptr)) {
        json_decref(g.wrong_ptrs);
        json_decref(res);
        return NULL;
    }

    json_t *out = json_object();
    json_object_set_new_nocheck(out, "correct", json_boolean(g.wrong == 0));
    json_object_set_new_nocheck(out, "feedback",
                                feedback(&g, want, unit_name, field_unit, reveal));
    json_object_set_new_nocheck(out, "kind", json_string(api_check_kind_name(kind)));
    json_object_set_new_nocheck(
        out, "unit",
        json_pack("{s:o,s:o,s:o}", "given", unit_name ? json_string(unit_name) : json_null(),
                  "field", field_unit ? json_string(field_unit) : json_null(), "factor",
                  api_real(c, g.factor)));
    json_object_set(out, "expected", want);
    json_object_set_new_nocheck(out, "absolute_error", api_real(c, g.max_abs_err));
    json_object_set_new_nocheck(out, "relative_error",
                                g.have_rel ? api_real(c, g.max_rel_err) : json_null());
    json_t *ta = json_object();
    json_object_set_new_nocheck(ta, "relative",
                                g.tol.rel >= 0 ? api_real(c, g.tol.rel) : json_null());
    json_object_set_new_nocheck(ta, "absolute",
                                g.tol.abs >= 0 ? api_real(c, g.tol.abs) : json_null());
    json_object_set_new_nocheck(ta, "significant_figures",
                                g.tol.sig > 0 ? json_integer(g.tol.sig) : json_null());
    json_object_set_new_nocheck(ta, "scale", api_real(c, g.tol.scale));
    json_object_set_new_nocheck(ta, "defaulted", json_boolean(!given || only_scale));
    json_object_set_new_nocheck(ta, "rule",
                                json_string("any: correct when the error <= the largest of the "
                                            "criteria and the recommended tolerance; both "
                                            "within the tolerance at the scale: zero"));
    json_object_set_new_nocheck(ta, "bound", api_real(c, g.max_bound));
    json_object_set_new_nocheck(out, "tolerance_applied", ta);
    json_t *rt = json_object();
    json_object_set_new_nocheck(rt, "relative", api_real(c, rec_rel));
    json_object_set_new_nocheck(rt, "absolute", api_real(c, rec_abs));
    json_object_set_new_nocheck(rt, "basis",
                                json_string(from_diag ? "diagnostics" : "closed_form"));
    json_object_set_new_nocheck(
        rt, "evidence",
        from_diag ? json_pack("{s:s,s:o}", "pointer", ev_where, "value", api_real(c, evidence))
                  : json_null());
    json_object_set_new_nocheck(out, "recommended_tolerance", rt);
    json_object_set_new_nocheck(out, "compared", json_integer((json_int_t)g.count));
    json_object_set_new_nocheck(out, "wrong", g.wrong_ptrs);
    json_decref(res);
    return out;
}
