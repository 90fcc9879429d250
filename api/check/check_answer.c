/* check_answer.c — reading what a student typed for POST /v1/check: numbers
 * and small expressions with a unit after them, arrays of them, and the unit
 * names students write (contracts in api/check/check_answer.h). A tiny recursive
 * descent reader (depth- and length-bounded) instead of a general parser:
 * numbers, pi, sqrt( ), + - * / ^, parentheses and "x 10^n".
 */
#include "check/check_answer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mech/base/constants.h"

#define ANSWER_TEXT_MAX 200 /* longest text read as a number with its unit */
#define ANSWER_DEPTH_MAX 24 /* nesting of parentheses and unary signs */
#define ANSWER_TREE_DEPTH 9 /* nesting of arrays (as api/check/check_tree.c) */

/* ---- the expression reader ------------------------------------------------------- */

struct reader {
    const char *s; /* the next unread byte */
    int depth;
    int err;
};

static void skip_space(struct reader *r)
{
    while (*r->s == ' ' || *r->s == '\t' || *r->s == '\n' || *r->s == '\r')
        r->s++;
}

/* The bytes at r->s start with word w (then consumed): 1, else 0. */
static int take(struct reader *r, const char *w)
{
    size_t n = strlen(w);
    if (strncmp(r->s, w, n)) return 0;
    r->s += n;
    return 1;
}

/* A minus sign: '-', or U+2212 (what word processors and phones put). */
static int take_minus(struct reader *r)
{
    return take(r, "-") || take(r, "\xe2\x88\x92");
}

static double expr(struct reader *r);
static double unary(struct reader *r);

/* Something that can start a factor: a digit, a point before a digit, pi,
 * sqrt, an opening parenthesis. */
static int starts_primary(const char *s)
{
    return (*s >= '0' && *s <= '9') || (*s == '.' && s[1] >= '0' && s[1] <= '9') || *s == '(' ||
           !strncmp(s, "pi", 2) || !strncmp(s, "\xcf\x80", 2) || !strncmp(s, "sqrt(", 5);
}

static double primary(struct reader *r)
{
    skip_space(r);
    if (take(r, "pi") || take(r, "\xcf\x80")) return MECH_PI;
    int sq = take(r, "sqrt(");
    if (sq || take(r, "(")) {
        if (++r->depth > ANSWER_DEPTH_MAX) {
            r->err = 1;
            return 0;
        }
        double v = expr(r);
        r->depth--;
        skip_space(r);
        if (!take(r, ")")) r->err = 1;
        return sq ? sqrt(v) : v;
    }
    if (!starts_primary(r->s)) {
        r->err = 1;
        return 0;
    }
    if (r->s[0] == '0' && (r->s[1] == 'x' || r->s[1] == 'X')) { /* "0x 10^3" is not hex */
        r->s++;
        return 0;
    }
    char *end;
    double v = strtod(r->s, &end); /* starts with a digit or ".d": no inf, nan or hex */
    r->s = end;
    return v;
}

/* A primary followed by implicit products ("2 pi", "2(1+x)", "3 sqrt(2)")
 * and "x 10^n" / "× 10^n". */
static double factor(struct reader *r)
{
    double v = primary(r);
    while (!r->err) {
        const char *save = r->s;
        skip_space(r);
        if (!strncmp(r->s, "pi", 2) || !strncmp(r->s, "\xcf\x80", 2) || *r->s == '(' ||
            !strncmp(r->s, "sqrt(", 5)) {
            v *= primary(r);
            continue;
        }
        if (take(r, "x") || take(r, "\xc3\x97")) { /* x 10^n, × 10^n */
            skip_space(r);
            if (starts_primary(r->s)) {
                double b = primary(r);
                const char *at = r->s;
                skip_space(r);
                if (take(r, "^") || take(r, "**"))
                    b = pow(b, unary(r));
                else
                    r->s = at;
                v *= b;
                continue;
            }
        }
        r->s = save;
        break;
    }
    return v;
}

static double power(struct reader *r)
{
    double v = factor(r);
    const char *save = r->s;
    skip_space(r);
    if (!r->err && (take(r, "^") || take(r, "**"))) {
        skip_space(r);
        if (starts_primary(r->s) || *r->s == '-' || *r->s == '+') return pow(v, unary(r));
    }
    r->s = save;
    return v;
}

