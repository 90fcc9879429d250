#!/usr/bin/python3
"""test_grading_questions.py — the ready questions of docs/grading/ run
against mechd's offline evaluator, and their answers checked against closed forms
computed here.

Usage: /usr/bin/python3 test_grading_questions.py PATH/TO/mechd
(mechd-eval is looked for next to it; it is what the questions call, through
MECHD_EVAL).

- PrairieLearn (prairielearn/RotatedBoxAxis): info.json and question.html agree
  with server.py; generate() on many seeds gives answers that change with the
  parameters and equal the closed forms (I = m (b^2 + c^2) / 12 about x', the
  axis (cos t, sin t, 0)); grade() gives 1 to right answers (either sign and any
  length of the axis), 0 to wrong ones, and its feedback never shows the value.
- WeBWorK (webwork/lorentz_boost.pg): its tables are what make_tables.py prints
  from mechd now; the PG file's own computation, run by perl with PG's functions
  stubbed, gives gamma = 1/sqrt(1 - b^2), ct' = gamma, x' = -gamma b for every
  variant.
- Moodle CodeRunner (moodle/coderunner_gamma.xml): the template, rendered as
  CodeRunner's Twig would for each test case, prints the expected "OK" for the
  question's own answer and not for a wrong formula.
- Moodle STACK (moodle/stack_box_moments.xml): exactly what make_stack.py
  writes from mechd now; its Maxima lists equal the closed forms.
- Every XML file under docs/grading is well-formed (xml.etree).
Prints "N passed, M failed"; exits 1 on failure.
"""
import importlib.util
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

from mechdtest import check, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_grading_questions.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
EVAL = os.path.join(os.path.dirname(MECHD), "mechd-eval")
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
Q = os.path.join(ROOT, "docs", "grading")
os.environ["MECHD_EVAL"] = EVAL
os.environ.pop("MECHD_URL", None)


def rel(a, b):
    return abs(a - b) / abs(b) if b else abs(a)


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


# ---- XML well-formed ------------------------------------------------------------
xmls = []
for d, _, files in os.walk(Q):
    xmls += [os.path.join(d, f) for f in files if f.endswith(".xml")]
check("docs/grading holds the CodeRunner and STACK XML files", len(xmls) >= 2, repr(xmls))
for x in sorted(xmls):
    try:
        ET.parse(x)
        ok = True
    except ET.ParseError as e:
        ok = e
    check("well-formed XML: %s" % os.path.relpath(x, ROOT), ok is True, repr(ok))

# ---- PrairieLearn ------------------------------------------------------------------
pl = os.path.join(Q, "prairielearn", "RotatedBoxAxis")
info = json.load(open(os.path.join(pl, "info.json")))
check("PrairieLearn info.json: v3 question with a uuid",
      info.get("type") == "v3" and re.fullmatch(r"[0-9a-f-]{36}", info.get("uuid", "")), info)
html = open(os.path.join(pl, "question.html")).read()
names = set(re.findall(r'answers-name="([^"]+)"', html))
server = load(os.path.join(pl, "server.py"), "pl_server")


def new_data():
    return {"params": {}, "correct_answers": {}, "submitted_answers": {}, "format_errors": {},
            "partial_scores": {}, "score": 0, "feedback": {}}


seen_I, seen_axis, good = set(), set(), True
datas = []
for seed in range(40):
    random.seed(seed)
    d = new_data()
    server.generate(d)
    p, ca = d["params"], d["correct_answers"]
    want_I = p["m"] * (p["b"] ** 2 + p["c"] ** 2) / 12  # a is the longest edge: smallest about x'
    t = math.radians(p["theta"])
    want_n = (math.cos(t), math.sin(t), 0.0)
    dot = sum(ca[k] * w for k, w in zip(("nx", "ny", "nz"), want_n))
    if rel(ca["I"], want_I) > 1e-13 or abs(abs(dot) - 1) > 1e-13:
        good = False
        print("  seed %d: %r %r" % (seed, p, ca))
    seen_I.add(round(ca["I"], 9))
    seen_axis.add(round(abs(ca["nx"]), 9))
    datas.append(d)
