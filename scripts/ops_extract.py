#!/usr/bin/env python3
"""ops_extract.py — convert old-style operations (a `const struct api_route`
in api/ep_*.c with its schema, description and example as C strings) into
data files api/ops/<domain>/<operation>.json, the form scripts/ops_gen.py
turns into the route table (issue 17).

Usage:
    scripts/ops_extract.py BUILD/mechd [--rewrite-c]

It starts BUILD/mechd (built from the old-style tree) on 127.0.0.1:0, reads
GET /v1 and GET /v1/openapi.json (what the route table serves: summary,
description, request schema, example) and, from the C sources, each route
struct's handler, reports_cost and quick flags. For every route still written
as a struct it writes api/ops/<domain>/<operation>.json (never overwriting an
existing data file) and appends the operation to api/ops/catalog_order.json
(move it to where it belongs in the catalog). Its response schema is a first guess inferred from the
example's answer (the server answers the example); correct it by hand.

With --rewrite-c it also converts the C: the route struct goes, the static
handler becomes the exported api_op_<path> the data file names, and the
now unused schema/description/example strings and macros of that file are
deleted (check the diff). Remove the route's extern and table entry from
api/routes.c if that file still lists routes by hand.

Python 3 standard library only.
"""
import json
import os
import re
import subprocess
import sys
import urllib.request

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OPS = os.path.join(ROOT, "api", "ops")
ENVELOPE_KEYS = ("cost",)

# Operations whose path has one segment, or whose first segment is not the
# domain folder they belong in.
DOMAIN_OVERRIDES = {
    "/v1/vectors": ("vectors", "vectors"),
    "/v1/tensor/symmetric": ("vectors", "tensor_symmetric"),
    "/v1/small-oscillations": ("rigid", "small_oscillations"),
    "/v1/trajectory": ("frames", "trajectory"),
    "/v1/compare": ("integrators", "compare"),
    "/v1/integrators": ("integrators", "integrators"),
    "/v1/check": ("tools", "check"),
    "/v1/batch": ("tools", "batch"),
    "/v1/examples": ("tools", "examples"),
}


def place(path):
    """(domain, operation) of a path: /v1/rigid/free-symmetric-top ->
    (rigid, free_symmetric_top)."""
    if path in DOMAIN_OVERRIDES:
        return DOMAIN_OVERRIDES[path]
    parts = path.split("/")[2:]
    return parts[0], "_".join(p.replace("-", "_") for p in parts[1:])


def handler_symbol(path):
    """The exported handler of a path: /v1/relativity/kinematics/invariant-mass
    -> api_op_relativity_kinematics_invariant_mass."""
    return "api_op_" + re.sub(r"[^a-z0-9]+", "_", path[len("/v1/"):].lower()).strip("_")


def start_mechd(binary):
    proc = subprocess.Popen([binary, "--port", "0"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL)
    line = proc.stdout.readline().decode()
    m = re.match(r"mechd listening on (http://127\.0\.0\.1:\d+)", line)
    if not m:
        proc.kill()
        sys.exit("ops_extract: mechd did not start: %r" % line)
    return proc, m.group(1)


def get(base, path, body=None):
    req = urllib.request.Request(base + path, data=body,
                                 headers={"Content-Type": "application/json"} if body else {})
    try:
        with urllib.request.urlopen(req, timeout=300) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()


# ---- the C side: route structs ---------------------------------------------

STRUCT_RE = re.compile(r"^const struct api_route (\w+) = \{(.*?)^\};\n", re.S | re.M)


def split_initializers(text):
    """Top-level comma-separated items of a C initializer list (strings,
    comments and parentheses respected)."""
    items, cur, depth, i = [], "", 0, 0
    while i < len(text):
        c = text[i]
        if text.startswith("/*", i):
            j = text.index("*/", i) + 2
            i = j
            continue
        if text.startswith("//", i):
            i = text.index("\n", i)
            continue
        if c == '"':
            j = i + 1
            while text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            cur += text[i:j + 1]
            i = j + 1
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        if c == "," and depth == 0:
            items.append(cur.strip())
            cur = ""
        else:
            cur += c
        i += 1
    if cur.strip():
        items.append(cur.strip())
    return items


def c_routes():
    """{struct name: (file, struct text, [initializers])} for every
    old-style route struct in api/."""
    found = {}
    for dirpath, _, files in os.walk(os.path.join(ROOT, "api")):
        for f in sorted(files):
            if not f.endswith(".c"):
                continue
            p = os.path.join(dirpath, f)
            src = open(p, encoding="utf-8").read()
            for m in STRUCT_RE.finditer(src):
                found[m.group(1)] = (p, m.group(0), split_initializers(m.group(2)))
    return found


def c_string_value(expr):
    """The text of a C expression made only of string literals, else None."""
    parts = re.findall(r'"((?:[^"\\]|\\.)*)"', expr)
    if not parts or re.sub(r'"((?:[^"\\]|\\.)*)"|\s', "", expr):
        return None
    return bytes("".join(parts), "utf-8").decode("unicode_escape").encode("latin-1").decode("utf-8")


# ---- response schema inference -----------------------------------------------


def infer(v):
    """A JSON Schema describing the value v (a first guess)."""
    if v is None:
        return {"type": "null"}
    if isinstance(v, bool):
        return {"type": "boolean"}
    if isinstance(v, int):
        return {"type": "integer"}
    if isinstance(v, float):
        return {"type": "number"}
    if isinstance(v, str):
        return {"type": "string"}
    if isinstance(v, list):
        s = {"type": "array"}
        if v:
            items = [infer(x) for x in v]
            merged = items[0]
            for it in items[1:]:
                merged = merge(merged, it)
            s["items"] = merged
            if all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v) and \
                    len(v) in (3, 4):
                s["minItems"] = s["maxItems"] = len(v)
        return s
    props = {k: infer(x) for k, x in v.items()}
    return {"type": "object", "required": list(v.keys()), "properties": props}