static double unary(struct reader *r)
{
    skip_space(r);
    if (++r->depth > ANSWER_DEPTH_MAX) {
        r->err = 1;
        return 0;
    }
    double v;
    if (take_minus(r))
        v = -unary(r);
    else if (take(r, "+"))
        v = unary(r);
    else
        v = power(r);
    r->depth--;
    return v;
}

static double term(struct reader *r)
{
    double v = unary(r);
    while (!r->err) {
        const char *save = r->s;
        skip_space(r);
        int div = 0;
        if (take(r, "/"))
            div = 1;
        else if (!(take(r, "*") || take(r, "\xc2\xb7") || take(r, "\xc3\x97"))) {
            r->s = save;
            break;
        }
        const char *after = r->s;
        skip_space(r);
        if (!starts_primary(r->s) && *r->s != '-' && *r->s != '+') { /* "5 m/s": a unit */
            r->s = save;
            break;
        }
        r->s = after;
        double w = unary(r);
        v = div ? v / w : v * w;
    }
    return v;
}

static double expr(struct reader *r)
{
    double v = term(r);
    while (!r->err) {
        const char *save = r->s;
        skip_space(r);
        int minus = take_minus(r);
        if (!minus && !take(r, "+")) {
            r->s = save;
            break;
        }
        skip_space(r);
        if (!starts_primary(r->s)) { /* not a sum: leave it to the unit */
            r->s = save;
            break;
        }
        double w = term(r);
        v = minus ? v - w : v + w;
    }
    return v;
}

/* Text -> number and the unit after it (copied into unit, n bytes; "" when
 * none). Returns the problem. */
static enum api_answer_problem read_text(const char *text, double *x, char *unit, size_t n)
{
    unit[0] = '\0';
    struct reader r = {text, 0, 0};
    skip_space(&r);
    if (!*r.s) return API_ANSWER_EMPTY;
    if (strlen(text) > ANSWER_TEXT_MAX) return API_ANSWER_NOT_NUMBER;
    *x = expr(&r);
    if (r.err) return API_ANSWER_NOT_NUMBER;
    skip_space(&r);
    size_t len = strlen(r.s);
    while (len && (r.s[len - 1] == ' ' || r.s[len - 1] == '\t' || r.s[len - 1] == '\n'))
        len--;
    if (len >= n) return API_ANSWER_UNIT_UNKNOWN;
    memcpy(unit, r.s, len);
    unit[len] = '\0';
    if (len && (unit[0] == ',' || (unit[0] >= '0' && unit[0] <= '9')))
        return API_ANSWER_NOT_NUMBER; /* "1,5", "3 4": no unit starts so */
    if (!isfinite(*x)) return API_ANSWER_NOT_FINITE;
    return API_ANSWER_OK;
}

/* ---- units ------------------------------------------------------------------------ */

/* Unit text without spaces, '*', '.', '·', '⋅' and '^', with µ/μ as u, ° as
 * deg, ² and ³ as digits, into out (n bytes). */
static void unit_squash(const char *in, char *out, size_t n)
{
    size_t o = 0;
    for (const unsigned char *p = (const unsigned char *)in; *p && o + 4 < n;) {
        const char *rep = NULL;
        size_t skip = 1;
        if (*p == ' ' || *p == '\t' || *p == '*' || *p == '.' || *p == '^') {
            rep = "";
        } else if (p[0] == 0xc2 && p[1]) {
            skip = 2;
            rep = p[1] == 0xb5 ? "u" : p[1] == 0xb0 ? "deg" : p[1] == 0xb2 ? "2"
                : p[1] == 0xb3 ? "3" : p[1] == 0xb7 ? "" : NULL;
        } else if (p[0] == 0xce && p[1] == 0xbc) {
            skip = 2;
            rep = "u";
        } else if (p[0] == 0xe2 && p[1] == 0x8b && p[2] == 0x85) {
            skip = 3;
            rep = "";
        }
        if (rep) {
            size_t k = strlen(rep);
            if (o + k + 1 >= n) break;
            memcpy(out + o, rep, k);
            o += k;
            p += skip;
        } else {
            out[o++] = (char)*p++;
        }
    }
    out[o] = '\0';
}

