#!/usr/bin/env python3
"""check_paths.py SOURCE_DIR — every repo path a comment names exists.

A comment that names a file (`core/frames/trajectory.c`, `api/ops/rigid/inertia.json`,
`docs/numerics.md`, `mech/rotation/rotation.h`) is a pointer a reader follows; when the file
moves, the pointer must move with it. This lint reads the comments of the tracked
sources (C and headers: /* */ and //; JavaScript and CSS likewise; Python, shell
and CMake: # lines and Python's docstrings) and fails, naming file and line, on a
path that does not exist in the tree.

What counts as a repo path: a word that starts with one of the tree's top folders
(api/ bench/ clients/ core/ docker/ docs/ scripts/ server/ tests/) and is not part
of a longer path or a URL (`/v1/rigid/inertia`, `src/...` of another project are
not), or a public header named as `mech/<domain>/<name>.h` or an umbrella
`mech/<domain>.h` (core/include/mech/). Words with
a placeholder or pattern (`<domain>`, `*`, `{a,b}`, `...`, `…`, `$`, `%`) are
templates, not paths, and are skipped; so are CTest names, which the comments
write as `CTest core/...` or `ctest -R ...`. A program may be named by its
source without the extension (`bench/bench_http` for bench/bench_http.c). A
trailing `:LINE`, `'s`, or punctuation is not part of the path.
Exit 0 when every named path exists, 1 otherwise.
"""
import os
import re
import subprocess
import sys

TOP = ("api", "bench", "clients", "core", "docker", "docs", "scripts", "server", "tests")
C_LIKE = (".c", ".h", ".js", ".mjs", ".css")
HASH_LIKE = (".py", ".sh")
PATH_RE = re.compile(r"(?<![\w./\-~$])((?:%s)/[\w./\-<>*{},…$%%+]*)" % "|".join(TOP))
MECH_RE = re.compile(r"(?<![\w./\-])(mech/(?:[\w\-]+/)*[\w\-]+\.h)\b")
TEMPLATE = re.compile(r"[<>*{}…$%]|\.\.\.|\.\./")
CTEST_BEFORE = re.compile(r"(CTest|ctest -R|ctest|test) `?$")


def comments(path, text):
    """(line number, comment text) pairs of one file."""
    out = []
    if path.endswith(C_LIKE):
        for m in re.finditer(r"/\*.*?\*/|//[^\n]*", text, re.S):
            # skip // inside string literals or URLs: a crude but sufficient test
            if m.group(0).startswith("//"):
                line_start = text.rfind("\n", 0, m.start()) + 1
                before = text[line_start:m.start()]
                if before.count('"') % 2 or before.count("'") % 2 or before.count("`") % 2 \
                        or before.endswith(":"):
                    continue
            out.append((text.count("\n", 0, m.start()) + 1, m.group(0)))
    elif path.endswith(HASH_LIKE) or os.path.basename(path) == "CMakeLists.txt":
        for i, line in enumerate(text.split("\n"), 1):
            j = line.find("#")
            if j >= 0 and line[:j].count('"') % 2 == 0 and line[:j].count("'") % 2 == 0:
                out.append((i, line[j:]))
        if path.endswith(".py"):
            for m in re.finditer(r'"""(.*?)"""', text, re.S):
                out.append((text.count("\n", 0, m.start()) + 1, m.group(1)))
    return out


def exists(src, word):
    """A path exists, or names a program by its source (bench/bench_http for
    bench/bench_http.c, scripts/cases_by_domain for its .py)."""
    return any(os.path.exists(os.path.join(src, word + ext)) for ext in ("", ".c", ".py", ".sh"))


def clean(word):
    word = re.sub(r":\d+(-\d+)?$", "", word)
    word = re.sub(r"'s$", "", word)
    return word.rstrip(".,;:)]'\"`")


def tracked_files(src):
    """The tracked files (git ls-files), or, in a copy without .git (a container
    build), every file outside build trees and node_modules."""
    try:
        r = subprocess.run(["git", "-C", src, "ls-files"], capture_output=True, text=True)
        if r.returncode == 0 and r.stdout.strip():
            return r.stdout.split("\n")
    except OSError:
        pass
    out = []
    for root, dirs, names in os.walk(src):
        dirs[:] = [d for d in dirs if not d.startswith((".", "build")) and d != "node_modules"]
        out += [os.path.relpath(os.path.join(root, n), src) for n in names]
    return out


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "."
    files = tracked_files(src)
    bad = []
    checked = 0
    for rel in files:
        if not rel or not (rel.endswith(C_LIKE + HASH_LIKE) or os.path.basename(rel) == "CMakeLists.txt"):
            continue
        if "/vendor/" in rel or rel.startswith("tests/fuzz/regress/"):
            continue
        full = os.path.join(src, rel)
        try:
            with open(full, encoding="utf-8") as f:
                text = f.read()
        except (OSError, UnicodeDecodeError):
            continue
        for line0, body in comments(rel, text):
            for k, cline in enumerate(body.split("\n")):
                for m in PATH_RE.finditer(cline):
                    word = clean(m.group(1))
                    if TEMPLATE.search(word) or CTEST_BEFORE.search(cline[:m.start()]):
                        continue
                    checked += 1
                    if not exists(src, word.rstrip("/")):
                        bad.append("%s:%d: %s" % (rel, line0 + k, word))
                for m in MECH_RE.finditer(cline):
                    checked += 1
                    if not os.path.exists(os.path.join(src, "core/include", m.group(1))):
                        bad.append("%s:%d: %s (core/include/%s)" % (rel, line0 + k, m.group(1), m.group(1)))
    if bad:
        print("comments name repo paths that do not exist:")
        for b in bad:
            print("    " + b)
        print("0 passed, 1 failed (%d of %d named paths missing)" % (len(bad), checked))
        return 1
    print("1 passed, 0 failed (%d named paths exist)" % checked)
    return 0


if __name__ == "__main__":
    sys.exit(main())
