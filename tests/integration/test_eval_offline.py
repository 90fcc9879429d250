#!/usr/bin/python3
"""test_eval_offline.py — mechd inside a grader: mechd-eval without
libmicrohttpd, the fully static mechd-eval-static, `make install`'s rules, and
what `mechd eval` answers to input that is not JSON.

Usage: /usr/bin/python3 test_eval_offline.py PATH/TO/mechd
(mechd-eval and mechd-eval-static are looked for next to it; the build tree's
cmake_install.cmake is what `make install` runs).

- mechd-eval's dynamic dependencies (read from its ELF DT_NEEDED entries, no
  ldd needed) hold no libmicrohttpd, gnutls, nettle or gmp; its answers are
  byte-identical to `mechd eval`'s.
- mechd-eval-static has no ELF interpreter (PT_INTERP) and no DT_NEEDED at
  all, so it loads no shared library whatever the machine has; run with an
  empty environment and LD_LIBRARY_PATH pointing nowhere, from a copy in an
  empty directory, its answers are byte-identical to `mechd eval`'s (a boost:
  gamma = 1.25 at beta = 0.6; a rotation; a trajectory integrated by RK4).
  Skipped only in sanitizer builds (MECHD_NO_STATIC_EVAL=1 from CMake).
- Input that is not JSON (bare with --operation, or an envelope; from stdin or
  a FILE): a 400 /problems/malformed-json problem on stdout naming the input
  ("standard input" or the file) and where the parser stopped, never "the
  request query parameter", and exit status 1 (a refused request), not 2 (usage).
- mechd --version and mechd-eval --version name the git commit of the build.
- cmake --install with DESTDIR and a prefix: bin/mechd, bin/mechd-eval, the
  docs, the front end and the Python client land under DESTDIR/PREFIX and
  nothing outside it; the installed mechd-eval answers.
Prints "N passed, M failed"; exits 1 on failure.
"""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import urllib.request

from mechdtest import check, start_mechd, stop_mechd, summary

if len(sys.argv) < 2:
    sys.stderr.write("usage: test_eval_offline.py PATH/TO/mechd\n")
    sys.exit(2)
MECHD = os.path.abspath(sys.argv[1])
BUILD = os.path.dirname(MECHD)
EVAL = os.path.join(BUILD, "mechd-eval")
STATIC = os.path.join(BUILD, "mechd-eval-static")

REQUESTS = [
    {"operation": "/v1/relativity/boost",
     "request": {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [0.6, 0, 0]}}},
    {"operation": "/v1/rotation/convert", "request": {"euler_zxz": [0.3, 0.4, 0.5]}},
    {"operation": "/v1/trajectory",
     "request": {"particle": {"mass": 1, "position": [1, 0, 0], "velocity": [0, 1, 0]},
                 "forces": [{"type": "spring", "k": 1}], "t_end": 6.283185307179586, "samples": 3,
                 "integrator": {"method": "rk4", "dt": 0.001}}},
]


