#!/usr/bin/python3
"""test_python_package.py — the Python client as people install and use it.

Usage: /usr/bin/python3 test_python_package.py PATH/TO/mechd

Against a real mechd: `pip install --no-index --no-build-isolation` of a copy of
clients/python into a temporary directory (offline; the installed module is then
used for every check below, and its mechd-client command runs); a method for every
POST operation of GET /v1, with one keyword-only, type-hinted parameter per field of
the operation's request schema and the catalog's summary as its docstring, and the
checked-in generated region equal to what gen_operations.py makes from this server's
catalog; named parameters giving the closed-form answers; the bearer token (argument
and MECHD_TOKEN; 401 -> Unauthorized without it) against `mechd --token-file`, and
every clients/curl script with MECHD_TOKEN; ProblemError carrying type, status and
the JSON pointers; retries on a dropped connection (a proxy that closes the first
connections before answering), bounded in attempts and in total time, and on 503 with
Retry-After bounded by retry_total. Prints "N passed, M failed"; exits 1 on failure.
"""
import http.server
import importlib
import inspect
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_python_package.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SRC = os.path.join(ROOT, "clients", "python")
sys.dont_write_bytecode = True
from mechdtest import check, summary, start_mechd, stop_mechd  # noqa: E402

CUBE = {"bodies": [{"shape": "box", "mass": 1, "size": [1, 1, 1], "position": [0.5, 0.5, 0.5]}],
        "origin": [0, 0, 0]}


def close(a, b, rtol):
    return isinstance(a, (int, float)) and abs(a - b) <= rtol * abs(b)


