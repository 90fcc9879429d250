#!/usr/bin/python3
"""HTTP details of the request head and of /metrics (Python 3 stdlib only).

Usage: /usr/bin/python3 test_http_edges.py PATH/TO/mechd

Checked here, on 127.0.0.1 only, every socket with a timeout:
- a request target over 32 KiB is refused 414 as application/problem+json
  (type /problems/uri-too-long), and a head over 32 KiB 431 likewise; a 20 KB
  target is still served;
- an HTTP/1.1 request without Host, or with two, is refused 400
  /problems/bad-request (RFC 9112 section 3.2) and the connection is closed;
  HTTP/1.0 without Host is served;
- OPTIONS that is not a CORS preflight gets 204 with Allow naming the methods
  of that path (an operation: POST, GET, HEAD, OPTIONS; /healthz: GET, HEAD,
  OPTIONS; "*": every method), an unknown path 404; with --cors-origin a
  preflight from a listed origin still gets its Access-Control-Allow-* set,
  one from any other origin (or with CORS off) 204 with Allow and no
  Access-Control-* header;
- /metrics: a latency histogram per route (labels from the operation table:
  the operation's path, never the raw path a client sent, so 200 distinct
  unknown paths add one label, "other"), cumulative buckets whose +Inf bucket
  equals the count; process metrics (CPU seconds, resident memory, open and
  allowed descriptors, start time between the test's start and now) and
  mechd_build_info with the version `mechd --version` prints.
"""
import json
import os
import re
import socket
import subprocess
import sys
import time

from mechdtest import check, start_mechd, stop_mechd, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_http_edges.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
BOOST = json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}).encode()
ORIGIN = "http://lab.example.org"


