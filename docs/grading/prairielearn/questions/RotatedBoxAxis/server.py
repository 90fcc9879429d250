"""PrairieLearn question: the smallest principal moment of a turned box and its axis,
graded by mechd (docs/grading.md, "PrairieLearn").

generate() draws the box and asks mechd (/v1/rigid/inertia) for the answers;
grade() sends each submitted answer to mechd's /v1/check and uses its verdict and
its feedback: the moment as the student typed it ("12.5", "12.5 kg m^2",
"1.25e8 g cm^2") to 3 significant figures counted in the student's unit, the axis as
an axis (either sign, any length, 2 %). The feedback names slips (a power of ten,
the wrong unit, a sign) and what was expected, never the value.

mechd is found by serverFilesCourse/mechd/mechd_pl.py: the static evaluator shipped in
the course (serverFilesCourse/mechd/bin/mechd-eval), so hosted PrairieLearn needs
nothing installed.
"""
import math
import os
import random
import sys

MOMENT_FIGURES = 3       # significant figures of the moment
AXIS_TOLERANCE = 0.02    # chord between unit directions (about 1.1 degrees)


def _mechd_pl(data):
    """serverFilesCourse/mechd/mechd_pl.py: from PrairieLearn's options, else found
    relative to this question (questions/<name>/ -> serverFilesCourse/)."""
    base = (data.get("options") or {}).get("server_files_course_path")
    if not base:
        base = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                            "serverFilesCourse")
    path = os.path.join(base, "mechd")
    if path not in sys.path:
        sys.path.insert(0, path)
    import mechd_pl
    return mechd_pl


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
    principal = _mechd_pl(data).mechd("/v1/rigid/inertia", box_request(p), data)["principal"]
    axis = principal["axes"][0]  # rows ascending with the moments
    data["correct_answers"] = {"I": "%.4g kg m^2" % principal["moments"][0],
                               "nx": axis[0], "ny": axis[1], "nz": axis[2]}


def grade(data):
    m = _mechd_pl(data)
    p, sub = data["params"], data["submitted_answers"]
    req = box_request(p)
    # The moment: whatever the student typed is graded (never an exception).
    r = m.check(data, "/v1/rigid/inertia", req, "/principal/moments/0", sub.get("I"),
                tolerance={"significant_figures": MOMENT_FIGURES,
                           "significant_figures_in": "answer"})
    moment = (1.0 if r["correct"] else 0.0, r["feedback"])
    n = [sub.get(k) for k in ("nx", "ny", "nz")]
    r = m.check(data, "/v1/rigid/inertia", req, "/principal/axes/0", n, kind="axis",
                tolerance={"absolute": AXIS_TOLERANCE})
    axis = (1.0 if r["correct"] else 0.0, r["feedback"])
    data["partial_scores"] = {"I": {"score": moment[0], "weight": 3, "feedback": moment[1]}}
    for k in ("nx", "ny", "nz"):
        data["partial_scores"][k] = {"score": axis[0], "weight": 1, "feedback": axis[1]}
    data["score"] = (3 * moment[0] + 3 * axis[0]) / 6
    data["feedback"]["moment"] = moment[1]
    data["feedback"]["axis"] = axis[1]