def install(tmp):
    """pip-install a copy of clients/python into tmp/site; returns the site dir or None."""
    src = os.path.join(tmp, "src")
    shutil.copytree(SRC, src, ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    site = os.path.join(tmp, "site")
    out = subprocess.run([sys.executable, "-m", "pip", "install", "--no-index",
                          "--no-cache-dir", "--disable-pip-version-check", "--target", site, src],
                         capture_output=True, text=True, timeout=240)
    ok = check("pip install --no-index ./clients/python succeeds (offline, build isolation on: "
               "its backend needs nothing)", out.returncode == 0,
               out.stdout[-800:] + out.stderr[-800:])
    return site if ok else None


def test_installed(mechd, site, url):
    check("the installed package is the one imported",
          os.path.dirname(os.path.abspath(mechd.__file__)) == os.path.join(os.path.abspath(site), "mechd"),
          mechd.__file__)
    check("the installed package is typed (PEP 561 py.typed) and has __version__",
          os.path.isfile(os.path.join(site, "mechd", "py.typed"))
          and re.fullmatch(r"\d+\.\d+\.\d+", getattr(mechd, "__version__", "")), mechd.__file__)
    cli = os.path.join(site, "bin", "mechd-client")
    if check("pip installed the mechd-client command", os.path.exists(cli)):
        env = dict(os.environ, PYTHONPATH=site, MECHD_URL=url)
        env.pop("MECHD_TOKEN", None)
        out = subprocess.run([sys.executable, cli, "/v1/relativity/velocity-addition",
                              json.dumps({"velocity": {"beta": [0.5, 0, 0]}, "frame_velocity": {"beta": [-0.5, 0, 0]}})],
                             capture_output=True, text=True, timeout=60, env=env)
        try:
            beta = json.loads(out.stdout)["velocity_in_frame"]["beta"][0]
        except (ValueError, KeyError, TypeError, IndexError):
            beta = None
        check("mechd-client: 0.5c (+) 0.5c = 0.8c (relativistic addition, 1/(1+0.25))",
              close(beta, 0.8, 1e-15), repr(out.stdout[:200]) + out.stderr[-300:])


def schema_props(op):
    return list(((op.get("schema") or {}).get("properties") or {}).keys())


def test_catalog_methods(mechd, catalog, url):
    posts = [o for o in catalog["operations"] if o.get("method", "POST") == "POST"]
    hand = getattr(mechd, "HANDWRITTEN_OPERATIONS", {})
    missing, unnamed, undocumented, unhinted = [], [], [], []
    for o in posts:
        name = hand.get(o["path"]) or mechd.method_name(o["path"])
        fn = getattr(mechd.Client, name, None)
        if fn is None or (o["path"] not in hand and mechd.OPERATIONS.get(name) != o["path"]):
            missing.append(o["path"])
            continue
        if o["path"] in hand:
            continue
        sig = inspect.signature(fn)
        kw = [p for p in sig.parameters.values() if p.kind == p.KEYWORD_ONLY]
        props = schema_props(o)
        got = [p.name.rstrip("_") if p.name.rstrip("_") in props else p.name for p in kw]
        if got != props:
            unnamed.append((o["path"], got, props))
        summ = (o.get("summary") or "").strip()
        if not (fn.__doc__ or "").strip().startswith(summ[:60]) or not summ:
            undocumented.append(o["path"])
        if sig.return_annotation is inspect.Signature.empty or \
                any(p.annotation is inspect.Parameter.empty for p in kw):
            unhinted.append(o["path"])
    check("a Client method for every POST operation of GET /v1 (%d)" % len(posts), not missing, repr(missing))
    check("each method has one keyword-only parameter per request-schema field, in order",
          not unnamed, repr(unnamed[:3])[:600])
    check("each method's docstring starts with the catalog's summary", not undocumented, repr(undocumented))
    check("each method's parameters and return value carry type hints", not unhinted, repr(unhinted))
    gen = os.path.join(SRC, "gen_operations.py")
    out = subprocess.run([sys.executable, gen, "--url", url, "--check"], capture_output=True, text=True,
                         timeout=120)
    check("mechd.py's generated region matches gen_operations.py on this server's catalog",
          out.returncode == 0, out.stderr[-400:])


def test_named_and_problems(mechd, url):
    m = mechd.Client(url, timeout=60, token="")
    r = m.rigid_inertia(bodies=CUBE["bodies"], origin=[0, 0, 0])
    check("named parameters: the unit cube about its corner has moments 1/6, 11/12, 11/12",
          all(close(a, b, 1e-13) for a, b in zip(sorted(r["principal"]["moments"]), [1 / 6, 11 / 12, 11 / 12])),
          repr(r.get("principal")))
    r = m.relativity_velocity_addition({"velocity": {"beta": [0.5, 0, 0]}},
                                       frame_velocity={"beta": [-0.6, 0, 0]})
    check("body dict merged with a named parameter: 0.5 (+) 0.6 = 1.1/1.3",
          close(r["velocity_in_frame"]["beta"][0], 1.1 / 1.3, 1e-15), repr(r)[:200])
    try:
        m.rigid_inertia(bodies=CUBE["bodies"], no_such_field=1)
        check("an unknown named parameter is a TypeError", False)
    except TypeError:
        check("an unknown named parameter is a TypeError", True)
    try:
        m.relativity_boost(vectors=[[1, 0, 0, 0]], velocity={"beta": [1, 0, 0]})
        e = None
    except mechd.MechdError as x:
        e = x
    check("beta = 1: DomainError, a ValidationError and a ProblemError",
          isinstance(e, mechd.DomainError) and isinstance(e, mechd.ValidationError) and
          isinstance(e, mechd.ProblemError), repr(e))
    check("ProblemError carries status 422, the type and the JSON pointers",
          e is not None and e.status == 422 and e.type == "/problems/domain-error" and
          e.pointers == ["/velocity/beta"] and e.problem.get("status") == 422, repr(e and (e.status, e.type, e.pointers)))
    check("ProblemError carries the answer's request id", e is not None and bool(e.request_id), repr(e and e.request_id))
    try:
        mechd.Client("http://127.0.0.1:1", retries=0, token="").rigid_inertia(CUBE)
        f = None
    except mechd.MechdError as x:
        f = x
    check("no server: ConnectionFailed, not a ProblemError, status None",
          isinstance(f, mechd.ConnectionFailed) and not isinstance(f, mechd.ProblemError) and f.status is None,
          repr(f))


def test_token(mechd):
    tmp = tempfile.mkdtemp(prefix="mechd-token-")
    tok = "s3cret-" + os.urandom(8).hex()
    with open(os.path.join(tmp, "token"), "w") as f:
        f.write(tok + "\n")
    # A long deadline: under the sanitizers the slower curl examples take seconds.
    proc, port = start_mechd(MECHD, ["--token-file", os.path.join(tmp, "token"), "--deadline-ms", "300000"],
                             stderr=subprocess.DEVNULL)
    url = "http://127.0.0.1:%d" % port
    try:
        try:
            mechd.Client(url, token="", retries=0).rigid_inertia(CUBE)
            e = None
        except mechd.MechdError as x:
            e = x
        check("token server, no token: Unauthorized (401)", isinstance(e, mechd.Unauthorized) and e.status == 401,
              repr(e))
        r = mechd.Client(url, token=tok).rigid_inertia(CUBE)
        check("token= argument: the answer (cube about its corner: 1/6)",
              close(min(r["principal"]["moments"]), 1 / 6, 1e-13), repr(r)[:200])
        old = os.environ.get("MECHD_TOKEN")
        os.environ["MECHD_TOKEN"] = tok
        try:
            r = mechd.Client(url).rigid_inertia(CUBE)
        finally:
            if old is None:
                del os.environ["MECHD_TOKEN"]
            else:
                os.environ["MECHD_TOKEN"] = old
        check("MECHD_TOKEN from the environment is sent",
              close(min(r["principal"]["moments"]), 1 / 6, 1e-13), repr(r)[:200])
        try:
            mechd.Client(url, token="bad\r\nX-Injected: 1")
            check("a token with a line break is refused", False)
        except ValueError:
            check("a token with a line break is refused", True)
        # Every curl script with MECHD_TOKEN: 200 (error.sh: 422), never 401.
        home = tempfile.mkdtemp(prefix="mechd-curlrc-")
        with open(os.path.join(home, ".curlrc"), "w") as rc:
            rc.write('write-out = "\\n%{http_code}"\n')
        d = os.path.join(ROOT, "clients", "curl")
        bad = []
        scripts = sorted(f for f in os.listdir(d) if f.endswith(".sh"))
        for f in scripts:
            env = dict(os.environ, MECHD_URL=url, MECHD_TOKEN=tok, CURL_HOME=home)
            out = subprocess.run(["sh", os.path.join(d, f)], capture_output=True, text=True, timeout=120, env=env)
            code = out.stdout.rpartition("\n")[2]
            want = ("422", 22) if f == "error.sh" else ("200", 0)
            if (code, out.returncode) != want:
                bad.append((f, code, out.returncode))
            if f == "error.sh" and "/problems/domain-error" not in out.stdout:
                bad.append((f, "no problem+json printed"))
        check("every clients/curl script sends MECHD_TOKEN (%d scripts: 200 exit 0; error.sh 422, "
              "exit 22 like curl --fail-with-body, its problem+json printed)" % len(scripts),
              scripts and not bad, repr(bad[:5]))
        env = dict(os.environ, MECHD_URL=url, CURL_HOME=home)
        env.pop("MECHD_TOKEN", None)
        out = subprocess.run(["sh", os.path.join(d, "inertia.sh")], capture_output=True, text=True, timeout=60, env=env)
        check("without MECHD_TOKEN a curl script gets the 401 and exits non-zero (22)",
              out.stdout.rpartition("\n")[2] == "401" and out.returncode == 22
              and "/problems/unauthorized" in out.stdout, repr((out.returncode, out.stdout[-200:])))
        # The command line: --token-file, --url, a request from a file and from stdin.
        cli = [sys.executable, "-m", "mechd"]
        cenv = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(mechd.__file__))
                    if mechd.__file__.endswith("__init__.py") else os.path.dirname(mechd.__file__))
        cenv.pop("MECHD_TOKEN", None)
        cenv.pop("MECHD_URL", None)
        req = os.path.join(tmp, "req.json")
        with open(req, "w") as f:
            json.dump(CUBE, f)
        out = subprocess.run(cli + ["--url", url, "--token-file", os.path.join(tmp, "token"),
                                    "/v1/rigid/inertia", "@" + req],
                             capture_output=True, text=True, timeout=60, env=cenv)
        try:
            lo = min(json.loads(out.stdout)["principal"]["moments"])
        except (ValueError, KeyError):
            lo = None
        check("mechd-client --url --token-file PATH @FILE: the cube's 1/6", close(lo, 1 / 6, 1e-13),
              repr((out.returncode, out.stdout[:200], out.stderr[-200:])))
        out = subprocess.run(cli + ["--url", url, "--token-file", os.path.join(tmp, "token"),
                                    "/v1/rigid/inertia", "-"], input=json.dumps(CUBE),
                             capture_output=True, text=True, timeout=60, env=cenv)
        check("mechd-client ... PATH - reads the request from stdin", out.returncode == 0
              and '"principal"' in out.stdout, repr((out.returncode, out.stderr[-200:])))
        out = subprocess.run(cli + ["--url", url, "/v1/rigid/inertia", "@" + req],
                             capture_output=True, text=True, timeout=60, env=cenv)
        check("mechd-client without the token: exit 1 and the 401 problem printed",
              out.returncode == 1 and "/problems/unauthorized" in out.stdout,
              repr((out.returncode, out.stdout[:200])))
    finally:
        stop_mechd(proc)
        shutil.rmtree(tmp, ignore_errors=True)


