#!/usr/bin/python3
"""Quick operations answered on the I/O threads, and the new server options
(Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_quick.py PATH/TO/mechd

mechd --workers 1 --queue 1: a slow integration occupies the only worker and
a second one fills the queue, so any request handed to the pool is refused
503. Checked:

- a quick POST (api_is_quick: a 1-vector boost) is still answered 200 with
  the right numbers: it runs on the I/O thread, not in the pool
  (--inline-max-us 1000000, so its measured cost never sends it to the pool,
  even under a sanitizer);
- a quick route with a body over 8 KiB (a boost of 400 vectors, 11 KB) is
  decided by its predicted cost, not its size: it too is answered 200 on the
  I/O thread while the pool is full (it used to go to the pool and get 503
  there, or wait behind the long jobs);
- quick requests are counted in /metrics (route and status labels, latency
  histogram count) and logged, one line each, like pooled ones;
- malformed and invalid quick requests get their 400/422 problem+json;
- the measured guard: with --inline-max-us 1 the first boost of 2000
  events runs inline (no measurement yet), the next is predicted slower than 1 µs and goes to
  the full pool: 503, and so do the next 62, but the 64th predicted too slow
  runs inline as a probe that re-measures the route (the decision can
  recover); with --inline-max-us 0 every boost goes to the pool;
- --io-threads 1 and 4 both serve; --worker-nice 7 gives exactly the
  --workers threads and the express worker nice 7 above mechd's own, with
  --worker-nice 0 they keep mechd's own nice, SCHED_BATCH either way (read
  from /proc on Linux); invalid values of --io-threads,
  --request-timeout-ms, --inline-max-us and --worker-nice are refused with
  exit status 2; --help lists the four options with their defaults and
  environment variables.
Only 127.0.0.1 is contacted; every socket has a timeout.
"""
import json
import math
import os
import re
import socket
import subprocess
import sys
import tempfile
import time

from mechdtest import check, metric_value, start_mechd, stop_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_quick.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
SLOW = json.dumps({"particle": {"mass": 1, "position": [0, 0, 0], "velocity": [1, 0, 0]},
                   "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                   "t_end": 10000, "samples": 11,
                   "integrator": {"method": "rk4", "dt": 1e-6}}).encode()
# Boost of the event (ct, x, y, z) = (1, 0, 0, 0) by beta = 0.6 along x:
# gamma = 1/sqrt(1 - 0.36) = 1.25; ct' = gamma (ct - beta x) = 1.25,
# x' = gamma (x - beta ct) = -0.75.
BOOST = json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}).encode()
BIG_N = 400
BIG_VECTORS = [[1.0 + i, 0.5, 0.25, -0.125] for i in range(BIG_N)]
BIG_BOOST = json.dumps({"vectors": BIG_VECTORS, "velocity": {"beta": [0.6, 0, 0]}}).encode()
# The guard's boost: 2000 events, so its measured cost (~0.4 µs an event
# read, boosted and written) is far above --inline-max-us 1 even with the
# queue full (quick_fits_when_full allows SRV_QUICK_FULL_FACTOR = 16 times
# the limit); a one-event boost now costs about 1 µs and would fit that.
GUARD_BOOST = json.dumps({"vectors": [[1.0 + i, 0.5, 0.25, -0.125] for i in range(2000)],
                          "velocity": {"beta": [0.6, 0, 0]}}).encode()


def send(port, method, path, body=b"", timeout=30):
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    s.sendall(method.encode() + b" " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n"
              b"Connection: close\r\nContent-Type: application/json\r\nContent-Length: %d\r\n\r\n"
              % len(body) + body)
    return s


def read_answer(s):
    data = b""
    while True:
        chunk = s.recv(65536)
        if not chunk:
            break
        data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.[01] (\d{3})", head)
    return (int(m.group(1)) if m else None), head.decode(errors="replace"), body


