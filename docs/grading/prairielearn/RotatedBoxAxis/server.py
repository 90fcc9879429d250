"""PrairieLearn question: the smallest principal moment of a turned box and its axis,
graded by mechd (docs/grading.md, "Ready questions").

mechd computes the answers (generate) and grades them (grade) with /v1/check: the
moment to 3 significant figures, the axis as an axis (either sign, any length, 2 %).
Feedback names what was expected (kind, shape, unit), never the value.

Where mechd runs: MECHD_URL (e.g. http://mechd.internal:8080) sends HTTP requests to
a mechd service; otherwise the offline evaluator MECHD_EVAL (default "mechd-eval", the
static build of docs/grading.md copied into the image) is run as a subprocess.
"""
import json
import math
import os
import random
import subprocess
import urllib.error
import urllib.request

MOMENT_FIGURES = 3       # significant figures of the moment
AXIS_TOLERANCE = 0.02    # chord between unit directions (about 1.1 degrees)


def mechd(operation, request):
    """The answer (a dict) of one mechd operation; raises RuntimeError when refused."""
    url = os.environ.get("MECHD_URL")
    if url:
        req = urllib.request.Request(url.rstrip("/") + operation, json.dumps(request).encode(),
                                     {"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=30) as r:
                return json.load(r)
        except urllib.error.HTTPError as e:
            raise RuntimeError(e.read().decode(errors="replace")) from None
    p = subprocess.run([os.environ.get("MECHD_EVAL", "mechd-eval")],
                       input=json.dumps({"operation": operation, "request": request}).encode(),
                       capture_output=True, timeout=30)
    if p.returncode != 0:
        raise RuntimeError(p.stdout.decode(errors="replace") or p.stderr.decode(errors="replace"))
    return json.loads(p.stdout)


def box_request(p):
    """The /v1/rigid/inertia request of the question's box (turned theta degrees about z)."""
    return {"bodies": [{"shape": "box", "mass": p["m"], "size": [p["a"], p["b"], p["c"]],
                        "position": [0, 0, 0],
                        "orientation": {"axis_angle": {"axis": [0, 0, 1],
                                                       "angle": math.radians(p["theta"])}}}]}


def generate(data):
    # Every parameter changes the answer: m and b, c the moment, theta the axis.
    p = {"m": random.choice([2, 3, 6, 12]), "a": random.choice([4, 5, 6]),
         "b": random.choice([1, 2, 3]), "c": random.choice([1, 2, 3]),
         "theta": random.choice([15, 20, 30, 40, 50, 60, 75])}
    data["params"] = p
    principal = mechd("/v1/rigid/inertia", box_request(p))["principal"]
    axis = principal["axes"][0]  # rows ascending with the moments
    data["correct_answers"] = {"I": principal["moments"][0],
                               "nx": axis[0], "ny": axis[1], "nz": axis[2]}


def check(p, pointer, value, **extra):
    body = {"operation": "/v1/rigid/inertia", "request": box_request(p),
            "answer": {"pointer": pointer, "value": value}}
    body["answer"].update(extra.pop("answer", {}))
    body.update(extra)
    return mechd("/v1/check", body)


def grade(data):
    p, sub = data["params"], data["submitted_answers"]
    scores = {}
    if isinstance(sub.get("I"), (int, float)):
        r = check(p, "/principal/moments/0", sub["I"],
                  tolerance={"significant_figures": MOMENT_FIGURES})
        scores["I"] = (1.0 if r["correct"] else 0.0, r["feedback"])
    else:
        scores["I"] = (0.0, "Give a number, in kg m².")
    n = [sub.get(k) for k in ("nx", "ny", "nz")]
    if all(isinstance(x, (int, float)) for x in n):
        r = check(p, "/principal/axes/0", n, answer={"kind": "axis"},
                  tolerance={"absolute": AXIS_TOLERANCE})
        axis_score = (1.0 if r["correct"] else 0.0, r["feedback"])
    else:
        axis_score = (0.0, "Give the three components of a vector along the axis.")
    for k in ("nx", "ny", "nz"):
        scores[k] = axis_score
    data["partial_scores"] = {
        k: {"score": s, "weight": 3 if k == "I" else 1, "feedback": fb}
        for k, (s, fb) in scores.items()}
    data["score"] = (3 * scores["I"][0] + 3 * axis_score[0]) / 6
    data["feedback"]["axis"] = axis_score[1]
