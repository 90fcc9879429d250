/* check.c — POST /v1/check: grade a student's answer against any
 * operation's answer (POST /v1/batch is api/ops/tools/batch.c).
 *
 * Both run the inner operations in-process through api_run_operation(), the
 * same pipeline api_handle() uses (schema validation, handler, non-finite
 * check), sharing this request's budget: one deadline, one cancel flag.
 * Nesting (/v1/check or /v1/batch inside either) is refused, so the work of
 * one request stays bounded by API_BATCH_MAX operations. The rules for
 * tolerances are documented in docs/grading.md and in the route descriptions.
 *
 * The handler reads the request (check_read), runs the operation (check_run),
 * finds the field in its answer (check_target), sets the tolerance
 * (api_check_recommend, check_tolerance), grades (api_check_grade_field) and
 * encodes the verdict (check_encode). What a field is lives in api/check/check_field.c,
 * the comparisons by kind in api/check/check_kind.c, JSON pointers and numeric trees in
 * api/check/check_tree.c, the recommended tolerance in api/check/check_evidence.c, the grading
 * and feedback in api/check/check_grade.c.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check/check_answer.h"
#include "check/check_evidence.h"
#include "check/check_field.h"
#include "check/check_grade.h"
#include "check/check_kind.h"
#include "check/check_slip.h"
#include "check/check_tree.h"
#include "check/grading_nest.h"
#include "mech/base/constants.h"
#include "run/endpoint.h"
#include "http/respond.h"

#define CHECK_DEFAULT_RELATIVE 1e-2 /* tolerance when none is given */

/* What the request asks, read and checked before the operation runs.
 * Borrowed: strings and values from the body, units static, field_unit from
 * the operation's response schema (static after api_init). */
struct check_request {
    const char *op;            /* the operation's path */
    const json_t *request;     /* its request body */
    const char *pointer;       /* the field: an RFC 6901 pointer into its answer */
    const json_t *value;       /* the student's value */
    const json_t *tol;         /* "tolerance", or NULL */
    const char *unit_name;     /* answer.unit as given, or NULL */
    enum api_check_kind kind;  /* answer.kind, else the field's x-mechd-check kind */
    const char *field_unit;    /* the field's unit (a template until expanded), or NULL */
    const char *kind_ptr;      /* where a kind that does not fit the field is reported */
    int reveal;                /* name the expected value in the feedback */
    int figures_in_answer;     /* significant figures counted in the student's unit */
};

/* The field in the operation's answer (borrowed from it). */
struct check_target {
    json_t *want;              /* the expected value */
    json_t *parent;            /* its container, NULL for the root */
    const struct api_unit *fu; /* its unit, NULL when the answer does not fix one */
};

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

/* Read the request into *q and refuse what is the grader's mistake before
 * the operation runs: a nested operation, a malformed pointer. What the
 * student gave (answer.value, answer.unit) is never refused: it is read and
 * graded after the operation ran. Returns 0, or -1 after recording a 422. */
static int check_read(struct api_call *c, const json_t *body, struct check_request *q)
{
    const json_t *answer = json_object_get(body, "answer");
    q->op = api_string_of(body, "operation");
    q->request = json_object_get(body, "request");
    q->pointer = api_string_of(answer, "pointer");
    q->value = json_object_get(answer, "value");
    q->tol = json_object_get(body, "tolerance");
    const char *kind_name = api_string(answer, "kind", NULL); /* no default: the schema's */
    q->unit_name = api_string(answer, "unit", NULL);          /* no default: the field's */
    q->reveal = json_is_true(json_object_get(body, "reveal"));
    const char *fig = json_string_value(json_object_get(q->tol, "significant_figures_in"));
    q->figures_in_answer = fig && !strcmp(fig, "answer");

    if (api_is_nested_op(q->op)) {
        api_call_invalid(c, "/operation", "%s cannot be checked: /v1/check runs one operation",
                         q->op);
        return -1;
    }
    int bad = 0;
    if (q->pointer[0] && q->pointer[0] != '/') bad = 1;
    for (const char *p = q->pointer; *p && !bad; p++)
        if (*p == '~' && p[1] != '0' && p[1] != '1') bad = 1;
    if (bad) {
        api_call_invalid(c, "/answer/pointer",
                         "not a JSON pointer (RFC 6901): it starts with '/' and escapes '~' as ~0 "
                         "and '/' as ~1");
        return -1;
    }
    /* What the field is, from the operation's response schema (its x-mechd-check
     * annotations); the request's answer.kind overrides the kind. */
    api_check_field(q->op, q->pointer, &q->kind, &q->field_unit);
    if (kind_name) api_check_kind_parse(kind_name, &q->kind); /* the schema's enum: always known */
    q->kind_ptr = kind_name ? "/answer/kind" : "/answer/pointer";
    return 0;
}