def types_of(s):
    t = s.get("type")
    return set(t) if isinstance(t, list) else {t}


def merge(a, b):
    """A schema matching what a or b matches (loosely)."""
    if a == b:
        return a
    ta, tb = types_of(a), types_of(b)
    if ta <= {"integer", "number"} and tb <= {"integer", "number"}:
        out = {"type": "number"}
        for k in ("minItems", "maxItems"):
            pass
        return out
    if ta == {"object"} and tb == {"object"}:
        props = dict(a["properties"])
        for k, s in b["properties"].items():
            props[k] = merge(props[k], s) if k in props else s
        req = [k for k in a["required"] if k in b["required"]]
        return {"type": "object", "required": req, "properties": props}
    if ta == {"array"} and tb == {"array"}:
        out = {"type": "array"}
        if "items" in a and "items" in b:
            out["items"] = merge(a["items"], b["items"])
        elif "items" in a or "items" in b:
            out["items"] = a.get("items") or b.get("items")
        if a.get("minItems") == b.get("minItems") and "minItems" in a:
            out["minItems"] = a["minItems"]
            out["maxItems"] = a["maxItems"]
        return out
    if "null" in tb and len(tb) == 1:
        return dict(a, type=sorted(ta | {"null"}))
    if "null" in ta and len(ta) == 1:
        return dict(b, type=sorted(tb | {"null"}))
    return {}


# ---- C rewrite ------------------------------------------------------------------


def rename_in_code(src, old, new, directives=False):
    """src with the identifier old renamed to new in C code only: not in
    comments, string or character literals, or (unless directives)
    preprocessor lines."""
    out, i, n = [], 0, len(src)
    ident = re.compile(r"[A-Za-z_]\w*")
    at_line_start = True
    while i < n:
        c = src[i]
        if src.startswith("/*", i):
            j = src.index("*/", i) + 2
        elif src.startswith("//", i):
            j = src.find("\n", i)
            j = n if j < 0 else j
        elif c in "\"'":
            j = i + 1
            while src[j] != c:
                j += 2 if src[j] == "\\" else 1
            j += 1
        elif c == "#" and at_line_start and (not directives or src.startswith("#include", i)):
            j = i
            while True:  # to the end of the (continued) directive
                e = src.find("\n", j)
                if e < 0:
                    j = n
                    break
                if src[e - 1] != "\\":
                    j = e
                    break
                j = e + 1
        elif c.isalpha() or c == "_":
            m = ident.match(src, i)
            j = m.end()
            out.append(new if m.group(0) == old else m.group(0))
            i = j
            at_line_start = False
            continue
        else:
            j = i + 1
        out.append(src[i:j])
        if c == "\n":
            at_line_start = True
        elif not c.isspace():
            at_line_start = False
        i = j
    return "".join(out)


def code_count(src, name):
    """How often the identifier name occurs in src outside comments and literals."""
    return rename_in_code(src, name, "\0", directives=True).count("\0")


