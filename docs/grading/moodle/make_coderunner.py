#!/usr/bin/python3
"""Write coderunner_gamma.xml: a Moodle CodeRunner question ("write gamma(beta)") that
mechd grades inside the Jobe sandbox, and that cannot be passed by printing text:

    python3 docs/grading/moodle/make_coderunner.py > docs/grading/moodle/coderunner_gamma.xml

How the per-test template (Python 3) grades, in the order it runs:
  * The student's code is never part of the template's program: CodeRunner's Twig
    puts it into a string literal ({{ STUDENT_ANSWER | e('py') }} escapes '\\' and
    '"'), and the template runs it in a child Python process. Whatever the child
    prints, however it exits and whatever builtins it patches stays in the child.
  * Each test's extra field is a seed: the template draws three speeds from it
    (random.Random(seed)), so every test asks other numbers and the hidden tests'
    numbers are not in the example.
  * The child calls the student's gamma() at those speeds and hands back numbers;
    the template asks mechd's offline evaluator (POST /v1/check through mechd-eval)
    whether each is the Lorentz factor to 1e-9: the expected value is computed by
    mechd inside the template and never printed.
  * The template prints one line per speed for a wrong value with mechd's feedback
    (which names slips such as the reciprocal, never the value), or, when all three
    are right, "gamma(beta) is right at beta = ...", naming that test's speeds; that
    line is the test's expected output.
  * The template makes itself undumpable (prctl PR_SET_DUMPABLE 0), so a child of the
    same user cannot open /proc/<template>/fd/1 to write into the graded output.

tests/integration/test_grading_questions.py regenerates the XML and compares, renders
the template as CodeRunner does for each test case and runs it with the model answer,
a wrong formula, and programs that print the expected text, exit early or patch
builtins (those score 0).
"""
import random
from xml.sax.saxutils import escape

SEEDS = [(11, True), (2027, False), (31337, False), (4242, False)]  # (seed, shown as example)
TOLERANCE = 1e-9  # relative: far above mechd's recommended 1e-12 (a closed form)


def speeds(seed):
    """The three speeds (v/c) of a test, drawn from its seed as the template draws them."""
    rng = random.Random(seed)
    return [round(rng.uniform(0.05, 0.995), 3) for _ in range(3)]


def right_line(seed):
    b = speeds(seed)
    return "gamma(beta) is right at beta = %g, %g and %g" % tuple(b)


TEMPLATE = r'''"""Graded by mechd (docs/grading.md, "Moodle: CodeRunner"): the student's code runs
in a child process; mechd's /v1/check compares its values with the Lorentz factor."""
import json
import math
import os
import random
import subprocess
import sys

STUDENT = """{{ STUDENT_ANSWER | e('py') }}"""
SEED = {{ TEST.extra }}
MECHD_EVAL = os.environ.get("MECHD_EVAL", "/usr/local/bin/mechd-eval")
TOLERANCE = %(tol)r


def undumpable():
    """A child of the same user can then not open /proc/<this>/fd/1 (the graded output)."""
    try:
        import ctypes
        ctypes.CDLL(None).prctl(4, 0, 0, 0, 0)  # PR_SET_DUMPABLE, 0
    except Exception:
        pass


CHILD = r"""
import json, sys
job = json.loads(sys.stdin.readline())
ns = {"__name__": "student"}
exec(compile(job["code"], "answer.py", "exec"), ns)
out = []
for b in job["speeds"]:
    try:
        out.append(float(ns["gamma"](b)))
    except Exception as e:
        out.append("%%s: %%s" %% (type(e).__name__, e))
sys.stdout.write("\n" + json.dumps(out) + "\n")
"""


def student_values(betas):
    """The student's gamma at each speed: numbers, or the error text per speed."""
    try:
        p = subprocess.run([sys.executable, "-I", "-c", CHILD], timeout=10,
                           input=json.dumps({"code": STUDENT, "speeds": betas}) + "\n",
                           capture_output=True, text=True)
    except subprocess.TimeoutExpired:
        return ["no answer within 10 s"] * len(betas)
    lines = p.stdout.strip().splitlines()
    try:
        got = json.loads(lines[-1])
        if isinstance(got, list) and len(got) == len(betas):
            return got
    except (IndexError, ValueError):
        pass
    err = p.stderr.strip().splitlines()
    return [err[-1] if err else "your program stopped before gamma() returned"] * len(betas)


def check(beta, value):
    """mechd's verdict on value as the Lorentz factor at beta (POST /v1/check)."""
    body = {"operation": "/v1/relativity/boost",
            "request": {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [beta, 0, 0]}},
            "answer": {"pointer": "/gamma", "value": value},
            "tolerance": {"relative": TOLERANCE}}
    p = subprocess.run([MECHD_EVAL], input=json.dumps({"operation": "/v1/check",
                                                       "request": body}).encode(),
                       capture_output=True, timeout=30)
    return json.loads(p.stdout)


undumpable()
rng = random.Random(SEED)
betas = [round(rng.uniform(0.05, 0.995), 3) for _ in range(3)]
wrong = []
for beta, got in zip(betas, student_values(betas)):
    if isinstance(got, bool) or not isinstance(got, (int, float)) or not math.isfinite(got):
        wrong.append("gamma(%%g): %%s" %% (beta, got if isinstance(got, str) else "not a number"))
        continue
    verdict = check(beta, got)
    if not verdict.get("correct"):
        wrong.append("gamma(%%g) = %%r: %%s" %% (beta, got, verdict.get("feedback",
                                                                   verdict.get("detail"))))
if wrong:
    print("\n".join(wrong))
else:
    print("gamma(beta) is right at beta = %%g, %%g and %%g" %% tuple(betas))
''' % {"tol": TOLERANCE}


