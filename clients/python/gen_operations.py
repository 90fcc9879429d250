#!/usr/bin/env python3
"""gen_operations.py — writes the per-operation methods of mechd.py from mechd's
catalog (GET /v1), between the "BEGIN GENERATED OPERATIONS" and "END GENERATED
OPERATIONS" lines of clients/python/mechd.py.

The generated code is checked in, so `pip install ./clients/python` and copying
mechd.py need no server; run this after an operation or its schema changes:

    python3 clients/python/gen_operations.py --mechd build/mechd      # starts it on a free port
    python3 clients/python/gen_operations.py --catalog catalog.json   # a saved GET /v1
    ... --check    exit 1 (and write nothing) when mechd.py is not up to date

Each POST operation becomes Client.<name>(self, body=None, *, <field>=None, ...)
-> Dict[str, Any]: name from the path (/v1/relativity/kinematics/decay ->
relativity_kinematics_decay), one keyword-only parameter per top-level property
of the request schema (a Python keyword gets a trailing "_"), a type hint from
the property's JSON type, and a docstring made of the summary, each property's
description (or its type and range) and the path. tests/integration/
test_python_client.py checks the checked-in file against the running server's
catalog. Standard library only."""
import argparse
import json
import keyword
import os
import re
import select
import subprocess
import sys
import textwrap
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
TARGET = os.path.join(HERE, "mechd.py")
BEGIN = "# ---- BEGIN GENERATED OPERATIONS (clients/python/gen_operations.py; do not edit) ----\n"
END = "# ---- END GENERATED OPERATIONS ----\n"

# Operations with a hand-written method of a different shape (path -> method name).
HANDWRITTEN = {"/v1/check": "check", "/v1/batch": "batch"}

_SCALAR = {"number": "float", "integer": "int", "boolean": "bool", "string": "str"}


def method_name(path):
    """/v1/relativity/velocity-addition -> relativity_velocity_addition."""
    p = path[4:] if path.startswith("/v1/") else path.lstrip("/")
    return re.sub(r"[^0-9A-Za-z_]", "_", p.replace("/", "_").replace("-", "_"))


def param_name(prop):
    """A JSON property name as a Python parameter name (keywords get a trailing _)."""
    name = re.sub(r"[^0-9A-Za-z_]", "_", prop)
    if not name or name[0].isdigit():
        name = "_" + name
    return name + "_" if keyword.iskeyword(name) or name in ("self", "body") else name


def type_hint(schema):
    """The Python annotation (as source text) for a JSON schema."""
    if not isinstance(schema, dict):
        return "Any"
    t = schema.get("type")
    if "const" in schema or "enum" in schema:
        vals = schema.get("enum", [schema.get("const")])
        kinds = {type(v).__name__ for v in vals}
        return {"str": "str", "int": "int", "float": "float", "bool": "bool"}.get(kinds.pop(), "Any") \
            if len(kinds) == 1 else "Any"
    if isinstance(t, list):
        return "Any"
    if t in _SCALAR:
        return "float" if t == "number" else _SCALAR[t]
    if t == "array":
        return "List[%s]" % type_hint(schema.get("items")) if isinstance(schema.get("items"), dict) \
            else "List[Any]"
    if t == "object":
        return "Dict[str, Any]"
    return "Any"


def _num(x):
    return ("%d" % x) if isinstance(x, float) and x.is_integer() and abs(x) < 1e15 else repr(x)


def describe(schema):
    """One line about a property: its description, else its kind and range."""
    if not isinstance(schema, dict):
        return "any JSON value"
    bits = []
    if schema.get("description"):
        bits.append(schema["description"])
    else:
        t = schema.get("type")
        if "enum" in schema:
            bits.append("one of " + ", ".join(json.dumps(v) for v in schema["enum"]))
        elif "oneOf" in schema or "anyOf" in schema:
            alts = schema.get("oneOf") or schema.get("anyOf")
            names = [a.get("description") or a.get("type") or "object" for a in alts if isinstance(a, dict)]
            bits.append("one of: " + "; ".join(str(n) for n in names))
        elif t == "array":
            rng = []
            if "minItems" in schema:
                rng.append(">= %s" % _num(schema["minItems"]))
            if "maxItems" in schema:
                rng.append("<= %s" % _num(schema["maxItems"]))
            bits.append("array of %s%s" % (type_hint(schema.get("items")).lower(),
                                           (" (" + ", ".join(rng) + " items)") if rng else ""))
        elif t:
            rng = []
            for k, op in (("minimum", ">="), ("exclusiveMinimum", ">"), ("maximum", "<="),
                          ("exclusiveMaximum", "<")):
                if k in schema:
                    rng.append("%s %s" % (op, _num(schema[k])))
            bits.append(str(t) + ((" " + ", ".join(rng)) if rng else ""))
    if "default" in schema:
        bits.append("default %s" % json.dumps(schema["default"]))
    return "; ".join(bits) if bits else "any JSON value"


