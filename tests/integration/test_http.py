#!/usr/bin/python3
"""Integration tests of mechd over real HTTP (Python 3 standard library only).

Usage: /usr/bin/python3 test_http.py PATH/TO/mechd

Starts `mechd --port 0` (reading the port from its one stdout line) and checks,
over sockets: the server routes, the catalog and its examples, every error
status of the HTTP contract (400 404 405 413 415 422 503) as problem+json,
the compute deadline, the bounded queue, /healthz staying fast while the pool
is busy, keep-alive across suspend/resume, options and environment, and a
clean SIGTERM/SIGINT shutdown (exit 0, pending requests answered, no hang).
Every socket and subprocess has a timeout. Prints "N passed, M failed" and
exits nonzero on any failure. Timing is asserted only as loose sanity bounds.
"""
import copy
import http.client
import json
import os
import re
import select
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
from mechdtest import check, summary, wait_for

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_http.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])

START_TIMEOUT = 20.0    # seconds for a server to print its listening line (ASan is slow)
REQUEST_TIMEOUT = 60.0  # socket timeout of every request
EXIT_TIMEOUT = 15.0     # seconds for a server to exit after a signal


class Server:
    """A mechd process on a free port; stderr goes to a temporary file."""

    def __init__(self, *args, env=None):
        self.args = ["--port", "0"] + [str(a) for a in args]
        self.errfile = tempfile.TemporaryFile()
        full_env = dict(os.environ)
        for k in list(full_env):
            if k.startswith("MECHD_"):
                del full_env[k]
        full_env.update(env or {})
        self.proc = subprocess.Popen([MECHD] + self.args, stdout=subprocess.PIPE,
                                     stderr=self.errfile, env=full_env)
        self.port = None
        self.line = self._read_line(START_TIMEOUT)
        m = re.fullmatch(r"mechd listening on http://([0-9.]+|\[[0-9a-fA-F:]+\]):(\d+)\n",
                         self.line or "")
        if not m:
            self.kill()
            raise RuntimeError("mechd %s did not print its listening line (got %r); stderr:\n%s"
                               % (self.args, self.line, self.stderr()))
        self.port = int(m.group(2))

    def _read_line(self, timeout):
        fd = self.proc.stdout.fileno()
        buf = b""
        end = time.monotonic() + timeout
        while not buf.endswith(b"\n"):
            left = end - time.monotonic()
            if left <= 0:
                return None
            ready, _, _ = select.select([fd], [], [], left)
            if not ready:
                return None
            chunk = os.read(fd, 1)
            if not chunk:
                return None
            buf += chunk
        return buf.decode("utf-8", "replace")

    def stderr(self):
        self.errfile.seek(0)
        return self.errfile.read().decode("utf-8", "replace")

    def signal_and_wait(self, sig, timeout=EXIT_TIMEOUT):
        """Send sig; return (returncode or None on timeout, seconds taken)."""
        t0 = time.monotonic()
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        try:
            rc = self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            rc = None
            self.kill()
        return rc, time.monotonic() - t0

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                pass


def request(port, method, path, body=None, content_type="application/json",
            timeout=REQUEST_TIMEOUT, headers=None, conn=None):
    """One HTTP request; returns (status, headers with lower-case names, body bytes).
    body may be bytes, str, a JSON-able object or None. On a socket error
    returns (None, {}, error text)."""
    hdrs = dict(headers or {})
    data = None
    if body is not None:
        if isinstance(body, (bytes, bytearray)):
            data = bytes(body)
        elif isinstance(body, str):
            data = body.encode()
        else:
            data = json.dumps(body).encode()
        if content_type is not None:
            hdrs["Content-Type"] = content_type
    own = conn is None
    if own:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        conn.request(method, path, body=data, headers=hdrs)
        resp = conn.getresponse()
        payload = resp.read()
        return resp.status, {k.lower(): v for k, v in resp.getheaders()}, payload
    except (OSError, http.client.HTTPException) as e:
        return None, {}, ("%s: %s" % (type(e).__name__, e)).encode()
    finally:
        if own:
            conn.close()


def as_json(payload):
    try:
        return json.loads(payload)
    except (ValueError, TypeError):
        return None


