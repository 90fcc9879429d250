"""mechd.py — a Python client for mechd, the mechanics computation server.

One module, standard library only (urllib, json, threading), so it runs in
locked-down grader images: `pip install ./clients/python` (offline: pip needs
nothing but setuptools), or copy this file next to your script.

    import mechd
    m = mechd.Client("http://127.0.0.1:8080", token=None)   # token: else $MECHD_TOKEN
    cube = m.rigid_inertia(bodies=[{"shape": "box", "mass": 1, "size": [1, 1, 1],
                                    "position": [0.5, 0.5, 0.5]}], origin=[0, 0, 0])
    print(cube["principal"]["moments"])          # [1/6, 11/12, 11/12]
    try:
        m.relativity_boost(vectors=[[1, 0, 0, 0]], velocity={"beta": [1, 0, 0]})
    except mechd.DomainError as e:               # a ValidationError, a ProblemError: 422
        print(e.status, e.type, e.pointers)      # 422 /problems/domain-error ['/velocity/beta']

Every POST operation of GET /v1 is a method named after its path (/v1/rigid/inertia
-> rigid_inertia, /v1/relativity/kinematics/decay -> relativity_kinematics_decay,
/v1/trajectory -> trajectory), with one keyword-only, type-hinted parameter per
field of the request schema and the catalog's summary and field descriptions as
its docstring. These methods are GENERATED from the catalog by
clients/python/gen_operations.py into the marked region below (checked in; the
test suite checks it against a running server's GET /v1). Each also takes the
request body as a dict (merged, keywords that are not None win); call(path, body)
reaches any path.

Errors are problem+json (RFC 9457) turned into exceptions that carry it:
MechdError(.status, .type, .title, .detail, .errors, .pointers, .problem,
.retry_after, .request_id)
  ProblemError: the server answered with an error status:
    BadRequest (400 malformed JSON, or GET without ?request=), Unauthorized (401 token missing
    or wrong), NotFound (404), MethodNotAllowed (405), PayloadTooLarge (413),
    UnsupportedMediaType (415),
    ValidationError (422 validation-error) > DomainError (422 domain-error),
      > AnswerTooLarge (422 answer-too-large: more samples than --max-samples; .limit, .requested),
    BudgetExceeded (422, .progress), NumericalFailure (422),
    InternalError (500), ServerBusy (503 queue full, .retry_after) > ShuttingDown (503 cancelled),
  ConnectionFailed (no HTTP answer; .status is None).

Retries. mechd's POST operations are pure computations (no state changes on the
server), so sending one again is safe. A 503 is retried after its Retry-After
(each wait capped by `max_retry_wait`); a connection refused, reset or closed
before an answer is retried with exponential back-off (`backoff`, doubling, capped
by `max_retry_wait`). Both count towards `retries` attempts and stop once
`retry_total` seconds have passed since the first attempt. A timeout (no answer
within `timeout`) is not retried: the server is computing, and asking again
would only double its work.

batch(items) runs many requests: through POST /v1/batch when the server has it
(chunks of 100), else with `concurrency` threads; it returns, in order, each
answer or the MechdError it raised (never raises for one bad item).
"""
import http.client
import json
import os
import socket
import threading
import time
import urllib.error
import urllib.parse
import urllib.request
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

__all__ = ["Client", "MechdError", "ProblemError", "BadRequest", "Unauthorized", "NotFound", "MethodNotAllowed",
           "PayloadTooLarge", "UnsupportedMediaType", "ValidationError", "DomainError",
           "AnswerTooLarge", "BudgetExceeded", "NumericalFailure", "InternalError", "ServerBusy", "ShuttingDown",
           "ConnectionFailed", "Timeout", "OPERATIONS", "resolve_pointer", "check_example",
           "__version__"]

__version__ = "0.2.0"

DEFAULT_URL = "http://127.0.0.1:8080"


class MechdError(Exception):
    """A failed request, with the server's problem details (RFC 9457) when it answered.

    .status: HTTP status (None: no answer); .type, .title, .detail: the problem's members;
    .errors: [{pointer, detail}, ...]; .pointers: the JSON pointers of .errors (the request
    fields at fault); .problem: the whole problem+json dict; .retry_after: seconds from a
    Retry-After header (or None); .request_id: the X-Request-Id of the answer (or None)."""

    def __init__(self, status: Optional[int] = None, problem: Optional[Dict[str, Any]] = None,
                 retry_after: Optional[float] = None, message: Optional[str] = None,
                 request_id: Optional[str] = None):
        self.problem = problem if isinstance(problem, dict) else {}
        self.status = status
        self.type = self.problem.get("type")
        self.title = self.problem.get("title")
        self.detail = self.problem.get("detail") or message
        self.errors = self.problem.get("errors") or []
        self.retry_after = retry_after
        self.request_id = request_id or self.problem.get("request_id")
        text = "%s %s: %s" % (status if status is not None else "-", self.title or type(self).__name__,
                              self.detail or "")
        if self.errors:
            text += " [" + "; ".join("%s: %s" % (e.get("pointer"), e.get("detail"))
                                     for e in self.errors if isinstance(e, dict)) + "]"
        super().__init__(text)

    @property
    def pointers(self) -> List[str]:
        """The JSON pointers (RFC 6901) of the fields the problem names, in order."""
        return [e["pointer"] for e in self.errors if isinstance(e, dict) and isinstance(e.get("pointer"), str)]


class ProblemError(MechdError):
    """The server answered with an error status (4xx, 5xx), usually with a problem+json."""


class BadRequest(ProblemError):
    """400: the body is not valid JSON (detail has line and column), or an operation was fetched
    with GET without ?request= (type /problems/request-missing)."""


class Unauthorized(ProblemError):
    """401: the server wants a bearer token (mechd --token-file) and none or a wrong one came;
    pass token= to Client or set MECHD_TOKEN."""


class NotFound(ProblemError):
    """404: no such path."""


class MethodNotAllowed(ProblemError):
    """405: the path exists with another method."""


class PayloadTooLarge(ProblemError):
    """413: the body is over the server's limit."""


class UnsupportedMediaType(ProblemError):
    """415: the body was not sent as application/json."""


class ValidationError(ProblemError):
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


class BudgetExceeded(ProblemError):
    """422: a step, sample or deadline budget ran out; .progress says how far it got."""

    @property
    def progress(self):
        return self.problem.get("progress")


class NumericalFailure(ProblemError):
    """422: the numerics failed (non-finite result, step-size underflow)."""


class InternalError(ProblemError):
    """500: a bug in mechd; the server log has the request id."""


class ServerBusy(ProblemError):
    """503: the compute queue is full; retry after .retry_after seconds."""


class ShuttingDown(ServerBusy):
    """503: the server is shutting down and cancelled the request."""


class ConnectionFailed(MechdError):
    """No HTTP answer (refused, reset, timed out); .status is None."""


class Timeout(ConnectionFailed):
    """No answer within the client's timeout (seconds per attempt); .status is None. Not
    retried: the server may still be computing, and asking again would double its work."""


