#!/usr/bin/python3
"""Few file descriptors: the connection limit is fitted to them, the server
never spins and /healthz stays answered (Python 3 stdlib only).

Usage: /usr/bin/python3 test_srv_descriptors.py PATH/TO/mechd

mechd runs with RLIMIT_NOFILE 64 (soft and hard: it cannot raise it) and the
default --max-connections 512. Before, libmicrohttpd ran out of descriptors
long before 512 connections: accept() failed with EMFILE, the server
busy-waited a core in 2 runs of 10 and /healthz went unanswered in all 10.
Checked here:
- at start the server says it lowered --max-connections, and /metrics shows
  the fitted limit (mechd_connections_max, below 64) and process_max_fds 64;
- 150 idle connections are opened (more than the descriptors): /healthz,
  probed 5 times on new connections while they stay open, is answered 200 each
  time (the longest-waiting idle connections are closed to make room);
- the server's CPU time over 1.5 s of that standoff stays under 0.5 s (a spin
  burns a whole core: 1.5 s), read from /proc/PID/stat;
- a boost is still served afterwards.
127.0.0.1 only; every socket has a timeout.
"""
import json
import os
import re
import resource
import select
import socket
import subprocess
import sys
import tempfile
import time

from mechdtest import check, metric_value, stop_mechd, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_srv_descriptors.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
NOFILE = 64
FLOOD = 150
BOOST = json.dumps({"vectors": [1, 0, 0, 0], "velocity": {"beta": [0.6, 0, 0]}}).encode()


def start(logf):
    """mechd --port 0 under RLIMIT_NOFILE = NOFILE; (proc, port)."""
    def limit():
        resource.setrlimit(resource.RLIMIT_NOFILE, (NOFILE, NOFILE))
    env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
    proc = subprocess.Popen([MECHD, "--port", "0"], stdout=subprocess.PIPE, stderr=logf,
                            env=env, preexec_fn=limit)
    fd = proc.stdout.fileno()
    buf = b""
    end = time.monotonic() + 20
    while not buf.endswith(b"\n") and time.monotonic() < end:
        if not select.select([fd], [], [], max(0.0, end - time.monotonic()))[0]:
            break
        c = os.read(fd, 1)
        if not c:
            break
        buf += c
    m = re.fullmatch(rb"mechd listening on http://127\.0\.0\.1:(\d+)\n", buf)
    if not m:
        proc.kill()
        raise RuntimeError("mechd did not start: %r" % buf)
    return proc, int(m.group(1))


def exchange(port, data, timeout=5):
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
        s.sendall(data)
        buf = b""
        while True:
            c = s.recv(65536)
            if not c:
                break
            buf += c
        s.close()
    except OSError:
        return None, b""
    head, _, body = buf.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.1 (\d+)", head)
    return (int(m.group(1)) if m else None), body


def get(port, path):
    return exchange(port, b"GET " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                    b"Connection: close\r\n\r\n")


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rpartition(")")[2].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def main():
    with tempfile.NamedTemporaryFile(prefix="mechd-nofile-", suffix=".log") as logf:
        proc, port = start(logf)
        conns = []
        try:
            st, body = get(port, "/metrics")
            text = body.decode("utf-8", "replace")
            cmax = metric_value(text, "mechd_connections_max")
            fdmax = metric_value(text, "process_max_fds")
            print("  mechd_connections_max %s, process_max_fds %s" % (cmax, fdmax))
            check("connection limit fitted below the descriptor limit",
                  st == 200 and cmax is not None and 2 <= cmax < NOFILE and fdmax == NOFILE,
                  (st, cmax, fdmax))
            with open(logf.name, "rb") as f:
                log = f.read().decode("utf-8", "replace")
            check("start-up note says --max-connections was lowered",
                  re.search(r"--max-connections 512 lowered to %d" % int(cmax or -1), log) is not None,
                  log[:600])
            for _ in range(FLOOD):
                try:
                    s = socket.create_connection(("127.0.0.1", port), timeout=5)
                    conns.append(s)
                except OSError:
                    break
            print("  %d idle connections opened" % len(conns))
            time.sleep(0.3)
            answered = 0
            for _ in range(5):
                st, body = get(port, "/healthz")
                answered += st == 200 and body == b'{"status":"ok"}'
            check("/healthz answered 5 of 5 times during the flood", answered == 5, answered)
            c0, t0 = cpu_seconds(proc.pid), time.monotonic()
            time.sleep(1.5)
            used, wall = cpu_seconds(proc.pid) - c0, time.monotonic() - t0
            print("  server CPU during %.2f s of the standoff: %.3f s" % (wall, used))
            check("no busy wait: CPU < 0.5 s over 1.5 s", used < 0.5, used)
            st, body = exchange(port, b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                                b"Connection: close\r\nContent-Type: application/json\r\n"
                                b"Content-Length: %d\r\n\r\n" % len(BOOST) + BOOST)
            check("a boost is served during the flood", st == 200, (st, body[:200]))
        finally:
            for s in conns:
                s.close()
            stop_mechd(proc)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
