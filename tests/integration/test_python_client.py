#!/usr/bin/python3
"""test_python_client.py — clients/python/mechd.py against a real mechd.

Usage: /usr/bin/python3 test_python_client.py PATH/TO/mechd

Starts `mechd --port 0` and checks the client: answers (an operation method, the
generic call, keyword bodies, the catalog, GET /v1/examples and run_example), a
method for every POST operation of GET /v1, each exception type with its problem
details (400, 404, 405, 413, 415, 422 validation / domain / budget, 503), the retry
on 503 honouring Retry-After (a server with --workers 1 --queue 1 kept busy by
slow requests, as in test_http.py), ConnectionFailed, and the batch helper (server
/v1/batch, the thread fallback, and the fallback when the server has no batch).
Then runs every clients/curl/*.sh against the server: each prints JSON with the
status its comment promises (error.sh: a problem+json). Python 3 standard library
only. Prints "N passed, M failed"; exits 1 on failure.
"""
import json
import os
import re
import select
import subprocess
import sys
import threading
import time

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_python_client.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.dont_write_bytecode = True  # keep clients/python free of __pycache__
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
import mechd  # noqa: E402
from mechdtest import check, summary, wait_for


def close(a, b, rtol):
    return isinstance(a, (int, float)) and abs(a - b) <= rtol * abs(b)


class Server:
    def __init__(self, *args):
        env = {k: v for k, v in os.environ.items() if not k.startswith("MECHD_")}
        self.proc = subprocess.Popen([MECHD, "--port", "0", "--deadline-ms", "300000"] + [str(a) for a in args],
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env)
        buf, end = b"", time.monotonic() + 20
        while not buf.endswith(b"\n") and time.monotonic() < end:
            ready, _, _ = select.select([self.proc.stdout], [], [], max(0.0, end - time.monotonic()))
            if not ready:
                break
            c = os.read(self.proc.stdout.fileno(), 1)
            if not c:
                break
            buf += c
        m = re.search(rb"http://([0-9.]+):(\d+)", buf)
        if not m:
            self.stop()
            raise RuntimeError("mechd printed no listening line: %r" % buf)
        self.url = "http://127.0.0.1:%s" % m.group(2).decode()

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=10)


def expect_error(name, cls, fn, status, ptype, pointer=None):
    try:
        fn()
    except mechd.MechdError as e:
        check("%s: raises %s" % (name, cls.__name__), isinstance(e, cls), "got %s: %s" % (type(e).__name__, e))
        check("%s: is a MechdError with status %s" % (name, status), e.status == status, repr(e.status))
        check("%s: type %s" % (name, ptype), e.type == ptype, repr(e.type))
        check("%s: title and detail" % name, bool(e.title) and bool(e.detail), repr((e.title, e.detail)))
        check("%s: .problem is the problem+json" % name, e.problem.get("status") == status, repr(e.problem))
        if pointer is not None:
            check("%s: errors name %s" % (name, pointer),
                  any(x.get("pointer") == pointer for x in e.errors), repr(e.errors))
        return e
    check("%s: raises %s" % (name, cls.__name__), False, "no exception")
    return None


CUBE = {"bodies": [{"shape": "box", "mass": 1, "size": [1, 1, 1], "position": [0.5, 0.5, 0.5]}],
        "origin": [0, 0, 0]}
# The same cube as 128 coincident boxes of mass 1/128 (exact in binary). The
# servers of test_busy run with --inline-max-us 0, so the server queues it for
# a worker instead of answering it on the I/O thread, and a full queue refuses
# it 503.
QUEUED_CUBE = {"bodies": [{"shape": "box", "mass": 1 / 128, "size": [1, 1, 1], "position": [0.5, 0.5, 0.5]}] * 128,
               "origin": [0, 0, 0]}