def call(port, method, path, body=b"", timeout=30):
    s = send(port, method, path, body, timeout)
    try:
        return read_answer(s)
    finally:
        s.close()


def metrics(port):
    return call(port, "GET", "/metrics")[2].decode()


def counter(text, route, status):
    m = re.search(r'(?m)^mechd_requests_total\{route="%s",status="%s"\} (\d+)$' % (re.escape(route), status),
                  text)
    return int(m.group(1)) if m else 0


def gauge(text, name):
    return metric_value(text, name)



stop = stop_mechd


POOL_ARGS = ["--workers", "1", "--queue", "1", "--deadline-ms", "60000", "--max-steps", "1000000000000"]


def fill_pool(port, socks, what):
    """Occupy the only worker and the one queue slot with slow integrations."""
    socks.append(send(port, "POST", "/v1/trajectory", SLOW))
    check("%s: a slow integration occupies the only worker" % what,
          wait_for(lambda: gauge(metrics(port), "mechd_workers_busy") == 1, 10))
    socks.append(send(port, "POST", "/v1/trajectory", SLOW))
    check("%s: a second one fills the queue" % what,
          wait_for(lambda: gauge(metrics(port), "mechd_queue_depth") == 1, 10))
    st, _, body = call(port, "POST", "/v1/trajectory", SLOW)
    check("%s: the pool is full: a trajectory is refused 503" % what, st == 503, repr(st))


def test_quick_while_pool_full():
    errf = tempfile.TemporaryFile()
    proc, port = start_mechd(MECHD, POOL_ARGS + ["--inline-max-us", "1000000"], stderr=errf)
    socks = []
    try:
        before = metrics(port)
        fill_pool(port, socks, "inline")

        t = time.monotonic()
        st, head, body = call(port, "POST", "/v1/relativity/boost", BOOST)
        dt = time.monotonic() - t
        print("quick boost while the pool is full: %s in %.2f ms" % (st, 1e3 * dt))
        ok = st == 200
        if ok:
            ans = json.loads(body)
            v = ans["vectors"]
            v = v[0] if isinstance(v[0], list) else v
            ok = (math.isclose(v[0], 1.25, rel_tol=1e-15) and math.isclose(v[1], -0.75, rel_tol=1e-15)
                  and math.isclose(ans["gamma"], 1.25, rel_tol=1e-15))
        check("a quick boost is answered 200 with gamma 1.25, (1.25, -0.75, 0, 0), while the pool is full",
              ok, repr((st, body[:200])))
        check("... with the usual headers (X-Request-Id, nosniff, Cache-Control no-store)",
              re.search(r"(?im)^x-request-id: [0-9a-f]{32}\r?$", head) is not None
              and re.search(r"(?im)^x-content-type-options: nosniff", head) is not None
              and re.search(r"(?im)^cache-control: no-store", head) is not None, head)
        st, _, body = call(port, "POST", "/v1/relativity/boost", b"{\"vectors\": [1, 0, 0")
        check("a malformed quick request gets 400 malformed-json", st == 400 and b"malformed-json" in body,
              repr((st, body[:120])))
        st, _, body = call(port, "POST", "/v1/relativity/boost",
                           json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [1.5, 0, 0]}}).encode())
        check("an invalid quick request gets 422", st == 422, repr((st, body[:160])))

        st, head, body = call(port, "POST", "/v1/relativity/boost", BIG_BOOST)
        ok = st == 200
        if ok:  # ct' = g (ct - b x), x' = g (x - b ct), g 1.25, b 0.6
            vs = json.loads(body)["vectors"]
            ok = len(vs) == BIG_N and all(
                math.isclose(v[0], 1.25 * w[0] - 0.75 * w[1], rel_tol=1e-14, abs_tol=1e-12)
                and math.isclose(v[1], 1.25 * w[1] - 0.75 * w[0], rel_tol=1e-14, abs_tol=1e-12)
                for v, w in zip(vs, BIG_VECTORS))
        check("a quick route with a body over 8 KiB (%d bytes) is decided by its predicted cost, "
              "not its size: answered inline 200 while the pool is full" % len(BIG_BOOST), ok,
              repr((st, body[:160])))
        check("... with the usual headers", re.search(r"(?im)^x-request-id: ", head) is not None, head)

        after = metrics(port)
        n200 = counter(after, "/v1/relativity/boost", "200") - counter(before, "/v1/relativity/boost", "200")
        n400 = counter(after, "/v1/relativity/boost", "400") - counter(before, "/v1/relativity/boost", "400")
        n422 = counter(after, "/v1/relativity/boost", "422") - counter(before, "/v1/relativity/boost", "422")
        n503 = counter(after, "/v1/relativity/boost", "503") - counter(before, "/v1/relativity/boost", "503")
        check("/metrics counts the quick requests by route and status (200, 400, 422), none refused",
              (n200, n400, n422, n503) == (2, 1, 1, 0), repr((n200, n400, n422, n503)))
        c0 = gauge(before, "mechd_request_duration_seconds_count")
        c1 = gauge(after, "mechd_request_duration_seconds_count")
        # between the two scrapes: 3 waits/probes of /metrics inside wait_for at least,
        # 1 trajectory 503, 4 boosts -> at least 5 more than before
        check("the latency histogram counts them too", c0 is not None and c1 is not None and c1 - c0 >= 5,
              repr((c0, c1)))
        st, _, _ = call(port, "GET", "/healthz")
        check("/healthz answers while the pool is full", st == 200, repr(st))
    finally:
        for s in socks:
            s.close()
        rc = stop(proc)
    check("mechd exits 0 on SIGTERM", rc == 0, repr(rc))
    errf.seek(0)
    log = errf.read().decode(errors="replace")
    check("every boost request has its log line (4)",
          len(re.findall(r"(?m)^mechd: \S+Z req=[0-9a-f]{32} POST /v1/relativity/boost \d{3} \d+us bytes=\d+ client=127\.0\.0\.1$", log)) == 4, log[-800:])


