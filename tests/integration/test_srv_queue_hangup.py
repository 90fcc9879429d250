#!/usr/bin/python3
"""Queued jobs of clients that hang up free their queue slots at once
(Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_queue_hangup.py PATH/TO/mechd

mechd --workers 1 --queue 2 --deadline-ms 60000: a slow integration occupies
the only worker for up to a minute; two more fill the queue, so a further
request is refused 503 queue-full. Then the two queued clients close their
connections. The hang-up watcher must take their jobs out of the queue at
once (not when the worker gets to them, a minute later): /metrics shows
mechd_queue_depth 0 and a new request is accepted into the queue instead of
503, well before the running job ends. The running job's client hangs up at
the end and the worker is free again (cancellation). Figures are printed; the
bound is a generous 10 s (the watcher looks every 10 ms). Only 127.0.0.1 is
contacted; every socket has a timeout.
"""
import json
import os
import re
import socket
import sys
import tempfile
import time

from mechdtest import check, metric_value, start_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_queue_hangup.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
BOUND = 10.0  # seconds; without the removal the slots stay taken ~60 s
# rk4 with dt 1e-6 over 1e4 s: minutes of work (not a quick operation: it is queued).
SLOW = json.dumps({"particle": {"mass": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                   "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                   "t_end": 10000, "samples": 11,
                   "integrator": {"method": "rk4", "dt": 1e-6}}).encode()


def send_post(port, body):
    s = socket.create_connection(("127.0.0.1", port), timeout=30)
    s.sendall(b"POST /v1/trajectory HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
              b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n" % len(body) + body)
    return s


def read_status(s):
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = s.recv(65536)
        if not chunk:
            break
        data += chunk
    m = re.match(rb"HTTP/1\.[01] (\d{3})", data)
    return int(m.group(1)) if m else None


def metrics(port):
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    try:
        s.sendall(b"GET /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        data = b""
        while True:
            chunk = s.recv(65536)
            if not chunk:
                break
            data += chunk
        return data.decode(errors="replace")
    finally:
        s.close()


def gauge(port, name):
    return metric_value(metrics(port), name)



def main():
    errf = tempfile.TemporaryFile()
    proc, port = start_mechd(MECHD, ["--workers", "1", "--queue", "2", "--deadline-ms", "60000",
                                     "--max-steps", "1000000000000"], stderr=errf)
    socks = []
    try:
        running = send_post(port, SLOW)
        socks.append(running)
        check("a slow integration occupies the only worker",
              wait_for(lambda: gauge(port, "mechd_workers_busy") == 1, BOUND))
        queued = [send_post(port, SLOW), send_post(port, SLOW)]
        socks += queued
        check("two more fill the queue (depth 2)",
              wait_for(lambda: gauge(port, "mechd_queue_depth") == 2, BOUND))
        probe = send_post(port, SLOW)
        socks.append(probe)
        st = read_status(probe)
        check("a further request is refused 503 (queue full)", st == 503, repr(st))

        t = time.monotonic()
        for s in queued:
            s.close()
        freed = wait_for(lambda: gauge(port, "mechd_queue_depth") == 0, BOUND)
        dt = time.monotonic() - t
        print("queue depth back to 0 %.1f ms after the two queued clients hung up" % (1e3 * dt))
        check("the hung-up clients' jobs leave the queue at once (depth 0 within %g s)" % BOUND, freed,
              "depth %r" % gauge(port, "mechd_queue_depth"))
        check("... while the long job still runs", gauge(port, "mechd_workers_busy") == 1)

        fresh = send_post(port, SLOW)
        socks.append(fresh)
        fresh.settimeout(1.0)
        try:
            early = read_status(fresh)
        except socket.timeout:
            early = "waiting"
        check("a new request is accepted into the queue, not refused 503", early == "waiting", repr(early))
        check("... and waits there (queue depth 1)",
              wait_for(lambda: gauge(port, "mechd_queue_depth") == 1, BOUND))

        # Hang up the waiting one and the running one: the worker is free again.
        fresh.close()
        running.close()
        check("after the remaining clients hang up the worker is free and the queue empty",
              wait_for(lambda: gauge(port, "mechd_workers_busy") == 0
                       and gauge(port, "mechd_queue_depth") == 0, BOUND))
        def counted():
            text = metrics(port)
            m = re.search(r'(?m)^mechd_requests_total\{route="/v1/trajectory",status="503"\} (\d+)', text)
            none = re.search(r'(?m)^mechd_requests_total\{route="/v1/trajectory",status="none"\} (\d+)',
                             text)
            return (int(m.group(1)) if m else 0), (int(none.group(1)) if none else 0)

        wait_for(lambda: sum(counted()) >= 5, BOUND)
        n503, nnone = counted()
        print("trajectory requests counted: 503 %d, none %d" % (n503, nnone))
        check("every request is counted in /metrics (5 trajectories: 503 or no answer, all hung up "
              "or refused)", n503 + nnone == 5, repr((n503, nnone)))
    finally:
        for s in socks:
            s.close()
        proc.terminate()
        try:
            rc = proc.wait(20)
        except Exception:  # noqa: BLE001 - stuck: kill it
            proc.kill()
            rc = proc.wait(20)
    check("mechd exits 0 on SIGTERM", rc == 0, repr(rc))
    errf.seek(0)
    log = errf.read().decode(errors="replace")
    check("the log has one line per trajectory request (5)",
          len(re.findall(r"(?m)^mechd: \S+Z req=[0-9a-f]{32} POST /v1/trajectory ", log)) == 5, log[-600:])
    return summary()


sys.exit(main())
