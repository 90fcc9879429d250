#!/usr/bin/python3
"""answer_snapshot.py — every answer mechd gives to its own documented requests,
as one file, so that a refactoring can be shown to change no byte of any answer.

Usage:
  scripts/answer_snapshot.py PATH/TO/mechd OUT.jsonl     write a snapshot
  scripts/answer_snapshot.py --diff A.jsonl B.jsonl       compare two snapshots

The snapshot holds, one JSON line each: GET /v1, /v1/openapi.json,
/v1/integrators, /v1/examples, /v1/relativity/particles, then every
operation's catalog example, every worked example of /v1/examples and every
data-driven API case under tests/api/cases/ (request.json: body or body_text,
content_type), with the status, the content type and the body's exact bytes.
Each request carries a fixed X-Request-Id, so the only parts of an answer that
may differ run to run are measured times: the keys listed in VOLATILE are
replaced by null before writing (CPU seconds, wall time), the steps
and time reached by a run cut off at its deadline, and the server's port
(free, new each run) where an answer quotes its own address; nothing else.
Exit status of --diff: 0 identical, 1 differences (each printed).
"""
import json
import os
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.parse
import urllib.request

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CASES = os.path.join(ROOT, "tests", "api", "cases")
# Keys whose values are measured durations, the only run-to-run differences.
VOLATILE = {"cpu_seconds", "measured_cpu_seconds", "wall_seconds", "elapsed_seconds",
            "cpu_s", "wall_s", "elapsed_ms", "cpu_ms", "measured_cpu_s", "measured"}


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    p = s.getsockname()[1]
    s.close()
    return p


def mask(v):
    if isinstance(v, dict) and v.get("limit") == "deadline":  # how far it got in the time
        return {k: (None if k in ("steps", "t_reached", "fraction_done") else mask(x)) for k, x in v.items()}
    if isinstance(v, dict):
        return {k: (None if k in VOLATILE and isinstance(v[k], (int, float)) else mask(x))
                for k, x in v.items()}
    if isinstance(v, list):
        return [mask(x) for x in v]
    return v


def unport(base, raw):
    """The server's own address (a free port, new each run) as written in the
    catalog's curl lines, replaced by a fixed placeholder."""
    return raw.replace(base.encode(), b"http://127.0.0.1:PORT")


def call(base, method, path, body=None, ctype="application/json", rid="snapshot"):
    data = None if body is None else (body if isinstance(body, bytes) else body.encode())
    path = urllib.parse.quote(path, safe="/?=&%:+,;@!$'()*[]~")  # non-ASCII cases
    req = urllib.request.Request(base + path, data=data, method=method)
    if data is not None and ctype:
        req.add_header("Content-Type", ctype)
    req.add_header("X-Request-Id", rid)
    try:
        with urllib.request.urlopen(req, timeout=120) as r:
            return r.status, r.headers.get("Content-Type", ""), unport(base, r.read())
    except urllib.error.HTTPError as e:
        return e.code, e.headers.get("Content-Type", ""), unport(base, e.read())
    except (OSError, ValueError) as e:  # a case the client library itself refuses to send
        return 0, "", ("client: %s" % type(e).__name__).encode()


def record(out, key, status, ctype, raw):
    try:
        body = json.dumps(mask(json.loads(raw)), ensure_ascii=False)
    except ValueError:
        body = raw.decode("utf-8", "replace")
    out.write(json.dumps({"key": key, "status": status, "type": ctype, "body": body}) + "\n")


def snapshot(mechd, path_out):
    port = free_port()
    proc = subprocess.Popen([mechd, "--port", str(port), "--workers", "2"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    base = "http://127.0.0.1:%d" % port
    try:
        for _ in range(200):
            try:
                urllib.request.urlopen(base + "/healthz", timeout=1).read()
                break
            except OSError:
                time.sleep(0.05)
        n = 0
        with open(path_out, "w") as out:
            for p in ["/v1", "/v1/openapi.json", "/v1/integrators", "/v1/examples",
                      "/v1/relativity/particles"]:
                record(out, "GET " + p, *call(base, "GET", p)); n += 1
            catalog = json.loads(call(base, "GET", "/v1")[2])
            for op in catalog["operations"]:
                if op.get("example") is not None:
                    st = call(base, op.get("method", "POST"), op["path"], json.dumps(op["example"]))
                    record(out, "example " + op["path"], *st); n += 1
            for ex in json.loads(call(base, "GET", "/v1/examples")[2])["examples"]:
                st = call(base, "POST", ex["operation"], json.dumps(ex["request"]))
                record(out, "worked " + ex["id"], *st); n += 1
            for dom in sorted(os.listdir(CASES)):
                for case in sorted(os.listdir(os.path.join(CASES, dom))):
                    f = os.path.join(CASES, dom, case, "request.json")
                    if not os.path.isfile(f):
                        continue
                    rq = json.load(open(f))
                    if "body_text" in rq:
                        body = rq["body_text"]
                    elif "body" in rq:
                        body = json.dumps(rq["body"])
                    else:
                        body = None
                    st = call(base, rq.get("method", "POST"), rq["path"], body,
                              rq.get("content_type", "application/json"))
                    record(out, "case %s/%s" % (dom, case), *st); n += 1
        print("%d answers written to %s" % (n, path_out))
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def diff(a, b):
    ra = {j["key"]: j for j in map(json.loads, open(a))}
    rb = {j["key"]: j for j in map(json.loads, open(b))}
    bad = 0
    for k in sorted(set(ra) | set(rb)):
        if k not in ra or k not in rb:
            print("only in %s: %s" % (a if k in ra else b, k)); bad += 1
        elif ra[k] != rb[k]:
            x, y = ra[k]["body"], rb[k]["body"]
            i = next((i for i in range(min(len(x), len(y))) if x[i] != y[i]), min(len(x), len(y)))
            print("differs: %s (status %s/%s) at byte %d: ...%s... vs ...%s..."
                  % (k, ra[k]["status"], rb[k]["status"], i, x[max(0, i - 60):i + 60],
                     y[max(0, i - 60):i + 60])); bad += 1
    print("%d answers compared, %d differ" % (len(set(ra) | set(rb)), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--diff":
        sys.exit(diff(sys.argv[2], sys.argv[3]))
    if len(sys.argv) != 3:
        sys.stderr.write(__doc__)
        sys.exit(2)
    snapshot(os.path.abspath(sys.argv[1]), sys.argv[2])