class Flaky:
    """An HTTP front on 127.0.0.1 that closes the first `drops` connections after reading
    the request (no answer), answers `busy` requests with 503 + Retry-After, and forwards
    the rest to `upstream`. .seen counts requests."""

    def __init__(self, upstream, drops=0, busy=0, retry_after="0"):
        self.upstream, self.drops, self.busy, self.retry_after = upstream, drops, busy, retry_after
        self.seen = 0
        self.lock = threading.Lock()
        outer = self

        class H(http.server.BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def log_message(self, *a):
                pass

            def do_POST(self):
                body = self.rfile.read(int(self.headers.get("Content-Length", "0")))
                with outer.lock:
                    outer.seen += 1
                    n = outer.seen
                if n <= outer.drops:
                    self.connection.shutdown(socket.SHUT_RDWR)
                    self.close_connection = True
                    return
                if n <= outer.drops + outer.busy:
                    b = b'{"type":"/problems/queue-full","title":"busy","status":503}'
                    self.send_response(503)
                    self.send_header("Content-Type", "application/problem+json")
                    self.send_header("Retry-After", outer.retry_after)
                    self.send_header("Content-Length", str(len(b)))
                    self.end_headers()
                    self.wfile.write(b)
                    return
                req = urllib.request.Request(outer.upstream + self.path, data=body, method="POST",
                                             headers={"Content-Type": "application/json"})
                with urllib.request.urlopen(req, timeout=60) as r:
                    b = r.read()
                    self.send_response(r.status)
                    self.send_header("Content-Type", r.headers.get("Content-Type"))
                    self.send_header("Content-Length", str(len(b)))
                    self.end_headers()
                    self.wfile.write(b)

        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), H)
        self.url = "http://127.0.0.1:%d" % self.httpd.server_address[1]
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()

    def stop(self):
        self.httpd.shutdown()
        self.httpd.server_close()


