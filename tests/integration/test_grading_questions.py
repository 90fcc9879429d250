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
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

from mechdtest import check, start_mechd, stop_mechd, summary

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
# A course as PrairieLearn checks it out: questions/ and serverFilesCourse/, with the
# static evaluator shipped in serverFilesCourse/mechd/bin/, no MECHD_* variable and no
# mechd-eval on the PATH (nothing installed by staff), data["options"] as
# PrairieLearn's freeform server passes it.
course = tempfile.mkdtemp(prefix="plcourse-")
shutil.copytree(os.path.join(Q, "prairielearn"), course, dirs_exist_ok=True)
shipped = os.path.join(course, "serverFilesCourse", "mechd", "bin", "mechd-eval")
static = os.path.join(os.path.dirname(MECHD), "mechd-eval-static")
shutil.copy(static if os.path.exists(static) else EVAL, shipped)
os.chmod(shipped, 0o755)
saved_env = {k: os.environ.pop(k) for k in list(os.environ) if k.startswith("MECHD_")}
saved_path = os.environ.get("PATH", "")
os.environ["PATH"] = "/usr/bin:/bin"
check("PrairieLearn: no mechd-eval on the PATH while the course runs",
      shutil.which("mechd-eval") is None)
pl = os.path.join(course, "questions", "RotatedBoxAxis")
OPTIONS = {"question_path": pl, "server_files_course_path": os.path.join(course, "serverFilesCourse"),
           "client_files_course_path": os.path.join(course, "clientFilesCourse")}
info = json.load(open(os.path.join(pl, "info.json")))
check("PrairieLearn info.json: v3 question with a uuid",
      info.get("type") == "v3" and re.fullmatch(r"[0-9a-f-]{36}", info.get("uuid", "")), info)
html = open(os.path.join(pl, "question.html")).read()
names = set(re.findall(r'answers-name="([^"]+)"', html))
server = load(os.path.join(pl, "server.py"), "pl_server")


def new_data():
    return {"params": {}, "correct_answers": {}, "submitted_answers": {}, "format_errors": {},
            "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": 1,
            "options": dict(OPTIONS)}


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
    got_I = float(ca["I"].split()[0])
    if rel(got_I, want_I) > 5e-4 or not ca["I"].endswith(" kg m^2") or abs(abs(dot) - 1) > 1e-13:
        good = False
        print("  seed %d: %r %r" % (seed, p, ca))
    seen_I.add(ca["I"])
    seen_axis.add(round(abs(ca["nx"]), 9))
    d["want_I"] = want_I
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
ca, I = d["correct_answers"], d["want_I"]
axis = {k: ca[k] for k in ("nx", "ny", "nz")}
r = graded(d, dict(axis, I="%.3g kg m^2" % I))
check("PrairieLearn grade(): the right answers score 1 (graded by the shipped evaluator)",
      r["score"] == 1, r["partial_scores"])
r = graded(d, {"I": "%.3g kg*m2" % I, "nx": -2 * ca["nx"], "ny": -2 * ca["ny"], "nz": 0})
check("PrairieLearn grade(): 3 figures in kg*m2, and the axis reversed and doubled, score 1",
      r["score"] == 1, r["partial_scores"])
r = graded(d, dict(axis, I="%.3g g cm^2" % (I * 1e7)))
check("PrairieLearn grade(): the moment in g cm^2 (figures counted in the student's unit) scores 1",
      r["score"] == 1, r["partial_scores"])
r = graded(d, dict(axis, I="%.3g" % (I * 1.1)))
check("PrairieLearn grade(): a moment 10 % off scores 0 for I, 1/2 overall",
      r["partial_scores"]["I"]["score"] == 0 and r["score"] == 0.5, r["partial_scores"])
fb = json.dumps(r["partial_scores"]) + json.dumps(r["feedback"])
leaks = [x for x in ("%.3g" % I, "%.4g" % I, repr(I), "%.3g" % ca["nx"]) if x in fb]
check("PrairieLearn grade(): the feedback does not show the expected values", not leaks,
      "%r in %s" % (leaks, fb))
r = graded(d, dict(axis, I="%.3g kg m^2" % (I * 1000)))
check("PrairieLearn grade(): a power-of-ten slip is named in mechd's feedback",
      r["partial_scores"]["I"]["score"] == 0
      and "1000 times too large" in r["partial_scores"]["I"]["feedback"], r["partial_scores"]["I"])
r = graded(d, dict(axis, I="%.3g m" % I))
check("PrairieLearn grade(): a length for a moment is wrong with feedback in words",
      r["partial_scores"]["I"]["score"] == 0
      and "A length was given" in r["partial_scores"]["I"]["feedback"], r["partial_scores"]["I"])