def test_guard():
    for limit, expect, what in (("1", [200, 503], "the first boost runs inline, the next is measured "
                                 "slower than 1 µs and goes to the full pool"),
                                ("0", [503, 503], "every boost goes to the full pool")):
        proc, port = start_mechd(MECHD, POOL_ARGS + ["--inline-max-us", limit], stderr=subprocess.DEVNULL)
        socks = []
        try:
            fill_pool(port, socks, "--inline-max-us %s" % limit)
            sts = [call(port, "POST", "/v1/relativity/boost", GUARD_BOOST)[0] for _ in range(2)]
            check("--inline-max-us %s: %s (%s)" % (limit, what, expect), sts == expect, repr(sts))
            if limit == "1":
                # The decision recovers: a route predicted too slow is still run
                # inline, and re-measured, once in 64 such requests
                # (SRV_QUICK_REPROBE), so the one above (too_slow #1) and the
                # next 62 go to the full pool and the 64th runs inline: 200.
                sts = [call(port, "POST", "/v1/relativity/boost", GUARD_BOOST)[0] for _ in range(63)]
                check("--inline-max-us 1: 62 more boosts go to the full pool (503), the 64th predicted "
                      "too slow is a re-measuring probe run inline (200)",
                      sts == [503] * 62 + [200], repr(sts))
        finally:
            for s in socks:
                s.close()
            rc = stop(proc)
        check("--inline-max-us %s: exits 0 on SIGTERM" % limit, rc == 0, repr(rc))