def exchange(port, data, timeout=10):
    """Send data, read until the server closes; return (status, headers dict, body, closed)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    s.sendall(data)
    buf = b""
    closed = False
    try:
        while True:
            c = s.recv(65536)
            if not c:
                closed = True
                break
            buf += c
            head, sep, rest = buf.partition(b"\r\n\r\n")
            if sep:
                m = re.search(rb"(?im)^content-length: *(\d+)", head)
                if m and len(rest) >= int(m.group(1)) and b"connection: close" not in head.lower():
                    break
    except socket.timeout:
        pass
    s.close()
    head, _, body = buf.partition(b"\r\n\r\n")
    lines = head.decode("latin-1").split("\r\n")
    st = int(lines[0].split()[1]) if lines and len(lines[0].split()) > 1 else None
    hdr = {}
    for ln in lines[1:]:
        k, _, v = ln.partition(":")
        hdr[k.strip().lower()] = v.strip()
    return st, hdr, body, closed


def problem(body):
    try:
        return json.loads(body)
    except ValueError:
        return {}


def get(port, path, extra=b""):
    return exchange(port, b"GET " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n" + extra
                    + b"Connection: close\r\n\r\n")


def test_head_limits(port):
    st, h, body, _ = exchange(port, b"GET /healthz?x=" + b"a" * 36000 +
                              b" HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
    doc = problem(body)
    check("36 KB target -> 414 problem+json",
          st == 414 and h.get("content-type") == "application/problem+json"
          and doc.get("type") == "/problems/uri-too-long" and doc.get("status") == 414
          and doc.get("request_id") == h.get("x-request-id"), (st, h, body[:200]))
    st, _, _, _ = get(port, "/healthz?x=" + "a" * 20000)
    check("20 KB target still served -> 200", st == 200, st)
    st, h, body, _ = get(port, "/healthz", b"X-Big: " + b"a" * 36000 + b"\r\n")
    check("36 KB header -> 431 problem+json",
          st == 431 and h.get("content-type") == "application/problem+json"
          and problem(body).get("type") == "/problems/headers-too-large", (st, h, body[:200]))


def test_host(port):
    st, h, body, closed = exchange(port, b"GET /healthz HTTP/1.1\r\n\r\n")
    doc = problem(body)
    check("HTTP/1.1 without Host -> 400 bad-request, connection closed",
          st == 400 and doc.get("type") == "/problems/bad-request" and "Host" in doc.get("detail", "")
          and h.get("content-type") == "application/problem+json" and closed, (st, h, body, closed))
    st, h, body, _ = exchange(port, b"POST /v1/relativity/boost HTTP/1.1\r\n"
                              b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n"
                              % len(BOOST) + BOOST)
    check("POST without Host -> 400 before the body is used", st == 400
          and problem(body).get("type") == "/problems/bad-request", (st, body))
    st, _, body, _ = exchange(port, b"GET /healthz HTTP/1.1\r\nHost: a\r\nHost: b\r\n"
                              b"Connection: close\r\n\r\n")
    check("two Host headers -> 400", st == 400 and problem(body).get("type") == "/problems/bad-request",
          (st, body))
    st, _, body, _ = exchange(port, b"GET /healthz HTTP/1.0\r\n\r\n")
    check("HTTP/1.0 without Host -> 200", st == 200 and body == b'{"status":"ok"}', (st, body))


def options(port, path, extra=b""):
    return exchange(port, b"OPTIONS " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n" + extra
                    + b"Connection: close\r\n\r\n")


def methods(allow):
    return sorted(m.strip() for m in allow.split(",") if m.strip())


def test_options(port, cors):
    for path, want in [("/v1/relativity/boost", ["GET", "HEAD", "OPTIONS", "POST"]),
                       ("/v1/integrators", ["GET", "HEAD", "OPTIONS"]),
                       ("/v1", ["GET", "HEAD", "OPTIONS"]),
                       ("/healthz", ["GET", "HEAD", "OPTIONS"]),
                       ("/metrics", ["GET", "HEAD", "OPTIONS"]),
                       ("*", ["GET", "HEAD", "OPTIONS", "POST"])]:
        st, h, body, _ = options(port, path)
        check("OPTIONS %s -> 204 Allow: %s" % (path, ", ".join(want)),
              st == 204 and methods(h.get("allow", "")) == want and body == b"", (st, h))
    st, h, body, _ = options(port, "/v1/no/such/operation")
    check("OPTIONS of an unknown path -> 404", st == 404
          and problem(body).get("type") == "/problems/not-found", (st, body[:200]))
    if cors:
        st, h, _, _ = options(port, "/v1/relativity/boost", b"Origin: " + ORIGIN.encode() + b"\r\n")
        check("OPTIONS (no preflight) from a listed origin -> 204 Allow + Allow-Origin",
              st == 204 and "POST" in h.get("allow", "")
              and h.get("access-control-allow-origin") == ORIGIN, (st, h))
        st, h, _, _ = options(port, "/v1/relativity/boost",
                              b"Origin: " + ORIGIN.encode() + b"\r\n"
                              b"Access-Control-Request-Method: POST\r\n"
                              b"Access-Control-Request-Headers: content-type\r\n")
        check("preflight from a listed origin -> 204 with Allow-Methods/Headers",
              st == 204 and "POST" in h.get("access-control-allow-methods", "")
              and "content-type" in h.get("access-control-allow-headers", "").lower()
              and h.get("access-control-allow-origin") == ORIGIN, (st, h))
    # A preflight from an origin not allowed (or with CORS off): Allow and no
    # CORS header, as for any OPTIONS; before, it was refused 403.
    st, h, body, _ = options(port, "/v1/relativity/boost",
                             b"Origin: http://other.example\r\n"
                             b"Access-Control-Request-Method: POST\r\n")
    check("preflight from an origin not allowed -> 204 Allow, no Access-Control-* (cors %s)"
          % ("on" if cors else "off"),
          st == 204 and methods(h.get("allow", "")) == ["GET", "HEAD", "OPTIONS", "POST"]
          and body == b"" and not any(k.startswith("access-control-") for k in h), (st, h, body[:200]))


def samples(text, name):
    """[(labels dict, value)] of every sample of metric `name`."""
    out = []
    for m in re.finditer(r"(?m)^" + re.escape(name) + r"(?:\{([^}]*)\})? (\S+)$", text):
        labels = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1) or ""))
        out.append((labels, float(m.group(2))))
    return out


def test_metrics(port, t_start):
    for _ in range(3):
        exchange(port, b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                 b"Content-Type: application/json\r\nConnection: close\r\nContent-Length: %d\r\n\r\n"
                 % len(BOOST) + BOOST)
    for i in range(200):  # 200 distinct unknown paths: bounded labels
        get(port, "/v1/unknown/%d" % i)
    st, _, body, _ = get(port, "/metrics")
    text = body.decode()
    check("GET /metrics -> 200", st == 200, st)
    b = samples(text, "mechd_route_request_duration_seconds_bucket")
    routes = sorted({lab["route"] for lab, _ in b})
    check("per-route histogram: the boost has its own route label",
          "/v1/relativity/boost" in routes, routes)
    check("per-route histogram: unknown paths fold into 'other' (bounded labels)",
          not any(r.startswith("/v1/unknown") for r in routes) and "other" in routes
          and len(routes) < 20, routes)
    cnt = dict((lab["route"], v) for lab, v in samples(text, "mechd_route_request_duration_seconds_count"))
    check("boost count = 3", cnt.get("/v1/relativity/boost") == 3, cnt)
    check("other count >= 200", cnt.get("other", 0) >= 200, cnt)
    ok = True
    for route in routes:
        vals = [(lab["le"], v) for lab, v in b if lab["route"] == route]
        cum = [v for _, v in vals]
        ok = ok and cum == sorted(cum) and vals[-1][0] == "+Inf" and vals[-1][1] == cnt.get(route)
    check("per-route buckets cumulative, +Inf = count", ok)
    tracked = sum(cnt.values())
    total = samples(text, "mechd_request_duration_seconds_count")
    check("per-route counts sum to the overall count", total and total[0][1] == tracked,
          (total, tracked))
    cpu = samples(text, "process_cpu_seconds_total")
    rss = samples(text, "process_resident_memory_bytes")
    fds = samples(text, "process_open_fds")
    maxfds = samples(text, "process_max_fds")
    start = samples(text, "process_start_time_seconds")
    check("process_cpu_seconds_total > 0", cpu and cpu[0][1] > 0, cpu)
    check("process_resident_memory_bytes between 1 MB and 4 GB",
          rss and 1e6 < rss[0][1] < 4e9, rss)
    check("process_open_fds between 4 and process_max_fds",
          fds and maxfds and 4 <= fds[0][1] <= maxfds[0][1], (fds, maxfds))
    check("process_start_time_seconds within the test's run",
          start and t_start - 5 <= start[0][1] <= time.time() + 5, (start, t_start))
    ver = subprocess.run([MECHD, "--version"], stdout=subprocess.PIPE, check=False).stdout.decode()
    m = re.match(r"mechd (\S+) \(commit (\S+)\)", ver)
    bi = samples(text, "mechd_build_info")
    check("mechd_build_info{version, commit} 1 as --version says",
          m and bi and bi[0][1] == 1 and bi[0][0].get("version") == m.group(1)
          and bi[0][0].get("commit") == m.group(2), (bi, ver))


def main():
    t_start = time.time()
    proc, port = start_mechd(MECHD, ["--cors-origin", ORIGIN], stderr=subprocess.DEVNULL)
    try:
        test_metrics(port, t_start)  # first: the counts are this test's requests
        test_head_limits(port)
        test_host(port)
        test_options(port, cors=True)
        st, _, _, _ = get(port, "/healthz")
        check("still answering /healthz", st == 200, st)
    finally:
        stop_mechd(proc)
    proc, port = start_mechd(MECHD, stderr=subprocess.DEVNULL)
    try:
        test_options(port, cors=False)
    finally:
        stop_mechd(proc)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