def test_success(m):
    r = m.rigid_inertia(CUBE)
    mom = r["principal"]["moments"]
    check("rigid_inertia: cube about a corner 1/6, 11/12, 11/12",
          close(mom[0], 1 / 6, 1e-13) and close(mom[1], 11 / 12, 1e-13) and close(mom[2], 11 / 12, 1e-13),
          repr(mom))
    r = m.relativity_velocity_addition(velocity={"beta": [0.5, 0, 0]}, frame_velocity={"beta": [-0.5, 0, 0]})
    check("keyword body: 0.5c (+) 0.5c = 0.8c", close(r["velocity_in_frame"]["beta"][0], 0.8, 1e-15), repr(r)[:200])
    r = m.relativity_boost({"vectors": [[1, 0, 0, 0]]}, velocity={"beta": [0.6, 0, 0]})
    check("dict + keywords merged: gamma 1.25", close(r["gamma"], 1.25, 1e-15), repr(r)[:200])
    r = m.call("/v1/rigid/inertia", CUBE)
    check("call(path, body) = the method", close(r["principal"]["moments"][0], 1 / 6, 1e-13))
    cat = m.catalog()
    posts = {o["path"] for o in cat["operations"] if o.get("method", "POST") == "POST"}
    missing = sorted(p for p in posts - {"/v1/check", "/v1/batch"}
                     if not callable(getattr(m, mechd.method_name(p), None)))
    check("a Client method for every POST operation of GET /v1", not missing, repr(missing))
    check("OPERATIONS has no path the server lacks", set(mechd.OPERATIONS.values()) <= posts,
          repr(set(mechd.OPERATIONS.values()) - posts))
    for name, path in mechd.OPERATIONS.items():
        if name != mechd.method_name(path):
            check("method name of %s" % path, False, name)
    ex = m.examples()
    check("examples(): a non-empty list", isinstance(ex, list) and len(ex) >= 30, repr(len(ex)))
    e = m.example("falling-object")
    answer, got, ok = m.run_example(e)
    check("run_example(falling-object): the notes' 1.9 cm", ok and abs(got - 0.019) < 5e-4, repr(got))
    _, got, ok = m.run_example("cube-corner-principal")
    check("run_example by id: 11/12", ok and close(got, 11 / 12, 1e-13), repr(got))
    bad = dict(e, notes_answer=dict(e["notes_answer"], value=0.025))
    check("check_example rejects a wrong notes value", not mechd.check_example(bad, answer)[1])
    check("health()", m.health() is True)


def test_errors(m, url):
    expect_error("unknown key", mechd.ValidationError,
                 lambda: m.rigid_inertia(dict(CUBE, colour="red")), 422,
                 "/problems/validation-error", "/colour")
    e = expect_error("beta = 1", mechd.DomainError,
                     lambda: m.relativity_boost(vectors=[[1, 0, 0, 0]], velocity={"beta": [1, 0, 0]}),
                     422, "/problems/domain-error", "/velocity/beta")
    check("DomainError is a ValidationError", isinstance(e, mechd.ValidationError))
    e = expect_error("step budget", mechd.BudgetExceeded,
                     lambda: m.trajectory({"particle": {"mass": 1, "position": [0, 0, 10], "velocity": [0, 0, 0]},
                                           "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.81]}],
                                           "t_end": 10, "integrator": {"method": "rk4", "dt": 1e-9}}),
                     422, "/problems/compute-budget-exceeded")
    check("BudgetExceeded.progress says how far it got",
          isinstance(e and e.progress, dict) and "fraction_done" in e.progress, repr(e and e.progress))
    geo = {"M": "sun", "kind": "timelike", "orbits": 3, "samples": 100000,
           "initial": {"semi_major_axis": 5.79e10, "eccentricity": 0.2}}
    e = expect_error("a batch over the answer budget", mechd.AnswerTooLarge,
                     lambda: m.call("/v1/batch", {"operations": [
                         {"operation": "/v1/gr/geodesic", "request": geo}] * 3}),
                     422, "/problems/answer-too-large", "/operations/2/request/samples")
    check("AnswerTooLarge says the limit and the size asked for",
          e is not None and e.limit == 200000 and e.requested == 300000, repr(e and e.problem))
    expect_error("unknown path", mechd.NotFound, lambda: m.call("/v1/no/such", {}), 404, "/problems/not-found")
    expect_error("DELETE on a POST operation", mechd.MethodNotAllowed,
                 lambda: m.call("/v1/rigid/inertia", method="DELETE"), 405, "/problems/method-not-allowed")
    expect_error("malformed JSON", mechd.BadRequest,
                 lambda: m.send("POST", "/v1/rigid/inertia", b'{"bodies": ['), 400, "/problems/malformed-json")
    expect_error("text/plain", mechd.UnsupportedMediaType,
                 lambda: m.send("POST", "/v1/rigid/inertia", json.dumps(CUBE).encode(), "text/plain"),
                 415, "/problems/unsupported-media-type")
    # 413 on a server with a 1 KiB limit (a body that fits the socket buffers, so the
    # answer is read before the server closes; a far larger body can end in ConnectionFailed)
    small = Server("--max-body", "1024")
    try:
        expect_error("body over the limit", mechd.PayloadTooLarge,
                     lambda: mechd.Client(small.url, retries=0).send(
                         "POST", "/v1/rigid/inertia", b" " * 8192 + b"{}"), 413, "/problems/body-too-large")
    finally:
        small.stop()
    check("error message names the field",
          "/colour" in str(_raised(lambda: m.rigid_inertia(dict(CUBE, colour="red")))))
    dead = mechd.Client("http://127.0.0.1:9", timeout=5, retries=0)
    e = _raised(lambda: dead.rigid_inertia(CUBE))
    check("no server: ConnectionFailed with status None",
          isinstance(e, mechd.ConnectionFailed) and e.status is None, repr(e))


