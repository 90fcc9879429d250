"""test_docs.py — the README stays true to the code.

Starts `mechd --port 0`, then checks that:
  * the README's endpoint table lists exactly the operations of GET /v1;
  * every script in clients/curl/ answers 200 with the physics its comment
    promises (checked against closed forms here);
  * every ```sh block holding a curl command to 127.0.0.1:8080, run against
    this server, prints what the ```json block right after it shows (numbers
    to 1e-12 relative; the measured "cost" is ignored).
Python 3 standard library only; argv[1] is the mechd binary.
"""
import json
import os
import re
import subprocess
import sys
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
README = os.path.join(HERE, "..", "..", "README.md")
passed = failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL:", what, file=sys.stderr)


def close(a, b, path=""):
    """Deep comparison: numbers within 1e-12 relative, the cost block ignored."""
    if isinstance(b, dict):
        if not isinstance(a, dict):
            return [path]
        bad = []
        for k in set(a) | set(b):
            if k == "cost":
                continue
            if k not in a or k not in b:
                bad.append(path + "/" + k)
            else:
                bad += close(a[k], b[k], path + "/" + k)
        return bad
    if isinstance(b, list):
        if not isinstance(a, list) or len(a) != len(b):
            return [path]
        return [p for i, (x, y) in enumerate(zip(a, b)) for p in close(x, y, "%s/%d" % (path, i))]
    if isinstance(b, (int, float)) and not isinstance(b, bool):
        ok = isinstance(a, (int, float)) and abs(a - b) <= 1e-12 * abs(b) + 1e-300
        return [] if ok else [path + " (%r vs %r)" % (a, b)]
    return [] if a == b else [path]


def run_client(base, name):
    env = dict(os.environ, MECHD_URL=base)
    out = subprocess.run(["sh", os.path.join(HERE, "..", "..", "clients", "curl", name)],
                         capture_output=True, text=True, timeout=60, env=env)
    try:
        return json.loads(out.stdout)
    except ValueError:
        check(False, "%s printed no JSON: %r" % (name, out.stdout[:200]))
        return {}


def rel(a, b):
    return abs(a - b) / abs(b)


def check_clients(base):
    import math
    r = run_client(base, "inertia.sh")
    m = r.get("principal", {}).get("moments", [0, 0, 0])
    check(rel(m[0], 1 / 6) < 1e-13 and rel(m[1], 11 / 12) < 1e-13 and rel(m[2], 11 / 12) < 1e-13,
          "inertia.sh moments %r, want 1/6, 11/12, 11/12" % (m,))
    r = run_client(base, "boost.sh")
    beta = 0.9999
    gamma = 1 / math.sqrt((1 - beta) * (1 + beta))
    ct = r.get("vectors", [[0]])[0][0]
    check(rel(ct, gamma * 599.584916) < 1e-14, "boost.sh ct %r, want %r" % (ct, gamma * 599.584916))
    check(abs(ct / 299792458 - 141.4e-6) < 0.1e-6, "boost.sh lifetime %r s, want 141.4 us" % (ct / 299792458))
    r = run_client(base, "trajectory.sh")
    h, g, lam, om = 100.0, 9.80665, math.radians(32), 7.292115e-5
    x_east = om * math.cos(lam) * math.sqrt(8 * h ** 3 / g) / 3
    stopped = r.get("stopped") or {}
    check(rel(stopped.get("position", [0])[0], x_east) < 2e-3,
          "trajectory.sh lands %r m east, want %r within 0.2%%" % (stopped.get("position"), x_east))
    check(rel(stopped.get("t", 0), math.sqrt(2 * h / g)) < 1e-6,
          "trajectory.sh lands at t = %r, want sqrt(2h/g)" % stopped.get("t"))


def main():
    binary = sys.argv[1]
    text = open(README, encoding="utf-8").read()
    proc = subprocess.Popen([binary, "--port", "0", "--deadline-ms", "300000"], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True)
    try:
        line = proc.stdout.readline()
        m = re.search(r"http://[^:]+:(\d+)", line)
        if not m:
            check(False, "server printed no port: %r" % line)
            return
        port = int(m.group(1))
        base = "http://127.0.0.1:%d" % port
        catalog = json.load(urllib.request.urlopen(base + "/v1", timeout=10))
        ops = {(o["method"], o["path"]) for o in catalog["operations"]}
        table = set(re.findall(r"^\|\s*`?(POST|GET)`?\s*\|\s*`(/[^`]*)`", text, re.M))
        table_ops = {t for t in table if t[0] == "POST"}
        check(table_ops == ops, "README endpoint table %s != catalog %s" % (sorted(table_ops), sorted(ops)))
        # GET resources: the catalog's list and the README's rows name the same paths.
        resources = {("GET", r["path"]) for r in catalog["resources"]}
        table_gets = {t for t in table if t[0] == "GET"}
        check(table_gets == resources, "README GET rows %s != catalog resources %s"
              % (sorted(table_gets ^ resources), "(symmetric difference)"))

        blocks = re.findall(r"```sh\n(curl [^\n]*127\.0\.0\.1:8080[^`]*?)```\s*```json\n(.*?)```", text, re.S)
        check(len(blocks) >= 3, "README has %d curl examples with output, want >= 3" % len(blocks))
        for cmd, shown in blocks:
            cmd = cmd.strip().replace("127.0.0.1:8080", "127.0.0.1:%d" % port)
            out = subprocess.run(["sh", "-c", cmd], capture_output=True, text=True, timeout=60)
            try:
                got = json.loads(out.stdout)
                want = json.loads(shown)
            except ValueError as e:
                check(False, "example output is not JSON (%s): %s" % (e, cmd[:100]))
                continue
            bad = close(got, want)
            check(not bad, "README example differs at %s: %s" % (bad[:5], cmd[:100]))
        check_clients(base)
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
    print("%d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