def test_io_threads():
    for n in ("1", "4"):
        proc, port = start_mechd(MECHD, ["--io-threads", n], stderr=subprocess.DEVNULL)
        try:
            sts = [call(port, "POST", "/v1/relativity/boost", BOOST)[0] for _ in range(20)]
            sts.append(call(port, "POST", "/v1/trajectory", json.dumps(
                {"particle": {"mass": 1, "position": [0, 0, 100], "velocity": [0, 0, 0]},
                 "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
                 "t_end": 1, "samples": 3}).encode())[0])
            check("--io-threads %s: quick and pooled requests answered 200" % n, sts == [200] * 21, repr(sts))
        finally:
            rc = stop(proc)
        check("--io-threads %s: exits 0 on SIGTERM" % n, rc == 0, repr(rc))
    for nice, n in (("7", 7), ("0", 0)):
        proc, port = start_mechd(MECHD, ["--workers", "3", "--worker-nice", nice], stderr=subprocess.DEVNULL)
        try:
            if os.path.isdir("/proc/%d/task" % proc.pid):
                def stat_fields(path):
                    with open(path) as f:
                        return f.read().rsplit(")", 1)[1].split()

                # The increment is relative to the nice mechd was started with
                # (the test may itself run under nice).
                base = int(stat_fields("/proc/%d/stat" % proc.pid)[16])  # field 19: nice
                # --workers 3 and the express worker: 4 threads, each SCHED_BATCH (3)
                expect = [(min(base + n, 19), 3)] * 4

                def threads():
                    got = []
                    for tid in os.listdir("/proc/%d/task" % proc.pid):
                        fields = stat_fields("/proc/%d/task/%s/stat" % (proc.pid, tid))
                        with open("/proc/%d/task/%s/comm" % (proc.pid, tid)) as f:
                            name = f.read().strip()
                        got.append((name, int(fields[16]), int(fields[38])))  # 19 nice, 41 policy
                    return got

                def workers():
                    return sorted((n, pol) for name, n, pol in threads()
                                  if name in ("mechd-worker", "mechd-express"))

                def others():
                    return sorted(set((n, pol) for name, n, pol in threads()
                                      if name not in ("mechd-worker", "mechd-express")))

                # each worker sets its own priority when it first runs: give them a moment
                wait_for(lambda: workers() == expect, 5)
                got = workers()
                check("--worker-nice %s: the 3 workers and the express worker run SCHED_BATCH "
                      "(3) at nice %d (mechd's own %d + %s)" % (nice, expect[0][0], base, nice),
                      got == expect, repr(got))
                check("--worker-nice %s: every other thread at mechd's own nice, SCHED_OTHER"
                      % nice, others() == [(base, 0)], repr(others()))
        finally:
            rc = stop(proc)
        check("--worker-nice %s: exits 0 on SIGTERM" % nice, rc == 0, repr(rc))
    env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
    for args in (["--io-threads", "0"], ["--io-threads", "65"], ["--request-timeout-ms", "50"],
                 ["--request-timeout-ms", "abc"], ["--inline-max-us", "-1"],
                 ["--worker-nice", "20"]):
        p = subprocess.run([MECHD, "--port", "0"] + args, capture_output=True, timeout=20, env=env)
        check("%s is refused with exit status 2 and a message" % " ".join(args),
              p.returncode == 2 and args[0].encode() in p.stderr, repr((p.returncode, p.stderr[:200])))
    p = subprocess.run([MECHD, "--help"], capture_output=True, timeout=20, env=env)
    out = p.stdout.decode()
    for flag, envname, default in (("--io-threads", "MECHD_IO_THREADS", "2"),
                                   ("--request-timeout-ms", "MECHD_REQUEST_TIMEOUT_MS", "30000"),
                                   ("--inline-max-us", "MECHD_INLINE_MAX_US", "100"),
                                   ("--worker-nice", "MECHD_WORKER_NICE", "0")):
        check("--help lists %s (default %s, env %s)" % (flag, default, envname),
              re.search(re.escape(flag) + r"=VALUE.*\n.*default %s, env %s" % (default, envname), out) is not None,
              out[-600:])


test_quick_while_pool_full()
test_guard()
test_io_threads()
sys.exit(summary())