def _raised(fn):
    try:
        fn()
    except mechd.MechdError as e:
        return e
    return None


def slow_trajectory():
    """rk4, dt 1e-6 over 1e4 s of an orbit: bounded only by the server's deadline."""
    return {"particle": {"mass": 1.0, "position": [1.0, 0.0, 0.0], "velocity": [0.0, 1.0, 0.0]},
            "frame": {"type": "inertial"},
            "forces": [{"type": "central_gravity", "gm": 1.0, "center": [0.0, 0.0, 0.0]}],
            "t_end": 1.0e4, "samples": 11, "integrator": {"method": "rk4", "dt": 1.0e-6}}


def metric(m, name):
    status, _, body = m.request("GET", "/metrics")
    mm = re.search(r"^%s (\S+)$" % re.escape(name), body.decode(), re.M) if status == 200 else None
    return float(mm.group(1)) if mm else None



def test_busy():
    # 5 s of deadline: the queue must still be full when the checks below run,
    # even on a loaded machine.
    s = Server("--workers", "1", "--queue", "1", "--deadline-ms", "5000", "--max-steps", "1000000000000",
               "--inline-max-us", "0")
    try:
        plain = mechd.Client(s.url, timeout=60, retries=0)
        results = {}

        def run(key):
            try:
                results[key] = plain.trajectory(slow_trajectory())
            except mechd.MechdError as e:
                results[key] = e

        t1 = threading.Thread(target=run, args=("first",))
        t1.start()
        check("a slow trajectory occupies the worker",
              wait_for(lambda: metric(plain, "mechd_workers_busy") == 1, 10))
        t2 = threading.Thread(target=run, args=("second",))
        t2.start()
        check("a second one waits in the queue",
              wait_for(lambda: metric(plain, "mechd_queue_depth") == 1, 10))
        e = expect_error("queue full, retries=0", mechd.ServerBusy,
                         lambda: plain.rigid_inertia(QUEUED_CUBE), 503, "/problems/queue-full")
        check("ServerBusy.retry_after from the Retry-After header",
              e is not None and e.retry_after is not None and e.retry_after >= 1, repr(e and e.retry_after))
        retries = []
        patient = mechd.Client(s.url, timeout=60, retries=20, max_retry_wait=1.0,
                               on_retry=lambda n, w, err: retries.append((n, w, type(err).__name__)))
        r = _answer(lambda: patient.rigid_inertia(QUEUED_CUBE))
        check("retry on 503: the request finally succeeds",
              isinstance(r, dict) and close(r["principal"]["moments"][0], 1 / 6, 1e-13), repr(r)[:200])
        check("retry on 503: it retried, after ServerBusy, waiting Retry-After capped at 1 s",
              len(retries) >= 1 and all(w == 1.0 and k == "ServerBusy" for _, w, k in retries),
              repr(retries))
        check("retries are bounded (at most 20)", len(retries) <= 20, repr(len(retries)))
        t1.join(60)
        t2.join(60)
        check("the slow requests end with BudgetExceeded (deadline)",
              all(isinstance(results.get(k), mechd.BudgetExceeded) for k in ("first", "second")),
              repr(results))
    finally:
        s.stop()
    # Bounded: with the pool busy and retries=1 the call gives up with ServerBusy.
    # A server of its own with a long deadline, so the worker and the queue stay
    # taken for the whole check however slow a loaded machine is; stopping it
    # ends the two slow requests (cancelled) without waiting for the deadline.
    s = Server("--workers", "1", "--queue", "1", "--deadline-ms", "120000", "--max-steps", "1000000000000",
               "--shutdown-grace-ms", "0", "--inline-max-us", "0")
    t3 = t4 = None
    try:
        plain = mechd.Client(s.url, timeout=180, retries=0)
        results = {}

        def run_slow(key):
            try:
                results[key] = plain.trajectory(slow_trajectory())
            except mechd.MechdError as e:
                results[key] = e

        t3 = threading.Thread(target=run_slow, args=("third",))
        t3.start()
        busy = wait_for(lambda: metric(plain, "mechd_workers_busy") == 1, 30)
        t4 = threading.Thread(target=run_slow, args=("fourth",))
        t4.start()
        queued = wait_for(lambda: metric(plain, "mechd_queue_depth") == 1, 30)
        check("a slow request runs and another waits (bounded-retry set-up)", busy and queued)
        once = []
        short = mechd.Client(s.url, timeout=60, retries=1, max_retry_wait=0.2,
                             on_retry=lambda n, w, err: once.append(w))
        e = _raised(lambda: short.rigid_inertia(QUEUED_CUBE))
        check("retries=1: one retry, then ServerBusy", isinstance(e, mechd.ServerBusy) and once == [0.2],
              repr((e, once)))
    finally:
        s.stop()
        for t in (t3, t4):
            if t is not None:
                t.join(60)


