#!/usr/bin/env python3
"""test_ops_gen.py — scripts/ops_gen.py runs clean on api/ops, and fails,
naming the file, on each kind of broken data file.

    test_ops_gen.py SOURCE_DIR

1. `ops_gen.py --check api/ops --sources api` passes: every data file is
   JSON with the required keys, listed once in catalog_order.json, with a
   handler that api/ defines.
2. Broken copies of api/ops (one fault each: not JSON, a missing key, an
   unknown key, a duplicate path, an unknown handler, a file not listed, a
   listed file missing, an envelope key in a request schema, an
   x-mechd-check annotation with an unknown kind or unit, without a kind or
   with an extra key, another x- keyword, an annotation in a request
   schema, a unit template that can expand to no unit, points at no string
   of the answer or has unbalanced braces, a "$ref" to no operation's
   request schema or a circular one) each make the generator exit 1 with a
   message naming the file; a "$ref" is replaced by the schema it names;
   the kinds and units it reads from api/check/check_kind.c are the C lists.
3. Generating into a scratch directory writes ops.def with one API_OP per
   data file and ops_handlers.h with one prototype each.
Python 3 standard library only.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

SRC = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                      os.path.join(os.path.dirname(__file__), "..", "..", ".."))
GEN = os.path.join(SRC, "scripts", "ops_gen.py")
OPS = os.path.join(SRC, "api", "ops")
API = os.path.join(SRC, "api")
failures = 0


def run(*args):
    p = subprocess.run([sys.executable, GEN] + list(args), capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def check(cond, what):
    global failures
    if not cond:
        failures += 1
        print("FAIL:", what)


rc, out = run("--check", OPS, "--sources", API)
check(rc == 0, "ops_gen --check on api/ops: %s" % out.strip())
order = json.load(open(os.path.join(OPS, "catalog_order.json")))
check(len(order) >= 55, "catalog_order lists every operation (%d)" % len(order))


def broken(name, mutate, expect_file, expect_text):
    tmp = tempfile.mkdtemp()
    try:
        ops = os.path.join(tmp, "ops")
        shutil.copytree(OPS, ops)
        mutate(ops)
        rc, out = run("--check", ops, "--sources", API)
        check(rc == 1, "%s: exit status %d, want 1" % (name, rc))
        check(expect_file in out and expect_text in out,
              "%s: message %r should name %s and say %r" % (name, out.strip(), expect_file,
                                                           expect_text))
    finally:
        shutil.rmtree(tmp)


def edit(rel, fn):
    def mutate(ops):
        p = os.path.join(ops, rel)
        doc = json.load(open(p))
        fn(doc)
        json.dump(doc, open(p, "w"), indent=2)
    return mutate


def write(rel, text):
    def mutate(ops):
        open(os.path.join(ops, rel), "w").write(text)
    return mutate


broken("not JSON", write("relativity/boost.json", '{"path": "/v1/relativity/boost",'),
       "api/ops/relativity/boost.json", "not JSON")
broken("missing key", edit("rigid/inertia.json", lambda d: d.pop("summary")),
       "api/ops/rigid/inertia.json", 'missing key "summary"')
broken("missing response schema", edit("rigid/inertia.json", lambda d: d.pop("response_schema")),
       "api/ops/rigid/inertia.json", 'missing key "response_schema"')
broken("unknown key", edit("vectors/vectors.json", lambda d: d.update(sumary="x")),
       "api/ops/vectors/vectors.json", "unknown key(s) sumary")
broken("duplicate path", edit("vectors/vectors.json", lambda d: d.update(path="/v1/tensor/symmetric")),
       "api/ops/vectors/vectors.json", "duplicate path /v1/tensor/symmetric")
broken("unknown handler", edit("gr/geodesic.json", lambda d: d.update(handler="api_op_no_such")),
       "api/ops/gr/geodesic.json", "handler api_op_no_such is not defined")
broken("envelope key", edit("gr/geodesic.json",
                            lambda d: d["request_schema"]["properties"].update(cost={})),
       "api/ops/gr/geodesic.json", 'envelope key "cost"')
broken("bad flag", edit("gr/geodesic.json", lambda d: d["flags"].update(quick=1)),
       "api/ops/gr/geodesic.json", 'flag "quick" must be true or false')
broken("not listed", write("gr/extra.json", "{}"), "api/ops/gr/extra.json",
       "not listed in api/ops/catalog_order.json")
broken("listed, missing", lambda ops: os.remove(os.path.join(ops, "gr", "geodesic.json")),
       "catalog_order.json", '"gr/geodesic" is listed but api/ops/gr/geodesic.json does not exist')

# "$ref" to another operation's request schema: resolved at build time; an
# unknown target, another kind of reference or a cycle fails the build.
def inertia_ref(d):
    return d["request_schema"]["properties"]["inertia"]


broken("unknown $ref", edit("rigid/rotate.json",
                            lambda d: inertia_ref(d).update({"$ref": "rigid/inertias.json#/request_schema"})),
       "api/ops/rigid/rotate.json", '"$ref": "rigid/inertias.json#/request_schema" is not')
broken("$ref outside request_schema", edit("rigid/rotate.json", lambda d: inertia_ref(d).update(
    {"$ref": "rigid/inertia.json#/response_schema"})),
       "api/ops/rigid/rotate.json", "is not \"<domain>/<operation>.json#/request_schema\"")
broken("circular $ref", edit("rigid/inertia.json", lambda d: d["request_schema"]["properties"]
                             .update(spin={"$ref": "rigid/rotate.json#/request_schema"})),
       "api/ops/rigid/", 'circular "$ref"')
sys.path.insert(0, os.path.join(SRC, "scripts"))
import ops_gen  # noqa: E402
_ops = {rel: doc for rel, doc, _ in ops_gen.collect(OPS, API)}
_inertia = _ops["api/ops/rigid/inertia.json"]["request_schema"]
_inlined = _ops["api/ops/rigid/rotate.json"]["request_schema"]["properties"]["inertia"]
check("$ref" not in json.dumps(_inlined) and _inlined["properties"] == _inertia["properties"]
      and _inlined["required"] == _inertia["required"]
      and _inlined["description"].startswith("a full POST /v1/rigid/inertia request"),
      "rotate's inertia is inertia's request schema inlined, its own description kept")

# A shared piece, api/ops/_defs/<name>.json, is taken whole by {"$ref":
# "_defs/<name>.json"} and inlined where it is used; an unknown piece fails.
broken("unknown _defs $ref", edit("relativity/boost.json", lambda d: d["request_schema"]
                                  ["properties"]["velocity"].update({"$ref": "_defs/velocty.json"})),
       "api/ops/relativity/boost.json", '"$ref": "_defs/velocty.json" is not')
broken("not a piece", write("_defs/Velocity.txt", "{}"), "api/ops/_defs/Velocity.txt",
       "not a shared schema piece")
# The worked examples (GET /v1/examples) are data too: an entry whose operation
# is no POST path, or an id given twice, fails the build naming the entry.
broken("example of no operation", edit("_examples/worked_examples.json",
                                       lambda d: d[1].update(operation="/v1/rotation/converts")),
       "api/ops/_examples/worked_examples.json: entry 1", "is no POST operation")
broken("example id twice", edit("_examples/worked_examples.json",
                                lambda d: d[2].update(id=d[0]["id"])),
       "api/ops/_examples/worked_examples.json: entry 2", "repeats an id")
_velocity = json.load(open(os.path.join(OPS, "_defs", "velocity.json"), encoding="utf-8"))
check(_ops["api/ops/relativity/boost.json"]["request_schema"]["properties"]["velocity"] == _velocity
      and _ops["api/ops/relativity/doppler.json"]["request_schema"]["properties"]
      ["observer_velocity"] == _velocity,
      "the velocity piece is inlined whole where the operations take it")


# x-mechd-check annotations (what a field is for POST /v1/check): a typo in a
# kind or unit, a malformed annotation, another x- keyword or an annotation
# in a request schema fails the build.
def axes(d):
    return d["response_schema"]["properties"]["principal"]["properties"]["axes"]


broken("unknown kind", edit("rigid/inertia.json",
                            lambda d: axes(d)["x-mechd-check"].update(kind="eigenvector")),
       "api/ops/rigid/inertia.json", 'unknown kind "eigenvector"')
broken("unknown unit", edit("rigid/inertia.json", lambda d: d["response_schema"]["properties"]
                            ["mass"]["x-mechd-check"].update(unit="kilogram")),
       "api/ops/rigid/inertia.json", 'unknown unit "kilogram"')
broken("annotation without kind", edit("rigid/inertia.json",
                                       lambda d: axes(d).update({"x-mechd-check": {"unit": "1"}})),
       "api/ops/rigid/inertia.json", "/principal/properties/axes/x-mechd-check: must be")
broken("annotation extra key", edit("rigid/inertia.json", lambda d: axes(d)["x-mechd-check"]
                                    .update(units="1")),
       "api/ops/rigid/inertia.json", "x-mechd-check: must be")
broken("other vendor keyword", edit("rigid/inertia.json",
                                    lambda d: axes(d).update({"x-mechd-kind": "axis"})),
       "api/ops/rigid/inertia.json", "unknown keyword x-mechd-kind")
broken("annotation in a request schema", edit("gr/geodesic.json", lambda d: d["request_schema"]
                                              .update({"x-mechd-check": {"kind": "number"}})),
       "api/ops/gr/geodesic.json", "it belongs in the response_schema")

def decay_unit(unit):
    def fn(d):
        d["response_schema"]["properties"]["q_value"]["x-mechd-check"]["unit"] = unit
    return edit("relativity/kinematics_decay.json", fn)


broken("template expanding to no unit", decay_unit("{/energy_unit}/s"),
       "api/ops/relativity/kinematics_decay.json", 'unknown unit "eV/s"')
broken("template pointing nowhere", decay_unit("{/units}/c"),
       "api/ops/relativity/kinematics_decay.json", "{/units} in '{/units}/c' must point at a string")
broken("template without listed values", decay_unit("{/parent/mass}"),
       "api/ops/relativity/kinematics_decay.json", "must point at a string")
broken("unbalanced template", decay_unit("{/energy_unit/c"),
       "api/ops/relativity/kinematics_decay.json", "unbalanced braces")

# Every kind and unit the C tables know is accepted (ops_gen reads them from
# api/check/check_kind.c): the vocabulary it reads is the one the server parses.
sys.path.insert(0, os.path.join(SRC, "scripts"))
import ops_gen  # noqa: E402
kinds, units = ops_gen.check_vocabulary(API)
kind_list = re.search(r'api_check_kind_list\[\] =\s*"([^;]*)";',
                      open(os.path.join(API, "check", "check_kind.c")).read(), re.S).group(1)
unit_list = re.search(r'api_unit_list\[\] =\s*(".*?");',
                      open(os.path.join(API, "check", "check_kind.c")).read(), re.S).group(1)
unit_list = "".join(re.findall(r'"([^"]*)"', unit_list))
check(kinds == set(kind_list.split(", ")), "kinds read %s = api_check_kind_list" % sorted(kinds))
check(units == set(unit_list.split(", ")), "units read = api_unit_list (%d)" % len(units))
check("eigenvectors" in kinds and "MeV/c" in units and "deg" in units, "vocabulary sample")

tmp = tempfile.mkdtemp()
try:
    rc, out = run(OPS, tmp, "--sources", API)
    check(rc == 0, "generation: %s" % out)
    ops_def = open(os.path.join(tmp, "ops.def")).read()
    handlers = open(os.path.join(tmp, "ops_handlers.h")).read()
    check(len(re.findall(r"^API_OP\(", ops_def, re.M)) == len(order), "one API_OP per data file")
    check(len(re.findall(r"^json_t \*api_op_\w+\(", handlers, re.M)) == len(order),
          "one prototype per data file")
    check("do not edit" in ops_def, "ops.def says it is generated")
finally:
    shutil.rmtree(tmp)

print("test_ops_gen: %s" % ("FAILED (%d)" % failures if failures else "ok"))
sys.exit(1 if failures else 0)
