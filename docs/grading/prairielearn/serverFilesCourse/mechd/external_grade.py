#!/usr/bin/env python3
"""PrairieLearn external grader for code questions graded by mechd
(docs/grading.md, "PrairieLearn: external grader").

PrairieLearn runs it in the grader image as the question's entrypoint
("python3 /grade/serverFilesCourse/mechd/external_grade.py") with the job mounted at
/grade (MECHD_PL_GRADE_ROOT overrides, for tests):

  /grade/student/<file>        the student's submitted file
  /grade/tests/cases.json      the question's cases (questions/<name>/tests/)
  /grade/serverFilesCourse/    this directory (info.json "serverFilesCourse": ["mechd/"])
  /grade/results/results.json  written here: score, message, one test per case

The student's code runs in a child Python process (its prints, exits and patched
builtins stay there) and hands back its return values; each is graded by mechd's
POST /v1/check against the operation named in cases.json, whose answer is never
shown. The cases are the listed ones plus seed_cases drawn per submission.
"""
import json
import os
import random
import subprocess
import sys

ROOT = os.environ.get("MECHD_PL_GRADE_ROOT", "/grade")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mechd_pl  # noqa: E402

CHILD = r"""
import json, sys
job = json.loads(sys.stdin.readline())
ns = {"__name__": "student"}
exec(compile(open(job["path"]).read(), job["file"], "exec"), ns)
out = []
for args in job["calls"]:
    try:
        r = ns[job["function"]](*args)
        out.append(json.loads(json.dumps(r, default=float)))
    except Exception as e:
        out.append({"error": "%s: %s" % (type(e).__name__, e)})
sys.stdout.write("\n" + json.dumps(out) + "\n")
"""


def fill(template, values):
    """The request with every string "{name}" replaced by that argument's value."""
    if isinstance(template, str) and template.startswith("{") and template.endswith("}"):
        return values.get(template[1:-1], template)
    if isinstance(template, list):
        return [fill(t, values) for t in template]
    if isinstance(template, dict):
        return {k: fill(v, values) for k, v in template.items()}
    return template


def student_results(spec, path, calls):
    """The student's return values (JSON), or {"error": text} per call."""
    job = {"path": path, "file": spec["file"], "function": spec["function"], "calls": calls}
    try:
        p = subprocess.run([sys.executable, "-I", "-c", CHILD], input=json.dumps(job) + "\n",
                           capture_output=True, text=True, timeout=20)
    except subprocess.TimeoutExpired:
        return [{"error": "no answer within 20 s"}] * len(calls)
    try:
        got = json.loads(p.stdout.strip().splitlines()[-1])
        if isinstance(got, list) and len(got) == len(calls):
            return got
    except (IndexError, ValueError):
        pass
    err = p.stderr.strip().splitlines()
    return [{"error": err[-1] if err else "the program stopped before returning"}] * len(calls)


def grade(root):
    spec = json.load(open(os.path.join(root, "tests", "cases.json")))
    path = os.path.join(root, "student", spec["file"])
    if not os.path.isfile(path):
        return {"gradable": False, "message": "No file %s was submitted." % spec["file"]}
    calls = [list(c) for c in spec["cases"]]
    rng = random.Random()
    for _ in range(int(spec.get("seed_cases", 0))):
        calls.append([round(rng.uniform(*spec["ranges"][a]), 3) for a in spec["args"]])
    results = student_results(spec, path, calls)
    tests, total = [], 0.0
    for args, got in zip(calls, results):
        name = "%s(%s)" % (spec["function"], ", ".join("%g" % a for a in args))
        if isinstance(got, dict) and "error" in got:
            verdict = {"correct": False, "feedback": got["error"]}
        else:
            req = fill(spec["request"], dict(zip(spec["args"], args)))
            verdict = mechd_pl.check(None, spec["operation"], req, spec["pointer"], got,
                                     tolerance=spec.get("tolerance", {"relative": 1e-9}))
        points = 1.0 if verdict["correct"] else 0.0
        total += points
        tests.append({"name": name, "points": points, "max_points": 1,
                      "message": verdict["feedback"]})
    score = total / len(calls) if calls else 0.0
    return {"gradable": True, "score": score, "tests": tests,
            "message": "%d of %d cases right." % (int(total), len(calls))}


def main():
    try:
        results = grade(ROOT)
    except Exception as e:  # the grader's own failure: not the student's score
        results = {"gradable": False, "message": "grading failed: %s" % e}
    os.makedirs(os.path.join(ROOT, "results"), exist_ok=True)
    with open(os.path.join(ROOT, "results", "results.json"), "w") as f:
        json.dump(results, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