def gen_method(op):
    """Source text of one method (indented for the class body)."""
    path = op["path"]
    name = method_name(path)
    schema = op.get("schema") or {}
    props = schema.get("properties") or {}
    required = set(schema.get("required") or [])
    params = [(param_name(p), p, s) for p, s in props.items()]
    sig = ["self", "body: Optional[Dict[str, Any]] = None"]
    if params:
        sig.append("*")
        sig += ["%s: Optional[%s] = None" % (pn, type_hint(s)) for pn, _, s in params]
    lines = ["    def %s(%s) -> Dict[str, Any]:" % (name, ", ".join(sig))]
    doc = [op.get("summary") or path, "",
           "POST %s. The request is `body` (a dict) and/or the keyword arguments below" % path,
           "(merged; a keyword that is not None wins). Returns the answer as a dict; raises",
           "ProblemError (ValidationError at the JSON pointer of a bad field, ...) or",
           "ConnectionFailed. GET /v1 has the full schema and an example.", "", "Args:"]
    for pn, p, s in params:
        req = " (required)" if p in required else ""
        text = textwrap.wrap("%s%s: %s" % (pn, req, describe(s)), 92,
                             subsequent_indent="        ", break_on_hyphens=False)
        doc += ["    " + t for t in text]
    lines.append('        """' + doc[0].replace("\\", "\\\\").replace('"""', "'''"))
    for d in doc[1:]:
        lines.append(("        " + d.replace("\\", "\\\\").replace('"""', "'''")).rstrip())
    lines.append('        """')
    pairs = ", ".join("(%r, %s)" % (p, pn) for pn, p, _ in params)
    lines.append("        return self._operation(%r, body, (%s%s))" % (path, pairs, "," if len(params) == 1 else ""))
    return "\n".join(lines) + "\n"


def generate(catalog):
    """The generated region (between BEGIN and END) for a GET /v1 document."""
    ops = [o for o in catalog["operations"] if o.get("method", "POST") == "POST"
           and o["path"] not in HANDWRITTEN]
    out = [BEGIN, "class _Operations:\n",
           '    """One method per POST operation of GET /v1."""\n\n',
           "    def _operation(self, path: str, body: Optional[Dict[str, Any]],\n"
           "                   fields: Tuple[Tuple[str, Any], ...]) -> Dict[str, Any]:\n"
           "        raise NotImplementedError\n\n"]
    for o in ops:
        out.append(gen_method(o) + "\n")
    out.append("\nOPERATIONS = {\n")
    for o in ops:
        out.append("    %r: %r,\n" % (method_name(o["path"]), o["path"]))
    out.append("}\n")
    out.append("HANDWRITTEN_OPERATIONS = %r\n" % HANDWRITTEN)
    out.append(END)
    return "".join(out)


def splice(text, region):
    """text with its generated region replaced; ValueError if the markers are missing."""
    i, j = text.find(BEGIN), text.find(END)
    if i < 0 or j < i:
        raise ValueError("mechd.py has no generated-operations markers")
    return text[:i] + region + text[j + len(END):]


def catalog_from_mechd(binary):
    """Start `binary --port 0`, GET /v1, stop it."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
    proc = subprocess.Popen([binary, "--port", "0"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env)
    try:
        if not select.select([proc.stdout], [], [], 20)[0]:
            raise RuntimeError("mechd did not start")
        line = proc.stdout.readline().decode()
        m = re.search(r"http://(\S+)", line)
        if not m:
            raise RuntimeError("mechd did not start: %r" % line)
        with urllib.request.urlopen("http://%s/v1" % m.group(1), timeout=30) as r:
            return json.load(r)
    finally:
        proc.terminate()
        proc.wait(20)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--mechd", help="a mechd binary to start and ask for GET /v1")
    src.add_argument("--catalog", help="a file holding GET /v1's answer")
    src.add_argument("--url", help="a running server's base URL")
    ap.add_argument("--check", action="store_true", help="only say whether mechd.py is up to date")
    ap.add_argument("--target", default=TARGET)
    a = ap.parse_args(argv)
    if a.mechd:
        cat = catalog_from_mechd(a.mechd)
    elif a.catalog:
        with open(a.catalog, encoding="utf-8") as f:
            cat = json.load(f)
    else:
        with urllib.request.urlopen(a.url.rstrip("/") + "/v1", timeout=30) as r:
            cat = json.load(r)
    with open(a.target, encoding="utf-8") as f:
        old = f.read()
    new = splice(old, generate(cat))
    if a.check:
        if new != old:
            sys.stderr.write("%s is out of date with the catalog: run clients/python/gen_operations.py\n" % a.target)
            return 1
        return 0
    if new != old:
        with open(a.target, "w", encoding="utf-8") as f:
            f.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
