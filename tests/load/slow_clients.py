#!/usr/bin/python3
"""Slow clients: 500 connections that are
idle (connected, nothing sent) or trickling (a request header sent one byte
per second) must not stop new clients from being served, and are timed out.

  slow_clients.py [PATH/TO/mechd] [--idle N] [--trickle N] [--wait S]

Opens the connections (default 250 idle + 250 trickling), then sends 100 new
requests (boost, one connection each) and prints their latency; then waits up
to S seconds (default 45: mechd's idle timeout and its default
--request-timeout-ms are both 30 s) and prints how many slow connections the
server closed, and when. Exit status 1 only on functional failures: a new
client not answered 200, an idle or a trickling connection still open at the
end of the wait (trickling ones never go idle: the total receive-time limit,
--request-timeout-ms, must close them), /metrics not counting the timed-out
connections, or mechd dying. Never on timing."""
import argparse
import select
import socket
import sys
import threading
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import loadlib  # noqa: E402

NAME = "load/slow-clients"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mechd", nargs="?")
    ap.add_argument("--idle", type=int, default=250)
    ap.add_argument("--trickle", type=int, default=250)
    ap.add_argument("--wait", type=int, default=45)
    a = ap.parse_args()
    m = loadlib.Mechd(loadlib.mechd_path([sys.argv[0]] + ([a.mechd] if a.mechd else [])), "--workers", "2")
    failures = []
    socks = []
    stop = threading.Event()
    try:
        t0 = time.monotonic()
        for i in range(a.idle + a.trickle):
            s = socket.create_connection(("127.0.0.1", m.port), timeout=10)
            s.setblocking(False)
            socks.append({"s": s, "kind": "idle" if i < a.idle else "trickle", "closed": None})
        loadlib.log(NAME, "opened %d idle + %d trickling connections in %.1f s" %
                    (a.idle, a.trickle, time.monotonic() - t0))
        header = b"POST /v1/relativity/boost HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: " + b"a" * 4000

        def trickle():
            k = 0
            while not stop.wait(1.0):
                for c in socks:
                    if c["kind"] == "trickle" and c["closed"] is None:
                        try:
                            c["s"].send(header[k % len(header):k % len(header) + 1])
                        except OSError:
                            pass
                k += 1

        tt = threading.Thread(target=trickle)
        tt.start()
        time.sleep(2)
        lat, bad = [], []
        for i in range(100):
            try:
                st, _, data, dt = loadlib.request(m.port, "POST", "/v1/relativity/boost", loadlib.BOOST, timeout=10)
                lat.append(1e3 * dt)
                if st != 200:
                    bad.append(st)
            except Exception as e:  # noqa: BLE001 - not served
                bad.append(repr(e))
        if lat:
            loadlib.log(NAME, "100 new clients while %d slow connections are open: %d answered 200, "
                        "p50 %.2f ms, p99 %.2f ms, max %.2f ms" %
                        (len(socks), 100 - len(bad), loadlib.pct(lat, 50), loadlib.pct(lat, 99), max(lat)))
        if bad:
            failures.append("%d new clients not served: %r" % (len(bad), bad[:3]))

        # Wait for the server to close the slow connections.
        deadline = t0 + a.wait
        while time.monotonic() < deadline and any(c["closed"] is None for c in socks):
            open_socks = [c for c in socks if c["closed"] is None]
            r, _, _ = select.select([c["s"] for c in open_socks], [], [], 0.5)
            rs = set(r)
            for c in open_socks:
                if c["s"] in rs:
                    try:
                        data = c["s"].recv(65536)
                    except (BlockingIOError, InterruptedError):
                        continue
                    except OSError:
                        data = b""
                    if not data:
                        c["closed"] = time.monotonic() - t0
                    # data (e.g. a 408 or 431 answer) is read; close comes next
        stop.set()
        tt.join()
        for kind in ("idle", "trickle"):
            cs = [c for c in socks if c["kind"] == kind]
            closed = sorted(c["closed"] for c in cs if c["closed"] is not None)
            loadlib.log(NAME, "%s: %d of %d closed by the server within %d s%s" %
                        (kind, len(closed), len(cs), a.wait,
                         (" (first after %.1f s, last after %.1f s)" % (closed[0], closed[-1])) if closed else ""))
            if kind == "idle" and cs and not closed:
                failures.append("no idle connection was timed out within %d s" % a.wait)
            if kind == "trickle" and len(closed) < len(cs):
                failures.append("%d trickling connections still open after %d s (--request-timeout-ms "
                                "should have closed them)" % (len(cs) - len(closed), a.wait))
            if kind == "idle" and len(closed) < len(cs):
                failures.append("%d idle connections still open after %d s" % (len(cs) - len(closed), a.wait))
        n = loadlib.metric(m.port, "mechd_request_timeouts_total")
        loadlib.log(NAME, "mechd_request_timeouts_total %s" % n)
        if a.trickle and (n is None or n < 1):
            failures.append("/metrics did not count the timed-out connections: %r" % n)
        st, _, _, dt = loadlib.request(m.port, "GET", "/healthz", timeout=10)
        if st != 200:
            failures.append("/healthz answered %d at the end" % st)
        if not m.alive():
            failures.append("mechd died")
    finally:
        stop.set()
        for c in socks:
            c["s"].close()
        rc = m.stop()
    if rc != 0:
        failures.append("mechd exited %s on SIGTERM" % rc)
    for f in failures:
        loadlib.log(NAME, "FAIL: " + f)
    loadlib.log(NAME, "PASS" if not failures else "FAILED")
    return 1 if failures else 0


sys.exit(main())
