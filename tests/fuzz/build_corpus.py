#!/usr/bin/python3
"""build_corpus.py ROUTES_TSV OUT_DIR — seed corpora for tests/fuzz/ harnesses.

Reads tests/api/cases/<domain>/*/request.json (next to this script's
../api/cases; a case not yet filed under a domain too) and
the route list printed by `FUZZ_LIST_ROUTES=1 fuzz_api` (index, method, path),
and writes OUT_DIR/api/ (fuzz_api.c layout: flags byte, route byte, body),
OUT_DIR/http/ (fuzz_http.c layout: METHOD\\nPATH?QUERY\\nCT\\nINM\\nBODY) and
OUT_DIR/server/ (fuzz_server.c: raw HTTP/1.1 requests as sent on the wire).
Python standard library only."""
import hashlib
import json
import os
import sys
import urllib.parse

here = os.path.dirname(os.path.abspath(__file__))
cases_dir = os.path.join(here, "..", "api", "cases")
web_dir = os.path.join(here, "..", "..", "clients", "web")
routes_tsv, out = sys.argv[1], sys.argv[2]

routes = {}
route_method = {}
with open(routes_tsv) as f:
    for line in f:
        i, m, p = line.rstrip("\n").split("\t")
        routes[p] = int(i)
        route_method[p] = m

for sub in ("api", "http", "server"):
    os.makedirs(os.path.join(out, sub), exist_ok=True)


def put(sub, data):
    name = hashlib.sha1(data).hexdigest()
    with open(os.path.join(out, sub, name), "wb") as f:
        f.write(data)


def wire(method, target, ct, body, headers=(), version="HTTP/1.1"):
    """A raw HTTP request: request line, headers (Content-Length when there is
    a body), blank line, body."""
    lines = [f"{method} {target} {version}", "Host: 127.0.0.1"]
    if ct:
        lines.append(f"Content-Type: {ct}")
    if body or method in ("POST", "PUT"):
        lines.append(f"Content-Length: {len(body)}")
    lines += list(headers)
    return ("\r\n".join(lines) + "\r\n\r\n").encode("latin-1", "replace") + body


def case_requests():
    """request.json of every case: tests/api/cases/<domain>/<case>/, and any
    case still at the top level (scripts/cases_by_domain.py files those)."""
    found = []
    for top in sorted(os.listdir(cases_dir)):
        d = os.path.join(cases_dir, top)
        if os.path.isfile(os.path.join(d, "request.json")):
            found.append(os.path.join(d, "request.json"))
        elif os.path.isdir(d):
            found += [os.path.join(d, c, "request.json") for c in sorted(os.listdir(d))
                      if os.path.isfile(os.path.join(d, c, "request.json"))]
    return found


METHOD_BITS = {"GET": 1, "HEAD": 2}
n = 0
for rq_path in case_requests():
    with open(rq_path) as f:
        rq = json.load(f)
    method, path = rq.get("method", "POST"), rq.get("path", "/")
    if "body_text" in rq:
        body = rq["body_text"].encode()
    elif "body" in rq:
        body = json.dumps(rq["body"], separators=(",", ":")).encode()
    else:
        body = b""
    ct = rq.get("content_type", "application/json") or ""  # null: no header
    # fuzz_api layout
    flags = 0
    if method != route_method.get(path, "POST"):
        flags |= METHOD_BITS.get(method, 3)
    if not ct.lower().startswith("application/json"):
        flags |= 8
    if path in routes:
        put("api", bytes([flags, routes[path]]) + body)
        if route_method[path] == "POST" and "body" in rq:
            put("api", bytes([1 | 4 | 32, routes[path]]) + body)  # GET ?request=
    else:
        put("api", bytes([flags, 255]) + path.encode() + b"\n" + body)
    # fuzz_server: the request on the wire
    put("server", wire(method, path, ct, body))
    # fuzz_http layout
    put("http", b"\n".join([method.encode(), path.encode(), ct.encode(), b"", body]))
    if "body" in rq and route_method.get(path) == "POST":
        q = urllib.parse.quote(body.decode(), safe="")
        put("http", b"\n".join([b"GET", (path + "?request=" + q).encode(), b"", b"*", b""]))
        put("server", wire("GET", path + "?request=" + q, "", b"", ["If-None-Match: *"]))
    n += 1

# Server-side and static paths.
extra = ["/", "/v1", "/v1/", "/v1/openapi.json", "/problems/validation-error", "/healthz",
         "/%2e%2e/etc/passwd", "/..%2f..%2fetc/passwd", "/%252e%252e/x", "//etc/passwd",
         "/.hidden", "/a\\b", "/index.html/"]
for root, dirs, files in os.walk(web_dir):
    for fn in files:
        extra.append("/" + os.path.relpath(os.path.join(root, fn), web_dir))
for p in extra:
    put("http", b"\n".join([b"GET", p.encode(), b"", b'W/"x", *', b""]))
    put("api", bytes([1, 255]) + p.encode() + b"\n")
    put("server", wire("GET", p, "", b"", ['If-None-Match: W/"x", *']))

# fuzz_server: what the HTTP layer itself handles (framing, limits, CORS,
# methods, pipelining, HTTP/1.0, garbage).
post = b'{"vectors":[[2,0,0,0],[5,3,4,0]],"velocity":{"beta":[0.6,0,0]}}'
raw = [
    wire("GET", "/healthz", "", b""),
    wire("GET", "/metrics", "", b""),
    wire("HEAD", "/", "", b""),
    wire("GET", "/", "", b"", version="HTTP/1.0"),
    wire("OPTIONS", "/v1/relativity/boost", "", b"",
         ["Origin: http://fuzz.example", "Access-Control-Request-Method: POST",
          "Access-Control-Request-Headers: content-type"]),
    wire("POST", "/v1/relativity/boost", "application/json", post,
         ["Origin: http://fuzz.example", "Authorization: Bearer x"]),
    wire("POST", "/v1/relativity/boost", "application/json", post, ["Expect: 100-continue"]),
    wire("POST", "/v1/relativity/boost", "application/json; charset=utf-8", post[:20]),
    wire("DELETE", "/v1/relativity/boost", "", b""),
    wire("GET", "/v1/openapi.json", "", b"", ["Accept-Encoding: gzip", "Connection: close"]),
    wire("GET", "/%2e%2e/%2e%2e/etc/passwd", "", b""),
    wire("GET", "/v1/nope?x=%00", "", b""),
    b"POST /v1/relativity/boost HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
    b"Transfer-Encoding: chunked\r\n\r\n10\r\n" + post[:16] + b"\r\n" +
    format(len(post) - 16, "x").encode() + b"\r\n" + post[16:] + b"\r\n0\r\n\r\n",
    wire("GET", "/healthz", "", b"") + wire("POST", "/v1/relativity/boost", "application/json", post)
    + wire("GET", "/metrics", "", b""),
    wire("POST", "/v1/relativity/boost", "application/json", b"x" * 5000),
    b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Long: " + b"a" * 6000 + b"\r\n\r\n",
    b"GET /healthz HTTP/1.1\nHost: x\n\n",
    b"GET\r\n\r\n",
    b"\x16\x03\x01\x00\xa5\x01\x00\x00\xa1\x03\x03",
]
for r in raw:
    put("server", r)
print(f"corpus: {n} cases, {len(os.listdir(os.path.join(out, 'api')))} api seeds, "
      f"{len(os.listdir(os.path.join(out, 'http')))} http seeds, "
      f"{len(os.listdir(os.path.join(out, 'server')))} server seeds")
