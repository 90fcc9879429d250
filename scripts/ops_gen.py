#!/usr/bin/env python3
"""ops_gen.py — generate the route table from the operation data files.

    scripts/ops_gen.py OPS_DIR OUT_DIR [--sources API_DIR]
    scripts/ops_gen.py --check OPS_DIR --sources API_DIR

Each operation mechd serves is one data file, OPS_DIR/<domain>/<operation>.json
(README, "Adding an operation"); OPS_DIR/catalog_order.json lists them all, in
the order the catalog and the OpenAPI document show them. This script checks
every file and writes, into OUT_DIR (the build tree):

  ops.def          one API_OP(handler, method, path, summary, description,
                   request_schema, example, reports_cost, quick,
                   response_schema) line per operation, in catalog order: an
                   X-macro file (as Redis generates commands.def from
                   src/commands/*.json). api/run/routes.c expands it into the
                   route table.
  ops_handlers.h   the prototype of every handler, included by the handler
                   files (api/run/endpoint.h) so the compiler checks each one.
  examples_data.h  the worked examples GET /v1/examples serves, from
                   OPS_DIR/_examples/worked_examples.json (one C string per
                   entry, its text as written in the data file)
  ops.stamp        written on every successful run (ops.def and
                   ops_handlers.h are rewritten only when their text changes,
                   so an edit that does not change them recompiles nothing).

Schemas become compact JSON text (integers stay integers, reals stay reals:
a default 1e-9 is a real, "samples": 200 an integer). The example is copied
as written in the data file (its spacing and number spelling), since the
catalog's curl line quotes it.

A response schema's properties and items may carry the annotation
"x-mechd-check": {"kind": K, "unit": U} (what the field is for POST
/v1/check: api/check/check_field.h, docs/grading.md "Kinds and units"); K must be
a kind and U a unit of api/check/check_kind.c (read from its kind_names[] and
units[] tables when --sources is given), or a template such as
"{/energy_unit}/c" whose every expansion (the enum of the answer's string at
/energy_unit, or of the request property energy_unit) is one; no other "x-"
keyword is taken.

A request schema may take another operation's whole request schema with
{"$ref": "<domain>/<operation>.json#/request_schema", "description": ...}
(as /v1/rigid/rotate takes a /v1/rigid/inertia request as its "inertia"):
the reference is resolved here, at build time, into a copy of that schema
(the node's other keys, such as its description, kept), so the validator
checks and fills the nested request with the rest of the body and the
catalog shows it whole; an unknown or circular reference is an error.
A piece several operations share (a velocity, a rotation, the integrator
block) is written once, as the whole of api/ops/_defs/<name>.json, and taken
with {"$ref": "_defs/<name>.json"}, resolved the same way: the catalog and the
OpenAPI document show each copy inline, as if written out where it is used.

Any error — a file that is not JSON, a missing or unknown key, a wrong type,
a duplicate path or handler, a file missing from catalog_order.json, a
malformed x-mechd-check annotation, or (with --sources) a handler no api/
source defines or an unknown kind or unit — is printed naming the file and
the script exits 1, so the build fails. --check only checks (the lint test).

Python 3 standard library only; runs under any python3.
"""
import json
import os
import re
import sys

ENVELOPE_KEYS = ("cost",)  # added to every POST schema by api/run/routes.c
METHODS = ("GET", "POST")
REQUIRED = {"path": str, "method": str, "summary": str, "description": str, "handler": str,
            "flags": dict, "response_schema": dict}
POST_REQUIRED = {"request_schema": dict, "examples": list}
FLAGS = ("reports_cost", "quick")


class GenError(Exception):
    pass


def fail(where, msg):
    raise GenError("%s: %s" % (where, msg))


def load(path, rel):
    try:
        text = open(path, encoding="utf-8").read()
    except (OSError, UnicodeDecodeError) as e:
        fail(rel, "cannot read: %s" % e)
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as e:
        fail(rel, "not JSON: %s (line %d, column %d)" % (e.msg, e.lineno, e.colno))
    return text, doc


