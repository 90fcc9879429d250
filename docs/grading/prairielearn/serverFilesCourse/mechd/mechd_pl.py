"""mechd for PrairieLearn questions: one function, mechd(operation, request, data), that
runs a mechd operation for a question's server.py (or the external grader) and returns
its answer.

It needs nothing installed by the course staff on hosted PrairieLearn. Where mechd is
found, first that exists wins:

  1. the static offline evaluator shipped in the course repository, next to this file:
     serverFilesCourse/mechd/bin/mechd-eval (copy build/mechd-eval-static there, or
     unpack dist/mechd-eval-static-*.tar.gz, and commit it with its executable bit);
     server.py finds it through data["options"]["server_files_course_path"], the
     external grader under /grade/serverFilesCourse;
  2. MECHD_EVAL, else mechd-eval on the PATH (the external-grader image built from
     docker/, where it is /usr/local/bin/mechd-eval);
  3. a mechd service over HTTP: MECHD_URL and MECHD_TOKEN, or the file
     serverFilesCourse/mechd/service.json {"url": "https://mechd.example.edu",
     "token": "..."} (sent as "Authorization: Bearer <token>"; keep the course
     repository private if it holds a token).

Python 3.8+ standard library only.
"""
import json
import os
import shutil
import subprocess
import urllib.error
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
TIMEOUT = 30  # seconds for one evaluation


class MechdError(RuntimeError):
    """mechd refused the request (the problem+json is in .problem) or could not run."""

    def __init__(self, message, problem=None):
        super().__init__(message)
        self.problem = problem


def _course_dir(data):
    """serverFilesCourse/mechd of the course, from PrairieLearn's data when given."""
    opts = (data or {}).get("options") or {}
    base = opts.get("server_files_course_path")
    if base:
        return os.path.join(base, "mechd")
    return HERE


def _evaluator(data):
    """The path of an offline evaluator, or None."""
    shipped = os.path.join(_course_dir(data), "bin", "mechd-eval")
    if os.path.isfile(shipped) and os.access(shipped, os.X_OK):
        return shipped
    env = os.environ.get("MECHD_EVAL")
    if env:
        return env
    return shutil.which("mechd-eval")


def _service(data):
    """(url, token) of a mechd service, or (None, None)."""
    url, token = os.environ.get("MECHD_URL"), os.environ.get("MECHD_TOKEN")
    cfg = os.path.join(_course_dir(data), "service.json")
    if not url and os.path.isfile(cfg):
        with open(cfg) as f:
            c = json.load(f)
        url, token = c.get("url"), c.get("token")
    return url, token


def mechd(operation, request, data=None):
    """The answer (a dict) of one mechd operation, e.g. mechd("/v1/check", {...}, data).
    data: PrairieLearn's data dict (to find serverFilesCourse), or None. Raises
    MechdError when mechd refuses the request or cannot be reached."""
    exe = _evaluator(data)
    if exe:
        p = subprocess.run([exe], input=json.dumps({"operation": operation,
                                                    "request": request}).encode(),
                           capture_output=True, timeout=TIMEOUT)
        if p.returncode == 0:
            return json.loads(p.stdout)
        try:
            problem = json.loads(p.stdout)
        except ValueError:
            problem = None
        raise MechdError((problem or {}).get("detail") or p.stderr.decode(errors="replace"),
                         problem)
    url, token = _service(data)
    if not url:
        raise MechdError("mechd not found: ship serverFilesCourse/mechd/bin/mechd-eval, "
                         "or set MECHD_EVAL or MECHD_URL (docs/grading.md)")
    headers = {"Content-Type": "application/json"}
    if token:
        headers["Authorization"] = "Bearer " + token
    req = urllib.request.Request(url.rstrip("/") + operation, json.dumps(request).encode(),
                                 headers)
    try:
        with urllib.request.urlopen(req, timeout=TIMEOUT) as r:
            return json.load(r)
    except urllib.error.HTTPError as e:
        body = e.read().decode(errors="replace")
        try:
            problem = json.loads(body)
        except ValueError:
            problem = None
        raise MechdError((problem or {}).get("detail") or body, problem) from None


def check(data, operation, request, pointer, value, **extra):
    """mechd's verdict (POST /v1/check) on a student's value at pointer of the answer of
    operation on request. extra: answer fields (kind, unit) and tolerance / reveal."""
    answer = {"pointer": pointer, "value": value}
    for k in ("kind", "unit"):
        if k in extra:
            answer[k] = extra.pop(k)
    body = {"operation": operation, "request": request, "answer": answer}
    body.update(extra)
    return mechd("/v1/check", body, data)
