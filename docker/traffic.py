#!/usr/bin/python3
"""Traffic for docker/test.sh: sends N requests through nginx and, after a
given number of answers, runs a command (docker kill of one replica).

  traffic.py URL N KILL_AFTER CMD...

Takes every operation's example from GET URL/v1 (the catalog) and sends them
round-robin with 4 threads, a new connection per request. Prints counts and
latency figures; exits 1 if any request did not get its 200 (an error status,
a reset, a timeout), 0 otherwise. Python standard library only."""
import json
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request


def main():
    url, n, kill_after, cmd = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]
    with urllib.request.urlopen(url + "/v1", timeout=10) as r:
        ops = [(o["path"], json.dumps(o["example"]).encode())
               for o in json.load(r)["operations"] if o["method"] == "POST"]
    lock = threading.Lock()
    state = {"next": 0, "done": 0, "killed": None}
    failures, lat = [], []

    def worker():
        while True:
            with lock:
                i = state["next"]
                if i >= n:
                    return
                state["next"] += 1
            path, body = ops[i % len(ops)]
            req = urllib.request.Request(url + path, data=body, method="POST",
                                         headers={"Content-Type": "application/json"})
            t0 = time.monotonic()
            try:
                with urllib.request.urlopen(req, timeout=30) as r:
                    r.read()
                    status = r.status
            except urllib.error.HTTPError as e:
                status = e.code
            except Exception as e:  # reset, refused, timeout
                status = repr(e)
            dt = time.monotonic() - t0
            with lock:
                lat.append(dt)
                if status != 200:
                    failures.append((i, path, status))
                state["done"] += 1
                fire = state["done"] == kill_after and cmd
            if fire:
                r = subprocess.run(cmd, capture_output=True, text=True)
                state["killed"] = (i, r.returncode, r.stdout.strip()[:12])
                print("traffic: after %d answers ran %s -> rc %d" % (kill_after, " ".join(cmd), r.returncode),
                      flush=True)

    t0 = time.monotonic()
    ts = [threading.Thread(target=worker) for _ in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    wall = time.monotonic() - t0
    lat.sort()
    print("traffic: %d requests over %d operations in %.1f s, %d failed; latency p50 %.1f ms, p99 %.1f ms, max %.1f ms"
          % (n, len(ops), wall, len(failures), 1e3 * lat[len(lat) // 2], 1e3 * lat[int(len(lat) * 0.99)],
             1e3 * lat[-1]))
    for f in failures[:20]:
        print("traffic: FAILED request %d %s: %s" % f)
    if cmd and state["killed"] is None:
        print("traffic: the kill command never ran")
        sys.exit(1)
    if cmd and state["killed"][1] != 0:
        print("traffic: the kill command failed")
        sys.exit(1)
    sys.exit(1 if failures else 0)


main()
