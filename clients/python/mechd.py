"""mechd.py — a Python client for mechd, the mechanics computation server.

One module, standard library only (urllib, json, threading), so it runs in
locked-down grader images: copy this file next to your script.

    import mechd
    m = mechd.Client("http://127.0.0.1:8080")
    cube = m.rigid_inertia({"bodies": [{"shape": "box", "mass": 1, "size": [1, 1, 1],
                                        "position": [0.5, 0.5, 0.5]}], "origin": [0, 0, 0]})
    print(cube["principal"]["moments"])          # [1/6, 11/12, 11/12]
    try:
        m.relativity_boost(vectors=[[1, 0, 0, 0]], velocity={"beta": [1, 0, 0]})
    except mechd.DomainError as e:               # a ValidationError: 422
        print(e.status, e.type, e.errors)        # 422 /problems/domain-error [{pointer, detail}]

Every operation of GET /v1 is a method named after its path (/v1/rigid/inertia
-> rigid_inertia, /v1/relativity/kinematics/decay -> relativity_kinematics_decay,
/v1/trajectory -> trajectory); each takes the request body as a dict and/or as
keyword arguments (merged, keywords win). call(path, body) reaches any path.

Errors are problem+json (RFC 9457) turned into exceptions that carry it:
MechdError(.status, .type, .title, .detail, .errors, .problem, .retry_after)
  BadRequest (400 malformed JSON, or GET without ?request=), NotFound (404), MethodNotAllowed (405),
  PayloadTooLarge (413), UnsupportedMediaType (415),
  ValidationError (422 validation-error) > DomainError (422 domain-error),
    > AnswerTooLarge (422 answer-too-large: more samples than --max-samples; .limit, .requested),
  BudgetExceeded (422, .progress), NumericalFailure (422),
  InternalError (500), ServerBusy (503 queue full, .retry_after) > ShuttingDown (503 cancelled),
  ConnectionFailed (no HTTP answer; .status is None).
A 503 is retried after its Retry-After (at most `retries` times, each wait
capped by `max_retry_wait` seconds) before ServerBusy is raised.

batch(items) runs many requests: through POST /v1/batch when the server has it
(chunks of 100), else with `concurrency` threads; it returns, in order, each
answer or the MechdError it raised (never raises for one bad item).
"""
import json
import socket
import threading
import time
import urllib.error
import urllib.parse
import urllib.request
from concurrent.futures import ThreadPoolExecutor

__all__ = ["Client", "MechdError", "BadRequest", "NotFound", "MethodNotAllowed",
           "PayloadTooLarge", "UnsupportedMediaType", "ValidationError", "DomainError",
           "AnswerTooLarge", "BudgetExceeded", "NumericalFailure", "InternalError", "ServerBusy", "ShuttingDown",
           "ConnectionFailed", "OPERATIONS", "resolve_pointer", "check_example"]

DEFAULT_URL = "http://127.0.0.1:8080"


class MechdError(Exception):
    """A failed request, with the server's problem details (RFC 9457)."""

    def __init__(self, status=None, problem=None, retry_after=None, message=None):
        self.problem = problem if isinstance(problem, dict) else {}
        self.status = status
        self.type = self.problem.get("type")
        self.title = self.problem.get("title")
        self.detail = self.problem.get("detail") or message
        self.errors = self.problem.get("errors") or []
        self.retry_after = retry_after
        text = "%s %s: %s" % (status if status is not None else "-", self.title or type(self).__name__,
                              self.detail or "")
        if self.errors:
            text += " [" + "; ".join("%s: %s" % (e.get("pointer"), e.get("detail"))
                                     for e in self.errors if isinstance(e, dict)) + "]"
        super().__init__(text)


class BadRequest(MechdError):
    """400: the body is not valid JSON (detail has line and column), or an operation was fetched
    with GET without ?request= (type /problems/request-missing)."""


class NotFound(MechdError):
    """404: no such path."""


class MethodNotAllowed(MechdError):
    """405: the path exists with another method."""


class PayloadTooLarge(MechdError):
    """413: the body is over the server's limit."""


class UnsupportedMediaType(MechdError):
    """415: the body was not sent as application/json."""


class ValidationError(MechdError):
    """422: the request breaks the operation's schema; .errors names the fields by JSON pointer."""


class DomainError(ValidationError):
    """422: physically impossible input (beta >= 1, m <= 0, r <= 2GM/c^2)."""


class AnswerTooLarge(ValidationError):
    """422: the request asks for more samples in all (a batch's items summed) than the server's
    --max-samples; .errors names the field where the sum passes .limit; nothing was computed."""

    @property
    def limit(self):
        return self.problem.get("limit")

    @property
    def requested(self):
        return self.problem.get("requested")