check("PrairieLearn generate(): correct_answers equal the closed forms (40 seeds)", good)
check("PrairieLearn: the parameters change the answer (moment and axis)",
      len(seen_I) >= 5 and len(seen_axis) >= 4, "%d moments, %d axes" % (len(seen_I), len(seen_axis)))
check("PrairieLearn: question.html asks for every correct_answers key",
      names == set(datas[0]["correct_answers"]), "%r vs %r" % (names, datas[0]["correct_answers"]))


def graded(d, answers):
    d = json.loads(json.dumps(d))
    d["submitted_answers"] = answers
    d["partial_scores"], d["feedback"] = {}, {}
    server.grade(d)
    return d


d = datas[0]
ca = d["correct_answers"]
r = graded(d, dict(ca))
check("PrairieLearn grade(): the correct answers score 1", r["score"] == 1, r["partial_scores"])
r = graded(d, {"I": float("%.3g" % ca["I"]), "nx": -2 * ca["nx"], "ny": -2 * ca["ny"], "nz": 0})
check("PrairieLearn grade(): 3 figures, and the axis reversed and doubled, score 1",
      r["score"] == 1, r["partial_scores"])
r = graded(d, {"I": ca["I"] * 1.1, "nx": ca["nx"], "ny": ca["ny"], "nz": 0})
check("PrairieLearn grade(): a moment 10 % off scores 0 for I, 1/2 overall",
      r["partial_scores"]["I"]["score"] == 0 and r["score"] == 0.5, r["partial_scores"])
fb = json.dumps(r["partial_scores"]) + json.dumps(r["feedback"])
leaks = [s for s in ("%.3g" % ca["I"], "%.4g" % ca["I"], repr(ca["I"]), "%.3g" % ca["nx"])
         if s in fb]
check("PrairieLearn grade(): the feedback does not show the expected values", not leaks,
      "%r in %s" % (leaks, fb))
r = graded(d, {"I": ca["I"], "nx": -ca["ny"], "ny": ca["nx"], "nz": 0})
check("PrairieLearn grade(): the perpendicular axis (y') scores 0 for the axis",
      r["partial_scores"]["nx"]["score"] == 0 and r["score"] == 0.5, r["partial_scores"])
r = graded(d, {"I": "five"})
check("PrairieLearn grade(): a missing or non-numeric answer scores 0 without an exception",
      r["score"] == 0, r["partial_scores"])

# ---- WeBWorK -------------------------------------------------------------------------
pg = open(os.path.join(Q, "webwork", "lorentz_boost.pg")).read()
tables = re.search(r"# BEGIN MECHD TABLES\n(.*?)# END MECHD TABLES", pg, re.S).group(1).strip()
made = subprocess.run(["/usr/bin/python3", os.path.join(Q, "webwork", "make_tables.py")],
                      capture_output=True, timeout=120, text=True)
check("WeBWorK: the PG tables are what make_tables.py prints from mechd now",
      made.returncode == 0 and made.stdout.strip() == tables, made.stdout + made.stderr)
code = pg[pg.index("DOCUMENT();"):pg.index("BEGIN_PGML")]
stubs = r'''
package PGReal; sub new { my ($c, $v) = @_; bless {v => $v}, $c }
sub with { my ($s, %o) = @_; $s->{tol} = $o{tolerance}; $s->{type} = $o{tolType}; $s }
package main;
sub DOCUMENT {} sub loadMacros {} sub Context {}
sub Real { PGReal->new($_[0]) }
sub random { my ($lo, $hi, $step) = @_; die "range" if $ENV{PICK} > $hi; $ENV{PICK} }
'''
good, variants = True, 0
with tempfile.NamedTemporaryFile("w", suffix=".pl", delete=False) as f:
    f.write(stubs + code + '\nprint join(" ", $b, $gamma->{v}, $ctp->{v}, $xp->{v}, '
            '$gamma->{tol}, $gamma->{type}, scalar(@beta)), "\\n";\n')
    script = f.name
