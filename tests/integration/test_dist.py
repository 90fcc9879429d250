#!/usr/bin/python3
"""test_dist.py — `make dist`'s artefacts (scripts/make_dist.py) as a user gets them.

Usage: /usr/bin/python3 test_dist.py PATH/TO/mechd
(mechd-eval-static is looked for next to it; a build without it, such as the
sanitizer build, checks only the wheel.) Into a temporary dist/: the wheel and
the evaluator's tarball exist with the names the docs give; SHA256SUMS and the
tarball's .sha256 verify with `sha256sum -c`; the tarball holds an executable
mechd-eval, a README and the licence notices of GSL, jansson, zlib and the C
library; unpacked into an empty directory and run with an empty environment, its
mechd-eval answers a boost at beta = 0.6 with gamma = 1/sqrt(1 - 0.36) = 1.25;
building twice gives the same bytes. Prints "N passed, M failed"; exits 1 on
failure.
"""
import json
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile

from mechdtest import check, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_dist.py PATH/TO/mechd\n")
    sys.exit(2)
BUILD = os.path.dirname(os.path.abspath(sys.argv[1]))
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
STATIC = os.path.join(BUILD, "mechd-eval-static")
BOOST = {"operation": "/v1/relativity/boost",
         "request": {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [0.6, 0, 0]}}}

tmp = tempfile.mkdtemp(prefix="mechd-dist-")
try:
    have_static = os.access(STATIC, os.X_OK)
    args = ["/usr/bin/python3", os.path.join(ROOT, "scripts", "make_dist.py"), "--build", BUILD]
    if not have_static:
        print("skip the evaluator's tarball (no mechd-eval-static in this build)")
        args.append("--no-evaluator")
    runs = []
    for k in ("a", "b"):
        out = os.path.join(tmp, k)
        p = subprocess.run(args + ["--out", out], capture_output=True, text=True, timeout=300)
        check("make_dist.py into %s succeeds" % k, p.returncode == 0, p.stdout + p.stderr[-500:])
        runs.append(out)
    dist = runs[0]
    files = sorted(os.listdir(dist))
    wheels = [f for f in files if f.startswith("mechd_client-") and f.endswith("-py3-none-any.whl")]
    check("dist/ holds the pure wheel mechd_client-<v>-py3-none-any.whl", len(wheels) == 1, files)
    p = subprocess.run(["sha256sum", "-c", "SHA256SUMS"], cwd=dist, capture_output=True, text=True)
    check("sha256sum -c SHA256SUMS verifies every artefact", p.returncode == 0
          and p.stdout.count(": OK") == (2 if have_static else 1), p.stdout + p.stderr)
    same = all(open(os.path.join(runs[0], f), "rb").read() == open(os.path.join(runs[1], f), "rb").read()
               for f in files)
    check("building dist twice gives the same bytes", same and files == sorted(os.listdir(runs[1])))
    if have_static:
        tars = [f for f in files if f.startswith("mechd-eval-static-") and f.endswith("-linux-x86_64.tar.gz")]
        if check("dist/ holds mechd-eval-static-<v>-linux-x86_64.tar.gz and its .sha256",
                 len(tars) == 1 and tars[0] + ".sha256" in files, files):
            p = subprocess.run(["sha256sum", "-c", tars[0] + ".sha256"], cwd=dist, capture_output=True,
                               text=True)
            check("its .sha256 verifies", p.returncode == 0, p.stdout + p.stderr)
            with tarfile.open(os.path.join(dist, tars[0])) as t:
                members = {m.name.split("/", 1)[1]: m for m in t.getmembers() if "/" in m.name}
                base = tars[0][:-len(".tar.gz")]
                names = set(members)
                want = {"mechd-eval", "README", "LICENSES/INDEX", "LICENSES/libgsl27.copyright",
                        "LICENSES/libjansson4.copyright", "LICENSES/zlib1g.copyright",
                        "LICENSES/libc6.copyright"}
                check("the tarball holds mechd-eval, README and the four licence notices",
                      want <= names and all(m.name.startswith(base + "/") for m in t.getmembers()),
                      sorted(names))
                check("mechd-eval is executable in the tarball, owned by root:root",
                      members["mechd-eval"].mode & 0o111 and members["mechd-eval"].uname == "root")
                gsl = t.extractfile(base + "/LICENSES/libgsl27.copyright").read().decode("utf-8", "replace")
                check("the GSL notice is its GPL licence", "GPL" in gsl, gsl[:200])
                empty = os.path.join(tmp, "empty")
                os.makedirs(empty)
                t.extract(base + "/mechd-eval", empty)
            exe = os.path.join(empty, base, "mechd-eval")
            p = subprocess.run([exe], input=json.dumps(BOOST).encode(), capture_output=True, env={},
                               cwd=empty, timeout=60)
            try:
                gamma = json.loads(p.stdout)["gamma"]
            except (ValueError, KeyError):
                gamma = None
            check("the unpacked mechd-eval, empty environment: gamma(0.6) = 1.25",
                  gamma is not None and abs(gamma - 1.25) < 1e-15, (p.returncode, p.stdout[:200]))
finally:
    shutil.rmtree(tmp, ignore_errors=True)

sys.exit(summary())