def rewrite_c(path, struct_text, fn, symbol):
    src = open(path, encoding="utf-8").read()
    src = src.replace(struct_text, "")
    src = re.sub(r"^static (json_t \*\s*)" + re.escape(fn) + r"\(", r"\1" + symbol + "(", src,
                 flags=re.M)
    src = rename_in_code(src, fn, symbol)
    # Drop static const char arrays and #defines nothing uses any more.
    changed = True
    while changed:
        changed = False
        for m in list(re.finditer(r"^static const char\s+(\w+)\[\] =.*?;\n", src, re.S | re.M)):
            name = m.group(1)
            if code_count(src, name) == 1:
                src = src.replace(m.group(0), "", 1)
                changed = True
        for m in list(re.finditer(r"^#define (\w+)(?:[^\n]*\\\n)*[^\n]*\n", src, re.M)):
            name = m.group(1)
            if code_count(src, name) == 1:
                src = src.replace(m.group(0), "", 1)
                changed = True
    src = re.sub(r"\n{3,}", "\n\n", src)
    open(path, "w", encoding="utf-8").write(src)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    binary = sys.argv[1]
    rewrite = "--rewrite-c" in sys.argv[2:]
    proc, base = start_mechd(binary)
    try:
        catalog = json.loads(get(base, "/v1")[1])
        openapi = json.loads(get(base, "/v1/openapi.json")[1])
        structs = c_routes()
        by_path = {}
        for name, (cfile, text, init) in structs.items():
            if len(init) < 9:
                sys.exit("ops_extract: %s in %s: expected 9 initialisers" % (name, cfile))
            path = c_string_value(init[1])
            by_path[path] = (name, cfile, text, init)
        order_file = os.path.join(OPS, "catalog_order.json")
        order = json.load(open(order_file)) if os.path.exists(order_file) else []
        ops = [(o["method"], o["path"], o) for o in catalog["operations"]]
        ops += [(r["method"], r["path"], r) for r in catalog["resources"] if r["path"] in by_path]
        written = []
        for method, path, entry in ops:
            if path not in by_path:
                continue  # already a data file
            name, cfile, text, init = by_path[path]
            domain, opname = place(path)
            out = os.path.join(OPS, domain, opname + ".json")
            rel = domain + "/" + opname
            fn = init[6].strip()
            symbol = handler_symbol(path)
            if os.path.exists(out):
                if not rewrite:
                    sys.exit("ops_extract: %s exists; remove it to convert %s again" % (out, path))
                rewrite_c(cfile, text, fn, symbol)  # the data file stays as it is
                continue
            doc = {"path": path, "method": method, "summary": entry["summary"]}
            if method == "GET":
                doc["description"] = openapi["paths"][path]["get"]["description"]
            else:
                doc["description"] = entry["description"]
            doc["handler"] = symbol
            doc["flags"] = {"reports_cost": init[7].strip() == "1",
                            "quick": init[8].split("/*")[0].strip() == "1"}
            if method == "POST":
                schema = entry["schema"]
                for k in ENVELOPE_KEYS:
                    schema["properties"].pop(k, None)
                doc["request_schema"] = schema
                # The example exactly as written: the catalog's curl line quotes it.
                ex_text = re.search(r"--json '(.*)'$", entry["curl"], re.S).group(1)
                example = json.loads(ex_text)
                if "\n" in ex_text:
                    sys.exit("ops_extract: %s: the example spans lines" % path)
                doc["examples"] = ["@@EXAMPLE@@"]  # its text, as written: see below
                status, ans = get(base, path, json.dumps(dict(example, cost=False)).encode())
                if status != 200:
                    sys.exit("ops_extract: %s: the example answers %d" % (path, status))
                answer = json.loads(ans)
            else:
                status, ans = get(base, path)
                answer = json.loads(ans)
            if "response_schema" in entry:
                doc["response_schema"] = entry["response_schema"]
            else:
                doc["response_schema"] = infer(answer)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with open(out, "w", encoding="utf-8") as f:
                text = json.dumps(doc, indent=2, ensure_ascii=False)
                if method == "POST":
                    # The example keeps its own spacing and number spelling
                    # (2e-6, not 2e-06): the catalog's curl line quotes it.
                    text = text.replace('"@@EXAMPLE@@"', ex_text, 1)
                    assert json.loads(text)["examples"][0] == example
                f.write(text + "\n")
            written.append(rel)
            if rel not in order:
                order.append(rel)  # the catalog lists operations in this order
            if rewrite:
                rewrite_c(cfile, text, fn, symbol)
        with open(order_file, "w") as f:
            json.dump(order, f, indent=2)
            f.write("\n")
        print("ops_extract: wrote %d data files: %s" % (len(written), " ".join(written)))
    finally:
        proc.terminate()
        proc.wait()


if __name__ == "__main__":
    main()