def check_problem(name, res, status, ptype):
    """Assert an application/problem+json answer with the given status and type."""
    st, hdrs, payload = res
    ok = check("%s: status %s" % (name, status), st == status,
               "got %r: %r" % (st, payload[:300]))
    ct = hdrs.get("content-type", "")
    check("%s: application/problem+json" % name,
          ct.split(";")[0].strip() == "application/problem+json", "got %r" % ct)
    doc = as_json(payload)
    fields = isinstance(doc, dict) and all(k in doc for k in ("type", "title", "status", "detail"))
    check("%s: problem has type/title/status/detail" % name, fields, repr(payload[:300]))
    if fields:
        check("%s: type %s" % (name, ptype), doc["type"] == ptype, "got %r" % doc["type"])
        check("%s: body status matches" % name, doc["status"] == st, "got %r" % doc["status"])
        check("%s: title and detail are non-empty strings" % name,
              isinstance(doc["title"], str) and doc["title"] and
              isinstance(doc["detail"], str) and doc["detail"], repr(doc))
    check("%s: X-Request-Id" % name, re.fullmatch(r"[0-9a-f]{32}", hdrs.get("x-request-id", "")), repr(hdrs))
    return doc if ok and isinstance(doc, dict) else None


def slow_trajectory(example):
    """A trajectory that cannot finish: rk4 with dt 1e-6 over 1e4 s of a
    central-gravity orbit (1e10 steps), bounded only by the server's budget."""
    body = copy.deepcopy(example) if isinstance(example, dict) else {}
    for k in ("stop", "fictitious", "cost"):
        body.pop(k, None)
    body.update({
        "particle": {"mass": 1.0, "position": [1.0, 0.0, 0.0], "velocity": [0.0, 1.0, 0.0]},
        "frame": {"type": "inertial"},
        "forces": [{"type": "central_gravity", "gm": 1.0, "center": [0.0, 0.0, 0.0]}],
        "t_end": 1.0e4,
        "samples": 11,
        "integrator": {"method": "rk4", "dt": 1.0e-6},
    })
    return body


def metric(port, name):
    st, _, payload = request(port, "GET", "/metrics", timeout=10)
    if st != 200:
        return None
    m = re.search(r"^%s (\S+)$" % re.escape(name), payload.decode(), re.M)
    return float(m.group(1)) if m else None



class Async:
    """Run request() in a thread; .result after .join()."""

    def __init__(self, *args, **kwargs):
        self.result = (None, {}, b"not finished")
        self.thread = threading.Thread(target=self._run, args=args, kwargs=kwargs, daemon=True)
        self.thread.start()

    def _run(self, *args, **kwargs):
        self.result = request(*args, **kwargs)

    def join(self, timeout):
        self.thread.join(timeout)
        return not self.thread.is_alive()


# ---- options -------------------------------------------------------------------

