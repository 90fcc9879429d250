#!/usr/bin/python3
"""bench_http_instructions — the small-boost cost of mechd against the bare
libmicrohttpd floor (bench/floor_server.c) in counts that do not depend on
what else the machine runs: user-space instructions per request (valgrind
--tool=callgrind, Ir) and system calls per request (strace -c), for the same
one-vector boost on one keep-alive connection, in the same run.

Wall and CPU time on a shared 2-core machine swing by 15-40 % between runs
(bench_http prints them with spreads); these counts repeat to a few per cent,
so their ratio says where mechd's extra cost is. They leave out what the
kernel does inside each system call (recv, send, epoll: most of the floor's
time per request), which is why the system calls are counted beside them.
libmicrohttpd zeroes each connection's whole memory pool after every request
(memset): its instructions are printed apart, as callgrind counts a
`rep stosb` per iteration and so overstates its time.

Usage: bench_http_instructions.py [OUTDIR]   (OUTDIR, from `make bench`, is
ignored). Environment: MECHD, FLOOR_SERVER (default: next to this program),
BENCH_REQUESTS (default 2000). Needs valgrind and strace (make bench
installs them). Exit status 0 when everything ran, 1 when a tool or server
could not run or a request failed.
"""
import glob
import http.client
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MECHD = os.environ.get("MECHD") or os.path.join(HERE, "mechd")
FLOOR = os.environ.get("FLOOR_SERVER") or os.path.join(HERE, "floor_server")
N = max(100, min(100000, int(os.environ.get("BENCH_REQUESTS", "2000"))))
BODY = json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}})


def start(argv, out):
    """Start argv with stdout and stderr into file out; return (proc, port)."""
    f = open(out, "w")
    p = subprocess.Popen(argv, stdout=f, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    t_end = time.monotonic() + 600  # mechd parses its schemas slowly under valgrind
    while time.monotonic() < t_end:
        with open(out) as g:
            m = re.search(r"127\.0\.0\.1:(\d+)", g.read())
        if m:
            return p, int(m.group(1))
        if p.poll() is not None:
            break
        time.sleep(0.2)
    p.kill()
    raise SystemExit("bench_http_instructions: %s did not start (see %s)" % (argv[0], out))


def boosts(port, n):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    for _ in range(n):
        c.request("POST", "/v1/relativity/boost", BODY, {"Content-Type": "application/json"})
        r = c.getresponse()
        r.read()
        if r.status != 200:
            raise SystemExit("bench_http_instructions: a boost was answered %d" % r.status)
    c.close()


def server_argv(name, slowed=False):
    """slowed: under callgrind every thread CPU time is ~50 times longer, so
    mechd would send its boosts to a worker by their measured cost; the
    largest --inline-max-us keeps them on the I/O thread, as unslowed."""
    if name == "floor":
        return [FLOOR, "0"]
    return [MECHD, "--port", "0"] + (["--inline-max-us", "1000000"] if slowed else [])


def instructions(name, tmp):
    """(Ir per request, memset Ir per request) under callgrind."""
    out = os.path.join(tmp, "cg.%s" % name)
    p, port = start(["valgrind", "--tool=callgrind", "--instr-atstart=no",
                     "--callgrind-out-file=" + out] + server_argv(name, True),
                    os.path.join(tmp, "%s.callgrind.log" % name))
    try:
        boosts(port, 50)  # warm: first-use allocations, the route's estimates
        subprocess.run(["callgrind_control", "-i", "on", str(p.pid)], capture_output=True,
                       timeout=120)
        boosts(port, N)
        subprocess.run(["callgrind_control", "-d", str(p.pid)], capture_output=True, timeout=120)
    finally:
        p.kill()
        p.wait()
    total = memset = 0
    for f in glob.glob(out + ".*"):
        with open(f) as g:
            m = re.search(r"(?m)^summary: (\d+)", g.read())
        if not m or int(m.group(1)) == 0:
            continue
        total += int(m.group(1))
        a = subprocess.run(["callgrind_annotate", "--threshold=100", f], capture_output=True,
                           text=True, timeout=300).stdout
        for line in a.splitlines():
            mm = re.match(r"\s*([\d,]+) .*memset", line)
            if mm:
                memset += int(mm.group(1).replace(",", ""))
    return total / N, memset / N


def syscalls(name, tmp):
    """{syscall: calls per request} under strace -c -f."""
    p, port = start(server_argv(name), os.path.join(tmp, "%s.log" % name))
    out = os.path.join(tmp, "strace.%s" % name)
    try:
        boosts(port, 50)
        s = subprocess.Popen(["strace", "-c", "-f", "-o", out, "-p", str(p.pid)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(1.0)  # attached to every thread
        boosts(port, N)
        time.sleep(0.3)
        s.send_signal(signal.SIGINT)
        s.wait(60)
    finally:
        p.terminate()
        p.wait(30)
    calls = {}
    with open(out) as f:
        for line in f:
            m = re.match(r"\s*[\d.]+\s+[\d.]+\s+\d+\s+(\d+)\s+(?:\d+\s+)?(\w+)\s*$", line)
            if m and m.group(2) != "total":
                calls[m.group(2)] = int(m.group(1)) / N
    # Sleeps of the watcher threads are time, not requests.
    calls.pop("clock_nanosleep", None)
    calls.pop("restart_syscall", None)
    return calls


def main():
    for tool in ("valgrind", "callgrind_control", "callgrind_annotate", "strace"):
        if not shutil.which(tool):
            print("bench_http_instructions: %s not found (apt-get install -y valgrind strace)" % tool)
            return 1
    for path in (MECHD, FLOOR):
        if not os.access(path, os.X_OK):
            print("bench_http_instructions: %s not found (build first)" % path)
            return 1
    tmp = tempfile.mkdtemp(prefix="bench-http-ir-")
    print("bench_http_instructions: one-vector boosts on one keep-alive connection, %d per "
          "server, same run" % N)
    res = {}
    for name in ("floor", "mechd"):
        ir, ms = instructions(name, tmp)
        sc = syscalls(name, tmp)
        res[name] = (ir, ms, sc)
        print("  %-6s %9.0f Ir/request (memset %7.0f, the rest %7.0f); %5.2f system calls/request: %s"
              % (name, ir, ms, ir - ms, sum(sc.values()),
                 ", ".join("%s %.2f" % kv for kv in sorted(sc.items(), key=lambda kv: -kv[1])
                           if kv[1] >= 0.05)))
    f, m = res["floor"], res["mechd"]
    print("  mechd/floor: %.2fx instructions, %.2fx without memset, %.2fx memset, "
          "%.2fx system calls" % (m[0] / f[0], (m[0] - m[1]) / (f[0] - f[1]),
                                  m[1] / f[1] if f[1] else float("nan"),
                                  sum(m[2].values()) / sum(f[2].values())))
    shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
