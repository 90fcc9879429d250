#!/usr/bin/python3
"""Security tests of mechd over real HTTP (Python 3 standard library only).

Usage: /usr/bin/python3 test_security.py PATH/TO/mechd

Starts mechd on 127.0.0.1 with --token-file and --cors-origin and checks:
bearer-token authentication of /v1 (401 problem+json with WWW-Authenticate
when the token is missing, wrong, a prefix, longer, or in another scheme; 200
with it, for GET and POST and HEAD), that /healthz, /metrics, the front end and
/problems stay open; CORS (preflight and Access-Control-Allow-Origin only for
listed origins; a preflight from any other origin, or with CORS off, is
answered as a plain OPTIONS: 204 with Allow and no Access-Control-*); the security headers on every kind
of answer; the static file server refusing traversal (plain, encoded,
double-encoded, absolute, backslashes) with 400 or 404; and option validation
(missing or empty token file, bad origins -> exit 2). Every socket and
subprocess has a timeout; only 127.0.0.1 is contacted. Prints "N passed, M
failed" and exits nonzero on any failure.
"""
import http.client
import json
import os
import re
import select
import socket
import subprocess
import sys
import tempfile
import time
from mechdtest import check, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_security.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])

START_TIMEOUT = 20.0
REQUEST_TIMEOUT = 30.0
TOKEN = "k7-Q2x.9_zz~tokenForTests"
ALLOWED = ["http://lab.example.org", "https://grading.example.org:8443", "http://localhost:3000"]


class Server:
    """A mechd process on a free port of 127.0.0.1; stderr to a temporary file."""

    def __init__(self, *args, env=None):
        self.args = ["--port", "0", "--bind", "127.0.0.1"] + [str(a) for a in args]
        self.errfile = tempfile.TemporaryFile()
        full_env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
        full_env.update(env or {})
        self.proc = subprocess.Popen([MECHD] + self.args, stdout=subprocess.PIPE,
                                     stderr=self.errfile, env=full_env)
        line = self._read_line(START_TIMEOUT)
        m = re.fullmatch(r"mechd listening on http://127\.0\.0\.1:(\d+)\n", line or "")
        if not m:
            self.stop()
            raise RuntimeError("mechd %s did not start (%r); stderr:\n%s"
                               % (self.args, line, self.stderr()))
        self.port = int(m.group(1))

    def _read_line(self, timeout):
        fd = self.proc.stdout.fileno()
        buf = b""
        end = time.monotonic() + timeout
        while not buf.endswith(b"\n"):
            left = end - time.monotonic()
            if left <= 0:
                return None
            if not select.select([fd], [], [], left)[0]:
                return None
            chunk = os.read(fd, 1)
            if not chunk:
                return None
            buf += chunk
        return buf.decode("utf-8", "replace")

    def stderr(self):
        self.errfile.seek(0)
        return self.errfile.read().decode("utf-8", "replace")

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=10)