def _answer(fn):
    try:
        return fn()
    except mechd.MechdError as e:
        return e


class NoBatchClient(mechd.Client):
    batch_path = "/v1/no-batch-here"  # as an older server without /v1/batch would answer: 404


def test_batch(url):
    items = [("/v1/rigid/inertia", CUBE),
             {"operation": "/v1/relativity/boost", "request": {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [1, 0, 0]}}},
             ("/v1/relativity/velocity-addition", {"velocity": {"beta": [0.5, 0, 0]}, "frame_velocity": {"beta": [-0.5, 0, 0]}}),
             ("/v1/no/such", {})]
    for label, client, kw in (("server /v1/batch", mechd.Client(url), {}),
                              ("threads", mechd.Client(url), {"use_server": False, "concurrency": 3}),
                              ("fallback when the server has no batch", NoBatchClient(url), {"concurrency": 2})):
        res = _answer(lambda: client.batch(items, **kw))
        if not check("batch (%s): a list in order" % label, isinstance(res, list) and len(res) == 4, repr(res)[:300]):
            continue
        check("batch (%s): 1st answers 1/6" % label,
              isinstance(res[0], dict) and close(res[0]["principal"]["moments"][0], 1 / 6, 1e-13), repr(res[0])[:200])
        check("batch (%s): 2nd is a DomainError at /velocity/beta" % label,
              isinstance(res[1], mechd.DomainError) and any("/velocity/beta" in (x.get("pointer") or "") for x in res[1].errors),
              repr(res[1]))
        check("batch (%s): 3rd answers 0.8" % label,
              isinstance(res[2], dict) and close(res[2]["velocity_in_frame"]["beta"][0], 0.8, 1e-15), repr(res[2])[:200])
        check("batch (%s): 4th is an error (unknown operation)" % label,
              isinstance(res[3], mechd.MechdError), repr(res[3]))
    sb = mechd.Client(url)
    sb.batch(items[:1])
    check("server batch used when the server has /v1/batch", sb._server_batch is True)
    nb = NoBatchClient(url)
    nb.batch(items[:1])
    check("fallback remembered: the client stops asking for /v1/batch", nb._server_batch is False)
    many = [("/v1/relativity/velocity-addition",
             {"velocity": {"beta": [0.001 * i, 0, 0]}, "frame_velocity": {"beta": [0, 0, 0]}}) for i in range(150)]
    res = _answer(lambda: mechd.Client(url).batch(many))
    check("batch of 150 (two server chunks): all answered in order",
          isinstance(res, list) and len(res) == 150 and
          all(isinstance(r, dict) and close(r["velocity_in_frame"]["beta"][0], 0.001 * i, 1e-15)
              for i, r in enumerate(res)), repr(res)[:300])
    check("batch of nothing", mechd.Client(url).batch([]) == [])