/* Words students write for units, squashed, and the unit each names. */
static const char *const unit_words[][2] = {
    {"metre", "m"},      {"metres", "m"},       {"meter", "m"},        {"meters", "m"},
    {"kilometre", "km"}, {"kilometres", "km"},  {"kilometer", "km"},   {"kilometers", "km"},
    {"micron", "um"},    {"microns", "um"},     {"second", "s"},       {"seconds", "s"},
    {"sec", "s"},        {"secs", "s"},         {"minute", "min"},     {"minutes", "min"},
    {"mins", "min"},     {"hour", "h"},         {"hours", "h"},        {"hr", "h"},
    {"hrs", "h"},        {"days", "day"},       {"d", "day"},          {"year", "yr"},
    {"years", "yr"},     {"yrs", "yr"},         {"kilogram", "kg"},    {"kilograms", "kg"},
    {"kgs", "kg"},       {"gram", "g"},         {"grams", "g"},        {"joule", "J"},
    {"joules", "J"},     {"degree", "deg"},     {"degrees", "deg"},    {"degs", "deg"},
    {"radian", "rad"},   {"radians", "rad"},    {"rev/min", "rpm"},    {"r/min", "rpm"},
    {"rad/sec", "rad/s"}, {"rads-1", "rad/s"},  {"1/s", "Hz"},         {"s-1", "Hz"},
    {"ms-1", "m/s"},     {"ms-2", "m/s^2"},     {"m/s/s", "m/s^2"},    {"kph", "km/h"},
    {"newton", "N"},     {"newtons", "N"},      {"newtonmetre", "N m"}, {"newtonmeter", "N m"},
    {"watt", "W"},       {"watts", "W"},        {"kgm2/s2", "J"},      {"Nms", "J s"},
    {"kgm/s2", "N"},     {"revolution", "rev"}, {"revolutions", "rev"}, {"turn", "rev"},
    {"turns", "rev"},    {"hertz", "Hz"},       {"none", "1"},         {"dimensionless", "1"},
};

const struct api_unit *api_unit_read(const char *typed)
{
    if (!typed) return NULL;
    const struct api_unit *u = api_unit_find(typed);
    if (u) return u;
    char want[96];
    unit_squash(typed, want, sizeof want);
    if (!want[0]) return NULL;
    for (size_t i = 0; i < sizeof unit_words / sizeof unit_words[0]; i++)
        if (!strcmp(want, unit_words[i][0])) return api_unit_find(unit_words[i][1]);
    /* every known name, squashed the same way (the list is "a, b, c") */
    for (const char *p = api_unit_list; *p;) {
        size_t len = strcspn(p, ",");
        char name[32], sq[48];
        if (len < sizeof name) {
            memcpy(name, p, len);
            name[len] = '\0';
            unit_squash(name, sq, sizeof sq);
            if (!strcmp(sq, want)) return api_unit_find(name);
        }
        p += len;
        while (*p == ',' || *p == ' ')
            p++;
    }
    return NULL;
}

const char *api_unit_dim_words(const char *dim)
{
    static const char *const words[][2] = {
        {"1", "a pure number"},           {"L", "a length"},
        {"T", "a time"},                  {"M", "a mass"},
        {"E", "an energy"},               {"angle", "an angle"},
        {"L/T", "a speed"},               {"L/T2", "an acceleration"},
        {"angle/T", "an angular velocity"}, {"1/T", "a frequency"},
        {"ML2", "a moment of inertia"},   {"ML2/T", "an angular momentum (or an action)"},
        {"ML/T", "a momentum"},           {"E2", "a squared energy"},
        {"F", "a force"},                 {"torque", "a torque"},
        {"P", "a power"},
    };
    for (size_t i = 0; dim && i < sizeof words / sizeof words[0]; i++)
        if (!strcmp(dim, words[i][0])) return words[i][1];
    return "a quantity";
}

const char *api_answer_problem_name(enum api_answer_problem p)
{
    switch (p) {
    case API_ANSWER_EMPTY: return "no_answer";
    case API_ANSWER_NOT_NUMBER: return "not_a_number";
    case API_ANSWER_NOT_FINITE: return "not_finite";
    case API_ANSWER_UNIT_UNKNOWN: return "unit_unknown";
    case API_ANSWER_UNIT_DIMENSION: return "unit_dimension";
    case API_ANSWER_SHAPE: return "shape";
    default: return NULL;
    }
}

/* ---- the value ---------------------------------------------------------------------- */

/* A unit met inside the value: adopt the first, refuse a second that differs. */
static enum api_answer_problem adopt_unit(struct api_answer *out, const char *unit)
{
    if (!unit[0]) return API_ANSWER_OK;
    if (!out->unit[0]) {
        strncpy(out->unit, unit, sizeof out->unit - 1);
        out->unit[sizeof out->unit - 1] = '\0';
        return API_ANSWER_OK;
    }
    return strcmp(out->unit, unit) ? API_ANSWER_NOT_NUMBER : API_ANSWER_OK;
}

