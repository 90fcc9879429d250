#!/usr/bin/python3
"""Fair queues: cheap work does not wait behind long jobs, and long jobs keep
their share under a flood of cheap work (Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_fair_queues.py PATH/TO/mechd

Checked here, by order of events and by thread attributes, never by timing:
- mechd --workers 1 --inline-max-us 0 (every request goes to the pool): a
  long integration occupies the only worker (rk4 at dt 1e-6, stopped by
  --deadline-ms 3000); a boost sent after it is answered 200 while the long
  job is still running (the express worker takes short jobs), not after it
  (before, the boost waited behind it in the one queue);
- a second long job queued behind the first is answered at its own deadline
  (422), not left waiting behind the 30 boosts sent meanwhile;
- by default the workers and the express worker run at the I/O threads' own
  nice value (equal CPU weight: a long job keeps a fair share of the CPU
  under a flood of cheap requests answered on the I/O threads), as
  SCHED_BATCH (a waking worker does not preempt an I/O thread); read from
  /proc on Linux.
The wall time of a long job under a flood of cheap requests is printed, not
asserted. 127.0.0.1 only; every socket has a timeout.
"""
import json
import os
import re
import socket
import subprocess
import sys
import threading
import time

from mechdtest import check, start_mechd, stop_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_fair_queues.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
BOOST = json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}).encode()
SLOW = json.dumps({"particle": {"mass": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                   "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                   "t_end": 10000, "samples": 11,
                   "integrator": {"method": "rk4", "dt": 1e-6}}).encode()


def request(path, body):
    return (b"POST " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
            b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n" % len(body) + body)


def call(port, path, body, timeout=60):
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    s.sendall(request(path, body))
    data = b""
    while True:
        c = s.recv(65536)
        if not c:
            break
        data += c
    s.close()
    m = re.match(rb"HTTP/1\.1 (\d+)", data)
    return int(m.group(1)) if m else None


class Async:
    """One request on its own thread; .status and .done_at once answered."""

    def __init__(self, port, path, body):
        self.status, self.done_at = None, None
        self.t = threading.Thread(target=self.run, args=(port, path, body))
        self.t.start()

    def run(self, port, path, body):
        try:
            self.status = call(port, path, body)
        finally:
            self.done_at = time.monotonic()


def busy(port):
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    s.sendall(b"GET /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
    data = b""
    while True:
        c = s.recv(65536)
        if not c:
            break
        data += c
    s.close()
    m = re.search(rb"(?m)^mechd_workers_busy (\d+)", data)
    return int(m.group(1)) if m else None


def test_express(port):
    long1 = Async(port, "/v1/trajectory", SLOW)
    check("the long job occupies the worker", wait_for(lambda: busy(port) == 1, 10))
    long2 = Async(port, "/v1/trajectory", SLOW)
    time.sleep(0.2)
    st = call(port, "/v1/relativity/boost", BOOST)
    running = long1.done_at is None
    check("a boost sent behind a long job is answered 200 while the long job still runs",
          st == 200 and running, (st, long1.status))
    sts = [call(port, "/v1/relativity/boost", BOOST) for _ in range(30)]
    check("30 more boosts answered 200 meanwhile", sts == [200] * 30, sts)
    long1.t.join(60)
    long2.t.join(60)
    check("the first long job ends at its deadline (422)", long1.status == 422, long1.status)
    check("the second long job, queued behind it under the boosts, is answered at its "
          "deadline (422), not left waiting or cancelled", long2.status == 422, long2.status)


def test_priorities(proc):
    if not os.path.isdir("/proc/%d/task" % proc.pid):
        return

    def threads():
        out = []
        for tid in os.listdir("/proc/%d/task" % proc.pid):
            with open("/proc/%d/task/%s/stat" % (proc.pid, tid)) as f:
                fields = f.read().rsplit(")", 1)[1].split()
            with open("/proc/%d/task/%s/comm" % (proc.pid, tid)) as f:
                out.append((f.read().strip(), int(fields[16]), int(fields[38])))
        return out

    def workers():
        return [(n, pol) for name, n, pol in threads() if name in ("mechd-worker", "mechd-express")]

    wait_for(lambda: len(workers()) == 2 and all(pol == 3 for _, pol in workers()), 5)
    io = [(n, pol) for name, n, pol in threads() if name == "mechd-io"]
    w = workers()
    check("by default the worker and the express worker run at the I/O threads' nice, SCHED_BATCH",
          len(w) == 2 and io and all(n == io[0][0] and pol == 3 for n, pol in w), (w, io))


def flood_figure():
    """Print the wall and CPU time of a long job under a flood of cheap requests."""
    proc, port = start_mechd(MECHD, ["--workers", "1"], stderr=subprocess.DEVNULL)
    stop = [False]

    def flood():
        while not stop[0]:
            try:
                call(port, "/v1/relativity/boost", BOOST, timeout=10)
            except OSError:
                pass

    try:
        job = json.dumps({"particle": {"mass": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                          "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                          "t_end": 0.1, "samples": 11,
                          "integrator": {"method": "rk4", "dt": 1e-6}}).encode()
        t0 = time.monotonic()
        call(port, "/v1/trajectory", job)
        alone = time.monotonic() - t0
        ts = [threading.Thread(target=flood) for _ in range(3)]
        for t in ts:
            t.start()
        time.sleep(0.3)
        t0 = time.monotonic()
        st = call(port, "/v1/trajectory", job)
        loaded = time.monotonic() - t0
        stop[0] = True
        for t in ts:
            t.join(20)
        print("  a long job: %.2f s alone, %.2f s under 3 flooding clients (status %s)"
              % (alone, loaded, st))
    finally:
        stop[0] = True
        stop_mechd(proc)


def main():
    proc, port = start_mechd(MECHD, ["--workers", "1", "--queue", "8", "--inline-max-us", "0",
                                     "--deadline-ms", "3000", "--max-steps", "1000000000000"],
                             stderr=subprocess.DEVNULL)
    try:
        test_priorities(proc)
        test_express(port)
    finally:
        stop_mechd(proc)
    flood_figure()
    return summary()


if __name__ == "__main__":
    sys.exit(main())
