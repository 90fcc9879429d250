#!/usr/bin/python3
"""test_check_kinds.py — /v1/check grades as a physicist would:
kinds (axis and eigenvectors up to sign, quaternion up to sign, angles modulo
2 pi and in degrees, axis with angle as a rotation, a degenerate principal
plane as a subspace), tolerances that make sense at zero (the problem's
scale), units (km, g cm^2, deg, eV ... converted; a unit of another dimension
graded wrong with feedback in words, never refused), shape messages that
count the expected numbers, text answers as students type them, and
feedback that never names the expected value unless reveal is true.

Usage: /usr/bin/python3 test_check_kinds.py PATH/TO/mechd
Runs `mechd eval` (same code as the server's /v1/check, no socket). Every
expected number comes from a closed form computed here (box and cylinder
inertia, the rotation quaternion of an axis and angle), never from mechd.
Prints "N passed, M failed"; exits 1 on failure.
"""
import json
import math
import subprocess
import sys

from mechdtest import check, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_check_kinds.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = sys.argv[1]

# Box 12 kg, edges 1 x 2 x 3 m at the origin: I = M/12 (b^2+c^2, a^2+c^2, a^2+b^2)
# = (13, 10, 5) kg m^2 about x, y, z; the smallest (5) is about z.
BOX = {"bodies": [{"shape": "box", "mass": 12, "size": [1, 2, 3], "position": [0, 0, 0]}]}
# Solid cylinder 2 kg, radius 1 m, height 1 m: about its axis (z) M r^2/2 = 1,
# about a diameter M (3 r^2 + h^2)/12 = 2/3 twice: the plane z = 0 is degenerate.
CYL = {"bodies": [{"shape": "cylinder", "mass": 2, "radius": 1, "height": 1,
                   "position": [0, 0, 0]}]}
# Rotation by 1 rad about z: q = [cos 0.5, 0, 0, sin 0.5].
ROT = {"axis_angle": {"axis": [0, 0, 1], "angle": 1.0}}
Q = [math.cos(0.5), 0.0, 0.0, math.sin(0.5)]


def run(body):
    p = subprocess.run([MECHD, "eval"], input=json.dumps({"operation": "/v1/check",
                       "request": body}).encode(), capture_output=True, timeout=60)
    return p.returncode, json.loads(p.stdout) if p.stdout else {}


def grade(op, req, pointer, value, **extra):
    answer = {"pointer": pointer, "value": value}
    for k in ("kind", "unit"):
        if k in extra:
            answer[k] = extra.pop(k)
    body = {"operation": op, "request": req, "answer": answer}
    body.update(extra)
    return run(body)


def verdict(name, want, rc, r, kind=None):
    ok = rc == 0 and r.get("correct") is want and (kind is None or r.get("kind") == kind)
    check(name, ok, "rc=%d %s" % (rc, json.dumps(r)[:400]))


def refused(name, rc, r, pointer, words):
    errs = r.get("errors", [])
    ok = (rc == 1 and r.get("status") == 422 and errs and errs[0].get("pointer") == pointer
          and all(w in errs[0].get("detail", "") for w in words))
    check(name, ok, "rc=%d %s" % (rc, json.dumps(r)[:400]))


# ---- axes and eigenvectors up to sign ----------------------------------------
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes/0", [0, 0, -1])
verdict("principal axis -z for +z is right (an axis has no sense)", True, rc, r, "axis")
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes/0", [0, 0, 7])
verdict("principal axis of any length is right", True, rc, r, "axis")
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes/0", [0, 1, 0])
verdict("the wrong principal axis is wrong", False, rc, r, "axis")
check("  ... its error is the chord sqrt(2) between the unit directions",
      rc == 0 and abs(r.get("absolute_error", 0) - math.sqrt(2)) < 1e-12, json.dumps(r)[:300])
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes/0", [0, 0, -1], kind="vector")
verdict("kind vector in the request overrides the table: -z is not +z", False, rc, r, "vector")
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes", [[0, 0, -1], [0, -1, 0], [1, 0, 0]])
verdict("all three principal axes, each of either sign", True, rc, r, "eigenvectors")
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes", [[0, 0, 1], [1, 0, 0], [0, 1, 0]])
verdict("axes in the wrong order (moments ascending) are wrong", False, rc, r)
check("  ... the wrong rows are named", r.get("wrong") == ["/principal/axes/1", "/principal/axes/2"],
      json.dumps(r.get("wrong")))
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/axes/0", [0, 0, 0])
verdict("a zero vector as an axis is wrong (not a crash, not a 422)", False, rc, r)
check("  ... and the feedback says why", "no direction" in r.get("feedback", ""), r.get("feedback"))