def example_texts(text, rel):
    """The raw text of each element of the file's "examples" array."""
    m = re.search(r'^\s*"examples"\s*:\s*\[', text, re.M)
    if not m:
        fail(rel, '"examples" must be a key of the top-level object')
    dec = json.JSONDecoder()
    out, i = [], m.end()
    while True:
        while text[i] in " \t\r\n":
            i += 1
        if text[i] == "]":
            return out
        _, end = dec.raw_decode(text, i)
        raw = text[i:end]
        if "\n" in raw:  # spread over lines: the curl line needs one
            raw = json.dumps(json.loads(raw), ensure_ascii=False)
        out.append(raw)
        i = end
        while text[i] in " \t\r\n":
            i += 1
        if text[i] == ",":
            i += 1


CHECK_KEY = "x-mechd-check"  # what a field of the answer is, for POST /v1/check


def check_vocabulary(src_dir):
    """The kind and unit names POST /v1/check knows, read from the C tables of
    SRC_DIR/check/check_kind.c (kind_names[], units[]): (kinds, units)."""
    rel = "api/check/check_kind.c"
    try:
        text = open(os.path.join(src_dir, "check", "check_kind.c"), encoding="utf-8").read()
    except OSError as e:
        fail(rel, "cannot read: %s" % e)
    m = re.search(r"kind_names\[API_KIND_COUNT\]\s*=\s*\{(.*?)\};", text, re.S)
    kinds = re.findall(r'"([^"]*)"', m.group(1)) if m else []
    m = re.search(r"struct api_unit units\[\]\s*=\s*\{(.*?)\n\};", text, re.S)
    units = re.findall(r'\{"([^"]*)",', m.group(1)) if m else []
    if not kinds or not units:
        fail(rel, "cannot find the kind_names[] and units[] tables (ops_gen.py reads them to "
             "check the %s annotations)" % CHECK_KEY)
    return set(kinds), set(units)


def unit_expansions(unit, doc, rel, where):
    """The units an annotation's unit can stand for: [unit], or for a template
    ("{/energy_unit}/c": the answer's string at /energy_unit, then "/c") one
    per value that string can take: the enum of that string in the response
    schema, else of the request property of the same name."""
    if unit is None:
        return []
    parts = re.split(r"\{([^{}]*)\}", unit)
    if len(parts) == 1:
        if "{" in unit or "}" in unit:
            fail(rel, "%s/unit: unbalanced braces in %r" % (where, unit))
        return [unit]
    choices = [[parts[0]]]
    for i in range(1, len(parts), 2):
        ptr = parts[i]
        node = doc["response_schema"]
        for tok in ptr.split("/")[1:] if ptr.startswith("/") else [None]:
            props = node.get("properties") if isinstance(node, dict) else None
            node = props.get(tok) if isinstance(props, dict) and tok is not None else None
            if node is None:
                break
        if not isinstance(node, dict) or node.get("type") != "string":
            fail(rel, "%s/unit: {%s} in %r must point at a string of the answer (a JSON "
                 "pointer through the response schema's properties)" % (where, ptr, unit))
        values = node.get("enum") or (doc.get("request_schema", {}).get("properties", {})
                                      .get(ptr.rsplit("/", 1)[-1], {}).get("enum"))
        if not values:
            fail(rel, "%s/unit: the values of {%s} are not listed (an enum in the response "
                 "schema or in the request property of that name)" % (where, ptr))
        choices.append([str(v) for v in values])
        choices.append([parts[i + 1]])
    out = [""]
    for c in choices:
        out = [a + b for a in out for b in c]
    return out