/* v (borrowed) -> a new numeric tree in *res (NULL on a problem); strings
 * are read as numbers with their unit (adopted into out). *nomem is set when
 * an allocation failed (then the problem returned is meaningless). */
static enum api_answer_problem tree_of(const json_t *v, struct api_answer *out, json_t **res,
                                       int depth, int *nomem)
{
    *res = NULL;
    double x = 0;
    if (json_is_number(v)) {
        x = json_number_value(v);
        if (!isfinite(x)) return API_ANSWER_NOT_FINITE;
    } else if (json_is_string(v)) {
        char unit[64];
        enum api_answer_problem p = read_text(json_string_value(v), &x, unit, sizeof unit);
        if (p == API_ANSWER_OK) p = adopt_unit(out, unit);
        if (p != API_ANSWER_OK) return p;
    } else if (json_is_array(v)) {
        if (depth >= ANSWER_TREE_DEPTH) return API_ANSWER_NOT_NUMBER;
        if (json_array_size(v) == 0) return depth ? API_ANSWER_NOT_NUMBER : API_ANSWER_EMPTY;
        json_t *a = json_array();
        if (!a) {
            *nomem = 1;
            return API_ANSWER_NOT_NUMBER;
        }
        size_t i;
        const json_t *e;
        json_array_foreach(v, i, e) {
            json_t *el;
            enum api_answer_problem p = tree_of(e, out, &el, depth + 1, nomem);
            if (p != API_ANSWER_OK || *nomem) {
                json_decref(a);
                return p;
            }
            if (json_array_append_new(a, el)) { /* steals el even when it fails */
                *nomem = 1;
                json_decref(a);
                return API_ANSWER_NOT_NUMBER;
            }
        }
        *res = a;
        return API_ANSWER_OK;
    } else if (json_is_null(v)) {
        return API_ANSWER_EMPTY;
    } else {
        return API_ANSWER_NOT_NUMBER; /* booleans; objects where a number belongs */
    }
    *res = json_real(x);
    if (!*res) *nomem = 1;
    return API_ANSWER_OK;
}

int api_answer_read(const json_t *value, const char *unit_given, struct api_answer *out)
{
    memset(out, 0, sizeof *out);
    enum api_answer_problem p;
    int nomem = 0;
    const char *text = json_string_value(value);
    while (text && (*text == ' ' || *text == '\t'))
        text++;
    if (text && (*text == '[' || *text == '{')) { /* an array or object written as text */
        json_error_t err;
        json_t *parsed = json_loads(text, JSON_DECODE_ANY, &err);
        if (!parsed) {
            out->problem = API_ANSWER_NOT_NUMBER;
            return json_error_code(&err) == json_error_out_of_memory ? -1 : 0;
        }
        int rc = api_answer_read(parsed, unit_given, out);
        json_decref(parsed);
        return rc;
    }
    if (json_is_object(value)) { /* {"axis": [...], "angle": a}: each part read */
        const json_t *axis = json_object_get(value, "axis"), *angle = json_object_get(value, "angle");
        json_t *ax = NULL, *an = NULL;
        p = axis && angle && json_object_size(value) == 2 ? tree_of(axis, out, &ax, 1, &nomem)
                                                          : API_ANSWER_NOT_NUMBER;
        if (p == API_ANSWER_OK && !nomem) p = tree_of(angle, out, &an, 1, &nomem);
        if (p == API_ANSWER_OK && !nomem && (!json_is_array(ax) || !json_is_number(an)))
            p = API_ANSWER_NOT_NUMBER;
        if (p == API_ANSWER_OK && !nomem) {
            out->value = json_object();
            if (!out->value || json_object_set(out->value, "axis", ax) ||
                json_object_set(out->value, "angle", an))
                nomem = 1;
        }
        json_decref(ax);
        json_decref(an);
    } else {
        p = tree_of(value, out, &out->value, 0, &nomem);
    }
    if (p == API_ANSWER_OK && !out->unit[0] && unit_given) {
        strncpy(out->unit, unit_given, sizeof out->unit - 1);
        out->unit[sizeof out->unit - 1] = '\0';
    }
    if (p == API_ANSWER_OK && out->unit[0] && !(out->su = api_unit_read(out->unit)))
        p = API_ANSWER_UNIT_UNKNOWN;
    out->problem = p;
    if (p != API_ANSWER_OK || nomem) {
        json_decref(out->value);
        out->value = NULL;
    }
    return nomem ? -1 : 0;
}
