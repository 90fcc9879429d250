#!/usr/bin/python3
"""Integration tests of mechd's grading contract over real HTTP (stdlib only).

Usage: /usr/bin/python3 test_grading.py PATH/TO/mechd

Checks: every POST operation answers GET ?request=<url-encoded JSON> with the
same bytes as a POST without cost; a strong ETag that depends only on the
canonical request (key order and number spelling do not matter) and
Cache-Control; If-None-Match -> 304 with no body (single tag, lists, W/, *);
POST and problems are "no-store" without an ETag; /v1/check and /v1/batch
over HTTP; `mechd eval` (stdin envelope and --operation FILE) prints bytes
identical to the server's answer and exits 0 / 1 / 2 as documented. Every
socket and subprocess has a timeout. Prints "N passed, M failed".
"""
import http.client
import json
import os
import re
import select
import subprocess
import sys
import tempfile
import time
import urllib.parse
from mechdtest import check, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_grading.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
START_TIMEOUT = 20.0
REQUEST_TIMEOUT = 60.0


class Server:
    def __init__(self, *args):
        env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
        self.errfile = tempfile.TemporaryFile()
        self.proc = subprocess.Popen([MECHD, "--port", "0", "--deadline-ms", "300000"] + list(args), stdout=subprocess.PIPE,
                                     stderr=self.errfile, env=env)
        fd = self.proc.stdout.fileno()
        buf = b""
        end = time.monotonic() + START_TIMEOUT
        while not buf.endswith(b"\n") and time.monotonic() < end:
            r, _, _ = select.select([fd], [], [], 0.1)
            if r:
                chunk = os.read(fd, 1)
                if not chunk:
                    break
                buf += chunk
        m = re.fullmatch(rb"mechd listening on http://[0-9.]+:(\d+)\n", buf)
        if not m:
            self.stop()
            raise RuntimeError("mechd did not start (got %r)" % buf)
        self.port = int(m.group(1))

    def request(self, method, path, body=None, headers=None):
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=REQUEST_TIMEOUT)
        h = dict(headers or {})
        data = None
        if body is not None:
            data = body if isinstance(body, bytes) else json.dumps(body).encode()
            h.setdefault("Content-Type", "application/json")
        conn.request(method, path, body=data, headers=h)
        r = conn.getresponse()
        out = (r.status, {k.lower(): v for k, v in r.getheaders()}, r.read())
        conn.close()
        return out

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)


def q(req):
    return urllib.parse.quote(json.dumps(req), safe="")


def eval_run(args, stdin_bytes):
    p = subprocess.run([MECHD, "eval"] + args, input=stdin_bytes, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, timeout=REQUEST_TIMEOUT)
    return p.returncode, p.stdout, p.stderr


BOX = {"bodies": [{"shape": "box", "mass": 12, "size": [1, 2, 3], "position": [0, 0, 0]}]}
BOOST = {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [0.6, 0, 0]}}
ETAG_RE = re.compile(r'"[0-9a-f]{16}"')


def main():
    s = Server()
    try:
        run(s)
    finally:
        s.stop()
    return summary()