def check_annotations(schema, rel, where, vocab, allowed, doc, props_map=False):
    """Every x-mechd-check annotation in schema (a response schema when allowed)
    is {"kind": known kind, "unit"?: known unit or template}; no other x-
    keyword. vocab: (kinds, units), or None (shape checked only); doc: the
    operation's data file (for templates)."""
    if isinstance(schema, list):
        for i, v in enumerate(schema):
            check_annotations(v, rel, "%s/%d" % (where, i), vocab, allowed, doc)
        return
    if not isinstance(schema, dict):
        return
    for key, val in schema.items():
        here = "%s/%s" % (where, key.replace("~", "~0").replace("/", "~1"))
        if props_map:  # property names, not keywords
            check_annotations(val, rel, here, vocab, allowed, doc)
            continue
        if key.startswith("x-") and key != CHECK_KEY:
            fail(rel, "%s: unknown keyword %s (the one vendor keyword is %s)" % (here, key,
                                                                                CHECK_KEY))
        if key == CHECK_KEY:
            if not allowed:
                fail(rel, "%s: %s describes a field of the answer; it belongs in the "
                     "response_schema" % (here, CHECK_KEY))
            if not isinstance(val, dict) or "kind" not in val or set(val) - {"kind", "unit"}:
                fail(rel, '%s: must be {"kind": ..., "unit": ...} ("unit" optional), got %s'
                     % (here, compact(val)))
            for k in ("kind", "unit"):
                if k in val and not isinstance(val[k], str):
                    fail(rel, "%s/%s: must be a string" % (here, k))
            if vocab and val["kind"] not in vocab[0]:
                fail(rel, '%s/kind: unknown kind "%s" (known: %s)'
                     % (here, val["kind"], ", ".join(sorted(vocab[0]))))
            for unit in unit_expansions(val.get("unit"), doc, rel, here):
                if vocab and unit not in vocab[1]:
                    fail(rel, '%s/unit: unknown unit "%s" (known: %s; add a unit to '
                         "api/check/check_kind.c units[] first)"
                         % (here, unit, ", ".join(sorted(vocab[1]))))
            continue
        if key in ("examples", "default", "const", "enum"):
            continue  # values, not schemas
        check_annotations(val, rel, here, vocab, allowed, doc, props_map=key == "properties")


def check_op(doc, text, rel, vocab=None):
    if not isinstance(doc, dict):
        fail(rel, "the top level must be an object")
    method = doc.get("method")
    need = dict(REQUIRED)
    if method == "POST":
        need.update(POST_REQUIRED)
    for key, typ in need.items():
        if key not in doc:
            fail(rel, 'missing key "%s"' % key)
        if not isinstance(doc[key], typ):
            fail(rel, '"%s" must be a %s' % (key, {str: "string", dict: "object",
                                                    list: "array"}[typ]))
    unknown = set(doc) - set(REQUIRED) - set(POST_REQUIRED)
    if unknown:
        fail(rel, "unknown key(s) %s" % ", ".join(sorted(unknown)))
    if method not in METHODS:
        fail(rel, '"method" must be one of %s, got %r' % (", ".join(METHODS), method))
    if method == "GET" and ("request_schema" in doc or "examples" in doc):
        fail(rel, "a GET operation takes no body: no request_schema or examples")
    if not re.fullmatch(r"/v1/[a-z0-9/_-]+", doc["path"]):
        fail(rel, '"path" must be /v1/ followed by lower-case words, got %r' % doc["path"])
    if not re.fullmatch(r"api_op_[a-z0-9_]+", doc["handler"]):
        fail(rel, '"handler" must be a C identifier api_op_..., got %r' % doc["handler"])
    for k, v in doc["flags"].items():
        if k not in FLAGS:
            fail(rel, 'unknown flag "%s" (known: %s)' % (k, ", ".join(FLAGS)))
        if not isinstance(v, bool):
            fail(rel, 'flag "%s" must be true or false' % k)
    for k in FLAGS:
        if k not in doc["flags"]:
            fail(rel, 'missing flag "%s"' % k)
    if doc["response_schema"].get("type") != "object":
        fail(rel, 'the response_schema must describe an object ("type": "object")')
    check_annotations(doc["response_schema"], rel, "/response_schema", vocab, True, doc)
    if "request_schema" in doc:
        check_annotations(doc["request_schema"], rel, "/request_schema", vocab, False, doc)
    if method == "POST":
        if not isinstance(doc["request_schema"], dict):
            fail(rel, 'request_schema must be an object schema with "properties"')
        if "$ref" not in doc["request_schema"]:
            check_request_root(doc["request_schema"], rel)
        if not doc["examples"]:
            fail(rel, "give at least one example request")
        for i, ex in enumerate(doc["examples"]):
            if not isinstance(ex, dict):
                fail(rel, "examples[%d] must be an object (a request body)" % i)
        return example_texts(text, rel)
    return []


def check_request_root(s, rel):
    """A POST request schema's root (after any "$ref" there is resolved)."""
    if s.get("type") != "object" or not isinstance(s.get("properties"), dict):
        fail(rel, 'request_schema must be an object schema with "properties"')
    for k in ENVELOPE_KEYS:
        if k in s["properties"]:
            fail(rel, 'request_schema declares the envelope key "%s"; the route table '
                 "adds it to every operation" % k)