def test_retries(mechd, url):
    f = Flaky(url, drops=2)
    try:
        seen = []
        c = mechd.Client(f.url, retries=3, backoff=0.01, token="",
                         on_retry=lambda n, w, e: seen.append((n, round(w, 4), type(e).__name__)))
        r = c.rigid_inertia(CUBE)
        check("two dropped connections, then the answer (cube: 1/6)",
              close(min(r["principal"]["moments"]), 1 / 6, 1e-13), repr(r)[:200])
        check("retried twice after ConnectionFailed with doubling back-off (0.01, 0.02 s)",
              seen == [(1, 0.01, "ConnectionFailed"), (2, 0.02, "ConnectionFailed")], repr(seen))
    finally:
        f.stop()
    f = Flaky(url, drops=10 ** 6)
    try:
        try:
            mechd.Client(f.url, retries=2, backoff=0.01, token="").rigid_inertia(CUBE)
            e = None
        except mechd.MechdError as x:
            e = x
        check("always dropped: ConnectionFailed after retries + 1 = 3 attempts",
              isinstance(e, mechd.ConnectionFailed) and f.seen == 3, repr((e, f.seen)))
    finally:
        f.stop()
    f = Flaky(url, drops=10 ** 6)
    try:
        try:
            mechd.Client(f.url, retries=50, backoff=5.0, retry_total=1.0, token="").rigid_inertia(CUBE)
            e = None
        except mechd.MechdError as x:
            e = x
        check("retry_total bounds the retries: a 5 s back-off does not start within 1 s (1 attempt)",
              isinstance(e, mechd.ConnectionFailed) and f.seen == 1, repr((e, f.seen)))
    finally:
        f.stop()
    f = Flaky(url, busy=2, retry_after="0")
    try:
        seen = []
        r = mechd.Client(f.url, retries=3, token="",
                         on_retry=lambda n, w, e: seen.append(type(e).__name__)).rigid_inertia(CUBE)
        check("503 with Retry-After twice, then the answer",
              close(min(r["principal"]["moments"]), 1 / 6, 1e-13) and seen == ["ServerBusy", "ServerBusy"],
              repr((seen, r))[:200])
    finally:
        f.stop()
    f = Flaky(url, busy=10 ** 6, retry_after="30")
    try:
        try:
            mechd.Client(f.url, retries=10, max_retry_wait=60, retry_total=5.0, token="").rigid_inertia(CUBE)
            e = None
        except mechd.MechdError as x:
            e = x
        check("Retry-After: 30 beyond retry_total = 5 s: ServerBusy at once (1 attempt), retry_after 30",
              isinstance(e, mechd.ServerBusy) and f.seen == 1 and e.retry_after == 30, repr((e, f.seen)))
    finally:
        f.stop()