def elf_dynamic(path):
    """(has PT_INTERP, [DT_NEEDED names]) of a 64-bit little-endian ELF file."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        raise ValueError("not a 64-bit little-endian ELF: %s" % path)
    e_phoff, = struct.unpack_from("<Q", data, 0x20)
    e_phentsize, e_phnum = struct.unpack_from("<HH", data, 0x36)
    interp, dyn = False, None
    loads = []
    for i in range(e_phnum):
        p_type, _, p_offset, p_vaddr, _, p_filesz = struct.unpack_from("<IIQQQQ", data, e_phoff + i * e_phentsize)
        if p_type == 3:
            interp = True
        elif p_type == 2:
            dyn = (p_offset, p_filesz)
        elif p_type == 1:
            loads.append((p_vaddr, p_offset, p_filesz))
    needed = []
    if dyn:
        strtab, offs = None, []
        for k in range(dyn[1] // 16):
            tag, val = struct.unpack_from("<qQ", data, dyn[0] + 16 * k)
            if tag == 0:
                break
            if tag == 1:
                offs.append(val)
            elif tag == 5:
                strtab = val
        if strtab is not None:
            base = next(off + strtab - va for va, off, sz in loads if va <= strtab < va + sz)
            for o in offs:
                end = data.index(b"\0", base + o)
                needed.append(data[base + o:end].decode())
    return interp, needed


def run(cmd, stdin=b"", env=None, cwd=None):
    p = subprocess.run(cmd, input=stdin, capture_output=True, timeout=120, env=env, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def reference(req):
    return run([MECHD, "eval"], json.dumps(req).encode())


def test_eval_dynamic():
    if not check("mechd-eval is built next to mechd", os.access(EVAL, os.X_OK), EVAL):
        return
    _, needed = elf_dynamic(EVAL)
    bad = [n for n in needed if any(x in n for x in ("microhttpd", "gnutls", "nettle", "gmp", "hogweed"))]
    check("mechd-eval needs no libmicrohttpd (nor its TLS stack)", needed and not bad, repr(needed))
    _, mneeded = elf_dynamic(MECHD)
    check("(the check can fail: mechd itself needs libmicrohttpd)",
          any("microhttpd" in n for n in mneeded), repr(mneeded))
    for req in REQUESTS:
        rc0, out0, _ = reference(req)
        rc, out, err = run([EVAL], json.dumps(req).encode())
        check("mechd-eval %s: the same bytes as mechd eval" % req["operation"],
              rc == rc0 == 0 and out == out0, (rc, err[:200]))


def test_eval_static():
    if os.environ.get("MECHD_NO_STATIC_EVAL"):
        print("skip mechd-eval-static (sanitizer build)")
        return
    if not check("mechd-eval-static is built next to mechd", os.access(STATIC, os.X_OK), STATIC):
        return
    interp, needed = elf_dynamic(STATIC)
    check("mechd-eval-static has no ELF interpreter and needs no shared library",
          not interp and needed == [], repr((interp, needed)))
    out = subprocess.run(["ldd", STATIC], capture_output=True, text=True)
    check("ldd says it is not a dynamic executable",
          "not a dynamic executable" in (out.stdout + out.stderr), out.stdout + out.stderr)
    empty = tempfile.mkdtemp(prefix="mechd-static-")
    try:
        exe = os.path.join(empty, "mechd-eval")
        shutil.copy2(STATIC, exe)
        env = {"LD_LIBRARY_PATH": os.path.join(empty, "nothing-here"), "PATH": "/nonexistent"}
        for req in REQUESTS:
            rc0, out0, _ = reference(req)
            rc, out, err = run([exe], json.dumps(req).encode(), env=env, cwd=empty)
            check("static %s from an empty directory and environment: the same bytes as mechd eval"
                  % req["operation"], rc == rc0 == 0 and out == out0, (rc, err[:200], out[:200], out0[:200]))
        rc, out, _ = run([exe], json.dumps(REQUESTS[0]).encode(), env=env, cwd=empty)
        doc = json.loads(out) if rc == 0 else {}
        check("static boost at beta = 0.6: gamma = 1/sqrt(1 - 0.36) = 1.25, t' = 1.25",
              abs(doc.get("gamma", 0) - 1.25) < 1e-15 and abs(doc["vectors"][0][0] - 1.25) < 1e-15, repr(doc)[:200])
        rc, out, _ = run([exe], json.dumps(REQUESTS[2]).encode(), env=env, cwd=empty)
        doc = json.loads(out) if rc == 0 else {}
        pos = doc.get("position") or doc.get("r") or []
        # x(t) = cos t, y(t) = sin t for the unit spring; after one period back at (1, 0, 0).
        last = pos[-1] if pos else None
        check("static trajectory: the unit-spring orbit closes after 2 pi (1e-9)",
              last is not None and abs(last[0] - 1) < 1e-9 and abs(last[1]) < 1e-9, repr(doc)[:300])
    finally:
        shutil.rmtree(empty, ignore_errors=True)


def test_malformed():
    tmp = tempfile.mkdtemp(prefix="mechd-eval-bad-")
    try:
        fname = os.path.join(tmp, "student.json")
        with open(fname, "wb") as f:
            f.write(b'{"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [0.6, 0, 0]')
        progs = [("mechd eval", [MECHD, "eval"])]
        if os.access(EVAL, os.X_OK):
            progs.append(("mechd-eval", [EVAL]))
        for name, prog in progs:
            cases = [("bare, stdin", prog + ["--operation", "/v1/relativity/boost"], b"{bad", "standard input"),
                     ("envelope, stdin", prog, b'{"operation": "/v1/relativity/boost", "request": ', "standard input"),
                     ("bare, FILE", prog + ["--operation", "/v1/relativity/boost", fname], b"", "file " + fname),
                     ("empty input", prog, b"", "standard input")]
            for label, cmd, stdin, where in cases:
                rc, out, err = run(cmd, stdin)
                try:
                    doc = json.loads(out)
                except ValueError:
                    doc = {}
                check("%s, not JSON (%s): exit 1, not the usage status 2" % (name, label), rc == 1, (rc, out, err))
                check("%s, not JSON (%s): 400 malformed-json naming the input (%s) and the place" % (name, label, where),
                      doc.get("status") == 400 and doc.get("type") == "/problems/malformed-json" and
                      ("the input (%s) is not valid JSON: line " % where) in doc.get("detail", "") and
                      "query parameter" not in doc.get("detail", ""), repr(doc))
            rc, out, err = run(prog, b'{"request": {}}')
            check("%s: valid JSON without an operation is still a usage error (2)" % name, rc == 2 and out == b"",
                  (rc, out, err))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def test_install():
    script = os.path.join(BUILD, "cmake_install.cmake")
    if not check("the build tree has install rules", os.path.exists(script), script):
        return
    stage = tempfile.mkdtemp(prefix="mechd-destdir-")
    try:
        env = dict(os.environ, DESTDIR=stage)
        p = subprocess.run(["cmake", "--install", BUILD, "--prefix", "/opt/mechd"], capture_output=True,
                           text=True, timeout=120, env=env)
        check("cmake --install with DESTDIR succeeds", p.returncode == 0, p.stdout[-500:] + p.stderr[-500:])
        root = os.path.join(stage, "opt", "mechd")
        want = ["bin/mechd", "bin/mechd-eval", "share/doc/mechd/README.md", "share/doc/mechd/grading.md",
                "share/mechd/web/index.html", "share/mechd/python/mechd.py", "share/mechd/python/pyproject.toml",
                "share/mechd/curl/inertia.sh"]
        missing = [w for w in want if not os.path.exists(os.path.join(root, w))]
        check("installed under DESTDIR/PREFIX: binaries, docs, front end, clients", not missing, repr(missing))
        outside = [d for d in os.listdir(stage) if d != "opt"]
        check("nothing installed outside DESTDIR/PREFIX", outside == [], repr(outside))
        check("the installed binaries are executable",
              all(os.access(os.path.join(root, "bin", b), os.X_OK) for b in ("mechd", "mechd-eval")))
        rc, out, err = run([os.path.join(root, "bin", "mechd-eval")], json.dumps(REQUESTS[0]).encode())
        doc = json.loads(out) if rc == 0 else {}
        check("the installed mechd-eval answers (gamma 1.25)", abs(doc.get("gamma", 0) - 1.25) < 1e-15, (rc, err[:200]))
        # An installed mechd serves PREFIX/share/mechd/web by default, not the build tree's.
        marker = "<!-- staged front end %s -->" % os.getpid()
        with open(os.path.join(root, "share", "mechd", "web", "index.html"), "a") as f:
            f.write(marker + "\n")
        try:
            proc, port = start_mechd(os.path.join(root, "bin", "mechd"), stderr=subprocess.DEVNULL)
        except RuntimeError as e:
            proc, port = None, str(e)
        if check("the installed mechd starts", proc is not None, port):
            try:
                with urllib.request.urlopen("http://127.0.0.1:%d/" % port, timeout=30) as r:
                    page = r.read().decode("utf-8", "replace")
            except OSError as e:
                page = str(e)
            finally:
                stop_mechd(proc)
            check("the installed mechd serves the front end under its prefix by default "
                  "(PREFIX/share/mechd/web)", marker in page, page[-300:])
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def test_version():
    """--version names the git commit the build was configured from (or "unknown" outside a checkout)."""
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    for name, exe in (("mechd", MECHD), ("mechd-eval", EVAL)):
        if not os.access(exe, os.X_OK):
            continue
        out = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=30).stdout
        m = re.fullmatch(r"%s \S+ \(commit ([0-9a-f]{12}|unknown)\)\n" % re.escape(name), out)
        known = m is not None and (m.group(1) == "unknown" or subprocess.run(
            ["git", "-C", root, "cat-file", "-e", m.group(1) + "^{commit}"], capture_output=True).returncode == 0)
        check("%s --version names its commit, a commit of this repository" % name, known, repr(out))


def main():
    test_version()
    test_eval_dynamic()
    test_eval_static()
    test_malformed()
    test_install()


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a crash is a failure, not a pass
        import traceback
        traceback.print_exc()
        check("test ran to the end", False, "%s: %s" % (type(e).__name__, e))
    sys.exit(summary())