def test_options():
    def run(args, env=None):
        e = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
        e.update(env or {})
        try:
            p = subprocess.run([MECHD] + args, capture_output=True, timeout=20, env=e)
            return p.returncode, p.stdout.decode(), p.stderr.decode()
        except subprocess.TimeoutExpired:
            return None, "", "timeout"

    rc, out, _ = run(["--help"])
    check("--help exits 0", rc == 0, "rc=%r" % rc)
    for flag, env, default in (("--bind", "MECHD_BIND", "127.0.0.1"), ("--port", "MECHD_PORT", "8080"),
                               ("--workers", "MECHD_WORKERS", "2"), ("--queue", "MECHD_QUEUE", "64"),
                               ("--max-body", "MECHD_MAX_BODY", "1048576"),
                               ("--deadline-ms", "MECHD_DEADLINE_MS", "10000"),
                               ("--max-steps", "MECHD_MAX_STEPS", "10000000")):
        check("--help lists %s, %s, default %s" % (flag, env, default),
              flag in out and env in out and default in out)
    rc, out, _ = run(["--version"])
    check("--version exits 0 and names mechd", rc == 0 and out.startswith("mechd "), repr(out))
    for args, env in ((["--port", "abc"], None), (["--port", "70000"], None),
                      (["--workers", "0"], None), (["--max-body", "-1"], None),
                      (["--bind", "not-an-address"], None), (["--no-such-option"], None),
                      (["--queue"], None), ([], {"MECHD_DEADLINE_MS": "soon"}),
                      ([], {"MECHD_MAX_STEPS": "0"})):
        rc, _, err = run(args, env)
        check("invalid %s %s exits 2 with a message" % (args, env or ""), rc == 2 and err.strip(),
              "rc=%r stderr=%r" % (rc, err))

    # Environment sets a value; the command line wins over it.
    small = b'{"x": "' + b"a" * 200 + b'"}'
    s = Server(env={"MECHD_MAX_BODY": "100"})
    try:
        st, _, _ = request(s.port, "POST", "/v1/relativity/boost", small)
        check("MECHD_MAX_BODY=100 rejects a 211-byte body with 413", st == 413, "got %r" % st)
    finally:
        s.signal_and_wait(signal.SIGTERM)
    s = Server("--max-body", "4096", env={"MECHD_MAX_BODY": "100", "MECHD_PORT": "1"})
    try:
        st, _, _ = request(s.port, "POST", "/v1/relativity/boost", small)
        check("--max-body 4096 wins over MECHD_MAX_BODY=100 (and --port 0 over MECHD_PORT)",
              st not in (413, None), "got %r" % st)
    finally:
        s.signal_and_wait(signal.SIGTERM)


# ---- the main server ---------------------------------------------------------------