r = graded(d, {"I": ca["I"], "nx": -ca["ny"], "ny": ca["nx"], "nz": 0})
check("PrairieLearn grade(): the perpendicular axis (y') scores 0 for the axis",
      r["partial_scores"]["nx"]["score"] == 0 and r["score"] == 0.5, r["partial_scores"])
for odd in ({"I": "five"}, {"I": None}, {}, {"I": "", "nx": "a"}):
    r = graded(d, odd)
    check("PrairieLearn grade(): %r scores 0 with feedback, without an exception" % (odd,),
          r["score"] == 0 and r["partial_scores"]["I"]["feedback"].startswith("Not correct"),
          r["partial_scores"])
os.unlink(shipped)
sys.modules.pop("mechd_pl", None)
try:
    server.generate(new_data())
    missing = "no error"
except Exception as e:
    missing = str(e)
check("PrairieLearn: without the shipped evaluator the error says where to put it",
      "serverFilesCourse/mechd/bin/mechd-eval" in missing, missing)

# The HTTP path with a bearer token (a mechd service, MECHD_URL and MECHD_TOKEN).
tokdir = tempfile.mkdtemp(prefix="pltok-")
with open(os.path.join(tokdir, "token"), "w") as f:
    f.write("s3cret-token-for-the-test\n")
proc, port = start_mechd(MECHD, ["--token-file", os.path.join(tokdir, "token")])
try:
    os.environ["MECHD_URL"] = "http://127.0.0.1:%d" % port
    os.environ["MECHD_TOKEN"] = "s3cret-token-for-the-test"
    sys.modules.pop("mechd_pl", None)
    r = graded(d, dict(axis, I="%.3g kg m^2" % I))
    check("PrairieLearn grade() over HTTP with the bearer token scores 1", r["score"] == 1,
          r["partial_scores"])
    os.environ["MECHD_TOKEN"] = "wrong"
    try:
        graded(d, dict(axis, I="1"))
        err = "no error"
    except Exception as e:
        err = str(e)
    check("PrairieLearn over HTTP: a wrong token is reported, not graded", "token" in err, err)
finally:
    stop_mechd(proc)
    for k in ("MECHD_URL", "MECHD_TOKEN"):
        os.environ.pop(k, None)
    shutil.rmtree(tokdir)

# ---- PrairieLearn: the external grader (code question) ---------------------------------
ext = os.path.join(course, "questions", "BoxMomentCode")
einfo = json.load(open(os.path.join(ext, "info.json")))
opts = einfo.get("externalGradingOptions", {})
check("PrairieLearn external grader: info.json names the image, serverFilesCourse/mechd and "
      "the entrypoint", einfo.get("gradingMethod") == "External" and opts.get("enabled")
      and opts.get("serverFilesCourse") == ["mechd/"]
      and opts.get("entrypoint", "").endswith("/grade/serverFilesCourse/mechd/external_grade.py"),
      einfo)
shutil.copy(static if os.path.exists(static) else EVAL, shipped)
os.chmod(shipped, 0o755)


def external(student_code):
    """Run the external grader on a /grade directory laid out as PrairieLearn mounts it."""
    root = tempfile.mkdtemp(prefix="plgrade-")
    shutil.copytree(os.path.join(ext, "tests"), os.path.join(root, "tests"))
    shutil.copytree(os.path.join(course, "serverFilesCourse", "mechd"),
                    os.path.join(root, "serverFilesCourse", "mechd"))
    os.makedirs(os.path.join(root, "student"))
    with open(os.path.join(root, "student", "moments.py"), "w") as f:
        f.write(student_code)
    subprocess.run(["/usr/bin/python3", os.path.join(root, "serverFilesCourse", "mechd",
                                                     "external_grade.py")],
                   env={"PATH": "/usr/bin:/bin", "MECHD_PL_GRADE_ROOT": root}, timeout=120)
    res = json.load(open(os.path.join(root, "results", "results.json")))
    shutil.rmtree(root)
    return res


right = ("def principal_moments(m, a, b, c):\n"
         "    return sorted(m * (y * y + z * z) / 12 for y, z in ((b, c), (a, c), (a, b)))\n")
res = external(right)
check("external grader: the right code scores 1 on the listed and the random cases",
      res.get("gradable") and res.get("score") == 1 and len(res.get("tests", [])) == 8, res)
res = external(right.replace("/ 12", "/ 6"))
check("external grader: a factor 2 off scores 0 and mechd's feedback names it",
      res.get("score") == 0 and "twice" in res["tests"][0]["message"], res)
