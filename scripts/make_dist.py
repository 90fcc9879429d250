#!/usr/bin/env python3
"""make_dist.py — the release artefacts that install without building, into dist/
(`make dist` runs it after `make static-eval`):

  mechd_client-<v>-py3-none-any.whl
      the Python client as a pure wheel, built by clients/python/mechd_build.py with
      the standard library only; `pip install --no-index dist/mechd_client-*.whl`
      works in any Python >= 3.8 (venv or not), offline.
  mechd-eval-static-<v>-linux-x86_64.tar.gz (+ .sha256)
      the static offline evaluator for grader containers (PrairieLearn's
      serverFilesCourse, Jobe, any x86-64 Linux image): mechd-eval, README, and the
      licence notices of what is linked into it (GSL, jansson, zlib, the GNU C
      library), taken from the build machine's Debian packages.
  SHA256SUMS
      sha256 of every file above (`cd dist && sha256sum -c SHA256SUMS`).

The grader image is built by `make grader-image` (docker/grader-pl.Dockerfile).
Standard library only; archives have fixed timestamps and owners.

    python3 scripts/make_dist.py --build build --out dist
"""
import argparse
import hashlib
import io
import os
import subprocess
import sys
import tarfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
EPOCH = 1577836800  # 2020-01-01: fixed mtimes, so the same inputs give the same bytes

# What the static evaluator links in, and the Debian package whose copyright file
# holds its licence.
NOTICES = [("GSL (GNU Scientific Library), GPL-3.0-or-later", "libgsl27"),
           ("jansson, MIT", "libjansson4"),
           ("zlib, Zlib licence", "zlib1g"),
           ("GNU C library, LGPL-2.1-or-later (static linking: see its section 6)", "libc6")]

README = """mechd-eval (static) %(version)s

One executable, fully static (glibc, GSL, jansson and zlib linked in), for any x86-64
Linux: it answers a mechd request offline, exactly as `mechd eval` does (same input,
bytes and exit statuses: 0 answer, 1 refused, 3 failure, 2 usage).

    echo '{"operation": "/v1/relativity/boost", "request": {"vectors": [[1,0,0,0]],
           "velocity": {"beta": [0.6,0,0]}}}' | ./mechd-eval

Install it where the grader looks for it: PrairieLearn courses as
serverFilesCourse/mechd/bin/mechd-eval (executable, committed), Jobe or an external
grader image as /usr/local/bin/mechd-eval. See docs/grading.md in the mechd
repository.

Licences: LICENSES/ holds the notices of the libraries linked into this binary. GSL
is GPL-3.0-or-later, so this binary is distributed under the GPL: its complete
corresponding source is the mechd repository at the commit shown by
`./mechd-eval --version` together with the Debian 12 source packages gsl, jansson,
zlib and glibc.
"""


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 16), b""):
            h.update(chunk)
    return h.hexdigest()


def add(tar, name, data, mode=0o644):
    ti = tarfile.TarInfo(name)
    ti.size, ti.mtime, ti.mode = len(data), EPOCH, mode
    ti.uid = ti.gid = 0
    ti.uname = ti.gname = "root"
    tar.addfile(ti, io.BytesIO(data))


def evaluator_tarball(build, out):
    exe = os.path.join(build, "mechd-eval-static")
    if not os.path.isfile(exe):
        sys.exit("make_dist: %s is missing (make static-eval)" % exe)
    ver = subprocess.run([exe, "--version"], capture_output=True, text=True,
                         timeout=30).stdout.split()
    version = ver[1] if len(ver) > 1 else "0"
    base = "mechd-eval-static-%s-linux-x86_64" % version
    path = os.path.join(out, base + ".tar.gz")
    with open(exe, "rb") as f:
        binary = f.read()
    notices = []
    for what, pkg in NOTICES:
        cfile = "/usr/share/doc/%s/copyright" % pkg
        if not os.path.isfile(cfile):
            sys.exit("make_dist: %s is missing: the licence of %s cannot be shipped" % (cfile, what))
        with open(cfile, "rb") as f:
            notices.append((pkg, what, f.read()))
    raw = io.BytesIO()
    with tarfile.open(fileobj=raw, mode="w", format=tarfile.PAX_FORMAT) as t:
        add(t, base + "/mechd-eval", binary, 0o755)
        add(t, base + "/README", (README % {"version": " ".join(ver[1:])}).encode())
        index = "".join("%-12s %s\n" % (pkg, what) for pkg, what, _ in notices)
        add(t, base + "/LICENSES/INDEX", index.encode())
        for pkg, _, text in notices:
            add(t, base + "/LICENSES/%s.copyright" % pkg, text)
    import gzip
    with open(path, "wb") as f:
        with gzip.GzipFile(fileobj=f, mode="wb", mtime=EPOCH, filename="") as gz:
            gz.write(raw.getvalue())
    with open(path + ".sha256", "w") as f:
        f.write("%s  %s\n" % (sha256(path), os.path.basename(path)))
    return path


def wheel(out):
    sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
    import mechd_build
    return os.path.join(out, mechd_build.build_wheel(out))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "dist"))
    ap.add_argument("--no-evaluator", action="store_true", help="only the wheel")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    made = [wheel(a.out)]
    if not a.no_evaluator:
        made.append(evaluator_tarball(a.build, a.out))
    with open(os.path.join(a.out, "SHA256SUMS"), "w") as f:
        for p in made:
            f.write("%s  %s\n" % (sha256(p), os.path.basename(p)))
    for p in made:
        print(os.path.relpath(p, os.getcwd()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