def test_main_server():
    s = Server("--max-body", "4096", "--workers", "2", "--queue", "64")
    port = s.port
    try:
        st, hdrs, payload = request(port, "GET", "/healthz")
        check("GET /healthz 200", st == 200, "got %r" % st)
        check("/healthz body is {\"status\":\"ok\"}", as_json(payload) == {"status": "ok"},
              repr(payload))
        check("/healthz is application/json",
              hdrs.get("content-type", "").startswith("application/json"), repr(hdrs))
        check("/healthz has X-Request-Id", re.fullmatch(r"[0-9a-f]{32}", hdrs.get("x-request-id", "")), repr(hdrs))

        st, hdrs, payload = request(port, "GET", "/")
        text = payload.decode("utf-8", "replace")
        check("GET / 200 text/html linking /v1 and /v1/openapi.json",
              st == 200 and hdrs.get("content-type", "").startswith("text/html") and
              'href="/v1"' in text and "/v1/openapi.json" in text and "mechd" in text,
              "%r %r" % (st, text[:200]))

        st, hdrs, payload = request(port, "GET", "/v1/openapi.json")
        doc = as_json(payload)
        check("GET /v1/openapi.json 200 JSON with an openapi version",
              st == 200 and isinstance(doc, dict) and "openapi" in doc, "%r %r" % (st, payload[:200]))

        # The catalog.
        st, hdrs, payload = request(port, "GET", "/v1")
        cat = as_json(payload)
        check("GET /v1 200 JSON", st == 200 and isinstance(cat, dict), "%r %r" % (st, payload[:200]))
        ops = cat.get("operations", []) if isinstance(cat, dict) else []
        by_path = {op.get("path"): op for op in ops if isinstance(op, dict)}
        examples = {}
        for path in ("/v1/rigid/inertia", "/v1/relativity/boost", "/v1/trajectory"):
            op = by_path.get(path)
            check("catalog lists %s" % path, op is not None, repr(sorted(by_path)))
            if op is None:
                continue
            check("%s: method POST, summary, description" % path,
                  op.get("method") == "POST" and op.get("summary") and op.get("description"), repr(op)[:300])
            check("%s: schema is an object schema" % path,
                  isinstance(op.get("schema"), dict) and op["schema"].get("type") == "object",
                  repr(op.get("schema"))[:300])
            check("%s: example is an object" % path, isinstance(op.get("example"), dict),
                  repr(op.get("example"))[:300])
            if isinstance(op.get("example"), dict):
                examples[path] = op["example"]

        # Each example succeeds, and a second identical request gives the same
        # bytes apart from the measured "cost".
        for path, ex in examples.items():
            st, hdrs, payload = request(port, "POST", path, ex)
            doc = as_json(payload)
            check("POST %s example: 200 application/json object" % path,
                  st == 200 and hdrs.get("content-type", "").startswith("application/json") and
                  isinstance(doc, dict), "%r %r" % (st, payload[:400]))
            check("POST %s example: X-Request-Id" % path, re.fullmatch(r"[0-9a-f]{32}", hdrs.get("x-request-id", "")))
            st2, _, payload2 = request(port, "POST", path, ex)
            doc2 = as_json(payload2)
            if isinstance(doc, dict) and isinstance(doc2, dict):
                doc.pop("cost", None)
                doc2.pop("cost", None)
            check("POST %s example: deterministic" % path, st2 == st and doc == doc2)

        boost_ex = examples.get("/v1/relativity/boost", {"vectors": [[1, 0, 0, 0]],
                                                          "velocity": {"beta": [0.5, 0, 0]}})
        inertia_ex = examples.get("/v1/rigid/inertia", {})

        # 400: malformed JSON names line and column.
        doc = check_problem("400 malformed JSON",
                            request(port, "POST", "/v1/relativity/boost", '{\n  "vectors": [[1, 2,\n'),
                            400, "/problems/malformed-json")
        if doc:
            check("400 detail names line and column",
                  re.search(r"line \d+", doc["detail"]) and re.search(r"column \d+", doc["detail"]),
                  repr(doc["detail"]))
        check_problem("400 empty body", request(port, "POST", "/v1/relativity/boost", b""),
                      400, "/problems/malformed-json")

        # 404 / 405.
        check_problem("404 GET unknown path", request(port, "GET", "/v1/no/such/thing"),
                      404, "/problems/not-found")
        check_problem("404 POST unknown path",
                      request(port, "POST", "/v1/no/such/thing", boost_ex), 404, "/problems/not-found")
        res = request(port, "GET", "/v1/trajectory")
        check_problem("400 GET on a POST route without ?request=", res, 400,
                      "/problems/request-missing")
        res = request(port, "DELETE", "/v1/trajectory")
        check_problem("405 DELETE on a POST route", res, 405, "/problems/method-not-allowed")
        check("405 on a POST route: Allow: POST, GET, HEAD (GET takes ?request=)",
              res[1].get("allow") == "POST, GET, HEAD", repr(res[1].get("allow")))
        res = request(port, "POST", "/v1/integrators", b"{}")
        check_problem("405 POST on a GET resource", res, 405, "/problems/method-not-allowed")
        check("405 POST on a GET resource: Allow: GET, HEAD", res[1].get("allow") == "GET, HEAD",
              repr(res[1].get("allow")))
        check_problem("405 PUT with a body on a POST route",
                      request(port, "PUT", "/v1/rigid/inertia", inertia_ex),
                      405, "/problems/method-not-allowed")
        check_problem("405 POST /healthz", request(port, "POST", "/healthz", b"{}"),
                      405, "/problems/method-not-allowed")

        # 413: Content-Length over --max-body, and a chunked body over it.
        big = b'{"vectors": [' + b"[1, 0, 0, 0], " * 400 + b"[1, 0, 0, 0]]}"
        check_problem("413 body over --max-body (Content-Length)",
                      request(port, "POST", "/v1/relativity/boost", big), 413, "/problems/body-too-large")

        def chunks():
            for i in range(0, len(big), 1000):
                yield big[i:i + 1000]
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=REQUEST_TIMEOUT)
        try:
            conn.request("POST", "/v1/relativity/boost", body=chunks(),
                         headers={"Content-Type": "application/json"}, encode_chunked=True)
            r = conn.getresponse()
            res = (r.status, {k.lower(): v for k, v in r.getheaders()}, r.read())
        except (OSError, http.client.HTTPException) as e:
            res = (None, {}, str(e).encode())
        finally:
            conn.close()
        check_problem("413 chunked body over --max-body", res, 413, "/problems/body-too-large")
        st, _, payload = request(port, "POST", "/v1/relativity/boost", boost_ex)
        check("a body under --max-body still works after 413s", st == 200, "%r %r" % (st, payload[:300]))

        # 415.
        check_problem("415 text/plain",
                      request(port, "POST", "/v1/relativity/boost", json.dumps(boost_ex),
                              content_type="text/plain"), 415, "/problems/unsupported-media-type")
        check_problem("415 no Content-Type",
                      request(port, "POST", "/v1/relativity/boost", json.dumps(boost_ex),
                              content_type=None), 415, "/problems/unsupported-media-type")

        # 422 validation: an unknown key, and a bad mass named by pointer.
        bad = copy.deepcopy(boost_ex)
        bad["no_such_key"] = 1
        doc = check_problem("422 unknown key", request(port, "POST", "/v1/relativity/boost", bad),
                            422, "/problems/validation-error")
        if doc:
            errs = doc.get("errors")
            check("422 errors[] with pointer and detail",
                  isinstance(errs, list) and errs and
                  all(isinstance(e.get("pointer"), str) and e.get("detail") for e in errs), repr(errs))
            check("422 unknown key is named", any("no_such_key" in (e.get("pointer", "") + e.get("detail", ""))
                                                  for e in (errs or [])), repr(errs))
        bad = copy.deepcopy(inertia_ex)
        if isinstance(bad.get("bodies"), list) and bad["bodies"] and isinstance(bad["bodies"][0], dict):
            bad["bodies"][0]["mass"] = -1.0
        else:
            bad = {"bodies": [{"shape": "point", "mass": -1.0, "position": [0, 0, 0]}]}
        doc = check_problem("422 negative mass", request(port, "POST", "/v1/rigid/inertia", bad),
                            422, "/problems/validation-error")
        if doc:
            check("422 errors[].pointer is /bodies/0/mass",
                  any(e.get("pointer") == "/bodies/0/mass" for e in doc.get("errors", [])),
                  repr(doc.get("errors")))
        bad = copy.deepcopy(boost_ex)
        bad["velocity"] = {"beta": [1.5, 0.0, 0.0]}
        res = request(port, "POST", "/v1/relativity/boost", bad)
        check("422 |beta| > 1 is rejected", res[0] == 422, "%r %r" % (res[0], res[2][:300]))

        # Keep-alive: a pooled POST (suspend/resume) then GETs on one connection.
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=REQUEST_TIMEOUT)
        try:
            sts = []
            for _ in range(3):
                sts.append(request(port, "POST", "/v1/relativity/boost", boost_ex, conn=conn)[0])
                sts.append(request(port, "GET", "/healthz", conn=conn)[0])
                sts.append(request(port, "GET", "/v1/trajectory", conn=conn)[0])
        finally:
            conn.close()
        check("keep-alive across suspend/resume", sts == [200, 200, 400] * 3, repr(sts))

        # Many concurrent pooled requests all get the same answer.
        first = request(port, "POST", "/v1/relativity/boost", boost_ex)
        jobs = [Async(port, "POST", "/v1/relativity/boost", boost_ex) for _ in range(24)]
        done = all(j.join(REQUEST_TIMEOUT) for j in jobs)
        check("24 concurrent POSTs all answered alike",
              done and all(j.result[0] == first[0] == 200 for j in jobs),
              repr([j.result[0] for j in jobs]))

        # Request ids are distinct.
        ids = {request(port, "GET", "/healthz")[1].get("x-request-id") for _ in range(5)}
        check("X-Request-Id differs per request", len(ids) == 5, repr(ids))

        # A client that goes away mid-body does not hurt the server.
        with socket.create_connection(("127.0.0.1", port), timeout=10) as sk:
            sk.sendall(b"POST /v1/relativity/boost HTTP/1.1\r\nHost: x\r\n"
                       b"Content-Type: application/json\r\nContent-Length: 1000\r\n\r\n{\"vec")
        st, _, _ = request(port, "GET", "/healthz")
        check("server fine after a client vanished mid-body", st == 200, repr(st))

        # Metrics.
        st, hdrs, payload = request(port, "GET", "/metrics")
        text = payload.decode("utf-8", "replace")
        check("GET /metrics 200 text/plain", st == 200 and hdrs.get("content-type", "").startswith("text/plain"))
        for name in ('mechd_requests_total{route="/healthz",status="200"}',
                     'mechd_requests_total{route="/v1/relativity/boost",status="413"}',
                     'mechd_requests_total{route="/v1/relativity/boost",status="200"}',
                     "mechd_queue_depth", "mechd_workers_busy", "mechd_request_duration_seconds_sum",
                     "mechd_request_duration_seconds_count",
                     'mechd_request_duration_seconds_bucket{le="0.001"}',
                     'mechd_request_duration_seconds_bucket{le="+Inf"}',
                     "mechd_worker_busy_seconds_total"):
            check("/metrics has %s" % name, re.search(r"^%s \d" % re.escape(name), text, re.M), text[:800])
        # The histogram is cumulative and its +Inf bucket equals the count.
        buckets = [float(v) for v in re.findall(
            r'^mechd_request_duration_seconds_bucket\{le="[^"]+"\} (\S+)$', text, re.M)]
        count = re.search(r"^mechd_request_duration_seconds_count (\S+)$", text, re.M)
        check("/metrics histogram cumulative, +Inf == count",
              len(buckets) >= 2 and buckets == sorted(buckets) and count
              and buckets[-1] == float(count.group(1)), text[:1500])
        busy_s = re.search(r"^mechd_worker_busy_seconds_total (\S+)$", text, re.M)
        check("/metrics worker busy seconds > 0 after operations ran",
              busy_s and float(busy_s.group(1)) > 0, text[-800:])
        # Route labels are bounded: made-up paths count as "other", not as themselves.
        for junk in ("/v1/made-up-1", "/v1/made-up-2", "/nope/%d" % os.getpid()):
            request(port, "GET", junk)
        st, _, payload = request(port, "GET", "/metrics")
        text = payload.decode("utf-8", "replace")
        check("/metrics: unknown paths are route=\"other\"",
              'route="other",status="404"' in text and "made-up" not in text
              and "/nope/" not in text, text[:1500])
    finally:
        rc, secs = s.signal_and_wait(signal.SIGINT)
        err = s.stderr()
        check("main server: SIGINT exits 0", rc == 0, "rc=%r\n%s" % (rc, err[-3000:]))
        check("main server: a log line per request (id, method, path, status, us)",
              re.search(r"req=[0-9a-f]{32} GET /healthz 200 \d+us", err) and
              re.search(r"req=[0-9a-f]{32} POST /v1/relativity/boost 413 \d+us", err), err[-2000:])
        check("main server: no sanitizer report",
              "AddressSanitizer" not in err and "runtime error" not in err and "LeakSanitizer" not in err,
              err[-3000:])
    return examples


