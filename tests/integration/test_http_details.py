"""test_http_details.py — HTTP details and answer budgets of a real mechd,
checked on the wire:

- GET of an operation without ?request= is a 400 problem saying what is needed, not a 405;
- a 304 never carries Content-Length: 0 (RFC 9110 8.6: only the 200's length, or none);
- GET /v1 and /v1/openapi.json carry a strong ETag, Cache-Control, Vary: Accept-Encoding, a
  gzip body for clients that accept it (which decompresses to the identity bytes) and 304 on
  If-None-Match;
- every problem+json body carries an RFC 9457 instance (the request path; a batch item's is
  /v1/batch#/operations/<i>), built by the API layer or by the server;
- a batch asking for more samples than --max-samples is refused at once (422
  answer-too-large naming the field and the limit) instead of building a 757 MB answer;
- an item running when the request's deadline passes stops near it;
- RSS returns near its baseline after large answers;
- a batch answer that depended on the deadline (a partial answer) is never cacheable:
  Cache-Control: no-store and no ETag, while the full answer keeps its ETag.
Timing bounds are generous (seconds against a 400 ms deadline) so the test never fails on
timing."""
import gzip
import json
import re
import socket
import sys
import time
import urllib.parse

sys.path.insert(0, __import__("os").path.dirname(__file__))
from mechdtest import check, start_mechd, summary  # noqa: E402

DEADLINE_MS = 400
GEODESIC = {"M": "sun", "kind": "timelike",
            "initial": {"semi_major_axis": 57909050000.0, "eccentricity": 0.20563593},
            "orbits": 3, "samples": 5, "integrator": {"accuracy": "precise"}}
BOOST = {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [0.6, 0, 0]}}


def raw(port, text, want_close=True, timeout=10.0):
    """Send raw request bytes; return everything received until the peer closes
    (want_close) or the timeout passes, and whether the peer closed."""
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    s.sendall(text if isinstance(text, bytes) else text.encode())
    data, closed = b"", False
    end = time.monotonic() + timeout
    try:
        while time.monotonic() < end:
            c = s.recv(1 << 20)
            if not c:
                closed = True
                break
            data += c
            if not want_close:
                head, sep, rest = data.partition(b"\r\n\r\n")
                m = re.search(rb"(?im)^content-length: *(\d+)", head)
                no_body = head.split(b" ", 2)[1:2] == [b"304"]
                if sep and (no_body or not m or len(rest) >= int(m.group(1))):
                    s.settimeout(0.3)  # whatever else comes (nothing should) in 0.3 s
    except socket.timeout:
        pass
    s.close()
    return data, closed


def split(resp):
    head, _, body = resp.partition(b"\r\n\r\n")
    lines = head.decode("latin-1").split("\r\n")
    status = int(lines[0].split()[1]) if lines and len(lines[0].split()) > 1 else 0
    headers = {}
    for ln in lines[1:]:
        k, _, v = ln.partition(":")
        headers.setdefault(k.strip().lower(), []).append(v.strip())
    return status, headers, body


def get(port, path, headers=(), method="GET"):
    req = "%s %s HTTP/1.1\r\nHost: t\r\nConnection: close\r\n%s\r\n" % (
        method, path, "".join("%s: %s\r\n" % h for h in headers))
    return split(raw(port, req)[0])


def post(port, path, body, timeout=60.0):
    data = json.dumps(body).encode()
    req = (b"POST %s HTTP/1.1\r\nHost: t\r\nConnection: close\r\nContent-Type: application/json"
           b"\r\nContent-Length: %d\r\n\r\n" % (path.encode(), len(data))) + data
    return split(raw(port, req, timeout=timeout)[0])


def one(h, name):
    v = h.get(name, [])
    return v[0] if len(v) == 1 else None


