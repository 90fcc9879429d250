#!/usr/bin/python3
"""Keep-alive clients that all send at once are all answered (Python 3
stdlib only).

Usage: /usr/bin/python3 test_io_burst.py PATH/TO/mechd

libmicrohttpd's internal-thread epoll loop calls epoll_wait again, with its
blocking timeout, whenever one call returned exactly 128 events (MAX_EVENTS),
before it processes the 128 it has: 128 keep-alive connections of one I/O
thread that send a request together, then wait for the answers, were
answered after the 30 s idle timeout, or when something unrelated happened
(the load scenario cheap-requests saw whole 5 s rounds without an answer at
256 connections on 2 I/O threads). mechd runs each daemon in its own loop
(server/io_loop.c), which never blocks holding collected events. Checked,
with --io-threads 1 (so one thread sees every event): 127, 128, 129 and 256
keep-alive connections, each first answered once, then sending a boost all
together, three rounds each: every connection gets its 200 with the right
numbers within 10 s (a stall lasts 30 s); with --io-threads 2, 256
connections the same; then SIGTERM with the connections open exits 0.
Only 127.0.0.1 is contacted; every socket has a timeout.
"""
import json
import math
import os
import select
import socket
import subprocess
import sys
import time

from mechdtest import check, start_mechd, stop_mechd, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_io_burst.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])

# Boost of the event (ct, x, y, z) = (1, 0, 0, 0) by beta = 0.6 along x:
# gamma = 1/sqrt(1 - 0.36) = 1.25; ct' = gamma (ct - beta x) = 1.25,
# x' = gamma (x - beta ct) = -0.75.
BODY = b'{"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}'
REQ = (b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
       b"Content-Length: %d\r\n\r\n%s" % (len(BODY), BODY))
WAIT_S = 10.0


class Reader:
    """One keep-alive connection's answers, parsed as bytes arrive."""

    def __init__(self, s):
        self.s, self.buf = s, b""

    def poll(self):
        """Read what is there; return (status line, body) once a whole answer
        has arrived, else None. Raises on a closed connection."""
        d = self.s.recv(65536)
        if not d:
            raise ConnectionError("closed by mechd")
        self.buf += d
        if b"\r\n\r\n" not in self.buf:
            return None
        head, rest = self.buf.split(b"\r\n\r\n", 1)
        lines = head.split(b"\r\n")
        cl = [int(l.split(b":", 1)[1]) for l in lines if l.lower().startswith(b"content-length:")]
        if not cl or len(rest) < cl[0]:
            return None
        self.buf = rest[cl[0]:]
        return lines[0], rest[:cl[0]]


def boosted_right(body):
    try:
        v = json.loads(body)["vectors"]
    except (ValueError, KeyError, TypeError):
        return False
    return (math.isclose(v[0], 1.25, rel_tol=1e-15) and math.isclose(v[1], -0.75, rel_tol=1e-15)
            and v[2] == 0 and v[3] == 0)


def answered_all(readers, deadline):
    """Wait for one answer on every reader; return how many were 200 with the
    boosted event [1.25, -0.75, 0, 0]."""
    pending = {r.s: r for r in readers}
    good = 0
    while pending and time.monotonic() < deadline:
        ready, _, _ = select.select(list(pending), [], [], 0.1)
        for s in ready:
            try:
                a = pending[s].poll()
            except OSError:
                del pending[s]
                continue
            if a is not None:
                del pending[s]
                status, body = a
                good += status.startswith(b"HTTP/1.1 200") and boosted_right(body)
    return good


def burst(port, n, rounds, label):
    socks = [socket.create_connection(("127.0.0.1", port), timeout=WAIT_S) for _ in range(n)]
    readers = [Reader(s) for s in socks]
    for s in socks:  # one answer each first: every connection accepted and idle
        s.sendall(REQ)
    ok = answered_all(readers, time.monotonic() + WAIT_S)
    check("%s: %d connections each answered once" % (label, n), ok == n, "%d of %d" % (ok, n))
    time.sleep(0.2)  # all idle, waiting for a request
    for k in range(rounds):
        t0 = time.monotonic()
        for s in socks:
            s.sendall(REQ)
        ok = answered_all(readers, t0 + WAIT_S)
        check("%s: round %d, %d connections sending together all answered" % (label, k + 1, n),
              ok == n, "%d of %d within %.0f s" % (ok, n, WAIT_S))
    return socks


def main():
    for threads, counts in ((1, (127, 128, 129, 256)), (2, (256,))):
        proc, port = start_mechd(MECHD, ["--io-threads", str(threads)], stderr=subprocess.DEVNULL)
        opened = []
        try:
            for n in counts:
                socks = burst(port, n, 3, "--io-threads %d" % threads)
                if n != counts[-1]:
                    for s in socks:
                        s.close()
                else:
                    opened = socks
        finally:
            rc = stop_mechd(proc)  # with the last burst's connections still open
            for s in opened:
                s.close()
        check("--io-threads %d: SIGTERM with %d connections open exits 0" % (threads, len(opened)),
              rc == 0, "exit status %r" % rc)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
