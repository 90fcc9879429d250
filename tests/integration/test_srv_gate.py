#!/usr/bin/python3
"""Integrations answered where their predicted cost says (Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_gate.py PATH/TO/mechd

/v1/trajectory predicts its cost (its chooser's predicted CPU) before it
integrates; the server starts it on the I/O thread and finishes it there when
the prediction is within --inline-max-us, else it goes to the pool. Checked
here by where the answer comes from, never by timing: mechd --workers 1
--queue 1 --inline-max-us 1000 (the example trajectory costs about 0.1 ms, the
default limit's size), the worker busy with a long job and the one queue slot taken by a
second, so that anything sent to the pool is refused 503 queue-full:
- a short trajectory (the catalog's example, the chooser predicts ~0.1 ms) is
  answered 200: computed on the I/O thread (before, every integration went to
  the pool and was refused);
- the same request padded with whitespace to 12 KB is answered 200 too: the
  decision is the predicted cost, not the body's size;
- a trajectory whose prediction is long (a Kepler orbit integrated over 1000
  periods at "precise", ~20 ms predicted) is sent to the pool: 503, though
  its body is small; so is one whose method and step the client gave (no
  prediction);
- --inline-max-us 0: nothing is started on the I/O thread, the short
  trajectory is refused 503 like everything else;
- with the pool free, the predicted-long trajectory and the short one are
  answered 200 with the same bytes as `mechd eval` (the answer does not depend
  on where it was computed; the measured cost dropped).
127.0.0.1 only; every socket has a timeout.
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
    sys.stderr.write("usage: test_srv_gate.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
SLOW = json.dumps({"particle": {"mass": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                   "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                   "t_end": 10000, "samples": 11,
                   "integrator": {"method": "rk4", "dt": 1e-6}}).encode()
KEPLER = json.dumps({"particle": {"mass": 1, "position": [1, 0, 0], "velocity": [0, 1.2, 0]},
                     "forces": [{"type": "central_gravity", "gm": 1}],
                     "t_end": 6283, "samples": 11,
                     "integrator": {"accuracy": "precise", "closed_form": False}}).encode()
GIVEN = json.dumps({"particle": {"mass": 1, "position": [0, 0, 100], "velocity": [0, 0, 0]},
                    "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                    "t_end": 1, "samples": 11,
                    "integrator": {"method": "rk4", "dt": 0.01}}).encode()


def exchange(port, method, path, body=b"", timeout=60):
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    head = (method.encode() + b" " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n"
            b"Connection: close\r\n")
    if body:
        head += b"Content-Type: application/json\r\nContent-Length: %d\r\n" % len(body)
    s.sendall(head + b"\r\n" + body)
    data = b""
    while True:
        c = s.recv(65536)
        if not c:
            break
        data += c
    s.close()
    m = re.match(rb"HTTP/1\.1 (\d+)", data)
    return (int(m.group(1)) if m else None), data.partition(b"\r\n\r\n")[2]


def post(port, body):
    return exchange(port, "POST", "/v1/trajectory", body)


def metric(port, name):
    _, text = exchange(port, "GET", "/metrics", timeout=10)
    m = re.search(rb"(?m)^" + re.escape(name.encode()) + rb" (\S+)$", text)
    return float(m.group(1)) if m else None


class Async:
    """One request on its own thread; .status once answered."""

    def __init__(self, port, body):
        self.status = None
        self.t = threading.Thread(target=self.run, args=(port, body))
        self.t.start()

    def run(self, port, body):
        self.status = post(port, body)[0]


def example(port):
    _, text = exchange(port, "GET", "/v1", timeout=10)
    cat = json.loads(text)
    op = next(o for o in cat["operations"] if o["path"] == "/v1/trajectory")
    return json.dumps(op["example"]).encode()


def fill_pool(port):
    """The worker on one long job, the one queue slot on another."""
    long1 = Async(port, SLOW)
    check("the first long job occupies the worker",
          wait_for(lambda: metric(port, "mechd_workers_busy") == 1, 10))
    long2 = Async(port, SLOW)
    check("the second long job waits in the queue",
          wait_for(lambda: metric(port, "mechd_queue_depth") == 1, 10))
    return long1, long2


def test_gate(port):
    short = example(port)
    # The route's ratio of measured to predicted CPU is learned from its
    # first runs (on the pool or here); all are answered.
    sts = [post(port, short)[0] for _ in range(8)]
    check("8 short trajectories answered 200 on a free server", sts == [200] * 8, sts)
    long1, long2 = fill_pool(port)
    st, body = post(port, short)
    check("a short trajectory is answered 200 while the pool is full (computed on the I/O "
          "thread)", st == 200, (st, body[:300]))
    padded = short[:-1] + b" " * (12000 - len(short)) + b"}"
    st, body = post(port, padded)
    check("the same request padded to %d bytes: 200 (the predicted cost decides, not the size)"
          % len(padded), st == 200, (st, body[:300]))
    st, body = post(port, KEPLER)
    check("a trajectory predicted long (Kepler, 1000 periods, integrated) goes to the pool: "
          "503 queue-full", st == 503 and b"queue-full" in body, (st, body[:300]))
    st, body = post(port, GIVEN)
    check("a trajectory without a prediction (method and dt given) goes to the pool: 503",
          st == 503, (st, body[:300]))
    long1.t.join(60)
    long2.t.join(60)
    check("the long jobs end at their deadline (422)", (long1.status, long2.status) == (422, 422),
          (long1.status, long2.status))


def eval_answer(body):
    p = subprocess.run([MECHD, "eval", "--operation=/v1/trajectory"], input=body,
                       capture_output=True, timeout=120)
    return p.stdout


def test_same_answer(port):
    for name, body in [("short", example(port)), ("predicted long", KEPLER)]:
        nocost = json.loads(body)
        nocost["cost"] = False
        nocost = json.dumps(nocost).encode()
        st, got = post(port, nocost)
        want = eval_answer(nocost)
        check("%s trajectory: 200, the same bytes as mechd eval" % name,
              st == 200 and got.strip() == want.strip() and len(want) > 100,
              (st, got[:200], want[:200]))


def main():
    args = ["--workers", "1", "--queue", "1", "--deadline-ms", "3000",
            "--max-steps", "1000000000000", "--inline-max-us", "1000"]
    proc, port = start_mechd(MECHD, args, stderr=subprocess.DEVNULL)
    try:
        test_gate(port)
        test_same_answer(port)
    finally:
        stop_mechd(proc)
    proc, port = start_mechd(MECHD, args[:-1] + ["0"], stderr=subprocess.DEVNULL)
    try:
        short = example(port)
        long1, long2 = fill_pool(port)
        st, _ = post(port, short)
        check("--inline-max-us 0: the short trajectory goes to the pool too (503)", st == 503, st)
        long1.t.join(60)
        long2.t.join(60)
    finally:
        stop_mechd(proc)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