res = external("print('8 of 8 cases right.')\nimport os\nos._exit(0)\n")
check("external grader: a program that prints the message and exits scores 0",
      res.get("score") == 0, res)
res = external("import builtins\nbuiltins.sorted = lambda x: [5, 10, 13]\n"
               "def principal_moments(m, a, b, c):\n    return sorted(0)\n")
check("external grader: patched builtins (fixed answers) score at most the one case they fit",
      res.get("score") <= 1 / 8 + 1e-12, res)
os.environ["PATH"] = saved_path
os.environ.update(saved_env)
shutil.rmtree(course)

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
path = os.path.join(Q, "moodle", "coderunner_gamma.xml")
made = subprocess.run(["/usr/bin/python3", os.path.join(Q, "moodle", "make_coderunner.py")],
                      capture_output=True, timeout=60, text=True)
check("CodeRunner: the XML is exactly what make_coderunner.py writes",
      made.returncode == 0 and made.stdout == open(path).read(), made.stderr[:300])
cr = ET.parse(path).getroot().find("question")
template = cr.find("template").text
model = cr.find("answer").text
cases = [(tc.find("extra/text").text, tc.find("expected/text").text,
          tc.find("display/text").text, tc.get("useasexample"))
         for tc in cr.findall("testcases/testcase")]


def py_escape(text):
    """CodeRunner's Twig escaper e('py'): backslashes doubled, then '"' as '\\"'."""
    return text.replace("\\", "\\\\").replace('"', '\\"')


def run_template(student, extra):
    """The per-test template rendered as CodeRunner's Twig does, run as Jobe runs it."""
    src = (template.replace("{{ STUDENT_ANSWER | e('py') }}", py_escape(student))
           .replace("{{ TEST.extra }}", extra))
    p = subprocess.run(["/usr/bin/python3", "-c", src], capture_output=True, text=True, timeout=120)
    return p.stdout.strip() if p.returncode == 0 else "exit %d: %s" % (p.returncode, p.stderr)


def score(student):
    """CodeRunner's all-or-nothing mark: 1 when every test's output is its expected text."""
    return all(run_template(student, x) == w for x, w, _, _ in cases)


check("CodeRunner: the student's answer is only inside a string literal of the template",
      template.count("{{ STUDENT_ANSWER") == 1 and 'STUDENT = """{{ STUDENT_ANSWER | e(\'py\') }}"""'
      in template, template[:400])
check("CodeRunner: 4 tests, seeds as extra, one example shown, the others hidden",
      len(cases) == 4 and len({x for x, _, _, _ in cases}) == 4
      and [d for _, _, d, _ in cases].count("HIDE") == 3
      and [e for _, _, _, e in cases].count("1") == 1, repr(cases))
good = True
for x, want, _, _ in cases:
    b = random.Random(int(x))
    speeds = [round(b.uniform(0.05, 0.995), 3) for _ in range(3)]
    good = good and want == "gamma(beta) is right at beta = %g, %g and %g" % tuple(speeds)
check("CodeRunner: each test's expected text names the speeds drawn from its seed", good,
      repr(cases))
outs = [(x, run_template(model, x), w) for x, w, _, _ in cases]
check("CodeRunner: the model answer passes every test", all(o == w for _, o, w in outs),
      repr(outs))
o = run_template("def gamma(beta):\n    return (1 - beta * beta) ** 0.5\n", cases[1][0])
check("CodeRunner: 1/gamma fails, told the reciprocal by mechd, never the value",
      o != cases[1][1] and "reciprocal" in o and "%.6g" % (1 / math.sqrt(1 - 0.152 ** 2)) not in o, o)
example = cases[0][1]
games = {
    "prints the example's text and exits": "print(%r)\nimport sys\nsys.exit(0)\n" % example,
    "prints every expected text": "".join("print(%r)\n" % w for _, w, _, _ in cases)
                                 + "def gamma(b):\n    return 1\n",
    "exits early with os._exit": "import os\nos._exit(0)\n",
    "patches builtins": "import builtins, json\nbuiltins.abs = lambda x: 0\n"
                        "builtins.print = lambda *a, **k: None\njson.loads = lambda s: True\n"
                        "def gamma(b):\n    return 1\n",
    "breaks out of the string": 'x = """\nprint(%r)\nimport sys; sys.exit(0)\n"""\n' % example,
    "raises": "def gamma(b):\n    raise ValueError('no')\n",
    "returns a lying object": "class L(float):\n    def __eq__(s, o): return True\n"
                              "def gamma(b):\n    return L(7)\n",
}
for name, prog in games.items():
    check("CodeRunner: a program that %s scores 0" % name, not score(prog), prog)

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
