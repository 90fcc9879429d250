#!/usr/bin/python3
"""test_catalog_host.py — GET /v1's curl lines name the host and port the catalog
was asked on (the Host header), so a line copied from the catalog works as it is.

Usage: /usr/bin/python3 test_catalog_host.py PATH/TO/mechd
Against a real mechd on a free port: the catalog asked on 127.0.0.1:PORT holds
curl lines for that port and none for 127.0.0.1:8080, and running one of them (the
boost at beta = 0.6) with sh gets gamma = 1/sqrt(1 - 0.36) = 1.25; asked with Host: grader.example.edu:9000 the lines say that host; a Host that
is not a host name or address keeps the default text; each variant has its own
ETag, answers If-None-Match with 304 and says Vary: Host. Prints "N passed, M
failed"; exits 1 on failure.
"""
import http.client
import json
import re
import subprocess
import sys

from mechdtest import check, start_mechd, stop_mechd, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_catalog_host.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = sys.argv[1]


def get(port, host, inm=None):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    c.putrequest("GET", "/v1", skip_host=True, skip_accept_encoding=True)
    c.putheader("Host", host)
    if inm:
        c.putheader("If-None-Match", inm)
    c.endheaders()
    r = c.getresponse()
    body = r.read()
    headers = {k.lower(): v for k, v in r.getheaders()}
    c.close()
    return r.status, headers, body


proc, port = start_mechd(MECHD)
try:
    here = "127.0.0.1:%d" % port
    st, h, body = get(port, here)
    cat = json.loads(body)
    lines = [o["curl"] for o in cat["operations"] if o.get("curl")]
    check("GET /v1 asked on %s: every curl line names it" % here,
          st == 200 and lines and all(("http://%s/v1/" % here) in ln for ln in lines), lines[:2])
    check("... and none names 127.0.0.1:8080", b"127.0.0.1:8080" not in body)
    st0, h0, _ = get(port, "127.0.0.1:8080")
    check("... with its own ETag and Vary: Host", h.get("etag") != h0.get("etag")
          and "Host" in h.get("vary", ""), (h, h0))
    st2, h2, _ = get(port, here, h.get("etag"))
    check("If-None-Match with that ETag: 304", st2 == 304, (st2, h2))
    boost = [o["curl"] for o in cat["operations"] if o["path"] == "/v1/relativity/boost"][0]
    out = subprocess.run(["sh", "-c", boost], capture_output=True, text=True, timeout=120)
    try:
        gamma = json.loads(out.stdout)["gamma"]
    except (ValueError, KeyError):
        gamma = None
    # The catalog's example boost: beta = 0.6, gamma = 1/sqrt(1 - 0.36) = 1.25.
    check("the catalog's curl line for /v1/relativity/boost runs as copied: gamma 1.25",
          gamma is not None and abs(gamma - 1.25) < 1e-15, repr(out.stdout[:200]) + out.stderr[-200:])
    st, h3, body = get(port, "grader.example.edu:9000")
    check("Host: grader.example.edu:9000 -> curl lines for http://grader.example.edu:9000",
          st == 200 and b"curl -s http://grader.example.edu:9000/v1/rigid/inertia" in body
          and h3.get("etag") != h.get("etag"), body[:0])
    st, h4, body = get(port, "evil host'; rm -rf /")
    check("a Host that is no host name keeps the default lines (127.0.0.1:8080)",
          st == 200 and b"curl -s http://127.0.0.1:8080/v1/rigid/inertia" in body
          and not re.search(rb"evil", body), h4)
    st, h5, body = get(port, "127.0.0.1:8080")
    check("asked on 127.0.0.1:8080: the default text", st == 200 and b"http://127.0.0.1:8080/v1/" in body,
          h5)
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    c.putrequest("GET", "/v1", skip_host=True, skip_accept_encoding=True)
    c.putheader("Host", here)
    c.putheader("Accept-Encoding", "gzip")
    c.endheaders()
    r = c.getresponse()
    gz = r.read()
    enc = r.getheader("Content-Encoding")
    c.close()
    import gzip
    check("a host's catalog is served gzip too (the same text)",
          enc == "gzip" and gzip.decompress(gz) == get(port, here)[2], enc)
finally:
    stop_mechd(proc)

sys.exit(summary())