def run(s):
    # ---- GET ?request= ------------------------------------------------------
    st, h, body = s.request("GET", "/v1/rigid/inertia?request=" + q(BOX))
    check("GET ?request= answers 200", st == 200, st)
    etag = h.get("etag", "")
    check("GET answer has a strong ETag", ETAG_RE.fullmatch(etag) is not None, etag)
    check("GET answer is publicly cacheable", h.get("cache-control") == "public, max-age=86400",
          h.get("cache-control"))
    ans = json.loads(body)
    check("GET answer is the operation's answer", ans["principal"]["moments"] == [5.0, 10.0, 13.0],
          ans.get("principal"))
    st2, h2, body2 = s.request("POST", "/v1/rigid/inertia", BOX)
    check("POST gives the same bytes as GET", st2 == 200 and body2 == body)
    check("POST is no-store without an ETag",
          h2.get("cache-control") == "no-store" and "etag" not in h2, h2)

    # The ETag is of the canonical request: key order and number spelling do not matter.
    reordered = '{"bodies":[{"position":[0,0,0.0],"size":[1e0,2,3],"mass":1.2e+1,"shape":"box"}]}'
    st3, h3, body3 = s.request("GET", "/v1/rigid/inertia?request=" +
                               urllib.parse.quote(reordered, safe=""))
    check("canonical request: same ETag", h3.get("etag") == etag, (h3.get("etag"), etag))
    check("same ETag => same bytes", st3 == 200 and body3 == body)
    other = json.loads(json.dumps(BOX))
    other["bodies"][0]["mass"] = 13
    _, h4, _ = s.request("GET", "/v1/rigid/inertia?request=" + q(other))
    check("another request, another ETag", h4.get("etag") not in (None, etag), h4.get("etag"))
    _, h5, _ = s.request("GET", "/v1/relativity/boost?request=" + q(BOX))
    check("the path is part of the ETag (or the request fails without one)",
          h5.get("etag") != etag)

    # ---- If-None-Match ----------------------------------------------------------
    for name, inm in [("exact", etag), ("list", '"0000000000000000", ' + etag),
                      ("weak", "W/" + etag), ("star", "*")]:
        st, h, b = s.request("GET", "/v1/rigid/inertia?request=" + q(BOX),
                             headers={"If-None-Match": inm})
        check("If-None-Match %s -> 304 with no body" % name, st == 304 and b == b"", (st, b[:80]))
        check("304 (%s) repeats ETag and Cache-Control" % name,
              h.get("etag") == etag and h.get("cache-control") == "public, max-age=86400", h)
    st, h, b = s.request("GET", "/v1/rigid/inertia?request=" + q(BOX),
                         headers={"If-None-Match": '"0123456789abcdef"'})
    check("a stale If-None-Match -> 200 with the body", st == 200 and b == body, st)
    st, h, b = s.request("HEAD", "/v1/rigid/inertia?request=" + q(BOX))
    check("HEAD ?request= -> 200, ETag, no body", st == 200 and h.get("etag") == etag and b == b"",
          (st, h.get("etag")))

    # ---- problems over GET ------------------------------------------------------------
    st, h, b = s.request("GET", "/v1/rigid/inertia?request=" + urllib.parse.quote("{not json"))
    check("GET malformed request -> 400 problem, no-store, no ETag",
          st == 400 and h.get("content-type") == "application/problem+json"
          and h.get("cache-control") == "no-store" and "etag" not in h, (st, h))
    bad = {"bodies": [{"shape": "box", "mass": -1, "size": [1, 2, 3], "position": [0, 0, 0]}]}
    st, h, b = s.request("GET", "/v1/rigid/inertia?request=" + q(bad))
    p = json.loads(b) if b else {}
    check("GET invalid request -> 422 with the pointer, no ETag",
          st == 422 and p.get("errors", [{}])[0].get("pointer") == "/bodies/0/mass"
          and "etag" not in h and h.get("cache-control") == "no-store", (st, p))
    st, h, b = s.request("GET", "/v1/rigid/inertia")
    p = json.loads(b) if b else {}
    check("GET of a POST operation without ?request= -> 400 request-missing, not 405",
          st == 400 and p.get("type") == "/problems/request-missing" and "?request=" in
          p.get("detail", "") and "POST" in p.get("detail", ""), (st, p))

    # ---- cost: GET drops it, so the bytes are deterministic ----------------------------------
    st, h, b = s.request("GET", "/v1")
    catalog = json.loads(b)
    traj = [o for o in catalog["operations"] if o["path"] == "/v1/trajectory"]
    if check("catalog lists /v1/trajectory", len(traj) == 1):
        ex = traj[0]["example"]
        st, h, b1 = s.request("GET", "/v1/trajectory?request=" + q(ex))
        st2, h2, b2 = s.request("GET", "/v1/trajectory?request=" + q(ex))
        check("GET /v1/trajectory twice: byte-identical, no cost",
              st == 200 and b1 == b2 and "cost" not in json.loads(b1), st)
        st3, h3, b3 = s.request("POST", "/v1/trajectory", ex)
        check("POST /v1/trajectory reports its measured cost", "cost" in json.loads(b3))
        ex_nc = dict(ex, cost=False)
        st4, _, b4 = s.request("POST", "/v1/trajectory", ex_nc)
        check("POST with cost:false == GET bytes", st4 == 200 and b4 == b1)
        rc, out, err = eval_run([], json.dumps({"operation": "/v1/trajectory",
                                                 "request": ex}).encode())
        check("mechd eval /v1/trajectory == GET bytes", rc == 0 and out == b1, (rc, err[:200]))

    # ---- check and batch over HTTP -------------------------------------------------
    chk = {"operation": "/v1/rigid/inertia", "request": BOX,
           "answer": {"pointer": "/principal/moments/2", "value": 13.04},
           "tolerance": {"significant_figures": 3}}
    st, h, b = s.request("POST", "/v1/check", chk)
    r = json.loads(b)
    check("POST /v1/check: 13.04 is 13 to 3 figures", st == 200 and r.get("correct") is True,
          (st, r))
    st, h, b2 = s.request("GET", "/v1/check?request=" + q(chk))
    check("GET /v1/check?request= == POST bytes, with an ETag",
          st == 200 and b2 == b and ETAG_RE.fullmatch(h.get("etag", "")), st)
    bat = {"operations": [{"operation": "/v1/relativity/boost", "request": BOOST},
                          {"operation": "/v1/rigid/inertia", "request": bad},
                          {"operation": "/v1/rigid/inertia", "request": BOX}]}
    st, h, b = s.request("POST", "/v1/batch", bat)
    r = json.loads(b)
    res = r.get("results", [])
    check("POST /v1/batch: 3 results in order, the bad one alone fails",
          st == 200 and [x["status"] for x in res] == [200, 422, 200]
          and res[0]["body"]["gamma"] == 1.25
          and res[1]["problem"]["errors"][0]["pointer"] == "/operations/1/request/bodies/0/mass"
          and res[2]["body"]["principal"]["moments"] == [5.0, 10.0, 13.0], (st, b[:300]))

    # ---- mechd eval ---------------------------------------------------------------------------
    st, _, get_body = s.request("GET", "/v1/relativity/boost?request=" + q(BOOST))
    rc, out, err = eval_run([], json.dumps({"operation": "/v1/relativity/boost",
                                             "request": BOOST}).encode())
    check("eval (stdin envelope) exits 0 with the server's bytes", rc == 0 and out == get_body,
          (rc, out[:120], err[:200]))
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(BOOST, f)
        fname = f.name
    try:
        rc, out, err = eval_run(["--operation", "/v1/relativity/boost", fname], b"")
        check("eval --operation PATH FILE: same bytes", rc == 0 and out == get_body, (rc, err))
        rc, out, err = eval_run(["--operation=/v1/relativity/boost"], json.dumps(BOOST).encode())
        check("eval --operation=PATH < bare request: same bytes", rc == 0 and out == get_body,
              (rc, err))
    finally:
        os.unlink(fname)
    domain = {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [1.5, 0, 0]}}
    st, _, srv_problem = s.request("POST", "/v1/relativity/boost", domain)
    rc, out, err = eval_run(["--operation", "/v1/relativity/boost"], json.dumps(domain).encode())
    # The server's problem ends with its request's "request_id" (no request in eval).
    srv_no_id = re.sub(rb',"request_id":"[0-9a-f]{32}"\}\n$', b"}\n", srv_problem)
    check("eval of a refused request exits 1 with the server's problem bytes (but request_id)",
          st == 422 and rc == 1 and srv_no_id != srv_problem and out == srv_no_id,
          (st, rc, out[:200], srv_problem[-60:]))
    rc, out, err = eval_run([], b'{"operation": "/v1/nothing", "request": {}}')
    check("eval of an unknown operation exits 1 with a 404 problem",
          rc == 1 and json.loads(out).get("status") == 404, (rc, out[:200]))
    rc, out, err = eval_run(["--bogus"], b"")
    check("eval with an unknown option exits 2", rc == 2 and b"unknown option" in err, (rc, err))
    rc, out, err = eval_run([], b'{"request": {}}')
    check("eval without an operation exits 2", rc == 2 and out == b"", (rc, err))
    rc, out, err = eval_run(["--help"], b"")
    check("eval --help exits 0 and documents the exit status",
          rc == 0 and b"Exit status" in out, rc)
    rc, out, err = eval_run([], json.dumps({"operation": "/v1/check", "request": chk}).encode())
    st, _, chk_body = s.request("POST", "/v1/check", chk)
    check("eval /v1/check == the server's check answer", rc == 0 and out == chk_body, (rc, err))


if __name__ == "__main__":
    sys.exit(main())