def request(port, method, path, body=None, headers=None, content_type="application/json"):
    """One request on a fresh connection: (status, lower-cased headers, bytes)."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=REQUEST_TIMEOUT)
    try:
        hdrs = dict(headers or {})
        data = None
        if body is not None:
            data = body if isinstance(body, bytes) else json.dumps(body).encode()
            hdrs.setdefault("Content-Type", content_type)
        conn.request(method, path, body=data, headers=hdrs)
        resp = conn.getresponse()
        payload = resp.read()
        return resp.status, {k.lower(): v for k, v in resp.getheaders()}, payload
    finally:
        conn.close()


def raw_request(port, target):
    """Send 'GET <target> HTTP/1.1' byte for byte (no client-side normalisation)."""
    with socket.create_connection(("127.0.0.1", port), timeout=REQUEST_TIMEOUT) as s:
        s.sendall(b"GET " + target + b" HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        data = b""
        while True:
            chunk = s.recv(65536)
            if not chunk:
                break
            data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.[01] (\d{3})", head)
    return (int(m.group(1)) if m else 0), head.decode("latin-1"), body


def auth(token=TOKEN):
    return {"Authorization": "Bearer " + token}


SECURITY_HEADERS = {"x-content-type-options": "nosniff", "referrer-policy": "no-referrer",
                    "x-frame-options": "DENY"}


def check_security_headers(name, hdrs):
    ok = all(hdrs.get(k) == v for k, v in SECURITY_HEADERS.items())
    csp = hdrs.get("content-security-policy", "")
    ok = ok and "frame-ancestors 'none'" in csp
    # Each header exactly once (no duplicates from two layers).
    check("%s: security headers" % name, ok, str(hdrs))


def check_problem(name, status, hdrs, payload, want_status, want_type=None):
    try:
        doc = json.loads(payload)
    except ValueError:
        doc = {}
    ok = (status == want_status and hdrs.get("content-type", "").startswith("application/problem+json")
          and doc.get("status") == want_status and (want_type is None or doc.get("type") == want_type))
    check("%s -> %d problem+json %s" % (name, want_status, want_type or ""), ok,
          "%s %s %r" % (status, hdrs.get("content-type"), payload[:300]))
    return doc


def test_auth(port, example_path, example_body):
    for name, hdrs, invalid in [
            ("no Authorization", {}, False),
            ("wrong token", auth("nope"), True),
            ("token prefix", auth(TOKEN[:-1]), True),
            ("token plus a character", auth(TOKEN + "x"), True),
            ("token in another case", auth(TOKEN.upper()), True),
            ("Basic scheme", {"Authorization": "Basic " + TOKEN}, True),
            ("bare token", {"Authorization": TOKEN}, True),
            ("empty bearer", {"Authorization": "Bearer "}, True)]:
        for method, path, body in [("GET", "/v1", None), ("POST", example_path, example_body)]:
            st, h, payload = request(port, method, path, body, headers=hdrs)
            check_problem("%s %s, %s" % (method, path, name), st, h, payload, 401,
                          "/problems/unauthorized")
            www = h.get("www-authenticate", "")
            check("%s %s, %s: WWW-Authenticate Bearer" % (method, path, name),
                  www.startswith("Bearer") and (("invalid_token" in www) == invalid), www)
            check_security_headers("401 %s %s" % (method, name), h)
    # The 401 is the problem table's (api/http/problem.c), built like every other
    # problem: its type's page names the same title, a newline ends the body,
    # "instance" is the path, and it is never cached.
    st, h, payload = request(port, "POST", example_path, example_body)
    table = json.loads(request(port, "GET", "/problems/unauthorized")[2])
    doc = json.loads(payload)
    check("401 body from the problem table (title, instance, newline-terminated, no-store)",
          doc.get("title") == table.get("title") and doc.get("instance") == example_path
          and payload.endswith(b"}\n") and h.get("cache-control") == "no-store", (payload, h))
    st, h, payload = request(port, "GET", "/v1/openapi.json")
    check("GET /v1/openapi.json without token -> 401", st == 401, st)
    st, h, _ = request(port, "HEAD", "/v1", headers={})
    check("HEAD /v1 without token -> 401", st == 401, st)

    st, h, payload = request(port, "GET", "/v1", headers=auth())
    check("GET /v1 with the token -> 200", st == 200 and json.loads(payload).get("operations"),
          st)
    st, h, payload = request(port, "POST", example_path, example_body, headers=auth())
    check("POST %s with the token -> 200" % example_path, st == 200, "%s %r" % (st, payload[:300]))
    check_security_headers("200 POST", h)
    st, h, payload = request(port, "POST", example_path, example_body,
                             headers={"Authorization": "bearer   " + TOKEN})
    check("scheme is case-insensitive -> 200", st == 200, st)

    # Open routes: no token needed.
    for path, want in [("/healthz", 200), ("/metrics", 200), ("/", 200),
                       ("/problems/validation-error", 200)]:
        st, h, _ = request(port, "GET", path)
        check("GET %s without token -> %d" % (path, want), st == want, st)
        check_security_headers("GET %s" % path, h)
        check("GET %s: no WWW-Authenticate" % path, "www-authenticate" not in h)


def test_cors(port, example_path, example_body):
    preflight = {"Access-Control-Request-Method": "POST",
                 "Access-Control-Request-Headers": "authorization, content-type"}
    for origin in ALLOWED:
        st, h, payload = request(port, "OPTIONS", example_path, headers=dict(preflight, Origin=origin))
        check("preflight from %s -> 204" % origin, st == 204 and payload == b"", st)
        check("preflight from %s: Allow-Origin is exactly it" % origin,
              h.get("access-control-allow-origin") == origin, h)
        check("preflight: Allow-Methods has POST",
              "POST" in h.get("access-control-allow-methods", ""), h)
        allow_h = h.get("access-control-allow-headers", "").lower()
        check("preflight: Allow-Headers has Authorization and Content-Type",
              "authorization" in allow_h and "content-type" in allow_h, allow_h)
        check("preflight: no wildcard, no credentials",
              h.get("access-control-allow-origin") != "*"
              and "access-control-allow-credentials" not in h, h)
        check_security_headers("204 preflight", h)
        st, h, payload = request(port, "POST", example_path, example_body,
                                 headers=dict(auth(), Origin=origin))
        check("POST from %s -> 200 with Allow-Origin" % origin,
              st == 200 and h.get("access-control-allow-origin") == origin
              and "Origin" in h.get("vary", ""), (st, h))
        check("POST from %s exposes X-Request-Id" % origin,
              "X-Request-Id" in h.get("access-control-expose-headers", ""), h)
    # A 401 to an allowed origin still carries Allow-Origin, so the page can read it.
    st, h, _ = request(port, "GET", "/v1", headers={"Origin": ALLOWED[0]})
    check("401 to an allowed origin carries Allow-Origin",
          st == 401 and h.get("access-control-allow-origin") == ALLOWED[0], (st, h))
    for origin in ["http://evil.example", "http://lab.example.org.evil.example",
                   "https://lab.example.org", "http://lab.example.org:80", "null",
                   "http://localhost:3001"]:
        # Answered as a plain OPTIONS (RFC 9110 9.3.7): Allow, no CORS header,
        # so the browser itself refuses the cross-origin request (was: 403).
        st, h, payload = request(port, "OPTIONS", example_path, headers=dict(preflight, Origin=origin))
        check("preflight from unlisted %s -> 204 with Allow, empty body" % origin,
              st == 204 and payload == b""
              and sorted(m.strip() for m in h.get("allow", "").split(","))
              == ["GET", "HEAD", "OPTIONS", "POST"], (st, h, payload[:200]))
        check("preflight from %s: no Access-Control-*" % origin,
              not any(k.startswith("access-control-") for k in h), h)
        check_security_headers("204 preflight from an unlisted origin", h)
        st, h, _ = request(port, "POST", example_path, example_body,
                           headers=dict(auth(), Origin=origin))
        check("POST from unlisted %s: 200 but no Allow-Origin" % origin,
              st == 200 and "access-control-allow-origin" not in h, (st, h))
    st, h, _ = request(port, "GET", "/healthz", headers={"Origin": ALLOWED[0]})
    check("/healthz: no CORS headers (only /v1 is shared)",
          "access-control-allow-origin" not in h, h)


def test_headers_everywhere(port, example_path, example_body):
    cases = [
        ("200 catalog", "GET", "/v1", None, auth(), {}),
        ("404 API", "GET", "/v1/no/such/thing", None, auth(), {}),
        ("404 unknown path", "GET", "/no/such/file.txt", None, {}, {}),
        ("405", "DELETE", "/healthz", None, {}, {}),
        ("400 malformed", "POST", example_path, b"{not json", auth(), {}),
        ("415", "POST", example_path, b"x=1", auth(), {"ct": "application/x-www-form-urlencoded"}),
        ("422", "POST", example_path, {"no_such_field": 1}, auth(), {}),
        ("413", "POST", example_path, b"[" + b" " * 70000 + b"]", auth(), {}),
        ("static file", "GET", "/app.js", None, {}, {}),
        ("metrics", "GET", "/metrics", None, {}, {}),
    ]
    for name, method, path, body, hdrs, opt in cases:
        st, h, _ = request(port, method, path, body, headers=hdrs,
                           content_type=opt.get("ct", "application/json"))
        check("%s answered (%d)" % (name, st), 200 <= st < 600, st)
        check_security_headers("%s %s %s" % (name, method, path), h)
        if h.get("content-type", "").startswith("application/"):
            check("%s: CSP default-src 'none' on JSON" % name,
                  "default-src 'none'" in h.get("content-security-policy", ""), h)


def test_traversal(port):
    st, _, body = raw_request(port, b"/app.js")
    check("static /app.js -> 200 (the file server works)", st == 200 and body, st)
    targets = [
        b"/../../../../etc/passwd", b"/../server/http.c", b"/labs/../../README.md",
        b"/%2e%2e/%2e%2e/%2e%2e/etc/passwd", b"/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd",
        b"/..%2f..%2f..%2fetc%2fpasswd", b"/%252e%252e/%252e%252e/etc/passwd",
        b"/%252e%252e%252f%252e%252e%252fetc%252fpasswd", b"/%25252e%25252e/etc/passwd",
        b"/etc/passwd", b"//etc/passwd", b"///etc/passwd", b"/./app.js/../../etc/passwd",
        b"/..\\..\\..\\etc\\passwd", b"/%5c..%5c..%5cetc%5cpasswd", b"/labs\\..\\app.js",
        b"/%c0%ae%c0%ae/%c0%ae%c0%ae/etc/passwd", b"/.%2e/.%2e/etc/passwd",
        b"/app.js%00.html", b"/.git/config", b"/.%67it/config", b"/labs/./index.html",
        b"/app.js/", b"/%2fetc%2fpasswd", b"/../../../../proc/self/environ",
        b"/C:\\Windows\\win.ini",
    ]
    for t in targets:
        st, head, body = raw_request(port, t)
        leaked = b"root:" in body or b"#include" in body or b"[core]" in body or b"PATH=" in body
        check("traversal %s -> 400/404, nothing leaked" % t.decode("latin-1"),
              st in (400, 404) and not leaked, "%d %r" % (st, body[:120]))
    # An absolute-form request target must not reach the file system either.
    st, _, body = raw_request(port, b"http://127.0.0.1/../../etc/passwd")
    check("absolute-form target -> 400/404", st in (400, 404) and b"root:" not in body, st)


def test_cors_off(example_path, example_body):
    srv = Server("--workers", "1")
    try:
        st, h, _ = request(srv.port, "GET", "/v1", headers={"Origin": ALLOWED[0]})
        check("CORS off: GET /v1 open (no token file) -> 200", st == 200, st)
        check("CORS off: no Allow-Origin, no Vary: Origin",
              "access-control-allow-origin" not in h and "origin" not in h.get("vary", "").lower(),
              h)
        st, h, _ = request(srv.port, "OPTIONS", example_path,
                           headers={"Origin": ALLOWED[0], "Access-Control-Request-Method": "POST"})
        check("CORS off: preflight answered 204 with Allow, no Access-Control-*",
              st == 204 and "POST" in h.get("allow", "")
              and not any(k.startswith("access-control-") for k in h), (st, h))
        st, h, payload = request(srv.port, "OPTIONS", "/v1/no/such/operation",
                                 headers={"Origin": ALLOWED[0],
                                          "Access-Control-Request-Method": "POST"})
        check("CORS off: preflight of an unknown path -> 404, no Access-Control-*",
              st == 404 and not any(k.startswith("access-control-") for k in h), (st, h))
    finally:
        srv.stop()


def test_options(tmp):
    def run(args, env=None):
        full_env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
        full_env.update(env or {})
        p = subprocess.run([MECHD, "--port", "0"] + args, capture_output=True, timeout=20,
                           env=full_env, input=b"")
        return p.returncode, p.stderr.decode("utf-8", "replace")

    empty = os.path.join(tmp, "empty")
    open(empty, "w").close()
    spaced = os.path.join(tmp, "spaced")
    with open(spaced, "w") as f:
        f.write("two words\n")
    longf = os.path.join(tmp, "long")
    with open(longf, "w") as f:
        f.write("a" * 300 + "\n")
    for name, args in [("missing token file", ["--token-file", os.path.join(tmp, "nope")]),
                       ("empty token file", ["--token-file", empty]),
                       ("token with a space", ["--token-file", spaced]),
                       ("token over 256 bytes", ["--token-file", longf]),
                       ("origin '*'", ["--cors-origin", "*"]),
                       ("origin with a path", ["--cors-origin", "http://a.example/x"]),
                       ("origin without scheme", ["--cors-origin", "a.example"])]:
        rc, err = run(args)
        check("%s -> exit 2 with a message" % name, rc == 2 and "mechd:" in err, (rc, err))
    rc, err = run(["--help"])
    check("--help lists --token-file and --cors-origin", rc == 0)
    p = subprocess.run([MECHD, "--help"], capture_output=True, timeout=20)
    out = p.stdout.decode()
    check("--help text", "--token-file" in out and "--cors-origin" in out
          and "MECHD_TOKEN_FILE" in out, out[-600:])


def main():
    tmp = tempfile.mkdtemp(prefix="mechd-sec-")
    token_file = os.path.join(tmp, "token")
    with open(token_file, "w") as f:
        f.write(TOKEN + "\n")
    os.chmod(token_file, 0o600)

    srv = Server("--token-file", token_file, "--cors-origin", ALLOWED[0],
                 "--cors-origin", ",".join(ALLOWED[1:]), "--workers", "1", "--max-body", "65536")
    try:
        st, _, payload = request(srv.port, "GET", "/v1", headers=auth())
        cat = json.loads(payload)
        op = next(o for o in cat["operations"] if o["method"] == "POST" and "example" in o
                  and o["path"].startswith("/v1/relativity/"))
        test_auth(srv.port, op["path"], op["example"])
        test_cors(srv.port, op["path"], op["example"])
        test_headers_everywhere(srv.port, op["path"], op["example"])
        test_traversal(srv.port)
    finally:
        srv.stop()
    check("server exits 0 on SIGTERM", srv.proc.returncode == 0, srv.proc.returncode)

    # The environment variable works like the option.
    srv = Server(env={"MECHD_TOKEN_FILE": token_file})
    try:
        st, _, _ = request(srv.port, "GET", "/v1")
        check("MECHD_TOKEN_FILE: no token -> 401", st == 401, st)
        st, _, _ = request(srv.port, "GET", "/v1", headers=auth())
        check("MECHD_TOKEN_FILE: token -> 200", st == 200, st)
    finally:
        srv.stop()

    test_cors_off(op["path"], op["example"])
    test_options(tmp)

    sys.exit(summary())


if __name__ == "__main__":
    main()
