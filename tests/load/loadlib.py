"""Shared helpers of the load scenarios (tests/load/*.py): start mechd on
127.0.0.1 with --port 0, read its resident memory and CPU time from /proc,
run wrk and parse its figures, time single requests. Python standard library
only; run with Debian's /usr/bin/python3. Nothing here ever fails on timing."""
import http.client
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

BOOST = '{"vectors":[1.0,0.5,0.25,-0.125],"velocity":{"beta":[0.6,0.0,0.0]}}'
INERTIA = ('{"bodies":[' + ",".join(
    '{"shape":"box","mass":%.1f,"size":[0.4,0.3,0.2],"position":[%.2f,0.0,0.1],'
    '"orientation":{"euler_zxz":[0.5,0.3,0.0]}}' % (1 + 0.1 * i, 0.05 * i) if i % 2 == 0 else
    '{"shape":"point","mass":%.1f,"position":[%.2f,-0.1,0.1]}' % (0.5 + 0.1 * i, 0.1 * i)
    for i in range(10)) + ']}')
TRAJECTORY = ('{"particle":{"mass":1.0,"position":[0.0,0.0,100.0],"velocity":[0.0,0.0,0.0]},'
              '"frame":{"type":"earth","latitude_deg":32.0},'
              '"forces":[{"type":"uniform_gravity","g":[0.0,0.0,-9.80665]}],"fictitious":["coriolis"],'
              '"t_end":10.0,"samples":11,'
              '"stop":{"coordinate":"z","crosses":0.0,"direction":"decreasing"}}')
# A long integration: a harmonic oscillator over ~3000 periods (a few hundred
# ms of one worker on this machine).
# "closed_form": false: the oscillator has a closed form, which an accuracy
# request would be answered from in microseconds; this one must
# keep a worker busy integrating.
LONG_TRAJECTORY = ('{"particle":{"mass":1.0,"position":[1.0,0.0,0.0],"velocity":[0.0,1.0,0.0]},'
                   '"forces":[{"type":"spring","k":1.0,"anchor":[0.0,0.0,0.0]}],"t_end":20000.0,"samples":11,'
                   '"integrator":{"accuracy":"balanced","closed_form":false}}')
MIXED = [("/v1/relativity/boost", BOOST), ("/v1/rigid/inertia", INERTIA), ("/v1/trajectory", TRAJECTORY)]


def log(name, msg):
    print("%s: %s" % (name, msg), flush=True)


def mechd_path(argv):
    if len(argv) > 1:
        return argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    for b in ("build", "build-rel"):
        p = os.path.join(here, "..", "..", b, "mechd")
        if os.access(p, os.X_OK):
            return p
    sys.exit("usage: %s PATH/TO/mechd" % argv[0])


class Mechd:
    """mechd --port 0 with extra arguments; stderr (one line per request) to a file."""

    def __init__(self, path, *args):
        self.err = tempfile.TemporaryFile()
        self.proc = subprocess.Popen([path, "--port", "0", "--bind", "127.0.0.1"] + list(args),
                                     stdout=subprocess.PIPE, stderr=self.err, text=True)
        line = self.proc.stdout.readline()
        m = re.search(r"127\.0\.0\.1:(\d+)", line)
        if not m:
            self.proc.kill()
            raise SystemExit("mechd did not start: %r" % line)
        self.port = int(m.group(1))
        self.url = "http://127.0.0.1:%d" % self.port

    def rss_kib(self):
        with open("/proc/%d/status" % self.proc.pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        return 0

    def cpu_seconds(self):
        with open("/proc/%d/stat" % self.proc.pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def wait_idle(self, limit=10.0):
        """Waits (at most limit s) until /metrics shows no queued job and no busy
        worker: jobs left by a previous wrk run's closed connections would
        otherwise refuse the next run's first requests with 503."""
        end = time.monotonic() + limit
        while time.monotonic() < end:
            try:
                _, _, data, _ = request(self.port, "GET", "/metrics", timeout=5)
                text = data.decode()
                q = re.search(r"^mechd_queue_depth (\d+)", text, re.M)
                b = re.search(r"^mechd_workers_busy (\d+)", text, re.M)
                if q and b and q.group(1) == "0" and b.group(1) == "0":
                    return
            except OSError:
                pass
            time.sleep(0.1)

    def alive(self):
        return self.proc.poll() is None

    def stop(self):
        """SIGTERM, wait (bounded); returns mechd's exit status."""
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        return self.proc.returncode


def request(port, method, path, body=None, timeout=30):
    """One request on a new connection: (status, headers dict, body bytes, seconds)."""
    t0 = time.monotonic()
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        c.request(method, path, body=body, headers={"Content-Type": "application/json"} if body else {})
        r = c.getresponse()
        data = r.read()
        return r.status, {k.lower(): v for k, v in r.getheaders()}, data, time.monotonic() - t0
    finally:
        c.close()


def metric(port, name):
    """The value of an unlabelled metric from /metrics (float), or None."""
    _, _, data, _ = request(port, "GET", "/metrics", timeout=10)
    m = re.search(r"^" + re.escape(name) + r" (\S+)$", data.decode(), re.M)
    return float(m.group(1)) if m else None


def pct(values, p):
    if not values:
        return float("nan")
    v = sorted(values)
    return v[min(len(v) - 1, int(p / 100.0 * len(v)))]


WRK_MIXED_LUA = r"""
local reqs = {}
local bodies = { %s }
local paths = { %s }
local i = 0
init = function(args)
  for k = 1, #paths do
    reqs[k] = wrk.format("POST", paths[k], {["Content-Type"] = "application/json"}, bodies[k])
  end
end
request = function()
  i = i %% #reqs + 1
  return reqs[i]
end
"""


def wrk(url, seconds, connections, requests=MIXED, threads=2):
    """Runs wrk round-robin over requests; returns a dict of figures."""
    if not shutil.which("wrk"):
        raise SystemExit("wrk not found: apt-get install -y wrk")
    lua = WRK_MIXED_LUA % (", ".join("[==[%s]==]" % b for _, b in requests),
                           ", ".join('"%s"' % p for p, _ in requests))
    with tempfile.NamedTemporaryFile("w", suffix=".lua", delete=False) as f:
        f.write(lua)
        script = f.name
    try:
        out = subprocess.run(["wrk", "-t%d" % threads, "-c%d" % connections, "-d%ds" % seconds, "--timeout", "15s",
                              "--latency", "-s", script, url], capture_output=True, text=True,
                             timeout=seconds + 60).stdout
    finally:
        os.unlink(script)
    r = {"out": out, "requests": 0, "non2xx": 0, "connect": 0, "read": 0, "write": 0, "timeout": 0}
    m = re.search(r"(\d+) requests in", out)
    if m:
        r["requests"] = int(m.group(1))
    m = re.search(r"Non-2xx or 3xx responses: (\d+)", out)
    if m:
        r["non2xx"] = int(m.group(1))
    m = re.search(r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", out)
    if m:
        r["connect"], r["read"], r["write"], r["timeout"] = map(int, m.groups())
    m = re.search(r"Requests/sec:\s*([\d.]+)", out)
    r["rps"] = float(m.group(1)) if m else 0.0
    for p in ("50", "99"):
        m = re.search(r"\s%s%%\s+([\d.]+)(us|ms|s)" % p, out)
        r["p" + p] = (float(m.group(1)) * {"us": 1e-3, "ms": 1.0, "s": 1e3}[m.group(2)]) if m else float("nan")
    return r
