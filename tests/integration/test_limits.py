#!/usr/bin/python3
"""Input limits of mechd over real HTTP (Python 3 standard library only).

Usage: /usr/bin/python3 test_limits.py PATH/TO/mechd

One test per limit, each answered with a clear status:
  header size   one 40 KB header, 5000 small headers, a 40 KB URL -> 431 (or 414)
                from libmicrohttpd (its connection memory limit, 32 KB by default;
                libmicrohttpd writes that answer itself, as a short HTML page);
                8 KB of headers still work;
  body size     Content-Length over --max-body and a chunked body over it
                -> 413 /problems/body-too-large;
  JSON depth    nesting deeper than jansson's 2048 -> 400 /problems/malformed-json
                naming the depth; 2048 deep -> 422 validation (no crash);
  array length  100001 vectors to /v1/relativity/boost (maxItems 100000)
                -> 422 /problems/validation-error at /vectors;
  samples       samples 100001 (maximum 100000) -> 422 at /samples;
  steps         a fixed-step trajectory needing 10000 steps under --max-steps 1000
                -> 422 /problems/compute-budget-exceeded.
Only 127.0.0.1 is contacted; every socket and subprocess has a timeout.
"""
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
from mechdtest import check, start_mechd, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_limits.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
TIMEOUT = 60.0


def start(*args):
    errf = tempfile.TemporaryFile()
    return start_mechd(MECHD, args, stderr=errf)


def exchange(port, raw):
    """Send raw bytes (tolerating a reset once the server has answered) and read
    the answer: (status, header text, body bytes)."""
    with socket.create_connection(("127.0.0.1", port), timeout=TIMEOUT) as s:
        try:
            s.sendall(raw)
        except (BrokenPipeError, ConnectionResetError):
            pass
        data = b""
        while True:
            try:
                chunk = s.recv(65536)
            except ConnectionResetError:
                break
            if not chunk:
                break
            data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.[01] (\d{3})", head)
    return (int(m.group(1)) if m else 0), head.decode("latin-1"), body


def post(port, path, body, extra=b""):
    data = body if isinstance(body, bytes) else json.dumps(body).encode()
    return exchange(port, b"POST " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                    b"Content-Type: application/json\r\nConnection: close\r\n" + extra +
                    b"Content-Length: %d\r\n\r\n" % len(data) + data)


def problem(body):
    try:
        return json.loads(body)
    except ValueError:
        return {}


def check_problem(name, got, status, ptype, pointer=None, detail_has=None):
    st, head, body = got
    doc = problem(body)
    ok = (st == status and "application/problem+json" in head.lower()
          and doc.get("type") == ptype and doc.get("status") == status)
    if pointer is not None:
        ok = ok and any(e.get("pointer") == pointer for e in doc.get("errors", []))
    if detail_has is not None:
        ok = ok and detail_has in doc.get("detail", "")
    check("%s -> %d %s%s" % (name, status, ptype, " at " + pointer if pointer else ""), ok,
          "%d %r" % (st, body[:400]))