# ---- a degenerate principal plane is a subspace ------------------------------
s = math.sqrt(0.5)
rc, r = grade("/v1/rigid/inertia", CYL, "/principal/axes", [[s, s, 0], [s, -s, 0], [0, 0, -1]])
verdict("cylinder: any orthonormal basis of the plane z = 0 for the equal moments", True, rc, r)
rc, r = grade("/v1/rigid/inertia", CYL, "/principal/axes", [[0.6, 0.8, 0], [-0.8, 0.6, 0], [0, 0, 1]])
verdict("cylinder: another basis of the plane (3-4-5)", True, rc, r)
rc, r = grade("/v1/rigid/inertia", CYL, "/principal/axes", [[0.6, 0.8, 0], [0.6, 0.8, 0], [0, 0, 1]])
verdict("cylinder: twice the same vector does not span the plane", False, rc, r)
check("  ... the second row is the wrong one", r.get("wrong") == ["/principal/axes/1"],
      json.dumps(r.get("wrong")))
rc, r = grade("/v1/rigid/inertia", CYL, "/principal/axes", [[0.6, 0.8, 0], [0, 0, 1], [0.8, -0.6, 0]])
verdict("cylinder: the symmetry axis inside the plane's rows is wrong", False, rc, r)

# ---- quaternions up to sign, angles modulo 2 pi, degrees -------------------
rc, r = grade("/v1/rotation/convert", ROT, "/quaternion", [-x for x in Q])
verdict("-q is the same rotation as q", True, rc, r, "quaternion")
rc, r = grade("/v1/rotation/convert", ROT, "/quaternion", [-Q[0], 0, 0, Q[3]])
verdict("the conjugate (the inverse rotation) is wrong", False, rc, r)
check("  ... error min(|a - q|, |a + q|) = 2 sin 0.5",
      rc == 0 and abs(r.get("absolute_error", 0) - 2 * math.sin(0.5)) < 1e-12, json.dumps(r)[:300])
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle/angle", 1 - 2 * math.pi)
verdict("an angle 2 pi off is the same angle", True, rc, r, "angle")
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle/angle", 360 + 57.2958, unit="deg")
verdict("the angle in degrees (and a turn more)", True, rc, r, "angle")
check("  ... its error is the degrees' rounding: |57.2958 deg - 1 rad|",
      rc == 0 and abs(r["absolute_error"] - abs(57.2958 * math.pi / 180 - 1)) < 1e-12,
      json.dumps(r)[:300])
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle/angle", 57.2958)
verdict("57.2958 given without unit is radians: wrong", False, rc, r)
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle", {"axis": [0, 0, -2], "angle": -1})
verdict("axis -n with angle -t is the same rotation", True, rc, r, "axis_angle")
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle", {"axis": [0, 0, 1], "angle": -1})
verdict("the opposite sense is wrong", False, rc, r)
check("  ... its error is the angle between the rotations, 2 rad",
      rc == 0 and abs(r["absolute_error"] - 2) < 1e-12, json.dumps(r)[:300])
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle", [0, 0, 1, 1])
verdict("an array for an axis_angle answer is wrong (mistake shape), not refused", False, rc, r)
check("  ... the feedback asks for an axis with its angle", r.get("mistake") == "shape"
      and "an axis of 3 numbers with an angle" in r.get("feedback", ""), json.dumps(r)[:300])
rc, r = grade("/v1/rotation/convert", ROT, "/axis_angle", {"axis": [0, 0, 2], "angle": "57.2958 deg"})
verdict("an axis_angle with its angle typed as text in degrees (57.2958 deg = 1 rad)", True, rc, r)

# ---- tolerances at zero --------------------------------------------------------
# tensor[0][1] = 0; the row's scale is 13 kg m^2; 3 figures of 13 -> 0.05.
rc, r = grade("/v1/rigid/inertia", BOX, "/tensor/0/1", 1e-6, tolerance={"significant_figures": 3})
verdict("1e-6 for an expected 0 at scale 13 with 3 figures is right", True, rc, r)
rc, r = grade("/v1/rigid/inertia", BOX, "/tensor/0/1", 0.2, tolerance={"significant_figures": 3})
verdict("0.2 for it is wrong (more than half a unit in the 3rd figure of 13)", False, rc, r)
rc, r = grade("/v1/rigid/inertia", BOX, "/tensor/0/1", 0.2,
              tolerance={"significant_figures": 3, "scale": 100})