def rss_mb(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return -1.0


def problem(body):
    try:
        return json.loads(body)
    except ValueError:
        return {}


def test_request_missing(port):
    for method in ("GET", "HEAD"):
        st, h, b = get(port, "/v1/relativity/boost", method=method)
        p = problem(b) if method == "GET" else {}
        check("%s of an operation without ?request= -> 400, not 405" % method, st == 400, st)
        check("%s without ?request=: problem+json, no Allow" % method,
              one(h, "content-type") == "application/problem+json" and "allow" not in h, h)
        if method == "GET":
            check("the 400 says what is needed (?request= or POST) and is typed",
                  p.get("type") == "/problems/request-missing" and "?request=" in p.get("detail", "")
                  and "POST" in p.get("detail", ""), p)


def test_304_length(port):
    q = urllib.parse.quote(json.dumps(BOOST))
    st, h, b = get(port, "/v1/relativity/boost?request=" + q)
    etag = one(h, "etag")
    check("GET ?request= 200 with an ETag", st == 200 and etag, (st, h))
    resp, closed = raw(port, "GET /v1/relativity/boost?request=%s HTTP/1.1\r\nHost: t\r\n"
                             "If-None-Match: %s\r\n\r\n" % (q, etag), want_close=False, timeout=5)
    st, h, body = split(resp)
    check("GET ?request= revalidation -> 304", st == 304, resp[:200])
    cl = h.get("content-length")
    check("the 304 of GET ?request= sends no Content-Length (the 200's length is not known "
          "without running it) and no chunked framing or body",
          cl is None and "transfer-encoding" not in h and body == b"", (h, body))
    for path in ("/v1", "/v1/openapi.json", "/"):
        st, h, b = get(port, path)
        etag, n200 = one(h, "etag"), len(b)
        resp, closed = raw(port, "GET %s HTTP/1.1\r\nHost: t\r\nIf-None-Match: %s\r\n\r\n"
                           % (path, etag), want_close=False, timeout=5)
        st, h, body = split(resp)
        cl = h.get("content-length")
        check("%s: 304 on a matching If-None-Match" % path, st == 304, resp[:200])
        check("%s: the 304's Content-Length is the 200's (%d) or absent, never 0" % (path, n200),
              cl is None or cl == [str(n200)], cl)
        check("%s: the 304 has no body" % path, body == b"", body[:80])


def test_documents(port):
    for path, least in (("/v1", 200000), ("/v1/openapi.json", 500000)):
        st, h, ident = get(port, path)
        etag = one(h, "etag")
        check("%s: 200, identity, strong ETag" % path,
              st == 200 and "content-encoding" not in h and etag and etag.startswith('"'), h)
        check("%s: Cache-Control says to revalidate" % path,
              one(h, "cache-control") in ("no-cache",) or
              "must-revalidate" in (one(h, "cache-control") or ""), h.get("cache-control"))
        check("%s: Vary: Accept-Encoding" % path,
              any("accept-encoding" in v.lower() for v in h.get("vary", [])), h.get("vary"))
        check("%s: is large (%d bytes)" % (path, len(ident)), len(ident) > least)
        st, hg, gz = get(port, path, [("Accept-Encoding", "br, gzip;q=0.8, deflate")])
        ok = st == 200 and one(hg, "content-encoding") == "gzip"
        check("%s: gzip for Accept-Encoding: ..., gzip;q=0.8" % path, ok, (st, hg))
        if ok:
            check("%s: the gzip body decompresses to the identity bytes" % path,
                  gzip.decompress(gz) == ident)
            check("%s: gzip is under a fifth of identity (%d of %d bytes)"
                  % (path, len(gz), len(ident)), 5 * len(gz) < len(ident))
            check("%s: the gzip representation has its own ETag" % path,
                  one(hg, "etag") and one(hg, "etag") != etag, (one(hg, "etag"), etag))
            st, h2, b2 = get(port, path, [("Accept-Encoding", "gzip"),
                                          ("If-None-Match", one(hg, "etag"))])
            check("%s: 304 for the gzip ETag" % path, st == 304 and b2 == b"", st)
        st, h, b = get(port, path, [("Accept-Encoding", "gzip;q=0, identity")])
        check("%s: gzip;q=0 gets identity" % path,
              st == 200 and "content-encoding" not in h and b == ident, h)
        st, h, b = get(port, path, [("Accept-Encoding", "*")])
        check("%s: * admits gzip" % path, one(h, "content-encoding") == "gzip", h)
        st, h, b = get(port, path, [("If-None-Match", etag)])
        check("%s: 304 for the identity ETag" % path, st == 304 and b == b"", st)
        st, h, b = get(port, path, method="HEAD")
        check("%s: HEAD 200 with the ETag, no body" % path,
              st == 200 and one(h, "etag") == etag and b == b"", (st, h))


def test_instance(port):
    cases = [("GET", "/v1/nothing/here", None, 404, "/v1/nothing/here"),
             ("POST", "/v1/relativity/boost", {"vectors": [[1, 0, 0, 0]],
                                               "velocity": {"beta": [1.5, 0, 0]}}, 422,
              "/v1/relativity/boost"),
             ("POST", "/v1/relativity/boost", {"vectors": 1}, 422, "/v1/relativity/boost"),
             ("POST", "/healthz", {}, 405, "/healthz"),
             ("GET", "/problems/none-such", None, 404, "/problems/none-such")]
    for method, path, body, status, inst in cases:
        st, h, b = post(port, path, body) if method == "POST" else get(port, path)
        p = problem(b)
        check("%s %s -> %d problem with instance %s" % (method, path, status, inst),
              st == status and p.get("instance") == inst, (st, p))
    # Built by the server, not the API layer: 415 and 413.
    req = ("POST /v1/relativity/boost HTTP/1.1\r\nHost: t\r\nConnection: close\r\n"
           "Content-Type: text/plain\r\nContent-Length: 2\r\n\r\n{}")
    st, h, b = split(raw(port, req)[0])
    check("415 carries instance", st == 415 and problem(b).get("instance") == "/v1/relativity/boost",
          (st, b[:300]))
    req = ("POST /v1/relativity/boost HTTP/1.1\r\nHost: t\r\nConnection: close\r\n"
           "Content-Type: application/json\r\nContent-Length: 999999999\r\n\r\n")
    st, h, b = split(raw(port, req)[0])
    check("413 carries instance", st == 413 and problem(b).get("instance") == "/v1/relativity/boost",
          (st, b[:300]))
    # A path with a quote and a control character stays valid JSON.
    st, h, b = get(port, "/v1/a%22b%01c")
    check("a path with \" and \\x01 gives a valid JSON instance",
          st == 404 and problem(b).get("instance") == '/v1/a"b\x01c', b[:300])
    # A batch item's problem.
    batch = {"operations": [{"operation": "/v1/relativity/boost", "request": BOOST},
                            {"operation": "/v1/relativity/boost", "request": {"vectors": 1}}]}
    st, h, b = post(port, "/v1/batch", batch)
    res = problem(b).get("results", [{}, {}])
    check("a batch item's problem has instance /v1/batch#/operations/1",
          st == 200 and res[1].get("problem", {}).get("instance") == "/v1/batch#/operations/1"
          and "instance" not in res[0].get("body", {}), res)


def test_answer_budget(port, pid):
    big = dict(GEODESIC, samples=100000)
    batch = {"operations": [{"operation": "/v1/gr/geodesic", "request": big}] * 100}
    base = rss_mb(pid)
    t0 = time.monotonic()
    st, h, b = post(port, "/v1/batch", batch)
    dt = time.monotonic() - t0
    p = problem(b)
    check("100 x 100000-sample geodesics -> 422 answer-too-large", st == 422 and
          p.get("type") == "/problems/answer-too-large", (st, b[:300]))
    errs = p.get("errors") or [{}]
    check("it names the field where the sum passes the limit, and the limit",
          errs[0].get("pointer") == "/operations/2/request/samples" and p.get("limit") == 200000
          and p.get("requested") == 10000000 and "200000" in p.get("detail", ""), p)
    check("refused at once (%.2f s; generous bound 3 s), before computing" % dt, dt < 3.0)
    check("and with little memory (RSS %.0f -> %.0f MB)" % (base, rss_mb(pid)),
          rss_mb(pid) < base + 50)
    # Defaults count too: an item without samples counts its operation's default.
    st, h, b = post(port, "/v1/batch", {"operations": [
        {"operation": "/v1/gr/geodesic", "request": dict(big, samples=99900)},
        {"operation": "/v1/gr/geodesic", "request": big},
        {"operation": "/v1/gr/geodesic",
         "request": {k: v for k, v in GEODESIC.items() if k != "samples"}}]})
    p = problem(b)
    check("an item's default samples (201) count: 99900 + 100000 + 201 > 200000",
          st == 422 and (p.get("errors") or [{}])[0].get("pointer") == "/operations/2/request",
          (st, b[:300]))
    st, h, b = post(port, "/v1/gr/geodesic", big)
    check("one 100000-sample geodesic (the schema's maximum) still answers 200", st == 200,
          (st, b[:200]))


def sanitized(binary):
    """Whether mechd is an ASan/TSan build (their allocators keep freed memory on purpose)."""
    with open(binary, "rb") as f:
        data = f.read()
    return b"__asan_init" in data or b"__tsan_init" in data


def test_memory_returned(port, pid):
    big = dict(GEODESIC, samples=100000)
    batch = {"operations": [{"operation": "/v1/gr/geodesic", "request": big}] * 2}
    post(port, "/v1/gr/geodesic", GEODESIC)
    base = rss_mb(pid)
    sizes = []
    for _ in range(3):
        st, h, b = post(port, "/v1/batch", batch)
        sizes.append(len(b))
    time.sleep(0.3)
    after = rss_mb(pid)
    check("three batches answered with %d-byte answers" % max(sizes),
          st == 200 and min(sizes) > 10 * 2 ** 20, sizes)
    check("RSS after large answers returns near its baseline (%.0f -> %.0f MB; bound +40 MB)"
          % (base, after), after < base + 40, (base, after))


def test_deadline_and_cache(port):
    slow = dict(GEODESIC, orbits=100000, samples=1000)
    batch = {"operations": [{"operation": "/v1/gr/geodesic", "request": slow},
                            {"operation": "/v1/relativity/boost", "request": BOOST}]}
    t0 = time.monotonic()
    st, h, b = post(port, "/v1/batch", batch)
    dt = time.monotonic() - t0
    res = problem(b).get("results", [{}, {}])
    p0 = res[0].get("problem", {})
    check("an item running past the deadline stops there (%.2f s for a %d ms deadline; "
          "bound 5 s)" % (dt, DEADLINE_MS), st == 200 and dt < 5.0 and
          p0.get("type") == "/problems/compute-budget-exceeded" and
          p0.get("progress", {}).get("limit") == "deadline", (st, dt, p0))
    check("the next item is not run after the deadline",
          res[1].get("status") == 422, res[1])
    check("a partial POST answer is no-store", one(h, "cache-control") == "no-store", h)
    q = urllib.parse.quote(json.dumps(batch))
    st, h, b = get(port, "/v1/batch?request=" + q)
    res = problem(b).get("results", [{}, {}])
    check("GET ?request= of the same batch: 200 with items stopped by the deadline",
          st == 200 and res[0].get("status") == 422, (st, b[:200]))
    check("... is never cacheable: Cache-Control: no-store and no ETag",
          one(h, "cache-control") == "no-store" and "etag" not in h, h)
    full = {"operations": [{"operation": "/v1/relativity/boost", "request": BOOST}]}
    st, h, b = get(port, "/v1/batch?request=" + urllib.parse.quote(json.dumps(full)))
    check("a full batch answer keeps its ETag and public caching",
          st == 200 and one(h, "etag") and "public" in (one(h, "cache-control") or ""), h)


def main():
    binary = sys.argv[1]
    proc, port = start_mechd(binary, ["--workers", "2"])
    try:
        test_request_missing(port)
        test_304_length(port)
        test_documents(port)
        test_instance(port)
        test_answer_budget(port, proc.pid)
        if sanitized(binary):
            print("skip RSS check: a sanitizer's allocator holds freed memory (quarantine)")
        else:
            test_memory_returned(port, proc.pid)
    finally:
        proc.terminate()
        proc.wait(15)
    # A short deadline, to stop an item deterministically.
    proc, port = start_mechd(binary, ["--deadline-ms", str(DEADLINE_MS), "--workers", "2"])
    try:
        test_deadline_and_cache(port)
    finally:
        proc.terminate()
        proc.wait(15)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