class BudgetExceeded(MechdError):
    """422: a step, sample or deadline budget ran out; .progress says how far it got."""

    @property
    def progress(self):
        return self.problem.get("progress")


class NumericalFailure(MechdError):
    """422: the numerics failed (non-finite result, step-size underflow)."""


class InternalError(MechdError):
    """500: a bug in mechd; the server log has the request id."""


class ServerBusy(MechdError):
    """503: the compute queue is full; retry after .retry_after seconds."""


class ShuttingDown(ServerBusy):
    """503: the server is shutting down and cancelled the request."""


class ConnectionFailed(MechdError):
    """No HTTP answer (refused, reset, timed out); .status is None."""


_BY_TYPE = {
    "/problems/malformed-json": BadRequest,
    "/problems/not-found": NotFound,
    "/problems/method-not-allowed": MethodNotAllowed,
    "/problems/body-too-large": PayloadTooLarge,
    "/problems/unsupported-media-type": UnsupportedMediaType,
    "/problems/validation-error": ValidationError,
    "/problems/domain-error": DomainError,
    "/problems/answer-too-large": AnswerTooLarge,
    "/problems/compute-budget-exceeded": BudgetExceeded,
    "/problems/numerical-failure": NumericalFailure,
    "/problems/queue-full": ServerBusy,
    "/problems/cancelled": ShuttingDown,
    "/problems/internal-error": InternalError,
}
_BY_STATUS = {400: BadRequest, 404: NotFound, 405: MethodNotAllowed, 413: PayloadTooLarge,
              415: UnsupportedMediaType, 422: ValidationError, 500: InternalError, 503: ServerBusy}


def error_for(status, problem, retry_after=None, message=None):
    """The MechdError subclass for a problem+json (by its type, else by status)."""
    ptype = problem.get("type") if isinstance(problem, dict) else None
    cls = _BY_TYPE.get(ptype) or _BY_STATUS.get(status) or MechdError
    return cls(status, problem, retry_after, message)


# Every POST operation of mechd v1: method name -> path (GET /v1 is the source of truth;
# call(path, body) reaches paths added later).
OPERATIONS = {
    "vectors": "/v1/vectors",
    "tensor_symmetric": "/v1/tensor/symmetric",
    "rotation_convert": "/v1/rotation/convert",
    "rotation_compose": "/v1/rotation/compose",
    "rotation_apply": "/v1/rotation/apply",
    "rotation_euler_rates": "/v1/rotation/euler-rates",
    "rigid_inertia": "/v1/rigid/inertia",
    "rigid_rotate": "/v1/rigid/rotate",
    "rigid_top": "/v1/rigid/top",
    "rigid_stability": "/v1/rigid/stability",
    "small_oscillations": "/v1/small-oscillations",
    "relativity_boost": "/v1/relativity/boost",
    "relativity_velocity_addition": "/v1/relativity/velocity-addition",
    "relativity_interval": "/v1/relativity/interval",
    "relativity_worldline": "/v1/relativity/worldline",
    "relativity_doppler": "/v1/relativity/doppler",
    "relativity_fields": "/v1/relativity/fields",
    "relativity_kinematics_invariant_mass": "/v1/relativity/kinematics/invariant-mass",
    "relativity_kinematics_decay": "/v1/relativity/kinematics/decay",
    "relativity_kinematics_compton": "/v1/relativity/kinematics/compton",
    "relativity_kinematics_collision": "/v1/relativity/kinematics/collision",
    "gr_schwarzschild": "/v1/gr/schwarzschild",
    "gr_geodesic": "/v1/gr/geodesic",
    "hamiltonian_flow": "/v1/hamiltonian/flow",
    "hamiltonian_liouville": "/v1/hamiltonian/liouville",
    "hamiltonian_poincare": "/v1/hamiltonian/poincare",
    "trajectory": "/v1/trajectory",
    "compare": "/v1/compare",
    "frames_effective_force": "/v1/frames/effective-force",
    "earth_gravity": "/v1/earth/gravity",
    "earth_tides": "/v1/earth/tides",
    "scenes_falling_object": "/v1/scenes/falling-object",
    "scenes_vertical_shot": "/v1/scenes/vertical-shot",
    "scenes_cannonball": "/v1/scenes/cannonball",
    "scenes_foucault": "/v1/scenes/foucault",
    "scenes_rotating_table": "/v1/scenes/rotating-table",
}


def method_name(path):
    """/v1/relativity/velocity-addition -> relativity_velocity_addition."""
    p = path[4:] if path.startswith("/v1/") else path.lstrip("/")
    return p.replace("/", "_").replace("-", "_")


