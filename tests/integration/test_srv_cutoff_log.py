#!/usr/bin/python3
"""The access log tells the bytes actually sent, and that an answer was cut
off (Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_cutoff_log.py PATH/TO/mechd

A client asks for a 100,000-sample trajectory (an answer of some 15 MB),
reads about 1 MB of it and closes the connection. The server's log line for
that request must say cut_off=true, answer_bytes = the Content-Length it
announced, and bytes = what was sent: less than the answer, and at least what
the client read of the body less one SRV_TRACK_BLOCK (32 KiB, the reader's
granularity). Before, it logged bytes = the whole answer. A client that reads
the whole answer gets a line with bytes = Content-Length and no cut_off. The
same in --log-format json ("cut_off": true, "answer_bytes"). 127.0.0.1 only;
every socket has a timeout.
"""
import json
import os
import re
import socket
import sys
import tempfile
import time

from mechdtest import check, start_mechd, stop_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_cutoff_log.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
BLOCK = 32 * 1024
BIG = json.dumps({"particle": {"mass": 1, "position": [0, 0, 100], "velocity": [1, 0, 0]},
                  "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                  "t_end": 4, "samples": 100000}).encode()


def ask(port, rid, read_limit=None):
    """POST BIG with X-Request-Id rid; read the head and up to read_limit body
    bytes (all when None), then close. Returns (content_length, body bytes read)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=60)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 65536)
    s.sendall(b"POST /v1/trajectory HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
              b"X-Request-Id: " + rid.encode() + b"\r\nContent-Type: application/json\r\n"
              b"Content-Length: %d\r\n\r\n" % len(BIG) + BIG)
    buf = b""
    while b"\r\n\r\n" not in buf:
        c = s.recv(65536)
        if not c:
            break
        buf += c
    head, _, body = buf.partition(b"\r\n\r\n")
    m = re.search(rb"(?i)content-length: *(\d+)", head)
    total = int(m.group(1)) if m else -1
    got = len(body)
    limit = total if read_limit is None else read_limit
    while got < limit:
        c = s.recv(65536)
        if not c:
            break
        got += len(c)
    s.close()
    return total, got


def log_line(path, rid):
    with open(path, "rb") as f:
        for ln in f.read().decode("utf-8", "replace").splitlines():
            if rid in ln:
                return ln
    return None


def run(json_log):
    fmt = "json" if json_log else "text"
    with tempfile.NamedTemporaryFile(prefix="mechd-cutoff-", suffix=".log") as logf:
        proc, port = start_mechd(MECHD, ["--log-format", fmt], stderr=logf)
        try:
            rid = "cutoff-%s-%d" % (fmt, os.getpid())
            total, got = ask(port, rid, read_limit=1000000)
            check("%s: the answer is large (%d bytes) and the client read ~1 MB (%d)"
                  % (fmt, total, got), total > 5000000 and 900000 <= got < total)
            wait_for(lambda: log_line(logf.name, rid) is not None, 20)
            ln = log_line(logf.name, rid)
            print("  log: %s" % ln)
            if json_log:
                d = json.loads(ln) if ln else {}
                sent, cut, whole = d.get("bytes"), d.get("cut_off"), d.get("answer_bytes")
            else:
                m = re.search(r" (\d+) \d+us bytes=(\d+)( cut_off=true answer_bytes=(\d+))?", ln or "")
                sent = int(m.group(2)) if m else None
                cut = bool(m and m.group(3))
                whole = int(m.group(4)) if m and m.group(4) else None
            check("%s: cut_off with answer_bytes = Content-Length" % fmt,
                  cut is True and whole == total, ln)
            check("%s: bytes = what was sent: < the answer, >= what the client read - 32 KiB"
                  % fmt, sent is not None and got - BLOCK <= sent < total, (sent, got, total))

            rid2 = "whole-%s-%d" % (fmt, os.getpid())
            total2, got2 = ask(port, rid2)
            wait_for(lambda: log_line(logf.name, rid2) is not None, 20)
            ln = log_line(logf.name, rid2) or ""
            if json_log:
                d = json.loads(ln) if ln else {}
                ok = d.get("bytes") == total2 and d.get("cut_off") is False
            else:
                ok = ("bytes=%d " % total2) in ln and "cut_off" not in ln
            check("%s: an answer read to its end: bytes = Content-Length, not cut off" % fmt,
                  got2 == total2 and ok, ln[:300])
        finally:
            stop_mechd(proc)


def main():
    run(json_log=False)
    run(json_log=True)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