def defined_handlers(src_dir):
    """Names of the non-static functions returning json_t * defined in src_dir."""
    names = set()
    for dirpath, _, files in os.walk(src_dir):
        for f in files:
            if f.endswith(".c"):
                src = open(os.path.join(dirpath, f), encoding="utf-8").read()
                names.update(re.findall(r"^json_t\s*\*\s*(api_op_\w+)\s*\(", src, re.M))
    return names


def collect(ops_dir, src_dir=None):
    """The checked operations, in catalog order: [(rel, doc, example_texts)]."""
    order_path = os.path.join(ops_dir, "catalog_order.json")
    _, order = load(order_path, "catalog_order.json")
    if not isinstance(order, list) or not all(isinstance(x, str) for x in order):
        fail("catalog_order.json", 'must be an array of "<domain>/<operation>" names')
    found = {}
    for dirpath, _, files in os.walk(ops_dir):
        for f in sorted(files):
            full = os.path.join(dirpath, f)
            rel = os.path.relpath(full, ops_dir)
            if os.path.relpath(dirpath, ops_dir).split(os.sep)[0] in (DEFS, "_examples"):
                continue  # shared schema pieces and worked examples, read apart
            if full == order_path or f.endswith((".c", ".h")):
                continue  # the handlers and their readers live beside their data
            if not f.endswith(".json") or os.sep not in rel or rel.count(os.sep) != 1:
                fail(os.path.join(os.path.basename(ops_dir), rel),
                     "not an operation file: expected <domain>/<operation>.json")
            found[rel[:-len(".json")].replace(os.sep, "/")] = full
    seen = set()
    for name in order:
        if name in seen:
            fail("catalog_order.json", '"%s" is listed twice' % name)
        seen.add(name)
        if name not in found:
            fail("catalog_order.json", '"%s" is listed but api/ops/%s.json does not exist'
                 % (name, name))
    for name in found:
        if name not in seen:
            fail("api/ops/%s.json" % name, "not listed in api/ops/catalog_order.json (add it "
                 "where the catalog should show it)")
    ops, paths, handlers = [], {}, {}
    known = defined_handlers(src_dir) if src_dir else None
    vocab = check_vocabulary(src_dir) if src_dir else None
    for name in order:
        rel = "api/ops/%s.json" % name
        text, doc = load(found[name], rel)
        examples = check_op(doc, text, rel, vocab)
        if doc["path"] in paths:
            fail(rel, "duplicate path %s (also in %s)" % (doc["path"], paths[doc["path"]]))
        paths[doc["path"]] = rel
        if doc["handler"] in handlers:
            fail(rel, "duplicate handler %s (also in %s)" % (doc["handler"],
                                                            handlers[doc["handler"]]))
        handlers[doc["handler"]] = rel
        if known is not None and doc["handler"] not in known:
            fail(rel, "handler %s is not defined in %s (expected a line starting "
                 "'json_t *%s(struct api_call *call, const json_t *body)')"
                 % (doc["handler"], src_dir, doc["handler"]))
        ops.append((rel, doc, examples))
    rooted = [rel for rel, doc, _ in ops if isinstance(doc.get("request_schema"), dict)
              and "$ref" in doc["request_schema"]]
    resolve_refs(ops, load_defs(ops_dir))
    for rel, doc, _ in ops:
        if rel in rooted:
            check_request_root(doc["request_schema"], rel)
    return ops


DEFS = "_defs"


def load_defs(ops_dir):
    """{name: schema} of the shared pieces api/ops/_defs/<name>.json."""
    defs = {}
    d = os.path.join(ops_dir, DEFS)
    if os.path.isdir(d):
        for f in sorted(os.listdir(d)):
            rel = "api/ops/%s/%s" % (DEFS, f)
            if not re.fullmatch(r"[a-z0-9_]+\.json", f):
                fail(rel, "not a shared schema piece: expected api/ops/_defs/<name>.json")
            _, doc = load(os.path.join(d, f), rel)
            if not isinstance(doc, dict):
                fail(rel, "must be a JSON Schema object")
            defs[f[:-len(".json")]] = doc
    return defs