# ---- a small pool: 503, deadline, /healthz while busy --------------------------------

def test_busy_pool(examples):
    s = Server("--workers", "1", "--queue", "1", "--deadline-ms", "3000", "--max-steps", "1000000000000")
    port = s.port
    slow = slow_trajectory(examples.get("/v1/trajectory"))
    try:
        first = Async(port, "POST", "/v1/trajectory", slow)
        busy = wait_for(lambda: metric(port, "mechd_workers_busy") == 1, 10)
        check("a slow trajectory occupies the worker", busy)
        others = []
        for _ in range(4):
            others.append(Async(port, "POST", "/v1/trajectory", slow))
            time.sleep(0.05)
        # /healthz is answered on the I/O thread while the pool is busy.
        t0 = time.monotonic()
        st, _, _ = request(port, "GET", "/healthz", timeout=10)
        dt = time.monotonic() - t0
        check("/healthz 200 while the pool is busy", st == 200, repr(st))
        check("/healthz answers in < 2 s while the pool is busy (took %.3f s)" % dt, dt < 2.0)
        t0 = time.monotonic()
        st, _, _ = request(port, "GET", "/v1", timeout=10)
        check("GET /v1 answers inline while the pool is busy", st == 200 and time.monotonic() - t0 < 2.0)

        done = first.join(REQUEST_TIMEOUT) and all(o.join(REQUEST_TIMEOUT) for o in others)
        check("every request of the busy pool was answered", done)
        results = [first.result] + [o.result for o in others]
        statuses = [r[0] for r in results]
        check("busy pool: every answer is 422 or 503", all(x in (422, 503) for x in statuses), repr(statuses))
        full = [r for r in results if r[0] == 503]
        check("busy pool: at least one 503 (1 worker, queue 1, 5 requests)", len(full) >= 1, repr(statuses))
        for i, r in enumerate(full[:2]):
            check_problem("503 queue full #%d" % i, r, 503, "/problems/queue-full")
            check("503 #%d has Retry-After" % i, r[1].get("retry-after", "").isdigit(), repr(r[1]))
        doc = check_problem("deadline exceeded", first.result, 422, "/problems/compute-budget-exceeded")
        if doc:
            check("deadline answer tells how far it got",
                  len(doc) > 4 or re.search(r"\d", doc.get("detail", "")), repr(doc))
        st, _, _ = request(port, "GET", "/healthz")
        check("server healthy after the burst", st == 200)
    finally:
        rc, secs = s.signal_and_wait(signal.SIGTERM)
        err = s.stderr()
        check("busy-pool server: SIGTERM exits 0", rc == 0, "rc=%r\n%s" % (rc, err[-3000:]))
        check("busy-pool server: no sanitizer report",
              "AddressSanitizer" not in err and "runtime error" not in err, err[-3000:])


