#!/usr/bin/python3
"""The answer-memory budget bounds what slow readers hold (Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_answer_memory.py PATH/TO/mechd

A slow reader keeps its whole answer in the server's memory until the last
byte is sent: 30 readers of 58 MB answers held 1.79 GB. With
--max-answer-memory 24 MiB and answers of about 5.6 MB (a 60,000-sample
trajectory), checked here:

- one answer read in full first (the server learns the route's answer size),
  then 6 clients ask for one each and never read past the head: the answers
  that fit are computed and held (200), the others are refused 503
  /problems/answer-memory-full with Retry-After after waiting up to 1 s,
  before anything is computed (at most 4 fit: 24 MiB / 5.6 MB);
- mechd_answer_memory_bytes never passes mechd_answer_memory_max_bytes while
  they hold it, and mechd_answer_memory_refused_total counts the refusals;
- /healthz is answered 200 meanwhile;
- when the readers close, the memory is given back (the gauge returns to 0)
  and the same request is served again;
- a request predicted larger than the whole budget runs alone (4 MiB budget,
  the same 5.6 MB answer): 200.
The server's resident memory is printed. 127.0.0.1 only; every socket has a
timeout; the whole test takes a few seconds of compute.
"""
import json
import os
import re
import socket
import subprocess
import sys
import time

from mechdtest import check, metric_value, start_mechd, stop_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_answer_memory.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
BUDGET = 24 << 20
READERS = 6
BIG = json.dumps({"particle": {"mass": 1, "position": [0, 0, 100], "velocity": [1, 0, 0]},
                  "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                  "t_end": 4, "samples": 60000}).encode()
REQ = (b"POST /v1/trajectory HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
       b"Content-Length: %d\r\n\r\n" % len(BIG) + BIG)


def read_head(s):
    """Read up to the end of the head; (status, head text, rest of the bytes read)."""
    buf = b""
    while b"\r\n\r\n" not in buf:
        c = s.recv(4096)
        if not c:
            break
        buf += c
    head, _, rest = buf.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.1 (\d+)", head)
    return (int(m.group(1)) if m else None), head.decode("latin-1"), rest


def full(port):
    """Send REQ, read the whole answer; (status, body length)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=60)
    s.sendall(REQ)
    st, head, body = read_head(s)
    m = re.search(r"(?i)content-length: *(\d+)", head)
    n = int(m.group(1)) if m else 0
    while len(body) < n:
        c = s.recv(1 << 20)
        if not c:
            break
        body += c
    s.close()
    return st, len(body)


def get(port, path):
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    s.sendall(b"GET " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
    data = b""
    while True:
        c = s.recv(65536)
        if not c:
            break
        data += c
    s.close()
    head, _, body = data.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.1 (\d+)", head)
    return (int(m.group(1)) if m else None), body


def metrics(port):
    return get(port, "/metrics")[1].decode()


def main():
    proc, port = start_mechd(MECHD, ["--max-answer-memory", str(BUDGET), "--workers", "2"],
                             stderr=subprocess.DEVNULL)
    readers = []
    try:
        st, n = full(port)
        check("warm-up answer read in full: 200, %d bytes" % n, st == 200 and n > 5000000, (st, n))
        for _ in range(READERS):
            s = socket.create_connection(("127.0.0.1", port), timeout=30)
            s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
            s.sendall(REQ)
            readers.append(s)
        statuses, heads, max_seen = [], [], 0
        for s in readers:
            st, head, rest = read_head(s)
            statuses.append(st)
            heads.append((head, rest))
            text = metrics(port)
            max_seen = max(max_seen, metric_value(text, "mechd_answer_memory_bytes") or 0)
        held = statuses.count(200)
        refused = [i for i, st in enumerate(statuses) if st == 503]
        print("  statuses of the %d slow readers: %s" % (READERS, statuses))
        check("some answers are held (200) and the rest refused (503), none else",
              held >= 1 and refused and held + len(refused) == READERS and held <= 4, statuses)
        ok = True
        for i in refused:
            head, rest = heads[i]
            doc = {}
            try:
                doc = json.loads(rest.decode() or "{}")
            except ValueError:
                pass
            ok = ok and re.search(r"(?im)^retry-after: *\d+", head) is not None \
                and doc.get("type") == "/problems/answer-memory-full" and doc.get("status") == 503
        check("a refusal is 503 answer-memory-full with Retry-After", ok, heads[refused[0]] if refused else None)
        text = metrics(port)
        used = metric_value(text, "mechd_answer_memory_bytes")
        cap = metric_value(text, "mechd_answer_memory_max_bytes")
        peak = metric_value(text, "mechd_answer_memory_peak_bytes")
        nref = metric_value(text, "mechd_answer_memory_refused_total")
        rss = metric_value(text, "process_resident_memory_bytes")
        print("  held %.1f MB of %.1f MB (peak %.1f MB), resident %.1f MB"
              % (used / 1e6, cap / 1e6, peak / 1e6, (rss or 0) / 1e6))
        check("budget = --max-answer-memory", cap == BUDGET, cap)
        check("answer memory never passes the budget (now, seen, peak)",
              0 < used <= cap and max_seen <= cap and peak <= cap, (used, max_seen, peak, cap))
        check("refusals counted", nref == len(refused), (nref, refused))
        st, body = get(port, "/healthz")
        check("/healthz answered while the readers hold the memory", st == 200, st)
        for s in readers:
            s.close()
        readers = []
        check("memory given back when the readers close",
              wait_for(lambda: metric_value(metrics(port), "mechd_answer_memory_bytes") == 0, 15))
        st, n = full(port)
        check("served again afterwards: 200", st == 200 and n > 5000000, (st, n))
    finally:
        for s in readers:
            s.close()
        stop_mechd(proc)

    proc, port = start_mechd(MECHD, ["--max-answer-memory", str(4 << 20)], stderr=subprocess.DEVNULL)
    try:
        st, n = full(port)
        check("an answer larger than the whole budget runs alone: 200 (%d bytes)" % n,
              st == 200 and n > (4 << 20), (st, n))
    finally:
        stop_mechd(proc)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
