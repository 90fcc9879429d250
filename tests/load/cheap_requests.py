#!/usr/bin/python3
"""Cheap requests under load: a one-vector boost (the
README's boost example, an event at rest [1, 0, 0, 0] boosted by beta = 0.6)
costs microseconds, so mechd must answer every one 200 while it is only busy
with I/O, even with a small queue.

  cheap_requests.py [PATH/TO/mechd] [--seconds S] [--connections N,N]

mechd runs with --workers 2 --queue 4; wrk (2 threads) sends the boost on
N keep-alive connections for S seconds (default 5 s at 64, then at 256),
counting the answers per status in a Lua script. Before the fix one preempted
I/O thread pushed the route's measured (wall-clock) cost over
--inline-max-us, every later boost went to the workers, and the 4-slot queue
answered 0.3-1.5 % of them 503. Prints requests/s and the status counts.
Exit status 1 only on functional failures: any answer other than 200, a wrk
socket error (connect, read, write, timeout), a wrong boosted vector, no
answers at all, or mechd dying. Never on timing. About 15 s."""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import loadlib  # noqa: E402

NAME = "load/cheap-requests"
BOOST = '{"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}'

# Every answer's status counted per wrk thread, summed in done() (thread:get
# copies each thread's table), printed as "status CODE COUNT" lines.
LUA = r"""
local threads = {}
function setup(thread)
  table.insert(threads, thread)
end
function init(args)
  counts = {}
  req = wrk.format("POST", "/v1/relativity/boost", {["Content-Type"] = "application/json"}, [==[%s]==])
end
function request()
  return req
end
function response(status, headers, body)
  counts[status] = (counts[status] or 0) + 1
end
function done(summary, latency, requests)
  local total = {}
  for _, t in ipairs(threads) do
    for k, v in pairs(t:get("counts")) do
      total[k] = (total[k] or 0) + v
    end
  end
  for k, v in pairs(total) do
    io.write(string.format("status %%d %%d\n", k, v))
  end
end
""" % BOOST