# ---- SIGTERM while work runs and waits ---------------------------------------------

def test_sigterm(examples):
    # --shutdown-grace-ms 0: cancel at once (the grace period is test_srv_ops.py's)
    s = Server("--workers", "1", "--queue", "4", "--deadline-ms", "60000", "--max-steps", "1000000000000",
               "--shutdown-grace-ms", "0")
    port = s.port
    slow = slow_trajectory(examples.get("/v1/trajectory"))
    running = Async(port, "POST", "/v1/trajectory", slow)
    check("SIGTERM test: the slow request is running",
          wait_for(lambda: metric(port, "mechd_workers_busy") == 1, 10))
    queued = Async(port, "POST", "/v1/trajectory", slow)
    check("SIGTERM test: a second request is queued",
          wait_for(lambda: metric(port, "mechd_queue_depth") == 1, 10))
    rc, secs = s.signal_and_wait(signal.SIGTERM)
    err = s.stderr()
    check("SIGTERM during work: exit 0", rc == 0, "rc=%r\n%s" % (rc, err[-3000:]))
    check("SIGTERM during work: exits within 10 s (took %.2f s)" % secs, rc is not None and secs < 10)
    check("SIGTERM: both requests answered", running.join(20) and queued.join(20))
    st = running.result[0]
    check("SIGTERM: the running request got 503 cancelled or 422", st in (503, 422),
          "got %r %r" % (st, running.result[2][:300]))
    if st == 503:
        check_problem("SIGTERM running request", running.result, 503, "/problems/cancelled")
    elif st == 422:
        check_problem("SIGTERM running request", running.result, 422, "/problems/compute-budget-exceeded")
    check_problem("SIGTERM queued request", queued.result, 503, "/problems/cancelled")
    check("SIGTERM: no sanitizer report", "AddressSanitizer" not in err and "runtime error" not in err,
          err[-3000:])
    try:
        socket.create_connection(("127.0.0.1", port), timeout=2).close()
        refused = False
    except OSError:
        refused = True
    check("SIGTERM: the port is closed afterwards", refused)


def main():
    if not os.access(MECHD, os.X_OK):
        print("mechd binary not found: %s" % MECHD)
        print("0 passed, 1 failed")
        return 1
    # A hard stop for the whole run, in case anything unforeseen blocks.
    signal.signal(signal.SIGALRM, lambda *a: (print("test_http.py: overall timeout"), os._exit(3)))
    signal.alarm(280)
    for fn in (test_options, test_main_server):
        try:
            res = fn()
        except Exception as e:  # a crash of the harness counts as a failure
            check("%s ran without an exception" % fn.__name__, False, "%s: %s" % (type(e).__name__, e))
            res = None
        if fn is test_main_server:
            examples = res or {}
    for fn in (test_busy_pool, test_sigterm):
        try:
            fn(examples)
        except Exception as e:
            check("%s ran without an exception" % fn.__name__, False, "%s: %s" % (type(e).__name__, e))
    return summary()


if __name__ == "__main__":
    sys.exit(main())