n = 1
i = 0
while i < n:
    out = subprocess.run(["perl", script], env=dict(os.environ, PICK=str(i)), capture_output=True,
                         text=True, timeout=30)
    if out.returncode != 0:
        good = False
        print("  perl: " + out.stderr)
        break
    b, g, ctp, xp, tol, typ, n = out.stdout.split()
    b, g, ctp, xp, tol, n = float(b), float(g), float(ctp), float(xp), float(tol), int(n)
    gw = 1 / math.sqrt(1 - b * b)
    if rel(g, gw) > 1e-14 or rel(ctp, gw) > 1e-14 or rel(xp, -gw * b) > 1e-14 or \
            typ != "relative" or not 1e-12 <= tol <= 0.01:
        good = False
        print("  variant %d: %s" % (i, out.stdout))
    variants += 1
    i += 1
os.unlink(script)
check("WeBWorK: the PG computation gives gamma, ct', x' of the closed forms (%d variants)"
      % variants, good and variants >= 4)

# ---- CodeRunner --------------------------------------------------------------------------
cr = ET.parse(os.path.join(Q, "moodle", "coderunner_gamma.xml")).getroot().find("question")
template = cr.find("template").text
model = cr.find("answer").text
cases = [(tc.find("extra/text").text, tc.find("expected/text").text)
         for tc in cr.findall("testcases/testcase")]


def run_template(student, extra):
    src = template.replace("{{ STUDENT_ANSWER }}", student).replace("{{ TEST.extra }}", extra)
    p = subprocess.run(["/usr/bin/python3", "-c", src], capture_output=True, text=True, timeout=60)
    return p.stdout.strip() if p.returncode == 0 else "exit %d: %s" % (p.returncode, p.stderr)


check("CodeRunner: the question has test cases", len(cases) >= 3, repr(cases))
outs = [(x, run_template(model, x), want) for x, want in cases]
check("CodeRunner: the template prints the expected output for the model answer",
      all(o == w for _, o, w in outs), repr(outs))
wrong = "def gamma(beta):\n    return 1 / (1 - beta * beta)\n"
o = run_template(wrong, "0.6")
check("CodeRunner: a wrong formula is not OK, and is told its relative error, not the value",
      o != "OK" and "relative error" in o and "1.25" not in o, o)

# ---- STACK ----------------------------------------------------------------------------------
path = os.path.join(Q, "moodle", "stack_box_moments.xml")
made = subprocess.run(["/usr/bin/python3", os.path.join(Q, "moodle", "make_stack.py")],
                      capture_output=True, timeout=120, text=True)
check("STACK: the XML is exactly what make_stack.py writes from mechd now",
      made.returncode == 0 and made.stdout == open(path).read(), made.stderr[:300])
qv = ET.parse(path).getroot().find("question/questionvariables/text").text


def maxima(name):
    return json.loads(re.search(r"^%s: (\[.*\]);$" % name, qv, re.M).group(1))


sets, imins, imaxs = maxima("P"), maxima("Imins"), maxima("Imaxs")
good = len(sets) == len(imins) == len(imaxs) >= 4
for (m, a, b, c), lo, hi in zip(sets, imins, imaxs):
    mom = sorted(m * (y * y + z * z) / 12 for y, z in ((b, c), (a, c), (a, b)))
    good = good and rel(lo, mom[0]) < 1e-14 and rel(hi, mom[2]) < 1e-14
check("STACK: the Maxima answers equal m (b^2 + c^2) / 12 ... for every parameter set", good,
      "%r %r %r" % (sets, imins, imaxs))

sys.exit(summary())