/* Run the operation in-process (same budget). Returns its answer without the
 * measured "cost" (new reference), or NULL after recording the failure on c:
 * a 422 for an unknown operation, else the operation's own problem. */
static json_t *check_run(struct api_call *c, const struct check_request *q)
{
    json_t *res = NULL;
    int st = api_run_operation(c, q->op, q->request, "/request", &res);
    if (st < 0) {
        api_call_invalid(c, "/operation", "no POST operation at %.120s; GET /v1 lists them", q->op);
        return NULL;
    }
    if (st != 200) {
        fail_with_problem(c, res);
        json_decref(res);
        return NULL;
    }
    json_object_del(res, "cost"); /* measured, not computed: never an answer */
    return res;
}

/* The student's value (read) fits want: an {"axis", "angle"} object exactly
 * for kind axis_angle, else a numeric tree of want's shape. Returns the
 * problem (API_ANSWER_OK when it fits). */
static enum api_answer_problem check_shape(const struct check_request *q, const json_t *want,
                                           const json_t *value)
{
    char where[512] = "";
    size_t count = 0;
    if (q->kind == API_KIND_AXIS_ANGLE) {
        double x[4];
        return api_check_axis_angle_of(value, x) ? API_ANSWER_SHAPE : API_ANSWER_OK;
    }
    if (json_is_object(value)) return API_ANSWER_SHAPE;
    return api_check_same_shape(want, value, where, sizeof where, &count, 0) ? API_ANSWER_SHAPE
                                                                              : API_ANSWER_OK;
}

/* Find the field in the operation's answer res: it exists and is numeric
 * (or an axis_angle object). Expands q->field_unit. Returns 0 with *t filled,
 * or -1 after recording a 422 (the grader asked for a field that is not
 * there or cannot be graded). */
static int check_target(struct api_call *c, struct check_request *q, json_t *res,
                        struct check_target *t)
{
    int bad;
    t->want = api_check_pointer_get(res, q->pointer, &t->parent, &bad);
    if (!t->want) {
        api_call_invalid(c, "/answer/pointer", "%.200s does not exist in the answer of %.100s",
                         q->pointer, q->op);
        return -1;
    }
    const json_t *w = t->want;
    int aa = q->kind == API_KIND_AXIS_ANGLE;
    if ((!aa && !api_check_numeric_tree(w, 0)) || (aa && !json_is_object(w))) {
        api_call_invalid(c, q->kind_ptr,
                         "%.200s names a %s in the answer of %.100s, not %s",
                         q->pointer,
                         json_is_object(w)    ? "JSON object"
                         : json_is_string(w)  ? "string"
                         : json_is_boolean(w) ? "boolean"
                         : json_is_null(w)    ? "null"
                         : json_is_number(w)  ? "number"
                                              : "array that is not all numbers",
                         q->op,
                         aa ? "an {\"axis\", \"angle\"} object" : "a number or an array of numbers");
        return -1;
    }
    q->field_unit = api_check_unit_expand(q->field_unit, res); /* "{/energy_unit}/c" -> "GeV/c" */
    t->fu = q->field_unit ? api_unit_find(q->field_unit) : NULL;
    return 0;
}

/* The tolerance applied: the request's criteria (no schema defaults: an absent
 * criterion is off), else 1 % relative; the scale given, else the field's
 * (at least pi for angles); mechd's recommended tolerance always. Returns 1
 * when the criteria were defaulted (no relative, absolute or significant
 * figures given). */