verdict("with tolerance.scale 100, 0.2 counts as zero (3 figures of 100: 0.5)", True, rc, r)
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments", [5.04, 10, 13],
              tolerance={"significant_figures": 3})
verdict("the scale does not loosen a nonzero number: 5.04 for 5 at 3 figures is wrong",
        False, rc, r)

# ---- units ---------------------------------------------------------------------
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", 5e7, unit="g cm^2")
verdict("5e7 g cm^2 is 5 kg m^2", True, rc, r)
rc, r = grade("/v1/rigid/inertia", BOX, "/center_of_mass", [0, 0, 0.0005], unit="km")
verdict("a centre of mass in km: 0.5 m off a zero vector with no scale is wrong", False, rc, r,
        "vector")
rc, r = grade("/v1/rigid/inertia", BOX, "/kinetic_energy", 1, unit="eV")
refused("no omega: /kinetic_energy is absent, refused at /answer/pointer", rc, r, "/answer/pointer",
        ["does not exist"])
rc, r = grade("/v1/rigid/inertia", dict(BOX, omega=[0, 0, 2]), "/kinetic_energy",
              10 / 1.602176634e-19, unit="eV")
verdict("kinetic energy I w^2/2 = 5 * 4 / 2 = 10 J given in eV", True, rc, r)
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", 5, unit="km")
verdict("km for a moment of inertia: graded wrong, not refused", False, rc, r)
check("  ... the feedback says in words a length was given and the answer is a moment of inertia",
      "A length was given" in r.get("feedback", "")
      and "moment of inertia, in kg m^2" in r.get("feedback", "")
      and r.get("mistake") == "unit_dimension", r.get("feedback"))
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", 5, unit="furlong")
verdict("an unknown unit: graded wrong, not refused", False, rc, r)
check("  ... mistake unit_unknown", r.get("mistake") == "unit_unknown", json.dumps(r)[:300])

# ---- shape messages, feedback ----------------------------------------------------
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments", [5, 10])
verdict("a wrong shape is wrong, not refused", False, rc, r)
check("  ... the feedback says 2 numbers were given and 3 expected",
      "an array of 2 numbers" in r.get("feedback", "")
      and "an array of 3 numbers" in r.get("feedback", ""), r.get("feedback"))
rc, r = grade("/v1/rigid/inertia", BOX, "/tensor", 5)
verdict("a number for a matrix is wrong", False, rc, r)
check("  ... the feedback names the 3 x 3 shape", "3 x 3" in r.get("feedback", ""), r.get("feedback"))
for odd in ["", "   ", "abc", "1e999", "--", "[1,", "{}", True, None, [], [[1]], ["x"],
            {"axis": 1}, "5 5", "5,5", "(((((((((((((((((((((((((((((1", "0x10", "nan", "inf",
            "\u00e9\u00e9", "5 " + "m" * 300, "1/0"]:
    rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", odd)
    check("an odd answer %r is graded wrong with feedback, never refused" % (odd,),
          rc == 0 and r.get("correct") is False and r.get("feedback", "").startswith("Not correct")
          and "/" not in r.get("feedback", "").replace("kg m^2", ""), "rc=%d %s" % (rc, json.dumps(r)[:300]))
for text, right in [("5", True), ("5.0 kg m^2", True), ("5 kg*m^2", True), ("5 kg m2", True),
                    ("5e7 g cm^2", True), ("10/2", True), ("2.5*2", True), ("5.0 x 10^0", True),
                    ("-5", False), ("sqrt(25)", True), ("(2+3)", True)]:
    rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", text)
    verdict("text %r for the moment 5 kg m^2 is %s" % (text, right), right, rc, r)
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", 5.3721)
fb = r.get("feedback", "")
check("feedback of a wrong answer names kind and unit, not the value",
      rc == 0 and r["correct"] is False and "kg m^2" in fb and "5" not in fb, fb)
rc, r = grade("/v1/rigid/inertia", BOX, "/principal/moments/0", 5.3721e7, unit="g cm^2",
              reveal=True)
fb = r.get("feedback", "")
check("reveal: the feedback names the expected value in the student's unit (5e7 g cm^2)",
      rc == 0 and ("5e7" in fb or "50000000" in fb) and "g cm^2" in fb, fb)

sys.exit(summary())
