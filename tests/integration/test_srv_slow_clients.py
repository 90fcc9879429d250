#!/usr/bin/python3
"""Slow (trickling) clients are cut off by --request-timeout-ms (Python 3
stdlib only).

Usage: /usr/bin/python3 test_srv_slow_clients.py PATH/TO/mechd

libmicrohttpd's own connection timeout counts idle time only, so a client that
sends one byte every 200 ms is never idle and would hold its connection
forever. mechd --request-timeout-ms 1500 closes a connection that has not
delivered one whole request (headers and body) within 1.5 s of connecting (or
of its previous answer). Checked here:

- a client trickling its request headers, and one trickling its body, are
  closed by the server: not before the limit (closing earlier would be a bug),
  and within a generous bound (the watcher looks every 10 ms);
- while they trickle, a normal client is answered 200 at once;
- a request sent in pieces that together take less than the limit is served;
- a request whose computation outlasts the limit is not cut (the limit counts
  receiving only): it gets its answer;
- keep-alive: a second request on the same connection is served; a connection
  left idle after its answer is closed after the limit (documented behaviour);
- /metrics counts mechd_request_timeouts_total and the log says why.
Figures are printed; the bounds are generous. Only 127.0.0.1 is contacted;
every socket has a timeout.
"""
import json
import os
import re
import socket
import sys
import tempfile
import threading
import time

