#!/usr/bin/python3
"""Overload: many more long integrations than
workers + queue, all at once, while /healthz is polled every 10 ms.

  overload.py [PATH/TO/mechd] [--clients N] [--waves N]

mechd runs with --workers 2 --queue 4 (a small queue, so the excess is large)
and a 60 s deadline (accepted work must finish, not time out on a loaded
machine). Each wave sends N (default 40) harmonic-oscillator trajectories of
~3000 periods at once, each on its own connection. Prints how many were
accepted and refused, how fast the refusals came (target: 503 + Retry-After
within 50 ms), how long accepted ones took, and /healthz p50/p99/max
(target p99 < 10 ms). /healthz is polled from a separate process (a new
connection per poll), so the 40 client threads of this one (and its GIL) do
not add to the latency measured. Exit status 1 only on functional failures: a refusal
without Retry-After or not /problems/queue-full, an answer other than 200 or
503, a lost answer (connection error), none accepted or none refused, a
/healthz failure, or mechd dying. Never on timing."""
import argparse
import json
import subprocess
import sys
import threading
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import loadlib  # noqa: E402

NAME = "load/overload"

# The /healthz poller, run as its own process: polls every 10 ms until its
# stdin closes, then prints a JSON list of [status or error, seconds].
POLLER = r"""
import json, select, socket, sys, time
port = int(sys.argv[1])
out = []
while True:
    t0 = time.monotonic()
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=10)
        s.sendall(b"GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        data = b""
        while True:
            c = s.recv(65536)
            if not c:
                break
            data += c
        s.close()
        st = int(data[9:12]) if data.startswith(b"HTTP/1.") else repr(data[:40])
    except Exception as e:  # noqa: BLE001 - any failure is a finding
        st = repr(e)
    out.append([st, time.monotonic() - t0])
    if select.select([sys.stdin], [], [], 0.01)[0]:
        break
print(json.dumps(out))
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mechd", nargs="?")
    ap.add_argument("--clients", type=int, default=40)
    ap.add_argument("--waves", type=int, default=3)
    a = ap.parse_args()
    m = loadlib.Mechd(loadlib.mechd_path([sys.argv[0]] + ([a.mechd] if a.mechd else [])),
                      "--workers", "2", "--queue", "4", "--deadline-ms", "60000")
    failures = []
    health, health_fail, poller = [], [], None

    try:
        st, _, data, dt = loadlib.request(m.port, "POST", "/v1/trajectory", loadlib.LONG_TRAJECTORY, timeout=60)
        if st != 200:
            raise SystemExit("%s: FAIL: the long trajectory answered %d: %s" % (NAME, st, data[:300]))
        loadlib.log(NAME, "one long trajectory alone: %.0f ms" % (1e3 * dt))
        poller = subprocess.Popen(["/usr/bin/python3", "-c", POLLER, str(m.port)], stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE)
        results = []
        lock = threading.Lock()

        def client():
            try:
                st, hdr, data, dt = loadlib.request(m.port, "POST", "/v1/trajectory", loadlib.LONG_TRAJECTORY,
                                                    timeout=120)
                typ = ""
                if st != 200:
                    try:
                        typ = json.loads(data).get("type", "")
                    except ValueError:
                        typ = "(not JSON)"
                r = (st, hdr.get("retry-after"), typ, dt)
            except Exception as e:  # noqa: BLE001 - a lost answer
                r = (repr(e), None, "", 0.0)
            with lock:
                results.append(r)

        for wave in range(a.waves):
            ts = [threading.Thread(target=client) for _ in range(a.clients)]
            for t in ts:
                t.start()
            for t in ts:
                t.join()
        out, _ = poller.communicate(timeout=60)  # closes its stdin: it stops and reports
        for st, dt in json.loads(out or b"[]"):
            health.append(dt)
            if st != 200:
                health_fail.append(st)
        ok = [r for r in results if r[0] == 200]
        refused = [r for r in results if r[0] == 503]
        other = [r for r in results if r[0] not in (200, 503)]
        ms = [1e3 * r[3] for r in refused]
        loadlib.log(NAME, "%d waves of %d long trajectories (workers 2, queue 4): %d accepted and answered 200, "
                    "%d refused 503, %d other" % (a.waves, a.clients, len(ok), len(refused), len(other)))
        if refused:
            loadlib.log(NAME, "503 answered in p50 %.1f ms, p99 %.1f ms, max %.1f ms (target: within 50 ms: %s)" %
                        (loadlib.pct(ms, 50), loadlib.pct(ms, 99), max(ms),
                         "MET" if max(ms) <= 50 else "NOT MET"))
        if ok:
            loadlib.log(NAME, "accepted answered in p50 %.0f ms, max %.0f ms" %
                        (1e3 * loadlib.pct([r[3] for r in ok], 50), 1e3 * max(r[3] for r in ok)))
        hm = [1e3 * x for x in health]
        if hm:
            loadlib.log(NAME, "/healthz during the run: %d polls, p50 %.2f ms, p99 %.2f ms, max %.2f ms "
                        "(target p99 < 10 ms: %s)" % (len(hm), loadlib.pct(hm, 50), loadlib.pct(hm, 99), max(hm),
                                                      "MET" if loadlib.pct(hm, 99) < 10 else "NOT MET"))
        for r in refused:
            if not r[1]:
                failures.append("a 503 without Retry-After")
                break
        for r in refused:
            if r[2] != "/problems/queue-full":
                failures.append("a 503 of type %r, want /problems/queue-full" % r[2])
                break
        for r in other[:5]:
            failures.append("answer %r (%s): want 200 or 503" % (r[0], r[2]))
        if not ok:
            failures.append("no request was accepted")
        if not refused:
            failures.append("no request was refused: not overloaded?")
        if health_fail:
            failures.append("/healthz failed %d times: %r" % (len(health_fail), health_fail[:3]))
        if not m.alive():
            failures.append("mechd died")
    finally:
        if poller and poller.poll() is None:
            poller.kill()
            poller.wait()
        rc = m.stop()
    if rc != 0:
        failures.append("mechd exited %s on SIGTERM" % rc)
    for f in failures:
        loadlib.log(NAME, "FAIL: " + f)
    loadlib.log(NAME, "PASS" if not failures else "FAILED")
    return 1 if failures else 0


sys.exit(main())