def testcase(seed, example):
    return """      <testcase testtype="0" useasexample="{ex}" hiderestiffail="0" mark="1.0000000">
        <testcode><text></text></testcode>
        <stdin><text></text></stdin>
        <expected><text>{want}</text></expected>
        <extra><text>{seed}</text></extra>
        <display><text>{display}</text></display>
      </testcase>""".format(ex=1 if example else 0, want=escape(right_line(seed)), seed=seed,
                            display="SHOW" if example else "HIDE")


def question():
    cases = "\n".join(testcase(s, ex) for s, ex in SEEDS)
    return """<?xml version="1.0" encoding="UTF-8"?>
<!-- Moodle question bank export, written by docs/grading/moodle/make_coderunner.py (do not
     edit by hand): a CodeRunner question ("write gamma(beta)") graded by mechd's offline
     evaluator inside the Jobe sandbox (mechd-eval-static copied into the Jobe image as
     /usr/local/bin/mechd-eval, see docs/grading.md). Import: Question bank > Import >
     Moodle XML. tests/integration/test_grading_questions.py runs its template. -->
<quiz>
  <question type="coderunner">
    <name><text>Lorentz factor gamma(beta) (graded by mechd)</text></name>
    <questiontext format="html">
      <text><![CDATA[<p>Write a Python function <code>gamma(beta)</code> returning the Lorentz
factor of a speed <code>beta</code> = v/c (0 &le; beta &lt; 1). Each test calls it at three
speeds of its own; the hidden tests use other speeds.</p>]]></text>
    </questiontext>
    <generalfeedback format="html"><text></text></generalfeedback>
    <defaultgrade>1</defaultgrade>
    <penalty>0.1</penalty>
    <hidden>0</hidden>
    <coderunnertype>python3</coderunnertype>
    <prototypetype>0</prototypetype>
    <allornothing>1</allornothing>
    <penaltyregime>10, 20, ...</penaltyregime>
    <precheck>0</precheck>
    <showsource>0</showsource>
    <answerboxlines>8</answerboxlines>
    <answer><![CDATA[def gamma(beta):
    return 1 / (1 - beta * beta) ** 0.5
]]></answer>
    <validateonsave>1</validateonsave>
    <testsplitterre><![CDATA[|#<ab@17943918#@>#\\n|ms]]></testsplitterre>
    <language>python3</language>
    <acelang></acelang>
    <sandbox>jobesandbox</sandbox>
    <grader>EqualityGrader</grader>
    <cputimelimitsecs>20</cputimelimitsecs>
    <memlimitmb></memlimitmb>
    <sandboxparams><![CDATA[{"numprocs": 50}]]></sandboxparams>
    <templateparams></templateparams>
    <hoisttemplateparams>1</hoisttemplateparams>
    <twigall>0</twigall>
    <uiplugin>ace</uiplugin>
    <attachments>0</attachments>
    <iscombinatortemplate>0</iscombinatortemplate>
    <allowmultiplestdins>0</allowmultiplestdins>
    <template><![CDATA[""" + TEMPLATE + """]]></template>
    <testcases>
""" + cases + """
    </testcases>
  </question>
</quiz>
"""


if __name__ == "__main__":
    print(question(), end="")