def test_cli_and_client(mechd, url):
    """--help, the context manager's connection reuse, Timeout."""
    cli = [sys.executable, "-m", "mechd"]
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(mechd.__file__)))
    out = subprocess.run(cli + ["--help"], capture_output=True, text=True, timeout=60, env=env)
    check("mechd-client --help: usage with --url and --token-file, exit 0, no request sent",
          out.returncode == 0 and "--url" in out.stdout and "--token-file" in out.stdout
          and "127.0.0.1:8080--help" not in out.stdout + out.stderr, out.stdout[:300] + out.stderr[-300:])
    out = subprocess.run(cli + ["--url", "http://127.0.0.1:1", "/v1"], capture_output=True, text=True,
                         timeout=60, env=env)
    check("mechd-client with no server: exit 3 and a message on stderr",
          out.returncode == 3 and "mechd-client:" in out.stderr, repr((out.returncode, out.stderr[-200:])))
    with mechd.Client(url, token="") as c:
        c.rigid_inertia(CUBE)
        s1 = c._local.conn.sock.getsockname()
        c.rigid_inertia(CUBE)
        s2 = c._local.conn.sock.getsockname()
        conn = c._local.conn
    check("Client as a context manager reuses one connection for two requests (same local port)",
          s1 == s2, repr((s1, s2)))
    check("... and closes it at the end of the with block", conn.sock is None, repr(conn.sock))
    # A server that accepts and never answers: Timeout, under ConnectionFailed and MechdError,
    # not retried (one connection), after about the timeout.
    lsock = socket.socket()
    lsock.bind(("127.0.0.1", 0))
    lsock.listen(8)
    accepted = []

    def hold():
        while True:
            try:
                cs, _ = lsock.accept()
            except OSError:
                return
            accepted.append(cs)

    threading.Thread(target=hold, daemon=True).start()
    t0 = time.monotonic()
    try:
        mechd.Client("http://127.0.0.1:%d" % lsock.getsockname()[1], timeout=0.5, retries=3,
                     token="").rigid_inertia(CUBE)
        e = None
    except mechd.MechdError as x:
        e = x
    dt = time.monotonic() - t0
    check("no answer within timeout=0.5 s: mechd.Timeout (a ConnectionFailed, a MechdError), "
          "not retried", isinstance(e, mechd.Timeout) and isinstance(e, mechd.ConnectionFailed)
          and len(accepted) == 1 and dt < 10, repr((e, len(accepted), dt)))
    lsock.close()
    for cs in accepted:
        cs.close()