static int check_tolerance(const json_t *tol, enum api_check_kind kind,
                           const struct api_check_recommended *rec, struct api_check_tol *t)
{
    int given = json_object_get(tol, "relative") || json_object_get(tol, "absolute") ||
                json_object_get(tol, "significant_figures");
    t->rel = given ? api_number(tol, "relative", -1) : CHECK_DEFAULT_RELATIVE;
    t->abs = given ? api_number(tol, "absolute", -1) : -1;
    t->sig = given ? (int)api_number(tol, "significant_figures", 0) : 0;
    t->sig_unit = 0;
    t->scale = json_object_get(tol, "scale") ? api_number(tol, "scale", rec->scale) : rec->scale;
    if ((kind == API_KIND_ANGLE || kind == API_KIND_AXIS_ANGLE) && t->scale < MECH_PI)
        t->scale = MECH_PI;
    t->rec_rel = rec->rel;
    t->rec_abs = rec->abs;
    return !given;
}

/* tolerance_applied of the answer (new reference). */
static json_t *check_encode_tolerance(struct api_call *c, const struct api_check_tol *t,
                                      int defaulted, double bound)
{
    json_t *ta = json_object();
    json_object_set_new_nocheck(ta, "relative", t->rel >= 0 ? api_real(c, t->rel) : json_null());
    json_object_set_new_nocheck(ta, "absolute", t->abs >= 0 ? api_real(c, t->abs) : json_null());
    json_object_set_new_nocheck(ta, "significant_figures",
                                t->sig > 0 ? json_integer(t->sig) : json_null());
    json_object_set_new_nocheck(ta, "significant_figures_in",
                                json_string(t->sig_unit > 0 ? "answer" : "field"));
    json_object_set_new_nocheck(ta, "scale", api_real(c, t->scale));
    json_object_set_new_nocheck(ta, "defaulted", json_boolean(defaulted));
    json_object_set_new_nocheck(ta, "rule",
                                json_string("any: correct when the error <= the largest of the "
                                            "criteria and the recommended tolerance; both "
                                            "within the tolerance at the scale: zero"));
    json_object_set_new_nocheck(ta, "bound", api_real(c, bound));
    return ta;
}

/* recommended_tolerance of the answer (new reference). */
static json_t *check_encode_recommended(struct api_call *c, const struct api_check_recommended *rec)
{
    json_t *rt = json_object();
    json_object_set_new_nocheck(rt, "relative", api_real(c, rec->rel));
    json_object_set_new_nocheck(rt, "absolute", api_real(c, rec->abs));
    json_object_set_new_nocheck(rt, "basis",
                                json_string(rec->from_diag ? "diagnostics" : "closed_form"));
    json_object_set_new_nocheck(rt, "evidence",
                                rec->from_diag ? json_pack("{s:s,s:o}", "pointer", rec->where,
                                                           "value", api_real(c, rec->evidence))
                                               : json_null());
    return rt;
}

/* What was found about the student's answer besides its errors. */
struct check_finding {
    enum api_answer_problem problem; /* API_ANSWER_OK: it was graded */
    struct api_check_slip slip;      /* a slip explaining a wrong graded answer */
    const char *unit_given;          /* the student's unit (canonical when known), or NULL */
    char why[600];                   /* the problem or the slip in words, or "" */
};

/* The verdict (new reference); steals g->wrong_ptrs, borrows want. An answer
 * that could not be graded (f->problem) is wrong, with no errors measured. */
