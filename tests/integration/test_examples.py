#!/usr/bin/python3
"""test_examples.py — every course example of GET /v1/examples runs and gives the notes' answer.

Usage: /usr/bin/python3 test_examples.py PATH/TO/mechd

Starts `mechd --port 0`, fetches GET /v1/examples and checks that the catalog
parses and is well formed (unique ids, every field present, operation is a POST
operation of GET /v1, rounding is {"relative": r} or {"absolute": a}), that the
notes' worked examples listed below are all there, and then POSTs every
example's request to its operation: status 200, and the number at
notes_answer.pointer equals notes_answer.value within notes_answer.rounding.
The comparison is also checked to reject a wrong value, so the test can fail.
Python 3 standard library only. Prints "N passed, M failed"; exits 1 on failure.
"""
import json
import os
import re
import select
import subprocess
import sys
import time
import urllib.error
import urllib.request
from mechdtest import check, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_examples.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])

# The notes' worked examples every release must carry (chapters 0-3) and the labs' extras:
# each must be in the catalog (matched by a word of the id).
REQUIRED = ["rotation", "puck", "falling-object", "cannonball", "foucault", "tides-moon",
            "tides-sun", "dumbbell", "cube-centre", "cube-corner", "cube-corner-principal",
            "muon", "length-contraction", "twin-paradox", "twin-doppler", "velocity-addition",
            "pi0", "neutron", "compton", "field-transformation", "kepler", "mercury",
            "light-bending", "gps", "heavy-top", "dzhanibekov", "henon-heiles"]