# clients/curl/*.sh: the status each script's answer must have.
CURL_EXPECT_ERROR = {"error.sh"}


def test_curl(url):
    d = os.path.join(ROOT, "clients", "curl")
    scripts = sorted(f for f in os.listdir(d) if f.endswith(".sh"))
    check("clients/curl has scripts", len(scripts) >= 30, repr(scripts))
    m = mechd.Client(url)
    posts = {o["path"] for o in m.catalog()["operations"] if o.get("method", "POST") == "POST"}
    covered = set()
    # A .curlrc in CURL_HOME makes every script's curl print the HTTP status on a last line.
    import tempfile
    home = tempfile.mkdtemp(prefix="mechd-curlrc-")
    with open(os.path.join(home, ".curlrc"), "w") as rc:
        rc.write('write-out = "\\n%{http_code}"\n')
    env = dict(os.environ, MECHD_URL=url, CURL_HOME=home)
    for f in scripts:
        path = os.path.join(d, f)
        text = open(path, encoding="utf-8").read()
        check("%s: has a comment saying what the answer shows" % f,
              len(re.findall(r"^#(?!!).{10,}", text, re.M)) >= 1)
        for p in re.findall(r"\$\{MECHD_URL:-http://127\.0\.0\.1:8080\}(/v1/[a-z0-9/-]+)", text):
            covered.add(p)
        out = subprocess.run(["sh", path], capture_output=True, text=True, timeout=120, env=env)
        body, _, code = out.stdout.rpartition("\n")
        try:
            doc = json.loads(body)
        except ValueError:
            check("%s prints JSON" % f, False, repr(out.stdout[:300]) + repr(out.stderr[:300]))
            continue
        want_rc = 22 if f == "error.sh" else 0  # curl --fail-with-body: 22 on an HTTP error
        check("%s exits %d" % (f, want_rc), out.returncode == want_rc, repr(out.returncode))
        if f in CURL_EXPECT_ERROR:
            check("%s: HTTP 422 and a problem+json with errors[].pointer" % f,
                  code == "422" and isinstance(doc, dict) and doc.get("status") == 422 and
                  doc.get("type") == "/problems/domain-error" and
                  any(e.get("pointer") == "/velocity/beta" for e in doc.get("errors", [])), code + repr(doc)[:300])
        else:
            check("%s: HTTP 200 and an answer" % f,
                  code == "200" and isinstance(doc, dict) and "type" not in doc, code + repr(doc)[:300])
    missing = sorted(posts - covered)
    check("a curl script for every POST operation", not missing, repr(missing))


def main():
    s = Server()
    try:
        m = mechd.Client(s.url, timeout=120)
        test_success(m)
        test_errors(m, s.url)
        test_batch(s.url)
        test_curl(s.url)
    finally:
        s.stop()
    test_busy()


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a crash is a failure, not a pass
        import traceback
        traceback.print_exc()
        check("test ran to the end", False, "%s: %s" % (type(e).__name__, e))
    sys.exit(summary())
