#!/usr/bin/python3
"""Sustained load: mixed traffic (boost,
inertia of 10 parts, short trajectory, round-robin) at 64 connections for
SECONDS (default 60) after a warm-up (default 10 s), with wrk on 127.0.0.1.

  sustained.py [PATH/TO/mechd] [--seconds N] [--warmup N] [--connections N]

Prints requests/s, p50/p99 latency, CPU per request and resident memory
(after warm-up, during and at the end). Exit status 1 only on functional
failures: an error response (non-2xx), a connect/write/timeout socket error,
mechd dying, or resident memory growing by more than 10 % (and 4 MiB) from
the end of the warm-up to the end (a leak). Never on timing."""
import argparse
import sys
import threading

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import loadlib  # noqa: E402

NAME = "load/sustained"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mechd", nargs="?")
    ap.add_argument("--seconds", type=int, default=60)
    ap.add_argument("--warmup", type=int, default=10)
    ap.add_argument("--connections", type=int, default=64)
    a = ap.parse_args()
    m = loadlib.Mechd(loadlib.mechd_path([sys.argv[0]] + ([a.mechd] if a.mechd else [])), "--workers", "2")
    failures = []
    try:
        for path, body in loadlib.MIXED:
            st, _, data, _ = loadlib.request(m.port, "POST", path, body)
            if st != 200:
                failures.append("%s answered %d: %s" % (path, st, data[:200]))
        if failures:
            raise SystemExit("%s: FAIL: %s" % (NAME, failures))
        rss0 = m.rss_kib()
        w = loadlib.wrk(m.url, a.warmup, a.connections)
        m.wait_idle()
        rss_warm = m.rss_kib()
        loadlib.log(NAME, "warm-up %d s: %d requests, RSS %.1f MiB -> %.1f MiB" %
                    (a.warmup, w["requests"], rss0 / 1024, rss_warm / 1024))
        samples, stop = [], threading.Event()

        def sample():
            while not stop.wait(1.0):
                if m.alive():
                    samples.append(m.rss_kib())

        t = threading.Thread(target=sample)
        t.start()
        c0 = m.cpu_seconds()
        r = loadlib.wrk(m.url, a.seconds, a.connections)
        cpu = m.cpu_seconds() - c0
        stop.set()
        t.join()
        rss_end = m.rss_kib() if m.alive() else 0
        loadlib.log(NAME, "%d s mixed (boost, inertia 10 parts, short trajectory) at %d connections: %d requests, "
                    "%.0f req/s, p50 %.2f ms, p99 %.2f ms, CPU %.1f µs/request" %
                    (a.seconds, a.connections, r["requests"], r["rps"], r["p50"], r["p99"],
                     1e6 * cpu / max(1, r["requests"])))
        growth = (rss_end - rss_warm) / rss_warm if rss_warm else 0
        loadlib.log(NAME, "RSS after warm-up %.1f MiB, max during %.1f MiB, end %.1f MiB: growth %+.1f %%" %
                    (rss_warm / 1024, max(samples or [0]) / 1024, rss_end / 1024, 100 * growth))
        if r["requests"] == 0:
            failures.append("wrk made no requests: %s" % r["out"][-500:])
        if r["non2xx"]:
            failures.append("%d error responses" % r["non2xx"])
        if r["connect"] or r["write"] or r["timeout"]:
            failures.append("socket errors: connect %d write %d timeout %d" % (r["connect"], r["write"], r["timeout"]))
        if not m.alive():
            failures.append("mechd died (status %s)" % m.proc.returncode)
        elif growth > 0.10 and rss_end - rss_warm > 4096:
            failures.append("resident memory grew %.1f %% after warm-up" % (100 * growth))
    finally:
        rc = m.stop()
    if rc != 0:
        failures.append("mechd exited %s on SIGTERM" % rc)
    for f in failures:
        loadlib.log(NAME, "FAIL: " + f)
    loadlib.log(NAME, "PASS" if not failures else "FAILED")
    return 1 if failures else 0


sys.exit(main())