def test_wheel(tmp):
    """The wheel of `make dist`, built with the standard library, installed with
    pip --no-index into a venv that has no setuptools."""
    sys.path.insert(0, SRC)
    import mechd_build
    sys.path.remove(SRC)
    out_dir = os.path.join(tmp, "dist")
    name = mechd_build.build_wheel(out_dir)
    whl = os.path.join(out_dir, name)
    import zipfile
    import hashlib
    import base64
    with zipfile.ZipFile(whl) as z:
        names = z.namelist()
        rec = z.read([n for n in names if n.endswith(".dist-info/RECORD")][0]).decode().splitlines()
        bad = []
        for line in rec:
            fn, h, size = line.rsplit(",", 2)
            if not h:
                continue
            data = z.read(fn)
            want = "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            if h != want or int(size) != len(data):
                bad.append(fn)
        wheel_meta = z.read([n for n in names if n.endswith(".dist-info/WHEEL")][0]).decode()
    check("the wheel is pure (py3-none-any) with mechd/__init__.py, __main__.py, py.typed, "
          "entry points", name.endswith("-py3-none-any.whl") and "Root-Is-Purelib: true" in wheel_meta
          and {"mechd/__init__.py", "mechd/__main__.py", "mechd/py.typed"} <= set(names)
          and any(n.endswith("entry_points.txt") for n in names), repr(names))
    check("its RECORD holds the right sha256 and size of every file", not bad and len(rec) == len(names),
          repr(bad))
    again = os.path.join(tmp, "dist2", mechd_build.build_wheel(os.path.join(tmp, "dist2")))
    check("building it twice gives the same bytes (fixed timestamps)",
          open(whl, "rb").read() == open(again, "rb").read())
    import ast
    try:
        for f in ("mechd.py", "mechd_build.py"):
            ast.parse(open(os.path.join(SRC, f)).read(), feature_version=(3, 8))
        syntax = True
    except SyntaxError as e:
        syntax = e
    check("mechd.py and its build backend are Python 3.8 syntax", syntax is True, repr(syntax))
    venv = os.path.join(tmp, "venv")
    out = subprocess.run([sys.executable, "-m", "venv", venv], capture_output=True, text=True, timeout=240)
    if not check("python3 -m venv works", out.returncode == 0, out.stderr[-300:]):
        return
    py = os.path.join(venv, "bin", "python")
    subprocess.run([py, "-m", "pip", "uninstall", "-q", "-y", "setuptools", "wheel"],
                   capture_output=True, timeout=240)
    out = subprocess.run([py, "-m", "pip", "install", "--no-index", "--disable-pip-version-check", whl],
                         capture_output=True, text=True, timeout=240)
    ok = subprocess.run([py, "-c", "import setuptools"], capture_output=True).returncode != 0
    check("pip install --no-index dist/*.whl in a venv without setuptools", out.returncode == 0 and ok,
          out.stdout[-300:] + out.stderr[-300:])
    out = subprocess.run([py, "-c", "import mechd, os; print(mechd.__version__, "
                          "os.path.exists(os.path.join(os.path.dirname(mechd.__file__), 'py.typed')))"],
                         capture_output=True, text=True, timeout=60)
    check("the installed wheel imports, with __version__ and py.typed",
          out.returncode == 0 and out.stdout.split() == [mechd_build.version(), "True"], out.stdout + out.stderr)
    out = subprocess.run([os.path.join(venv, "bin", "mechd-client"), "--version"], capture_output=True,
                         text=True, timeout=60)
    check("the wheel's mechd-client command runs", out.returncode == 0 and mechd_build.version() in out.stdout,
          out.stdout + out.stderr)


def main():
    tmp = tempfile.mkdtemp(prefix="mechd-pip-")
    proc, port = start_mechd(MECHD, ["--deadline-ms", "300000"], stderr=subprocess.DEVNULL)
    url = "http://127.0.0.1:%d" % port
    try:
        site = install(tmp)
        sys.path.insert(0, site if site else SRC)
        mechd = importlib.import_module("mechd")
        with urllib.request.urlopen(url + "/v1", timeout=60) as r:
            catalog = json.load(r)
        if site:
            test_installed(mechd, site, url)
        test_catalog_methods(mechd, catalog, url)
        test_named_and_problems(mechd, url)
        test_retries(mechd, url)
        test_cli_and_client(mechd, url)
        test_token(mechd)
        test_wheel(tmp)
    finally:
        stop_mechd(proc)
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a crash is a failure, not a pass
        import traceback
        traceback.print_exc()
        check("test ran to the end", False, "%s: %s" % (type(e).__name__, e))
    sys.exit(summary())