static json_t *check_encode(struct api_call *c, const struct check_request *q,
                            const struct api_check_grade *g, json_t *want,
                            const struct api_check_recommended *rec, int defaulted,
                            const struct check_finding *f)
{
    int graded = f->problem == API_ANSWER_OK;
    int correct = graded && g->wrong == 0;
    const char *mistake = graded ? api_check_slip_name(f->slip.kind)
                                 : api_answer_problem_name(f->problem);
    int unit_ok = (graded && f->slip.kind != API_SLIP_UNIT) || f->problem == API_ANSWER_SHAPE;
    json_t *out = json_object();
    json_object_set_new_nocheck(out, "correct", json_boolean(correct));
    json_object_set_new_nocheck(out, "feedback",
                                api_check_feedback(g, correct, want,
                                                   unit_ok ? f->unit_given : NULL, q->field_unit,
                                                   q->reveal, f->why));
    json_object_set_new_nocheck(out, "mistake", mistake ? json_string(mistake) : json_null());
    json_object_set_new_nocheck(out, "kind", json_string(api_check_kind_name(q->kind)));
    json_object_set_new_nocheck(
        out, "unit",
        json_pack("{s:o,s:o,s:o}", "given", f->unit_given ? json_string(f->unit_given) : json_null(),
                  "field", q->field_unit ? json_string(q->field_unit) : json_null(), "factor",
                  api_real(c, g->factor)));
    json_object_set(out, "expected", want);
    json_object_set_new_nocheck(out, "absolute_error",
                                graded ? api_real(c, g->max_abs_err) : json_null());
    json_object_set_new_nocheck(out, "relative_error",
                                graded && g->have_rel ? api_real(c, g->max_rel_err) : json_null());
    double bound = graded ? g->max_bound
                          : api_check_bound(&g->tol, json_is_object(want)
                                                         ? fabs(json_number_value(
                                                               json_object_get(want, "angle")))
                                                         : api_check_max_abs(want, 0));
    json_object_set_new_nocheck(out, "tolerance_applied",
                                check_encode_tolerance(c, &g->tol, defaulted, bound));
    json_object_set_new_nocheck(out, "recommended_tolerance", check_encode_recommended(c, rec));
    json_object_set_new_nocheck(out, "compared", json_integer((json_int_t)g->count));
    if (!graded && g->wrong_ptrs) json_array_append_new(g->wrong_ptrs, json_string(q->pointer));
    json_object_set_new_nocheck(out, "wrong", g->wrong_ptrs);
    return out;
}

/* The factor from the student's unit to the field's, given / field in SI.
 * Between decimal prefixes it is a power of ten that the two rounded SI
 * factors miss by an ulp or two (GeV^2 / MeV^2 = 1.0000000000000002e6): then
 * that power of ten itself, so the answer shows 1e6 and grades with it. */
static double unit_ratio(double given_si, double field_si)
{
    const double r = given_si / field_si;
    if (!(r > 0) || !isfinite(r)) return r;
    const double p = pow(10.0, round(log10(r)));
    return fabs(r - p) <= 4 * DBL_EPSILON * p ? p : r;
}

/* A problem with the student's answer in words, into f->why: what was given
 * and what the answer is. value: as the student gave it; a: as read; fu: the
 * field's unit (NULL when unknown); shape: the expected shape in words. */
static void problem_words(struct check_finding *f, const json_t *value, const struct api_answer *a,
                          const struct api_unit *fu, const char *field_unit, int magnitude_right)
{
    char what[200] = "";
    if (fu)
        snprintf(what, sizeof what, "this answer is %s%s%s", api_unit_dim_words(fu->dim),
                 strcmp(fu->name, "1") ? ", in " : " (leave the unit out)",
                 strcmp(fu->name, "1") ? field_unit : "");
    const char *text = json_string_value(value);
    switch (f->problem) {
    case API_ANSWER_EMPTY: snprintf(f->why, sizeof f->why, "No answer was given."); break;
    case API_ANSWER_NOT_NUMBER:
        if (text && strchr(text, ','))
            snprintf(f->why, sizeof f->why,
                     "No number could be read from \"%.60s\": write decimals with a point "
                     "(2.5, not 2,5).", text);
        else if (text)
            snprintf(f->why, sizeof f->why, "No number could be read from \"%.60s\".", text);
        else
            snprintf(f->why, sizeof f->why, "No number could be read from your answer.");
        break;
    case API_ANSWER_NOT_FINITE:
        snprintf(f->why, sizeof f->why, "Your answer is not a finite number.");
        break;
    case API_ANSWER_UNIT_UNKNOWN:
        snprintf(f->why, sizeof f->why, "\"%.40s\" is not a unit mechd knows%s%s.", a->unit,
                 what[0] ? "; " : "", what);
        break;
    case API_ANSWER_UNIT_DIMENSION: {
        char dw[64];
        snprintf(dw, sizeof dw, "%s", api_unit_dim_words(a->su->dim));
        dw[0] = (char)(dw[0] - 'a' + 'A');
        snprintf(f->why, sizeof f->why, "%s was given (%s); %s.%s%s%s", dw, a->su->name, what,
                 magnitude_right ? " The number itself would be right in " : "",
                 magnitude_right ? field_unit : "", magnitude_right ? "." : "");
        break;
    }
    default: break;
    }
}

