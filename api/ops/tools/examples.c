/* examples.c — GET /v1/examples: the course notes' worked examples (chapters
 * 0-3: rotations, the puck, the falling object, cannon balls, Foucault, tides,
 * dumbbell, cube, principal axes, the muon, length contraction, the twin
 * paradox, velocity addition, pi0 and neutron decay, Compton, the fields) and
 * the classic extras the labs use (Kepler, Mercury, light bending, GPS, heavy
 * top, Dzhanibekov, Henon-Heiles), each a ready request for one operation with
 * the notes' answer: a JSON pointer into the response, the value and the
 * rounding the notes print it with. The data is the file
 * api/ops/_examples/worked_examples.json (one object per entry: {id, title,
 * section (the notes' section), operation (path), request (a ready request
 * body), notes_answer: {pointer (JSON pointer into the answer), value,
 * rounding ({"relative": r} or {"absolute": a}, the notes' printed precision),
 * text}}; values are the notes' printed numbers or closed forms evaluated
 * independently), which the build turns into C strings (scripts/ops_gen.py ->
 * generated examples_data.h): compiled in, so the server reads no data files.
 * tests/integration/test_examples.py runs every entry against a server and
 * compares with the notes' answer. */
#include <pthread.h>

#include "run/endpoint.h"
#include "examples_data.h" /* generated */

static const char examples_doc[] =
    "Each example: id, title, section (of the course notes), operation (the path to POST to), "
    "request (a ready body), notes_answer {pointer (JSON pointer into the answer), value, "
    "rounding ({\"relative\": r} or {\"absolute\": a}: the precision the notes print), text}. "
    "POST request to operation and compare the number at pointer with value within rounding.";

/* The answer is built once (the data is compiled in) and shared: handlers
 * return a new reference to it, and jansson's reference counts are atomic,
 * so threads may hold it at once; nobody modifies it. */
static json_t *examples_answer;
static pthread_once_t examples_once = PTHREAD_ONCE_INIT;

static void examples_build(void)
{
    json_t *list = json_array();
    if (!list) return;
    const size_t n = sizeof api_examples_data / sizeof api_examples_data[0];
    for (size_t i = 0; i < n; i++) {
        json_error_t jerr;
        json_t *e = json_loads(api_examples_data[i], JSON_DECODE_INT_AS_REAL | JSON_REJECT_DUPLICATES,
                               &jerr);
        if (!e || json_array_append_new(list, e) != 0) {
            /* A broken entry is a build bug: the resource handler fails (500)
             * and tests/integration/test_examples.py catches it. */
            json_decref(list);
            return;
        }
    }
    examples_answer = json_pack("{s:i,s:s,s:o}", "count", (int)n, "doc", examples_doc,
                                "examples", list);
}

json_t *api_op_examples(struct api_call *c, const json_t *body)
{
    (void)c;
    (void)body;
    pthread_once(&examples_once, examples_build);
    return examples_answer ? json_incref(examples_answer) : NULL;
}

