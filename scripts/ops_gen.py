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
                   src/commands/*.json). api/routes.c expands it into the
                   route table.
  ops_handlers.h   the prototype of every handler, included by the handler
                   files (api/endpoint.h) so the compiler checks each one.
  ops.stamp        written on every successful run (ops.def and
                   ops_handlers.h are rewritten only when their text changes,
                   so an edit that does not change them recompiles nothing).

Schemas become compact JSON text (integers stay integers, reals stay reals:
a default 1e-9 is a real, "samples": 200 an integer). The example is copied
as written in the data file (its spacing and number spelling), since the
catalog's curl line quotes it.

Any error — a file that is not JSON, a missing or unknown key, a wrong type,
a duplicate path or handler, a file missing from catalog_order.json, or (with
--sources) a handler no api/ source defines — is printed naming the file and
the script exits 1, so the build fails. --check only checks (the lint test).

Python 3 standard library only; runs under any python3.
"""
import json
import os
import re
import sys

ENVELOPE_KEYS = ("cost",)  # added to every POST schema by api/routes.c
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


def check_op(doc, text, rel):
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
    if method == "POST":
        s = doc["request_schema"]
        if s.get("type") != "object" or not isinstance(s.get("properties"), dict):
            fail(rel, 'request_schema must be an object schema with "properties"')
        for k in ENVELOPE_KEYS:
            if k in s["properties"]:
                fail(rel, 'request_schema declares the envelope key "%s"; the route table '
                     "adds it to every operation" % k)
        if not doc["examples"]:
            fail(rel, "give at least one example request")
        for i, ex in enumerate(doc["examples"]):
            if not isinstance(ex, dict):
                fail(rel, "examples[%d] must be an object (a request body)" % i)
        return example_texts(text, rel)
    return []


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
            if full == order_path:
                continue
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
    for name in order:
        rel = "api/ops/%s.json" % name
        text, doc = load(found[name], rel)
        examples = check_op(doc, text, rel)
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
    return ops


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
    except GenError as e:
        sys.stderr.write("ops_gen: error: %s\n" % e)
        return 1
    if check:
        print("ops_gen: %d operations, all valid" % len(ops))
        return 0
    os.makedirs(args[1], exist_ok=True)
    table, handlers = generate(ops)
    write_if_changed(os.path.join(args[1], "ops.def"), table)
    write_if_changed(os.path.join(args[1], "ops_handlers.h"), handlers)
    # Unchanged outputs keep their time (nothing recompiles); the stamp tells
    # the build the data files were checked.
    with open(os.path.join(args[1], "ops.stamp"), "w") as f:
        f.write("%d operations\n" % len(ops))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