def start_server():
    env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
    proc = subprocess.Popen([MECHD, "--port", "0", "--deadline-ms", "300000"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, env=env)
    buf, end = b"", time.monotonic() + 20
    while not buf.endswith(b"\n") and time.monotonic() < end:
        ready, _, _ = select.select([proc.stdout], [], [], max(0.0, end - time.monotonic()))
        if not ready:
            break
        c = os.read(proc.stdout.fileno(), 1)
        if not c:
            break
        buf += c
    m = re.search(rb"http://([0-9.]+):(\d+)", buf)
    if not m:
        proc.kill()
        raise RuntimeError("mechd printed no listening line: %r" % buf)
    return proc, "http://127.0.0.1:%s" % m.group(2).decode()


def http(base, method, path, body=None):
    data = json.dumps(body).encode() if body is not None else None
    req = urllib.request.Request(base + path, data=data, method=method,
                                 headers={"Content-Type": "application/json"} if data else {})
    try:
        with urllib.request.urlopen(req, timeout=120) as r:
            return r.status, json.loads(r.read())
    except urllib.error.HTTPError as e:
        payload = e.read()
        try:
            return e.code, json.loads(payload)
        except ValueError:
            return e.code, payload


def at_pointer(doc, pointer):
    """RFC 6901 JSON pointer; raises KeyError/IndexError/ValueError when absent."""
    if pointer == "":
        return doc
    if not pointer.startswith("/"):
        raise ValueError("pointer must start with /")
    for tok in pointer[1:].split("/"):
        tok = tok.replace("~1", "/").replace("~0", "~")
        doc = doc[int(tok)] if isinstance(doc, list) else doc[tok]
    return doc


def within(got, want, rounding):
    """|got - want| <= absolute, or <= relative * |want|."""
    if isinstance(got, bool) or not isinstance(got, (int, float)):
        return False
    tol = rounding.get("absolute", 0.0) + rounding.get("relative", 0.0) * abs(want)
    return abs(got - want) <= tol


def check_shape(ex, post_ops):
    name = ex.get("id", "?")
    keys = {"id", "title", "section", "operation", "request", "notes_answer"}
    check("%s: has exactly %s" % (name, sorted(keys)), set(ex) == keys, repr(sorted(ex)))
    check("%s: title, section are non-empty strings" % name,
          all(isinstance(ex.get(k), str) and ex.get(k) for k in ("title", "section")))
    check("%s: operation is a POST operation of GET /v1" % name, ex.get("operation") in post_ops,
          repr(ex.get("operation")))
    check("%s: request is an object" % name, isinstance(ex.get("request"), dict))
    na = ex.get("notes_answer") or {}
    check("%s: notes_answer has pointer, value, rounding, text" % name,
          set(na) == {"pointer", "value", "rounding", "text"}, repr(sorted(na)))
    r = na.get("rounding")
    ok_r = (isinstance(r, dict) and len(r) == 1 and set(r) <= {"relative", "absolute"} and
            isinstance(list(r.values())[0], (int, float)) and list(r.values())[0] > 0 and
            r.get("relative", 0) < 0.1)
    check("%s: rounding is {relative: 0 < r < 0.1} or {absolute: a > 0}" % name, ok_r, repr(r))
    check("%s: value is a number, text a sentence" % name,
          isinstance(na.get("value"), (int, float)) and isinstance(na.get("text"), str)
          and len(na.get("text", "")) > 10)
    return ok_r


def main():
    # The comparison can fail: a wrong value, a wrong type and a missing key are rejected.
    check("comparator rejects 0.02 against 0.019 ± 0.0005", not within(0.02, 0.019, {"absolute": 5e-4}))
    check("comparator accepts 0.0186 against 0.019 ± 0.0005", within(0.0186, 0.019, {"absolute": 5e-4}))
    check("comparator rejects 1 + 2e-12 against 1 (relative 1e-12)",
          not within(1 + 2e-12, 1.0, {"relative": 1e-12}))
    check("comparator rejects a string", not within("1", 1.0, {"relative": 0.5}))
    try:
        at_pointer({"a": [1]}, "/a/1")
        check("pointer to a missing element raises", False)
    except (KeyError, IndexError, ValueError):
        check("pointer to a missing element raises", True)

    proc, base = start_server()
    try:
        st, cat = http(base, "GET", "/v1")
        post_ops = {o["path"] for o in cat.get("operations", []) if o.get("method", "POST") == "POST"}
        st, doc = http(base, "GET", "/v1/examples")
        check("GET /v1/examples: 200", st == 200, repr(st))
        examples = doc.get("examples") if isinstance(doc, dict) else None
        if not check("GET /v1/examples: a list of examples", isinstance(examples, list) and examples):
            return
        check("count matches", doc.get("count") == len(examples), repr(doc.get("count")))
        ids = [e.get("id") for e in examples]
        check("ids unique", len(ids) == len(set(ids)), repr(ids))
        check("ids are slugs", all(isinstance(i, str) and re.fullmatch(r"[a-z0-9-]+", i) for i in ids))
        for word in REQUIRED:
            check("catalog has an example for %r" % word, any(word in i for i in ids))
        # Deterministic: a second fetch gives the same bytes.
        with urllib.request.urlopen(base + "/v1/examples", timeout=30) as r1, \
                urllib.request.urlopen(base + "/v1/examples", timeout=30) as r2:
            check("GET /v1/examples is byte-identical twice", r1.read() == r2.read())

        worst = []
        for ex in examples:
            name = ex.get("id", "?")
            if not check_shape(ex, post_ops):
                continue
            na = ex["notes_answer"]
            st, ans = http(base, "POST", ex["operation"], ex["request"])
            if not check("%s: %s answers 200" % (name, ex["operation"]), st == 200,
                         repr(ans)[:400]):
                continue
            try:
                got = at_pointer(ans, na["pointer"])
            except (KeyError, IndexError, ValueError, TypeError):
                check("%s: pointer %s exists in the answer" % (name, na["pointer"]), False)
                continue
            ok = within(got, na["value"], na["rounding"])
            check("%s: %s = %r, notes %r within %r" % (name, na["pointer"], got, na["value"],
                                                       na["rounding"]), ok)
            if isinstance(got, (int, float)) and na["value"]:
                worst.append((abs(got - na["value"]) / abs(na["value"]), name))
        worst.sort(reverse=True)
        print("relative differences from the notes (largest first): %s"
              % ", ".join("%s %.2g" % (n, d) for d, n in worst[:8]))
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a crash is a failure, not a pass
        check("test ran to the end", False, "%s: %s" % (type(e).__name__, e))
    sys.exit(summary())