_BY_TYPE = {
    "/problems/malformed-json": BadRequest,
    "/problems/unauthorized": Unauthorized,
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
_BY_STATUS = {400: BadRequest, 401: Unauthorized, 404: NotFound, 405: MethodNotAllowed, 413: PayloadTooLarge,
              415: UnsupportedMediaType, 422: ValidationError, 500: InternalError, 503: ServerBusy}


def error_for(status: int, problem: Any, retry_after: Optional[float] = None,
              message: Optional[str] = None, request_id: Optional[str] = None) -> "MechdError":
    """The MechdError subclass for a problem+json (by its type, else by status)."""
    ptype = problem.get("type") if isinstance(problem, dict) else None
    cls = _BY_TYPE.get(ptype) or _BY_STATUS.get(status) or MechdError
    if cls is MechdError:
        cls = ProblemError
    return cls(status, problem, retry_after, message, request_id)


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


# ---- BEGIN GENERATED OPERATIONS (clients/python/gen_operations.py; do not edit) ----
class _Operations:
    """One method per POST operation of GET /v1."""

    def _operation(self, path: str, body: Optional[Dict[str, Any]],
                   fields: Tuple[Tuple[str, Any], ...]) -> Dict[str, Any]:
        raise NotImplementedError

    def vectors(self, body: Optional[Dict[str, Any]] = None, *, a: Optional[List[float]] = None, b: Optional[List[float]] = None, c: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Vector algebra: norms, dot and cross products (with the antisymmetric tensor form), angle, components, projections, scalar and vector triple products

        POST /v1/vectors. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            a (required): [x, y, z], any units (r for r x p); |components| <= 1e153
            b: [x, y, z], optional (p for r x p)
            c: [x, y, z], optional, needs b: the triple products a.(b x c), a x (b x c)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/vectors', body, (('a', a), ('b', b), ('c', c), ('cost', cost)))

    def tensor_symmetric(self, body: Optional[Dict[str, Any]] = None, *, tensor: Optional[List[List[float]]] = None, vector: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """A symmetric tensor's trace, invariants, isotropic and deviatoric parts, principal values and axes (with the degeneracy flag), and T v

        POST /v1/tensor/symmetric. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            tensor (required): [[t11,t12,t13],[t21,t22,t23],[t31,t32,t33]], any units, symmetric (t_ij
                    and t_ji may differ by 1e-12 of the largest |entry|), |entries| <= 1e102 (so that
                    det T stays in the double range)
            vector: optional v: answers T v and v.T.v (omega for an inertia tensor: L = I omega, 2 T_rot
                    = omega.I.omega)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/tensor/symmetric', body, (('tensor', tensor), ('vector', vector), ('cost', cost)))

    def rotation_convert(self, body: Optional[Dict[str, Any]] = None, *, matrix: Optional[List[List[float]]] = None, euler_zxz: Optional[List[float]] = None, euler: Optional[Dict[str, Any]] = None, axis_angle: Optional[Dict[str, Any]] = None, quaternion: Optional[List[float]] = None, rotation_vector: Optional[List[float]] = None, sense: Optional[str] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """A rotation in every representation: matrix, quaternion, axis-angle, rotation vector, z-x-z and all 24 Euler readings, with residuals and gimbal-lock handling

        POST /v1/rotation/convert. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            matrix: 3x3 rows: the rotation matrix R in the given sense (passive: rows = new axes in old
                    coordinates); orthonormal with det +1 to 1e-9 (max |R^T R - 1|), then polished to
                    round-off
            euler_zxz: [phi, theta, psi] rad, the notes' z-x-z angles: phi about z, theta about the new
                    x (line of nodes), psi about the new z; passive R = R_psi R_theta R_phi; the same as
                    euler {sequence ZXZ, intrinsic true}
            euler: any of the 12 Euler/Tait-Bryan sequences, intrinsic or extrinsic
            axis_angle: a right-handed turn by angle (rad) about axis
            quaternion: [w, x, y, z] = [cos(a/2), sin(a/2) n] for the turn by a about n; any non-zero
                    length (normalised here); q and -q are the same turn
            rotation_vector: angle (rad) times the unit axis; [0, 0, 0] is the identity
            sense: passive (the notes): R takes a vector's components in the old axes to the new axes;
                    active: R turns the vector in fixed axes. R_active = R_passive^T for the same turn;
                    the angle/axis/quaternion parameters of a turn do not depend on the sense; default
                    "passive"
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rotation/convert', body, (('matrix', matrix), ('euler_zxz', euler_zxz), ('euler', euler), ('axis_angle', axis_angle), ('quaternion', quaternion), ('rotation_vector', rotation_vector), ('sense', sense), ('cost', cost)))

    def rotation_compose(self, body: Optional[Dict[str, Any]] = None, *, rotations: Optional[List[Dict[str, Any]]] = None, sense: Optional[str] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The product of a list of rotations applied in order (passive: R_n ... R_1 about the moving axes; active: about the fixed axes), in every representation

        POST /v1/rotation/compose. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            rotations (required): applied in order, first the first
            sense: how the list is applied and the product reported; also the default sense of each
                    item; default "passive"
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rotation/compose', body, (('rotations', rotations), ('sense', sense), ('cost', cost)))

    def rotation_apply(self, body: Optional[Dict[str, Any]] = None, *, rotation: Optional[Dict[str, Any]] = None, vectors: Optional[List[List[float]]] = None, tensors: Optional[List[List[List[float]]]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """A rotation applied to vectors (R v) and rank-2 tensors (R T R^T), passive or active

        POST /v1/rotation/apply. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            rotation (required): a rotation given as exactly one of matrix, euler_zxz, euler,
                    axis_angle, quaternion, rotation_vector, with an optional sense
            vectors: 3-vectors v, any units, |components| <= 1e150
            tensors: rank-2 tensors T as 3x3 rows, any units
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rotation/apply', body, (('rotation', rotation), ('vectors', vectors), ('tensors', tensors), ('cost', cost)))

    def rotation_euler_rates(self, body: Optional[Dict[str, Any]] = None, *, euler_zxz: Optional[List[float]] = None, rates: Optional[List[float]] = None, omega_body: Optional[List[float]] = None, omega_space: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Euler-angle kinematics: angular velocity in body and space axes from z-x-z angles and rates (or the rates from omega), dR/dt and its relation to omega, gimbal lock typed

        POST /v1/rotation/euler-rates. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            euler_zxz (required): [phi, theta, psi], rad, z-x-z (notes §2.6), R = R_psi R_theta R_phi
                    (passive)
            rates: [phi', theta', psi'], rad/s
            omega_body: omega in body components, rad/s (instead of rates)
            omega_space: omega in space components, rad/s (instead of rates)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rotation/euler-rates', body, (('euler_zxz', euler_zxz), ('rates', rates), ('omega_body', omega_body), ('omega_space', omega_space), ('cost', cost)))

    def rigid_inertia(self, body: Optional[Dict[str, Any]] = None, *, bodies: Optional[List[Any]] = None, origin: Optional[Any] = None, omega: Optional[List[float]] = None, incline: Optional[Dict[str, Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Inertia tensor, principal axes, angular momentum and kinetic energy of a rigid body

        POST /v1/rigid/inertia. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            bodies (required): the parts of one rigid body
            origin: one of: m, point the tensor is taken about; object; default "center_of_mass"
            omega: rad/s, angular velocity in scene axes (rotation about origin)
            incline: rolling without slipping down an incline, for this body: the moment about the
                    rolling axis through the centre of mass, a = g sin(angle)/(1 + I/(m R^2)), the
                    friction needed and, with length, the time and speed (ignored inside
                    /v1/rigid/rotate's inertia)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/inertia', body, (('bodies', bodies), ('origin', origin), ('omega', omega), ('incline', incline), ('cost', cost)))

    def rigid_rotate(self, body: Optional[Dict[str, Any]] = None, *, moments: Optional[List[float]] = None, inertia: Optional[Dict[str, Any]] = None, omega: Optional[List[float]] = None, orientation: Optional[Dict[str, Any]] = None, torque: Optional[Dict[str, Any]] = None, t_end: Optional[float] = None, samples: Optional[int] = None, integrator: Optional[Any] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Euler's equations with a quaternion attitude: free or torqued rotation of a rigid body, checked against the exact torque-free solution

        POST /v1/rigid/rotate. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            moments: principal moments [I1, I2, I3], kg m^2, > 0, each at most the sum of the other two;
                    body axes = principal axes. Give this or inertia.
            inertia: a full POST /v1/rigid/inertia request (its schema, inlined here by the build,
                    errors under /inertia): the body is rotated about that request's origin (default its
                    centre of mass), its principal frame is the body frame, and omega and orientation
                    refer to the scene axes of that request (the body as built). Give this or moments.
            omega (required): initial angular velocity, rad/s, body axes
            orientation: a rotation given as exactly one of matrix, euler_zxz, euler, axis_angle,
                    quaternion, rotation_vector, with an optional sense
            torque: optional constant torque; default none (torque-free)
            t_end (required): s
            samples: integer >= 2, <= 100000; default 101
            integrator: a method (adaptive: rtol/atol; fixed-step: dt), or {"accuracy": preset}, or
                    {"target_error": relative error}; default {"accuracy": "balanced"}. GET
                    /v1/integrators lists the methods and presets.
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/rotate', body, (('moments', moments), ('inertia', inertia), ('omega', omega), ('orientation', orientation), ('torque', torque), ('t_end', t_end), ('samples', samples), ('integrator', integrator), ('dry_run', dry_run), ('cost', cost)))

    def rigid_top(self, body: Optional[Dict[str, Any]] = None, *, I1: Optional[float] = None, I3: Optional[float] = None, mass: Optional[float] = None, distance: Optional[float] = None, g: Optional[float] = None, theta: Optional[float] = None, phi: Optional[float] = None, psi: Optional[float] = None, theta_dot: Optional[float] = None, phi_dot: Optional[float] = None, psi_dot: Optional[float] = None, t_end: Optional[float] = None, samples: Optional[int] = None, integrator: Optional[Any] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Heavy symmetric top with a fixed tip: Euler angles, nutation range, conserved momenta, sleeping-top stability

        POST /v1/rigid/top. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            I1 (required): kg m^2, about the tip, perpendicular to the symmetry axis; I1 >= mass
                    distance^2
            I3 (required): kg m^2, about the symmetry axis; I3 <= 2 I1
            mass (required): kg
            distance (required): m, tip to centre of mass (h)
            g: m/s^2, along -z of space; default 9.80665
            theta (required): rad, tilt of the symmetry axis from vertical (0: upright)
            phi: rad, azimuth of the line of nodes; default 0
            psi: rad, spin angle; default 0
            theta_dot: rad/s, nutation rate; default 0
            phi_dot: rad/s, precession rate; default 0
            psi_dot: rad/s, spin rate; default 0
            t_end (required): s
            samples: integer >= 2, <= 100000; default 101
            integrator: a method (adaptive: rtol/atol; fixed-step: dt), or {"accuracy": preset}, or
                    {"target_error": relative error}; default {"accuracy": "balanced"}. GET
                    /v1/integrators lists the methods and presets.
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/top', body, (('I1', I1), ('I3', I3), ('mass', mass), ('distance', distance), ('g', g), ('theta', theta), ('phi', phi), ('psi', psi), ('theta_dot', theta_dot), ('phi_dot', phi_dot), ('psi_dot', psi_dot), ('t_end', t_end), ('samples', samples), ('integrator', integrator), ('dry_run', dry_run), ('cost', cost)))

    def rigid_stability(self, body: Optional[Dict[str, Any]] = None, *, moments: Optional[List[float]] = None, axis: Optional[int] = None, spin: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Stability of spin about a principal axis: k in eps'' = k eps, the frequency or growth rate, and which axis is intermediate

        POST /v1/rigid/stability. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            moments (required): principal moments [I1, I2, I3], kg m^2, > 0, any order; each at most the
                    sum of the other two (to 1e-12 relative), as for every rigid body
            axis (required): the principal axis of the spin (1-based index into moments)
            spin (required): spin rate about that axis, rad/s (sign irrelevant)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/stability', body, (('moments', moments), ('axis', axis), ('spin', spin), ('cost', cost)))

    def rigid_free_symmetric_top(self, body: Optional[Dict[str, Any]] = None, *, moments: Optional[List[float]] = None, omega: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The torque-free symmetric top in closed form: space and body precession rates, the body and space cones, the angle between L and omega

        POST /v1/rigid/free-symmetric-top. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            moments (required): [I_perp, I3]: the two equal principal moments and the one about the
                    symmetry axis, kg m^2
            omega (required): rad/s, body components (w1, w2, w3), w3 along the symmetry axis; not all
                    zero
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/free-symmetric-top', body, (('moments', moments), ('omega', omega), ('cost', cost)))

    def rigid_struck_ball(self, body: Optional[Dict[str, Any]] = None, *, radius: Optional[float] = None, shape: Optional[str] = None, moment_of_inertia: Optional[float] = None, mass: Optional[float] = None, impulse: Optional[float] = None, height: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The height at which a struck ball rolls without slipping (2R/5 above the centre for a solid sphere), and the rolling speed and energy lost when struck elsewhere

        POST /v1/rigid/struck-ball. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            radius (required): m, the ball's radius R (the contact point is R below the centre)
            shape: I_cm/(m R^2) = 2/5, 2/3, 1/2, 1; moment_of_inertia overrides it; default
                    "solid_sphere"
            moment_of_inertia: kg m^2, I_cm about the rolling axis (instead of shape)
            mass: kg; default 1
            impulse: N s, the horizontal impulse of the strike; default 1
            height: m, where the strike hits above the centre (|height| <= radius); default the rolling
                    height
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/struck-ball', body, (('radius', radius), ('shape', shape), ('moment_of_inertia', moment_of_inertia), ('mass', mass), ('impulse', impulse), ('height', height), ('cost', cost)))

    def rigid_topple(self, body: Optional[Dict[str, Any]] = None, *, width: Optional[float] = None, height: Optional[float] = None, mass: Optional[float] = None, g: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """A box balanced on an edge falls onto its base: the angular velocity as it lands with the edge held or on a frictionless floor, and the floor's impulse that stops it

        POST /v1/rigid/topple. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            width (required): m, the box's side a in the plane of the fall (a cube: its side)
            height: m, the side b that ends vertical; default width (a cube)
            mass: kg (scales the impulses only); default 1
            g: m/s^2; default 9.80665
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/rigid/topple', body, (('width', width), ('height', height), ('mass', mass), ('g', g), ('cost', cost)))

    def small_oscillations(self, body: Optional[Dict[str, Any]] = None, *, system: Optional[Any] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Small oscillations about a steady motion: near-circular orbits in a central potential (radial and azimuthal frequencies, apsidal angle), the conical pendulum, a physical pendulum about any pivot and axis, the Foucault pendulum's normal modes

        POST /v1/small-oscillations. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            system (required): one of: object; object; object; object
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/small-oscillations', body, (('system', system), ('cost', cost)))

    def coupled_oscillations(self, body: Optional[Dict[str, Any]] = None, *, system: Optional[Any] = None, initial: Optional[Dict[str, Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Coupled oscillations: normal modes and frequencies from mass and stiffness matrices (K v = w^2 M v, mass-normalised, degeneracy flagged), chains of masses and springs, the double pendulum, coupled pendulums, and the motion from initial conditions as a sum of modes

        POST /v1/coupled-oscillations. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            system (required): one of: object; object; object; object
            initial: initial conditions: answers the modal coordinates and the motion as a sum of modes
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/coupled-oscillations', body, (('system', system), ('initial', initial), ('cost', cost)))

    def relativity_boost(self, body: Optional[Dict[str, Any]] = None, *, vectors: Optional[Any] = None, velocity: Optional[Dict[str, Any]] = None, matrix: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Lorentz-boost 4-vectors, precise from 1 m/s to gamma = 1e15

        POST /v1/relativity/boost. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            vectors (required): one 4-vector, or a list of 1 to 100000; the answer has the same shape
            velocity (required): a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            matrix: true adds matrix, the 4x4 Lorentz matrix of the boost (x' = matrix x, rows and
                    columns in the order ct, x, y, z); default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/boost', body, (('vectors', vectors), ('velocity', velocity), ('matrix', matrix), ('cost', cost)))

    def relativity_particle(self, body: Optional[Dict[str, Any]] = None, *, particle: Optional[Any] = None, energy_unit: Optional[str] = None, beta: Optional[float] = None, speed: Optional[float] = None, gamma: Optional[float] = None, gamma_minus_one: Optional[float] = None, one_minus_beta: Optional[float] = None, rapidity: Optional[float] = None, beta_gamma: Optional[float] = None, energy: Optional[float] = None, momentum: Optional[float] = None, kinetic_energy: Optional[float] = None, proper_lifetime: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """One particle's gamma, beta, E, p, T and rapidity from any one of them, precise at 1 m/s and near c, with the non-relativistic approximations and the lifetime (c tau, gamma tau)

        POST /v1/relativity/particle. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            particle (required): a particle name (GET /v1/relativity/particles) or a mass >= 0 in
                    energy_unit/c^2
            energy_unit: unit of the mass (unit/c^2), energies and momentum (unit/c), c = 1; default
                    "MeV"
            beta: speed over c, in [0, 1)
            speed: speed in m/s, below c = 299792458
            gamma: Lorentz factor >= 1
            gamma_minus_one: gamma - 1 >= 0, the precise form near rest
            one_minus_beta: 1 - beta in (0, 1], the precise form near c
            rapidity: rapidity atanh(beta) >= 0
            beta_gamma: beta gamma = p/(m c) >= 0
            energy: total energy E = gamma m c^2 >= m c^2, in energy_unit
            momentum: momentum |p| >= 0, in energy_unit/c
            kinetic_energy: kinetic energy T = E - m c^2 >= 0, in energy_unit
            proper_lifetime: mean lifetime tau in the rest frame, s (> 0): adds lifetime {proper, c_tau,
                    lab, lab_c_tau, decay_length}
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/particle', body, (('particle', particle), ('energy_unit', energy_unit), ('beta', beta), ('speed', speed), ('gamma', gamma), ('gamma_minus_one', gamma_minus_one), ('one_minus_beta', one_minus_beta), ('rapidity', rapidity), ('beta_gamma', beta_gamma), ('energy', energy), ('momentum', momentum), ('kinetic_energy', kinetic_energy), ('proper_lifetime', proper_lifetime), ('cost', cost)))

    def relativity_dot(self, body: Optional[Dict[str, Any]] = None, *, a: Optional[List[float]] = None, b: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Minkowski dot product of two 4-vectors, their squares and kinds, and the relative gamma of two timelike ones

        POST /v1/relativity/dot. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            a (required): a 4-vector [x0, x1, x2, x3], x0 = ct or E/c, any one unit, |x_i| <= 1e150
            b (required): a second 4-vector in the same metric (units multiply)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/dot', body, (('a', a), ('b', b), ('cost', cost)))

    def relativity_mass_energy(self, body: Optional[Dict[str, Any]] = None, *, mass: Optional[float] = None, energy: Optional[float] = None, luminosity: Optional[float] = None, flux: Optional[float] = None, distance: Optional[float] = None, duration: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Rest energy E = m c^2 either way, and the rest-mass loss L/c^2 of a luminosity (the Sun's mass loss from its luminosity or the solar constant)

        POST /v1/relativity/mass-energy. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            mass: rest mass, kg: answers its rest energy
            energy: energy, J: answers the rest mass E / c^2 it is equivalent to
            luminosity: radiated power L, W: answers the rest-mass loss rate L / c^2
            flux: energy flux F at the distance `distance`, W/m^2 (isotropic emission: L = 4 pi d^2 F)
            distance: distance from the source at which the flux was measured, m (with flux only)
            duration: s, with a luminosity or a flux: adds mass_lost = L t / c^2
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/mass-energy', body, (('mass', mass), ('energy', energy), ('luminosity', luminosity), ('flux', flux), ('distance', distance), ('duration', duration), ('cost', cost)))

    def relativity_rocket(self, body: Optional[Dict[str, Any]] = None, *, beta: Optional[float] = None, speed: Optional[float] = None, gamma: Optional[float] = None, gamma_minus_one: Optional[float] = None, one_minus_beta: Optional[float] = None, rapidity: Optional[float] = None, beta_gamma: Optional[float] = None, mass_ratio: Optional[float] = None, exhaust_beta: Optional[float] = None, exhaust_speed: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The relativistic rocket: the mass ratio for a final speed or rapidity (or the speed a mass ratio gives), any exhaust speed, beside Tsiolkovsky's

        POST /v1/relativity/rocket. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            beta: final speed over c, in [0, 1)
            speed: final speed, m/s
            gamma: final Lorentz factor
            gamma_minus_one: final gamma - 1
            one_minus_beta: final 1 - beta, in (0, 1]
            rapidity: final rapidity
            beta_gamma: final beta gamma (proper velocity over c)
            mass_ratio: m_initial/m_final >= 1: answers the final speed
            exhaust_beta: exhaust speed over c relative to the rocket, (0, 1]; default 1 (a photon
                    rocket)
            exhaust_speed: exhaust speed relative to the rocket, m/s (instead of exhaust_beta)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/rocket', body, (('beta', beta), ('speed', speed), ('gamma', gamma), ('gamma_minus_one', gamma_minus_one), ('one_minus_beta', one_minus_beta), ('rapidity', rapidity), ('beta_gamma', beta_gamma), ('mass_ratio', mass_ratio), ('exhaust_beta', exhaust_beta), ('exhaust_speed', exhaust_speed), ('cost', cost)))

    def relativity_force(self, body: Optional[Dict[str, Any]] = None, *, mass: Optional[float] = None, velocity: Optional[Dict[str, Any]] = None, acceleration: Optional[List[float]] = None, force: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """F = dp/dt split along and across v (gamma^3 m a and gamma m a), either way round, with the power and the 4-force

        POST /v1/relativity/force. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            mass (required): rest mass m, kg
            velocity (required): a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            acceleration: the acceleration dv/dt, m/s^2 (or give force)
            force: the force F = dp/dt, N (or give acceleration)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/force', body, (('mass', mass), ('velocity', velocity), ('acceleration', acceleration), ('force', force), ('cost', cost)))

    def relativity_lagrangian(self, body: Optional[Dict[str, Any]] = None, *, mass: Optional[float] = None, charge: Optional[float] = None, velocity: Optional[Dict[str, Any]] = None, scalar_potential: Optional[float] = None, vector_potential: Optional[List[float]] = None, fields: Optional[Dict[str, Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The relativistic Lagrangian, canonical momentum and Hamiltonian of a charged particle in given potentials or uniform fields

        POST /v1/relativity/lagrangian. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            mass (required): rest mass m, kg
            charge: charge q, C (0: a neutral particle, no coupling to the potentials); default 0
            velocity (required): a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            scalar_potential: phi at the particle, V (or give uniform fields); default 0
            vector_potential: A at the particle, T m (or give uniform fields); default [0, 0, 0]
            fields: uniform fields instead of potentials: phi = -E.r, A = (1/2) B x r at position r
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/lagrangian', body, (('mass', mass), ('charge', charge), ('velocity', velocity), ('scalar_potential', scalar_potential), ('vector_potential', vector_potential), ('fields', fields), ('cost', cost)))

    def relativity_michelson_morley(self, body: Optional[Dict[str, Any]] = None, *, arm_length: Optional[float] = None, speed: Optional[float] = None, wavelength: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Michelson-Morley: the ether's predicted path difference and fringe shift (exact beside the notes' beta^2 L) and the null result with the Lorentz contraction

        POST /v1/relativity/michelson-morley. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            arm_length (required): L, m (the notes: 11 m)
            speed: the apparatus' speed through the ether, m/s (the Earth's orbital speed ~3e4); default
                    30000
            wavelength: light's wavelength, m: adds the fringe shift on a 90 degree rotation
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/michelson-morley', body, (('arm_length', arm_length), ('speed', speed), ('wavelength', wavelength), ('cost', cost)))

    def relativity_velocity_addition(self, body: Optional[Dict[str, Any]] = None, *, velocity: Optional[Any] = None, frame_velocity: Optional[Dict[str, Any]] = None, compose: Optional[List[Dict[str, Any]]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Relativistic velocity addition in any directions, composition of boosts, and the Wigner (Thomas) rotation

        POST /v1/relativity/velocity-addition. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            velocity: the object's velocity in the original frame: a velocity, or {"light": direction}
                    for light
            frame_velocity: a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            compose: boosts applied in order: the first is the velocity of frame 1 in the original
                    frame, each next one the velocity of the next frame relative to the previous one, in
                    the previous frame's axes
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/velocity-addition', body, (('velocity', velocity), ('frame_velocity', frame_velocity), ('compose', compose), ('cost', cost)))

    def relativity_interval(self, body: Optional[Dict[str, Any]] = None, *, events: Optional[List[List[float]]] = None, units: Optional[str] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The interval between two events: s2, timelike/spacelike/lightlike, proper time or length, whether the time order can be reversed

        POST /v1/relativity/interval. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            events (required): two events [ct, x, y, z], all four coordinates in one length unit
            units: metres: coordinates in m, proper_time in s; years: coordinates in light-years (ct in
                    light-years = years, c = 1), proper_time in years; default "metres"
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/interval', body, (('events', events), ('units', units), ('cost', cost)))

    def relativity_worldline(self, body: Optional[Dict[str, Any]] = None, *, legs: Optional[List[Any]] = None, units: Optional[str] = None, tick_interval: Optional[float] = None, telescope_home_times: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """A trip as legs of constant velocity or constant proper acceleration: proper times, the stay-at-home time, and the Doppler ticks each twin sees

        POST /v1/relativity/worldline. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            legs (required): array of any (>= 1, <= 1000 items)
            units: seconds: times in s, lengths in m, c = 299792458 m/s; years: times in Julian years,
                    lengths in light-years, c = 1; default "seconds"
            tick_interval: each twin's clock ticks once per this proper time (default 1 s or 1 year);
                    default 1
            telescope_home_times: home times at which the stay-at-home twin reads the traveller's clock
                    through a telescope (the light arriving then); up to the time the trip's end is seen
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/worldline', body, (('legs', legs), ('units', units), ('tick_interval', tick_interval), ('telescope_home_times', telescope_home_times), ('cost', cost)))

    def relativity_doppler(self, body: Optional[Dict[str, Any]] = None, *, source_velocity: Optional[Dict[str, Any]] = None, observer_velocity: Optional[Dict[str, Any]] = None, emission_direction: Optional[List[float]] = None, arrival_direction: Optional[List[float]] = None, direction: Optional[Dict[str, Any]] = None, frequency: Optional[float] = None, wavelength: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Relativistic Doppler shift at any angle (longitudinal, both transverse cases) with aberration

        POST /v1/relativity/doppler. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            source_velocity: a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            observer_velocity: a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            emission_direction: deprecated alias of direction {vector, frame: source}: the direction the
                    light travels (from the source towards the observer) in the SOURCE's rest frame;
                    give exactly one of direction, emission_direction and arrival_direction
            arrival_direction: deprecated alias of direction {vector, frame: observer}: the direction
                    the light travels when it reaches the observer, in the OBSERVER's rest frame
                    (opposite to the line of sight towards the source)
            direction: the light's propagation direction and the frame it is seen in, in one field: give
                    this, or one of the older emission_direction (= frame source) and arrival_direction
                    (= frame observer), which stay as documented aliases
            frequency: emitted frequency in Hz, in the source's rest frame (optional; at most one of
                    frequency and wavelength)
            wavelength: emitted wavelength in m, in the source's rest frame (optional)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/doppler', body, (('source_velocity', source_velocity), ('observer_velocity', observer_velocity), ('emission_direction', emission_direction), ('arrival_direction', arrival_direction), ('direction', direction), ('frequency', frequency), ('wavelength', wavelength), ('cost', cost)))

    def relativity_fields(self, body: Optional[Dict[str, Any]] = None, *, E: Optional[List[float]] = None, B: Optional[List[float]] = None, velocity: Optional[Dict[str, Any]] = None, units: Optional[str] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """E and B under a boost, Heaviside–Lorentz or SI, with the invariants E² − B² and E·B

        POST /v1/relativity/fields. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            E (required): electric field: V/m in SI; in Heaviside-Lorentz the same unit as B; each
                    |component| <= 1e100
            B (required): magnetic field: T in SI; in Heaviside-Lorentz the same unit as E
            velocity (required): a velocity as exactly one of four forms; give the one that carries the
                    precision you have (near c: rapidity, gamma or one_minus_beta)
            units: heaviside_lorentz: c = 1, the notes' units (default); si: E in V/m, B in T; default
                    "heaviside_lorentz"
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/fields', body, (('E', E), ('B', B), ('velocity', velocity), ('units', units), ('cost', cost)))

    def relativity_charge_in_fields(self, body: Optional[Dict[str, Any]] = None, *, mass: Optional[float] = None, charge: Optional[float] = None, E: Optional[List[float]] = None, B: Optional[List[float]] = None, force: Optional[List[float]] = None, position: Optional[List[float]] = None, velocity: Optional[Dict[str, Any]] = None, proper_velocity: Optional[List[float]] = None, times: Optional[List[float]] = None, proper_times: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """A charge in uniform E and B: the frame where they are parallel or one vanishes, the helix or hyperbolic motion there, and the state at lab or proper times

        POST /v1/relativity/charge-in-fields. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            mass (required): rest mass m, kg
            charge (required): charge q, C
            E: electric field, V/m; default 0
            B: magnetic field, T; default 0
            force: a constant extra force, N (e.g. m g): an electric field F/q; default 0
            position: position at t = 0, m; default 0
            velocity: a velocity as exactly one of four forms; give the one that carries the precision
                    you have (near c: rapidity, gamma or one_minus_beta)
            proper_velocity: u = gamma v at t = 0, m/s (instead of velocity); default 0
            times: lab (coordinate) times since the start, s; default []
            proper_times: proper times since the start, s; default []
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/charge-in-fields', body, (('mass', mass), ('charge', charge), ('E', E), ('B', B), ('force', force), ('position', position), ('velocity', velocity), ('proper_velocity', proper_velocity), ('times', times), ('proper_times', proper_times), ('cost', cost)))

    def relativity_kinematics_invariant_mass(self, body: Optional[Dict[str, Any]] = None, *, energy_unit: Optional[str] = None, momenta: Optional[List[Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Invariant mass and centre-of-momentum velocity of a set of 4-momenta or particles

        POST /v1/relativity/kinematics/invariant-mass. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            energy_unit: unit of every energy, mass (unit/c^2) and momentum (unit/c), c = 1; default
                    "MeV"
            momenta (required): 1 to 1000 particles, each a 4-momentum [E, px, py, pz] or {particle,
                    momentum}
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/kinematics/invariant-mass', body, (('energy_unit', energy_unit), ('momenta', momenta), ('cost', cost)))

    def relativity_kinematics_decay(self, body: Optional[Dict[str, Any]] = None, *, energy_unit: Optional[str] = None, parent: Optional[Dict[str, Any]] = None, daughters: Optional[List[Any]] = None, theta_star: Optional[float] = None, theta_star_deg: Optional[float] = None, cone: Optional[Dict[str, Any]] = None, angles: Optional[List[float]] = None, angles_deg: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Two- and three-body decays: rest-frame momentum, lab energies and angles, opening angles, cone energy ranges, endpoints

        POST /v1/relativity/kinematics/decay. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            energy_unit: unit of every energy, mass (unit/c^2) and momentum (unit/c), c = 1; default
                    "MeV"
            parent (required): the decaying particle in the lab; it moves along +z; at most one of
                    energy, kinetic_energy, momentum, velocity (none: at rest)
            daughters (required): two or three decay products
            theta_star: two-body: rest-frame angle of daughter 0 to the parent's direction; daughter 1
                    goes the opposite way (radians)
            theta_star_deg: the same in degrees (degrees)
            cone: two-body: the energy range of one daughter seen within a cone around the parent's
                    direction
            angles: three-body, rest frame, one plane: [angle between daughters 0 and 1, angle between 1
                    and 2] in radians
            angles_deg: the same in degrees
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/kinematics/decay', body, (('energy_unit', energy_unit), ('parent', parent), ('daughters', daughters), ('theta_star', theta_star), ('theta_star_deg', theta_star_deg), ('cone', cone), ('angles', angles), ('angles_deg', angles_deg), ('cost', cost)))

    def relativity_kinematics_compton(self, body: Optional[Dict[str, Any]] = None, *, energy_unit: Optional[str] = None, energy: Optional[float] = None, wavelength: Optional[float] = None, angle: Optional[float] = None, angle_deg: Optional[float] = None, target: Optional[Any] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Compton scattering off an electron or any target: scattered photon, recoil energy and angle

        POST /v1/relativity/kinematics/compton. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            energy_unit: unit of every energy, mass (unit/c^2) and momentum (unit/c), c = 1; default
                    "MeV"
            energy: incident photon energy (give this or wavelength)
            wavelength: incident photon wavelength in metres (give this or energy)
            angle: photon scattering angle theta (radians)
            angle_deg: photon scattering angle theta (degrees)
            target: a particle name (table in the operation description) or a mass >= 0 in
                    energy_unit/c^2
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/kinematics/compton', body, (('energy_unit', energy_unit), ('energy', energy), ('wavelength', wavelength), ('angle', angle), ('angle_deg', angle_deg), ('target', target), ('cost', cost)))

    def relativity_kinematics_elastic(self, body: Optional[Dict[str, Any]] = None, *, energy_unit: Optional[str] = None, projectile: Optional[Dict[str, Any]] = None, target: Optional[Any] = None, cm_angle: Optional[float] = None, cm_angle_deg: Optional[float] = None, angle: Optional[float] = None, angle_deg: Optional[float] = None, recoil_angle: Optional[float] = None, recoil_angle_deg: Optional[float] = None, branch: Optional[int] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Relativistic elastic scattering at a given CM, lab or recoil angle: lab energies, momenta and angles of both particles, the recoil, the CM frame, s, t, u

        POST /v1/relativity/kinematics/elastic. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            energy_unit: unit of every energy, mass (unit/c^2) and momentum (unit/c), c = 1; default
                    "MeV"
            projectile (required): the incoming particle and its lab motion along +z: exactly one of
                    energy, kinetic_energy, momentum, velocity
            target (required): the target, at rest in the lab (mass > 0): a particle name (as
                    /v1/relativity/particles lists them) or a mass >= 0 in energy_unit/c^2
            cm_angle: the projectile's scattering angle theta* in the CM frame (radians)
            cm_angle_deg: the projectile's scattering angle theta* in the CM frame (degrees)
            angle: the projectile's scattering angle in the lab (radians)
            angle_deg: the projectile's scattering angle in the lab (degrees)
            recoil_angle: the recoil's lab angle to the beam, below pi/2 (radians)
            recoil_angle_deg: the recoil's lab angle to the beam, below 90 (degrees)
            branch: which of two CM solutions a lab angle has (a projectile heavier than the target): 0
                    the smaller theta* (the faster projectile), 1 the larger; default 0
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/kinematics/elastic', body, (('energy_unit', energy_unit), ('projectile', projectile), ('target', target), ('cm_angle', cm_angle), ('cm_angle_deg', cm_angle_deg), ('angle', angle), ('angle_deg', angle_deg), ('recoil_angle', recoil_angle), ('recoil_angle_deg', recoil_angle_deg), ('branch', branch), ('cost', cost)))

    def relativity_kinematics_collision(self, body: Optional[Dict[str, Any]] = None, *, energy_unit: Optional[str] = None, beam: Optional[Dict[str, Any]] = None, target: Optional[Dict[str, Any]] = None, crossing_angle: Optional[float] = None, crossing_angle_deg: Optional[float] = None, sqrt_s: Optional[float] = None, final_state: Optional[List[Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """sqrt(s) of fixed-target and colliding beams, the beam energy for a given sqrt(s), production thresholds

        POST /v1/relativity/kinematics/collision. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            energy_unit: unit of every energy, mass (unit/c^2) and momentum (unit/c), c = 1; default
                    "MeV"
            beam (required): the incoming particle, moving along +z; at most one of energy,
                    kinetic_energy, momentum, velocity (none: at rest)
            target (required): the target: at rest, or a second beam moving along -z (tilted by
                    crossing_angle); at most one of energy, kinetic_energy, momentum, velocity (none: at
                    rest)
            crossing_angle: colliding beams: deviation from head-on; the momenta are at pi -
                    crossing_angle (radians)
            crossing_angle_deg: the same in degrees (degrees)
            sqrt_s: inverse problem: the CM energy wanted on a target at rest; the beam's energy is then
                    computed (give no beam energy)
            final_state: particles to produce: threshold energies
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/relativity/kinematics/collision', body, (('energy_unit', energy_unit), ('beam', beam), ('target', target), ('crossing_angle', crossing_angle), ('crossing_angle_deg', crossing_angle_deg), ('sqrt_s', sqrt_s), ('final_state', final_state), ('cost', cost)))

    def gr_schwarzschild(self, body: Optional[Dict[str, Any]] = None, *, M: Optional[Any] = None, named_bodies: Optional[str] = None, units: Optional[str] = None, r: Optional[float] = None, infall_from: Optional[float] = None, reference_r: Optional[float] = None, effective_potential: Optional[Dict[str, Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Schwarzschild radius, clock rates and red shift, circular orbits and their stability, ISCO, photon sphere, effective potentials; GPS-style clock comparison

        POST /v1/gr/schwarzschild. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            M: the central mass: kg, or {gm: m^3/s^2} (GM, the precisely known quantity), or
                    {surface_gravity: g, radius: R} (GM = g R^2, for a problem that gives the surface
                    gravity), or "sun" (GM = 1.32712440041279419e20 m^3/s^2, JPL DE440;
                    1.32712440018e20, DE405, with named_bodies "legacy") or "earth" (GM = 3.986004418e14
                    m^3/s^2, IERS 2010); a mass in kg uses G = 6.67430e-11. Required with units SI;
                    optional with units geometric (then it only adds the SI scale GM/c^2 to the answer).
            named_bodies: the set of named-body constants M = "sun"/"earth" takes: DE440 (default: the
                    Sun's GM 1.32712440041279419e20 m^3/s^2, JPL DE440) or legacy (the values mechd used
                    before DE440: the Sun's GM 1.32712440018e20 m^3/s^2, DE405, so an older client's
                    answers stay the same); the Earth's GM is 3.986004418e14 m^3/s^2 (IERS 2010) in
                    both. units.GM_source states the value used and its source, units.named_bodies the
                    set; default "DE440"
            units: SI: lengths m, times s, specific angular momentum m^2/s, speeds m/s. geometric: G = c
                    = 1 with M = 1: lengths in GM/c^2, times in GM/c^3, specific angular momentum in
                    GM/c, speeds in c.; default "SI"
            r: radius (Schwarzschild r: circumference / 2 pi) for the clocks and the circular orbit; >
                    r_s
            infall_from: radius of rest from which a body falls radially: adds radial_infall, the proper
                    times to the horizon and to r = 0; >= r_s (r_s itself, within 1e-12, is answered as
                    the limit from outside)
            reference_r: radius of a static reference clock (e.g. the ground: 6371000 m mean or 6378137
                    m equatorial for the Earth): compares it with a clock on a circular orbit at r
                    (GPS). Needs r.
            effective_potential: object
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/gr/schwarzschild', body, (('M', M), ('named_bodies', named_bodies), ('units', units), ('r', r), ('infall_from', infall_from), ('reference_r', reference_r), ('effective_potential', effective_potential), ('cost', cost)))

    def gr_geodesic(self, body: Optional[Dict[str, Any]] = None, *, M: Optional[Any] = None, named_bodies: Optional[str] = None, units: Optional[str] = None, kind: Optional[str] = None, r0: Optional[float] = None, phi0: Optional[float] = None, initial: Optional[Any] = None, tau_end: Optional[float] = None, orbits: Optional[int] = None, lambda_end: Optional[float] = None, r_escape: Optional[float] = None, samples: Optional[int] = None, constraint_bound: Optional[float] = None, integrator: Optional[Any] = None, orbital_period: Optional[float] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Equatorial timelike and null geodesics of Schwarzschild: periapsis advance and light deflection measured beside the exact values and 1PN formulas

        POST /v1/gr/geodesic. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            M: the central mass: kg, or {gm: m^3/s^2} (GM, the precisely known quantity), or
                    {surface_gravity: g, radius: R} (GM = g R^2, for a problem that gives the surface
                    gravity), or "sun" (GM = 1.32712440041279419e20 m^3/s^2, JPL DE440;
                    1.32712440018e20, DE405, with named_bodies "legacy") or "earth" (GM = 3.986004418e14
                    m^3/s^2, IERS 2010); a mass in kg uses G = 6.67430e-11. Required with units SI;
                    optional with units geometric (then it only adds the SI scale GM/c^2 to the answer).
            named_bodies: the set of named-body constants M = "sun"/"earth" takes: DE440 (default: the
                    Sun's GM 1.32712440041279419e20 m^3/s^2, JPL DE440) or legacy (the values mechd used
                    before DE440: the Sun's GM 1.32712440018e20 m^3/s^2, DE405, so an older client's
                    answers stay the same); the Earth's GM is 3.986004418e14 m^3/s^2 (IERS 2010) in
                    both. units.GM_source states the value used and its source, units.named_bodies the
                    set; default "DE440"
            units: SI: lengths m, times s, specific angular momentum m^2/s, speeds m/s. geometric: G = c
                    = 1 with M = 1: lengths in GM/c^2, times in GM/c^3, specific angular momentum in
                    GM/c, speeds in c.; default "SI"
            kind (required): timelike: a massive particle (proper time tau); null: light (affine
                    parameter lambda, normalised to dt/dlambda -> 1 far away)
            r0: start radius (not with the orbit forms, which start at periapsis); for light given by
                    impact_parameter, default 100 b (at least 1000 GM/c^2), a ray from far away
            phi0: rad; default 0
            initial (required): one of: conserved energy and angular momentum (timelike); the velocity
                    measured by a static observer at r0; an impact parameter (null); the turning points
                    or a, e of a bound orbit (timelike, start at periapsis)
            tau_end: timelike: proper time to integrate (s, GM/c^3 geometric)
            orbits: timelike bound orbits: integrate this many radial periods (exact, by quadrature)
            lambda_end: null: affine parameter to integrate (s, GM/c^3 geometric); default 1.02 x the
                    straight-line path from r0 to r_escape + 600 pi GM/c^3 (100 loops of the photon
                    sphere)
            r_escape: escape when r passes it moving outward; default 2 r0 (2 r_a for bound orbits)
            samples: integer >= 2, <= 100000; default 201
            constraint_bound: stop with a numerical-failure error when the constraint g(u,u) = -1 (0 for
                    light) drifts by more than this, relative to the size of its terms; default 0.001
            integrator: a method (adaptive: rtol/atol; fixed-step: dt), or {"accuracy": preset}, or
                    {"target_error": relative error}; default {"accuracy": "balanced"}. GET
                    /v1/integrators lists the methods and presets.
            orbital_period: s, SI only: an orbital period the problem gives (Mercury: 87.969 days =
                    7600521.6 s, sidereal) to turn the advance per orbit into arcsec per century;
                    default the integrated orbit's radial period in coordinate time
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/gr/geodesic', body, (('M', M), ('named_bodies', named_bodies), ('units', units), ('kind', kind), ('r0', r0), ('phi0', phi0), ('initial', initial), ('tau_end', tau_end), ('orbits', orbits), ('lambda_end', lambda_end), ('r_escape', r_escape), ('samples', samples), ('constraint_bound', constraint_bound), ('integrator', integrator), ('orbital_period', orbital_period), ('dry_run', dry_run), ('cost', cost)))

    def hamiltonian_flow(self, body: Optional[Dict[str, Any]] = None, *, system: Optional[Any] = None, q: Optional[List[float]] = None, p: Optional[List[float]] = None, t_end: Optional[float] = None, samples: Optional[int] = None, integrator: Optional[Any] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Hamiltonian systems from a catalog (oscillator, pendulums, cylinder, central power laws, Hénon–Heiles, 3D potentials) with conserved momenta and energy

        POST /v1/hamiltonian/flow. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            system (required): a system of the catalog, chosen by name (see the route description)
            q (required): array of float (>= 1, <= 3 items)
            p (required): array of float (>= 1, <= 3 items)
            t_end (required): s
            samples: integer >= 2, <= 100000; default 101
            integrator: a method (adaptive: rtol/atol; fixed-step: dt), or {"accuracy": preset}, or
                    {"target_error": relative error}; default {"accuracy": "balanced"}. GET
                    /v1/integrators lists the methods and presets.
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/hamiltonian/flow', body, (('system', system), ('q', q), ('p', p), ('t_end', t_end), ('samples', samples), ('integrator', integrator), ('dry_run', dry_run), ('cost', cost)))

    def hamiltonian_liouville(self, body: Optional[Dict[str, Any]] = None, *, system: Optional[Any] = None, curve: Optional[Any] = None, reference: Optional[List[float]] = None, t_end: Optional[float] = None, samples: Optional[int] = None, integrators: Optional[List[Any]] = None, tol: Optional[float] = None, max_intervals: Optional[int] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Phase-space area of a closed curve of initial conditions over time and the tangent map's determinant, symplectic beside non-symplectic

        POST /v1/hamiltonian/liouville. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            system (required): a system of the catalog, chosen by name (see the route description)
            curve (required): the closed curve of initial conditions, points (q..., p...)
            reference: array of float (>= 2, <= 6 items)
            t_end (required): s
            samples: integer >= 2, <= 1001; default 11
            integrators: one or two integrator blocks run side by side; default gauss4 (dt = time
                    scale/20) and rk4 (dt = time scale/2)
            tol: relative quadrature bound on the area; default 1e-12
            max_intervals: integer >= 4, <= 4096; default 256
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/hamiltonian/liouville', body, (('system', system), ('curve', curve), ('reference', reference), ('t_end', t_end), ('samples', samples), ('integrators', integrators), ('tol', tol), ('max_intervals', max_intervals), ('dry_run', dry_run), ('cost', cost)))

    def hamiltonian_poincare(self, body: Optional[Dict[str, Any]] = None, *, system: Optional[Any] = None, section: Optional[Dict[str, Any]] = None, orbits: Optional[List[Any]] = None, t_max: Optional[float] = None, max_crossings: Optional[int] = None, integrator: Optional[Any] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Poincaré sections (Hénon–Heiles, spherical pendulum, ...) with crossings located by root-finding

        POST /v1/hamiltonian/poincare. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            system (required): a system of the catalog, chosen by name (see the route description)
            section: object
            orbits (required): array of any (>= 1, <= 50 items)
            t_max (required): s, per orbit
            max_crossings: integer >= 1, <= 10000; default 200
            integrator: a method (adaptive: rtol/atol; fixed-step: dt), or {"accuracy": preset}, or
                    {"target_error": relative error}; default {"accuracy": "balanced"}. GET
                    /v1/integrators lists the methods and presets.
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/hamiltonian/poincare', body, (('system', system), ('section', section), ('orbits', orbits), ('t_max', t_max), ('max_crossings', max_crossings), ('integrator', integrator), ('dry_run', dry_run), ('cost', cost)))

    def hamiltonian_phase_area(self, body: Optional[Dict[str, Any]] = None, *, system: Optional[str] = None, mass: Optional[float] = None, omega: Optional[float] = None, length: Optional[float] = None, g: Optional[float] = None, energy: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Phase-space area enclosed by an energy contour of the oscillator or the pendulum, the action, and the period as dA/dE

        POST /v1/hamiltonian/phase-area. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            system (required): oscillator: H = p^2/2m + m omega^2 q^2/2; pendulum: H = p^2/(2 m l^2) + m
                    g l (1 - cos theta)
            mass (required): mass m, kg
            omega: oscillator's angular frequency, rad/s (oscillator only)
            length: pendulum length l, m (pendulum only)
            g: gravity, m/s^2 (pendulum only; absent: 9.80665, not a schema default because an
                    oscillator must not receive it)
            energy (required): energy above the minimum of the potential, J
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/hamiltonian/phase-area', body, (('system', system), ('mass', mass), ('omega', omega), ('length', length), ('g', g), ('energy', energy), ('cost', cost)))

    def hamiltonian_rotating_frame(self, body: Optional[Dict[str, Any]] = None, *, mass: Optional[float] = None, omega: Optional[List[float]] = None, position: Optional[List[float]] = None, velocity: Optional[List[float]] = None, potential_energy: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Lagrangian, canonical momentum m(v + omega x r) and Hamiltonian in a rotating frame, beside the inertial energy (H_rot = E - omega.L)

        POST /v1/hamiltonian/rotating-frame. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            mass (required): mass m, kg
            omega (required): the frame's constant angular velocity, rad/s
            position (required): r in the rotating frame (origin on the axis), m
            velocity (required): v = dr/dt measured in the rotating frame, m/s
            potential_energy: V at r, J; default 0
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/hamiltonian/rotating-frame', body, (('mass', mass), ('omega', omega), ('position', position), ('velocity', velocity), ('potential_energy', potential_energy), ('cost', cost)))

    def hamiltonian_circular_orbit(self, body: Optional[Dict[str, Any]] = None, *, mass: Optional[float] = None, angular_momentum: Optional[float] = None, terms: Optional[List[Dict[str, Any]]] = None, gm: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The circular orbits of a given angular momentum in a central potential: radius, energy, angular and radial frequencies, periods, apsidal angle, stability

        POST /v1/hamiltonian/circular-orbit. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            mass (required): kg, the orbiting particle (the reduced mass for two bodies)
            angular_momentum (required): kg m^2/s, L = m r^2 phi_dot
            terms: V(r) = sum of the terms (Kepler: n = -1, k = -G M m; isotropic oscillator: n = 2, k =
                    m w^2/2)
            gm: m^3/s^2: adds the Kepler term V = -gm m/r (G M of the centre)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/hamiltonian/circular-orbit', body, (('mass', mass), ('angular_momentum', angular_momentum), ('terms', terms), ('gm', gm), ('cost', cost)))

    def continuum_string(self, body: Optional[Dict[str, Any]] = None, *, tension: Optional[float] = None, linear_density: Optional[float] = None, mass: Optional[float] = None, length: Optional[float] = None, modes: Optional[int] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Continuum mechanics: transverse waves on a string with fixed ends — wave speed and normal modes

        POST /v1/continuum/string. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            tension (required): tension T, N
            linear_density: mass per length mu, kg/m (or give mass)
            mass: the string's mass, kg: mu = mass/length (or give linear_density)
            length (required): length L between the fixed ends, m
            modes: how many modes to list, 1 .. 1000 (the lowest ones); default 5
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/continuum/string', body, (('tension', tension), ('linear_density', linear_density), ('mass', mass), ('length', length), ('modes', modes), ('cost', cost)))

    def continuum_rod(self, body: Optional[Dict[str, Any]] = None, *, length: Optional[float] = None, density: Optional[float] = None, youngs_modulus: Optional[float] = None, section: Optional[Any] = None, ends: Optional[str] = None, shear_modulus: Optional[float] = None, poisson_ratio: Optional[float] = None, modes: Optional[int] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Continuum mechanics: axial, torsional and bending waves of a rod — speeds, the dispersion of bending waves and the normal modes free, clamped, cantilevered or pinned

        POST /v1/continuum/rod. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            length (required): length L, m
            density (required): density rho, kg/m^3
            youngs_modulus (required): Young's modulus E, Pa
            section (required): the cross-section: a solid circle, a rectangle (bending across its
                    height), or its area and second moment of area
            ends: end conditions (clamped-free: a cantilever); default "clamped-free"
            shear_modulus: shear modulus G, Pa (torsional waves; or give poisson_ratio)
            poisson_ratio: Poisson's ratio nu: G = E/(2(1 + nu)) for the torsional waves
            modes: how many modes to list, 1 .. 1000 (the lowest ones); default 5
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/continuum/rod', body, (('length', length), ('density', density), ('youngs_modulus', youngs_modulus), ('section', section), ('ends', ends), ('shear_modulus', shear_modulus), ('poisson_ratio', poisson_ratio), ('modes', modes), ('cost', cost)))

    def trajectory(self, body: Optional[Dict[str, Any]] = None, *, particle: Optional[Dict[str, Any]] = None, frame: Optional[Any] = None, forces: Optional[List[Any]] = None, fictitious: Optional[Any] = None, relativity: Optional[Any] = None, t_end: Optional[float] = None, samples: Optional[int] = None, dry_run: Optional[bool] = None, integrator: Optional[Any] = None, error_estimate: Optional[bool] = None, stop: Optional[Dict[str, Any]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Integrate a particle in an inertial, rotating or Earth frame, with model terms and drift

        POST /v1/trajectory. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            particle (required): object
            frame: default {"type": "inertial"}
            forces: array of any (<= 32 items)
            fictitious: terms modelled in a rotating or earth frame: a list, or "auto" (model only the
                    terms that matter at the requested accuracy); default all four
            relativity: relativistic corrections: "auto" (default: each is judged from the answer's run
                    - its largest size eps relative to the acceleration it corrects, measured along the
                    run, over the run's phase V T / L (L, V the largest |r| and |v|, T the duration):
                    estimated effect eps (1 + V T / L), above target/10 (the safety of fictitious
                    "auto") it is included and the scene runs again; a correction needed that cannot be
                    modelled is a 422 naming it) or the list to model (an empty list: Newtonian).
                    relativistic: dp/dt = F with p = gamma m v for every force, integrated in (r, u =
                    gamma v), inertial frame, |v| < c; schwarzschild_1pn: the 1PN acceleration (GM/(c^2
                    d^2)) [(4 GM/d - v^2) n + 4 (n.v) v] about the one central_gravity mass
                    (Schwarzschild field, harmonic coordinates; periapsis advance 6 pi GM/(c^2 a (1 -
                    e^2)) per orbit), inertial frame; not both at once; default "auto"
            t_end (required): s
            samples: integer >= 2, <= 100000; default 101
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            integrator: a method (adaptive: rtol/atol; fixed-step: dt), or {"accuracy": preset}, or
                    {"target_error": relative error}; default {"accuracy": "balanced"}. GET
                    /v1/integrators lists the methods and presets.
            error_estimate: when the scene has no exact or first-order reference, run it again at a
                    tighter setting (adaptive: rtol/100, atol/100, or radau15/rk8pd at round-off when
                    that is beyond the method; fixed step: dt/2, Richardson-scaled) and report the
                    difference; default false
            stop: object
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/trajectory', body, (('particle', particle), ('frame', frame), ('forces', forces), ('fictitious', fictitious), ('relativity', relativity), ('t_end', t_end), ('samples', samples), ('dry_run', dry_run), ('integrator', integrator), ('error_estimate', error_estimate), ('stop', stop), ('cost', cost)))

    def compare(self, body: Optional[Dict[str, Any]] = None, *, operation: Optional[str] = None, request: Optional[Dict[str, Any]] = None, runs: Optional[List[Any]] = None, sweep: Optional[Dict[str, Any]] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Run one scene with many integrator settings: error, drift, steps and CPU per run

        POST /v1/compare. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            operation (required): the operation compared
            request (required): object
            runs: integrator blocks, one row each; give runs or sweep
            sweep: object
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/compare', body, (('operation', operation), ('request', request), ('runs', runs), ('sweep', sweep), ('dry_run', dry_run), ('cost', cost)))

    def frames_effective_force(self, body: Optional[Dict[str, Any]] = None, *, frame: Optional[Dict[str, Any]] = None, particle: Optional[Dict[str, Any]] = None, force: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The fictitious forces in an accelerating, rotating frame, term by term (translational, Euler, Coriolis, centrifugal), and the effective force and acceleration seen in the frame

        POST /v1/frames/effective-force. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            frame (required): how the frame moves (at the instant considered)
            particle (required): object
            force: the real (inertial) force on the particle, N, components on the frame's axes; default
                    [0,0,0]
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/frames/effective-force', body, (('frame', frame), ('particle', particle), ('force', force), ('cost', cost)))

    def frames_rotating_liquid(self, body: Optional[Dict[str, Any]] = None, *, omega: Optional[float] = None, g: Optional[float] = None, radius: Optional[float] = None, depth: Optional[float] = None, container_height: Optional[float] = None, radii: Optional[List[float]] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The free surface of a liquid turning with its container: the paraboloid z = z0 + omega^2 r^2/(2g), its centre and rim heights at fixed volume, the dry disc, spilling

        POST /v1/frames/rotating-liquid. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            omega (required): rad/s, the container's rotation rate about its vertical axis
            g: m/s^2, gravity (default standard gravity); default 9.80665
            radius (required): m, inner radius R of the cylindrical container
            depth (required): m, depth h0 of the liquid at rest
            container_height: m, height H of the wall (optional): answers whether the liquid spills and
                    the rate at which it starts to; must be >= depth
            radii: m, radii (each <= radius) at which to give the surface's height above the bottom and
                    its slope
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/frames/rotating-liquid', body, (('omega', omega), ('g', g), ('radius', radius), ('depth', depth), ('container_height', container_height), ('radii', radii), ('cost', cost)))

    def earth_gravity(self, body: Optional[Dict[str, Any]] = None, *, latitude_deg: Optional[float] = None, height: Optional[float] = None, radius: Optional[float] = None, gm: Optional[float] = None, g0: Optional[float] = None, omega: Optional[float] = None, sidereal_day: Optional[float] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Effective gravity on a rotating spherical Earth at a latitude and height (magnitude, radial and horizontal parts, plumb-line deviation), beside the WGS 84 ellipsoid's normal gravity

        POST /v1/earth/gravity. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            latitude_deg (required): degrees, north positive: geocentric on the sphere, geodetic on the
                    ellipsoid
            height: m above the sphere / the ellipsoid, from the deepest trench to 100 km; default 0
            radius: m, radius of the spherical model; default the IUGG mean radius 6371008.8 m (use
                    6378137 for the equatorial radius); default 6371008.8
            gm: m^3/s^2, the sphere's GM (default IERS 2010 / WGS 84); at most one of gm, g0; default
                    398600441800000
            g0: m/s^2, gravitation GM/R^2 at the sphere's surface (radius R, without the centrifugal
                    part): sets GM = g0 R^2; at most one of gm, g0
            omega: rad/s, the rotation rate (default IERS 2010 / WGS 84, the one default of every
                    operation); at most one of omega, sidereal_day; default 7.292115e-05
            sidereal_day: s, the rotation period relative to the stars: sets omega = 2 pi /
                    sidereal_day; at most one of omega, sidereal_day
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/earth/gravity', body, (('latitude_deg', latitude_deg), ('height', height), ('radius', radius), ('gm', gm), ('g0', g0), ('omega', omega), ('sidereal_day', sidereal_day), ('cost', cost)))

    def earth_tides(self, body: Optional[Dict[str, Any]] = None, *, body_: Optional[Any] = None, moon: Optional[Dict[str, Any]] = None, sun: Optional[Dict[str, Any]] = None, gm_earth: Optional[float] = None, angle_deg: Optional[float] = None, radius: Optional[float] = None, named_bodies: Optional[str] = None, on: Optional[Any] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Tidal acceleration of the Moon, the Sun or any body, exact (without cancellation) and to first order in r/d, equilibrium tide heights, spring and neap tides

        POST /v1/earth/tides. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            body_ (required): the tide-raising body: "moon", "sun" or {gm (m^3/s^2) or mass (kg),
                    distance (m, centre to centre)}
            moon: the Moon used by body "moon" and by spring_neap: any of gm or mass, distance; default
                    DE440 GM, 3.844e8 m
            sun: the Sun used by body "sun" and by spring_neap: any of gm or mass, distance; default
                    DE440 GM, 1 au
            gm_earth: m^3/s^2, the Earth's GM in the tide height (g = GM_E / r^2); default IERS 2010;
                    for tides raised on another body use on (gm_earth set to that body's GM is the
                    older, deprecated form); default 398600441800000
            angle_deg: degrees, angle at the Earth's centre between the body and the point; default 0
            radius: m, distance of the point from the Earth's centre; for tides raised on another body
                    use on (radius set to that body's radius is the older, deprecated form); default
                    6371008.8
            named_bodies: the constants of the named bodies ("moon", "sun", and `on`): DE440 (default:
                    GM_moon 4.902800118e12, GM_sun 1.32712440041279419e20 m^3/s^2, JPL DE440) or legacy
                    (the values mechd used before DE440: the Moon's mass 7.342e22 kg, GM = G m; GM_sun
                    1.32712440018e20, DE405); the answer states the values used and their source
                    (body.source, on.source, spring_neap.moon_source, sun_source) and named_bodies the
                    set; default "DE440"
            on: the body the tides are raised on (default the Earth of radius and gm_earth): "earth",
                    "moon" or "sun" (the set's GM and mean radius: 6371008.8 m, 1.7374e6 m, 6.957e8 m),
                    or {gm (m^3/s^2) or mass (kg), radius (m): the point's distance from its centre}; a
                    named body takes radius to move the point. The tide-raising body's distance and
                    angle_deg are then from its centre. Replaces the older way, still accepted as a
                    deprecated alias: radius and gm_earth set to the other body's radius and GM (not
                    both forms at once)
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/earth/tides', body, (('body', body_), ('moon', moon), ('sun', sun), ('gm_earth', gm_earth), ('angle_deg', angle_deg), ('radius', radius), ('named_bodies', named_bodies), ('on', on), ('cost', cost)))

    def scenes_falling_object(self, body: Optional[Dict[str, Any]] = None, *, height: Optional[float] = None, latitude_deg: Optional[float] = None, g: Optional[float] = None, omega_magnitude: Optional[float] = None, sidereal_day: Optional[float] = None, model: Optional[str] = None, accuracy: Optional[str] = None, target_error: Optional[float] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Drop from a height near the Earth: east (and small south) deflection vs the notes' formula

        POST /v1/scenes/falling-object. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            height (required): drop height above the ground, m (released at rest)
            latitude_deg (required): geographic latitude, degrees (north > 0)
            g: local effective g, m/s^2 (its centrifugal part included, notes §1.3); default 9.80665
            omega_magnitude: Earth rotation rate, rad/s (IERS 2010); default 7.292115e-05
            sidereal_day: s, the Earth's rotation period relative to the stars (86164.0989 s for the
                    default rate): sets the rotation rate to 2 pi / sidereal_day; give it or the rate,
                    not both
            model: the equations of motion: auto (default: the fictitious terms that matter at the
                    requested accuracy, model.terms says which), coriolis (r'' = g - 2 w x r', Coriolis
                    only, as most textbooks solve the scene: the centrifugal term at the launch point is
                    inside the effective g), coriolis_centrifugal (r'' = g - 2 w x r' - w x (w x r), the
                    centrifugal term's change along the path too); physics_model in the answer names the
                    one solved; default "auto"
            accuracy: preset (relative error 1e-3, 1e-8, 1e-10, 1e-11); or target_error; default
                    "balanced"
            target_error: relative error on positions and velocities (not with accuracy)
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/scenes/falling-object', body, (('height', height), ('latitude_deg', latitude_deg), ('g', g), ('omega_magnitude', omega_magnitude), ('sidereal_day', sidereal_day), ('model', model), ('accuracy', accuracy), ('target_error', target_error), ('dry_run', dry_run), ('cost', cost)))

    def scenes_vertical_shot(self, body: Optional[Dict[str, Any]] = None, *, speed: Optional[float] = None, height: Optional[float] = None, latitude_deg: Optional[float] = None, g: Optional[float] = None, omega_magnitude: Optional[float] = None, sidereal_day: Optional[float] = None, model: Optional[str] = None, accuracy: Optional[str] = None, target_error: Optional[float] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Shot straight up near the Earth: lands west, (4/3) W cos(lat) sqrt(8 h^3/g), vs numerical

        POST /v1/scenes/vertical-shot. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            speed: initial upward speed, m/s (or give height)
            height: height reached without rotation, m: speed = sqrt(2 g h)
            latitude_deg (required): geographic latitude, degrees (north > 0)
            g: local effective g, m/s^2 (its centrifugal part included, notes §1.3); default 9.80665
            omega_magnitude: Earth rotation rate, rad/s (IERS 2010); default 7.292115e-05
            sidereal_day: s, the Earth's rotation period relative to the stars (86164.0989 s for the
                    default rate): sets the rotation rate to 2 pi / sidereal_day; give it or the rate,
                    not both
            model: the equations of motion: auto (default: the fictitious terms that matter at the
                    requested accuracy, model.terms says which), coriolis (r'' = g - 2 w x r', Coriolis
                    only, as most textbooks solve the scene: the centrifugal term at the launch point is
                    inside the effective g), coriolis_centrifugal (r'' = g - 2 w x r' - w x (w x r), the
                    centrifugal term's change along the path too); physics_model in the answer names the
                    one solved; default "auto"
            accuracy: preset (relative error 1e-3, 1e-8, 1e-10, 1e-11); or target_error; default
                    "balanced"
            target_error: relative error on positions and velocities (not with accuracy)
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/scenes/vertical-shot', body, (('speed', speed), ('height', height), ('latitude_deg', latitude_deg), ('g', g), ('omega_magnitude', omega_magnitude), ('sidereal_day', sidereal_day), ('model', model), ('accuracy', accuracy), ('target_error', target_error), ('dry_run', dry_run), ('cost', cost)))

    def scenes_cannonball(self, body: Optional[Dict[str, Any]] = None, *, speed: Optional[float] = None, elevation_deg: Optional[float] = None, azimuth_deg: Optional[float] = None, latitude_deg: Optional[float] = None, g: Optional[float] = None, omega_magnitude: Optional[float] = None, sidereal_day: Optional[float] = None, model: Optional[str] = None, accuracy: Optional[str] = None, target_error: Optional[float] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Cannonball at any elevation and azimuth: Coriolis deflection, range and flight-time change

        POST /v1/scenes/cannonball. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            speed (required): muzzle speed v0, m/s
            elevation_deg (required): inclination above the horizontal (the notes' problems 4-5 theta;
                    the notes' spherical theta from the vertical is 90 - elevation)
            azimuth_deg: the notes' phi: from east towards north, degrees (0 east, 90 north); default 0
            latitude_deg (required): geographic latitude, degrees (north > 0)
            g: local effective g, m/s^2 (its centrifugal part included, notes §1.3); default 9.80665
            omega_magnitude: Earth rotation rate, rad/s (IERS 2010); default 7.292115e-05
            sidereal_day: s, the Earth's rotation period relative to the stars (86164.0989 s for the
                    default rate): sets the rotation rate to 2 pi / sidereal_day; give it or the rate,
                    not both
            model: the equations of motion: auto (default: the fictitious terms that matter at the
                    requested accuracy, model.terms says which), coriolis (r'' = g - 2 w x r', Coriolis
                    only, as most textbooks solve the scene: the centrifugal term at the launch point is
                    inside the effective g), coriolis_centrifugal (r'' = g - 2 w x r' - w x (w x r), the
                    centrifugal term's change along the path too); physics_model in the answer names the
                    one solved; default "auto"
            accuracy: preset (relative error 1e-3, 1e-8, 1e-10, 1e-11); or target_error; default
                    "balanced"
            target_error: relative error on positions and velocities (not with accuracy)
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/scenes/cannonball', body, (('speed', speed), ('elevation_deg', elevation_deg), ('azimuth_deg', azimuth_deg), ('latitude_deg', latitude_deg), ('g', g), ('omega_magnitude', omega_magnitude), ('sidereal_day', sidereal_day), ('model', model), ('accuracy', accuracy), ('target_error', target_error), ('dry_run', dry_run), ('cost', cost)))

    def scenes_foucault(self, body: Optional[Dict[str, Any]] = None, *, latitude_deg: Optional[float] = None, length: Optional[float] = None, g: Optional[float] = None, omega_magnitude: Optional[float] = None, sidereal_day: Optional[float] = None, mass: Optional[float] = None, release: Optional[Dict[str, Any]] = None, swings: Optional[float] = None, precessions: Optional[float] = None, duration: Optional[float] = None, integrator: Optional[Dict[str, Any]] = None, accuracy: Optional[str] = None, fictitious: Optional[Any] = None, target_error: Optional[float] = None, error_estimate: Optional[bool] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """Foucault pendulum: the full nonlinear pendulum in the Earth frame, precession vs W sin(lat)

        POST /v1/scenes/foucault. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            latitude_deg (required): geographic latitude, degrees (south negative)
            length: l, m: rod or cable length (Foucault's Pantheon pendulum: 67 m); default 67
            g: local effective gravity, m/s^2 (includes the centrifugal acceleration of the origin, as
                    in the notes); default 9.80665
            omega_magnitude: Earth's rotation rate W, rad/s (default IERS 2010); default 7.292115e-05
            sidereal_day: s, the Earth's rotation period relative to the stars (86164.0989 s for the
                    default rate): sets the rotation rate to 2 pi / sidereal_day; give it or the rate,
                    not both
            mass: bob mass, kg (scales the energy only; Foucault's bob: 28 kg); default 28
            release: default: from rest at 3 degrees, towards the east
            swings: length of the run in swings (full periods of the planar pendulum at this amplitude);
                    at most one of swings, precessions, duration; default 100
            precessions: length of the run in full turns of the swing plane, 2 pi / (W |sin lat|)
            duration: length of the run, s
            integrator: constrained symplectic methods: rattle (order 2) or its Yoshida triple jump
                    (order 4); given (method or steps_per_swing), used as given (200 steps per swing by
                    default); absent, the predictive chooser picks both for accuracy or target_error
                    (diagnostics.selection)
            accuracy: preset: relative error 1e-3, 1e-8, 1e-10, 1e-11 of the swing period and of the
                    precession rate (relative to W); the chooser picks the method and steps per swing
                    predicted cheapest to meet it (not with target_error, nor with integrator.method /
                    steps_per_swing)
            fictitious: "auto" (default) or the list of terms to model; coriolis is the effect and must
                    be in it
            target_error: relative accuracy wanted of the precession rate (relative to W) and the period
                    (or the accuracy preset's): without integrator.method / steps_per_swing the chooser
                    picks the cheapest method and steps per swing predicted to meet it; fictitious auto
                    leaves out a term whose estimated effect is below target/10; default 1e-06
            error_estimate: run again with half the steps per swing and report the Richardson estimate
                    of the error; default true
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/scenes/foucault', body, (('latitude_deg', latitude_deg), ('length', length), ('g', g), ('omega_magnitude', omega_magnitude), ('sidereal_day', sidereal_day), ('mass', mass), ('release', release), ('swings', swings), ('precessions', precessions), ('duration', duration), ('integrator', integrator), ('accuracy', accuracy), ('fictitious', fictitious), ('target_error', target_error), ('error_estimate', error_estimate), ('dry_run', dry_run), ('cost', cost)))

    def scenes_rotating_table(self, body: Optional[Dict[str, Any]] = None, *, experiment: Optional[str] = None, omega: Optional[float] = None, radius: Optional[float] = None, mass: Optional[float] = None, position: Optional[List[float]] = None, velocity: Optional[List[float]] = None, t_end: Optional[float] = None, samples: Optional[int] = None, accuracy: Optional[str] = None, target_error: Optional[float] = None, dry_run: Optional[bool] = None, cost: Optional[bool] = None) -> Dict[str, Any]:
        """The notes' rotating-table puck experiments seen from the inertial and the rotating frame

        POST /v1/scenes/rotating-table. The request is `body` (a dict) and/or the keyword arguments below
        (merged; a keyword that is not None wins). Returns the answer as a dict; raises
        ProblemError (ValidationError at the JSON pointer of a bad field, ...) or
        ConnectionFailed. GET /v1 has the full schema and an example.

        Args:
            experiment: one of "through_center", "at_rest", "custom"; default "through_center"
            omega (required): table rotation rate about +z, rad/s, non-zero
            radius: r1, m (through_center, at_rest); default 1
            mass: number > 0, <= 1e+30; default 1
            position: custom: inertial position at t = 0, m
            velocity: custom: inertial velocity, m/s
            t_end: custom: duration, s
            samples: integer >= 2, <= 100000; default 21
            accuracy: preset (relative error 1e-3, 1e-8, 1e-10, 1e-11); or target_error; default
                    "balanced"
            target_error: relative error on positions and velocities (not with accuracy)
            dry_run: true: answer only diagnostics.selection (every candidate method with its predicted
                    error, evaluations and CPU seconds from the calibrated model) without integrating:
                    no samples, no pilot run; default false
            cost: envelope key, taken by every operation: false leaves out the measured time (the cost
                    block of the operations that integrate), so equal requests give byte-identical
                    answers; in a batch, false also applies to every item; default true
        """
        return self._operation('/v1/scenes/rotating-table', body, (('experiment', experiment), ('omega', omega), ('radius', radius), ('mass', mass), ('position', position), ('velocity', velocity), ('t_end', t_end), ('samples', samples), ('accuracy', accuracy), ('target_error', target_error), ('dry_run', dry_run), ('cost', cost)))


OPERATIONS = {
    'vectors': '/v1/vectors',
    'tensor_symmetric': '/v1/tensor/symmetric',
    'rotation_convert': '/v1/rotation/convert',
    'rotation_compose': '/v1/rotation/compose',
    'rotation_apply': '/v1/rotation/apply',
    'rotation_euler_rates': '/v1/rotation/euler-rates',
    'rigid_inertia': '/v1/rigid/inertia',
    'rigid_rotate': '/v1/rigid/rotate',
    'rigid_top': '/v1/rigid/top',
    'rigid_stability': '/v1/rigid/stability',
    'rigid_free_symmetric_top': '/v1/rigid/free-symmetric-top',
    'rigid_struck_ball': '/v1/rigid/struck-ball',
    'rigid_topple': '/v1/rigid/topple',
    'small_oscillations': '/v1/small-oscillations',
    'coupled_oscillations': '/v1/coupled-oscillations',
    'relativity_boost': '/v1/relativity/boost',
    'relativity_particle': '/v1/relativity/particle',
    'relativity_dot': '/v1/relativity/dot',
    'relativity_mass_energy': '/v1/relativity/mass-energy',
    'relativity_rocket': '/v1/relativity/rocket',
    'relativity_force': '/v1/relativity/force',
    'relativity_lagrangian': '/v1/relativity/lagrangian',
    'relativity_michelson_morley': '/v1/relativity/michelson-morley',
    'relativity_velocity_addition': '/v1/relativity/velocity-addition',
    'relativity_interval': '/v1/relativity/interval',
    'relativity_worldline': '/v1/relativity/worldline',
    'relativity_doppler': '/v1/relativity/doppler',
    'relativity_fields': '/v1/relativity/fields',
    'relativity_charge_in_fields': '/v1/relativity/charge-in-fields',
    'relativity_kinematics_invariant_mass': '/v1/relativity/kinematics/invariant-mass',
    'relativity_kinematics_decay': '/v1/relativity/kinematics/decay',
    'relativity_kinematics_compton': '/v1/relativity/kinematics/compton',
    'relativity_kinematics_elastic': '/v1/relativity/kinematics/elastic',
    'relativity_kinematics_collision': '/v1/relativity/kinematics/collision',
    'gr_schwarzschild': '/v1/gr/schwarzschild',
    'gr_geodesic': '/v1/gr/geodesic',
    'hamiltonian_flow': '/v1/hamiltonian/flow',
    'hamiltonian_liouville': '/v1/hamiltonian/liouville',
    'hamiltonian_poincare': '/v1/hamiltonian/poincare',
    'hamiltonian_phase_area': '/v1/hamiltonian/phase-area',
    'hamiltonian_rotating_frame': '/v1/hamiltonian/rotating-frame',
    'hamiltonian_circular_orbit': '/v1/hamiltonian/circular-orbit',
    'continuum_string': '/v1/continuum/string',
    'continuum_rod': '/v1/continuum/rod',
    'trajectory': '/v1/trajectory',
    'compare': '/v1/compare',
    'frames_effective_force': '/v1/frames/effective-force',
    'frames_rotating_liquid': '/v1/frames/rotating-liquid',
    'earth_gravity': '/v1/earth/gravity',
    'earth_tides': '/v1/earth/tides',
    'scenes_falling_object': '/v1/scenes/falling-object',
    'scenes_vertical_shot': '/v1/scenes/vertical-shot',
    'scenes_cannonball': '/v1/scenes/cannonball',
    'scenes_foucault': '/v1/scenes/foucault',
    'scenes_rotating_table': '/v1/scenes/rotating-table',
}
HANDWRITTEN_OPERATIONS = {'/v1/check': 'check', '/v1/batch': 'batch'}
# ---- END GENERATED OPERATIONS ----


class _NoRedirect(urllib.request.HTTPRedirectHandler):
    """mechd never redirects; following one would hand the bearer token to another URL."""

    def redirect_request(self, req, fp, code, msg, headers, newurl):
        return None


_OPENER = urllib.request.build_opener(_NoRedirect())

# What a dropped connection looks like: refused, reset, closed before the status line.
_DROPPED = (ConnectionRefusedError, ConnectionResetError, ConnectionAbortedError, BrokenPipeError,
            http.client.RemoteDisconnected, http.client.IncompleteRead, http.client.BadStatusLine)


class ConnectionDropped(Exception):
    """Internal: a retryable connection failure (wrapped into ConnectionFailed)."""


class Client(_Operations):
    """A mechd server at base_url. Thread-safe: one Client may be shared by threads.

    token: bearer token sent as 'Authorization: Bearer TOKEN' (default: $MECHD_TOKEN; None
    or "" sends none). timeout: socket timeout per attempt (s). retries: how many times a
    503 or a dropped connection is retried (0: never). max_retry_wait: cap on each wait (s),
    whatever Retry-After says. backoff: first wait after a dropped connection (s), doubled
    each time. retry_total: no retry starts later than this many seconds after the first
    attempt. on_retry(attempt, wait_seconds, error): optional hook called before each
    retry's sleep (for logging). batch_path: the server's batch operation."""

    batch_path = "/v1/batch"
    batch_limit = 100

    def __init__(self, base_url: str = DEFAULT_URL, timeout: float = 60.0, retries: int = 3,
                 max_retry_wait: float = 30.0, on_retry: Optional[Callable[[int, float, "MechdError"], None]] = None,
                 user_agent: str = "mechd.py", token: Optional[str] = None, backoff: float = 0.25,
                 retry_total: float = 120.0):
        self.base_url = base_url.rstrip("/")
        self.timeout = timeout
        self.retries = max(0, int(retries))
        self.max_retry_wait = max_retry_wait
        self.backoff = max(0.0, float(backoff))
        self.retry_total = max(0.0, float(retry_total))
        self.on_retry = on_retry
        self.user_agent = user_agent
        self.token = token if token is not None else os.environ.get("MECHD_TOKEN") or None
        if self.token is not None and ("\r" in self.token or "\n" in self.token):
            raise ValueError("token: a bearer token cannot hold a line break")
        self._server_batch = None  # None: unknown yet; False: the server has no batch
        self._lock = threading.Lock()
        # Connection reuse: one kept-alive HTTP connection per thread (http.client is
        # not thread-safe), all closed by close() or at the end of a `with` block. A
        # proxy from the environment (http_proxy ...) makes every request go through
        # urllib instead, one connection each.
        u = urllib.parse.urlsplit(self.base_url)
        self._scheme, self._host, self._port = u.scheme or "http", u.hostname or "", u.port
        self._prefix = u.path.rstrip("/")
        self._via_urllib = self._scheme not in ("http", "https") or bool(
            urllib.request.getproxies().get(self._scheme)
            and not urllib.request.proxy_bypass(u.netloc))
        self._local = threading.local()
        self._conns = []  # every connection opened, for close()

    def __enter__(self) -> "Client":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def close(self) -> None:
        """Close the kept-alive connections of every thread (the client stays usable: the
        next request opens a new one)."""
        with self._lock:
            conns, self._conns = self._conns, []
        for c in conns:
            c.close()
        self._local = threading.local()

    def _connection(self) -> http.client.HTTPConnection:
        conn = getattr(self._local, "conn", None)
        if conn is None:
            cls = http.client.HTTPSConnection if self._scheme == "https" else http.client.HTTPConnection
            conn = cls(self._host, self._port, timeout=self.timeout)
            self._local.conn = conn
            with self._lock:
                self._conns.append(conn)
        return conn

    # -- low level ------------------------------------------------------------------
    def request(self, method: str, path: str, data: Optional[bytes] = None,
                content_type: Optional[str] = "application/json",
                query: Optional[Dict[str, str]] = None) -> Tuple[int, Dict[str, str], bytes]:
        """One HTTP exchange without retries: returns (status, headers dict, body bytes).
        Raises ConnectionFailed when no HTTP answer comes back."""
        try:
            return self._exchange(method, path, data, content_type, query)
        except ConnectionDropped as e:
            raise ConnectionFailed(None, None, None, str(e)) from None

    def _exchange(self, method, path, data, content_type, query):
        url = self.base_url + path
        if query:
            url += "?" + urllib.parse.urlencode(query)
        headers = {"Accept": "application/json, application/problem+json",
                   "User-Agent": self.user_agent}
        if self.token:
            headers["Authorization"] = "Bearer " + self.token
        if data is not None and content_type:
            headers["Content-Type"] = content_type
        if not self._via_urllib:
            target = self._prefix + path + (url[len(self.base_url + path):] if query else "")
            return self._exchange_kept(method, url, target, data, headers)
        req = urllib.request.Request(url, data=data, method=method, headers=headers)
        try:
            with _OPENER.open(req, timeout=self.timeout) as resp:
                return resp.status, {k.lower(): v for k, v in resp.getheaders()}, resp.read()
        except urllib.error.HTTPError as e:
            try:
                body = e.read()
            except _DROPPED + (OSError,) as ex:
                raise ConnectionDropped("%s %s: %s" % (method, url, ex)) from None
            finally:
                e.close()
            return e.code, {k.lower(): v for k, v in (e.headers or {}).items()}, body
        except (urllib.error.URLError, socket.timeout, ConnectionError, OSError, http.client.HTTPException) as e:
            reason = getattr(e, "reason", e)
            if isinstance(reason, socket.timeout) or isinstance(e, socket.timeout):
                raise Timeout(None, None, None, "%s %s: no answer within %g s"
                              % (method, url, self.timeout)) from None
            if isinstance(reason, _DROPPED) or isinstance(e, _DROPPED):
                raise ConnectionDropped("%s %s: %s" % (method, url, reason)) from None
            raise ConnectionFailed(None, None, None, "%s %s: %s" % (method, url, reason)) from None

    def _exchange_kept(self, method, url, target, data, headers):
        """One exchange on this thread's kept-alive connection. A connection the server
        closed while it was idle is replaced once, at once (nothing was sent on it);
        otherwise failures map as in _exchange."""
        for attempt in (0, 1):
            conn = self._connection()
            reused = conn.sock is not None
            try:
                conn.request(method, target or "/", body=data, headers=headers)
                resp = conn.getresponse()
                body = resp.read()
                hdrs = {k.lower(): v for k, v in resp.getheaders()}
                if resp.will_close:
                    conn.close()
                return resp.status, hdrs, body
            except socket.timeout:
                conn.close()
                raise Timeout(None, None, None, "%s %s: no answer within %g s"
                              % (method, url, self.timeout)) from None
            except _DROPPED + (OSError, http.client.HTTPException) as e:
                conn.close()
                if reused and attempt == 0 and isinstance(e, _DROPPED):
                    continue
                if isinstance(e, _DROPPED):
                    raise ConnectionDropped("%s %s: %s" % (method, url, e)) from None
                raise ConnectionFailed(None, None, None, "%s %s: %s" % (method, url, e)) from None
        raise ConnectionDropped("%s %s: closed twice" % (method, url))

    def _once(self, method, path, data, content_type):
        status, headers, body = self._exchange(method, path, data, content_type, None)
        try:
            doc = json.loads(body.decode("utf-8")) if body else None
        except (ValueError, UnicodeDecodeError):
            doc = None
        if 200 <= status < 300:
            if doc is None and body:
                raise MechdError(status, None, None, "the answer is not JSON: %r" % body[:200],
                                 headers.get("x-request-id"))
            return doc
        retry_after = None
        if "retry-after" in headers:
            try:
                retry_after = max(0.0, float(headers["retry-after"]))
            except ValueError:
                retry_after = None
        message = None if isinstance(doc, dict) else (body[:200].decode("utf-8", "replace") or
                                                       "HTTP %d" % status)
        raise error_for(status, doc, retry_after, message, headers.get("x-request-id"))

    def send(self, method: str, path: str, data: Optional[bytes] = None,
             content_type: Optional[str] = "application/json") -> Any:
        """Send raw bytes, retrying a 503 and a dropped connection (see the module's
        "Retries"); returns the parsed JSON answer or raises MechdError."""
        attempt = 0
        start = time.monotonic()
        while True:
            try:
                return self._once(method, path, data, content_type)
            except ServerBusy as e:
                err = e
                wait = e.retry_after if e.retry_after is not None else 1.0
                wait = min(max(wait, 0.05), self.max_retry_wait)
            except ConnectionDropped as e:
                err = ConnectionFailed(None, None, None, str(e))
                wait = min(self.backoff * (2 ** attempt), self.max_retry_wait)
            if attempt >= self.retries or time.monotonic() - start + wait > self.retry_total:
                raise err
            attempt += 1
            if self.on_retry:
                self.on_retry(attempt, wait, err)
            time.sleep(wait)

    def call(self, path: str, body: Optional[Dict[str, Any]] = None, method: Optional[str] = None) -> Any:
        """POST body (a dict) as JSON to path, or GET when body is None; the answer as a dict."""
        if method is None:
            method = "GET" if body is None else "POST"
        data = None if body is None else json.dumps(body, allow_nan=False).encode("utf-8")
        return self.send(method, path, data)

    def _operation(self, path, body, fields):
        """POST body merged with the fields (name, value) that are not None."""
        if body is not None and not isinstance(body, dict):
            raise TypeError("body: a dict (the request), got %s" % type(body).__name__)
        req = dict(body or {})
        for k, v in fields:
            if v is not None:
                req[k] = v
        return self.call(path, req)

    # -- resources ------------------------------------------------------------------
    def catalog(self) -> Dict[str, Any]:
        """GET /v1: every operation with its summary, schema and example request."""
        return self.call("/v1")

    def examples(self) -> List[Dict[str, Any]]:
        """GET /v1/examples: the course notes' worked examples (a list)."""
        return self.call("/v1/examples")["examples"]

    def example(self, example_id: str) -> Dict[str, Any]:
        """One example of GET /v1/examples by id; KeyError if there is none."""
        for e in self.examples():
            if e["id"] == example_id:
                return e
        raise KeyError(example_id)

    def run_example(self, example: Union[str, Dict[str, Any]]) -> Tuple[Any, Any, bool]:
        """Run an example (a dict or its id): (answer, value at its pointer, matches the notes)."""
        if isinstance(example, str):
            example = self.example(example)
        answer = self.call(example["operation"], example["request"])
        got, ok = check_example(example, answer)
        return answer, got, ok

    def integrators(self) -> Dict[str, Any]:
        """GET /v1/integrators: the ODE methods and accuracy presets."""
        return self.call("/v1/integrators")

    def health(self) -> bool:
        """True when GET /healthz answers 2xx."""
        status, _, _ = self.request("GET", "/healthz")
        return 200 <= status < 300

    def check(self, operation: str, request: Dict[str, Any], pointer: str, value: Any,
              relative: Optional[float] = None, absolute: Optional[float] = None,
              significant_figures: Optional[int] = None, *, kind: Optional[str] = None,
              unit: Optional[str] = None, scale: Optional[float] = None,
              reveal: Optional[bool] = None,
              significant_figures_in: Optional[str] = None) -> Dict[str, Any]:
        """POST /v1/check: grade a student's value at pointer of operation's answer.

        kind ("axis", "quaternion", "angle", "eigenvectors", ...; default what the
        operation's response schema says of the field), unit (the student's unit: "km", "eV", "deg", ...), scale (the
        problem's size in the field's unit, for values that should be zero) and reveal
        (the feedback names the expected value) are passed when not None;
        significant_figures_in ("field" or "answer") says in which unit the figures count.
        value may be what the student typed ("27.9 deg"): it is graded, never refused.
        """
        tol = {k: v for k, v in (("relative", relative), ("absolute", absolute),
                                 ("significant_figures", significant_figures),
                                 ("significant_figures_in", significant_figures_in),
                                 ("scale", scale)) if v is not None}
        answer = {"pointer": pointer, "value": value}
        if kind is not None:
            answer["kind"] = kind
        if unit is not None:
            answer["unit"] = unit
        body = {"operation": operation, "request": request, "answer": answer}
        if tol:
            body["tolerance"] = tol
        if reveal is not None:
            body["reveal"] = reveal
        return self.call("/v1/check", body)

    # -- many requests ----------------------------------------------------------------
    def batch(self, items: List[Any], concurrency: int = 4,
              use_server: bool = True) -> List[Any]:
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


def main(argv: Optional[List[str]] = None) -> int:
    """The mechd-client command (also python3 -m mechd, python3 mechd.py); see --help.
    Exit status: 0 the answer printed; 1 the server refused the request (its
    problem+json printed); 2 usage; 3 no answer (connection failed, timeout)."""
    import argparse
    import sys
    argv = sys.argv[1:] if argv is None else list(argv)
    ap = argparse.ArgumentParser(
        prog="mechd-client",
        description="Send one request to a mechd server and print its JSON answer.",
        epilog="The request body is JSON text, '-' (read from standard input) or @FILE; "
               "without one, PATH is fetched with GET. Examples: mechd-client /v1 ; "
               "mechd-client /v1/relativity/boost @boost.json ; "
               "echo '{...}' | mechd-client --url http://mechd:8080 /v1/check -")
    ap.add_argument("path", metavar="PATH", help="the operation's path, e.g. /v1/rigid/inertia")
    ap.add_argument("body", metavar="BODY", nargs="?",
                    help="the request: JSON text, - for standard input, or @FILE")
    ap.add_argument("--url", default=os.environ.get("MECHD_URL", DEFAULT_URL),
                    help="the server (default: $MECHD_URL, else %s)" % DEFAULT_URL)
    ap.add_argument("--token-file", metavar="FILE",
                    help="a file holding the bearer token (default: $MECHD_TOKEN)")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per attempt (default 60)")
    ap.add_argument("--version", action="version", version="%(prog)s " + __version__)
    args = ap.parse_args(argv)
    if not args.path.startswith("/"):
        ap.error("PATH must start with '/' (e.g. /v1/rigid/inertia), not %r" % args.path)
    body = None
    try:
        if args.body == "-":
            text = sys.stdin.read()
        elif args.body is not None and args.body.startswith("@"):
            with open(args.body[1:], encoding="utf-8") as f:
                text = f.read()
        else:
            text = args.body
        if text is not None:
            body = json.loads(text)
        token = None
        if args.token_file:
            with open(args.token_file, encoding="utf-8") as f:
                token = f.read().strip()
    except OSError as e:
        ap.error(str(e))
    except ValueError as e:
        ap.error("the request is not JSON: %s" % e)
    try:
        with Client(args.url, timeout=args.timeout, token=token) as client:
            print(json.dumps(client.call(args.path, body), indent=2))
        return 0
    except ConnectionFailed as e:
        sys.stderr.write("mechd-client: %s\n" % e.detail)
        return 3
    except MechdError as e:
        print(json.dumps(e.problem or {"detail": e.detail}, indent=2))
        return 1


if __name__ == "__main__":
    import sys
    sys.exit(main())