REF_RE = re.compile(r"^([a-z0-9_]+/[a-z0-9_]+)\.json#/request_schema$")
DEF_RE = re.compile(r"^_defs/([a-z0-9_]+)\.json$")


def resolve_refs(ops, defs=None):
    """Replace every {"$ref": "<domain>/<op>.json#/request_schema", ...} node of
    the request schemas by a copy of that operation's (resolved) request
    schema, and every {"$ref": "_defs/<name>.json", ...} by a copy of that
    shared piece (resolved), the node's other keys kept."""
    by_name = {rel[len("api/ops/"):-len(".json")]: doc for rel, doc, _ in ops}
    defs = defs or {}
    done, active = {}, set()

    def resolved(name, rel):
        if name in done:
            return done[name]
        if name in active:
            fail(rel, 'circular "$ref" through %s' % name)
        active.add(name)
        if name.startswith(DEFS + "/"):
            done[name] = walk(defs[name[len(DEFS) + 1:]], "api/ops/%s.json" % name)
        else:
            done[name] = walk(by_name[name].get("request_schema"), "api/ops/%s.json" % name)
        active.discard(name)
        return done[name]

    def walk(node, rel):
        if isinstance(node, list):
            return [walk(v, rel) for v in node]
        if not isinstance(node, dict):
            return node
        if "$ref" in node:
            ref = node["$ref"]
            d = DEF_RE.match(ref) if isinstance(ref, str) else None
            m = REF_RE.match(ref) if isinstance(ref, str) else None
            if d and d.group(1) in defs:
                target = DEFS + "/" + d.group(1)
            elif m and m.group(1) in by_name and "request_schema" in by_name[m.group(1)]:
                target = m.group(1)
            else:
                fail(rel, '"$ref": %s is not "<domain>/<operation>.json#/request_schema" of a '
                     'POST operation, nor "_defs/<name>.json" of a file in api/ops/_defs/'
                     % compact(ref))
            out = json.loads(json.dumps(resolved(target, rel)))
            for k, v in node.items():
                if k != "$ref":
                    out[k] = walk(v, rel)
            return out
        return {k: (v if k in ("examples", "default", "const", "enum") else walk(v, rel))
                for k, v in node.items()}

    for rel, doc, _ in ops:
        if "request_schema" in doc:
            doc["request_schema"] = resolved(rel[len("api/ops/"):-len(".json")], rel)


def c_string(s, indent="    "):
    """A C string literal (split into ~96-character pieces) holding s."""
    if s is None:
        return "NULL"
    b = s.encode("utf-8")
    pieces, cur = [], ""
    for ch in s:
        if ch == "\\":
            e = "\\\\"
        elif ch == '"':
            e = '\\"'
        elif ch == "\n":
            e = "\\n"
        elif ch == "?":
            e = "\\?"  # no trigraphs under -std=c11
        elif ord(ch) < 0x20:
            e = "\\%03o" % ord(ch)
        else:
            e = ch
        cur += e
        if len(cur) >= 96 and ch in " ,:":
            pieces.append(cur)
            cur = ""
    pieces.append(cur)
    del b
    return ("\n" + indent).join('"%s"' % p for p in pieces)


def compact(v):
    return json.dumps(v, ensure_ascii=False, separators=(",", ":"))


def generate(ops):
    hdr = ("/* Generated by scripts/ops_gen.py from api/ops/<domain>/<operation>.json: do not edit.\n"
           " * Edit the data file of the operation and rebuild. */\n")
    out = [hdr]
    for rel, doc, examples in ops:
        post = doc["method"] == "POST"
        out.append("/* %s */\nAPI_OP(%s, %s, %s,\n    %s,\n    %s,\n    %s,\n    %s,\n"
                   "    %d, %d,\n    %s)\n" % (
                       rel, doc["handler"], c_string(doc["method"]), c_string(doc["path"]),
                       c_string(doc["summary"]), c_string(doc["description"]),
                       c_string(compact(doc["request_schema"])) if post else "NULL",
                       c_string(examples[0]) if post else "NULL",
                       doc["flags"]["reports_cost"], doc["flags"]["quick"],
                       c_string(compact(doc["response_schema"]))))
    handlers = [hdr, "#ifndef API_OPS_HANDLERS_H\n#define API_OPS_HANDLERS_H\n\n",
                "struct api_call;\n\n"]
    for rel, doc, _ in ops:
        handlers.append("json_t *%s(struct api_call *call, const json_t *body); /* %s %s */\n"
                        % (doc["handler"], doc["method"], doc["path"]))
    handlers.append("\n#endif\n")
    return "".join(out), "".join(handlers)