def resolve_pointer(doc, pointer):
    """The value at an RFC 6901 JSON pointer ("/principal/moments/0"); KeyError if absent."""
    if pointer in ("", None):
        return doc
    if not pointer.startswith("/"):
        raise KeyError(pointer)
    for tok in pointer[1:].split("/"):
        tok = tok.replace("~1", "/").replace("~0", "~")
        try:
            doc = doc[int(tok)] if isinstance(doc, list) else doc[tok]
        except (IndexError, ValueError, TypeError, KeyError):
            raise KeyError(pointer) from None
    return doc


def check_example(example, answer):
    """(value at the example's pointer, whether it matches the notes' answer within rounding)."""
    na = example["notes_answer"]
    got = resolve_pointer(answer, na["pointer"])
    r = na.get("rounding", {})
    tol = r.get("absolute", 0.0) + r.get("relative", 0.0) * abs(na["value"])
    ok = isinstance(got, (int, float)) and not isinstance(got, bool) and abs(got - na["value"]) <= tol
    return got, ok


class Client:
    """A mechd server at base_url. Thread-safe: one Client may be shared by threads.

    timeout: socket timeout per request (s). retries: how many times a 503 is
    retried (0: never). max_retry_wait: cap on each wait (s), whatever Retry-After
    says. on_retry(attempt, wait_seconds, error): optional hook called before each
    retry's sleep (for logging). batch_path: the server's batch operation."""

    batch_path = "/v1/batch"
    batch_limit = 100

    def __init__(self, base_url=DEFAULT_URL, timeout=60.0, retries=3, max_retry_wait=30.0,
                 on_retry=None, user_agent="mechd.py"):
        self.base_url = base_url.rstrip("/")
        self.timeout = timeout
        self.retries = max(0, int(retries))
        self.max_retry_wait = max_retry_wait
        self.on_retry = on_retry
        self.user_agent = user_agent
        self._server_batch = None  # None: unknown yet; False: the server has no batch
        self._lock = threading.Lock()

    # -- low level ------------------------------------------------------------------
    def request(self, method, path, data=None, content_type="application/json", query=None):
        """One HTTP exchange without retries: returns (status, headers dict, body bytes).
        Raises ConnectionFailed when no HTTP answer comes back."""
        url = self.base_url + path
        if query:
            url += "?" + urllib.parse.urlencode(query)
        headers = {"Accept": "application/json, application/problem+json",
                   "User-Agent": self.user_agent}
        if data is not None and content_type:
            headers["Content-Type"] = content_type
        req = urllib.request.Request(url, data=data, method=method, headers=headers)
        try:
            with urllib.request.urlopen(req, timeout=self.timeout) as resp:
                return resp.status, {k.lower(): v for k, v in resp.getheaders()}, resp.read()
        except urllib.error.HTTPError as e:
            try:
                body = e.read()
            finally:
                e.close()
            return e.code, {k.lower(): v for k, v in (e.headers or {}).items()}, body
        except (urllib.error.URLError, socket.timeout, ConnectionError, OSError) as e:
            reason = getattr(e, "reason", e)
            raise ConnectionFailed(None, None, None, "%s %s: %s" % (method, url, reason)) from None

    def _once(self, method, path, data, content_type):
        status, headers, body = self.request(method, path, data, content_type)
        try:
            doc = json.loads(body.decode("utf-8")) if body else None
        except (ValueError, UnicodeDecodeError):
            doc = None
        if 200 <= status < 300:
            if doc is None and body:
                raise MechdError(status, None, None, "the answer is not JSON: %r" % body[:200])
            return doc
        retry_after = None
        if "retry-after" in headers:
            try:
                retry_after = max(0.0, float(headers["retry-after"]))
            except ValueError:
                retry_after = None
        message = None if isinstance(doc, dict) else (body[:200].decode("utf-8", "replace") or
                                                       "HTTP %d" % status)
        raise error_for(status, doc, retry_after, message)

    def send(self, method, path, data=None, content_type="application/json"):
        """Send raw bytes (retrying 503s); returns the parsed JSON answer or raises MechdError."""
        attempt = 0
        while True:
            try:
                return self._once(method, path, data, content_type)
            except ServerBusy as e:
                if attempt >= self.retries:
                    raise
                attempt += 1
                wait = e.retry_after if e.retry_after is not None else 1.0
                wait = min(max(wait, 0.05), self.max_retry_wait)
                if self.on_retry:
                    self.on_retry(attempt, wait, e)
                time.sleep(wait)

    def call(self, path, body=None, method=None):
        """POST body (a dict) as JSON to path, or GET when body is None; the answer as a dict."""
        if method is None:
            method = "GET" if body is None else "POST"
        data = None if body is None else json.dumps(body, allow_nan=False).encode("utf-8")
        return self.send(method, path, data)

    # -- resources ------------------------------------------------------------------
    def catalog(self):
        """GET /v1: every operation with its summary, schema and example request."""
        return self.call("/v1")

    def examples(self):
        """GET /v1/examples: the course notes' worked examples (a list)."""
        return self.call("/v1/examples")["examples"]

    def example(self, example_id):
        """One example of GET /v1/examples by id; KeyError if there is none."""
        for e in self.examples():
            if e["id"] == example_id:
                return e
        raise KeyError(example_id)

    def run_example(self, example):
        """Run an example (a dict or its id): (answer, value at its pointer, matches the notes)."""
        if isinstance(example, str):
            example = self.example(example)
        answer = self.call(example["operation"], example["request"])
        got, ok = check_example(example, answer)
        return answer, got, ok

    def integrators(self):
        """GET /v1/integrators: the ODE methods and accuracy presets."""
        return self.call("/v1/integrators")

    def health(self):
        """True when GET /healthz answers 2xx."""
        status, _, _ = self.request("GET", "/healthz")
        return 200 <= status < 300

    def check(self, operation, request, pointer, value, relative=None, absolute=None,
              significant_figures=None):
        """POST /v1/check: grade a student's value at pointer of operation's answer."""
        tol = {k: v for k, v in (("relative", relative), ("absolute", absolute),
                                 ("significant_figures", significant_figures)) if v is not None}
        body = {"operation": operation, "request": request,
                "answer": {"pointer": pointer, "value": value}}
        if tol:
            body["tolerance"] = tol
        return self.call("/v1/check", body)

    # -- many requests ----------------------------------------------------------------
    def batch(self, items, concurrency=4, use_server=True):
        """Run many operations; items are (path, body) pairs or {"operation", "request"} dicts.
        Returns a list in the same order: the answer dict, or the MechdError for that item.
        Uses POST /v1/batch when the server has it (and use_server), else `concurrency`
        threads (bounded, >= 1)."""
        norm = []
        for it in items:
            if isinstance(it, dict):
                norm.append((it["operation"], it["request"]))
            else:
                path, body = it
                norm.append((path, body))
        if not norm:
            return []
        if use_server and self._server_batch is not False:
            try:
                out = []
                for i in range(0, len(norm), self.batch_limit):
                    out.extend(self._server_batch_chunk(norm[i:i + self.batch_limit]))
                with self._lock:
                    self._server_batch = True
                return out
            except (NotFound, MethodNotAllowed):
                with self._lock:
                    self._server_batch = False  # an older server: use threads from now on
        return self._thread_batch(norm, max(1, int(concurrency)))

    def _server_batch_chunk(self, chunk):
        doc = self.call(self.batch_path, {"operations": [{"operation": p, "request": b}
                                                         for p, b in chunk]})
        results = doc.get("results") if isinstance(doc, dict) else None
        if not isinstance(results, list) or len(results) != len(chunk):
            raise MechdError(200, None, None, "malformed batch answer")
        out = []
        for r in results:
            st = r.get("status")
            if st == 200:
                out.append(r.get("body"))
            else:
                out.append(error_for(st, r.get("problem") or {}))
        return out

    def _thread_batch(self, norm, concurrency):
        def one(pb):
            try:
                return self.call(pb[0], pb[1])
            except MechdError as e:
                return e
        with ThreadPoolExecutor(max_workers=min(concurrency, len(norm))) as pool:
            return list(pool.map(one, norm))


def _make_operation(name, path):
    def op(self, body=None, **fields):
        req = dict(body or {})
        req.update(fields)
        return self.call(path, req)
    op.__name__ = name
    op.__doc__ = "POST %s (the request as a dict and/or keyword arguments); the answer as a dict." % path
    return op


for _name, _path in OPERATIONS.items():
    setattr(Client, _name, _make_operation(_name, _path))
del _name, _path


def _main(argv):
    """python3 mechd.py PATH [JSON-BODY|-] : print the answer (MECHD_URL picks the server)."""
    import os
    import sys
    if len(argv) < 2:
        sys.stderr.write("usage: mechd.py PATH [JSON-BODY | -]   (MECHD_URL=%s)\n" % DEFAULT_URL)
        return 2
    body = None
    if len(argv) > 2:
        body = json.loads(sys.stdin.read() if argv[2] == "-" else argv[2])
    client = Client(os.environ.get("MECHD_URL", DEFAULT_URL))
    try:
        print(json.dumps(client.call(argv[1], body), indent=2))
        return 0
    except MechdError as e:
        print(json.dumps(e.problem or {"detail": e.detail}, indent=2))
        return 1


if __name__ == "__main__":
    import sys
    sys.exit(_main(sys.argv))
