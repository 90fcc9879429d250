/* check_field.h — what a field of an operation's answer is, for POST
 * /v1/check: its kind and SI unit, read from the operation's response schema
 * (api/ops/<domain>/<operation>.json), where a property or an array's items
 * may carry the annotation
 *
 *     "x-mechd-check": {"kind": "eigenvectors", "unit": "1"}
 *
 * ("kind" one of api_check_kind_parse's names, required; "unit" one of
 * api_unit_find's names, the unit the answer gives that field in, absent when
 * the operation does not fix it). A unit that depends on the request is a
 * template: "{/energy_unit}/c" is the answer's string at /energy_unit
 * followed by "/c" (MeV/c by default, GeV/c when the request asked for GeV).
 * scripts/ops_gen.py refuses an unknown kind or unit, and a template that
 * could expand to one, when it generates the route table, so a typo fails
 * the build.
 * docs/grading.md, "Kinds and units", is the user's description.
 */
#ifndef API_CHECK_FIELD_H
#define API_CHECK_FIELD_H

#include <jansson.h>

#include "check/check_kind.h"

/* The kind and unit of the field at JSON pointer `pointer` (RFC 6901, "" =
 * the whole answer) in an answer described by `schema` (a response schema;
 * borrowed). The schema is walked token by token: an object's "properties"
 * (the token unescaped: ~1 is '/', ~0 is '~'), an array's "items" (the token
 * must be an array index: digits), and where a node offers alternatives
 * ("oneOf"), the first alternative that has the next step.
 *
 *   kind: the annotation's kind at the field itself; API_KIND_NUMBER when the
 *         field has none (a part of a vector is a number).
 *   unit: the annotation's unit at the field, else the unit of the nearest
 *         enclosing array whose annotation has one (the elements of an array
 *         in metres are in metres); never through an object's properties (an
 *         axis with its angle in rad has a dimensionless axis). NULL when
 *         nothing says. Borrowed from the schema: valid while it lives. It
 *         may be a template: pass it through api_check_unit_expand.
 *
 * Returns 1 when an annotation applied (to the kind or the unit), 0 when none
 * did (then *kind = API_KIND_NUMBER, *unit = NULL). Never fails: a pointer the
 * schema does not describe, a NULL schema or an annotation with an unknown
 * kind or unit (which the build refuses) simply leave the defaults. Work is
 * linear in the pointer's length; no allocation; reentrant. */
int api_check_field_in_schema(const json_t *schema, const char *pointer,
                              enum api_check_kind *kind, const char **unit);

/* The same for the answer of the operation at `path` (e.g. "/v1/rigid/inertia"),
 * from its route's response schema (api_route_response_schema; available after
 * api_init()). An unknown path gives the defaults and 0. */
int api_check_field(const char *path, const char *pointer, enum api_check_kind *kind,
                    const char **unit);

/* The unit a field's unit (as api_check_field gave it) stands for in the
 * operation's answer (borrowed): spec itself when it is a unit name; each
 * "{/pointer}" in it replaced by the string at that JSON pointer of answer.
 * Returns the unit's static name (api_unit_find), or NULL when spec is NULL,
 * the answer has no string there or the result is no unit mechd knows. */
const char *api_check_unit_expand(const char *spec, const json_t *answer);

#endif