EXAMPLES = os.path.join("_examples", "worked_examples.json")
EXAMPLE_KEYS = ("id", "title", "section", "operation", "request", "notes_answer")
ANSWER_KEYS = ("pointer", "value", "rounding", "text")


def load_examples(ops_dir, ops):
    """The worked examples of GET /v1/examples, checked: [entry text as written].

    The data file is a JSON array of objects {id, title, section, operation,
    request, notes_answer: {pointer, value, rounding, text}}; each id once, each
    operation the path of a POST operation, each request an object."""
    rel = "api/ops/" + EXAMPLES.replace(os.sep, "/")
    path = os.path.join(ops_dir, EXAMPLES)
    if not os.path.exists(path):
        return []
    text, doc = load(path, rel)
    if not isinstance(doc, list):
        fail(rel, "must be a JSON array of worked examples")
    posts = {d["path"] for _, d, _ in ops if d["method"] == "POST"}
    texts, ids, dec, i = [], set(), json.JSONDecoder(), text.index("[") + 1
    for n, entry in enumerate(doc):
        where = "%s: entry %d (%s)" % (rel, n, entry.get("id") if isinstance(entry, dict) else "?")
        if not isinstance(entry, dict) or tuple(entry) != EXAMPLE_KEYS:
            fail(where, "must be an object with the keys %s in that order" % ", ".join(EXAMPLE_KEYS))
        if entry["id"] in ids:
            fail(where, "repeats an id")
        ids.add(entry["id"])
        if entry["operation"] not in posts:
            fail(where, '"operation" %s is no POST operation\'s path' % compact(entry["operation"]))
        if not isinstance(entry["request"], dict):
            fail(where, '"request" must be an object (a request body)')
        na = entry["notes_answer"]
        if not isinstance(na, dict) or any(k not in na for k in ANSWER_KEYS):
            fail(where, '"notes_answer" needs %s' % ", ".join(ANSWER_KEYS))
        # the entry's own text, as written (spacing and number spelling kept)
        while text[i] in " \t\r\n,":
            i += 1
        _, end = dec.raw_decode(text, i)
        texts.append(text[i:end])
        i = end
    return texts


def generate_examples(texts):
    out = ["/* Generated by scripts/ops_gen.py from api/ops/_examples/worked_examples.json: do not\n"
           " * edit. Edit the data file and rebuild. */\n",
           "#ifndef API_EXAMPLES_DATA_H\n#define API_EXAMPLES_DATA_H\n\n",
           "static const char *const api_examples_data[] = {\n"]
    for t in texts:
        out.append("    %s,\n" % c_string(t))
    out.append("};\n\n#endif\n")
    return "".join(out)


def write_if_changed(path, text):
    try:
        if open(path, encoding="utf-8").read() == text:
            return
    except OSError:
        pass
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    args = list(argv[1:])
    check = "--check" in args
    if check:
        args.remove("--check")
    src = None
    if "--sources" in args:
        i = args.index("--sources")
        src = args[i + 1]
        del args[i:i + 2]
    if len(args) != (1 if check else 2):
        sys.stderr.write(__doc__)
        return 2
    try:
        ops = collect(args[0], src)
        examples = load_examples(args[0], ops)
    except GenError as e:
        sys.stderr.write("ops_gen: error: %s\n" % e)
        return 1
    if check:
        print("ops_gen: %d operations and %d worked examples, all valid" % (len(ops), len(examples)))
        return 0
    os.makedirs(args[1], exist_ok=True)
    table, handlers = generate(ops)
    write_if_changed(os.path.join(args[1], "ops.def"), table)
    write_if_changed(os.path.join(args[1], "ops_handlers.h"), handlers)
    write_if_changed(os.path.join(args[1], "examples_data.h"), generate_examples(examples))
    # Unchanged outputs keep their time (nothing recompiles); the stamp tells
    # the build the data files were checked.
    with open(os.path.join(args[1], "ops.stamp"), "w") as f:
        f.write("%d operations\n" % len(ops))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