json_t *api_op_check(struct api_call *c, const json_t *body)
{
    struct check_request q;
    if (check_read(c, body, &q)) return NULL;
    json_t *res = check_run(c, &q);
    if (!res) return NULL;
    json_t *out = NULL;
    struct check_target t;
    struct api_answer a;
    memset(&a, 0, sizeof a);
    int read = check_target(c, &q, res, &t) ? 1 : api_answer_read(q.value, q.unit_name, &a);
    if (read < 0) {
        struct mech_error me;
        mech_error_clear(&me);
        mech_error_set(&me, MECH_ENOMEM, NULL, "out of memory");
        api_call_fail_core(c, MECH_ENOMEM, &me, "");
    }
    if (read == 0) {
        struct check_finding f;
        memset(&f, 0, sizeof f);
        f.problem = a.problem;
        f.unit_given = a.su ? a.su->name : a.unit[0] ? a.unit : NULL;
        if (f.problem == API_ANSWER_OK && a.su && t.fu && strcmp(a.su->dim, t.fu->dim))
            f.problem = API_ANSWER_UNIT_DIMENSION;
        if (f.problem == API_ANSWER_OK || f.problem == API_ANSWER_UNIT_DIMENSION)
            if (check_shape(&q, t.want, a.value) != API_ANSWER_OK) f.problem = API_ANSWER_SHAPE;
        struct api_check_recommended rec;
        api_check_recommend(res, q.pointer, t.want, t.parent, &rec);
        struct api_check_grade g;
        memset(&g, 0, sizeof g);
        int defaulted = check_tolerance(q.tol, q.kind, &rec, &g.tol);
        g.kind = q.kind;
        g.factor = a.su && f.problem == API_ANSWER_OK
                       ? unit_ratio(a.su->factor, t.fu ? t.fu->factor : 1)
                       : 1;
        if (q.figures_in_answer) g.tol.sig_unit = g.factor;
        g.wrong_ptrs = json_array();
        int failed = 0;
        if (f.problem == API_ANSWER_OK) {
            failed = api_check_grade_field(c, &g, t.want, a.value, t.parent, q.pointer, q.kind_ptr);
            if (!failed && g.wrong)
                failed = api_check_slip_find(c, &g, t.want, a.value, t.parent, q.pointer,
                                             t.fu ? t.fu->dim : NULL, g.factor != 1, &f.slip);
            if (!failed)
                api_check_slip_words(&f.slip, json_array_size(t.want), q.field_unit,
                                     f.unit_given, f.why, sizeof f.why);
        } else if (f.problem == API_ANSWER_SHAPE) {
            char shape[128] = "something that is not a number";
            if (a.value && !json_is_object(a.value)) api_check_shape_words(a.value, shape, sizeof shape);
            snprintf(f.why, sizeof f.why, "Your answer is %s.", shape);
        } else {
            int right = 0;
            if (f.problem == API_ANSWER_UNIT_DIMENSION) { /* is the number right as it stands? */
                struct api_check_grade g1 = g;
                g1.wrong_ptrs = NULL;
                failed = api_check_grade_field(c, &g1, t.want, a.value, t.parent, q.pointer,
                                               q.kind_ptr);
                right = !failed && g1.wrong == 0;
            }
            problem_words(&f, q.value, &a, t.fu, q.field_unit, right);
        }
        if (failed)
            json_decref(g.wrong_ptrs);
        else
            out = check_encode(c, &q, &g, t.want, &rec, defaulted, &f);
    }
    json_decref(a.value);
    json_decref(res);
    return out;
}