from mechdtest import check, metric_value, start_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_slow_clients.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
LIMIT = 1.5  # seconds: --request-timeout-ms 1500
BOUND = 15.0  # seconds: a generous upper bound for "closed by the server"
FAST = json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}).encode()
# rk4 with dt 1e-6 over 1e4 s: minutes of work, stopped by --deadline-ms 2500.
SLOW = json.dumps({"particle": {"mass": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                   "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                   "t_end": 10000, "samples": 11,
                   "integrator": {"method": "rk4", "dt": 1e-6}}).encode()


def request_bytes(path, body, keep_alive=False):
    return (b"POST " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n"
            + (b"" if keep_alive else b"Connection: close\r\n")
            + b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n" % len(body) + body)


def read_answer(s):
    """Read one HTTP answer (headers + Content-Length body); return (status, body)
    or (None, b"") if the connection closed first."""
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = s.recv(65536)
        if not chunk:
            return None, b""
        data += chunk
    head, _, rest = data.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.[01] (\d{3})", head)
    n = re.search(rb"(?i)\r\ncontent-length: *(\d+)", head)
    need = int(n.group(1)) if n else 0
    while len(rest) < need:
        chunk = s.recv(65536)
        if not chunk:
            break
        rest += chunk
    return (int(m.group(1)) if m else None), rest


def post(port, path, body, timeout=30):
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    try:
        s.sendall(request_bytes(path, body))
        return read_answer(s)
    finally:
        s.close()


def get(port, path):
    s = socket.create_connection(("127.0.0.1", port), timeout=30)
    try:
        s.sendall(b"GET " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        return read_answer(s)
    finally:
        s.close()


def metric(port, name):
    _, text = get(port, "/metrics")
    return metric_value(text, name)



class Trickler(threading.Thread):
    """Connects, sends `head` at once, then `tail` one byte every `period` s
    until the server closes the connection; records when (seconds after the
    moment just before connecting), or None if it stays open for BOUND s."""

    def __init__(self, port, head, tail, period=0.2):
        super().__init__()
        self.port, self.head, self.tail, self.period = port, head, tail, period
        self.closed_after = None
        self.error = None

    def run(self):
        t0 = time.monotonic()
        try:
            s = socket.create_connection(("127.0.0.1", self.port), timeout=BOUND)
        except OSError as e:
            self.error = repr(e)
            return
        try:
            s.settimeout(self.period)
            s.sendall(self.head)
            k = 0
            while time.monotonic() - t0 < BOUND:
                try:
                    if not s.recv(65536):  # EOF: the server closed it
                        self.closed_after = time.monotonic() - t0
                        return
                except socket.timeout:
                    pass
                except OSError:  # reset: closed too
                    self.closed_after = time.monotonic() - t0
                    return
                try:
                    s.sendall(self.tail[k % len(self.tail):k % len(self.tail) + 1])
                except OSError:
                    self.closed_after = time.monotonic() - t0
                    return
                k += 1
        finally:
            s.close()


def main():
    errf = tempfile.TemporaryFile()
    proc, port = start_mechd(MECHD, ["--request-timeout-ms", "1500", "--workers", "1",
                                     "--deadline-ms", "2500", "--max-steps", "1000000000000"],
                             stderr=errf)
    try:
        # 1. tricklers: one in the headers, one in the body; a normal client meanwhile.
        header_trickler = Trickler(port, b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                                   b"X-Slow: ", b"a" * 4000)
        body = FAST + b" " * 200
        body_trickler = Trickler(port, b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                                 b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n" % len(body),
                                 body)
        header_trickler.start()
        body_trickler.start()
        time.sleep(0.5)
        t = time.monotonic()
        st, _ = post(port, "/v1/relativity/boost", FAST, timeout=10)
        dt = time.monotonic() - t
        print("normal client while two connections trickle: %d in %.1f ms" % (st or 0, 1e3 * dt))
        check("a normal client is answered 200 while others trickle", st == 200, repr(st))
        check("... at once (under 5 s)", dt < 5.0, "%.3f s" % dt)
        header_trickler.join(BOUND + 5)
        body_trickler.join(BOUND + 5)
        for name, tr in (("headers", header_trickler), ("body", body_trickler)):
            print("client trickling its %s: closed by the server after %s s" %
                  (name, "%.2f" % tr.closed_after if tr.closed_after is not None else "never"))
            check("a client trickling its %s is closed by the server" % name,
                  tr.closed_after is not None and tr.error is None, repr((tr.closed_after, tr.error)))
            check("... not before the %.1f s limit" % LIMIT,
                  tr.closed_after is not None and tr.closed_after >= LIMIT - 0.05, repr(tr.closed_after))

        # 2. a request in pieces that together take less than the limit is served.
        s = socket.create_connection(("127.0.0.1", port), timeout=10)
        data = request_bytes("/v1/relativity/boost", FAST)
        third = len(data) // 3
        for piece in (data[:third], data[third:2 * third], data[2 * third:]):
            s.sendall(piece)
            time.sleep(0.25)
        st, _ = read_answer(s)
        s.close()
        check("a request sent in pieces within the limit is answered 200", st == 200, repr(st))

        # 3. a computation longer than the limit is not cut: the limit counts receiving only.
        t = time.monotonic()
        st, ans = post(port, "/v1/trajectory", SLOW, timeout=60)
        dt = time.monotonic() - t
        print("a 2.5 s-deadline integration answered %s after %.2f s" % (st, dt))
        check("a computation outlasting the receive limit still gets its answer (422 budget)",
              st == 422 and b"compute-budget-exceeded" in ans, repr((st, ans[:120])))
        check("... after more than the limit", dt > LIMIT, "%.2f s" % dt)

        # 4. keep-alive: two requests on one connection, then idle past the limit.
        s = socket.create_connection(("127.0.0.1", port), timeout=BOUND)
        s.sendall(request_bytes("/v1/relativity/boost", FAST, keep_alive=True))
        st1, _ = read_answer(s)
        time.sleep(0.3)
        s.sendall(request_bytes("/v1/relativity/boost", FAST, keep_alive=True))
        st2, _ = read_answer(s)
        check("keep-alive: two requests on one connection are answered", (st1, st2) == (200, 200),
              repr((st1, st2)))
        t = time.monotonic()
        try:
            eof = s.recv(1) == b""
        except OSError:
            eof = True
        dt = time.monotonic() - t
        s.close()
        print("keep-alive connection left idle: closed after %.2f s" % dt)
        check("keep-alive: a connection left idle is closed after the limit",
              eof and LIMIT - 0.5 <= dt < BOUND, "eof=%r after %.2f s" % (eof, dt))

        wait_for(lambda: (metric(port, "mechd_request_timeouts_total") or 0) >= 3, 5)
        n = metric(port, "mechd_request_timeouts_total")
        check("/metrics counts the timed-out connections (>= 3)", n is not None and n >= 3, repr(n))
        st, _ = get(port, "/healthz")
        check("/healthz still answers 200", st == 200, repr(st))
    finally:
        proc.terminate()
        try:
            rc = proc.wait(20)
        except Exception:  # noqa: BLE001 - stuck: kill it
            proc.kill()
            rc = proc.wait(20)
    check("mechd exits 0 on SIGTERM", rc == 0, repr(rc))
    errf.seek(0)
    log = errf.read().decode(errors="replace")
    check("the log says why connections were closed",
          "sent no whole request within 1500 ms" in log, log[-400:])
    return summary()


sys.exit(main())