def main():
    proc, port = start("--workers", "1", "--max-steps", "1000")
    try:
        healthz = b"GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
        # --- header size (libmicrohttpd's connection memory limit) ---
        st, head, body = exchange(port, healthz + b"X-Big: " + b"a" * 40000 + b"\r\n\r\n")
        check("one 40 KB header -> 431", st == 431, (st, head))
        st, head, _ = exchange(port, healthz +
                               b"".join(b"X-H%d: v\r\n" % i for i in range(5000)) + b"\r\n")
        check("5000 headers -> 431", st == 431, (st, head))
        st, head, _ = exchange(port, b"GET /healthz?x=" + b"a" * 40000 +
                               b" HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        check("40 KB request line -> 414 or 431", st in (414, 431), (st, head))
        st, head, _ = exchange(port, healthz +
                               b"".join(b"X-H%d: %s\r\n" % (i, b"v" * 70) for i in range(100)) +
                               b"\r\n")
        check("8 KB of headers still served -> 200", st == 200, (st, head))
        st, _, _ = exchange(port, healthz + b"\r\n")
        check("server still answers after the header floods", st == 200, st)

        # --- body size (--max-body, default 1 MiB) ---
        big = b"[" + b"0," * 600000 + b"0]"
        check_problem("Content-Length over --max-body",
                      post(port, "/v1/relativity/boost", big),
                      413, "/problems/body-too-large")
        chunks = b""
        piece = b" " * 65536
        for _ in range(20):
            chunks += b"%x\r\n" % len(piece) + piece + b"\r\n"
        chunks += b"0\r\n\r\n"
        check_problem("chunked body over --max-body",
                      exchange(port, b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                               b"Content-Type: application/json\r\nConnection: close\r\n"
                               b"Transfer-Encoding: chunked\r\n\r\n" + chunks),
                      413, "/problems/body-too-large")

        # --- JSON nesting depth (jansson's JSON_PARSER_MAX_DEPTH = 2048) ---
        for depth in (2049, 100000):
            check_problem("arrays nested %d deep" % depth,
                          post(port, "/v1/relativity/boost", b"[" * depth + b"]" * depth),
                          400, "/problems/malformed-json", detail_has="depth")
        check_problem("objects nested 3000 deep",
                      post(port, "/v1/relativity/boost",
                           b'{"a":' * 3000 + b"1" + b"}" * 3000),
                      400, "/problems/malformed-json", detail_has="depth")
        check_problem("arrays nested 2048 deep (parsed, then refused by the schema)",
                      post(port, "/v1/relativity/boost", b"[" * 2048 + b"]" * 2048),
                      422, "/problems/validation-error", pointer="")
        deep_member = b'{"vectors":' + b"[" * 2040 + b"]" * 2040 + b',"velocity":{"beta":[0.5,0,0]}}'
        check_problem("a member nested 2040 deep",
                      post(port, "/v1/relativity/boost", deep_member),
                      422, "/problems/validation-error")

        # --- array length (maxItems 100000) ---
        vecs = b'{"vectors":[' + b"[1,0,0,0]," * 100000 + b'[1,0,0,0]],"velocity":{"beta":[0.5,0,0]}}'
        check_problem("100001 vectors", post(port, "/v1/relativity/boost", vecs),
                      422, "/problems/validation-error", pointer="/vectors")
        ok_vecs = b'{"vectors":[' + b"[1,0,0,0]," * 999 + b'[1,0,0,0]],"velocity":{"beta":[0.5,0,0]}}'
        st, _, body = post(port, "/v1/relativity/boost", ok_vecs)
        check("1000 vectors -> 200", st == 200, (st, body[:200]))

        # --- samples (maximum 100000) and steps (--max-steps) ---
        traj = {"particle": {"mass": 1, "position": [0, 0, 100], "velocity": [0, 0, 0]},
                "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                "t_end": 10, "samples": 100001}
        check_problem("samples 100001", post(port, "/v1/trajectory", traj),
                      422, "/problems/validation-error", pointer="/samples")
        traj["samples"] = 11
        traj["integrator"] = {"method": "rk4", "dt": 1e-3}
        check_problem("10000 fixed steps over --max-steps 1000", post(port, "/v1/trajectory", traj),
                      422, "/problems/compute-budget-exceeded")
        traj["integrator"] = {"method": "rk4", "dt": 0.1}
        st, _, body = post(port, "/v1/trajectory", traj)
        check("100 fixed steps under --max-steps 1000 -> 200", st == 200, (st, body[:300]))
        st, _, _ = exchange(port, healthz + b"\r\n")
        check("server healthy at the end", st == 200, st)
    finally:
        proc.terminate()
        try:
            rc = proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            rc = proc.wait(timeout=10)
    check("exit 0 on SIGTERM", rc == 0, rc)
    sys.exit(summary())


if __name__ == "__main__":
    main()