def run_wrk(url, seconds, connections, script, watch=None):
    """wrk for `seconds`; while it runs, watch() is called every 0.5 s (the
    in-round stall watch, see stall_watch)."""
    p = subprocess.Popen(["wrk", "-t2", "-c%d" % connections, "-d%ds" % seconds, "--timeout", "15s",
                          "-s", script, url], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        while p.poll() is None and watch is not None:
            time.sleep(0.5)
            if p.poll() is None:
                watch(p.pid)
        out, _ = p.communicate(timeout=seconds + 60)
    except subprocess.TimeoutExpired:
        p.kill()
        out, _ = p.communicate()
    counts = {int(a): int(b) for a, b in re.findall(r"(?m)^status (\d+) (\d+)$", out)}
    r = {"out": out, "counts": counts, "non2xx": 0, "errors": (0, 0, 0, 0), "rps": 0.0}
    m = re.search(r"Non-2xx or 3xx responses: (\d+)", out)
    if m:
        r["non2xx"] = int(m.group(1))
    m = re.search(r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", out)
    if m:
        r["errors"] = tuple(map(int, m.groups()))
    m = re.search(r"Requests/sec:\s*([\d.]+)", out)
    if m:
        r["rps"] = float(m.group(1))
    return r


def requests_done(port):
    """mechd's count of finished requests (/metrics), or None if it did not
    answer within 2 s."""
    try:
        _, _, data, _ = loadlib.request(port, "GET", "/metrics", timeout=2)
        m = re.search(r"^mechd_request_duration_seconds_count (\d+)", data.decode(), re.M)
        return int(m.group(1)) if m else None
    except (OSError, ValueError):
        return None


def sockets_by_state(port):
    """Server-side and client-side TCP sockets of `port`, counted by state
    and by whether bytes wait unread (Recv-Q) or unacknowledged (Send-Q)."""
    res = {}
    for side, flt in (("server", "( sport = :%d )" % port), ("client", "( dport = :%d )" % port)):
        out = subprocess.run(["ss", "-tanH", flt], capture_output=True, text=True, timeout=10).stdout
        c = {}
        for l in out.splitlines():
            f = l.split()
            if len(f) < 3:
                continue
            k = "%s%s%s" % (f[0], " recvq" if f[1] != "0" else "", " sendq" if f[2] != "0" else "")
            c[k] = c.get(k, 0) + 1
        res[side] = c
    return res


class StallWatch:
    """In-round watch. A round with no answers for 5 s was seen twice (once in
    CI): libmicrohttpd's internal epoll loop slept holding the events of
    exactly 128 connections (see server/io_loop.c, which replaced it, and
    tests/integration/test_io_burst.py). Kept so that any other stall
    explains itself: every 0.5 s mechd's finished-request
    count is read; when it has not moved for 1.5 s while wrk runs, what the
    server and the kernel show at that moment is printed once (the count, the
    sockets by state and queue, and every mechd thread's stack when gdb is
    installed, mechd's and wrk's), so the next occurrence explains itself. The probe is a new
    connection: a probe that gets no answer says the server is not accepting
    or not processing at all."""

    def __init__(self, m):
        self.m, self.last, self.since, self.reported = m, None, time.monotonic(), False

    def __call__(self, wrk_pid):
        n = requests_done(self.m.port)
        now = time.monotonic()
        # The previous probe is itself one finished request.
        if n is None or self.last is None or n > self.last + 1:
            if n is not None:
                self.last, self.since = n, now
            if n is not None or now - self.since < 1.5:
                return
        else:
            self.last = n
        if self.reported or now - self.since < 1.5:
            return
        self.reported = True
        loadlib.log(NAME, "stall: mechd finished no request for %.1f s (count %s, probe %s)"
                    % (now - self.since, self.last, "answered" if n is not None else "unanswered"))
        try:
            loadlib.log(NAME, "stall: sockets %s" % (sockets_by_state(self.m.port),))
        except Exception as e:  # the diagnosis must not hide the failure
            loadlib.log(NAME, "stall: ss failed: %r" % (e,))
        if shutil.which("gdb"):
            for who, pid in (("mechd", self.m.proc.pid), ("wrk", wrk_pid)):
                try:
                    out = subprocess.run(["gdb", "-p", str(pid), "-batch", "-ex", "thread apply all bt 12"],
                                         capture_output=True, text=True, timeout=30).stdout
                    frames = [l[:160] for l in out.splitlines() if l.startswith(("Thread ", "#"))]
                    loadlib.log(NAME, "stall: %s's threads:\n%s" % (who, "\n".join(frames[:150])))
                except Exception as e:
                    loadlib.log(NAME, "stall: gdb on %s failed: %r" % (who, e))


def diagnose(m):
    """After a round with no answers at all: print what mechd and the kernel
    say (see StallWatch for what is printed while the round runs)."""
    try:
        st, _, data, dt = loadlib.request(m.port, "GET", "/metrics", timeout=10)
        lines = [l for l in data.decode(errors="replace").splitlines()
                 if l.startswith(("mechd_connections", "mechd_pool", "mechd_queue", "mechd_workers",
                                  "mechd_requests_in_flight", "mechd_inline"))]
        loadlib.log(NAME, "diagnosis: /metrics %s in %.3f s: %s" % (st, dt, "; ".join(lines)[:1500]))
    except Exception as e:  # the diagnosis must not hide the failure
        loadlib.log(NAME, "diagnosis: /metrics failed: %r" % (e,))
    try:
        out = subprocess.run(["ss", "-tan", "( sport = :%d )" % m.port], capture_output=True, text=True,
                             timeout=10).stdout
        states = {}
        for l in out.splitlines()[1:]:
            states[l.split()[0]] = states.get(l.split()[0], 0) + 1
        loadlib.log(NAME, "diagnosis: server sockets by state %s" % states)
    except Exception as e:
        loadlib.log(NAME, "diagnosis: ss failed: %r" % (e,))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mechd", nargs="?")
    ap.add_argument("--seconds", type=int, default=5)
    ap.add_argument("--connections", default="64,256")
    a = ap.parse_args()
    if not shutil.which("wrk"):
        raise SystemExit("wrk not found: apt-get install -y wrk")
    seconds = max(1, min(a.seconds, 60))
    m = loadlib.Mechd(loadlib.mechd_path([sys.argv[0]] + ([a.mechd] if a.mechd else [])),
                      "--workers", "2", "--queue", "4")
    failures = []
    with tempfile.NamedTemporaryFile("w", suffix=".lua", delete=False) as f:
        f.write(LUA)
        script = f.name
    try:
        # The answer itself, once: gamma = 1/sqrt(1 - 0.36) = 1.25,
        # ct' = gamma (ct - beta x) = 1.25, x' = gamma (x - beta ct) = -0.75.
        st, _, data, _ = loadlib.request(m.port, "POST", "/v1/relativity/boost", BOOST)
        v = json.loads(data)["vectors"] if st == 200 else None
        v = v[0] if v and isinstance(v[0], list) else v
        if not (v and math.isclose(v[0], 1.25, rel_tol=1e-15) and math.isclose(v[1], -0.75, rel_tol=1e-15)
                and v[2] == 0 and v[3] == 0):
            failures.append("the boost answered %s %r, expected 200 with [1.25, -0.75, 0, 0]" % (st, data[:200]))
        for c in [int(x) for x in a.connections.split(",") if x]:
            m.wait_idle()
            r = run_wrk(m.url, seconds, c, script, StallWatch(m))
            total = sum(r["counts"].values())
            bad = {k: n for k, n in r["counts"].items() if not 200 <= k < 300}
            loadlib.log(NAME, "%d connections, %d s: %.0f requests/s, statuses %s, socket errors "
                        "connect/read/write/timeout %s" % (c, seconds, r["rps"], dict(sorted(r["counts"].items())),
                                                            "/".join(map(str, r["errors"]))))
            if total == 0:
                failures.append("%d connections: no answers counted (wrk output: %r)" % (c, r["out"][-400:]))
                diagnose(m)
            if bad or r["non2xx"]:
                failures.append("%d connections: %d of %d cheap boosts refused (%s; wrk's non-2xx count %d)"
                                % (c, sum(bad.values()), total, bad, r["non2xx"]))
            if any(r["errors"]):
                failures.append("%d connections: wrk socket errors connect/read/write/timeout %s"
                                % (c, "/".join(map(str, r["errors"]))))
            if not m.alive():
                failures.append("mechd died")
                break
    finally:
        os.unlink(script)
        rc = m.stop()
    if rc != 0:
        failures.append("mechd exited with status %r on SIGTERM" % rc)
    for f in failures:
        loadlib.log(NAME, "FAIL: " + f)
    loadlib.log(NAME, "passed" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
